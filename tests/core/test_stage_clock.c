/*
 * test_stage_clock.c - the optional per-stage timing of a frame
 * (silk_stage_clock, include/silk/render.h).
 *
 * The clock here counts its own reads, so every timed piece with no read
 * nested inside it takes exactly one tick: the ticks say which pieces were
 * timed and that nothing is counted twice.  The frames drawn with the clock
 * must be the frames drawn without it, byte for byte.
 */
#include <stdlib.h>
#include "check.h"
#include "silk/silk.h"
#include "support/scene.h"
#include "support/testframe.h"

static uint32_t count_reads(void *user)
{
    uint32_t *n = user;
    return ++*n;
}

TEST(stages_are_timed_and_pixels_unchanged)
{
    enum { W = 160, H = 128, ROWS = 8 };
    static uint8_t arena_mem[1 << 20];
    static uint8_t plain[W * H * 2], timed[W * H * 2];
    silk_arena a;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 16, 10, 1.0, 0, 0, 0);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    const double dir[3] = { 0.3, 0.4, 1.0 };
    silk_view v;
    CHECK(tf_view_around_size(&m, dir, 3, 0, W, H, &v));
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    for (int mode = 0; mode < 2; mode++) {
        silk_render_opts o;
        silk_render_opts_default(&o);
        CHECK(o.clock == NULL);
        o.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
        silk_frame_stats st;
        tf_collect c = { plain, 0, 0, 0, 0, 0 };
        CHECK(tf_render_bands(&a, &m, &v, &hal, &o, SILK_PIX_RGB565, ROWS, &c, &st, &err) == SILK_OK);
        CHECK(!st.fell_back);

        uint32_t reads = 0;
        silk_stage_clock clock = { count_reads, &reads, { 0 }, { 0 } };
        o.clock = &clock;
        c.frame = timed;
        CHECK(tf_render_bands(&a, &m, &v, &hal, &o, SILK_PIX_RGB565, ROWS, &c, &st, &err) == SILK_OK);
        CHECKF(memcmp(plain, timed, sizeof plain) == 0, "%s: the timed frame differs", silk_mode_name(o.mode));

        uint32_t pieces = 0;
        for (int s = 0; s < SILK_STAGE_COUNT; s++) pieces += clock.pieces[s];
        CHECKF(reads == 2 * pieces, "%u reads for %u pieces", reads, pieces);
        /* the visibility test and the plan once, in SMOOTH mode only; the
         * plan's time excludes the visibility test's, whose two reads it holds */
        CHECK(clock.pieces[SILK_STAGE_VISIBILITY] == (uint32_t)mode && clock.pieces[SILK_STAGE_PLAN] == (uint32_t)mode);
        CHECK(clock.ticks[SILK_STAGE_VISIBILITY] == (uint32_t)mode && clock.ticks[SILK_STAGE_PLAN] == 2u * mode);
        /* every share emitted is put through the vertex stage; a band's
         * clear and every share drawn into it are rasterizer pieces */
        CHECK(clock.pieces[SILK_STAGE_EMIT] >= m.ntris && clock.pieces[SILK_STAGE_EMIT] == clock.pieces[SILK_STAGE_VERTEX]);
        CHECK(clock.pieces[SILK_STAGE_RASTER] > (H + ROWS - 1) / ROWS);
        for (int s = SILK_STAGE_EMIT; s < SILK_STAGE_COUNT; s++)
            CHECKF(clock.ticks[s] == clock.pieces[s], "%s: %u ticks in %u pieces", silk_stage_name((silk_stage)s),
                   clock.ticks[s], clock.pieces[s]);
    }
    CHECK(strcmp(silk_stage_name(SILK_STAGE_RASTER), "raster") == 0 && strcmp(silk_stage_name(SILK_STAGE_COUNT), "?") == 0);
}

int main(void)
{
    RUN(stages_are_timed_and_pixels_unchanged);
    return check_done();
}
