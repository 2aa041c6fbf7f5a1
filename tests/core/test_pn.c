/*
 * test_pn.c - PN triangles (src/pn.c, mode PN) against a double-precision
 * reference: the edge control points of Dyken & Reimers eqs. 7-8, whole
 * patches (control points and Vlachos' quadratic normals) for random
 * triangles and normals, tessellated points on the double patch, linear
 * normals, level 1 = the coarse mesh, planes reproduced, a sphere better
 * approximated than by its facets, and crack-freeness on closed shared
 * meshes (sphere-200, fandisk-128 with its split normals, torus-576): every
 * directed edge of the output meets its reverse exactly once, compared by
 * the bits of the evaluated positions.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "src/patch.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (16u << 20)
#define ULP (1.0 / 65536.0)
static unsigned char *arena_buf;

static silk_vec3 rand_normal_fx(void)
{
    silk_vec3 n;
    silk_v3_normalize(tofx(rand_unit()), &n);
    return n;
}

/* ---- the double reference ------------------------------------------------------ */

/* eqs. 7-8 as printed, from the fixed-point inputs */
static dvec ref_edge_ctrl(silk_vec3 pi, silk_vec3 pj, silk_vec3 ns, silk_vec3 nt)
{
    dvec p = dv(pi), q = dv(pj), e = dsub(q, p), a = dv(ns);
    if (!v3_eq(ns, nt)) {
        dvec x = dcross(dv(nt), a);
        if (dlen(x) > 0) {
            dvec m = dnorm(x);
            return dadd(p, dscale(m, ddot(e, m) / 3));
        }
    }
    return dsub(dscale(dadd(dscale(p, 2), q), 1.0 / 3), dscale(a, ddot(e, a) / 3));
}

static silk_vec3 corner_normal(const silk_mesh *m, silk_index t, silk_index v)
{
    for (int k = 0; k < 3; k++)
        if (m->tri[3 * t + k] == v) return m->normal[m->tri_normal[3 * t + k]];
    return silk_v3(0, 0, 0);
}

typedef struct dpatch { dvec b[10], n[6]; double uv[3][2]; } dpatch;

/* The patch of triangle t by the rule of pn.c in doubles: each side's inner
 * points from its mesh edge (both triangles' normals at each end), blended
 * by alpha; b111 = E + (E - V)/2; Vlachos' normals or linear ones. */
static void ref_patch(const silk_mesh *m, uint32_t t, const double *alpha, int linear, dpatch *p)
{
    static const int near[3][2] = { { SILK_B210, SILK_B120 }, { SILK_B021, SILK_B012 }, { SILK_B102, SILK_B201 } };
    static const int mid[3] = { SILK_N110, SILK_N011, SILK_N101 };
    dvec P[3], N[3], E = dmk(0, 0, 0);
    for (int k = 0; k < 3; k++) {
        P[k] = p->b[k] = dv(m->pos[m->tri[3 * t + k]]);
        N[k] = p->n[k] = dv(m->normal[m->tri_normal[3 * t + k]]);
        p->uv[k][0] = m->uv ? fx2d(m->uv[m->tri_uv[3 * t + k]].x) : 0;
        p->uv[k][1] = m->uv ? fx2d(m->uv[m->tri_uv[3 * t + k]].y) : 0;
    }
    for (int k = 0; k < 3; k++) {
        int k1 = (k + 1) % 3;
        silk_index va = m->tri[3 * t + k], vb = m->tri[3 * t + k1];
        const silk_edge *ed = &m->edge[m->tri_edge[3 * t + k]];
        silk_index s = ed->t[0], u = ed->t[1] != SILK_NO_INDEX ? ed->t[1] : ed->t[0];
        dvec ca = ref_edge_ctrl(m->pos[va], m->pos[vb], corner_normal(m, s, va), corner_normal(m, u, va));
        dvec cb = ref_edge_ctrl(m->pos[vb], m->pos[va], corner_normal(m, s, vb), corner_normal(m, u, vb));
        dvec la = dscale(dadd(dscale(P[k], 2), P[k1]), 1.0 / 3), lb = dscale(dadd(dscale(P[k1], 2), P[k]), 1.0 / 3);
        double al = alpha ? alpha[k] : 1;
        p->b[near[k][0]] = dadd(la, dscale(dsub(ca, la), al));
        p->b[near[k][1]] = dadd(lb, dscale(dsub(cb, lb), al));
        E = dadd(E, dadd(p->b[near[k][0]], p->b[near[k][1]]));
        dvec S = dadd(N[k], N[k1]), e = dsub(P[k1], P[k]);
        if (linear) {
            p->n[mid[k]] = S;
        } else {
            double ee = ddot(e, e), v = ee > 0 ? 2 * ddot(e, S) / ee : 0;
            p->n[mid[k]] = dnorm(dsub(S, dscale(e, v)));
        }
    }
    E = dscale(E, 1.0 / 6);
    dvec V = dscale(dadd(dadd(P[0], P[1]), P[2]), 1.0 / 3);
    p->b[SILK_B111] = dadd(E, dscale(dsub(E, V), 0.5));
}

static dvec ref_point(const dpatch *p, double u, double v, double w)
{
    const double c[10] = { u * u * u, v * v * v, w * w * w, 3 * u * u * v, 3 * u * v * v,
                           3 * v * v * w, 3 * v * w * w, 3 * u * w * w, 3 * u * u * w, 6 * u * v * w };
    dvec s = dmk(0, 0, 0);
    for (int q = 0; q < 10; q++) s = dadd(s, dscale(p->b[q], c[q]));
    return s;
}
static dvec ref_normal(const dpatch *p, double u, double v, double w)
{
    const double c[6] = { u * u, v * v, w * w, u * v, v * w, u * w };
    dvec s = dmk(0, 0, 0);
    for (int q = 0; q < 6; q++) s = dadd(s, dscale(p->n[q], c[q]));
    return dnorm(s);
}

/* ---- meshes ---------------------------------------------------------------------- */

static int load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    return tm_load_shared(a, name, m);
}

/* A mesh of nt triangles over nv random-ish vertices, with one file normal
 * and one uv per corner (so every corner may differ from its neighbours). */
static int build_mesh(silk_arena *a, const dvec *pos, uint32_t nv, const uint32_t *tri, uint32_t nt,
                      const silk_vec3 *corner_n, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = nv;
    in.ntris = nt;
    in.pos = silk_arena_array(a, nv, sizeof(silk_vec3), SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 3 * (size_t)nt, sizeof(silk_index), SILK_MEM_MESH);
    in.file_normal = silk_arena_array(a, 3 * (size_t)nt, sizeof(silk_vec3), SILK_MEM_MESH);
    in.tri_file_normal = silk_arena_array(a, 3 * (size_t)nt, sizeof(silk_index), SILK_MEM_MESH);
    in.uv = silk_arena_array(a, 3 * (size_t)nt, sizeof(silk_vec2), SILK_MEM_MESH);
    in.tri_uv = silk_arena_array(a, 3 * (size_t)nt, sizeof(silk_index), SILK_MEM_MESH);
    in.nfile_normals = in.nuvs = 3 * nt;
    for (uint32_t v = 0; v < nv; v++) in.pos[v] = tofx(pos[v]);
    for (uint32_t c = 0; c < 3 * nt; c++) {
        in.tri[c] = tri[c];
        in.file_normal[c] = corner_n[c];
        in.tri_file_normal[c] = in.tri_uv[c] = c;
        in.uv[c].x = d2fx(check_uniform(-4, 4));
        in.uv[c].y = d2fx(check_uniform(-4, 4));
    }
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.normals = SILK_NORMALS_FILE;
    silk_error err;
    if (silk_mesh_build(&in, "random", &o, a, m, &err) != SILK_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    return 1;
}

/* Two random triangles sharing the edge 0-1 (a quad 0,1,2 / 1,0,3), with
 * normals near the face normals but different on every corner. */
static int random_quad(silk_arena *a, double scale, double spread, silk_mesh *m)
{
    dvec p[4];
    dvec c = dmk(check_uniform(-400, 400), check_uniform(-400, 400), check_uniform(-400, 400));
    for (int i = 0; i < 4; i++) p[i] = dadd(c, dscale(rand_unit(), scale * check_uniform(0.3, 1)));
    static const uint32_t tri[6] = { 0, 1, 2, 1, 0, 3 };
    silk_vec3 n[6];
    for (int t = 0; t < 2; t++) {
        dvec fn = dnorm(dcross(dsub(p[tri[3 * t + 1]], p[tri[3 * t]]), dsub(p[tri[3 * t + 2]], p[tri[3 * t]])));
        for (int k = 0; k < 3; k++) n[3 * t + k] = tofx(dnorm(dadd(fn, dscale(rand_unit(), spread))));
    }
    return build_mesh(a, p, 4, tri, 2, n, m);
}

/* ---- tests ------------------------------------------------------------------------ */

/* Eqs. 7 and 8 on random edges and normals at several scales.  Eq. 7 is
 * rounded once from exact 64-bit terms: within 0.5 ulp.  Eq. 8 also rounds
 * e.m and carries the 2^-29 of the unit direction m: within 0.75 ulp +
 * 1e-8 |e|.  Both satisfy conditions (5) to the same precision. */
TEST(edge_ctrl_vs_double)
{
    static const double scales[] = { 0.01, 0.3, 5, 80, 600 };
    double worst7 = 0, worst8 = 0, worst_tan = 0;
    int fails = 0;
    for (int s = 0; s < 5; s++)
        for (int it = 0; it < 4000; it++) {
            dvec c = dmk(check_uniform(-300, 300), check_uniform(-300, 300), check_uniform(-300, 300));
            silk_vec3 pi = tofx(dadd(c, dscale(rand_unit(), scales[s]))), pj = tofx(dadd(c, dscale(rand_unit(), scales[s])));
            silk_vec3 ns = rand_normal_fx(), nt;
            int kind = it % 3;   /* 0: smooth end; 1: a crease; 2: nearly parallel normals */
            if (kind == 0) nt = ns;
            else if (kind == 1) nt = rand_normal_fx();
            else silk_v3_normalize(tofx(dadd(dv(ns), dscale(rand_unit(), 1e-3))), &nt);
            silk_vec3 got = silk_patch_edge_ctrl(pi, pj, ns, nt);
            dvec want = ref_edge_ctrl(pi, pj, ns, nt);
            double err = ddist(want, got), elen = dlen(dsub(dv(pj), dv(pi)));
            double bound = kind == 0 ? 0.5 * ULP + 1e-12 : 0.75 * ULP + 1e-8 * elen;
            if (err / bound > (kind == 0 ? worst7 : worst8)) *(kind == 0 ? &worst7 : &worst8) = err / bound;
            if (err > bound) fails++;
            /* conditions (5): the tangent c - p_i lies in both tangent planes */
            dvec tng = dsub(dv(got), dv(pi));
            double off = fmax(fabs(ddot(tng, dv(ns))), fabs(ddot(tng, dv(nt))));
            double allowed = 1.5 * ULP + 1e-8 * elen;
            if (kind == 2) allowed += 1e-3 * elen;   /* eq. 8 planes only: nt is ns moved by 1e-3 */
            if (kind == 1 && off / allowed > worst_tan) worst_tan = off / allowed;
            if (kind != 0 && off > allowed) fails++;
        }
    printf("# eq. 7: worst %.3f of its bound (0.5 ulp); eq. 8: worst %.3f of 0.75 ulp + 1e-8 |e|; "
           "tangent-plane residual %.3f of bound\n", worst7, worst8, worst_tan);
    CHECKF(fails == 0, "%d edge control points outside the bound", fails);
}

/* Whole patches of random quads (two triangles with eight different corner
 * normals, so the shared side is built by eq. 8 and the others by eq. 7)
 * against the double reference: control points within 1.5 ulp, normal
 * coefficients within 4 ulp; the two patches' shared side is bit-identical. */
TEST(patch_vs_double)
{
    silk_arena a;
    silk_mesh m;
    double worst_b = 0, worst_b111 = 0, worst_n = 0;
    int fails = 0, shared_fail = 0;
    for (int it = 0; it < 3000; it++) {
        double scale = it % 3 == 0 ? 0.05 : (it % 3 == 1 ? 2 : 150);
        if (!random_quad(&a, scale, it % 2 ? 0.3 : 0.9, &m)) { fails++; continue; }
        silk_patch p[2];
        for (uint32_t t = 0; t < 2; t++) {
            int linear = it % 4 == 3;
            silk_patch_build(&m, t, NULL, linear ? SILK_PN_LINEAR : SILK_PN_QUADRATIC, &p[t]);
            dpatch r;
            ref_patch(&m, t, NULL, linear, &r);
            for (int q = 0; q < 10; q++) {
                double e = ddist(r.b[q], p[t].b[q]) / ULP;
                double *worst = q == SILK_B111 ? &worst_b111 : &worst_b;
                if (e > *worst) *worst = e;
                if (e > 1.5) fails++;
            }
            for (int q = 0; q < 6; q++) {
                double e = ddist(r.n[q], p[t].n[q]) / ULP;
                if (e > worst_n) worst_n = e;
                if (e > 4) fails++;
            }
        }
        /* side 0 of triangle 0 runs 0 -> 1, side 0 of triangle 1 runs 1 -> 0 */
        if (!v3_eq(p[0].b[SILK_B210], p[1].b[SILK_B120]) || !v3_eq(p[0].b[SILK_B120], p[1].b[SILK_B210]))
            shared_fail++;
    }
    printf("# patch control points: worst %.3f ulp (b111 %.3f ulp), normal coefficients %.3f ulp\n", worst_b,
           worst_b111, worst_n);
    CHECKF(fails == 0, "%d coefficients outside the bound", fails);
    CHECKF(shared_fail == 0, "%d shared sides differ", shared_fail);
}

/* PN frames of random quads at levels 1..8: every tessellated point lies on
 * the double patch (position within 2 ulp of the reference patch, normal
 * within 4e-5, uv within 1 ulp). */
TEST(tessellation_on_double_patch)
{
    silk_arena a;
    silk_mesh m;
    double worst_p = 0, worst_n = 0, worst_uv = 0;
    int fails = 0;
    for (int it = 0; it < 400; it++) {
        if (!random_quad(&a, it % 2 ? 1.5 : 60, 0.6, &m)) { fails++; continue; }
        uint32_t L = 1 + (uint32_t)(it % 8);
        int linear = it % 3 == 2;
        silk_frame_geom g;
        silk_frame_stats st;
        silk_error err;
        memset(&st, 0, sizeof st);
        if (silk_frame_pn(&a, &m, L, linear ? SILK_PN_LINEAR : SILK_PN_QUADRATIC, &g, &st, &err) != SILK_OK ||
            st.fell_back) {
            fails++;
            continue;
        }
        CHECK(g.ntri == 2 * L * L && g.nvrec == 2 * (L + 1) * (L + 2) / 2 && g.npatch == 2);
        dpatch r[2];
        ref_patch(&m, 0, NULL, linear, &r[0]);
        ref_patch(&m, 1, NULL, linear, &r[1]);
        silk_geom geom = { .mesh = &m, .patches = g.patch };
        for (uint32_t i = 0; i < g.nvrec; i++) {
            const silk_vrec *rec = &g.vrec[i];
            CHECK(rec->kind == SILK_VREC_PATCH && rec->a < 2);
            if (rec->kind != SILK_VREC_PATCH || rec->a >= 2) continue;
            double pi = rec->b & 0xFF, pj = (rec->b >> 8) & 0xFF, pn = (rec->b >> 16) & 0xFF;
            CHECK(pn == L && pi + pj <= L);
            double u = pi / pn, v = pj / pn, w = (pn - pi - pj) / pn;
            silk_vertex_attr at;
            silk_vrec_eval(&geom, rec, &at);
            double ep = ddist(ref_point(&r[rec->a], u, v, w), at.pos) / ULP;
            double en = ddist(ref_normal(&r[rec->a], u, v, w), at.normal);
            const dpatch *rp = &r[rec->a];
            double eu = fmax(fabs(u * rp->uv[0][0] + v * rp->uv[1][0] + w * rp->uv[2][0] - fx2d(at.uv.x)),
                             fabs(u * rp->uv[0][1] + v * rp->uv[1][1] + w * rp->uv[2][1] - fx2d(at.uv.y))) / ULP;
            if (ep > worst_p) worst_p = ep;
            if (en > worst_n) worst_n = en;
            if (eu > worst_uv) worst_uv = eu;
            if (ep > 2 || en > 4e-5 || eu > 1) fails++;
        }
    }
    printf("# tessellated points: position %.3f ulp, normal %.2e, uv %.3f ulp from the double patch\n", worst_p,
           worst_n, worst_uv);
    CHECKF(fails == 0, "%d points off the double patch", fails);
}

/* Linear normals: the normal at (i,j,k)/L is normalize(i N0 + j N1 + k N2)
 * within 4e-5; quadratic ones differ from it inside the patch. */
TEST(linear_normals)
{
    silk_arena a;
    silk_mesh m;
    double worst = 0, quad_diff = 0;
    for (int it = 0; it < 200; it++) {
        CHECK(random_quad(&a, 3, 0.8, &m));
        silk_patch pl, pq;
        silk_patch_build(&m, 0, NULL, SILK_PN_LINEAR, &pl);
        silk_patch_build(&m, 0, NULL, SILK_PN_QUADRATIC, &pq);
        for (uint32_t i = 0; i <= 6; i++)
            for (uint32_t j = 0; i + j <= 6; j++) {
                silk_vertex_attr al, aq;
                silk_patch_eval(&pl, SILK_PATCH_POINT(i, j, 6), &al);
                silk_patch_eval(&pq, SILK_PATCH_POINT(i, j, 6), &aq);
                dvec want = dnorm(dadd(dadd(dscale(dv(pl.n[0]), i), dscale(dv(pl.n[1]), j)), dscale(dv(pl.n[2]), 6 - i - j)));
                double e = ddist(want, al.normal);
                if (e > worst) worst = e;
                double q = ddist(want, aq.normal);
                if (q > quad_diff) quad_diff = q;
            }
    }
    printf("# linear normals: worst %.2e from normalize(lerp); quadratic ones differ by up to %.3f\n", worst, quad_diff);
    CHECKF(worst <= 4e-5, "linear normal off by %g", worst);
    CHECKF(quad_diff > 1e-2, "quadratic normals never differ from linear ones (%g)", quad_diff);
}

/* Level 1 is the coarse mesh: three records per triangle that evaluate to
 * the mesh positions bit for bit, one triangle per triangle. */
TEST(level1_is_the_mesh)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "bunny-500.obj", &m)) { CHECK(0); return; }
    silk_frame_geom g;
    silk_frame_stats st;
    silk_error err;
    CHECK(silk_frame_pn(&a, &m, 1, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_OK);
    CHECK(g.ntri == m.ntris && g.nvrec == 3 * m.ntris);
    silk_geom geom = { .mesh = &m, .patches = g.patch };
    int bad = 0;
    for (uint32_t t = 0; t < g.ntri; t++)
        for (int k = 0; k < 3; k++) {
            silk_vertex_attr at;
            silk_vrec_eval(&geom, &g.vrec[g.tri[3 * t + k]], &at);
            if (!v3_eq(at.pos, m.pos[m.tri[3 * t + k]])) bad++;
            if (g.tri_added[t]) bad++;
        }
    CHECKF(bad == 0, "%d corners differ from the mesh", bad);
}

/* A plane stays a plane.  Triangles in z = 0 with normals (0,0,1) give
 * patches with z exactly 0 everywhere.  Random triangles with all normals
 * the (rounded) face normal stay within 1 ulp + 1e-5 |e| of their plane:
 * the rounding of the normal is all that bends them. */
TEST(plane_reproduced)
{
    silk_arena a;
    silk_mesh m;
    double worst = 0;
    int exact_fail = 0;
    for (int it = 0; it < 400; it++) {
        int axis = it % 2 == 0;
        dvec p[3];
        double emax = 0;
        for (int i = 0; i < 3; i++) {
            p[i] = dscale(rand_unit(), check_uniform(0.5, 50));
            if (axis) p[i].z = 0;
        }
        for (int i = 0; i < 3; i++) emax = fmax(emax, dlen(dsub(p[(i + 1) % 3], p[i])));
        static const uint32_t tri[3] = { 0, 1, 2 };
        dvec fn = dnorm(dcross(dsub(p[1], p[0]), dsub(p[2], p[0])));
        silk_vec3 n[3];
        n[0] = n[1] = n[2] = tofx(fn);
        CHECK(build_mesh(&a, p, 3, tri, 1, n, &m));
        silk_patch pt;
        silk_patch_build(&m, 0, NULL, it % 3 ? SILK_PN_QUADRATIC : SILK_PN_LINEAR, &pt);
        dvec q0 = dv(m.pos[0]), nn = dnorm(dcross(dsub(dv(m.pos[1]), q0), dsub(dv(m.pos[2]), q0)));
        for (uint32_t i = 0; i <= 5; i++)
            for (uint32_t j = 0; i + j <= 5; j++) {
                silk_vertex_attr at;
                silk_patch_eval(&pt, SILK_PATCH_POINT(i, j, 5), &at);
                if (axis) {
                    if (at.pos.z != 0 || at.normal.x != 0 || at.normal.y != 0) exact_fail++;
                    continue;
                }
                double off = fabs(ddot(dsub(dv(at.pos), q0), nn)) / (ULP + 1e-5 * emax);
                if (off > worst) worst = off;
            }
    }
    printf("# plane reproduction: z = 0 exact; random planes %.3f of the bound 1 ulp + 1e-5 |e|\n", worst);
    CHECKF(exact_fail == 0, "%d points left z = 0", exact_fail);
    CHECKF(worst <= 1, "a flat patch bends by %g of the bound", worst);
}

/* A UV sphere with exact radial normals: at level 4 the PN surface stays
 * more than five times closer to the sphere than the facets' edges do (a
 * cubic with the right tangent planes at the vertices against a chord). */
TEST(sphere_closer_than_facets)
{
    enum { SEG = 10, BANDS = 7 };
    dvec p[SEG * (BANDS - 1) + 2];
    uint32_t tri[3 * 2 * SEG * (BANDS - 1)], nv = 0, nt = 0;
    const double R = 3, pi = 3.14159265358979323846;
    p[nv++] = dmk(0, R, 0);
    for (int b = 1; b < BANDS; b++)
        for (int s = 0; s < SEG; s++) {
            double th = pi * b / BANDS, ph = 2 * pi * s / SEG;
            p[nv++] = dmk(R * sin(th) * cos(ph), R * cos(th), -R * sin(th) * sin(ph));
        }
    p[nv++] = dmk(0, -R, 0);
    for (uint32_t s = 0; s < SEG; s++) {
        uint32_t s1 = (s + 1) % SEG;
        tri[nt++] = 0; tri[nt++] = 1 + s; tri[nt++] = 1 + s1;
        for (uint32_t b = 0; b + 2 < BANDS; b++) {
            uint32_t a0 = 1 + b * SEG + s, a1 = 1 + b * SEG + s1, c0 = a0 + SEG, c1 = a1 + SEG;
            tri[nt++] = a0; tri[nt++] = c0; tri[nt++] = c1;
            tri[nt++] = a0; tri[nt++] = c1; tri[nt++] = a1;
        }
        uint32_t last = 1 + (BANDS - 2) * SEG;
        tri[nt++] = nv - 1; tri[nt++] = last + s1; tri[nt++] = last + s;
    }
    nt /= 3;
    silk_vec3 n[3 * 2 * SEG * (BANDS - 1)];
    for (uint32_t c = 0; c < 3 * nt; c++) n[c] = tofx(dnorm(p[tri[c]]));
    silk_arena a;
    silk_mesh m;
    if (!build_mesh(&a, p, nv, tri, nt, n, &m)) { CHECK(0); return; }
    silk_frame_geom g;
    silk_frame_stats st;
    silk_error err;
    CHECK(silk_frame_pn(&a, &m, 4, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_OK);
    silk_geom geom = { .mesh = &m, .patches = g.patch };
    double pn_err = 0, flat_err = 0;
    for (uint32_t i = 0; i < g.nvrec; i++) {
        silk_vertex_attr at;
        silk_vrec_eval(&geom, &g.vrec[i], &at);
        pn_err = fmax(pn_err, fabs(dlen(dv(at.pos)) - R));
    }
    for (uint32_t t = 0; t < m.ntris; t++)
        for (int k = 0; k < 3; k++) {
            dvec mid = dscale(dadd(dv(m.pos[m.tri[3 * t + k]]), dv(m.pos[m.tri[3 * t + (k + 1) % 3]])), 0.5);
            flat_err = fmax(flat_err, fabs(dlen(mid) - R));
        }
    uint32_t checked;
    CHECK(tf_crack_check(&m, &g, &checked) == 0);
    printf("# UV sphere (r 3, %u triangles): PN level 4 off the sphere by %.5f, facet edge midpoints by %.5f\n",
           m.ntris, pn_err, flat_err);
    CHECKF(pn_err < flat_err / 5, "PN %g vs facets %g", pn_err, flat_err);
}

/* The shared meshes at several levels, both normal modes: every directed
 * edge of the output meets its reverse exactly once.  fandisk-128's split
 * normals would crack with Vlachos' per-triangle b210; this checks that they
 * do differ there, and that the patches still close.  On the two meshes
 * without split normals the normals meet bit for bit too. */
TEST(crack_free_shared_meshes)
{
    static const char *names[] = { "sphere-200.obj", "fandisk-128.obj", "torus-576.obj" };
    static const uint32_t levels[] = { 1, 2, 3, 4, 7 };
    silk_arena a;
    silk_mesh m;
    for (int f = 0; f < 3; f++) {
        if (!load_shared(&a, names[f], &m)) { CHECK(0); continue; }
        uint32_t naive_differ = 0;
        for (uint32_t e = 0; e < m.nedges; e++) {
            const silk_edge *ed = &m.edge[e];
            if (ed->t[1] == SILK_NO_INDEX) continue;
            silk_vec3 p0 = m.pos[ed->v[0]], p1 = m.pos[ed->v[1]];
            silk_vec3 na = corner_normal(&m, ed->t[0], ed->v[0]), nb = corner_normal(&m, ed->t[1], ed->v[0]);
            if (!v3_eq(silk_patch_edge_ctrl(p0, p1, na, na), silk_patch_edge_ctrl(p0, p1, nb, nb))) naive_differ++;
        }
        if (f == 1) CHECKF(naive_differ > 20, "fandisk: only %u edges with split normals", naive_differ);
        if (f != 1) CHECKF(naive_differ == 0, "%s: %u split edges", names[f], naive_differ);
        for (int l = 0; l < 5; l++)
            for (int q = 0; q < 2; q++) {
                silk_arena_mark mk = silk_arena_top_mark(&a);
                silk_frame_geom g;
                silk_frame_stats st;
                silk_error err;
                CHECK(silk_frame_pn(&a, &m, levels[l], q ? SILK_PN_LINEAR : SILK_PN_QUADRATIC, &g, &st, &err) == SILK_OK);
                uint32_t checked, bad = tf_crack_check(&m, &g, &checked);
                CHECKF(bad == 0 && checked == 3 * m.ntris * levels[l] * levels[l], "%s level %u: %u of %u edges unpaired",
                       names[f], levels[l], bad, checked);
                if (f != 1) {
                    uint32_t seams = tf_normal_seams(&m, &g);
                    CHECKF(seams == 0, "%s level %u: %u normal seams", names[f], levels[l], seams);
                }
                silk_arena_top_release(&a, &mk);
            }
    }
}

static void make_view(const silk_mesh *m, dvec dir, double dist, int w, int h, silk_view *v)
{
    dvec c = dscale(dadd(dv(m->bbox_min), dv(m->bbox_max)), 0.5);
    double r = dlen(dsub(dv(m->bbox_max), dv(m->bbox_min))) / 2;
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = tofx(dadd(c, dscale(dnorm(dir), dist * r)));
    cam.target = tofx(c);
    cam.up = fabs(dnorm(dir).y) > 0.9 ? silk_v3(SILK_FX_ONE, 0, 0) : silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(40, 1);
    cam.znear = d2fx(r * 0.05);
    cam.zfar = d2fx(r * (dist + 4));
    cam.width = w;
    cam.height = h;
    silk_error err;
    CHECK(silk_view_init(v, &cam, &err) == SILK_OK);
}

/* The whole pipeline: silk_render in PN mode draws more pixels of a sphere
 * than FLAT (the patches bulge out to the sphere), releases its scratch,
 * and reports the expected triangle count. */
TEST(render_pn_mode)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    silk_view v;
    make_view(&m, dmk(0.3, 0.4, 1), 3, 96, 96, &v);
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal hal;
    silk_hal_phong(&hal, &ph);
    static uint8_t color[96 * 96 * 3];
    static uint32_t depth[96 * 96];
    silk_target t;
    silk_target_init(&t, 96, 96, 0, 96, SILK_PIX_RGB888, color, depth);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;   /* coverage by pixel centres */
    int covered[2] = { 0, 0 };
    for (int pass = 0; pass < 2; pass++) {
        o.mode = pass ? SILK_MODE_PN : SILK_MODE_FLAT;
        silk_frame_stats st;
        silk_error err;
        size_t top = a.top;
        CHECK(silk_render(&a, &m, &v, &hal, &o, &t, &st, &err) == SILK_OK);
        CHECK(a.top == top);
        if (pass) CHECK(st.tris_drawn == m.ntris * 9 && !st.fell_back && st.frame_bytes > 0);
        for (int y = 0; y < 96; y++)
            for (int x = 0; x < 96; x++) covered[pass] += silk_target_get(&t, x, y) != o.bg_rgb;
    }
    printf("# sphere-200 at 96x96: %d pixels flat, %d PN\n", covered[0], covered[1]);
    CHECKF(covered[1] > covered[0] + covered[0] / 100, "PN covers %d, flat %d", covered[1], covered[0]);
}

TEST(bad_arguments_and_small_arenas)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    silk_frame_geom g;
    silk_frame_stats st;
    silk_error err;
    memset(&st, 0, sizeof st);
    CHECK(silk_frame_pn(&a, &m, 0, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "level 0 out of range 1..32") != NULL, "%s", err.msg);
    CHECK(silk_frame_pn(&a, &m, SILK_PN_MAX_LEVEL + 1, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_ERR_ARG);
    CHECK(silk_frame_pn(&a, &m, 3, (silk_pn_normals)7, &g, &st, &err) == SILK_ERR_ARG);
    CHECK(silk_frame_pn(NULL, &m, 3, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_ERR_ARG);
    silk_mesh bare = m;
    bare.tri_normal = NULL;
    CHECK(silk_frame_pn(&a, &bare, 3, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "no shading normals") != NULL, "%s", err.msg);
    CHECK(strchr(err.msg, '\n') == NULL);

    /* Room for the coarse mesh but not the patches: the coarse mesh, flagged. */
    silk_arena_mark mk = silk_arena_top_mark(&a);
    size_t flat_bytes = 3 * m.ntris * (sizeof(silk_vrec) + sizeof(uint32_t)) + m.ntris + 64;
    silk_arena small = a;
    small.size = small.bottom + small.top + flat_bytes;
    CHECK(silk_frame_pn(&small, &m, 3, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_OK);
    CHECK(st.fell_back == 1 && g.ntri == m.ntris && g.npatch == 0 && g.vrec[0].kind == SILK_VREC_CORNER);
    /* Not even that: a clean error. */
    small = a;
    small.size = small.bottom + small.top + 100;
    CHECK(silk_frame_pn(&small, &m, 3, SILK_PN_QUADRATIC, &g, &st, &err) == SILK_ERR_NOMEM);
    CHECKF(strstr(err.msg, "arena") != NULL, "%s", err.msg);
    silk_arena_top_release(&a, &mk);

    /* Through silk_render: a bad level is an error, not a crash. */
    silk_view v;
    make_view(&m, dmk(0, 0, 1), 3, 16, 16, &v);
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal hal;
    silk_hal_phong(&hal, &ph);
    static uint8_t color[16 * 16 * 3];
    static uint32_t depth[16 * 16];
    silk_target t;
    silk_target_init(&t, 16, 16, 0, 16, SILK_PIX_RGB888, color, depth);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = SILK_MODE_PN;
    o.level = 99;
    CHECK(silk_render(&a, &m, &v, &hal, &o, &t, &st, &err) == SILK_ERR_ARG);

    /* Malformed patch points evaluate to zeros. */
    silk_patch p;
    silk_patch_build(&m, 0, NULL, SILK_PN_QUADRATIC, &p);
    silk_vertex_attr at;
    silk_patch_eval(&p, SILK_PATCH_POINT(2, 2, 3), &at);
    CHECK(at.pos.x == 0 && at.pos.y == 0 && at.pos.z == 0 && at.normal.x == 0);
    silk_patch_eval(&p, SILK_PATCH_POINT(0, 0, 0), &at);
    CHECK(at.pos.x == 0 && at.normal.z == 0);
    silk_patch_eval(&p, SILK_PATCH_POINT(1, 0, 1) | (1u << 24), &at);
    CHECK(at.pos.x == 0);
    silk_patch_eval(&p, SILK_PATCH_POINT(1, 0, 1), &at);
    CHECK(v3_eq(at.pos, m.pos[m.tri[0]]));
}

int main(void)
{
    CHECK_PROGRAM_NEEDS(SILK_REFERENCE_MODES);
    arena_buf = malloc(ARENA_BYTES);
    RUN(edge_ctrl_vs_double);
    RUN(patch_vs_double);
    RUN(tessellation_on_double_patch);
    RUN(linear_normals);
    RUN(level1_is_the_mesh);
    RUN(plane_reproduced);
    RUN(sphere_closer_than_facets);
    RUN(crack_free_shared_meshes);
    RUN(render_pn_mode);
    RUN(bad_arguments_and_small_arenas);
    free(arena_buf);
    return check_done();
}
