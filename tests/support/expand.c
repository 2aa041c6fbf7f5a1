/*
 * expand.c - test support: a compact model written out into the arrays of
 * a silk_mesh (expand.h).
 */
#include <string.h>
#include "expand.h"

#define GET(n, T) silk_arena_array(a, (n) > 0 ? (size_t)(n) : 1, sizeof(T), SILK_MEM_MESH)

int ex_expand(const silk_mesh *p, silk_arena *a, silk_mesh *out)
{
    silk_mesh m = *p;
    memset(&m.packed, 0, sizeof m.packed);
    uint32_t nc = 3 * p->ntris;
    m.pos = GET(p->nverts, silk_vec3);
    m.normal = GET(p->nnormals, silk_vec3);
    m.normal_vertex = GET(p->nnormals, silk_index);
    m.tri = GET(nc, silk_index);
    m.tri_normal = GET(nc, silk_index);
    if (!m.pos || !m.normal || !m.normal_vertex || !m.tri || !m.tri_normal) return 0;
    for (uint32_t v = 0; v < p->nverts; v++) m.pos[v] = silk_mesh_pos(p, v);
    for (uint32_t n = 0; n < p->nnormals; n++) {
        m.normal[n] = silk_mesh_normal(p, n);
        m.normal_vertex[n] = silk_mesh_normal_vertex(p, n);
    }
    for (uint32_t c = 0; c < nc; c++) {
        m.tri[c] = silk_mesh_corner(p, c);
        m.tri_normal[c] = silk_mesh_corner_normal(p, c);
    }
    m.tri_edge = NULL;
    m.edge = NULL;
    m.vert_edge_start = NULL;
    m.vert_edge = NULL;
    m.edge_feature = NULL;
    m.feature = NULL;
    if (p->nedges) {
        m.tri_edge = GET(nc, silk_index);
        m.edge = GET(p->nedges, silk_edge);
        m.edge_feature = GET(p->nedges, silk_index);
        m.feature = GET(p->nfeature_edges, silk_feature_seg);
        m.vert_edge_start = GET(p->nverts + 1, silk_index);
        m.vert_edge = GET(2 * p->nedges, silk_index);
        /* the arrays number the edges 0.. in the compact model's order */
        uint32_t bound = silk_mesh_edge_bound(p);
        silk_index *dense = GET(bound, silk_index);
        if (!m.tri_edge || !m.edge || !m.edge_feature || !m.feature || !m.vert_edge_start || !m.vert_edge || !dense)
            return 0;
        for (uint32_t e = 0; e < bound; e++) dense[e] = SILK_NO_INDEX;
        silk_mesh_edges it;
        silk_edge ed;
        uint32_t nf = 0, ne = 0;
        for (silk_index e = silk_mesh_edges_first(p, &it, &ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(p, &it, &ed)) {
            silk_edge direct = silk_mesh_edge(p, e);
            if (memcmp(&direct.v, &ed.v, sizeof ed.v) || memcmp(&direct.t, &ed.t, sizeof ed.t) ||
                direct.flags != ed.flags || e >= bound || ne >= p->nedges)
                return 0;   /* the walk and the random access disagree */
            dense[e] = ne;
            m.edge[ne] = ed;
            silk_feature_seg s;
            m.edge_feature[ne] = SILK_NO_INDEX;
            if (silk_mesh_feature_seg(p, e, &s)) {
                if (nf >= p->nfeature_edges) return 0;
                m.feature[nf] = s;
                m.edge_feature[ne] = nf++;
            }
            ne++;
        }
        if (ne != p->nedges || nf != p->nfeature_edges) return 0;
        for (uint32_t t = 0; t < p->ntris; t++)
            for (uint32_t k = 0; k < 3; k++) {
                silk_index e = silk_mesh_tri_edge(p, t, k);
                if (e >= bound || dense[e] == SILK_NO_INDEX) return 0;
                m.tri_edge[3 * t + k] = dense[e];
            }
        uint32_t at = 0;
        for (uint32_t v = 0; v < p->nverts; v++) {
            m.vert_edge_start[v] = at;
            silk_mesh_ring r;
            for (silk_index e = silk_mesh_ring_first(p, v, &r); e != SILK_NO_INDEX; e = silk_mesh_ring_next(p, &r)) {
                if (at >= 2 * p->nedges || e >= bound || dense[e] == SILK_NO_INDEX) return 0;
                m.vert_edge[at++] = dense[e];
            }
        }
        m.vert_edge_start[p->nverts] = at;
        if (at != 2 * p->nedges) return 0;
    }
    *out = m;
    return 1;
}
