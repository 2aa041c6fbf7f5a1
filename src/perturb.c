/*
 * perturb.c - vertex perturbation against silhouette blocking (paper III-E,
 * Figs. 14 and 15).
 *
 * A concave silhouette segment S_i (N_A.F > 0 and N_B.F < 0, F = B - A) runs
 * inside the coarse mesh, so the triangles around it hide it and the
 * silhouette stays polygonal (the inner rim of a torus).  Its mid point
 * M_i = S_i(1/2) and the normal N_i there define a plane P_i that contains the
 * view direction, with the segment above it.  Every neighbouring vertex V (a
 * corner of the silhouette triangle, or one edge away from a corner) is
 * lowered along R^ = normalise(sum of the N_i of the concave segments it
 * neighbours) until it is below all their planes:
 *
 *     s = max_i ( (V - M_i).N_i / (R^.N_i) ),   V' = V - s R^   when s > 0.
 *
 * The paper prints l = max_i { -(V - M_i).N_i / (R^.N_i) }, V' = V + l R^;
 * taken literally that satisfies only the plane needing the least motion (and
 * moves V up when it is already below one), so the sign is turned here into
 * what the text asks for: the largest motion needed, downwards.
 *
 * Guards the paper does not have.  A plane nearly parallel to R^
 * (R^.N_i < 1/4) is skipped rather than divided by.  A plane constrains only
 * the vertices beside its segment: those whose projection onto the
 * segment's chord on screen falls within it or a quarter of it past its
 * ends, and that stand out beyond the chord by no more than twice the
 * segment's own sagitta there (the coarse polygon around the concave curve
 * it approximates; a vertex further out is the surface going on beyond
 * the curve, which dragon-500 prepared with --fit showed cut 10 px deep
 * when lowered).  The plane is the segment's
 * tangent plane at M_i, and an outline that goes on curving beyond the
 * segment's ends rises above it: the plain rule lowered the vertices along
 * the outline far beyond the segment, which cannot hide it, and cut notches
 * into the outline there (bunny-500's ears seen from below, 11 px at
 * 320x240).  And a vertex that would have to move further than the
 * segment's rise (how far its ends lie above P_i: the depth by which the
 * coarse triangles stick out over a concave curve they approximate) is
 * another part of the surface standing in front of the segment - the far
 * sheet of a thin ear, a tail curled over the body - which hides it as the
 * detailed model would: it stays where it is, and the segment stays hidden
 * (capping the move instead tore holes into feline's tail).  On a coarse,
 * strongly curved mesh the plain rule pushed vertices of knot-480 through
 * the tube's far side; no vertex moves more than a rise now.
 *
 * The result is one offset per moved vertex; every corner at that vertex
 * becomes a MOVED record with it, so the vertex moves as one.
 */
#include <string.h>
#include "perturb.h"
#include "remesh.h"

#define MIN_COS ((int64_t)1 << 30)     /* 1/4 in Q32.32 */

static void visit_near(silk_sil_frame *f, uint32_t t, const silk_sil_seg *s, uint32_t stamp, int pass);

int silk_perturb_alloc(silk_sil_frame *f)
{
    silk_arena *a = f->a;
    const silk_mesh *m = f->m;
    f->vert_slot = f->vert_offset = NULL;
    f->offset = NULL;
    f->noffset = f->nslots = f->near_bound = 0;
    uint32_t t = 0;
    /* every segment kept, in triangle order (silk_remesh_keep): the concave
     * ones read from there, not sought among every triangle */
    const silk_sil_keep *k = f->keep;
    int listed = SILK_KEEP_SEGMENTS && k && k->seg_kept && k->nseg_kept == f->nsegs;
    uint32_t j = 0;
    if (listed) {
        while (j < k->nseg_kept && !k->seg_kept[j].concave) j++;
        if (j == k->nseg_kept) return 1;   /* no concave segment: nothing moves */
        f->vert_slot = silk_arena_array_top_unfilled(a, m->nverts, sizeof *f->vert_slot, SILK_MEM_FRAME);   /* set below */
    } else {
        for (t = 0; t < m->ntris && !(f->tri_state[t] & SILK_TS_CONCAVE); t++) continue;
        if (t == m->ntris) return 1;   /* no concave segment: nothing moves */
        f->vert_slot = silk_arena_array_top(a, m->nverts, sizeof *f->vert_slot, SILK_MEM_FRAME);
    }
    if (!f->vert_slot) return 0;
    /* Exactly the vertices visit_near will visit: one slot each. */
    memset(f->vert_slot, 0xFF, (size_t)m->nverts * sizeof *f->vert_slot);   /* SILK_PLAN_NONE */
    if (listed) {
        for (; j < k->nseg_kept; j++)
            if (k->seg_kept[j].concave) visit_near(f, k->seg_tri[j], NULL, 0, -1);
    } else {
        for (; t < m->ntris; t++)
            if (f->tri_state[t] & SILK_TS_CONCAVE) visit_near(f, t, NULL, 0, -1);
    }
    memset(f->vert_slot, 0xFF, (size_t)m->nverts * sizeof *f->vert_slot);
    uint32_t b = f->near_bound = f->nslots;
    f->nslots = 0;
    f->acc = silk_arena_array_top(a, b, sizeof *f->acc, SILK_MEM_FRAME);
    /* the offsets are written over acc (offset j from slot j or a later one) */
    f->offset = f->acc;
    return f->acc != NULL;
}

/* Whether p lies beside segment s: its projection onto the segment's chord
 * on screen falls within the chord or a quarter of it past either end
 * (where the corners at the segment's ends lie), and it stands out beyond
 * the chord, away from the segment's middle, by no more than SAG_CAP
 * times the middle's distance from the chord.  In eighths of a pixel, so
 * that the products fit 32 bits: a point more than 1024 px from the
 * segment's start is not beside it. */
#define SAG_CAP 2
#define PT_MAX (1 << 13)   /* 2 PT_MAX = 2^14: the range test below */
static int beside(silk_sil_frame *f, const silk_sil_seg *s, silk_vec3 p)
{
    /* from A on screen, in eighths of a pixel: B (the chord), p, the middle M */
    const silk_vec3 *pts[4] = { &s->c.p0, &s->c.p1, &p, &s->m };
    int32_t x[4], y[4];
    for (int i = 0; i < 4; i++) {
        silk_vec2 q;
        if (!silk_view_project(f->v, *pts[i], &q)) return 0;
        x[i] = (q.x >> 13) - (i ? x[0] : 0);
        y[i] = (q.y >> 13) - (i ? y[0] : 0);
        if (i && ((uint32_t)(x[i] + PT_MAX) | (uint32_t)(y[i] + PT_MAX)) >> 14) return 0;   /* beyond +-2^13 */
    }
    int32_t d = x[1] * x[2] + y[1] * y[2], l = (int32_t)((uint32_t)(x[1] * x[1] + y[1] * y[1]) >> 2);
    int32_t cq = x[1] * y[2] - y[1] * x[2], cm = x[1] * y[3] - y[1] * x[3];
    /* out <= SAG_CAP |cm|, out = cq on the side away from M: cq + SAG_CAP cm on M's side */
    int in = (uint32_t)(d + l) <= (uint32_t)(6 * l);   /* -l <= d <= 5 l */
    if (in && ((cq + SAG_CAP * cm) ^ cm) < 0) f->refused = 1;   /* left standing in front: counted */
    return in && ((cq + SAG_CAP * cm) ^ cm) >= 0;
}

/* One neighbouring vertex of segment s, once per stamp.  Pass -1 only
 * counts the vertices (nslots), marking them in vert_slot. */
static void visit(silk_sil_frame *f, silk_index vtx, const silk_sil_seg *s, uint32_t stamp, int pass)
{
    uint32_t sl = f->vert_slot[vtx];
    if (pass < 0) {
        if (sl == SILK_PLAN_NONE) f->nslots++;
        f->vert_slot[vtx] = 0;
        return;
    }
    if (sl == SILK_PLAN_NONE) {
        if (f->nslots >= f->near_bound) return;   /* cannot happen: the bound counts every visit */
        sl = f->nslots++;
        f->vert_slot[vtx] = (silk_plan_index)sl;  /* < near_bound <= nverts */
        f->slot_vert[sl] = (silk_plan_index)vtx;
        f->acc[sl] = silk_v3(0, 0, 0);
        f->lift[sl] = 0;
        f->slot_stamp[sl] = 0;
    }
    if (f->slot_stamp[sl] == stamp) return;
    f->slot_stamp[sl] = stamp;
    if (pass == 0) {
        f->acc[sl] = silk_v3_add(f->acc[sl], s->nm);
        return;
    }
    int64_t den = silk_v3_dot64(f->acc[sl], s->nm);
    if (den < MIN_COS) return;
    int64_t num = silk_v3_dot64(silk_v3_sub(silk_mesh_pos(f->m, vtx), s->m), s->nm);
    if (num <= 0 || !beside(f, s, silk_mesh_pos(f->m, vtx))) return;   /* already below P_i, or not in its way */
    /* num < 2^46 for model coordinates within SILK_COORD_MAX: the shift fits */
    silk_fx lift = silk_fx_sat((num << 16) / den);
    if (lift <= s->rise && lift > f->lift[sl]) f->lift[sl] = lift;   /* beyond a rise: not the segment's (above) */
    if (lift > s->rise) f->refused = 1;
}

/* visit() for triangle t's corners and every vertex one edge away. */
static void visit_near(silk_sil_frame *f, uint32_t t, const silk_sil_seg *s, uint32_t stamp, int pass)
{
    const silk_mesh *m = f->m;
    for (int c = 0; c < 3; c++) {
        silk_index vtx = silk_mesh_corner(m, 3 * t + c);
        visit(f, vtx, s, stamp, pass);
        silk_mesh_ring r;
        for (silk_index e = silk_mesh_ring_first(m, vtx, &r); e != SILK_NO_INDEX; e = silk_mesh_ring_next(m, &r)) {
            silk_index ev[2];
            silk_mesh_edge_ends(m, e, ev);
            visit(f, ev[0] == vtx ? ev[1] : ev[0], s, stamp, pass);
        }
    }
}

/* Whether a point on one of vtx's edges lies exactly at vtx (the silhouette
 * passes through the vertex, or so close to it that the point rounds onto
 * it).  That point is a record on its edge's curve, at the vertex's original
 * position, so moving the vertex would stretch zero-area triangles between
 * the two into overlapping slivers; the vertex stays. */
static int silhouette_at(const silk_sil_frame *f, silk_index vtx)
{
    const silk_mesh *m = f->m;
    silk_vec3 p = silk_mesh_pos(m, vtx);
    silk_mesh_ring r;
    for (silk_index e = silk_mesh_ring_first(m, vtx, &r); e != SILK_NO_INDEX; e = silk_mesh_ring_next(m, &r)) {
        if (!silk_sil_chained(f, e)) continue;
        const silk_sil_edge *w = &f->edges[silk_sil_slot(f, e)];
        /* the chain's point nearest vtx */
        silk_fx t = silk_mesh_edge_v0(m, e) == vtx ? f->chain[w->chain0] : f->chain[w->chain0 + w->nchain - 1];
        silk_curve c;
        silk_sil_edge_curve(f, w, &c);
        silk_vec3 q = silk_hermite_point(&c, t);
        if (q.x == p.x && q.y == p.y && q.z == p.z) return 1;
    }
    return 0;
}

int silk_perturb(silk_sil_frame *f)
{
    if (!f->near_bound) return 1;
    /* The slots' lifts, vertices and stamps are needed only here: taken
     * above the offsets and given back, so the frame keeps 12 bytes a slot
     * (acc, then the offsets) instead of 22. */
    silk_arena *a = f->a;
    silk_arena_mark mark = silk_arena_top_mark(a);
    uint32_t b = f->near_bound;
    f->lift = silk_arena_array_top(a, b, sizeof *f->lift, SILK_MEM_FRAME);
    f->slot_vert = silk_arena_array_top(a, b, sizeof *f->slot_vert, SILK_MEM_FRAME);
    f->slot_stamp = silk_arena_array_top(a, b, sizeof *f->slot_stamp, SILK_MEM_FRAME);
    if (!f->lift || !f->slot_vert || !f->slot_stamp) return 0;
    uint32_t ns = f->nsegs;
    const silk_sil_keep *k = f->keep;
    for (int pass = 0; pass < 2; pass++) {
        if (SILK_KEEP_SEGMENTS && k && k->seg_kept && k->nseg_kept == ns) {
            /* every segment kept, in triangle order (silk_remesh_keep): the
             * concave ones read from there, not sought among every triangle */
            for (uint32_t j = 0; j < ns; j++) {
                if (!k->seg_kept[j].concave) continue;
                f->refused = 0;
                visit_near(f, k->seg_tri[j], &k->seg_kept[j], pass * ns + j + 1, pass);
                f->flat_segs += f->refused;
            }
        } else {
            /* the segments in triangle order */
            for (uint32_t t = 0, i = 0; t < f->m->ntris && i < ns; t++) {
                if (!(f->tri_state[t] & SILK_TS_SIL)) continue;
                i++;
                silk_sil_seg tmp;   /* rebuilt only where the plan found it concave */
                const silk_sil_seg *s = (f->tri_state[t] & SILK_TS_CONCAVE) && silk_remesh_seg(f, t, &tmp) ? &tmp : NULL;
                if (!s || !s->concave) continue;
                f->refused = 0;
                visit_near(f, t, s, pass * ns + i, pass);
                f->flat_segs += f->refused;
            }
        }
        if (pass == 0)
            for (uint32_t sl = 0; sl < f->nslots; sl++)
                if (!silk_v3_normalize(f->acc[sl], &f->acc[sl])) f->acc[sl] = silk_v3(0, 0, 0);
    }
    /* From here on vert_slot maps a vertex to its offset. */
    for (uint32_t sl = 0; sl < f->nslots; sl++) {
        silk_index vtx = f->slot_vert[sl];
        if (f->lift[sl] > 0 && !silhouette_at(f, vtx)) {
            /* silk_v3_scale(acc, -lift) by components, noffset <= sl */
            const silk_fx *r = &f->acc[sl].x;
            silk_fx *o = &f->offset[f->noffset].x;
            for (int c = 0; c < 3; c++) o[c] = silk_fx_sat(silk_shr_round64((int64_t)r[c] * -f->lift[sl], 16));
            f->vert_slot[vtx] = (silk_plan_index)f->noffset++;
        } else {
            f->vert_slot[vtx] = SILK_PLAN_NONE;
        }
    }
    f->vert_offset = f->vert_slot;
    silk_arena_top_release(a, &mark);
    f->lift = NULL;
    f->slot_vert = NULL;
    f->slot_stamp = NULL;
    return 1;
}
