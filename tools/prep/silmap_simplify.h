/*
 * silmap_simplify.h - silhouette map simplification (Gu, Gortler, Hoppe et
 * al., "Silhouette Mapping", section 6), host-side: greedy collapses of
 * the polytope's edges, each dropping one view, cheapest first, where the
 * cost is how far the outlines interpolated from the remaining views (by
 * the renderer's own fixed-point interpolation, src/silmap_interp.c) miss
 * the dropped views' own outlines; collapses that would make the polytope
 * not star-shaped about its centre are never made.
 */
#ifndef SILK_TOOLS_SILMAP_SIMPLIFY_H
#define SILK_TOOLS_SILMAP_SIMPLIFY_H

#include "silmap.h"

typedef struct silmap_simplify_stats {
    uint32_t views_before, views_after;
    uint32_t bytes_before, bytes_after;   /* silk_silmap_bytes of the fixed-point maps */
    double error;                          /* the worst dropped view's error, pixels */
    uint32_t evaluations;                  /* interpolations made */
} silmap_simplify_stats;

/* The error of predicting a view from the others, in pixels: the pixels of
 * its image that the interpolated outline classifies differently from the
 * view's own outline, divided by that outline's length in pixels (about the
 * mean distance between the two). */

/* img (w x h) := 1 where the pixel centre is inside the outline (parity
 * rule), else 0. */
void silmap_fill(const silk_outline *o, int w, int h, uint8_t *img);

/* Collapse edges of m's polytope while the cheapest collapse costs at most
 * max_error pixels and more than min_views views remain.  out is a new map
 * (free with silmap_free).  0, or -1 when out of memory or m cannot be
 * exported to fixed point. */
int silmap_simplify_map(const silmap *m, double max_error, uint32_t min_views, silmap *out,
                        silmap_simplify_stats *stats);

#endif
