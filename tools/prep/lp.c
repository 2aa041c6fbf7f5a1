/*
 * lp.c - Seidel's randomized incremental linear programming in three
 * variables (see lp.h).
 *
 * The optimum of the box alone is a corner.  Half-spaces are added in a
 * random order; while the current optimum meets the new one it stays
 * optimal, else the new optimum lies on the new one's plane, and is found
 * by the same algorithm one dimension down: a two-variable problem in the
 * plane (over the box and the half-spaces added before), whose own misses
 * drop to a one-variable problem on a line: an interval.  Every subproblem
 * carries a box of its own that holds the 3D box's part of it, so none is
 * unbounded and each starts from a corner.  Constraints are loosened by tol
 * throughout, so that a point on several planes at once still meets them
 * after rounding.
 */
#include <math.h>

#include "lp.h"

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The problem as the subproblems see it: the box as six half-spaces in
 * front of the caller's. */
typedef struct lp3 {
    lp_halfspace box[6];
    const lp_halfspace *h;
    double tol;
} lp3;

static const lp_halfspace *get(const lp3 *p, int k) { return k < 6 ? &p->box[k] : &p->h[k - 6]; }

/* A plane of the 3D problem as a 2D frame: x = p0 + s e1 + t e2. */
typedef struct frame { double p0[3], e1[3], e2[3]; } frame;

/* The 2D half-plane (n . y >= r) that half-space g cuts from frame f. */
static void project(const frame *f, const lp_halfspace *g, double n[2], double *r)
{
    n[0] = dot3(g->a, f->e1);
    n[1] = dot3(g->a, f->e2);
    *r = g->b - dot3(g->a, f->p0);
}

/* One variable: minimise c2 . y on the line n . y = r of frame f, inside
 * the square |s|, |t| <= R and the half-spaces 0..m-1.  0 or -1. */
static int solve1(const lp3 *p, const frame *f, int m, const double n[2], double r, const double c2[2], double R,
                  double y[2])
{
    double nn = n[0] * n[0] + n[1] * n[1], ln = sqrt(nn);
    double q[2] = { n[0] * r / nn, n[1] * r / nn }, d[2] = { -n[1] / ln, n[0] / ln };
    double lo = -INFINITY, hi = INFINITY, tol = p->tol;
    /* alpha * u >= gamma for each constraint, u the position along d */
    for (int k = -4; k < m; k++) {
        double gn[2], gr;
        if (k < 0) {   /* the square: +-s <= R, +-t <= R */
            int axis = (k + 4) >> 1;
            double sign = (k + 4) & 1 ? 1 : -1;   /* sign * y[axis] >= -R */
            gn[0] = axis == 0 ? sign : 0;
            gn[1] = axis == 1 ? sign : 0;
            gr = -R;
        } else {
            project(f, get(p, k), gn, &gr);
        }
        double alpha = gn[0] * d[0] + gn[1] * d[1];
        double gamma = gr - tol - (gn[0] * q[0] + gn[1] * q[1]);
        if (fabs(alpha) < 1e-12) {
            if (gamma > 0) return -1;
        } else if (alpha > 0) {
            if (gamma / alpha > lo) lo = gamma / alpha;
        } else if (gamma / alpha < hi) {
            hi = gamma / alpha;
        }
    }
    if (!(lo <= hi)) return -1;
    double c1 = c2[0] * d[0] + c2[1] * d[1];
    double u = c1 > 0 ? lo : c1 < 0 ? hi : (lo + hi) / 2;
    y[0] = q[0] + u * d[0];
    y[1] = q[1] + u * d[1];
    return 0;
}

/* Two variables: minimise c on the plane of half-space g (taken as an
 * equality) over half-spaces 0..m-1 of p; the answer into x.  0 or -1. */
static int solve2(const lp3 *p, const lp_halfspace *g, int m, const double c[3], const double mid[3], double R,
                  double x[3])
{
    frame f;
    double off = g->b - dot3(g->a, mid);
    if (fabs(off) > R + p->tol) return -1;   /* the plane misses the box's ball */
    for (int k = 0; k < 3; k++) f.p0[k] = mid[k] + off * g->a[k];
    /* e1: a unit vector across the normal, from the axis it is least along */
    int ax = fabs(g->a[0]) <= fabs(g->a[1]) && fabs(g->a[0]) <= fabs(g->a[2]) ? 0 : fabs(g->a[1]) <= fabs(g->a[2]) ? 1 : 2;
    double e[3] = { 0, 0, 0 };
    e[ax] = 1;
    f.e1[0] = g->a[1] * e[2] - g->a[2] * e[1];
    f.e1[1] = g->a[2] * e[0] - g->a[0] * e[2];
    f.e1[2] = g->a[0] * e[1] - g->a[1] * e[0];
    double l = sqrt(dot3(f.e1, f.e1));
    for (int k = 0; k < 3; k++) f.e1[k] /= l;
    f.e2[0] = g->a[1] * f.e1[2] - g->a[2] * f.e1[1];
    f.e2[1] = g->a[2] * f.e1[0] - g->a[0] * f.e1[2];
    f.e2[2] = g->a[0] * f.e1[1] - g->a[1] * f.e1[0];

    double c2[2] = { dot3(c, f.e1), dot3(c, f.e2) };
    double y[2] = { c2[0] > 0 ? -R : R, c2[1] > 0 ? -R : R };
    for (int j = 0; j < m; j++) {
        double n[2], r;
        project(&f, get(p, j), n, &r);
        if (n[0] * y[0] + n[1] * y[1] >= r - p->tol) continue;
        if (n[0] * n[0] + n[1] * n[1] < 1e-24) return -1;   /* parallel to the plane, and missed */
        if (solve1(p, &f, j, n, r, c2, R, y)) return -1;
    }
    for (int k = 0; k < 3; k++) x[k] = f.p0[k] + y[0] * f.e1[k] + y[1] * f.e2[k];
    return 0;
}

static uint64_t next(uint64_t *s)
{
    uint64_t x = *s;
    x ^= x >> 12, x ^= x << 25, x ^= x >> 27;
    *s = x;
    return x * 0x2545F4914F6CDD1Dull;
}

int lp3_solve(lp_halfspace *h, int n, const double c[3], const double lo[3], const double hi[3], double tol,
              uint64_t *rng, double x[3])
{
    /* Unit normals; a zero normal is met or not everywhere. */
    int m = 0;
    for (int i = 0; i < n; i++) {
        double l = sqrt(dot3(h[i].a, h[i].a));
        if (!(l > 1e-300)) {
            if (h[i].b > tol) return LP_INFEASIBLE;
            continue;
        }
        lp_halfspace g = { { h[i].a[0] / l, h[i].a[1] / l, h[i].a[2] / l }, h[i].b / l };
        h[m++] = g;
    }
    for (int i = m - 1; i > 0; i--) {
        int j = (int)(next(rng) % (uint64_t)(i + 1));
        lp_halfspace t = h[i];
        h[i] = h[j];
        h[j] = t;
    }
    lp3 p = { .h = h, .tol = tol };
    double mid[3], R2 = 0;
    for (int k = 0; k < 3; k++) {
        if (!(lo[k] <= hi[k])) return LP_INFEASIBLE;
        p.box[2 * k] = (lp_halfspace){ { k == 0, k == 1, k == 2 }, lo[k] };
        p.box[2 * k + 1] = (lp_halfspace){ { -(k == 0), -(k == 1), -(k == 2) }, -hi[k] };
        mid[k] = (lo[k] + hi[k]) / 2;
        R2 += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
        x[k] = c[k] > 0 ? lo[k] : hi[k];
    }
    double R = sqrt(R2) + tol;
    for (int i = 0; i < m; i++) {
        if (dot3(h[i].a, x) >= h[i].b - tol) continue;
        if (solve2(&p, &h[i], 6 + i, c, mid, R, x)) return LP_INFEASIBLE;
    }
    return LP_OK;
}
