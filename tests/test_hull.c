/*
 * test_hull.c - the progressive hulls of tools/prep/hull.c ("Silhouette
 * Mapping", section 7).  Outer hulls of the shared bunny, armadillo and
 * spot at 1000, 500 and 200 triangles (each made from the one before: the
 * sequence is progressive) and of generated spheres and tori: every vertex
 * of the detailed mesh is inside the hull or on it, by winding numbers in
 * double precision (the solid angles of the hull's faces, Van Oosterom and
 * Strackee); the hull is closed, manifold and consistently oriented; it
 * has the target's triangle count within 2%; its vertices lie on silk's
 * Q16.16 grid.  Inner hulls: every vertex inside the detailed mesh.  A
 * cube is its own hull: every collapse would cut a corner.
 */
#include <math.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "support/testmesh.h"
#include "support/testvec.h"
#include "../tools/prep/closest.h"
#include "../tools/prep/gen.h"
#include "../tools/prep/hull.h"

static const double PI = 3.14159265358979323846;

static dvec at(const simp_mesh *m, uint32_t i) { return dmk(m->pos[3 * i], m->pos[3 * i + 1], m->pos[3 * i + 2]); }

/* The winding number of m about p: the solid angles of its faces / 4 pi. */
static double winding(const simp_mesh *m, const double p[3])
{
    double sum = 0;
    dvec q = dmk(p[0], p[1], p[2]);
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *t = &m->tri[3 * f];
        dvec a = dsub(at(m, t[0]), q), b = dsub(at(m, t[1]), q), c = dsub(at(m, t[2]), q);
        double la = dlen(a), lb = dlen(b), lc = dlen(c);
        sum += 2 * atan2(ddot(a, dcross(b, c)), la * lb * lc + ddot(a, b) * lc + ddot(a, c) * lb + ddot(b, c) * la);
    }
    return sum / (4 * PI);
}

static double surface_distance(const simp_mesh *m, const double p[3])
{
    double best = INFINITY;
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *t = &m->tri[3 * f];
        best = fmin(best, point_tri_d2(p, &m->pos[3 * t[0]], &m->pos[3 * t[1]], &m->pos[3 * t[2]]));
    }
    return sqrt(best);
}

/* Points of pts (n of them) that are neither inside `outer` (winding
 * number 1 or more) nor on its surface (within 1e-9). */
static uint32_t outside(const simp_mesh *outer, const double *pts, uint32_t n, double *worst)
{
    uint32_t bad = 0;
    *worst = 0;
    for (uint32_t i = 0; i < n; i++) {
        double w = winding(outer, &pts[3 * i]);
        if (w > 0.999) continue;
        double d = surface_distance(outer, &pts[3 * i]);   /* on the surface, the sum is ambiguous */
        if (d <= 1e-9) continue;
        bad++;
        if (d > *worst) *worst = d;
    }
    return bad;
}

static void copy_mesh(const simp_mesh *src, simp_mesh *dst)
{
    CHECK(simp_copy(src, dst) == 0);
}

/* The nearest face of m to p, and its distance. */
static uint32_t nearest_face(const simp_mesh *m, const double p[3], double *dist)
{
    double best = INFINITY;
    uint32_t at = 0;
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *t = &m->tri[3 * f];
        double d = point_tri_d2(p, &m->pos[3 * t[0]], &m->pos[3 * t[1]], &m->pos[3 * t[2]]);
        if (d < best) best = d, at = f;
    }
    *dist = sqrt(best);
    return at;
}

/* What the hull's vertices stand for (section 7's closest points): near
 * the detailed surface (nearer than half the hull vertices' distance, on
 * average: interpolating across faces cuts the curved surface), with normals
 * close to the detailed surface's there. */
static void check_stands_for(const char *name, const simp_mesh *fine, const simp_mesh *h, const hull_fine *s)
{
    double worst = 0, sum_cos = 0, sum_hull = 0, sum_point = 0;
    uint32_t facing_away = 0;
    for (uint32_t i = 0; i < h->nverts; i++) {
        double d, dh;
        uint32_t f = nearest_face(fine, &s->point[3 * i], &d);
        nearest_face(fine, &h->pos[3 * i], &dh);
        const uint32_t *t = &fine->tri[3 * f];
        dvec n = dnorm(dcross(dsub(at(fine, t[1]), at(fine, t[0])), dsub(at(fine, t[2]), at(fine, t[0]))));
        double c = ddot(n, dmk(s->normal[3 * i], s->normal[3 * i + 1], s->normal[3 * i + 2]));
        sum_cos += c, facing_away += c < 0;
        worst = fmax(worst, d), sum_point += d, sum_hull += dh;
    }
    double mean_cos = sum_cos / h->nverts;
    CHECKF(sum_point < 0.5 * sum_hull, "%s: the points are %g from the surface on average, the hull's vertices %g",
           name, sum_point / h->nverts, sum_hull / h->nverts);
    CHECKF(mean_cos > 0.8 && facing_away <= h->nverts / 50, "%s: normals' mean cosine %.3f, %u facing away", name,
           mean_cos, facing_away);
    printf("  %s: closest points %.2g from the surface on average (hull vertices %.2g), at most %.2g; normals' mean "
           "cosine %.3f\n", name, sum_point / h->nverts, sum_hull / h->nverts, worst, mean_cos);
}

/* Closed, manifold, oriented, the target's count within 2%. */
static void check_shape(const char *name, const simp_mesh *h, uint32_t target)
{
    simp_topology t;
    CHECK(simp_topology_check(h, &t) == 0);
    CHECKF(t.boundary_edges == 0 && t.nonmanifold_edges == 0 && t.nonmanifold_verts == 0 &&
               t.misoriented_edges == 0 && t.degenerate_tris == 0 && t.unused_verts == 0,
           "%s: %u boundary, %u non-manifold, %u misoriented edges, %u non-manifold vertices, %u degenerate", name,
           t.boundary_edges, t.nonmanifold_edges, t.misoriented_edges, t.nonmanifold_verts, t.degenerate_tris);
    CHECKF(fabs((double)h->ntris - target) <= 0.02 * target, "%s: %u triangles for %u", name, h->ntris, target);
}

/* The outer hull of fine at target (made from prev, a hull of fine or fine
 * itself) into out: the checks, and what it took. */
static void outer_step(const char *name, const simp_mesh *fine, const simp_mesh *prev, uint32_t target, simp_mesh *out)
{
    copy_mesh(prev, out);
    hull_opts o;
    hull_opts_default(&o, target);
    hull_stats st;
    clock_t t0 = clock();
    hull_fine stands;
    CHECK(hull_run(out, &o, &st, &stands) == 0);
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    check_shape(name, out, target);
    double worst;
    uint32_t bad = outside(out, fine->pos, fine->nverts, &worst);
    CHECKF(bad == 0, "%s at %u: %u of %u fine vertices outside the hull, up to %g", name, target, bad, fine->nverts,
           worst);
    uint32_t off_grid = 0;
    for (uint32_t i = 0; i < 3 * out->nverts; i++) off_grid += out->pos[i] * 65536 != nearbyint(out->pos[i] * 65536);
    CHECKF(off_grid == 0, "%s: %u coordinates off the Q16.16 grid", name, off_grid);
    CHECKF(st.volume_out >= hull_volume(fine), "%s: the hull holds less volume than the mesh", name);
    printf("  %s: %u -> %u triangles in %.2f s (%u LPs), volume +%.1f%%\n", name, prev->ntris, out->ntris, secs,
           st.lps, 100 * (st.volume_out / hull_volume(fine) - 1));
    if (prev == fine) check_stands_for(name, fine, out, &stands);
    hull_fine_free(&stands);
}

static void inner_check(const char *name, const simp_mesh *fine, uint32_t target)
{
    simp_mesh in;
    copy_mesh(fine, &in);
    hull_opts o;
    hull_opts_default(&o, target);
    o.inner = 1;
    hull_stats st;
    CHECK(hull_run(&in, &o, &st, NULL) == 0);
    check_shape(name, &in, target);
    double worst;
    uint32_t bad = outside(fine, in.pos, in.nverts, &worst);
    CHECKF(bad == 0, "%s inner at %u: %u of %u hull vertices outside the mesh, up to %g", name, target, bad,
           in.nverts, worst);
    CHECKF(st.volume_out <= st.volume_in && st.volume_out > 0, "%s: inner volume %g, mesh %g", name, st.volume_out,
           st.volume_in);
    printf("  %s inner: %u triangles, volume %.1f%%\n", name, in.ntris, 100 * (st.volume_out / st.volume_in - 1));
    simp_free(&in);
}

static int from_gen(gen_shape s, int segments, int bands, simp_mesh *m)
{
    gen_params p;
    gen_defaults(s, &p);
    p.segments = segments, p.bands = bands;
    gen_mesh g;
    if (gen_build(&p, &g)) return -1;
    m->nverts = g.nverts, m->ntris = g.ntris, m->pos = g.pos, m->tri = g.tri, m->origin = NULL;
    return 0;
}

TEST(hull_generated)
{
    const struct { gen_shape s; int seg, bands; uint32_t target; const char *name; } cases[] = {
        { GEN_SPHERE, 40, 40, 200, "sphere" },
        { GEN_TORUS, 48, 24, 200, "torus" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        simp_mesh fine, h;
        CHECK(from_gen(cases[i].s, cases[i].seg, cases[i].bands, &fine) == 0);
        outer_step(cases[i].name, &fine, &fine, cases[i].target, &h);
        inner_check(cases[i].name, &fine, cases[i].target);
        simp_free(&h);
        simp_free(&fine);
    }
}

TEST(hull_cube_is_its_own_hull)
{
    double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
    uint32_t tri[] = { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                       1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7 };
    simp_mesh m = { 8, 12, malloc(sizeof pos), malloc(sizeof tri), NULL };
    memcpy(m.pos, pos, sizeof pos), memcpy(m.tri, tri, sizeof tri);
    CHECK(hull_volume(&m) > 0.999 && hull_volume(&m) < 1.001);
    hull_opts o;
    hull_opts_default(&o, 4);
    hull_stats st;
    CHECK(hull_run(&m, &o, &st, NULL) == 0);
    CHECKF(m.ntris == 12 && st.collapses == 0 && st.refused_infeasible > 0, "%u triangles, %u collapses", m.ntris,
           st.collapses);
    simp_free(&m);
}

/* The shared mesh NAME as silk loads it, widened to double; -1 (with a
 * skip line) when it is not there. */
static int load_shared(const char *name, simp_mesh *out)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
    out->origin = NULL;
    int r = tm_load_doubles(path, &out->pos, &out->nverts, &out->tri, &out->ntris);
    CHECKF(r >= 0, "%s does not load", name);
    return r == 1 ? 0 : -1;
}

static void shared_sequence(const char *name)
{
    simp_mesh fine, h[3];
    if (load_shared(name, &fine)) return;
    const uint32_t targets[3] = { 1000, 500, 200 };
    for (int i = 0; i < 3; i++) outer_step(name, &fine, i ? &h[i - 1] : &fine, targets[i], &h[i]);
    for (int i = 0; i < 3; i++) simp_free(&h[i]);
    simp_free(&fine);
}

TEST(hull_bunny) { shared_sequence("bunny-fine.obj"); }
TEST(hull_armadillo) { shared_sequence("armadillo-fine.obj"); }
TEST(hull_spot) { shared_sequence("spot-fine.obj"); }

TEST(hull_inner_spot)
{
    simp_mesh fine;
    if (load_shared("spot-fine.obj", &fine)) return;
    inner_check("spot", &fine, 500);
    simp_free(&fine);
}

int main(void)
{
    RUN(hull_cube_is_its_own_hull);
    RUN(hull_generated);
    RUN(hull_bunny);
    RUN(hull_armadillo);
    RUN(hull_spot);
    RUN(hull_inner_spot);
    return check_done();
}
