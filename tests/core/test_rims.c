/*
 * test_rims.c - feature curves: a capped cylinder
 * and a cone whose rims are feature edges (paper III-A) render with smooth
 * rims.
 *
 * The meshes are `silk gen cylinder` (radius 1, height 2, 24 segments: 96
 * triangles) and `silk gen cone` (radius 1, height 1.5, 35 segments: 70
 * triangles), every vertex on the analytic surface.  Each is rendered at
 * 384x384 from views above the rim, grazing it (the eye a few degrees off
 * the plane of a cap) and below it, three azimuths each, in perspective
 * and orthographic projection, whole and zoomed in 4x on the lowest (or
 * highest) point of a rim on the outline, FLAT and SMOOTH, and its object
 * mask is compared with the exact mask of the analytic solid, ray cast in
 * double (tests/support/exact_silhouette.c):
 *   mean error = differing pixels / boundary pixels of the exact mask (px)
 *   max error  = farthest differing pixel from the true outline (px)
 *   rim offset = at samples of the true outline within 2 px of a rim, the
 *                distance to the rendered mask's edge (0.5 px for a
 *                perfect rasterization)
 * Smooth mode must stay within the bounds below in every view and, zoomed
 * in, be clearly better than flat (unzoomed, the polygons of these rims are
 * within a pixel of the circles already).  The first test checks the exact
 * shapes on views with known answers.
 *
 * SILK_RIMS_DUMP=dir writes each compared mask pair as PGM.
 */
#define _POSIX_C_SOURCE 200809L   /* popen, for `silk gen` */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "support/exact_silhouette.h"

#define PI 3.14159265358979323846
#define W 384
#define H 384
#define BG 0xFF00FFu

/* Bounds for SMOOTH mode, every view (measured: mean 0.25, max 0.66, rim
 * offsets 1.02 at most - where a rim meets the side's outline - and 0.30 on
 * average; a perfect rasterization has offsets up to 0.5, 0.25 on average). */
#define SMOOTH_MEAN_BOUND 0.30
#define SMOOTH_MAX_BOUND 1.0
#define SMOOTH_RIM_BOUND 1.1      /* largest rim offset */
#define SMOOTH_RIM_MEAN 0.35      /* mean rim offset */
/* Zoomed in ZOOM times on a rim, where the polygon of the coarse rim is
 * seen (the cylinder's 24-gon is 0.86 px off the circle unzoomed, the
 * cone's 35-gon 0.4 px), FLAT's mean error over the views is at least
 * FLAT_RATIO times SMOOTH's, and its rim offsets larger.  Unzoomed, smooth
 * must not be worse. */
#define ZOOM 4.0
#define FLAT_RATIO 3.0

static char silk_path[512] = "build/silk";
static silk_arena arena;
static unsigned char color[W * H * 3];
static uint32_t depth[W * H];
static const char *dump_dir;

/* ---- the exact shapes on known answers ------------------------------------------- */

static es_camera ortho_cam(double ex, double ey, double ez, double tx, double ty, double tz, double half)
{
    es_camera c;
    memset(&c, 0, sizeof c);
    c.eye[0] = ex; c.eye[1] = ey; c.eye[2] = ez;
    c.target[0] = tx; c.target[1] = ty; c.target[2] = tz;
    c.up[1] = 1;
    if (fabs(ey - ty) > 0.99 * sqrt((ex - tx) * (ex - tx) + (ey - ty) * (ey - ty) + (ez - tz) * (ez - tz))) {
        c.up[1] = 0;
        c.up[2] = -1;
    }
    c.ortho = 1;
    c.ortho_half_height = half;
    c.znear = 0.1;
    c.zfar = 100;
    c.width = W;
    c.height = H;
    return c;
}

/* Orthographic, half height 2 (96 px per unit): seen along the axis a
 * cylinder or a cone is a disc, seen across it a rectangle or a triangle.
 * Every pixel more than 1e-6 px from the outline must agree. */
TEST(exact_shapes_known_answers)
{
    static unsigned char m[W * H];
    const double ppu = H / 4.0;
    es_shape cyl = es_cylinder(0.2, -0.8, 0, 0, 1, 0, 1.1, 1.7), cone = es_cone(0.2, -0.8, 0, 0, 1, 0, 1.1, 1.7);
    int wrong[4] = { 0, 0, 0, 0 }, inside[4] = { 0, 0, 0, 0 };
    for (int s = 0; s < 2; s++) {
        const es_shape *sh = s ? &cone : &cyl;
        /* from above, down the axis */
        es_camera top = ortho_cam(0.2, 10, 0, 0.2, 0, 0, 2);
        es_mask(&top, sh, m);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                /* looking down -y with up -z: image x is world x, image y is world z */
                double wx = (x + 0.5 - W / 2.0) / ppu, wz = (y + 0.5 - H / 2.0) / ppu;
                double d = hypot(wx, wz) - 1.1;
                inside[s] += m[y * W + x];
                if (fabs(d) * ppu > 1e-6 && m[y * W + x] != (d < 0)) wrong[s]++;
            }
        /* from the side, along -z */
        es_camera side = ortho_cam(0, 0, 10, 0, 0, 0, 2);
        es_mask(&side, sh, m);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double wx = (x + 0.5 - W / 2.0) / ppu - 0.2, wy = -(y + 0.5 - H / 2.0) / ppu + 0.8;
                double half = s ? 1.1 * (1.7 - wy) / 1.7 : 1.1;        /* half width at height wy */
                double d = fmax(fmax(fabs(wx) - half, -wy), wy - 1.7);
                if (s) {
                    /* distance to the slanted side, not along x */
                    double ds = (fabs(wx) - half) * 1.7 / hypot(1.7, 1.1);
                    d = fmax(ds, fmax(-wy, wy - 1.7));
                }
                inside[2 + s] += m[y * W + x];
                if (fabs(d) * ppu > 1e-6 && m[y * W + x] != (d < 0)) wrong[2 + s]++;
            }
    }
    CHECKF(wrong[0] == 0 && wrong[1] == 0 && wrong[2] == 0 && wrong[3] == 0,
           "pixels wrong: cylinder top %d, cone top %d, cylinder side %d, cone side %d", wrong[0], wrong[1], wrong[2],
           wrong[3]);
    /* areas: pi 1.1^2, 2.2 x 1.7 and half that, in px^2 */
    double disc = PI * 1.1 * 1.1 * ppu * ppu, rect = 2.2 * 1.7 * ppu * ppu;
    CHECKF(fabs(inside[0] - disc) < 0.01 * disc && fabs(inside[1] - disc) < 0.01 * disc, "%d %d vs %.0f", inside[0],
           inside[1], disc);
    CHECKF(fabs(inside[2] - rect) < 0.01 * rect && fabs(inside[3] - rect / 2) < 0.01 * rect, "%d %d vs %.0f", inside[2],
           inside[3], rect);

    /* perspective, an oblique view: a ray through the middle of the cap
     * hits, one past the rim misses; behind the eye nothing is hit */
    es_camera p;
    memset(&p, 0, sizeof p);
    p.eye[0] = 0; p.eye[1] = 5; p.eye[2] = 5;
    p.target[1] = 1;
    p.up[1] = 1;
    p.fov_deg = 40;
    p.znear = 0.1;
    p.zfar = 100;
    p.width = W;
    p.height = H;
    es_shape c2 = es_cylinder(0, 0, 0, 0, 1, 0, 1, 2);
    CHECK(es_hit(&p, &c2, W / 2.0, H / 2.0));
    CHECK(!es_hit(&p, &c2, 2, 2) && !es_hit(&p, &c2, W - 2, H - 2));
    p.eye[2] = -5;                                      /* looking away from it */
    p.target[2] = -10;
    CHECK(!es_hit(&p, &c2, W / 2.0, H / 2.0));
}

/* ---- meshes from `silk gen` ------------------------------------------------------- */

static char *run_gen(const char *args, size_t *len)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s gen %s -o -", silk_path, args);
    FILE *fp = popen(cmd, "r");
    if (!fp) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) break;
        if (n == cap) {
            char *nb = realloc(buf, cap *= 2);
            if (!nb) { free(buf); buf = NULL; break; }
            buf = nb;
        }
        size_t got = fread(buf + n, 1, cap - n, fp);
        if (!got) break;
        n += got;
    }
    if (pclose(fp) != 0 || n == 0) { free(buf); return NULL; }
    *len = n;
    return buf;
}

typedef struct scene {
    const char *name;
    silk_mesh mesh;
    es_shape shape;
    double target_y;            /* the middle of the shape */
    double dist, half_height;   /* perspective eye distance, orthographic half height */
    double rim_y[2];            /* heights of the rims (cone: one) */
    int nrims;
    double el[4];               /* above, grazing, grazing, below (degrees) */
    int ok;
} scene;

static scene scenes[2];

static int load_scene(scene *s, const char *args)
{
    size_t len = 0;
    char *text = run_gen(args, &len);
    if (!text) {
        fprintf(stderr, "`%s gen %s -o -` failed (make tests builds it)\n", silk_path, args);
        return 0;
    }
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    silk_status st = silk_load_obj(text, len, s->name, &o, &arena, &s->mesh, &err);
    free(text);
    if (st != SILK_OK) fprintf(stderr, "%s\n", err.msg);
    return s->ok = st == SILK_OK;
}

/* The two meshes, as `silk gen` writes them. */
TEST(gen_meshes)
{
    static uint8_t *buf;
    size_t size = 8u << 20;
    buf = malloc(size);
    if (!buf) return;
    silk_arena_init(&arena, buf, size);

    scene *c = &scenes[0];
    c->name = "cylinder";
    c->shape = es_cylinder(0, 0, 0, 0, 1, 0, 1, 2);
    c->target_y = 1;
    c->dist = 6;
    c->half_height = 1.9;
    c->nrims = 2;
    c->rim_y[0] = 2;
    c->rim_y[1] = 0;
    /* grazing: from 6 units away the eye is about 2.4 degrees off the plane of a cap */
    c->el[0] = 35; c->el[1] = 12; c->el[2] = -12; c->el[3] = -35;
    if (load_scene(c, "cylinder")) CHECK(c->mesh.ntris == 96 && c->mesh.nfeature_edges == 48);

    scene *k = &scenes[1];
    k->name = "cone";
    k->shape = es_cone(0, 0, 0, 0, 1, 0, 1, 1.5);
    k->target_y = 0.6;
    k->dist = 5;
    k->half_height = 1.5;
    k->nrims = 1;
    k->rim_y[0] = 0;
    /* grazing the base: the eye 1.3 degrees above it, then 1.8 below */
    k->el[0] = 35; k->el[1] = -6; k->el[2] = -8; k->el[3] = -35;
    if (load_scene(k, "cone")) CHECK(k->mesh.ntris == 70 && k->mesh.nfeature_edges == 35);
}

/* ---- rendering and measuring ------------------------------------------------------- */

static silk_fx fx(double v) { return (silk_fx)floor(v * 65536.0 + 0.5); }

/* View (e, a): elevation s->el[e], azimuth 47 a + 11.3 degrees (so that no
 * two views see the mesh alike), looking at the middle of the shape; zoomed
 * in `zoom` times around aim (perspective: the eye turns towards it;
 * orthographic: the view slides to it). */
static void view_camera(const scene *s, int ortho, int e, int a, double zoom, const double aim[3], silk_camera *cam)
{
    double az = (47.0 * a + 11.3) * PI / 180, el = s->el[e] * PI / 180;
    double dir[3] = { cos(el) * sin(az), sin(el), cos(el) * cos(az) };
    double D = ortho ? 10 : s->dist, t[3] = { 0, s->target_y, 0 };
    if (zoom > 1)
        for (int i = 0; i < 3; i++) t[i] = aim[i];
    double eye[3] = { dir[0] * D, s->target_y + dir[1] * D, dir[2] * D };
    if (ortho && zoom > 1)
        for (int i = 0; i < 3; i++) eye[i] += aim[i] - (i == 1 ? s->target_y : 0);
    memset(cam, 0, sizeof *cam);
    cam->eye = silk_v3(fx(eye[0]), fx(eye[1]), fx(eye[2]));
    cam->target = silk_v3(fx(t[0]), fx(t[1]), fx(t[2]));
    cam->up = silk_v3(0, SILK_FX_ONE, 0);
    cam->ortho = ortho;
    cam->fov_deg = fx(2 * atan(tan(20 * PI / 180) / zoom) * 180 / PI);
    cam->ortho_half_height = fx(s->half_height / zoom);
    cam->znear = fx(0.1);
    cam->zfar = fx(100);
    cam->width = W;
    cam->height = H;
}

static int render_mask(const scene *s, const silk_camera *cam, silk_mode mode, unsigned char *mask)
{
    silk_view v;
    silk_error err;
    if (silk_view_init(&v, cam, &err) != SILK_OK) return -1;
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;   /* the outline by pixel centres (test_aa measures anti-aliasing) */
    o.mode = mode;
    o.bg_rgb = BG;
    silk_frame_stats fs;
    if (silk_render(&arena, &s->mesh, &v, &hal, &o, &t, &fs, &err) != SILK_OK || fs.fell_back) return -1;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) mask[y * W + x] = silk_target_get(&t, x, y) != BG;
    return 0;
}

static void dump(const char *tag, const unsigned char *m)
{
    if (!dump_dir) return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.pgm", dump_dir, tag);
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fprintf(f, "P5\n%d %d\n255\n", W, H);
    for (int i = 0; i < W * H; i++) fputc(m[i] ? 255 : 0, f);
    fclose(f);
}

/* Project p with the exact camera (as exact_silhouette.c's rays do). */
static void project(const es_camera *c, const double p[3], double *x, double *y)
{
    double f[3], s[3], u[3], d[3];
    for (int i = 0; i < 3; i++) {
        f[i] = c->target[i] - c->eye[i];
        d[i] = p[i] - c->eye[i];
    }
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++) f[i] /= fl;
    s[0] = f[1] * c->up[2] - f[2] * c->up[1];
    s[1] = f[2] * c->up[0] - f[0] * c->up[2];
    s[2] = f[0] * c->up[1] - f[1] * c->up[0];
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int i = 0; i < 3; i++) s[i] /= sl;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    double h = c->ortho ? c->ortho_half_height : tan(c->fov_deg * PI / 360);
    double z = c->ortho ? 1 : d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    double nx = (d[0] * s[0] + d[1] * s[1] + d[2] * s[2]) / (z * h * c->width / c->height);
    double ny = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / (z * h);
    *x = (nx + 1) * c->width / 2;
    *y = (1 - ny) * c->height / 2;
}

/* The point of a rim farthest down (or, when that is not on the outline,
 * farthest up) in the image: where the zoomed views look. */
static void rim_aim(const scene *s, const es_camera *c, double aim[3])
{
    double best[2] = { -1e9, 1e9 }, pt[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
    for (int r = 0; r < s->nrims; r++)
        for (int i = 0; i < 3600; i++) {
            double phi = 2 * PI * i / 3600, p[3] = { cos(phi), s->rim_y[r], sin(phi) }, x, y;
            project(c, p, &x, &y);
            if (y > best[0]) { best[0] = y; memcpy(pt[0], p, sizeof p); }
            if (y < best[1]) { best[1] = y; memcpy(pt[1], p, sizeof p); }
        }
    double x, y;
    project(c, pt[0], &x, &y);
    int down_on_outline = !es_hit(c, &s->shape, x, y + 2);
    memcpy(aim, pt[down_on_outline ? 0 : 1], 3 * sizeof *aim);
}

/* Which outline samples lie within 2 px of a rim (the projected circles). */
static void rim_samples(const scene *s, const es_camera *c, const es_points *pts, unsigned char *near_rim)
{
    static unsigned char grid[W * H];
    memset(grid, 0, sizeof grid);
    for (int r = 0; r < s->nrims; r++)
        for (int i = 0; i < 4000; i++) {
            double phi = 2 * PI * i / 4000, p[3] = { cos(phi), s->rim_y[r], sin(phi) }, x, y;
            project(c, p, &x, &y);
            for (int yy = (int)floor(y) - 2; yy <= (int)floor(y) + 2; yy++)
                for (int xx = (int)floor(x) - 2; xx <= (int)floor(x) + 2; xx++)
                    if (xx >= 0 && yy >= 0 && xx < W && yy < H && hypot(xx + 0.5 - x, yy + 0.5 - y) <= 2.5)
                        grid[yy * W + xx] = 1;
        }
    for (int i = 0; i < pts->n; i++) {
        int x = (int)floor(pts->x[i]), y = (int)floor(pts->y[i]);
        near_rim[i] = x >= 0 && y >= 0 && x < W && y < H && grid[y * W + x];
    }
}

typedef struct tally {
    int views;
    double sum_mean, worst_mean, worst_max, worst_rim, sum_rim;
    long rim_samples;
} tally;

TEST(rims_smooth)
{
    static unsigned char exact[W * H], got[W * H], near_rim[2 * W * H];
    static double off[2 * W * H];
    static const char *const el_name[4] = { "above", "grazing", "grazing", "below" };
    es_points pts;
    memset(&pts, 0, sizeof pts);
    for (int si = 0; si < 2; si++) {
        scene *s = &scenes[si];
        CHECKF(s->ok, "%s did not load", s->name);
        if (!s->ok) continue;
        tally t[2][2][2];                       /* [zoomed][ortho][mode] */
        memset(t, 0, sizeof t);
        for (int zoomed = 0; zoomed < 2; zoomed++)
        for (int ortho = 0; ortho < 2; ortho++)
            for (int e = 0; e < 4; e++)
                for (int a = 0; a < 3; a++) {
                    silk_camera cam;
                    es_camera ec;
                    double aim[3] = { 0, 0, 0 };
                    view_camera(s, ortho, e, a, 1, aim, &cam);
                    if (zoomed) {
                        es_camera_from_silk(&ec, &cam);
                        rim_aim(s, &ec, aim);
                        view_camera(s, ortho, e, a, ZOOM, aim, &cam);
                    }
                    es_camera_from_silk(&ec, &cam);
                    es_mask(&ec, &s->shape, exact);
                    int n = es_silhouette_points(&ec, &s->shape, exact, &pts);
                    CHECK(n > 100 && n <= 2 * W * H);
                    if (n <= 0 || n > 2 * W * H) continue;
                    rim_samples(s, &ec, &pts, near_rim);
                    for (int mode = 0; mode < 2; mode++) {
                        char tag[96];
                        snprintf(tag, sizeof tag, "%s-%s-%s%d-az%d%s-%s", s->name, ortho ? "ortho" : "persp",
                                 el_name[e], e, a, zoomed ? "-zoom" : "", mode ? "smooth" : "flat");
                        if (render_mask(s, &cam, mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT, got)) {
                            CHECKF(0, "%s: render failed or fell back", tag);
                            continue;
                        }
                        dump(tag, got);
                        es_stats st;
                        CHECK(es_compare(got, exact, &pts, W, H, &st) == 0 && es_offsets(got, &pts, W, H, off) == 0);
                        double rim_worst = 0, rim_sum = 0;
                        long rim_n = 0;
                        for (int i = 0; i < n; i++)
                            if (near_rim[i]) {
                                rim_worst = fmax(rim_worst, fabs(off[i]));
                                rim_sum += fabs(off[i]);
                                rim_n++;
                            }
                        tally *tt = &t[zoomed][ortho][mode];
                        tt->views++;
                        tt->sum_mean += st.mean_error;
                        tt->worst_mean = fmax(tt->worst_mean, st.mean_error);
                        tt->worst_max = fmax(tt->worst_max, st.max_dist);
                        tt->worst_rim = fmax(tt->worst_rim, rim_worst);
                        tt->sum_rim += rim_sum;
                        tt->rim_samples += rim_n;
                        if (mode && (st.mean_error > SMOOTH_MEAN_BOUND || st.max_dist > SMOOTH_MAX_BOUND ||
                                     rim_worst > SMOOTH_RIM_BOUND))
                            fprintf(stderr, "  %s: mean %.3f px, max %.2f px, rim offset up to %.2f px\n", tag,
                                    st.mean_error, st.max_dist, rim_worst);
                    }
                    if (dump_dir) {
                        char tag[96];
                        snprintf(tag, sizeof tag, "%s-%s-%s%d-az%d%s-exact", s->name, ortho ? "ortho" : "persp",
                                 el_name[e], e, a, zoomed ? "-zoom" : "");
                        dump(tag, exact);
                    }
                }
        for (int zoomed = 0; zoomed < 2; zoomed++)
        for (int ortho = 0; ortho < 2; ortho++) {
            for (int mode = 0; mode < 2; mode++) {
                tally *tt = &t[zoomed][ortho][mode];
                printf("  %-8s %-5s %-3s %-6s mean %.3f px (worst %.3f), max %.2f px; rims: mean |offset| %.3f px, "
                       "max %.2f px (%ld samples), %d views\n",
                       s->name, ortho ? "ortho" : "persp", zoomed ? "x4" : "x1", mode ? "smooth" : "flat",
                       tt->sum_mean / tt->views, tt->worst_mean, tt->worst_max,
                       tt->rim_samples ? tt->sum_rim / tt->rim_samples : 0, tt->worst_rim, tt->rim_samples, tt->views);
            }
            tally *f = &t[zoomed][ortho][0], *m = &t[zoomed][ortho][1];
            char pr[16];
            snprintf(pr, sizeof pr, "%s %s", ortho ? "ortho" : "persp", zoomed ? "x4" : "x1");
            CHECKF(m->views == 12 && m->rim_samples > 1000, "%s %s: %d views, %ld rim samples", s->name, pr, m->views,
                   m->rim_samples);
            CHECKF(m->worst_mean <= SMOOTH_MEAN_BOUND, "%s %s smooth: worst mean %.3f px", s->name, pr, m->worst_mean);
            CHECKF(m->worst_max <= SMOOTH_MAX_BOUND, "%s %s smooth: max %.2f px", s->name, pr, m->worst_max);
            CHECKF(m->worst_rim <= SMOOTH_RIM_BOUND && m->sum_rim <= SMOOTH_RIM_MEAN * m->rim_samples,
                   "%s %s smooth: rim offset up to %.2f px, mean %.3f px", s->name, pr, m->worst_rim,
                   m->sum_rim / m->rim_samples);
            if (zoomed)
                CHECKF(f->sum_mean >= FLAT_RATIO * m->sum_mean && f->worst_rim > m->worst_rim && f->sum_rim > m->sum_rim,
                       "%s %s: flat (mean %.3f, rim max %.2f) not clearly worse than smooth (mean %.3f, rim max %.2f)",
                       s->name, pr, f->sum_mean / f->views, f->worst_rim, m->sum_mean / m->views, m->worst_rim);
            else
                CHECKF(m->sum_mean <= f->sum_mean && m->worst_rim <= f->worst_rim,
                       "%s %s: smooth (mean %.3f, rim max %.2f) worse than flat (mean %.3f, rim max %.2f)", s->name, pr,
                       m->sum_mean / m->views, m->worst_rim, f->sum_mean / f->views, f->worst_rim);
        }
    }
    es_points_free(&pts);
}

int main(int argc, char **argv)
{
    /* BUILD/tests/test_rims -> BUILD/silk */
    const char *slash = argc > 0 ? strrchr(argv[0], '/') : NULL;
    if (slash && slash - argv[0] >= 6 && !strncmp(slash - 6, "/tests", 6))
        snprintf(silk_path, sizeof silk_path, "%.*s/silk", (int)(slash - 6 - argv[0]), argv[0]);
    /* The CLI is a host tool: a board configuration's tests use the host's. */
    if (getenv("SILK") && *getenv("SILK")) snprintf(silk_path, sizeof silk_path, "%s", getenv("SILK"));
    dump_dir = getenv("SILK_RIMS_DUMP");
    RUN(exact_shapes_known_answers);
    RUN(gen_meshes);
    RUN(rims_smooth);
    return check_done();
}
