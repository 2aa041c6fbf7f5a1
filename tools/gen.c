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
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
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

/* Unit tangent, normal, binormal and the curvature at t.  The Frenet frame is
 * a smooth periodic function of t for a curve without inflections, so the
 * tube closes on itself exactly (a transported frame would not). */
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

/* Why the knot's tube would not be a clean surface, or NULL.  Sampled: the
 * tube must be thinner than the smallest radius of curvature, and two points
 * of the curve that are far apart along it must be more than two tube radii
 * apart in space. */
static const char *knot_problem(const gen_params *k)
{
    enum { N = 1440 };
    double (*pts)[3] = malloc(N * sizeof *pts);
    if (!pts) return "out of memory";
    const char *why = NULL;
    double min_radius = INFINITY, len = 0;
    for (int i = 0; i < N; i++) {
        double T[3], Nn[3], B[3];
        double kappa = knot_frame(k, TAU * i / N, pts[i], T, Nn, B);
        if (!(kappa > 1e-12)) {
            free(pts);
            return "the knot's curve has a straight point (no Frenet frame)";
        }
        if (1 / kappa < min_radius) min_radius = 1 / kappa;
        if (i) len += sqrt((pts[i][0] - pts[i - 1][0]) * (pts[i][0] - pts[i - 1][0]) +
                           (pts[i][1] - pts[i - 1][1]) * (pts[i][1] - pts[i - 1][1]) +
                           (pts[i][2] - pts[i - 1][2]) * (pts[i][2] - pts[i - 1][2]));
    }
    if (k->tube >= 0.95 * min_radius) why = "--tube is too thick for the curve's tightest bend";
    /* Points closer than pi*tube along the curve may be closer than 2*tube in
     * space legitimately (the curve bends); farther ones may not. */
    int near = (int)ceil(PI * k->tube / (len / N)) + 1;
    for (int i = 0; i < N && !why; i++)
        for (int j = i + near; j < N && j - i <= N - near; j++) {
            double dx = pts[i][0] - pts[j][0], dy = pts[i][1] - pts[j][1], dz = pts[i][2] - pts[j][2];
            if (dx * dx + dy * dy + dz * dz < 4 * k->tube * k->tube) {
                why = "--tube is too thick: the tube would intersect itself";
                break;
            }
        }
    free(pts);
    return why;
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
        else why = knot_problem(p);
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

/* North pole, rings from north to south (theta down the sphere), south pole. */
static void build_sphere(const gen_params *p, gen_mesh *m)
{
    double R = p->radius;
    int n = p->segments, b = p->bands;
    uint32_t north = put_vertex(m, 0, R, 0, R), prev = 0;
    for (int k = 1; k < b; k++) {
        double th = PI * k / b;
        uint32_t ring = put_circle(m, n, R * sin(th), R * cos(th), R);
        if (k == 1) join_point_ring(m, north, ring, n);
        else join_rings(m, prev, ring, n);
        prev = ring;
    }
    uint32_t south = put_vertex(m, 0, -R, 0, R);
    join_ring_point(m, prev, south, n);
}

/* Apex, side rings down to the rim, base centre: the rim ring is shared by
 * the side and the base, which meet there at a sharp angle. */
static void build_cone(const gen_params *p, gen_mesh *m)
{
    double R = p->radius, H = p->height, s = fmax(R, H);
    int n = p->segments, b = p->bands;
    uint32_t apex = put_vertex(m, 0, H, 0, s), prev = 0;
    for (int k = 1; k <= b; k++) {
        double f = (double)k / b;   /* 0 at the apex, 1 at the rim */
        uint32_t ring = put_circle(m, n, R * f, H * (1 - f), s);
        if (k == 1) join_point_ring(m, apex, ring, n);
        else join_rings(m, prev, ring, n);
        prev = ring;
    }
    uint32_t base = put_vertex(m, 0, 0, 0, s);
    join_ring_point(m, prev, base, n);
}

/* Top centre, top rim, side rings, bottom rim, bottom centre. */
static void build_cylinder(const gen_params *p, gen_mesh *m)
{
    double R = p->radius, H = p->height, s = fmax(R, H);
    int n = p->segments, b = p->bands;
    uint32_t top = put_vertex(m, 0, H, 0, s), prev = 0;
    for (int k = 0; k <= b; k++) {
        uint32_t ring = put_circle(m, n, R, H * (b - k) / b, s);
        if (k == 0) join_point_ring(m, top, ring, n);
        else join_rings(m, prev, ring, n);
        prev = ring;
    }
    uint32_t bottom = put_vertex(m, 0, 0, 0, s);
    join_ring_point(m, prev, bottom, n);
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

/* One ring of `bands` points around the tube per step along the curve: the
 * in-ring angle plays phi, the curve parameter theta; (cos N + sin B) x T is
 * the outward normal, so this order is outward too. */
static void build_knot(const gen_params *p, gen_mesh *m)
{
    int n = p->segments, b = p->bands;
    double s = p->R + p->r + p->tube;
    for (int i = 0; i < n; i++) {
        double c[3], T[3], N[3], B[3];
        knot_frame(p, TAU * i / n, c, T, N, B);
        for (int j = 0; j < b; j++) {
            double be = TAU * j / b, cb = cos(be), sb = sin(be);
            put_vertex(m, c[0] + p->tube * (cb * N[0] + sb * B[0]), c[1] + p->tube * (cb * N[1] + sb * B[1]),
                       c[2] + p->tube * (cb * N[2] + sb * B[2]), s);
        }
    }
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
    fputc('\n', f);
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
    for (uint32_t i = 0; i < m->ntris; i++) {
        const uint32_t *t = m->tri + 3 * (size_t)i;
        fprintf(f, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    return ferror(f) ? -1 : 0;
}
