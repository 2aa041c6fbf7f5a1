/*
 * silmap_interp.h - internal: the silhouette map as the renderer reads it,
 * and the outline interpolated from it for the current eye (Gu, Gortler,
 * Hoppe et al., "Silhouette Mapping", sections 4 and 5).  Not installed.
 *
 * The map is plain arrays of fixed-point numbers and indices, no pointers
 * into itself, so a file section or a C array in flash can hold it as it
 * is: the loader only points a silk_silmap at the arrays.  tools/prep/silmap.c
 * makes it from the double-precision map (silmap_export).
 *
 * Outlines are closed polygons under the parity (even-odd) rule: a point
 * is inside when a ray from it crosses the loops' edges an odd number of
 * times.  The map's outlines are simple loops with holes; interpolated
 * ones are unions of disjoint quadrilaterals, one per interval of a band
 * of scan lines, which is the same set under that rule.
 */
#ifndef SILK_SILMAP_INTERP_H
#define SILK_SILMAP_INTERP_H

#include <stdint.h>
#include "silk/arena.h"
#include "silk/camera.h"
#include "silk/error.h"
#include "silk/fixed.h"

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

/* ---- the stages (exposed for the tests) ------------------------------------------ */

/* A 3x3 homography in block floating point, one exponent per column
 * (entry (i, j) is m[3i + j] * 2^e[j], |m| < 2^28), and the row whose sign
 * times the third row's says which points lie in front of the camera. */
typedef struct silk_h3 {
    int64_t m[9];
    int32_t e[3];
    int64_t depth[3];
    int32_t de[3];
} silk_h3;

/* The map from the image of camera a (perspective) to the image of camera b.
 * plane == NULL: the two share their eye and the map is exact (a
 * rectification, section 5.2).  Otherwise the points are taken to lie on
 * the plane through *centre with unit normal *plane (the second step of
 * section 5).  SILK_ERR_RANGE when the numbers do not fit. */
silk_status silk_h3_between(const silk_silmap_cam *a, const silk_silmap_cam *b, const silk_vec3 *plane,
                            const silk_vec3 *centre, silk_h3 *h);
/* Map one point; 0, or -1 when it lands behind camera b or at infinity. */
int silk_h3_apply(const silk_h3 *h, silk_vec2 p, silk_vec2 *out);

/* Map every point of in into a new outline on the arena's top.
 * SILK_ERR_RANGE when a point lands behind the camera. */
silk_status silk_outline_map(const silk_outline *in, const silk_h3 *h, silk_arena *a, silk_outline *out);

/* The two rectified cameras of section 5.2 for eyes pa and pb: the same
 * orientation, right along pb - pa, looking at centre square to it, so that
 * both see every point on the same scan line; principal point 0 and the
 * given focal length.  SILK_ERR_ARG when the eyes coincide. */
silk_status silk_silmap_rectified(silk_vec3 pa, silk_vec3 pb, silk_vec3 centre, silk_fx focal,
                                  silk_silmap_cam *ra, silk_silmap_cam *rb);

/* Linear silhouette interpolation (section 5.2) of two outlines seen by two
 * rectified cameras, at alpha in [0, 1] from a to b: on every band of scan
 * lines between the outlines' vertices, every interval of a with every
 * interval of b interpolated end by end (section 5.3's equations; all pairs
 * is the pants connection and its n-legged variants), their union.  This is
 * the silhouette of the two views' visual hull seen from the eye at alpha.
 * The result lives on the arena's top. */
silk_status silk_outline_lerp(const silk_outline *a, const silk_outline *b, silk_fx alpha, silk_arena *ar,
                              silk_outline *out);

/* The polytope triangle that the ray from the centre through eye meets
 * (section 4), searched from triangle hint by walking towards it, and the
 * meeting point's barycentric coordinates (Q16.16, summing to one). */
silk_status silk_silmap_locate(const silk_silmap *m, silk_vec3 eye, uint32_t hint, uint32_t *tri,
                               silk_fx bary[3]);

/* What one interpolation did. */
typedef struct silk_silmap_frame {
    uint32_t tri;                   /* the triangle met: the next frame's hint */
    uint32_t views[3];              /* its views, in the order interpolated: (v1, v2) then v3 */
    silk_fx alpha12, alpha3;        /* the two interpolation parameters */
    silk_silmap_cam vt;             /* the interpolated view, on the triangle */
} silk_silmap_frame;

/* The outline for the current view (section 5): locate, interpolate the
 * views of the triangle's closest edge, then that with the third view, and
 * map the result to the current view as if the outline lay in the plane
 * through the centre parallel to the triangle.  out is in the current
 * view's pixels, on the arena's top (release it with a mark taken before). */
silk_status silk_silmap_interp(const silk_silmap *m, const silk_view *cur, uint32_t hint, silk_arena *a,
                               silk_outline *out, silk_silmap_frame *info, silk_error *err);

/* The current view as a map camera. */
void silk_silmap_cam_of_view(const silk_view *v, silk_silmap_cam *c);

#endif
