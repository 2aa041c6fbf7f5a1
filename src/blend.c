/*
 * blend.c - silhouetteness blending (Dyken & Reimers, "Real-time linear
 * silhouette enhancement"): the continuous silhouetteness alpha of every
 * edge (eqs. 1-2), patches whose boundary control points are blended by it
 * between the straight edge and the edge curve (section 3: b210 = alpha
 * c_ij + (1 - alpha) l_ij, curves from eqs. 4-8 in pn.c, b111 as for PN
 * triangles), and the frame of section 4: a triangle whose three edges have
 * alpha 0 is drawn as it is; any other is split into three sub-patches with
 * a common apex at the patch centre, each drawn as a fan over its base,
 * the base edge cut into as many segments as it needs.
 *
 * Where the paper leaves a choice (docs/methods.md says why):
 *  - beta is one constant for all edges (the paper's 0.25 by default), not
 *    eq. 3's per-edge wedge;
 *  - feature edges (boundary, crease, smoothing groups, non-manifold) have
 *    alpha 1, as section 5 suggests, so feature lines are always curves;
 *    an edge next to a zero-area triangle, which faces nowhere, has 0;
 *  - an edge is cut into the fewest segments, at most
 *    SILK_BLEND_MAX_SEGMENTS, that keep it within the render tolerance of
 *    its curve in pixels (silk_blend_segments); alpha 0 means one segment,
 *    so a flat neighbour meets a curved triangle without a T-junction;
 *  - normals and uvs are interpolated linearly over the patch (section 4).
 */
#include <string.h>
#include "patch.h"

static silk_vec3 midpoint(silk_vec3 a, silk_vec3 b)
{
    return silk_v3(silk_fx_sat(silk_shr_round64((int64_t)a.x + b.x, 1)),
                   silk_fx_sat(silk_shr_round64((int64_t)a.y + b.y, 1)),
                   silk_fx_sat(silk_shr_round64((int64_t)a.z + b.z, 1)));
}

silk_fx silk_blend_alpha(silk_vec3 to_eye, silk_vec3 ns, silk_vec3 nt, silk_fx beta)
{
    silk_vec3 u;
    /* The eye on the edge: every direction is a view direction; call it a silhouette. */
    if (!silk_v3_normalize(to_eye, &u)) return SILK_FX_ONE;
    /* The two cosines in Q2.30 and their product in Q4.60: one rounding
     * each, none in the product. */
    int64_t cs = silk_shr_round64(silk_v3_dot64(u, ns), 2);
    int64_t ct = silk_shr_round64(silk_v3_dot64(u, nt), 2);
    int64_t f = cs * ct;
    if (f <= 0) return SILK_FX_ONE;
    if (beta <= 0) return 0;
    /* f / beta in Q16.16: Q4.60 / Q16.16 = Q16.16 after dividing by 2^28 */
    int64_t d = (int64_t)beta << 28, q = (f + d / 2) / d;
    return q >= SILK_FX_ONE ? 0 : SILK_FX_ONE - (silk_fx)q;
}

static silk_fx edge_alpha(const silk_mesh *m, const silk_view *v, uint32_t e, const silk_vec3 *face_normal,
                          silk_fx beta)
{
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    if (ed->flags & SILK_EDGE_FEATURE) return SILK_FX_ONE;
    if ((ed->flags & SILK_EDGE_DEGENERATE) || ed->t[1] == SILK_NO_INDEX) return 0;
    silk_vec3 ns = face_normal[ed->t[0]], nt = face_normal[ed->t[1]];
    if ((ns.x == 0 && ns.y == 0 && ns.z == 0) || (nt.x == 0 && nt.y == 0 && nt.z == 0)) return 0;
    silk_vec3 mid = midpoint(silk_mesh_pos(m, ed->v[0]), silk_mesh_pos(m, ed->v[1]));
    return silk_blend_alpha(silk_view_to_eye(v, mid), ns, nt, beta);
}

uint32_t silk_blend_segments(const silk_mesh *m, const silk_view *v, uint32_t e, silk_fx alpha,
                             silk_fx tol_px)
{
    const int64_t max = SILK_BLEND_MAX_SEGMENTS;
    if (alpha <= 0) return 1;
    if (tol_px <= 0) return (uint32_t)max;
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    silk_vec3 p0 = silk_mesh_pos(m, ed->v[0]), p1 = silk_mesh_pos(m, ed->v[1]), c[2];
    silk_patch_edge_curve(m, e, c);
    silk_vec3 d0 = silk_v3_sub(c[0], silk_patch_lin(p0, p1)), d1 = silk_v3_sub(c[1], silk_patch_lin(p1, p0));
    /* |D''| is largest at an end: 6 |2 d0 - d1| at t = 0, 6 |d0 - 2 d1| at t = 1. */
    silk_vec3 a0 = silk_v3_sub(silk_v3_add(d0, d0), d1), a1 = silk_v3_sub(d0, silk_v3_add(d1, d1));
    silk_fx dev = silk_fx_mul(alpha, silk_fx_max(silk_v3_length(a0), silk_v3_length(a1)));
    if (dev <= 0) return 1;

    silk_fx px_per_unit = v->pixels_per_unit;
    if (!v->cam.ortho) {
        silk_vec3 mid = midpoint(p0, p1);
        silk_fx depth = silk_v3_dot(silk_v3_sub(mid, v->cam.eye), v->forward);
        px_per_unit = silk_fx_div(v->pixels_per_unit, silk_fx_max(depth, v->cam.znear));
    }
    /* Smallest n with (3/4) dev px / n^2 <= tol, i.e. 3 q <= 4 n^2, q = dev px / tol
     * in Q16.16.  dev px < 2^62 (two silk_fx); a q beyond 2^40 asks for more
     * than the cap anyway. */
    int64_t q = ((int64_t)dev * px_per_unit) / tol_px;
    if (q > ((int64_t)1 << 40)) return (uint32_t)max;
    int64_t n = silk_isqrt64((uint64_t)(3 * q) / (4u << 16));
    while (4 * n * n * 65536 < 3 * q) n++;
    if (n < 1) n = 1;
    return (uint32_t)(n > max ? max : n);
}

/* The point s of n on side k (corner k -> corner k+1) as a patch point. */
static uint32_t side_point(uint32_t k, uint32_t s, uint32_t n)
{
    if (k == 0) return SILK_PATCH_POINT(n - s, s, n);
    if (k == 1) return SILK_PATCH_POINT(0, n - s, n);
    return SILK_PATCH_POINT(s, 0, n);
}

/* Triangle t appended to g: as it is when its three edges have
 * silhouetteness 0, else its blended patch fanned around the centre with
 * each side cut into nseg segments. */
static void emit_tri(const silk_mesh *m, uint32_t t, const silk_fx *alpha, const uint8_t *nseg, silk_frame_geom *g)
{
    uint32_t r = g->nvrec, nt = g->ntri, p = g->npatch;
    silk_index te[3] = { silk_mesh_tri_edge(m, t, 0), silk_mesh_tri_edge(m, t, 1), silk_mesh_tri_edge(m, t, 2) };
    silk_fx sa[3] = { alpha[te[0]], alpha[te[1]], alpha[te[2]] };
    if (sa[0] == 0 && sa[1] == 0 && sa[2] == 0) {
        for (uint32_t k = 0; k < 3; k++) {
            g->vrec[r].kind = SILK_VREC_CORNER;
            g->vrec[r].a = 3 * t + k;
            g->tri[3 * nt + k] = r++;
        }
        g->tri_added[nt++] = 0;
        g->nvrec = r;
        g->ntri = nt;
        return;
    }
    silk_patch_build(m, t, sa, SILK_PN_LINEAR, &g->patch[p]);
    uint32_t centre = r, first = r + 1, nb = 0;
    g->vrec[r].kind = SILK_VREC_PATCH;
    g->vrec[r].a = p;
    g->vrec[r++].b = SILK_PATCH_POINT(1, 1, 3);
    /* The boundary counter-clockwise: each corner, then its side's inner points. */
    for (uint32_t k = 0; k < 3; k++) {
        uint32_t n = nseg[te[k]];
        for (uint32_t s = 0; s < n; s++) {
            g->vrec[r].kind = SILK_VREC_PATCH;
            g->vrec[r].a = p;
            g->vrec[r++].b = s == 0 ? SILK_PATCH_POINT(k == 0, k == 1, 1) : side_point(k, s, n);
            nb++;
        }
    }
    for (uint32_t q = 0; q < nb; q++) {
        g->tri[3 * nt] = first + q;
        g->tri[3 * nt + 1] = first + (q + 1) % nb;
        g->tri[3 * nt + 2] = centre;
        g->tri_added[nt++] = 1;
    }
    g->nvrec = r;
    g->ntri = nt;
    g->npatch = p + 1;
}

silk_status silk_frame_blend(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx beta,
                             silk_fx tolerance_px, silk_frame_geom *g, silk_frame_stats *stats,
                             silk_error *err)
{
    if (!a || !m || !v || !g) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_blend: missing argument");
    if (beta < 0 || beta > SILK_FX_ONE) {
        char buf[16];
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "blend beta %s out of range 0..1", silk_fx_format(beta, buf));
    }
    if (tolerance_px <= 0)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_blend: tolerance must be positive");
    silk_status st = silk_patch_check_mesh(m, "silk_frame_blend", err);
    if (st != SILK_OK) return st;
    memset(g, 0, sizeof *g);
    if (stats) stats->fell_back = 0;

    silk_arena_mark mark = silk_arena_top_mark(a);
    uint32_t ne = silk_mesh_edge_bound(m);
    silk_fx *alpha = silk_arena_array_top(a, ne, sizeof *alpha, SILK_MEM_FRAME);
    uint8_t *nseg = silk_arena_array_top(a, ne, sizeof *nseg, SILK_MEM_FRAME);
    if (!alpha || !nseg) return silk_frame_fall_back(a, m, &mark, g, stats, err);
    /* Face normals are needed only for eq. 1: scratch, gone before the output. */
    silk_arena_mark scratch = silk_arena_top_mark(a);
    silk_vec3 *fn = silk_arena_array_top(a, m->ntris, sizeof *fn, SILK_MEM_FRAME);
    if (!fn) return silk_frame_fall_back(a, m, &mark, g, stats, err);
    for (uint32_t t = 0; t < m->ntris; t++) fn[t] = silk_mesh_face_normal(m, t);
    silk_mesh_edges it;
    silk_edge ed;
    for (silk_index e = silk_mesh_edges_first(m, &it, &ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, &ed)) {
        alpha[e] = edge_alpha(m, v, e, fn, beta);
        nseg[e] = (uint8_t)silk_blend_segments(m, v, e, alpha[e], tolerance_px);
    }
    silk_arena_top_release(a, &scratch);

    /* A curved triangle: centre, corners and each side's inner points;
     * one fan triangle per side segment. */
    uint64_t nrec = 0, ntri = 0;
    uint32_t npatch = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        silk_index te[3] = { silk_mesh_tri_edge(m, t, 0), silk_mesh_tri_edge(m, t, 1), silk_mesh_tri_edge(m, t, 2) };
        if (alpha[te[0]] == 0 && alpha[te[1]] == 0 && alpha[te[2]] == 0) {
            nrec += 3;
            ntri += 1;
        } else {
            uint32_t segs = (uint32_t)nseg[te[0]] + nseg[te[1]] + nseg[te[2]];
            npatch++;
            nrec += 1 + segs;
            ntri += segs;
        }
    }
    if (nrec > UINT32_MAX / 3 || ntri > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, "frame", 0, "too many triangles (%lu)", (unsigned long)m->ntris);
    g->patch = silk_arena_array_top(a, npatch, sizeof *g->patch, SILK_MEM_FRAME);
    g->vrec = silk_arena_array_top(a, (size_t)nrec, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, (size_t)ntri * 3, sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, (size_t)ntri, 1, SILK_MEM_FRAME);
    if (!g->patch || !g->vrec || !g->tri || !g->tri_added)
        return silk_frame_fall_back(a, m, &mark, g, stats, err);

    g->nvrec = g->ntri = g->npatch = 0;
    for (uint32_t t = 0; t < m->ntris; t++) emit_tri(m, t, alpha, nseg, g);
    if (stats) stats->silhouette_tris = npatch;
    return SILK_OK;
}
