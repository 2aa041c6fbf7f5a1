/*
 * clip.h - internal: clip mode's per-frame stage (src/clip.c), the outer
 * hull drawn through the detailed model's interpolated silhouette (Gu,
 * Gortler, Hoppe et al., "Silhouette Mapping", sections 8.1 and 8.3).
 */
#ifndef SILK_CLIP_H
#define SILK_CLIP_H

#include "silk/render.h"
#include "silmap_interp.h"

/* One outline edge, top (smaller y) first, clamped to +-2^14 pixels. */
typedef struct silk_clip_edge {
    silk_fx y0, y1, x0, x1;
} silk_clip_edge;

typedef struct silk_clip {
    int width, height;
    int antialias;               /* blend the outline's coverage (else: pixel centres only) */
    silk_silmap_frame info;      /* the interpolation's triangle and views */
    uint32_t npts;               /* the interpolated polygon's vertices */
    uint32_t nedges;             /* its non-horizontal edges, by first row */
    silk_clip_edge *edge;
    uint32_t *row_start;         /* height + 1: edges whose first row is r are row_start[r] .. [r + 1] - 1 */
    uint32_t *active;            /* scratch: the edges crossing a row */
    silk_fx *xs;                 /* scratch: crossings on a scan line */
    uint32_t *cov;               /* scratch: one row's coverage, 256 = the whole pixel */
    uint8_t *mask;               /* the stencil: one band's rows, (width + 7) / 8 bytes each */
    int mask_rows;
    uint32_t spans;              /* stencil spans drawn this frame */
} silk_clip;

/* The outline for view v interpolated from map (starting the triangle
 * search at hint), made into edges, and the stencil for bands of up to
 * band_rows rows, all on the arena's top. */
silk_status silk_clip_prepare(silk_clip *c, silk_arena *a, const silk_silmap *map, const silk_view *v,
                              uint32_t hint, int band_rows, int antialias, silk_error *err);

/* Scan-convert the outline into the stencil for t's band (parity rule) and
 * point t->mask at it: the hull's fragments outside it are discarded. */
void silk_clip_stencil(silk_clip *c, silk_target *t);

/* After the hull is drawn (t->mask cleared): the band's pixels the outline
 * covers only partly, blended between what was drawn there and bg_rgb by
 * the polygon's coverage. */
void silk_clip_antialias(silk_clip *c, silk_target *t, uint32_t bg_rgb);

#endif
