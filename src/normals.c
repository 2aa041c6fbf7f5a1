/*
 * normals.c - feature-edge flags and the split shading normals of paper
 * section III-B (Fig. 8).
 *
 * An edge is a crease when its two face normals differ by more than the
 * crease angle (n0.n1 < cos(crease)); a smoothing-group edge when its two
 * triangles are in different OBJ smoothing groups.  Around each vertex the
 * incident triangles fall into groups connected through non-feature edges
 * (union-find over triangle corners); each group gets one normal, the
 * angle-weighted average of its face normals (Thurmer & Wuthrich 1998, the
 * paper's [18]), so a vertex on a crease has one normal per side.  With
 * file normals on every corner, the groups are the corners of a vertex that
 * share a file normal, and that normal is used as given (normalised); an
 * edge across which they differ is a feature edge too.
 */
#include <string.h>
#include "mesh_build.h"

static silk_status nomem(silk_error *err, const char *name, const silk_arena *a)
{
    return silk_fail(err, SILK_ERR_NOMEM, name, 0,
                     "out of arena memory for the shading normals (%lu bytes requested, %lu free)",
                     (unsigned long)a->failed_request, (unsigned long)silk_arena_free_bytes(a));
}

/* ---- union-find over corners (corner c = 3*t + k) ------------------------------ */

static uint32_t uf_find(uint32_t *parent, uint32_t c)
{
    while (parent[c] != c) {
        parent[c] = parent[parent[c]];
        c = parent[c];
    }
    return c;
}

/* The smaller corner becomes the root, so the result does not depend on
 * the order of the unions. */
static void uf_union(uint32_t *parent, uint32_t a, uint32_t b)
{
    a = uf_find(parent, a);
    b = uf_find(parent, b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
}

static uint32_t corner_at(const silk_mesh *m, uint32_t t, silk_index v)
{
    for (uint32_t k = 0; k < 3; k++)
        if (m->tri[3 * t + k] == v) return 3 * t + k;
    return 3 * t;   /* not reached: both triangles of an edge hold its ends */
}

/* ---- feature flags ------------------------------------------------------------ */

static void mark_creases(silk_mesh *m, const silk_vec3 *fn, silk_fx crease_deg)
{
    silk_fx s, c;
    if (crease_deg >= SILK_FX_C(180, 1)) return;   /* nothing is sharper than a fold */
    silk_fx_sincos_deg(crease_deg, &s, &c);
    int64_t limit = (int64_t)c * SILK_FX_ONE;   /* Q32.32, like silk_v3_dot64 */
    for (uint32_t e = 0; e < m->nedges; e++) {
        silk_edge *ed = &m->edge[e];
        /* Degenerate triangles have no direction to compare. */
        if (ed->t[1] == SILK_NO_INDEX ||
            (ed->flags & (SILK_EDGE_BOUNDARY | SILK_EDGE_NONMANIFOLD | SILK_EDGE_DEGENERATE)))
            continue;
        if (silk_v3_dot64(fn[ed->t[0]], fn[ed->t[1]]) < limit) ed->flags |= SILK_EDGE_CREASE;
    }
}

static void mark_group_changes(silk_mesh *m, const uint32_t *tri_group)
{
    for (uint32_t e = 0; e < m->nedges; e++) {
        silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || ed->v[0] == ed->v[1]) continue;
        if (tri_group[ed->t[0]] != tri_group[ed->t[1]]) ed->flags |= SILK_EDGE_GROUPS;
    }
}

/* With file normals: an edge whose two triangles give one of its ends
 * different normals is a feature (flagged like a smoothing-group change),
 * or the curves the two sides build along it (III-C) would differ and
 * open a crack. */
static void mark_normal_splits(silk_mesh *m)
{
    for (uint32_t e = 0; e < m->nedges; e++) {
        silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || ed->v[0] == ed->v[1]) continue;
        for (int end = 0; end < 2; end++)
            if (m->tri_normal[corner_at(m, ed->t[0], ed->v[end])] != m->tri_normal[corner_at(m, ed->t[1], ed->v[end])])
                ed->flags |= SILK_EDGE_GROUPS;
    }
}

/* ---- grouping ------------------------------------------------------------------ */

static void group_by_features(const silk_mesh *m, uint32_t *parent)
{
    for (uint32_t t = 0; t < m->ntris; t++) {
        const silk_index *v = &m->tri[3 * t];
        if (v[0] == v[1]) uf_union(parent, 3 * t, 3 * t + 1);
        if (v[1] == v[2]) uf_union(parent, 3 * t + 1, 3 * t + 2);
        if (v[0] == v[2]) uf_union(parent, 3 * t, 3 * t + 2);
    }
    for (uint32_t e = 0; e < m->nedges; e++) {
        const silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || (ed->flags & SILK_EDGE_FEATURE)) continue;
        for (int end = 0; end < 2; end++) {
            if (end == 1 && ed->v[1] == ed->v[0]) break;
            uf_union(parent, corner_at(m, ed->t[0], ed->v[end]), corner_at(m, ed->t[1], ed->v[end]));
        }
    }
}

/* Corners of one vertex that name the same file normal form one group:
 * a stamp per file normal remembers the last vertex that used it. */
static void group_by_file_normals(const silk_mesh *m, const silk_mesh_input *in, const uint32_t *vc_start,
                                  const uint32_t *vc, uint32_t *stamp, uint32_t *first, uint32_t *parent)
{
    for (uint32_t v = 0; v < m->nverts; v++) {
        for (uint32_t i = vc_start[v]; i < vc_start[v + 1]; i++) {
            uint32_t c = vc[i], f = in->tri_file_normal[c];
            if (stamp[f] == v + 1) {
                uf_union(parent, first[f], c);
            } else {
                stamp[f] = v + 1;
                first[f] = c;
            }
        }
    }
}

/* ---- angle weights -------------------------------------------------------------- */

/* Angle at a corner: atan2(|e1 x e2|, e1.e2) from the exact 64-bit cross
 * product (the same for all three corners) and the exact dot product, both
 * brought to about 29 bits by one common shift.  Unlike acos of a rounded
 * dot, this keeps its accuracy for thin angles. */
static silk_fx corner_angle(const int64_t cr[3], int64_t dot)
{
    int64_t v[4] = { cr[0], cr[1], cr[2], dot };
    uint64_t big = 0;
    for (int i = 0; i < 4; i++) {
        uint64_t u = v[i] < 0 ? (uint64_t)0 - (uint64_t)v[i] : (uint64_t)v[i];
        if (u > big) big = u;
    }
    if (big == 0) return 0;
    int bits = 0;
    while (bits < 64 && (big >> bits) != 0) bits++;
    int s = bits - 29;
    for (int i = 0; i < 4; i++)
        v[i] = s > 0 ? silk_shr_round64(v[i], s) : v[i] * ((int64_t)1 << -s);
    uint64_t sq = (uint64_t)(v[0] * v[0]) + (uint64_t)(v[1] * v[1]) + (uint64_t)(v[2] * v[2]);
    return silk_fx_atan2((silk_fx)silk_isqrt64(sq), (silk_fx)v[3]);
}

static int64_t corner_dot(const silk_mesh *m, uint32_t t, uint32_t k)
{
    silk_vec3 p = m->pos[m->tri[3 * t + k]];
    silk_vec3 a = m->pos[m->tri[3 * t + (k + 1) % 3]], b = m->pos[m->tri[3 * t + (k + 2) % 3]];
    return ((int64_t)a.x - p.x) * ((int64_t)b.x - p.x) + ((int64_t)a.y - p.y) * ((int64_t)b.y - p.y) +
           ((int64_t)a.z - p.z) * ((int64_t)b.z - p.z);
}

/* A cone apex (the tip of `silk gen cone`, a spike) has no tangent plane:
 * its averaged normal points along the axis, far from every face around it,
 * so the whole fan becomes silhouette triangles and the bridges bulge the
 * tip into a dome.  A group whose angle-weighted normal is more than
 * SILK_APEX_DEG from every one of its faces is treated as such a point: its
 * corners are split apart, and each triangle keeps its own face normal
 * there.  On the shared coarse models this catches the cone's apex and one
 * spike of armadillo-500 and nothing else (docs/formats.md). */
#define SILK_APEX_DEG 50

static void split_apex_groups(const silk_mesh *m, const silk_vec3 *fn, const uint32_t *vc_start,
                              const uint32_t *vc, uint32_t *parent)
{
    silk_fx s, c;
    silk_fx_sincos_deg(SILK_FX_C(SILK_APEX_DEG, 1), &s, &c);
    const int64_t limit = (int64_t)c * SILK_FX_ONE;   /* Q32.32, like silk_v3_dot64 */
    for (uint32_t v = 0; v < m->nverts; v++) {
        for (uint32_t i = vc_start[v]; i < vc_start[v + 1]; i++) {
            uint32_t root = uf_find(parent, vc[i]);
            if (root != vc[i]) continue;   /* each group once, at its root */
            int64_t acc[3] = { 0, 0, 0 };
            uint32_t members = 0;
            for (uint32_t j = vc_start[v]; j < vc_start[v + 1]; j++) {
                uint32_t cj = vc[j], t = cj / 3;
                if (uf_find(parent, cj) != root) continue;
                members++;
                silk_vec3 n = fn[t];
                int64_t cr[3];
                silk_tri_cross64(m, t, cr);
                int64_t w = corner_angle(cr, corner_dot(m, t, cj % 3));
                acc[0] += w * n.x;
                acc[1] += w * n.y;
                acc[2] += w * n.z;
            }
            silk_vec3 u;
            if (members < 2 || !silk_v3_normalize64(acc, &u)) continue;
            int apex = 1;
            for (uint32_t j = vc_start[v]; j < vc_start[v + 1] && apex; j++) {
                uint32_t cj = vc[j];
                silk_vec3 n = fn[cj / 3];
                if (uf_find(parent, cj) != root || (n.x == 0 && n.y == 0 && n.z == 0)) continue;
                if (silk_v3_dot64(n, u) >= limit) apex = 0;
            }
            if (!apex) continue;
            /* Unions never cross vertices, so cutting this group's corners
             * loose splits exactly this group.  Point every member straight
             * at the root first, so that cutting one does not hide another. */
            for (uint32_t j = vc_start[v]; j < vc_start[v + 1]; j++)
                if (uf_find(parent, vc[j]) == root) parent[vc[j]] = root;
            for (uint32_t j = vc_start[v]; j < vc_start[v + 1]; j++)
                if (parent[vc[j]] == root) parent[vc[j]] = vc[j];
        }
    }
}

/* Sum angle * face normal per group in Q32.32 (exact), then normalise once.
 * A group whose sum vanishes (only degenerate triangles, or faces that
 * cancel) takes the first face normal it has, else +z. */
static silk_status average_normals(const silk_mesh *m, const silk_vec3 *fn, silk_arena *a, silk_vec3 *normal)
{
    int64_t *acc = silk_arena_array_top(a, 3 * (size_t)m->nnormals, sizeof *acc, SILK_MEM_LOAD);
    if (!acc) return SILK_ERR_NOMEM;
    for (uint32_t t = 0; t < m->ntris; t++) {
        silk_vec3 n = fn[t];
        if (n.x == 0 && n.y == 0 && n.z == 0) continue;
        int64_t cr[3];
        silk_tri_cross64(m, t, cr);
        for (uint32_t k = 0; k < 3; k++) {
            silk_index g = m->tri_normal[3 * t + k];
            int64_t w = corner_angle(cr, corner_dot(m, t, k));
            acc[3 * g] += w * n.x;
            acc[3 * g + 1] += w * n.y;
            acc[3 * g + 2] += w * n.z;
            if (normal[g].x == 0 && normal[g].y == 0 && normal[g].z == 0) normal[g] = n;
        }
    }
    for (uint32_t g = 0; g < m->nnormals; g++) {
        silk_vec3 u;
        if (silk_v3_normalize64(&acc[3 * g], &u)) normal[g] = u;
        else if (normal[g].x == 0 && normal[g].y == 0 && normal[g].z == 0) normal[g] = silk_v3(0, 0, SILK_FX_ONE);
    }
    return SILK_OK;
}

static void file_normals(const silk_mesh *m, const silk_mesh_input *in, const silk_vec3 *fn, silk_vec3 *normal)
{
    /* All corners of a group name the same file normal; the first sets it. */
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        silk_index g = m->tri_normal[c];
        if (normal[g].x != 0 || normal[g].y != 0 || normal[g].z != 0) continue;
        silk_vec3 u;
        if (!silk_v3_normalize(in->file_normal[in->tri_file_normal[c]], &u)) {
            u = fn[c / 3];   /* a zero file normal: use the face's */
            if (u.x == 0 && u.y == 0 && u.z == 0) u = silk_v3(0, 0, SILK_FX_ONE);
        }
        normal[g] = u;
    }
}

static int have_file_normals(const silk_mesh_input *in, const silk_load_opts *opts)
{
    if (opts->normals == SILK_NORMALS_COMPUTE || !in->file_normal || !in->tri_file_normal || in->nfile_normals == 0)
        return 0;
    for (uint32_t c = 0; c < 3 * in->ntris; c++)
        if (in->tri_file_normal[c] == SILK_NO_INDEX) return 0;
    return 1;
}

/* Each vertex's corners, in corner order (a stable counting sort): those
 * of vertex v are vc[vc_start[v] .. vc_start[v + 1]). */
static void vertex_corners(const silk_mesh *m, uint32_t *vc_start, uint32_t *vc)
{
    uint32_t nc = 3 * m->ntris, nv = m->nverts;
    for (uint32_t c = 0; c < nc; c++) vc_start[m->tri[c] + 1]++;
    for (uint32_t v = 0; v < nv; v++) vc_start[v + 1] += vc_start[v];
    for (uint32_t c = 0; c < nc; c++) vc[vc_start[m->tri[c]]++] = c;
    for (uint32_t v = nv; v > 0; v--) vc_start[v] = vc_start[v - 1];
    vc_start[0] = 0;

}

/* One normal per group of corners (parent, union-find), numbered in
 * vertex order: m->tri_normal and m->normal_vertex. */
static void number_groups(silk_mesh *m, uint32_t *parent, const uint32_t *vc_start, const uint32_t *vc)
{
    uint32_t nc = 3 * m->ntris, nv = m->nverts;
    for (uint32_t c = 0; c < nc; c++) m->tri_normal[c] = SILK_NO_INDEX;
    uint32_t g = 0;
    for (uint32_t v = 0; v < nv; v++) {
        for (uint32_t i = vc_start[v]; i < vc_start[v + 1]; i++) {
            uint32_t c = vc[i], r = uf_find(parent, c);
            if (m->tri_normal[r] == SILK_NO_INDEX) {
                m->normal_vertex[g] = v;
                m->tri_normal[r] = g++;
            }
            m->tri_normal[c] = m->tri_normal[r];
        }
    }
}

silk_status silk_build_normals(const silk_mesh_input *in, const silk_load_opts *opts,
                               const char *name, silk_arena *a, silk_mesh *m, silk_error *err)
{
    if (opts->crease_deg < 0 || opts->crease_deg > SILK_FX_C(180, 1)) {
        char buf[16];
        return silk_fail(err, SILK_ERR_ARG, name, 0, "crease angle %s is outside 0..180 degrees",
                         silk_fx_format(opts->crease_deg, buf));
    }
    uint32_t nc = 3 * m->ntris, nv = m->nverts;
    int from_file = have_file_normals(in, opts);
    m->normals_used = from_file ? SILK_NORMALS_FILE : SILK_NORMALS_COMPUTE;
    silk_status st = SILK_OK;
    silk_arena_mark mark = silk_arena_top_mark(a);

    m->tri_normal = silk_arena_array(a, nc, sizeof *m->tri_normal, SILK_MEM_MESH);
    silk_vec3 *fn = silk_arena_array_top(a, m->ntris, sizeof *fn, SILK_MEM_LOAD);
    uint32_t *parent = silk_arena_array_top(a, nc, sizeof *parent, SILK_MEM_LOAD);
    uint32_t *vc_start = silk_arena_array_top(a, (size_t)nv + 1, sizeof *vc_start, SILK_MEM_LOAD);
    uint32_t *vc = silk_arena_array_top(a, nc, sizeof *vc, SILK_MEM_LOAD);
    if (!m->tri_normal || !fn || !parent || !vc_start || !vc) goto out_of_memory;

    for (uint32_t t = 0; t < m->ntris; t++) fn[t] = silk_mesh_face_normal(m, t);
    mark_creases(m, fn, opts->crease_deg);
    if (in->tri_group) mark_group_changes(m, in->tri_group);

    vertex_corners(m, vc_start, vc);
    for (uint32_t c = 0; c < nc; c++) parent[c] = c;
    if (from_file) {
        uint32_t *stamp = silk_arena_array_top(a, in->nfile_normals, sizeof *stamp, SILK_MEM_LOAD);
        uint32_t *first = silk_arena_array_top(a, in->nfile_normals, sizeof *first, SILK_MEM_LOAD);
        if (!stamp || !first) goto out_of_memory;
        group_by_file_normals(m, in, vc_start, vc, stamp, first, parent);
    } else {
        group_by_features(m, parent);
        split_apex_groups(m, fn, vc_start, vc, parent);
    }

    /* One normal per group, numbered in vertex order. */
    uint32_t ngroups = 0;
    for (uint32_t c = 0; c < nc; c++)
        if (uf_find(parent, c) == c) ngroups++;
    if ((uint64_t)ngroups >= (uint64_t)SILK_NO_INDEX) {
        st = silk_fail(err, SILK_ERR_RANGE, name, 0, "%lu shading normals do not fit the %u-byte vertex index",
                       (unsigned long)ngroups, (unsigned)sizeof(silk_index));
        silk_arena_top_release(a, &mark);
        return st;
    }
    m->nnormals = ngroups;
    m->normal = silk_arena_array(a, ngroups, sizeof *m->normal, SILK_MEM_MESH);
    m->normal_vertex = silk_arena_array(a, ngroups, sizeof *m->normal_vertex, SILK_MEM_MESH);
    if (!m->normal || !m->normal_vertex) goto out_of_memory;
    number_groups(m, parent, vc_start, vc);

    if (from_file) {
        file_normals(m, in, fn, m->normal);
        mark_normal_splits(m);
    }
    else if (average_normals(m, fn, a, m->normal) != SILK_OK) goto out_of_memory;
    silk_arena_top_release(a, &mark);
    return st;

out_of_memory:
    st = nomem(err, name, a);
    silk_arena_top_release(a, &mark);
    return st;
}
