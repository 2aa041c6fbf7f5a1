/*
 * testvec.h - test support: the double-precision reference arithmetic the
 * tests compare the fixed-point core against.  Q16.16 <-> double, 3-vectors
 * as a struct (dvec) and as double[3].
 *
 * Header-only on purpose: rand_unit draws from check.h's generator, whose
 * state is private to each test program, so the tests keep their random
 * sequences.  It is there when check.h is included first (the tests); the
 * support files use the rest.
 */
#ifndef SILK_TESTVEC_H
#define SILK_TESTVEC_H

#include <math.h>
#include "silk/fixed.h"

/* Exact: every Q16.16 value is a double. */
static inline double fx2d(silk_fx v) { return v / 65536.0; }
/* Nearest, halves away from zero; no saturation (callers stay in range). */
static inline silk_fx d2fx(double v) { return (silk_fx)llround(v * 65536.0); }

typedef struct dvec { double x, y, z; } dvec;

static inline dvec dmk(double x, double y, double z) { dvec r = { x, y, z }; return r; }
static inline dvec dv(silk_vec3 a) { return dmk(fx2d(a.x), fx2d(a.y), fx2d(a.z)); }
static inline silk_vec3 tofx(dvec a) { return silk_v3(d2fx(a.x), d2fx(a.y), d2fx(a.z)); }
static inline dvec dadd(dvec a, dvec b) { return dmk(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline dvec dsub(dvec a, dvec b) { return dmk(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline dvec dscale(dvec a, double s) { return dmk(a.x * s, a.y * s, a.z * s); }
static inline double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline dvec dcross(dvec a, dvec b)
{
    return dmk(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double dlen(dvec a) { return sqrt(ddot(a, a)); }
/* The zero vector stays zero rather than becoming NaN. */
static inline dvec dnorm(dvec a) { double l = dlen(a); return l > 0 ? dscale(a, 1 / l) : a; }
/* Largest component difference between the reference and a fixed-point vector. */
static inline double ddist(dvec a, silk_vec3 b)
{
    return fmax(fabs(a.x - fx2d(b.x)), fmax(fabs(a.y - fx2d(b.y)), fabs(a.z - fx2d(b.z))));
}
static inline int v3_eq(silk_vec3 a, silk_vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

#ifdef SILK_CHECK_H
/* Uniform on the unit sphere, by rejection from the cube (the shell
 * 0.1 < |v| <= 1 keeps the division well conditioned). */
static inline dvec rand_unit(void)
{
    for (;;) {
        dvec v = dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1));
        double l = dlen(v);
        if (l > 0.1 && l <= 1) return dscale(v, 1 / l);
    }
}
#endif

/* ---- the same as double[3] ------------------------------------------------- */

static inline void vec3d(silk_vec3 v, double o[3]) { o[0] = fx2d(v.x); o[1] = fx2d(v.y); o[2] = fx2d(v.z); }
static inline double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

#endif
