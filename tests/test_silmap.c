/*
 * test_silmap.c - the building blocks of a silhouette map (tools/prep/silmap.c):
 * the subdivided icosahedron of views (counts, unit directions, closed and
 * oriented outward); binary images against a per-pixel barycentric
 * reference; outlines traced from random and hand-made images (areas add
 * up to the set pixels, outer loops positive, holes negative, diagonal
 * neighbours apart, every boundary side once) and the loops through the
 * sides' middles; Douglas-Peucker within its tolerance; and the dense map
 * of a sphere against its exact projected circle.
 */
#include <math.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "support/testmesh.h"
#include "../tools/prep/gen.h"
#include "../tools/prep/silmap.h"

TEST(icosphere_views)
{
    for (int level = 0; level <= 3; level++) {
        silmap_polytope p;
        CHECK(silmap_icosphere(level, &p) == 0);
        uint32_t want_v = 10u * (1u << (2 * level)) + 2, want_f = 20u * (1u << (2 * level));
        CHECKF(p.nviews == want_v && p.ntris == want_f, "level %d: %u views, %u triangles", level, p.nviews, p.ntris);
        double worst = 0, volume = 0;
        for (uint32_t i = 0; i < p.nviews; i++) {
            const double *d = &p.dir[3 * i];
            worst = fmax(worst, fabs(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 1));
        }
        CHECKF(worst < 1e-12, "level %d: a direction off the unit sphere by %g", level, worst);
        uint32_t inward = 0, bad_index = 0;
        for (uint32_t f = 0; f < p.ntris; f++) {
            const uint32_t *t = &p.tri[3 * f];
            bad_index += t[0] >= p.nviews || t[1] >= p.nviews || t[2] >= p.nviews;
            if (bad_index) break;
            const double *a = &p.dir[3 * t[0]], *b = &p.dir[3 * t[1]], *c = &p.dir[3 * t[2]];
            double n[3] = { (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                            (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                            (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) };
            inward += n[0] * a[0] + n[1] * a[1] + n[2] * a[2] <= 0;
            volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        }
        CHECKF(bad_index == 0 && inward == 0, "level %d: %u bad indices, %u faces not outward", level, bad_index, inward);
        /* the polytope's volume approaches the ball's from below */
        CHECKF(volume > 0.6 * 4.18879 && volume < 4.18879, "level %d: volume %g", level, volume);
        /* every edge in both directions exactly once: a closed, oriented surface */
        uint32_t unmatched = 0;
        for (uint32_t f = 0; f < p.ntris && level <= 2; f++)
            for (int k = 0; k < 3; k++) {
                uint32_t a = p.tri[3 * f + k], b = p.tri[3 * f + (k + 1) % 3], found = 0;
                for (uint32_t g = 0; g < p.ntris; g++)
                    for (int m = 0; m < 3; m++) found += p.tri[3 * g + m] == b && p.tri[3 * g + (m + 1) % 3] == a;
                unmatched += found != 1;
            }
        CHECKF(unmatched == 0, "level %d: %u edges without exactly one twin", level, unmatched);
        silmap_polytope_free(&p);
    }
    silmap_polytope p;
    CHECK(silmap_icosphere(7, &p) == -1 && silmap_icosphere(-1, &p) == -1);
}

static silmap_camera facing_z(int res, double focal)
{
    silmap_camera c = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, focal, res };
    return c;
}

TEST(rasterize_square)
{
    silmap_camera cam = facing_z(20, 10);
    double pos[] = { -0.5, -0.5, 1, 0.5, -0.5, 1, 0.5, 0.5, 1, -0.5, 0.5, 1 };
    uint32_t tri[] = { 0, 1, 2, 0, 2, 3 };
    uint8_t img[400];
    CHECK(silmap_rasterize(&cam, pos, 4, tri, 2, img) == 0);
    int wrong = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) wrong += img[y * 20 + x] != (x >= 5 && x < 15 && y >= 5 && y < 15);
    CHECKF(wrong == 0, "%d pixels wrong", wrong);
    double behind[] = { 0, 0, -1, 1, 0, 1, 0, 1, 1 };
    CHECK(silmap_rasterize(&cam, behind, 3, tri, 1, img) == -1);
}

/* Random triangles against barycentric coordinates per pixel centre. */
TEST(rasterize_matches_barycentric)
{
    enum { R = 48 };
    silmap_camera cam = facing_z(R, 30);
    uint8_t img[R * R];
    int wrong = 0;
    for (int trial = 0; trial < 100; trial++) {
        double pos[9];
        for (int k = 0; k < 3; k++) {
            pos[3 * k] = check_uniform(-1, 1), pos[3 * k + 1] = check_uniform(-1, 1), pos[3 * k + 2] = check_uniform(1, 2);
        }
        uint32_t tri[3] = { 0, 1, 2 };
        CHECK(silmap_rasterize(&cam, pos, 3, tri, 1, img) == 0);
        double q[3][2];
        for (int k = 0; k < 3; k++) silmap_project(&cam, &pos[3 * k], q[k]);
        double det = (q[1][1] - q[2][1]) * (q[0][0] - q[2][0]) + (q[2][0] - q[1][0]) * (q[0][1] - q[2][1]);
        for (int y = 0; y < R; y++)
            for (int x = 0; x < R; x++) {
                double px = x + 0.5, py = y + 0.5;
                double l0 = ((q[1][1] - q[2][1]) * (px - q[2][0]) + (q[2][0] - q[1][0]) * (py - q[2][1])) / det;
                double l1 = ((q[2][1] - q[0][1]) * (px - q[2][0]) + (q[0][0] - q[2][0]) * (py - q[2][1])) / det;
                double l2 = 1 - l0 - l1, m = fmin(l0, fmin(l1, l2));
                if (fabs(m) < 1e-9) continue;   /* on an edge: either answer */
                wrong += img[y * R + x] != (m > 0);
            }
    }
    CHECKF(wrong == 0, "%d pixels differ from the barycentric reference", wrong);
}

/* Loops of c: corners only (no straight-through points), axis-aligned
 * sides, areas adding up to the set pixels, perimeter = boundary sides. */
static void check_trace(const char *name, const uint8_t *img, int w, int h, const silmap_contours *c)
{
    long set = 0, sides = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (!img[y * w + x]) continue;
            set++;
            sides += y == 0 || !img[(y - 1) * w + x];
            sides += y == h - 1 || !img[(y + 1) * w + x];
            sides += x == 0 || !img[y * w + x - 1];
            sides += x == w - 1 || !img[y * w + x + 1];
        }
    double area2 = 0, perimeter = 0;
    int not_axis = 0, straight = 0;
    for (uint32_t l = 0; l < c->nloops; l++) {
        area2 += silmap_loop_area2(c, l);
        uint32_t a = c->start[l], b = c->start[l + 1], n = b - a;
        for (uint32_t k = 0; k < n; k++) {
            const double *p = &c->pt[2 * (a + k)], *q = &c->pt[2 * (a + (k + 1) % n)], *r = &c->pt[2 * (a + (k + 2) % n)];
            not_axis += p[0] != q[0] && p[1] != q[1];
            straight += (p[0] == q[0] && q[0] == r[0]) || (p[1] == q[1] && q[1] == r[1]);
            perimeter += fabs(q[0] - p[0]) + fabs(q[1] - p[1]);
        }
    }
    CHECKF(area2 == 2.0 * set, "%s: loops' area %g, %ld pixels set", name, area2 / 2, set);
    CHECKF(perimeter == (double)sides, "%s: perimeter %g, %ld boundary sides", name, perimeter, sides);
    CHECKF(not_axis == 0 && straight == 0, "%s: %d slanted sides, %d straight-through points", name, not_axis, straight);
}

TEST(trace_random_images)
{
    enum { W = 37, H = 29 };
    uint8_t img[W * H];
    for (int trial = 0; trial < 200; trial++) {
        double density = check_uniform(0.1, 0.9);
        for (int i = 0; i < W * H; i++) img[i] = check_uniform(0, 1) < density;
        silmap_contours c;
        CHECK(silmap_trace(img, W, H, &c) == 0);
        check_trace("random", img, W, H, &c);
        /* through the sides' middles: each corner cut by an eighth of a
         * pixel of area, every point the middle of a unit side */
        silmap_contours m;
        CHECK(silmap_midpoints(&c, &m) == 0);
        CHECK(m.nloops == c.nloops && m.npts <= 2 * c.npts);
        int off = 0;
        for (uint32_t l = 0; l < c.nloops && m.nloops == c.nloops; l++) {
            double corners = c.start[l + 1] - c.start[l];
            off += fabs(silmap_loop_area2(&m, l) - silmap_loop_area2(&c, l)) / 2 > corners / 8 + 1e-9;
        }
        for (uint32_t k = 0; k < m.npts; k++) {
            double fx = m.pt[2 * k] - floor(m.pt[2 * k]), fy = m.pt[2 * k + 1] - floor(m.pt[2 * k + 1]);
            off += !((fx == 0.5 && fy == 0) || (fx == 0 && fy == 0.5));
        }
        CHECKF(off == 0, "%d loops or points of the middles wrong", off);
        silmap_contours_free(&m);
        silmap_contours_free(&c);
    }
}

TEST(trace_hole_and_diagonal)
{
    /* a 5x5 ring around one unset pixel: an outer loop and a hole */
    uint8_t ring[7 * 7] = { 0 };
    for (int y = 1; y < 6; y++)
        for (int x = 1; x < 6; x++) ring[y * 7 + x] = !(x == 3 && y == 3);
    silmap_contours c;
    CHECK(silmap_trace(ring, 7, 7, &c) == 0);
    check_trace("ring", ring, 7, 7, &c);
    CHECKF(c.nloops == 2, "%u loops", c.nloops);
    if (c.nloops == 2) {
        double a0 = silmap_loop_area2(&c, 0) / 2, a1 = silmap_loop_area2(&c, 1) / 2;
        CHECKF((a0 == 25 && a1 == -1) || (a0 == -1 && a1 == 25), "areas %g and %g", a0, a1);
    }
    silmap_contours_free(&c);
    /* two pixels touching at a corner: two loops of area 1 */
    const uint8_t diag[3 * 3] = { 1, 0, 0, 0, 1, 0, 0, 0, 0 }, anti[3 * 3] = { 0, 1, 0, 1, 0, 0, 0, 0, 0 };
    const uint8_t *imgs[2] = { diag, anti };
    for (int i = 0; i < 2; i++) {
        CHECK(silmap_trace(imgs[i], 3, 3, &c) == 0);
        check_trace("diagonal", imgs[i], 3, 3, &c);
        CHECKF(c.nloops == 2 && c.npts == 8, "%u loops, %u points", c.nloops, c.npts);
        silmap_contours_free(&c);
    }
    /* the whole image set: one loop along its border */
    uint8_t full[4 * 3];
    memset(full, 1, sizeof full);
    CHECK(silmap_trace(full, 4, 3, &c) == 0);
    CHECKF(c.nloops == 1 && c.npts == 4 && silmap_loop_area2(&c, 0) == 24, "%u loops", c.nloops);
    silmap_contours_free(&c);
}

static double dist_to_loop(const silmap_contours *c, uint32_t l, const double *p)
{
    uint32_t a = c->start[l], n = c->start[l + 1] - a;
    double best = INFINITY;
    for (uint32_t k = 0; k < n; k++) {
        const double *u = &c->pt[2 * (a + k)], *v = &c->pt[2 * (a + (k + 1) % n)];
        double ab[2] = { v[0] - u[0], v[1] - u[1] }, ap[2] = { p[0] - u[0], p[1] - u[1] };
        double l2 = ab[0] * ab[0] + ab[1] * ab[1], t = l2 > 0 ? (ap[0] * ab[0] + ap[1] * ab[1]) / l2 : 0;
        t = fmin(1, fmax(0, t));
        best = fmin(best, hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]));
    }
    return best;
}

/* Douglas-Peucker keeps a subset, in order, and every point within tol. */
TEST(simplify_within_tolerance)
{
    enum { R = 96 };
    uint8_t img[R * R];
    for (int trial = 0; trial < 20; trial++) {
        /* a few overlapping discs and a hole */
        memset(img, 0, sizeof img);
        for (int d = 0; d < 4; d++) {
            double cx = check_uniform(20, 76), cy = check_uniform(20, 76), r = check_uniform(5, 20);
            for (int y = 0; y < R; y++)
                for (int x = 0; x < R; x++)
                    if (hypot(x + 0.5 - cx, y + 0.5 - cy) < r) img[y * R + x] = d < 3;
        }
        silmap_contours c, s;
        CHECK(silmap_trace(img, R, R, &c) == 0);
        double tol = check_uniform(0.3, 3);
        CHECK(silmap_simplify(&c, tol, &s) == 0);
        CHECK(s.nloops == c.nloops);
        double worst = 0;
        int not_subset = 0, few = 0;
        for (uint32_t l = 0; l < c.nloops && s.nloops == c.nloops; l++) {
            uint32_t a = c.start[l], n = c.start[l + 1] - a, k = 0;
            few += s.start[l + 1] - s.start[l] < 3;
            for (uint32_t j = s.start[l]; j < s.start[l + 1]; j++) {
                while (k < n && (c.pt[2 * (a + k)] != s.pt[2 * j] || c.pt[2 * (a + k) + 1] != s.pt[2 * j + 1])) k++;
                not_subset += k == n;
            }
            for (uint32_t k2 = 0; k2 < n; k2++) worst = fmax(worst, dist_to_loop(&s, l, &c.pt[2 * (a + k2)]));
        }
        CHECKF(worst <= tol + 1e-12, "a traced corner %g from the simplified outline, tolerance %g", worst, tol);
        CHECKF(not_subset == 0 && few == 0, "%d points not in the original, in order; %d loops under 3 points",
               not_subset, few);
        CHECKF(s.npts < c.npts, "%u points of %u kept", s.npts, c.npts);
        silmap_contours_free(&c);
        silmap_contours_free(&s);
    }
}

/* The dense map of a sphere: one loop per view, close to the exact
 * projected circle. */
TEST(sphere_map)
{
    gen_params gp;
    gen_defaults(GEN_SPHERE, &gp);
    gp.segments = 96, gp.bands = 96, gp.radius = 1;
    gen_mesh g;
    CHECK(gen_build(&gp, &g) == 0);
    silmap_params p;
    silmap_params_default(&p);
    p.level = 1;
    silmap m;
    CHECK(silmap_build(g.pos, g.nverts, g.tri, g.ntris, &p, &m) == 0);
    CHECKF(m.poly.nviews == 42 && fabs(m.radius - 1) < 1e-9, "%u views, radius %g", m.poly.nviews, m.radius);
    double worst = 0, area_err = 0;
    uint32_t pts = 0;
    for (uint32_t v = 0; v < m.poly.nviews; v++) {
        const silmap_view *view = &m.views[v];
        const silmap_contours *s = &view->outline;
        CHECKF(s->nloops == 1, "view %u: %u loops", v, s->nloops);
        pts += s->npts;
        /* the sphere's outline: a circle about the image centre */
        double rho = view->cam.focal * tan(asin(1.0 / p.distance)), half = p.res / 2.0;
        for (uint32_t k = 0; k < s->npts; k++)
            worst = fmax(worst, fabs(hypot(s->pt[2 * k] - half, s->pt[2 * k + 1] - half) - rho));
        if (s->nloops == 1)
            area_err = fmax(area_err, fabs(silmap_loop_area2(s, 0) / 2 / (3.14159265358979323846 * rho * rho) - 1));
    }
    CHECKF(worst < 1.5, "a polygon vertex %.3f px off the exact circle", worst);
    CHECKF(area_err < 0.01, "area off by %.4f", area_err);
    printf("  sphere, %u views at %d px: %u polygon vertices, within %.2f px of the circle, area within %.2f%%\n",
           m.poly.nviews, p.res, pts, worst, 100 * area_err);
    silmap_free(&m);
    p.res = 4;
    CHECK(silmap_build(g.pos, g.nverts, g.tri, g.ntris, &p, &m) == -1);
    gen_free(&g);
}

/* The dense map of the shared bunny: every view has an outline; what it
 * costs. */
TEST(bunny_map)
{
    char path[512];
    snprintf(path, sizeof path, "%s/bunny-fine.obj", check_meshes_dir());
    double *pos;
    uint32_t *tri, nv, nt;
    int r = tm_load_doubles(path, &pos, &nv, &tri, &nt);
    CHECK(r >= 0);
    if (r != 1) return;
    silmap_params p;
    silmap_params_default(&p);
    silmap m;
    clock_t t0 = clock();
    CHECK(silmap_build(pos, nv, tri, nt, &p, &m) == 0);
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    uint32_t pts = 0, most = 0, empty = 0, traced = 0;
    for (uint32_t v = 0; v < m.poly.nviews; v++) {
        const silmap_contours *o = &m.views[v].outline;
        double area = 0;
        for (uint32_t l = 0; l < o->nloops; l++) area += silmap_loop_area2(o, l) / 2;
        empty += !(area > 100);
        pts += o->npts, traced += m.views[v].traced_pts;
        if (o->npts > most) most = o->npts;
    }
    CHECKF(empty == 0, "%u views without an outline", empty);
    printf("  bunny-fine, %u views at %d px, %.2g px: %u corners traced, %u kept (%.0f a view, at most %u), %.2f s\n",
           m.poly.nviews, p.res, p.tol, traced, pts, (double)pts / m.poly.nviews, most, secs);
    silmap_free(&m);
    free(pos);
    free(tri);
}

int main(void)
{
    RUN(icosphere_views);
    RUN(rasterize_square);
    RUN(rasterize_matches_barycentric);
    RUN(trace_random_images);
    RUN(trace_hole_and_diagonal);
    RUN(simplify_within_tolerance);
    RUN(sphere_map);
    RUN(bunny_map);
    return check_done();
}
