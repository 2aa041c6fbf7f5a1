/*
 * stex_atlas.h - a texture atlas over a hull for its silhouette texture
 * (Wu, Wei, Wang, Guo, "Silhouette Texture", section 3.3: "parameterize
 * the hull into a 2D texture atlas").  Charts grow from a seed triangle
 * across shared sides, each new triangle unfolded flat about its side, so
 * every chart keeps its triangles' shapes and all charts one texel
 * density; a chart takes the neighbour that keeps it most compact, as long
 * as it overlaps itself nowhere, covers at least 70% of its convex hull
 * and has at most 16 triangles.  Each chart is turned so its bounding box
 * is smallest, framed by one texel of gutter on every side, and the boxes
 * are skyline-packed (tallest first, each where it lies lowest); the
 * density is the largest for which they fit.  Every texel of a box stands
 * for the chart point nearest its centre: its own point inside the chart,
 * the nearest edge point in the gutter, so a bilinear lookup from inside a
 * chart only ever blends that chart's data.
 * Host-side, double precision.
 */
#ifndef SILK_TOOLS_STEX_ATLAS_H
#define SILK_TOOLS_STEX_ATLAS_H

#include <stdint.h>

#include "simplify.h"

typedef struct stex_atlas {
    int w, h;
    uint32_t ncharts;
    double density;          /* texels per unit of length */
    uint16_t *uv;            /* 6 per hull triangle: (u, v) of each corner in 1/16 texel */
    int32_t *tri;            /* w * h: the hull triangle the texel's point lies on, -1: no chart's */
    double *bary;            /* 3 per texel: the point's barycentric coordinates in that triangle */
    uint8_t *inside;         /* w * h: 1 when the texel's centre lies in its chart (not gutter) */
} stex_atlas;

/* The atlas of a closed manifold hull on w x h texels.  0; -1 when out of
 * memory; -2 when the charts do not fit at any density (more triangles than
 * the texels can frame). */
int stex_atlas_build(const simp_mesh *hull, int w, int h, stex_atlas *a);
void stex_atlas_free(stex_atlas *a);

#endif
