/*
 * test_stream.c - streamed frames (src/render.c, plan.h STREAM mode):
 * the renderer keeps only the silhouette plan and rebuilds each input
 * triangle's share of a FLAT or SMOOTH frame whenever a band needs it.
 *
 *   - Every share is exactly what the stored frame (silk_frame_smooth)
 *     holds for that input triangle: the same triangles in the same order,
 *     their corners evaluating to the same position, normal and uv bits,
 *     the same "added" flags; shares stay within the plan's maxima, and the
 *     frame's counts (triangles, samples, bridges, moved vertices) agree.
 *     Shared meshes with creases, boundaries, perturbed vertices (torus),
 *     and a sphere with uvs and a uv seam.
 *   - So the pixels agree too: silk_render and silk_render_bands (8-row
 *     bands: only the triangles that reach into a band are rebuilt) against
 *     the stored frame rasterized by hand, FLAT and SMOOTH, with and
 *     without --wire.
 *   - The edge tangents a frame keeps where there is room (none, some,
 *     all) change no pixel and not the frame's need.
 *   - And a smooth frame fits a 64 KiB part: bunny-500 and knot-480 at
 *     320x240 in 8-row bands need at most 43 776 bytes of frame scratch
 *     from 16 views (the mps2-an385 board's arena, 59 136 bytes, less its
 *     15 360 bytes of band buffers), and none falls back.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/testframe.h"
#include "silk/silk.h"
#include "support/testmesh.h"
#include "src/smooth.h"
#include "src/remesh.h"
#include "src/lines.h"

#define ARENA_BYTES (16u << 20)
#define BOARD_FRAME_BYTES 43776u      /* 59136 - 320 * 8 * (2 + 4) */
#define BG 0x40C0A0u

static uint8_t *arena_buf;

static silk_fx d2fx(double v) { return (silk_fx)llround(v * 65536.0); }

/* A shared mesh (or OBJ text) with its visibility hierarchy, as `silk render` loads it. */
static int load(silk_arena *a, const char *name, const char *text, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    silk_error err;
    if (text) {
        silk_load_opts o;
        silk_load_opts_default(&o);
        if (silk_load_obj(text, strlen(text), name, &o, a, m, &err) != SILK_OK) {
            fprintf(stderr, "%s: %s\n", name, err.msg);
            return 0;
        }
    } else if (!tm_load_shared(a, name, m)) {
        return 0;
    }
    if (silk_vis_build(m, NULL, a, &err) != SILK_OK) {
        fprintf(stderr, "%s: %s\n", name, err.msg);
        return 0;
    }
    return 1;
}

/* A sphere with texture coordinates: u around, v up, one seam where u
 * jumps from 1 to 0, so the two sides of a seam edge have different uvs. */
static char *uv_sphere(int segs, int rings)
{
    size_t cap = 64 + (size_t)(segs + 1) * (rings + 1) * 80 + (size_t)segs * rings * 80, n = 0;
    char *s = malloc(cap);
    const double pi = 3.14159265358979323846;
    for (int j = 0; j <= rings; j++)
        for (int i = 0; i < segs; i++) {
            double th = pi * j / rings, ph = 2 * pi * i / segs;
            n += (size_t)snprintf(s + n, cap - n, "v %.6f %.6f %.6f\n", sin(th) * cos(ph), cos(th), -sin(th) * sin(ph));
        }
    for (int j = 0; j <= rings; j++)
        for (int i = 0; i <= segs; i++)
            n += (size_t)snprintf(s + n, cap - n, "vt %.6f %.6f\n", (double)i / segs, 1 - (double)j / rings);
    for (int j = 0; j < rings; j++)
        for (int i = 0; i < segs; i++) {
            int a = j * segs + i, b = j * segs + (i + 1) % segs, c = a + segs, d = b + segs;
            int ta = j * (segs + 1) + i, tb = ta + 1, tc = ta + segs + 1, td = tc + 1;
            if (j > 0)
                n += (size_t)snprintf(s + n, cap - n, "f %d/%d %d/%d %d/%d\n", a + 1, ta + 1, c + 1, tc + 1, d + 1, td + 1);
            if (j < rings - 1)
                n += (size_t)snprintf(s + n, cap - n, "f %d/%d %d/%d %d/%d\n", a + 1, ta + 1, d + 1, td + 1, b + 1, tb + 1);
        }
    return s;
}

/* The bounding-box centre seen from azimuth/elevation (degrees) at `dist`
 * bounding radii, the model filling about two thirds of the height. */
static int make_view(const silk_mesh *m, double az, double el, double dist, int ortho, int w, int h, silk_view *v)
{
    const double deg = 3.14159265358979323846 / 180;
    double c[3], r = tf_bounds(m, c);
    double d[3] = { cos(el * deg) * sin(az * deg), sin(el * deg), cos(el * deg) * cos(az * deg) };
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(d2fx(c[0] + d[0] * dist * r), d2fx(c[1] + d[1] * dist * r), d2fx(c[2] + d[2] * dist * r));
    cam.target = silk_v3(d2fx(c[0]), d2fx(c[1]), d2fx(c[2]));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.ortho = ortho;
    cam.fov_deg = SILK_FX_C(35, 1);
    cam.ortho_half_height = d2fx(r * 1.3);
    cam.znear = d2fx(r * 0.05);
    cam.zfar = d2fx(r * (dist + 4));
    cam.width = w;
    cam.height = h;
    silk_error err;
    return silk_view_init(v, &cam, &err) == SILK_OK;
}

static int same_attr(const silk_vertex_attr *x, const silk_vertex_attr *y)
{
    return x->pos.x == y->pos.x && x->pos.y == y->pos.y && x->pos.z == y->pos.z && x->normal.x == y->normal.x &&
           x->normal.y == y->normal.y && x->normal.z == y->normal.z && x->uv.x == y->uv.x && x->uv.y == y->uv.y;
}

/* ---- shares against the stored frame ------------------------------------------------- */

typedef struct share_stats {
    uint32_t frames, tris, differ, order, over, counts, flags, seg_at, segs;
} share_stats;

static void compare_shares(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tol, share_stats *ss)
{
    silk_arena_mark mk = silk_arena_top_mark(a);
    silk_frame_geom g, part;
    silk_frame_stats st;
    silk_error err;
    memset(&st, 0, sizeof st);
    if (silk_frame_smooth(a, m, v, tol, SILK_VIS_AUTO, &g, &st, &err) != SILK_OK || st.fell_back) {
        CHECKF(0, "stored frame: %s", st.fell_back ? "fell back" : err.msg);
        silk_arena_top_release(a, &mk);
        return;
    }
    silk_sil_frame f;
    silk_sil_cursor cur;
    silk_sil_keep keep;
    keep.room = SIZE_MAX;   /* segments and tangents kept (a build with the shortcuts): the same shares */
    f.keep = &keep;
    if (!silk_frame_smooth_plan(a, m, v, tol, SILK_VIS_AUTO, NULL, &f, &cur, &part)) {
        CHECKF(0, "the stream plan does not fit %u bytes", ARENA_BYTES);
        silk_arena_top_release(a, &mk);
        return;
    }
    silk_frame_stats ps;
    memset(&ps, 0, sizeof ps);
    silk_remesh_stats(&f, &ps);
    if (ps.tris_drawn != st.tris_drawn || ps.samples != st.samples || ps.bridges != st.bridges ||
        ps.moved_vertices != st.moved_vertices || ps.silhouette_tris != st.silhouette_tris)
        ss->counts++;
    silk_geom gs = { m, g.curve, g.offset, NULL };
    uint32_t k = 0;   /* the stored frame's next triangle */
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (f.tri_state[t] & SILK_TS_SIL) {
            /* where the outline (aa.c) finds the segment in the share, from
             * the kept layout: where seg_recs finds it, after a curve per
             * side with points */
            uint32_t rec[3], want[3], curve, sides = 0;
            for (uint32_t j = 0; j < 3; j++) {
                const silk_sil_edge *e = silk_sil_side_edge(&f, t, j);
                sides += e && e->nchain;
            }
            silk_remesh_seg_recs(&f, t, 0, want);
            if (!silk_remesh_seg_at(&f, t, rec, &curve) || memcmp(rec, want, sizeof rec) || curve != sides) ss->seg_at++;
            ss->segs++;
        }
        part.nvrec = part.ntri = part.ncurve = 0;
        silk_remesh_emit_tri(&f, &part, t);
        if (part.nvrec > f.max_recs || part.ntri > f.max_tris || part.ncurve > f.max_curves) ss->over++;
        silk_geom gp = { m, part.curve, part.offset, NULL };
        for (uint32_t i = 0; i < part.ntri; i++, k++) {
            if (k >= g.ntri) { ss->order++; continue; }
            if (part.tri_added[i] != g.tri_added[k]) ss->flags++;
            for (int c = 0; c < 3; c++) {
                silk_vertex_attr x, y;
                silk_vrec_eval(&gs, &g.vrec[g.tri[3 * k + c]], &x);
                silk_vrec_eval(&gp, &part.vrec[part.tri[3 * i + c]], &y);
                if (!same_attr(&x, &y)) ss->differ++;
            }
        }
    }
    if (k != g.ntri) ss->order++;
    ss->tris += k;
    ss->frames++;
    silk_arena_top_release(a, &mk);
}

static void shares_of(const char *name, const char *text, share_stats *ss)
{
    silk_arena a;
    silk_mesh m;
    if (!load(&a, name, text, &m)) { CHECK(0); return; }
    for (int i = 0; i < 12; i++) {
        silk_view v;
        double az = check_uniform(0, 360), el = check_uniform(-60, 60);
        if (!make_view(&m, az, el, 2.2 + check_uniform(0, 3), i % 3 == 2, 320 + 160 * (i & 1), 240 + 120 * (i & 1),
                       &v)) {
            CHECK(0);
            return;
        }
        compare_shares(&a, &m, &v, i & 2 ? SILK_FX_C(1, 4) : SILK_FX_HALF, ss);
    }
}

TEST(shares_are_the_stored_frame)
{
    share_stats ss;
    memset(&ss, 0, sizeof ss);
    const char *names[] = { "bunny-500.obj", "knot-480.obj", "torus-576.obj", "fandisk-128.obj", "cone-70.obj" };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) shares_of(names[i], NULL, &ss);
    char *sphere = uv_sphere(16, 10);
    shares_of("uv-sphere", sphere, &ss);
    free(sphere);
    printf("  %u frames, %u triangles compared\n", ss.frames, ss.tris);
    CHECK(ss.frames == 6 * 12 && ss.tris > 6 * 12 * 100);
    CHECKF(ss.differ == 0, "%u corners evaluate differently", ss.differ);
    CHECKF(ss.order == 0, "%u frames with a different number of triangles", ss.order);
    CHECKF(ss.flags == 0, "%u triangles with a different added flag", ss.flags);
    CHECKF(ss.over == 0, "%u shares beyond the plan's maxima", ss.over);
    CHECKF(ss.counts == 0, "%u frames with different counts", ss.counts);
    CHECK(ss.segs > 0);
    CHECKF(ss.seg_at == 0, "%u of %u segments found elsewhere than seg_recs finds them", ss.seg_at, ss.segs);
}

/* ---- pixels ----------------------------------------------------------------------------- */

/* The stored frame (silk_frame_smooth, or silk_frame_flat) drawn by hand:
 * every record through the vertex stage, the triangles, then --wire's
 * edges of the original triangles and of the added ones. */
static int draw_stored(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *hal, silk_mode mode,
                       int wire, silk_target *t)
{
    silk_arena_mark mk = silk_arena_top_mark(a);
    silk_frame_geom g;
    silk_frame_stats st;
    silk_error err;
    memset(&st, 0, sizeof st);
    silk_status s = mode == SILK_MODE_SMOOTH ? silk_frame_smooth(a, m, v, SILK_FX_HALF, SILK_VIS_AUTO, &g, &st, &err)
                                             : silk_frame_flat(a, m, &g, &err);
    silk_vertex_out *out = s == SILK_OK ? malloc((g.nvrec + 1) * sizeof *out) : NULL;
    if (!out) {
        silk_arena_top_release(a, &mk);
        return 0;
    }
    silk_geom geom = { m, g.curve, g.offset, NULL };
    for (uint32_t i = 0; i < g.nvrec; i++) hal->vertex(hal, &geom, &g.vrec[i], &out[i]);
    silk_target_clear(t, BG);
    for (int pass = 0; pass < (wire ? 3 : 1); pass++)
        for (uint32_t k = 0; k < g.ntri; k++) {
            const uint32_t *c = &g.tri[3 * k];
            if (pass == 0) silk_raster_triangle(t, hal, &out[c[0]], &out[c[1]], &out[c[2]]);
            else if (g.tri_added[k] == pass - 1)
                for (int e = 0; e < 3; e++)
                    silk_raster_line(t, &out[c[e]], &out[c[(e + 1) % 3]], g.tri_added[k] ? 0xE02020 : 0x202020);
        }
    free(out);
    silk_arena_top_release(a, &mk);
    return !st.fell_back;
}

typedef struct band_copy { uint8_t *frame; size_t stride; } band_copy;

static int take_band(void *user, const silk_target *b)
{
    band_copy *c = user;
    memcpy(c->frame + (size_t)b->y0 * c->stride, b->color, (size_t)b->rows * c->stride);
    return 0;
}

TEST(pixels_are_the_stored_frame)
{
    enum { W = 320, H = 240, ROWS = 8 };
    static uint8_t ref[W * H * 3], img[W * H * 3], bands[W * H * 3], band_rgb[W * ROWS * 3];
    static uint32_t depth[W * H], band_depth[W * ROWS];
    const char *names[] = { "bunny-500.obj", "torus-576.obj", "fandisk-128.obj" };
    uint32_t frames = 0, differ = 0, band_differ = 0, lost = 0;
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++) {
        silk_arena a;
        silk_mesh m;
        if (!load(&a, names[n], NULL, &m)) { CHECK(0); continue; }
        for (int i = 0; i < 4; i++) {
            silk_view v;
            if (!make_view(&m, 40 + 90 * i, i & 1 ? -35 : 30, 3, i == 3, W, H, &v)) { CHECK(0); continue; }
            silk_phong ph;
            silk_hal hal;
            silk_phong_default(&ph, &v);
            silk_hal_phong(&hal, &ph);
            for (int mode = 0; mode < 2; mode++)
                for (int wire = 0; wire < (SILK_LINES ? 2 : 1); wire++) {   /* (--wire: SILK_LINES) */
                    silk_render_opts o;
                    silk_render_opts_default(&o);
                    o.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                    o.wire = wire;
                    o.bg_rgb = BG;
                    o.aa = 0;   /* the triangles are compared: a stored frame has no anti-aliasing */
                    silk_target t;
                    silk_error err;
                    silk_frame_stats fs;
                    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, ref, depth);
                    if (!draw_stored(&a, &m, &v, &hal, o.mode, wire, &t)) lost++;
                    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, img, depth);
                    if (silk_render(&a, &m, &v, &hal, &o, &t, &fs, &err) != SILK_OK || fs.fell_back) lost++;
                    silk_target band;
                    silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB888, band_rgb, band_depth);
                    band_copy bc = { bands, (size_t)W * 3 };
                    silk_sink sink = { .band = take_band, .user = &bc };
                    if (silk_render_bands(&a, &m, &v, &hal, &o, &band, &sink, &fs, &err) != SILK_OK || fs.fell_back)
                        lost++;
                    differ += memcmp(ref, img, sizeof ref) != 0;
                    band_differ += memcmp(ref, bands, sizeof ref) != 0;
                    frames++;
                }
        }
    }
    printf("  %u frames drawn three ways\n", frames);
    CHECK(frames == 3 * 4 * 2 * (SILK_LINES ? 2 : 1));
    CHECKF(lost == 0, "%u frames failed or fell back", lost);
    CHECKF(differ == 0, "%u streamed frames differ from the stored frame", differ);
    CHECKF(band_differ == 0, "%u streamed frames in %d-row bands differ from the stored frame", band_differ, ROWS);
}

/* A perspective view from (yaw, pitch) at distance 3, lit by the default
 * Phong HAL. */
static int lit_view(const silk_mesh *m, double yaw, double pitch, int w, int h, silk_view *v, silk_phong *ph,
                    silk_hal *hal)
{
    if (!make_view(m, yaw, pitch, 3, 0, w, h, v)) return 0;
    silk_phong_default(ph, v);
    silk_hal_phong(hal, ph);
    return 1;
}

/* The edge tangents a frame keeps where the arena has room (render.c,
 * keep_tangents): none, some or all of them, the same pixels and the same
 * need.  The arena's free space is cut to the frame's need plus a margin
 * by a block taken from the top before the frame.  Then the same with the
 * vertex cache's budget, under which the plan also keeps its edge ranks,
 * segments and tangents where the arena is roomy (silk_remesh_keep: the
 * whole arena) and none where it is cut. */
TEST(kept_tangents_change_no_pixel)
{
    enum { W = 320, H = 240, ROWS = 4 };
    static uint8_t ref[W * H * 2], img[W * H * 2], band_rgb[W * ROWS * 2];
    static uint32_t band_depth[W * ROWS];
    silk_arena a;
    silk_mesh m;
    if (!load(&a, "bunny-500.obj", NULL, &m)) { CHECK(0); return; }
    silk_view v;
    silk_phong ph;
    silk_hal hal;
    if (!lit_view(&m, 130, -35, W, H, &v, &ph, &hal)) { CHECK(0); return; }
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;
    o.vertex_cache_bytes = 0;
    silk_target band;
    silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB565, band_rgb, band_depth);
    /* SIZE_MAX: the whole arena (every tangent kept); 8: none (the room
     * one allocation's alignment takes); 40: one; 1000: some 40 */
    const size_t margin[] = { SIZE_MAX, 8, 40, 1000, 2, 4, 8, 16, 32 };   /* from 2 on: eighths of the need */
    size_t need = 0;
    uint32_t differ = 0, lost = 0;
    for (size_t j = 0; j < 2 * sizeof margin / sizeof margin[0]; j++) {
        size_t i = j % (sizeof margin / sizeof margin[0]), cut = i < 4 ? margin[i] : need * margin[i] / 8;
        o.vertex_cache_bytes = j == i ? 0 : SIZE_MAX;
        silk_arena_mark mk = silk_arena_top_mark(&a);
        size_t free0 = silk_arena_free_bytes(&a);
        if (cut != SIZE_MAX && !silk_arena_alloc_top(&a, free0 - need - cut, SILK_MEM_LOAD)) {
            CHECK(0);
            continue;
        }
        band_copy bc = { j ? img : ref, (size_t)W * 2 };
        silk_sink sink = { .band = take_band, .user = &bc };
        silk_frame_stats fs;
        silk_error err;
        if (silk_render_bands(&a, &m, &v, &hal, &o, &band, &sink, &fs, &err) != SILK_OK || fs.fell_back) lost++;
        silk_arena_top_release(&a, &mk);
        if (j == 0) {   /* the whole arena first: the need, then the cut ones */
            need = fs.frame_bytes;
            continue;
        }
        differ += memcmp(ref, img, sizeof ref) != 0 || fs.frame_bytes != need;
    }
    CHECK(need > 0);
    CHECKF(lost == 0, "%u frames failed or fell back", lost);
    CHECKF(differ == 0, "%u frames with fewer kept tangents differ", differ);
}

/* ---- memory ----------------------------------------------------------------------------- */

static int band_none(void *user, const silk_target *b)
{
    (void)user;
    (void)b;
    return 0;
}

TEST(smooth_frame_fits_a_64k_part)
{
    enum { W = 320, H = 240, ROWS = 8 };
    static uint8_t band_rgb[W * ROWS * 2];
    static uint32_t band_depth[W * ROWS];
    const char *names[] = { "bunny-500.obj", "knot-480.obj" };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++) {
        silk_arena a;
        silk_mesh m;
        if (!load(&a, names[n], NULL, &m)) { CHECK(0); continue; }
        size_t worst = 0;
        uint32_t fell = 0, tris = 0;
        for (int i = 0; i < 16; i++) {
            silk_view v;
            silk_phong ph;
            silk_hal hal;
            if (!lit_view(&m, 22.5 * i, i & 1 ? -25 : 25, W, H, &v, &ph, &hal)) { CHECK(0); continue; }
            silk_render_opts o;
            silk_render_opts_default(&o);
            silk_target band;
            silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB565, band_rgb, band_depth);
            silk_sink sink = { .band = band_none, .user = NULL };
            silk_frame_stats fs;
            silk_error err;
            CHECK(silk_render_bands(&a, &m, &v, &hal, &o, &band, &sink, &fs, &err) == SILK_OK);
            fell += fs.fell_back;
            tris += fs.tris_drawn;
            if (fs.frame_bytes > worst) worst = fs.frame_bytes;
        }
        printf("  %s: smooth frames need at most %zu bytes of scratch (%u triangles drawn in 16 views)\n", names[n],
               worst, tris);
        CHECKF(fell == 0, "%s: %u frames fell back", names[n], fell);
        CHECKF(tris > 16 * m.ntris, "%s: %u triangles: nothing smoothed", names[n], tris);
        CHECKF(worst <= BOARD_FRAME_BYTES, "%s: a smooth frame needs %zu bytes, the 64 KiB board has %u", names[n],
               worst, BOARD_FRAME_BYTES);
    }
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    RUN(shares_are_the_stored_frame);
    RUN(pixels_are_the_stored_frame);
    RUN(kept_tangents_change_no_pixel);
    RUN(smooth_frame_fits_a_64k_part);
    free(arena_buf);
    return check_done();
}
