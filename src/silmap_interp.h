/*
 * silmap_interp.h - internal: the steps of the outline interpolated from a
 * silhouette map for the current eye (Gu, Gortler, Hoppe et al.,
 * "Silhouette Mapping", section 5), exposed for the tests.  The map, its
 * outlines and the interpolation itself are public: silk/silmap.h.  Not
 * installed.
 */
#ifndef SILK_SILMAP_INTERP_H
#define SILK_SILMAP_INTERP_H

#include <stdint.h>
#include "silk/silmap.h"

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

#endif
