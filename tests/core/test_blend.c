/*
 * test_blend.c - silhouetteness blending (src/blend.c, mode BLEND) against
 * a double-precision reference: silhouetteness (Dyken & Reimers eqs. 1-2)
 * for random perspective and parallel views, its continuity as the eye
 * moves, blended control points, alpha 1 = the PN patch and alpha 0 = the
 * flat triangle, the frame's flat and curved triangles, the segment count of
 * every edge against its tolerance, and crack-freeness on closed shared
 * meshes (sphere-200, fandisk-128, torus-576) from many views: every
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

/* ---- meshes and views -------------------------------------------------------- */

static int load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    return tm_load_shared(a, name, m);
}

/* Looking at the model's centre from direction dir, dist bounding radii away. */
static int make_view(const silk_mesh *m, dvec dir, double dist, int ortho, silk_view *v)
{
    dvec c = dscale(dadd(dv(m->bbox_min), dv(m->bbox_max)), 0.5);
    double r = dlen(dsub(dv(m->bbox_max), dv(m->bbox_min))) / 2;
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = tofx(dadd(c, dscale(dnorm(dir), dist * r)));
    cam.target = tofx(c);
    cam.up = fabs(dnorm(dir).y) > 0.9 ? silk_v3(SILK_FX_ONE, 0, 0) : silk_v3(0, SILK_FX_ONE, 0);
    cam.ortho = ortho;
    cam.fov_deg = SILK_FX_C(40, 1);
    cam.ortho_half_height = d2fx(1.2 * r);
    cam.znear = d2fx(r * 0.05);
    cam.zfar = d2fx(r * (dist + 4));
    cam.width = 320;
    cam.height = 240;
    silk_error err;
    if (silk_view_init(v, &cam, &err) != SILK_OK) { fprintf(stderr, "%s\n", err.msg); return 0; }
    return 1;
}

/* ---- the double reference --------------------------------------------------------- */

/* f of eq. 1 for edge e with exact face normals and the exact view direction. */
static double ref_f(const silk_mesh *m, const silk_view *v, uint32_t e)
{
    const silk_edge *ed = &m->edge[e];
    dvec n[2];
    for (int s = 0; s < 2; s++) {
        const silk_index *t = &m->tri[3 * ed->t[s]];
        dvec p0 = dv(m->pos[t[0]]);
        n[s] = dnorm(dcross(dsub(dv(m->pos[t[1]]), p0), dsub(dv(m->pos[t[2]]), p0)));
    }
    dvec mid = dscale(dadd(dv(m->pos[ed->v[0]]), dv(m->pos[ed->v[1]])), 0.5);
    dvec u = v->cam.ortho ? dsub(dv(v->cam.eye), dv(v->cam.target)) : dsub(dv(v->cam.eye), mid);
    u = dnorm(u);
    return ddot(u, n[0]) * ddot(u, n[1]);
}

static double alpha_of_f(double f, double beta)
{
    if (f <= 0) return 1;
    if (f > beta) return 0;
    return 1 - f / beta;
}

/* What silk_frame_blend computes for edge e (features 1, degenerate 0). */
static silk_fx fixed_alpha(const silk_mesh *m, const silk_view *v, uint32_t e, silk_fx beta)
{
    const silk_edge *ed = &m->edge[e];
    if (ed->flags & SILK_EDGE_FEATURE) return SILK_FX_ONE;
    if ((ed->flags & SILK_EDGE_DEGENERATE) || ed->t[1] == SILK_NO_INDEX) return 0;
    silk_vec3 p0 = m->pos[ed->v[0]], p1 = m->pos[ed->v[1]];
    silk_vec3 mr = silk_v3(silk_fx_sat(silk_shr_round64((int64_t)p0.x + p1.x, 1)),
                           silk_fx_sat(silk_shr_round64((int64_t)p0.y + p1.y, 1)),
                           silk_fx_sat(silk_shr_round64((int64_t)p0.z + p1.z, 1)));
    return silk_blend_alpha(silk_view_to_eye(v, mr), silk_mesh_face_normal(m, ed->t[0]),
                            silk_mesh_face_normal(m, ed->t[1]), beta);
}

/* The frame's record layout, read back: per mesh triangle either three
 * CORNER records (flat) or a centre and a boundary loop; seg[3t+k] gets the
 * segment count of side k (1 for a flat triangle).  Returns 0 on a layout
 * that does not match. */
static int read_layout(const silk_mesh *m, const silk_frame_geom *g, uint8_t *curved, uint32_t *seg)
{
    uint32_t r = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (r >= g->nvrec) return 0;
        if (g->vrec[r].kind == SILK_VREC_CORNER) {
            for (uint32_t k = 0; k < 3; k++)
                if (g->vrec[r + k].kind != SILK_VREC_CORNER || g->vrec[r + k].a != 3 * t + k) return 0;
            curved[t] = 0;
            seg[3 * t] = seg[3 * t + 1] = seg[3 * t + 2] = 1;
            r += 3;
            continue;
        }
        curved[t] = 1;
        if (g->vrec[r].b != SILK_PATCH_POINT(1, 1, 3)) return 0;
        r++;
        for (uint32_t k = 0; k < 3; k++) {
            if (g->vrec[r].b != SILK_PATCH_POINT(k == 0, k == 1, 1)) return 0;
            r++;
            uint32_t n = 1;
            while (r < g->nvrec && g->vrec[r].kind == SILK_VREC_PATCH && (g->vrec[r].b >> 16) != 1 &&
                   g->vrec[r].b != SILK_PATCH_POINT(1, 1, 3)) {
                r++;
                n++;
            }
            seg[3 * t + k] = n;
        }
    }
    return r == g->nvrec;
}

/* ---- tests ----------------------------------------------------------------------- */

/* Eqs. 1-2 for every smooth edge of bunny-500 from random perspective and
 * parallel views and several beta, against the exact double (exact face
 * normals, exact view direction).  The unit view direction and the two
 * face normals are each rounded to Q16.16 (|error| <= 0.5 sqrt 3 ulp =
 * 1.3e-5), so |f - f_ref| <= 4 x 1.3e-5 and |alpha - alpha_ref| <= 6e-5 /
 * beta + 2^-16; with beta 0 the binary test, which may differ only where
 * |f| is below 1e-4. */
TEST(alpha_vs_double)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "bunny-500.obj", &m)) { CHECK(0); return; }
    static const double betas[] = { 0, 0.05, 0.25, 1 };
    double worst = 0;
    int fails = 0, partial = 0;
    for (int it = 0; it < 40; it++) {
        silk_view v;
        int ortho = it % 2;
        if (!make_view(&m, rand_unit(), check_uniform(1.3, 6), ortho, &v)) { CHECK(0); continue; }
        for (int b = 0; b < 4; b++) {
            silk_fx beta = d2fx(betas[b]);
            for (uint32_t e = 0; e < m.nedges; e++) {
                if (m.edge[e].flags & (SILK_EDGE_FEATURE | SILK_EDGE_DEGENERATE)) continue;
                double f = ref_f(&m, &v, e), want = alpha_of_f(f, fx2d(beta));
                double got = fx2d(fixed_alpha(&m, &v, e, beta));
                double err = fabs(got - want);
                if (got < 0 || got > 1) fails++;
                if (beta == 0) {
                    if (err > 0 && fabs(f) > 1e-4) fails++;
                    continue;
                }
                partial += got > 0 && got < 1;
                double bound = 6e-5 / fx2d(beta) + ULP;
                if (err / bound > worst) worst = err / bound;
                if (err > bound) fails++;
            }
        }
    }
    printf("# silhouetteness: worst %.3f of the bound 6e-5/beta + 2^-16; %d edges strictly between 0 and 1\n", worst,
           partial);
    CHECKF(fails == 0, "%d alphas outside the bound", fails);
    CHECK(partial > 1000);
}

/* Silhouetteness is continuous in the eye position: moving the eye by h
 * along a circle of radius D changes every alpha by at most about
 * 2 h / (D beta) (|d f| <= 2 |d u|), never a jump. */
TEST(alpha_continuous_in_the_eye)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "torus-576.obj", &m)) { CHECK(0); return; }
    uint32_t *prev = malloc(sizeof *prev * m.nedges);
    const double beta = 0.25, D = 4;
    double worst = 0;
    int steps = 0;
    for (int i = 0; i <= 400; i++) {
        double ang = i * 0.005;   /* radians: eye moves D * 0.005 per step */
        silk_view v;
        if (!make_view(&m, dmk(sin(ang), 0.5, cos(ang)), D, 0, &v)) { CHECK(0); break; }
        double r = dlen(dsub(dv(m.bbox_max), dv(m.bbox_min))) / 2;
        double h = D * r * 0.005 * sqrt(1.25), dmin = (D - 1) * r;
        for (uint32_t e = 0; e < m.nedges; e++) {
            silk_fx al = fixed_alpha(&m, &v, e, d2fx(beta));
            if (i > 0) {
                double jump = fabs(fx2d(al) - fx2d((silk_fx)prev[e]));
                double allowed = 2 * h / (dmin * beta) * 1.05 + 4e-5 / beta;
                if (jump / allowed > worst) worst = jump / allowed;
            }
            prev[e] = (uint32_t)al;
        }
        steps++;
    }
    free(prev);
    printf("# continuity: worst step %.3f of its bound over %d eye positions\n", worst, steps);
    CHECKF(worst <= 1, "alpha jumps (%.3f of the bound)", worst);
}

/* Two random triangles sharing an edge, with eight different corner normals. */
static int random_quad(silk_arena *a, silk_mesh *m)
{
    dvec p[4];
    dvec c = dmk(check_uniform(-100, 100), check_uniform(-100, 100), check_uniform(-100, 100));
    double scale = check_uniform(0.05, 40);
    for (int i = 0; i < 4; i++) p[i] = dadd(c, dscale(rand_unit(), scale * check_uniform(0.3, 1)));
    static const uint32_t tri[6] = { 0, 1, 2, 1, 0, 3 };
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = 4;
    in.ntris = 2;
    in.pos = silk_arena_array(a, 4, sizeof(silk_vec3), SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 6, sizeof(silk_index), SILK_MEM_MESH);
    in.file_normal = silk_arena_array(a, 6, sizeof(silk_vec3), SILK_MEM_MESH);
    in.tri_file_normal = silk_arena_array(a, 6, sizeof(silk_index), SILK_MEM_MESH);
    in.nfile_normals = 6;
    for (int i = 0; i < 4; i++) in.pos[i] = tofx(p[i]);
    for (int t = 0; t < 2; t++) {
        dvec fn = dnorm(dcross(dsub(p[tri[3 * t + 1]], p[tri[3 * t]]), dsub(p[tri[3 * t + 2]], p[tri[3 * t]])));
        for (int k = 0; k < 3; k++) {
            in.tri[3 * t + k] = tri[3 * t + k];
            in.tri_file_normal[3 * t + k] = (silk_index)(3 * t + k);
            in.file_normal[3 * t + k] = tofx(dnorm(dadd(fn, dscale(rand_unit(), 0.7))));
        }
    }
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.normals = SILK_NORMALS_FILE;
    silk_error err;
    return silk_mesh_build(&in, "quad", &o, a, m, &err) == SILK_OK;
}

/* Blended control points: alpha 1 gives the PN patch bit for bit, alpha 0
 * the straight sides (b = l exactly, b111 within 1 ulp of the centroid), and
 * any alpha the convex combination alpha c + (1 - alpha) l within 1.5 ulp. */
TEST(blended_control_points)
{
    silk_arena a;
    silk_mesh m;
    double worst = 0;
    int fails = 0;
    for (int it = 0; it < 2000; it++) {
        if (!random_quad(&a, &m)) { fails++; continue; }
        for (uint32_t t = 0; t < 2; t++) {
            const silk_fx one[3] = { SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE }, zero[3] = { 0, 0, 0 };
            silk_patch pn, p1, p0, pa;
            silk_patch_build(&m, t, NULL, SILK_PN_LINEAR, &pn);
            silk_patch_build(&m, t, one, SILK_PN_LINEAR, &p1);
            if (memcmp(&pn, &p1, sizeof pn) != 0) fails++;
            silk_patch_build(&m, t, zero, SILK_PN_LINEAR, &p0);
            static const int near[3][2] = { { SILK_B210, SILK_B120 }, { SILK_B021, SILK_B012 }, { SILK_B102, SILK_B201 } };
            dvec cen = dmk(0, 0, 0);
            for (int k = 0; k < 3; k++) {
                silk_vec3 P = m.pos[m.tri[3 * t + k]], Q = m.pos[m.tri[3 * t + (k + 1) % 3]];
                if (!v3_eq(p0.b[near[k][0]], silk_patch_lin(P, Q)) || !v3_eq(p0.b[near[k][1]], silk_patch_lin(Q, P)))
                    fails++;
                cen = dadd(cen, dscale(dv(P), 1.0 / 3));
            }
            if (ddist(cen, p0.b[SILK_B111]) > 1.0 * ULP) fails++;
            /* random alphas: each side point between its l and c */
            silk_fx al[3];
            for (int k = 0; k < 3; k++) al[k] = d2fx(check_uniform(0, 1));
            silk_patch_build(&m, t, al, SILK_PN_LINEAR, &pa);
            for (int k = 0; k < 3; k++)
                for (int s = 0; s < 2; s++) {
                    int q = near[k][s];
                    dvec l = dv(p0.b[q]), c = dv(pn.b[q]);
                    dvec want = dadd(l, dscale(dsub(c, l), fx2d(al[k])));
                    double e = ddist(want, pa.b[q]) / ULP;
                    if (e > worst) worst = e;
                    if (e > 1.5) fails++;
                }
        }
    }
    printf("# blended control points: worst %.3f ulp from alpha c + (1 - alpha) l\n", worst);
    CHECKF(fails == 0, "%d blended patches wrong", fails);
}

/* One frame, read back: a triangle is flat exactly when its three edges
 * have alpha 0; flat triangles are the mesh's own corners; every edge of a
 * curved triangle has the segment count of its formula (n-1 would break
 * the bound, n keeps it), counted the same from both sides; and the
 * polygon through the curve stays within the tolerance in pixels. */
TEST(frame_structure_and_tolerance)
{
    static const char *names[] = { "bunny-500.obj", "fandisk-128.obj" };
    static const double tols[] = { 0.25, 1, 4 };
    silk_arena a;
    silk_mesh m;
    int fails = 0, curved_total = 0, flat_total = 0, multi = 0;
    double worst_px = 0;
    for (int f = 0; f < 2; f++) {
        if (!load_shared(&a, names[f], &m)) { CHECK(0); continue; }
        uint8_t *curved = malloc(m.ntris);
        uint32_t *seg = malloc(sizeof *seg * 3 * m.ntris);
        for (int it = 0; it < 12; it++) {
            silk_view v;
            if (!make_view(&m, rand_unit(), check_uniform(1.2, 5), it % 3 == 2, &v)) { CHECK(0); continue; }
            silk_fx tol = d2fx(tols[it % 3]), beta = SILK_FX_C(1, 4);
            silk_arena_mark mk = silk_arena_top_mark(&a);
            silk_frame_geom g;
            silk_frame_stats st;
            silk_error err;
            memset(&st, 0, sizeof st);
            if (silk_frame_blend(&a, &m, &v, beta, tol, &g, &st, &err) != SILK_OK || st.fell_back) {
                fails++;
                continue;
            }
            if (!read_layout(&m, &g, curved, seg)) { fails++; silk_arena_top_release(&a, &mk); continue; }
            uint32_t ncurved = 0;
            for (uint32_t t = 0; t < m.ntris; t++) {
                silk_fx al[3];
                for (int k = 0; k < 3; k++) al[k] = fixed_alpha(&m, &v, m.tri_edge[3 * t + k], beta);
                int want_curved = al[0] || al[1] || al[2];
                if (want_curved != curved[t]) fails++;
                ncurved += curved[t];
                if (!curved[t]) continue;
                for (int k = 0; k < 3; k++) {
                    uint32_t e = m.tri_edge[3 * t + k], n = seg[3 * t + k];
                    if (n != silk_blend_segments(&m, &v, e, al[k], tol)) fails++;
                    if (al[k] == 0 && n != 1) fails++;
                    if (n > 1) multi++;
                    /* the curve in doubles from the fixed control points */
                    const silk_edge *ed = &m.edge[e];
                    silk_vec3 c[2];
                    silk_patch_edge_curve(&m, e, c);
                    dvec p0 = dv(m.pos[ed->v[0]]), p1 = dv(m.pos[ed->v[1]]);
                    dvec d0 = dsub(dv(c[0]), dv(silk_patch_lin(m.pos[ed->v[0]], m.pos[ed->v[1]])));
                    dvec d1 = dsub(dv(c[1]), dv(silk_patch_lin(m.pos[ed->v[1]], m.pos[ed->v[0]])));
                    double A = fx2d(al[k]);
                    dvec mid = dscale(dadd(p0, p1), 0.5);
                    double ppu = fx2d(v.pixels_per_unit);
                    if (!v.cam.ortho) {
                        dvec fw = dnorm(dsub(dv(v.cam.target), dv(v.cam.eye)));
                        ppu /= fmax(ddot(dsub(mid, dv(v.cam.eye)), fw), fx2d(v.cam.znear));
                    }
                    double M = A * fmax(dlen(dsub(dscale(d0, 2), d1)), dlen(dsub(d0, dscale(d1, 2))));
                    double bound_px = 0.75 * M * ppu / ((double)n * n);
                    /* the actual polygon error, sampled */
                    double err_px = 0;
                    for (uint32_t s = 0; s < n; s++)
                        for (int q = 1; q < 16; q++) {
                            double t0 = (double)s / n, t1 = (double)(s + 1) / n, tt = t0 + (t1 - t0) * q / 16;
                            double w = (tt - t0) / (t1 - t0);
                            double D0 = 3 * tt * (1 - tt) * (1 - tt), D1 = 3 * tt * tt * (1 - tt);
                            double E0 = 3 * t0 * (1 - t0) * (1 - t0), E1 = 3 * t0 * t0 * (1 - t0);
                            double F0 = 3 * t1 * (1 - t1) * (1 - t1), F1 = 3 * t1 * t1 * (1 - t1);
                            /* the straight part is linear in t: only alpha D(t) deviates */
                            dvec on = dscale(dadd(dscale(d0, D0), dscale(d1, D1)), A);
                            dvec chord = dscale(dadd(dscale(dadd(dscale(d0, E0), dscale(d1, E1)), 1 - w),
                                                     dscale(dadd(dscale(d0, F0), dscale(d1, F1)), w)), A);
                            err_px = fmax(err_px, dlen(dsub(on, chord)) * ppu);
                        }
                    if (err_px > bound_px * 1.0001 + 1e-9) fails++;
                    if (n < SILK_BLEND_MAX_SEGMENTS && bound_px > fx2d(tol) * 1.001) fails++;
                    if (n > 1 && 0.75 * M * ppu / ((double)(n - 1) * (n - 1)) < fx2d(tol) * 0.999) fails++;
                    if (err_px / fx2d(tol) > worst_px) worst_px = err_px / fx2d(tol);
                }
            }
            CHECK(st.silhouette_tris == ncurved && g.npatch == ncurved);
            curved_total += ncurved;
            flat_total += m.ntris - ncurved;
            silk_arena_top_release(&a, &mk);
        }
        free(curved);
        free(seg);
    }
    printf("# blend frames: %d curved and %d flat triangles, %d sides cut; worst chord error %.3f of the tolerance\n",
           curved_total, flat_total, multi, worst_px);
    CHECKF(fails == 0, "%d mismatches", fails);
    CHECK(curved_total > 0 && flat_total > 0 && multi > 0);
}

/* The shared meshes from many views, perspective and parallel, several beta
 * and tolerances: every directed edge of the output meets its reverse, and
 * on the meshes without split normals flat and curved triangles give a
 * shared vertex the same normal bits. */
TEST(crack_free_shared_meshes)
{
    static const char *names[] = { "sphere-200.obj", "fandisk-128.obj", "torus-576.obj" };
    static const double betas[] = { 0, 0.25, 1 }, tols[] = { 0.25, 1, 4 };
    silk_arena a;
    silk_mesh m;
    int frames = 0, bad_frames = 0;
    uint32_t curved = 0, flat = 0;
    for (int f = 0; f < 3; f++) {
        if (!load_shared(&a, names[f], &m)) { CHECK(0); continue; }
        for (int it = 0; it < 18; it++) {
            silk_view v;
            if (!make_view(&m, rand_unit(), check_uniform(1.1, 8), it % 2, &v)) { CHECK(0); continue; }
            silk_arena_mark mk = silk_arena_top_mark(&a);
            silk_frame_geom g;
            silk_frame_stats st;
            silk_error err;
            memset(&st, 0, sizeof st);
            CHECK(silk_frame_blend(&a, &m, &v, d2fx(betas[it % 3]), d2fx(tols[(it / 3) % 3]), &g, &st, &err) == SILK_OK);
            CHECK(!st.fell_back);
            uint32_t checked, bad = tf_crack_check(&m, &g, &checked), seams = f != 1 ? tf_normal_seams(&m, &g) : 0;
            if (bad || seams) {
                bad_frames++;
                fprintf(stderr, "%s view %d: %u of %u edges unpaired, %u normal seams\n", names[f], it, bad, checked,
                        seams);
            }
            curved += g.npatch;
            flat += m.ntris - g.npatch;
            frames++;
            silk_arena_top_release(&a, &mk);
        }
    }
    printf("# crack check: %d frames, %u curved and %u flat triangles\n", frames, curved, flat);
    CHECKF(bad_frames == 0, "%d frames with cracks or seams", bad_frames);
    CHECK(curved > 0 && flat > 0);
}

/* Feature edges are always curved: on fandisk-128 every triangle at a
 * feature edge is a patch, from any view. */
TEST(features_always_curved)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "fandisk-128.obj", &m)) { CHECK(0); return; }
    CHECK(m.nfeature_edges > 0);
    uint8_t *curved = malloc(m.ntris);
    uint32_t *seg = malloc(sizeof *seg * 3 * m.ntris);
    int fails = 0;
    for (int it = 0; it < 6; it++) {
        silk_view v;
        if (!make_view(&m, rand_unit(), 3, it % 2, &v)) { CHECK(0); continue; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_frame_geom g;
        silk_frame_stats st;
        silk_error err;
        CHECK(silk_frame_blend(&a, &m, &v, SILK_FX_C(1, 4), SILK_FX_ONE, &g, &st, &err) == SILK_OK);
        CHECK(read_layout(&m, &g, curved, seg));
        for (uint32_t t = 0; t < m.ntris; t++)
            for (int k = 0; k < 3; k++)
                if ((m.edge[m.tri_edge[3 * t + k]].flags & SILK_EDGE_FEATURE) && !curved[t]) fails++;
        silk_arena_top_release(&a, &mk);
    }
    free(curved);
    free(seg);
    CHECKF(fails == 0, "%d feature-edge triangles drawn flat", fails);
}

/* The whole pipeline on bunny-500: BLEND draws fewer triangles than PN at
 * level 3, more than FLAT, curves only some triangles, releases its
 * scratch; bad arguments and small arenas fail cleanly. */
TEST(render_blend_mode)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "bunny-500.obj", &m)) { CHECK(0); return; }
    silk_view v;
    CHECK(make_view(&m, dmk(0.4, 0.3, 1), 2.5, 0, &v));
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal hal;
    silk_hal_phong(&hal, &ph);
    static uint8_t color[320 * 240 * 3];
    static uint32_t depth[320 * 240];
    silk_target t;
    silk_target_init(&t, 320, 240, 0, 240, SILK_PIX_RGB888, color, depth);
    silk_render_opts o;
    silk_render_opts_default(&o);
    CHECK(o.level == 3 && o.pn_normals == SILK_PN_QUADRATIC && o.blend_beta == SILK_FX_C(1, 4));
    static const silk_mode modes[] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH, SILK_MODE_PN, SILK_MODE_BLEND };
    static const char *mode_names[] = { "flat", "smooth", "pn", "blend" };
    silk_frame_stats st[4];
    silk_error err;
    for (int i = 0; i < 4; i++) {
        o.mode = modes[i];
        size_t top = a.top;
        CHECK(silk_render(&a, &m, &v, &hal, &o, &t, &st[i], &err) == SILK_OK);
        CHECK(a.top == top && !st[i].fell_back);
        printf("# bunny-500 320x240 %s: %u triangles drawn, %lu frame bytes\n", mode_names[i], st[i].tris_drawn,
               (unsigned long)st[i].frame_bytes);
    }
    CHECK(st[3].tris_drawn > st[0].tris_drawn && st[3].tris_drawn < st[2].tris_drawn);
    CHECK(st[3].silhouette_tris > 0 && st[3].silhouette_tris < m.ntris);

    o.mode = SILK_MODE_BLEND;
    o.blend_beta = -1;
    CHECK(silk_render(&a, &m, &v, &hal, &o, &t, NULL, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "beta") != NULL, "%s", err.msg);
    o.blend_beta = SILK_FX_C(3, 2);
    CHECK(silk_render(&a, &m, &v, &hal, &o, &t, NULL, &err) == SILK_ERR_ARG);
    o.blend_beta = SILK_FX_C(1, 4);
    o.tolerance_px = 0;
    CHECK(silk_render(&a, &m, &v, &hal, &o, &t, NULL, &err) == SILK_ERR_ARG);
    o.tolerance_px = SILK_FX_HALF;

    /* room for the coarse mesh only: drawn flat and flagged */
    silk_frame_geom g;
    silk_frame_stats fs;
    silk_arena small = a;
    small.size = small.bottom + small.top + 3 * m.ntris * (sizeof(silk_vrec) + sizeof(uint32_t)) + m.ntris + 64;
    CHECK(silk_frame_blend(&small, &m, &v, o.blend_beta, o.tolerance_px, &g, &fs, &err) == SILK_OK);
    CHECK(fs.fell_back == 1 && g.npatch == 0 && g.ntri == m.ntris);
    small = a;
    small.size = small.bottom + small.top + 64;
    CHECK(silk_frame_blend(&small, &m, &v, o.blend_beta, o.tolerance_px, &g, &fs, &err) == SILK_ERR_NOMEM);
}

int main(void)
{
    CHECK_PROGRAM_NEEDS(SILK_REFERENCE_MODES);
    arena_buf = malloc(ARENA_BYTES);
    RUN(alpha_vs_double);
    RUN(alpha_continuous_in_the_eye);
    RUN(blended_control_points);
    RUN(frame_structure_and_tolerance);
    RUN(crack_free_shared_meshes);
    RUN(features_always_curved);
    RUN(render_blend_mode);
    free(arena_buf);
    return check_done();
}
