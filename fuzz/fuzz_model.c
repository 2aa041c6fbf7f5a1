/*
 * fuzz_model.c - libFuzzer harness for the prepared-model reader
 * (src/model.c: the container, its checksums and the MESH section) and the
 * mesh build behind it.
 *
 * With a valid silhouette map (SMAP) the outline is also interpolated
 * for one eye and scan-converted into clip mode's stencil (src/clip.c),
 * in a small arena, so that out-of-range maps meet the fixed point.
 *
 * The input is a .silk file.  It is loaded as it is (so the fuzzer meets
 * the header and checksum checks), then once more with the file size, the
 * section table's checksum and every in-range section's checksum made
 * right, with the file's normals and with computed ones, so the fuzzer also
 * reaches the checks of the contents behind the checksums.  The outcomes
 * are checked as for the other readers (fuzz.h): a failure is one clean
 * line and leaves the arena as it was; a loaded mesh passes
 * silk_mesh_validate.
 */
#include "fuzz.h"
#include "../src/clip.h"

/* The map's outline for an eye on the first view's side, into a 32 x 24
 * stencil; every outcome is fine but a crash or a dirty error. */
static void fuzz_clip(const uint8_t *b, size_t size)
{
    silk_silmap map;
    silk_error err;
    silk_status st = silk_model_silmap(b, size, "fuzz.silk", &map, &err);
    if (st) {
        fuzz_check_error(st, &err, "fuzz.silk");
        return;
    }
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = map.views[0].cam.eye;
    cam.target = map.centre;
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(35, 1);
    cam.znear = SILK_FX_C(1, 100);
    cam.zfar = SILK_FX_C(1000, 1);
    cam.width = 32;
    cam.height = 24;
    silk_view v;
    if (silk_view_init(&v, &cam, &err) != SILK_OK) return;
    static uint8_t mem[(size_t)1 << 20];
    silk_arena a;
    silk_arena_init(&a, mem, sizeof mem);
    silk_clip c;
    st = silk_clip_prepare(&c, &a, &map, &v, 0, 8, (int)(size & 1), &err);
    if (st) {
        fuzz_check_error(st, &err, NULL);
        return;
    }
    static uint8_t color[32 * 8 * 3];
    static uint32_t depth[32 * 8];
    silk_target t;
    for (int y0 = 0; y0 < 24; y0 += 8) {
        silk_target_init(&t, 32, 24, y0, 8, SILK_PIX_RGB888, color, depth);
        silk_target_clear(&t, 0xFFFFFF);
        silk_clip_stencil(&c, &t);
        t.mask = NULL;
        silk_clip_antialias(&c, &t, 0xFFFFFF);
    }
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_reader(silk_load_model, "fuzz.silk", data, size);
    if (size < SILK_MODEL_HEADER_BYTES || size > ((size_t)1 << 20)) return 0;
    uint8_t *b = malloc(size);
    if (!b) return 0;
    memcpy(b, data, size);
    fuzz_model_fix(b, size);
    silk_load_opts o;
    silk_load_opts_default(&o);
    fuzz_load_checked(silk_load_model, "fuzz.silk", b, size, &o, NULL, 64 * size + 4096);
    o.normals = SILK_NORMALS_COMPUTE;
    o.crease_deg = SILK_FX_C((int64_t)(size % 181), 1);
    fuzz_load_checked(silk_load_model, "fuzz.silk", b, size, &o, NULL, 64 * size + 4096);
    silk_load_opts_default(&o);
    o.part = SILK_PART_HULL;
    fuzz_load_checked(silk_load_model, "fuzz.silk", b, size, &o, NULL, 64 * size + 4096);
    fuzz_clip(b, size);
    free(b);
    return 0;
}
