/*
 * raster.c - render targets and the scanline rasterizer: homogeneous
 * clipping, subpixel snapping, edge walking with the top-left fill rule,
 * perspective-correct varyings, a 32-bit depth buffer, and depth-tested
 * lines.
 *
 * Not a paper equation: this is the fixed-function part of the OpenGL
 * pipeline the paper renders with.  docs/raster.md states every convention
 * (clip volume, guard band, subpixel grid, fill rule, depth format,
 * interpolation) and its error bounds.
 *
 * Exactness is the design rule.  Edges are walked with exact rational
 * (quotient + remainder) steppers, depth is an exact rational plane, and the
 * perspective weights come from integer edge functions, so every pixel's
 * coverage and values are a function of that pixel and the triangle alone:
 * shared edges have no gaps and no pixel drawn twice, and rendering in bands gives
 * the same bytes as rendering the whole frame.
 */
#include <string.h>
#include "silk/raster.h"
#include "silk/hal.h"
#include "frame.h"
#include "raster_place.h"
#include "phong_parts.h"
#include "compiler.h"

#define SUB_BITS 4                  /* subpixel grid: 1/16 pixel */
#define SUB      (1 << SUB_BITS)
_Static_assert(SUB == SILK_RASTER_SUB, "frame.h names the subpixel grid");
#define GUARD    2                  /* clip to |x|, |y| <= GUARD * w */
#define QN_BITS  24                 /* precision of the per-triangle 1/w weights */
#define W_MIN    16                 /* w below 2^-12 counts as behind the eye */
#define NPLANES  7
#define MAXPOLY  (3 + NPLANES)
#define DEPTH_MAX 0xFFFFFFFFu

/* ---- small integer helpers -------------------------------------------------- */


/* floor(n / d) for n < d 2^32 (a 32-bit quotient).  Where the processor
 * has no 64-bit divide (a 32-bit target: Cortex-M), silk_udiv64_32's two
 * 32-bit divisions instead of libgcc's 64-bit routine, a few hundred
 * instructions; on a 64-bit host the divide instruction. */
static uint32_t udiv_q32(uint64_t n, uint32_t d, uint32_t *rem)
{
    if (SILK_CPU32) return silk_udiv64_32(n, d, rem);
    *rem = (uint32_t)(n % d);
    return (uint32_t)(n / d);
}

/* floor(n / d), d > 0.  Most operands here fit in 32 bits (subpixel
 * coordinates, areas of small triangles): those take a 32-bit division, a
 * single instruction on a Cortex-M3 and a short library routine on a
 * Cortex-M0, where libgcc's 64-bit one costs several hundred instructions.
 * Most of the rest (depths, edges of large triangles) have a 32-bit divisor
 * and quotient: udiv_q32, on a 32-bit processor (a 64-bit host divides as
 * fast).  The quotient is the same either way. */
static int64_t floor_div(int64_t n, int64_t d)    /* d > 0 */
{
    /* a 64-bit host divides in one instruction either way: no test of
     * the operands' size, and the floor without a branch (both go either
     * way from one call to the next) */
    if (!SILK_CPU32) return n / d - ((n % d != 0) & (n < 0));
    if (d <= INT32_MAX && n >= -INT32_MAX && n <= INT32_MAX) {
        int32_t n32 = (int32_t)n, d32 = (int32_t)d, q32 = n32 / d32;
        return (n32 % d32 != 0 && n32 < 0) ? q32 - 1 : q32;
    }
    uint64_t un = silk_abs64(n);
    if (d <= (int64_t)UINT32_MAX && un >> 32 < (uint64_t)d) {
        uint32_t r, q = udiv_q32(un, (uint32_t)d, &r);
        return n < 0 ? -(int64_t)q - (r != 0) : (int64_t)q;
    }
    int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

/* floor(2^61 / tt), tt > 0: the reciprocal of the perspective weights. */
static int64_t recip61(int64_t tt)
{
    uint32_t r;
    if (tt >= ((int64_t)1 << 29) && tt <= (int64_t)UINT32_MAX) return udiv_q32((uint64_t)1 << 61, (uint32_t)tt, &r);
    return ((int64_t)1 << 61) / tt;
}

static int64_t ceil_div(int64_t n, int64_t d)     /* d > 0 */
{
    return -floor_div(-n, d);
}

/* An exact rational sequence q + r/den, 0 <= r < den, advanced by a fixed
 * rational step: the Bresenham idea, used for edges, lines and depth. */
typedef struct rstep { int64_t q, r, den, sq, sr; } rstep;

static void rstep_init(rstep *s, int64_t num, int64_t den, int64_t step)
{
    s->den = den;
    s->q = floor_div(num, den);
    s->r = num - s->q * den;
    s->sq = floor_div(step, den);
    s->sr = step - s->sq * den;
}

static inline void rstep_next(rstep *s)
{
    s->q += s->sq;
    s->r += s->sr;
    if (SILK_CPU32) {
        if (s->r >= s->den) { s->r -= s->den; s->q++; }
        return;
    }
    /* without a branch on a host: the carry comes pixel by pixel either
     * way, and a mispredicted branch costs more than the arithmetic */
    int64_t carry = s->r >= s->den;
    s->r -= s->den & -carry;
    s->q += carry;
}

/* ---- targets ------------------------------------------------------------------ */

size_t silk_pixfmt_bytes(silk_pixfmt f) { return f == SILK_PIX_RGB565 ? 2 : 3; }

void silk_target_init(silk_target *t, int width, int height, int y0, int rows, silk_pixfmt fmt,
                      uint8_t *color, uint32_t *depth)
{
    memset(t, 0, sizeof *t);
    t->width = width;
    t->height = height;
    t->y0 = y0;
    t->rows = rows;
    t->fmt = fmt;
    t->color = color;
    t->depth = depth;
    t->stride = (size_t)(width > 0 ? width : 0) * silk_pixfmt_bytes(fmt);
}

/* Rows [*lo, *hi) of the frame that the band holds; 0 if the target is unusable. */
static int band_rows(const silk_target *t, int *lo, int *hi)
{
    if (t->width < 1 || t->height < 1 || t->width > SILK_MAX_DIM || t->height > SILK_MAX_DIM ||
        t->rows < 1)
        return 0;
    int64_t end = (int64_t)t->y0 + t->rows;
    *lo = t->y0 > 0 ? t->y0 : 0;
    *hi = end < t->height ? (int)end : t->height;
    return *lo < *hi;
}

/* x / 255 for x < 65535, without a division (stores run once per pixel) */
static uint32_t div255(uint32_t x) { return (x + 1 + (x >> 8)) >> 8; }

/* Per shaded pixel on a 64-bit host: inline there (a call costs as much as
 * the work); a 32-bit processor keeps one copy of each (SILK_HOST_INLINE). */
static SILK_HOST_INLINE void store(const silk_target *t, uint8_t *p, uint32_t rgb)
{
    uint32_t r = (rgb >> 16) & 255, g = (rgb >> 8) & 255, b = rgb & 255;
    if (t->fmt == SILK_PIX_RGB565) {
        /* rounded to 5/6/5 bits; load()'s bit replication is its inverse */
        uint32_t v = div255(r * 31 + 127) << 11 | div255(g * 63 + 127) << 5 | div255(b * 31 + 127);
        p[0] = (uint8_t)v;
        p[1] = (uint8_t)(v >> 8);
    } else {
        p[0] = (uint8_t)r;
        p[1] = (uint8_t)g;
        p[2] = (uint8_t)b;
    }
}

static uint32_t load(const silk_target *t, const uint8_t *p)
{
    if (t->fmt == SILK_PIX_RGB565) {
        uint32_t v = (uint32_t)p[0] | (uint32_t)p[1] << 8;
        /* widened by bit replication, which the rounding in store() inverts */
        uint32_t r5 = v >> 11, g6 = (v >> 5) & 63, b5 = v & 31;
        uint32_t r = r5 << 3 | r5 >> 2, g = g6 << 2 | g6 >> 4, b = b5 << 3 | b5 >> 2;
        return r << 16 | g << 8 | b;
    }
    return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

void silk_target_clear(silk_target *t, uint32_t rgb)
{
    int lo, hi;
    if (!band_rows(t, &lo, &hi)) return;
    size_t bpp = silk_pixfmt_bytes(t->fmt), wbytes = (size_t)t->width * bpp;
    uint8_t *first = t->color ? t->color + (size_t)(lo - t->y0) * t->stride : NULL;
    if (first) {
        /* one pixel, then the row by doubling copies, then row copies */
        store(t, first, rgb);
        for (size_t n = bpp; n < wbytes; n *= 2) memcpy(first + n, first, n < wbytes - n ? n : wbytes - n);
    }
    for (int y = lo; y < hi; y++) {
        size_t row = (size_t)(y - t->y0);
        if (first && y > lo) memcpy(t->color + row * t->stride, first, wbytes);
        if (t->depth) memset(t->depth + row * (size_t)t->width, 0, (size_t)t->width * sizeof(uint32_t));
        if (t->writes) memset(t->writes + row * (size_t)t->width, 0, (size_t)t->width * sizeof(uint16_t));
    }
}

void silk_target_put(silk_target *t, int x, int y, uint32_t rgb)
{
    int lo, hi;
    if (!t->color || !band_rows(t, &lo, &hi) || x < 0 || x >= t->width || y < lo || y >= hi) return;
    store(t, t->color + (size_t)(y - t->y0) * t->stride + (size_t)x * silk_pixfmt_bytes(t->fmt), rgb);
}

uint32_t silk_target_get(const silk_target *t, int x, int y)
{
    int lo, hi;
    if (!t->color || !band_rows(t, &lo, &hi) || x < 0 || x >= t->width || y < lo || y >= hi) return 0;
    return load(t, t->color + (size_t)(y - t->y0) * t->stride + (size_t)x * silk_pixfmt_bytes(t->fmt));
}

/* ---- clipping in homogeneous space ------------------------------------------ */

/* Signed distance to clip plane i; inside when >= 0.  Planes: near z >= -w,
 * far z <= w, the guard band |x|, |y| <= GUARD w, and w >= W_MIN (only a
 * user vertex stage can reach it: near already implies w > 0). */
static int64_t plane_dist(int i, const silk_vec4 *c)
{
    int64_t gw = GUARD * (int64_t)c->w;
    switch (i) {
    case 0: return (int64_t)c->z + c->w;
    case 1: return (int64_t)c->w - c->z;
    case 2: return gw + c->x;
    case 3: return gw - c->x;
    case 4: return gw + c->y;
    case 5: return gw - c->y;
    default: return (int64_t)c->w - W_MIN;
    }
}

/* The planes c is outside of, plane i as bit i: plane_dist's tests,
 * written out (every triangle of every band asks for three). */
static unsigned outcode(const silk_vec4 *c)
{
    int64_t x = c->x, y = c->y, z = c->z, w = c->w, gw = GUARD * w;
    return (unsigned)(z + w < 0) | (unsigned)(w - z < 0) << 1 | (unsigned)(gw + x < 0) << 2 |
           (unsigned)(gw - x < 0) << 3 | (unsigned)(gw + y < 0) << 4 | (unsigned)(gw - y < 0) << 5 |
           (unsigned)(w < W_MIN) << 6;
}

/* Whether c is inside every plane (outcode 0), in four tests: most corners
 * are, and those need no more (where the usual cases are written out,
 * SILK_FAST_CASES; a board keeps the code bytes instead). */
static int inside(const silk_vec4 *c)
{
    int64_t w = c->w, gw = GUARD * w;
    return w >= W_MIN && (uint64_t)(c->z + w) <= (uint64_t)(2 * w) && (uint64_t)(c->x + gw) <= (uint64_t)(2 * gw) &&
           (uint64_t)(c->y + gw) <= (uint64_t)(2 * gw);
}

static silk_fx lerp30(silk_fx a, silk_fx b, int64_t t30)
{
    /* |b - a| < 2^32, t30 < 2^30: the product stays below 2^62 */
    return silk_fx_sat((int64_t)a + silk_shr_round64(((int64_t)b - a) * t30, 30));
}

/* The point where segment in->out crosses a plane, din >= 0 > dout.  Always
 * computed from the inside end, so the two triangles of a shared edge, which
 * walk it in opposite directions, get the same bits. */
static void intersect(const silk_vertex_out *in, const silk_vertex_out *out, int64_t din,
                      int64_t dout, int nvar, silk_vertex_out *r)
{
    int64_t den = din - dout;
    while (den >= ((int64_t)1 << 32)) { den >>= 1; din >>= 1; }
    int64_t t = (din << 30) / den;
    r->clip.x = lerp30(in->clip.x, out->clip.x, t);
    r->clip.y = lerp30(in->clip.y, out->clip.y, t);
    r->clip.z = lerp30(in->clip.z, out->clip.z, t);
    r->clip.w = lerp30(in->clip.w, out->clip.w, t);
    for (int k = 0; k < nvar; k++) r->var[k] = lerp30(in->var[k], out->var[k], t);
}

/* Sutherland-Hodgman against one plane; returns the new vertex count. */
static int clip_poly(const silk_vertex_out *src, int n, silk_vertex_out *dst, int plane, int nvar)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const silk_vertex_out *a = &src[i], *b = &src[(i + 1) % n];
        int64_t da = plane_dist(plane, &a->clip), db = plane_dist(plane, &b->clip);
        if (da >= 0) dst[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            if (da >= 0) intersect(a, b, da, db, nvar, &dst[m++]);
            else intersect(b, a, db, da, nvar, &dst[m++]);
        }
    }
    return m;
}

/* ---- screen space -------------------------------------------------------------- */

/* A vertex after the perspective division: subpixel position, depth, w. */
typedef struct svert {
    int64_t x, y;          /* subpixels, pixel (0,0) covers [0, SUB)^2 */
    int64_t d;             /* depth in [0, 2^32): (w - z) / w in Q1.31, larger = nearer */
    silk_fx w;
    const silk_fx *var;
} svert;

/* n / d rounded to nearest (halves up), d > 0 */
static int64_t round_div(int64_t n, int64_t d)
{
    if (SILK_CPU32) return floor_div(2 * n + d, 2 * d);
    /* a 64-bit host divides in one instruction: floor_div's narrowing is
     * for 32-bit processors (every corner of every triangle comes here) */
    int64_t m = 2 * n + d, q = m / (2 * d);
    return q - (m % (2 * d) != 0 && m < 0);
}

/* y' = (1 - y/w) H/2 in subpixels (w > 0); below 2^50 within the guard
 * band, below 2^55 for any clip point. */
static int64_t screen_y(const silk_vec4 *c, int height)
{
    return round_div(((int64_t)c->w - c->y) * height * SUB, 2 * (int64_t)c->w);
}

/* x' = (x/w + 1) W/2 in subpixels: with the guard band the products stay
 * below 2^50 */
static int64_t screen_x(const silk_vec4 *c, int width)
{
    return round_div(((int64_t)c->x + c->w) * width * SUB, 2 * (int64_t)c->w);
}

int64_t silk_raster_row(const silk_vec4 *c, int height) { return floor_div(screen_y(c, height), SUB); }

static void project(const silk_target *t, const silk_vertex_out *v, svert *s);

void silk_raster_point(const silk_target *t, const silk_vertex_out *v, int64_t *x, int64_t *y, uint32_t *d)
{
    svert s;
    project(t, v, &s);
    *x = s.x;
    *y = s.y;
    *d = (uint32_t)s.d;
}

/* The screen position alone (project_depth adds the depth). */
static void project_xy(const silk_target *t, const silk_vertex_out *v, svert *s)
{
    const silk_vec4 *c = &v->clip;
    s->x = screen_x(c, t->width);
    s->y = screen_y(c, t->height);
    s->w = c->w;
    s->var = v->var;
}

static void project_depth(const silk_vertex_out *v, svert *s)
{
    const silk_vec4 *c = &v->clip;
    int64_t num = (int64_t)c->w - c->z;
    if (num <= 0) {
        s->d = 0;
    } else {
        /* num < 2^32 and 0 < w < 2^31: 32-bit divisions */
        uint32_t w = (uint32_t)c->w, q = (uint32_t)num / w, r = (uint32_t)num % w, r2;
        int64_t d = (int64_t)q * ((int64_t)1 << 31) + udiv_q32((uint64_t)r << 31, w, &r2);
        s->d = d > (int64_t)DEPTH_MAX ? (int64_t)DEPTH_MAX : d;
    }
}

static void project(const silk_target *t, const silk_vertex_out *v, svert *s)
{
    project_xy(t, v, s);
    project_depth(v, s);
}

/* ---- triangles ---------------------------------------------------------------- */

/* (a b) >> 31 for a product within 64 bits; one multiply instruction on a
 * 32-bit processor when both factors are within 32 bits, unsigned (inside
 * the triangle, the usual case). */
static int64_t mul_shr31(int64_t a, int64_t b)
{
    if (SILK_CPU32 && ((uint64_t)a | (uint64_t)b) <= UINT32_MAX)
        return (int64_t)(((uint64_t)(uint32_t)a * (uint32_t)b) >> 31);
    return (a * b) >> 31;
}

/* Perspective-correct barycentric weights b1, b2 in Q0.30 from the planes
 * U = e1 q1, V = e2 q2, T = e0 q0 + U + V (e_i edge functions, q_i ~ 1/w_i):
 * b_i = U/T, V/T.  One division. */
static inline void weights(int64_t u, int64_t v, int64_t tt, int64_t *b1, int64_t *b2)
{
    if (tt <= 0) { *b1 = *b2 = 0; return; }       /* only outside the triangle */
    int s = silk_bitlen64((uint64_t)tt) - 31;
    if (s > 0) { u >>= s; v >>= s; tt >>= s; }
    int64_t inv = recip61(tt);                   /* tt in [1, 2^31): inv in (2^30, 2^61] */
    *b1 = mul_shr31(u, inv);                     /* u <= tt: product <= 2^61 */
    *b2 = mul_shr31(v, inv);
}

typedef struct tri_setup {
    const svert *v[3];     /* ordered so that the area below is positive */
    int affine;            /* all q equal: one reciprocal for the whole triangle (here: no padding on a 32-bit part) */
    int64_t area;          /* twice the area in subpixels^2, > 0 */
    int64_t ea[3], eb[3];  /* edge function i: ea*(X - Xj) + eb*(Y - Yj), j = i+1 */
    int64_t qn[3];
    int64_t aff_inv; int aff_shift;
    int64_t gxq, gxr, gyq, gyr;   /* depth plane per subpixel: quotient and remainder */
    rstep dstep;                  /* depth per pixel in x */
    int64_t du, dv, dt;           /* U, V, T per pixel in x */
    int64_t duy, dvy, dty;        /* and in y: row to row, and the texture footprint */
    int nvar;
    /* var_k = a0_k + (a1_k - a0_k) b1 + (a2_k - a0_k) b2 is a0 b0 + a1 b1 + a2 b2
     * exactly (b0 = 1 - b1 - b2 is never negative inside the triangle), with
     * two products instead of three; |a_i - a0| < 2^32 and b1 + b2 <= 2^30
     * keep the sum below 2^63.  vbase holds a0 in Q30 plus the rounding half. */
    int64_t vbase[SILK_MAX_VARYINGS], vd1[SILK_MAX_VARYINGS], vd2[SILK_MAX_VARYINGS];
    int vnarrow;           /* a 32-bit processor and every vd1, vd2 within 32 bits */
    const silk_phong *plain;   /* silk_hal_phong_plain of the stages, when shading (SILK_PHONG_PLAIN), or NULL */
    struct span_memo *memo;    /* span_depth's, or NULL (without SILK_SPAN_DEPTH_STEP) */
} tri_setup;

/* What span_depth keeps of a triangle from span to span: raster_tri's,
 * only where the build steps the depth (SILK_SPAN_DEPTH_STEP), so that a
 * small part's stack holds none of it. */
typedef struct span_memo {
    int64_t ryq, ryr;          /* depth per row: quotient and remainder */
    rstep dat;                 /* the depth at the centre of pixel (dat_x, dat_y), the last span's first */
    int dat_x, dat_y;
} span_memo;

/* Depth at subpixel point (X, Y): D0 + (e1 dD1 + e2 dD2) / area, floored,
 * exact.  The quotient parts may overflow int64 on their own for slivers, so
 * they are summed modulo 2^64 (unsigned); the total is in [0, 2^32) for any
 * covered pixel, so the wrapped sum is the right answer. */
static void depth_at(const tri_setup *s, int64_t X, int64_t Y, rstep *d)
{
    int64_t dx = X - s->v[0]->x, dy = Y - s->v[0]->y;
    int64_t rem = s->gxr * dx + s->gyr * dy;               /* < 2^55 */
    int64_t f = floor_div(rem, s->area);
    uint64_t q = (uint64_t)s->v[0]->d + (uint64_t)s->gxq * (uint64_t)dx +
                 (uint64_t)s->gyq * (uint64_t)dy + (uint64_t)f;
    d->q = q <= (uint64_t)INT64_MAX ? (int64_t)q : -(int64_t)(~q) - 1;
    d->r = rem - f * s->area;
}

/* depth_at the centre of pixel (x, row) where a span starts, stepped from
 * the last span's first pixel where that is the row above and a few
 * pixels across (most rows of a triangle: the edge moves a pixel or two),
 * by additions: the same quotient and remainder of the same rational
 * (the quotient modulo 2^64, as depth_at sums it), without its division. */
static void span_depth(const tri_setup *s, int x, int row, rstep *d)
{
    span_memo *mo = s->memo;
    int64_t k = (int64_t)x - mo->dat_x;
    if (row - mo->dat_y == 1 && k >= -4 && k <= 4) {
        /* r in [0, 10 area) after the 4 area added: back below area in
         * four steps of 8, 4, 2 and 1 area, without branches (the carry
         * goes either way row by row) */
        uint64_t q = (uint64_t)mo->dat.q + (uint64_t)mo->ryq + (uint64_t)k * (uint64_t)s->dstep.sq - 4;
        int64_t r = mo->dat.r + mo->ryr + k * s->dstep.sr + 4 * s->area;
        for (int b = 3; b >= 0; b--) {
            int64_t over = r >= (s->area << b);
            r -= (s->area << b) & -over;
            q += (uint64_t)over << b;
        }
        d->q = q <= (uint64_t)INT64_MAX ? (int64_t)q : -(int64_t)(~q) - 1;
        d->r = r;
    } else {
        depth_at(s, (int64_t)x * SUB + SUB / 2, (int64_t)row * SUB + SUB / 2, d);
    }
    mo->dat.q = d->q;
    mo->dat.r = d->r;
    mo->dat_x = x;
    mo->dat_y = row;
}

/* Perspective-correct weights at the pixel whose planes are U, V, T. */
static SILK_HOST_INLINE void bary(const tri_setup *s, int64_t U, int64_t V, int64_t T, int64_t *b1, int64_t *b2)
{
    if (s->affine) {
        *b1 = mul_shr31(U >> s->aff_shift, s->aff_inv);
        *b2 = mul_shr31(V >> s->aff_shift, s->aff_inv);
    } else {
        weights(U, V, T, b1, b2);
    }
}

/* The texture footprint (silk_hal.footprint_var): how far varyings k and
 * k+1 move from this pixel (weights b1, b2) to its right and its lower
 * neighbour, the larger of the two for each, into var[nvar] and
 * var[nvar + 1].  Finite differences of the same perspective-correct
 * interpolation, per pixel.  A neighbour past the triangle's horizon
 * (T <= 0) counts as no movement; the weight steps are clamped to 2^29
 * (one half) so every product stays far inside 64 bits. */
static void footprint(const tri_setup *s, int k, int64_t U, int64_t V, int64_t T, int64_t b1, int64_t b2,
                      silk_fx *var)
{
    const int64_t lim = (int64_t)1 << 29;
    int64_t db[2][2] = { { 0, 0 }, { 0, 0 } };
    const int64_t step[2][3] = { { s->du, s->dv, s->dt }, { s->duy, s->dvy, s->dty } };
    for (int i = 0; i < 2; i++) {
        int64_t c1, c2, u = U + step[i][0], v = V + step[i][1], t = T + step[i][2];
        if (t <= 0) continue;
        /* bary's products are bounded for weights in [-1, 1]; a weight
         * beyond (a triangle under a pixel wide) moves by more than the
         * clamp below anyway, so +-2 stands for it */
        int64_t uc = u > t ? t : (u < -t ? -t : u), vc = v > t ? t : (v < -t ? -t : v);
        bary(s, uc, vc, t, &c1, &c2);
        if (uc != u) c1 = u > 0 ? 4 * lim : -4 * lim;
        if (vc != v) c2 = v > 0 ? 4 * lim : -4 * lim;
        c1 -= b1;
        c2 -= b2;
        db[i][0] = c1 < -lim ? -lim : (c1 > lim ? lim : c1);
        db[i][1] = c2 < -lim ? -lim : (c2 > lim ? lim : c2);
    }
    for (int j = 0; j < 2; j++) {
        int64_t m = 0;
        for (int i = 0; i < 2; i++) {
            int64_t d = (s->vd1[k + j] * db[i][0] + s->vd2[k + j] * db[i][1]) >> 30;
            d = d < 0 ? -d : d;
            if (d > m) m = d;
        }
        var[s->nvar + j] = m > SILK_FX_MAX ? SILK_FX_MAX : (silk_fx)m;
    }
}

/* What a span's fragments share: the triangle, the row's buffers, and the
 * planes U, V, T at the row's pixel 0.  At pixel x they are these plus x
 * steps, formed only where a fragment is shaded: most pixels a triangle
 * visits fail the depth test. */
typedef struct span_ctx {
    silk_target *t;
    const silk_hal *h;
    const tri_setup *s;
    const int64_t *uvt;
    uint16_t *wrow;
    uint8_t *crow;
} span_ctx;

/* varyings() where every factor is within 32 bits: two multiply-accumulates
 * each.  Out of line, and the weights as 32-bit arguments: inlined, the
 * compiler sees through the narrowing and multiplies in 64 bits again. */
SILK_CPU32_NOINLINE static void varyings32(const tri_setup *s, int32_t b1, int32_t b2, silk_fx *var)
{
    const int64_t *base = s->vbase, *d1 = s->vd1, *d2 = s->vd2;
    for (int k = 0; k < s->nvar; k++)
        var[k] = (silk_fx)((base[k] + (int64_t)(int32_t)d1[k] * b1 + (int64_t)(int32_t)d2[k] * b2) >> 30);
}

/* varyings() of the default stage's usual case (SILK_PHONG_PLAIN): a known
 * count, unrolled (a loop's counting costs as much as the interpolation). */
static inline silk_fx varying(const tri_setup *s, int k, int64_t b1, int64_t b2)
{
    return (silk_fx)((s->vbase[k] + s->vd1[k] * b1 + s->vd2[k] * b2) >> 30);
}

_Static_assert(SILK_PHONG_PLAIN_NVAR == 6, "varyings_plain interpolates six varyings");
static inline void varyings_plain(const tri_setup *s, int64_t b1, int64_t b2, silk_fx *var)
{
    var[0] = varying(s, 0, b1, b2), var[1] = varying(s, 1, b1, b2), var[2] = varying(s, 2, b1, b2);
    var[3] = varying(s, 3, b1, b2), var[4] = varying(s, 4, b1, b2), var[5] = varying(s, 5, b1, b2);
}

/* var_k = a0 + (a1 - a0) b1 + (a2 - a0) b2 in Q30, rounded (tri_setup). */
static void varyings(const tri_setup *s, int64_t b1, int64_t b2, silk_fx *var)
{
    const int64_t *base = s->vbase, *d1 = s->vd1, *d2 = s->vd2;
    int k = 0;
    if (s->vnarrow && b1 == (int32_t)b1 && b2 == (int32_t)b2) {
        varyings32(s, (int32_t)b1, (int32_t)b2, var);
        return;
    }
    for (; k + 2 <= s->nvar; k += 2) {     /* pairs: most stages use 6 */
        var[k] = (silk_fx)((base[k] + d1[k] * b1 + d2[k] * b2) >> 30);
        var[k + 1] = (silk_fx)((base[k + 1] + d1[k + 1] * b1 + d2[k + 1] * b2) >> 30);
    }
    if (k < s->nvar) var[k] = (silk_fx)((base[k] + d1[k] * b1 + d2[k] * b2) >> 30);
}

/* The pixel x of a span that passed the depth test at depth z: its
 * fragment, then its depth, write count and colour.  Out of line on a
 * 32-bit processor, so the span's loop keeps its few values in registers. */
SILK_CPU32_NOINLINE static void fragment_at(const span_ctx *c, int x, uint32_t z, uint32_t *zrow)
{
    const silk_hal *h = c->h;
    /* read once on a host (the stage's call may not change it); again
     * after the call on a 32-bit processor: fewer registers held across it */
    const int shading = h && h->fragment;
    uint32_t rgb = SILK_FRAGMENT_DISCARD;
    if (shading) {
        const tri_setup *s = c->s;
        int64_t U = c->uvt[0] + x * s->du, V = c->uvt[1] + x * s->dv, T = c->uvt[2] + x * s->dt;
        silk_fx var[SILK_MAX_VARYINGS + 2];   /* + the texture footprint (silk_hal.footprint_var) */
        int64_t b1, b2;
        bary(s, U, V, T, &b1, &b2);
        if (SILK_PHONG_PLAIN && s->plain) {   /* the default stage, with its per-frame tests made per triangle */
            varyings_plain(s, b1, b2, var);
            rgb = silk_phong_plain_fragment(s->plain, var);
        } else {
            varyings(s, b1, b2, var);
            if (SILK_TEXTURES && h->footprint_var > 0 && h->footprint_var < s->nvar)
                footprint(s, h->footprint_var - 1, U, V, T, b1, b2, var);
            rgb = h->fragment(h, var);
            /* a discarded fragment leaves the pixel, depth and all, to what lies behind */
            if (rgb == SILK_FRAGMENT_DISCARD) return;
        }
    }
    if (zrow) zrow[x] = z;
    if (SILK_DEPTH_WINS) c->t->drew = 1;
    if (c->wrow) c->wrow[x]++;
    if (c->crow && (SILK_CPU32 ? h && h->fragment : shading))
        store(c->t, c->crow + (size_t)x * silk_pixfmt_bytes(c->t->fmt), rgb);
}

static void span(silk_target *t, const silk_hal *h, const tri_setup *s, int row, int xl, int xr, const int64_t *uvt)
{
    span_ctx c;
    c.t = t;
    c.h = h;
    c.s = s;
    c.uvt = uvt;
    size_t r = (size_t)(row - t->y0);
    c.wrow = t->writes ? t->writes + r * (size_t)t->width : NULL;
    c.crow = t->color ? t->color + r * t->stride : NULL;
    uint32_t *zrow = t->depth ? t->depth + r * (size_t)t->width : NULL;
    rstep D = s->dstep;
    if (SILK_SPAN_DEPTH_STEP) span_depth(s, xl, row, &D);
    else depth_at(s, (int64_t)xl * SUB + SUB / 2, (int64_t)row * SUB + SUB / 2, &D);
    /* depth test z > stored, or z >= stored after a depth pass (stored = 0,
     * nothing there, wraps to the largest value: no pixel passes) */
    uint32_t eq = t->depth_equal ? 1u : 0u;
    const uint8_t *mrow = t->mask ? t->mask + r * (((size_t)t->width + 7) / 8) : NULL;
    if (SILK_BACK_FACES_LAST && t->depth_equal == SILK_DEPTH_TIES && zrow && !mrow) {   /* depth alone: render.c's back_draw */
        for (int x = xl; x < xr; x++) {
            uint32_t z = D.q < 0 ? 0 : (D.q > (int64_t)DEPTH_MAX ? DEPTH_MAX : (uint32_t)D.q);
            if (z >= zrow[x] && z) {   /* (nothing there is 0: never as near) */
                zrow[x] = z;
                t->drew = 1;
            }
            rstep_next(&D);
        }
        return;
    }
    if (SILK_CPU32 && zrow && !mrow && D.den <= ((int64_t)1 << 31)) {
        /* The usual case on a 32-bit processor, where most of a span's
         * pixels fail the depth test: the loop's values in registers and
         * the depth's remainder in 32 bits (the area allows it for all but
         * clipped triangles spanning most of the guard band). */
        uint64_t q = (uint64_t)D.q;
        const uint64_t sq = (uint64_t)D.sq;
        uint32_t dr = (uint32_t)D.r;
        const uint32_t dsr = (uint32_t)D.sr, dden = (uint32_t)D.den;
        const int call = (h && h->fragment) || c.wrow;   /* else a depth pass: the depth alone */
        for (int x = xl; x < xr; x++) {
            uint32_t z = q >> 32 == 0 ? (uint32_t)q : ((int64_t)q < 0 ? 0 : DEPTH_MAX);
            if (z > zrow[x] - eq) {
                if (call) fragment_at(&c, x, z, zrow);
                else zrow[x] = z;
                if (SILK_DEPTH_WINS) t->drew = 1;
            }
            q += sq;                    /* rstep_next */
            dr += dsr;
            if (dr >= dden) { dr -= dden; q++; }
        }
        return;
    }
    for (int x = xl; x < xr; x++) {
        uint32_t z = D.q < 0 ? 0 : (D.q > (int64_t)DEPTH_MAX ? DEPTH_MAX : (uint32_t)D.q);
        if ((!mrow || (mrow[x >> 3] >> (x & 7) & 1)) && (!zrow || z > zrow[x] - eq)) fragment_at(&c, x, z, zrow);
        rstep_next(&D);
    }
}

/* Edge walker for edge a -> b (a above b), starting at row `row`: the first
 * pixel whose centre is at or right of the edge is ceil((Xe - SUB/2) / SUB). */
static void edge_init(rstep *e, const svert *a, const svert *b, int row)
{
    int64_t dy = b->y - a->y, dx = b->x - a->x;
    int64_t yc = (int64_t)row * SUB + SUB / 2;
    rstep_init(e, (a->x - SUB / 2) * dy + (yc - a->y) * dx, SUB * dy, SUB * dx);
}

static int edge_x(const rstep *e) { return (int)(e->q + (e->r != 0)); }

/* The first pixel centre at or after subpixel position v:
 * ceil((v - SUB/2) / SUB). */
static int64_t first_centre(int64_t v)
{
    /* floor by a shift where right shifts of negative values are
     * arithmetic (gcc, clang), else by the division */
    int64_t n = SUB / 2 - v;
    return -((-1 >> 1) == -1 ? n >> SUB_BITS : floor_div(n, SUB));
}

static int first_row(int64_t y) { return (int)first_centre(y); }

/* Whether triangle p[0] p[1] p[2], twice its signed area `area`, can cover
 * a pixel centre of rows [lo, hi): not degenerate, not culled, and a pixel
 * centre row and column within its bounding box.  raster_tri draws nothing
 * for one that cannot.  box: the rows and then the columns of those pixel
 * centres, [box[0][0], box[0][1]) and [box[1][0], box[1][1]) (when it
 * can: its bounding box's). */
SILK_NOINLINE   /* its locals stay off the stack under every span */
static int tri_reaches(const silk_target *t, int lo, int hi, const svert *p, int64_t area, int64_t box[2][2])
{
    if (area == 0 || (t->cull_back && area > 0)) return 0;
    const int64_t lim[2][2] = { { lo, hi }, { 0, t->width } };
    for (int a = 0; a < 2; a++) {                  /* rows, then columns */
        int64_t lo_v = a ? p[0].x : p[0].y, hi_v = lo_v;
        for (int i = 1; i < 3; i++) {
            int64_t v = a ? p[i].x : p[i].y;
            if (v < lo_v) lo_v = v;
            if (v > hi_v) hi_v = v;
        }
        int64_t c0 = first_centre(lo_v), c1 = first_centre(hi_v);
        box[a][0] = c0 > lim[a][0] ? c0 : lim[a][0];
        box[a][1] = c1 < lim[a][1] ? c1 : lim[a][1];
        if (box[a][0] >= box[a][1]) return 0;
    }
    return 1;
}

static int64_t orient(const svert *a, const svert *b, const svert *c)
{
    return (b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y);
}

/* What raster_tri needs only where it draws a pixel: the weights and
 * varyings' set-up (when shading), the depth plane, and the planes U, V, T
 * at pixel 0 of row y, stepped from there row by row by additions only
 * (the same exact values as stepped from the triangle's first row).  Most
 * triangles of a fine mesh that reach a row cover no pixel centre at all. */
static void tri_pixels(tri_setup *s, int shading, int y, int64_t uvt[3])
{
    if (shading) {
        s->vnarrow = SILK_CPU32;
        for (int k = 0; k < s->nvar; k++) {
            const silk_fx *a0 = s->v[0]->var, *a1 = s->v[1]->var, *a2 = s->v[2]->var;
            s->vbase[k] = (int64_t)a0[k] * ((int64_t)1 << 30) + ((int64_t)1 << 29);
            s->vd1[k] = (int64_t)a1[k] - a0[k];
            s->vd2[k] = (int64_t)a2[k] - a0[k];
            if (s->vd1[k] != (int32_t)s->vd1[k] || s->vd2[k] != (int32_t)s->vd2[k]) s->vnarrow = 0;
        }
        silk_fx wmin = s->v[0]->w;
        for (int i = 1; i < 3; i++) if (s->v[i]->w < wmin) wmin = s->v[i]->w;
        for (int i = 0; i < 3; i++) {
            uint32_t r;   /* 0 < wmin <= w < 2^31: the quotient is at most 2^QN_BITS */
            s->qn[i] = udiv_q32((uint64_t)wmin << QN_BITS, (uint32_t)s->v[i]->w, &r);
            if (s->qn[i] < 1) s->qn[i] = 1;
        }
        s->du = s->qn[1] * s->ea[1] * SUB;
        s->dv = s->qn[2] * s->ea[2] * SUB;
        s->dt = (s->qn[0] * s->ea[0] + s->qn[1] * s->ea[1] + s->qn[2] * s->ea[2]) * SUB;
        s->duy = s->qn[1] * s->eb[1] * SUB;
        s->dvy = s->qn[2] * s->eb[2] * SUB;
        s->dty = (s->qn[0] * s->eb[0] + s->qn[1] * s->eb[1] + s->qn[2] * s->eb[2]) * SUB;
        s->affine = s->qn[0] == s->qn[1] && s->qn[1] == s->qn[2];
        s->aff_inv = 0;
        s->aff_shift = 0;
        if (s->affine) {
            int64_t tt = s->qn[0] * s->area;
            s->aff_shift = silk_bitlen64((uint64_t)tt) - 31;
            if (s->aff_shift < 0) s->aff_shift = 0;
            s->aff_inv = recip61(tt >> s->aff_shift);
        }
    }

    int64_t dd1 = s->v[1]->d - s->v[0]->d, dd2 = s->v[2]->d - s->v[0]->d;
    int64_t gxn = s->ea[1] * dd1 + s->ea[2] * dd2, gyn = s->eb[1] * dd1 + s->eb[2] * dd2;
    s->gxq = floor_div(gxn, s->area);
    s->gxr = gxn - s->gxq * s->area;
    s->gyq = floor_div(gyn, s->area);
    s->gyr = gyn - s->gyq * s->area;
    rstep_init(&s->dstep, 0, s->area, SUB * gxn);
    if (SILK_SPAN_DEPTH_STEP) {
        span_memo *mo = s->memo;
        mo->ryq = floor_div(SUB * gyn, s->area);   /* |gyn| < 2^53 */
        mo->ryr = SUB * gyn - mo->ryq * s->area;
        mo->dat_y = -2;   /* rows are >= 0: no span above */
    }

    int64_t dx = SUB / 2 - s->v[0]->x, dy = (int64_t)y * SUB + SUB / 2 - s->v[0]->y;
    int64_t e1 = s->ea[1] * dx + s->eb[1] * dy, e2 = s->ea[2] * dx + s->eb[2] * dy;
    uvt[0] = s->qn[1] * e1;
    uvt[1] = s->qn[2] * e2;
    uvt[2] = s->qn[0] * (s->area - e1 - e2) + uvt[0] + uvt[1];
}

static void raster_tri(silk_target *t, const silk_hal *h, int nvar, int lo, int hi,
                       const svert *p0, const svert *p1, const svert *p2)
{
    tri_setup s;
    span_memo memo;   /* (a build that does not step the depth has none: s.memo is never read there) */
    if (SILK_SPAN_DEPTH_STEP) s.memo = &memo;
    s.area = orient(p0, p1, p2);
    if (s.area == 0 || (t->cull_back && s.area > 0)) return;   /* y down: counter-clockwise is negative */
    s.v[0] = p0;
    s.v[1] = s.area > 0 ? p1 : p2;
    s.v[2] = s.area > 0 ? p2 : p1;
    if (s.area < 0) s.area = -s.area;
    s.nvar = nvar;

    /* rows covered: pixel centres in [ytop, ybottom) */
    const svert *o[3] = { s.v[0], s.v[1], s.v[2] };
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2 - i; j++)
            if (o[j]->y > o[j + 1]->y) { const svert *tmp = o[j]; o[j] = o[j + 1]; o[j + 1] = tmp; }
    int r0 = first_row(o[0]->y), r1 = first_row(o[1]->y), r2 = first_row(o[2]->y);
    int ys = r0 > lo ? r0 : lo, ye = r2 < hi ? r2 : hi;
    if (ys >= ye) return;

    for (int i = 0; i < 3; i++) {
        const svert *a = s.v[(i + 1) % 3], *b = s.v[(i + 2) % 3];
        s.ea[i] = a->y - b->y;
        s.eb[i] = b->x - a->x;
    }
    /* The weights and varyings only where fragments are shaded: a depth
     * pass needs the depth alone.  Both at the first pixel (tri_pixels):
     * until then the planes' steps are 0. */
    const int shading = h && h->fragment;
    s.qn[0] = s.qn[1] = s.qn[2] = 0;
    s.du = s.dv = s.dt = s.duy = s.dvy = s.dty = 0;
    s.affine = 0;
    int ready = 0;

    /* Is the middle vertex right of the long edge o0 -> o2? */
    int64_t cross = (o[1]->x - o[0]->x) * (o[2]->y - o[0]->y) - (o[2]->x - o[0]->x) * (o[1]->y - o[0]->y);
    int mid_right = cross > 0;
    int64_t uvt[3] = { 0, 0, 0 };
    rstep lng, sht;
    edge_init(&lng, o[0], o[2], ys);
    for (int part = 0; part < 2; part++) {
        int a = part ? (r1 > ys ? r1 : ys) : ys;
        int b = part ? ye : (r1 < ye ? r1 : ye);
        if (a >= b) continue;
        if (part) edge_init(&sht, o[1], o[2], a);
        else edge_init(&sht, o[0], o[1], a);
        for (int y = a; y < b; y++) {
            int xl = edge_x(mid_right ? &lng : &sht), xr = edge_x(mid_right ? &sht : &lng);
            if (xl < 0) xl = 0;
            if (xr > t->width) xr = t->width;
            if (xl < xr) {
                if (!ready) {
                    tri_pixels(&s, shading, y, uvt);
                    if (SILK_PHONG_PLAIN)   /* (a build without it never reads s.plain) */
                        s.plain = shading && s.nvar == SILK_PHONG_PLAIN_NVAR ? silk_hal_phong_plain(h) : NULL;
                }
                ready = 1;
                span(t, h, &s, y, xl, xr, uvt);
            }
            rstep_next(&lng);
            rstep_next(&sht);
            uvt[0] += s.duy;
            uvt[1] += s.dvy;
            uvt[2] += s.dty;
        }
    }
}

static int sgn(int64_t v) { return (v > 0) - (v < 0); }

/* A clipped triangle is a convex polygon, but snapping its vertices to the
 * subpixel grid can dent it where it turns by a tiny angle, and a fan over a
 * dented polygon has a flipped sliver that covers pixels twice.  So: fan
 * when every fan triangle keeps the polygon's orientation (the usual case),
 * else clip ears with exact orientation tests, which tiles any simple
 * polygon.  Only a polygon that snapping made self-intersecting (a sliver
 * thinner than the subpixel grid) falls back to the fan without its flipped
 * triangles. */
static void raster_polygon(silk_target *t, const silk_hal *h, int nvar, int lo, int hi, svert *sv, int n)
{
    int64_t total = 0;
    int fan_ok = 1;
    for (int i = 1; i + 1 < n; i++) total += orient(&sv[0], &sv[i], &sv[i + 1]);
    int s = sgn(total);
    if (s == 0) return;
    for (int i = 1; i + 1 < n; i++)
        if (sgn(orient(&sv[0], &sv[i], &sv[i + 1])) == -s) fan_ok = 0;
    if (fan_ok) {
        for (int i = 1; i + 1 < n; i++) raster_tri(t, h, nvar, lo, hi, &sv[0], &sv[i], &sv[i + 1]);
        return;
    }
    int idx[MAXPOLY], m = 0;
    for (int i = 0; i < n; i++)                     /* drop repeated points */
        if (m == 0 || sv[i].x != sv[idx[m - 1]].x || sv[i].y != sv[idx[m - 1]].y) idx[m++] = i;
    while (m > 1 && sv[idx[0]].x == sv[idx[m - 1]].x && sv[idx[0]].y == sv[idx[m - 1]].y) m--;
    while (m > 3) {
        int ear = -1;
        for (int i = 0; i < m && ear < 0; i++) {
            const svert *a = &sv[idx[(i + m - 1) % m]], *b = &sv[idx[i]], *c = &sv[idx[(i + 1) % m]];
            int o = sgn(orient(a, b, c)) * s;
            if (o < 0) continue;                    /* reflex */
            int blocked = 0;
            for (int j = 0; j < m && !blocked && o > 0; j++) {
                const svert *q = &sv[idx[j]];
                if (q == a || q == b || q == c) continue;
                blocked = sgn(orient(a, b, q)) * s >= 0 && sgn(orient(b, c, q)) * s >= 0 &&
                          sgn(orient(c, a, q)) * s >= 0;
            }
            if (!blocked) ear = i;
        }
        if (ear < 0) break;
        const svert *a = &sv[idx[(ear + m - 1) % m]], *b = &sv[idx[ear]], *c = &sv[idx[(ear + 1) % m]];
        if (orient(a, b, c) != 0) raster_tri(t, h, nvar, lo, hi, a, b, c);
        for (int j = ear; j + 1 < m; j++) idx[j] = idx[j + 1];
        m--;
    }
    if (m == 3) {
        if (sgn(orient(&sv[idx[0]], &sv[idx[1]], &sv[idx[2]])) == s)
            raster_tri(t, h, nvar, lo, hi, &sv[idx[0]], &sv[idx[1]], &sv[idx[2]]);
        return;
    }
    for (int i = 1; i + 1 < m; i++)
        if (sgn(orient(&sv[idx[0]], &sv[idx[i]], &sv[idx[i + 1]])) == s)
            raster_tri(t, h, nvar, lo, hi, &sv[idx[0]], &sv[idx[i]], &sv[idx[i + 1]]);
}

static int varying_count(const silk_hal *h)
{
    if (!h) return 0;
    return h->nvaryings < 0 ? 0 : (h->nvaryings > SILK_MAX_VARYINGS ? SILK_MAX_VARYINGS : h->nvaryings);
}

void silk_raster_triangle(silk_target *t, const silk_hal *h, const silk_vertex_out *a,
                          const silk_vertex_out *b, const silk_vertex_out *c)
{
    int lo, hi;
    if (!t || !a || !b || !c || !band_rows(t, &lo, &hi)) return;
    int nvar = varying_count(h);
    unsigned oa = 0, ob = 0, oc = 0;
    if (!SILK_FAST_CASES || !inside(&a->clip) || !inside(&b->clip) || !inside(&c->clip))
        oa = outcode(&a->clip), ob = outcode(&b->clip), oc = outcode(&c->clip);
    if (oa & ob & oc) return;                      /* wholly outside one plane */

    silk_vertex_out buf[2][MAXPOLY];
    const silk_vertex_out *poly = NULL;
    int n = 3;
    const silk_vertex_out *in3[3] = { a, b, c };
    unsigned any = oa | ob | oc;
    if (any) {
        buf[0][0] = *a;
        buf[0][1] = *b;
        buf[0][2] = *c;
        int cur = 0;
        for (int p = 0; p < NPLANES && n >= 3; p++) {
            if (!(any & (1u << p))) continue;
            n = clip_poly(buf[cur], n, buf[cur ^ 1], p, nvar);
            cur ^= 1;
        }
        if (n < 3) return;
        poly = buf[cur];
    }

    svert sv[MAXPOLY];
    for (int i = 0; i < n; i++) {
        const silk_vertex_out *v = poly ? &poly[i] : in3[i];
        if (v->clip.w <= 0) return;                 /* cannot happen after clipping */
        project_xy(t, v, &sv[i]);
    }
    /* Where back faces are culled, most triangles of a fine mesh are
     * culled or fall between pixel centres: those are known from the
     * positions alone.  (Elsewhere raster_tri finds the few that do.) */
    int64_t box[2][2];
    if (n == 3 && t->cull_back && !tri_reaches(t, lo, hi, sv, orient(&sv[0], &sv[1], &sv[2]), box)) return;
    for (int i = 0; i < n; i++) project_depth(poly ? &poly[i] : in3[i], &sv[i]);
    if (n == 3) raster_tri(t, h, nvar, lo, hi, &sv[0], &sv[1], &sv[2]);
    else raster_polygon(t, h, nvar, lo, hi, sv, n);
}

int silk_raster_culled(const silk_target *t, const silk_vertex_out *a, const silk_vertex_out *b,
                       const silk_vertex_out *c)
{
    unsigned oa = outcode(&a->clip), ob = outcode(&b->clip), oc = outcode(&c->clip);
    if (oa & ob & oc) return 1;
    if (oa | ob | oc) return 0;                    /* clipped: the polygon decides */
    /* silk_raster_triangle's test (tri_reaches, raster_tri): the screen
     * positions do not depend on the band */
    svert sv[3];
    project_xy(t, a, &sv[0]);
    project_xy(t, b, &sv[1]);
    project_xy(t, c, &sv[2]);
    return orient(&sv[0], &sv[1], &sv[2]) >= 0;
}

/* (The three are the shortcuts' alone: a build without them has stubs.) */
#define RASTER_PLACED (SILK_PLACE_ONCE || SILK_DRAW_DIRECT)

int silk_raster_place(const silk_target *t, const silk_vec4 *clip, int32_t xy[2])
{
    if (!RASTER_PLACED || !inside(clip)) return 0;
    /* within the guard band: |x|, |y| below 2 SILK_MAX_DIM SUB */
    xy[0] = (int32_t)screen_x(clip, t->width);
    xy[1] = (int32_t)screen_y(clip, t->height);
    return 1;
}

static void placed_xy(const int32_t *const xy[3], svert sv[3])
{
    /* written out: a loop of three is not unrolled at -O2 (every triangle of a fine mesh comes here) */
    sv[0].x = xy[0][0];
    sv[0].y = xy[0][1];
    sv[1].x = xy[1][0];
    sv[1].y = xy[1][1];
    sv[2].x = xy[2][0];
    sv[2].y = xy[2][1];
}

/* Whether triangle p, twice its signed area `area`, covers one of the
 * pixel centres in box (tri_reaches') by raster_tri's rule, when the box
 * holds at most COVER_ASK of them (else 1: it may).  raster_tri draws the
 * centres of a row from the first at or right of its left edge to the last
 * left of its right edge, the rows from the first centre at or below the
 * top to the last above the bottom: the top-left rule, a centre on a left
 * or a horizontal top edge in, on a right or bottom one out.  (On a row,
 * the edge raster_tri walks on either side is the nearest of the
 * triangle's edges on that side, and it meets the other at the middle
 * vertex's row, so asking every edge is asking the walked one.) */
#define COVER_ASK 4
static int covers_centre(const svert *p, int64_t area, int64_t box[2][2])
{
    if ((box[0][1] - box[0][0]) * (box[1][1] - box[1][0]) > COVER_ASK) return 1;
    /* edge i, a -> b: the centre is in where ex y - ey x + e0 > 0 (the
     * inside positive, a centre on it in by one for a left or top edge) */
    int64_t ex[3], ey[3], e0[3];
    for (int i = 0; i < 3; i++) {
        const svert *a = &p[i], *b = &p[i == 2 ? 0 : i + 1];
        int64_t dx = b->x - a->x, dy = b->y - a->y;
        if (area < 0) {
            dx = -dx;
            dy = -dy;
        }
        ex[i] = dx;
        ey[i] = dy;
        e0[i] = dy * a->x - dx * a->y + (dy < 0 || (dy == 0 && dx > 0));
    }
    for (int64_t y = box[0][0]; y < box[0][1]; y++)
        for (int64_t x = box[1][0]; x < box[1][1]; x++) {
            int64_t cx = x * SUB + SUB / 2, cy = y * SUB + SUB / 2;
            if (ex[0] * cy - ey[0] * cx + e0[0] > 0 && ex[1] * cy - ey[1] * cx + e0[1] > 0 &&
                ex[2] * cy - ey[2] * cx + e0[2] > 0)
                return 1;
        }
    return 0;
}

int silk_raster_reaches(const silk_target *t, const int32_t *const xy[3])
{
    /* silk_raster_triangle's own test, culled or not: raster_tri draws
     * nothing for a triangle it fails (tri_reaches).  The cheapest part
     * first: half of a closed mesh faces away.  Then, where its bounding
     * box holds few pixel centres, whether it covers one: of those that
     * reach a row, a third of a fine mesh's at 320x240 cover none. */
    const int32_t *a = xy[0], *b = xy[1], *c = xy[2];
    int64_t area = ((int64_t)b[0] - a[0]) * ((int64_t)c[1] - a[1]) - ((int64_t)c[0] - a[0]) * ((int64_t)b[1] - a[1]);
    if (!RASTER_PLACED || area == 0 || (t->cull_back && area > 0)) return 0;   /* orient()'s, from the places themselves */
    svert sv[3];
    int64_t box[2][2];
    int lo, hi;
    placed_xy(xy, sv);
    return band_rows(t, &lo, &hi) && tri_reaches(t, lo, hi, sv, area, box) && covers_centre(sv, area, box);
}

void silk_raster_placed(silk_target *t, const silk_hal *h, const silk_vertex_out *const v[3],
                        const int32_t *const xy[3])
{
    svert sv[3];
    int lo, hi;
    if (!RASTER_PLACED) return;
    placed_xy(xy, sv);
    if (!band_rows(t, &lo, &hi)) return;   /* (silk_raster_reaches: it is usable) */
    for (int i = 0; i < 3; i++) {
        sv[i].w = v[i]->clip.w;
        sv[i].var = v[i]->var;
        project_depth(v[i], &sv[i]);
    }
    raster_tri(t, h, varying_count(h), lo, hi, &sv[0], &sv[1], &sv[2]);
}

/* ---- lines ----------------------------------------------------------------------- */

/* Depth bias of a line towards the viewer.  A line pixel takes the line's
 * depth at the major-axis pixel centre, the surface under it its own depth
 * at the true pixel centre, up to half a pixel away across the line: the
 * bias covers the depth change over one pixel along the line, plus 1/256 of
 * the depth for the unknown slope across it (in perspective: the line is
 * drawn as if 0.4% nearer). */
static int64_t line_bias(int64_t d, int64_t per_pixel)
{
    d += (d >> 8) + per_pixel + 1;
    return d > (int64_t)DEPTH_MAX ? (int64_t)DEPTH_MAX : d;
}

static void line_pixel(silk_target *t, int x, int y, uint32_t z, uint32_t rgb)
{
    size_t r = (size_t)(y - t->y0), i = r * (size_t)t->width + (size_t)x;
    if (t->depth && z <= t->depth[i]) return;
    if (t->writes) t->writes[i]++;
    if (t->color) store(t, t->color + r * t->stride + (size_t)x * silk_pixfmt_bytes(t->fmt), rgb);
}

void silk_raster_line(silk_target *t, const silk_vertex_out *a, const silk_vertex_out *b, uint32_t rgb)
{
    int lo, hi;
    if (!t || !a || !b || !band_rows(t, &lo, &hi)) return;
    silk_vertex_out p = *a, q = *b, tmp;
    memset(&tmp, 0, sizeof tmp);
    for (int i = 0; i < NPLANES; i++) {
        int64_t dp = plane_dist(i, &p.clip), dq = plane_dist(i, &q.clip);
        if (dp < 0 && dq < 0) return;
        if (dp < 0) { intersect(&q, &p, dq, dp, 0, &tmp); p = tmp; }
        else if (dq < 0) { intersect(&p, &q, dp, dq, 0, &tmp); q = tmp; }
    }
    if (p.clip.w <= 0 || q.clip.w <= 0) return;
    svert s0, s1;
    project(t, &p, &s0);
    project(t, &q, &s1);
    int64_t adx = s1.x - s0.x, ady = s1.y - s0.y;
    if (adx < 0) adx = -adx;
    if (ady < 0) ady = -ady;
    int64_t len = adx > ady ? adx : ady, dd = s1.d > s0.d ? s1.d - s0.d : s0.d - s1.d;
    int64_t per_pixel = len > SUB ? dd * SUB / len : dd;
    s0.d = line_bias(s0.d, per_pixel);
    s1.d = line_bias(s1.d, per_pixel);
    int xmajor = adx >= ady;
    /* major axis u, minor axis v; ordered so u grows: the same pixels for a->b and b->a */
    int64_t u0 = xmajor ? s0.x : s0.y, v0 = xmajor ? s0.y : s0.x, d0 = s0.d;
    int64_t u1 = xmajor ? s1.x : s1.y, v1 = xmajor ? s1.y : s1.x, d1 = s1.d;
    if (u0 > u1 || (u0 == u1 && v0 > v1)) {
        int64_t x;
        x = u0; u0 = u1; u1 = x;
        x = v0; v0 = v1; v1 = x;
        x = d0; d0 = d1; d1 = x;
    }
    int64_t du = u1 - u0, dv = v1 - v0;
    if (du == 0) {                                  /* a point */
        int x = (int)floor_div(s0.x, SUB), y = (int)floor_div(s0.y, SUB);
        if (x >= 0 && x < t->width && y >= lo && y < hi) line_pixel(t, x, y, (uint32_t)d0, rgb);
        return;
    }
    /* pixels whose centre along the major axis lies in [u0, u1] */
    int64_t c0 = ceil_div(u0 - SUB / 2, SUB), c1 = floor_div(u1 - SUB / 2, SUB);
    int64_t umax = xmajor ? t->width : hi, umin = xmajor ? 0 : lo;
    if (c0 < umin) c0 = umin;
    if (c1 > umax - 1) c1 = umax - 1;
    if (xmajor && dv != 0) {
        /* only the columns whose row can fall in the band */
        int64_t ya = (int64_t)lo * SUB - v0, yb = (int64_t)hi * SUB - v0;
        int64_t ua = u0 + floor_div(ya * du, dv), ub = u0 + floor_div(yb * du, dv);
        if (ua > ub) { int64_t x = ua; ua = ub; ub = x; }
        int64_t ca = floor_div(ua - SUB / 2, SUB) - 1, cb = ceil_div(ub - SUB / 2, SUB) + 1;
        if (c0 < ca) c0 = ca;
        if (c1 > cb) c1 = cb;
    }
    if (c0 > c1) return;
    int64_t uc = c0 * SUB + SUB / 2;
    rstep vs, ds;
    rstep_init(&vs, v0 * du + (uc - u0) * dv, SUB * du, SUB * dv);   /* minor pixel index */
    rstep_init(&ds, d0 * du + (uc - u0) * (d1 - d0), du, SUB * (d1 - d0));
    for (int64_t c = c0; c <= c1; c++) {
        int x = (int)(xmajor ? c : vs.q), y = (int)(xmajor ? vs.q : c);
        if (x >= 0 && x < t->width && y >= lo && y < hi) line_pixel(t, x, y, (uint32_t)ds.q, rgb);
        rstep_next(&vs);
        rstep_next(&ds);
    }
}
