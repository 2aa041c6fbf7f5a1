/*
 * test_silmap_interp.c - the silhouette map's interpolation (paper
 * section 5) against double-precision references written here: the
 * rectification, the projective map to the current view, linear
 * interpolation of two outlines as the silhouette of the two views' visual
 * hull, the polytope triangle, and whole outlines of generated shapes and
 * the shared bunny against the true silhouette drawn at the current view.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "support/testmesh.h"
#include "../tools/prep/gen.h"
#include "../tools/prep/silmap.h"
#include "../tools/prep/silmap_simplify.h"

static silk_fx fx(double v) { return (silk_fx)floor(v * 65536 + 0.5); }
static double dbl(silk_fx v) { return v / 65536.0; }
static void v3d(silk_vec3 v, double out[3]) { out[0] = dbl(v.x), out[1] = dbl(v.y), out[2] = dbl(v.z); }
static double ddot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void unit_rand(double d[3])
{
    double n;
    do {
        for (int k = 0; k < 3; k++) d[k] = check_uniform(-1, 1);
        n = sqrt(ddot(d, d));
    } while (n < 0.1 || n > 1);
    for (int k = 0; k < 3; k++) d[k] /= n;
}

/* The reference projection by the (rounded) fixed-point camera. */
static int project_d(const silk_silmap_cam *c, const double q[3], double out[2])
{
    double e[3], r[3], u[3], f[3];
    v3d(c->eye, e), v3d(c->right, r), v3d(c->up, u), v3d(c->fwd, f);
    double d[3] = { q[0] - e[0], q[1] - e[1], q[2] - e[2] };
    double z = c->ortho ? 1 : ddot(d, f);
    if (!(z > 0)) return -1;
    out[0] = dbl(c->cx) + dbl(c->focal) * ddot(d, r) / z;
    out[1] = dbl(c->cy) - dbl(c->focal) * ddot(d, u) / z;
    return 0;
}

/* A map camera 3 radii from centre (radius 1) along dir. */
static void map_cam(const double centre[3], const double dir[3], silk_silmap_cam *c)
{
    silmap_camera cam;
    silmap_camera_at(centre, 1, dir, 3, 256, &cam);
    CHECK(silmap_cam_export(&cam, c) == 0);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* ---- the tests ---------------------------------------------------------------------- */

/* Section 5.2: rectifying a view's image is exact (the 3x3 map lands every
 * point where the rectified camera sees it), and the two rectified views
 * see every point on the same scan line. */
TEST(rectification)
{
    double worst = 0, epi = 0;
    for (int trial = 0; trial < 40; trial++) {
        double c[3] = { check_uniform(-3, 3), check_uniform(-3, 3), check_uniform(-3, 3) }, da[3], db[3];
        unit_rand(da);
        do {
            unit_rand(db);
        } while (ddot(da, db) < 0.9 || ddot(da, db) > 0.999);
        silk_silmap_cam ca, cb, ra, rb;
        map_cam(c, da, &ca);
        map_cam(c, db, &cb);
        silk_vec3 cf = { fx(c[0]), fx(c[1]), fx(c[2]) };
        CHECK(silk_silmap_rectified(ca.eye, cb.eye, cf, ca.focal, &ra, &rb) == SILK_OK);
        silk_h3 ha, hb;
        CHECK(silk_h3_between(&ca, &ra, NULL, NULL, &ha) == SILK_OK);
        CHECK(silk_h3_between(&cb, &rb, NULL, NULL, &hb) == SILK_OK);
        for (int i = 0; i < 20; i++) {
            double q[3], d[3];
            unit_rand(d);
            double rho = check_uniform(0, 1);
            for (int k = 0; k < 3; k++) q[k] = c[k] + rho * d[k];
            double pa[2], pb[2], refa[2], refb[2];
            CHECK(project_d(&ca, q, pa) == 0 && project_d(&cb, q, pb) == 0);
            CHECK(project_d(&ra, q, refa) == 0 && project_d(&rb, q, refb) == 0);
            silk_vec2 ua, ub;
            CHECK(silk_h3_apply(&ha, (silk_vec2){ fx(pa[0]), fx(pa[1]) }, &ua) == 0);
            CHECK(silk_h3_apply(&hb, (silk_vec2){ fx(pb[0]), fx(pb[1]) }, &ub) == 0);
            worst = fmax(worst, fmax(hypot(dbl(ua.x) - refa[0], dbl(ua.y) - refa[1]),
                                     hypot(dbl(ub.x) - refb[0], dbl(ub.y) - refb[1])));
            epi = fmax(epi, fabs(dbl(ua.y) - dbl(ub.y)));
        }
    }
    CHECKF(worst < 0.02, "rectified point %.4f px off", worst);
    CHECKF(epi < 0.03, "scan lines %.4f px apart", epi);
    printf("  rectification: within %.5f px of the double reference, scan lines agree to %.5f px\n", worst, epi);
}

/* Section 5: points on the plane through the centre seen by a map view
 * land, through the 3x3 map, where the current camera sees them;
 * perspective and orthographic; and the current camera in the map's terms
 * projects like silk_view_project. */
TEST(projective_map)
{
    double worst = 0, conv = 0;
    for (int trial = 0; trial < 60; trial++) {
        double c[3] = { check_uniform(-2, 2), check_uniform(-2, 2), check_uniform(-2, 2) }, da[3], n[3], de[3];
        unit_rand(da);
        unit_rand(n);
        unit_rand(de);
        if (ddot(n, da) < 0) for (int k = 0; k < 3; k++) n[k] = -n[k];
        if (ddot(de, da) < 0.3) for (int k = 0; k < 3; k++) de[k] = da[k];
        silk_silmap_cam ca, cb;
        map_cam(c, da, &ca);
        silk_camera cam;
        memset(&cam, 0, sizeof cam);
        double dist = check_uniform(2.2, 6);
        cam.eye = (silk_vec3){ fx(c[0] + dist * de[0]), fx(c[1] + dist * de[1]), fx(c[2] + dist * de[2]) };
        cam.target = (silk_vec3){ fx(c[0] + 0.1), fx(c[1]), fx(c[2] - 0.1) };
        cam.up = (silk_vec3){ 0, SILK_FX_ONE, 0 };
        cam.ortho = trial & 1;
        cam.fov_deg = fx(40);
        cam.ortho_half_height = fx(1.5);
        cam.znear = fx(0.1);
        cam.zfar = fx(20);
        cam.width = 320, cam.height = 240;
        silk_view view;
        silk_error err;
        if (fabs(de[1]) > 0.95) continue;
        CHECK(silk_view_init(&view, &cam, &err) == SILK_OK);
        silk_silmap_cam_of_view(&view, &cb);
        silk_vec3 nf, cf = { fx(c[0]), fx(c[1]), fx(c[2]) };
        CHECK(silk_v3_normalize((silk_vec3){ fx(n[0]), fx(n[1]), fx(n[2]) }, &nf));
        double nd[3];
        v3d(nf, nd);
        silk_h3 h;
        CHECK(silk_h3_between(&ca, &cb, &nf, &cf, &h) == SILK_OK);
        for (int i = 0; i < 20; i++) {
            /* a point of the plane within the unit sphere */
            double q[3], d[3];
            unit_rand(d);
            double s = ddot(d, nd), rho = check_uniform(0, 1);
            for (int k = 0; k < 3; k++) q[k] = c[k] + rho * (d[k] - s * nd[k]);
            double pa[2], ref[2];
            CHECK(project_d(&ca, q, pa) == 0);
            CHECK(project_d(&cb, q, ref) == 0);
            silk_vec2 u;
            CHECK(silk_h3_apply(&h, (silk_vec2){ fx(pa[0]), fx(pa[1]) }, &u) == 0);
            worst = fmax(worst, hypot(dbl(u.x) - ref[0], dbl(u.y) - ref[1]));
            silk_vec2 sv;
            CHECK(silk_view_project(&view, (silk_vec3){ fx(q[0]), fx(q[1]), fx(q[2]) }, &sv));
            conv = fmax(conv, hypot(dbl(sv.x) - ref[0], dbl(sv.y) - ref[1]));
        }
    }
    CHECKF(worst < 0.05, "mapped point %.4f px off", worst);
    CHECKF(conv < 0.05, "the current camera %.4f px off silk_view_project", conv);
    printf("  projective map: within %.5f px of the double reference (camera conventions agree to %.5f px)\n",
           worst, conv);
}

/* Intervals of a double-precision parity outline on scan line y. */
static int spans_at(const silk_outline *o, double y, double *xs)
{
    int n = 0;
    for (uint32_t l = 0; l < o->nloops; l++)
        for (uint32_t i = o->start[l]; i < o->start[l + 1]; i++) {
            silk_vec2 p = o->pt[i], q = o->pt[i + 1 < o->start[l + 1] ? i + 1 : o->start[l]];
            double py = dbl(p.y), qy = dbl(q.y);
            if ((py <= y) == (qy <= y)) continue;
            xs[n++] = dbl(p.x) + (y - py) * (dbl(q.x) - dbl(p.x)) / (qy - py);
        }
    qsort(xs, (size_t)n, sizeof *xs, cmp_double);
    return n & ~1;
}

/* The flatland visual hull: is (x, y) seen from the eye at alpha inside the
 * silhouette of the intersection of the two views' cones?  With as many
 * intervals in both views, the hull of each matched pair (the cliques of
 * section 5.3), else of every pair (the pants).  Along its ray
 * (t = focal * baseline / depth > 0) a point is seen at x + alpha t from a
 * and x - (1 - alpha) t from b. */
static int in_visual_hull(const double *xa, int na, const double *xb, int nb, double alpha, double x)
{
    for (int i = 0; i < na; i += 2)
        for (int j = 0; j < nb; j += 2) {
            if (na == nb && i != j) continue;   /* matched cliques */
            double lo = fmax(0, fmax((xa[i] - x) / alpha, (x - xb[j + 1]) / (1 - alpha)));
            double hi = fmin((xa[i + 1] - x) / alpha, (x - xb[j]) / (1 - alpha));
            if (lo < hi) return 1;
        }
    return 0;
}

/* Pixels where the interpolated outline and the visual hull differ, not
 * counting pixel centres within 0.01 px of the reference's boundary. */
static int visual_hull_mismatch(const silk_outline *a, const silk_outline *b, double alpha, const silk_outline *out,
                                int w, int h, int *inside)
{
    uint8_t *img = malloc((size_t)w * h);
    double *xa = malloc((a->npts + 2) * sizeof *xa), *xb = malloc((b->npts + 2) * sizeof *xb);
    silmap_fill(out, w, h, img);
    int bad = 0;
    *inside = 0;
    for (int y = 0; y < h; y++) {
        int na = spans_at(a, y + 0.5, xa), nb = spans_at(b, y + 0.5, xb);
        for (int x = 0; x < w; x++) {
            int ref = in_visual_hull(xa, na, xb, nb, alpha, x + 0.5);
            *inside += ref;
            if (ref != img[y * w + x] && in_visual_hull(xa, na, xb, nb, alpha, x + 0.49) == ref &&
                in_visual_hull(xa, na, xb, nb, alpha, x + 0.51) == ref)
                bad++;
        }
    }
    free(img);
    free(xa);
    free(xb);
    return bad;
}

/* Projected points' convex hull (monotone chain) as one loop. */
static uint32_t hull2d(double (*p)[2], uint32_t n, silk_vec2 *out)
{
    for (uint32_t i = 1; i < n; i++)
        for (uint32_t j = i; j > 0 && (p[j - 1][0] > p[j][0] || (p[j - 1][0] == p[j][0] && p[j - 1][1] > p[j][1])); j--) {
            double t0 = p[j][0], t1 = p[j][1];
            p[j][0] = p[j - 1][0], p[j][1] = p[j - 1][1], p[j - 1][0] = t0, p[j - 1][1] = t1;
        }
    uint32_t k = 0;
    double (*hq)[2] = malloc(2 * (n + 1) * sizeof *hq);
    for (int pass = 0; pass < 2; pass++) {
        uint32_t base = k;
        for (uint32_t ii = 0; ii < n; ii++) {
            uint32_t i = pass ? n - 1 - ii : ii;
            while (k >= base + 2 && (hq[k - 1][0] - hq[k - 2][0]) * (p[i][1] - hq[k - 2][1]) -
                                        (hq[k - 1][1] - hq[k - 2][1]) * (p[i][0] - hq[k - 2][0]) <= 0)
                k--;
            hq[k][0] = p[i][0], hq[k][1] = p[i][1];
            k++;
        }
        k--;
    }
    for (uint32_t i = 0; i < k; i++) out[i] = (silk_vec2){ fx(hq[i][0]), fx(hq[i][1]) };
    free(hq);
    return k;
}

/* Section 5.2's property: for a convex polyhedron seen by two rectified
 * views, the interpolated outline is the silhouette of the two views'
 * visual hull, at every alpha. */
TEST(lerp_convex_is_visual_hull)
{
    const int W = 200, H = 200;
    const double f = 150, L = 1.5;
    int worst = 0, inside = 0;
    for (int trial = 0; trial < 12; trial++) {
        double pc[3] = { check_uniform(0, L), check_uniform(-0.5, 0.5), check_uniform(4, 6) };
        enum { N = 24 };
        double pa[N][2], pb[N][2];
        for (int i = 0; i < N; i++) {
            double d[3];
            unit_rand(d);
            double q[3] = { pc[0] + d[0] * 1.5, pc[1] + d[1], pc[2] + d[2] };
            pa[i][0] = W / 2.0 + f * q[0] / q[2], pa[i][1] = H / 2.0 - f * q[1] / q[2];
            pb[i][0] = W / 2.0 + f * (q[0] - L) / q[2], pb[i][1] = pa[i][1];
        }
        silk_vec2 la[N + 1], lb[N + 1];
        uint32_t sa[2] = { 0, hull2d(pa, N, la) }, sb[2] = { 0, hull2d(pb, N, lb) };
        silk_outline a = { 1, sa[1], sa, la }, b = { 1, sb[1], sb, lb };
        static uint8_t buf[1 << 20];
        silk_arena ar;
        for (double alpha = 0.125; alpha < 1; alpha += 0.25) {
            silk_arena_init(&ar, buf, sizeof buf);
            silk_outline out;
            CHECK(silk_outline_lerp(&a, &b, fx(alpha), &ar, &out) == SILK_OK);
            int in;
            int bad = visual_hull_mismatch(&a, &b, alpha, &out, W, H, &in);
            worst = bad > worst ? bad : worst;
            inside += in;
        }
    }
    CHECKF(worst == 0, "%d pixels differ from the visual hull's silhouette", worst);
    printf("  convex polyhedra, 48 interpolations: at most %d of %d pixels differ from the visual hull\n", worst,
           inside);
}

/* Two blobs side by side at different depths: one interval from one view,
 * two from the other, and every mixture (the pants); the outlines traced
 * from images.  The union is exact at the outlines' vertex scan lines and
 * linear between them, so a few pixels may differ where a leg's end moves
 * non-linearly. */
TEST(lerp_pants)
{
    const int W = 240, H = 160;
    const double f = 200, L = 2;
    double worst_frac = 0;
    int total_bad = 0, total_in = 0;
    for (int trial = 0; trial < 8; trial++) {
        double c1[3] = { check_uniform(-0.3, 0.3), check_uniform(-0.2, 0.2), 5 };
        double c2[3] = { c1[0] + check_uniform(0.4, 1.2), c1[1] + check_uniform(-0.3, 0.3), check_uniform(7, 9) };
        uint8_t *img = malloc((size_t)W * H);
        silmap_contours tr[2];
        for (int view = 0; view < 2; view++) {
            memset(img, 0, (size_t)W * H);
            const double *cs[2] = { c1, c2 };
            for (int bl = 0; bl < 2; bl++) {
                /* a ball of radius 0.35: its outline is a circle (nearly) */
                double z = cs[bl][2], cx = W / 2.0 + f * (cs[bl][0] - view * L) / z, cy = H / 2.0 - f * cs[bl][1] / z;
                double r = f * 0.35 / z;
                for (int y = 0; y < H; y++)
                    for (int x = 0; x < W; x++)
                        if (hypot(x + 0.5 - cx, y + 0.5 - cy) < r) img[y * W + x] = 1;
            }
            CHECK(silmap_trace(img, W, H, &tr[view]) == 0);
        }
        free(img);
        silk_outline o[2];
        uint32_t *st[2];
        silk_vec2 *pt[2];
        for (int v = 0; v < 2; v++) {
            st[v] = malloc((tr[v].nloops + 1) * sizeof **st);
            pt[v] = malloc(tr[v].npts * sizeof **pt);
            memcpy(st[v], tr[v].start, (tr[v].nloops + 1) * sizeof **st);
            for (uint32_t i = 0; i < tr[v].npts; i++) pt[v][i] = (silk_vec2){ fx(tr[v].pt[2 * i]), fx(tr[v].pt[2 * i + 1]) };
            o[v] = (silk_outline){ tr[v].nloops, tr[v].npts, st[v], pt[v] };
        }
        static uint8_t buf[1 << 21];
        for (double alpha = 0.1; alpha < 1; alpha += 0.2) {
            silk_arena ar;
            silk_arena_init(&ar, buf, sizeof buf);
            silk_outline out;
            CHECK(silk_outline_lerp(&o[0], &o[1], fx(alpha), &ar, &out) == SILK_OK);
            int in, bad = visual_hull_mismatch(&o[0], &o[1], alpha, &out, W, H, &in);
            total_bad += bad, total_in += in;
            worst_frac = fmax(worst_frac, in ? (double)bad / in : 0);
        }
        for (int v = 0; v < 2; v++) {
            silmap_contours_free(&tr[v]);
            free(st[v]);
            free(pt[v]);
        }
    }
    CHECKF(worst_frac < 0.002, "%.4f of the pixels differ from the visual hull", worst_frac);
    printf("  two blobs (pants), 40 interpolations: %d of %d pixels differ from the visual hull\n", total_bad,
           total_in);
}

/* Section 4: the triangle the ray from the centre through the eye meets,
 * found by walking from any triangle, against a double search over all. */
TEST(locate_triangle)
{
    silmap_polytope poly;
    CHECK(silmap_icosphere(2, &poly) == 0);
    silmap m;
    memset(&m, 0, sizeof m);
    m.poly = poly;
    m.radius = 1;
    m.views = calloc(poly.nviews, sizeof *m.views);
    double c[3] = { 0.25, -0.5, 1 };
    for (uint32_t i = 0; i < poly.nviews; i++) silmap_camera_at(c, 1, &poly.dir[3 * i], 3, 64, &m.views[i].cam);
    memcpy(m.centre, c, sizeof c);
    silmap_fixed f;
    CHECK(silmap_export(&m, &f) == 0);
    int wrong = 0;
    double worst = 0;
    uint32_t hint = 0;
    for (int trial = 0; trial < 2000; trial++) {
        double d[3];
        unit_rand(d);
        double dist = check_uniform(0.2, 6);
        silk_vec3 eye = { fx(c[0] + dist * d[0]), fx(c[1] + dist * d[1]), fx(c[2] + dist * d[2]) };
        uint32_t t;
        silk_fx b[3];
        CHECK(silk_silmap_locate(&f.map, eye, trial & 1 ? hint : (uint32_t)trial % poly.ntris, &t, b) == SILK_OK);
        hint = t;
        /* the reference: every triangle's ray barycentrics */
        double de[3];
        v3d(eye, de);
        for (int k = 0; k < 3; k++) de[k] -= dbl(f.map.centre.x) * (k == 0) + dbl(f.map.centre.y) * (k == 1) + dbl(f.map.centre.z) * (k == 2);
        int found = 0;
        for (uint32_t u = 0; u < poly.ntris && !found; u++) {
            double a[3][3];
            for (int k = 0; k < 3; k++) v3d(silk_v3_sub(f.map.views[poly.tri[3 * u + k]].cam.eye, f.map.centre), a[k]);
            double w[3];
            for (int k = 0; k < 3; k++) {
                const double *p = a[(k + 1) % 3], *q = a[(k + 2) % 3];
                double cr[3] = { p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0] };
                w[k] = ddot(de, cr);
            }
            if (w[0] >= -1e-9 && w[1] >= -1e-9 && w[2] >= -1e-9) {
                found = 1;
                double sum = w[0] + w[1] + w[2];
                if (u != t) {
                    /* on an edge both are right: the weights must say so */
                    double small = fmin(w[0], fmin(w[1], w[2])) / sum;
                    if (small > 1e-4) wrong++;
                } else
                    for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(w[k] / sum - dbl(b[k])));
            }
        }
    }
    CHECKF(wrong == 0, "%d eyes in the wrong triangle", wrong);
    CHECKF(worst < 1e-3, "barycentric coordinates %.2g off", worst);
    printf("  2000 eyes: the right triangle every time, barycentric coordinates within %.1e\n", worst);
    silmap_fixed_free(&f);
    silmap_free(&m);
}

/* An interpolated outline against the true silhouette from the same eye:
 * the pixels that differ, per pixel of outline (the true image's boundary
 * sides), which is about the mean distance in pixels.  The map's views are
 * 3 radii away; the outline is carried to the current eye as if it lay in
 * the plane through the centre (section 5), so eyes nearer or farther
 * (orthographic: infinitely far) see it scaled: the sphere's contour seen
 * from 3 radii lies a third of a radius in front of that plane. */
typedef struct e2e_result { long bad, perimeter; double worst_ratio; int frames; } e2e_result;

static void e2e_frame(const silmap_fixed *f, const double *pos, uint32_t nv, const uint32_t *tri, uint32_t nt,
                      const double centre[3], double radius, const double dir[3], double dist, int ortho, int res,
                      uint32_t *hint, e2e_result *r)
{
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = centre[k] + dist * radius * dir[k];
    cam.eye = (silk_vec3){ fx(e[0]), fx(e[1]), fx(e[2]) };
    cam.target = (silk_vec3){ fx(centre[0]), fx(centre[1]), fx(centre[2]) };
    cam.up = (silk_vec3){ 0, SILK_FX_ONE, 0 };
    cam.ortho = ortho;
    cam.fov_deg = fx(2 * asin(1 / dist) * 1.15 * 180 / 3.14159265358979323846);
    cam.ortho_half_height = fx(radius * 1.15);
    cam.znear = fx(radius * 0.01);
    cam.zfar = fx(radius * 20);
    cam.width = cam.height = res;
    silk_view view;
    silk_error err;
    CHECK(silk_view_init(&view, &cam, &err) == SILK_OK);
    static uint8_t buf[1 << 23];
    silk_arena ar;
    silk_arena_init(&ar, buf, sizeof buf);
    silk_outline out;
    silk_silmap_frame info;
    silk_status st = silk_silmap_interp(&f->map, &view, *hint, &ar, &out, &info, &err);
    CHECKF(st == SILK_OK, "%s", err.msg);
    if (st) return;
    *hint = info.tri;   /* tracked from frame to frame */
    /* the truth: the detailed mesh drawn from the same camera (an
     * orthographic one as a perspective one very far away) */
    silmap_camera tc;
    v3d(view.cam.eye, tc.eye), v3d(view.right, tc.right), v3d(view.upv, tc.up), v3d(view.forward, tc.fwd);
    tc.focal = dbl(view.pixels_per_unit);
    tc.res = res;
    /* orthonormal in double: the rounded axes would tilt a far camera */
    double nf = sqrt(ddot(tc.fwd, tc.fwd)), dr = ddot(tc.right, tc.fwd) / nf;
    for (int k = 0; k < 3; k++) tc.fwd[k] /= nf;
    for (int k = 0; k < 3; k++) tc.right[k] -= dr * tc.fwd[k];
    double nr = sqrt(ddot(tc.right, tc.right));
    for (int k = 0; k < 3; k++) tc.right[k] /= nr;
    tc.up[0] = tc.right[1] * tc.fwd[2] - tc.right[2] * tc.fwd[1];
    tc.up[1] = tc.right[2] * tc.fwd[0] - tc.right[0] * tc.fwd[2];
    tc.up[2] = tc.right[0] * tc.fwd[1] - tc.right[1] * tc.fwd[0];
    if (ortho) {
        double far = 1e4 * radius, ce[3] = { dbl(view.cam.target.x), dbl(view.cam.target.y), dbl(view.cam.target.z) };
        double along = ddot(tc.fwd, ce) - ddot(tc.fwd, tc.eye);
        for (int k = 0; k < 3; k++) tc.eye[k] += (along - far) * tc.fwd[k];
        tc.focal = dbl(view.pixels_per_unit) * far;
    }
    uint8_t *truth = malloc((size_t)res * res), *img = malloc((size_t)res * res);
    CHECK(silmap_rasterize(&tc, pos, nv, tri, nt, truth) == 0);
    silmap_fill(&out, res, res, img);
    long bad = 0, per = 0;
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++) {
            bad += truth[y * res + x] != img[y * res + x];
            if (x + 1 < res) per += truth[y * res + x] != truth[y * res + x + 1];
            if (y + 1 < res) per += truth[y * res + x] != truth[(y + 1) * res + x];
        }
    r->bad += bad, r->perimeter += per, r->frames++;
    if (per) r->worst_ratio = fmax(r->worst_ratio, (double)bad / per);
    free(truth);
    free(img);
}

static void e2e_mesh(const char *name, const double *pos, uint32_t nv, const uint32_t *tri, uint32_t nt, int level,
                     int res, double limit)
{
    silmap_params p;
    silmap_params_default(&p);
    p.level = level;
    p.res = res;
    silmap m;
    CHECK(silmap_build(pos, nv, tri, nt, &p, &m) == 0);
    silmap_fixed f;
    CHECK(silmap_export(&m, &f) == 0);
    /* eyes inside the polytope (2.2 radii), on it (3) and outside (5) */
    static const double dists[3] = { 2.2, 3, 5 };
    e2e_result r[3][2];
    memset(r, 0, sizeof r);
    uint32_t hint = 0;
    for (int i = 0; i < 36; i++) {
        double d[3];
        do unit_rand(d);
        while (fabs(d[1]) > 0.9);
        int di = i % 3, o = (i / 3) & 1;
        e2e_frame(&f, pos, nv, tri, nt, m.centre, m.radius, d, dists[di], o, res, &hint, &r[di][o]);
    }
    for (int o = 0; o < 2; o++) {
        printf("  %s, %u views, %d px, %s:", name, m.poly.nviews, res, o ? "orthographic" : "perspective ");
        for (int di = 0; di < (o ? 1 : 3); di++)
            printf("  %s%.3f px (worst %.3f)", o ? "" : di == 0 ? "inside " : di == 1 ? "on " : "outside ",
                   (double)r[di][o].bad / r[di][o].perimeter, r[di][o].worst_ratio);
        printf("\n");
    }
    CHECKF(r[1][0].worst_ratio < limit, "%s: %.3f px from eyes on the polytope", name, r[1][0].worst_ratio);
    for (int di = 0; di < 3; di++)
        for (int o = 0; o < 2; o++)
            CHECKF(r[di][o].worst_ratio < 12, "%s: %.3f px", name, r[di][o].worst_ratio);
    printf("  %s: map %u bytes in fixed point\n", name, silk_silmap_bytes(&f.map));
    silmap_fixed_free(&f);
    silmap_free(&m);
}

TEST(sphere_and_torus)
{
    gen_shape shapes[2] = { GEN_SPHERE, GEN_TORUS };
    const char *names[2] = { "sphere", "torus" };
    for (int s = 0; s < 2; s++) {
        gen_params gp;
        gen_defaults(shapes[s], &gp);
        gen_mesh g;
        CHECK(gen_build(&gp, &g) == 0);
        e2e_mesh(names[s], g.pos, g.nverts, g.tri, g.ntris, 2, 256, s ? 3.0 : 1.5);
        gen_free(&g);
    }
}

TEST(bunny)
{
    char path[512];
    snprintf(path, sizeof path, "%s/bunny-fine.obj", check_meshes_dir());
    double *pos;
    uint32_t *tri, nv, nt;
    int r = tm_load_doubles(path, &pos, &nv, &tri, &nt);
    CHECK(r >= 0);
    if (r != 1) return;
    e2e_mesh("bunny-fine", pos, nv, tri, nt, 2, 256, 1.5);
    free(pos);
    free(tri);
}

/* Section 6: the 42-view map of a torus simplified to 3 px: fewer views and
 * bytes, the polytope still star-shaped (every triangle counter-clockwise
 * about the centre), and every view of the dense map, dropped or not,
 * predicted by what is left within the threshold. */
TEST(simplify_map)
{
    gen_params gp;
    gen_defaults(GEN_TORUS, &gp);
    gen_mesh g;
    CHECK(gen_build(&gp, &g) == 0);
    silmap_params p;
    silmap_params_default(&p);
    p.level = 1;
    p.res = 128;
    silmap m, s;
    CHECK(silmap_build(g.pos, g.nverts, g.tri, g.ntris, &p, &m) == 0);
    silmap_simplify_stats st;
    const double limit = 3.0;
    CHECK(silmap_simplify_map(&m, limit, 4, &s, &st) == 0);
    CHECKF(st.views_after < st.views_before && st.bytes_after < st.bytes_before, "%u -> %u views", st.views_before,
           st.views_after);
    CHECK(s.poly.nviews == st.views_after && s.poly.ntris == 2 * s.poly.nviews - 4);
    int flipped = 0;
    for (uint32_t t = 0; t < s.poly.ntris; t++) {
        const double *a = &s.poly.dir[3 * s.poly.tri[3 * t]], *b = &s.poly.dir[3 * s.poly.tri[3 * t + 1]],
                     *c = &s.poly.dir[3 * s.poly.tri[3 * t + 2]];
        double cr[3] = { b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0] };
        flipped += !(ddot(a, cr) > 0);
    }
    CHECKF(flipped == 0, "%d triangles turned over", flipped);
    /* every dense view from the simplified map */
    silmap_fixed f;
    CHECK(silmap_export(&s, &f) == 0);
    double worst = 0;
    uint32_t hint = 0;
    for (uint32_t v = 0; v < m.poly.nviews; v++) {
        e2e_result r = { 0, 0, 0, 0 };
        const double *d = &m.poly.dir[3 * v];
        if (fabs(d[1]) > 0.9) continue;
        e2e_frame(&f, g.pos, g.nverts, g.tri, g.ntris, m.centre, m.radius, d, p.distance, 0, p.res, &hint, &r);
        worst = fmax(worst, r.worst_ratio);
    }
    /* against the true silhouette rather than the dense outline: the dense
     * map's own error comes on top */
    CHECKF(worst < limit + 0.6, "a view predicted %.3f px off", worst);
    printf("  torus, %d px: %u -> %u views, %u -> %u bytes at %.1f px (worst collapse %.3f px, %u interpolations); "
           "every dense view within %.3f px of the true silhouette\n",
           p.res, st.views_before, st.views_after, st.bytes_before, st.bytes_after, limit, st.error, st.evaluations,
           worst);
    silmap_fixed_free(&f);
    silmap_free(&s);
    silmap_free(&m);
    gen_free(&g);
}

int main(void)
{
    RUN(rectification);
    RUN(projective_map);
    RUN(lerp_convex_is_visual_hull);
    RUN(lerp_pants);
    RUN(locate_triangle);
    RUN(sphere_and_torus);
    RUN(bunny);
    RUN(simplify_map);
    return check_done();
}
