/*
 * silhouette.c - silhouette triangles, silhouette bridges and silhouette
 * points for one view (paper III-B, III-C, III-D).
 *
 * A triangle is a silhouette triangle when the visibility of its three
 * corner normals (the normal of the triangle's own smooth group at feature
 * vertices) is not the same.  Its two sides whose end normals disagree get a
 * silhouette point: on the bridge of eqs. 2-5 for an ordinary edge, on the
 * precomputed feature segment for a feature edge (case a of III-D), at the
 * parameter of eqs. 6-7.  Visible feature edges are also sampled, with a
 * count from eq. 8 that depends on the edge alone.
 *
 * Everything placed on an edge is computed here once per edge and frame and
 * collected into the edge's chain of parameters, which every triangle on the
 * edge then walks (see plan.h), so neighbours agree bit for bit.
 */
#include <string.h>
#include "plan.h"
#include "stages.h"
#include "curve.h"
#include "mesh_build.h"
#include "compiler.h"

/* ---- small helpers ---------------------------------------------------------- */

static int edge_ok(const silk_mesh *m, silk_index e) { return e < silk_mesh_edge_bound(m); }

/* The normals (and uvs) at edge.v[0] (v0), edge.v[1] as side k of t sees them. */
void silk_sil_side_attrs(const silk_mesh *m, uint32_t t, uint32_t k, silk_index v0, silk_sil_side *s)
{
    uint32_t ca = 3 * t + k, cb = 3 * t + (k + 1) % 3;
    if (silk_mesh_corner(m, ca) != v0) { uint32_t x = ca; ca = cb; cb = x; }
    s->tri = t;
    s->k = k;
    s->n0 = (silk_plan_index)silk_mesh_corner_normal(m, ca);   /* (silk_sil_find: every count fits) */
    s->n1 = (silk_plan_index)silk_mesh_corner_normal(m, cb);
    if (m->tri_uv && m->uv) { s->uv0 = (silk_plan_index)m->tri_uv[ca]; s->uv1 = (silk_plan_index)m->tri_uv[cb]; }
    else { s->uv0 = SILK_PLAN_NONE; s->uv1 = SILK_PLAN_NONE; }
}

static uint64_t mag(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

static int32_t abs32(int32_t v) { return v < 0 ? -v : v; }   /* |v| < 2^31 here */

/* The smallest s with v >> s below 2^14. */
static int cut14(uint64_t v)
{
    int n = silk_bitlen64(v);
    return n > 14 ? n - 14 : 0;
}

/* silk_view_to_eye and silk_tri_cross64 for triangle t: written out where
 * the build writes out its usual cases (SILK_FAST_CASES: the outline asks
 * every triangle every frame), called on a board, which keeps the code
 * bytes. */
SILK_FAST_INLINE static inline silk_vec3 front_inputs(const silk_mesh *m, const silk_view *v, uint32_t t,
                                                      int64_t c[3])
{
    if (!SILK_FAST_CASES) {
        silk_vec3 e = silk_view_to_eye(v, silk_mesh_pos(m, silk_mesh_corner(m, 3 * t)));
        silk_tri_cross64(m, t, c);
        return e;
    }
    silk_vec3 p0 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t)), p1 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + 1)),
              p2 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + 2));
    int64_t ax = (int64_t)p1.x - p0.x, ay = (int64_t)p1.y - p0.y, az = (int64_t)p1.z - p0.z;
    int64_t bx = (int64_t)p2.x - p0.x, by = (int64_t)p2.y - p0.y, bz = (int64_t)p2.z - p0.z;
    c[0] = ay * bz - az * by;
    c[1] = az * bx - ax * bz;
    c[2] = ax * by - ay * bx;
    return v->cam.ortho ? silk_v3_neg(v->forward) : silk_v3_sub(v->cam.eye, p0);
}

/* The face normal is normalised (a square root) before the dot product
 * with the direction to the eye, so that every caller gets the same
 * rounded answer; that rounding tilts it by a few 2^-16.  Cut to 14 bits,
 * the normal and the direction tilt by under 2^-11 each (their largest
 * component keeps 13 bits): where the cut ones already make an angle with
 * |cos| above 2^-8, the sign is the rounded one's.  Only triangles seen
 * nearly edge-on (and zero-area ones) are normalised.  The anti-aliased
 * outline asks every triangle every frame; a build without it (SILK_AA 0)
 * asks only of feature edges' triangles and keeps the 0.4 KiB of
 * Cortex-M3 code the cut test takes.  (Inline where the usual cases are
 * written out: silk_sil_tri_fronts' loop asks every triangle.) */
SILK_FAST_INLINE static inline int front_of(const silk_mesh *m, const silk_view *v, uint32_t t)
{
    if (!SILK_AA) {
        silk_vec3 e = silk_view_to_eye(v, silk_mesh_pos(m, silk_mesh_corner(m, 3 * t)));
        silk_vec3 fn = silk_mesh_face_normal(m, t);
        return silk_v3_dot64(fn, e) > 0;
    }
    int64_t c[3];
    silk_vec3 e = front_inputs(m, v, t, c);
    /* Where the usual cases are written out (SILK_FAST_CASES), the uncut
     * vectors first, where their L1 norms keep every product within 63
     * bits (a mesh within +-2^3 units of the eye): |c.e| > cn en / 2^10 >=
     * |c| |e| / 2^10 is an angle with |cos| above 2^-10, far more than the
     * rounded normal's tilt of a few 2^-16 can turn, so the sign is its. */
    if (SILK_FAST_CASES) {
        uint64_t cn = mag(c[0]) + mag(c[1]) + mag(c[2]), en = mag(e.x) + mag(e.y) + mag(e.z);
        if (cn < ((uint64_t)1 << 40) && en < ((uint64_t)1 << 22)) {
            int64_t d = c[0] * e.x + c[1] * e.y + c[2] * e.z;   /* |d| <= cn en < 2^62 */
            if (mag(d) > (cn * en >> 10)) return d > 0;
        }
    }
    int sc = cut14(mag(c[0]) | mag(c[1]) | mag(c[2])), se = cut14(mag(e.x) | mag(e.y) | mag(e.z));
    /* |c_i|, |e_i| < 2^14: d below 2^30; |c| |e| <= n1 e1 < 2^32 (written out: every triangle, every frame) */
    int32_t x0 = (int32_t)(c[0] >> sc), x1 = (int32_t)(c[1] >> sc), x2 = (int32_t)(c[2] >> sc);
    int32_t y0 = e.x >> se, y1 = e.y >> se, y2 = e.z >> se;
    int32_t d = x0 * y0 + x1 * y1 + x2 * y2;
    uint32_t n1 = (uint32_t)abs32(x0) + (uint32_t)abs32(x1) + (uint32_t)abs32(x2),
             e1 = (uint32_t)abs32(y0) + (uint32_t)abs32(y1) + (uint32_t)abs32(y2);
    if ((uint32_t)abs32(d) > (n1 * e1 >> 8)) return d > 0;
    silk_vec3 fn = silk_mesh_face_normal(m, t);
    return silk_v3_dot64(fn, e) > 0;
}

int silk_sil_tri_front(const silk_mesh *m, const silk_view *v, uint32_t t)
{
    for (int k = 0; k < 3; k++)
        if (silk_mesh_corner(m, 3 * t + k) >= m->nverts) return 0;
    return front_of(m, v, t);
}

void silk_sil_tri_fronts(const silk_mesh *m, const silk_view *v, uint8_t *facing)
{
    if (!SILK_AA_CANDIDATES) return;   /* (only its caller's) */
    for (uint32_t t = 0; t < m->ntris; t += 4) {
        unsigned b = 0;
        for (uint32_t i = 0; i < 4 && t + i < m->ntris; i++) {
            uint32_t c = 3 * (t + i);
            int front = silk_mesh_corner(m, c) < m->nverts && silk_mesh_corner(m, c + 1) < m->nverts &&
                        silk_mesh_corner(m, c + 2) < m->nverts && front_of(m, v, t + i);
            b |= (2u | (unsigned)front) << 2 * i;
        }
        facing[t / 4] = (uint8_t)b;
    }
}

/* Triangles whose three normals and corners are usable; anything else is
 * drawn as it is (never smoothed), so a broken index cannot crash a frame. */
int silk_sil_tri_ok(const silk_mesh *m, uint32_t t)
{
    /* a compact model's indices were all checked once (silk_compact_mesh);
     * without its corner table no side has an edge */
    if (m->packed.base) return m->nedges != 0;
    for (int k = 0; k < 3; k++)
        if (silk_mesh_corner(m, 3 * t + k) >= m->nverts || silk_mesh_corner_normal(m, 3 * t + k) >= m->nnormals ||
            !edge_ok(m, silk_mesh_tri_edge(m, t, k)))
            return 0;
    return 1;
}

/* The point at u on edge e and its normal, as side s sees the edge.  (It
 * and edge_point_attrs inline: a board has silk_sil_edge_point alone.) */
SILK_ALWAYS_INLINE static inline void edge_point_pn(const silk_sil_frame *f, const silk_mesh *m, const silk_sil_edge *e,
                                 const silk_sil_side *s, silk_fx u, silk_vec3 *p, silk_vec3 *n)
{
    silk_curve c;
    silk_sil_edge_curve(f, e, &c);
    *p = silk_hermite_point(&c, u);
    /* eq. 6: the normal along a bridge is interpolated linearly */
    if (!silk_v3_normalize(silk_v3_lerp(silk_mesh_normal(m, s->n0), silk_mesh_normal(m, s->n1), u), n))
        *n = silk_mesh_normal(m, s->n0);
}

/* The uv and colour at u on edge e, as side s sees the edge. */
SILK_ALWAYS_INLINE static inline void edge_point_attrs(const silk_mesh *m, const silk_sil_edge *e, const silk_sil_side *s, silk_fx u,
                                    silk_vec2 *uv, uint32_t *rgb)
{
    if (s->uv0 != SILK_PLAN_NONE && s->uv0 < m->nuvs && s->uv1 < m->nuvs) {
        silk_vec2 a = m->uv[s->uv0], b = m->uv[s->uv1];
        uv->x = silk_fx_add(a.x, silk_fx_mul(silk_fx_sub(b.x, a.x), u));
        uv->y = silk_fx_add(a.y, silk_fx_mul(silk_fx_sub(b.y, a.y), u));
    } else {
        uv->x = uv->y = 0;
    }
    *rgb = m->color ? silk_sil_edge_rgb(m, (const silk_edge[]){ silk_mesh_edge(m, e->edge) }, u) : 0xffffff;
}

void silk_sil_edge_point(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s,
                         silk_fx u, silk_vec3 *p, silk_vec3 *n, silk_vec2 *uv, uint32_t *rgb)
{
    const silk_mesh *m = f->m;
    edge_point_pn(f, m, e, s, u, p, n);
    edge_point_attrs(m, e, s, u, uv, rgb);
}

void silk_sil_pair_point(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s,
                         const silk_sil_pair *pr, silk_vec3 *p, silk_vec3 *n, silk_vec2 *uv, uint32_t *rgb)
{
    size_t i = (size_t)(pr - f->pairs);
    silk_sil_cursor *k = f->cur;   /* its memo */
    if (!SILK_KEEP_SEGMENTS) {   /* (its only caller takes silk_sil_edge_point then) */
        silk_sil_edge_point(f, e, s, pr->u, p, n, uv, rgb);
        return;
    }
    if (!k->pair_pn) {
        edge_point_pn(f, f->m, e, s, pr->u, p, n);
    } else {
        /* the pair's normals are the side's (side_pair matched them) */
        if (!k->pair_ready[i]) {
            edge_point_pn(f, f->m, e, s, pr->u, &k->pair_pn[2 * i], &k->pair_pn[2 * i + 1]);
            k->pair_ready[i] = 1;
        }
        *p = k->pair_pn[2 * i];
        *n = k->pair_pn[2 * i + 1];
    }
    edge_point_attrs(f->m, e, s, pr->u, uv, rgb);
}

uint32_t silk_sil_edge_rgb(const silk_mesh *m, const silk_edge *e, silk_fx u)
{
    if (!m->color) return 0xffffff;
    return silk_rgb_lerp(m->color[e->v[0]], m->color[e->v[1]], u);
}

/* ---- per-edge geometry ------------------------------------------------------- */

/* The curve every point on edge w lies on: the feature segment of a feature
 * edge (a straight one if it has none), else the silhouette bridge built from
 * the normals of the first silhouette point found on it.  Either way it ends
 * exactly on the vertices.  Made whenever it is asked for, unless kept
 * (silk_sil_keep_tangents: 24 bytes an edge would otherwise be the plan's
 * largest part; a bridge is about 4 000 instructions on a Cortex-M3), the
 * tangents of the last few edges kept in the frame's memo: emitting one
 * triangle asks for each of its sides several times. */
static void edge_tangents(const silk_sil_frame *f, const silk_sil_edge *w, silk_vec3 t[2])
{
    const silk_mesh *m = f->m;
    silk_index ev[2];
    silk_mesh_edge_ends(m, w->edge, ev);
    silk_vec3 p0 = silk_mesh_pos(m, ev[0]), p1 = silk_mesh_pos(m, ev[1]);
    if (w->is_feature || w->npairs == 0) {
        silk_feature_seg seg;
        if (silk_mesh_feature_seg(m, w->edge, &seg)) {
            t[0] = seg.t0;
            t[1] = seg.t1;
        } else {
            t[0] = t[1] = silk_v3_sub(p1, p0);
        }
    } else {
        const silk_sil_pair *p = &f->pairs[w->pair0];
        silk_curve c;
        silk_bridge(p0, silk_mesh_normal(m, p->n0), p1, silk_mesh_normal(m, p->n1), silk_tilt_bound(m), &c);
        t[0] = c.t0;
        t[1] = c.t1;
    }
}

void silk_sil_edge_curve(const silk_sil_frame *f, const silk_sil_edge *e, silk_curve *c)
{
    const silk_vec3 *t;
    uint32_t w = (uint32_t)(e - f->edges);
    if (w < f->ntan_kept) {
        t = &f->tan_kept[2 * (size_t)w];
    } else {
        silk_sil_cursor *memo = f->cur;
        uint32_t i = 0;
        while (i < SILK_SIL_TAN_MEMO && memo->tan_edge[i] != e) i++;
        if (i == SILK_SIL_TAN_MEMO) {
            i = memo->tan_next;
            memo->tan_next = i + 1 < SILK_SIL_TAN_MEMO ? i + 1 : 0;
            memo->tan_edge[i] = e;
            edge_tangents(f, e, memo->tan[i]);
        }
        t = memo->tan[i];
    }
    silk_index ev[2];
    silk_mesh_edge_ends(f->m, e->edge, ev);
    memset(c, 0, sizeof *c);
    c->p0 = silk_mesh_pos(f->m, ev[0]);
    c->p1 = silk_mesh_pos(f->m, ev[1]);
    c->t0 = t[0];
    c->t1 = t[1];
}

size_t silk_sil_keep_tangents(silk_sil_frame *f, size_t room)
{
    size_t free0 = silk_arena_free_bytes(f->a);
    size_t fit = room > SILK_ARENA_ALIGN ? (room - SILK_ARENA_ALIGN) / (2 * sizeof *f->tan_kept) : 0;
    uint32_t n = fit < f->nedges ? (uint32_t)fit : f->nedges;
    if (f->tan_kept || n == 0) return 0;
    /* every one written below: unfilled, where the build spends the code (SILK_FAST_CASES) */
    silk_vec3 *t = SILK_FAST_CASES ? silk_arena_array_top_unfilled(f->a, 2 * (size_t)n, sizeof *t, SILK_MEM_FRAME)
                                   : silk_arena_array_top(f->a, 2 * (size_t)n, sizeof *t, SILK_MEM_FRAME);
    if (!t) return 0;
    for (uint32_t w = 0; w < n; w++) edge_tangents(f, &f->edges[w], &t[2 * w]);
    f->tan_kept = t;
    f->ntan_kept = n;
    return free0 - silk_arena_free_bytes(f->a);
}

/* Eq. 8 reads n_s = ceil(sqrt(h r / e) / 2) with r = sin(alpha/2).  For a
 * circular arc of radius R split into n equal pieces the error is about
 * R alpha^2 / (8 n^2); with h the arc's projected CHORD, h = 2 R r, that is
 * h r / (4 n^2), and requiring it <= e gives exactly eq. 8 for n pieces.
 * With h the arc's height (the text's wording, R alpha^2 / 8) the formula
 * would give 2/sqrt(r) times too few pieces - a single chord for every
 * silhouette triangle of a 200-triangle sphere at 512x512, 1.4 px off - so
 * h here is the projected chord, and n_s the number of intervals. */
uint32_t silk_sil_intervals(const silk_view *v, const silk_curve *c, silk_fx cos_alpha, silk_fx tol)
{
    silk_vec2 a, b;
    /* A curve reaching behind the eye is clipped anyway: one interval. */
    if (!silk_view_project(v, c->p0, &a) || !silk_view_project(v, c->p1, &b)) return 1;
    silk_fx chord = silk_v3_length(silk_v3(silk_fx_sub(a.x, b.x), silk_fx_sub(a.y, b.y), 0));
    return silk_sample_count(chord, cos_alpha, tol);
}

static silk_fx unit_dot(silk_vec3 a, silk_vec3 b)
{
    silk_vec3 ua, ub;
    if (!silk_v3_normalize(a, &ua) || !silk_v3_normalize(b, &ub)) return SILK_FX_ONE;
    return silk_v3_dot(ua, ub);
}

/* Insert u into the ascending, distinct list c[0..*n). */
static void chain_insert(silk_fx *c, uint32_t *n, silk_fx u)
{
    uint32_t i = *n;
    while (i > 0 && c[i - 1] > u) i--;
    if (i > 0 && c[i - 1] == u) return;
    memmove(&c[i + 1], &c[i], (*n - i) * sizeof *c);
    c[i] = u;
    (*n)++;
}

/* ---- the stage ----------------------------------------------------------------- */

/* Whether triangle t is whole (silk_sil_tri_ok), and then its sides'
 * edges in e.  A loaded mesh has them listed (tri_edge): every triangle
 * is tested every frame, so there the test is written out, each index
 * read once (SILK_PLAN_BY_EDGES); a board's packed mesh finds them, and
 * its build keeps the code bytes. */
static int tri_edges(const silk_mesh *m, uint32_t t, silk_index e[3])
{
    if (SILK_PLAN_BY_EDGES && m->tri_edge) {
        const silk_index *tv = &m->tri[3 * (size_t)t], *tn = &m->tri_normal[3 * (size_t)t],
                         *te = &m->tri_edge[3 * (size_t)t];
        uint32_t nv = m->nverts, nn = m->nnormals, ne = m->nedges;
        e[0] = te[0];
        e[1] = te[1];
        e[2] = te[2];
        return (tv[0] < nv) & (tv[1] < nv) & (tv[2] < nv) & (tn[0] < nn) & (tn[1] < nn) & (tn[2] < nn) &
               (e[0] < ne) & (e[1] < ne) & (e[2] < ne);
    }
    if (!silk_sil_tri_ok(m, t)) return 0;
    for (uint32_t k = 0; k < 3; k++) e[k] = silk_mesh_tri_edge(m, t, k);
    return 1;
}

/* Mark edge e as carrying points, counting it the first time. */
static void mark_edge(silk_sil_frame *f, silk_index e, uint32_t *n)
{
    uint8_t bit = (uint8_t)(1u << (e & 7));
    if (!(f->carrying[e >> 3] & bit)) (*n)++;
    f->carrying[e >> 3] |= bit;
}

/* Whether the sides on the carrying edges may be found from the edges'
 * triangles instead of a pass over every triangle (SILK_PLAN_BY_EDGES):
 * with listed edges (tri_edge) and no edge of more than two triangles,
 * edge.t names every triangle with a side on the edge (silk_mesh_build),
 * so the work is the silhouette's, not the mesh's.  A board's packed mesh
 * has no tri_edge, and its build keeps the code bytes. */
static int by_edges(const silk_mesh *m)
{
    return m->tri_edge && !m->nnonmanifold_edges;
}

/* Whether the n indices x[] are all below lim, 1 <= lim <= 2^31: x < lim
 * exactly when neither x nor lim - 1 - x has its top bit set.  Or-ed
 * eight lanes at a time, a loop a compiler vectorises. */
static int all_below(const silk_index *x, size_t n, uint32_t lim)
{
    if (lim == 0 || lim > (uint32_t)1 << 31) return n == 0;
    uint32_t top = lim - 1, lane[8] = { 0 }, acc = 0;
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (uint32_t j = 0; j < 8; j++) lane[j] |= x[i + j] | (top - x[i + j]);
    for (; i < n; i++) acc |= x[i] | (top - x[i]);
    for (uint32_t j = 0; j < 8; j++) acc |= lane[j];
    return acc >> 31 == 0;
}

/* Whether every triangle is whole (silk_sil_tri_ok): three passes over
 * the index lists instead of nine tests for each triangle. */
static int all_whole(const silk_mesh *m)
{
    size_t n = 3 * (size_t)m->ntris;
    return all_below(m->tri, n, m->nverts) && all_below(m->tri_normal, n, m->nnormals) &&
           all_below(m->tri_edge, n, m->nedges);
}

/* find_triangles' loop for a host's mesh of whole triangles and listed
 * edges, none of more than two triangles (by_edges): the same states and
 * marks with three reads a triangle, and the feature edges' triangles
 * found from the edges, instead of three edges' flags read for every
 * triangle. */
static void find_whole(silk_sil_frame *f, int features, uint32_t *nwork)
{
    const silk_mesh *m = f->m;
    const uint8_t *vis = f->visible;
    uint32_t nsil = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        const silk_index *tn = &m->tri_normal[3 * (size_t)t];
        uint8_t v0 = vis[tn[0]], v1 = vis[tn[1]], v2 = vis[tn[2]], st = 0;
        if (v0 != v1 || v1 != v2) {
            const silk_index *te = &m->tri_edge[3 * (size_t)t];
            uint8_t lone = v0 == v1 ? 2 : (v0 == v2 ? 1 : 0);
            st = (uint8_t)(SILK_TS_SIL | lone);
            nsil++;
            mark_edge(f, te[lone], nwork);
            mark_edge(f, te[(lone + 2) % 3], nwork);
        }
        f->tri_state[t] = st;
    }
    f->nsil = nsil;
    const silk_edge *ed = m->edge, *end = features ? ed + m->nedges : ed;
    for (; ed < end; ed++) {
        if (!(ed->flags & SILK_EDGE_FEATURE)) continue;
        for (uint32_t i = 0; i < 2; i++) {
            uint32_t t = ed->t[i];
            if (t >= m->ntris || (f->tri_state[t] & SILK_TS_FRONT) || !silk_sil_tri_front(m, f->v, t)) continue;
            f->tri_state[t] |= SILK_TS_FRONT;
            for (uint32_t k = 0; k < 3; k++) {
                silk_index ek = m->tri_edge[3 * (size_t)t + k];
                if (silk_mesh_edge_flags(m, ek) & SILK_EDGE_FEATURE) mark_edge(f, ek, nwork);
            }
        }
    }
}

/* The carrying edges ranked (carry_rank, silk_sil_slot), where the caller
 * gave the plan room to keep them (SILK_CARRY_RANK); bits: carrying's bytes. */
static void rank_carrying(silk_sil_frame *f, size_t bits)
{
    silk_arena *a = f->a;
    size_t free0 = silk_arena_free_bytes(a), peak = a->top_peak;
    size_t want = bits * sizeof *f->carry_rank + SILK_ARENA_ALIGN;
    if (want <= f->keep->room && silk_sil_keep_fits(want, free0) &&
        (f->carry_rank = silk_arena_array_top_unfilled(a, bits, sizeof *f->carry_rank, SILK_MEM_FRAME))) {
        for (size_t i = 0, r = 0; i < bits; i++) {
            f->carry_rank[i] = (uint32_t)r;
            for (unsigned b = f->carrying[i]; b; b &= b - 1) r++;
        }
        silk_sil_kept(f, free0, peak);
    }
}

/* Visibility of the normals (III-B), the silhouette triangles and the
 * front-facing triangles next to a feature edge (tri_state), and a slot for
 * every edge that carries points this frame (carrying; f->nedges of them). */
static silk_status find_triangles(silk_sil_frame *f)
{
    const silk_mesh *m = f->m;
    const silk_view *v = f->v;
    silk_arena *a = f->a;

    f->tri_state = silk_arena_array_top(a, m->ntris, 1, SILK_MEM_FRAME);
    size_t bits = ((size_t)silk_mesh_edge_bound(m) + 7) / 8;
    f->carrying = silk_arena_array_top(a, bits, 1, SILK_MEM_FRAME);   /* zeroed */
    /* The normals' visibility is needed only here: taken last, given back
     * before the edges are laid out in its place. */
    silk_arena_mark mark = silk_arena_top_mark(a);
    f->visible = silk_arena_array_top(a, m->nnormals, 1, SILK_MEM_FRAME);
    if (!f->visible || !f->tri_state || !f->carrying) return SILK_ERR_NOMEM;

    /* III-B.  The hierarchy may want scratch we do not have; the brute pass
     * gives the same answer without any. */
    uint32_t t0 = silk_stage_start(f->clock);
    if (silk_visibility(m, v, f->vis, f->visible, a, NULL) != SILK_OK)
        silk_visibility_brute(m, v, f->visible);
    silk_stage_stop(f->clock, SILK_STAGE_VISIBILITY, t0);

    /* Silhouette triangles, and which triangles next to a feature edge face us. */
    int features = m->nfeature_edges > 0 || m->nboundary_edges > 0 || m->nnonmanifold_edges > 0;
    uint32_t nwork = 0;
    f->nsil = 0;
    if (SILK_PLAN_BY_EDGES && by_edges(m) && all_whole(m)) {
        find_whole(f, features, &nwork);
    } else {
        for (uint32_t t = 0; t < m->ntris; t++) {
            uint8_t st = 0;
            silk_index e[3];
            f->tri_state[t] = SILK_TS_BROKEN;   /* tested once here, read by lay_out_edges */
            if (!tri_edges(m, t, e)) continue;
            uint8_t v0 = f->visible[silk_mesh_corner_normal(m, 3 * t)], v1 = f->visible[silk_mesh_corner_normal(m, 3 * t + 1)],
                    v2 = f->visible[silk_mesh_corner_normal(m, 3 * t + 2)];
            if (v0 != v1 || v1 != v2) {
                uint8_t lone = v0 == v1 ? 2 : (v0 == v2 ? 1 : 0);
                st |= (uint8_t)(SILK_TS_SIL | lone);
                f->nsil++;
                mark_edge(f, e[lone], &nwork);
                mark_edge(f, e[(lone + 2) % 3], &nwork);
            }
            if (features && ((silk_mesh_edge_flags(m, e[0]) | silk_mesh_edge_flags(m, e[1]) | silk_mesh_edge_flags(m, e[2])) & SILK_EDGE_FEATURE) &&
                silk_sil_tri_front(m, v, t)) {
                st |= SILK_TS_FRONT;
                for (int k = 0; k < 3; k++)
                    if (silk_mesh_edge_flags(m, e[k]) & SILK_EDGE_FEATURE) mark_edge(f, e[k], &nwork);
            }
            f->tri_state[t] = st;
        }
    }
    f->nedges = nwork;
    silk_arena_top_release(a, &mark);
    f->visible = NULL;
    if (SILK_CARRY_RANK && f->keep) rank_carrying(f, bits);
    return SILK_OK;
}

void silk_sil_kept(silk_sil_frame *f, size_t free0, size_t peak)
{
    silk_sil_keep *k = SILK_SIL_KEEPS ? f->keep : NULL;
    if (!k) return;
    size_t need = peak - k->kept_bytes;   /* the high-water so far without what was kept before */
    if (need > k->kept_need) k->kept_need = need;
    k->kept_bytes += free0 - silk_arena_free_bytes(f->a);
}

/* Whether silhouette side k of triangle t, on mesh edge e, gives the same
 * silhouette point as a silhouette side of the edge's other triangle, met
 * earlier in triangle order: fill_pairs then keeps one point for both.  So
 * the points are counted exactly on a manifold edge (two triangles); on a
 * non-manifold one (edge.t holds only two of them) every side counts. */
static int pair_seen(const silk_sil_frame *f, uint32_t t, uint32_t k, silk_index e)
{
    const silk_mesh *m = f->m;
    if (m->nnonmanifold_edges && (silk_mesh_edge_flags(m, e) & SILK_EDGE_NONMANIFOLD)) return 0;
    silk_index et[2], v0 = silk_mesh_edge_v0(m, e);
    silk_mesh_edge_tris(m, e, et);
    uint32_t o = et[0] == t ? et[1] : et[0];
    if (o >= t || !(f->tri_state[o] & SILK_TS_SIL)) return 0;   /* also SILK_NO_INDEX: no other */
    uint32_t lone = f->tri_state[o] & SILK_TS_LONE;
    silk_sil_side a, b;
    silk_sil_side_attrs(m, t, k, v0, &a);
    for (uint32_t ko = 0; ko < 3; ko++) {
        if ((ko != lone && ko != (lone + 2) % 3) || silk_mesh_tri_edge(m, o, ko) != e) continue;
        silk_sil_side_attrs(m, o, ko, v0, &b);
        if (a.n0 == b.n0 && a.n1 == b.n1) return 1;
    }
    return 0;
}

/* Side k of triangle t lies on carrying edge we: counted, and with it
 * its silhouette point unless the triangle across gave the same one;
 * 0 when the edge has more sides than it can count. */
static int count_side(silk_sil_frame *f, uint32_t t, uint32_t k, silk_sil_edge *we)
{
    uint8_t st = f->tri_state[t];
    if (we->nsides == SILK_SIL_SIDES_MAX) return 0;
    f->tri_state[t] |= (uint8_t)(SILK_TS_CARRY0 << k);
    we->nsides++;
    if (st & SILK_TS_SIL) {
        uint32_t lone = st & SILK_TS_LONE;
        if ((k == lone || k == (lone + 2) % 3) && !pair_seen(f, t, k, we->edge)) we->npairs++;
    }
    if ((st & SILK_TS_FRONT) && we->is_feature) we->sampled = 1;
    return 1;
}

/* Whether triangle t is whole (find_triangles tested it). */
static int tri_whole(const silk_sil_frame *f, uint32_t t)
{
    return t < f->m->ntris && (f->tri_state[t] & (SILK_TS_SIL | SILK_TS_LONE)) != SILK_TS_BROKEN;
}

/* The whole triangles on edge e, ascending (the order a pass over every
 * triangle meets them in): tt[0 .. n). */
static uint32_t edge_tris(const silk_sil_frame *f, silk_index e, uint32_t tt[2])
{
    silk_index et[2];
    silk_mesh_edge_tris(f->m, e, et);
    uint32_t a = et[0], b = et[1], n = 0;
    if (b < a) { uint32_t x = a; a = b; b = x; }
    if (tri_whole(f, a)) tt[n++] = a;
    if (b != a && tri_whole(f, b)) tt[n++] = b;
    return n;
}

/* The carrying edges, and room for their sides and silhouette points:
 * each edge's run of sides and of points laid out edge by edge. */
static silk_status lay_out_edges(silk_sil_frame *f)
{
    const silk_mesh *m = f->m;
    silk_arena *a = f->a;
    uint32_t nwork = f->nedges;
    f->edges = silk_arena_array_top(a, nwork, sizeof *f->edges, SILK_MEM_FRAME);
    if (!f->edges) return SILK_ERR_NOMEM;
    for (uint32_t e = 0, w = 0, ne = silk_mesh_edge_bound(m); e < ne; e++) {
        if (!f->carrying[e >> 3]) { e |= 7; continue; }   /* most bytes: none of their eight */
        if (!(f->carrying[e >> 3] & (1u << (e & 7)))) continue;
        f->edges[w].edge = (silk_plan_index)e;
        f->edges[w++].is_feature = (silk_mesh_edge_flags(m, e) & SILK_EDGE_FEATURE) != 0;
    }

    /* Count the sides (every triangle side on a carrying edge) and the
     * silhouette sides of each edge, then lay them out edge by edge. */
    if (SILK_PLAN_BY_EDGES && by_edges(m)) {
        for (uint32_t w = 0; w < nwork; w++) {
            silk_sil_edge *we = &f->edges[w];
            uint32_t tt[2];
            for (uint32_t i = 0, n = edge_tris(f, we->edge, tt); i < n; i++)
                for (uint32_t k = 0; k < 3; k++)
                    if (m->tri_edge[3 * (size_t)tt[i] + k] == we->edge && !count_side(f, tt[i], k, we))
                        return SILK_ERR_NOMEM;
        }
    } else {
        for (uint32_t t = 0; t < m->ntris; t++) {
            if ((f->tri_state[t] & (SILK_TS_SIL | SILK_TS_LONE)) == SILK_TS_BROKEN) continue;
            for (uint32_t k = 0; k < 3; k++) {
                uint32_t w = silk_sil_slot(f, silk_mesh_tri_edge(m, t, k));
                if (w != SILK_SIL_NONE && !count_side(f, t, k, &f->edges[w])) return SILK_ERR_NOMEM;
            }
        }
    }
    uint32_t nsides = 0, npairs = 0;
    for (uint32_t w = 0; w < nwork; w++) {
        nsides += f->edges[w].nsides;
        f->edges[w].pair0 = (silk_plan_index)npairs; npairs += f->edges[w].npairs; f->edges[w].npairs = 0;
        if (npairs >= SILK_PLAN_NONE) return SILK_ERR_NOMEM;   /* pair0 could not index them */
    }
    f->nsides = nsides;
    f->npairs = npairs;
    f->pairs = silk_arena_array_top(a, npairs, sizeof *f->pairs, SILK_MEM_FRAME);
    return f->pairs ? SILK_OK : SILK_ERR_NOMEM;
}

/* The silhouette point of silhouette side k of t on its edge we, unless
 * the edge has one of the same normal pair. */
static void add_pair(silk_sil_frame *f, uint32_t t, uint32_t k, silk_sil_edge *we)
{
    const silk_mesh *m = f->m;
    silk_sil_side s;
    silk_sil_side_attrs(m, t, k, silk_mesh_edge_v0(m, we->edge), &s);
    for (uint32_t j = 0; j < we->npairs; j++) {
        const silk_sil_pair *p = &f->pairs[we->pair0 + j];
        if (p->n0 == s.n0 && p->n1 == s.n1) return;
    }
    silk_sil_pair *p = &f->pairs[we->pair0 + we->npairs++];
    p->n0 = s.n0;
    p->n1 = s.n1;
}

/* One silhouette point per distinct normal pair on each edge a silhouette
 * triangle's silhouette side lies on. */
static void fill_pairs(silk_sil_frame *f)
{
    const silk_mesh *m = f->m;
    if (SILK_PLAN_BY_EDGES && by_edges(m)) {   /* the same points in the same order, edge by edge */
        for (uint32_t w = 0; w < f->nedges; w++) {
            silk_sil_edge *we = &f->edges[w];
            uint32_t tt[2];
            for (uint32_t i = 0, n = edge_tris(f, we->edge, tt); i < n; i++) {
                uint8_t st = f->tri_state[tt[i]];
                if (!(st & SILK_TS_SIL)) continue;
                uint32_t lone = st & SILK_TS_LONE;
                for (uint32_t k = 0; k < 3; k++)
                    if ((k == lone || k == (lone + 2) % 3) && m->tri_edge[3 * (size_t)tt[i] + k] == we->edge)
                        add_pair(f, tt[i], k, we);
            }
        }
        return;
    }
    for (uint32_t t = 0; t < m->ntris; t++) {
        uint8_t st = f->tri_state[t];
        if (!(st & SILK_TS_SIL)) continue;
        uint32_t lone = st & SILK_TS_LONE;
        for (uint32_t k = 0; k < 3; k++) {
            if (k != lone && k != (lone + 2) % 3) continue;
            add_pair(f, t, k, &f->edges[silk_sil_slot(f, silk_mesh_tri_edge(m, t, k))]);
        }
    }
}

/* Per edge: its curve, its silhouette points (eqs. 6-7), its feature
 * sampling (eq. 8), then the chain of all its parameters. */
static silk_status chain_points(silk_sil_frame *f)
{
    const silk_mesh *m = f->m;
    const silk_view *v = f->v;
    silk_arena *a = f->a;
    uint32_t nwork = f->nedges;
    /* Per edge: its curve, its silhouette points (eqs. 6-7), its feature
     * sampling (eq. 8), then the chain of all its parameters. */
    uint32_t nchain = 0;
    for (uint32_t w = 0; w < nwork; w++) {
        silk_sil_edge *we = &f->edges[w];
        silk_index ev[2];
        silk_mesh_edge_ends(m, we->edge, ev);
        silk_vec3 d0 = silk_view_to_eye(v, silk_mesh_pos(m, ev[0])), d1 = silk_view_to_eye(v, silk_mesh_pos(m, ev[1]));
        for (uint32_t i = 0; i < we->npairs; i++) {
            silk_sil_pair *p = &f->pairs[we->pair0 + i];
            p->u = silk_fx_clamp(silk_silhouette_param(silk_mesh_normal(m, p->n0), d0, silk_mesh_normal(m, p->n1), d1),
                                 0, SILK_FX_ONE);
        }
        we->nfeat = 0;
        if (we->sampled && !(silk_mesh_edge_flags(m, we->edge) & SILK_EDGE_DEGENERATE)) {   /* at most SILK_MAX_SAMPLES */
            silk_curve c;   /* only a sampled edge's tangents are needed here */
            silk_sil_edge_curve(f, we, &c);
            we->nfeat = (uint8_t)silk_sil_intervals(v, &c, unit_dot(c.t0, c.t1), f->tol);
        }
        nchain += (we->nfeat > 1 ? we->nfeat - 1 : 0) + we->npairs;
    }
    if (nchain >= SILK_PLAN_NONE) return SILK_ERR_NOMEM;   /* chain0 could not index them */
    f->chain = silk_arena_array_top(a, nchain, sizeof *f->chain, SILK_MEM_FRAME);
    if (!f->chain) return SILK_ERR_NOMEM;
    nchain = 0;
    for (uint32_t w = 0; w < nwork; w++) {
        silk_sil_edge *we = &f->edges[w];
        silk_fx *c = &f->chain[nchain];
        uint32_t n = 0;
        for (uint32_t i = 1; i < we->nfeat; i++)
            c[n++] = silk_sample_param(i, we->nfeat);
        for (uint32_t i = 0; i < we->npairs; i++) chain_insert(c, &n, f->pairs[we->pair0 + i].u);
        we->chain0 = (silk_plan_index)nchain;
        we->nchain = (uint16_t)n;
        nchain += n;
    }
    f->nchain = nchain;
    return SILK_OK;
}

silk_status silk_sil_find(silk_sil_frame *f)
{
    /* the plan keeps vertex, normal, uv and edge indices in 16 bits
     * (SILK_PLAN_INDEX16): at most 65 535 of each, so that none is
     * SILK_PLAN_NONE */
    const silk_mesh *m = f->m;
    if (SILK_PLAN_INDEX16 && (m->nverts | m->nnormals | m->nuvs | silk_mesh_edge_bound(m)) >> 16) return SILK_ERR_NOMEM;
    memset(f->cur, 0, sizeof *f->cur);   /* nothing asked yet */
    silk_status st = find_triangles(f);
    if (st == SILK_OK) st = lay_out_edges(f);
    if (st != SILK_OK) return st;
    fill_pairs(f);
    return chain_points(f);
}
