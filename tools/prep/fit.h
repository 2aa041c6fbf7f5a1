/*
 * fit.h - fitted normals for `silk prepare --fit` (beyond the paper).
 *
 * Smooth mode's outline runs along the curves it builds over the coarse
 * edges from the vertex normals (paper III-C, eqs. 2-4, with silk's bulge
 * bound): the silhouette points lie on them.  The detailed surface's own
 * normals make those curves circular arcs, which the surface between two
 * coarse vertices rarely is.  Here each vertex normal (vertices with one
 * normal; split ones stay as they are) is moved, within FIT_MAX_DEG of the
 * detailed surface's normal, to bring the curves over its edges closer to
 * the detailed surface: coordinate descent on the sum of squared distances
 * from the detailed surface of the curves' points at u = 1/4, 1/2, 3/4,
 * each curve built exactly as curve.c builds it, the other end's normal
 * held.  The silhouette point on a curve is where the normal interpolated
 * along it (eq. 6) turns away from the eye, so that normal should also be
 * the detailed surface's there: a second term, weighted by
 * FIT_NORMAL_WEIGHT times the chord's length, adds how far it is from the
 * normal of the nearest detailed triangle.  (Positions alone made smooth
 * mode worse on bunny and feline; 0.1 was the best of 0.05, 0.1, 0.3 on
 * bunny and feline.)  Host-side, double precision.
 */
#ifndef SILK_TOOLS_FIT_H
#define SILK_TOOLS_FIT_H

#include "simplify.h"
#include "surface.h"

#define FIT_MAX_DEG 30.0
#define FIT_NORMAL_WEIGHT 0.1

typedef struct fit_stats {
    double before, after;    /* the objective: mean squared distance of the sampled curve points */
    uint32_t moved;          /* normals changed */
} fit_stats;

/* sn's normals are changed in place.  0, or -1 when out of memory. */
int fit_normals(const simp_mesh *fine, const simp_mesh *coarse, surf_normals *sn, fit_stats *st);

#endif
