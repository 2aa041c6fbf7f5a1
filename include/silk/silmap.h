/*
 * silk/silmap.h - silhouette maps (Gu, Gortler, Hoppe et al., "Silhouette
 * Mapping", sections 4 and 5): the detailed model's outline seen from many
 * views around it, from which clip mode interpolates the outline for any
 * eye and draws the outer hull through it.
 *
 * The map is plain arrays of fixed-point numbers and indices, no pointers
 * into itself, so a file section or a C array in flash holds it as it is:
 * silk_model_silmap (silk/model.h) checks a model's SMAP section and points
 * a silk_silmap at its arrays; `silk prepare` makes the section
 * (docs/formats.md "SMAP" has the byte layout, docs/clipping.md the method).
 * This header is what a program that makes or reads maps shares with the
 * renderer; the interpolation's inner steps are the core's own.
 *
 * Outlines are closed polygons under the parity (even-odd) rule: a point
 * is inside when a ray from it crosses the loops' edges an odd number of
 * times.  The map's outlines are simple loops with holes; interpolated
 * ones are unions of disjoint quadrilaterals, one per interval of a band
 * of scan lines, which is the same set under that rule.
 */
#ifndef SILK_SILMAP_H
#define SILK_SILMAP_H

#include <stdint.h>
#include "arena.h"
#include "camera.h"
#include "error.h"
#include "fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A pinhole camera in the map's terms: a world point q is seen at
 *   x = cx + focal * (q - eye).right / (q - eye).fwd
 *   y = cy - focal * (q - eye).up    / (q - eye).fwd      (y down),
 * or with ortho set, without the divisions (focal: pixels per world unit).
 * right, up, fwd are orthonormal; the map's own views are perspective. */
typedef struct silk_silmap_cam {
    silk_vec3 eye, right, up, fwd;
    silk_fx focal, cx, cy;       /* pixels */
    int32_t ortho;
} silk_silmap_cam;

typedef struct silk_silmap_view {
    silk_silmap_cam cam;
    uint32_t first_loop, nloops; /* its outline: loops first_loop .. first_loop + nloops - 1 */
} silk_silmap_view;

/* The map (section 4): one view per vertex of a star-shaped polytope around
 * centre, the polytope's triangles (counter-clockwise seen from outside)
 * with their neighbours, and every view's outline in its image. */
typedef struct silk_silmap {
    silk_vec3 centre;
    uint32_t nviews, ntris, nloops, npts;
    const silk_silmap_view *views;  /* nviews; view i's eye is polytope vertex i */
    const uint32_t *tri;            /* 3 * ntris view indices */
    const uint32_t *adj;            /* 3 * ntris: the triangle across the edge opposite corner k */
    const uint32_t *loop_start;     /* nloops + 1 offsets into pts */
    const silk_vec2 *pts;           /* npts image points, pixels */
} silk_silmap;

/* Bytes the map's arrays take (what a file section or flash holds). */
uint32_t silk_silmap_bytes(const silk_silmap *m);

/* Closed loops in some camera's image: loop i is pt[start[i]] ..
 * pt[start[i + 1] - 1], joined back to its first point. */
typedef struct silk_outline {
    uint32_t nloops, npts;
    const uint32_t *start;          /* nloops + 1 */
    const silk_vec2 *pt;
} silk_outline;

/* View i's outline, pointing into the map's arrays. */
silk_outline silk_silmap_outline(const silk_silmap *m, uint32_t view);

/* The current view as a map camera. */
void silk_silmap_cam_of_view(const silk_view *v, silk_silmap_cam *c);

/* An outline seen by camera from, as camera to sees it from the same eye
 * (exact: a 3x3 projective map of the image).  The result lives on the
 * arena's top.  SILK_ERR_RANGE when a point lands behind camera to or the
 * numbers do not fit. */
silk_status silk_outline_reproject(const silk_outline *in, const silk_silmap_cam *from, const silk_silmap_cam *to,
                                   silk_arena *a, silk_outline *out);

/* What one interpolation did. */
typedef struct silk_silmap_frame {
    uint32_t tri;                   /* the triangle met: the next frame's hint */
    uint32_t views[3];              /* its views, in the order interpolated: (v1, v2) then v3 */
    silk_fx alpha12, alpha3;        /* the two interpolation parameters */
    silk_silmap_cam vt;             /* the interpolated view, on the triangle */
} silk_silmap_frame;

/* The outline for the current view (section 5): the polytope triangle the
 * ray from the centre through the eye meets (searched from triangle hint),
 * the views of its closest edge interpolated, then that with the third
 * view, and the result mapped to the current view as if the outline lay
 * in the plane through the centre parallel to the triangle.  out is in the
 * current view's pixels, on the arena's top (release it with a mark taken
 * before); info, when not NULL, says what was done. */
silk_status silk_silmap_interp(const silk_silmap *m, const silk_view *cur, uint32_t hint, silk_arena *a,
                               silk_outline *out, silk_silmap_frame *info, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
