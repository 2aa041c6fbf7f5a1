/*
 * compact.c - the compact packed model (silk/compact.h, docs/formats.md
 * "Compact models"): checking one once, then reading any element of it in
 * place, for every stage, through the accessors of silk/mesh.h.
 *
 * The connectivity is a corner table (J. Rossignac, "3D compression made
 * simple: Edgebreaker with ZipandWrap on a corner-table", 2001): each side
 * of a triangle stores the triangle across it.  Edges, a triangle's edges
 * and the edges around a vertex all follow from it:
 *   - the side (t, k) joins corners k and k+1; its edge belongs to t when
 *     no triangle, or a higher one, lies across, and is numbered 3t + k
 *     after that side (so not every number below 3 ntris is an edge:
 *     silk_mesh_edge_bound);
 *   - the edges at a vertex are found by turning about it, side by side,
 *     from the first triangle that uses it (VFIRST, then a short scan).
 * Every field is a fixed-width bit field, so nothing is decoded that a
 * caller did not ask for, and nothing is copied to RAM.
 */
#include <string.h>
#include "silk/compact.h"
#include "silk/model.h"
#include "compiler.h"
#include "curve.h"
#include "mesh_build.h"

#define BAD(...) silk_fail(err, SILK_ERR_PARSE, name, 0, __VA_ARGS__)
#define UL(x) ((unsigned long)(x))
#define VFIRST_BLOCK 8    /* vertices a VFIRST entry covers */

/* ---- bit fields ----------------------------------------------------------------- */

SILK_ALWAYS_INLINE static inline uint32_t rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Value i of width w (0..24) of the bit array at a.  Reads four bytes: the
 * model ends with four zero bytes, so the last field of the last array is
 * read inside it too. */
SILK_ALWAYS_INLINE static inline uint32_t field(const uint8_t *a, uint32_t i, unsigned w)
{
    uint32_t b = i * w;
    return (rd32(a + (b >> 3)) >> (b & 7)) & ((1u << w) - 1u);
}

/* A record field: w bits (0..24) from bit b of the array at a. */
SILK_ALWAYS_INLINE static inline uint32_t bits_from(const uint8_t *a, uint32_t b, unsigned w)
{
    return (rd32(a + (b >> 3)) >> (b & 7)) & ((1u << w) - 1u);
}

#define PK(m) (&(m)->packed)
#define ARR(m, f) ((m)->packed.base + (m)->packed.f)
static uint32_t none_tri(const silk_mesh_packed *p) { return (1u << p->tri_bits) - 1u; }

/* ---- vectors -------------------------------------------------------------------- */

silk_vec3 silk_compact_octa(uint32_t u, uint32_t v, unsigned bits)
{
    int32_t M = (int32_t)((1u << bits) - 1u), X = 2 * (int32_t)u - M, Y = 2 * (int32_t)v - M;
    int32_t ax = X < 0 ? -X : X, ay = Y < 0 ? -Y : Y, Z = M - ax - ay;
    if (Z < 0) {
        int32_t fx = M - ay, fy = M - ax;
        X = X < 0 ? -fx : fx;
        Y = Y < 0 ? -fy : fy;
    }
    unsigned s = 30 - bits;   /* |X|, |Y|, |Z| <= M < 2^bits */
    silk_vec3 n;
    silk_v3_normalize(silk_v3(X * (1 << s), Y * (1 << s), Z * (1 << s)), &n);
    return n;
}

silk_vec3 silk_packed_pos(const silk_mesh *m, silk_index v)
{
    const silk_mesh_packed *p = PK(m);
    const uint8_t *a = ARR(m, pos);
    uint32_t i = 3 * v;
    return silk_v3(p->org.x + (silk_fx)(field(a, i, p->pos_bits) << p->pos_shift),
                   p->org.y + (silk_fx)(field(a, i + 1, p->pos_bits) << p->pos_shift),
                   p->org.z + (silk_fx)(field(a, i + 2, p->pos_bits) << p->pos_shift));
}

silk_vec3 silk_packed_normal(const silk_mesh *m, silk_index n)
{
    const uint8_t *a = ARR(m, nrm);
    unsigned w = PK(m)->nrm_bits;
    return silk_compact_octa(field(a, 2 * n, w), field(a, 2 * n + 1, w), w);
}

#if !SILK_INLINE_ACCESS
/* silk/mesh.h's accessors as calls (SILK_INLINE_ACCESS 0). */
silk_vec3 silk_mesh_pos(const silk_mesh *m, silk_index v) { return m->packed.base ? silk_packed_pos(m, v) : m->pos[v]; }
silk_vec3 silk_mesh_normal(const silk_mesh *m, silk_index n)
{
    return m->packed.base ? silk_packed_normal(m, n) : m->normal[n];
}
silk_index silk_mesh_corner(const silk_mesh *m, uint32_t c)
{
    return m->packed.base ? silk_packed_corner(m, c) : m->tri[c];
}
silk_index silk_mesh_corner_normal(const silk_mesh *m, uint32_t c)
{
    return m->packed.base ? silk_packed_corner_normal(m, c) : m->tri_normal[c];
}
silk_index silk_mesh_normal_vertex(const silk_mesh *m, silk_index n)
{
    return m->packed.base ? silk_packed_normal_vertex(m, n) : m->normal_vertex[n];
}
silk_edge silk_mesh_edge(const silk_mesh *m, silk_index e) { return m->packed.base ? silk_packed_edge(m, e) : m->edge[e]; }
void silk_mesh_edge_ends(const silk_mesh *m, silk_index e, silk_index v[2])
{
    if (m->packed.base) {
        silk_packed_edge_ends(m, e, v);
    } else {
        v[0] = m->edge[e].v[0];
        v[1] = m->edge[e].v[1];
    }
}
void silk_mesh_edge_tris(const silk_mesh *m, silk_index e, silk_index t[2])
{
    if (m->packed.base) {
        silk_packed_edge_tris(m, e, t);
    } else {
        t[0] = m->edge[e].t[0];
        t[1] = m->edge[e].t[1];
    }
}
uint8_t silk_mesh_edge_flags(const silk_mesh *m, silk_index e)
{
    return m->packed.base ? silk_packed_edge_flags(m, e) : m->edge[e].flags;
}
#endif

/* ---- vertices and their normals ------------------------------------------------- */

/* The bits of n (at least 1). */
static unsigned width_of(uint32_t n)
{
    unsigned w = 1;
    while (w < 32 && (n >> w)) w++;
    return w;
}

/* EXTRA entries below vertex v (EXTRA is non-decreasing): XPRE's count
 * for v's block of 8, then the few entries of the block's vertices. */
static uint32_t extra_below(const silk_mesh *m, silk_index v)
{
    const silk_mesh_packed *p = PK(m);
    const uint8_t *a = ARR(m, extra);
    uint32_t i = field(ARR(m, xpre), v / VFIRST_BLOCK, width_of(p->nextra));
    while (i < p->nextra && field(a, i, p->vtx_bits) < v) i++;
    return i;
}

silk_index silk_packed_corner(const silk_mesh *m, uint32_t c)
{
    return field(ARR(m, corner), c, PK(m)->vtx_bits);
}

silk_index silk_packed_corner_normal(const silk_mesh *m, uint32_t c)
{
    const silk_mesh_packed *p = PK(m);
    silk_index v = field(ARR(m, corner), c, p->vtx_bits);
    uint32_t s = p->nextra ? field(ARR(m, sel), c, p->sel_bits) : 0;
    /* a vertex's first normal has its index; the others follow them all */
    return s ? m->nverts + extra_below(m, v) + s - 1 : v;
}

silk_index silk_packed_normal_vertex(const silk_mesh *m, silk_index n)
{
    return n < m->nverts ? n : field(ARR(m, extra), n - m->nverts, PK(m)->vtx_bits);
}

/* ---- the corner table ----------------------------------------------------------- */

static uint32_t next3(uint32_t k) { return k == 2 ? 0 : k + 1; }

/* The triangle across side k of t, or none_tri. */
static uint32_t opp(const silk_mesh *m, uint32_t t, uint32_t k)
{
    return field(ARR(m, opp), 3 * t + k, PK(m)->tri_bits);
}

/* The side of triangle t joining vertices a and b (either way round). */
static uint32_t side_of(const silk_mesh *m, uint32_t t, silk_index a, silk_index b)
{
    for (uint32_t k = 0; k < 3; k++) {
        silk_index p = silk_packed_corner(m, 3 * t + k), q = silk_packed_corner(m, 3 * t + next3(k));
        if ((p == a && q == b) || (p == b && q == a)) return k;
    }
    return 0;   /* not reached in a checked model */
}

silk_index silk_packed_tri_edge(const silk_mesh *m, uint32_t t, uint32_t k)
{
    if (!m->nedges) return SILK_NO_INDEX;   /* a model for flat frames only */
    uint32_t o = opp(m, t, k);
    if (o == none_tri(PK(m)) || o > t) return 3 * t + k;   /* the edge is this side */
    silk_index a = silk_packed_corner(m, 3 * t + k), b = silk_packed_corner(m, 3 * t + next3(k));
    return 3 * o + side_of(m, o, a, b);
}

/* LIST: the bit offset of the record of edge e, or UINT32_MAX. */
static uint32_t listed(const silk_mesh *m, silk_index e)
{
    const silk_mesh_packed *p = PK(m);
    const uint8_t *a = ARR(m, list);
    uint32_t lo = 0, hi = p->nlisted;
    while (lo < hi) {
        uint32_t mid = (lo + hi) >> 1, f = bits_from(a, mid * p->list_bits, p->edge_bits);
        if (f == e) return mid * p->list_bits;
        if (f < e) lo = mid + 1;
        else hi = mid;
    }
    return UINT32_MAX;
}

/* LIST's three flag bits, as enum silk_edge_flag. */
static uint8_t list_flags(uint32_t x)
{
    return (uint8_t)((x & 1u ? SILK_EDGE_CREASE : 0) | (x & 2u ? SILK_EDGE_GROUPS : 0) |
                     (x & 4u ? SILK_EDGE_DEGENERATE : 0));
}

void silk_packed_edge_ends(const silk_mesh *m, silk_index e, silk_index v[2])
{
    uint32_t t = e / 3, k = e - 3 * t;
    silk_index a = silk_packed_corner(m, 3 * t + k), b = silk_packed_corner(m, 3 * t + next3(k));
    v[0] = a < b ? a : b;
    v[1] = a < b ? b : a;
}

void silk_packed_edge_tris(const silk_mesh *m, silk_index e, silk_index t[2])
{
    uint32_t o = opp(m, e / 3, e % 3);
    t[0] = e / 3;
    t[1] = o == none_tri(PK(m)) ? SILK_NO_INDEX : o;
}

silk_edge silk_packed_edge(const silk_mesh *m, silk_index e)
{
    uint32_t t = e / 3, k = e - 3 * t;   /* the side that owns it */
    silk_index a = silk_packed_corner(m, 3 * t + k), b = silk_packed_corner(m, 3 * t + next3(k));
    uint32_t o = opp(m, t, k);
    silk_edge ed;
    ed.v[0] = a < b ? a : b;
    ed.v[1] = a < b ? b : a;
    ed.t[0] = t;
    ed.t[1] = o == none_tri(PK(m)) ? SILK_NO_INDEX : o;
    ed.flags = ed.t[1] == SILK_NO_INDEX ? SILK_EDGE_BOUNDARY : 0;
    uint32_t r = PK(m)->nlisted ? listed(m, e) : UINT32_MAX;
    if (r != UINT32_MAX) ed.flags |= list_flags(bits_from(ARR(m, list), r + PK(m)->edge_bits, 3));
    return ed;
}

uint8_t silk_packed_edge_flags(const silk_mesh *m, silk_index e)
{
    /* LIST holds every edge with a flag, boundary ones included */
    return PK(m)->nlisted && listed(m, e) != UINT32_MAX ? silk_packed_edge(m, e).flags : 0;
}

/* The tangent at one end of a LIST record, its straight bit at bit b: the
 * chord, or eq. 4's tangent along the decoded direction.  Apart from its
 * caller, whose frame then stays small: it runs under the curve stages'
 * deepest calls. */
SILK_NOINLINE static silk_vec3 list_end(const silk_mesh *m, uint32_t b, silk_vec3 chord)
{
    const uint8_t *a = ARR(m, list);
    unsigned w = PK(m)->dir_bits;
    if (bits_from(a, b, 1)) return chord;
    return silk_feature_tangent(silk_compact_octa(bits_from(a, b + 1, w), bits_from(a, b + 1 + w, w), w), chord);
}

int silk_compact_feature_seg(const silk_mesh *m, silk_index e, silk_feature_seg *out)
{
    const silk_mesh_packed *p = PK(m);
    uint32_t r = p->nlisted ? listed(m, e) : UINT32_MAX;
    if (r == UINT32_MAX) return 0;
    /* silk_edge_has_feature: a feature flag (a listed boundary edge has one) and a length */
    uint32_t t = e / 3, k = e - 3 * t;
    uint8_t fl = list_flags(bits_from(ARR(m, list), r + p->edge_bits, 3));
    if (opp(m, t, k) == none_tri(p)) fl |= SILK_EDGE_BOUNDARY;
    silk_index v[2];
    silk_packed_edge_ends(m, e, v);
    if (!(fl & SILK_EDGE_FEATURE) || v[0] == v[1]) return 0;
    silk_vec3 chord = silk_v3_sub(silk_packed_pos(m, v[1]), silk_packed_pos(m, v[0]));
    uint32_t b = r + p->edge_bits + 3;
    out->t0 = list_end(m, b, chord);
    out->t1 = list_end(m, b + 1 + 2u * p->dir_bits, chord);
    return 1;
}

/* ---- all edges in order ----------------------------------------------------------- */

/* Edge it->e from its side (it->t, it->k), LIST's flags from the record
 * it->list points at when that record is this edge's. */
static silk_index edges_here(const silk_mesh *m, silk_mesh_edges *it, silk_edge *ed)
{
    const silk_mesh_packed *p = PK(m);
    uint32_t t = it->t, k = it->k, o = opp(m, t, k);
    silk_index a = silk_packed_corner(m, 3 * t + k), b = silk_packed_corner(m, 3 * t + next3(k));
    ed->v[0] = a < b ? a : b;
    ed->v[1] = a < b ? b : a;
    ed->t[0] = t;
    ed->t[1] = o == none_tri(p) ? SILK_NO_INDEX : o;
    ed->flags = ed->t[1] == SILK_NO_INDEX ? SILK_EDGE_BOUNDARY : 0;
    if (it->list < p->nlisted && bits_from(ARR(m, list), it->list * p->list_bits, p->edge_bits) == it->e) {
        ed->flags |= list_flags(bits_from(ARR(m, list), it->list * p->list_bits + p->edge_bits, 3));
        it->list++;
    }
    return it->e;
}

/* Whether side k of t owns its edge: nothing, or a higher triangle, across. */
static int owns(const silk_mesh *m, uint32_t t, uint32_t k)
{
    uint32_t o = opp(m, t, k);
    return o == none_tri(PK(m)) || o > t;
}

/* The first owned side from (t, k) on, into it (e its edge). */
static int edges_seek(const silk_mesh *m, silk_mesh_edges *it, uint32_t t, uint32_t k)
{
    for (; t < m->ntris; t++, k = 0)
        for (; k < 3; k++)
            if (owns(m, t, k)) {
                it->t = t;
                it->k = k;
                it->e = 3 * t + k;
                return 1;
            }
    return 0;
}

silk_index silk_mesh_edges_first(const silk_mesh *m, silk_mesh_edges *it, silk_edge *ed)
{
    memset(it, 0, sizeof *it);
    if (!m->packed.base) {
        if (m->nedges == 0) return SILK_NO_INDEX;
        *ed = m->edge[0];
        return 0;
    }
    if (m->nedges == 0 || !edges_seek(m, it, 0, 0)) return SILK_NO_INDEX;
    return edges_here(m, it, ed);
}

silk_index silk_mesh_edges_next(const silk_mesh *m, silk_mesh_edges *it, silk_edge *ed)
{
    if (!m->packed.base) {
        if (++it->e >= m->nedges) return SILK_NO_INDEX;
        *ed = m->edge[it->e];
        return it->e;
    }
    if (!edges_seek(m, it, it->t, it->k + 1)) return SILK_NO_INDEX;
    return edges_here(m, it, ed);
}

/* ---- turning about a vertex ------------------------------------------------------ */

/* The corner of triangle t at vertex v (3 when there is none). */
static uint32_t corner_at(const silk_mesh *m, uint32_t t, silk_index v)
{
    for (uint32_t k = 0; k < 3; k++)
        if (silk_packed_corner(m, 3 * t + k) == v) return k;
    return 3;
}

/* The first triangle using v: VFIRST's triangle for v's block, then on. */
static uint32_t first_tri(const silk_mesh *m, silk_index v)
{
    for (uint32_t t = field(ARR(m, vfirst), v / VFIRST_BLOCK, PK(m)->tri_bits); t < m->ntris; t++)
        if (corner_at(m, t, v) < 3) return t;
    return 0;   /* not reached in a checked model: every vertex is used */
}

/* Cross side r->side of r->t into the triangle across and leave that one by
 * its other side at r->v.  0 at a boundary or back at the first triangle. */
static int turn(const silk_mesh *m, silk_mesh_ring *r)
{
    uint32_t o = opp(m, r->t, r->side);
    if (o == none_tri(PK(m)) || o == r->t0) return 0;
    /* the vertex of the side crossed that is not v */
    silk_index w = silk_packed_corner(m, 3 * r->t + r->side);
    if (w == r->v) w = silk_packed_corner(m, 3 * r->t + next3(r->side));
    uint32_t j = corner_at(m, o, r->v), prev = j == 0 ? 2 : j - 1;
    /* sides j (v to j+1) and j-1 (j-1 to v); the crossed one holds w */
    r->side = silk_packed_corner(m, 3 * o + next3(j)) == w ? prev : j;
    r->t = o;
    return 1;
}

static silk_index ring_next_packed(const silk_mesh *m, silk_mesh_ring *r)
{
    if (r->phase == 3) return SILK_NO_INDEX;
    if (r->phase == 0) {
        if (turn(m, r)) return silk_packed_tri_edge(m, r->t, r->side);
        if (opp(m, r->t, r->side) == r->t0) {
            r->phase = 3;
            return SILK_NO_INDEX;
        }
        /* a boundary: the sides the other way from the first triangle */
        uint32_t j = corner_at(m, r->t0, r->v);
        r->t = r->t0;
        r->side = j == 0 ? 2 : j - 1;
        r->phase = 1;
        return silk_packed_tri_edge(m, r->t, r->side);
    }
    if (r->phase == 1 && turn(m, r)) return silk_packed_tri_edge(m, r->t, r->side);
    r->phase = 3;
    return SILK_NO_INDEX;
}

silk_index silk_mesh_ring_first(const silk_mesh *m, silk_index v, silk_mesh_ring *r)
{
    memset(r, 0, sizeof *r);
    r->v = v;
    if (!m->packed.base) {
        r->i = m->vert_edge_start[v];
        r->end = m->vert_edge_start[v + 1];
        return r->i < r->end ? m->vert_edge[r->i] : SILK_NO_INDEX;
    }
    if (!m->nedges) {
        r->phase = 3;
        return SILK_NO_INDEX;
    }
    r->t0 = r->t = first_tri(m, v);
    r->side = corner_at(m, r->t, v);
    return silk_packed_tri_edge(m, r->t, r->side);
}

silk_index silk_mesh_ring_next(const silk_mesh *m, silk_mesh_ring *r)
{
    if (!m->packed.base) return ++r->i < r->end ? m->vert_edge[r->i] : SILK_NO_INDEX;
    return ring_next_packed(m, r);
}

/* ---- checking a model ------------------------------------------------------------ */

int silk_is_compact(const void *data, size_t len)
{
    return data && len >= 4 && memcmp(data, SILK_COMPACT_MAGIC, 4) == 0;
}

/* The header's fields and the arrays' places. */
typedef struct layout {
    uint32_t flags, nverts, ntris, nnormals, nedges, nlisted;
    uint64_t end;             /* where the arrays end (the 4 zero bytes follow) */
} layout;

/* Places array n x w bits at the end of the arrays so far. */
static uint32_t place(layout *l, uint64_t n, unsigned w)
{
    uint32_t at = (uint32_t)l->end;
    l->end += (n * w + 7) / 8;
    return at;
}

static silk_status check_header(const uint8_t *d, size_t len, const char *name, silk_mesh_packed *p, layout *l,
                                silk_error *err)
{
    if (len < SILK_COMPACT_HEADER_BYTES + 4)
        return BAD("truncated: %lu bytes, a compact model's header alone is %u", UL(len), SILK_COMPACT_HEADER_BYTES);
    unsigned version = (unsigned)(d[4] | d[5] << 8);
    if (version != SILK_COMPACT_VERSION)
        return BAD("compact model version %u; this silk reads version %u", version, SILK_COMPACT_VERSION);
    if (rd32(d + 48) != len)
        return BAD("the header says %lu bytes, the data has %lu (truncated or padded)", UL(rd32(d + 48)), UL(len));
    if (silk_crc32(0, d + SILK_COMPACT_HEADER_BYTES, len - SILK_COMPACT_HEADER_BYTES) != rd32(d + 52))
        return BAD("checksum mismatch (the model is damaged)");
    l->flags = (uint32_t)(d[6] | d[7] << 8);
    l->nverts = rd32(d + 8);
    l->ntris = rd32(d + 12);
    l->nnormals = rd32(d + 16);
    l->nedges = rd32(d + 20);
    l->nlisted = rd32(d + 24);
    if (l->flags & ~7u) return BAD("unknown flags 0x%lx", UL(l->flags));
    p->org = silk_v3((silk_fx)rd32(d + 28), (silk_fx)rd32(d + 32), (silk_fx)rd32(d + 36));
    p->pos_bits = d[40], p->pos_shift = d[41], p->nrm_bits = d[42], p->sel_bits = d[43];
    p->vtx_bits = d[44], p->tri_bits = d[45], p->edge_bits = d[46], p->dir_bits = d[47];
    if (p->pos_bits < 1 || p->pos_bits > 16 || p->pos_shift > 15 || p->nrm_bits < 2 || p->nrm_bits > 16 ||
        p->sel_bits > 6 || p->vtx_bits < 1 || p->vtx_bits > 24 || p->tri_bits < 1 || p->tri_bits > 24 ||
        p->edge_bits < 1 || p->edge_bits > 24 || p->dir_bits < 2 || p->dir_bits > 16)
        return BAD("field widths out of range (positions %u<<%u, normals %u, selectors %u, vertices %u, "
                   "triangles %u, edges %u, directions %u)",
                   p->pos_bits, p->pos_shift, p->nrm_bits, p->sel_bits, p->vtx_bits, p->tri_bits, p->edge_bits,
                   p->dir_bits);
    const uint32_t lim = (1u << 24) - 1u;
    if (l->nverts < 3 || l->ntris == 0 || l->nverts > lim || l->ntris >= lim || l->nnormals < l->nverts ||
        l->nnormals > lim)
        return BAD("%lu vertices, %lu triangles, %lu normals (3.. vertices, 1.. triangles, a normal a vertex at "
                   "least, all below 2^24)",
                   UL(l->nverts), UL(l->ntris), UL(l->nnormals));
    if ((l->nverts - 1) >> p->vtx_bits) return BAD("%lu vertices do not fit %u-bit indices", UL(l->nverts), p->vtx_bits);
    int adj = (l->flags & SILK_COMPACT_ADJACENCY) != 0;
    if (adj && (uint64_t)l->ntris + 1 >= (1u << p->tri_bits))
        return BAD("%lu triangles do not fit %u-bit indices", UL(l->ntris), p->tri_bits);
    if (adj && (3 * l->ntris - 1) >> p->edge_bits)
        return BAD("the sides of %lu triangles do not fit %u-bit edge indices", UL(l->ntris), p->edge_bits);
    if (adj ? (l->nedges == 0 || l->nedges > 3 * l->ntris || l->nlisted > l->nedges)
            : (l->nedges != 0 || l->nlisted != 0))
        return BAD("%lu edges, %lu listed (%s)", UL(l->nedges), UL(l->nlisted),
                   adj ? "at most a side each, listed ones are edges" : "a model without adjacency has none");
    /* the arrays' places: the 56-byte header, then in the order of silk/compact.h */
    p->nextra = l->nnormals - l->nverts;
    p->nlisted = l->nlisted;
    p->list_bits = (uint8_t)(p->edge_bits + 3 + 2 * (1 + 2 * p->dir_bits));
    l->end = SILK_COMPACT_HEADER_BYTES;
    p->pos = place(l, 3 * (uint64_t)l->nverts, p->pos_bits);
    p->nrm = place(l, 2 * (uint64_t)l->nnormals, p->nrm_bits);
    p->extra = place(l, p->nextra, p->vtx_bits);
    if (p->nextra) p->xpre = place(l, (l->nverts + VFIRST_BLOCK - 1) / VFIRST_BLOCK, width_of(p->nextra));
    p->corner = place(l, 3 * (uint64_t)l->ntris, p->vtx_bits);
    p->sel = place(l, 3 * (uint64_t)l->ntris, p->sel_bits);
    if (adj) {
        p->opp = place(l, 3 * (uint64_t)l->ntris, p->tri_bits);
        p->list = place(l, l->nlisted, p->list_bits);
        p->vfirst = place(l, (l->nverts + VFIRST_BLOCK - 1) / VFIRST_BLOCK, p->tri_bits);
    }
    if (l->end + 4 != len)
        return BAD("the counts and widths make %llu bytes, the model has %lu", (unsigned long long)(l->end + 4),
                   UL(len));
    if (rd32(d + len - 4) != 0) return BAD("the last 4 bytes are not zero");
    int64_t top = (int64_t)((1u << p->pos_bits) - 1u) << p->pos_shift;
    const silk_fx *o = &p->org.x;
    for (int k = 0; k < 3; k++)
        if (o[k] < -SILK_COORD_MAX || (int64_t)o[k] + top > SILK_COORD_MAX)
            return BAD("coordinates may lie outside +-%d model units", (int)(SILK_COORD_MAX >> 16));
    return SILK_OK;
}

/* The bounding box, and that the model is not too small. */
static silk_status check_positions(const silk_mesh *m, const char *name, silk_mesh *out, silk_error *err)
{
    silk_vec3 lo = silk_packed_pos(m, 0), hi = lo;
    for (uint32_t v = 1; v < m->nverts; v++) {
        silk_vec3 q = silk_packed_pos(m, v);
        lo = silk_v3(q.x < lo.x ? q.x : lo.x, q.y < lo.y ? q.y : lo.y, q.z < lo.z ? q.z : lo.z);
        hi = silk_v3(q.x > hi.x ? q.x : hi.x, q.y > hi.y ? q.y : hi.y, q.z > hi.z ? q.z : hi.z);
    }
    silk_vec3 d = silk_v3_sub(hi, lo);
    if ((int64_t)d.x * d.x + (int64_t)d.y * d.y + (int64_t)d.z * d.z < (int64_t)SILK_SIZE_MIN * SILK_SIZE_MIN)
        return BAD("the model is smaller than 1/16 unit across");
    out->bbox_min = lo;
    out->bbox_max = hi;
    return SILK_OK;
}

/* EXTRA in order and in range; corners in range, three different vertices
 * a triangle, vertices numbered in order of first use (all used), VFIRST
 * the first triangle of each block's first vertex; every selector within its
 * vertex's normals. */
static silk_status check_corners(const silk_mesh *m, const char *name, silk_error *err)
{
    const silk_mesh_packed *p = PK(m);
    for (uint32_t i = 0, prev = 0, b = 0; i <= p->nextra; i++) {
        uint32_t v = i < p->nextra ? field(ARR(m, extra), i, p->vtx_bits) : m->nverts;
        if (v > m->nverts || (i < p->nextra && v == m->nverts) || v < prev)
            return BAD("EXTRA entry %lu: vertex %lu out of order or range", UL(i), UL(v));
        /* XPRE: the entries below each block's first vertex */
        for (; p->nextra && b * VFIRST_BLOCK <= v && b < (m->nverts + VFIRST_BLOCK - 1) / VFIRST_BLOCK; b++)
            if (field(ARR(m, xpre), b, width_of(p->nextra)) != i)
                return BAD("XPRE entry %lu is not %lu, the extra normals of the vertices before it", UL(b), UL(i));
        prev = v;
    }
    uint32_t fresh = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        silk_index c[3];
        for (uint32_t k = 0; k < 3; k++) {
            c[k] = silk_packed_corner(m, 3 * t + k);
            if (c[k] > fresh || c[k] >= m->nverts)
                return BAD("triangle %lu: vertex %lu is out of range or not numbered in order of first use",
                           UL(t), UL(c[k]));
            if (c[k] == fresh) {
                if (p->vfirst && fresh % VFIRST_BLOCK == 0 &&
                    field(ARR(m, vfirst), fresh / VFIRST_BLOCK, p->tri_bits) != t)
                    return BAD("VFIRST entry %lu is not triangle %lu, the first to use vertex %lu",
                               UL(fresh / VFIRST_BLOCK), UL(t), UL(fresh));
                fresh++;
            }
            if (p->nextra) {
                uint32_t n = 1 + extra_below(m, c[k] + 1) - extra_below(m, c[k]);
                if (field(ARR(m, sel), 3 * t + k, p->sel_bits) >= n)
                    return BAD("triangle %lu corner %lu: normal %lu of a vertex with %lu", UL(t), UL(k),
                               UL(field(ARR(m, sel), 3 * t + k, p->sel_bits)), UL(n));
            }
        }
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) return BAD("triangle %lu repeats a vertex", UL(t));
    }
    if (fresh != m->nverts) return BAD("vertices %lu.. are used by no triangle", UL(fresh));
    if (!p->nextra)
        for (uint32_t c = 0; c < 3 * m->ntris; c++)
            if (field(ARR(m, sel), c, p->sel_bits) != 0) return BAD("corner %lu: a selector without extra normals", UL(c));
    return SILK_OK;
}

/* The corner table symmetric (the triangle across a side has that side,
 * once, and has this triangle across it), the edges counted, LIST in edge order
 * with every boundary edge in it. */
static silk_status check_adjacency(silk_mesh *m, const char *name, silk_error *err)
{
    const silk_mesh_packed *p = PK(m);
    uint32_t none = none_tri(p), owned = 0, boundary_sides = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        for (uint32_t k = 0; k < 3; k++) {
            uint32_t o = opp(m, t, k);
            if (o == none) {
                boundary_sides++;
                owned++;
                continue;
            }
            silk_index a = silk_packed_corner(m, 3 * t + k), b = silk_packed_corner(m, 3 * t + next3(k));
            uint32_t n = 0, j = 0;
            if (o < m->ntris && o != t)
                for (uint32_t i = 0; i < 3; i++) {
                    silk_index x = silk_packed_corner(m, 3 * o + i), y = silk_packed_corner(m, 3 * o + next3(i));
                    if ((x == a && y == b) || (x == b && y == a)) n++, j = i;
                }
            if (n != 1 || opp(m, o, j) != t)
                return BAD("triangle %lu side %lu: triangle %lu across it does not share it back", UL(t), UL(k), UL(o));
            owned += o > t;
        }
    }
    if (owned != m->nedges) return BAD("the corner table has %lu edges, the header says %lu", UL(owned), UL(m->nedges));
    uint32_t listed_boundary = 0, features = 0;
    for (uint32_t i = 0, prev = 0; i < p->nlisted; i++) {
        uint32_t e = bits_from(ARR(m, list), i * p->list_bits, p->edge_bits);
        if (e >= 3 * m->ntris || (i && e <= prev) || !owns(m, e / 3, e % 3))
            return BAD("LIST record %lu: edge %lu out of order, or not a side that owns its edge", UL(i), UL(e));
        prev = e;
        silk_edge ed = silk_packed_edge(m, e);
        listed_boundary += ed.t[1] == SILK_NO_INDEX;
        features += silk_edge_has_feature(&ed);
    }
    if (listed_boundary != boundary_sides)
        return BAD("%lu boundary edges, %lu of them listed (LIST must hold them all)", UL(boundary_sides),
                   UL(listed_boundary));
    m->nboundary_edges = boundary_sides;
    m->nfeature_edges = features;
    return SILK_OK;
}

silk_status silk_compact_mesh(const void *data, size_t len, const char *name, silk_mesh *out, silk_error *err)
{
    const uint8_t *d = data;
    if (!name) name = "model";
    memset(out, 0, sizeof *out);
    if (!silk_is_compact(data, len)) return BAD("not a compact model (no SLKC signature)");
    silk_mesh m;
    memset(&m, 0, sizeof m);
    layout l = { 0 };
    silk_status st = check_header(d, len, name, &m.packed, &l, err);
    if (st != SILK_OK) return st;
    m.packed.base = d;
    m.nverts = l.nverts;
    m.ntris = l.ntris;
    m.nnormals = l.nnormals;
    m.nedges = l.nedges;
    if ((st = check_positions(&m, name, &m, err)) != SILK_OK || (st = check_corners(&m, name, err)) != SILK_OK)
        return st;
    if ((l.flags & SILK_COMPACT_ADJACENCY) && (st = check_adjacency(&m, name, err)) != SILK_OK) return st;
    m.normals_used = (l.flags & SILK_COMPACT_FILE_NORMALS) ? SILK_NORMALS_FILE : SILK_NORMALS_COMPUTE;
    m.closed_outward = (l.flags & SILK_COMPACT_CLOSED) != 0;
    *out = m;
    return SILK_OK;
}
