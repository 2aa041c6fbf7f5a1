/*
 * stexgen.h - test support: prepared models with a silhouette texture made
 * analytically, for the tests of siltex mode before any ray casting.
 *
 * The detailed model is one or two spheres of radius r; the hull of each
 * is an icosphere of circumradius R > r about the same centre (its faces
 * clear the sphere).  A hull point p sees its sphere along exactly the
 * directions within asin(r / |p - c|) of C = (c - p) / |p - c|, and no
 * other sphere before another part of the hull, so every texel's
 * visibility function is that cone: phi the same at every azimuth, C
 * interpolated from the vertices' C exact at every hull point.  The atlas
 * is one square cell per triangle, the triangle a right triangle in it one
 * texel in from the cell's top and left sides, every texel of a cell
 * holding the data of the nearest point of its triangle.
 */
#ifndef SILK_STEXGEN_H
#define SILK_STEXGEN_H

#include <stddef.h>
#include <stdint.h>

typedef struct stexgen_opts {
    int nspheres;            /* 1 or 2 */
    double c[2][3];          /* centres */
    double r[2], R[2];       /* sphere and hull radii */
    int level;               /* icosphere subdivisions (0: the icosahedron, 20 triangles) */
    int cell;                /* texels on a cell's side, 4.. */
    int k;                   /* azimuth samples */
    int eigen;               /* 0: angles stored; 1..k: compressed with that many eigenfunctions */
    int color;               /* a colour map (the normal's direction as colour) */
} stexgen_opts;

/* One sphere of radius 1 at the origin, its hull R = 1.06, level 2, cells
 * of 6 texels, 8 azimuths, stored angles, no colour. */
void stexgen_defaults(stexgen_opts *o);

/* The model file (HULL and STEX sections) in a malloc'd buffer; NULL when
 * out of memory or the options are out of range. */
uint8_t *stexgen_model(const stexgen_opts *o, size_t *len);

#endif
