/*
 * gen.c - the analytic meshes of `silk gen` (host-side, double precision).
 *
 * Every shape is a sequence of rings: a ring is either one point (a pole, an
 * apex, a cap centre) or `n` points around a circle.  Consecutive rings are
 * joined by fans or quads, and periodic shapes (torus, knot) join the last
 * ring to the first.  Within a ring the points advance in the direction phi,
 * from ring to ring in the direction theta, and each shape orders its rings
 * so that dP/dphi x dP/dtheta points out of the solid: the quad
 * (a, b, c, d) = ((j,k), (j+1,k), (j+1,k+1), (j,k+1)) then gives the
 * triangles (a,b,c) and (a,c,d), counter-clockwise seen from outside.
 */
#define _POSIX_C_SOURCE 200809L   /* open_memstream */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "gen.h"

static const double PI = CLI_PI;
static const double TAU = 2 * CLI_PI;

static const char *const shape_names[GEN_SHAPE_COUNT] = { "sphere", "torus", "cone", "cylinder", "knot" };

const char *gen_shape_name(gen_shape s)
{
    return (unsigned)s < GEN_SHAPE_COUNT ? shape_names[s] : "?";
}

gen_shape gen_shape_from_name(const char *name)
{
    for (int i = 0; i < GEN_SHAPE_COUNT; i++)
        if (strcmp(name, shape_names[i]) == 0) return (gen_shape)i;
    return GEN_SHAPE_COUNT;
}

void gen_defaults(gen_shape s, gen_params *p)
{
    memset(p, 0, sizeof *p);
    p->shape = s;
    p->radius = 1.0;
    p->R = 1.0;
    p->r = 0.4;
    p->tube = 0.25;
    p->p = 2;
    p->q = 3;
    switch (s) {
    case GEN_SPHERE:   p->segments = 10; p->bands = 11; break;   /* 200 triangles, as in the paper */
    case GEN_TORUS:    p->segments = 24; p->bands = 12; break;   /* 576 triangles, as in the paper */
    case GEN_CONE:     p->segments = 35; p->bands = 1; p->height = 1.5; break;  /* like cone-70 */
    case GEN_CYLINDER: p->segments = 24; p->bands = 1; p->height = 2.0; break;
    case GEN_KNOT:     p->segments = 64; p->bands = 8; break;
    default: break;
    }
}

/* ---- counts ------------------------------------------------------------------ */

static uint64_t count_tris(const gen_params *p)
{
    uint64_t n = (uint64_t)p->segments, b = (uint64_t)p->bands;
    switch (p->shape) {
    case GEN_SPHERE:   return 2 * n * (b - 1);          /* two fans + (b-2) rows of quads */
    case GEN_TORUS:    return 2 * n * b;
    case GEN_CONE:     return 2 * n * b;                /* apex fan, b-1 rows, base fan */
    case GEN_CYLINDER: return 2 * n * (b + 1);          /* two fans, b rows */
    case GEN_KNOT:     return 2 * n * b;
    default:           return 0;
    }
}

static uint64_t count_verts(const gen_params *p)
{
    uint64_t n = (uint64_t)p->segments, b = (uint64_t)p->bands;
    switch (p->shape) {
    case GEN_SPHERE:   return n * (b - 1) + 2;
    case GEN_TORUS:    return n * b;
    case GEN_CONE:     return n * b + 2;
    case GEN_CYLINDER: return n * (b + 1) + 2;
    case GEN_KNOT:     return n * b;
    default:           return 0;
    }
}

/* ---- the knot's centre curve and its Frenet frame ------------------------------ */

/* A (p,q) torus knot on the torus with radii R, r around the y axis. */
static void knot_derivs(const gen_params *k, double t, double c[3], double d1[3], double d2[3])
{
    double P = k->p, Q = k->q;
    double cp = cos(P * t), sp = sin(P * t), cq = cos(Q * t), sq = sin(Q * t);
    double rho = k->R + k->r * cq;
    double drho = -k->r * Q * sq, ddrho = -k->r * Q * Q * cq;
    c[0] = rho * cp;
    c[1] = -k->r * sq;
    c[2] = -rho * sp;
    d1[0] = drho * cp - rho * P * sp;
    d1[1] = -k->r * Q * cq;
    d1[2] = -drho * sp - rho * P * cp;
    d2[0] = ddrho * cp - 2 * drho * P * sp - rho * P * P * cp;
    d2[1] = k->r * Q * Q * sq;
    d2[2] = -ddrho * sp - 2 * drho * P * cp + rho * P * P * sp;
}

void gen_knot_curve(const gen_params *p, double t, double out[3])
{
    double d1[3], d2[3];
    knot_derivs(p, t, out, d1, d2);
}

static void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* Unit tangent, normal, binormal and the curvature at t (the tube is built
 * on the frame of knot_rings below; this one gives the curvature and the
 * starting normal). */
static double knot_frame(const gen_params *k, double t, double c[3], double T[3], double N[3], double B[3])
{
    double d1[3], d2[3], b[3];
    knot_derivs(k, t, c, d1, d2);
    double s = norm(d1);
    cross(d1, d2, b);
    double bn = norm(b);
    for (int i = 0; i < 3; i++) {
        T[i] = d1[i] / s;
        B[i] = b[i] / bn;
    }
    cross(B, T, N);
    return bn / (s * s * s);
}

static int gcd(int a, int b)
{
    while (b) {
        int t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* 1 if the closed polyline pts[0..n) passes within 2 * tube of itself
 * between points farther apart along it than pi * tube (closer ones may be
 * that close legitimately, where the curve bends). */
static int passes_through_itself(const double (*pts)[3], int n, double tube)
{
    double len = 0;
    for (int i = 0; i < n; i++) {
        const double *a = pts[i], *b = pts[(i + 1) % n];
        len += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
    int near = (int)ceil(PI * tube / (len / n)) + 1;
    for (int i = 0; i < n; i++)
        for (int j = i + near; j < n && j - i <= n - near; j++) {
            double dx = pts[i][0] - pts[j][0], dy = pts[i][1] - pts[j][1], dz = pts[i][2] - pts[j][2];
            if (dx * dx + dy * dy + dz * dz < 4 * tube * tube) return 1;
        }
    return 0;
}

enum { KNOT_SAMPLES = 1440 };

/* Why a tube of radius `tube` around the knot's curve would not be a clean
 * surface, or NULL.  Sampled: the tube must be thinner than the smallest
 * radius of curvature (else its inner side folds), and must not pass
 * through itself.  With `segments` > 0 the tube is the mesh's: around the
 * polyline through the rings' centres, whose straight pieces may cut
 * through another part of the tube where the curve's would not. */
static const char *knot_problem(const gen_params *k, double tube, int segments)
{
    int per = segments > 0 ? (KNOT_SAMPLES + segments - 1) / segments : 1;
    int n = segments > 0 ? segments * per : KNOT_SAMPLES;
    double (*pts)[3] = malloc((size_t)n * sizeof *pts);
    if (!pts) return "out of memory";
    const char *why = NULL;
    double min_radius = INFINITY;
    for (int i = 0; i < KNOT_SAMPLES && segments <= 0; i++) {
        double T[3], Nn[3], B[3];
        double kappa = knot_frame(k, TAU * i / KNOT_SAMPLES, pts[i], T, Nn, B);
        if (!(kappa > 1e-12)) {
            free(pts);
            return "the knot's curve has a straight point (no Frenet frame)";
        }
        if (1 / kappa < min_radius) min_radius = 1 / kappa;
    }
    /* The polyline: each ring's centre, then points along the chord to the next. */
    for (int i = 0; i < segments; i++) {
        double c0[3], c1[3];
        gen_knot_curve(k, TAU * i / segments, c0);
        gen_knot_curve(k, TAU * (i + 1) / segments, c1);
        for (int s = 0; s < per; s++)
            for (int c = 0; c < 3; c++) pts[i * per + s][c] = c0[c] + (c1[c] - c0[c]) * s / per;
    }
    if (segments <= 0 && tube >= 0.95 * min_radius) why = "is too thick for the curve's tightest bend";
    else if (passes_through_itself((const double (*)[3])pts, n, tube))
        why = segments > 0 ? "is too few: the tube's straight pieces would pass through each other"
                           : "is too thick: the tube would pass through itself";
    free(pts);
    return why;
}

/* The thickest tube the curve takes, to 1%, below `bad`. */
static double knot_max_tube(const gen_params *k, double bad)
{
    double lo = 0, hi = bad;
    while (hi - lo > 0.01 * hi) {
        double mid = (lo + hi) / 2;
        if (knot_problem(k, mid, 0)) hi = mid;
        else lo = mid;
    }
    return lo;
}

/* The fewest segments, above `bad`, whose polyline tube is clean (0 if none
 * up to the point where the polyline follows the curve). */
static int knot_min_segments(const gen_params *k, int bad)
{
    int lo = bad, hi = bad;
    do {
        lo = hi;
        hi *= 2;
        if (hi >= KNOT_SAMPLES) return knot_problem(k, k->tube, KNOT_SAMPLES) ? 0 : KNOT_SAMPLES;
    } while (knot_problem(k, k->tube, hi));
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (knot_problem(k, k->tube, mid)) lo = mid;
        else hi = mid;
    }
    return hi;
}

const char *gen_check(const gen_params *p, char *buf, size_t n)
{
    const char *why = NULL;
    int min_bands = p->shape == GEN_SPHERE ? 2 : (p->shape == GEN_TORUS || p->shape == GEN_KNOT) ? 3 : 1;
    if (p->segments < 3 || p->segments > 100000) {
        snprintf(buf, n, "--segments must be between 3 and 100000 (got %d)", p->segments);
        return buf;
    }
    if (p->bands < min_bands || p->bands > 100000) {
        snprintf(buf, n, "--bands must be between %d and 100000 for a %s (got %d)", min_bands,
                 gen_shape_name(p->shape), p->bands);
        return buf;
    }
    if (count_tris(p) > GEN_MAX_TRIS) {
        snprintf(buf, n, "too many triangles (%llu; at most %u)", (unsigned long long)count_tris(p),
                 GEN_MAX_TRIS);
        return buf;
    }
    switch (p->shape) {
    case GEN_SPHERE:
        if (!(p->radius > 0)) why = "--radius must be positive";
        break;
    case GEN_CONE:
    case GEN_CYLINDER:
        if (!(p->radius > 0)) why = "--radius must be positive";
        else if (!(p->height > 0)) why = "--height must be positive";
        break;
    case GEN_TORUS:
        if (!(p->R > 0) || !(p->r > 0)) why = "--R and --r must be positive";
        else if (!(p->r < p->R)) why = "--r must be smaller than --R (the torus would intersect itself)";
        break;
    case GEN_KNOT:
        if (p->p < 1 || p->q < 1 || p->p > 50 || p->q > 50) why = "--p and --q must be between 1 and 50";
        else if (gcd(p->p, p->q) != 1) why = "--p and --q must have no common factor (else the curve closes early)";
        else if (!(p->R > 0) || !(p->r > 0) || !(p->tube > 0)) why = "--R, --r and --tube must be positive";
        else if (!(p->r < p->R)) why = "--r must be smaller than --R";
        else if ((why = knot_problem(p, p->tube, 0)) && why[0] == 'i') {
            /* "is too thick ...": say how thick it may be. */
            snprintf(buf, n, "--tube %g %s (at most %.3g for --p %d --q %d --R %g --r %g)", p->tube, why,
                     knot_max_tube(p, p->tube), p->p, p->q, p->R, p->r);
            return buf;
        } else if (!why && p->segments < KNOT_SAMPLES && (why = knot_problem(p, p->tube, p->segments)) &&
                   why[0] == 'i') {
            int least = knot_min_segments(p, p->segments);
            if (least) snprintf(buf, n, "--segments %d %s (at least %d for this knot)", p->segments, why, least);
            else snprintf(buf, n, "--segments %d %s (make --tube thinner)", p->segments, why);
            return buf;
        }
        break;
    default:
        why = "unknown shape";
    }
    if (!why) return NULL;
    snprintf(buf, n, "%s", why);
    return buf;
}

/* ---- building ------------------------------------------------------------------ */

/* Round-off in cos/sin gives 6e-17 where 0 is meant; write 0 (and never -0). */
static double tidy(double v, double scale)
{
    return fabs(v) < 1e-14 * scale ? 0.0 : v;
}

static uint32_t put_vertex(gen_mesh *m, double x, double y, double z, double scale)
{
    double *v = m->pos + 3 * (size_t)m->nverts;
    v[0] = tidy(x, scale);
    v[1] = tidy(y, scale);
    v[2] = tidy(z, scale);
    return m->nverts++;
}

static void put_tri(gen_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t *t = m->tri + 3 * (size_t)m->ntris++;
    t[0] = a;
    t[1] = b;
    t[2] = c;
}

/* A ring of n points at height y and radius rho around the y axis, phi
 * increasing from +x towards +z: then dP/dphi x (down the side) points out
 * of the solid, as the orientation rule needs. */
static uint32_t put_circle(gen_mesh *m, int n, double rho, double y, double scale)
{
    uint32_t first = m->nverts;
    for (int j = 0; j < n; j++) {
        double phi = TAU * j / n;
        put_vertex(m, rho * cos(phi), y, rho * sin(phi), scale);
    }
    return first;
}

/* Joins between consecutive rings; see the orientation rule at the top. */
static void join_point_ring(gen_mesh *m, uint32_t point, uint32_t ring, int n)
{
    for (int j = 0; j < n; j++) put_tri(m, point, ring + (uint32_t)((j + 1) % n), ring + (uint32_t)j);
}

static void join_ring_point(gen_mesh *m, uint32_t ring, uint32_t point, int n)
{
    for (int j = 0; j < n; j++) put_tri(m, ring + (uint32_t)j, ring + (uint32_t)((j + 1) % n), point);
}

static void join_rings(gen_mesh *m, uint32_t r0, uint32_t r1, int n)
{
    for (int j = 0; j < n; j++) {
        uint32_t j1 = (uint32_t)((j + 1) % n);
        put_tri(m, r0 + (uint32_t)j, r0 + j1, r1 + j1);
        put_tri(m, r0 + (uint32_t)j, r1 + j1, r1 + (uint32_t)j);
    }
}

/* A closed surface of revolution around the y axis: a pole at height
 * top_y, rings 0..nrings-1 (ring k: radius and height from ring(p, k)), a
 * pole at bottom_y, joined in that order; s scales the vertices as
 * put_vertex does. */
typedef void ring_fn(const gen_params *p, int k, double *radius, double *y);

static void lathe(const gen_params *p, gen_mesh *m, double top_y, double bottom_y, double s, int nrings,
                  ring_fn *ring)
{
    int n = p->segments;
    uint32_t top = put_vertex(m, 0, top_y, 0, s), prev = 0;
    for (int k = 0; k < nrings; k++) {
        double r, y;
        ring(p, k, &r, &y);
        uint32_t cur = put_circle(m, n, r, y, s);
        if (k == 0) join_point_ring(m, top, cur, n);
        else join_rings(m, prev, cur, n);
        prev = cur;
    }
    uint32_t bottom = put_vertex(m, 0, bottom_y, 0, s);
    join_ring_point(m, prev, bottom, n);
}

/* Sphere: rings from north to south (theta down the sphere). */
static void sphere_ring(const gen_params *p, int k, double *r, double *y)
{
    double R = p->radius, th = PI * (k + 1) / p->bands;
    *r = R * sin(th);
    *y = R * cos(th);
}

static void build_sphere(const gen_params *p, gen_mesh *m)
{
    lathe(p, m, p->radius, -p->radius, p->radius, p->bands - 1, sphere_ring);
}

/* Cone: apex, side rings down to the rim, base centre: the rim ring is
 * shared by the side and the base, which meet there at a sharp angle. */
static void cone_ring(const gen_params *p, int k, double *r, double *y)
{
    double f = (double)(k + 1) / p->bands;   /* 0 at the apex, 1 at the rim */
    *r = p->radius * f;
    *y = p->height * (1 - f);
}

static void build_cone(const gen_params *p, gen_mesh *m)
{
    lathe(p, m, p->height, 0, fmax(p->radius, p->height), p->bands, cone_ring);
}

/* Cylinder: top centre, top rim, side rings, bottom rim, bottom centre. */
static void cylinder_ring(const gen_params *p, int k, double *r, double *y)
{
    *r = p->radius;
    *y = p->height * (p->bands - k) / p->bands;
}

static void build_cylinder(const gen_params *p, gen_mesh *m)
{
    lathe(p, m, p->height, 0, fmax(p->radius, p->height), p->bands + 1, cylinder_ring);
}

/* Rings around the y axis, one per angle theta around the tube; y = -r sin
 * theta makes dP/dphi x dP/dtheta point away from the tube's core. */
static void build_torus(const gen_params *p, gen_mesh *m)
{
    int n = p->segments, b = p->bands;
    double s = p->R + p->r;
    for (int k = 0; k < b; k++) {
        double th = TAU * k / b;
        put_circle(m, n, p->R + p->r * cos(th), -p->r * sin(th), s);
    }
    for (int k = 0; k < b; k++)
        join_rings(m, (uint32_t)(k * n), (uint32_t)(((k + 1) % b) * n), n);
}

/* A frame along the knot's centre curve that does not twist about the
 * tangent: T the tangent, U a unit normal, V = T x U.  The Frenet frame spins
 * about T as fast as the curve's torsion, which near a torus knot's core is so
 * fast that the quads between two rings twist into a fold; a rotation-
 * minimizing frame (the double-reflection method: W. Wang, B. Juettler, D.
 * Zheng, Y. Liu, "Computation of rotation minimizing frames", ACM TOG 27(1),
 * 2008, section 4) does not.  Transported once around the closed curve it
 * comes back turned about T by some angle; that angle is spread evenly over
 * the rings so that the tube closes on itself. */
typedef struct knot_ring {
    double c[3], U[3], V[3];
} knot_ring;

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Reflect a in the plane normal to v (|v|^2 = vv). */
static void reflect(double a[3], const double v[3], double vv)
{
    double f = 2 * dot3(v, a) / vv;
    for (int i = 0; i < 3; i++) a[i] -= f * v[i];
}

static void knot_tangent(const gen_params *p, double t, double c[3], double T[3])
{
    double d2[3];
    knot_derivs(p, t, c, T, d2);
    double s = norm(T);
    for (int i = 0; i < 3; i++) T[i] /= s;
}

/* One step of the double reflection from (x0, T0, U) to (x1, T1): U is
 * carried along. */
static void transport(const double x0[3], const double T0[3], const double x1[3], const double T1[3], double U[3])
{
    double v1[3], tl[3], v2[3];
    for (int i = 0; i < 3; i++) {
        v1[i] = x1[i] - x0[i];
        tl[i] = T0[i];
    }
    double c1 = dot3(v1, v1);
    if (c1 > 0) {
        reflect(U, v1, c1);
        reflect(tl, v1, c1);
    }
    for (int i = 0; i < 3; i++) v2[i] = T1[i] - tl[i];
    double c2 = dot3(v2, v2);
    if (c2 > 0) reflect(U, v2, c2);
    /* Keep U exactly unit and normal to T1 against rounding. */
    double d = dot3(U, T1);
    for (int i = 0; i < 3; i++) U[i] -= d * T1[i];
    double l = norm(U);
    for (int i = 0; i < 3; i++) U[i] /= l;
}

/* The n rings' centres and frames (U, V), closed as described above. */
static void knot_rings(const gen_params *p, int n, knot_ring *ring)
{
    int sub = n >= 4096 ? 1 : (4096 + n - 1) / n;   /* transport steps per ring */
    double x0[3], T0[3], U[3], B[3];
    knot_frame(p, 0, x0, T0, U, B);                  /* start from the Frenet normal */
    double U0[3] = { U[0], U[1], U[2] }, V0[3];
    cross(T0, U0, V0);
    for (int i = 0; i < n; i++) {
        knot_ring *r = &ring[i];
        double T[3];
        knot_tangent(p, TAU * i / n, r->c, T);
        memcpy(r->U, U, sizeof U);
        cross(T, U, r->V);
        for (int k = 1; k <= sub; k++) {
            double x1[3], T1[3];
            knot_tangent(p, TAU * (i + (double)k / sub) / n, x1, T1);
            transport(x0, T0, x1, T1, U);
            memcpy(x0, x1, sizeof x1);
            memcpy(T0, T1, sizeof T1);
        }
    }
    /* Back at t = 2 pi, U is U0 turned about T0 by alpha; ring i turns back
     * by alpha * i / n. */
    double alpha = atan2(dot3(U, V0), dot3(U, U0));
    for (int i = 1; i < n; i++) {
        knot_ring *r = &ring[i];
        double a = -alpha * i / n, ca = cos(a), sa = sin(a), u[3], v[3];
        for (int k = 0; k < 3; k++) {
            u[k] = ca * r->U[k] + sa * r->V[k];
            v[k] = ca * r->V[k] - sa * r->U[k];
        }
        memcpy(r->U, u, sizeof u);
        memcpy(r->V, v, sizeof v);
    }
}

/* One ring of `bands` points around the tube per step along the curve: the
 * in-ring angle plays phi, the curve parameter theta; (cos U + sin V) x T is
 * the outward normal (V = T x U), so this order is outward too. */
static void build_knot(const gen_params *p, gen_mesh *m)
{
    int n = p->segments, b = p->bands;
    double s = p->R + p->r + p->tube;
    knot_ring *ring = malloc((size_t)n * sizeof *ring);
    if (!ring) return;   /* gen_build sees the short count */
    knot_rings(p, n, ring);
    for (int i = 0; i < n; i++) {
        const knot_ring *r = &ring[i];
        for (int j = 0; j < b; j++) {
            double be = TAU * j / b, cb = cos(be), sb = sin(be);
            put_vertex(m, r->c[0] + p->tube * (cb * r->U[0] + sb * r->V[0]),
                       r->c[1] + p->tube * (cb * r->U[1] + sb * r->V[1]),
                       r->c[2] + p->tube * (cb * r->U[2] + sb * r->V[2]), s);
        }
    }
    free(ring);
    for (int i = 0; i < n; i++)
        join_rings(m, (uint32_t)(i * b), (uint32_t)(((i + 1) % n) * b), b);
}

int gen_build(const gen_params *p, gen_mesh *m)
{
    memset(m, 0, sizeof *m);
    uint64_t nv = count_verts(p), nt = count_tris(p);
    m->pos = malloc((size_t)nv * 3 * sizeof *m->pos);
    m->tri = malloc((size_t)nt * 3 * sizeof *m->tri);
    if (!m->pos || !m->tri) {
        gen_free(m);
        return -1;
    }
    switch (p->shape) {
    case GEN_SPHERE:   build_sphere(p, m); break;
    case GEN_TORUS:    build_torus(p, m); break;
    case GEN_CONE:     build_cone(p, m); break;
    case GEN_CYLINDER: build_cylinder(p, m); break;
    case GEN_KNOT:     build_knot(p, m); break;
    default: break;
    }
    /* The counts above and the builders must agree; a mismatch is a bug here. */
    if (m->nverts != nv || m->ntris != nt) {
        gen_free(m);
        return -1;
    }
    return 0;
}

void gen_free(gen_mesh *m)
{
    free(m->pos);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

static void write_params(const gen_params *p, FILE *f)
{
    fprintf(f, "# silk gen %s --segments %d --bands %d", gen_shape_name(p->shape), p->segments, p->bands);
    switch (p->shape) {
    case GEN_SPHERE:   fprintf(f, " --radius %.9g", p->radius); break;
    case GEN_TORUS:    fprintf(f, " --R %.9g --r %.9g", p->R, p->r); break;
    case GEN_CONE:
    case GEN_CYLINDER: fprintf(f, " --radius %.9g --height %.9g", p->radius, p->height); break;
    case GEN_KNOT:
        fprintf(f, " --p %d --q %d --R %.9g --r %.9g --tube %.9g", p->p, p->q, p->R, p->r, p->tube);
        break;
    default: break;
    }
    if (p->uv) fputs(" --uv", f);
    fputc('\n', f);
}

/* The surface parameters of vertex v in [0, 1): u = phi / 2 pi around the
 * y axis (phi from +x towards +z, as put_circle goes), and v from the
 * south pole up (sphere) or theta / 2 pi around the tube (torus). */
static void vertex_uv(const gen_params *p, const double *x, double uv[2])
{
    double phi = atan2(x[2], x[0]);
    uv[0] = phi < 0 ? phi / TAU + 1 : phi / TAU;
    if (uv[0] >= 1) uv[0] = 0;
    if (p->shape == GEN_SPHERE) {
        double c = x[1] / p->radius;
        uv[1] = 1 - acos(c > 1 ? 1 : (c < -1 ? -1 : c)) / PI;
    } else {
        double th = atan2(-x[1], sqrt(x[0] * x[0] + x[2] * x[2]) - p->R);
        uv[1] = th < 0 ? th / TAU + 1 : th / TAU;
        if (uv[1] >= 1) uv[1] = 0;
    }
}

static int is_pole(const gen_params *p, const double *x)
{
    return p->shape == GEN_SPHERE && x[0] == 0 && x[2] == 0;
}

/* The uvs of triangle t's corners: a triangle across the seam u = 0 (or
 * v = 0 on the torus) takes u + 1 at its corners near 0, so its uvs run on
 * without a jump; a pole takes the mean u of the other two corners. */
static void tri_uv(const gen_mesh *m, const gen_params *p, uint32_t t, double uv[3][2])
{
    const uint32_t *c = m->tri + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) vertex_uv(p, m->pos + 3 * (size_t)c[k], uv[k]);
    for (int a = 0; a < 2; a++) {
        if (a == 1 && p->shape != GEN_TORUS) break;
        double lo = 2, hi = -1;
        for (int k = 0; k < 3; k++) {
            if (is_pole(p, m->pos + 3 * (size_t)c[k])) continue;
            lo = fmin(lo, uv[k][a]);
            hi = fmax(hi, uv[k][a]);
        }
        if (hi - lo > 0.5)
            for (int k = 0; k < 3; k++)
                if (uv[k][a] < 0.5) uv[k][a] += 1;
    }
    for (int k = 0; k < 3; k++)
        if (is_pole(p, m->pos + 3 * (size_t)c[k])) uv[k][0] = (uv[(k + 1) % 3][0] + uv[(k + 2) % 3][0]) / 2;
}

static int cmp_uv(const void *a, const void *b)
{
    const double *x = a, *y = b;
    return x[0] < y[0] ? -1 : x[0] > y[0] ? 1 : x[1] < y[1] ? -1 : x[1] > y[1];
}

/* 1-based index of uv in the sorted unique list u[0..n). */
static unsigned long find_uv(double (*u)[2], size_t n, const double uv[2])
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (cmp_uv(u[mid], uv) < 0) lo = mid + 1;
        else hi = mid;
    }
    return (unsigned long)lo + 1;
}

/* vt lines (rounded to 6 decimals, so that equal values print equal), then
 * the faces as v/vt. */
static int write_uv_faces(const gen_mesh *m, const gen_params *p, FILE *f)
{
    size_t n = 3 * (size_t)m->ntris;
    double (*u)[2] = malloc(n * sizeof *u);
    if (!u) return -1;
    for (uint32_t t = 0; t < m->ntris; t++) {
        double uv[3][2];
        tri_uv(m, p, t, uv);
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 2; a++) u[3 * (size_t)t + k][a] = round(uv[k][a] * 1e6) / 1e6;
    }
    double (*s)[2] = malloc(n * sizeof *s);
    if (!s) { free(u); return -1; }
    memcpy(s, u, n * sizeof *u);
    qsort(s, n, sizeof *s, cmp_uv);
    size_t ns = 0;
    for (size_t i = 0; i < n; i++)
        if (ns == 0 || cmp_uv(s[ns - 1], s[i]) != 0) memcpy(s[ns++], s[i], sizeof s[i]);
    for (size_t i = 0; i < ns; i++) fprintf(f, "vt %.6f %.6f\n", s[i][0], s[i][1]);
    for (uint32_t t = 0; t < m->ntris; t++) {
        const uint32_t *c = m->tri + 3 * (size_t)t;
        fprintf(f, "f %u/%lu %u/%lu %u/%lu\n", c[0] + 1, find_uv(s, ns, u[3 * (size_t)t]), c[1] + 1,
                find_uv(s, ns, u[3 * (size_t)t + 1]), c[2] + 1, find_uv(s, ns, u[3 * (size_t)t + 2]));
    }
    free(s);
    free(u);
    return 0;
}

int gen_write_obj(const gen_mesh *m, const gen_params *p, FILE *f)
{
    write_params(p, f);
    fprintf(f, "# %u vertices, %u triangles; closed, counter-clockwise seen from outside\n", m->nverts,
            m->ntris);
    for (uint32_t i = 0; i < m->nverts; i++) {
        const double *v = m->pos + 3 * (size_t)i;
        fprintf(f, "v %.9g %.9g %.9g\n", v[0], v[1], v[2]);
    }
    if (p->uv) return write_uv_faces(m, p, f) != 0 || ferror(f) ? -1 : 0;
    for (uint32_t i = 0; i < m->ntris; i++) {
        const uint32_t *t = m->tri + 3 * (size_t)i;
        fprintf(f, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    return ferror(f) ? -1 : 0;
}

char *gen_obj_text(const gen_params *p, size_t *len)
{
    char why[160];
    gen_mesh m;
    if (gen_check(p, why, sizeof why) || gen_build(p, &m) != 0) return NULL;
    char *text = NULL;
    *len = 0;
    FILE *f = open_memstream(&text, len);
    int ok = f && gen_write_obj(&m, p, f) == 0;
    if (f && fclose(f) != 0) ok = 0;
    gen_free(&m);
    if (!ok) {
        free(text);
        return NULL;
    }
    return text;
}

void gen_checker(uint8_t *rgb, int size, int squares)
{
    static const uint8_t col[2][3] = { { 232, 196, 120 }, { 70, 110, 170 } };
    int cell = size / squares > 0 ? size / squares : 1;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++) {
            int c = (x / cell + y / cell) & 1, line = x % cell == 0 || y % cell == 0;
            uint8_t *p = rgb + 3 * ((size_t)y * (size_t)size + (size_t)x);
            for (int k = 0; k < 3; k++) p[k] = (uint8_t)(line ? col[c][k] * 3 / 4 : col[c][k]);
        }
}
