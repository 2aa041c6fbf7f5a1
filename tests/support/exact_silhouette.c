/*
 * exact_silhouette.c - test support, double precision: ray-cast object masks
 * of a sphere, a torus, a capped cylinder and a capped cone, the exact
 * silhouette sampled between pixel
 * centres, and the comparison of a rendered mask with the exact one (see
 * exact_silhouette.h).  This is the reference the silhouette-accuracy test
 * measures silk against, so it is written for being right, not fast.
 */
#include "exact_silhouette.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ES_PI 3.14159265358979323846
#define ES_FAR 1e9

/* ---- small vector helpers --------------------------------------------------- */

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void sub3(double r[3], const double a[3], const double b[3])
{
    r[0] = a[0] - b[0]; r[1] = a[1] - b[1]; r[2] = a[2] - b[2];
}
static void cross3(double r[3], const double a[3], const double b[3])
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    r[0] = x; r[1] = y; r[2] = z;
}
static void unit3(double a[3])
{
    double l = sqrt(dot3(a, a));
    if (l > 0) { a[0] /= l; a[1] /= l; a[2] /= l; }
}

/* ---- camera ----------------------------------------------------------------- */

void es_camera_from_silk(es_camera *c, const silk_camera *s)
{
    memset(c, 0, sizeof *c);
    const silk_vec3 *v[3] = { &s->eye, &s->target, &s->up };
    double *d[3] = { c->eye, c->target, c->up };
    for (int i = 0; i < 3; i++) {
        d[i][0] = v[i]->x / 65536.0;
        d[i][1] = v[i]->y / 65536.0;
        d[i][2] = v[i]->z / 65536.0;
    }
    c->ortho = s->ortho;
    c->fov_deg = s->fov_deg / 65536.0;
    c->ortho_half_height = s->ortho_half_height / 65536.0;
    c->znear = s->znear / 65536.0;
    c->zfar = s->zfar / 65536.0;
    c->width = s->width;
    c->height = s->height;
}

/* The camera's frame, computed once per mask rather than per ray. */
typedef struct frame {
    double f[3], s[3], u[3];   /* forward, right, up */
    double sx, sy;             /* image half extents: tan(fov/2) or the half height, times aspect for x */
} frame;

static void camera_frame(const es_camera *c, frame *fr)
{
    sub3(fr->f, c->target, c->eye);
    unit3(fr->f);
    cross3(fr->s, fr->f, c->up);
    unit3(fr->s);
    cross3(fr->u, fr->s, fr->f);
    double aspect = (double)c->width / c->height;
    double h = c->ortho ? c->ortho_half_height : tan(c->fov_deg * ES_PI / 360);
    fr->sx = h * aspect;
    fr->sy = h;
}

/* The ray through image point (px, py): origin o, direction d with unit
 * component along the view axis, so the ray parameter is the view depth. */
static void camera_ray(const es_camera *c, const frame *fr, double px, double py, double o[3], double d[3])
{
    double nx = (2 * px / c->width - 1) * fr->sx, ny = (1 - 2 * py / c->height) * fr->sy;
    for (int k = 0; k < 3; k++) {
        if (c->ortho) {
            o[k] = c->eye[k] + fr->s[k] * nx + fr->u[k] * ny;
            d[k] = fr->f[k];
        } else {
            o[k] = c->eye[k];
            d[k] = fr->f[k] + fr->s[k] * nx + fr->u[k] * ny;
        }
    }
}

/* ---- shapes ----------------------------------------------------------------- */

es_shape es_sphere(double cx, double cy, double cz, double radius)
{
    es_shape s;
    memset(&s, 0, sizeof s);
    s.kind = ES_SPHERE;
    s.centre[0] = cx; s.centre[1] = cy; s.centre[2] = cz;
    s.radius = radius;
    return s;
}

es_shape es_torus(double cx, double cy, double cz, double ax, double ay, double az, double R, double r)
{
    es_shape s;
    memset(&s, 0, sizeof s);
    s.kind = ES_TORUS;
    s.centre[0] = cx; s.centre[1] = cy; s.centre[2] = cz;
    s.axis[0] = ax; s.axis[1] = ay; s.axis[2] = az;
    unit3(s.axis);
    s.R = R;
    s.r = r;
    return s;
}

static es_shape revolved(es_kind kind, double cx, double cy, double cz, double ax, double ay, double az,
                         double radius, double height)
{
    es_shape s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.centre[0] = cx; s.centre[1] = cy; s.centre[2] = cz;
    s.axis[0] = ax; s.axis[1] = ay; s.axis[2] = az;
    unit3(s.axis);
    s.radius = radius;
    s.height = height;
    return s;
}

es_shape es_cylinder(double cx, double cy, double cz, double ax, double ay, double az, double radius, double height)
{
    return revolved(ES_CYLINDER, cx, cy, cz, ax, ay, az, radius, height);
}

es_shape es_cone(double cx, double cy, double cz, double ax, double ay, double az, double radius, double height)
{
    return revolved(ES_CONE, cx, cy, cz, ax, ay, az, radius, height);
}

/* Parameters where the ray o + t d (d unit) is within radius rad of ctr;
 * 0 when it misses. */
static int ball_interval(const double o[3], const double d[3], const double ctr[3], double rad,
                         double *t0, double *t1)
{
    double oc[3];
    sub3(oc, o, ctr);
    double b = dot3(oc, d);
    /* distance of the closest approach, computed without the b^2 - |oc|^2
     * cancellation */
    double q[3] = { oc[0] - b * d[0], oc[1] - b * d[1], oc[2] - b * d[2] };
    double h = rad * rad - dot3(q, q);
    if (h < 0) return 0;
    h = sqrt(h);
    *t0 = -b - h;
    *t1 = -b + h;
    return 1;
}

/* Quartic F(s) = s^4 + c2 s^2 + c1 s + c0 (no cubic term: s is measured from
 * the ray's closest approach to the centre) and its derivatives. */
typedef struct quartic { double c2, c1, c0; } quartic;

static double q_f(const quartic *q, double s) { double s2 = s * s; return s2 * s2 + q->c2 * s2 + q->c1 * s + q->c0; }
static double q_d1(const quartic *q, double s) { return 4 * s * s * s + 2 * q->c2 * s + q->c1; }
static double q_d2(const quartic *q, double s) { return 12 * s * s + 2 * q->c2; }

/* The root of F' in [a, b] where F' changes sign: Newton steps kept inside
 * the bracket, bisection when a step leaves it. */
static double q_d1_root(const quartic *q, double a, double b)
{
    double fa = q_d1(q, a);
    double x = 0.5 * (a + b);
    for (int i = 0; i < 200; i++) {
        double fx = q_d1(q, x);
        if (fx == 0) return x;
        if ((fx < 0) == (fa < 0)) { a = x; fa = fx; }
        else b = x;
        double d2 = q_d2(q, x), nx = d2 != 0 ? x - fx / d2 : a;
        if (!(nx > a && nx < b)) nx = 0.5 * (a + b);
        if (fabs(nx - x) <= 1e-14 * (1 + fabs(x)) || b - a <= 1e-14 * (1 + fabs(a))) return nx;
        x = nx;
    }
    return x;
}

/* Whether F has a zero on [lo, hi]: its minimum and maximum there are at the
 * ends or at zeros of F', and F' is monotone between the zeros of F''. */
static int quartic_zero_in(const quartic *q, double lo, double hi)
{
    double cut[4];
    int nc = 0;
    cut[nc++] = lo;
    if (q->c2 < 0) {                                  /* F'' = 12 s^2 + 2 c2 has zeros */
        double z = sqrt(-q->c2 / 6);
        if (-z > lo && -z < hi) cut[nc++] = -z;
        if (z > lo && z < hi) cut[nc++] = z;
    }
    cut[nc++] = hi;
    double fmin = q_f(q, lo), fmax = fmin;
    double fh = q_f(q, hi);
    if (fh < fmin) fmin = fh;
    if (fh > fmax) fmax = fh;
    for (int i = 0; i + 1 < nc; i++) {
        double a = cut[i], b = cut[i + 1];
        double da = q_d1(q, a), db = q_d1(q, b);
        if ((da < 0) == (db < 0) && da != 0 && db != 0) continue;
        double f = q_f(q, q_d1_root(q, a, b));
        if (f < fmin) fmin = f;
        if (f > fmax) fmax = f;
        if (fmin <= 0 && fmax >= 0) return 1;
    }
    return fmin <= 0 && fmax >= 0;
}

static int torus_hit(const es_shape *s, const double o[3], const double dir[3], double lo, double hi)
{
    double d[3] = { dir[0], dir[1], dir[2] };
    double dl = sqrt(dot3(d, d));
    unit3(d);
    lo *= dl;                                         /* depths to distances along the unit ray */
    hi *= dl;
    double b0, b1;
    if (!ball_interval(o, d, s->centre, s->R + s->r, &b0, &b1)) return 0;
    if (b0 > lo) lo = b0;
    if (b1 < hi) hi = b1;
    if (lo > hi) return 0;
    /* Origin moved to the closest approach to the centre: t = tc + s. */
    double oc[3];
    sub3(oc, o, s->centre);
    double tc = -dot3(oc, d);
    double p[3] = { oc[0] + tc * d[0], oc[1] + tc * d[1], oc[2] + tc * d[2] };
    /* (|x|^2 + R^2 - r^2)^2 - 4 R^2 (|x|^2 - (x.a)^2), x = p + s d, p.d = 0 */
    double R2 = s->R * s->R, g = dot3(p, p), pz = dot3(p, s->axis), dz = dot3(d, s->axis);
    double k = g + R2 - s->r * s->r;
    quartic q;
    q.c2 = 2 * k - 4 * R2 * (1 - dz * dz);
    q.c1 = 8 * R2 * pz * dz;
    q.c0 = k * k - 4 * R2 * (g - pz * pz);
    return quartic_zero_in(&q, lo - tc, hi - tc);
}

static int sphere_hit(const es_shape *s, const double o[3], const double dir[3], double lo, double hi)
{
    double d[3] = { dir[0], dir[1], dir[2] };
    double dl = sqrt(dot3(d, d));
    unit3(d);
    double t0, t1;
    if (!ball_interval(o, d, s->centre, s->radius, &t0, &t1)) return 0;
    lo *= dl;
    hi *= dl;
    return (t0 >= lo && t0 <= hi) || (t1 >= lo && t1 <= hi);
}

/* An interval of ray parameters; empty when lo > hi. */
typedef struct span { double lo, hi; } span;

static span span_cut(span a, span b)
{
    span r = { a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi };
    return r;
}

/* The roots of A t^2 + B t + C, ascending, without cancellation; 0 when
 * there are none. */
static int quadratic_roots(double A, double B, double C, double *r0, double *r1)
{
    double disc = B * B - 4 * A * C;
    if (disc < 0 || A == 0) return 0;
    double q = -0.5 * (B + (B < 0 ? -sqrt(disc) : sqrt(disc)));
    double a = q / A, b = q != 0 ? C / q : a;
    *r0 = a < b ? a : b;
    *r1 = a < b ? b : a;
    return 1;
}

/* Where A t^2 + B t + C <= 0 within the span `within`: one span, the hull
 * of the two pieces when A < 0 leaves two (they can both meet `within` only
 * at a cone's apex, where the hull adds nothing that matters). */
static span quadric_inside(double A, double B, double C, span within)
{
    span none = { 1, 0 }, all = { -ES_FAR, ES_FAR };
    double r0, r1;
    if (fabs(A) < 1e-15) {                             /* linear (or constant) along the ray */
        if (fabs(B) < 1e-300) return C <= 0 ? span_cut(all, within) : none;
        span h = B > 0 ? (span){ -ES_FAR, -C / B } : (span){ -C / B, ES_FAR };
        return span_cut(h, within);
    }
    if (!quadratic_roots(A, B, C, &r0, &r1)) return A > 0 ? none : span_cut(all, within);
    if (A > 0) return span_cut((span){ r0, r1 }, within);
    span p = span_cut((span){ -ES_FAR, r0 }, within), q = span_cut((span){ r1, ES_FAR }, within);
    if (p.lo > p.hi) return q;
    if (q.lo > q.hi) return p;
    return (span){ p.lo, q.hi };
}

/* The capped cylinder or cone: with y the height above the base along the
 * axis and rho the distance from the axis, rho^2 <= (k (h0 - y))^2 + c0
 * inside the side, 0 <= y <= height between the caps (cylinder: k = 0,
 * c0 = radius^2; cone: k = radius / height, h0 = height, c0 = 0). */
static int revolved_hit(const es_shape *s, const double o[3], const double dir[3], double lo, double hi)
{
    double d[3] = { dir[0], dir[1], dir[2] };
    double dl = sqrt(dot3(d, d));
    unit3(d);
    lo *= dl;
    hi *= dl;
    double q[3];
    sub3(q, o, s->centre);
    double y0 = dot3(q, s->axis), dy = dot3(d, s->axis);
    span slab;
    if (fabs(dy) < 1e-300) {
        if (y0 < 0 || y0 > s->height) return 0;
        slab = (span){ -ES_FAR, ES_FAR };
    } else {
        double a = -y0 / dy, b = (s->height - y0) / dy;
        slab = (span){ a < b ? a : b, a < b ? b : a };
    }
    /* rho^2 = |q + t d|^2 - (y0 + t dy)^2, the radial part taken out first */
    double qr[3] = { q[0] - y0 * s->axis[0], q[1] - y0 * s->axis[1], q[2] - y0 * s->axis[2] };
    double dr[3] = { d[0] - dy * s->axis[0], d[1] - dy * s->axis[1], d[2] - dy * s->axis[2] };
    double A = dot3(dr, dr), B = 2 * dot3(qr, dr), C = dot3(qr, qr);
    if (s->kind == ES_CYLINDER) {
        C -= s->radius * s->radius;
    } else {
        double k = s->radius / s->height, h0 = s->height - y0;   /* (k (h0 - t dy))^2 */
        A -= k * k * dy * dy;
        B += 2 * k * k * h0 * dy;
        C -= k * k * h0 * h0;
    }
    span in = quadric_inside(A, B, C, slab);
    if (in.lo > in.hi) return 0;
    return (in.lo >= lo && in.lo <= hi) || (in.hi >= lo && in.hi <= hi);
}

static int hit(const es_camera *c, const frame *fr, const es_shape *s, double px, double py)
{
    double o[3], d[3];
    camera_ray(c, fr, px, py, o, d);
    if (s->kind == ES_SPHERE) return sphere_hit(s, o, d, c->znear, c->zfar);
    if (s->kind == ES_CYLINDER || s->kind == ES_CONE) return revolved_hit(s, o, d, c->znear, c->zfar);
    return torus_hit(s, o, d, c->znear, c->zfar);
}

int es_hit(const es_camera *c, const es_shape *s, double px, double py)
{
    frame fr;
    camera_frame(c, &fr);
    return hit(c, &fr, s, px, py);
}

void es_mask(const es_camera *c, const es_shape *s, unsigned char *mask)
{
    frame fr;
    camera_frame(c, &fr);
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++)
            mask[(size_t)y * c->width + x] = (unsigned char)hit(c, &fr, s, x + 0.5, y + 0.5);
}

/* ---- silhouette samples ----------------------------------------------------- */

static int points_push(es_points *p, double x, double y)
{
    if (p->n == p->cap) {
        int cap = p->cap ? 2 * p->cap : 1024;
        double *nx = realloc(p->x, (size_t)cap * sizeof *nx);
        if (!nx) return -1;
        p->x = nx;
        double *ny = realloc(p->y, (size_t)cap * sizeof *ny);
        if (!ny) return -1;
        p->y = ny;
        p->cap = cap;
    }
    p->x[p->n] = x;
    p->y[p->n] = y;
    p->n++;
    return 0;
}

void es_points_free(es_points *p)
{
    free(p->x);
    free(p->y);
    memset(p, 0, sizeof *p);
}

/* Where es_hit changes between (ax, ay) (value va) and (bx, by). */
static void bisect_crossing(const es_camera *c, const frame *fr, const es_shape *s, double ax, double ay, int va,
                            double bx, double by, double *x, double *y)
{
    double lo = 0, hi = 1;
    while (hi - lo > 1e-6) {
        double m = 0.5 * (lo + hi);
        if (hit(c, fr, s, ax + m * (bx - ax), ay + m * (by - ay)) == va) lo = m;
        else hi = m;
    }
    double m = 0.5 * (lo + hi);
    *x = ax + m * (bx - ax);
    *y = ay + m * (by - ay);
}

int es_silhouette_points(const es_camera *c, const es_shape *s, const unsigned char *mask, es_points *out)
{
    int w = c->width, h = c->height;
    frame fr;
    camera_frame(c, &fr);
    out->n = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int v = mask[(size_t)y * w + x];
            double cx = x + 0.5, cy = y + 0.5, qx, qy;
            if (x + 1 < w && mask[(size_t)y * w + x + 1] != v) {
                bisect_crossing(c, &fr, s, cx, cy, v, cx + 1, cy, &qx, &qy);
                if (points_push(out, qx, qy)) return -1;
            }
            if (y + 1 < h && mask[(size_t)(y + 1) * w + x] != v) {
                bisect_crossing(c, &fr, s, cx, cy, v, cx, cy + 1, &qx, &qy);
                if (points_push(out, qx, qy)) return -1;
            }
        }
    return out->n;
}

/* ---- segment sets with a grid index ----------------------------------------- */

/* Segments (points are segments of length 0) bucketed by the pixel cell of
 * their midpoint; half is the largest half length, which bounds how far a
 * segment reaches out of its cell. */
typedef struct segs {
    int n, cap;
    double *v;                 /* 4 per segment: x0 y0 x1 y1 */
    double half;
    int gw, gh;                /* grid cells, one per pixel plus a margin of 1 */
    int *start, *item;
    int *near;                 /* per cell: a segment near its centre (propagated), or -1;
                                  made on the first query that needs it */
    double *near_d;            /* its distance from the cell centre */
} segs;

static int segs_push(segs *g, double x0, double y0, double x1, double y1)
{
    if (g->n == g->cap) {
        int cap = g->cap ? 2 * g->cap : 1024;
        double *v = realloc(g->v, (size_t)cap * 4 * sizeof *v);
        if (!v) return -1;
        g->v = v;
        g->cap = cap;
    }
    double *s = &g->v[(size_t)g->n * 4];
    s[0] = x0; s[1] = y0; s[2] = x1; s[3] = y1;
    g->n++;
    return 0;
}

static void segs_free(segs *g)
{
    free(g->v);
    free(g->start);
    free(g->item);
    free(g->near);
    free(g->near_d);
    memset(g, 0, sizeof *g);
}

static int clampi(int v, int lo, int hi) { return v < lo ? lo : (v > hi ? hi : v); }

static int cell_of(const segs *g, double x, double y)
{
    int cx = clampi((int)floor(x) + 1, 0, g->gw - 1), cy = clampi((int)floor(y) + 1, 0, g->gh - 1);
    return cy * g->gw + cx;
}

static double point_segment(double px, double py, const double *s)
{
    double dx = s[2] - s[0], dy = s[3] - s[1];
    double l2 = dx * dx + dy * dy, t = 0;
    if (l2 > 0) {
        t = ((px - s[0]) * dx + (py - s[1]) * dy) / l2;
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
    }
    return hypot(px - (s[0] + t * dx), py - (s[1] + t * dy));
}

/* Offer cell k the segment held by cell o, if nearer to k's centre. */
static void propagate(segs *g, int k, int o)
{
    int cand = g->near[o];
    if (cand < 0 || cand == g->near[k]) return;
    double d = point_segment(k % g->gw - 0.5, k / g->gw - 0.5, &g->v[(size_t)cand * 4]);
    if (d < g->near_d[k]) {
        g->near[k] = cand;
        g->near_d[k] = d;
    }
}

/* A nearest-segment map over the cells, by two raster passes that carry
 * each cell's candidate to its neighbours (as in 8SSEDT).  Nearly exact;
 * used only for queries farther than a few cells, where the ring search
 * would be slow and a hundredth of a pixel does not matter. */
static int segs_nearest_map(segs *g)
{
    int gw = g->gw, gh = g->gh;
    g->near = malloc((size_t)gw * gh * sizeof *g->near);
    g->near_d = malloc((size_t)gw * gh * sizeof *g->near_d);
    if (!g->near || !g->near_d) {
        free(g->near);
        free(g->near_d);
        g->near = NULL;
        g->near_d = NULL;
        return -1;
    }
    for (int k = 0; k < gw * gh; k++) {
        g->near[k] = -1;
        g->near_d[k] = ES_FAR;
        for (int i = g->start[k]; i < g->start[k + 1]; i++) {
            double d = point_segment(k % gw - 0.5, k / gw - 0.5, &g->v[(size_t)g->item[i] * 4]);
            if (d < g->near_d[k]) {
                g->near[k] = g->item[i];
                g->near_d[k] = d;
            }
        }
    }
    for (int y = 0; y < gh; y++) {
        for (int x = 0; x < gw; x++) {
            int k = y * gw + x;
            if (x > 0) propagate(g, k, k - 1);
            if (y > 0) {
                propagate(g, k, k - gw);
                if (x > 0) propagate(g, k, k - gw - 1);
                if (x + 1 < gw) propagate(g, k, k - gw + 1);
            }
        }
        for (int x = gw - 2; x >= 0; x--) propagate(g, y * gw + x, y * gw + x + 1);
    }
    for (int y = gh - 1; y >= 0; y--) {
        for (int x = gw - 1; x >= 0; x--) {
            int k = y * gw + x;
            if (x + 1 < gw) propagate(g, k, k + 1);
            if (y + 1 < gh) {
                propagate(g, k, k + gw);
                if (x + 1 < gw) propagate(g, k, k + gw + 1);
                if (x > 0) propagate(g, k, k + gw - 1);
            }
        }
        for (int x = 1; x < gw; x++) propagate(g, y * gw + x, y * gw + x - 1);
    }
    return 0;
}

static int segs_index(segs *g, int width, int height)
{
    g->gw = width + 2;
    g->gh = height + 2;
    size_t cells = (size_t)g->gw * g->gh;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->item = malloc((size_t)(g->n ? g->n : 1) * sizeof *g->item);
    if (!g->start || !g->item) return -1;
    for (int i = 0; i < g->n; i++) {
        const double *s = &g->v[(size_t)i * 4];
        g->start[cell_of(g, 0.5 * (s[0] + s[2]), 0.5 * (s[1] + s[3])) + 1]++;
    }
    for (size_t k = 0; k < cells; k++) g->start[k + 1] += g->start[k];
    int *fill = malloc(cells * sizeof *fill);
    if (!fill) return -1;
    memcpy(fill, g->start, cells * sizeof *fill);
    for (int i = 0; i < g->n; i++) {
        const double *s = &g->v[(size_t)i * 4];
        g->item[fill[cell_of(g, 0.5 * (s[0] + s[2]), 0.5 * (s[1] + s[3]))]++] = i;
    }
    free(fill);
    return 0;
}

/* Distance from (x, y) to the nearest segment: exact by searching rings of
 * cells outwards up to RING_LIMIT (a segment whose midpoint is k rings away
 * is farther than k - 1 - half), beyond that from the propagated map. */
#define RING_LIMIT 4
static double segs_nearest(segs *g, double x, double y)
{
    if (g->n == 0) return ES_FAR;
    int c = cell_of(g, x, y), cx = c % g->gw, cy = c / g->gw;
    double best = ES_FAR;
    for (int r = 0; r <= RING_LIMIT; r++) {
        for (int yy = cy - r; yy <= cy + r; yy++) {
            if (yy < 0 || yy >= g->gh) continue;
            int step = (yy == cy - r || yy == cy + r || r == 0) ? 1 : 2 * r;
            for (int xx = cx - r; xx <= cx + r; xx += step) {
                if (xx < 0 || xx >= g->gw) continue;
                int k = yy * g->gw + xx;
                for (int i = g->start[k]; i < g->start[k + 1]; i++) {
                    double d = point_segment(x, y, &g->v[(size_t)g->item[i] * 4]);
                    if (d < best) best = d;
                }
            }
        }
        if (best <= r - g->half) return best;
    }
    if (!g->near && segs_nearest_map(g)) return best;   /* out of memory: the rings' answer */
    for (int yy = cy - 1; yy <= cy + 1; yy++)
        for (int xx = cx - 1; xx <= cx + 1; xx++) {
            if (xx < 0 || yy < 0 || xx >= g->gw || yy >= g->gh) continue;
            int i = g->near[yy * g->gw + xx];
            if (i < 0) continue;
            double d = point_segment(x, y, &g->v[(size_t)i * 4]);
            if (d < best) best = d;
        }
    return best;
}

/* The pixel edges between in and out pixels of a mask. */
static int mask_cracks(const unsigned char *m, int w, int h, segs *g)
{
    memset(g, 0, sizeof *g);
    g->half = 0.5;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int v = m[(size_t)y * w + x];
            if (x + 1 < w && m[(size_t)y * w + x + 1] != v && segs_push(g, x + 1, y, x + 1, y + 1)) return -1;
            if (y + 1 < h && m[(size_t)(y + 1) * w + x] != v && segs_push(g, x, y + 1, x + 1, y + 1)) return -1;
        }
    return segs_index(g, w, h);
}

/* The exact silhouette: its samples, and the segments joining samples
 * closer than ES_LINK px (neighbours along the curve). */
#define ES_LINK 1.5
static int silhouette_segs(const es_points *p, int w, int h, segs *g)
{
    segs pts;
    memset(&pts, 0, sizeof pts);
    memset(g, 0, sizeof *g);
    g->half = 0.5 * ES_LINK;
    for (int i = 0; i < p->n; i++)
        if (segs_push(&pts, p->x[i], p->y[i], p->x[i], p->y[i]) || segs_push(g, p->x[i], p->y[i], p->x[i], p->y[i])) {
            segs_free(&pts);
            return -1;
        }
    if (segs_index(&pts, w, h)) { segs_free(&pts); return -1; }
    for (int i = 0; i < p->n; i++) {
        int c = cell_of(&pts, p->x[i], p->y[i]), cx = c % pts.gw, cy = c / pts.gw;
        for (int yy = cy - 2; yy <= cy + 2; yy++)
            for (int xx = cx - 2; xx <= cx + 2; xx++) {
                if (xx < 0 || yy < 0 || xx >= pts.gw || yy >= pts.gh) continue;
                int k = yy * pts.gw + xx;
                for (int j = pts.start[k]; j < pts.start[k + 1]; j++) {
                    int o = pts.item[j];
                    if (o <= i || hypot(p->x[o] - p->x[i], p->y[o] - p->y[i]) >= ES_LINK) continue;
                    if (segs_push(g, p->x[i], p->y[i], p->x[o], p->y[o])) { segs_free(&pts); return -1; }
                }
            }
    }
    segs_free(&pts);
    return segs_index(g, w, h);
}

/* ---- comparisons ------------------------------------------------------------ */

int es_compare(const unsigned char *test, const unsigned char *exact, const es_points *pts, int w, int h,
               es_stats *out)
{
    memset(out, 0, sizeof *out);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (test[i] && !exact[i]) out->extra++;
            if (!test[i] && exact[i]) out->missing++;
            if (exact[i] && ((x > 0 && !exact[i - 1]) || (x + 1 < w && !exact[i + 1]) ||
                             (y > 0 && !exact[i - w]) || (y + 1 < h && !exact[i + w])))
                out->boundary++;
        }
    out->differing = out->extra + out->missing;
    out->mean_error = out->boundary ? (double)out->differing / out->boundary : (out->differing ? ES_FAR : 0);

    segs sil;
    if (silhouette_segs(pts, w, h, &sil)) { segs_free(&sil); return -1; }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (test[i] == exact[i]) continue;
            double d = segs_nearest(&sil, x + 0.5, y + 0.5);
            if (d > out->max_dist) out->max_dist = d;
        }
    segs_free(&sil);

    double *off = malloc((size_t)(pts->n ? pts->n : 1) * sizeof *off);
    if (!off || es_offsets(test, pts, w, h, off)) { free(off); return -1; }
    double sum = 0, sum_abs = 0;
    for (int i = 0; i < pts->n; i++) {
        sum += off[i];
        sum_abs += fabs(off[i]);
        if (fabs(off[i]) > out->max_abs_offset) out->max_abs_offset = fabs(off[i]);
    }
    free(off);
    out->samples = pts->n;
    if (pts->n) {
        out->mean_offset = sum / pts->n;
        out->mean_abs_offset = sum_abs / pts->n;
    }
    return 0;
}

int es_offsets(const unsigned char *test, const es_points *pts, int w, int h, double *out)
{
    segs cracks;
    if (mask_cracks(test, w, h, &cracks)) { segs_free(&cracks); return -1; }
    for (int i = 0; i < pts->n; i++) {
        double d = segs_nearest(&cracks, pts->x[i], pts->y[i]);
        int px = clampi((int)floor(pts->x[i]), 0, w - 1), py = clampi((int)floor(pts->y[i]), 0, h - 1);
        out[i] = test[(size_t)py * w + px] ? d : -d;
    }
    segs_free(&cracks);
    return 0;
}

static double directed_hausdorff(const segs *from, segs *to)
{
    double worst = 0;
    for (int i = 0; i < from->n; i++) {
        const double *s = &from->v[(size_t)i * 4];
        double d = segs_nearest(to, 0.5 * (s[0] + s[2]), 0.5 * (s[1] + s[3]));
        if (d > worst) worst = d;
    }
    return worst;
}

double es_boundary_hausdorff(const unsigned char *a, const unsigned char *b, int w, int h)
{
    segs ca, cb;
    double r = -1;
    if (mask_cracks(a, w, h, &ca) == 0 && mask_cracks(b, w, h, &cb) == 0) {
        if (ca.n == 0 && cb.n == 0) r = 0;
        else if (ca.n == 0 || cb.n == 0) r = ES_FAR;
        else {
            double ab = directed_hausdorff(&ca, &cb), ba = directed_hausdorff(&cb, &ca);
            r = ab > ba ? ab : ba;
        }
    }
    segs_free(&ca);
    segs_free(&cb);
    return r;
}
