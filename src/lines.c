/*
 * lines.c - pen-and-ink lines: the outline of what a frame draws, as
 * polylines of vertex records for silk_raster_line.
 *
 * SMOOTH mode (paper III-D and III-A): each silhouette segment S(t) of eq. 5
 * through its n+1 samples of eq. 8 (A, the interior samples, B), and each
 * visible feature segment through its end vertices and its edge chain.
 * The records are copies of the ones the re-meshed triangles use, so a line
 * runs exactly along the triangle edges that make the drawn outline: at
 * the silhouette it is the boundary of the rendered object, bit for bit.
 *
 * The polygonal outline of the coarse mesh, for comparison and for the
 * other modes: every edge between a front-facing and a back-facing
 * triangle (the face-based silhouette) and every feature edge next to a
 * front-facing triangle, corner to corner.
 *
 * Lines only say where the outline runs; which parts show is left to the
 * depth test of silk_raster_line against the drawn surface.
 */
#include <string.h>
#include "silhouette.h"

/* Room for nlines polylines over nrec records, from the top of the arena. */
static int lines_alloc(silk_arena *a, silk_frame_geom *g, uint32_t nlines, uint64_t nrec)
{
    g->nlines = g->nline_vrec = 0;
    if (nrec > UINT32_MAX || nlines == UINT32_MAX) return 0;
    g->line_vrec = silk_arena_array_top(a, (size_t)nrec, sizeof *g->line_vrec, SILK_MEM_FRAME);
    g->line_start = silk_arena_array_top(a, (size_t)nlines + 1, sizeof *g->line_start, SILK_MEM_FRAME);
    g->line_feature = silk_arena_array_top(a, nlines, 1, SILK_MEM_FRAME);
    if (!g->line_vrec || !g->line_start || !g->line_feature) return 0;
    g->line_start[0] = 0;
    return 1;
}

static void line_point(silk_frame_geom *g, const silk_vrec *r) { g->line_vrec[g->nline_vrec++] = *r; }

static void line_end(silk_frame_geom *g, int feature)
{
    g->line_feature[g->nlines++] = (uint8_t)feature;
    g->line_start[g->nlines] = g->nline_vrec;
}

/* ---- SMOOTH mode ------------------------------------------------------------- */

/* Whether silhouette segment s was drawn re-meshed (its part not dropped). */
static int seg_drawn(const silk_sil_frame *f, const silk_sil_seg *s)
{
    return !f->edges[s->comp].rejected;
}

/* The corner record of side s at edge.v[0] (end 0) or edge.v[1] (end 1):
 * record 3t+k is corner k of triangle t in every SMOOTH frame (CORNER, or
 * MOVED at a perturbed vertex). */
static uint32_t side_corner(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s, int end)
{
    const silk_mesh *m = f->m;
    uint32_t ca = 3 * s->tri + s->k, cb = 3 * s->tri + (s->k + 1) % 3;
    int fwd = m->tri[ca] == m->edge[e->edge].v[0];
    return (end == 0) == fwd ? ca : cb;
}

silk_status silk_lines_smooth(const silk_sil_frame *f, silk_frame_geom *g)
{
    uint32_t nlines = 0;
    uint64_t nrec = 0;
    for (uint32_t i = 0; i < f->nsegs; i++) {
        if (!seg_drawn(f, &f->segs[i])) continue;
        nlines++;
        nrec += f->segs[i].n + 1;
    }
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        if (!e->sampled || !e->nsides) continue;
        nlines++;
        nrec += 2 + (silk_sil_chained(f, e->edge) ? e->nchain : 0);
    }
    if (!lines_alloc(f->a, g, nlines, nrec)) return SILK_ERR_NOMEM;

    for (uint32_t i = 0; i < f->nsegs; i++) {
        const silk_sil_seg *s = &f->segs[i];
        if (!seg_drawn(f, s)) continue;
        line_point(g, &g->vrec[s->rec_a]);
        for (uint32_t j = 1; j < s->n; j++) line_point(g, &g->vrec[s->rec + j - 1]);
        line_point(g, &g->vrec[s->rec_b]);
        line_end(g, 0);
    }
    /* A feature edge whose part was dropped, or that needed no samples, is
     * drawn straight between its corners, and so is its line. */
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        if (!e->sampled || !e->nsides) continue;
        const silk_sil_side *s = &f->sides[e->side0];
        line_point(g, &g->vrec[side_corner(f, e, s, 0)]);
        if (silk_sil_chained(f, e->edge)) {
            uint32_t rec = f->sides[s->owner].rec;
            for (uint32_t j = 0; j < e->nchain; j++) line_point(g, &g->vrec[rec + j]);
        }
        line_point(g, &g->vrec[side_corner(f, e, s, 1)]);
        line_end(g, 1);
    }
    return SILK_OK;
}

/* ---- the coarse mesh's outline -------------------------------------------------- */

/* Front-facing by the face normal, as silhouette.c decides it for feature
 * triangles; a zero-area or broken triangle faces nowhere. */
static int tri_front(const silk_mesh *m, const silk_view *v, uint32_t t)
{
    for (int k = 0; k < 3; k++)
        if (m->tri[3 * t + k] >= m->nverts) return 0;
    silk_vec3 fn = silk_mesh_face_normal(m, t);
    return silk_v3_dot64(fn, silk_view_to_eye(v, m->pos[m->tri[3 * t]])) > 0;
}

/* What edge e is in the outline: 0 nothing, 1 silhouette, 2 feature. */
static int edge_kind(const silk_mesh *m, const uint8_t *front, uint32_t e)
{
    const silk_edge *ed = &m->edge[e];
    uint32_t t0 = ed->t[0], t1 = ed->t[1];
    int f0 = t0 < m->ntris && front[t0], f1 = t1 < m->ntris && front[t1];
    if (t0 < m->ntris && t1 < m->ntris && f0 != f1) return 1;
    if ((ed->flags & SILK_EDGE_FEATURE) && (f0 || f1)) return 2;
    return 0;
}

/* A CORNER record at mesh vertex vtx of triangle t, if t has it. */
static int corner_rec(const silk_mesh *m, uint32_t t, silk_index vtx, silk_vrec *r)
{
    for (uint32_t k = 0; k < 3; k++)
        if (m->tri[3 * t + k] == vtx) {
            memset(r, 0, sizeof *r);
            r->kind = SILK_VREC_CORNER;
            r->a = 3 * t + k;
            return 1;
        }
    return 0;
}

silk_status silk_lines_polygonal(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_frame_geom *g)
{
    g->nlines = g->nline_vrec = 0;
    if (!m->edge || !m->tri) return SILK_OK;
    uint8_t *front = silk_arena_array_top(a, m->ntris, 1, SILK_MEM_FRAME);
    if (!front) return SILK_ERR_NOMEM;
    for (uint32_t t = 0; t < m->ntris; t++) front[t] = (uint8_t)tri_front(m, v, t);
    uint32_t nlines = 0;
    for (uint32_t e = 0; e < m->nedges; e++) nlines += edge_kind(m, front, e) != 0;
    if (!lines_alloc(a, g, nlines, 2 * (uint64_t)nlines)) return SILK_ERR_NOMEM;
    for (uint32_t e = 0; e < m->nedges; e++) {
        int kind = edge_kind(m, front, e);
        if (!kind) continue;
        const silk_edge *ed = &m->edge[e];
        /* the corners of a front-facing triangle where there is one */
        uint32_t t = ed->t[0] < m->ntris && front[ed->t[0]] ? ed->t[0] : ed->t[1];
        if (t >= m->ntris) t = ed->t[0];
        silk_vrec r0, r1;
        if (!corner_rec(m, t, ed->v[0], &r0) || !corner_rec(m, t, ed->v[1], &r1)) continue;
        line_point(g, &r0);
        line_point(g, &r1);
        line_end(g, kind == 2);
    }
    return SILK_OK;
}
