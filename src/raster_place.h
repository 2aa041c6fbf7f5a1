/*
 * raster_place.h - internal: what the rasterizer (raster.c) tells the
 * renderer (render.c and its frame_*.c) and the outline (aa.c) of where it
 * puts a vertex, and the triangles it draws from vertices placed once.
 * Not installed.
 */
#ifndef SILK_RASTER_PLACE_H
#define SILK_RASTER_PLACE_H

#include "silk/silk.h"

/* raster.c: the row of a frame `height` rows high that the rasterizer
 * maps clip point c to (w > 0), so that a renderer can tell which band a
 * vertex falls in exactly as the rasterizer will. */
int64_t silk_raster_row(const silk_vec4 *c, int height);
/* raster.c: whether triangle a b c, drawn into t (any of its bands) with
 * back faces culled, draws nothing for a reason the vertices alone give:
 * wholly outside one clip plane, or inside every plane (not clipped) and
 * degenerate or seen from behind on the screen. */
int silk_raster_culled(const silk_target *t, const silk_vertex_out *a, const silk_vertex_out *b,
                       const silk_vertex_out *c);
/* raster.c: where the rasterizer puts v (w > 0): x, y in 1/SILK_RASTER_SUB
 * pixels (pixel (0,0) covers [0, SILK_RASTER_SUB)^2), depth d as in the
 * depth buffer. */
#define SILK_RASTER_SUB 16
void silk_raster_point(const silk_target *t, const silk_vertex_out *v, int64_t *x, int64_t *y, uint32_t *d);

/* raster.c, for a renderer that places each vertex once a frame
 * (frame_fast.c's SILK_DRAW_DIRECT, frame_draw.c's SILK_PLACE_ONCE):
 * silk_raster_place puts a vertex at clip coordinates clip where
 * silk_raster_triangle does (xy in 1/SILK_RASTER_SUB pixels) and returns
 * 1, or returns 0 when it lies outside a clip plane (then the triangles at
 * it are clipped); silk_raster_reaches says from three vertices so placed
 * alone whether silk_raster_triangle could draw a pixel of their triangle
 * (0: it draws none, whatever the rest of the vertices' output); for one
 * that could, silk_raster_placed is silk_raster_triangle, the same pixels
 * without placing them again. */
int silk_raster_place(const silk_target *t, const silk_vec4 *clip, int32_t xy[2]);
int silk_raster_reaches(const silk_target *t, const int32_t *const xy[3]);
void silk_raster_placed(silk_target *t, const silk_hal *h, const silk_vertex_out *const v[3],
                        const int32_t *const xy[3]);

#endif
