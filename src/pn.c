/*
 * pn.c - PN triangles (Vlachos, Peters, Boyd, Mitchell, "Curved PN
 * triangles", I3D 2001) built from the edge curves of Dyken & Reimers
 * ("Real-time linear silhouette enhancement", eqs. 4-8): the cubic Bezier
 * patch of a triangle and its quadratic normal patch, their exact
 * evaluation at a barycentric grid point, and PN mode's frame, in which
 * every patch is cut uniformly into level^2 triangles.
 *
 * Split normals.  Vlachos' b210 = (2 P1 + P2 - w12 N1) / 3 takes the
 * triangle's own normal at P1.  Across a feature edge the two triangles have
 * different normals there, so their patches would bend the shared side in
 * two ways and open a crack.  Here a side's control points come from its
 * mesh edge instead: where both triangles have the same normal at an edge
 * end it is Vlachos' point (eq. 7); where they differ, the linear control
 * point is projected onto the line where the two tangent planes meet
 * (eq. 8).  Both patches get the same bits, and each still has the shading
 * normal's plane as its tangent plane at every corner.
 */
#include <string.h>
#include "patch.h"
#include "mesh_build.h"

#define Q32 ((int64_t)1 << 32)

/* v / d rounded to nearest, halves away from zero (d > 0): symmetric, so
 * that a computation and its mirror image round alike. */
static int64_t div_round(int64_t v, int64_t d)
{
    return v >= 0 ? (v + d / 2) / d : -((-v + d / 2) / d);
}

silk_vec3 silk_patch_lin(silk_vec3 pi, silk_vec3 pj)
{
    return silk_v3(silk_fx_sat(div_round(2 * (int64_t)pi.x + pj.x, 3)),
                   silk_fx_sat(div_round(2 * (int64_t)pi.y + pj.y, 3)),
                   silk_fx_sat(div_round(2 * (int64_t)pi.z + pj.z, 3)));
}

/* (base + w dir) / 3 with base in Q16.16 units, w a Q32.32 dot product
 * and dir a Q16.16 unit component: both terms are exact in units of 2^-48
 * (below 2^61 for coordinates within SILK_COORD_MAX), rounded once. */
static silk_fx third_of(int64_t base, int64_t w, silk_fx dir)
{
    return silk_fx_sat(div_round(base * Q32 + w * dir, 3 * Q32));
}

static int v3_equal(silk_vec3 a, silk_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* v / |v| in Q2.30 (components within +-2^30), for v of any scale: v is
 * first shifted so its largest component has 30 bits, then the length is
 * an exact integer square root, good to 2^-29.  0 for the zero vector. */
static int unit30(const int64_t v[3], int64_t out[3])
{
    int64_t w[3], big = 0;
    for (int k = 0; k < 3; k++) {
        int64_t a = v[k] < 0 ? -v[k] : v[k];
        if (a > big) big = a;
    }
    if (big == 0) return 0;
    int down = 0, up = 0;
    while ((big >> down) >= ((int64_t)1 << 30)) down++;
    while ((big << up) < ((int64_t)1 << 29)) up++;
    for (int k = 0; k < 3; k++) w[k] = down ? silk_shr_round64(v[k], down) : v[k] * ((int64_t)1 << up);
    int64_t len = (int64_t)silk_isqrt64((uint64_t)(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    for (int k = 0; k < 3; k++) out[k] = div_round(w[k] * ((int64_t)1 << 30), len);
    return 1;
}

silk_vec3 silk_patch_edge_ctrl(silk_vec3 pi, silk_vec3 pj, silk_vec3 ns, silk_vec3 nt)
{
    silk_vec3 e = silk_v3_sub(pj, pi);
    int64_t m[3];
    if (!v3_equal(ns, nt)) {
        /* eq. 8: m along nt x ns, exact in 64 bits (so nearly parallel
         * normals still give a clean direction) and made unit in Q2.30, as
         * a Q16.16 unit vector would cost |e| 2^-17 here.  c = p_i +
         * (e.m / 3) m with e.m rounded to Q16.16; the sign of m cancels. */
        int64_t x[3] = { (int64_t)nt.y * ns.z - (int64_t)nt.z * ns.y,
                         (int64_t)nt.z * ns.x - (int64_t)nt.x * ns.z,
                         (int64_t)nt.x * ns.y - (int64_t)nt.y * ns.x };
        if (unit30(x, m)) {
            int64_t w = silk_shr_round64(e.x * m[0] + e.y * m[1] + e.z * m[2], 30);  /* < 2^59 before */
            const int64_t q30 = (int64_t)1 << 30;
            return silk_v3(silk_fx_sat(div_round(3 * (int64_t)pi.x * q30 + w * m[0], 3 * q30)),
                           silk_fx_sat(div_round(3 * (int64_t)pi.y * q30 + w * m[1], 3 * q30)),
                           silk_fx_sat(div_round(3 * (int64_t)pi.z * q30 + w * m[2], 3 * q30)));
        }
    }
    /* eq. 7: c = (2 p_i + p_j - (e.n) n) / 3 */
    int64_t w = -silk_v3_dot64(e, ns);
    return silk_v3(third_of(2 * (int64_t)pi.x + pj.x, w, ns.x), third_of(2 * (int64_t)pi.y + pj.y, w, ns.y),
                   third_of(2 * (int64_t)pi.z + pj.z, w, ns.z));
}

/* The normal triangle t has at its corner on vertex v. */
static silk_vec3 corner_normal(const silk_mesh *m, silk_index t, silk_index v)
{
    for (int k = 0; k < 3; k++)
        if (silk_mesh_corner(m, 3 * t + k) == v) return silk_mesh_normal(m, silk_mesh_corner_normal(m, 3 * t + k));
    return silk_v3(0, 0, 0);
}

void silk_patch_edge_curve(const silk_mesh *m, uint32_t e, silk_vec3 c[2])
{
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    silk_vec3 p0 = silk_mesh_pos(m, ed->v[0]), p1 = silk_mesh_pos(m, ed->v[1]);
    /* On a non-manifold edge the first two triangles speak for all. */
    silk_index s = ed->t[0], t = ed->t[1] != SILK_NO_INDEX ? ed->t[1] : ed->t[0];
    c[0] = silk_patch_edge_ctrl(p0, p1, corner_normal(m, s, ed->v[0]), corner_normal(m, t, ed->v[0]));
    c[1] = silk_patch_edge_ctrl(p1, p0, corner_normal(m, s, ed->v[1]), corner_normal(m, t, ed->v[1]));
}

silk_vec3 silk_patch_mid_normal(silk_vec3 pa, silk_vec3 pb, silk_vec3 na, silk_vec3 nb)
{
    /* Vlachos: h = Na + Nb - v (Pb - Pa), v = 2 (Pb - Pa).(Na + Nb) / |Pb - Pa|^2,
     * which is Na + Nb reflected in the plane perpendicular to the side:
     * S - 2 (S.u) u with u the unit side.  Reversing the side flips u
     * and leaves h as it is (normalisation is sign-symmetric). */
    silk_vec3 s = silk_v3_add(na, nb), u, out;
    if (!silk_v3_normalize(silk_v3_sub(pb, pa), &u)) u = silk_v3(0, 0, 0);
    int64_t d = silk_v3_dot64(s, u);
    int64_t h[3] = { s.x * Q32 - 2 * d * u.x, s.y * Q32 - 2 * d * u.y, s.z * Q32 - 2 * d * u.z };
    if (!silk_v3_normalize64(h, &out)) return silk_v3(0, 0, 0);
    return out;
}

/* l + alpha (c - l): at alpha = 1 exactly c. */
static silk_vec3 blend_ctrl(silk_vec3 l, silk_vec3 c, silk_fx alpha)
{
    return silk_v3(silk_fx_sat(l.x + silk_shr_round64(((int64_t)c.x - l.x) * alpha, 16)),
                   silk_fx_sat(l.y + silk_shr_round64(((int64_t)c.y - l.y) * alpha, 16)),
                   silk_fx_sat(l.z + silk_shr_round64(((int64_t)c.z - l.z) * alpha, 16)));
}

void silk_patch_build(const silk_mesh *m, uint32_t t, const silk_fx *alpha, silk_pn_normals normals,
                      silk_patch *p)
{
    /* Side k runs from corner k to corner k+1; its control points near
     * each end, and its mid normal coefficient. */
    static const uint8_t near[3][2] = { { SILK_B210, SILK_B120 }, { SILK_B021, SILK_B012 },
                                        { SILK_B102, SILK_B201 } };
    static const uint8_t mid[3] = { SILK_N110, SILK_N011, SILK_N101 };
    silk_index v[3] = { silk_mesh_corner(m, 3 * t), silk_mesh_corner(m, 3 * t + 1), silk_mesh_corner(m, 3 * t + 2) };
    silk_vec3 P[3], N[3];
    for (int k = 0; k < 3; k++) {
        P[k] = silk_mesh_pos(m, v[k]);
        N[k] = silk_mesh_normal(m, silk_mesh_corner_normal(m, 3 * t + k));
        p->b[SILK_B300 + k] = P[k];
        p->n[SILK_N200 + k] = N[k];
        if (m->uv && m->tri_uv) {
            p->uv[k] = m->uv[m->tri_uv[3 * t + k]];
        } else {
            p->uv[k].x = p->uv[k].y = 0;
        }
        p->rgb[k] = m->color ? m->color[v[k]] : 0xffffff;
    }
    int64_t side_sum[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; k++) {
        int k1 = (k + 1) % 3;
        uint32_t e = silk_mesh_tri_edge(m, t, k);
        silk_vec3 c[2];
        silk_patch_edge_curve(m, e, c);
        int fwd = silk_mesh_edge(m, e).v[0] == v[k];
        silk_fx a = alpha ? alpha[k] : SILK_FX_ONE;
        silk_vec3 b0 = blend_ctrl(silk_patch_lin(P[k], P[k1]), c[fwd ? 0 : 1], a);
        silk_vec3 b1 = blend_ctrl(silk_patch_lin(P[k1], P[k]), c[fwd ? 1 : 0], a);
        p->b[near[k][0]] = b0;
        p->b[near[k][1]] = b1;
        side_sum[0] += (int64_t)b0.x + b1.x;
        side_sum[1] += (int64_t)b0.y + b1.y;
        side_sum[2] += (int64_t)b0.z + b1.z;
        /* Linear normals in Vlachos' form: n110 = N1 + N2 makes the sum
         * (u N1 + v N2 + w N3)(u + v + w). */
        p->n[mid[k]] = normals == SILK_PN_LINEAR ? silk_v3_add(N[k], N[k1])
                                                 : silk_patch_mid_normal(P[k], P[k1], N[k], N[k1]);
    }
    /* b111 = E + (E - V)/2 = (3 * sum of the six - 2 * sum of the corners) / 12 */
    p->b[SILK_B111] = silk_v3(
        silk_fx_sat(div_round(3 * side_sum[0] - 2 * ((int64_t)P[0].x + P[1].x + P[2].x), 12)),
        silk_fx_sat(div_round(3 * side_sum[1] - 2 * ((int64_t)P[0].y + P[1].y + P[2].y), 12)),
        silk_fx_sat(div_round(3 * side_sum[2] - 2 * ((int64_t)P[0].z + P[1].z + P[2].z), 12)));
}

void silk_patch_eval(const silk_patch *p, uint32_t point, silk_vertex_attr *out)
{
    int64_t i = point & 0xFF, j = (point >> 8) & 0xFF, n = (point >> 16) & 0xFF;
    memset(out, 0, sizeof *out);
    if (!p || n == 0 || i + j > n || (point >> 24) != 0) return;
    int64_t k = n - i - j;
    /* Bernstein weights times n^3 (and n^2 for the normal): integers, so
     * the sums are exact and a side's points do not depend on the
     * control points off that side (their weights are exactly 0). */
    const int64_t w[10] = { i * i * i,     j * j * j,     k * k * k,     3 * i * i * j, 3 * i * j * j,
                            3 * j * j * k, 3 * j * k * k, 3 * i * k * k, 3 * i * i * k, 6 * i * j * k };
    const int64_t wn[6] = { i * i, j * j, k * k, i * j, j * k, i * k };
    int64_t s[3] = { 0, 0, 0 }, ns[3] = { 0, 0, 0 };
    for (int q = 0; q < 10; q++) {
        s[0] += w[q] * p->b[q].x;    /* |b| < 2^31, sum of w = n^3 <= 2^24 */
        s[1] += w[q] * p->b[q].y;
        s[2] += w[q] * p->b[q].z;
    }
    for (int q = 0; q < 6; q++) {
        ns[0] += wn[q] * p->n[q].x;
        ns[1] += wn[q] * p->n[q].y;
        ns[2] += wn[q] * p->n[q].z;
    }
    int64_t n3 = n * n * n;
    out->pos = silk_v3(silk_fx_sat(div_round(s[0], n3)), silk_fx_sat(div_round(s[1], n3)),
                       silk_fx_sat(div_round(s[2], n3)));
    /* At a corner the corner's own normal, bit for bit as a CORNER record
     * has it (BLEND mode mixes the two); where the normals cancel (opposite
     * corner normals), the nearest corner's. */
    int c = i >= j && i >= k ? 0 : (j >= k ? 1 : 2);
    if (i == n || j == n || k == n)
        out->normal = p->n[SILK_N200 + c];
    else if (!silk_v3_normalize64(ns, &out->normal))
        silk_v3_normalize(p->n[SILK_N200 + c], &out->normal);
    out->uv.x = silk_fx_sat(div_round(i * p->uv[0].x + j * p->uv[1].x + k * p->uv[2].x, n));
    out->uv.y = silk_fx_sat(div_round(i * p->uv[0].y + j * p->uv[1].y + k * p->uv[2].y, n));
    out->rgb = 0;
    for (int sh = 0; sh <= 16; sh += 8)
        out->rgb |= (uint32_t)div_round(i * (int64_t)(p->rgb[0] >> sh & 0xff) + j * (int64_t)(p->rgb[1] >> sh & 0xff) +
                                        k * (int64_t)(p->rgb[2] >> sh & 0xff), n) << sh;
}

silk_status silk_patch_check_mesh(const silk_mesh *m, const char *who, silk_error *err)
{
    if (m->ntris > 0 && !m->packed.base && (!m->pos || !m->tri || !m->normal || !m->tri_normal || !m->edge))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0,
                         "%s: the mesh has no shading normals or edges (build it with silk_mesh_build)", who);
    return SILK_OK;
}

/* Grid point (i, j) of a level-L patch: rows of constant i, j ascending. */
static uint32_t grid_index(uint32_t i, uint32_t j, uint32_t L)
{
    return i * (2 * L + 3 - i) / 2 + j;
}

silk_status silk_frame_pn(silk_arena *a, const silk_mesh *m, uint32_t level, silk_pn_normals normals,
                          silk_frame_geom *g, silk_frame_stats *stats, silk_error *err)
{
    if (!a || !m || !g) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_pn: missing argument");
    if (level < 1 || level > SILK_PN_MAX_LEVEL)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "PN level %lu out of range 1..%u", (unsigned long)level,
                         SILK_PN_MAX_LEVEL);
    if (normals != SILK_PN_QUADRATIC && normals != SILK_PN_LINEAR)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "unknown PN normals %d", (int)normals);
    silk_status st = silk_patch_check_mesh(m, "silk_frame_pn", err);
    if (st != SILK_OK) return st;
    memset(g, 0, sizeof *g);
    if (stats) stats->fell_back = 0;

    const uint32_t L = level, per_rec = (L + 1) * (L + 2) / 2, per_tri = L * L;
    uint64_t nrec = (uint64_t)m->ntris * per_rec, ntri = (uint64_t)m->ntris * per_tri;
    if (nrec > UINT32_MAX / 3 || ntri > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, "frame", 0, "PN level %lu: too many triangles (%lu x %lu)",
                         (unsigned long)L, (unsigned long)m->ntris, (unsigned long)per_tri);

    silk_arena_mark mark = silk_arena_top_mark(a);
    g->patch = silk_arena_array_top(a, m->ntris, sizeof *g->patch, SILK_MEM_FRAME);
    g->vrec = silk_arena_array_top(a, (size_t)nrec, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, (size_t)ntri * 3, sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, (size_t)ntri, 1, SILK_MEM_FRAME);
    if (!g->patch || !g->vrec || !g->tri || !g->tri_added)
        return silk_frame_fall_back(a, m, &mark, g, stats, err);

    uint32_t *tri = g->tri;
    for (uint32_t t = 0; t < m->ntris; t++) {
        silk_patch_build(m, t, NULL, normals, &g->patch[t]);
        uint32_t base = t * per_rec;
        for (uint32_t i = 0; i <= L; i++)
            for (uint32_t j = 0; i + j <= L; j++) {
                silk_vrec *r = &g->vrec[base + grid_index(i, j, L)];
                r->kind = SILK_VREC_PATCH;
                r->a = t;
                r->b = SILK_PATCH_POINT(i, j, L);
            }
        /* Counter-clockwise like the triangle: corner 0 is (L,0), 1 is (0,L), 2 is (0,0). */
        for (uint32_t i = 0; i < L; i++)
            for (uint32_t j = 0; i + j < L; j++) {
                *tri++ = base + grid_index(i + 1, j, L);
                *tri++ = base + grid_index(i, j + 1, L);
                *tri++ = base + grid_index(i, j, L);
                if (i + j + 2 <= L) {
                    *tri++ = base + grid_index(i + 1, j + 1, L);
                    *tri++ = base + grid_index(i, j + 1, L);
                    *tri++ = base + grid_index(i + 1, j, L);
                }
            }
    }
    memset(g->tri_added, L > 1, (size_t)ntri);
    g->nvrec = (uint32_t)nrec;
    g->ntri = (uint32_t)ntri;
    g->npatch = m->ntris;
    return SILK_OK;
}
