/*
 * test_simplify.c - `silk simplify`'s edge collapse (tools/prep/simplify.c):
 * bunny-fine, sphere-fine and fandisk-fine simplified to 500, 200 and 128
 * triangles stay closed, manifold and consistently oriented, with the
 * genus of the input, land within 2% of the target, and are as close to
 * the fine mesh as the reference meshes made by MeshLab's quadric
 * simplification (the shared bunny-500 etc., SOURCES.md), measured the
 * same way: the distance of every vertex of one mesh to the surface of the
 * other, both ways.  Open meshes keep their boundary.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "support/testmesh.h"
#include "silk/silk.h"
#include "../platform/platform.h"
#include "../tools/prep/simplify.c"
#include "../tools/prep/surface.c"
#include "../tools/prep/closest.c"

/* Load with silk's loader, as the command does. */
static int load(const char *name, simp_mesh *out)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
    memset(out, 0, sizeof *out);
    int r = tm_load_doubles(path, &out->pos, &out->nverts, &out->tri, &out->ntris);
    CHECKF(r >= 0, "%s does not load", name);
    return r == 1 ? 0 : -1;
}

typedef struct dist { double mean, max; } dist;

/* Every vertex of a to the surface of b, brute force. */
static void one_way(const simp_mesh *a, const simp_mesh *b, double *sum, double *max)
{
    for (uint32_t i = 0; i < a->nverts; i++) {
        double best = INFINITY;
        for (uint32_t f = 0; f < b->ntris; f++) {
            const uint32_t *t = &b->tri[3 * f];
            double d = point_tri_d2(&a->pos[3 * i], &b->pos[3 * t[0]], &b->pos[3 * t[1]], &b->pos[3 * t[2]]);
            if (d < best) best = d;
        }
        best = sqrt(best);
        *sum += best;
        if (best > *max) *max = best;
    }
}

/* Both ways, over the fine mesh's bounding-box diagonal. */
static dist distance(const simp_mesh *coarse, const simp_mesh *fine)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t i = 0; i < fine->nverts; i++)
        for (int k = 0; k < 3; k++) {
            if (fine->pos[3 * i + k] < lo[k]) lo[k] = fine->pos[3 * i + k];
            if (fine->pos[3 * i + k] > hi[k]) hi[k] = fine->pos[3 * i + k];
        }
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double s1 = 0, s2 = 0, m1 = 0, m2 = 0;
    one_way(coarse, fine, &s1, &m1);
    one_way(fine, coarse, &s2, &m2);
    dist d = { (s1 / coarse->nverts + s2 / fine->nverts) / 2 / diag, (m1 > m2 ? m1 : m2) / diag };
    return d;
}

static void closed_manifold(const simp_mesh *m, int euler, const char *what)
{
    simp_topology t;
    CHECK(simp_topology_check(m, &t) == 0);
    CHECKF(t.boundary_edges == 0 && t.nonmanifold_edges == 0 && t.misoriented_edges == 0 && t.nonmanifold_verts == 0 &&
               t.degenerate_tris == 0 && t.unused_verts == 0,
           "%s: %u boundary, %u non-manifold, %u misoriented edges, %u non-manifold vertices, %u degenerate, %u unused",
           what, t.boundary_edges, t.nonmanifold_edges, t.misoriented_edges, t.nonmanifold_verts, t.degenerate_tris,
           t.unused_verts);
    CHECKF(t.euler == euler, "%s: Euler characteristic %d, the input's %d", what, t.euler, euler);
}

/* The fine mesh, the reference made from it and a copy of the fine one to
 * simplify; the fine mesh's Euler characteristic.  -1 (skipped) when the
 * shared meshes are not there. */
static int load_pair(const char *fine_name, const char *ref_name, simp_mesh *fine, simp_mesh *ref, simp_mesh *out,
                     int *euler)
{
    if (load(fine_name, fine)) return -1;
    if (load(ref_name, ref)) {
        simp_free(fine);
        return -1;
    }
    simp_topology t;
    CHECK(simp_topology_check(fine, &t) == 0);
    *euler = t.euler;
    CHECK(simp_copy(fine, out) == 0);
    return 0;
}

static void simplify_like_reference(const char *fine_name, const char *ref_name, uint32_t target)
{
    simp_mesh fine, out, ref;
    int euler;
    if (load_pair(fine_name, ref_name, &fine, &ref, &out, &euler)) return;
    simp_opts o;
    simp_opts_default(&o, target);
    simp_stats st;
    CHECK(simp_run(&out, &o, &st) == 0);
    CHECKF(fabs((double)out.ntris - target) <= 0.02 * target, "%s: %u triangles for a target of %u", fine_name,
           out.ntris, target);
    CHECK(st.tris_out == out.ntris && st.collapses == (fine.ntris - out.ntris) / 2);
    closed_manifold(&out, euler, fine_name);
    dist ours = distance(&out, &fine), theirs = distance(&ref, &fine);
    printf("  %s -> %u: distance/diagonal mean %.2e max %.2e; %s: mean %.2e max %.2e\n", fine_name, out.ntris, ours.mean,
           ours.max, ref_name, theirs.mean, theirs.max);
    CHECKF(ours.mean <= 1.5 * theirs.mean, "%s: mean distance %.3g, MeshLab's %.3g", fine_name, ours.mean, theirs.mean);
    CHECKF(ours.max <= 2 * theirs.max, "%s: max distance %.3g, MeshLab's %.3g", fine_name, ours.max, theirs.max);
    simp_free(&fine);
    simp_free(&out);
    simp_free(&ref);
}

TEST(bunny_to_500) { simplify_like_reference("bunny-fine.obj", "bunny-500.obj", 500); }
TEST(sphere_to_200) { simplify_like_reference("sphere-fine.obj", "sphere-200.obj", 200); }
TEST(fandisk_to_128) { simplify_like_reference("fandisk-fine.obj", "fandisk-128.obj", 128); }

/* Subset placement (--for smooth): every output vertex is the input vertex
 * origin[] names, bit for bit; the count and topology hold as with optimal
 * placement; the surface stays about as close to the fine one (it cannot
 * be quite as close: no vertex may leave the surface); and the normals are
 * the fine mesh's: at a vertex with one normal, the angle-weighted normal
 * of the fine faces around it, computed here independently. */
static void on_surface(const char *fine_name, const char *ref_name, uint32_t target, int want_splits)
{
    simp_mesh fine, out, ref;
    int euler;
    if (load_pair(fine_name, ref_name, &fine, &ref, &out, &euler)) return;
    simp_opts o;
    simp_opts_default(&o, target);
    o.subset = 1;
    simp_stats st;
    CHECK(simp_run(&out, &o, &st) == 0);
    CHECKF(fabs((double)out.ntris - target) <= 0.02 * target, "%s: %u triangles for %u", fine_name, out.ntris, target);
    closed_manifold(&out, euler, fine_name);
    uint32_t moved = 0;
    for (uint32_t v = 0; v < out.nverts; v++)
        moved += memcmp(&out.pos[3 * v], &fine.pos[3 * out.origin[v]], 3 * sizeof(double)) != 0;
    CHECKF(moved == 0, "%s: %u vertices are not input vertices", fine_name, moved);
    dist ours = distance(&out, &fine), theirs = distance(&ref, &fine);
    printf("  %s -> %u on the surface: distance/diagonal mean %.2e max %.2e; %s: mean %.2e max %.2e\n", fine_name,
           out.ntris, ours.mean, ours.max, ref_name, theirs.mean, theirs.max);
    CHECKF(ours.mean <= 2 * theirs.mean, "%s: mean distance %.3g, MeshLab's %.3g", fine_name, ours.mean, theirs.mean);

    surf_normals sn;
    CHECK(surf_normals_compute(&fine, &out, 60, &sn) == 0);
    uint32_t *count = calloc(out.nverts, sizeof *count), *first = malloc(out.nverts * sizeof *first), split = 0;
    for (uint32_t c = 0; c < 3 * out.ntris; c++) {
        uint32_t v = out.tri[c], n = sn.tri_normal[c];
        CHECK(n < sn.nnormals && fabs(len3(&sn.normal[3 * n]) - 1) < 1e-12);
        if (count[v]++ == 0) first[v] = n;
        else if (first[v] != n && first[v] != UINT32_MAX) first[v] = UINT32_MAX, split++;
    }
    double worst = 0;
    for (uint32_t v = 0; v < out.nverts; v++) {
        if (first[v] == UINT32_MAX) continue;
        double ref_n[3] = { 0, 0, 0 };
        uint32_t f = out.origin[v];
        for (uint32_t ft = 0; ft < fine.ntris; ft++)
            for (int k = 0; k < 3; k++) {
                if (fine.tri[3 * ft + k] != f) continue;
                const double *p = &fine.pos[3 * f], *a = &fine.pos[3 * fine.tri[3 * ft + (k + 1) % 3]],
                             *b = &fine.pos[3 * fine.tri[3 * ft + (k + 2) % 3]];
                double e1[3], e2[3], n[3];
                sub3(a, p, e1);
                sub3(b, p, e2);
                cross3(e1, e2, n);
                double l = len3(n), ang = acos(dot3(e1, e2) / (len3(e1) * len3(e2)));
                for (int j = 0; j < 3; j++) ref_n[j] += ang * n[j] / l;
            }
        double l = len3(ref_n), d = 0;
        for (int j = 0; j < 3; j++) d += fabs(ref_n[j] / l - sn.normal[3 * first[v] + j]);
        if (d > worst) worst = d;
    }
    CHECKF(worst < 1e-9, "%s: a normal differs from the fine angle-weighted normal by %.3g", fine_name, worst);
    CHECKF(want_splits ? split > 0 : split == 0, "%s: %u vertices with split normals", fine_name, split);
    printf("  %s: %u normals for %u vertices, %u split\n", fine_name, sn.nnormals, out.nverts, split);
    free(count), free(first);
    surf_normals_free(&sn);
    simp_free(&fine);
    simp_free(&out);
    simp_free(&ref);
}

/* The box hierarchy (tools/prep/closest.c) against brute force: the same
 * squared distance, bit for bit, from points near and far from bunny-fine. */
TEST(closest_point_tree)
{
    simp_mesh fine;
    if (load("bunny-fine.obj", &fine)) return;
    cp_tree t;
    CHECK(cp_build(&t, fine.pos, fine.tri, fine.ntris) == 0);
    int bad = 0;
    for (int i = 0; i < 200; i++) {
        const double *v = &fine.pos[3 * ((uint32_t)i * 2654435761u % fine.nverts)];
        double s = i < 150 ? 0.02 : 1.5, p[3] = { v[0] + s * check_uniform(-1, 1), v[1] + s * check_uniform(-1, 1),
                                                   v[2] + s * check_uniform(-1, 1) };
        double best = INFINITY;
        for (uint32_t f = 0; f < fine.ntris; f++) {
            const uint32_t *tr = &fine.tri[3 * f];
            double d = point_tri_d2(p, &fine.pos[3 * tr[0]], &fine.pos[3 * tr[1]], &fine.pos[3 * tr[2]]);
            if (d < best) best = d;
        }
        uint32_t ft;
        double got = cp_nearest(&t, p, &ft);
        const uint32_t *tr = &fine.tri[3 * ft];
        bad += got != best || point_tri_d2(p, &fine.pos[3 * tr[0]], &fine.pos[3 * tr[1]], &fine.pos[3 * tr[2]]) != got;
    }
    CHECKF(bad == 0, "%d of 200 distances differ from brute force", bad);
    cp_free(&t);
    simp_free(&fine);
}

TEST(bunny_on_surface) { on_surface("bunny-fine.obj", "bunny-500.obj", 500, 1); }
TEST(fandisk_on_surface) { on_surface("fandisk-fine.obj", "fandisk-128.obj", 128, 1); }
TEST(sphere_on_surface) { on_surface("sphere-fine.obj", "sphere-200.obj", 200, 0); }

/* A torus (genus 1) as a U x V grid of quads, two triangles each. */
static simp_mesh grid_torus(int U, int V)
{
    simp_mesh m = { (uint32_t)(U * V), (uint32_t)(2 * U * V), malloc(3 * sizeof(double) * U * V),
                    malloc(6 * sizeof(uint32_t) * U * V), NULL };
    for (int i = 0; i < U; i++)
        for (int j = 0; j < V; j++) {
            double a = 2 * 3.14159265358979 * i / U, b = 2 * 3.14159265358979 * j / V;
            double *p = &m.pos[3 * (i * V + j)];
            p[0] = (1 + 0.4 * cos(b)) * cos(a), p[1] = 0.4 * sin(b), p[2] = -(1 + 0.4 * cos(b)) * sin(a);
            uint32_t q[4] = { (uint32_t)(i * V + j), (uint32_t)(((i + 1) % U) * V + j),
                              (uint32_t)(((i + 1) % U) * V + (j + 1) % V), (uint32_t)(i * V + (j + 1) % V) };
            uint32_t *t = &m.tri[6 * (i * V + j)];
            t[0] = q[0], t[1] = q[1], t[2] = q[2], t[3] = q[0], t[4] = q[2], t[5] = q[3];
        }
    return m;
}

/* Stays a closed torus down to a few dozen triangles, every collapse
 * removing two. */
TEST(torus_keeps_its_genus)
{
    simp_mesh m = grid_torus(40, 20);
    simp_topology t;
    CHECK(simp_topology_check(&m, &t) == 0);
    CHECK(t.euler == 0 && t.boundary_edges == 0 && t.misoriented_edges == 0);
    for (uint32_t target = 600; target >= 30; target = target * 2 / 3) {
        simp_opts o;
        simp_opts_default(&o, target);
        simp_stats st;
        CHECK(simp_run(&m, &o, &st) == 0);
        CHECKF(m.ntris <= target && m.ntris >= target - 2, "%u triangles for %u", m.ntris, target);
        closed_manifold(&m, 0, "torus");
    }
    simp_free(&m);
}

/* The link condition alone: on a torus whose tube is three vertices round,
 * the vertices of a ring are all adjacent, so collapsing a ring edge would
 * merge the edges to the third vertex into a non-manifold one; an edge
 * along the tube is fine. */
TEST(link_condition)
{
    enum { U = 12, V = 3 };
    simp_mesh m = grid_torus(U, V);
    simp_opts o;
    simp_opts_default(&o, 0);
    simp_stats st;
    state s;
    CHECK(state_init(&s, &m, &o, &st) == 0);
    cand c;
    price(&s, 0, 1, &c);                   /* vertices (0,0) and (0,1): a ring edge */
    CHECK(check(&s, &c) == REFUSE_TOPOLOGY);
    price(&s, 0, V, &c);                   /* (0,0) and (1,0): along the tube */
    CHECK(check(&s, &c) != REFUSE_TOPOLOGY);
    state_free(&s);
    simp_free(&m);
}

/* An open, wavy square: the boundary is a feature, so its corners stay and
 * its vertices stay on the square's sides. */
TEST(open_mesh_keeps_its_boundary)
{
    enum { N = 30 };
    simp_mesh m = { (N + 1) * (N + 1), 2 * N * N, malloc(3 * sizeof(double) * (N + 1) * (N + 1)),
                    malloc(6 * sizeof(uint32_t) * N * N), NULL };
    for (int i = 0; i <= N; i++)
        for (int j = 0; j <= N; j++) {
            double *p = &m.pos[3 * (i * (N + 1) + j)];
            p[0] = (double)i / N, p[1] = (double)j / N, p[2] = 0.05 * sin(6 * p[0]) * sin(5 * p[1]);
        }
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            uint32_t a = (uint32_t)(i * (N + 1) + j), b = a + N + 1, *t = &m.tri[6 * (i * N + j)];
            t[0] = a, t[1] = b, t[2] = b + 1, t[3] = a, t[4] = b + 1, t[5] = a + 1;
        }
    simp_opts o;
    simp_opts_default(&o, 100);
    simp_stats st;
    CHECK(simp_run(&m, &o, &st) == 0);
    CHECKF(m.ntris <= 100 && m.ntris >= 98, "%u triangles", m.ntris);
    simp_topology t;
    CHECK(simp_topology_check(&m, &t) == 0);
    CHECK(t.nonmanifold_edges == 0 && t.nonmanifold_verts == 0 && t.misoriented_edges == 0 && t.boundary_edges > 0);
    CHECKF(t.euler == 1, "euler %d (a disc has 1)", t.euler);
    /* Quadrics keep features approximately, not exactly: within 1% of
     * the side (the grid spacing is 3.3%). */
    const double tol = 0.01;
    int corners = 0, off_side = 0, on_side = 0;
    for (uint32_t i = 0; i < m.nverts; i++) {
        const double *p = &m.pos[3 * i];
        int on_x = fabs(p[0]) < tol || fabs(p[0] - 1) < tol, on_y = fabs(p[1]) < tol || fabs(p[1] - 1) < tol;
        corners += on_x && on_y;
        on_side += on_x || on_y;
        if (p[0] < -tol || p[0] > 1 + tol || p[1] < -tol || p[1] > 1 + tol) off_side++;
    }
    CHECKF(corners == 4, "%d corners kept", corners);
    CHECKF(off_side == 0, "%d vertices moved out of the square", off_side);
    CHECKF((uint32_t)on_side == t.boundary_edges, "%d vertices on the sides, %u boundary edges", on_side,
           t.boundary_edges);
    simp_free(&m);
}

int main(void)
{
    RUN(bunny_to_500);
    RUN(sphere_to_200);
    RUN(fandisk_to_128);
    RUN(closest_point_tree);
    RUN(bunny_on_surface);
    RUN(fandisk_on_surface);
    RUN(sphere_on_surface);
    RUN(torus_keeps_its_genus);
    RUN(link_condition);
    RUN(open_mesh_keeps_its_boundary);
    return check_done();
}
