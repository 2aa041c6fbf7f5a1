/*
 * silk/budget.h - how much arena a frame needs, before drawing it.
 *
 * A device sizes its one static arena once.  silk_budget_frame() gives,
 * for a mesh, a frame size and band height, a pixel format and render
 * options, in this build's configuration (index type, what is built in),
 * the arena a FLAT or SMOOTH frame takes at most from any camera: the band
 * buffers and the per-frame scratch (the arena's top).  It is a safe upper
 * bound, not a measurement: it assumes the worst a mesh allows (every
 * triangle on the silhouette, every feature edge sampled as finely as eq. 8
 * ever asks), so it is a few times what a frame really takes.  What one
 * frame takes exactly, from one camera, is its silk_frame_stats.frame_bytes
 * (silk info prints it, and make profile the worst of a board's views);
 * docs/porting.md says how to use both, tests/core/test_budget.c checks that
 * every frame drawn with the bound's bytes is the same as with plenty.
 *
 * The bound holds with render_opts.vertex_cache_bytes 0 (what the boards
 * set): a larger budget lets the renderer take more for speed on top.
 */
#ifndef SILK_BUDGET_H
#define SILK_BUDGET_H

#include <stddef.h>
#include "error.h"
#include "mesh.h"
#include "raster.h"
#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct silk_budget {
    size_t bands;            /* band buffers: colour (two with a second buffer for DMA) and depth, from the arena's bottom */
    size_t frame;            /* per-frame scratch at most, from the top: the plan, one share, rows, outline */
    size_t total;            /* bands + frame: the arena beside a mesh packed into flash */
} silk_budget;

/* The arena a frame of m at width x height in bands of rows rows (height:
 * the whole frame in one) in format fmt with options o takes at most, from
 * any camera, into *b.  double_buffered: a second colour buffer for a DMA
 * sink (silk_sink.color2).  A mesh loaded into the arena adds its bytes
 * (silk_mesh_bytes_used) below.  SILK_ERR_ARG for a mode other than FLAT
 * and SMOOTH, or with lines or wire (their frames are stored, not
 * bounded here), or sizes out of range. */
silk_status silk_budget_frame(const silk_mesh *m, const silk_render_opts *o, int width, int height, int rows,
                              silk_pixfmt fmt, int double_buffered, silk_budget *b, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
