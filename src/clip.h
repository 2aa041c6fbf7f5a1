/*
 * clip.h - internal: clip mode's per-frame stage (src/clip.c), the outer
 * hull drawn through the detailed model's interpolated silhouette (Gu,
 * Gortler, Hoppe et al., "Silhouette Mapping", sections 8.1 and 8.3).
 */
#ifndef SILK_CLIP_H
#define SILK_CLIP_H

#include "silk/render.h"
#include "silmap_interp.h"

/* One outline edge, top (smaller y) first, clamped to +-2^14 pixels:
 * x = x0 + (y - y0) * slope on y0 <= y < y1. */
typedef struct silk_clip_edge {
    silk_fx y0, y1, x0;
    int32_t slope;               /* Q16.16 pixels per row, within +-2^15 */
} silk_clip_edge;

/* One loop of the outline: its edges and the rows they reach. */
typedef struct silk_clip_loop {
    uint32_t first, n;           /* edges first .. first + n - 1 */
    int32_t row0, row1;          /* rows row0 .. row1 */
} silk_clip_loop;

typedef struct silk_clip {
    int width, height;
    int antialias;               /* blend the outline's coverage (else: pixel centres only) */
    silk_silmap_frame info;      /* the interpolation's triangle and views */
    uint32_t npts;               /* the interpolated polygon's vertices */
    uint32_t nedges, nloops;     /* its non-horizontal edges, loop by loop */
    silk_clip_edge *edge;
    silk_clip_loop *loop;        /* by first row */
    uint32_t *row_start;         /* height + 2: loops whose first row is r are row_start[r] .. [r + 1] - 1 */
    uint32_t *active, nactive;   /* the loops that reach the current row */
    int active_row;              /* that row; -1: none yet */
    silk_fx *xs;                 /* scratch: one loop's crossings on a scan line */
    uint32_t *cov;               /* scratch: one row's coverage, 256 = the whole pixel */
    uint8_t *mask;               /* the stencil: one band's rows, (width + 7) / 8 bytes each */
    uint8_t *partial;            /* anti-aliasing: the band's coverage where partial (1..255), else 0 */
    int mask_rows;
    uint32_t spans;              /* stencil spans drawn this frame */
} silk_clip;

/* The outline for view v interpolated from map (starting the triangle
 * search at hint), made into edges, and the stencil for bands of up to
 * band_rows rows, all on the arena's top. */
silk_status silk_clip_prepare(silk_clip *c, silk_arena *a, const silk_silmap *map, const silk_view *v,
                              uint32_t hint, int band_rows, int antialias, silk_error *err);

/* The same for a given outline in a width x height frame (the second half
 * of silk_clip_prepare; the tests feed it polygons).  Its loops must be
 * disjoint: coverages of different loops are added. */
silk_status silk_clip_outline(silk_clip *c, silk_arena *a, const silk_outline *o, int width, int height,
                              int band_rows, int antialias, silk_error *err);

/* Scan-convert the outline into the stencil for t's band (parity rule) and
 * point t->mask at it: the hull's fragments outside it are discarded. */
void silk_clip_stencil(silk_clip *c, silk_target *t);

/* After the hull is drawn (t->mask cleared): the band's pixels the outline
 * covers only partly, blended between what was drawn there and bg_rgb by
 * the polygon's coverage, as silk_clip_stencil found it for this band; with
 * t->alpha (filled for the band already) that coverage is their alpha
 * instead, and their colour the hull's. */
void silk_clip_antialias(silk_clip *c, silk_target *t, uint32_t bg_rgb);

#endif
