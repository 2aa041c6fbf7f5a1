/*
 * test_silhouette_accuracy.c - how close
 * silk's silhouettes come to the true outline of the surface a coarse mesh
 * samples.
 *
 * A 200-triangle UV sphere (radius 1; 10 segments around, 11 bands pole to
 * pole) and a 576-triangle torus (R = 1, r = 0.4; 24 x 12, axis y) are
 * built here with their vertices on the analytic surfaces, rendered at
 * 512x512 through the public API from 36 views around them, in perspective
 * and orthographic projection, in FLAT and SMOOTH mode.  Each object mask
 * (pixels not of the background colour) is compared with the exact mask of
 * the analytic surface (tests/support/exact_silhouette.c, ray cast in
 * double):
 *   mean error = differing pixels / boundary pixels of the exact mask (px)
 *   max error  = largest distance of a differing pixel from the true
 *                silhouette (px)
 * Smooth mode must keep every view's mean <= 0.35 px and max <= 2 px; flat
 * mode is reported (the paper shows a few px for these meshes) and must be
 * clearly worse.  Also: a 0.5-degree move of the eye (about the axis both
 * shapes are symmetric about, so the true outline does not move) moves no
 * rendered silhouette pixel by more than 1.5 px, and the bounds hold zoomed
 * in 8x on a silhouette.
 *
 * The first tests check the harness itself on cases with known answers.
 *
 * SILK_ACCURACY_VIEWS=N changes the number of views (default 36; under
 * sanitizers, SILK_SAN=1, 12).  SILK_ACCURACY_DUMP=dir writes each compared
 * mask pair as PGM for inspection.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "support/exact_silhouette.h"

#define PI 3.14159265358979323846
#define W 512
#define H 512
#define BG 0xFF00FFu              /* magenta: Phong of a grey-blue material never makes it */

#define SMOOTH_MEAN_BOUND 0.35
#define SMOOTH_MAX_BOUND 2.0
/* Zoomed 8x, the reconstructed curve's own small deviation from the true
 * surface (about 0.1 px unzoomed) is magnified 8x; what must not come back
 * is the polygon: the max error stays under SMOOTH_MAX_BOUND because the
 * sample count grows with the projected size, and the mean stays a small
 * fraction of flat mode's. */
#define ZOOM_MEAN_BOUND 1.25
#define ZOOM_FLAT_RATIO 10.0
#define MOVE_BOUND 1.5

/* ---- harness self-tests ------------------------------------------------------- */

static es_camera make_cam(int ortho, double eye_x, double eye_y, double eye_z, double size)
{
    es_camera c;
    memset(&c, 0, sizeof c);
    c.eye[0] = eye_x; c.eye[1] = eye_y; c.eye[2] = eye_z;
    c.up[1] = 1;
    c.ortho = ortho;
    c.fov_deg = size;
    c.ortho_half_height = size;
    c.znear = 0.1;
    c.zfar = 100;
    c.width = W;
    c.height = H;
    return c;
}

static long mask_count(const unsigned char *m)
{
    long n = 0;
    for (int i = 0; i < W * H; i++) n += m[i];
    return n;
}

/* Orthographic, looking down -z: a sphere is a disk, a torus with axis z an
 * annulus, a torus with axis y a "stadium" (points within r of a segment of
 * length 2R); perspective: a sphere is the cone of rays within asin(rad/D)
 * of the direction to its centre.  The masks must match these closed forms
 * at every pixel not within 1e-6 px of the outline. */
TEST(harness_masks)
{
    static unsigned char m[W * H];
    double hh = 2.0, ppu = H / (2 * hh);             /* pixels per unit */
    es_camera c = make_cam(1, 0.3, -0.2, 10, hh);
    c.target[0] = 0.3;
    c.target[1] = -0.2;
    es_shape sph = es_sphere(0.3 + 0.4, -0.2 - 0.25, 0, 1.1);
    es_shape tz = es_torus(0.3, -0.2, 0, 0, 0, 1, 1.0, 0.4);
    es_shape ty = es_torus(0.3, -0.2, 0, 0, 1, 0, 1.0, 0.4);
    int wrong[4] = { 0, 0, 0, 0 };
    es_mask(&c, &sph, m);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dx = (x + 0.5 - W / 2.0) / ppu - 0.4, dy = -(y + 0.5 - H / 2.0) / ppu + 0.25;
            double d = hypot(dx, dy) - 1.1;
            if (fabs(d) * ppu > 1e-6 && m[y * W + x] != (d < 0)) wrong[0]++;
        }
    es_mask(&c, &tz, m);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dx = (x + 0.5 - W / 2.0) / ppu, dy = -(y + 0.5 - H / 2.0) / ppu;
            double d = fabs(hypot(dx, dy) - 1.0) - 0.4;
            if (fabs(d) * ppu > 1e-6 && m[y * W + x] != (d < 0)) wrong[1]++;
        }
    es_mask(&c, &ty, m);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dx = (x + 0.5 - W / 2.0) / ppu, dy = -(y + 0.5 - H / 2.0) / ppu;
            double sx = dx < -1 ? -1 : (dx > 1 ? 1 : dx);
            double d = hypot(dx - sx, dy) - 0.4;
            if (fabs(d) * ppu > 1e-6 && m[y * W + x] != (d < 0)) wrong[2]++;
        }
    /* perspective sphere off the view axis */
    es_camera p = make_cam(0, 0.5, 0.8, 6, 40);
    p.target[0] = 0.2;
    es_shape s2 = es_sphere(-0.6, 0.3, 0.5, 0.9);
    es_mask(&p, &s2, m);
    double f[3] = { p.target[0] - p.eye[0], p.target[1] - p.eye[1], p.target[2] - p.eye[2] };
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++) f[k] /= fl;
    double s[3] = { f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0 };   /* f x up */
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; k++) s[k] /= sl;
    double u[3] = { s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0] };
    double to[3] = { s2.centre[0] - p.eye[0], s2.centre[1] - p.eye[1], s2.centre[2] - p.eye[2] };
    double D = sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
    double half = asin(0.9 / D), t = tan(20 * PI / 180);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double nx = (x + 0.5) * 2 / W - 1, ny = 1 - (y + 0.5) * 2 / H;
            double r[3], rl = 0, dt = 0;
            for (int k = 0; k < 3; k++) {
                r[k] = f[k] + s[k] * nx * t + u[k] * ny * t;
                rl += r[k] * r[k];
                dt += r[k] * to[k];
            }
            double ang = acos(fmin(1, dt / (sqrt(rl) * D)));
            /* 1e-6 px in angle: t * 2 / H radians per pixel at the centre */
            if (fabs(ang - half) > 1e-6 * 2 * t / H && m[y * W + x] != (ang < half)) wrong[3]++;
        }
    CHECKF(wrong[0] == 0 && wrong[1] == 0 && wrong[2] == 0 && wrong[3] == 0,
           "pixels wrong: sphere %d, torus z %d, torus y %d, perspective sphere %d", wrong[0], wrong[1], wrong[2], wrong[3]);
    CHECK(mask_count(m) > 1000);
}

/* A perspective torus from an oblique view against brute force: the
 * implicit function sampled densely along each ray (every 1e-4 units, then
 * refined around the smallest sample).  Only rays that clear the surface by
 * more than 1e-7 either way are compared. */
TEST(harness_torus_brute)
{
    es_camera c = make_cam(0, 2.1, 2.7, 4.2, 40);
    es_shape t = es_torus(0.1, -0.1, 0.2, 0.3, 1, -0.2, 1.0, 0.4);
    int compared = 0, wrong = 0, hits = 0;
    for (int i = 0; i < 600; i++) {
        double px = check_uniform(0, W), py = check_uniform(0, H);
        /* the ray, as the harness builds it */
        double f[3] = { -c.eye[0], -c.eye[1], -c.eye[2] };
        double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        for (int k = 0; k < 3; k++) f[k] /= fl;
        double s[3] = { -f[2], 0, f[0] };
        double sl = sqrt(s[0] * s[0] + s[2] * s[2]);
        s[0] /= sl; s[2] /= sl;
        double u[3] = { s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0] };
        double tn = tan(20 * PI / 180), nx = 2 * px / W - 1, ny = 1 - 2 * py / H;
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = f[k] + s[k] * nx * tn + u[k] * ny * tn;
        double best = 1e9, bt = 0, dc = sqrt(4.2 * 4.2 + 2.1 * 2.1 + 2.7 * 2.7) / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double tt = dc - 1.6; tt < dc + 1.6; tt += 1e-4) {
            double q[3], qa = 0, qq = 0;
            for (int k = 0; k < 3; k++) q[k] = c.eye[k] + tt * d[k] - t.centre[k];
            for (int k = 0; k < 3; k++) { qa += q[k] * t.axis[k]; qq += q[k] * q[k]; }
            double rho = sqrt(fmax(0, qq - qa * qa));
            double v = hypot(rho - t.R, qa) - t.r;
            if (v < best) { best = v; bt = tt; }
        }
        /* golden-section refinement of the minimum */
        double a = bt - 2e-4, b = bt + 2e-4;
        for (int it = 0; it < 60; it++) {
            double m1 = b - (b - a) * 0.618, m2 = a + (b - a) * 0.618, v1, v2;
            double q[3], qa, qq;
            qa = qq = 0;
            for (int k = 0; k < 3; k++) q[k] = c.eye[k] + m1 * d[k] - t.centre[k];
            for (int k = 0; k < 3; k++) { qa += q[k] * t.axis[k]; qq += q[k] * q[k]; }
            v1 = hypot(sqrt(fmax(0, qq - qa * qa)) - t.R, qa) - t.r;
            qa = qq = 0;
            for (int k = 0; k < 3; k++) q[k] = c.eye[k] + m2 * d[k] - t.centre[k];
            for (int k = 0; k < 3; k++) { qa += q[k] * t.axis[k]; qq += q[k] * q[k]; }
            v2 = hypot(sqrt(fmax(0, qq - qa * qa)) - t.R, qa) - t.r;
            if (v1 < v2) b = m2;
            else a = m1;
            if (fmin(v1, v2) < best) best = fmin(v1, v2);
        }
        if (fabs(best) < 1e-7) continue;
        compared++;
        hits += best < 0;
        if (es_hit(&c, &t, px, py) != (best < 0)) wrong++;
    }
    CHECKF(wrong == 0, "%d of %d rays disagree with brute force", wrong, compared);
    CHECKF(compared > 550 && hits > 50 && hits < compared - 50, "compared %d, hits %d", compared, hits);
}

/* Shifted by (dx, dy), the border pixels repeated into the gap. */
static void shift_mask(const unsigned char *in, unsigned char *out, int dx, int dy)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int sx = x - dx, sy = y - dy;
            sx = sx < 0 ? 0 : (sx >= W ? W - 1 : sx);
            sy = sy < 0 ? 0 : (sy >= H ? H - 1 : sy);
            out[y * W + x] = in[sy * W + sx];
        }
}

/* The measures on masks with known answers. */
TEST(harness_measures)
{
    static unsigned char exact[W * H], test[W * H];
    es_stats st;
    es_points pts;
    memset(&pts, 0, sizeof pts);

    /* a straight edge: rows above y = 200.3 (a sphere so large its outline
     * is straight to 1e-4 px across the image) */
    es_camera c = make_cam(1, 0, 0, 1000, H / 2.0);  /* 1 unit = 1 px */
    c.zfar = 1e10;
    es_shape big = es_sphere(0, 1e9 + 56 - 0.3, 0, 1e9);   /* bottom at y = 256 - 56 + 0.3 px */
    es_mask(&c, &big, exact);
    CHECK(es_silhouette_points(&c, &big, exact, &pts) == W);
    double ydev = 0;
    for (int i = 0; i < pts.n; i++) ydev = fmax(ydev, fabs(pts.y[i] - 200.3));
    CHECKF(ydev < 1e-4, "straight outline sampled at y off by %g", ydev);
    CHECK(es_compare(exact, exact, &pts, W, H, &st) == 0);
    CHECK(st.differing == 0 && st.mean_error == 0 && st.max_dist == 0 && st.boundary == W);
    /* the outline at 200.3 lies in row 200, outside: 0.3 px beyond the mask's edge at 200 */
    CHECKF(fabs(st.mean_offset + 0.3) < 1e-4 && fabs(st.max_abs_offset - 0.3) < 1e-4, "%g %g", st.mean_offset, st.max_abs_offset);
    shift_mask(exact, test, 0, 1);                    /* one pixel down: one row more */
    es_compare(test, exact, &pts, W, H, &st);
    CHECKF(st.differing == W && st.extra == W && fabs(st.mean_error - 1) < 1e-12, "%ld %g", st.differing, st.mean_error);
    CHECKF(fabs(st.max_dist - 0.2) < 1e-4, "max %g: row 200's centres are 0.2 px below the edge", st.max_dist);
    CHECKF(fabs(st.mean_offset - 0.7) < 1e-4, "offset %g", st.mean_offset);
    shift_mask(exact, test, 0, -3);                   /* three up: three rows fewer */
    es_compare(test, exact, &pts, W, H, &st);
    CHECKF(st.missing == 3 * W && fabs(st.mean_error - 3) < 1e-12, "%ld %g", st.missing, st.mean_error);
    CHECKF(fabs(st.max_dist - 2.8) < 1e-4 && fabs(st.mean_offset + 3.3) < 1e-4, "%g %g", st.max_dist, st.mean_offset);
    CHECKF(es_boundary_hausdorff(test, exact, W, H) == 3, "%g", es_boundary_hausdorff(test, exact, W, H));

    /* a disk of radius 150 px */
    es_shape disk = es_sphere(0.2, -0.1, 0, 150);
    es_mask(&c, &disk, exact);
    int n = es_silhouette_points(&c, &disk, exact, &pts);
    double rdev = 0;
    for (int i = 0; i < n; i++) rdev = fmax(rdev, fabs(hypot(pts.x[i] - 256.2, pts.y[i] - 256.1) - 150));
    CHECKF(rdev < 1e-5, "samples off the circle by %g px", rdev);
    CHECK(n > 4 * 150 * 1.4 && n < 8 * 150 * 1.05);
    es_compare(exact, exact, &pts, W, H, &st);
    CHECK(st.differing == 0 && st.max_abs_offset <= 0.5 + 1e-9 && fabs(st.mean_offset) < 0.05);
    for (int k = 1; k <= 4; k++) {
        shift_mask(exact, test, k, 0);
        es_compare(test, exact, &pts, W, H, &st);
        /* a sideways shift by k moves the outline by k |cos| along its
         * normal: mean 2k/pi over the length, and the differing pixels are
         * 4k r while the boundary has 4 sqrt2 r pixels (an 8-connected
         * curve of a disk) */
        CHECKF(fabs(st.mean_error - k / sqrt(2.0)) < 0.02 * k, "shift %d: mean %g", k, st.mean_error);
        CHECKF(st.max_dist <= k + 1e-6 && st.max_dist > k - 0.5, "shift %d: max %g", k, st.max_dist);
        /* ... plus the staircase's own up-to-half-pixel steps */
        CHECKF(fabs(st.mean_abs_offset - 2 * k / PI) < 0.25, "shift %d: mean |offset| %g", k, st.mean_abs_offset);
        double hd = es_boundary_hausdorff(test, exact, W, H);
        CHECKF(hd <= k + 1e-9 && hd > k - 0.5, "shift %d: Hausdorff %g", k, hd);
    }
    /* grown by one pixel (4-neighbour dilation): about one pixel everywhere */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int i = y * W + x;
            test[i] = exact[i] || (x > 0 && exact[i - 1]) || (x + 1 < W && exact[i + 1]) ||
                      (y > 0 && exact[i - W]) || (y + 1 < H && exact[i + W]);
        }
    es_compare(test, exact, &pts, W, H, &st);
    CHECKF(st.missing == 0 && st.mean_error > 0.9 && st.mean_error < 1.2, "dilated: mean %g", st.mean_error);
    CHECKF(st.mean_offset > 0.6 && st.mean_offset < 1.4 && st.max_dist <= 1.5, "dilated: offset %g max %g", st.mean_offset, st.max_dist);
    /* empty test mask */
    memset(test, 0, sizeof test);
    es_compare(test, exact, &pts, W, H, &st);
    CHECK(st.missing == mask_count(exact) && st.max_dist > 140);
    CHECK(es_boundary_hausdorff(test, exact, W, H) >= 1e9);
    es_points_free(&pts);
}

/* ---- the meshes ------------------------------------------------------------------ */

typedef struct dmesh {
    int nv, nt;
    double v[300][3];
    int t[600][3];
} dmesh;

/* Orient every triangle counter-clockwise seen from outside: its normal
 * must point away from the surface's inner core (the centre for the sphere,
 * the tube's centre circle for the torus). */
static void orient(dmesh *m, int torus, double R)
{
    for (int i = 0; i < m->nt; i++) {
        double *a = m->v[m->t[i][0]], *b = m->v[m->t[i][1]], *c = m->v[m->t[i][2]];
        double e1[3], e2[3], n[3], g[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = b[k] - a[k];
            e2[k] = c[k] - a[k];
            g[k] = (a[k] + b[k] + c[k]) / 3;
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        if (torus) {                                   /* minus the core point (axis y) */
            double rho = hypot(g[0], g[2]);
            g[0] -= g[0] / rho * R;
            g[2] -= g[2] / rho * R;
        }
        if (n[0] * g[0] + n[1] * g[1] + n[2] * g[2] < 0) {
            int s = m->t[i][1];
            m->t[i][1] = m->t[i][2];
            m->t[i][2] = s;
        }
    }
}

/* UV sphere: poles on the y axis, `bands` bands from pole to pole,
 * `segs` segments around: 2 segs (bands - 1) triangles. */
static void uv_sphere(dmesh *m, int segs, int bands, double r)
{
    m->nv = 0;
    m->nt = 0;
    m->v[m->nv][0] = 0; m->v[m->nv][1] = r; m->v[m->nv][2] = 0; m->nv++;
    for (int b = 1; b < bands; b++) {
        double th = PI * b / bands;
        for (int s = 0; s < segs; s++) {
            double ph = 2 * PI * s / segs;
            m->v[m->nv][0] = r * sin(th) * cos(ph);
            m->v[m->nv][1] = r * cos(th);
            m->v[m->nv][2] = r * sin(th) * sin(ph);
            m->nv++;
        }
    }
    m->v[m->nv][0] = 0; m->v[m->nv][1] = -r; m->v[m->nv][2] = 0; m->nv++;
    int south = m->nv - 1;
    for (int s = 0; s < segs; s++) {
        int s1 = (s + 1) % segs;
        m->t[m->nt][0] = 0; m->t[m->nt][1] = 1 + s; m->t[m->nt][2] = 1 + s1; m->nt++;
        int base = 1 + (bands - 2) * segs;
        m->t[m->nt][0] = south; m->t[m->nt][1] = base + s; m->t[m->nt][2] = base + s1; m->nt++;
        for (int b = 0; b + 2 < bands; b++) {
            int a0 = 1 + b * segs + s, a1 = 1 + b * segs + s1, c0 = a0 + segs, c1 = a1 + segs;
            m->t[m->nt][0] = a0; m->t[m->nt][1] = c0; m->t[m->nt][2] = c1; m->nt++;
            m->t[m->nt][0] = a0; m->t[m->nt][1] = c1; m->t[m->nt][2] = a1; m->nt++;
        }
    }
    orient(m, 0, 0);
}

/* Torus about the y axis: nu segments around the axis, nv around the tube. */
static void torus(dmesh *m, int nu, int nv, double R, double r)
{
    m->nv = 0;
    m->nt = 0;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 2 * PI * i / nu, v = 2 * PI * j / nv;
            m->v[m->nv][0] = (R + r * cos(v)) * cos(u);
            m->v[m->nv][1] = r * sin(v);
            m->v[m->nv][2] = (R + r * cos(v)) * sin(u);
            m->nv++;
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            int a = i * nv + j, b = ((i + 1) % nu) * nv + j;
            int c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
            m->t[m->nt][0] = a; m->t[m->nt][1] = b; m->t[m->nt][2] = c; m->nt++;
            m->t[m->nt][0] = a; m->t[m->nt][1] = c; m->t[m->nt][2] = d; m->nt++;
        }
    orient(m, 1, R);
}

static silk_fx fx(double v) { return (silk_fx)floor(v * 65536.0 + 0.5); }

static int build_mesh(const dmesh *d, silk_arena *a, silk_mesh *m)
{
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = (uint32_t)d->nv;
    in.ntris = (uint32_t)d->nt;
    in.pos = silk_arena_array(a, in.nverts, sizeof *in.pos, SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 3 * in.ntris, sizeof *in.tri, SILK_MEM_MESH);
    if (!in.pos || !in.tri) return -1;
    for (int i = 0; i < d->nv; i++) in.pos[i] = silk_v3(fx(d->v[i][0]), fx(d->v[i][1]), fx(d->v[i][2]));
    for (int i = 0; i < d->nt; i++)
        for (int k = 0; k < 3; k++) in.tri[3 * i + k] = (silk_index)d->t[i][k];
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_mesh_build(&in, "test mesh", &o, a, m, &err);
    if (st != SILK_OK) {
        fprintf(stderr, "silk_mesh_build: %s\n", err.msg);
        return -1;
    }
    return 0;
}

TEST(meshes_as_specified)
{
    static dmesh d;
    uv_sphere(&d, 10, 11, 1.0);
    CHECK(d.nt == 200 && d.nv == 102);
    double vol = 0;
    for (int i = 0; i < d.nt; i++) {
        double *a = d.v[d.t[i][0]], *b = d.v[d.t[i][1]], *c = d.v[d.t[i][2]];
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    }
    CHECKF(vol > 3.0 && vol < 4 * PI / 3, "sphere volume %g", vol);
    torus(&d, 24, 12, 1.0, 0.4);
    CHECK(d.nt == 576 && d.nv == 288);
    vol = 0;
    for (int i = 0; i < d.nt; i++) {
        double *a = d.v[d.t[i][0]], *b = d.v[d.t[i][1]], *c = d.v[d.t[i][2]];
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    }
    CHECKF(vol > 2.6 && vol < 2 * PI * PI * 0.16, "torus volume %g", vol);
}

/* ---- rendering and measuring ------------------------------------------------------- */

typedef struct scene {
    const char *name;
    silk_mesh mesh;
    es_shape shape;
    double dist;               /* eye distance from the centre (perspective) */
    double half_height;        /* orthographic */
} scene;

static silk_arena arena;
static unsigned char color[W * H * 3];
static uint32_t depth[W * H];
static const char *dump_dir;

/* The camera of view k of n: azimuth about y in 10-degree steps (plus a
 * phase, so mesh edges do not line up with the view), elevation sweeping
 * from -70 to +70 degrees. */
static void view_camera(const scene *sc, int ortho, int k, int n, double extra_az, double zoom, double aim_px,
                        silk_camera *cam)
{
    double az = (360.0 * k / n + 3.7 + extra_az) * PI / 180;
    double el = (-70 + 140 * (k + 0.5) / n) * PI / 180;
    double dir[3] = { cos(el) * sin(az), sin(el), cos(el) * cos(az) };
    double D = ortho ? 10 : sc->dist;
    double eye[3], target[3] = { 0, 0, 0 };
    /* Aim at the point aim_px to the right of the centre of the unzoomed
     * image (the zoom test puts the outline in the middle): perspective
     * turns the camera towards it, orthographic slides sideways. */
    double right[3] = { cos(az), 0, -sin(az) };       /* forward x up, forward = -dir */
    double units = ortho ? aim_px * 2 * sc->half_height / H : aim_px * 2 * tan(20 * PI / 180) * D / H;
    for (int i = 0; i < 3; i++) {
        target[i] = right[i] * units;
        eye[i] = (ortho ? target[i] : 0) + dir[i] * D;
    }
    memset(cam, 0, sizeof *cam);
    cam->eye = silk_v3(fx(eye[0]), fx(eye[1]), fx(eye[2]));
    cam->target = silk_v3(fx(target[0]), fx(target[1]), fx(target[2]));
    cam->up = silk_v3(0, SILK_FX_ONE, 0);
    cam->ortho = ortho;
    cam->fov_deg = fx(2 * atan(tan(20 * PI / 180) / zoom) * 180 / PI);
    cam->ortho_half_height = fx(sc->half_height / zoom);
    cam->znear = fx(0.1);
    cam->zfar = fx(100);
    cam->width = W;
    cam->height = H;
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

/* Render and take the object mask; 0 on success. */
static int render_mask(const scene *sc, const silk_camera *cam, silk_mode mode, unsigned char *mask,
                       silk_frame_stats *fs)
{
    silk_view view;
    silk_error err;
    memset(&err, 0, sizeof err);
    if (silk_view_init(&view, cam, &err) != SILK_OK) {
        fprintf(stderr, "silk_view_init: %s\n", err.msg);
        return -1;
    }
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &view);
    silk_hal_phong(&hal, &phong);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;   /* the outline by pixel centres (test_aa measures anti-aliasing) */
    o.mode = mode;
    o.bg_rgb = BG;
    silk_status st = silk_render(&arena, &sc->mesh, &view, &hal, &o, &t, fs, &err);
    if (st != SILK_OK) {
        fprintf(stderr, "silk_render (%s): %s\n", sc->name, err.msg);
        return -1;
    }
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) mask[y * W + x] = silk_target_get(&t, x, y) != BG;
    return 0;
}

typedef struct tally {
    int views;
    double sum_mean, worst_mean, worst_max, sum_offset;
    int worst_view;
} tally;

static void tally_add(tally *t, const es_stats *st, int view)
{
    t->views++;
    t->sum_mean += st->mean_error;
    t->sum_offset += st->mean_offset;
    if (st->mean_error > t->worst_mean) { t->worst_mean = st->mean_error; t->worst_view = view; }
    if (st->max_dist > t->worst_max) t->worst_max = st->max_dist;
}

static int nviews(void)
{
    const char *e = getenv("SILK_ACCURACY_VIEWS");
    if (e && atoi(e) > 0) return atoi(e);
    e = getenv("SILK_SAN");
    return e && *e == '1' ? 12 : 36;
}

static scene scenes[2];
static int scenes_ok;

static void setup_scenes(void)
{
    static dmesh d;
    static uint8_t *buf;
    size_t size = 16u << 20;
    buf = malloc(size);
    if (!buf) return;
    silk_arena_init(&arena, buf, size);
    uv_sphere(&d, 10, 11, 1.0);
    scenes[0].name = "sphere-200";
    scenes[0].shape = es_sphere(0, 0, 0, 1);
    scenes[0].dist = 4;
    scenes[0].half_height = 1.4;
    if (build_mesh(&d, &arena, &scenes[0].mesh)) return;
    torus(&d, 24, 12, 1.0, 0.4);
    scenes[1].name = "torus-576";
    scenes[1].shape = es_torus(0, 0, 0, 0, 1, 0, 1.0, 0.4);
    scenes[1].dist = 5;
    scenes[1].half_height = 1.9;
    if (build_mesh(&d, &arena, &scenes[1].mesh)) return;
    scenes_ok = 1;
}

static tally results[2][2][2];   /* scene, ortho, mode */

/* 36 views x 2 projections x 2 meshes, flat and smooth. */
TEST(accuracy_views)
{
    static unsigned char exact[W * H], got[W * H];
    CHECK(scenes_ok);
    if (!scenes_ok) return;
    int n = nviews(), failures = 0;
    es_points pts;
    memset(&pts, 0, sizeof pts);
    for (int s = 0; s < 2; s++)
        for (int ortho = 0; ortho < 2; ortho++)
            for (int k = 0; k < n; k++) {
                silk_camera cam;
                es_camera ec;
                view_camera(&scenes[s], ortho, k, n, 0, 1, 0, &cam);
                es_camera_from_silk(&ec, &cam);
                es_mask(&ec, &scenes[s].shape, exact);
                CHECK(es_silhouette_points(&ec, &scenes[s].shape, exact, &pts) > 0);
                for (int mode = 0; mode < 2; mode++) {
                    silk_frame_stats fs;
                    if (render_mask(&scenes[s], &cam, mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT, got, &fs)) {
                        CHECKF(0, "%s view %d: render failed", scenes[s].name, k);
                        continue;
                    }
                    es_stats st;
                    CHECK(es_compare(got, exact, &pts, W, H, &st) == 0);
                    tally_add(&results[s][ortho][mode], &st, k);
                    char tag[96];
                    snprintf(tag, sizeof tag, "%s-%s-%02d-%s", scenes[s].name, ortho ? "ortho" : "persp", k,
                             mode ? "smooth" : "flat");
                    dump(tag, got);
                    if (mode == 1 && (st.mean_error > SMOOTH_MEAN_BOUND || st.max_dist > SMOOTH_MAX_BOUND) &&
                        failures++ < 8)
                        fprintf(stderr, "  %s: mean %.3f px, max %.2f px, %ld extra / %ld missing pixels\n", tag,
                                st.mean_error, st.max_dist, st.extra, st.missing);
                }
                if (dump_dir) {
                    char tag[96];
                    snprintf(tag, sizeof tag, "%s-%s-%02d-exact", scenes[s].name, ortho ? "ortho" : "persp", k);
                    dump(tag, exact);
                }
            }
    es_points_free(&pts);
    for (int s = 0; s < 2; s++)
        for (int ortho = 0; ortho < 2; ortho++) {
            for (int mode = 0; mode < 2; mode++) {
                tally *t = &results[s][ortho][mode];
                printf("  %-10s %-5s %-6s mean %.3f px (worst view %d: %.3f), max %.2f px, bias %+.3f px, %d views\n",
                       scenes[s].name, ortho ? "ortho" : "persp", mode ? "smooth" : "flat",
                       t->sum_mean / t->views, t->worst_view, t->worst_mean, t->worst_max,
                       t->sum_offset / t->views, t->views);
            }
            tally *f = &results[s][ortho][0], *m = &results[s][ortho][1];
            CHECKF(m->worst_mean <= SMOOTH_MEAN_BOUND, "%s %s smooth: worst mean %.3f px > %.2f", scenes[s].name,
                   ortho ? "ortho" : "persp", m->worst_mean, SMOOTH_MEAN_BOUND);
            CHECKF(m->worst_max <= SMOOTH_MAX_BOUND, "%s %s smooth: max %.2f px > %.1f", scenes[s].name,
                   ortho ? "ortho" : "persp", m->worst_max, SMOOTH_MAX_BOUND);
            /* flat is clearly worse: three times the mean error, and a larger maximum */
            CHECKF(f->sum_mean >= 3 * m->sum_mean && f->worst_max > m->worst_max,
                   "%s %s: flat (mean %.3f, max %.2f) not clearly worse than smooth (mean %.3f, max %.2f)",
                   scenes[s].name, ortho ? "ortho" : "persp", f->sum_mean / f->views, f->worst_max,
                   m->sum_mean / m->views, m->worst_max);
        }
}

/* Moving the eye by 0.5 degrees about y, the axis both shapes are symmetric
 * about: the true outline stays where it is, the mesh turns under it.  No
 * rendered silhouette pixel may move by more than MOVE_BOUND. */
TEST(stable_under_small_eye_motion)
{
    static unsigned char a[W * H], b[W * H], ea[W * H], eb[W * H];
    CHECK(scenes_ok);
    if (!scenes_ok) return;
    int n = nviews();
    for (int s = 0; s < 2; s++)
        for (int ortho = 0; ortho < 2; ortho++) {
            double worst[2] = { 0, 0 }, worst_exact = 0;
            for (int k = 0; k < n; k += 3) {
                silk_camera c0, c1;
                es_camera e0, e1;
                view_camera(&scenes[s], ortho, k, n, 0, 1, 0, &c0);
                view_camera(&scenes[s], ortho, k, n, 0.5, 1, 0, &c1);
                es_camera_from_silk(&e0, &c0);
                es_camera_from_silk(&e1, &c1);
                es_mask(&e0, &scenes[s].shape, ea);
                es_mask(&e1, &scenes[s].shape, eb);
                double he = es_boundary_hausdorff(ea, eb, W, H);
                if (he > worst_exact) worst_exact = he;
                for (int mode = 0; mode < 2; mode++) {
                    silk_mode md = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                    if (render_mask(&scenes[s], &c0, md, a, NULL) || render_mask(&scenes[s], &c1, md, b, NULL)) {
                        CHECKF(0, "render failed");
                        continue;
                    }
                    double hd = es_boundary_hausdorff(a, b, W, H);
                    if (hd > worst[mode]) worst[mode] = hd;
                }
            }
            for (int mode = 0; mode < 2; mode++)
                printf("  %-10s %-5s %-6s 0.5-degree eye move: silhouette moved <= %.2f px (true outline %.2f px)\n",
                       scenes[s].name, ortho ? "ortho" : "persp", mode ? "smooth" : "flat", worst[mode], worst_exact);
            CHECKF(worst[1] <= MOVE_BOUND, "%s %s smooth: a 0.5-degree eye move moved the silhouette %.2f px",
                   scenes[s].name, ortho ? "ortho" : "persp", worst[1]);
        }
}

/* Zoomed in 8x on the outline (the aim point is where the middle row
 * leaves the object in the unzoomed view): errors in px stay in bounds. */
TEST(accuracy_zoomed)
{
    static unsigned char exact[W * H], got[W * H];
    CHECK(scenes_ok);
    if (!scenes_ok) return;
    int n = nviews();
    es_points pts;
    memset(&pts, 0, sizeof pts);
    for (int s = 0; s < 2; s++)
        for (int ortho = 0; ortho < 2; ortho++) {
            tally t[2];
            memset(t, 0, sizeof t);
            unsigned long samples_1x = 0, samples_8x = 0;
            for (int k = 1; k < n; k += 6) {
                silk_camera cam;
                es_camera ec;
                /* where the middle row leaves the object, unzoomed */
                view_camera(&scenes[s], ortho, k, n, 0, 1, 0, &cam);
                es_camera_from_silk(&ec, &cam);
                double x = W - 0.5;
                while (x > W / 2 && !es_hit(&ec, &scenes[s].shape, x, H / 2.0)) x -= 1;
                view_camera(&scenes[s], ortho, k, n, 0, 8, x - W / 2.0, &cam);
                es_camera_from_silk(&ec, &cam);
                es_mask(&ec, &scenes[s].shape, exact);
                es_silhouette_points(&ec, &scenes[s].shape, exact, &pts);
                long inside = mask_count(exact);
                CHECKF(pts.n > W / 2 && inside > W * H / 8 && inside < W * H * 7 / 8,
                       "%s zoomed view %d: the outline is not across the image (%d samples)", scenes[s].name, k, pts.n);
                silk_frame_stats fs1, fs8;
                silk_camera cam1;
                view_camera(&scenes[s], ortho, k, n, 0, 1, 0, &cam1);
                if (render_mask(&scenes[s], &cam1, SILK_MODE_SMOOTH, got, &fs1) == 0 &&
                    render_mask(&scenes[s], &cam, SILK_MODE_SMOOTH, got, &fs8) == 0)
                    samples_1x += fs1.samples, samples_8x += fs8.samples;
                for (int mode = 0; mode < 2; mode++) {
                    if (render_mask(&scenes[s], &cam, mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT, got, NULL)) {
                        CHECKF(0, "render failed");
                        continue;
                    }
                    es_stats st;
                    es_compare(got, exact, &pts, W, H, &st);
                    tally_add(&t[mode], &st, k);
                    char tag[96];
                    snprintf(tag, sizeof tag, "%s-%s-%02d-zoom8-%s", scenes[s].name, ortho ? "ortho" : "persp", k,
                             mode ? "smooth" : "flat");
                    dump(tag, got);
                }
            }
            for (int mode = 0; mode < 2; mode++)
                printf("  %-10s %-5s %-6s zoom 8x: mean %.3f px (worst view %d: %.3f), max %.2f px, bias %+.3f px, %d views\n",
                       scenes[s].name, ortho ? "ortho" : "persp", mode ? "smooth" : "flat", t[mode].sum_mean / t[mode].views,
                       t[mode].worst_view, t[mode].worst_mean, t[mode].worst_max, t[mode].sum_offset / t[mode].views,
                       t[mode].views);
            printf("  %-10s %-5s smooth samples per frame: %lu unzoomed, %lu zoomed 8x\n", scenes[s].name,
                   ortho ? "ortho" : "persp", samples_1x, samples_8x);
            CHECKF(t[1].worst_mean <= ZOOM_MEAN_BOUND && t[1].worst_max <= SMOOTH_MAX_BOUND,
                   "%s %s smooth zoomed 8x: worst mean %.3f px, max %.2f px", scenes[s].name, ortho ? "ortho" : "persp",
                   t[1].worst_mean, t[1].worst_max);
            CHECKF(t[1].sum_mean * ZOOM_FLAT_RATIO <= t[0].sum_mean,
                   "%s %s zoomed 8x: smooth mean %.3f px is not a tenth of flat's %.3f px", scenes[s].name,
                   ortho ? "ortho" : "persp", t[1].sum_mean / t[1].views, t[0].sum_mean / t[0].views);
            CHECKF(samples_8x > samples_1x, "%s %s: zooming in 8x did not add samples (%lu -> %lu)", scenes[s].name,
                   ortho ? "ortho" : "persp", samples_1x, samples_8x);
        }
    es_points_free(&pts);
}

int main(void)
{
    dump_dir = getenv("SILK_ACCURACY_DUMP");
    RUN(harness_masks);
    RUN(harness_torus_brute);
    RUN(harness_measures);
    RUN(meshes_as_specified);
    setup_scenes();
    RUN(accuracy_views);
    RUN(stable_under_small_eye_motion);
    RUN(accuracy_zoomed);
    return check_done();
}
