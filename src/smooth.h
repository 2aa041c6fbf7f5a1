/*
 * smooth.h - internal: what the per-frame silhouette stages hand to the
 * renderer.  Not installed; the public entry point is silk_render().
 *
 * A frame's geometry is a list of vertex records (silk/hal.h) and triangles
 * over them.  In FLAT mode every triangle corner is a CORNER record; in SMOOTH
 * mode silhouette triangles and triangles with visible feature segments are
 * replaced by triangles through CURVE samples, and vertices next to concave
 * silhouette segments become MOVED records.
 */
#ifndef SILK_SMOOTH_H
#define SILK_SMOOTH_H

#include "silk/silk.h"

typedef struct silk_frame_geom {
    silk_vrec  *vrec;  uint32_t nvrec;
    uint32_t   *tri;   uint32_t ntri;    /* 3 per triangle, indices into vrec */
    uint8_t    *tri_added;               /* per triangle: 1 if made by re-meshing (drawn red by --wire) */
    silk_curve *curve; uint32_t ncurve;
    silk_vec3  *offset; uint32_t noffset;
    silk_patch *patch; uint32_t npatch;  /* PN and BLEND modes */
    /* Pen-and-ink lines (lines.c), when asked for: line i is the polyline
     * through line_vrec[line_start[i] .. line_start[i+1]-1], a silhouette
     * line or a feature line (line_feature[i]).  Records of their own;
     * where a line runs along the triangles' edges they are copies of the
     * triangles' records, and line_src says which (else SILK_LINE_NO_SRC). */
    silk_vrec  *line_vrec; uint32_t nline_vrec;
    uint32_t   *line_src;                /* nline_vrec */
    uint32_t   *line_start;              /* nlines + 1 */
    uint8_t    *line_feature;            /* nlines */
    uint32_t    nlines;
} silk_frame_geom;

/* The coarse mesh as it is: one CORNER record per triangle corner. */
silk_status silk_frame_flat(silk_arena *a, const silk_mesh *m, silk_frame_geom *g, silk_error *err);

/* Paper section III for one view.  All arrays come from the top of the arena
 * (purpose FRAME); the caller releases them.  When the arena runs out part way,
 * the triangles not yet re-meshed are emitted as they are, stats->fell_back is
 * set and SILK_OK is returned. */
silk_status silk_frame_smooth(silk_arena *a, const silk_mesh *m, const silk_view *v,
                              silk_fx tolerance_px, silk_vis_method vis,
                              silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

/* silk_frame_smooth, and with lines non-zero also the lines of the frame
 * (lines.c): the sampled silhouette segments and visible feature curves
 * through the very records the triangles use.  When the frame falls back to
 * the coarse mesh, its polygonal lines instead. */
silk_status silk_frame_smooth_lines(silk_arena *a, const silk_mesh *m, const silk_view *v,
                                    silk_fx tolerance_px, silk_vis_method vis, int lines,
                                    silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

#define SILK_LINE_NO_SRC UINT32_MAX

/* The coarse mesh's outline for lines (lines.c): every edge between a
 * front- and a back-facing triangle, and every feature edge next to a
 * front-facing triangle, as two CORNER records.  Fills g's line arrays
 * (from the top of the arena); SILK_ERR_NOMEM when they do not fit.  With
 * on_mesh, g's records 3t+k are the mesh's corners (FLAT mode), and the
 * lines name them as their sources. */
silk_status silk_lines_polygonal(silk_arena *a, const silk_mesh *m, const silk_view *v, int on_mesh,
                                 silk_frame_geom *g);

/* The contour of the drawn triangles (after the vertex stage; out: its
 * output for every record of g): every side shared by two triangles of g
 * that face opposite ways on screen and that no line of g runs along yet,
 * added to g's lines as a silhouette line.  Where the outline of the
 * re-meshed surface leaves its silhouette segments (a fold along a mesh
 * edge, round a cone's apex) these close it.  SILK_ERR_NOMEM, with g's
 * lines unchanged, when they do not fit. */
silk_status silk_lines_contour(silk_arena *a, silk_frame_geom *g, const silk_vertex_out *out, int width, int height);

/* How far to lift each line vertex towards the eye so that the triangles
 * it lies on do not hide it: per line record, in units of 2^-24 of the
 * rasterizer's depth (w - z) / w, from the depth slopes of the triangles
 * through its source point (out: the vertex stage's output for every
 * record of g).  NULL when the arena has no room (the lines then get only
 * silk_raster_line's own bias). */
uint32_t *silk_lines_lift(silk_arena *a, const silk_mesh *m, const silk_frame_geom *g, const silk_vertex_out *out,
                          int width, int height);
/* o moved towards the eye by lift (as above), keeping its pixel. */
void silk_lines_apply_lift(silk_vertex_out *o, uint32_t lift);

/* PN triangles (src/pn.c): every triangle's cubic patch, its sides cut
 * into level segments, with quadratic or linear normals.  View-independent.
 * Same contract as silk_frame_smooth: arrays from the top of the arena, and
 * when they do not fit the coarse mesh is emitted with stats->fell_back set. */
silk_status silk_frame_pn(silk_arena *a, const silk_mesh *m, uint32_t level, silk_pn_normals normals,
                          silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

/* Silhouetteness blending (src/blend.c, Dyken & Reimers): triangles whose
 * three edges have silhouetteness 0 stay as they are; the others become
 * patches blended between flat and PN by the silhouetteness of each edge,
 * drawn as a fan around the patch centre with each edge cut into as many
 * segments as tolerance_px needs.  Same contract as silk_frame_smooth. */
silk_status silk_frame_blend(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx beta,
                             silk_fx tolerance_px, silk_frame_geom *g, silk_frame_stats *stats,
                             silk_error *err);

#endif
