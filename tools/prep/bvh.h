/*
 * bvh.h - the nearest hit of a ray on a triangle mesh, through the box
 * hierarchy of tools/prep/closest.h (the same tree answers closest-point and ray
 * queries): slab tests against the boxes, nearer child first, and the
 * Moller-Trumbore test on the triangles of the leaves (both sides).
 * Host-side, double precision; for the visibility functions of silhouette
 * textures (tools/prep/stex_build.c).
 */
#ifndef SILK_TOOLS_BVH_H
#define SILK_TOOLS_BVH_H

#include <stdint.h>

#include "closest.h"

#define BVH_NO_TRI UINT32_MAX

/* Distance t along the ray o + t d (d need not be unit; t in units of |d|)
 * of the triangle abc, or INFINITY when the ray's line misses it.  Either
 * side counts. */
double ray_tri(const double o[3], const double d[3], const double *a, const double *b, const double *c);

/* The nearest hit with tmin < t < tmax, triangle skip left out (BVH_NO_TRI:
 * none): its t, its triangle in *tri when tri is not NULL; INFINITY when
 * there is none (*tri untouched). */
double bvh_ray(const cp_tree *t, const double o[3], const double d[3], double tmin, double tmax, uint32_t skip,
               uint32_t *tri);

#endif
