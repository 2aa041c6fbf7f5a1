/*
 * lp.h - a linear program in three variables: minimise c.x subject to
 * half-spaces a.x >= b and a bounding box lo <= x <= hi, by Seidel's
 * randomized incremental algorithm ("Small-dimensional linear programming
 * and convex hulls made easy", 1991).  The box keeps every subproblem
 * bounded, so the answer is a point, or "infeasible".  Expected time is
 * linear in the number of half-spaces.  Host-side, double precision; used
 * by the outer-hull edge collapses (tools/prep/hull.c) to place the merged vertex.
 */
#ifndef SILK_TOOLS_LP_H
#define SILK_TOOLS_LP_H

#include <stdint.h>

typedef struct lp_halfspace {
    double a[3], b;   /* the points x with a.x >= b */
} lp_halfspace;

enum { LP_OK = 0, LP_INFEASIBLE = 1 };

/* Solve into x.  h is rewritten (unit normals, in a random order, drawn from *rng, a
 * nonzero xorshift state); half-spaces with a zero normal are satisfied
 * or not by their b alone.  A constraint (the box's faces too) counts as
 * met when it is violated by at most tol, a length: normals are taken at
 * unit length.  Among several optimal points any one may be returned. */
int lp3_solve(lp_halfspace *h, int n, const double c[3], const double lo[3], const double hi[3], double tol,
              uint64_t *rng, double x[3]);

#endif
