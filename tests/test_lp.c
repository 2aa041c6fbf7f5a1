/*
 * test_lp.c - the three-variable linear program of tools/prep/lp.c against
 * brute force: every vertex of the arrangement (each triple of planes,
 * box faces included, solved by Cramer's rule) that meets every
 * constraint, the best of them by the objective.  Random problems that are
 * feasible, infeasible, or open on some side so that the box bounds them;
 * degenerate objectives (zero, or along a constraint's normal); many
 * constraints.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "../tools/prep/lp.c"

enum { MAXH = 60 };
#define TOL 1e-9

typedef struct problem {
    lp_halfspace h[MAXH];
    int n;
    double c[3], lo[3], hi[3];
} problem;

/* The worst violation of x against the problem (0: met; box included). */
static double violation(const problem *p, const double x[3])
{
    double worst = 0;
    for (int i = 0; i < p->n; i++) {
        double l = sqrt(dot3(p->h[i].a, p->h[i].a));
        double v = (p->h[i].b - dot3(p->h[i].a, x)) / l;
        if (v > worst) worst = v;
    }
    for (int k = 0; k < 3; k++) {
        if (p->lo[k] - x[k] > worst) worst = p->lo[k] - x[k];
        if (x[k] - p->hi[k] > worst) worst = x[k] - p->hi[k];
    }
    return worst;
}

/* Brute force: the best vertex meeting every constraint within tol, as
 * its objective value; INFINITY when there is none. */
static double brute(const problem *p, double tol)
{
    int m = p->n + 6;
    double A[MAXH + 6][4];
    for (int i = 0; i < p->n; i++) {
        memcpy(A[i], p->h[i].a, sizeof p->h[i].a);
        A[i][3] = p->h[i].b;
    }
    for (int k = 0; k < 3; k++) {
        double *lo = A[p->n + 2 * k], *hi = A[p->n + 2 * k + 1];
        for (int j = 0; j < 3; j++) lo[j] = hi[j] = 0;
        lo[k] = 1, lo[3] = p->lo[k];
        hi[k] = 1, hi[3] = p->hi[k];
    }
    double best = INFINITY;
    for (int i = 0; i < m; i++)
        for (int j = i + 1; j < m; j++)
            for (int k = j + 1; k < m; k++) {
                const double *a = A[i], *b = A[j], *c = A[k];
                double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                             a[2] * (b[0] * c[1] - b[1] * c[0]);
                if (fabs(det) < 1e-12) continue;
                double x[3];
                for (int col = 0; col < 3; col++) {
                    double M[3][3];
                    for (int r = 0; r < 3; r++) {
                        const double *row = r == 0 ? a : r == 1 ? b : c;
                        for (int q = 0; q < 3; q++) M[r][q] = q == col ? row[3] : row[q];
                    }
                    x[col] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                              M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                              M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
                }
                if (violation(p, x) <= tol) {
                    double v = dot3(p->c, x);
                    if (v < best) best = v;
                }
            }
    return best;
}

static void random_halfspace(lp_halfspace *g, const double x0[3], double slack_lo, double slack_hi)
{
    for (int k = 0; k < 3; k++) g->a[k] = check_uniform(-1, 1);
    double s = check_uniform(0.1, 3);   /* normals of any length */
    for (int k = 0; k < 3; k++) g->a[k] *= s;
    g->b = dot3(g->a, x0) - check_uniform(slack_lo, slack_hi);
}

/* A random box, a point x0 in it, n half-spaces whose planes pass
 * between slack_lo and slack_hi from x0 (positive: x0 inside), and a
 * random objective. */
static void random_problem(problem *p, int n, double slack_lo, double slack_hi, double x0[3])
{
    for (int k = 0; k < 3; k++) {
        p->lo[k] = check_uniform(-3, 0);
        p->hi[k] = p->lo[k] + check_uniform(0.5, 4);
        x0[k] = check_uniform(p->lo[k], p->hi[k]);
    }
    p->n = n;
    for (int i = 0; i < n; i++) random_halfspace(&p->h[i], x0, slack_lo, slack_hi);
    for (int k = 0; k < 3; k++) p->c[k] = check_uniform(-1, 1);
}

/* Solve with lp3 and compare with brute force; returns 1 when the case
 * was decided (0: too close to the feasibility boundary to call). */
static int compare(const problem *p, uint64_t *rng)
{
    double feasible_loose = brute(p, 1e-7), feasible_tight = brute(p, 1e-11);
    if (isinf(feasible_loose) != isinf(feasible_tight)) return 0;
    lp_halfspace h[MAXH];
    memcpy(h, p->h, sizeof h);
    double x[3];
    int r = lp3_solve(h, p->n, p->c, p->lo, p->hi, TOL, rng, x);
    if (isinf(feasible_tight)) {
        CHECKF(r == LP_INFEASIBLE, "n %d: solver found a point, brute force none", p->n);
        return 1;
    }
    CHECKF(r == LP_OK, "n %d: solver says infeasible, brute force has %g", p->n, feasible_tight);
    if (r != LP_OK) return 1;
    double v = violation(p, x), scale = 1 + fabs(feasible_tight);
    CHECKF(v <= 1e-8, "n %d: the solver's point violates a constraint by %g", p->n, v);
    CHECKF(fabs(dot3(p->c, x) - feasible_tight) <= 1e-7 * scale, "n %d: objective %.12g, brute force %.12g", p->n,
           dot3(p->c, x), feasible_tight);
    return 1;
}

TEST(lp_feasible_matches_brute_force)
{
    uint64_t rng = 12345;
    for (int trial = 0; trial < 400; trial++) {
        problem p;
        double x0[3];
        random_problem(&p, 1 + (int)(check_rand64() % 30), 0, 1, x0);
        compare(&p, &rng);
    }
}

TEST(lp_infeasible_matches_brute_force)
{
    uint64_t rng = 777;
    int infeasible = 0, decided = 0;
    for (int trial = 0; trial < 400; trial++) {
        problem p;
        double x0[3];
        /* slack of either sign: many of these have no feasible point */
        random_problem(&p, 2 + (int)(check_rand64() % 20), -0.15, 0.5, x0);
        decided += compare(&p, &rng);
        infeasible += isinf(brute(&p, 1e-11));
    }
    printf("  %d of 400 infeasible\n", infeasible);
    CHECKF(infeasible > 50 && infeasible < 350, "%d of 400 infeasible: the cases do not test both sides", infeasible);
    CHECKF(decided > 380, "only %d of 400 decided", decided);
}

/* Few constraints, all open towards the objective: the box decides. */
TEST(lp_unbounded_without_the_box)
{
    uint64_t rng = 99;
    for (int trial = 0; trial < 200; trial++) {
        problem p;
        double x0[3];
        random_problem(&p, 1 + (int)(check_rand64() % 3), 0, 0.5, x0);
        for (int i = 0; i < p.n; i++) {
            /* make the half-space contain the direction -c */
            if (dot3(p.h[i].a, p.c) > 0)
                for (int k = 0; k < 3; k++) p.h[i].a[k] = -p.h[i].a[k];
            p.h[i].b = dot3(p.h[i].a, x0) - 0.1;
        }
        compare(&p, &rng);
    }
}

/* A zero objective (any feasible point), and one along a constraint's
 * normal (a whole face optimal). */
TEST(lp_degenerate_objectives)
{
    uint64_t rng = 5;
    for (int trial = 0; trial < 200; trial++) {
        problem p;
        double x0[3];
        random_problem(&p, 3 + (int)(check_rand64() % 10), 0, 1, x0);
        for (int k = 0; k < 3; k++) p.c[k] = trial & 1 ? 0 : p.h[0].a[k];
        compare(&p, &rng);
    }
}

TEST(lp_many_constraints)
{
    uint64_t rng = 31337;
    for (int trial = 0; trial < 10; trial++) {
        problem p;
        double x0[3];
        random_problem(&p, MAXH, 0, 0.3, x0);
        compare(&p, &rng);
    }
}

/* Zero normals: met or not by b alone. */
TEST(lp_zero_normals)
{
    uint64_t rng = 1;
    lp_halfspace h[2] = { { { 0, 0, 0 }, -1 }, { { 1, 0, 0 }, 0.5 } };
    double c[3] = { 1, 1, 1 }, lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 }, x[3];
    CHECK(lp3_solve(h, 2, c, lo, hi, TOL, &rng, x) == LP_OK);
    CHECKF(fabs(x[0] - 0.5) < 1e-8 && fabs(x[1]) < 1e-8 && fabs(x[2]) < 1e-8, "%g %g %g", x[0], x[1], x[2]);
    lp_halfspace g[1] = { { { 0, 0, 0 }, 1 } };
    CHECK(lp3_solve(g, 1, c, lo, hi, TOL, &rng, x) == LP_INFEASIBLE);
}

int main(void)
{
    RUN(lp_feasible_matches_brute_force);
    RUN(lp_infeasible_matches_brute_force);
    RUN(lp_unbounded_without_the_box);
    RUN(lp_degenerate_objectives);
    RUN(lp_many_constraints);
    RUN(lp_zero_normals);
    return check_done();
}
