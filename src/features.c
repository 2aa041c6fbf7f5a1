/*
 * features.c - feature segments (paper section III-A): the Hermite end
 * tangents of every feature edge, computed once at load.
 *
 * Feature edges are chained into maximal feature polylines V0..Vk, which
 * end where a vertex has other than two feature edges (or close on
 * themselves), and also where the polyline turns by more than
 * SILK_FEATURE_TURN_DEG: such a vertex is a corner of the feature curve
 * (fandisk's concave arc meeting a straight edge, a zig-zag of creases on a
 * coarse scan), and a circle through a corner overshoots into a loop.  At an inner vertex the tangent direction is that of the
 * circle through Vi-1, Vi, Vi+1 (eq. 1, with W0 = Vi - Vi-1, W1 = Vi+1 - Vi
 * taken as unit directions, see inner_dir); at an end it is the tangent of
 * the circle through the first (last) three vertices.  Lengths follow eq. 4
 * (silk_arc_tangent), so a polyline sampled from a circle gives Hermite
 * segments that stay on the circle.  A polyline of one edge stays straight.
 */
#include "mesh_build.h"
#include "curve.h"

static silk_status nomem(silk_error *err, const char *name, const silk_arena *a)
{
    return silk_fail(err, SILK_ERR_NOMEM, name, 0,
                     "out of arena memory for the feature segments (%lu bytes requested, %lu free)",
                     (unsigned long)a->failed_request, (unsigned long)silk_arena_free_bytes(a));
}

static int is_feature(const silk_edge *e) { return silk_edge_has_feature(e); }

silk_index silk_mesh_edge_feature(const silk_mesh *m, uint32_t e)
{
    if (m->edge_feature) return m->edge_feature[e];
    if (!m->feature || !is_feature(&m->edge[e])) return SILK_NO_INDEX;
    /* a packed mesh (no edge_feature) counts the feature edges before e:
     * silk_edge_has_feature written out, which -Os would call per edge */
    uint32_t f = 0;
    for (const silk_edge *x = m->edge, *end = m->edge + e; x < end; x++)
        f += (x->flags & SILK_EDGE_FEATURE) && x->v[0] != x->v[1];
    return (silk_index)f;
}

int silk_mesh_feature_seg(const silk_mesh *m, silk_index e, silk_feature_seg *out)
{
    if (m->packed.base) return silk_compact_feature_seg(m, e, out);
    silk_index fi = silk_mesh_edge_feature(m, e);
    if (fi == SILK_NO_INDEX || fi >= m->nfeature_edges || !m->feature) return 0;
    *out = m->feature[fi];
    return 1;
}

static silk_index other_end(const silk_edge *e, silk_index v)
{
    return e->v[0] == v ? e->v[1] : e->v[0];
}

/* 45 degrees keeps an octagon's rim (45 per vertex) one smooth loop and
 * breaks every sharp turn measured on the shared models (docs/formats.md).
 * A turn of exactly 45 must pass, but the two unit vectors carry up to 0.87
 * ulp of rounding each and the cosine 0.5 ulp (it rounds to cos 44.9995):
 * the limit is lowered by SILK_FEATURE_TURN_SLACK ulp, about 0.005 degrees,
 * so that rounding cannot make a corner of an octagon's vertex. */
#define SILK_FEATURE_TURN_DEG 45
#define SILK_FEATURE_TURN_SLACK 4

/* 1 if a feature polyline may not pass through v: other than two feature
 * edges, or two that turn by more than SILK_FEATURE_TURN_DEG. */
static int polyline_stops_at(const silk_mesh *m, const uint32_t *fdeg, silk_index v, int64_t cos_turn)
{
    if (fdeg[v] != 2) return 1;
    silk_index nb[2];
    int n = 0;
    for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1] && n < 2; i++) {
        const silk_edge *e = &m->edge[m->vert_edge[i]];
        if (is_feature(e)) nb[n++] = other_end(e, v);
    }
    if (n < 2) return 1;
    silk_vec3 in, out;
    if (!silk_v3_normalize(silk_v3_sub(m->pos[v], m->pos[nb[0]]), &in) ||
        !silk_v3_normalize(silk_v3_sub(m->pos[nb[1]], m->pos[v]), &out))
        return 1;
    return silk_v3_dot64(in, out) < cos_turn;
}

/* The tangent at p of the circle through prev, p, next.  Eq. 1 as printed,
 * |W1| W0 + |W0| W1, bisects the two directions; that is the circle's
 * tangent only for equal spacing.  The circle's tangent for any spacing is
 * |W1| W0/|W0| + |W0| W1/|W1|, or (times |W0||W1|) |W1|^2 W0 + |W0|^2 W1,
 * which needs no square root: the squared lengths are exact 64-bit dot
 * products, brought to 30 bits by one common shift so their ratio stays.
 * Where it vanishes (the polyline turns straight back, or a neighbour sits
 * on the vertex) there is no circle; follow whichever side has a length. */
static silk_vec3 inner_dir(silk_vec3 prev, silk_vec3 p, silk_vec3 next)
{
    silk_vec3 w0 = silk_v3_sub(p, prev), w1 = silk_v3_sub(next, p), d;
    int64_t s0 = silk_v3_dot64(w0, w0), s1 = silk_v3_dot64(w1, w1);
    while (s0 >= ((int64_t)1 << 30) || s1 >= ((int64_t)1 << 30)) {
        s0 = silk_shr_round64(s0, 1);
        s1 = silk_shr_round64(s1, 1);
    }
    int64_t t[3] = { s1 * w0.x + s0 * w1.x, s1 * w0.y + s0 * w1.y, s1 * w0.z + s0 * w1.z };
    if (silk_v3_normalize64(t, &d)) return d;
    if (silk_v3_normalize(w1, &d)) return d;
    silk_v3_normalize(w0, &d);
    return d;
}

/* Tangent at an end of a polyline.  chord runs along the polyline from the
 * end vertex to its neighbour's position (forward at the start, backward
 * reversed at the finish: always the direction of travel), d is the unit
 * tangent at that neighbour.  The circle through the end, the neighbour and
 * the next vertex is symmetric about the bisector plane of the chord, so its
 * tangent at the end is d mirrored in that plane and reversed:
 * 2 (d.u) u - d, u the unit chord. */
static silk_vec3 end_dir(silk_vec3 chord, silk_vec3 d)
{
    silk_vec3 u, r;
    if (!silk_v3_normalize(chord, &u)) return u;
    int64_t du = silk_v3_dot64(d, u);   /* Q32.32 */
    const int64_t one = (int64_t)1 << 32;
    int64_t t[3] = { 2 * du * u.x - d.x * one, 2 * du * u.y - d.y * one, 2 * du * u.z - d.z * one };
    if (silk_v3_normalize64(t, &r)) return r;
    return u;
}

/* Follows feature edges from vertex start along edge e until a vertex where
 * polylines stop, or back to start.  Fills vert[0..k] and edges[0..k-1];
 * returns k. */
static uint32_t walk(const silk_mesh *m, const uint8_t *stop, uint8_t *used, silk_index start, uint32_t e,
                     silk_index *vert, uint32_t *edges)
{
    uint32_t k = 0;
    silk_index v = start;
    vert[0] = start;
    for (;;) {
        used[e] = 1;
        edges[k] = e;
        v = other_end(&m->edge[e], v);
        vert[++k] = v;
        if (stop[v] || v == start) return k;
        uint32_t next = e;
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) {
            uint32_t f = m->vert_edge[i];
            if (f != e && is_feature(&m->edge[f])) next = f;
        }
        if (next == e || used[next]) return k;
        e = next;
    }
}

static void store(silk_mesh *m, uint32_t e, silk_index from, silk_vec3 t_from, silk_vec3 t_to)
{
    silk_feature_seg *s = &m->feature[m->edge_feature[e]];
    if (m->edge[e].v[0] == from) {
        s->t0 = t_from;
        s->t1 = t_to;
    } else {
        /* The same curve run backwards: swap the ends, reverse the tangents. */
        s->t0 = silk_v3_neg(t_to);
        s->t1 = silk_v3_neg(t_from);
    }
}

/* The sine of the turn at vertex j of a polyline (vert[0..k], vert[k] ==
 * vert[0] when closed), Q16; 0 at an end of an open one. */
static silk_fx turn_at(const silk_vec3 *p, const silk_index *vert, uint32_t k, int closed, uint32_t j)
{
    if (!closed && (j == 0 || j == k)) return 0;
    uint32_t a = j == 0 ? k - 1 : j - 1, b = j == k ? 1 : j + 1;
    silk_vec3 u, w;
    if (!silk_v3_normalize(silk_v3_sub(p[vert[j]], p[vert[a]]), &u) ||
        !silk_v3_normalize(silk_v3_sub(p[vert[b]], p[vert[j]]), &w))
        return 0;
    return silk_v3_length(silk_v3_cross(u, w));
}

/* Where a feature polyline's spacing changes sharply - an edge next to one
 * SILK_FEATURE_G1 times as long or longer - and the long edge's far end
 * turns less than a quarter as much as this vertex (or ends the polyline),
 * the polyline is a CAD model's straight line meeting the arc it is
 * tangent to (fandisk's creases: a fillet's short edges, then a long
 * straight one), not a circle sampled unevenly, whose far end would turn
 * as much again.  A circle through the three points would bend the long,
 * straight edge - fandisk-1000's 150 px edges by 10 px at 640x480.  The
 * tangent at vertex i < k is then the long edge's direction, so the line
 * stays straight (silk_feature_tangent gives the chord itself) and the arc meets it
 * tangentially. */
#define SILK_FEATURE_G1 2

static void g1_dir(const silk_vec3 *p, const silk_index *vert, uint32_t k, int closed, uint32_t i, silk_vec3 *dir)
{
    uint32_t a = i == 0 ? k - 1 : i - 1, b = i + 1;
    silk_vec3 w0 = silk_v3_sub(p[vert[i]], p[vert[a]]), w1 = silk_v3_sub(p[vert[b]], p[vert[i]]);
    int64_t s0 = silk_v3_dot64(w0, w0), s1 = silk_v3_dot64(w1, w1), g2 = SILK_FEATURE_G1 * SILK_FEATURE_G1;
    silk_fx ti = turn_at(p, vert, k, closed, i) / 4;
    if (s1 / g2 > s0 && turn_at(p, vert, k, closed, b) < ti) silk_v3_normalize(w1, dir);
    else if (s0 / g2 > s1 && turn_at(p, vert, k, closed, a) < ti) silk_v3_normalize(w0, dir);
}

/* Eq. 4's tangent (silk_arc_tangent) for the unit direction d over chord,
 * and straight stays straight: a direction within 2^-10 of the chord's
 * (|d x chord| below |chord| / 1024, d.chord > 0) gives the chord itself,
 * which eq. 4 at theta = 0 is, bit for bit - so a polyline that is straight
 * gives exactly its edges (eq. 5 with t0 = t1 = the chord), not curves bent
 * by the rounding of its points and unit vectors (such a turn moves a curve
 * by less than 1/4000 of its chord). */
silk_vec3 silk_feature_tangent(silk_vec3 d, silk_vec3 chord)
{
    if (silk_v3_dot64(d, chord) > 0 &&
        (int64_t)silk_v3_length(silk_v3_cross(d, chord)) * 1024 < (int64_t)silk_v3_length(chord))
        return chord;
    return silk_arc_tangent(d, chord);
}

/* closed: vert[k] == vert[0] is an inner vertex.  An open polyline may also
 * come back to its first vertex (a loop through a junction): then that
 * vertex is two ends. */
static void polyline_segments(silk_mesh *m, const silk_index *vert, const uint32_t *edges, uint32_t k,
                              int closed, silk_vec3 *dir)
{
    const silk_vec3 *p = m->pos;
    if (k == 1) {
        silk_vec3 chord = silk_v3_sub(p[vert[1]], p[vert[0]]);
        store(m, edges[0], vert[0], chord, chord);
        return;
    }
    for (uint32_t i = 1; i < k; i++) {
        dir[i] = inner_dir(p[vert[i - 1]], p[vert[i]], p[vert[i + 1]]);
        g1_dir(p, vert, k, closed, i, &dir[i]);
    }
    if (closed) {
        dir[0] = inner_dir(p[vert[k - 1]], p[vert[0]], p[vert[1]]);
        g1_dir(p, vert, k, closed, 0, &dir[0]);
        dir[k] = dir[0];
    } else {
        dir[0] = end_dir(silk_v3_sub(p[vert[1]], p[vert[0]]), dir[1]);
        dir[k] = end_dir(silk_v3_sub(p[vert[k]], p[vert[k - 1]]), dir[k - 1]);
    }
    for (uint32_t j = 0; j < k; j++) {
        silk_vec3 chord = silk_v3_sub(p[vert[j + 1]], p[vert[j]]);
        store(m, edges[j], vert[j], silk_feature_tangent(dir[j], chord), silk_feature_tangent(dir[j + 1], chord));
    }
}

silk_status silk_build_features(const char *name, silk_arena *a, silk_mesh *m, silk_error *err)
{
    uint32_t nfe = 0;
    for (uint32_t e = 0; e < m->nedges; e++) nfe += (uint32_t)is_feature(&m->edge[e]);
    m->nfeature_edges = nfe;
    m->edge_feature = silk_arena_array(a, m->nedges, sizeof *m->edge_feature, SILK_MEM_FEATURES);
    m->feature = silk_arena_array(a, nfe, sizeof *m->feature, SILK_MEM_FEATURES);
    if (!m->edge_feature || !m->feature) return nomem(err, name, a);
    for (uint32_t e = 0, f = 0; e < m->nedges; e++)
        m->edge_feature[e] = is_feature(&m->edge[e]) ? f++ : SILK_NO_INDEX;
    if (nfe == 0) return SILK_OK;

    silk_arena_mark mark = silk_arena_top_mark(a);
    uint32_t *fdeg = silk_arena_array_top(a, m->nverts, sizeof *fdeg, SILK_MEM_LOAD);
    uint8_t *stop = silk_arena_array_top(a, m->nverts, sizeof *stop, SILK_MEM_LOAD);
    uint8_t *used = silk_arena_array_top(a, m->nedges, sizeof *used, SILK_MEM_LOAD);
    silk_index *vert = silk_arena_array_top(a, (size_t)nfe + 1, sizeof *vert, SILK_MEM_LOAD);
    uint32_t *edges = silk_arena_array_top(a, nfe, sizeof *edges, SILK_MEM_LOAD);
    silk_vec3 *dir = silk_arena_array_top(a, (size_t)nfe + 1, sizeof *dir, SILK_MEM_LOAD);
    if (!fdeg || !stop || !used || !vert || !edges || !dir) {
        silk_status st = nomem(err, name, a);
        silk_arena_top_release(a, &mark);
        return st;
    }
    for (uint32_t e = 0; e < m->nedges; e++)
        if (is_feature(&m->edge[e])) {
            fdeg[m->edge[e].v[0]]++;
            fdeg[m->edge[e].v[1]]++;
        }

    silk_fx sin_turn, cos_turn;
    silk_fx_sincos_deg(SILK_FX_C(SILK_FEATURE_TURN_DEG, 1), &sin_turn, &cos_turn);
    const int64_t turn_limit = (int64_t)(cos_turn - SILK_FEATURE_TURN_SLACK) * SILK_FX_ONE;   /* Q32.32 */
    for (silk_index v = 0; v < m->nverts; v++)
        stop[v] = fdeg[v] != 0 && (uint8_t)polyline_stops_at(m, fdeg, v, turn_limit);

    /* Open polylines start at their ends (junctions, corners) ... */
    for (silk_index v = 0; v < m->nverts; v++) {
        if (!stop[v]) continue;
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) {
            uint32_t e = m->vert_edge[i];
            if (!is_feature(&m->edge[e]) || used[e]) continue;
            uint32_t k = walk(m, stop, used, v, e, vert, edges);
            polyline_segments(m, vert, edges, k, 0, dir);
        }
    }
    /* ... what is left are closed loops through vertices of two feature edges. */
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(&m->edge[e]) || used[e]) continue;
        uint32_t k = walk(m, stop, used, m->edge[e].v[0], e, vert, edges);
        polyline_segments(m, vert, edges, k, k >= 3 && vert[k] == vert[0], dir);
    }
    silk_arena_top_release(a, &mark);
    return SILK_OK;
}
