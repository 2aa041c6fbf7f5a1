/*
 * lines.h - internal: pen-and-ink lines (lines.c): the smooth outline from
 * the plan, the coarse mesh's outline, the contour of the drawn triangles,
 * and the lift that keeps them off the surface they lie on.  Not installed.
 */
#ifndef SILK_LINES_H
#define SILK_LINES_H

#include "plan.h"

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
 * that face opposite ways on screen, added to g's lines as a silhouette
 * line.  Where the outline of the re-meshed surface leaves its silhouette
 * segments (a fold along a mesh edge, round a cone's apex) these close it.  SILK_ERR_NOMEM, with g's
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

/* From the plan f and its stored frame g (silk_remesh_store), the lines
 * of the frame into g (the silhouette segments and visible feature curves
 * drawn, through the records of the shares), and g->rec_key, which point
 * each record is; SILK_ERR_NOMEM when they do not fit, with no lines in g. */
silk_status silk_lines_smooth(const silk_sil_frame *f, silk_frame_geom *g);

#endif
