/*
 * remesh.c - silhouette segments, adaptive sampling and local re-meshing
 * (paper III-D, III-E, Figs. 11 and 12), and the vertex records they become.
 *
 * A silhouette triangle L B1 B2 (L the corner whose visibility differs) has
 * silhouette points A on side L-B1 and B on side B2-L; its silhouette segment
 * S(t) runs from A to B (Hermite over the points and their normals, eq. 5)
 * and is sampled with n intervals from eq. 8.  S cuts the triangle in two:
 *
 *   the part around L:     its samples are connected to L (Fig. 11, samples
 *                          joined to the opposite vertex);
 *   the part along B1-B2:  its samples are connected to the base edge (Fig.
 *                          11, samples joined to the base): the early samples
 *                          to B1, the late ones to B2, and the sample nearest
 *                          the base edge's bisector to both.
 *
 * Fig. 11 shows the two as separate cases (S behind the base edge, S in
 * front of it); here both parts are always built, whichever the viewer
 * sees, so the output is closed wherever the input is.  The base edge gets no points of its own
 * (its "points" are its end vertices), so the triangle across it is left
 * alone.  Points on the sides are the edge chains of silhouette.c and are
 * walked in full, so any other points there (feature samples, the other
 * side's silhouette point across a crease) are included.  One rule keeps the
 * result a clean 2-manifold: no output triangle may have all three corners on
 * one side of the input triangle (the triangle across that side would build
 * the same sliver, and two surfaces would share an edge).  When a part of a
 * silhouette triangle has such extra side points, a fan from a corner would
 * break the rule, so that part is fanned from its own centre instead, as
 * Fig. 12b does for feature segments.  A triangle that is not a silhouette
 * triangle but has points on its sides is fanned from the opposite vertex
 * when one side has points (Fig. 12a), else from its centre (Fig. 12b).
 *
 * Emission is one function, silk_remesh_emit_tri: one input triangle's
 * share of the frame (its corner records, its own copies of the records
 * and curves of its sides' chains, its segment's samples and centres, its
 * triangles), rebuilt from the plan alone (segments are recomputed from the
 * edges' points).  The renderer refills one share at a time; a stored
 * frame is the shares of all input triangles appended into one buffer.
 * The plan counts what both cost (the largest share, the sum of all of
 * them), so that smooth.c can tell before emitting whether it fits; when it
 * does not, the frame is the coarse mesh (silk_frame_fall_back).
 */
#include <string.h>
#include "remesh.h"
#include "curve.h"

#define T_TWO_THIRDS ((silk_fx)43691)

static silk_sil_edge *edge_at(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    return silk_sil_side_edge(f, t, k);
}

/* Points on side k of t this frame. */
static uint32_t side_points(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    const silk_sil_edge *e = edge_at(f, t, k);
    return e ? e->nchain : 0;
}

/* The silhouette point side s puts on edge e: the one of its normal pair. */
static const silk_sil_pair *side_pair(const silk_sil_frame *f, const silk_sil_edge *e,
                                      const silk_sil_side *s)
{
    for (uint32_t i = 0; i < e->npairs; i++) {
        const silk_sil_pair *p = &f->pairs[e->pair0 + i];
        if (p->n0 == s->n0 && p->n1 == s->n1) return p;
    }
    return NULL;
}

static silk_vec3 mid3(silk_vec3 a, silk_vec3 b)
{
    return silk_v3(silk_fx_sat(((int64_t)a.x + b.x) / 2), silk_fx_sat(((int64_t)a.y + b.y) / 2),
                   silk_fx_sat(((int64_t)a.z + b.z) / 2));
}

/* The sample of segment s closest to the bisector plane of the base edge
 * b1 -> b2: joined to both base vertices it gives the fattest middle triangle. */
static uint32_t split_sample(const silk_sil_seg *s, silk_vec3 b1, silk_vec3 b2)
{
    silk_vec3 dir = silk_v3_sub(b2, b1), mid = mid3(b1, b2);
    uint32_t best = s->n / 2;
    int64_t best_d = INT64_MAX;
    for (uint32_t i = 0; i <= s->n; i++) {
        /* the ends are the curve's ends, bit for bit (eq. 5 at 0 and 1 is exact) */
        silk_vec3 p = i == 0 ? s->c.p0 : i == s->n ? s->c.p1 : silk_hermite_point(&s->c, silk_sample_param(i, s->n));
        int64_t d = silk_v3_dot64(silk_v3_sub(p, mid), dir);
        if (d < 0) d = -d;
        if (d < best_d) { best_d = d; best = i; }
    }
    return best;
}

/* Where things are on the boundary of silhouette triangle t, walked from L:
 * cyc = L, side L's points, B1, the base's points, B2, side L+2's points. */
typedef struct sil_layout {
    uint32_t len;            /* boundary length */
    uint32_t iA, iB;         /* the silhouette points */
    uint32_t iB1, iB2;       /* the base vertices */
    int centre1, centre2;    /* the part around L / along the base needs a centre */
} sil_layout;

/* Index, in the edge's chain, of the silhouette point side k of t puts
 * on its edge. */
static uint32_t pair_chain(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    const silk_sil_edge *e = edge_at(f, t, k);
    silk_sil_side s;
    silk_sil_side_attrs(f->m, t, k, silk_mesh_edge_v0(f->m, e->edge), &s);
    return silk_sil_chain_index(&f->chain[e->chain0], e->nchain, side_pair(f, e, &s)->u);
}

/* The same in triangle direction. */
static uint32_t pair_pos(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    const silk_sil_edge *e = edge_at(f, t, k);
    uint32_t c = pair_chain(f, t, k);
    return silk_mesh_corner(f->m, 3 * t + k) == silk_mesh_edge_v0(f->m, e->edge) ? c : e->nchain - 1 - c;
}

static void layout(const silk_sil_frame *f, uint32_t t, sil_layout *l)
{
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE;
    uint32_t kb = (lone + 1) % 3, k2 = (lone + 2) % 3;
    uint32_t na = side_points(f, t, lone), nb = side_points(f, t, kb), n2 = side_points(f, t, k2);
    l->iA = 1 + pair_pos(f, t, lone);
    l->iB1 = 1 + na;
    l->iB2 = 2 + na + nb;
    l->iB = 3 + na + nb + pair_pos(f, t, k2);
    l->len = 3 + na + nb + n2;
    /* a corner fan is safe only when no other point shares a side with the apex's part */
    l->centre1 = l->iA != 1 || l->iB != l->len - 1;
    l->centre2 = l->iA != l->iB1 - 1 || l->iB != l->iB2 + 1;
}

/* What one input triangle's share holds: its output triangles, records
 * and curves, and its boundary length. */
typedef struct tri_count {
    uint32_t tris, recs, curves, poly;
} tri_count;

/* seg: t's segment, or NULL; its layout also to *lk unless lk is NULL */
static void tri_cost(const silk_sil_frame *f, uint32_t t, const silk_sil_seg *seg, sil_layout *lk, tri_count *c)
{
    uint32_t sum = 0, nchained = 0;
    for (uint32_t k = 0; k < 3; k++) {
        uint32_t np = side_points(f, t, k);
        sum += np;
        nchained += np > 0;
    }
    /* the corners, the sides' points, one curve per side with points */
    c->poly = 3 + sum;
    c->recs = 3 + sum;
    c->curves = nchained;
    if (seg) {
        sil_layout l;
        layout(f, t, &l);
        if (SILK_KEEP_SEGMENTS && lk) *lk = l;
        uint32_t n = seg->n;
        c->recs += n - 1;
        c->curves++;
        c->tris = 2 * n;
        if (l.centre1) { c->tris += l.iA + l.len - l.iB; c->recs++; c->curves++; }
        if (l.centre2) { c->tris += l.iB - l.iA; c->recs++; c->curves++; }
        else c->tris += 1 + (l.iB2 - l.iB1 - 1);
        c->poly += n + 2;
    } else if (nchained == 1) {
        c->tris = sum + 1;
    } else if (nchained >= 2) {
        c->tris = sum + 3; c->recs++; c->curves++;
    } else {
        c->tris = 1;
    }
}

uint32_t silk_remesh_kept_index(const silk_sil_frame *f, uint32_t t)
{
    const silk_sil_keep *k = f->keep;
    if (!SILK_KEEP_SEGMENTS || !k) return SILK_SIL_NONE;
    uint32_t lo = 0, hi = k->nseg_kept, last = f->cur->kept_last;   /* (its memo, the cursor's) */
    if (!hi || k->seg_tri[hi - 1] < t) return SILK_SIL_NONE;   /* past them all: as the plan asks while it keeps them */
    /* the emitter and the outline ask in triangle order, each share a few times */
    if (last < hi && k->seg_tri[last] == t) return last;
    if (last + 1 < hi && k->seg_tri[last + 1] == t) lo = last + 1;
    else {
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (k->seg_tri[mid] < t) lo = mid + 1; else hi = mid;
        }
        if (lo >= k->nseg_kept || k->seg_tri[lo] != t) return SILK_SIL_NONE;
    }
    f->cur->kept_last = lo;
    return lo;
}

/* Triangle t's kept segment (silk_remesh_keep), or NULL. */
static const silk_sil_seg *seg_kept(const silk_sil_frame *f, uint32_t t)
{
    uint32_t i = silk_remesh_kept_index(f, t);
    return i == SILK_SIL_NONE ? NULL : &f->keep->seg_kept[i];
}

size_t silk_remesh_keep(silk_sil_frame *f, size_t room)
{
    silk_arena *a = f->a;
    silk_sil_keep *k = SILK_KEEP_SEGMENTS ? f->keep : NULL;
    if (!k) return 0;
    size_t free0 = silk_arena_free_bytes(a),
           want = 2 * (size_t)f->nedges * sizeof(silk_vec3) +
                  (size_t)f->nsil * (sizeof *k->seg_kept + sizeof *k->seg_tri + sizeof *k->lay_kept) + 4 * SILK_ARENA_ALIGN,
           pairs = (size_t)f->npairs * (2 * sizeof *f->cur->pair_pn + 1) + 2 * SILK_ARENA_ALIGN;
    if (!f->nsil || k->seg_kept || want > room || !silk_sil_keep_fits(want, free0)) return 0;
    size_t peak = a->top_peak;
    k->seg_kept = silk_arena_array_top_unfilled(a, f->nsil, sizeof *k->seg_kept, SILK_MEM_FRAME);   /* written as made */
    k->seg_tri = silk_arena_array_top(a, f->nsil, sizeof *k->seg_tri, SILK_MEM_FRAME);
    k->lay_kept = silk_arena_array_top_unfilled(a, f->nsil, sizeof *k->lay_kept, SILK_MEM_FRAME);   /* with seg_kept */
    if (!k->seg_kept || !k->seg_tri || !k->lay_kept || !silk_sil_keep_tangents(f, free0)) {   /* cannot happen: want fits */
        k->seg_kept = NULL;
        k->seg_tri = NULL;
        k->lay_kept = NULL;
    } else if (f->npairs && want + pairs <= room && silk_sil_keep_fits(want + pairs, free0)) {
        /* the silhouette points, each made once for the two segments that end on it */
        silk_sil_cursor *c = f->cur;   /* (filled as they are asked for: the cursor's) */
        c->pair_pn = silk_arena_array_top_unfilled(a, 2 * (size_t)f->npairs, sizeof *c->pair_pn, SILK_MEM_FRAME);
        c->pair_ready = silk_arena_array_top(a, f->npairs, 1, SILK_MEM_FRAME);   /* zeroed: none made */
        if (!c->pair_ready) c->pair_pn = NULL;
    }
    k->nseg_kept = 0;
    silk_sil_kept(f, free0, peak);
    return free0 - silk_arena_free_bytes(a);
}

int silk_remesh_seg(const silk_sil_frame *f, uint32_t t, silk_sil_seg *s)
{
    const silk_sil_seg *kept = seg_kept(f, t);
    if (kept) {
        *s = *kept;
        return 1;
    }
    const silk_mesh *m = f->m;
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE, kb = (lone + 2) % 3;
    const silk_sil_edge *ea = edge_at(f, t, lone), *eb = edge_at(f, t, kb);
    if (!ea || !eb) return 0;
    silk_sil_side sa, sb;
    silk_sil_side_attrs(m, t, lone, silk_mesh_edge_v0(m, ea->edge), &sa);
    silk_sil_side_attrs(m, t, kb, silk_mesh_edge_v0(m, eb->edge), &sb);
    const silk_sil_pair *pa = side_pair(f, ea, &sa), *pb = side_pair(f, eb, &sb);
    if (!pa || !pb) return 0;   /* cannot happen for a sane mesh */
    memset(s, 0, sizeof *s);
    s->tri = t;
    silk_vec3 A, B, nA, nB;
    if (SILK_KEEP_SEGMENTS) {   /* each point made once for the two segments that end on it, where kept */
        silk_sil_pair_point(f, ea, &sa, pa, &A, &nA, &s->c.uv0, &s->c.rgb0);
        silk_sil_pair_point(f, eb, &sb, pb, &B, &nB, &s->c.uv1, &s->c.rgb1);
    } else {
        silk_sil_edge_point(f, ea, &sa, pa->u, &A, &nA, &s->c.uv0, &s->c.rgb0);
        silk_sil_edge_point(f, eb, &sb, pb->u, &B, &nB, &s->c.uv1, &s->c.rgb1);
    }
    silk_bridge(A, nA, B, nB, silk_tilt_bound(m), &s->c);
    s->c.p0 = A;
    s->c.p1 = B;
    s->n = silk_sil_intervals(f->v, &s->c, silk_v3_dot(nA, nB), f->tol);
    if (s->n < 1) s->n = 1;
    s->split = split_sample(s, silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + (lone + 1) % 3)), silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + kb)));
    /* III-E: concave when N_A.F > 0 and N_B.F < 0, F = B - A */
    silk_vec3 F = silk_v3_sub(B, A);
    s->concave = silk_v3_dot64(nA, F) > 0 && silk_v3_dot64(nB, F) < 0;
    if (!s->concave) return 1;   /* the plane P_i is only a concave segment's (perturb.c) */
    s->m = silk_hermite_point(&s->c, SILK_FX_HALF);
    if (!silk_v3_normalize(silk_v3_lerp(nA, nB, SILK_FX_HALF), &s->nm)) s->concave = 0;
    s->rise = silk_fx_max(silk_fx_max(silk_v3_dot(silk_v3_sub(A, s->m), s->nm),
                                      silk_v3_dot(silk_v3_sub(B, s->m), s->nm)), 0);
    return 1;
}

silk_status silk_remesh_plan(silk_sil_frame *f)
{
    const silk_mesh *m = f->m;
    /* What the frame costs: the most one input triangle becomes (one
     * share, what a frame drawn share by share holds), all of them (a
     * stored frame), the perturbation's slots.  Segments (III-D) are made
     * here and again where they are needed; silhouette.c gave every
     * silhouette triangle the points its segment needs, and tri_state
     * only gains SILK_TS_CONCAVE here; it is only read from here on. */
    f->store_recs = 0;
    f->store_curves = 0;
    f->nsegs = 0;
    f->max_poly = 0;
    f->max_recs = 3;
    f->max_tris = 1;
    f->max_curves = 0;
    f->seg_samples = 0;
    f->out_tris = m->ntris;
    /* where the segments are kept as they are made (silk_remesh_keep), or NULL */
    silk_sil_keep *k = SILK_KEEP_SEGMENTS && f->keep && f->keep->seg_kept ? f->keep : NULL;
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (SILK_FAST_CASES && !(f->tri_state[t] & (SILK_TS_SIL | SILK_TS_CARRY))) {
            f->store_recs += 3;   /* most: as it is (tri_cost's three corners), written out */
            continue;
        }
        silk_sil_seg tmp, *s = NULL;
        if ((f->tri_state[t] & SILK_TS_SIL) && silk_remesh_seg(f, t, &tmp)) {
            s = &tmp;
            f->nsegs++;
            if (k && k->nseg_kept < f->nsil) {   /* ascending: t is past every kept one */
                k->seg_tri[k->nseg_kept] = t;
                k->seg_kept[k->nseg_kept++] = tmp;
            }
        }
        tri_count tc;
        int kept = k && s && k->nseg_kept && k->seg_tri[k->nseg_kept - 1] == t;
        tri_cost(f, t, s, kept ? &k->lay_kept[k->nseg_kept - 1] : NULL, &tc);
        if (kept) {
            k->kept_recs += tc.recs;
            k->kept_tris += tc.tris;
            k->kept_curves += tc.curves;
        }
        f->store_recs += tc.recs;
        f->store_curves += tc.curves;
        f->out_tris += tc.tris - 1;
        if (tc.poly == 3) continue;     /* as it is: three corners, one triangle */
        if (tc.poly > f->max_poly) f->max_poly = tc.poly;
        if (tc.recs > f->max_recs) f->max_recs = tc.recs;
        if (tc.tris > f->max_tris) f->max_tris = tc.tris;
        if (tc.curves > f->max_curves) f->max_curves = tc.curves;
        if (s) {
            f->seg_samples += s->n - 1;
            if (s->concave) f->tri_state[t] |= SILK_TS_CONCAVE;   /* perturb.c sizes its slots by them and rebuilds only these */
        }
    }
    return SILK_OK;
}

int silk_remesh_alloc(silk_sil_frame *f, silk_frame_geom *g, uint64_t recs, uint64_t tris, uint64_t curves)
{
    if (recs > UINT32_MAX || 3 * tris > UINT32_MAX || curves > UINT32_MAX) return 0;
    silk_arena *a = f->a;
    memset(g, 0, sizeof *g);
    g->vrec = silk_arena_array_top(a, (size_t)recs, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, (size_t)(3 * tris), sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, (size_t)tris, 1, SILK_MEM_FRAME);
    g->curve = silk_arena_array_top(a, (size_t)curves, sizeof *g->curve, SILK_MEM_FRAME);
    f->poly = silk_arena_array_top(a, 2 * (size_t)f->max_poly, sizeof *f->poly, SILK_MEM_FRAME);
    return g->vrec && g->tri && g->tri_added && g->curve && f->poly;
}

/* ---- emission ------------------------------------------------------------------ */

static void put_tri(silk_frame_geom *g, uint32_t a, uint32_t b, uint32_t c, uint8_t added)
{
    uint32_t *p = &g->tri[3 * g->ntri];
    p[0] = a; p[1] = b; p[2] = c;
    g->tri_added[g->ntri++] = added;
}

/* Triangles (apex, list[j], list[j+1]): a fan over a boundary chain. */
static void fan(silk_frame_geom *g, uint32_t apex, const uint32_t *list, uint32_t n)
{
    for (uint32_t j = 0; j + 1 < n; j++) put_tri(g, apex, list[j], list[j + 1], 1);
}

static uint32_t put_curve_rec(silk_frame_geom *g, uint32_t curve, silk_fx t)
{
    silk_vrec *r = &g->vrec[g->nvrec];
    r->kind = SILK_VREC_CURVE;
    r->a = curve;
    r->b = 0;
    r->t = t;
    return g->nvrec++;
}

/* The record of corner c: CORNER, or MOVED when perturbation moved its
 * vertex (every corner at the vertex gets the same offset, so the vertex
 * moves as one). */
static uint32_t put_corner(const silk_sil_frame *f, silk_frame_geom *g, uint32_t c)
{
    silk_vrec *r = &g->vrec[g->nvrec];
    silk_plan_index off = f->vert_offset ? f->vert_offset[silk_mesh_corner(f->m, c)] : SILK_PLAN_NONE;
    r->kind = off == SILK_PLAN_NONE ? SILK_VREC_CORNER : SILK_VREC_MOVED;
    r->a = c;
    r->b = off == SILK_PLAN_NONE ? 0 : off;
    r->t = 0;
    return g->nvrec++;
}

/* The curve of side s's points: the edge's, with the side's normals and uvs. */
static void side_curve(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s, silk_curve *c)
{
    const silk_mesh *m = f->m;
    silk_sil_edge_curve(f, e, c);
    c->n0 = silk_mesh_normal(m, s->n0);
    c->n1 = silk_mesh_normal(m, s->n1);
    if (s->uv0 != SILK_PLAN_NONE && s->uv0 < m->nuvs && s->uv1 < m->nuvs) {
        c->uv0 = m->uv[s->uv0];
        c->uv1 = m->uv[s->uv1];
    }
    silk_index ev[2] = { 0, 0 };
    if (m->color) silk_mesh_edge_ends(m, e->edge, ev);
    c->rgb0 = m->color ? m->color[ev[0]] : 0xffffff;
    c->rgb1 = m->color ? m->color[ev[1]] : 0xffffff;
}

/* Append side k of t (its chain, in the triangle's direction) to out:
 * this triangle's own copy of the side's curve and of its records, in
 * chain order.  The triangle across the edge makes its own copy from the
 * same chain, so both evaluate to the same bits. */
static uint32_t walk_side(const silk_sil_frame *f, silk_frame_geom *g, uint32_t t, uint32_t k, uint32_t *out)
{
    uint32_t n = side_points(f, t, k);
    if (!n) return 0;
    const silk_sil_edge *e = edge_at(f, t, k);
    silk_sil_side s;
    silk_sil_side_attrs(f->m, t, k, silk_mesh_edge_v0(f->m, e->edge), &s);
    side_curve(f, e, &s, &g->curve[g->ncurve]);
    uint32_t rec = g->nvrec;
    for (uint32_t j = 0; j < n; j++) put_curve_rec(g, g->ncurve, f->chain[e->chain0 + j]);
    g->ncurve++;
    int fwd = silk_mesh_corner(f->m, 3 * t + k) == silk_mesh_edge_v0(f->m, e->edge);
    for (uint32_t j = 0; j < n; j++) out[j] = fwd ? rec + j : rec + n - 1 - j;
    return n;
}

/* The corner triangle t's boundary walk starts at: L for a silhouette
 * triangle, the corner opposite the only side with points, else corner 0. */
static uint32_t first_corner(const silk_sil_frame *f, uint32_t t)
{
    if (f->tri_state[t] & SILK_TS_SIL) return f->tri_state[t] & SILK_TS_LONE;
    uint32_t nchained = 0, only = 0;
    for (uint32_t k = 0; k < 3; k++)
        if (side_points(f, t, k)) { nchained++; only = k; }
    return nchained == 1 ? (only + 2) % 3 : 0;
}

/* The boundary of t into cyc from its first corner: each corner's record,
 * then its side's chain; returns the length. */
static uint32_t walk_boundary(const silk_sil_frame *f, silk_frame_geom *g, uint32_t t, uint32_t *cyc)
{
    uint32_t k0 = first_corner(f, t), len = 0;
    for (uint32_t i = 0; i < 3; i++) {
        uint32_t k = (k0 + i) % 3;
        cyc[len++] = put_corner(f, g, 3 * t + k);
        len += walk_side(f, g, t, k, &cyc[len]);
    }
    return len;
}

uint32_t silk_remesh_corner_rec(const silk_sil_frame *f, uint32_t t, uint32_t k, uint32_t base)
{
    uint32_t k0 = first_corner(f, t);
    for (uint32_t i = 0; (k0 + i) % 3 != k; i++) base += 1 + side_points(f, t, (k0 + i) % 3);
    return base;
}

static silk_vec2 mid2(silk_vec2 a, silk_vec2 b)
{
    silk_vec2 r = { silk_fx_sat(((int64_t)a.x + b.x) / 2), silk_fx_sat(((int64_t)a.y + b.y) / 2) };
    return r;
}

static silk_vec3 mean_normal(silk_vec3 a, silk_vec3 b)
{
    silk_vec3 r;
    return silk_v3_normalize(silk_v3_add(a, b), &r) ? r : a;
}

/* A new vertex t along the straight line p0 -> p1 (a Hermite curve with
 * both tangents equal to the chord is exactly linear), normal and uv
 * interpolated linearly: the centres of Fig. 12b. */
static uint32_t put_centre(silk_frame_geom *g, silk_vec3 p0, silk_vec3 n0, silk_vec2 uv0, uint32_t rgb0,
                           silk_vec3 p1, silk_vec3 n1, silk_vec2 uv1, uint32_t rgb1, silk_fx t)
{
    silk_curve *c = &g->curve[g->ncurve];
    c->p0 = p0; c->n0 = n0; c->uv0 = uv0; c->rgb0 = rgb0;
    c->p1 = p1; c->n1 = n1; c->uv1 = uv1; c->rgb1 = rgb1;
    c->t0 = c->t1 = silk_v3_sub(p1, p0);
    return put_curve_rec(g, g->ncurve++, t);
}

static void corner_attrs(const silk_mesh *m, uint32_t c, silk_vec3 *p, silk_vec3 *n, silk_vec2 *uv, uint32_t *rgb)
{
    *p = silk_mesh_pos(m, silk_mesh_corner(m, c));
    *rgb = m->color ? m->color[silk_mesh_corner(m, c)] : 0xffffff;
    *n = silk_mesh_normal(m, silk_mesh_corner_normal(m, c));
    uv->x = uv->y = 0;
    if (m->tri_uv && m->uv && m->tri_uv[c] < m->nuvs) *uv = m->uv[m->tri_uv[c]];
}

/* A closed fan: (apex, cyc[j], cyc[j+1 mod n]) for every boundary edge. */
static void fan_closed(silk_frame_geom *g, uint32_t apex, const uint32_t *cyc, uint32_t n)
{
    for (uint32_t j = 0; j < n; j++) put_tri(g, apex, cyc[j], cyc[(j + 1) % n], 1);
}

/* Fig. 11: the silhouette triangle cut by its segment s, laid out as lp
 * says (NULL: laid out here). */
static void emit_silhouette(const silk_sil_frame *f, silk_frame_geom *g, uint32_t t, const silk_sil_seg *s,
                            const sil_layout *lp)
{
    const silk_mesh *m = f->m;
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE;
    uint32_t *cyc = f->poly, *list = f->poly + f->max_poly;
    sil_layout l;
    if (SILK_KEEP_SEGMENTS && lp) l = *lp;
    else layout(f, t, &l);
    walk_boundary(f, g, t, cyc);

    /* the segment: interior samples as records on its own curve */
    uint32_t curve = g->ncurve++, rec = g->nvrec;
    g->curve[curve] = s->c;
    for (uint32_t i = 1; i < s->n; i++) put_curve_rec(g, curve, silk_sample_param(i, s->n));
#define SAMPLE(i) ((i) == 0 ? cyc[l.iA] : (i) == s->n ? cyc[l.iB] : rec + (i) - 1)

    /* around L: L, side L up to A, the samples, B and side L+2 back to L */
    uint32_t n = 0;
    if (l.centre1) list[n++] = cyc[0];
    for (uint32_t j = 1; j <= l.iA; j++) list[n++] = cyc[j];
    for (uint32_t i = 1; i < s->n; i++) list[n++] = SAMPLE(i);
    for (uint32_t j = l.iB; j < l.len; j++) list[n++] = cyc[j];
    /* the midpoint of A B, for a centre (only where one is made, where the
     * usual cases are written out: most segments of a fine mesh need none;
     * a board keeps the code bytes) */
    silk_vec3 pl, nl, pab, nab;
    silk_vec2 uvl, uvab;
    uint32_t rgbl, rgbab = 0;
    if (!SILK_FAST_CASES || l.centre1 || l.centre2) {
        pab = mid3(s->c.p0, s->c.p1);
        nab = mean_normal(s->c.n0, s->c.n1);
        uvab = mid2(s->c.uv0, s->c.uv1);
        rgbab = silk_rgb_lerp(s->c.rgb0, s->c.rgb1, SILK_FX_HALF);
    }
    if (l.centre1) {
        corner_attrs(m, 3 * t + lone, &pl, &nl, &uvl, &rgbl);
        fan_closed(g, put_centre(g, pl, nl, uvl, rgbl, pab, nab, uvab, rgbab, T_TWO_THIRDS), list, n);
    } else {
        fan(g, cyc[0], list, n);
    }

    if (l.centre2) {
        /* A .. B1 .. B2 .. B along the sides, then the samples back to A */
        n = 0;
        for (uint32_t j = l.iA; j <= l.iB; j++) list[n++] = cyc[j];
        for (uint32_t i = s->n - 1; i > 0; i--) list[n++] = SAMPLE(i);
        silk_vec3 p1, n1, p2, n2;
        silk_vec2 uv1, uv2;
        uint32_t rgb1, rgb2;
        corner_attrs(m, 3 * t + (lone + 1) % 3, &p1, &n1, &uv1, &rgb1);
        corner_attrs(m, 3 * t + (lone + 2) % 3, &p2, &n2, &uv2, &rgb2);
        fan_closed(g, put_centre(g, pab, nab, uvab, rgbab, mid3(p1, p2), mean_normal(n1, n2), mid2(uv1, uv2),
                                 silk_rgb_lerp(rgb1, rgb2, SILK_FX_HALF), SILK_FX_HALF), list, n);
    } else {
        /* samples 0..split to B1, split..n to B2, the split sample to the base */
        uint32_t ks = s->split;
        n = 0;
        for (uint32_t i = ks; i > 0; i--) list[n++] = SAMPLE(i);
        list[n++] = SAMPLE(0);
        fan(g, cyc[l.iB1], list, n);
        n = 0;
        for (uint32_t j = l.iB1; j <= l.iB2; j++) list[n++] = cyc[j];
        fan(g, SAMPLE(ks), list, n);
        n = 0;
        for (uint32_t i = s->n; i > ks; i--) list[n++] = SAMPLE(i);
        list[n++] = SAMPLE(ks);
        fan(g, cyc[l.iB2], list, n);
    }
#undef SAMPLE
}

void silk_remesh_emit_tri(const silk_sil_frame *f, silk_frame_geom *g, uint32_t t)
{
    silk_sil_seg seg;
    g->offset = f->offset;
    g->noffset = f->noffset;
    if (SILK_FAST_CASES && !(f->tri_state[t] & (SILK_TS_SIL | SILK_TS_CARRY))) {
        /* most triangles, as they are: put_corner's three records written
         * out (a small part keeps the code bytes) */
        silk_vrec *r = &g->vrec[g->nvrec];
        const silk_plan_index *vo = f->vert_offset;
        uint32_t n = g->nvrec;
        for (uint32_t k = 0; k < 3; k++) {
            silk_plan_index off = vo ? vo[silk_mesh_corner(f->m, 3 * t + k)] : SILK_PLAN_NONE;
            r[k].kind = off == SILK_PLAN_NONE ? SILK_VREC_CORNER : SILK_VREC_MOVED;
            r[k].a = 3 * t + k;
            r[k].b = off == SILK_PLAN_NONE ? 0 : off;
            r[k].t = 0;
        }
        g->nvrec = n + 3;
        put_tri(g, n, n + 1, n + 2, 0);
        return;
    }
    if (f->tri_state[t] & SILK_TS_SIL) {
        uint32_t i = silk_remesh_kept_index(f, t);   /* as the plan made it and laid it out */
        if (i != SILK_SIL_NONE) {
            emit_silhouette(f, g, t, &f->keep->seg_kept[i], &f->keep->lay_kept[i]);   /* Fig. 11 */
            return;
        }
        if (silk_remesh_seg(f, t, &seg)) {
            emit_silhouette(f, g, t, &seg, NULL);     /* Fig. 11 */
            return;
        }
    }
    uint32_t nchained = 0;
    if (!SILK_FAST_CASES || (f->tri_state[t] & SILK_TS_CARRY))   /* (the same shortcut) */
        for (uint32_t k = 0; k < 3; k++) nchained += side_points(f, t, k) > 0;
    if (nchained == 0) {                            /* as it is: what walk_boundary gives, directly */
        uint32_t c0 = put_corner(f, g, 3 * t), c1 = put_corner(f, g, 3 * t + 1);
        put_tri(g, c0, c1, put_corner(f, g, 3 * t + 2), 0);
        return;
    }
    uint32_t *cyc = f->poly;
    uint32_t len = walk_boundary(f, g, t, cyc);
    /* Fig. 12a: from the opposite vertex over the only side with points */
    if (nchained == 1) {
        fan(g, cyc[0], cyc + 1, len - 1);
        return;
    }
    /* Fig. 12b: from the centre, two thirds along from corner 0 to the
     * midpoint of the opposite side, so position, normal and uv are the
     * corners' average */
    silk_vec3 p[3], n[3];
    silk_vec2 uv[3];
    uint32_t rgb[3];
    for (uint32_t k = 0; k < 3; k++) corner_attrs(f->m, 3 * t + k, &p[k], &n[k], &uv[k], &rgb[k]);
    fan_closed(g, put_centre(g, p[0], n[0], uv[0], rgb[0], mid3(p[1], p[2]), mean_normal(n[1], n[2]),
                             mid2(uv[1], uv[2]), silk_rgb_lerp(rgb[1], rgb[2], SILK_FX_HALF), T_TWO_THIRDS),
               cyc, len);
}

int silk_remesh_store(silk_sil_frame *f, silk_frame_geom *g)
{
    uint32_t n = f->m->ntris;
    if (!silk_remesh_alloc(f, g, f->store_recs, f->out_tris, f->store_curves)) return 0;
    g->part_rec = silk_arena_array_top(f->a, (size_t)n + 1, sizeof *g->part_rec, SILK_MEM_FRAME);
    if (!g->part_rec) return 0;
    for (uint32_t t = 0; t < n; t++) {
        g->part_rec[t] = g->nvrec;
        silk_remesh_emit_tri(f, g, t);
    }
    g->part_rec[n] = g->nvrec;
    return 1;
}

/* The silhouette point side k of t puts on its edge, or NULL. */
static const silk_sil_pair *side_pair_of(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    const silk_sil_edge *e = edge_at(f, t, k);
    silk_sil_side s;
    if (!e) return NULL;
    silk_sil_side_attrs(f->m, t, k, silk_mesh_edge_v0(f->m, e->edge), &s);
    return side_pair(f, e, &s);
}

/* The share's boundary starts at L (first_corner), L's side first: its
 * chain follows L's record, then B1's record and the base's chain, then
 * B2's record (L+2's corner) and L+2's chain, then the samples. */
static void seg_recs(const silk_sil_frame *f, uint32_t t, uint32_t base, const silk_fx u[2], uint32_t rec[3])
{
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE, k2 = (lone + 2) % 3;
    const silk_sil_edge *ea = edge_at(f, t, lone), *eb = edge_at(f, t, k2);
    uint32_t c2 = base + 2 + ea->nchain + side_points(f, t, (lone + 1) % 3);
    rec[0] = base + 1 + silk_sil_chain_index(&f->chain[ea->chain0], ea->nchain, u[0]);
    rec[1] = c2 + 1 + silk_sil_chain_index(&f->chain[eb->chain0], eb->nchain, u[1]);
    rec[2] = c2 + 1 + eb->nchain;
}

void silk_remesh_seg_recs(const silk_sil_frame *f, uint32_t t, uint32_t base, uint32_t rec[3])
{
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE;
    silk_fx u[2] = { side_pair_of(f, t, lone)->u, side_pair_of(f, t, (lone + 2) % 3)->u };
    seg_recs(f, t, base, u, rec);
}

/* The index in side k's chain of the point at position pos of the side's
 * n, in triangle direction (pair_pos the other way round). */
static uint32_t chain_at(const silk_sil_frame *f, uint32_t t, uint32_t k, uint32_t pos, uint32_t n)
{
    const silk_sil_edge *e = edge_at(f, t, k);
    return silk_mesh_corner(f->m, 3 * t + k) == silk_mesh_edge_v0(f->m, e->edge) ? pos : n - 1 - pos;
}

int silk_remesh_seg_at(const silk_sil_frame *f, uint32_t t, uint32_t rec[3], uint32_t *curve)
{
    uint32_t i = silk_remesh_kept_index(f, t);
    if (i != SILK_SIL_NONE) {   /* what seg_recs finds, from where the plan laid the points out */
        const sil_layout *l = &f->keep->lay_kept[i];
        uint32_t lone = f->tri_state[t] & SILK_TS_LONE;
        uint32_t na = l->iB1 - 1, nb = l->iB2 - l->iB1 - 1, n2 = l->len - l->iB2 - 1;
        rec[0] = 1 + chain_at(f, t, lone, l->iA - 1, na);
        rec[1] = l->iB2 + 1 + chain_at(f, t, (lone + 2) % 3, l->iB - l->iB2 - 1, n2);
        rec[2] = l->len;
        *curve = (na > 0) + (nb > 0) + (n2 > 0);
        return 1;
    }
    /* what silk_remesh_seg needs before it builds anything: both silhouette points */
    uint32_t lone = f->tri_state[t] & SILK_TS_LONE;
    const silk_sil_pair *pa = side_pair_of(f, t, lone), *pb = side_pair_of(f, t, (lone + 2) % 3);
    if (!pa || !pb) return 0;
    silk_fx u[2] = { pa->u, pb->u };
    seg_recs(f, t, 0, u, rec);
    *curve = 0;
    for (uint32_t k = 0; k < 3; k++) *curve += side_points(f, t, k) > 0;   /* walk_side: a curve per side with points */
    return 1;
}

void silk_remesh_stats(const silk_sil_frame *f, silk_frame_stats *stats)
{
    if (!stats) return;
    uint32_t bridges = 0, samples = f->seg_samples;
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        if (!e->nchain) continue;
        bridges += e->npairs;
        samples += e->nchain;
    }
    stats->silhouette_tris = f->nsil;
    stats->bridges = bridges;
    stats->samples = samples;
    stats->tris_drawn = f->out_tris;
    stats->moved_vertices = f->noffset;
    stats->flat_segments = f->flat_segs;
}
