/*
 * test_lines.c - pen-and-ink lines (silk_render_opts.lines, src/lines.c).
 *
 * A 200-triangle UV sphere from views around it, perspective and
 * orthographic:
 *   - in SMOOTH mode the silhouette lines lie on the rendered object's
 *     boundary (every line pixel within 1.5 px of the edge of the object
 *     mask rendered without lines) and run along all of it (every boundary
 *     pixel edge within 1.5 px of a line pixel: no gaps);
 *   - on a torus, a knot, a cone and bunny-500 (when the shared meshes
 *     are there), from many views and close up, every outline pixel edge
 *     lies within 1.5 px of a line pixel (the outline leaves the
 *     silhouette segments along mesh edges and round the cone's apex);
 *   - the polygonal variant is the coarse mesh's silhouette: its pixels lie
 *     within 1 px of the edges between a front- and a back-facing triangle
 *     (found here in double) and cover them, while the smooth lines leave
 *     that polygon by more;
 *   - lines alone draw nothing but lines on the background, the same
 *     pixels as over the shading, and the shading elsewhere is untouched.
 * A capped cylinder (rims as feature curves) with a ball in front of its
 * top rim: the rim's line follows the true circle within 1 px where it is
 * seen, is not drawn where the ball hides it, and the back half of the
 * bottom rim (behind the cylinder) is not drawn at all.  Band rendering
 * draws the same lines; a bad setting, outlines asked of PN or BLEND (whose
 * patches are not outlined by the coarse edges) and a short arena fail
 * cleanly, the last by drawing the frame and setting fell_back.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "support/scene.h"
#include "support/testmesh.h"
#include "tools/prep/gen.h"

#define PI 3.14159265358979323846
#define W 320
#define H 320
#define BG 0xFF00FFu          /* magenta, like pure green and blue never made by the default Phong */
#define SIL_RGB 0x00FF00u
#define FEAT_RGB 0x0000FFu

static uint8_t color[W * H * 3];
static uint32_t depth[W * H];

/* ---- scenes ----------------------------------------------------------------------- */

/* Flip the triangles from first_tri on that face the point c. */
static void orient_from(ts_mesh *m, uint32_t first_tri, const double c[3])
{
    for (uint32_t t = first_tri; t < m->nf; t++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = &m->v[3 * m->f[3 * t + k]];
        double e1[3], e2[3], g[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = p[1][i] - p[0][i];
            e2[i] = p[2][i] - p[0][i];
            g[i] = (p[0][i] + p[1][i] + p[2][i]) / 3 - c[i];
        }
        double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
        if (n[0] * g[0] + n[1] * g[1] + n[2] * g[2] < 0) {
            uint32_t s = m->f[3 * t + 1];
            m->f[3 * t + 1] = m->f[3 * t + 2];
            m->f[3 * t + 2] = s;
        }
    }
}

/* Capped cylinder on the y axis from 0 to h, n segments: `silk gen cylinder`. */
static void cylinder(ts_mesh *m, int n, double r, double h)
{
    uint32_t first = m->nf, top = ts_vertex(m, 0, h, 0), ring[2];
    for (int k = 0; k < 2; k++) {
        ring[k] = m->nv;
        for (int j = 0; j < n; j++) ts_vertex(m, r * cos(2 * PI * j / n), k ? 0 : h, r * sin(2 * PI * j / n));
    }
    uint32_t bottom = ts_vertex(m, 0, 0, 0);
    for (int j = 0; j < n; j++) {
        uint32_t j1 = (uint32_t)((j + 1) % n);
        ts_tri(m, top, ring[0] + (uint32_t)j, ring[0] + j1);
        ts_tri(m, ring[0] + (uint32_t)j, ring[1] + (uint32_t)j, ring[1] + j1);
        ts_tri(m, ring[0] + (uint32_t)j, ring[1] + j1, ring[0] + j1);
        ts_tri(m, bottom, ring[1] + j1, ring[1] + (uint32_t)j);
    }
    double c[3] = { 0, h / 2, 0 };
    orient_from(m, first, c);
}

typedef struct scene {
    silk_arena arena;
    void *buf;
    silk_mesh mesh;
    int ok;
} scene;

static int scene_build(scene *s, const ts_mesh *tm)
{
    memset(s, 0, sizeof *s);
    size_t size = 8u << 20;
    s->buf = malloc(size);
    if (!s->buf) return 0;
    silk_arena_init(&s->arena, s->buf, size);
    silk_error err;
    if (ts_build(tm, &s->arena, &s->mesh, &err) != SILK_OK) {
        fprintf(stderr, "ts_build: %s\n", err.msg);
        return 0;
    }
    return s->ok = 1;
}

static void scene_free(scene *s)
{
    free(s->buf);
    memset(s, 0, sizeof *s);
}

/* View k of n around the origin: azimuth steps, elevation sweeping -50..50
 * degrees, perspective for even k, orthographic for odd. */
static silk_camera sphere_camera(int k, int n)
{
    double az = (360.0 * k / n + 7.3) * PI / 180, el = (-50 + 100.0 * k / (n - 1)) * PI / 180;
    double eye[3] = { 4 * cos(el) * sin(az), 4 * sin(el), 4 * cos(el) * cos(az) }, target[3] = { 0, 0, 0 };
    return ts_camera(eye, target, k % 2 ? -1.3 : 40, 0.5, 10, W, H);
}

/* ---- rendering ---------------------------------------------------------------------- */

static silk_render_opts opts(silk_mode mode, silk_lines lines, int polygonal)
{
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = mode;
    o.bg_rgb = BG;
    o.lines = lines;
    o.lines_polygonal = polygonal;
    o.line_rgb = SIL_RGB;
    o.line_feature_rgb = FEAT_RGB;
    o.aa = 0;   /* outlines by pixel centres, the same with lines or without */
    return o;
}

static silk_status render(scene *s, const silk_camera *cam, const silk_render_opts *o, silk_frame_stats *fs)
{
    silk_view v;
    silk_error err;
    if (silk_view_init(&v, cam, &err) != SILK_OK) return SILK_ERR_ARG;
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
    silk_status st = silk_render(&s->arena, &s->mesh, &v, &hal, o, &t, fs, &err);
    if (st != SILK_OK) fprintf(stderr, "silk_render: %s\n", err.msg);
    return st;
}

/* SILK_LINES_DUMP=dir: every image the checks look at, as PPM. */
static void dump(const char *tag)
{
    const char *dir = getenv("SILK_LINES_DUMP");
    if (!dir) return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.ppm", dir, tag);
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    fwrite(color, 1, sizeof color, f);
    fclose(f);
}

static uint32_t pixel(const uint8_t *img, int x, int y)
{
    const uint8_t *p = img + ((size_t)y * W + x) * 3;
    return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

/* Pixels of colour rgb (or, with rgb BG, everything not background). */
static void take(const uint8_t *img, uint32_t rgb, uint8_t *mask)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint32_t c = pixel(img, x, y);
            mask[y * W + x] = rgb == BG ? c != BG : c == rgb;
        }
}

static long count(const uint8_t *mask)
{
    long n = 0;
    for (int i = 0; i < W * H; i++) n += mask[i];
    return n;
}

/* ---- distances ------------------------------------------------------------------- */

static double seg_dist(double px, double py, double x0, double y0, double x1, double y1)
{
    double dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy, t = 0;
    if (l2 > 0) t = fmax(0, fmin(1, ((px - x0) * dx + (py - y0) * dy) / l2));
    return hypot(px - x0 - t * dx, py - y0 - t * dy);
}

/* Distance from (px, py) to the nearest pixel edge between an in and an out
 * pixel of mask, looked for within 3 px (farther gives 1e9). */
static double crack_dist(const uint8_t *mask, double px, double py)
{
    double best = 1e9;
    int cx = (int)floor(px), cy = (int)floor(py);
    for (int y = cy - 3; y <= cy + 3; y++)
        for (int x = cx - 3; x <= cx + 3; x++) {
            if (x < 0 || y < 0 || x >= W || y >= H) continue;
            int v = mask[y * W + x];
            if (x + 1 < W && mask[y * W + x + 1] != v) best = fmin(best, seg_dist(px, py, x + 1, y, x + 1, y + 1));
            if (y + 1 < H && mask[(y + 1) * W + x] != v) best = fmin(best, seg_dist(px, py, x, y + 1, x + 1, y + 1));
        }
    return best;
}

/* Distance from (px, py) to the nearest pixel centre set in mask, within 3 px. */
static double pixel_dist(const uint8_t *mask, double px, double py)
{
    double best = 1e9;
    int cx = (int)floor(px), cy = (int)floor(py);
    for (int y = cy - 3; y <= cy + 3; y++)
        for (int x = cx - 3; x <= cx + 3; x++)
            if (x >= 0 && y >= 0 && x < W && y < H && mask[y * W + x]) best = fmin(best, hypot(px - x - 0.5, py - y - 0.5));
    return best;
}

/* ---- the camera in double ------------------------------------------------------------ */

typedef struct dcam {
    double eye[3], f[3], s[3], u[3], scale;   /* scale: tan(fov/2) or the half height */
    int ortho;
} dcam;

static void unit(double a[3])
{
    double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int i = 0; i < 3; i++) a[i] /= l;
}

static dcam dcam_from(const silk_camera *c)
{
    dcam d;
    double t[3] = { ts_fx2d(c->target.x), ts_fx2d(c->target.y), ts_fx2d(c->target.z) };
    double up[3] = { ts_fx2d(c->up.x), ts_fx2d(c->up.y), ts_fx2d(c->up.z) };
    d.eye[0] = ts_fx2d(c->eye.x);
    d.eye[1] = ts_fx2d(c->eye.y);
    d.eye[2] = ts_fx2d(c->eye.z);
    for (int i = 0; i < 3; i++) d.f[i] = t[i] - d.eye[i];
    unit(d.f);
    d.s[0] = d.f[1] * up[2] - d.f[2] * up[1];
    d.s[1] = d.f[2] * up[0] - d.f[0] * up[2];
    d.s[2] = d.f[0] * up[1] - d.f[1] * up[0];
    unit(d.s);
    d.u[0] = d.s[1] * d.f[2] - d.s[2] * d.f[1];
    d.u[1] = d.s[2] * d.f[0] - d.s[0] * d.f[2];
    d.u[2] = d.s[0] * d.f[1] - d.s[1] * d.f[0];
    d.ortho = c->ortho;
    d.scale = c->ortho ? ts_fx2d(c->ortho_half_height) : tan(ts_fx2d(c->fov_deg) * PI / 360);
    return d;
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void project(const dcam *c, const double p[3], double *x, double *y)
{
    double d[3] = { p[0] - c->eye[0], p[1] - c->eye[1], p[2] - c->eye[2] };
    double depth_ = c->ortho ? 1 : dot(d, c->f);
    *x = W / 2.0 + dot(d, c->s) / (depth_ * c->scale) * (H / 2.0);
    *y = H / 2.0 - dot(d, c->u) / (depth_ * c->scale) * (H / 2.0);
}

/* Direction from p towards the viewer. */
static void to_eye(const dcam *c, const double p[3], double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = c->ortho ? -c->f[i] : c->eye[i] - p[i];
}

static void posd(const silk_mesh *m, uint32_t v, double p[3])
{
    p[0] = ts_fx2d(m->pos[v].x);
    p[1] = ts_fx2d(m->pos[v].y);
    p[2] = ts_fx2d(m->pos[v].z);
}

static int front_facing(const silk_mesh *m, const dcam *c, uint32_t t)
{
    double p[3][3], e1[3], e2[3], d[3];
    for (int k = 0; k < 3; k++) posd(m, m->tri[3 * t + k], p[k]);
    for (int i = 0; i < 3; i++) {
        e1[i] = p[1][i] - p[0][i];
        e2[i] = p[2][i] - p[0][i];
    }
    double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
    to_eye(c, p[0], d);
    return dot(n, d) > 0;
}

/* The coarse silhouette in pixels: 4 doubles per edge between a front- and
 * a back-facing triangle. */
static int coarse_silhouette(const silk_mesh *m, const dcam *c, double *seg, int max)
{
    int n = 0;
    for (uint32_t e = 0; e < m->nedges && n < max; e++) {
        const silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || front_facing(m, c, ed->t[0]) == front_facing(m, c, ed->t[1])) continue;
        double a[3], b[3];
        posd(m, ed->v[0], a);
        posd(m, ed->v[1], b);
        project(c, a, &seg[4 * n], &seg[4 * n + 1]);
        project(c, b, &seg[4 * n + 2], &seg[4 * n + 3]);
        n++;
    }
    return n;
}

static double segs_dist(const double *seg, int n, double px, double py)
{
    double best = 1e9;
    for (int i = 0; i < n; i++)
        best = fmin(best, seg_dist(px, py, seg[4 * i], seg[4 * i + 1], seg[4 * i + 2], seg[4 * i + 3]));
    return best;
}

/* ---- the sphere --------------------------------------------------------------------- */

#define SPHERE_VIEWS 8
static scene sphere;

static void sphere_setup(void)
{
    ts_mesh tm;
    memset(&tm, 0, sizeof tm);
    ts_sphere(&tm, 10, 11, 1.0, 0, 0, 0);
    scene_build(&sphere, &tm);
    ts_mesh_free(&tm);
}

/* Smooth silhouette lines on the boundary of the object, and along all of it. */
TEST(smooth_lines_on_the_boundary)
{
    static uint8_t plain[W * H * 3], mask[W * H], lines[W * H], feat[W * H];
    CHECK(sphere.ok);
    if (!sphere.ok) return;
    double worst_off = 0, worst_gap = 0;
    long total = 0, changed = 0;
    for (int k = 0; k < SPHERE_VIEWS; k++) {
        silk_camera cam = sphere_camera(k, SPHERE_VIEWS);
        silk_render_opts o = opts(SILK_MODE_SMOOTH, SILK_LINES_NONE, 0);
        silk_frame_stats fs;
        CHECK(render(&sphere, &cam, &o, &fs) == SILK_OK && !fs.fell_back);
        memcpy(plain, color, sizeof plain);
        take(plain, BG, mask);
        o.lines = SILK_LINES_OVER;
        CHECK(render(&sphere, &cam, &o, &fs) == SILK_OK && !fs.fell_back);
        take(color, SIL_RGB, lines);
        take(color, FEAT_RGB, feat);
        CHECKF(count(feat) == 0, "view %d: %ld feature pixels on a sphere", k, count(feat));
        total += count(lines);
        /* every line pixel on the outline */
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int i = y * W + x;
                if (lines[i]) worst_off = fmax(worst_off, crack_dist(mask, x + 0.5, y + 0.5));
                else changed += memcmp(&color[3 * i], &plain[3 * i], 3) != 0;
            }
        /* every outline pixel edge near a line pixel */
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int v = mask[y * W + x];
                if (x + 1 < W && mask[y * W + x + 1] != v) worst_gap = fmax(worst_gap, pixel_dist(lines, x + 1, y + 0.5));
                if (y + 1 < H && mask[(y + 1) * W + x] != v) worst_gap = fmax(worst_gap, pixel_dist(lines, x + 0.5, y + 1));
            }
    }
    printf("  sphere, %d views: %ld line pixels, farthest %.2f px from the outline; outline at most %.2f px from a line\n",
           SPHERE_VIEWS, total, worst_off, worst_gap);
    CHECKF(total > SPHERE_VIEWS * 500L, "%ld line pixels", total);
    CHECKF(worst_off <= 1.5, "a line pixel %.2f px from the outline", worst_off);
    CHECKF(worst_gap <= 1.5, "a part of the outline %.2f px from the nearest line pixel", worst_gap);
    CHECKF(changed == 0, "%ld pixels away from the lines changed", changed);
}

/* Lines alone: background and lines only, the same line pixels as over the shading. */
TEST(lines_only_on_background)
{
    static uint8_t over[W * H], only[W * H];
    CHECK(sphere.ok);
    if (!sphere.ok) return;
    for (int k = 0; k < SPHERE_VIEWS; k += 3)
        for (int poly = 0; poly < 2; poly++) {
            silk_camera cam = sphere_camera(k, SPHERE_VIEWS);
            silk_mode mode = poly ? SILK_MODE_FLAT : SILK_MODE_SMOOTH;
            silk_render_opts o = opts(mode, SILK_LINES_OVER, poly);
            CHECK(render(&sphere, &cam, &o, NULL) == SILK_OK);
            take(color, SIL_RGB, over);
            o.lines = SILK_LINES_ONLY;
            CHECK(render(&sphere, &cam, &o, NULL) == SILK_OK);
            take(color, SIL_RGB, only);
            long other = 0, differ = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    uint32_t c = pixel(color, x, y);
                    other += c != BG && c != SIL_RGB;
                    differ += over[y * W + x] != only[y * W + x];
                }
            CHECKF(other == 0, "view %d %s: %ld pixels neither background nor line", k, poly ? "polygonal" : "smooth", other);
            CHECKF(differ == 0, "view %d %s: %ld line pixels differ from --lines over", k, poly ? "polygonal" : "smooth",
                   differ);
            CHECK(count(only) > 500);
        }
}

/* The polygonal variant is the coarse mesh's silhouette; the smooth one is not. */
TEST(polygonal_is_coarse_silhouette)
{
    static uint8_t poly[W * H], smooth[W * H];
    static double seg[4 * 400];
    CHECK(sphere.ok);
    if (!sphere.ok) return;
    double worst_off = 0, worst_gap = 0, smooth_far = 0;
    for (int k = 0; k < SPHERE_VIEWS; k++) {
        silk_camera cam = sphere_camera(k, SPHERE_VIEWS);
        dcam dc = dcam_from(&cam);
        int n = coarse_silhouette(&sphere.mesh, &dc, seg, 400);
        CHECK(n >= 10);
        silk_render_opts o = opts(SILK_MODE_FLAT, SILK_LINES_ONLY, 1);
        CHECK(render(&sphere, &cam, &o, NULL) == SILK_OK);
        take(color, SIL_RGB, poly);
        o = opts(SILK_MODE_SMOOTH, SILK_LINES_ONLY, 0);
        CHECK(render(&sphere, &cam, &o, NULL) == SILK_OK);
        take(color, SIL_RGB, smooth);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                if (poly[y * W + x]) worst_off = fmax(worst_off, segs_dist(seg, n, x + 0.5, y + 0.5));
                if (smooth[y * W + x]) smooth_far = fmax(smooth_far, segs_dist(seg, n, x + 0.5, y + 0.5));
            }
        /* every coarse silhouette edge drawn: points every half pixel along it */
        for (int i = 0; i < n; i++) {
            double *s = &seg[4 * i], len = hypot(s[2] - s[0], s[3] - s[1]);
            for (double t = 0; t <= len; t += 0.5) {
                double u = len > 0 ? t / len : 0;
                worst_gap = fmax(worst_gap, pixel_dist(poly, s[0] + u * (s[2] - s[0]), s[1] + u * (s[3] - s[1])));
            }
        }
    }
    printf("  polygonal: line pixels within %.2f px of the coarse silhouette edges, which are within %.2f px of a "
           "line pixel; smooth lines up to %.2f px off them\n", worst_off, worst_gap, smooth_far);
    CHECKF(worst_off <= 1.0, "a polygonal line pixel %.2f px off the coarse silhouette", worst_off);
    /* a one-pixel line leaves points of a diagonal up to 1.12 px from a pixel centre */
    CHECKF(worst_gap <= 1.25, "a coarse silhouette edge %.2f px from the nearest line pixel", worst_gap);
    CHECKF(smooth_far >= 3.0, "smooth lines within %.2f px of the polygon", smooth_far);
}

/* ---- the cylinder behind a ball --------------------------------------------------------- */

#define CYL_R 1.0
#define CYL_H 2.0
#define BALL_R 0.3

/* Where the viewer sees p from: the eye, or far back along the view axis. */
static void viewpoint(const dcam *c, const double p[3], double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = c->ortho ? p[i] - 50 * c->f[i] : c->eye[i];
}

/* Where the ball goes: 40% of the way from the viewer to the top rim point
 * at azimuth phi, so that it hides the rim around that point. */
static void ball_centre(const dcam *c, double phi, double out[3])
{
    double p[3] = { CYL_R * cos(phi), CYL_H, CYL_R * sin(phi) }, e[3];
    viewpoint(c, p, e);
    double len = c->ortho ? 0.4 * sqrt(dot(c->eye, c->eye)) : 0.4;
    for (int i = 0; i < 3; i++) out[i] = c->ortho ? p[i] - len * c->f[i] : p[i] + len * (e[i] - p[i]);
}

/* 1 when the line of sight to p passes through the ball shrunk (margin < 0)
 * or grown (margin > 0) by margin. */
static int ball_blocks(const dcam *dc, const double c[3], const double p[3], double margin)
{
    double d[3], q[3], eye[3];
    viewpoint(dc, p, eye);
    for (int i = 0; i < 3; i++) {
        d[i] = p[i] - eye[i];
        q[i] = c[i] - eye[i];
    }
    double t = dot(q, d) / dot(d, d);
    if (t <= 0 || t >= 1) return 0;
    double x[3] = { q[0] - t * d[0], q[1] - t * d[1], q[2] - t * d[2] };
    return sqrt(dot(x, x)) < BALL_R + margin;
}

/* The rims' lines: where seen, on the true circle (SMOOTH) and drawn;
 * where the ball or the cylinder hides them, not drawn. */
TEST(feature_lines_hidden_where_hidden)
{
    static uint8_t feat[W * H], any[W * H];
    const double eye[3] = { 1.6, 5.2, 5.0 }, target[3] = { 0, 1, 0 };
    for (int ortho = 0; ortho < 2; ortho++) {
        silk_camera cam = ts_camera(eye, target, ortho ? -1.8 : 40, 1, 20, W, H);
        dcam dc = dcam_from(&cam);
        double bc[3];
        ball_centre(&dc, 1.3, bc);
        ts_mesh tm;
        memset(&tm, 0, sizeof tm);
        cylinder(&tm, 24, CYL_R, CYL_H);
        uint32_t first = tm.nf;
        ts_sphere(&tm, 10, 11, BALL_R, bc[0], bc[1], bc[2]);
        orient_from(&tm, first, bc);
        scene s;
        int ok = scene_build(&s, &tm);
        ts_mesh_free(&tm);
        CHECK(ok);
        if (!ok) { scene_free(&s); return; }
        CHECK(s.mesh.nfeature_edges >= 48);
        double px_per_unit = ortho ? H / 3.6 : H / (2 * dc.scale * 7.2);  /* about, at the rims */
        for (int poly = 0; poly < 2; poly++) {
            silk_render_opts o = opts(poly ? SILK_MODE_FLAT : SILK_MODE_SMOOTH, SILK_LINES_ONLY, poly);
            silk_frame_stats fs;
            CHECK(render(&s, &cam, &o, &fs) == SILK_OK && !fs.fell_back);
            char tag[64];
            snprintf(tag, sizeof tag, "cylinder-%s-%s", ortho ? "ortho" : "persp", poly ? "polygonal" : "smooth");
            dump(tag);
            take(color, FEAT_RGB, feat);
            take(color, SIL_RGB, any);
            for (int i = 0; i < W * H; i++) any[i] |= feat[i];
            double seen_off = 0, seen_gap = 0, hidden_near = 1e9;
            int nseen = 0, nhidden = 0, nback = 0;
            for (int rim = 0; rim < 2; rim++)
                for (int i = 0; i < 720; i++) {
                    double phi = 2 * PI * i / 720, p[3] = { CYL_R * cos(phi), rim ? 0 : CYL_H, CYL_R * sin(phi) };
                    double x, y, te[3], nrm[3] = { cos(phi), 0, sin(phi) };
                    project(&dc, p, &x, &y);
                    to_eye(&dc, p, te);
                    /* the bottom rim's back half: behind the side, by more than 3 px */
                    int back = rim == 1 && dot(nrm, te) < -0.3 * sqrt(dot(te, te));
                    double margin = 3 / px_per_unit;
                    if (back || ball_blocks(&dc, bc, p, -margin)) {
                        hidden_near = fmin(hidden_near, pixel_dist(feat, x, y));
                        nhidden++;
                        nback += back;
                    } else if (rim == 0 && !ball_blocks(&dc, bc, p, margin)) {
                        /* seen: the top rim faces the eye, all of it (where the
                         * side's outline meets it, that line may be drawn over it) */
                        double d = pixel_dist(any, x, y);
                        seen_gap = fmax(seen_gap, d);
                        nseen++;
                    }
                }
            /* every feature pixel near the true top or bottom rim */
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    if (!feat[y * W + x]) continue;
                    double best = 1e9;
                    for (int rim = 0; rim < 2; rim++)
                        for (int i = 0; i < 720; i++) {
                            double phi = 2 * PI * i / 720, p[3] = { CYL_R * cos(phi), rim ? 0 : CYL_H, CYL_R * sin(phi) };
                            double q[3] = { CYL_R * cos(phi + 2 * PI / 720), p[1], CYL_R * sin(phi + 2 * PI / 720) };
                            double ax, ay, bx, by;
                            project(&dc, p, &ax, &ay);
                            project(&dc, q, &bx, &by);
                            best = fmin(best, seg_dist(x + 0.5, y + 0.5, ax, ay, bx, by));
                        }
                    seen_off = fmax(seen_off, best);
                }
            char near[32];
            snprintf(near, sizeof near, hidden_near > 3 ? "more than 3 px" : "%.2f px", hidden_near);
            printf("  cylinder %s %s: feature pixels within %.2f px of the rims; seen rim (%d points) within %.2f px of "
                   "a line pixel; hidden rim (%d points, %d behind the side) %s from the nearest feature pixel\n",
                   ortho ? "ortho" : "persp", poly ? "polygonal" : "smooth", seen_off, nseen, seen_gap, nhidden, nback,
                   near);
            CHECK(nseen > 300 && nhidden > 300 && nback > 100 && nhidden > nback + 10);
            /* half a pixel, plus the sampling tolerance (0.5 px), plus the curve's own error */
            if (!poly) CHECKF(seen_off <= 1.25, "smooth rim line %.2f px off the circle", seen_off);
            CHECKF(seen_gap <= 1.5, "%s: seen rim %.2f px from the nearest line pixel", poly ? "polygonal" : "smooth",
                   seen_gap);
            CHECKF(hidden_near >= 1.5, "%s: a line pixel %.2f px from a hidden rim point", poly ? "polygonal" : "smooth",
                   hidden_near);
        }
        scene_free(&s);
    }
}

/* ---- bands, bad settings, a short arena ---------------------------------------------------- */

typedef struct collect {
    uint8_t *img;
} collect;

static int collect_band(void *user, const silk_target *band)
{
    collect *c = user;
    for (int r = 0; r < band->rows; r++)
        memcpy(c->img + (size_t)(band->y0 + r) * W * 3, band->color + (size_t)r * band->stride, (size_t)W * 3);
    return 0;
}

TEST(bands_draw_the_same_lines)
{
    static uint8_t full[W * H * 3], banded[W * H * 3], band_color[W * 24 * 3];
    static uint32_t band_depth[W * 24];
    CHECK(sphere.ok);
    if (!sphere.ok) return;
    for (int k = 0; k < 2; k++) {
        silk_camera cam = sphere_camera(k, SPHERE_VIEWS);
        silk_render_opts o = opts(SILK_MODE_SMOOTH, k ? SILK_LINES_ONLY : SILK_LINES_OVER, 0);
        CHECK(render(&sphere, &cam, &o, NULL) == SILK_OK);
        memcpy(full, color, sizeof full);
        silk_view v;
        silk_error err;
        CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
        silk_phong ph;
        silk_hal hal;
        silk_phong_default(&ph, &v);
        silk_hal_phong(&hal, &ph);
        silk_target band;
        silk_target_init(&band, W, H, 0, 24, SILK_PIX_RGB888, band_color, band_depth);
        collect c = { banded };
        silk_sink sink = { .band = collect_band, .user = &c };
        CHECK(silk_render_bands(&sphere.arena, &sphere.mesh, &v, &hal, &o, &band, &sink, NULL, &err) == SILK_OK);
        CHECKF(memcmp(full, banded, sizeof full) == 0, "view %d: bands differ from the whole frame", k);
    }
}

TEST(bad_setting_and_short_arena)
{
    CHECK(sphere.ok);
    if (!sphere.ok) return;
    silk_camera cam = sphere_camera(0, SPHERE_VIEWS);
    silk_render_opts o = opts(SILK_MODE_SMOOTH, (silk_lines)3, 0);
    silk_view v;
    silk_error err;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
    memset(&err, 0, sizeof err);
    CHECK(silk_render(&sphere.arena, &sphere.mesh, &v, &hal, &o, &t, NULL, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "lines") != NULL, "message: %s", err.msg);
    /* PN and BLEND: the coarse mesh's edges only when asked for by name */
    for (int k = 0; k < 2; k++) {
        o = opts(k ? SILK_MODE_BLEND : SILK_MODE_PN, SILK_LINES_OVER, 0);
        memset(&err, 0, sizeof err);
        CHECK(silk_render(&sphere.arena, &sphere.mesh, &v, &hal, &o, &t, NULL, &err) == SILK_ERR_ARG);
        CHECKF(strstr(err.msg, "polygonal") != NULL, "message: %s", err.msg);
        o.lines_polygonal = 1;
        CHECK(silk_render(&sphere.arena, &sphere.mesh, &v, &hal, &o, &t, NULL, &err) == SILK_OK);
        long n = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) n += pixel(color, x, y) == SIL_RGB;
        /* the patches hide most of the coarse edges, but not all */
        CHECKF(n > 10, "%s with polygonal lines: %ld line pixels", k ? "blend" : "pn", n);
    }
    o = opts(SILK_MODE_SMOOTH, SILK_LINES_OVER, 0);

    /* The frame's peak with and without lines; then an arena with room for
     * the frame but not for all of its lines. */
    silk_frame_stats plain, with;
    o.lines = SILK_LINES_NONE;
    CHECK(silk_render(&sphere.arena, &sphere.mesh, &v, &hal, &o, &t, &plain, &err) == SILK_OK);
    o.lines = SILK_LINES_OVER;
    CHECK(silk_render(&sphere.arena, &sphere.mesh, &v, &hal, &o, &t, &with, &err) == SILK_OK);
    CHECKF(with.frame_bytes > plain.frame_bytes, "%zu vs %zu bytes", with.frame_bytes, plain.frame_bytes);
    ts_mesh tm;
    memset(&tm, 0, sizeof tm);
    ts_sphere(&tm, 10, 11, 1.0, 0, 0, 0);
    int fell = 0, drawn = 0, tries = 0, full_fell = 1;
    /* down to where the frame drops its vertex caches and the lines still do not fit */
    for (size_t room = with.frame_bytes / 3 & ~(size_t)7; room <= with.frame_bytes; room += 256) {
        if (room + 256 > with.frame_bytes) room = with.frame_bytes;
        scene s;
        if (!scene_build(&s, &tm)) break;
        size_t spare = silk_arena_free_bytes(&s.arena);
        if (spare > room + 8) silk_arena_alloc(&s.arena, spare - room - 8, SILK_MEM_LOAD);
        silk_frame_stats fs;
        silk_status st = silk_render(&s.arena, &s.mesh, &v, &hal, &o, &t, &fs, &err);
        tries++;
        if (st == SILK_OK) {
            drawn++;
            fell += fs.fell_back;
        }
        if (room == with.frame_bytes) full_fell = fs.fell_back;
        scene_free(&s);
    }
    ts_mesh_free(&tm);
    printf("  short arenas: %d sizes from %zu to %zu frame bytes, %d drawn, %d of them fell back\n", tries,
           with.frame_bytes / 3, with.frame_bytes, drawn, fell);
    CHECK(tries > 0 && drawn == tries && fell > 0 && !full_fell);
}

/* ---- the outline of every mesh ------------------------------------------------------ */

/* A `silk gen` mesh (tools/prep/gen.c) as a scene. */
static int gen_scene(scene *s, gen_shape shape, void (*set)(gen_params *))
{
    gen_params p;
    gen_mesh gm;
    gen_defaults(shape, &p);
    set(&p);
    char msg[256];
    if (gen_check(&p, msg, sizeof msg) || gen_build(&p, &gm) != 0) return 0;
    ts_mesh tm;
    memset(&tm, 0, sizeof tm);
    for (uint32_t v = 0; v < gm.nverts; v++) ts_vertex(&tm, gm.pos[3 * v], gm.pos[3 * v + 1], gm.pos[3 * v + 2]);
    for (uint32_t t = 0; t < gm.ntris; t++) ts_tri(&tm, gm.tri[3 * t], gm.tri[3 * t + 1], gm.tri[3 * t + 2]);
    gen_free(&gm);
    int ok = scene_build(s, &tm);
    ts_mesh_free(&tm);
    return ok;
}

static void set_torus(gen_params *p) { p->segments = 24; p->bands = 12; }
static void set_knot(gen_params *p) { p->p = 2; p->q = 3; p->tube = 0.2; p->segments = 64; p->bands = 8; }
static void set_cone(gen_params *p) { p->segments = 35; }

/* View k of n around the mesh's bounding box, dist radii away: azimuth
 * steps, elevation sweeping -50..50 degrees, perspective for even k and
 * orthographic for odd. */
static silk_camera mesh_camera(const silk_mesh *m, int k, int n, double dist)
{
    double lo[3] = { 1e9, 1e9, 1e9 }, hi[3] = { -1e9, -1e9, -1e9 }, c[3], r = 0;
    for (uint32_t v = 0; v < m->nverts; v++) {
        double p[3];
        posd(m, v, p);
        for (int i = 0; i < 3; i++) { lo[i] = fmin(lo[i], p[i]); hi[i] = fmax(hi[i], p[i]); }
    }
    for (int i = 0; i < 3; i++) { c[i] = (lo[i] + hi[i]) / 2; r += (hi[i] - lo[i]) * (hi[i] - lo[i]) / 4; }
    r = sqrt(r);
    double az = (360.0 * k / n + 7.3) * PI / 180, el = (-50 + 100.0 * k / (n - 1)) * PI / 180;
    double eye[3] = { c[0] + dist * r * cos(el) * sin(az), c[1] + dist * r * sin(el), c[2] + dist * r * cos(el) * cos(az) };
    return ts_camera(eye, c, k % 2 ? -r * 1.05 : 40, 0.05 * r, (dist + 2) * r, W, H);
}

/* The farthest pixel edge of the object's outline (SMOOTH mode, no lines)
 * from a pixel of its smooth lines, over n views. */
static double outline_gap(scene *s, int n, double dist, const char *name)
{
    static uint8_t mask[W * H], lines[W * H];
    double worst = 0;
    for (int k = 0; k < n; k++) {
        silk_camera cam = mesh_camera(&s->mesh, k, n, dist);
        silk_render_opts o = opts(SILK_MODE_SMOOTH, SILK_LINES_NONE, 0);
        silk_frame_stats fs;
        CHECK(render(s, &cam, &o, &fs) == SILK_OK && !fs.fell_back);
        take(color, BG, mask);
        o.lines = SILK_LINES_ONLY;
        CHECK(render(s, &cam, &o, &fs) == SILK_OK && !fs.fell_back);
        take(color, BG, lines);
        double gap = 0;
        int gx = 0, gy = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int v = mask[y * W + x];
                double d;
                if (x + 1 < W && mask[y * W + x + 1] != v && (d = pixel_dist(lines, x + 1, y + 0.5)) > gap) {
                    gap = d; gx = x; gy = y;
                }
                if (y + 1 < H && mask[(y + 1) * W + x] != v && (d = pixel_dist(lines, x + 0.5, y + 1)) > gap) {
                    gap = d; gx = x; gy = y;
                }
            }
        if (gap > 1.5) {
            char tag[64];
            snprintf(tag, sizeof tag, "outline-%s-%d", name, k);
            dump(tag);
            printf("  %s view %d: the outline at (%d, %d) is %.2f px from a line\n", name, k, gx, gy, gap);
        }
        worst = fmax(worst, gap);
    }
    return worst;
}

/* Every pixel of the outline of a SMOOTH frame within 1.5 px of a line
 * pixel, on curved meshes of every kind, from many views and close up. */
TEST(smooth_lines_close_every_outline)
{
    static const struct { const char *name; gen_shape shape; void (*set)(gen_params *); } gens[] = {
        { "torus", GEN_TORUS, set_torus }, { "knot", GEN_KNOT, set_knot }, { "cone", GEN_CONE, set_cone },
    };
    double g = outline_gap(&sphere, 12, 3.0, "sphere");
    printf("  sphere: the outline at most %.2f px from a line\n", g);
    CHECKF(g <= 1.5, "sphere: a part of the outline %.2f px from the nearest line pixel", g);
    for (size_t i = 0; i < sizeof gens / sizeof gens[0]; i++) {
        scene s;
        if (!gen_scene(&s, gens[i].shape, gens[i].set)) {
            CHECKF(0, "%s: cannot make the mesh", gens[i].name);
            continue;
        }
        g = fmax(outline_gap(&s, 12, 3.0, gens[i].name), outline_gap(&s, 4, 1.6, gens[i].name));
        printf("  %s: the outline at most %.2f px from a line\n", gens[i].name, g);
        CHECKF(g <= 1.5, "%s: a part of the outline %.2f px from the nearest line pixel", gens[i].name, g);
        scene_free(&s);
    }
    scene b;
    memset(&b, 0, sizeof b);
    size_t size = 16u << 20;
    b.buf = malloc(size);
    silk_arena_init(&b.arena, b.buf, size);
    char path[512];
    snprintf(path, sizeof path, "%s/bunny-500.obj", check_meshes_dir());
    FILE *probe = fopen(path, "rb");
    if (probe) fclose(probe);
    if (!probe) {
        printf("  skip: bunny-500: the shared meshes are missing\n");
    } else if (tm_load_shared(&b.arena, "bunny-500.obj", &b.mesh)) {
        g = fmax(outline_gap(&b, 12, 3.0, "bunny"), outline_gap(&b, 6, 1.4, "bunny"));
        printf("  bunny-500: the outline at most %.2f px from a line\n", g);
        CHECKF(g <= 1.5, "bunny-500: a part of the outline %.2f px from the nearest line pixel", g);
    } else {
        CHECKF(0, "bunny-500 does not load");
    }
    free(b.buf);
}

int main(void)
{
    CHECK_PROGRAM_NEEDS(SILK_LINES);
    sphere_setup();
    RUN(smooth_lines_on_the_boundary);
    RUN(smooth_lines_close_every_outline);
    RUN(lines_only_on_background);
    RUN(polygonal_is_coarse_silhouette);
    RUN(feature_lines_hidden_where_hidden);
    RUN(bands_draw_the_same_lines);
    RUN(bad_setting_and_short_arena);
    scene_free(&sphere);
    return check_done();
}
