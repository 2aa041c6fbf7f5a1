/*
 * validate.c - is a mesh built elsewhere safe to render?  (silk/validate.h)
 *
 * Not a paper equation: this guards the data every stage of section III
 * walks - triangles, their edges, the vertex->edge lists, the split shading
 * normals of III-B, the feature segments of III-A and the visibility
 * hierarchy - when it comes from a `silk pack` header or any other source
 * than silk's own loaders.  One pass over each array, no memory of its own:
 * every check is local to one element, plus one count (edge ends against
 * list entries) that makes the local checks of the vertex->edge lists add
 * up to a whole.  Messages number elements from 0, as the arrays do.
 */
#include <string.h>
#include "silk/validate.h"
#include "silk/compact.h"
#include "silk/visibility.h"

/* Triangles silk_mesh_build accepts (mesh_build.c's MAX_TRIS): per-frame
 * counts of 3 * ntris and more stay far inside uint32. */
#define VALID_MAX_TRIS (1u << 28)
/* |n|^2 within 1 +- 1/64, in Q32.32 like silk_v3_dot64 */
#define UNIT_SLACK ((int64_t)1 << 26)

#define BAD(...) silk_fail(err, SILK_ERR_PARSE, name, 0, __VA_ARGS__)
#define UL(x) ((unsigned long)(x))

static int in_coord_range(silk_vec3 p)
{
    return silk_fx_abs(p.x) <= SILK_COORD_MAX && silk_fx_abs(p.y) <= SILK_COORD_MAX &&
           silk_fx_abs(p.z) <= SILK_COORD_MAX;
}

/* Whether edge e joins vertices a and b (either way round). */
static int edge_joins(const silk_edge *e, silk_index a, silk_index b)
{
    silk_index lo = a < b ? a : b, hi = a < b ? b : a;
    return e->v[0] == lo && e->v[1] == hi;
}

/* Whether triangle t has edge e on one of its sides. */
static int tri_has_edge(const silk_mesh *m, silk_index t, uint32_t e)
{
    for (int k = 0; k < 3; k++)
        if (silk_mesh_tri_edge(m, t, k) == e) return 1;
    return 0;
}

static silk_status check_counts(const silk_mesh *m, const char *name, silk_error *err)
{
    if (!m->ntris || !m->nverts || !m->nnormals || !m->nedges)
        return BAD("empty mesh (%lu triangles, %lu vertices, %lu normals, %lu edges)", UL(m->ntris),
                   UL(m->nverts), UL(m->nnormals), UL(m->nedges));
    if (m->ntris > VALID_MAX_TRIS)
        return BAD("%lu triangles is more than the %lu supported", UL(m->ntris), UL(VALID_MAX_TRIS));
    if ((uint64_t)m->nverts >= SILK_NO_INDEX || (uint64_t)m->nnormals >= SILK_NO_INDEX ||
        (uint64_t)m->nedges >= SILK_NO_INDEX || (uint64_t)m->nuvs >= SILK_NO_INDEX)
        return BAD("%lu vertices, %lu normals, %lu edges or %lu uvs do not fit silk_index", UL(m->nverts),
                   UL(m->nnormals), UL(m->nedges), UL(m->nuvs));
    if (!m->pos || !m->tri || !m->normal || !m->normal_vertex || !m->tri_normal || !m->edge ||
        !m->vert_edge_start || !m->vert_edge)
        return BAD("an array is missing (positions, triangles, normals, edges or vertex edges)");
    if ((m->uv != NULL) != (m->tri_uv != NULL) || (m->uv && !m->nuvs))
        return BAD("texture coordinates (%lu) without their indices, or indices without them", UL(m->nuvs));
    if (m->nfeature_edges > m->nedges)
        return BAD("%lu feature edges of %lu edges", UL(m->nfeature_edges), UL(m->nedges));
    if (m->nfeature_edges && !m->feature)
        return BAD("%lu feature edges but no feature segments", UL(m->nfeature_edges));
    return SILK_OK;
}

static silk_status check_vertices(const silk_mesh *m, const char *name, silk_error *err)
{
    for (uint32_t v = 0; v < m->nverts; v++)
        if (!in_coord_range(m->pos[v]))
            return BAD("vertex %lu is outside +-%lu", UL(v), UL(SILK_COORD_MAX >> SILK_FX_SHIFT));
    for (uint32_t i = 0; i < m->nnormals; i++) {
        int64_t q = silk_v3_dot64(m->normal[i], m->normal[i]) - ((int64_t)1 << 32);
        if (q > UNIT_SLACK || q < -UNIT_SLACK) return BAD("normal %lu is not of unit length", UL(i));
        if (m->normal_vertex[i] >= m->nverts)
            return BAD("normal %lu belongs to vertex %lu (%lu vertices)", UL(i), UL(m->normal_vertex[i]),
                       UL(m->nverts));
    }
    return SILK_OK;
}

static silk_status check_triangles(const silk_mesh *m, const char *name, silk_error *err)
{
    for (uint32_t t = 0; t < m->ntris; t++) {
        for (uint32_t k = 0; k < 3; k++) {
            size_t c = 3 * (size_t)t + k;
            silk_index v = m->tri[c], n = m->tri_normal[c];
            if (v >= m->nverts)
                return BAD("triangle %lu uses vertex %lu (%lu vertices)", UL(t), UL(v), UL(m->nverts));
            if (n >= m->nnormals)
                return BAD("triangle %lu uses normal %lu (%lu normals)", UL(t), UL(n), UL(m->nnormals));
            if (m->normal_vertex[n] != v)
                return BAD("triangle %lu: normal %lu belongs to vertex %lu, not %lu", UL(t), UL(n),
                           UL(m->normal_vertex[n]), UL(v));
            if (m->tri_uv && m->tri_uv[c] >= m->nuvs)
                return BAD("triangle %lu uses texture coordinate %lu (%lu given)", UL(t), UL(m->tri_uv[c]),
                           UL(m->nuvs));
        }
        /* all three corners are in range now; so are the vertex-edge lists
         * (checked first) that find a side's edge without tri_edge */
        for (uint32_t k = 0; k < 3; k++) {
            size_t c = 3 * (size_t)t + k, c1 = 3 * (size_t)t + (k + 1) % 3;
            silk_index e = silk_mesh_tri_edge(m, t, k);
            if (!m->tri_edge && e == SILK_NO_INDEX)
                return BAD("triangle %lu: no edge joins its corners %lu and %lu", UL(t), UL(m->tri[c]),
                           UL(m->tri[c1]));
            if (e >= m->nedges) return BAD("triangle %lu uses edge %lu (%lu edges)", UL(t), UL(e), UL(m->nedges));
            if (!edge_joins(&m->edge[e], m->tri[c], m->tri[c1]))
                return BAD("triangle %lu: side %lu is not its edge %lu", UL(t), UL(k), UL(e));
        }
    }
    return SILK_OK;
}

static silk_status check_edges(const silk_mesh *m, const char *name, silk_error *err)
{
    uint32_t nfe = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        const silk_edge *ed = &m->edge[e];
        if (ed->v[0] > ed->v[1] || ed->v[1] >= m->nverts)
            return BAD("edge %lu joins vertices %lu and %lu (out of order or range)", UL(e), UL(ed->v[0]),
                       UL(ed->v[1]));
        for (int s = 0; s < 2; s++) {
            silk_index t = ed->t[s];
            if (s == 1 && t == SILK_NO_INDEX) continue;
            if (t >= m->ntris || !tri_has_edge(m, t, e))
                return BAD("edge %lu: its triangle %lu does not use it", UL(e), UL(t));
        }
        if (m->edge_feature && m->edge_feature[e] != SILK_NO_INDEX && m->edge_feature[e] >= m->nfeature_edges)
            return BAD("edge %lu has feature segment %lu (%lu segments)", UL(e), UL(m->edge_feature[e]),
                       UL(m->nfeature_edges));
        nfe += (uint32_t)silk_edge_has_feature(ed);
    }
    /* without edge_feature the segments are counted along the edges */
    if (!m->edge_feature && m->feature && nfe > m->nfeature_edges)
        return BAD("%lu feature edges but %lu feature segments", UL(nfe), UL(m->nfeature_edges));
    return SILK_OK;
}

/* Before the triangles: without tri_edge, their sides' edges are found in
 * these lists. */
static silk_status check_vertex_edges(const silk_mesh *m, const char *name, silk_error *err)
{
    uint64_t ends = 0;
    for (uint32_t e = 0; e < m->nedges; e++) ends += m->edge[e].v[0] == m->edge[e].v[1] ? 1 : 2;
    const silk_index *start = m->vert_edge_start;
    if (start[0] != 0) return BAD("the vertex-edge lists start at %lu, not 0", UL(start[0]));
    for (uint32_t v = 0; v < m->nverts; v++) {
        if (start[v + 1] < start[v] || start[v + 1] > ends)
            return BAD("the vertex-edge list of vertex %lu runs from %lu to %lu", UL(v), UL(start[v]),
                       UL(start[v + 1]));
        for (uint32_t i = start[v]; i < start[v + 1]; i++) {
            silk_index e = m->vert_edge[i];
            if (e >= m->nedges || (m->edge[e].v[0] != v && m->edge[e].v[1] != v))
                return BAD("vertex %lu lists edge %lu, which does not end there", UL(v), UL(e));
        }
    }
    if (start[m->nverts] != ends)
        return BAD("the vertex-edge lists hold %lu entries for %lu edge ends", UL(start[m->nverts]), UL(ends));
    return SILK_OK;
}

static silk_status check_vis(const silk_mesh *m, const char *name, silk_error *err)
{
    const silk_vis *vis = m->vis;
    /* A hierarchy built for other normals is not used (the renderer takes
     * the brute pass instead), so only a matching one must be sound. */
    if (!vis || vis->nnormals != m->nnormals) return SILK_OK;
    uint32_t nn = vis->nnodes, n = vis->nnormals;
    if (nn && !vis->node) return BAD("the visibility hierarchy's %lu nodes are missing", UL(nn));
    if (vis->scale_log2 < 0 || vis->scale_log2 > 46)
        return BAD("visibility scale 2^%ld is out of range", (long)vis->scale_log2);
    for (uint32_t i = 0; i < nn; i++) {
        const silk_vis_node *c = &vis->node[i];
        if (c->skip <= i || c->skip > nn)
            return BAD("visibility node %lu skips to %lu (%lu nodes)", UL(i), UL(c->skip), UL(nn));
        uint32_t end = c->skip < nn ? vis->node[c->skip].first : n;
        if (c->first > end || end > n)
            return BAD("visibility node %lu holds normals %lu to %lu (%lu normals)", UL(i), UL(c->first), UL(end),
                       UL(n));
        /* a child's normals lie inside its parent's */
        if (c->skip > i + 1 && vis->node[i + 1].first < c->first)
            return BAD("visibility node %lu starts before its parent %lu", UL(i + 1), UL(i));
    }
    return SILK_OK;
}

/* A compact model is checked again as silk_compact_mesh checks it, and
 * must be the mesh it makes. */
static silk_status check_compact(const silk_mesh *m, const char *name, silk_error *err)
{
    const uint8_t *b = m->packed.base;
    size_t len = (size_t)b[48] | (size_t)b[49] << 8 | (size_t)b[50] << 16 | (size_t)b[51] << 24;
    silk_mesh again;
    silk_status st = silk_compact_mesh(b, len, name, &again, err);
    if (st != SILK_OK) return st;
    if (memcmp(&again.packed, &m->packed, sizeof again.packed) != 0 || again.nverts != m->nverts ||
        again.ntris != m->ntris || again.nnormals != m->nnormals || again.nedges != m->nedges)
        return silk_fail(err, SILK_ERR_PARSE, name, 0, "the mesh's counts or fields are not its compact model's");
    return SILK_OK;
}

silk_status silk_mesh_validate(const silk_mesh *m, const char *name, silk_error *err)
{
    if (!name) name = "mesh";
    if (!m) return silk_fail(err, SILK_ERR_ARG, name, 0, "no mesh given");
    if (m->packed.base) return check_compact(m, name, err);
    silk_status st = check_counts(m, name, err);
    if (st == SILK_OK) st = check_vertices(m, name, err);
    if (st == SILK_OK) st = check_vertex_edges(m, name, err);
    if (st == SILK_OK) st = check_triangles(m, name, err);
    if (st == SILK_OK) st = check_edges(m, name, err);
    if (st == SILK_OK) st = check_vis(m, name, err);
    return st;
}
