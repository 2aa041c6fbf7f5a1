/*
 * budget.c - the arena a frame takes at most (silk/budget.h).
 *
 * Every allocation a streamed FLAT or SMOOTH frame makes from the top of
 * the arena (render.c, silhouette.c, remesh.c, perturb.c, aa.c), each at
 * its largest over every camera, added up with the arena's alignment.
 * The counts are bounded from the mesh alone:
 *   - silhouette triangles: at most every triangle (T); each has two
 *     silhouette sides, so at most 2T silhouette points and 2T carrying
 *     edges from them, plus every feature edge (F), and never more than
 *     the mesh's edges (E);
 *   - an edge's chain: its silhouette points (at most its sides, S: 2 on a
 *     manifold edge) and, on a feature edge, up to SILK_MAX_SAMPLES - 1
 *     samples (eq. 8 is capped there);
 *   - one input triangle's share: its corners, its three sides' chains, a
 *     segment of up to SILK_MAX_SAMPLES intervals and two centres
 *     (remesh.c, tri_cost);
 *   - the perturbation: a slot per mesh vertex (V) at most;
 *   - a band's outline (aa.c, silk_aa_bytes): two apron rows, a projected
 *     point per record of a share, its pixel list of 3 (width + rows)
 *     entries.
 * Released scratch (the normals' visibility, the perturbation's lifts) is
 * counted as if it were kept: the bound only has to be safe.
 *
 * Kept in step with those files: tests/core/test_budget.c draws frames with
 * exactly these bytes over many views and fails when one needed more.
 */
#include <string.h>
#include "silk/budget.h"
#include "plan.h"
#include "aa.h"

#define A(n) (((size_t)(n) + SILK_ARENA_ALIGN - 1) & ~(size_t)(SILK_ARENA_ALIGN - 1))

/* The most triangle sides on one edge: two on a manifold mesh; a
 * non-manifold edge's counted (at most SILK_SIL_SIDES_MAX, beyond which
 * the plan gives up and the frame falls back). */
static uint32_t max_sides(const silk_mesh *m)
{
    uint32_t most = 2;
    silk_mesh_edges it;
    silk_edge ed;
    for (silk_index e = silk_mesh_edges_first(m, &it, &ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, &ed)) {
        if (!(ed.flags & SILK_EDGE_NONMANIFOLD)) continue;
        if ((uint64_t)m->ntris * m->nnonmanifold_edges > 50000000u) return SILK_SIL_SIDES_MAX;   /* too long to count */
        uint32_t n = 0;
        for (uint32_t t = 0; t < m->ntris; t++)
            for (uint32_t k = 0; k < 3; k++) n += silk_mesh_tri_edge(m, t, k) == e;
        if (n > most) most = n;
    }
    return most < SILK_SIL_SIDES_MAX ? most : SILK_SIL_SIDES_MAX;
}

/* The share scratch of one input triangle with at most recs records,
 * tris triangles, curves curves and a boundary of poly points
 * (silk_remesh_alloc), and the vertex stage's output for its records. */
static size_t share_bytes(uint64_t recs, uint64_t tris, uint64_t curves, uint64_t poly)
{
    return A(recs * sizeof(silk_vrec)) + A(3 * tris * sizeof(uint32_t)) + A(tris) + A(curves * sizeof(silk_curve)) +
           A(2 * poly * sizeof(uint32_t)) + A(recs * sizeof(silk_vertex_out));
}

/* A band's outline (silk_aa_begin), for shares of at most recs records:
 * what the renderer leaves free for it. */
static size_t outline_bytes(const silk_render_opts *o, int width, int rows, silk_pixfmt fmt, uint64_t recs)
{
    if (!SILK_AA || !o->aa) return 0;
    silk_target t;
    memset(&t, 0, sizeof t);
    t.width = width;
    t.rows = rows;
    t.fmt = fmt;
    return silk_aa_bytes(&t, (uint32_t)recs);
}

silk_status silk_budget_frame(const silk_mesh *m, const silk_render_opts *o, int width, int height, int rows,
                              silk_pixfmt fmt, int double_buffered, silk_budget *b, silk_error *err)
{
    if (b) memset(b, 0, sizeof *b);
    if (!m || !o || !b) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_budget_frame: missing argument");
    if (o->mode != SILK_MODE_FLAT && o->mode != SILK_MODE_SMOOTH)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_budget_frame: FLAT and SMOOTH frames only (not %s)",
                         silk_mode_name(o->mode));
    if (o->lines || o->wire)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_budget_frame: frames with lines or wire are stored, not bounded");
    if (width < 1 || height < 1 || width > SILK_MAX_DIM || height > SILK_MAX_DIM || rows < 1 ||
        (fmt != SILK_PIX_RGB565 && fmt != SILK_PIX_RGB888))
        return silk_fail(err, SILK_ERR_RANGE, NULL, 0, "silk_budget_frame: a %dx%d frame in bands of %d rows", width,
                         height, rows);
    if (rows > height) rows = height;
    size_t px = (size_t)width * (size_t)rows;
    b->bands = A(px * silk_pixfmt_bytes(fmt)) * (double_buffered ? 2 : 1) + A(px * sizeof(uint32_t));

    uint64_t T = m->ntris, E = m->nedges, V = m->nverts, N = m->nnormals, F = 0;
    silk_mesh_edges it;
    silk_edge ed;
    for (silk_index e = silk_mesh_edges_first(m, &it, &ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, &ed))
        F += (ed.flags & SILK_EDGE_FEATURE) != 0;
    /* the rows each input triangle reaches, in bands */
    size_t frame = rows < height && T > 1 ? A(2 * T) : 0, need;
    if (o->mode == SILK_MODE_FLAT) {
        /* one triangle's three CORNER records and their vertex-stage output */
        need = A(3 * sizeof(silk_vrec)) + A(3 * sizeof(uint32_t)) + A(1) + A(3 * sizeof(silk_vertex_out)) +
               outline_bytes(o, width, rows, fmt, 3);
    } else {
        uint64_t S = max_sides(m), sampled = SILK_MAX_SAMPLES - 1;
        uint64_t nwork = 2 * T + F < E ? 2 * T + F : E, npairs = 2 * T;
        uint64_t nchain = npairs + F * sampled, per_edge = (F ? sampled : 0) + S;
        if (nchain > nwork * per_edge) nchain = nwork * per_edge;
        /* silhouette.c: triangle states, carrying bits, the normals'
         * visibility, the carrying edges, their points and chains */
        size_t plan = A(T) + A((E + 7) / 8) + A(N) + A(nwork * sizeof(silk_sil_edge)) +
                      A(npairs * sizeof(silk_sil_pair)) + A(nchain * sizeof(silk_fx));
        /* perturb.c: a slot per vertex, its sums (then offsets), and while
         * it works the lifts, vertices and stamps */
        plan += A(V * sizeof(silk_index)) + A(V * sizeof(silk_vec3)) + A(V * sizeof(silk_fx)) +
                A(V * sizeof(silk_index)) + A(V * sizeof(uint32_t));
        /* one share (remesh.c tri_cost) */
        uint64_t sum = 3 * per_edge, n = SILK_MAX_SAMPLES, poly = 3 + sum + n + 2, recs = 3 + sum + (n - 1) + 2,
                 tris = 2 * n + 2 * (3 + sum) + 2, curves = 3 + 1 + 2;
        need = plan + share_bytes(recs, tris, curves, poly) + outline_bytes(o, width, rows, fmt, recs);
    }
    b->frame = frame + need;
    b->total = b->bands + b->frame;
    return SILK_OK;
}
