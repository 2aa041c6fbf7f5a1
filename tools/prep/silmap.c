/*
 * silmap.c - the views, cameras, binary images and outlines of a
 * silhouette map ("Silhouette Mapping", section 4; see silmap.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "silmap.h"

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}
static void normalize(double *a)
{
    double l = sqrt(dot(a, a));
    a[0] /= l, a[1] /= l, a[2] /= l;
}

/* ---- the polytope ----------------------------------------------------------- */

void silmap_polytope_free(silmap_polytope *p)
{
    free(p->dir);
    free(p->tri);
    memset(p, 0, sizeof *p);
}

/* The midpoint of edge (a, b) on the sphere: found in an open-addressing
 * table keyed by the edge, or made. */
typedef struct midpoints { uint64_t *key; uint32_t *val, cap; } midpoints;

static uint32_t midpoint(midpoints *t, silmap_polytope *p, uint32_t a, uint32_t b)
{
    if (a > b) {
        uint32_t s = a;
        a = b, b = s;
    }
    uint64_t key = (uint64_t)a << 32 | b;
    uint32_t i = (uint32_t)((key * 0x9E3779B97F4A7C15ull) >> 40) & (t->cap - 1);
    while (t->key[i] != UINT64_MAX && t->key[i] != key) i = (i + 1) & (t->cap - 1);
    if (t->key[i] == key) return t->val[i];
    uint32_t m = p->nviews++;
    for (int k = 0; k < 3; k++) p->dir[3 * m + k] = p->dir[3 * a + k] + p->dir[3 * b + k];
    normalize(&p->dir[3 * m]);
    t->key[i] = key;
    t->val[i] = m;
    return m;
}

int silmap_icosphere(int level, silmap_polytope *p)
{
    memset(p, 0, sizeof *p);
    if (level < 0 || level > 6) return -1;
    uint32_t nv = 10u * (1u << (2 * level)) + 2, nt = 20u * (1u << (2 * level));
    p->dir = malloc(3 * sizeof *p->dir * nv);
    p->tri = malloc(3 * sizeof *p->tri * nt);
    uint32_t *next = malloc(3 * sizeof *next * nt);
    midpoints t = { NULL, NULL, 1 };
    while (t.cap < 2 * 3 * nt / 2) t.cap *= 2;   /* at most 3/2 nt edges per level, half full */
    t.key = malloc(sizeof *t.key * t.cap);
    t.val = malloc(sizeof *t.val * t.cap);
    if (!p->dir || !p->tri || !next || !t.key || !t.val) {
        free(next), free(t.key), free(t.val);
        silmap_polytope_free(p);
        return -1;
    }
    const double g = (1 + sqrt(5.0)) / 2;
    const double v0[12][3] = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g }, { 0, 1, g },
                               { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 }, { -g, 0, 1 } };
    const uint32_t t0[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
                                 { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                                 { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
                                 { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
    for (int i = 0; i < 12; i++) {
        memcpy(&p->dir[3 * i], v0[i], sizeof v0[i]);
        normalize(&p->dir[3 * i]);
    }
    p->nviews = 12;
    p->ntris = 20;
    for (int i = 0; i < 20; i++) {
        /* counter-clockwise from outside: the normal along the centroid */
        const double *a = &p->dir[3 * t0[i][0]], *b = &p->dir[3 * t0[i][1]], *c = &p->dir[3 * t0[i][2]];
        double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] }, n[3];
        cross(e1, e2, n);
        int flip = dot(n, a) < 0;
        p->tri[3 * i] = t0[i][0];
        p->tri[3 * i + 1] = t0[i][flip ? 2 : 1];
        p->tri[3 * i + 2] = t0[i][flip ? 1 : 2];
    }
    for (int l = 0; l < level; l++) {
        for (uint32_t i = 0; i < t.cap; i++) t.key[i] = UINT64_MAX;
        uint32_t n = 0;
        for (uint32_t f = 0; f < p->ntris; f++) {
            uint32_t a = p->tri[3 * f], b = p->tri[3 * f + 1], c = p->tri[3 * f + 2];
            uint32_t ab = midpoint(&t, p, a, b), bc = midpoint(&t, p, b, c), ca = midpoint(&t, p, c, a);
            const uint32_t sub[4][3] = { { a, ab, ca }, { ab, b, bc }, { ca, bc, c }, { ab, bc, ca } };
            memcpy(&next[3 * n], sub, sizeof sub);
            n += 4;
        }
        memcpy(p->tri, next, 3 * sizeof *next * n);
        p->ntris = n;
    }
    free(next), free(t.key), free(t.val);
    return 0;
}

/* ---- cameras and images -------------------------------------------------------- */

void silmap_camera_at(const double centre[3], double radius, const double dir[3], double distance, int res,
                      silmap_camera *cam)
{
    double d[3] = { dir[0], dir[1], dir[2] };
    normalize(d);
    for (int k = 0; k < 3; k++) {
        cam->eye[k] = centre[k] + distance * radius * d[k];
        cam->fwd[k] = -d[k];
    }
    /* the world's y up, unless the view looks along it */
    double world_up[3] = { 0, fabs(d[1]) > 0.99 ? 0 : 1, fabs(d[1]) > 0.99 ? 1 : 0 };
    cross(cam->fwd, world_up, cam->right);
    normalize(cam->right);
    cross(cam->right, cam->fwd, cam->up);
    double half = asin(1 / distance) * 1.05;   /* the sphere's tangent cone, 5% to spare */
    cam->focal = res / (2 * tan(half));
    cam->res = res;
}

int silmap_project(const silmap_camera *cam, const double q[3], double out[2])
{
    double d[3] = { q[0] - cam->eye[0], q[1] - cam->eye[1], q[2] - cam->eye[2] };
    double z = dot(d, cam->fwd);
    if (!(z > 0)) return -1;
    out[0] = cam->res / 2.0 + cam->focal * dot(d, cam->right) / z;
    out[1] = cam->res / 2.0 - cam->focal * dot(d, cam->up) / z;
    return 0;
}

int silmap_rasterize(const silmap_camera *cam, const double *pos, uint32_t nverts, const uint32_t *tri,
                     uint32_t ntris, uint8_t *img)
{
    int res = cam->res;
    memset(img, 0, (size_t)res * res);
    double *xy = malloc(2 * sizeof *xy * (nverts ? nverts : 1));
    if (!xy) return -1;
    for (uint32_t i = 0; i < nverts; i++)
        if (silmap_project(cam, &pos[3 * i], &xy[2 * i])) {
            free(xy);
            return -1;
        }
    for (uint32_t f = 0; f < ntris; f++) {
        const double *a = &xy[2 * tri[3 * f]], *b = &xy[2 * tri[3 * f + 1]], *c = &xy[2 * tri[3 * f + 2]];
        double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (area == 0) continue;
        double s = area > 0 ? 1 : -1;
        /* pixels whose centre (x + 0.5, y + 0.5) can lie in the triangle */
        int x0 = (int)fmax(0, ceil(fmin(a[0], fmin(b[0], c[0])) - 0.5));
        int x1 = (int)fmin(res - 1, floor(fmax(a[0], fmax(b[0], c[0])) - 0.5));
        int y0 = (int)fmax(0, ceil(fmin(a[1], fmin(b[1], c[1])) - 0.5));
        int y1 = (int)fmin(res - 1, floor(fmax(a[1], fmax(b[1], c[1])) - 0.5));
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++) {
                double px = x + 0.5, py = y + 0.5;
                double w0 = s * ((b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]));
                double w1 = s * ((c[0] - b[0]) * (py - b[1]) - (c[1] - b[1]) * (px - b[0]));
                double w2 = s * ((a[0] - c[0]) * (py - c[1]) - (a[1] - c[1]) * (px - c[0]));
                if (w0 >= 0 && w1 >= 0 && w2 >= 0) img[(size_t)y * res + x] = 1;
            }
    }
    free(xy);
    return 0;
}

/* ---- outlines ------------------------------------------------------------------- */

void silmap_contours_free(silmap_contours *c)
{
    free(c->start);
    free(c->pt);
    memset(c, 0, sizeof *c);
}

double silmap_loop_area2(const silmap_contours *c, uint32_t i)
{
    double s = 0;
    uint32_t a = c->start[i], b = c->start[i + 1];
    for (uint32_t k = a; k < b; k++) {
        const double *p = &c->pt[2 * k], *q = &c->pt[2 * (k + 1 < b ? k + 1 : a)];
        s += p[0] * q[1] - q[0] * p[1];
    }
    return s;
}

/* Growing output: points and loop starts. */
static int put_point(silmap_contours *c, uint32_t *cap, double x, double y)
{
    if (c->npts == *cap) {
        uint32_t n = *cap ? 2 * *cap : 256;
        double *p = realloc(c->pt, 2 * sizeof *p * n);
        if (!p) return -1;
        c->pt = p;
        *cap = n;
    }
    c->pt[2 * c->npts] = x;
    c->pt[2 * c->npts + 1] = y;
    c->npts++;
    return 0;
}

static int put_loop(silmap_contours *c, uint32_t *cap)
{
    if (c->nloops + 2 > *cap) {
        uint32_t n = *cap ? 2 * *cap : 16;
        uint32_t *s = realloc(c->start, sizeof *s * n);
        if (!s) return -1;
        c->start = s;
        *cap = n;
    }
    c->start[++c->nloops] = c->npts;
    return 0;
}

/* The boundary edges, directed with the set pixel on the right when y
 * points down (so outer loops have positive area): at most two leave a
 * pixel corner, each remembered with its pixel. */
enum { RIGHT, DOWN, LEFT, UP };
static const int DX[4] = { 1, 0, -1, 0 }, DY[4] = { 0, 1, 0, -1 };

int silmap_trace(const uint8_t *img, int w, int h, silmap_contours *c)
{
    memset(c, 0, sizeof *c);
    size_t nv = (size_t)(w + 1) * (h + 1);
    uint8_t *nout = calloc(nv, 1), *dir = malloc(2 * nv), *used = calloc(2 * nv, 1);
    uint32_t *pix = malloc(2 * nv * sizeof *pix), cap_pts = 0, cap_loops = 0;
    int rc = -1;
    if (!nout || !dir || !used || !pix || !(c->start = malloc(16 * sizeof *c->start))) goto done;
    cap_loops = 16;
    c->start[0] = 0;
#define SET(x, y) ((x) >= 0 && (y) >= 0 && (x) < w && (y) < h && img[(size_t)(y) * w + (x)])
#define EDGE(vx, vy, d)                                                   \
    do {                                                                  \
        size_t v_ = (size_t)(vy) * (w + 1) + (vx);                        \
        dir[2 * v_ + nout[v_]] = (d);                                     \
        pix[2 * v_ + nout[v_]] = (uint32_t)((size_t)y * w + x);           \
        nout[v_]++;                                                       \
    } while (0)
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (!SET(x, y)) continue;
            if (!SET(x, y - 1)) EDGE(x, y, RIGHT);
            if (!SET(x + 1, y)) EDGE(x + 1, y, DOWN);
            if (!SET(x, y + 1)) EDGE(x + 1, y + 1, LEFT);
            if (!SET(x - 1, y)) EDGE(x, y + 1, UP);
        }
#undef SET
#undef EDGE
    for (size_t v = 0; v < nv; v++)
        for (int k = 0; k < nout[v]; k++) {
            if (used[2 * v + k]) continue;
            /* Walk the loop; keep the corners where it turns.  Where two
             * edges leave a corner (set pixels touching diagonally), stay
             * with the pixel of the edge that arrived. */
            size_t cur = v;
            int j = k, prev = -1, first_dir = -1;
            while (!used[2 * cur + j]) {
                used[2 * cur + j] = 1;
                int d = dir[2 * cur + j];
                if (first_dir < 0) first_dir = d;
                else if (d != prev && put_point(c, &cap_pts, (double)(cur % (w + 1)), (double)(cur / (w + 1)))) goto done;
                prev = d;
                uint32_t p = pix[2 * cur + j];
                cur = (size_t)((long)cur + DX[d] + (long)DY[d] * (w + 1));
                j = nout[cur] == 2 && pix[2 * cur + 1] == p ? 1 : 0;
            }
            /* the start corner, if the loop turns there */
            if (prev != first_dir && put_point(c, &cap_pts, (double)(v % (w + 1)), (double)(v / (w + 1)))) goto done;
            if (put_loop(c, &cap_loops)) goto done;
        }
    rc = 0;
done:
    free(nout), free(dir), free(used), free(pix);
    if (rc) silmap_contours_free(c);
    return rc;
}

int silmap_midpoints(const silmap_contours *in, silmap_contours *out)
{
    memset(out, 0, sizeof *out);
    out->start = malloc(sizeof *out->start * (in->nloops + 1));
    out->pt = malloc(4 * sizeof *out->pt * (in->npts ? in->npts : 1));
    if (!out->start || !out->pt) {
        silmap_contours_free(out);
        return -1;
    }
    out->start[0] = 0;
    for (uint32_t l = 0; l < in->nloops; l++) {
        uint32_t a = in->start[l], n = in->start[l + 1] - a;
        for (uint32_t k = 0; k < n; k++) {
            const double *p = &in->pt[2 * (a + k)], *q = &in->pt[2 * (a + (k + 1) % n)];
            double dx = q[0] - p[0], dy = q[1] - p[1], len = fabs(dx) + fabs(dy);   /* axis-aligned */
            dx /= len, dy /= len;
            out->pt[2 * out->npts] = p[0] + dx / 2, out->pt[2 * out->npts + 1] = p[1] + dy / 2, out->npts++;
            if (len > 1) out->pt[2 * out->npts] = q[0] - dx / 2, out->pt[2 * out->npts + 1] = q[1] - dy / 2, out->npts++;
        }
        out->start[++out->nloops] = out->npts;
    }
    return 0;
}

/* ---- Douglas-Peucker ---------------------------------------------------------------- */

static double seg_dist(const double *p, const double *a, const double *b)
{
    double ab[2] = { b[0] - a[0], b[1] - a[1] }, ap[2] = { p[0] - a[0], p[1] - a[1] };
    double l2 = ab[0] * ab[0] + ab[1] * ab[1], t = l2 > 0 ? (ap[0] * ab[0] + ap[1] * ab[1]) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double d[2] = { ap[0] - t * ab[0], ap[1] - t * ab[1] };
    return sqrt(d[0] * d[0] + d[1] * d[1]);
}

/* Keep the points of the chain i..j (indices mod n of loop P) that
 * Douglas-Peucker keeps; force: split once even within tol.  stack holds
 * 2 * n pairs. */
static void dp_chain(const double *P, uint32_t n, uint32_t i, uint32_t j, double tol, int force, uint8_t *keep,
                     uint32_t *stack)
{
    uint32_t top = 0;
    stack[top++] = i, stack[top++] = j + (j < i ? n : 0);
    while (top) {
        uint32_t b = stack[--top], a = stack[--top];
        if (b - a < 2) continue;
        double worst = -1;
        uint32_t at = a;
        for (uint32_t k = a + 1; k < b; k++) {
            double d = seg_dist(&P[2 * (k % n)], &P[2 * (a % n)], &P[2 * (b % n)]);
            if (d > worst) worst = d, at = k;
        }
        if (worst > tol || force) {
            keep[at % n] = 1;
            stack[top++] = a, stack[top++] = at;
            stack[top++] = at, stack[top++] = b;
        }
        force = 0;
    }
}

int silmap_simplify(const silmap_contours *in, double tol, silmap_contours *out)
{
    memset(out, 0, sizeof *out);
    uint32_t np = in->npts ? in->npts : 1;
    uint8_t *keep = malloc(np);
    uint32_t *stack = malloc(4 * sizeof *stack * np + 4 * sizeof *stack);
    out->start = malloc(sizeof *out->start * (in->nloops + 1));
    out->pt = malloc(2 * sizeof *out->pt * np);
    if (!keep || !stack || !out->start || !out->pt) {
        free(keep), free(stack);
        silmap_contours_free(out);
        return -1;
    }
    out->start[0] = 0;
    for (uint32_t l = 0; l < in->nloops; l++) {
        uint32_t s = in->start[l], n = in->start[l + 1] - s;
        const double *P = &in->pt[2 * s];
        memset(keep, 0, n);
        if (n <= 3) {
            memset(keep, 1, n);
        } else {
            /* anchors: the first point and the one farthest from it */
            uint32_t far = 0;
            double best = -1;
            for (uint32_t k = 1; k < n; k++) {
                double dx = P[2 * k] - P[0], dy = P[2 * k + 1] - P[1], d = dx * dx + dy * dy;
                if (d > best) best = d, far = k;
            }
            keep[0] = keep[far] = 1;
            dp_chain(P, n, 0, far, tol, 1, keep, stack);
            dp_chain(P, n, far, 0, tol, 1, keep, stack);
        }
        for (uint32_t k = 0; k < n; k++)
            if (keep[k]) {
                out->pt[2 * out->npts] = P[2 * k];
                out->pt[2 * out->npts + 1] = P[2 * k + 1];
                out->npts++;
            }
        out->start[++out->nloops] = out->npts;
    }
    free(keep), free(stack);
    return 0;
}

/* ---- the whole dense map -------------------------------------------------------------- */

void silmap_params_default(silmap_params *p)
{
    p->level = 2;
    p->res = 256;
    p->tol = 0.5;
    p->distance = 3;
}

void silmap_free(silmap *m)
{
    if (m->views)
        for (uint32_t i = 0; i < m->poly.nviews; i++) silmap_contours_free(&m->views[i].outline);
    free(m->views);
    silmap_polytope_free(&m->poly);
    memset(m, 0, sizeof *m);
}

int silmap_build(const double *pos, uint32_t nverts, const uint32_t *tri, uint32_t ntris, const silmap_params *p,
                 silmap *m)
{
    memset(m, 0, sizeof *m);
    if (p->level < 0 || p->level > 6 || p->res < 8 || p->res > 4096 || !(p->tol >= 0) || !(p->distance > 1) ||
        nverts == 0)
        return -1;
    m->params = *p;
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t i = 0; i < nverts; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], pos[3 * i + k]), hi[k] = fmax(hi[k], pos[3 * i + k]);
    for (int k = 0; k < 3; k++) m->centre[k] = (lo[k] + hi[k]) / 2;
    double r2 = 0;
    for (uint32_t i = 0; i < nverts; i++) {
        double d[3] = { pos[3 * i] - m->centre[0], pos[3 * i + 1] - m->centre[1], pos[3 * i + 2] - m->centre[2] };
        r2 = fmax(r2, dot(d, d));
    }
    m->radius = r2 > 0 ? sqrt(r2) : 1;
    uint8_t *img = malloc((size_t)p->res * p->res);
    if (!img || silmap_icosphere(p->level, &m->poly) ||
        !(m->views = calloc(m->poly.nviews, sizeof *m->views))) {
        free(img);
        silmap_free(m);
        return -1;
    }
    for (uint32_t i = 0; i < m->poly.nviews; i++) {
        silmap_view *v = &m->views[i];
        silmap_contours traced;
        silmap_camera_at(m->centre, m->radius, &m->poly.dir[3 * i], p->distance, p->res, &v->cam);
        if (silmap_rasterize(&v->cam, pos, nverts, tri, ntris, img) || silmap_trace(img, p->res, p->res, &traced)) {
            free(img);
            silmap_free(m);
            return -1;
        }
        v->traced_pts = traced.npts;
        silmap_contours mid;
        int rc = silmap_midpoints(&traced, &mid);
        silmap_contours_free(&traced);
        if (!rc) {
            rc = silmap_simplify(&mid, p->tol, &v->outline);
            silmap_contours_free(&mid);
        }
        if (rc) {
            free(img);
            silmap_free(m);
            return -1;
        }
    }
    free(img);
    return 0;
}

/* ---- the map as the renderer reads it ------------------------------------------ */

uint32_t *silmap_adjacency(const silmap_polytope *p)
{
    uint32_t *adj = malloc((size_t)3 * (p->ntris ? p->ntris : 1) * sizeof *adj);
    if (!adj) return NULL;
    for (uint32_t t = 0; t < p->ntris; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = p->tri[3 * t + (k + 1) % 3], b = p->tri[3 * t + (k + 2) % 3];
            adj[3 * t + k] = UINT32_MAX;
            for (uint32_t u = 0; u < p->ntris && adj[3 * t + k] == UINT32_MAX; u++)
                for (int j = 0; j < 3; j++)
                    if (u != t && p->tri[3 * u + j] == b && p->tri[3 * u + (j + 1) % 3] == a) adj[3 * t + k] = u;
        }
    return adj;
}

static int to_fx(double v, silk_fx *out)
{
    double s = floor(v * 65536 + 0.5);
    if (!(s > -2147483647.0 && s < 2147483647.0)) return -1;
    *out = (silk_fx)s;
    return 0;
}

static int to_v3(const double *v, silk_vec3 *out)
{
    return to_fx(v[0], &out->x) | to_fx(v[1], &out->y) | to_fx(v[2], &out->z);
}

int silmap_cam_export(const silmap_camera *cam, silk_silmap_cam *c)
{
    memset(c, 0, sizeof *c);
    return to_v3(cam->eye, &c->eye) | to_v3(cam->right, &c->right) | to_v3(cam->up, &c->up) |
           to_v3(cam->fwd, &c->fwd) | to_fx(cam->focal, &c->focal) | to_fx(cam->res / 2.0, &c->cx) |
           to_fx(cam->res / 2.0, &c->cy);
}

void silmap_fixed_free(silmap_fixed *f)
{
    free(f->block);
    memset(f, 0, sizeof *f);
}

int silmap_export(const silmap *m, silmap_fixed *out)
{
    memset(out, 0, sizeof *out);
    silk_silmap *s = &out->map;
    s->nviews = m->poly.nviews;
    s->ntris = m->poly.ntris;
    for (uint32_t i = 0; i < s->nviews; i++) {
        s->nloops += m->views[i].outline.nloops;
        s->npts += m->views[i].outline.npts;
    }
    size_t bytes = s->nviews * sizeof(silk_silmap_view) + (size_t)6 * s->ntris * sizeof(uint32_t) +
                   (s->nloops + 1) * sizeof(uint32_t) + s->npts * sizeof(silk_vec2);
    uint8_t *b = calloc(1, bytes);
    uint32_t *adj = silmap_adjacency(&m->poly);
    if (!b || !adj) {
        free(b);
        free(adj);
        return -1;
    }
    out->block = b;
    silk_silmap_view *views = (silk_silmap_view *)b;
    uint32_t *tri = (uint32_t *)(views + s->nviews), *ad = tri + 3 * s->ntris, *start = ad + 3 * s->ntris;
    silk_vec2 *pts = (silk_vec2 *)(start + s->nloops + 1);
    memcpy(tri, m->poly.tri, 3 * sizeof *tri * s->ntris);
    memcpy(ad, adj, 3 * sizeof *ad * s->ntris);
    free(adj);
    int bad = to_v3(m->centre, &s->centre);
    uint32_t loop = 0, npt = 0;
    for (uint32_t i = 0; i < s->nviews; i++) {
        const silmap_view *v = &m->views[i];
        bad |= silmap_cam_export(&v->cam, &views[i].cam);
        views[i].first_loop = loop;
        views[i].nloops = v->outline.nloops;
        for (uint32_t l = 0; l < v->outline.nloops; l++) start[loop++] = npt + v->outline.start[l];
        for (uint32_t k = 0; k < v->outline.npts; k++) {
            bad |= to_fx(v->outline.pt[2 * k], &pts[npt + k].x) | to_fx(v->outline.pt[2 * k + 1], &pts[npt + k].y);
        }
        npt += v->outline.npts;
    }
    start[loop] = npt;
    s->views = views;
    s->tri = tri;
    s->adj = ad;
    s->loop_start = start;
    s->pts = pts;
    if (bad) {
        silmap_fixed_free(out);
        return -1;
    }
    return 0;
}
