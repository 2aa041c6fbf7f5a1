/*
 * fw_soak.c - the firmware's soak run: the packed model (fwmodel.h, as
 * fw_main.c draws it) rendered frame after frame along a random camera
 * path, FLAT and SMOOTH, in the board's bands, for as long as the command
 * line asks: what a device that shows a turning model for hours does.
 *
 * Command line: PROGRAM FRAMES [SEED].  The path starts at the packed
 * camera 0 and walks: each frame the eye turns 0 to 20 degrees further
 * around the target, its elevation moves by up to 6 degrees (kept within
 * 70 of the horizon) and its distance by up to 4% (kept between 1 and 1.5
 * times camera 0's), all in fixed point from a xorshift generator, so the
 * board and the host build walk the same path to the bit.  One report line
 * per frame,
 *   fw soak frame=K mode=M crc=X peak=N fell_back=0|1 kept=N
 * (the frame's checksum as fw_main.c takes it, the arena's high-water mark
 * in the frame, and the bytes the arena held after it: the band buffers
 * only, or something leaked), then
 *   fw soak frames=N flat_peak=N smooth_peak=N fell_back=N leaked=N crc=X
 *   fw result=ok|error
 * where crc combines every frame's.  tests/boards/cli_soak.sh compares a
 * board's run with the host build's line by line.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "silk/silk.h"
#include "silk/validate.h"
#include "fw_io.h"
#include "fw_say.h"
#include "fwmodel.h"


static uint8_t arena_mem[FW_ARENA_BYTES] __attribute__((aligned(SILK_ARENA_ALIGN)));

/* FNV-1a over the frame's pixels as rendered, band by band. */
static int checksum_band(void *user, const silk_target *t)
{
    uint32_t *crc = user;
    size_t n = (size_t)t->width * silk_pixfmt_bytes(t->fmt);
    for (int y = 0; y < t->rows; y++) {
        const uint8_t *row = t->color + (size_t)y * t->stride;
        for (size_t i = 0; i < n; i++) *crc = (*crc ^ row[i]) * 16777619u;
    }
    return 0;
}

static uint32_t rng_next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

/* A step in [-range, range] of Q16.16. */
static silk_fx rng_step(uint32_t *s, silk_fx range)
{
    return (silk_fx)((int64_t)(rng_next(s) % 65537u) * 2 * range / 65536 - range);
}

static silk_fx clamp_fx(silk_fx v, silk_fx lo, silk_fx hi) { return v < lo ? lo : v > hi ? hi : v; }

/* The path: azimuth and elevation in degrees, distance as a factor of
 * camera 0's, all Q16.16. */
typedef struct path {
    uint32_t rng;
    silk_fx az, el, dist;
} path;

static void path_step(path *p)
{
    p->az += (silk_fx)(rng_next(&p->rng) % (20u * 65536u));
    if (p->az >= SILK_FX_C(360, 1)) p->az -= SILK_FX_C(360, 1);
    p->el = clamp_fx(p->el + rng_step(&p->rng, SILK_FX_C(6, 1)), SILK_FX_C(-70, 1), SILK_FX_C(70, 1));
    p->dist = clamp_fx(p->dist + rng_step(&p->rng, SILK_FX_C(4, 100)), SILK_FX_ONE, SILK_FX_C(15, 10));
}

/* Camera 0 moved to the path's point: the eye at az, el around the target
 * (y up), dist times as far; the far plane as much further. */
static silk_camera path_camera(const silk_camera *c0, const path *p)
{
    silk_camera c = *c0;
    silk_vec3 d = silk_v3_sub(c0->eye, c0->target);
    silk_fx r = silk_fx_mul(silk_v3_length(d), p->dist), sa, ca, se, ce;
    silk_fx_sincos_deg(p->az, &sa, &ca);
    silk_fx_sincos_deg(p->el, &se, &ce);
    silk_vec3 dir = silk_v3(silk_fx_mul(ce, sa), se, silk_fx_mul(ce, ca));
    c.eye = silk_v3_add(c0->target, silk_v3_scale(dir, r));
    c.up = silk_v3(0, SILK_FX_ONE, 0);
    c.zfar = silk_fx_mul(c0->zfar, p->dist) + (c0->zfar >> 4);
    return c;
}

/* The number of frames and the seed from "PROGRAM FRAMES [SEED]". */
static void arguments(long *frames, uint32_t *seed)
{
    char cmd[160];
    fw_cmdline(cmd, sizeof cmd);
    char *p = strchr(cmd, ' ');
    *frames = p ? strtol(p, &p, 10) : 0;
    long s = p && *p ? strtol(p, NULL, 10) : 0;
    *seed = s > 0 ? (uint32_t)s : 2463534242u;
}

int fw_scene(void)
{
    long frames;
    uint32_t seed;
    arguments(&frames, &seed);
    silk_mesh mesh;
    fwmodel_mesh(&mesh);
    const silk_camera *c0 = fwmodel_camera(0);
    silk_error err;
    if (!c0 || silk_mesh_validate(&mesh, "fwmodel", &err) != SILK_OK) {
        say("fw error %s", c0 ? err.msg : "the model has no camera");
        say("fw result=error");
        return 1;
    }
    if (frames < 1) {
        say("fw error give the number of frames: PROGRAM FRAMES [SEED]");
        say("fw result=error");
        return 1;
    }
    say("fw soak board=%s size=%dx%d band_rows=%d frames=%ld seed=%lu", FW_BOARD, c0->width, c0->height,
        FW_BAND_ROWS, frames, (unsigned long)seed);

    silk_arena arena;
    silk_arena_init(&arena, arena_mem, sizeof arena_mem);
    int rows = FW_BAND_ROWS < c0->height ? FW_BAND_ROWS : c0->height;
    uint8_t *color = silk_arena_array(&arena, (size_t)rows * (size_t)c0->width, silk_pixfmt_bytes(FW_FORMAT),
                                      SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&arena, (size_t)rows * (size_t)c0->width, sizeof *depth, SILK_MEM_RASTER);
    if (!color || !depth) {
        say("fw error the arena cannot hold a band of %d rows", rows);
        say("fw result=error");
        return 1;
    }
    size_t band_bytes = arena.bottom, peak[2] = { 0, 0 };
    silk_target band;
    silk_target_init(&band, c0->width, c0->height, 0, rows, FW_FORMAT, color, depth);

    path p = { seed, 0, 0, SILK_FX_ONE };
    uint32_t all = 2166136261u;
    long fell = 0, leaked = 0, failed = 0;
    for (long k = 0; k < frames && !failed; k++) {
        silk_camera cam = k ? path_camera(c0, &p) : *c0;
        silk_view view;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) {
            say("fw error frame=%ld %s", k, err.msg);
            failed = 1;
            break;
        }
        silk_phong phong;
        silk_hal hal;
        silk_phong_default(&phong, &view);
        fwmodel_look(&phong);
        silk_hal_phong(&hal, &phong);
        for (int m = 0; m < 2; m++) {
            silk_render_opts ro;
            silk_render_opts_default(&ro);
            ro.mode = m ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
            ro.vertex_cache_bytes = 0;
            uint32_t crc = 2166136261u;
            silk_sink sink = { .band = checksum_band, .user = &crc };
            silk_frame_stats st;
            arena.peak = arena.bottom + arena.top;   /* this frame's high-water mark */
            if (silk_render_bands(&arena, &mesh, &view, &hal, &ro, &band, &sink, &st, &err) != SILK_OK) {
                say("fw error frame=%ld %s", k, err.msg);
                failed = 1;
                break;
            }
            size_t kept = arena.bottom + arena.top;
            if (arena.peak > peak[m]) peak[m] = arena.peak;
            fell += st.fell_back;
            leaked += kept != band_bytes;
            all = (all ^ crc) * 16777619u;
            say("fw soak frame=%ld mode=%s crc=%08lx peak=%lu fell_back=%d kept=%lu", k, m ? "smooth" : "flat",
                (unsigned long)crc, (unsigned long)arena.peak, st.fell_back, (unsigned long)kept);
        }
        path_step(&p);
    }
    say("fw soak frames=%ld flat_peak=%lu smooth_peak=%lu fell_back=%ld leaked=%ld crc=%08lx", frames,
        (unsigned long)peak[0], (unsigned long)peak[1], fell, leaked, (unsigned long)all);
    int ok = !failed && !fell && !leaked;
    say("fw result=%s", ok ? "ok" : "error");
    return ok ? 0 : 1;
}
