/*
 * test_budget.c - silk_budget_frame(), the arena a frame takes at most.
 *
 * For meshes with and without feature edges (generated sphere, torus, cone
 * and cylinder; the shared bunny-500, knot-480, fandisk-128 and bunny-2k
 * when they are there), FLAT and SMOOTH, without anti-aliasing, with the
 * outline's (as the boards draw it) and with creases too (whole frames),
 * in bands of 1, 8 and 240 rows, from the 14 directions of a
 * cube's corners and faces (a third of them under the sanitizers, SILK_SAN=1)
 * at two distances (the model framed, and close
 * enough to reach past the frame) and orthographic: an arena of exactly the budget's bytes (the band
 * buffers at its bottom, the mesh elsewhere, as in flash) must draw the
 * frame the same as a roomy full-frame render, byte for byte, without
 * falling back and without an outline pixel left aliased; the frame's own
 * report (frame_bytes) and the arena's high-water mark must be within the
 * budget.  Given exactly the bytes it reported needing (frame_bytes), a
 * frame is drawn the same again and reports the same, which is then the
 * arena's high-water mark: its true peak; 8 bytes fewer and it cannot be.
 * How far above the worst frame the bound lies is printed, not checked.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "tools/prep/gen.h"
#include "silk/silk.h"

#define W 320
#define H 240

static uint8_t *roomy;          /* the reference's arena */
#define ROOMY_BYTES (16u << 20)
static uint8_t ref[W * H * 2], got[W * H * 2];

typedef struct collect {
    uint8_t *frame;
} collect;

static int take(void *user, const silk_target *t)
{
    collect *c = user;
    for (int y = 0; y < t->rows; y++)
        memcpy(c->frame + (size_t)(t->y0 + y) * W * 2, t->color + (size_t)y * t->stride, (size_t)W * 2);
    return 0;
}

typedef struct tally {
    size_t worst_need, bound;   /* the largest frame_bytes seen, and the bound then */
    int frames;
} tally;

/* One frame of m from view v: the reference, then in an arena of exactly
 * the budget; for a third of the views then in exactly what that frame
 * reported needing, with the boards' options and the default ones, then
 * in 8 bytes fewer. */
static void check_frame(const silk_mesh *m, const silk_view *v, silk_mode mode, int aa, int rows, const char *what,
                        tally *tl)
{
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;
    ro.aa = aa;
    silk_error err;

    silk_arena a;
    silk_arena_init(&a, roomy, ROOMY_BYTES);
    uint8_t *color = silk_arena_alloc(&a, sizeof ref, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&a, (size_t)W * H, sizeof *depth, SILK_MEM_RASTER);
    silk_target full;
    silk_target_init(&full, W, H, 0, H, SILK_PIX_RGB565, color, depth);
    silk_frame_stats fs;
    if (silk_render(&a, m, v, &hal, &ro, &full, &fs, &err) != SILK_OK || fs.fell_back || fs.aa_aliased) {
        CHECKF(0, "%s: the reference frame: %s", what, err.msg);
        return;
    }
    memcpy(ref, color, sizeof ref);

    silk_budget b;
    CHECKF(silk_budget_frame(m, &ro, W, H, rows, SILK_PIX_RGB565, 0, &b, &err) == SILK_OK, "%s", err.msg);
    /* 0: in the bound, the boards' options; 1: in exactly the bytes run 0
     * reported, the same; 2: the same with the vertex cache's default
     * budget; 3: 8 bytes fewer than that */
    size_t need = 0;
    for (int run = 0; run < 4; run++) {
        size_t bytes = run == 0 ? b.total : run == 3 ? b.bands + need - 8 : b.bands + need;
        ro.vertex_cache_bytes = run == 2 ? SIZE_MAX : 0;
        uint8_t *buf = malloc(bytes + SILK_ARENA_ALIGN);
        if (!buf) return;
        silk_arena fa;
        silk_arena_init(&fa, buf, bytes);
        int r = rows < H ? rows : H;
        uint8_t *bc = silk_arena_alloc(&fa, (size_t)W * r * 2, SILK_MEM_RASTER);
        uint32_t *bd = silk_arena_array(&fa, (size_t)W * r, sizeof *bd, SILK_MEM_RASTER);
        CHECKF(bc && bd && fa.bottom == b.bands, "%s: band buffers %zu bytes, the budget says %zu", what, fa.bottom,
               b.bands);
        if (!bc || !bd) {
            free(buf);
            return;
        }
        silk_target band;
        silk_target_init(&band, W, H, 0, r, SILK_PIX_RGB565, bc, bd);
        collect c = { got };
        silk_sink sink = { .band = take, .user = &c };
        silk_frame_stats st;
        memset(got, 0, sizeof got);
        silk_status s = silk_render_bands(&fa, m, v, &hal, &ro, &band, &sink, &st, &err);
        /* 8 bytes short of a frame that takes nothing it could do without
         * (a flat frame with no outline to anti-alias: a board's without
         * SILK_AA) is refused, not drawn short */
        if (run == 3 && s == SILK_ERR_NOMEM) {
            free(buf);
            break;
        }
        CHECKF(s == SILK_OK, "%s: %s", what, err.msg);
        size_t diff = 0;
        for (size_t i = 0; i < sizeof ref; i++) diff += got[i] != ref[i];
        if (run == 3) {   /* the need is exact: with less, something the frame took is missing */
            CHECKF(st.fell_back || st.aa_aliased || st.frame_bytes < need, "%s: %zu bytes fewer than it reported "
                   "needing, and the frame is the same (%zu bytes)", what, (size_t)8, st.frame_bytes);
        } else {
            CHECKF(!st.fell_back && !st.aa_aliased, "%s, run %d: in %zu bytes it fell back (%d) or left %u pixels "
                   "aliased", what, run, bytes, st.fell_back, st.aa_aliased);
            CHECKF(diff == 0, "%s, run %d: in %zu bytes of arena, %zu bytes differ from the roomy frame", what, run,
                   bytes, diff);
        }
        if (run == 0) {
            need = st.frame_bytes;
            CHECKF(need <= b.frame && fa.peak <= b.total, "%s: needed %zu (peak %zu), the bound says %zu", what,
                   need, fa.peak, b.frame);
            tl->frames++;
            if (need > tl->worst_need || (need == tl->worst_need && b.frame < tl->bound)) {
                tl->worst_need = need;
                tl->bound = b.frame;
            }
        } else if (run == 1) {   /* and it reports the same, which was its true peak */
            CHECKF(st.frame_bytes == need && fa.peak == b.bands + need, "%s: in exactly its need %zu it reports %zu, "
                   "peak %zu", what, need, st.frame_bytes, fa.peak - b.bands);
        }
        free(buf);
        if (run == 0 && (need < 16 || tl->frames % 3 != 1)) break;   /* the exact runs for a third of the views */
    }
}

/* 14 directions around the model (the cube's corners and faces), framed
 * and half of them close, and two orthographic views. */
static const char *aa_name(int aa)
{
    return aa == 1 ? " aa" : aa ? " aa outline" : "";
}

static void check_mesh(const silk_mesh *m, const char *name)
{
    const int san = getenv("SILK_SAN") != NULL;   /* the sanitizers' run: fewer views, the same checks */
    static const int modes[][3] = {   /* mode, aa, rows */
        { SILK_MODE_SMOOTH, 0, 8 }, { SILK_MODE_SMOOTH, 2, 1 }, { SILK_MODE_FLAT, 0, 8 }, { SILK_MODE_FLAT, 1, 240 },
        { SILK_MODE_SMOOTH, 1, 240 },
    };
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++) {
        tally tl = { 0, 0, 0 };
        int n = 0, ndir = 0;
        for (int x = -1; x <= 1; x++)
            for (int y = -1; y <= 1; y++)
                for (int z = -1; z <= 1; z++) {
                    int axes = (x != 0) + (y != 0) + (z != 0);
                    if (axes == 0 || axes == 2) continue;   /* the cube's corners and faces */
                    if (san && (ndir++ % 3)) continue;      /* under the sanitizers a third of them */
                    const double dir[3] = { x + 0.13, y + 0.07, z };   /* off the axes */
                    for (int near = 0; near < 2; near++) {
                        if (near && (n++ % 2)) continue;   /* half of the close views: the time */
                        silk_view v;
                        if (!tf_view_around_size(m, dir, near ? 1.3 : 2.6, 0, W, H, &v)) continue;
                        char what[160];
                        snprintf(what, sizeof what, "%s %s%s rows %d from %d,%d,%d%s", name,
                                 modes[k][0] == SILK_MODE_SMOOTH ? "smooth" : "flat", aa_name(modes[k][1]),
                                 modes[k][2], x, y, z, near ? " close" : "");
                        check_frame(m, &v, (silk_mode)modes[k][0], modes[k][1], modes[k][2], what, &tl);
                    }
                }
        for (int o = 0; o < 2; o++) {
            const double dir[3] = { o ? -0.4 : 0.9, 0.3, 1 };
            silk_view v;
            if (tf_view_around_size(m, dir, 2.6, 1, W, H, &v))
                check_frame(m, &v, (silk_mode)modes[k][0], modes[k][1], modes[k][2], name, &tl);
        }
        if (tl.worst_need)
            printf("note %s %s%s rows %d: %d frames, the worst needed %zu bytes of frame scratch, the bound %zu (%.1fx)\n",
                   name, modes[k][0] == SILK_MODE_SMOOTH ? "smooth" : "flat", aa_name(modes[k][1]), modes[k][2],
                   tl.frames, tl.worst_need, tl.bound, (double)tl.bound / (double)tl.worst_need);
    }
}

static void check_generated(gen_shape shape, const char *name)
{
    gen_params gp;
    gen_mesh gm;
    gen_defaults(shape, &gp);
    tm_fixture f;
    tm_fixture_init(&f, 8u << 20);
    int ok = gen_build(&gp, &gm) == 0;
    ok = ok && tm_fixture_input(&f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(&f) == SILK_OK;
    if (gm.pos) gen_free(&gm);
    CHECKF(ok, "cannot build the %s", name);
    if (ok) check_mesh(&f.m, name);
    tm_fixture_free(&f);
}

TEST(generated_meshes_draw_in_their_budget)
{
    check_generated(GEN_SPHERE, "sphere");
    check_generated(GEN_TORUS, "torus");
    check_generated(GEN_CONE, "cone");
    check_generated(GEN_CYLINDER, "cylinder");
}

static void check_shared(const char *file)
{
    static uint8_t mem[24u << 20];
    silk_arena a;
    silk_arena_init(&a, mem, sizeof mem);
    silk_mesh m;
    if (!tm_load_shared(&a, file, &m)) {
        CHECKF(0, "cannot load %s", file);
        return;
    }
    check_mesh(&m, file);
}

TEST(shared_meshes_draw_in_their_budget)
{
    check_shared("bunny-500.obj");
    check_shared("knot-480.obj");
    check_shared("fandisk-128.obj");
    check_shared("bunny-2k.obj");
}

/* The budget's parts and its refusals; a frame short of the smooth
 * plan's bytes falls back and says so. */
TEST(budget_parts_and_errors)
{
    tm_fixture f;
    tm_fixture_init(&f, 1u << 20);
    gen_params gp;
    gen_mesh gm;
    gen_defaults(GEN_SPHERE, &gp);
    int ok = gen_build(&gp, &gm) == 0;
    ok = ok && tm_fixture_input(&f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(&f) == SILK_OK;
    if (gm.pos) gen_free(&gm);
    CHECK(ok);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    silk_budget one, two, whole;
    silk_error err;
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 8, SILK_PIX_RGB565, 0, &one, &err) == SILK_OK);
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 8, SILK_PIX_RGB565, 1, &two, &err) == SILK_OK);
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 999, SILK_PIX_RGB565, 0, &whole, &err) == SILK_OK);
    CHECK(one.bands == 320 * 8 * 6 && two.bands == one.bands + 320 * 8 * 2 && two.frame == one.frame);
    CHECK(whole.bands == 320 * 240 * 6 && one.total == one.bands + one.frame);
    ro.mode = SILK_MODE_PN;
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 8, SILK_PIX_RGB565, 0, &one, &err) == SILK_ERR_ARG &&
          strstr(err.msg, "FLAT and SMOOTH"));
    ro.mode = SILK_MODE_SMOOTH;
    ro.wire = 1;
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 8, SILK_PIX_RGB565, 0, &one, &err) == SILK_ERR_ARG);
    ro.wire = 0;
    CHECK(silk_budget_frame(&f.m, &ro, 0, 240, 8, SILK_PIX_RGB565, 0, &one, &err) == SILK_ERR_RANGE);
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 0, SILK_PIX_RGB565, 0, &one, &err) == SILK_ERR_RANGE);
    CHECK(silk_budget_frame(NULL, &ro, 320, 240, 8, SILK_PIX_RGB565, 0, &one, &err) == SILK_ERR_ARG);

    /* A smooth frame in an arena with room for a flat frame only is drawn
     * flat, and its statistics say so: no silent fall-back. */
    ro.mode = SILK_MODE_FLAT;
    ro.aa = 0;
    silk_budget flat;
    CHECK(silk_budget_frame(&f.m, &ro, 320, 240, 8, SILK_PIX_RGB565, 0, &flat, &err) == SILK_OK);
    ro.mode = SILK_MODE_SMOOTH;
    ro.vertex_cache_bytes = 0;
    static uint8_t small[32768];
    silk_arena sa;
    silk_arena_init(&sa, small, flat.total);
    uint8_t *bc = silk_arena_alloc(&sa, 320 * 8 * 2, SILK_MEM_RASTER);
    uint32_t *bd = silk_arena_array(&sa, 320 * 8, sizeof *bd, SILK_MEM_RASTER);
    silk_view v;
    const double dir[3] = { 0.5, 0.3, 1 };
    int viewed = tf_view_around_size(&f.m, dir, 2.6, 0, 320, 240, &v);
    CHECKF(bc && bd && flat.total <= sizeof small && viewed, "%p %p %zu %d", (void *)bc, (void *)bd, flat.total, viewed);
    if (bc && bd) {
        silk_phong ph;
        silk_hal hal;
        silk_phong_default(&ph, &v);
        silk_hal_phong(&hal, &ph);
        silk_target band;
        silk_target_init(&band, 320, 240, 0, 8, SILK_PIX_RGB565, bc, bd);
        collect c = { got };
        silk_sink sink = { .band = take, .user = &c };
        silk_frame_stats st;
        CHECK(silk_render_bands(&sa, &f.m, &v, &hal, &ro, &band, &sink, &st, &err) == SILK_OK);
        CHECKF(st.fell_back == 1 && st.silhouette_tris == 0 && st.tris_drawn == f.m.ntris,
               "fell back %d, %u silhouette triangles, %u drawn", st.fell_back, st.silhouette_tris, st.tris_drawn);
    }
    tm_fixture_free(&f);
}

int main(void)
{
    roomy = malloc(ROOMY_BYTES);
    if (!roomy) return 1;
    RUN(generated_meshes_draw_in_their_budget);
    RUN(shared_meshes_draw_in_their_budget);
    RUN(budget_parts_and_errors);
    free(roomy);
    return check_done();
}
