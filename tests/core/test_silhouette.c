/*
 * test_silhouette.c - silhouette triangles, bridges, silhouette points and
 * sampling (paper III-B..E) against double-precision references, and the
 * sharing rule: every point on a mesh edge is computed once per frame and
 * evaluates to the same bits in every triangle that uses the edge.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "src/plan.h"
#include "src/remesh.h"
#include "src/curve.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (32u << 20)
static unsigned char *arena_buf;

static int load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    return tm_load_shared(a, name, m);
}

static void random_dir(double d[3])
{
    double l;
    do {
        for (int i = 0; i < 3; i++) d[i] = check_uniform(-1, 1);
        l = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (l < 0.01 || l > 1);
}

/* View direction towards the eye, in double, from the same camera. */
static void to_eye_d(const silk_view *v, silk_vec3 p, double d[3])
{
    if (v->cam.ortho) { vec3d(v->forward, d); for (int i = 0; i < 3; i++) d[i] = -d[i]; return; }
    double e[3], q[3];
    vec3d(v->cam.eye, e);
    vec3d(p, q);
    for (int i = 0; i < 3; i++) d[i] = e[i] - q[i];
}

/* View i of a test's random ones: a random direction, 1.2 to 6.2 radii
 * away, perspective and orthographic in turn; 0 when it cannot be made. */
static int random_view(const silk_mesh *m, int i, silk_view *v)
{
    double dir[3];
    random_dir(dir);
    return tf_view_around(m, dir, 1.2 + check_uniform(0, 5), i & 1, v);
}

/* ---- references ------------------------------------------------------------ */

/* Eqs. 2-5: tangents of the bridge over p0 -> p1, with the tilt and bulge
 * bounds. */
static void bridge_ref(const double p0[3], const double n0[3], const double p1[3], const double n1[3],
                       double t0[3], double t1[3])
{
    double c[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    double cl = sqrt(dot3(c, c));
    const double *n[2] = { n0, n1 };
    double *t[2] = { t0, t1 };
    double lean[2] = { dot3(c, n0) / sqrt(dot3(n0, n0)), dot3(c, n1) / sqrt(dot3(n1, n1)) };
    for (int k = 0; k < 2; k++) {
        double nl = sqrt(dot3(n[k], n[k])), cap = fabs(lean[1 - k]) + cl / SILK_TILT_SLACK;
        double cn = fmax(-cap, fmin(cap, lean[k])) / nl;   /* the tilt bound (curve.h) */
        double d[3] = { c[0] - cn * n[k][0], c[1] - cn * n[k][1], c[2] - cn * n[k][2] };
        double dl = sqrt(dot3(d, d));
        double cos_t = dl > 0 ? dot3(d, c) / (dl * cl) : 1;
        double len = 2 * cl / (1 + cos_t), sin_t = sqrt(fmax(0, 1 - cos_t * cos_t));
        if (sin_t > 0) len = fmin(len, cl / (SILK_BULGE_DIV * sin_t));   /* the bulge bound, curve.h */
        for (int i = 0; i < 3; i++) t[k][i] = dl > 0 ? d[i] / dl * len : c[i];
    }
}

/* Eqs. 6-7: the root in [0,1] of ((1-u) d0 + u d1).((1-u) n0 + u n1), by bisection. */
static double param_ref(const double n0[3], const double d0[3], const double n1[3], const double d1[3])
{
    double lo = 0, hi = 1;
    double h0 = dot3(n0, d0);
    for (int it = 0; it < 200; it++) {
        double u = (lo + hi) / 2, n[3], d[3];
        for (int i = 0; i < 3; i++) { n[i] = (1 - u) * n0[i] + u * n1[i]; d[i] = (1 - u) * d0[i] + u * d1[i]; }
        double h = dot3(n, d);
        if ((h >= 0) == (h0 >= 0)) lo = u; else hi = u;
    }
    return (lo + hi) / 2;
}

static void hermite_ref(const double p0[3], const double p1[3], const double t0[3], const double t1[3], double u,
                        double out[3])
{
    double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
    double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
    for (int i = 0; i < 3; i++) out[i] = h00 * p0[i] + h10 * t0[i] + h01 * p1[i] + h11 * t1[i];
}

/* ---- tests ----------------------------------------------------------------- */

/* III-B: a triangle is a silhouette triangle when its corner normals'
 * visibility N.(E-V) >= 0 disagrees.  The double reference is exact here:
 * every product of two Q16.16 numbers below 2^27 fits a double's mantissa. */
static void silhouette_triangles(const char *name, int nviews)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    uint32_t wrong_tri = 0, wrong_lone = 0, wrong_count = 0, total = 0;
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        uint32_t count = 0;
        for (uint32_t t = 0; t < m.ntris; t++) {
            int vis[3];
            for (int k = 0; k < 3; k++) {
                double n[3], e[3];
                vec3d(m.normal[m.tri_normal[3 * t + k]], n);
                to_eye_d(&v, m.pos[m.tri[3 * t + k]], e);
                vis[k] = dot3(n, e) >= 0;
            }
            int sil = vis[0] != vis[1] || vis[1] != vis[2];
            count += sil;
            int got = (f.tri_state[t] & SILK_TS_SIL) != 0;
            if (got != sil) wrong_tri++;
            if (sil && got) {
                int lone = vis[0] == vis[1] ? 2 : (vis[0] == vis[2] ? 1 : 0);
                if ((int)(f.tri_state[t] & SILK_TS_LONE) != lone) wrong_lone++;
            }
        }
        if (st.silhouette_tris != count) wrong_count++;
        total += count;
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %d views, %u silhouette triangles in all\n", name, nviews, total);
    CHECKF(wrong_tri == 0, "%s: %u triangles misclassified", name, wrong_tri);
    CHECKF(wrong_lone == 0, "%s: %u wrong lone corners", name, wrong_lone);
    CHECKF(wrong_count == 0, "%s: stats count wrong in %u views", name, wrong_count);
    CHECK(total > 0);
}

TEST(silhouette_triangles_sphere) { silhouette_triangles("sphere-200.obj", 40); }

/* silk_sil_tri_front decides most triangles without normalising the face
 * normal: the same answers as the normalised test, edge-on triangles
 * (|cos| < 1e-3 between face normal and eye direction, counted) included;
 * silk_sil_tri_fronts gives them all at once (a build with
 * SILK_AA_CANDIDATES; in one without, it is not called). */
static void tri_front_as_normalised(const char *name, int nviews)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    uint8_t *facing = silk_arena_array(&a, (m.ntris + 3) / 4, 1, SILK_MEM_FRAME);
    if (!facing) { CHECK(0); return; }
    uint32_t wrong = 0, grazing = 0, wrong_all = 0;
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_sil_tri_fronts(&m, &v, facing);
        for (uint32_t t = 0; t < m.ntris; t++) {
            silk_vec3 e = silk_view_to_eye(&v, m.pos[m.tri[3 * t]]);
            int want = silk_v3_dot64(silk_mesh_face_normal(&m, t), e) > 0;
            wrong += silk_sil_tri_front(&m, &v, t) != want;
            wrong_all += (facing[t / 4] >> 2 * (t % 4) & 3) != (2u | (unsigned)want);
            double n[3], ed[3];
            vec3d(silk_mesh_face_normal(&m, t), n);
            vec3d(e, ed);
            double c = dot3(n, ed) / sqrt(dot3(n, n) * dot3(ed, ed) + 1e-300);
            grazing += fabs(c) < 1e-3;
        }
    }
    printf("  %s: %d views, %u edge-on triangles\n", name, nviews, grazing);
    CHECKF(wrong == 0, "%s: %u triangles face the other way", name, wrong);
    CHECKF(!SILK_AA_CANDIDATES || wrong_all == 0, "%s: %u triangles face the other way all at once", name,
           wrong_all);
}

TEST(tri_front_as_normalised_test)
{
    tri_front_as_normalised("sphere-200.obj", 200);
    tri_front_as_normalised("fandisk-1000.obj", 100);
    tri_front_as_normalised("bunny-500.obj", 100);
}
/* a fine mesh: many edge-on triangles */
TEST(tri_front_as_normalised_fine) { tri_front_as_normalised("bunny-fine.obj", 10); }
TEST(silhouette_triangles_torus) { silhouette_triangles("torus-576.obj", 40); }
TEST(silhouette_triangles_split_normals) { silhouette_triangles("fandisk-128.obj", 40); silhouette_triangles("cone-70.obj", 40); }

/* III-C, III-D: bridges and silhouette points against double references. */
static void bridges_vs_reference(const char *name, int nviews)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    double worst_t = 0, worst_u = 0, worst_p = 0;
    uint32_t n_bridges = 0, n_points = 0, bad_in_range = 0;
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        for (uint32_t w = 0; w < f.nedges; w++) {
            const silk_sil_edge *e = &f.edges[w];
            const silk_edge *me = &m.edge[e->edge];
            silk_curve ec;
            silk_sil_edge_curve(&f, e, &ec);
            double p0[3], p1[3], n0[3], n1[3], t0[3], t1[3];
            vec3d(m.pos[me->v[0]], p0);
            vec3d(m.pos[me->v[1]], p1);
            double chord = sqrt((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]) +
                                (p1[2] - p0[2]) * (p1[2] - p0[2]));
            if (!e->is_feature && e->npairs) {
                /* the bridge is built from the normals of the edge's first silhouette point */
                vec3d(m.normal[f.pairs[e->pair0].n0], n0);
                vec3d(m.normal[f.pairs[e->pair0].n1], n1);
                bridge_ref(p0, n0, p1, n1, t0, t1);
                double g0[3], g1[3];
                vec3d(ec.t0, g0);
                vec3d(ec.t1, g1);
                for (int k = 0; k < 3; k++) {
                    double err = fmax(fabs(g0[k] - t0[k]), fabs(g1[k] - t1[k])) / chord;
                    if (err > worst_t) worst_t = err;
                }
                n_bridges++;
            } else {
                vec3d(ec.t0, t0);
                vec3d(ec.t1, t1);
            }
            double d0[3], d1[3];
            to_eye_d(&v, m.pos[me->v[0]], d0);
            to_eye_d(&v, m.pos[me->v[1]], d1);
            for (uint32_t j = 0; j < e->npairs; j++) {
                const silk_sil_pair *p = &f.pairs[e->pair0 + j];
                double a0[3], a1[3];
                vec3d(m.normal[p->n0], a0);
                vec3d(m.normal[p->n1], a1);
                /* the two ends must disagree: that is why this is a silhouette side */
                if ((dot3(a0, d0) >= 0) == (dot3(a1, d1) >= 0)) bad_in_range++;
                double u = param_ref(a0, d0, a1, d1);
                double du = fabs(fx2d(p->u) - u);
                if (du > worst_u) worst_u = du;
                /* the point itself, on the edge's curve (ref curve from the fixed tangents) */
                double q[3], qr[3];
                hermite_ref(p0, p1, t0, t1, u, qr);
                silk_curve ec;
                silk_sil_edge_curve(&f, e, &ec);
                vec3d(silk_hermite_point(&ec, p->u), q);
                double dp = sqrt((q[0] - qr[0]) * (q[0] - qr[0]) + (q[1] - qr[1]) * (q[1] - qr[1]) +
                                 (q[2] - qr[2]) * (q[2] - qr[2])) / chord;
                if (dp > worst_p) worst_p = dp;
                n_points++;
            }
        }
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u bridges, worst tangent error %.2e x chord; %u silhouette points, worst |u - u_ref| %.2e, "
           "worst position error %.2e x chord\n", name, n_bridges, worst_t, n_points, worst_u, worst_p);
    CHECK(n_points > 0);
    CHECKF(bad_in_range == 0, "%u silhouette points on sides whose ends agree", bad_in_range);
    /* Q16.16 tangents of edges ~0.1..50 units long: a few ulp relative */
    CHECKF(worst_t < 2e-3, "tangent error %.3g", worst_t);
    /* u is Q16.16: half an ulp from rounding plus the inputs' rounding */
    CHECKF(worst_u < 1e-3, "u error %.3g", worst_u);
    CHECKF(worst_p < 2e-3, "point error %.3g", worst_p);
}

TEST(bridges_and_points_sphere) { bridges_vs_reference("sphere-200.obj", 30); }
TEST(bridges_and_points_torus) { bridges_vs_reference("torus-576.obj", 30); }
TEST(bridges_and_points_features) { bridges_vs_reference("fandisk-128.obj", 30); bridges_vs_reference("cone-70.obj", 30); }

/* The sharing rule, checked on the emitted records: for every edge that
 * carries points, every triangle side on it walks the same chain, and the
 * records of different sides evaluate to bit-identical positions.  Across a
 * feature edge the sides have different normals (the crease stays sharp). */
static void shared_points(const char *name, int nviews, int want_split)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    uint32_t compared = 0, mismatched = 0, split_normals = 0, edges_two_sides = 0, bad_sides = 0;
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        silk_geom gg = { .mesh = &m, .curves = g.curve, .offsets = g.offset };
        for (uint32_t w = 0; w < f.nedges; w++) {
            const silk_sil_edge *e = &f.edges[w];
            if (!e->nchain) continue;
            /* every triangle using the edge has a side on it */
            uint32_t users = 0;
            for (uint32_t t = 0; t < m.ntris; t++)
                for (int k = 0; k < 3; k++) users += m.tri_edge[3 * t + k] == e->edge;
            if (users != e->nsides) bad_sides++;
            if (e->nsides < 2) continue;
            edges_two_sides++;
            /* every side's own copy of the chain against the first side's */
            uint32_t r0 = UINT32_MAX;
            for (uint32_t c = 0; c < 3 * m.ntris; c++) {
                if (m.tri_edge[c] != e->edge) continue;
                uint32_t r = tf_side_rec(&f, &g, c / 3, c % 3);
                if (r0 == UINT32_MAX) { r0 = r; continue; }
                for (uint32_t j = 0; j < e->nchain; j++) {
                    silk_vertex_attr x, y;
                    silk_vrec_eval(&gg, &g.vrec[r0 + j], &x);
                    silk_vrec_eval(&gg, &g.vrec[r + j], &y);
                    compared++;
                    if (x.pos.x != y.pos.x || x.pos.y != y.pos.y || x.pos.z != y.pos.z) mismatched++;
                    if (x.normal.x != y.normal.x || x.normal.y != y.normal.y || x.normal.z != y.normal.z)
                        split_normals++;
                }
            }
        }
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u shared edges, %u point pairs compared, %u with split normals\n", name, edges_two_sides,
           compared, split_normals);
    CHECK(compared > 0);
    CHECKF(mismatched == 0, "%u points differ between the two sides of an edge", mismatched);
    CHECKF(bad_sides == 0, "%u edges not walked by all their triangles", bad_sides);
    if (want_split) CHECKF(split_normals > 0, "no crease with different normals on its two sides");
}

/* The sides on the carrying edges found edge by edge, and the feature
 * edges' front triangles from the edges (a mesh with its listed edges,
 * tri_edge), and both by a pass over every triangle (the same mesh without
 * them, as a packed one finds its edges): the same plan, bit for bit, in
 * the same order. */
static void plan_by_edges(const char *name, int nviews)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    silk_mesh packed = m;
    packed.tri_edge = NULL;
    uint32_t differ = 0, edges = 0;
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f[2];
        silk_sil_cursor cur[2];
        for (int j = 0; j < 2; j++) {
            memset(&f[j], 0, sizeof f[j]);
            f[j].cur = &cur[j];
            f[j].a = &a; f[j].m = j ? &packed : &m; f[j].v = &v; f[j].tol = SILK_FX_HALF; f[j].vis = SILK_VIS_BRUTE;
            if (silk_sil_find(&f[j]) != SILK_OK) { CHECK(0); return; }
        }
        const silk_sil_frame *x = &f[0], *y = &f[1];
        if (x->nedges != y->nedges || x->npairs != y->npairs || x->nsides != y->nsides || x->nchain != y->nchain ||
            memcmp(x->tri_state, y->tri_state, m.ntris) || memcmp(x->pairs, y->pairs, x->npairs * sizeof *x->pairs) ||
            memcmp(x->chain, y->chain, x->nchain * sizeof *x->chain)) {
            differ++;
        } else {
            for (uint32_t w = 0; w < x->nedges; w++) {
                const silk_sil_edge *ex = &x->edges[w], *ey = &y->edges[w];
                differ += ex->edge != ey->edge || ex->nsides != ey->nsides || ex->npairs != ey->npairs ||
                          ex->pair0 != ey->pair0 || ex->chain0 != ey->chain0 || ex->nchain != ey->nchain ||
                          ex->nfeat != ey->nfeat || ex->sampled != ey->sampled;
            }
        }
        edges += x->nedges;
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u carrying edges in %d views\n", name, edges, nviews);
    CHECK(edges > 0);
    CHECKF(differ == 0, "%u differences between the plans found edge by edge and triangle by triangle", differ);
}

TEST(plan_by_edges_as_by_triangles)
{
    plan_by_edges("sphere-200.obj", 20);
    plan_by_edges("fandisk-128.obj", 20);
    plan_by_edges("cone-70.obj", 20);
    plan_by_edges("bunny-500.obj", 20);
}

TEST(shared_points_bit_identical_sphere) { shared_points("sphere-200.obj", 30, 0); }
TEST(shared_points_bit_identical_torus) { shared_points("torus-576.obj", 30, 0); }
TEST(shared_points_bit_identical_creases) { shared_points("cone-70.obj", 40, 1); shared_points("fandisk-128.obj", 40, 1); }

/* Which point each record of a stored frame with lines is (rec_key, what
 * the lines' depth lift groups by): every triangle has its own copy of an
 * edge's points, and the copies of sides with the same normals and uvs are
 * one point, so records with one key evaluate to the same position and
 * normal; across a crease the copies keep keys of their own. */
static uint32_t *key_of;
static int cmp_by_key(const void *pa, const void *pb)
{
    uint32_t a = *(const uint32_t *)pa, b = *(const uint32_t *)pb;
    if (key_of[a] != key_of[b]) return key_of[a] < key_of[b] ? -1 : 1;
    return a < b ? -1 : a > b;
}

static void point_keys(const char *name, int nviews, int want_split)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    uint32_t shared = 0, differ = 0, split = 0, frames = 0;
    for (int i = 0; i < nviews; i++) {
        double dir[3];
        random_dir(dir);
        silk_view v;
        if (!tf_view_around(&m, dir, 1.5 + check_uniform(0, 4), i & 1, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_frame_geom g;
        silk_frame_stats st;
        silk_error err;
        if (silk_frame_smooth_lines(&a, &m, &v, SILK_FX_HALF, SILK_VIS_BRUTE, 1, &g, &st, &err) != SILK_OK ||
            st.fell_back || !g.rec_key) {
            CHECK(0);
            silk_arena_top_release(&a, &mk);
            return;
        }
        frames++;
        silk_geom gg = { .mesh = &m, .curves = g.curve, .offsets = g.offset };
        uint32_t *idx = malloc(g.nvrec * sizeof *idx);
        silk_vertex_attr *at = malloc(g.nvrec * sizeof *at);
        for (uint32_t r = 0; r < g.nvrec; r++) {
            idx[r] = r;
            silk_vrec_eval(&gg, &g.vrec[r], &at[r]);
        }
        key_of = g.rec_key;
        qsort(idx, g.nvrec, sizeof *idx, cmp_by_key);
        for (uint32_t j = 1; j < g.nvrec; j++) {
            const silk_vertex_attr *x = &at[idx[j - 1]], *y = &at[idx[j]];
            int same_pos = x->pos.x == y->pos.x && x->pos.y == y->pos.y && x->pos.z == y->pos.z;
            int same_n = x->normal.x == y->normal.x && x->normal.y == y->normal.y && x->normal.z == y->normal.z;
            int curves = g.vrec[idx[j]].kind == SILK_VREC_CURVE && g.vrec[idx[j - 1]].kind == SILK_VREC_CURVE;
            if (key_of[idx[j - 1]] == key_of[idx[j]]) {
                shared += curves;
                if (!same_pos || (curves && !same_n)) differ++;
            } else if (curves && same_pos && !same_n) {
                split++;
            }
        }
        free(idx);
        free(at);
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u frames, %u edge-point copies sharing a key, %u crease copies apart\n", name, frames, shared,
           split);
    CHECKF(differ == 0, "%u records with one key differ", differ);
    if (want_split) CHECKF(split > 0, "no crease copies with keys of their own");
    else CHECKF(shared > 0, "no edge point shared by the two sides of its edge");
}

TEST(point_keys_sphere) { point_keys("sphere-200.obj", 10, 0); }
TEST(point_keys_creases) { point_keys("cone-70.obj", 20, 1); point_keys("fandisk-128.obj", 20, 1); }

/* Eq. 8 (read with h = the projected chord, see silhouette.c): the number of
 * intervals of every silhouette segment and every sampled feature segment
 * against a double reference; feature counts come from the edge alone. */
static void sample_counts(const char *name, int nviews, silk_fx tol)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    uint32_t segs = 0, feats = 0, off = 0, multi = 0, zero = 0;
    double e = fx2d(tol);
    for (int i = 0; i < nviews; i++) {
        silk_view v;
        if (!random_view(&m, i, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, tol, &f, &g, &st)) { CHECK(0); return; }
        silk_sil_seg *sg = tf_segs(&f);
        for (uint32_t s = 0; s < f.nsegs + f.nedges; s++) {
            const silk_curve *c;
            silk_curve wc;
            double cosa;
            uint32_t n;
            if (s < f.nsegs) {
                c = &sg[s].c;
                double na[3], nb[3];
                vec3d(c->n0, na);
                vec3d(c->n1, nb);
                cosa = dot3(na, nb);
                n = sg[s].n;
                segs++;
            } else {
                const silk_sil_edge *w = &f.edges[s - f.nsegs];
                if (!w->sampled || (m.edge[w->edge].flags & SILK_EDGE_DEGENERATE)) continue;
                silk_sil_edge_curve(&f, w, &wc);
                c = &wc;
                double ta[3], tb[3];
                vec3d(c->t0, ta);
                vec3d(c->t1, tb);
                double la = sqrt(dot3(ta, ta)), lb = sqrt(dot3(tb, tb));
                cosa = la > 0 && lb > 0 ? dot3(ta, tb) / (la * lb) : 1;
                n = w->nfeat;
                feats++;
            }
            silk_vec2 pa, pb;
            if (!silk_view_project(&v, c->p0, &pa) || !silk_view_project(&v, c->p1, &pb)) {
                if (n != 1) off++;
                continue;
            }
            double h = hypot(fx2d(pa.x - pb.x), fx2d(pa.y - pb.y));
            double r = sqrt(fmax(0, (1 - cosa) / 2));
            double x = sqrt(h * r / e) / 2;
            double ref = h > 0 ? fmax(1, ceil(x)) : 1;
            if (ref > SILK_MAX_SAMPLES) ref = SILK_MAX_SAMPLES;
            /* the inputs are rounded to Q16.16: only a value within a hair of an integer may go either way */
            if (fabs(n - ref) > 0 && !(fabs(n - ref) <= 1 && fabs(x - round(x)) < 2e-3)) off++;
            if (n > 1) multi++;
            if (n == 0) zero++;
        }
        free(sg);
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s at tolerance %.2f: %u segments, %u feature segments, %u sampled more than once\n", name, e, segs,
           feats, multi);
    CHECKF(off == 0, "%u counts differ from eq. 8", off);
    CHECKF(zero == 0, "%u curves with no interval", zero);
    CHECK(segs > 0 && multi > 0);
}

TEST(sample_counts_eq8)
{
    sample_counts("sphere-200.obj", 30, SILK_FX_HALF);
    sample_counts("torus-576.obj", 30, SILK_FX_C(1, 4));
    sample_counts("cone-70.obj", 30, SILK_FX_ONE);
}

/* Tighter tolerance, more samples; more pixels, more samples. */
TEST(sample_counts_monotone)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    double dir[3] = { 0.3, 0.4, 1 };
    silk_view v;
    if (!tf_view_around(&m, dir, 3, 0, &v)) { CHECK(0); return; }
    uint32_t prev = 0;
    int mono = 1;
    static const silk_fx tols[] = { SILK_FX_C(4, 1), SILK_FX_C(2, 1), SILK_FX_ONE, SILK_FX_HALF, SILK_FX_C(1, 4) };
    for (int i = 0; i < 5; i++) {
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, tols[i], &f, &g, &st)) { CHECK(0); return; }
        if (st.samples < prev) mono = 0;
        printf("  tolerance %.2f px: %u samples, %u triangles\n", fx2d(tols[i]), st.samples, g.ntri);
        prev = st.samples;
        silk_arena_top_release(&a, &mk);
    }
    CHECK(mono);
}

/* Texture coordinates interpolate linearly: the curve of every side carries
 * that side's own corner uvs (seams stay seams), a silhouette segment starts
 * and ends with the uvs interpolated at its silhouette points, and positions
 * on the two sides of a seam still agree bit for bit. */
TEST(uvs_interpolate_linearly_across_seams)
{
    char path[512];
    snprintf(path, sizeof path, "%s/sphere-200.obj", check_meshes_dir());
    FILE *fp = fopen(path, "rb");
    if (!fp) { CHECK(0); return; }
    /* rewrite the sphere with one uv per corner: every edge is a uv seam */
    size_t cap = 1 << 20, n = 0;
    char *out = malloc(cap), line[256];
    double vx[200][3];
    int nv = 0, nf = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == 'v' && line[1] == ' ' && nv < 200) {
            sscanf(line + 2, "%lf %lf %lf", &vx[nv][0], &vx[nv][1], &vx[nv][2]);
            nv++;
            n += (size_t)snprintf(out + n, cap - n, "%s", line);
        } else if (line[0] == 'f') {
            int a, b, c;
            if (sscanf(line + 2, "%d %d %d", &a, &b, &c) != 3) continue;
            int idx[3] = { a, b, c };
            for (int k = 0; k < 3; k++)
                n += (size_t)snprintf(out + n, cap - n, "vt %.6f %.6f\n", vx[idx[k] - 1][0] * 0.25 + 0.5 + 0.001 * (nf % 7),
                                      vx[idx[k] - 1][1] * 0.25 + 0.5);
            n += (size_t)snprintf(out + n, cap - n, "f %d/%d %d/%d %d/%d\n", a, 3 * nf + 1, b, 3 * nf + 2, c, 3 * nf + 3);
            nf++;
        }
    }
    fclose(fp);
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_mesh m;
    silk_error err;
    silk_status st0 = silk_load_obj(out, n, "seams.obj", &o, &a, &m, &err);
    free(out);
    if (st0 != SILK_OK) { fprintf(stderr, "%s\n", err.msg); CHECK(0); return; }
    CHECK(m.uv && m.tri_uv);
    uint32_t bad_side = 0, bad_seg = 0, mismatched = 0, seams = 0;
    double worst = 0;
    for (int i = 0; i < 20; i++) {
        double dir[3];
        random_dir(dir);
        silk_view v;
        if (!tf_view_around(&m, dir, 2 + i % 3, i & 1, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        silk_geom gg = { .mesh = &m, .curves = g.curve, .offsets = g.offset };
        for (uint32_t w = 0; w < f.nedges; w++) {
            const silk_sil_edge *e = &f.edges[w];
            if (!e->nchain) continue;
            /* every side on the edge: its own curve carries its uvs; a side
             * whose uvs differ from the first side's is on a seam */
            uint32_t r0 = UINT32_MAX;
            silk_sil_side s0;
            for (uint32_t cn = 0; cn < 3 * m.ntris; cn++) {
                if (m.tri_edge[cn] != e->edge) continue;
                uint32_t t = cn / 3, r = tf_side_rec(&f, &g, t, cn % 3);
                silk_sil_side sd;
                silk_sil_side_attrs(&m, t, cn % 3, m.edge[e->edge].v[0], &sd);
                const silk_curve *c = &g.curve[g.vrec[r].a];
                silk_vec2 u0 = m.uv[sd.uv0], u1 = m.uv[sd.uv1];
                if (c->uv0.x != u0.x || c->uv0.y != u0.y || c->uv1.x != u1.x || c->uv1.y != u1.y) bad_side++;
                if (r0 == UINT32_MAX) { r0 = r; s0 = sd; continue; }
                seams += s0.uv0 != sd.uv0 || s0.uv1 != sd.uv1 || s0.n0 != sd.n0 || s0.n1 != sd.n1;
                for (uint32_t j = 0; j < e->nchain; j++) {
                    silk_vertex_attr x, y;
                    silk_vrec_eval(&gg, &g.vrec[r0 + j], &x);
                    silk_vrec_eval(&gg, &g.vrec[r + j], &y);
                    if (x.pos.x != y.pos.x || x.pos.y != y.pos.y || x.pos.z != y.pos.z) mismatched++;
                }
            }
        }
        silk_sil_seg *segs = tf_segs(&f);
        for (uint32_t s = 0; s < f.nsegs; s++) {
            const silk_sil_seg *sg = &segs[s];
            uint32_t t = sg->tri, lone = f.tri_state[t] & SILK_TS_LONE;
            /* A on side lone (corner lone -> lone+1), at its pair's parameter */
            for (int end = 0; end < 2; end++) {
                uint32_t k = end == 0 ? lone : (lone + 2) % 3;
                const silk_sil_edge *e = &f.edges[silk_sil_slot(&f, m.tri_edge[3 * t + k])];
                silk_sil_side sdv, *sd = &sdv;
                silk_sil_side_attrs(&m, t, k, m.edge[e->edge].v[0], sd);
                const silk_sil_pair *p = NULL;
                for (uint32_t j = 0; j < e->npairs; j++)
                    if (f.pairs[e->pair0 + j].n0 == sd->n0 && f.pairs[e->pair0 + j].n1 == sd->n1) p = &f.pairs[e->pair0 + j];
                if (!p) { bad_seg++; continue; }
                double u = fx2d(p->u);
                silk_vec2 a0 = m.uv[sd->uv0], a1 = m.uv[sd->uv1], got = end == 0 ? sg->c.uv0 : sg->c.uv1;
                double ex = fx2d(a0.x) + u * (fx2d(a1.x) - fx2d(a0.x)), ey = fx2d(a0.y) + u * (fx2d(a1.y) - fx2d(a0.y));
                double d = fmax(fabs(ex - fx2d(got.x)), fabs(ey - fx2d(got.y))) * 65536;
                if (d > worst) worst = d;
                if (d > 1.5) bad_seg++;
            }
        }
        free(segs);
        silk_arena_top_release(&a, &mk);
    }
    printf("  %u sides on seams, worst segment-end uv error %.2f ulp\n", seams, worst);
    CHECK(seams > 0);
    CHECKF(bad_side == 0, "%u side curves with the wrong uvs", bad_side);
    CHECKF(bad_seg == 0, "%u segment ends with the wrong uvs", bad_seg);
    CHECKF(mismatched == 0, "%u positions differ across a seam", mismatched);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    RUN(silhouette_triangles_sphere);
    RUN(tri_front_as_normalised_test);
    RUN(silhouette_triangles_torus);
    RUN(silhouette_triangles_split_normals);
    RUN(bridges_and_points_sphere);
    RUN(bridges_and_points_torus);
    RUN(bridges_and_points_features);
    RUN(shared_points_bit_identical_sphere);
    RUN(shared_points_bit_identical_torus);
    RUN(shared_points_bit_identical_creases);
    RUN(sample_counts_eq8);
    RUN(sample_counts_monotone);
    RUN(uvs_interpolate_linearly_across_seams);
    RUN(point_keys_sphere);
    RUN(point_keys_creases);
    /* last: their random views leave the other tests' as they were */
    RUN(plan_by_edges_as_by_triangles);
    RUN(tri_front_as_normalised_fine);
    free(arena_buf);
    return check_done();
}
