/*
 * vec3.h - the few double-precision 3-vector helpers the host-side mesh
 * tools share (simplify.c, surface.c).  Vectors are double[3].
 */
#ifndef SILK_TOOLS_VEC3_H
#define SILK_TOOLS_VEC3_H

#include <math.h>

static inline void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}
static inline void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline double len3(const double *a) { return sqrt(dot3(a, a)); }

/* Twice the area vector of triangle (a, b, c). */
static inline void tri_normal(const double *a, const double *b, const double *c, double *n)
{
    double e1[3], e2[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, n);
}

#endif
