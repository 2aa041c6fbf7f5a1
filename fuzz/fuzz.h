/*
 * fuzz.h - what the libFuzzer harnesses in fuzz/ share: the checks that
 * turn a wrong answer (not only a crash) into a finding.
 *
 * A harness calls fuzz_expect() for every property it checks; a failed one
 * prints what went wrong and aborts, which libFuzzer reports as a crash and
 * saves the input.  Harnesses run on the host and may use malloc; the core
 * they drive gets its memory from an arena as always.
 */
#ifndef SILK_FUZZ_H
#define SILK_FUZZ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "silk/silk.h"
#include "silk/validate.h"

/* The entry point: libFuzzer's, unless tests/core/test_regress.c, which runs
 * every harness in one program, names each one itself. */
#ifndef FUZZ_ENTRY
#define FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

#define fuzz_expect(cond, ...)                                                    \
    do {                                                                          \
        if (!(cond)) {                                                            \
            fprintf(stderr, "fuzz: %s:%d: %s: ", __FILE__, __LINE__, #cond);      \
            fprintf(stderr, __VA_ARGS__);                                         \
            fputc('\n', stderr);                                                  \
            abort();                                                              \
        }                                                                         \
    } while (0)

/* A failed call must leave one clean line: non-empty, no newline, starting
 * with the name it was given (or a stage name when there is no input name),
 * and a code that is an error. */
static inline void fuzz_check_error(silk_status st, const silk_error *err, const char *name)
{
    fuzz_expect(st != SILK_OK, "not an error");
    fuzz_expect(err->code == st, "err.code %d but returned %d", (int)err->code, (int)st);
    const char *nul = memchr(err->msg, '\0', sizeof err->msg);
    fuzz_expect(nul && nul > err->msg, "message empty or not terminated");
    fuzz_expect(strchr(err->msg, '\n') == NULL, "message has a newline: \"%s\"", err->msg);
    if (name) fuzz_expect(strncmp(err->msg, name, strlen(name)) == 0, "message \"%s\" does not name %s", err->msg, name);
}

/* The arena as the loader found it: a failed load takes nothing. */
static inline void fuzz_check_arena_empty(const silk_arena *a)
{
    fuzz_expect(a->bottom == 0 && a->top == 0, "arena not restored: bottom %zu top %zu", a->bottom, a->top);
    for (int p = 0; p < SILK_MEM_COUNT; p++)
        fuzz_expect(a->used[p] == 0, "purpose %s still holds %zu bytes", silk_purpose_name((silk_purpose)p),
                    a->used[p]);
}

/* Little-endian reads from the fuzz input, zero past its end. */
typedef struct fuzz_bytes {
    const uint8_t *p;
    size_t n, at;
} fuzz_bytes;

static inline uint32_t fuzz_u8(fuzz_bytes *b)
{
    return b->at < b->n ? b->p[b->at++] : 0;
}

static inline int32_t fuzz_i16(fuzz_bytes *b)
{
    uint32_t lo = fuzz_u8(b), hi = fuzz_u8(b);
    return (int32_t)(int16_t)(uint16_t)(lo | hi << 8);
}

static inline uint32_t fuzz_u32(fuzz_bytes *b)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) v |= fuzz_u8(b) << (8 * i);
    return v;
}


/* A mesh reader: silk_load_obj or silk_load_ply. */
typedef silk_status (*fuzz_reader_fn)(const void *data, size_t len, const char *name, const silk_load_opts *o,
                                      silk_arena *a, silk_mesh *out, silk_error *err);

/* One load into mem (or a heap block of arena_size when mem is NULL), with
 * every outcome checked:
 *   failure: one clean line naming the file, the arena as it was;
 *   success: the mesh passes silk_mesh_validate (every index consistent),
 *            and the visibility hierarchy builds over it (or fails cleanly). */
static inline void fuzz_load_checked(fuzz_reader_fn load, const char *name, const uint8_t *data, size_t size,
                                     const silk_load_opts *o, uint8_t *mem, size_t arena_size)
{
    uint8_t *own = mem ? NULL : malloc(arena_size);
    if (!mem && !(mem = own)) return;
    silk_arena a;
    silk_mesh m;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_arena_init(&a, mem, arena_size);
    silk_status st = load(data, size, name, o, &a, &m, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, name);
        fuzz_check_arena_empty(&a);
    } else {
        fuzz_expect(a.top == 0, "loading left %zu bytes of scratch", a.top);
        silk_status v = silk_mesh_validate(&m, name, &err);
        fuzz_expect(v == SILK_OK, "the loaded mesh is inconsistent: %s", err.msg);
        size_t bottom = a.bottom;
        st = silk_vis_build(&m, NULL, &a, &err);
        if (st != SILK_OK) {
            fuzz_check_error(st, &err, NULL);
            fuzz_expect(a.bottom == bottom && a.top == 0, "failed hierarchy build kept memory");
        } else {
            v = silk_mesh_validate(&m, name, &err);
            fuzz_expect(v == SILK_OK, "the mesh is inconsistent after the hierarchy: %s", err.msg);
        }
    }
    free(own);
}

/* A reader harness: the input loaded twice, with the default options into
 * an arena of 64 bytes per input byte (so the out-of-memory paths run for
 * dense files), and with file normals, a --scale and a crease angle taken
 * from its length into a roomy one. */
static inline void fuzz_reader(fuzz_reader_fn load, const char *name, const uint8_t *data, size_t size)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    fuzz_load_checked(load, name, data, size, &o, NULL, 64 * size + 4096);

    /* The other options, chosen by the length so that one input covers both. */
    o.normals = SILK_NORMALS_FILE;
    o.crease_deg = SILK_FX_C((int64_t)(size % 181), 1);
    o.scale.mant = (int64_t)(size % 7) + 1;
    o.scale.exp10 = (int32_t)(size % 5) - 2;
    /* the roomy arena is kept between runs: a fresh 4 MB block per run costs
     * more than the load */
    static uint8_t roomy[(size_t)1 << 22];
    fuzz_load_checked(load, name, data, size, &o, roomy, sizeof roomy);
}

/* A prepared model's file size, section checksums and table checksum made
 * right in place (the fuzz_model and fuzz_siltex harnesses), so that the
 * checks behind the checksums are reached. */
static inline uint32_t fuzz_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline void fuzz_wr32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}
static inline void fuzz_model_fix(uint8_t *b, size_t size)
{
    if (size < SILK_MODEL_HEADER_BYTES) return;
    fuzz_wr32(b + 16, (uint32_t)size);
    uint32_t n = fuzz_rd32(b + 20);
    if (n >= 1 && n <= SILK_MODEL_MAX_SECTIONS &&
        SILK_MODEL_HEADER_BYTES + (size_t)n * SILK_MODEL_ENTRY_BYTES <= size) {
        for (uint32_t i = 0; i < n; i++) {
            uint8_t *e = b + SILK_MODEL_HEADER_BYTES + (size_t)i * SILK_MODEL_ENTRY_BYTES;
            uint32_t off = fuzz_rd32(e + 8), len = fuzz_rd32(e + 12);
            if (off <= size && len <= size - off) fuzz_wr32(e + 16, silk_crc32(0, b + off, len));
        }
        fuzz_wr32(b + 24, silk_crc32(0, b + SILK_MODEL_HEADER_BYTES, (size_t)n * SILK_MODEL_ENTRY_BYTES));
    }
}

/* Points cam at the centre of m's box; returns a distance from which the
 * whole box is in view (three times its largest side, at least 1). */
static inline silk_fx fuzz_aim(const silk_mesh *m, silk_camera *cam)
{
    silk_vec3 lo = m->bbox_min, hi = m->bbox_max;
    cam->target = silk_v3((silk_fx)(((int64_t)lo.x + hi.x) / 2), (silk_fx)(((int64_t)lo.y + hi.y) / 2),
                          (silk_fx)(((int64_t)lo.z + hi.z) / 2));
    silk_fx d = silk_fx_max(silk_fx_max(silk_fx_sub(hi.x, lo.x), silk_fx_sub(hi.y, lo.y)), silk_fx_sub(hi.z, lo.z));
    return silk_fx_max(silk_fx_mul(d, 3 * SILK_FX_ONE), SILK_FX_ONE);
}

#endif
