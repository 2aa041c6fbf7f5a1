/*
 * fuzz_ply.c - libFuzzer harness for the PLY reader (src/ply.c: ASCII and
 * both binary byte orders) and the mesh build behind it (edges, normals,
 * features; paper III-A, III-B).
 *
 * The input is a PLY file.  It is loaded twice: with the default options
 * into an arena of 64 bytes per input byte (binary PLY is dense, so the
 * out-of-memory paths run often), and with file normals, a --scale and a
 * crease angle taken from its length into a roomy one.  Besides "no crash",
 * every outcome is checked:
 *   failure: one clean line naming the file, the arena as it was;
 *   success: the mesh passes silk_mesh_validate (every index consistent),
 *            and the visibility hierarchy builds over it (or fails cleanly).
 * `make fuzz` builds it with clang -fsanitize=fuzzer,address,undefined.
 */
#include "fuzz.h"
#include "silk/validate.h"

#define PLY_NAME "fuzz.ply"

/* Loads into mem, or into a heap block of arena_size when mem is NULL. */
static void ply_load(const uint8_t *data, size_t size, const silk_load_opts *o, uint8_t *mem, size_t arena_size)
{
    uint8_t *own = mem ? NULL : malloc(arena_size);
    if (!mem && !(mem = own)) return;
    silk_arena a;
    silk_mesh m;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_arena_init(&a, mem, arena_size);
    silk_status st = silk_load_ply(data, size, PLY_NAME, o, &a, &m, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, PLY_NAME);
        fuzz_check_arena_empty(&a);
    } else {
        fuzz_expect(a.top == 0, "loading left %zu bytes of scratch", a.top);
        silk_status v = silk_mesh_validate(&m, PLY_NAME, &err);
        fuzz_expect(v == SILK_OK, "the loaded mesh is inconsistent: %s", err.msg);
        size_t bottom = a.bottom;
        st = silk_vis_build(&m, NULL, &a, &err);
        if (st != SILK_OK) {
            fuzz_check_error(st, &err, NULL);
            fuzz_expect(a.bottom == bottom && a.top == 0, "failed hierarchy build kept memory");
        } else {
            v = silk_mesh_validate(&m, PLY_NAME, &err);
            fuzz_expect(v == SILK_OK, "the mesh is inconsistent after the hierarchy: %s", err.msg);
        }
    }
    free(own);
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    ply_load(data, size, &o, NULL, 64 * size + 4096);

    /* The other options, chosen by the length so that one input covers both. */
    o.normals = SILK_NORMALS_FILE;
    o.crease_deg = SILK_FX_C((int64_t)(size % 181), 1);
    o.scale.mant = (int64_t)(size % 7) + 1;
    o.scale.exp10 = (int32_t)(size % 5) - 2;
    /* the roomy arena is kept between runs: a fresh 4 MB block per run costs
     * more than the load */
    static uint8_t roomy[(size_t)1 << 22];
    ply_load(data, size, &o, roomy, sizeof roomy);
    return 0;
}
