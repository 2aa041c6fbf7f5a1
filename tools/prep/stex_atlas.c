/*
 * stex_atlas.c - charts of hull triangles unfolded flat, skyline-packed
 * (stex_atlas.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "closest.h"
#include "stex_atlas.h"
#include "vec3.h"

#define CHART_TRIS 16            /* triangles a chart grows to at most */
#define CHART_FILL 0.7           /* least share of its convex hull a chart covers */

typedef struct chart {
    int ntris;
    uint32_t tri[CHART_TRIS];
    double p[CHART_TRIS][3][2];  /* each triangle's corners (hull order) in the plane, lengths */
    double w, h;             /* bounding box, lengths; corners from (0, 0) */
    int x, y, bw, bh;        /* the box in texels, gutter included */
} chart;

typedef struct edge_ref { uint32_t lo, hi, tri; int side; } edge_ref;

static int by_edge(const void *a, const void *b)
{
    const edge_ref *x = a, *y = b;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
    return x->tri < y->tri ? -1 : x->tri > y->tri;
}

static double edge_len(const simp_mesh *m, uint32_t t, int side)
{
    double d[3];
    sub3(&m->pos[3 * m->tri[3 * t + (side + 1) % 3]], &m->pos[3 * m->tri[3 * t + side]], d);
    return len3(d);
}

/* Plane coordinates of c, with a at the origin and b on the +x axis. */
static void flat(const double *a, const double *b, const double *c, double sign, double out[2])
{
    double e[3], f[3], n[3];
    sub3(b, a, e);
    sub3(c, a, f);
    double l = len3(e);
    cross3(e, f, n);
    out[0] = dot3(f, e) / l;
    out[1] = sign * len3(n) / l;
}

/* Lay triangle t out with its corner `side` and the next one on the x
 * axis, the third at y >= 0 (sign 1) or <= 0 (sign -1). */
static void lay(const simp_mesh *m, uint32_t t, int side, double sign, double p[3][2])
{
    const uint32_t *v = &m->tri[3 * t];
    const double *a = &m->pos[3 * v[side]], *b = &m->pos[3 * v[(side + 1) % 3]], *c = &m->pos[3 * v[(side + 2) % 3]];
    double e[3];
    sub3(b, a, e);
    p[side][0] = 0, p[side][1] = 0;
    p[(side + 1) % 3][0] = len3(e), p[(side + 1) % 3][1] = 0;
    flat(a, b, c, sign, p[(side + 2) % 3]);
}

/* Turn the chart so that its bounding box is smallest, one of its edges
 * along x, and move it to the origin. */
static void orient(chart *c)
{
    double best = INFINITY, bc = 1, bs = 0;
    for (int i = 0; i < c->ntris; i++)
        for (int k = 0; k < 3; k++) {
            double dx = c->p[i][(k + 1) % 3][0] - c->p[i][k][0], dy = c->p[i][(k + 1) % 3][1] - c->p[i][k][1];
            double l = hypot(dx, dy), co = dx / l, si = dy / l, lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
            for (int j = 0; j < c->ntris; j++)
                for (int q = 0; q < 3; q++) {
                    double x = co * c->p[j][q][0] + si * c->p[j][q][1], y = -si * c->p[j][q][0] + co * c->p[j][q][1];
                    lo[0] = fmin(lo[0], x), hi[0] = fmax(hi[0], x), lo[1] = fmin(lo[1], y), hi[1] = fmax(hi[1], y);
                }
            if ((hi[0] - lo[0]) * (hi[1] - lo[1]) < best) best = (hi[0] - lo[0]) * (hi[1] - lo[1]), bc = co, bs = si;
        }
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
    for (int j = 0; j < c->ntris; j++)
        for (int q = 0; q < 3; q++) {
            double x = bc * c->p[j][q][0] + bs * c->p[j][q][1], y = -bs * c->p[j][q][0] + bc * c->p[j][q][1];
            c->p[j][q][0] = x, c->p[j][q][1] = y;
            lo[0] = fmin(lo[0], x), hi[0] = fmax(hi[0], x), lo[1] = fmin(lo[1], y), hi[1] = fmax(hi[1], y);
        }
    for (int j = 0; j < c->ntris; j++)
        for (int q = 0; q < 3; q++) c->p[j][q][0] -= lo[0], c->p[j][q][1] -= lo[1];
    c->w = hi[0] - lo[0], c->h = hi[1] - lo[1];
}

static double area2(double p[3][2])
{
    return fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1])) / 2;
}

/* Whether the plane triangles a and b overlap with more than their
 * boundaries (separating axes: the sides' normals). */
static int overlap(double a[3][2], double b[3][2], double eps)
{
    double (*t[2])[2] = { a, b };
    for (int w = 0; w < 2; w++)
        for (int k = 0; k < 3; k++) {
            double nx = t[w][(k + 1) % 3][1] - t[w][k][1], ny = t[w][k][0] - t[w][(k + 1) % 3][0];
            double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
            for (int v = 0; v < 2; v++)
                for (int i = 0; i < 3; i++) {
                    double x = nx * t[v][i][0] + ny * t[v][i][1];
                    lo[v] = fmin(lo[v], x), hi[v] = fmax(hi[v], x);
                }
            double l = hypot(nx, ny);
            if (hi[0] <= lo[1] + eps * l || hi[1] <= lo[0] + eps * l) return 0;
        }
    return 1;
}

static double cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static int by_xy(const void *a, const void *b)
{
    const double *x = a, *y = b;
    return x[0] != y[0] ? (x[0] < y[0] ? -1 : 1) : (x[1] < y[1] ? -1 : x[1] > y[1]);
}

/* The area of the convex hull of the chart's corners with extra (Andrew's
 * monotone chain). */
static double hull_area(const chart *c, double extra[3][2])
{
    double pt[3 * CHART_TRIS + 3][2], h[2 * (3 * CHART_TRIS + 3)][2];
    int n = 0, k = 0;
    for (int j = 0; j < c->ntris; j++)
        for (int q = 0; q < 3; q++) pt[n][0] = c->p[j][q][0], pt[n][1] = c->p[j][q][1], n++;
    for (int q = 0; q < 3; q++) pt[n][0] = extra[q][0], pt[n][1] = extra[q][1], n++;
    qsort(pt, (size_t)n, sizeof pt[0], by_xy);
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross2(h[k - 2], h[k - 1], pt[i]) <= 0) k--;
        h[k][0] = pt[i][0], h[k][1] = pt[i][1], k++;
    }
    for (int i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && cross2(h[k - 2], h[k - 1], pt[i]) <= 0) k--;
        h[k][0] = pt[i][0], h[k][1] = pt[i][1], k++;
    }
    double a = 0;
    for (int i = 0; i + 1 < k; i++) a += h[i][0] * h[i + 1][1] - h[i + 1][0] * h[i][1];
    return fabs(a) / 2;
}

/* Triangle o laid out across the side of chart triangle j whose first
 * corner is side, on the other side of it from j. */
static void unfold(const simp_mesh *m, const chart *c, int j, int side, uint32_t o, double out[3][2])
{
    uint32_t a = m->tri[3 * c->tri[j] + side], b = m->tri[3 * c->tri[j] + (side + 1) % 3];
    const double *pa = c->p[j][side], *pb = c->p[j][(side + 1) % 3], *pc = c->p[j][(side + 2) % 3];
    int oa = 0;
    while (oa < 3 && m->tri[3 * o + oa] != a) oa++;
    int ob = (oa + 2) % 3, oc = (oa + 1) % 3;   /* o runs the shared side the other way: b then a */
    double f[2];
    flat(&m->pos[3 * a], &m->pos[3 * b], &m->pos[3 * m->tri[3 * o + oc]], 1, f);
    double ex = pb[0] - pa[0], ey = pb[1] - pa[1], l = hypot(ex, ey);
    ex /= l, ey /= l;
    double nx = -ey, ny = ex;
    if ((pc[0] - pa[0]) * nx + (pc[1] - pa[1]) * ny > 0) nx = -nx, ny = -ny;
    out[oa][0] = pa[0], out[oa][1] = pa[1];
    out[ob][0] = pb[0], out[ob][1] = pb[1];
    out[oc][0] = pa[0] + f[0] * ex + f[1] * nx, out[oc][1] = pa[1] + f[0] * ey + f[1] * ny;
}

/* Charts grown from seed triangles across shared sides, each new triangle
 * unfolded flat about its side, while the chart overlaps nowhere, covers
 * CHART_FILL of its convex hull and has at most CHART_TRIS triangles.
 * Returns the number of charts, or -1 when out of memory. */
static long make_charts(const simp_mesh *m, chart *ch)
{
    size_t ne = 3 * (size_t)m->ntris;
    edge_ref *e = malloc((ne ? ne : 1) * sizeof *e);
    uint32_t *nb = malloc((ne ? ne : 1) * sizeof *nb);
    int32_t *mate = malloc((m->ntris ? m->ntris : 1) * sizeof *mate);
    if (!e || !nb || !mate) {
        free(e), free(nb), free(mate);
        return -1;
    }
    for (uint32_t t = 0; t < m->ntris; t++)
        for (int s = 0; s < 3; s++) {
            uint32_t a = m->tri[3 * t + s], b = m->tri[3 * t + (s + 1) % 3];
            e[3 * t + s] = (edge_ref){ a < b ? a : b, a < b ? b : a, t, s };
            nb[3 * t + s] = UINT32_MAX;
        }
    qsort(e, ne, sizeof *e, by_edge);
    for (size_t i = 0; i + 1 < ne; i++)
        if (e[i].lo == e[i + 1].lo && e[i].hi == e[i + 1].hi) {
            nb[3 * e[i].tri + e[i].side] = e[i + 1].tri;
            nb[3 * e[i + 1].tri + e[i + 1].side] = e[i].tri;
        }
    for (uint32_t t = 0; t < m->ntris; t++) mate[t] = -1;
    long n = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (mate[t] >= 0) continue;
        chart *c = &ch[n];
        memset(c, 0, sizeof *c);
        int longest = 0;
        for (int s = 1; s < 3; s++)
            if (edge_len(m, t, s) > edge_len(m, t, longest)) longest = s;
        c->ntris = 1;
        c->tri[0] = t;
        mate[t] = (int32_t)n;
        lay(m, t, longest, 1, c->p[0]);
        double area = area2(c->p[0]), eps = 1e-9 * edge_len(m, t, longest);
        while (c->ntris < CHART_TRIS) {
            /* the candidate that keeps the chart most compact */
            double best = CHART_FILL, cand[3][2], keep[3][2];
            uint32_t pick = UINT32_MAX;
            for (int j = 0; j < c->ntris; j++)
                for (int s = 0; s < 3; s++) {
                    uint32_t o = nb[3 * c->tri[j] + s];
                    if (o == UINT32_MAX || mate[o] >= 0) continue;
                    unfold(m, c, j, s, o, cand);
                    int bad = 0;
                    for (int i = 0; i < c->ntris && !bad; i++) bad = overlap(cand, c->p[i], eps);
                    if (bad) continue;
                    double fill = (area + area2(cand)) / hull_area(c, cand);
                    if (fill > best) best = fill, pick = o, memcpy(keep, cand, sizeof keep);
                }
            if (pick == UINT32_MAX) break;
            c->tri[c->ntris] = pick;
            memcpy(c->p[c->ntris], keep, sizeof keep);
            c->ntris++;
            mate[pick] = (int32_t)n;
            area += area2(keep);
        }
        orient(c);
        n++;
    }
    free(e), free(nb), free(mate);
    return n;
}

static int by_height(const void *a, const void *b)
{
    const chart *x = a, *y = b;
    return x->h > y->h ? -1 : x->h < y->h;
}

/* Skyline packing at density s: each box, tallest first, where it lies
 * lowest (leftmost among equals) on the boxes below.  1 when every box
 * fits in w x h. */
static int pack(chart *ch, long n, double s, int w, int h, int *sky)
{
    for (int x = 0; x < w; x++) sky[x] = 0;
    for (long i = 0; i < n; i++) {
        chart *c = &ch[i];
        double bw = ceil(c->w * s) + 2, bh = ceil(c->h * s) + 2;
        if (bw > w || bh > h) return 0;
        c->bw = (int)bw, c->bh = (int)bh;
        int best = -1, by = h;
        for (int x = 0; x + c->bw <= w; x++) {
            int y = 0;
            for (int k = x; k < x + c->bw; k++) y = sky[k] > y ? sky[k] : y;
            if (y < by) by = y, best = x;
        }
        if (best < 0 || by + c->bh > h) return 0;
        c->x = best, c->y = by;
        for (int k = best; k < best + c->bw; k++) sky[k] = by + c->bh;
    }
    return 1;
}

/* Barycentric coordinates of (x, y) in the plane triangle p; for a
 * triangle squashed flat (a sliver of the hull, rounded to 1/16 texel),
 * those of the nearest point of its longest side. */
static void bary2(double p[3][2], double x, double y, double b[3])
{
    double d = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    if (d == 0) {
        int i = 0;
        double best = -1;
        for (int k = 0; k < 3; k++) {
            double l = hypot(p[(k + 1) % 3][0] - p[k][0], p[(k + 1) % 3][1] - p[k][1]);
            if (l > best) best = l, i = k;
        }
        int j = (i + 1) % 3;
        double ex = p[j][0] - p[i][0], ey = p[j][1] - p[i][1], l2 = ex * ex + ey * ey;
        double t = l2 > 0 ? ((x - p[i][0]) * ex + (y - p[i][1]) * ey) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        b[0] = b[1] = b[2] = 0;
        b[i] = 1 - t, b[j] = t;
        return;
    }
    b[1] = ((x - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (y - p[0][1])) / d;
    b[2] = ((p[1][0] - p[0][0]) * (y - p[0][1]) - (x - p[0][0]) * (p[1][1] - p[0][1])) / d;
    b[0] = 1 - b[1] - b[2];
}

/* Every texel of c's box: the chart point nearest its centre. */
static void fill(const chart *c, const uint16_t *uv, stex_atlas *a)
{
    for (int iy = c->y; iy < c->y + c->bh; iy++)
        for (int ix = c->x; ix < c->x + c->bw; ix++) {
            size_t t = (size_t)iy * a->w + ix;
            double px = ix + 0.5, py = iy + 0.5, best = INFINITY;
            for (int j = 0; j < c->ntris; j++) {
                double p[3][2], p3[3][3], cen[3] = { px, py, 0 }, q[3], b[3];
                for (int k = 0; k < 3; k++) {
                    p[k][0] = uv[6 * c->tri[j] + 2 * k] / 16.0, p[k][1] = uv[6 * c->tri[j] + 2 * k + 1] / 16.0;
                    p3[k][0] = p[k][0], p3[k][1] = p[k][1], p3[k][2] = 0;
                }
                double area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
                bary2(p, px, py, b);
                int in = area != 0 && b[0] >= 0 && b[1] >= 0 && b[2] >= 0;
                double d2 = in ? 0 : point_tri_closest(cen, p3[0], p3[1], p3[2], q);
                if (d2 >= best) continue;
                best = d2;
                if (!in) {
                    bary2(p, q[0], q[1], b);
                    double sum = 0;
                    for (int k = 0; k < 3; k++) sum += (b[k] = fmax(0, b[k]));
                    for (int k = 0; k < 3; k++) b[k] /= sum;
                }
                a->tri[t] = (int32_t)c->tri[j];
                memcpy(&a->bary[3 * t], b, sizeof b);
                a->inside[t] = (uint8_t)in;
            }
        }
}

int stex_atlas_build(const simp_mesh *hull, int w, int h, stex_atlas *a)
{
    memset(a, 0, sizeof *a);
    a->w = w, a->h = h;
    size_t nt = (size_t)w * h;
    chart *ch = malloc((hull->ntris ? hull->ntris : 1) * sizeof *ch);
    a->uv = calloc(6 * (size_t)hull->ntris + 1, sizeof *a->uv);
    a->tri = malloc(nt * sizeof *a->tri);
    a->bary = calloc(3 * nt, sizeof *a->bary);
    a->inside = calloc(nt, 1);
    long n = ch ? make_charts(hull, ch) : -1;
    if (n < 0 || !a->uv || !a->tri || !a->bary || !a->inside) {
        free(ch);
        stex_atlas_free(a);
        return -1;
    }
    qsort(ch, (size_t)n, sizeof *ch, by_height);
    double area = 0;
    for (long i = 0; i < n; i++) area += ch[i].w * ch[i].h;
    double lo = 1e-9, hi = 2 * sqrt((double)w * h / (area > 0 ? area : 1));
    int *sky = malloc((size_t)w * sizeof *sky);
    if (!sky || !pack(ch, n, lo / 1e6, w, h, sky)) {
        int rc = sky ? -2 : -1;
        free(sky);
        free(ch);
        stex_atlas_free(a);
        return rc;
    }
    for (int it = 0; it < 50; it++) {
        double mid = (lo + hi) / 2;
        if (pack(ch, n, mid, w, h, sky)) lo = mid;
        else hi = mid;
    }
    pack(ch, n, lo, w, h, sky);
    free(sky);
    a->density = lo;
    a->ncharts = (uint32_t)n;
    for (size_t t = 0; t < nt; t++) a->tri[t] = -1;
    for (long i = 0; i < n; i++) {
        const chart *c = &ch[i];
        for (int j = 0; j < c->ntris; j++)
            for (int k = 0; k < 3; k++) {
                a->uv[6 * c->tri[j] + 2 * k] = (uint16_t)lround((c->x + 1 + c->p[j][k][0] * lo) * 16);
                a->uv[6 * c->tri[j] + 2 * k + 1] = (uint16_t)lround((c->y + 1 + c->p[j][k][1] * lo) * 16);
            }
        fill(c, a->uv, a);
    }
    free(ch);
    return 0;
}

void stex_atlas_free(stex_atlas *a)
{
    free(a->uv);
    free(a->tri);
    free(a->bary);
    free(a->inside);
    memset(a, 0, sizeof *a);
}
