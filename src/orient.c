/*
 * orient.c - consistent, outward triangle orientation at load.
 *
 * Every later stage takes a triangle's corner order as its facing
 * (counter-clockwise seen from outside, silk/mesh.h): the face normals that
 * weight the shading normals (paper III-B), the front/back test of the
 * silhouette edges (III-C).  Files exported with some or all triangles wound
 * the other way are common, so before the normals are built:
 *
 *   1. Consistency.  Triangles are walked breadth-first across manifold
 *      edges (exactly two triangles, two distinct vertices); two neighbours
 *      agree when they run along their shared edge in opposite directions.
 *      Each component (triangles connected by manifold edges) gets one flip
 *      bit per triangle relative to its first triangle.  A component where
 *      the walk meets a contradiction is non-orientable (a Moebius band) and
 *      is left exactly as the file has it.
 *   2. Outward.  A closed component (none of its edges is a boundary or
 *      non-manifold edge) is turned so that its signed volume
 *      V = 1/6 sum_t (p1 - p0) x (p2 - p0) . (p0 - r)  (divergence theorem,
 *      r any fixed point) is positive.  An open component has no inside: it
 *      keeps the orientation most of its triangles have in the file.
 *
 * When every component is closed and so turned outward, the mesh says so
 * (silk_mesh.closed_outward): seen from outside, a closed surface hides its
 * own back faces, and the renderer skips them.
 *
 * A flipped triangle (a, b, c) becomes (a, c, b), with its uv and file
 * normal corners and its triangle->edge links permuted the same way, so the
 * result is what loading the correctly wound file gives.
 *
 * The volume is exact: with |coordinate| <= 2^26 (Q16.16, SILK_COORD_MAX),
 * each cross product component is below 2^55 and each p0 - r component
 * below 2^27, so each of the three products is below 2^82 and the sum over
 * at most 2^28 triangles below 2^112; it is accumulated as a 128-bit number
 * in two 64-bit words (no floating point, no compiler extension).
 */
#include <string.h>
#include "mesh_build.h"

/* Triangle state in the walk. */
#define VISITED 1u
#define FLIP    2u

/* Signed 128-bit accumulator: hi * 2^64 + lo. */
typedef struct acc128 { uint64_t lo; int64_t hi; } acc128;

/* acc += a * b, for |a| < 2^62 and |b| < 2^31. */
static void acc_add_mul(acc128 *acc, int64_t a, int64_t b)
{
    int neg = (a < 0) != (b < 0);
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    uint64_t p0 = (ua & 0xffffffffu) * ub, p1 = (ua >> 32) * ub;   /* < 2^63, < 2^61 */
    uint64_t lo = p0 + (p1 << 32);
    uint64_t hi = (p1 >> 32) + (lo < p0);
    if (neg) {                                     /* two's complement of (hi, lo) */
        lo = ~lo + 1;
        hi = ~hi + (lo == 0);
    }
    uint64_t s = acc->lo + lo;
    acc->hi = (int64_t)((uint64_t)acc->hi + hi + (s < lo));
    acc->lo = s;
}

static int acc_sign(const acc128 *acc)
{
    if (acc->hi != 0) return acc->hi < 0 ? -1 : 1;
    return acc->lo != 0;
}

/* 1 when triangle t runs along edge e from e.v[0] to e.v[1]. */
static int runs_forward(const silk_mesh *m, uint32_t t, uint32_t e)
{
    for (int k = 0; k < 3; k++)
        if (m->tri_edge[3 * t + k] == e) return m->tri[3 * t + k] == m->edge[e].v[0];
    return 0;
}

static int repeats_vertex(const silk_mesh *m, uint32_t t)
{
    const silk_index *v = &m->tri[3 * t];
    return v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
}

/* The other triangle of a manifold edge e of t, or SILK_NO_INDEX. */
static uint32_t across(const silk_mesh *m, uint32_t t, uint32_t e)
{
    const silk_edge *ed = &m->edge[e];
    if ((ed->flags & (SILK_EDGE_BOUNDARY | SILK_EDGE_NONMANIFOLD)) || ed->v[0] == ed->v[1] ||
        ed->t[1] == SILK_NO_INDEX)
        return SILK_NO_INDEX;
    uint32_t u = ed->t[0] == t ? ed->t[1] : ed->t[0];
    return repeats_vertex(m, u) ? SILK_NO_INDEX : u;
}

static void swap_idx(silk_index *a, silk_index *b)
{
    silk_index t = *a;
    *a = *b;
    *b = t;
}

/* (a, b, c) -> (a, c, b): edges (a,b), (b,c), (c,a) become (a,c), (c,b),
 * (b,a), i.e. old links 2, 1, 0.  Corner arrays that are the same array as
 * tri (PLY shares its indices) are swapped once. */
static void flip_triangle(silk_mesh *m, const silk_mesh_input *in, uint32_t t)
{
    swap_idx(&m->tri[3 * t + 1], &m->tri[3 * t + 2]);
    swap_idx(&m->tri_edge[3 * t], &m->tri_edge[3 * t + 2]);
    if (in->tri_uv && in->tri_uv != in->tri) swap_idx(&in->tri_uv[3 * t + 1], &in->tri_uv[3 * t + 2]);
    if (in->tri_file_normal && in->tri_file_normal != in->tri && in->tri_file_normal != in->tri_uv)
        swap_idx(&in->tri_file_normal[3 * t + 1], &in->tri_file_normal[3 * t + 2]);
}

silk_status silk_orient(const silk_mesh_input *in, const char *name, silk_arena *a, silk_mesh *m, silk_error *err)
{
    uint32_t nt = m->ntris;
    uint8_t *state = silk_arena_array_top(a, nt, sizeof *state, SILK_MEM_LOAD);
    uint32_t *queue = silk_arena_array_top(a, nt, sizeof *queue, SILK_MEM_LOAD);
    if (!state || !queue)
        return silk_fail(err, SILK_ERR_NOMEM, name, 0,
                         "out of arena memory for orienting the triangles (%lu bytes requested, %lu free)",
                         (unsigned long)a->failed_request, (unsigned long)silk_arena_free_bytes(a));
    memset(state, 0, nt);

    uint32_t qn = 0;
    int all_outward = nt > 0;   /* every component closed and now turned outward */
    for (uint32_t seed = 0; seed < nt; seed++) {
        if (state[seed] & VISITED) continue;
        uint32_t start = qn;
        int consistent = 1, closed = 1;
        state[seed] = VISITED;
        queue[qn++] = seed;
        for (uint32_t h = start; h < qn; h++) {
            uint32_t t = queue[h];
            if (repeats_vertex(m, t)) { closed = 0; continue; }
            for (int k = 0; k < 3; k++) {
                uint32_t e = m->tri_edge[3 * t + k], u = across(m, t, e);
                if (u == SILK_NO_INDEX) { closed = 0; continue; }
                /* Agreeing neighbours run along e in opposite directions. */
                unsigned want = (state[t] & FLIP) ^ (runs_forward(m, t, e) == runs_forward(m, u, e) ? FLIP : 0);
                if (!(state[u] & VISITED)) {
                    state[u] = (uint8_t)(VISITED | want);
                    queue[qn++] = u;
                } else if ((state[u] & FLIP) != want) {
                    consistent = 0;
                }
            }
        }
        uint32_t n = qn - start, flips = 0;
        if (!consistent) {
            for (uint32_t h = start; h < qn; h++) state[queue[h]] = VISITED;
            m->nnonorientable_tris += n;
            all_outward = 0;
            continue;
        }
        for (uint32_t h = start; h < qn; h++) flips += (state[queue[h]] & FLIP) != 0;
        int sign = 0;
        if (closed) {
            acc128 vol = { 0, 0 };
            silk_vec3 r = m->pos[m->tri[3 * seed]];
            for (uint32_t h = start; h < qn; h++) {
                uint32_t t = queue[h];
                int64_t c[3];
                silk_vec3 p = m->pos[m->tri[3 * t]];
                silk_tri_cross64(m, t, c);
                if (state[t] & FLIP) c[0] = -c[0], c[1] = -c[1], c[2] = -c[2];
                acc_add_mul(&vol, c[0], (int64_t)p.x - r.x);
                acc_add_mul(&vol, c[1], (int64_t)p.y - r.y);
                acc_add_mul(&vol, c[2], (int64_t)p.z - r.z);
            }
            sign = acc_sign(&vol);
        }
        /* Inside out, or (open, or of no volume) mostly wound the other way. */
        int invert = sign < 0 || (sign == 0 && 2 * (uint64_t)flips > n);
        if (sign == 0) all_outward = 0;
        for (uint32_t h = start; h < qn; h++) {
            uint32_t t = queue[h];
            if (((state[t] & FLIP) != 0) != invert) {
                flip_triangle(m, in, t);
                m->nreoriented_tris++;
            }
        }
    }
    m->closed_outward = (uint8_t)all_outward;
    return SILK_OK;
}
