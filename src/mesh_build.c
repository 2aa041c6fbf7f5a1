/*
 * mesh_build.c - the loaders' common back end: from positions and triangles
 * to the adjacency every later stage walks.
 *
 * Builds the unique undirected edges (two stable counting sorts of the
 * half-edges, so the result and the "first two triangles" of an edge depend
 * only on the input order), the triangle->edge and vertex->edge links, the
 * BOUNDARY / NONMANIFOLD / DEGENERATE flags and the bounding box, then hands
 * over to orient.c (consistent, outward winding), normals.c (crease flags
 * and split shading normals, paper III-B) and features.c (feature
 * segments, paper III-A, eqs. 1 and 4).
 *
 * A zero-length edge (a triangle that repeats an index) is kept, so that
 * every triangle has three valid tri_edge links; it has v[0] == v[1] and
 * only the DEGENERATE flag, and is never a feature edge.
 */
#include <string.h>
#include "mesh_build.h"

/* Keeps every per-vertex sum of angle-weighted normals (at most pi * 2^16
 * per corner, in Q32.32) far inside int64, and corner numbers in uint32. */
#define MAX_TRIS (1u << 28)

static silk_status nomem(silk_error *err, const char *name, const silk_arena *a, const char *what)
{
    return silk_fail(err, SILK_ERR_NOMEM, name, 0,
                     "out of arena memory for %s (%lu bytes requested, %lu free)", what,
                     (unsigned long)a->failed_request, (unsigned long)silk_arena_free_bytes(a));
}

void silk_tri_cross64(const silk_mesh *m, uint32_t t, int64_t c[3])
{
    silk_vec3 p0 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t)), p1 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + 1)),
              p2 = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + 2));
    int64_t ax = (int64_t)p1.x - p0.x, ay = (int64_t)p1.y - p0.y, az = (int64_t)p1.z - p0.z;
    int64_t bx = (int64_t)p2.x - p0.x, by = (int64_t)p2.y - p0.y, bz = (int64_t)p2.z - p0.z;
    c[0] = ay * bz - az * by;
    c[1] = az * bx - ax * bz;
    c[2] = ax * by - ay * bx;
}

static uint64_t abs64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

int silk_v3_normalize64(const int64_t v[3], silk_vec3 *out)
{
    uint64_t big = abs64(v[0]);
    if (abs64(v[1]) > big) big = abs64(v[1]);
    if (abs64(v[2]) > big) big = abs64(v[2]);
    int s = 0;
    while ((big >> s) >= ((uint64_t)1 << 30)) s++;
    silk_vec3 w;
    if (s == 0) {
        w = silk_v3((silk_fx)v[0], (silk_fx)v[1], (silk_fx)v[2]);
    } else {
        w = silk_v3((silk_fx)silk_shr_round64(v[0], s), (silk_fx)silk_shr_round64(v[1], s),
                    (silk_fx)silk_shr_round64(v[2], s));
    }
    *out = silk_v3(0, 0, 0);
    if (big == 0) return 0;
    return silk_v3_normalize(w, out);
}

silk_index silk_mesh_find_edge(const silk_mesh *m, silk_index a, silk_index b)
{
    silk_index lo = a < b ? a : b, hi = a < b ? b : a;
    if (hi >= m->nverts) return SILK_NO_INDEX;
    for (uint32_t i = m->vert_edge_start[lo]; i < m->vert_edge_start[lo + 1]; i++) {
        silk_index e = m->vert_edge[i];
        if (e < m->nedges && m->edge[e].v[0] == lo && m->edge[e].v[1] == hi) return e;
    }
    return SILK_NO_INDEX;
}

silk_vec3 silk_mesh_face_normal(const silk_mesh *m, uint32_t t)
{
    silk_vec3 n = silk_v3(0, 0, 0);
    int64_t c[3];
    if (!m || t >= m->ntris) return n;
    uint32_t a = silk_mesh_corner(m, 3 * t), b = silk_mesh_corner(m, 3 * t + 1), d = silk_mesh_corner(m, 3 * t + 2);
    if (a == b || b == d || a == d) return n;
    silk_tri_cross64(m, t, c);
    silk_v3_normalize64(c, &n);
    return n;
}

/* ---- input checks ------------------------------------------------------------ */

static silk_status check_input(const silk_mesh_input *in, const char *name, silk_error *err)
{
    if (in->ntris == 0 || !in->tri)
        return silk_fail(err, SILK_ERR_EMPTY, name, 0, "no triangles");
    if (in->nverts == 0 || !in->pos)
        return silk_fail(err, SILK_ERR_EMPTY, name, 0, "no vertices");
    if (in->ntris > MAX_TRIS)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "%lu triangles is more than the %lu supported",
                         (unsigned long)in->ntris, (unsigned long)MAX_TRIS);
    /* Vertex and triangle numbers must fit silk_index below its SILK_NO_INDEX
     * marker (so must the edge and normal counts, checked once known). */
    if ((uint64_t)in->nverts >= (uint64_t)SILK_NO_INDEX || (uint64_t)in->ntris >= (uint64_t)SILK_NO_INDEX)
        return silk_fail(err, SILK_ERR_RANGE, name, 0,
                         "%lu vertices / %lu triangles do not fit the %u-byte vertex index",
                         (unsigned long)in->nverts, (unsigned long)in->ntris, (unsigned)sizeof(silk_index));
    for (uint32_t v = 0; v < in->nverts; v++) {
        silk_vec3 p = in->pos[v];
        if (silk_fx_abs(p.x) > SILK_COORD_MAX || silk_fx_abs(p.y) > SILK_COORD_MAX ||
            silk_fx_abs(p.z) > SILK_COORD_MAX) {
            char bx[16], by[16], bz[16];
            return silk_fail(err, SILK_ERR_RANGE, name, 0,
                             "vertex %lu (%s %s %s) is outside the fixed-point range (+-1024)",
                             (unsigned long)v + 1, silk_fx_format(p.x, bx), silk_fx_format(p.y, by),
                             silk_fx_format(p.z, bz));
        }
    }
    for (uint32_t c = 0; c < 3 * in->ntris; c++) {
        if (in->tri[c] >= in->nverts)
            return silk_fail(err, SILK_ERR_ARG, name, 0, "triangle %lu uses vertex %lu (%lu vertices)",
                             (unsigned long)(c / 3) + 1, (unsigned long)in->tri[c] + 1,
                             (unsigned long)in->nverts);
        if (in->tri_uv && in->uv && in->tri_uv[c] >= in->nuvs)
            return silk_fail(err, SILK_ERR_ARG, name, 0,
                             "triangle %lu uses texture coordinate %lu (%lu given)",
                             (unsigned long)(c / 3) + 1, (unsigned long)in->tri_uv[c] + 1,
                             (unsigned long)in->nuvs);
        if (in->tri_file_normal && in->tri_file_normal[c] != SILK_NO_INDEX &&
            (!in->file_normal || in->tri_file_normal[c] >= in->nfile_normals))
            return silk_fail(err, SILK_ERR_ARG, name, 0, "triangle %lu uses normal %lu (%lu given)",
                             (unsigned long)(c / 3) + 1, (unsigned long)in->tri_file_normal[c] + 1,
                             (unsigned long)in->nfile_normals);
    }
    return SILK_OK;
}

/* ---- edges ------------------------------------------------------------------- */

static silk_index half_lo(const silk_index *tri, uint32_t h)
{
    silk_index a = tri[h], b = tri[h - h % 3 + (h % 3 + 1) % 3];
    return a < b ? a : b;
}
static silk_index half_hi(const silk_index *tri, uint32_t h)
{
    silk_index a = tri[h], b = tri[h - h % 3 + (h % 3 + 1) % 3];
    return a < b ? b : a;
}

/* Half-edge h = 3t+k runs from corner k to corner (k+1)%3 of triangle t.
 * Sorting the half-edges by (lo, hi) with two stable counting sorts (by hi,
 * then by lo) puts the copies of each undirected edge next to each other,
 * in triangle order: linear time, no comparisons, no recursion. */
static silk_status build_edges(const char *name, silk_arena *a, silk_mesh *m, silk_error *err)
{
    uint32_t nh = 3 * m->ntris, nv = m->nverts;
    uint32_t *count = silk_arena_array_top(a, (size_t)nv + 1, sizeof *count, SILK_MEM_LOAD);
    uint32_t *by_hi = silk_arena_array_top(a, nh, sizeof *by_hi, SILK_MEM_LOAD);
    uint32_t *sorted = silk_arena_array_top(a, nh, sizeof *sorted, SILK_MEM_LOAD);
    if (!count || !by_hi || !sorted) return nomem(err, name, a, "sorting edges");

    for (uint32_t h = 0; h < nh; h++) count[half_hi(m->tri, h) + 1]++;
    for (uint32_t v = 0; v < nv; v++) count[v + 1] += count[v];
    for (uint32_t h = 0; h < nh; h++) by_hi[count[half_hi(m->tri, h)]++] = h;

    memset(count, 0, ((size_t)nv + 1) * sizeof *count);
    for (uint32_t h = 0; h < nh; h++) count[half_lo(m->tri, h) + 1]++;
    for (uint32_t v = 0; v < nv; v++) count[v + 1] += count[v];
    for (uint32_t i = 0; i < nh; i++) {
        uint32_t h = by_hi[i];
        sorted[count[half_lo(m->tri, h)]++] = h;
    }

    uint32_t ne = 0;
    for (uint32_t i = 0; i < nh; i++)
        if (i == 0 || half_lo(m->tri, sorted[i]) != half_lo(m->tri, sorted[i - 1]) ||
            half_hi(m->tri, sorted[i]) != half_hi(m->tri, sorted[i - 1]))
            ne++;
    if ((uint64_t)ne >= (uint64_t)SILK_NO_INDEX)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "%lu edges do not fit the %u-byte vertex index",
                         (unsigned long)ne, (unsigned)sizeof(silk_index));
    m->nedges = ne;
    m->edge = silk_arena_array(a, ne, sizeof *m->edge, SILK_MEM_ADJACENCY);
    m->tri_edge = silk_arena_array(a, nh, sizeof *m->tri_edge, SILK_MEM_ADJACENCY);
    if (!m->edge || !m->tri_edge) return nomem(err, name, a, "the edge list");

    uint32_t e = 0, i = 0;
    while (i < nh) {
        silk_index lo = half_lo(m->tri, sorted[i]), hi = half_hi(m->tri, sorted[i]);
        silk_edge *ed = &m->edge[e];
        uint32_t ntri = 0, last_t = UINT32_MAX;
        ed->v[0] = lo;
        ed->v[1] = hi;
        ed->t[0] = ed->t[1] = SILK_NO_INDEX;
        for (; i < nh && half_lo(m->tri, sorted[i]) == lo && half_hi(m->tri, sorted[i]) == hi; i++) {
            uint32_t h = sorted[i], t = h / 3;
            m->tri_edge[h] = e;
            /* A triangle that repeats an index has two sides on one edge;
             * it counts once. Copies arrive in triangle order. */
            if (t == last_t) continue;
            last_t = t;
            if (ntri < 2) ed->t[ntri] = t;
            ntri++;
        }
        if (lo == hi) ed->flags = SILK_EDGE_DEGENERATE;
        else if (ntri == 1) ed->flags = SILK_EDGE_BOUNDARY;
        else if (ntri > 2) ed->flags = SILK_EDGE_NONMANIFOLD;
        e++;
    }
    return SILK_OK;
}

static void mark_degenerate(silk_mesh *m)
{
    for (uint32_t t = 0; t < m->ntris; t++) {
        const silk_index *v = &m->tri[3 * t];
        int64_t c[3] = { 0, 0, 0 };
        if (v[0] != v[1] && v[1] != v[2] && v[0] != v[2]) silk_tri_cross64(m, t, c);
        if (c[0] == 0 && c[1] == 0 && c[2] == 0) {
            m->ndegenerate_tris++;
            for (int k = 0; k < 3; k++) m->edge[m->tri_edge[3 * t + k]].flags |= SILK_EDGE_DEGENERATE;
        }
    }
}

static silk_status build_vertex_edges(const char *name, silk_arena *a, silk_mesh *m, silk_error *err)
{
    uint32_t nv = m->nverts;
    m->vert_edge_start = silk_arena_array(a, (size_t)nv + 1, sizeof *m->vert_edge_start, SILK_MEM_ADJACENCY);
    if (!m->vert_edge_start) return nomem(err, name, a, "the vertex-edge links");
    silk_index *start = m->vert_edge_start;
    uint64_t ends = 0;
    for (uint32_t e = 0; e < m->nedges; e++) ends += m->edge[e].v[1] != m->edge[e].v[0] ? 2 : 1;
    if (ends >= SILK_NO_INDEX)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "%lu edge ends do not fit silk_index (%lu bits)",
                         (unsigned long)ends, (unsigned long)(8 * sizeof(silk_index)));
    for (uint32_t e = 0; e < m->nedges; e++) {
        start[m->edge[e].v[0] + 1]++;
        if (m->edge[e].v[1] != m->edge[e].v[0]) start[m->edge[e].v[1] + 1]++;
    }
    for (uint32_t v = 0; v < nv; v++) start[v + 1] += start[v];
    m->vert_edge = silk_arena_array(a, start[nv], sizeof *m->vert_edge, SILK_MEM_ADJACENCY);
    uint32_t *fill = silk_arena_array_top(a, nv, sizeof *fill, SILK_MEM_LOAD);
    if (!m->vert_edge || !fill) return nomem(err, name, a, "the vertex-edge links");
    for (uint32_t e = 0; e < m->nedges; e++) {
        silk_index v0 = m->edge[e].v[0], v1 = m->edge[e].v[1];
        m->vert_edge[start[v0] + fill[v0]++] = e;
        if (v1 != v0) m->vert_edge[start[v1] + fill[v1]++] = e;
    }
    return SILK_OK;
}

static void bounding_box(silk_mesh *m)
{
    silk_vec3 lo = m->pos[0], hi = m->pos[0];
    for (uint32_t v = 1; v < m->nverts; v++) {
        silk_vec3 p = m->pos[v];
        lo = silk_v3(silk_fx_min(lo.x, p.x), silk_fx_min(lo.y, p.y), silk_fx_min(lo.z, p.z));
        hi = silk_v3(silk_fx_max(hi.x, p.x), silk_fx_max(hi.y, p.y), silk_fx_max(hi.z, p.z));
    }
    m->bbox_min = lo;
    m->bbox_max = hi;
}

silk_status silk_mesh_build(const silk_mesh_input *in, const char *name, const silk_load_opts *opts,
                            silk_arena *a, silk_mesh *out, silk_error *err)
{
    if (!in || !opts || !a || !out)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "silk_mesh_build: missing input, options, arena or output");
    silk_status st = check_input(in, name, err);
    if (st != SILK_OK) return st;

    silk_mesh *m = out;
    memset(m, 0, sizeof *m);
    m->nverts = in->nverts;
    m->ntris = in->ntris;
    m->pos = in->pos;
    m->tri = in->tri;
    if (in->uv && in->tri_uv) {
        m->nuvs = in->nuvs;
        m->uv = in->uv;
        m->tri_uv = in->tri_uv;
    }
    m->color = in->color;
    bounding_box(m);

    silk_arena_mark mark = silk_arena_top_mark(a);
    st = build_edges(name, a, m, err);
    silk_arena_top_release(a, &mark);
    if (st != SILK_OK) return st;
    mark_degenerate(m);

    if (opts->orient != SILK_ORIENT_KEEP) {
        st = silk_orient(in, name, a, m, err);
        silk_arena_top_release(a, &mark);
        if (st != SILK_OK) return st;
    }

    st = build_vertex_edges(name, a, m, err);
    silk_arena_top_release(a, &mark);
    if (st != SILK_OK) return st;

    st = silk_build_normals(in, opts, name, a, m, err);
    if (st != SILK_OK) return st;

    for (uint32_t e = 0; e < m->nedges; e++) {
        if (m->edge[e].flags & SILK_EDGE_BOUNDARY) m->nboundary_edges++;
        if (m->edge[e].flags & SILK_EDGE_NONMANIFOLD) m->nnonmanifold_edges++;
    }
    return silk_build_features(name, a, m, err);
}

/* ---- memory report ------------------------------------------------------------ */

static size_t arena_bytes(size_t count, size_t size)
{
    size_t n = count * size;
    if (n == 0) n = 1;    /* the arena hands out at least one aligned unit */
    return (n + (SILK_ARENA_ALIGN - 1)) & ~(size_t)(SILK_ARENA_ALIGN - 1);
}

void silk_mesh_bytes_used(const silk_mesh *m, silk_mesh_bytes *b)
{
    memset(b, 0, sizeof *b);
    if (!m) return;
    size_t corners = 3 * (size_t)m->ntris;
    b->positions = arena_bytes(m->nverts, sizeof(silk_vec3));
    b->normals = arena_bytes(m->nnormals, sizeof(silk_vec3)) + arena_bytes(m->nnormals, sizeof(silk_index)) +
                 (m->tri_normal ? arena_bytes(corners, sizeof(silk_index)) : 0);
    b->uvs = m->uv ? arena_bytes(m->nuvs, sizeof(silk_vec2)) + arena_bytes(corners, sizeof(silk_index)) : 0;
    b->triangles = arena_bytes(corners, sizeof(silk_index));
    b->edges = arena_bytes(m->nedges, sizeof(silk_edge)) +
               (m->tri_edge ? arena_bytes(corners, sizeof(silk_index)) : 0);
    b->vertex_edges = m->vert_edge_start ? arena_bytes((size_t)m->nverts + 1, sizeof(silk_index)) +
                                           arena_bytes(m->vert_edge_start[m->nverts], sizeof(silk_index))
                                         : 0;
    b->features = (m->edge_feature ? arena_bytes(m->nedges, sizeof(silk_index)) : 0) +
                  arena_bytes(m->nfeature_edges, sizeof(silk_feature_seg));
    b->colors = m->color ? arena_bytes(m->nverts, sizeof(uint32_t)) : 0;
    b->total = b->positions + b->normals + b->uvs + b->colors + b->triangles + b->edges + b->vertex_edges + b->features;
}
