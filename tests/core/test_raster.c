/*
 * test_raster.c - the scanline rasterizer: exact coverage (top-left rule, no
 * gaps, no double hits), golden images, perspective-correct varyings against
 * a double reference, clipping, bands, lines, and frame sizes.
 *
 * Golden images live in tests/golden/ and are compared byte for byte by
 * tests/support/golden.c (`make golden` rewrites them).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "src/raster_place.h"   /* silk_raster_place, _reaches, _placed */
#include "support/golden.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define SUB 16   /* the rasterizer's subpixel grid (docs/raster.md) */

/* ---- images ------------------------------------------------------------------ */

typedef struct img {
    silk_target t;
    uint8_t *color;
    uint32_t *depth;
    uint16_t *writes;
} img;

static void img_new(img *m, int w, int h, silk_pixfmt fmt, int y0, int rows, int with_depth)
{
    size_t n = (size_t)w * (size_t)rows;
    m->color = calloc(n, silk_pixfmt_bytes(fmt));
    m->depth = with_depth ? calloc(n, sizeof(uint32_t)) : NULL;
    m->writes = calloc(n, sizeof(uint16_t));
    silk_target_init(&m->t, w, h, y0, rows, fmt, m->color, m->depth);
    m->t.writes = m->writes;
    silk_target_clear(&m->t, 0);
}

static void img_free(img *m)
{
    free(m->color);
    free(m->depth);
    free(m->writes);
}

static int cnt(const img *m, int x, int y) { return m->writes[(size_t)(y - m->t.y0) * m->t.width + x]; }

/* ---- vertices at exact subpixel positions -------------------------------------- */

/* A clip-space vertex that projects exactly to subpixel (X, Y) of a W x H
 * frame (W, H powers of two up to 1024), with w = k * 2^-6 * max(W,H)*16 /
 * 1024... any k: x and w are chosen so that (x + w) W 16 / (2w) == X exactly. */
static silk_vertex_out vat(int W, int H, int64_t X, int64_t Y, int k)
{
    int64_t big = (W > H ? W : H) * (int64_t)SUB;
    int64_t w = (int64_t)k * big;                      /* raw Q16.16 */
    silk_vertex_out v;
    memset(&v, 0, sizeof v);
    v.clip.w = (silk_fx)w;
    v.clip.x = (silk_fx)((2 * X - (int64_t)W * SUB) * w / ((int64_t)W * SUB));
    v.clip.y = (silk_fx)(((int64_t)H * SUB - 2 * Y) * w / ((int64_t)H * SUB));
    v.clip.z = 0;
    return v;
}

static int64_t rnd(int64_t lo, int64_t hi) { return lo + (int64_t)(check_rand64() % (uint64_t)(hi - lo + 1)); }

/* fragment stages for tests */
static uint32_t frag_white(const silk_hal *h, const silk_fx *var)
{
    (void)h; (void)var;
    return 0xFFFFFF;
}

static silk_hal hal_flat(void)
{
    silk_hal h;
    memset(&h, 0, sizeof h);
    h.fragment = frag_white;
    return h;
}

/* ---- (a) coverage ---------------------------------------------------------------- */

/* A rectangle cut into a fan of triangles around a random inner point, with
 * random extra points on its sides and random w per vertex: every pixel
 * whose centre is in [x0,x1) x [y0,y1) must be written exactly once, every
 * other pixel never. */
TEST(fan_rectangle_exactly_once)
{
    const int W = 64, H = 64;
    silk_hal h = hal_flat();
    int bad = 0;
    for (int trial = 0; trial < 400 && !bad; trial++) {
        int64_t x0 = rnd(-8 * SUB, 40 * SUB), y0 = rnd(-8 * SUB, 40 * SUB);
        int64_t x1 = x0 + rnd(1, 40 * SUB), y1 = y0 + rnd(1, 40 * SUB);
        if (trial % 5 == 0) { x0 = 3 * SUB; y0 = 5 * SUB + SUB / 2; x1 = x0 + SUB * rnd(1, 30); }
        /* rim, counter-clockwise: corners plus up to 3 points per side */
        int64_t rx[20], ry[20];
        int n = 0;
        int64_t cx[4] = { x0, x1, x1, x0 }, cy[4] = { y0, y0, y1, y1 };
        for (int s = 0; s < 4; s++) {
            rx[n] = cx[s]; ry[n] = cy[s]; n++;
            int extra = (int)rnd(0, 3);
            int64_t ax = cx[s], ay = cy[s], bx = cx[(s + 1) % 4], by = cy[(s + 1) % 4];
            int64_t prev = 0, len = (bx - ax) + (by - ay);
            if (len < 0) len = -len;
            for (int e = 0; e < extra; e++) {
                if (prev + 1 > len - 1) break;
                int64_t d = rnd(prev + 1, len - 1);
                prev = d;
                rx[n] = ax + (bx > ax ? d : (bx < ax ? -d : 0));
                ry[n] = ay + (by > ay ? d : (by < ay ? -d : 0));
                n++;
            }
        }
        int64_t px = rnd(x0 + 1, x1 - 1 > x0 + 1 ? x1 - 1 : x0 + 1);
        int64_t py = rnd(y0 + 1, y1 - 1 > y0 + 1 ? y1 - 1 : y0 + 1);
        if (x1 - x0 < 2 || y1 - y0 < 2) continue;
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 0);
        int kc = (int)rnd(64, 1024);
        int kr[20];
        for (int i = 0; i < n; i++) kr[i] = (int)rnd(64, 1024);
        int rev = trial & 1;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            silk_vertex_out c = vat(W, H, px, py, kc), a = vat(W, H, rx[i], ry[i], kr[i]),
                            b = vat(W, H, rx[j], ry[j], kr[j]);
            if (rev) silk_raster_triangle(&m.t, &h, &c, &b, &a);
            else silk_raster_triangle(&m.t, &h, &a, &c, &b);
        }
        for (int y = 0; y < H && !bad; y++)
            for (int x = 0; x < W; x++) {
                int64_t sx = x * SUB + SUB / 2, sy = y * SUB + SUB / 2;
                int want = sx >= x0 && sx < x1 && sy >= y0 && sy < y1;
                if (cnt(&m, x, y) != want) {
                    CHECKF(0, "trial %d pixel (%d,%d) written %d times, want %d", trial, x, y,
                           cnt(&m, x, y), want);
                    bad = 1;
                    break;
                }
            }
        img_free(&m);
    }
}

/* Random star-shaped polygons fanned around a random centre: no pixel is
 * written twice, pixels clearly inside are written once, clearly outside never. */
TEST(fan_star_random)
{
    const int W = 64, H = 64;
    silk_hal h = hal_flat();
    int bad = 0, used = 0;
    for (int trial = 0; trial < 300 && !bad; trial++) {
        int n = (int)rnd(3, 24);
        double ang[24];
        /* angles sorted, every gap below pi, so the triangles do not fold over */
        for (int ok = 0; !ok;) {
            for (int i = 0; i < n; i++) ang[i] = check_uniform(0, 2 * M_PI);
            for (int i = 1; i < n; i++)
                for (int j = i; j > 0 && ang[j - 1] > ang[j]; j--) { double t = ang[j]; ang[j] = ang[j - 1]; ang[j - 1] = t; }
            ok = ang[0] + 2 * M_PI - ang[n - 1] < M_PI - 0.05;
            for (int i = 1; i < n; i++) if (ang[i] - ang[i - 1] > M_PI - 0.05) ok = 0;
        }
        int64_t cx = rnd(10 * SUB, 54 * SUB), cy = rnd(10 * SUB, 54 * SUB);
        int64_t rx[24], ry[24];
        for (int i = 0; i < n; i++) {
            double r = check_uniform(2, 50) * SUB;
            rx[i] = cx + (int64_t)llround(r * cos(ang[i]));
            ry[i] = cy + (int64_t)llround(r * sin(ang[i]));
        }
        /* rounding may fold a nearly collinear pair over: skip such polygons */
        int folded = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            if ((rx[i] - cx) * (ry[j] - cy) - (ry[i] - cy) * (rx[j] - cx) <= 0) folded = 1;
        }
        if (folded) continue;
        used++;
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 0);
        int kc = (int)rnd(64, 1024);
        int kr[24];
        for (int i = 0; i < n; i++) kr[i] = (int)rnd(64, 1024);
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            silk_vertex_out c = vat(W, H, cx, cy, kc), a = vat(W, H, rx[i], ry[i], kr[i]),
                            b = vat(W, H, rx[j], ry[j], kr[j]);
            silk_raster_triangle(&m.t, &h, &c, &a, &b);
        }
        /* inside test in exact integers: the centre of pixel p is inside the
         * fan if it is strictly inside one of its triangles */
        for (int y = 0; y < H && !bad; y++)
            for (int x = 0; x < W; x++) {
                int64_t sx = x * SUB + SUB / 2, sy = y * SUB + SUB / 2;
                int strict_in = 0, on_edge = 0;
                for (int i = 0; i < n; i++) {
                    int j = (i + 1) % n;
                    int64_t X[3] = { cx, rx[i], rx[j] }, Y[3] = { cy, ry[i], ry[j] };
                    int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
                    if (area == 0) continue;
                    int pos = 0, zero = 0;
                    for (int e = 0; e < 3; e++) {
                        int a = (e + 1) % 3, b = (e + 2) % 3;
                        int64_t f = (X[b] - X[a]) * (sy - Y[a]) - (Y[b] - Y[a]) * (sx - X[a]);
                        if (area < 0) f = -f;
                        if (f > 0) pos++;
                        else if (f == 0) zero++;
                    }
                    if (pos == 3) strict_in = 1;
                    else if (pos + zero == 3) on_edge = 1;
                }
                int c = cnt(&m, x, y);
                int ok = c <= 1 && (!strict_in || c == 1) && (strict_in || on_edge || c == 0);
                if (!ok) {
                    CHECKF(0, "trial %d pixel (%d,%d) written %d times (inside %d, on edge %d)", trial, x,
                           y, c, strict_in, on_edge);
                    bad = 1;
                    break;
                }
            }
        img_free(&m);
    }
    CHECKF(used > 200, "only %d of 300 polygons usable", used);
}

/* ---- meshes built in the test ------------------------------------------------------- */

typedef struct tmesh {
    silk_mesh m;
    silk_vec3 pos[700];
    silk_vec3 nrm[700];
    silk_index tri[3 * 1400], tn[3 * 1400];
} tmesh;

static silk_fx fxd(double v) { return (silk_fx)llround(v * 65536.0); }

/* Icosphere: an icosahedron subdivided `level` times, points pushed to the
 * sphere with sqrt (correctly rounded, so the mesh is the same bits on every
 * machine), normals = unit positions. */
static void icosphere(tmesh *t, int level, double r, double cx, double cy, double cz)
{
    static double v[700][3];
    static int f[1400][3];
    const double p = (1 + sqrt(5.0)) / 2;
    double base[12][3] = { { -1, p, 0 }, { 1, p, 0 }, { -1, -p, 0 }, { 1, -p, 0 },
                           { 0, -1, p }, { 0, 1, p }, { 0, -1, -p }, { 0, 1, -p },
                           { p, 0, -1 }, { p, 0, 1 }, { -p, 0, -1 }, { -p, 0, 1 } };
    int faces[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
                         { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                         { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
                         { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
    int nv = 12, nf = 20;
    for (int i = 0; i < 12; i++) {
        double l = sqrt(base[i][0] * base[i][0] + base[i][1] * base[i][1] + base[i][2] * base[i][2]);
        for (int k = 0; k < 3; k++) v[i][k] = base[i][k] / l;
    }
    memcpy(f, faces, sizeof faces);
    for (int lv = 0; lv < level; lv++) {
        static int nf2[1400][3];
        int m = 0;
        for (int i = 0; i < nf; i++) {
            int mid[3];
            for (int e = 0; e < 3; e++) {
                int a = f[i][e], b = f[i][(e + 1) % 3];
                double q[3], l = 0;
                for (int k = 0; k < 3; k++) { q[k] = (v[a][k] + v[b][k]) / 2; l += q[k] * q[k]; }
                l = sqrt(l);
                int found = -1;
                for (int j = 12; j < nv && found < 0; j++)
                    if (v[j][0] == q[0] / l && v[j][1] == q[1] / l && v[j][2] == q[2] / l) found = j;
                if (found < 0) {
                    for (int k = 0; k < 3; k++) v[nv][k] = q[k] / l;
                    found = nv++;
                }
                mid[e] = found;
            }
            int tri4[4][3] = { { f[i][0], mid[0], mid[2] }, { f[i][1], mid[1], mid[0] },
                               { f[i][2], mid[2], mid[1] }, { mid[0], mid[1], mid[2] } };
            memcpy(&nf2[m], tri4, sizeof tri4);
            m += 4;
        }
        memcpy(f, nf2, sizeof(int[3]) * (size_t)m);
        nf = m;
    }
    memset(&t->m, 0, sizeof t->m);
    for (int i = 0; i < nv; i++) {
        t->pos[i] = silk_v3(fxd(cx + r * v[i][0]), fxd(cy + r * v[i][1]), fxd(cz + r * v[i][2]));
        t->nrm[i] = silk_v3(fxd(v[i][0]), fxd(v[i][1]), fxd(v[i][2]));
    }
    for (int i = 0; i < nf; i++)
        for (int k = 0; k < 3; k++) t->tri[3 * i + k] = t->tn[3 * i + k] = (silk_index)f[i][k];
    t->m.nverts = t->m.nnormals = (uint32_t)nv;
    t->m.ntris = (uint32_t)nf;
    t->m.pos = t->pos;
    t->m.normal = t->nrm;
    t->m.tri = t->tri;
    t->m.tri_normal = t->tn;
}

/* Axis-aligned box with one normal per face (24 normals). */
static void box(tmesh *t, double x0, double y0, double z0, double x1, double y1, double z1)
{
    static const int q[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                 { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
    static const double n[6][3] = { { -1, 0, 0 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0, 1, 0 }, { 0, 0, -1 }, { 0, 0, 1 } };
    memset(&t->m, 0, sizeof t->m);
    for (int i = 0; i < 8; i++)
        t->pos[i] = silk_v3(fxd(i & 4 ? x1 : x0), fxd(i & 2 ? y1 : y0), fxd(i & 1 ? z1 : z0));
    /* corner bits: 4 = x, 2 = y, 1 = z; the quads above are listed so that
     * their normals point out (checked by the closed-mesh test's 0-or-2 count
     * not depending on it, and by the lighting in the golden image) */
    for (int f = 0; f < 6; f++) {
        t->nrm[f] = silk_v3(fxd(n[f][0]), fxd(n[f][1]), fxd(n[f][2]));
        int a[6] = { q[f][0], q[f][1], q[f][2], q[f][0], q[f][2], q[f][3] };
        for (int k = 0; k < 6; k++) {
            t->tri[6 * f + k] = (silk_index)a[k];
            t->tn[6 * f + k] = (silk_index)f;
        }
    }
    t->m.nverts = 8;
    t->m.nnormals = 6;
    t->m.ntris = 12;
    t->m.pos = t->pos;
    t->m.normal = t->nrm;
    t->m.tri = t->tri;
    t->m.tri_normal = t->tn;
}

static void draw_mesh(silk_target *tg, const silk_hal *h, const silk_mesh *m)
{
    silk_geom g = { .mesh = m };
    for (uint32_t i = 0; i < m->ntris; i++) {
        silk_vertex_out o[3];
        for (int k = 0; k < 3; k++) {
            silk_vrec r = { SILK_VREC_CORNER, 3 * i + (uint32_t)k, 0, 0 };
            h->vertex(h, &g, &r, &o[k]);
        }
        silk_raster_triangle(tg, h, &o[0], &o[1], &o[2]);
    }
}

static void draw_wire(silk_target *tg, const silk_hal *h, const silk_mesh *m, uint32_t rgb)
{
    silk_geom g = { .mesh = m };
    for (uint32_t i = 0; i < m->ntris; i++) {
        silk_vertex_out o[3];
        for (int k = 0; k < 3; k++) {
            silk_vrec r = { SILK_VREC_CORNER, 3 * i + (uint32_t)k, 0, 0 };
            h->vertex(h, &g, &r, &o[k]);
        }
        for (int k = 0; k < 3; k++) silk_raster_line(tg, &o[k], &o[(k + 1) % 3], rgb);
    }
}

static silk_camera cam_default(int w, int h, int ortho)
{
    silk_camera c;
    memset(&c, 0, sizeof c);
    c.eye = silk_v3(fxd(1.2), fxd(0.9), fxd(3.2));
    c.target = silk_v3(0, 0, 0);
    c.up = silk_v3(0, SILK_FX_ONE, 0);
    c.ortho = ortho;
    c.fov_deg = SILK_FX_C(40, 1);
    c.ortho_half_height = fxd(1.25);
    c.znear = fxd(0.1);
    c.zfar = fxd(20);
    c.width = w;
    c.height = h;
    return c;
}

/* Ray through the centre of pixel (x, y) for camera c, in doubles. */
static void pixel_ray(const silk_camera *c, double x, double y, double o[3], double d[3])
{
    double e[3] = { c->eye.x / 65536.0, c->eye.y / 65536.0, c->eye.z / 65536.0 };
    double t[3] = { c->target.x / 65536.0, c->target.y / 65536.0, c->target.z / 65536.0 };
    double u[3] = { c->up.x / 65536.0, c->up.y / 65536.0, c->up.z / 65536.0 };
    double f[3], r[3], v[3], l;
    for (int k = 0; k < 3; k++) f[k] = t[k] - e[k];
    l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++) f[k] /= l;
    r[0] = f[1] * u[2] - f[2] * u[1]; r[1] = f[2] * u[0] - f[0] * u[2]; r[2] = f[0] * u[1] - f[1] * u[0];
    l = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++) r[k] /= l;
    v[0] = r[1] * f[2] - r[2] * f[1]; v[1] = r[2] * f[0] - r[0] * f[2]; v[2] = r[0] * f[1] - r[1] * f[0];
    double nx = (x + 0.5) / c->width * 2 - 1, ny = 1 - (y + 0.5) / c->height * 2;
    double aspect = (double)c->width / c->height;
    if (c->ortho) {
        double hh = c->ortho_half_height / 65536.0;
        for (int k = 0; k < 3; k++) {
            o[k] = e[k] + nx * hh * aspect * r[k] + ny * hh * v[k];
            d[k] = f[k];
        }
    } else {
        double th = tan(c->fov_deg / 65536.0 * M_PI / 360);
        for (int k = 0; k < 3; k++) {
            o[k] = e[k];
            d[k] = f[k] + nx * th * aspect * r[k] + ny * th * v[k];
        }
    }
}

/* Distance from the origin to a ray's line, the ray in front of its origin. */
static double ray_dist0(const double o[3], const double d[3])
{
    double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double t = -(o[0] * d[0] + o[1] * d[1] + o[2] * d[2]) / dd;
    if (t < 0) t = 0;
    double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}

/* Smallest distance from the origin to a face plane of a mesh. */
static double inradius(const silk_mesh *m)
{
    double best = 1e9;
    for (uint32_t i = 0; i < m->ntris; i++) {
        double p[3][3];
        for (int k = 0; k < 3; k++) {
            silk_vec3 q = m->pos[m->tri[3 * i + k]];
            p[k][0] = q.x / 65536.0; p[k][1] = q.y / 65536.0; p[k][2] = q.z / 65536.0;
        }
        double a[3], b[3], n[3];
        for (int k = 0; k < 3; k++) { a[k] = p[1][k] - p[0][k]; b[k] = p[2][k] - p[0][k]; }
        n[0] = a[1] * b[2] - a[2] * b[1]; n[1] = a[2] * b[0] - a[0] * b[2]; n[2] = a[0] * b[1] - a[1] * b[0];
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double dd = fabs(n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]) / l;
        if (dd < best) best = dd;
    }
    return best;
}

/* A closed convex mesh seen from outside: the front and the back layer each
 * cover the silhouette once, so with the depth test off every pixel is
 * written 0 or 2 times, never 1 or 3.  Pixels whose ray passes through the
 * inscribed sphere must be 2, pixels whose ray misses the circumscribed
 * sphere 0. */
TEST(closed_mesh_zero_or_two)
{
    static tmesh sph;
    icosphere(&sph, 3, 1.0, 0, 0, 0);
    double rin = inradius(&sph.m);
    for (int trial = 0; trial < 12; trial++) {
        silk_camera c = cam_default(96, 80, trial % 3 == 2);
        double a = check_uniform(0, 2 * M_PI), e = check_uniform(-1.2, 1.2), d = check_uniform(1.6, 6);
        c.eye = silk_v3(fxd(d * cos(e) * cos(a)), fxd(d * sin(e)), fxd(d * cos(e) * sin(a)));
        c.target = silk_v3(fxd(check_uniform(-0.5, 0.5)), fxd(check_uniform(-0.5, 0.5)), 0);
        silk_view v;
        silk_error err;
        CHECK(silk_view_init(&v, &c, &err) == SILK_OK);
        silk_phong ph;
        silk_phong_default(&ph, &v);
        silk_hal h;
        silk_hal_phong(&h, &ph);
        img m;
        img_new(&m, c.width, c.height, SILK_PIX_RGB565, 0, c.height, 0);
        draw_mesh(&m.t, &h, &sph.m);
        int odd = 0, two = 0, wrong = 0;
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++) {
                int k = cnt(&m, x, y);
                if (k != 0 && k != 2) odd++;
                if (k == 2) two++;
                double o[3], dir[3];
                pixel_ray(&c, x, y, o, dir);
                double dist = ray_dist0(o, dir);
                if ((dist < rin * 0.995 && k != 2) || (dist > 1.005 && k != 0)) wrong++;
            }
        CHECKF(odd == 0, "trial %d: %d pixels written neither 0 nor 2 times", trial, odd);
        CHECKF(wrong == 0, "trial %d: %d pixels disagree with the ray-cast sphere", trial, wrong);
        CHECKF(two > 100, "trial %d: only %d pixels covered", trial, two);
        img_free(&m);
    }
}

/* The mesh's triangles in order or reversed, shaded by `shade` (NULL: depth
 * only), positions from h's vertex stage. */
static void draw_mesh_pass(silk_target *tg, const silk_hal *h, const silk_hal *shade, const silk_mesh *m, int rev)
{
    silk_geom g = { .mesh = m };
    for (uint32_t j = 0; j < m->ntris; j++) {
        uint32_t i = rev ? m->ntris - 1 - j : j;
        silk_vertex_out o[3];
        for (int k = 0; k < 3; k++) {
            silk_vrec r = { SILK_VREC_CORNER, 3 * i + (uint32_t)k, 0, 0 };
            h->vertex(h, &g, &r, &o[k]);
        }
        silk_raster_triangle(tg, shade, &o[0], &o[1], &o[2]);
    }
}

/* What silk_render does: a depth-only pass, then shading in reverse order
 * where a fragment is as near as the depth buffer.  The same bytes as one
 * pass, ties included (the sphere drawn twice in two colours: the first
 * drawn keeps every pixel), and every covered pixel shaded. */
TEST(depth_pass_then_shade)
{
    static tmesh sph, bx;
    icosphere(&sph, 2, 1.0, 0, 0, 0);
    box(&bx, -0.3, -1.0, 1.05, 0.8, 0.1, 1.9);
    for (int trial = 0; trial < 8; trial++) {
        silk_camera c = cam_default(96, 80, trial % 3 == 2);
        double a = check_uniform(0, 2 * M_PI), e = check_uniform(-1.2, 1.2), d = check_uniform(1.6, 6);
        c.eye = silk_v3(fxd(d * cos(e) * cos(a)), fxd(d * sin(e)), fxd(d * cos(e) * sin(a)));
        silk_view v;
        silk_error err;
        CHECK(silk_view_init(&v, &c, &err) == SILK_OK);
        silk_phong pa, pb;
        silk_phong_default(&pa, &v);
        silk_phong_default(&pb, &v);
        pb.mat.color = silk_v3(SILK_FX_ONE, 0, 0);
        silk_hal ha, hb;
        silk_hal_phong(&ha, &pa);
        silk_hal_phong(&hb, &pb);
        const silk_mesh *ms[3] = { &sph.m, &sph.m, &bx.m };
        const silk_hal *hs[3] = { &ha, &hb, &ha };
        img one, two;
        img_new(&one, c.width, c.height, SILK_PIX_RGB888, 0, c.height, 1);
        img_new(&two, c.width, c.height, SILK_PIX_RGB888, 0, c.height, 1);
        for (int i = 0; i < 3; i++) draw_mesh_pass(&one.t, hs[i], hs[i], ms[i], 0);
        for (int i = 0; i < 3; i++) draw_mesh_pass(&two.t, hs[i], NULL, ms[i], 0);
        memset(two.writes, 0, (size_t)c.width * c.height * sizeof *two.writes);
        two.t.depth_equal = 1;
        for (int i = 2; i >= 0; i--) draw_mesh_pass(&two.t, hs[i], hs[i], ms[i], 1);
        size_t n = (size_t)c.width * c.height;
        CHECKF(memcmp(one.color, two.color, 3 * n) == 0, "trial %d: colours differ", trial);
        CHECKF(memcmp(one.depth, two.depth, 4 * n) == 0, "trial %d: depths differ", trial);
        long unshaded = 0, covered = 0;
        for (size_t p = 0; p < n; p++) {
            covered += one.depth[p] != 0;
            unshaded += one.depth[p] != 0 && two.writes[p] == 0;
        }
        CHECKF(unshaded == 0 && covered > 100, "trial %d: %ld of %ld covered pixels not shaded", trial, unshaded,
               covered);
        img_free(&one);
        img_free(&two);
    }
}

/* ---- (b) golden images ------------------------------------------------------------- */

/* The frame against tests/golden/NAME.ppm (support/golden.h). */
static void check_golden(const char *name, const silk_target *t)
{
    char msg[600];
    CHECKF(golden_compare(t, name, msg, sizeof msg), "%s", msg);
}

/* The scenes: a Phong sphere, perspective or orthographic, and a sphere
 * behind a box with the box's edges drawn as lines. */
static void scene(silk_target *t, int which)
{
    static tmesh sph, bx;
    icosphere(&sph, 2, 1.0, 0, 0, 0);
    silk_camera c = cam_default(t->width, t->height, which == 2);
    silk_view v;
    silk_error err;
    if (silk_view_init(&v, &c, &err) != SILK_OK) { CHECKF(0, "%s", err.msg); return; }
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal h;
    silk_hal_phong(&h, &ph);
    silk_target_clear(t, 0xF4F4F0);
    draw_mesh(t, &h, &sph.m);
    if (which == 2) {
        box(&bx, -0.3, -1.0, 1.05, 0.8, 0.1, 1.9);   /* in front of the sphere, not touching it */
        draw_mesh(t, &h, &bx.m);
        draw_wire(t, &h, &bx.m, 0x202020);
    }
}

TEST(golden_images)
{
    static const struct { const char *name; int w, h, which; silk_pixfmt fmt; } g[] = {
        { "sphere_persp_rgb888", 64, 64, 0, SILK_PIX_RGB888 },
        { "sphere_persp_rgb565", 64, 64, 0, SILK_PIX_RGB565 },
        { "scene_ortho_rgb888", 80, 64, 2, SILK_PIX_RGB888 },
    };
    for (size_t i = 0; i < sizeof g / sizeof g[0]; i++) {
        img m;
        img_new(&m, g[i].w, g[i].h, g[i].fmt, 0, g[i].h, 1);
        scene(&m.t, g[i].which);
        check_golden(g[i].name, &m.t);
        img_free(&m);
    }
}

/* ---- (e) bands ---------------------------------------------------------------------- */

TEST(bands_equal_full_frame)
{
    const int W = 80, H = 64;
    for (int fmt = 0; fmt < 2; fmt++) {
        img full;
        img_new(&full, W, H, (silk_pixfmt)fmt, 0, H, 1);
        scene(&full.t, 2);
        int rows[3] = { 1, 7, 16 };
        for (int r = 0; r < 3; r++) {
            int diff = 0;
            for (int y0 = 0; y0 < H; y0 += rows[r]) {
                int n = y0 + rows[r] <= H ? rows[r] : H - y0;
                img b;
                img_new(&b, W, H, (silk_pixfmt)fmt, y0, n, 1);
                scene(&b.t, 2);
                size_t bpp = silk_pixfmt_bytes((silk_pixfmt)fmt);
                if (memcmp(b.color, full.color + (size_t)y0 * W * bpp, (size_t)n * W * bpp) != 0) diff++;
                if (memcmp(b.depth, full.depth + (size_t)y0 * W, (size_t)n * W * 4) != 0) diff++;
                img_free(&b);
            }
            CHECKF(diff == 0, "format %d, bands of %d rows: %d bands differ", fmt, rows[r], diff);
        }
        img_free(&full);
    }
}

/* ---- (c) perspective-correct interpolation -------------------------------------------- */

/* A fragment stage that records the varyings it was given and returns the
 * record's index as the colour, so the test can map pixels to values. */
typedef struct capture {
    int n;
    silk_fx var[1 << 16][2];
} capture;

static uint32_t frag_capture(const silk_hal *h, const silk_fx *var)
{
    capture *c = (capture *)h->uniforms;
    if (c->n >= (1 << 16) - 1) return 0;
    int i = ++c->n;
    c->var[i][0] = var[0];
    c->var[i][1] = var[1];
    return (uint32_t)i;
}

/* Screen position exactly as the rasterizer snaps it (docs/raster.md). */
static void snap(const silk_vertex_out *v, int W, int H, double *X, double *Y)
{
    int64_t w2 = 2 * (int64_t)v->clip.w;
    int64_t nx = ((int64_t)v->clip.x + v->clip.w) * W * SUB, ny = ((int64_t)v->clip.w - v->clip.y) * H * SUB;
    *X = (double)(int64_t)floor((2.0 * (double)nx + (double)w2) / (2.0 * (double)w2));
    *Y = (double)(int64_t)floor((2.0 * (double)ny + (double)w2) / (2.0 * (double)w2));
}

TEST(perspective_correct_uv)
{
    static capture cap;
    const int W = 128, H = 96;
    double worst = 0;
    for (int trial = 0; trial < 20; trial++) {
        /* a quad on a tilted plane, seen from a random point */
        silk_camera c = cam_default(W, H, 0);
        c.eye = silk_v3(fxd(check_uniform(-1, 1)), fxd(check_uniform(0.2, 2)), fxd(check_uniform(1.5, 4)));
        c.target = silk_v3(0, 0, fxd(-1));
        silk_view v;
        CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
        double P[4][3] = { { -2, -0.5, 1 }, { 2, -0.5, 1 }, { 2, 0.3, -6 }, { -2, 0.3, -6 } };
        double UV[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        silk_vertex_out o[4];
        for (int i = 0; i < 4; i++) {
            o[i].clip = silk_view_clip(&v, silk_v3(fxd(P[i][0]), fxd(P[i][1]), fxd(P[i][2])));
            o[i].var[0] = fxd(UV[i][0]);
            o[i].var[1] = fxd(UV[i][1]);
        }
        silk_hal h;
        memset(&h, 0, sizeof h);
        h.fragment = frag_capture;
        h.nvaryings = 2;
        h.uniforms = &cap;
        cap.n = 0;
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 1);
        int tris[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
        for (int k = 0; k < 2; k++) {
            silk_target_clear(&m.t, 0);
            cap.n = 0;
            silk_raster_triangle(&m.t, &h, &o[tris[k][0]], &o[tris[k][1]], &o[tris[k][2]]);
            int all_in_front = 1;
            for (int i = 0; i < 3; i++) {
                const silk_vec4 *q = &o[tris[k][i]].clip;
                if (q->w < c.znear || labs((long)q->x) > 2L * q->w || labs((long)q->y) > 2L * q->w)
                    all_in_front = 0;
            }
            if (!all_in_front) continue;   /* the reference below assumes no clipping */
            double X[3], Y[3], q[3];
            for (int i = 0; i < 3; i++) {
                snap(&o[tris[k][i]], W, H, &X[i], &Y[i]);
                q[i] = 65536.0 / o[tris[k][i]].clip.w;
            }
            double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    uint32_t id = silk_target_get(&m.t, x, y);
                    if (!id) continue;
                    double sx = x * SUB + SUB / 2, sy = y * SUB + SUB / 2, l[3];
                    for (int i = 0; i < 3; i++) {
                        int a = (i + 1) % 3, b = (i + 2) % 3;
                        l[i] = ((X[b] - X[a]) * (sy - Y[a]) - (Y[b] - Y[a]) * (sx - X[a])) / area;
                    }
                    double den = l[0] * q[0] + l[1] * q[1] + l[2] * q[2];
                    for (int j = 0; j < 2; j++) {
                        double ref = 0;
                        for (int i = 0; i < 3; i++) ref += l[i] * q[i] * UV[tris[k][i]][j];
                        ref /= den;
                        double got = cap.var[id][j] / 65536.0, err = fabs(got - ref);
                        if (err > worst) worst = err;
                    }
                }
        }
        img_free(&m);
    }
    printf("  perspective-correct uv: worst error %.3g (%.2f ulp of Q16.16)\n", worst, worst * 65536);
    CHECKF(worst < 3.0 / 65536, "worst uv error %g", worst);
}

/* ---- (d) clipping ---------------------------------------------------------------------- */

/* The eye inside a closed box: every view ray hits the box exactly once in
 * front of the eye, so with the depth test off every pixel is written once -
 * through near-plane and guard-band clipping of faces that reach behind the
 * camera. */
TEST(eye_inside_box_every_pixel_once)
{
    static tmesh bx, sph;
    box(&bx, -2, -1.5, -2.5, 2.2, 1.7, 1.9);
    icosphere(&sph, 2, 2.5, 0.1, -0.2, 0.3);
    for (int trial = 0; trial < 400; trial++) {
        const silk_mesh *mesh = trial & 1 ? &sph.m : &bx.m;
        silk_camera c = cam_default(trial < 40 ? 72 : 40, trial < 40 ? 56 : 32, 0);
        c.eye = silk_v3(fxd(check_uniform(-1, 1)), fxd(check_uniform(-1, 1)), fxd(check_uniform(-1, 1)));
        c.target = silk_v3(fxd(check_uniform(-3, 3)), fxd(check_uniform(-3, 3)), fxd(check_uniform(-3, 3)));
        double fov = check_uniform(20, 150), tn = tan(fov * M_PI / 360), asp = (double)c.width / c.height;
        c.fov_deg = fxd(fov);
        /* the near rectangle must stay inside the walls (0.5 from the eye at least) */
        c.znear = fxd(check_uniform(0.01, 0.45) / sqrt(1 + tn * tn * (1 + asp * asp)));
        silk_view v;
        if (silk_view_init(&v, &c, NULL) != SILK_OK) continue;
        silk_phong ph;
        silk_phong_default(&ph, &v);
        silk_hal h;
        silk_hal_phong(&h, &ph);
        img m;
        img_new(&m, c.width, c.height, SILK_PIX_RGB888, 0, c.height, 0);
        draw_mesh(&m.t, &h, mesh);
        int bad = 0;
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++) bad += cnt(&m, x, y) != 1;
        CHECKF(bad == 0, "trial %d: %d pixels not written exactly once", trial, bad);
        img_free(&m);
    }
}

/* A ground plane y = -1 reaching from behind the camera to far in front: it
 * is clipped at the near plane; pixels below the horizon show it, with the
 * world position varying equal to the ray-plane intersection. */
TEST(ground_plane_through_near_plane)
{
    const int W = 64, H = 48;
    silk_camera c = cam_default(W, H, 0);
    c.eye = silk_v3(0, 0, 0);
    c.target = silk_v3(0, 0, -SILK_FX_ONE);
    c.fov_deg = SILK_FX_C(60, 1);
    c.znear = fxd(0.05);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    double P[4][3] = { { -300, -1, 50 }, { 300, -1, 50 }, { 300, -1, -300 }, { -300, -1, -300 } };
    silk_vertex_out o[4];
    for (int i = 0; i < 4; i++) {
        o[i].clip = silk_view_clip(&v, silk_v3(fxd(P[i][0]), fxd(P[i][1]), fxd(P[i][2])));
        o[i].var[0] = fxd(P[i][0]);
        o[i].var[1] = fxd(P[i][2]);
    }
    static capture cap;
    silk_hal h;
    memset(&h, 0, sizeof h);
    h.fragment = frag_capture;
    h.nvaryings = 2;
    h.uniforms = &cap;
    cap.n = 0;
    img m;
    img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 1);
    silk_raster_triangle(&m.t, &h, &o[0], &o[1], &o[2]);
    silk_raster_triangle(&m.t, &h, &o[0], &o[2], &o[3]);
    int wrong = 0;
    double worst = -1, worst_raw = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double ro[3], rd[3];
            pixel_ray(&c, x, y, ro, rd);
            int k = cnt(&m, x, y);
            /* the far edge is at z = -300: near the horizon, leave a margin */
            if (rd[1] > -0.004) { wrong += k != 0; continue; }
            if (rd[1] > -0.02) continue;
            if (k != 1) { wrong++; continue; }
            double t = -1 / rd[1], wx = t * rd[0], wz = t * rd[2];
            uint32_t id = silk_target_get(&m.t, x, y);
            /* error relative to distance, less what 1/32 pixel of vertex
             * snapping does to a plane seen this close to its horizon */
            double snap_err = (1.0 / 16) / (y + 0.5 - H / 2.0);
            double ex = fabs(cap.var[id][0] / 65536.0 - wx) / t, ez = fabs(cap.var[id][1] / 65536.0 - wz) / t;
            if (ex > worst_raw) worst_raw = ex;
            if (ez > worst_raw) worst_raw = ez;
            ex -= snap_err;
            ez -= snap_err;
            if (ex > worst) worst = ex;
            if (ez > worst) worst = ez;
        }
    CHECKF(wrong == 0, "%d pixels wrong", wrong);
    /* relative to distance: the pixel's footprint, 1/32 pixel of subpixel snapping, rounding */
    printf("  ground plane: worst position error %.3g x distance (%.3g beyond snapping)\n", worst_raw, worst);
    CHECKF(worst < 1e-3, "worst position error %g x distance", worst);
    img_free(&m);
}

/* Triangles with wild clip coordinates - behind the eye, crossing it, huge,
 * tiny, w of either sign: no crash, no hang, and one triangle never writes
 * a pixel twice (its clipped polygon's fan does not overlap itself).  For
 * triangles wholly in front, pixels clearly inside the projected triangle
 * are written and pixels clearly outside are not. */
TEST(wild_triangles)
{
    const int W = 48, H = 40;
    silk_hal h = hal_flat();
    int bad = 0, checked = 0;
    for (int trial = 0; trial < 3000 && bad < 5; trial++) {
        silk_vertex_out v[3];
        memset(v, 0, sizeof v);
        int scale = (int)rnd(0, 4);
        for (int i = 0; i < 3; i++) {
            int64_t lim = scale == 0 ? 4 * 65536 : scale == 1 ? 100 * 65536 : scale == 2 ? 30000LL * 65536 : INT32_MAX;
            v[i].clip.x = (silk_fx)rnd(-lim, lim);
            v[i].clip.y = (silk_fx)rnd(-lim, lim);
            v[i].clip.z = (silk_fx)rnd(-lim, lim);
            v[i].clip.w = (silk_fx)rnd(scale == 4 ? -lim : -lim / 4, lim);
            if (trial % 3 == 0) v[i].clip.z = v[i].clip.w - 2 * 6554;   /* perspective-like */
        }
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 0);
        silk_raster_triangle(&m.t, &h, &v[0], &v[1], &v[2]);
        int front = 1;
        double X[3], Y[3];
        for (int i = 0; i < 3; i++) {
            const silk_vec4 *c = &v[i].clip;
            if (c->w <= 0 || c->z < -c->w || c->z > c->w || labs((long)c->x) > 2L * c->w || labs((long)c->y) > 2L * c->w)
                front = 0;
            else
                snap(&v[i], W, H, &X[i], &Y[i]);
        }
        double area = front ? (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]) : 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int k = cnt(&m, x, y);
                if (k > 1) { bad++; CHECKF(0, "trial %d: pixel (%d,%d) written %d times", trial, x, y, k);}
                if (!front || area == 0) continue;
                double sx = x * SUB + SUB / 2, sy = y * SUB + SUB / 2, mn = 1e300;
                for (int i = 0; i < 3; i++) {
                    int a = (i + 1) % 3, b = (i + 2) % 3;
                    double f = ((X[b] - X[a]) * (sy - Y[a]) - (Y[b] - Y[a]) * (sx - X[a])) / area;
                    double len = hypot(X[b] - X[a], Y[b] - Y[a]);
                    f = f * fabs(area) / len;              /* signed distance in subpixels */
                    if (f < mn) mn = f;
                }
                checked++;
                if ((mn > 0.01 && k != 1) || (mn < -0.01 && k != 0)) {
                    bad++;
                    CHECKF(0, "trial %d: pixel (%d,%d) written %d times, distance inside %g", trial, x, y, k, mn);
                }
            }
        img_free(&m);
    }
    CHECKF(checked > 10000, "only %d pixels of unclipped triangles checked", checked);
}

/* A renderer that places each vertex once (silk_raster_place) learns from
 * silk_raster_reaches which triangles silk_raster_triangle would draw no
 * pixel of, and silk_raster_placed draws the others the same: random
 * triangles a pixel or two across, their corners often on pixel centres
 * and their edges often through them (the top-left rule's ties), culled or
 * not.  Below two pixels each way it asks every pixel centre: then it
 * reaches exactly the triangles that draw a pixel. */
TEST(placed_triangles_reach_what_they_draw)
{
    const int W = 32, H = 24;
    /* (the renderer's shortcuts' alone: a build without them has stubs) */
    if (!check_built(SILK_PLACE_ONCE || SILK_DRAW_DIRECT, "SILK_PLACE_ONCE")) return;
    silk_hal h = hal_flat();
    int bad = 0, small = 0, drawn = 0;
    for (int trial = 0; trial < 20000 && bad < 5; trial++) {
        silk_vertex_out v[3];
        int64_t big = (trial % 3 ? 2 : 6) * SUB, X0 = rnd(-SUB, W * SUB), Y0 = rnd(-SUB, H * SUB);
        for (int i = 0; i < 3; i++) {
            int64_t X = X0 + rnd(0, big), Y = Y0 + rnd(0, big);
            if (rnd(0, 2) == 0) X = X / SUB * SUB + SUB / 2;   /* on a centre's column */
            if (rnd(0, 2) == 0) Y = Y / SUB * SUB + SUB / 2;
            v[i] = vat(W, H, X, Y, (int)rnd(1, 3));
        }
        img a, b;
        img_new(&a, W, H, SILK_PIX_RGB888, 0, H, 1);
        img_new(&b, W, H, SILK_PIX_RGB888, 0, H, 1);
        a.t.cull_back = b.t.cull_back = (int)rnd(0, 1);
        int32_t xy[3][2];
        const int32_t *p[3] = { xy[0], xy[1], xy[2] };
        const silk_vertex_out *pv[3] = { &v[0], &v[1], &v[2] };
        int placed = 1;
        int64_t lo[2] = { INT64_MAX, INT64_MAX }, hi[2] = { INT64_MIN, INT64_MIN };
        for (int i = 0; i < 3; i++) {
            placed &= silk_raster_place(&a.t, &v[i].clip, xy[i]);
            for (int k = 0; k < 2; k++) {
                if (xy[i][k] < lo[k]) lo[k] = xy[i][k];
                if (xy[i][k] > hi[k]) hi[k] = xy[i][k];
            }
        }
        silk_raster_triangle(&a.t, &h, &v[0], &v[1], &v[2]);
        int n = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) n += cnt(&a, x, y);
        drawn += n > 0;
        if (placed) {
            int reaches = silk_raster_reaches(&b.t, p);
            if (reaches) silk_raster_placed(&b.t, &h, pv, p);
            int tiny = hi[0] - lo[0] < 2 * SUB && hi[1] - lo[1] < 2 * SUB;
            small += tiny;
            if ((n > 0 && !reaches) || (tiny && reaches && n == 0) ||
                memcmp(a.color, b.color, (size_t)W * H * 3) || memcmp(a.depth, b.depth, (size_t)W * H * 4)) {
                bad++;
                CHECKF(0, "trial %d: %d pixels drawn, reaches %d", trial, n, reaches);
            }
        }
        img_free(&a);
        img_free(&b);
    }
    CHECKF(small > 2000 && drawn > 2000, "%d tiny triangles, %d drawn", small, drawn);
}

/* A star-shaped fan cut by the far plane along a line passing near its rim
 * vertices: the cut makes new vertices that snapping can dent, which is the
 * hard case for exact coverage of clipped polygons.  No pixel twice; pixels
 * clearly inside the cut star once, clearly outside never. */
TEST(clipped_fans_exactly_once)
{
    const int W = 64, H = 64;
    silk_hal h = hal_flat();
    int bad = 0, used = 0;
    for (int trial = 0; trial < 800 && bad < 3; trial++) {
        int n = (int)rnd(3, 12);
        double ang[12];
        for (int ok = 0; !ok;) {
            for (int i = 0; i < n; i++) ang[i] = check_uniform(0, 2 * M_PI);
            for (int i = 1; i < n; i++)
                for (int j = i; j > 0 && ang[j - 1] > ang[j]; j--) { double t = ang[j]; ang[j] = ang[j - 1]; ang[j - 1] = t; }
            ok = ang[0] + 2 * M_PI - ang[n - 1] < M_PI - 0.05;
            for (int i = 1; i < n; i++) if (ang[i] - ang[i - 1] > M_PI - 0.05) ok = 0;
        }
        int64_t cx = rnd(20 * SUB, 44 * SUB), cy = rnd(20 * SUB, 44 * SUB), rx[12], ry[12];
        for (int i = 0; i < n; i++) {
            double r = check_uniform(4, 40) * SUB;
            rx[i] = cx + (int64_t)llround(r * cos(ang[i]));
            ry[i] = cy + (int64_t)llround(r * sin(ang[i]));
        }
        int folded = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            if ((rx[i] - cx) * (ry[j] - cy) - (ry[i] - cy) * (rx[j] - cx) <= 0) folded = 1;
        }
        if (folded) continue;
        /* the cut: f(X, Y) = 0 through rim vertex a and near rim vertex b */
        int a = (int)rnd(0, n - 1), b = (int)rnd(0, n - 1);
        if (a == b) b = (a + 1) % n;
        double lx = (double)(rx[b] - rx[a]), ly = (double)(ry[b] - ry[a]) + check_uniform(-0.3, 0.3);
        double len = hypot(lx, ly), nx = -ly / len, ny = lx / len;   /* unit normal: f in subpixels */
        /* 2 to 6 subpixels from vertex a, nearly parallel to edge a-b: thin
         * pieces whose new vertices snapping can dent (the ear-clipping
         * path), but no piece thinner than the snapping error, which could
         * fold over (docs/raster.md) */
        double off = check_uniform(2, 6) * (trial & 1 ? 1 : -1);
        int near = 0;
        for (int i = 0; i <= n; i++) {
            double px = i < n ? (double)rx[i] : (double)cx, py = i < n ? (double)ry[i] : (double)cy;
            if (fabs((px - rx[a]) * nx + (py - ry[a]) * ny + off) < 2) near = 1;
        }
        if (near) continue;
        used++;
        int k = (int)rnd(64, 512);
        silk_vertex_out vc = vat(W, H, cx, cy, k), vr[12];
        double fscale = 1.0 / 2048;               /* z - w = f * fscale * w, within (-w, w): no near cut */
#define FOF(X, Y) (((X) - rx[a]) * nx + ((Y) - ry[a]) * ny + off)
        vc.clip.z = vc.clip.w + (silk_fx)llround(FOF((double)cx, (double)cy) * fscale * vc.clip.w);
        for (int i = 0; i < n; i++) {
            vr[i] = vat(W, H, rx[i], ry[i], k);
            vr[i].clip.z = vr[i].clip.w + (silk_fx)llround(FOF((double)rx[i], (double)ry[i]) * fscale * vr[i].clip.w);
        }
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 0);
        for (int i = 0; i < n; i++) silk_raster_triangle(&m.t, &h, &vc, &vr[i], &vr[(i + 1) % n]);
        for (int y = 0; y < H && bad < 3; y++)
            for (int x = 0; x < W; x++) {
                double sx = x * SUB + SUB / 2, sy = y * SUB + SUB / 2;
                double f = FOF(sx, sy), inside = -1e300;   /* signed distance into the star */
                for (int i = 0; i < n; i++) {
                    int j = (i + 1) % n;
                    double X[3] = { (double)cx, (double)rx[i], (double)rx[j] }, Y[3] = { (double)cy, (double)ry[i], (double)ry[j] };
                    double mn = 1e300;
                    for (int e = 0; e < 3; e++) {
                        int p = (e + 1) % 3, q = (e + 2) % 3;
                        double d = ((X[q] - X[p]) * (sy - Y[p]) - (Y[q] - Y[p]) * (sx - X[p])) / hypot(X[q] - X[p], Y[q] - Y[p]);
                        if (d < mn) mn = d;
                    }
                    if (mn > inside) inside = mn;
                }
                int c = cnt(&m, x, y);
                /* new vertices snap by up to half a subpixel */
                int want = (inside > 0.75 && f < -1) ? 1 : (inside < -0.75 || f > 1) ? 0 : -1;
                if (c > 1 || (want >= 0 && c != want)) {
                    CHECKF(0, "trial %d pixel (%d,%d) written %d times, want %d (inside %g, f %g)", trial, x, y, c,
                           want, inside, f);
                    bad++;
                }
            }
#undef FOF
        img_free(&m);
    }
    CHECKF(used > 200, "only %d of 800 fans usable", used);
}

/* Zero-area triangles, a triangle behind the eye, coincident vertices, and
 * unusable targets draw nothing and do not crash. */
TEST(degenerate_input)
{
    const int W = 16, H = 16;
    silk_hal h = hal_flat();
    img m;
    img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 1);
    silk_vertex_out a = vat(W, H, 10, 10, 64), b = vat(W, H, 200, 100, 64), c = vat(W, H, 390, 190, 64);
    silk_raster_triangle(&m.t, &h, &a, &b, &c);            /* collinear */
    silk_raster_triangle(&m.t, &h, &a, &a, &b);            /* repeated vertex */
    silk_raster_triangle(&m.t, &h, &a, &a, &a);
    silk_vertex_out d = a, e = b, f = vat(W, H, 10, 200, 64);
    d.clip.w = e.clip.w = f.clip.w = -SILK_FX_ONE;           /* behind the eye */
    d.clip.z = e.clip.z = f.clip.z = -2 * SILK_FX_ONE;
    silk_raster_triangle(&m.t, &h, &d, &e, &f);
    memset(&d, 0, sizeof d);                                /* all zero */
    silk_raster_triangle(&m.t, &h, &d, &d, &d);
    silk_raster_line(&m.t, &d, &d, 0xFF0000);
    int any = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) any += cnt(&m, x, y);
    CHECKF(any == 0, "%d pixels written by degenerate triangles", any);
    silk_target bad = m.t;
    bad.width = 0;
    silk_raster_triangle(&bad, &h, &a, &b, &f);
    bad = m.t;
    bad.rows = 0;
    silk_raster_triangle(&bad, &h, &a, &b, &f);
    bad = m.t;
    bad.width = SILK_MAX_DIM + 1;
    silk_raster_triangle(&bad, &h, &a, &b, &f);
    silk_raster_triangle(&m.t, NULL, &a, &b, &f);           /* no HAL: depth only */
    int drawn = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) drawn += cnt(&m, x, y);
    CHECKF(drawn > 0, "a depth-only triangle wrote nothing");
    CHECK(silk_target_get(&m.t, 1, 1) == 0);                 /* and no colour */
    img_free(&m);
}

/* The nearer surface wins whatever the drawing order; equal depth keeps the
 * first (the test is strict). */
TEST(depth_order)
{
    const int W = 32, H = 32;
    silk_hal h = hal_flat();
    for (int order = 0; order < 2; order++) {
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 1);
        silk_vertex_out t[2][3];
        for (int k = 0; k < 2; k++) {
            int kk = k ? 200 : 100;                         /* w: the second is farther */
            t[k][0] = vat(W, H, 0, 0, kk);
            t[k][1] = vat(W, H, 600, 0, kk);
            t[k][2] = vat(W, H, 0, 600, kk);
            for (int i = 0; i < 3; i++) t[k][i].clip.z = t[k][i].clip.w - 6554;
        }
        silk_raster_triangle(&m.t, &h, &t[order][0], &t[order][1], &t[order][2]);
        uint32_t z1 = m.depth[5 * W + 5];
        silk_raster_triangle(&m.t, &h, &t[!order][0], &t[!order][1], &t[!order][2]);
        uint32_t z2 = m.depth[5 * W + 5];
        CHECKF(order == 0 ? z2 == z1 && cnt(&m, 5, 5) == 1 : z2 > z1 && cnt(&m, 5, 5) == 2,
               "order %d: depths %u %u, writes %d", order, z1, z2, cnt(&m, 5, 5));
        /* the same triangle again: equal depth, rejected */
        silk_raster_triangle(&m.t, &h, &t[0][0], &t[0][1], &t[0][2]);
        CHECK(cnt(&m, 5, 5) == (order == 0 ? 1 : 2));
        img_free(&m);
    }
}

/* ---- (g) lines ------------------------------------------------------------------------ */

static int count_all(const img *m)
{
    int n = 0;
    for (int y = m->t.y0; y < m->t.y0 + m->t.rows; y++)
        for (int x = 0; x < m->t.width; x++) n += cnt(m, x, y);
    return n;
}

TEST(lines)
{
    const int W = 32, H = 32;
    img m;
    img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 0);
    /* horizontal from the centre of pixel (2,3) to the centre of (10,3): 9 pixels */
    silk_vertex_out a = vat(W, H, 2 * SUB + 8, 3 * SUB + 8, 64), b = vat(W, H, 10 * SUB + 8, 3 * SUB + 8, 90);
    silk_raster_line(&m.t, &a, &b, 0xFF0000);
    int ok = count_all(&m) == 9;
    for (int x = 2; x <= 10; x++) ok &= cnt(&m, x, 3) == 1 && silk_target_get(&m.t, x, 3) == 0xFF0000;
    CHECKF(ok, "horizontal line: %d pixels", count_all(&m));
    /* vertical and diagonal: one pixel per step of the major axis */
    silk_target_clear(&m.t, 0);
    silk_vertex_out c = vat(W, H, 5 * SUB + 8, 1 * SUB + 8, 64), d = vat(W, H, 5 * SUB + 8, 20 * SUB + 8, 64);
    silk_raster_line(&m.t, &c, &d, 0xFFFFFF);
    ok = count_all(&m) == 20;
    for (int y = 1; y <= 20; y++) ok &= cnt(&m, 5, y) == 1;
    CHECKF(ok, "vertical line: %d pixels", count_all(&m));
    silk_target_clear(&m.t, 0);
    silk_vertex_out e = vat(W, H, 8, 8, 64), f = vat(W, H, 30 * SUB + 8, 30 * SUB + 8, 64);
    silk_raster_line(&m.t, &e, &f, 0xFFFFFF);
    ok = count_all(&m) == 31;
    for (int i = 0; i <= 30; i++) ok &= cnt(&m, i, i) == 1;
    CHECKF(ok, "diagonal line: %d pixels", count_all(&m));
    /* random lines: one pixel per major-axis column, the same set both ways,
     * each pixel within half a pixel of the true line */
    int bad = 0;
    for (int trial = 0; trial < 500; trial++) {
        int64_t x0 = rnd(-100, 40 * SUB), y0 = rnd(-100, 40 * SUB), x1 = rnd(-100, 40 * SUB), y1 = rnd(-100, 40 * SUB);
        silk_vertex_out p = vat(W, H, x0, y0, (int)rnd(64, 500)), q = vat(W, H, x1, y1, (int)rnd(64, 500));
        img m1, m2;
        img_new(&m1, W, H, SILK_PIX_RGB565, 0, H, 0);
        img_new(&m2, W, H, SILK_PIX_RGB565, 0, H, 0);
        silk_raster_line(&m1.t, &p, &q, 0xFFFFFF);
        silk_raster_line(&m2.t, &q, &p, 0xFFFFFF);
        if (memcmp(m1.writes, m2.writes, (size_t)W * H * 2) != 0) bad++;
        int xmaj = llabs(x1 - x0) >= llabs(y1 - y0);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int k = cnt(&m1, x, y);
                if (k > 1) bad++;
                if (!k) continue;
                double cx = x * SUB + 8, cy = y * SUB + 8;
                /* distance along the minor axis from the pixel centre to the line */
                double dist = xmaj ? fabs(y0 + (cx - x0) * (double)(y1 - y0) / (double)(x1 - x0) - cy)
                                   : fabs(x0 + (cy - y0) * (double)(x1 - x0) / (double)(y1 - y0) - cx);
                if (dist > SUB / 2 + 1e-9) bad++;
            }
        img_free(&m1);
        img_free(&m2);
    }
    CHECKF(bad == 0, "%d problems in random lines", bad);
    img_free(&m);
}

/* Lines against surfaces: a line on a surface shows (the bias), a line
 * clearly behind it does not, a line in front does. */
TEST(line_depth)
{
    const int W = 32, H = 32;
    silk_camera c = cam_default(W, H, 0);
    c.eye = silk_v3(0, 0, fxd(3));
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_hal h = hal_flat();
    for (int ortho = 0; ortho < 2; ortho++) {
        c.ortho = ortho;
        CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
        img m;
        img_new(&m, W, H, SILK_PIX_RGB888, 0, H, 1);
        /* a slanted quad through the origin */
        double P[4][3] = { { -2, -2, -0.8 }, { 2, -2, 0.8 }, { 2, 2, 0.8 }, { -2, 2, -0.8 } };
        silk_vertex_out q[4];
        for (int i = 0; i < 4; i++) q[i].clip = silk_view_clip(&v, silk_v3(fxd(P[i][0]), fxd(P[i][1]), fxd(P[i][2])));
        silk_raster_triangle(&m.t, &h, &q[0], &q[1], &q[2]);
        silk_raster_triangle(&m.t, &h, &q[0], &q[2], &q[3]);
        double zs[3] = { 0, -0.3, 0.3 };     /* on, behind, in front (along z) */
        for (int k = 0; k < 3; k++) {
            silk_vertex_out a, b;
            /* a diagonal line on the plane z = 0.4 x (+ offset) */
            a.clip = silk_view_clip(&v, silk_v3(fxd(-0.9), fxd(-0.7), fxd(-0.36 + zs[k])));
            b.clip = silk_view_clip(&v, silk_v3(fxd(0.9), fxd(0.6), fxd(0.36 + zs[k])));
            uint32_t col = 0x10 + (uint32_t)k;
            silk_raster_line(&m.t, &a, &b, col);
            int shown = 0, total = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) shown += silk_target_get(&m.t, x, y) == col;
            silk_vec2 pa, pb;
            silk_view_project(&v, silk_v3(fxd(-0.9), fxd(-0.7), fxd(-0.36 + zs[k])), &pa);
            silk_view_project(&v, silk_v3(fxd(0.9), fxd(0.6), fxd(0.36 + zs[k])), &pb);
            total = (int)(fabs((pb.x - pa.x) / 65536.0) > fabs((pb.y - pa.y) / 65536.0) ? fabs((pb.x - pa.x) / 65536.0)
                                                                                   : fabs((pb.y - pa.y) / 65536.0));
            if (k == 1) CHECKF(shown == 0, "ortho %d: line behind the surface shows %d pixels", ortho, shown);
            else CHECKF(shown >= total - 1 && total > 5, "ortho %d case %d: line shows %d of ~%d pixels", ortho, k, shown, total);
        }
        img_free(&m);
    }
}

/* ---- (h) frame sizes ---------------------------------------------------------------------- */

static uint32_t frag_normal_rgb(const silk_hal *h, const silk_fx *var)
{
    (void)h;
    uint32_t r = 0;
    for (int k = 3; k < 6; k++) {
        silk_fx c = silk_fx_clamp(var[k] / 2 + SILK_FX_HALF, 0, SILK_FX_ONE - 1);
        r = r << 8 | (uint32_t)(c >> 8);
    }
    return r;
}

/* From 1x1 to 2048x2048, and a one-row band of the largest frame: the
 * sphere covers about the area it should, nothing overflows. */
TEST(frame_sizes)
{
    static tmesh sph;
    icosphere(&sph, 2, 1.0, 0, 0, 0);
    static const int sz[][2] = { { 1, 1 }, { 1, 9 }, { 9, 1 }, { 3, 5 }, { 17, 13 }, { 640, 480 }, { 2048, 2048 } };
    for (size_t i = 0; i < sizeof sz / sizeof sz[0]; i++) {
        int W = sz[i][0], H = sz[i][1];
        silk_camera c = cam_default(W, H, 1);
        c.eye = silk_v3(0, 0, fxd(4));
        c.ortho_half_height = fxd(1.25);
        silk_view v;
        CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
        silk_phong ph;
        silk_phong_default(&ph, &v);
        silk_hal h;
        silk_hal_phong(&h, &ph);
        h.fragment = frag_normal_rgb;                    /* cheap: the big frame is 4M pixels */
        img m;
        img_new(&m, W, H, SILK_PIX_RGB565, 0, H, 1);
        draw_mesh(&m.t, &h, &sph.m);
        long n = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) n += cnt(&m, x, y) > 0;
        /* ortho: the disc of radius H/2.5 pixels (inscribed polyhedron: a bit less) */
        double r = H / 2.5, want = M_PI * r * r;
        if (W < H) want = -1;                           /* cut by the narrow frame: only no crash */
        if (want > 200) CHECKF(n > 0.93 * want && n < 1.001 * want, "%dx%d: %ld pixels, disc %.0f", W, H, n, want);
        if (W == 1 && H == 1) CHECKF(n == 1, "1x1: centre pixel not drawn (%ld)", n);
        img_free(&m);
    }
    /* a one-row band through the middle of an 8192 x 8192 frame */
    int W = SILK_MAX_DIM, H = SILK_MAX_DIM;
    silk_camera c = cam_default(W, H, 0);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal h;
    silk_hal_phong(&h, &ph);
    h.fragment = frag_normal_rgb;
    img m;
    img_new(&m, W, H, SILK_PIX_RGB888, H / 2, 1, 1);
    draw_mesh(&m.t, &h, &sph.m);
    int first = -1, last = -1;
    for (int x = 0; x < W; x++)
        if (cnt(&m, x, H / 2)) { if (first < 0) first = x; last = x; }
    /* the sphere's row through its centre, about 2 * ppu / sqrt(d^2 - 1) pixels wide */
    double d = sqrt(1.2 * 1.2 + 0.9 * 0.9 + 3.2 * 3.2), width = 2 * (v.pixels_per_unit / 65536.0) / sqrt(d * d - 1);
    CHECKF(first >= 0 && fabs((last - first) - width) < 0.05 * width, "8192 band: span %d..%d, want ~%.0f", first,
           last, width);
    img_free(&m);
}

/* ---- pixel formats and targets ------------------------------------------------------- */

TEST(pixel_formats)
{
    img m;
    img_new(&m, 4, 6, SILK_PIX_RGB565, 2, 3, 1);
    CHECK(m.t.stride == 8 && silk_pixfmt_bytes(SILK_PIX_RGB565) == 2 && silk_pixfmt_bytes(SILK_PIX_RGB888) == 3);
    /* every RGB565 value survives get -> put, stored little-endian */
    int bad = 0;
    for (uint32_t v = 0; v < 65536; v++) {
        m.color[0] = (uint8_t)v;
        m.color[1] = (uint8_t)(v >> 8);
        uint32_t c = silk_target_get(&m.t, 0, 2);
        silk_target_put(&m.t, 1, 2, c);
        if ((uint32_t)(m.color[2] | m.color[3] << 8) != v) bad++;
    }
    CHECKF(bad == 0, "%d RGB565 values do not round-trip", bad);
    /* 8-bit channels go to the nearest 5/6-bit level */
    for (int trial = 0; trial < 20000; trial++) {
        uint32_t c = (uint32_t)(check_rand64() & 0xFFFFFF);
        silk_target_put(&m.t, 3, 4, c);
        uint32_t g = silk_target_get(&m.t, 3, 4);
        for (int sh = 0; sh < 24; sh += 8) {
            int bits = sh == 8 ? 6 : 5, a = (int)(c >> sh & 255), b = (int)(g >> sh & 255);
            double step = 255.0 / ((1 << bits) - 1);
            if (abs(a - b) > step / 2 + 1) bad++;
        }
    }
    CHECKF(bad == 0, "%d channels off by more than half a step", bad);
    /* outside the band: ignored, reads 0 */
    silk_target_clear(&m.t, 0x123456);
    silk_target_put(&m.t, 0, 1, 0xFFFFFF);
    silk_target_put(&m.t, 0, 5, 0xFFFFFF);
    silk_target_put(&m.t, -1, 3, 0xFFFFFF);
    silk_target_put(&m.t, 4, 3, 0xFFFFFF);
    CHECK(silk_target_get(&m.t, 0, 1) == 0 && silk_target_get(&m.t, 0, 5) == 0);
    uint32_t want = silk_target_get(&m.t, 0, 2);
    for (int y = 2; y < 5; y++)
        for (int x = 0; x < 4; x++) CHECK(silk_target_get(&m.t, x, y) == want && m.depth[(y - 2) * 4 + x] == 0);
    img_free(&m);
    img_new(&m, 5, 2, SILK_PIX_RGB888, 0, 2, 0);
    silk_target_put(&m.t, 4, 1, 0xA1B2C3);
    CHECK(m.color[15 + 12] == 0xA1 && m.color[15 + 13] == 0xB2 && m.color[15 + 14] == 0xC3);
    CHECK(silk_target_get(&m.t, 4, 1) == 0xA1B2C3);
    img_free(&m);
}

int main(void)
{
    RUN(fan_rectangle_exactly_once);
    RUN(fan_star_random);
    RUN(closed_mesh_zero_or_two);
    RUN(golden_images);
    RUN(bands_equal_full_frame);
    RUN(perspective_correct_uv);
    RUN(eye_inside_box_every_pixel_once);
    RUN(ground_plane_through_near_plane);
    RUN(wild_triangles);
    RUN(placed_triangles_reach_what_they_draw);
    RUN(clipped_fans_exactly_once);
    RUN(degenerate_input);
    RUN(depth_order);
    RUN(lines);
    RUN(line_depth);
    RUN(depth_pass_then_shade);
    RUN(frame_sizes);
    RUN(pixel_formats);
    golden_summary();
    return check_done();
}
