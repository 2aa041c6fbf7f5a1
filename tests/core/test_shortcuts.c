/*
 * test_shortcuts.c - the renderer's shortcuts draw the pixels of the plain
 * path, byte for byte (but where a mesh passes through itself).
 *
 * With the default vertex stage silk_render evaluates each corner's vertex
 * once per frame instead of once per triangle (the vertex cache), and on a
 * closed, outward-wound mesh seen from outside it skips the triangles seen
 * from behind in FLAT mode and SMOOTH's re-meshed parts seen wholly from
 * behind (render.c, back_faces_hidden, part_faces_away); and on a 64-bit
 * host the rasterizer shades the default fragment stage's usual case
 * without its per-pixel tests (silk_hal_phong_plain).  Stages of the
 * caller's own take none of these shortcuts, so the same default stages
 * behind wrappers draw the reference.  Shared meshes from views all round, near
 * and far, perspective and orthographic, FLAT and SMOOTH, whole frames and
 * bands; the arena left for the cache from nothing to plenty; the
 * anti-aliased outline with and without its shortcuts (the facing memo, a
 * closed mesh's candidates from its edges); and silk_mesh.closed_outward
 * for closed, open, inside-out and kept meshes.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/scene.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "silk/silk.h"

#define W 160
#define H 120
#define ARENA_BYTES (64u << 20)

static uint8_t *arena_buf;

static void (*default_vertex)(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out);
static uint32_t (*default_fragment)(const silk_hal *h, const silk_fx *var);

/* The default stage, but not known to be: no shortcut applies. */
static void wrapped_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out)
{
    default_vertex(h, g, r, out);
}

static uint32_t wrapped_fragment(const silk_hal *h, const silk_fx *var)
{
    return default_fragment(h, var);
}

/* One frame into rgb (W x H x 3) in bands of `rows`, with the default
 * stages or (plain) the wrapped ones, anti-aliased outlines (aa) and the
 * vertex cache's budget as given; fragment writes summed into *writes
 * when not NULL (whole frames only). */
static int draw_with(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_mode mode, int plain, int rows,
                     int aa, size_t cache_bytes, uint8_t *rgb, long *writes)
{
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, v);
    silk_hal_phong(&hal, &ph);
    default_vertex = hal.vertex;
    default_fragment = hal.fragment;
    if (plain) hal.vertex = wrapped_vertex, hal.fragment = wrapped_fragment;
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = mode;
    o.aa = aa;
    o.vertex_cache_bytes = cache_bytes;
    silk_frame_stats st;
    silk_error err;
    silk_status s;
    if (writes) {
        uint32_t *depth = malloc((size_t)W * H * sizeof *depth);
        uint16_t *w = calloc((size_t)W * H, sizeof *w);
        silk_target t;
        silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, rgb, depth);
        t.writes = w;
        s = silk_render(a, m, v, &hal, &o, &t, &st, &err);
        *writes = 0;
        for (long i = 0; i < (long)W * H; i++) *writes += w[i];
        free(depth);
        free(w);
    } else {
        tf_collect c = { .frame = rgb };
        s = tf_render_bands(a, m, v, &hal, &o, SILK_PIX_RGB888, rows, &c, &st, &err);
    }
    if (s != SILK_OK) fprintf(stderr, "render: %s\n", err.msg);
    return s == SILK_OK && !st.fell_back;
}

/* Without the outline (it takes arena too, and with too little leaves pixels aliased). */
static int draw(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_mode mode, int plain, int rows,
                uint8_t *rgb, long *writes)
{
    return draw_with(a, m, v, mode, plain, rows, 0, SIZE_MAX, rgb, writes);
}

static long differ(const uint8_t *a, const uint8_t *b)
{
    long n = 0;
    for (long i = 0; i < (long)W * H; i++) n += memcmp(a + 3 * i, b + 3 * i, 3) != 0;
    return n;
}

TEST(shortcuts_draw_the_plain_pixels)
{
    /* cow-500 passes through itself at the legs (edges of some triangles
     * pierce others): there a back face can be the nearest surface, and
     * skipping it shows the front face behind it, a few pixels a frame. */
    static const struct { const char *name; long may_differ; } meshes[] = {
        { "bunny-500.obj", 0 }, { "sphere-200.obj", 0 }, { "knot-480.obj", 0 }, { "torus-576.obj", 0 },
        { "fandisk-128.obj", 0 }, { "cow-500.obj", 16 } };
    static const double dirs[][3] = { { 1, 0.4, 0.8 }, { -1, -0.3, 0.2 }, { 0.1, 1, 0.2 }, { 0.3, -1, -0.5 },
                                      { -0.4, 0.2, -1 } };
    static const double dists[] = { 3, 1.6, 0.7 };   /* the last puts the near plane into the mesh */
    uint8_t *fast = malloc((size_t)W * H * 3), *plain = malloc((size_t)W * H * 3);
    long cases = 0, bad = 0;
    for (size_t i = 0; i < sizeof meshes / sizeof *meshes; i++) {
        silk_arena a;
        silk_arena_init(&a, arena_buf, ARENA_BYTES);
        silk_mesh m;
        if (!tm_load_shared(&a, meshes[i].name, &m)) {
            CHECK(check_cur_skipped);
            break;
        }
        for (size_t d = 0; d < sizeof dirs / sizeof *dirs; d++)
            for (size_t k = 0; k < sizeof dists / sizeof *dists; k++)
                for (int ortho = 0; ortho < 2; ortho++) {
                    silk_view v;
                    CHECK(tf_view_around_size(&m, dirs[d], dists[k], ortho, W, H, &v));
                    for (int mode = 0; mode < 2; mode++) {
                        int rows = (d + k) % 2 ? 16 : H;
                        silk_mode md = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                        CHECK(draw(&a, &m, &v, md, 0, rows, fast, NULL));
                        CHECK(draw(&a, &m, &v, md, 1, rows, plain, NULL));
                        long n = differ(fast, plain);
                        cases++;
                        bad += n != 0;
                        CHECKF(n <= meshes[i].may_differ, "%s dir %zu dist %g %s %s: %ld pixels differ",
                               meshes[i].name, d, dists[k],
                               ortho ? "ortho" : "persp", silk_mode_name(md), n);
                    }
                }
    }
    printf("  %ld frames, %ld differ\n", cases, bad);
    free(fast);
    free(plain);
}

/* The anti-aliased outline's shortcuts under the vertex cache's budget
 * (the facing memo; in a FLAT frame of a closed mesh the candidates found
 * once a frame from the edges, aa.c silk_aa_candidates) and the FLAT
 * triangles drawn straight from the cache: the pixels of a frame without
 * them (budget 0) and of one through the wrapped stage (aa.c place), FLAT and SMOOTH, whole frames and bands, outlines with
 * and without creases, closed meshes and an open one. */
TEST(outline_shortcuts_draw_the_plain_pixels)
{
    static const char *meshes[] = { "bunny-500.obj", "fandisk-128.obj", "knot-480.obj", "cone-70.obj" };
    static const double dirs[][3] = { { 1, 0.4, 0.8 }, { -0.4, 0.2, -1 }, { 0.3, -1, -0.5 } };
    static const double dists[] = { 3, 0.7 };
    uint8_t *fast = malloc((size_t)W * H * 3), *plain = malloc((size_t)W * H * 3);
    long cases = 0, open = 0;
    /* the shared meshes, then a sphere with a hole, whose inside shows */
    ts_mesh hole = { 0 };
    ts_sphere(&hole, 16, 10, 1, 0, 0, 0);
    hole.nf -= 6;
    tm_fixture fx;
    tm_fixture_init(&fx, 8u << 20);
    for (size_t i = 0; i <= sizeof meshes / sizeof *meshes; i++) {
        silk_arena a;
        silk_mesh m;
        if (i == sizeof meshes / sizeof *meshes) {
            if (!tm_fixture_input(&fx, hole.v, hole.nv, hole.f, hole.nf) || tm_fixture_build(&fx) != SILK_OK) {
                CHECK(0);
                break;
            }
            a = fx.a;
            m = fx.m;
        } else {
            silk_arena_init(&a, arena_buf, ARENA_BYTES);
            if (!tm_load_shared(&a, meshes[i], &m)) {
                CHECK(check_cur_skipped);
                continue;
            }
        }
        open += !m.closed_outward;
        for (size_t d = 0; d < sizeof dirs / sizeof *dirs; d++)
            for (size_t k = 0; k < sizeof dists / sizeof *dists; k++) {
                silk_view v;
                CHECK(tf_view_around_size(&m, dirs[d], dists[k], 0, W, H, &v));
                for (int mode = 0; mode < 2; mode++) {
                    int rows = (d + k + mode) % 2 ? 16 : H, aa = 1 + (int)(d == 1);   /* 2: no creases */
                    silk_mode md = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                    CHECK(draw_with(&a, &m, &v, md, 0, rows, aa, SIZE_MAX, fast, NULL));
                    CHECK(draw_with(&a, &m, &v, md, 0, rows, aa, 0, plain, NULL));
                    long n = differ(fast, plain);
                    /* and the wrapped stage's, whose curve points are not placed from their positions alone */
                    CHECK(draw_with(&a, &m, &v, md, 1, rows, aa, SIZE_MAX, plain, NULL));
                    n += differ(fast, plain);
                    cases++;
                    CHECKF(n == 0, "%s dir %zu dist %g %s: %ld pixels differ",
                           i < sizeof meshes / sizeof *meshes ? meshes[i] : "open sphere", d, dists[k],
                           silk_mode_name(md), n);
                }
            }
    }
    printf("  %ld frames, %ld of them of an open mesh\n", cases, open * 12);
    CHECK(open == 1);
    tm_fixture_free(&fx);
    ts_mesh_free(&hole);
    free(fast);
    free(plain);
}

/* A shared mesh in the arena over arena_buf and a perspective view of it
 * from dir at dist times its size; 0 (the test skipped or failed) when not. */
static int mesh_and_view(silk_arena *a, const char *name, const double dir[3], double dist, silk_mesh *m,
                         silk_view *v)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    if (!tm_load_shared(a, name, m)) {
        CHECK(check_cur_skipped);
        return 0;
    }
    CHECK(tf_view_around_size(m, dir, dist, 0, W, H, v));
    return 1;
}

/* FLAT on a closed mesh seen from outside writes fewer fragments (the back
 * faces drawn before the front faces that hide them are skipped), with the
 * same picture. */
TEST(back_faces_are_skipped)
{
    silk_arena a;
    silk_mesh m;
    silk_view v;
    const double dir[3] = { 1, 0.5, 0.7 };
    if (!mesh_and_view(&a, "sphere-200.obj", dir, 3, &m, &v)) return;
    CHECK(m.closed_outward == 1);
    uint8_t *fast = malloc((size_t)W * H * 3), *plain = malloc((size_t)W * H * 3);
    long wf = 0, wp = 0;
    CHECK(draw(&a, &m, &v, SILK_MODE_FLAT, 0, H, fast, &wf));
    CHECK(draw(&a, &m, &v, SILK_MODE_FLAT, 1, H, plain, &wp));
    CHECK(differ(fast, plain) == 0);
    CHECKF(wf > 0 && wf < wp, "%ld fragment writes with the shortcut, %ld without", wf, wp);
    free(fast);
    free(plain);
}

/* SMOOTH whole frames with a depth pass: the shading pass skips the
 * triangles that wrote no depth in it (render.c, depth_wins) under the
 * vertex cache's budget.  The pixels of frames without (budget 0), meshes
 * closed and open (cone-70), from all round, near and far, perspective
 * and orthographic, with and without the outline; and never more
 * fragments written (fewer where a skipped triangle met the depth of one
 * that overwrote it). */
TEST(unshaded_triangles_are_skipped)
{
    static const char *meshes[] = { "bunny-500.obj", "sphere-200.obj", "knot-480.obj", "torus-576.obj",
                                    "fandisk-128.obj", "cow-500.obj", "cone-70.obj" };
    static const double dirs[][3] = { { 1, 0.4, 0.8 }, { -1, -0.3, 0.2 }, { 0.1, 1, 0.2 }, { 0.3, -1, -0.5 },
                                      { -0.4, 0.2, -1 } };
    static const double dists[] = { 3, 1.6, 0.7 };
    uint8_t *fast = malloc((size_t)W * H * 3), *plain = malloc((size_t)W * H * 3);
    long cases = 0, fewer = 0;
    for (size_t i = 0; i < sizeof meshes / sizeof *meshes; i++) {
        silk_arena a;
        silk_mesh m;
        silk_view v;
        if (!mesh_and_view(&a, meshes[i], dirs[0], 3, &m, &v)) break;
        for (size_t d = 0; d < sizeof dirs / sizeof *dirs; d++)
            for (size_t k = 0; k < sizeof dists / sizeof *dists; k++)
                for (int ortho = 0; ortho < 2; ortho++) {
                    CHECK(tf_view_around_size(&m, dirs[d], dists[k], ortho, W, H, &v));
                    int aa = (int)((d + k) % 3);   /* none, with creases, without */
                    long wf = 0, wp = 0;
                    CHECK(draw_with(&a, &m, &v, SILK_MODE_SMOOTH, 0, H, aa, SIZE_MAX, fast, aa ? NULL : &wf));
                    CHECK(draw_with(&a, &m, &v, SILK_MODE_SMOOTH, 0, H, aa, 0, plain, aa ? NULL : &wp));
                    long n = differ(fast, plain);
                    cases++;
                    fewer += wf < wp;
                    CHECKF(n == 0 && wf <= wp, "%s dir %zu dist %g %s: %ld pixels differ, %ld writes against %ld",
                           meshes[i], d, dists[k], ortho ? "ortho" : "persp", n, wf, wp);
                }
    }
    printf("  %ld frames, %ld with fewer fragments written\n", cases, fewer);
    CHECK(check_cur_skipped || !SILK_DEPTH_WINS || fewer > 0);   /* (a build without it: the same pixels) */
    free(fast);
    free(plain);
}

/* The cache takes half of what the arena has left, down to none: the
 * pictures stay the same. */
TEST(cache_sized_by_the_arena)
{
    silk_arena big;
    silk_mesh m;
    silk_view v;
    const double dir[3] = { -0.6, 0.3, 1 };
    if (!mesh_and_view(&big, "bunny-500.obj", dir, 2.5, &m, &v)) return;
    uint8_t *ref = malloc((size_t)W * H * 3), *img = malloc((size_t)W * H * 3);
    CHECK(draw(&big, &m, &v, SILK_MODE_FLAT, 1, H, ref, NULL));
    static const size_t rooms[] = { 0, 2048, 8192, 40000, 1u << 20 };
    size_t frame = 4096;   /* FLAT share by share: three records and their outputs, rounded up */
    long writes;
    for (size_t i = 0; i < sizeof rooms / sizeof *rooms; i++) {
        silk_arena small;
        size_t bytes = frame + rooms[i];
        uint8_t *mem = malloc(bytes);
        silk_arena_init(&small, mem, bytes);
        CHECKF(draw(&small, &m, &v, SILK_MODE_FLAT, 0, H, img, &writes), "%zu bytes", bytes);
        CHECKF(differ(ref, img) == 0, "with %zu bytes: %ld pixels differ", bytes, differ(ref, img));
        free(mem);
    }
    free(ref);
    free(img);
}

static int closed_outward(const ts_mesh *tm, silk_orient_mode orient)
{
    tm_fixture f;
    tm_fixture_init(&f, 4u << 20);
    f.opts.orient = orient;
    int r = -1;
    if (tm_fixture_input(&f, tm->v, tm->nv, tm->f, tm->nf) && tm_fixture_build(&f) == SILK_OK)
        r = f.m.closed_outward;
    tm_fixture_free(&f);
    return r;
}

TEST(closed_outward_flag)
{
    ts_mesh s = { 0 };
    ts_sphere(&s, 12, 8, 1, 0, 0, 0);
    CHECK(closed_outward(&s, SILK_ORIENT_FIX) == 1);
    CHECK(closed_outward(&s, SILK_ORIENT_KEEP) == 0);        /* winding not checked: not known */
    for (uint32_t t = 0; t < s.nf; t++) {                     /* inside out: turned round at load */
        uint32_t c = s.f[3 * t + 1];
        s.f[3 * t + 1] = s.f[3 * t + 2];
        s.f[3 * t + 2] = c;
    }
    CHECK(closed_outward(&s, SILK_ORIENT_FIX) == 1);
    s.nf--;                                                   /* a hole: open */
    CHECK(closed_outward(&s, SILK_ORIENT_FIX) == 0);
    ts_mesh_free(&s);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    RUN(closed_outward_flag);
    RUN(shortcuts_draw_the_plain_pixels);
    RUN(outline_shortcuts_draw_the_plain_pixels);
    RUN(back_faces_are_skipped);
    RUN(unshaded_triangles_are_skipped);
    RUN(cache_sized_by_the_arena);
    free(arena_buf);
    return check_done();
}
