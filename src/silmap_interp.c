/*
 * silmap_interp.c - the outline of the detailed model for the current eye,
 * interpolated from a silhouette map (Gu, Gortler, Hoppe et al.,
 * "Silhouette Mapping", section 5; the map of section 4).
 *
 *   locate   the polytope triangle met by the ray from the centre through
 *            the eye (section 4), walking from the previous frame's
 *            triangle; its barycentric coordinates (b1, b2, b3).
 *   section 5.1: the edge closest to the point, say p1 p2 (b3 smallest);
 *            p_e on it at alpha12 = b2 / (b1 + b2), the point p_t at
 *            alpha3 = b3 from p_e towards p3.
 *   section 5.2: rectify both outlines of a pair of views (a 3x3 map per
 *            view to cameras with the same orientation whose scan lines
 *            are the pair's epipolar lines), then interpolate scan line by
 *            scan line.
 *   section 5.3: on a scan line, the intervals (x1l, x1r) and (x2l, x2r)
 *            give (xel, xer) = ((1 - a) x1l + a x2l, (1 - a) x1r + a x2r);
 *            with several intervals on a side every pair is interpolated
 *            and the results united (the "pants": two legs that overlap
 *            become one interval).  That is the silhouette of the visual
 *            hull of the two views, exactly, between the outlines' vertex
 *            scan lines, where every interval end moves linearly.
 *   section 5: the outline at p_t mapped to the current view by the 3x3
 *            projective map of the plane through the centre parallel to
 *            the triangle.
 *
 * Fixed point throughout: image points are Q16.16 pixels, world points
 * Q16.16; products go through 64 bits; the 3x3 maps keep a shared exponent
 * so that focal lengths in the hundreds and world sizes of any scale fit.
 * All memory is the arena's top.
 */
#include <string.h>
#include "silmap_interp.h"

/* ---- small integer helpers ------------------------------------------------------ */

static int bits64(uint64_t v)
{
    int n = 0;
    while (v) {
        n++;
        v >>= 1;
    }
    return n;
}

static uint64_t abs64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

/* n / d as Q16.16, rounded, saturated; d != 0. */
static silk_fx div_q16(int64_t n, int64_t d)
{
    while (abs64(n) >= ((uint64_t)1 << 46) || abs64(d) >= ((uint64_t)1 << 46)) {
        n /= 2;
        d /= 2;
    }
    if (d == 0) return n >= 0 ? SILK_FX_MAX : SILK_FX_MIN;
    if (d < 0) {
        n = -n;
        d = -d;
    }
    int64_t num = n * 65536;
    int64_t q = num >= 0 ? (num + d / 2) / d : -((-num + d / 2) / d);
    return silk_fx_sat(q);
}

/* Shift the mantissas right until the largest has at most maxbits bits. */
static void norm_bits(int64_t *m, int n, int32_t *e, int maxbits)
{
    uint64_t mx = 0;
    for (int i = 0; i < n; i++)
        if (abs64(m[i]) > mx) mx = abs64(m[i]);
    int s = bits64(mx) - maxbits;
    if (s <= 0) return;
    for (int i = 0; i < n; i++) m[i] = silk_shr_round64(m[i], s);
    *e += s;
}

/* A 3x3 (or 1x3) matrix in block floating point, one exponent per column:
 * entry (i, j) is m[3i + j] * 2^e[j].  The columns of a map from image
 * points differ in scale by the focal length squared and more (u and v in
 * pixels against the constant 1), so one shared exponent would leave the
 * small ones a few bits. */
typedef struct bfm {
    int64_t m[9];
    int32_t e[3];
} bfm;

/* Each column's mantissas to at most maxbits bits. */
static void norm_cols(bfm *a, int rows, int maxbits)
{
    for (int j = 0; j < 3; j++) {
        int64_t col[3] = { 0, 0, 0 };
        for (int i = 0; i < rows; i++) col[i] = a->m[3 * i + j];
        norm_bits(col, rows, &a->e[j], maxbits);
        for (int i = 0; i < rows; i++) a->m[3 * i + j] = col[i];
    }
}

/* One exponent for all columns (the largest), then maxbits bits. */
static void make_uniform(bfm *a, int rows, int maxbits)
{
    int32_t e = a->e[0] > a->e[1] ? a->e[0] : a->e[1];
    if (a->e[2] > e) e = a->e[2];
    for (int j = 0; j < 3; j++) {
        int s = e - a->e[j];
        for (int i = 0; i < rows; i++)
            a->m[3 * i + j] = s == 0 ? a->m[3 * i + j] : s > 62 ? 0 : silk_shr_round64(a->m[3 * i + j], s);
    }
    int32_t ee = e;
    norm_bits(a->m, 3 * rows, &ee, maxbits);
    a->e[0] = a->e[1] = a->e[2] = ee;
}

/* From Q32.32 entries with one exponent. */
static bfm bf_q32(const int64_t m[9], int rows)
{
    bfm r;
    memset(&r, 0, sizeof r);
    memcpy(r.m, m, (size_t)rows * 3 * sizeof *m);
    r.e[0] = r.e[1] = r.e[2] = -32;
    make_uniform(&r, rows, 30);
    return r;
}

/* a (rows x 3, made uniform first) times b (3 x 3, per column). */
static bfm bf_mul(const bfm *a0, int rows, const bfm *b)
{
    bfm a = *a0, r;
    make_uniform(&a, rows, 30);
    memset(&r, 0, sizeof r);
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < 3; j++)
            r.m[3 * i + j] = a.m[3 * i] * b->m[j] + a.m[3 * i + 1] * b->m[3 + j] + a.m[3 * i + 2] * b->m[6 + j];
    for (int j = 0; j < 3; j++) r.e[j] = a.e[0] + b->e[j];
    norm_cols(&r, rows, 30);
    return r;
}

static bfm bf_add(const bfm *a, const bfm *b)
{
    bfm r;
    for (int j = 0; j < 3; j++) {
        int hi_a = a->e[j] >= b->e[j];
        const bfm *hi = hi_a ? a : b, *lo = hi_a ? b : a;
        int s = hi->e[j] - lo->e[j];
        for (int i = 0; i < 3; i++)
            r.m[3 * i + j] =
                hi->m[3 * i + j] + (s == 0 ? lo->m[3 * i + j] : s > 62 ? 0 : silk_shr_round64(lo->m[3 * i + j], s));
        r.e[j] = hi->e[j];
    }
    norm_cols(&r, 3, 30);
    return r;
}

/* ---- the 3x3 maps ---------------------------------------------------------------- */

static int64_t q32(silk_fx a, silk_fx b) { return (int64_t)a * b; }

/* Image point (u, v, 1) of perspective camera c -> a world direction. */
static bfm image_to_dir(const silk_silmap_cam *c)
{
    bfm m;
    const silk_fx *r = &c->right.x, *u = &c->up.x, *f = &c->fwd.x;
    for (int i = 0; i < 3; i++) {
        m.m[3 * i] = (int64_t)r[i] * 65536;
        m.m[3 * i + 1] = -((int64_t)u[i] * 65536);
        m.m[3 * i + 2] = q32(c->focal, f[i]) - q32(c->cx, r[i]) + q32(c->cy, u[i]);
    }
    m.e[0] = m.e[1] = m.e[2] = -32;
    norm_cols(&m, 3, 30);
    return m;
}

/* World direction (relative to the eye) -> homogeneous image point. */
static bfm dir_to_image(const silk_silmap_cam *c)
{
    int64_t m[9];
    const silk_fx *r = &c->right.x, *u = &c->up.x, *f = &c->fwd.x;
    for (int i = 0; i < 3; i++) {
        if (c->ortho) {
            m[i] = q32(c->focal, r[i]);
            m[3 + i] = -q32(c->focal, u[i]);
            m[6 + i] = 0;
        } else {
            m[i] = q32(c->focal, r[i]) + q32(c->cx, f[i]);
            m[3 + i] = -q32(c->focal, u[i]) + q32(c->cy, f[i]);
            m[6 + i] = (int64_t)f[i] * 65536;
        }
    }
    return bf_q32(m, 3);
}

silk_status silk_h3_between(const silk_silmap_cam *a, const silk_silmap_cam *b, const silk_vec3 *plane,
                            const silk_vec3 *centre, silk_h3 *h)
{
    if (a->ortho || (b->ortho && !plane)) return SILK_ERR_ARG;
    bfm ma = image_to_dir(a), pb = dir_to_image(b);
    bfm full, depth;                /* depth: a row whose sign times w's is the depth's in b */
    if (!plane) {
        /* same eye: the direction is the point */
        full = bf_mul(&pb, 3, &ma);
        int64_t fr[9] = { (int64_t)b->fwd.x * 65536, (int64_t)b->fwd.y * 65536, (int64_t)b->fwd.z * 65536 };
        bfm fb = bf_q32(fr, 1);
        depth = bf_mul(&fb, 1, &ma);
    } else {
        /* X = pa + d k / (n.d), k = n.(centre - pa):
         * (X - pb) (n.d) = [(pa - pb) n^T + k I] d */
        const silk_fx *n = &plane->x;
        silk_vec3 dp = silk_v3_sub(a->eye, b->eye);
        const silk_fx *dpp = &dp.x;
        int64_t k = silk_v3_dot64(*plane, silk_v3_sub(*centre, a->eye));
        int64_t gm[9];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) gm[3 * i + j] = q32(dpp[i], n[j]) + (i == j ? k : 0);
        bfm g = bf_q32(gm, 3);
        int64_t nm[9] = { (int64_t)n[0] * 65536, (int64_t)n[1] * 65536, (int64_t)n[2] * 65536 };
        bfm nr = bf_q32(nm, 1);
        bfm p = bf_mul(&pb, 3, &g);
        if (b->ortho) {
            /* x w = cx (n.d) + f right.(G d), likewise y; w = n.d */
            int64_t am[9];
            for (int j = 0; j < 3; j++) {
                am[j] = q32(b->cx, n[j]);
                am[3 + j] = q32(b->cy, n[j]);
                am[6 + j] = (int64_t)n[j] * 65536;
            }
            bfm add = bf_q32(am, 3);
            p = bf_add(&p, &add);
        }
        full = bf_mul(&p, 3, &ma);
        depth = bf_mul(&nr, 1, &ma);
    }
    norm_cols(&full, 3, 28);
    norm_cols(&depth, 1, 28);
    memcpy(h->m, full.m, sizeof h->m);
    memcpy(h->e, full.e, sizeof h->e);
    memcpy(h->depth, depth.m, sizeof h->depth);
    memcpy(h->de, depth.e, sizeof h->de);
    uint64_t mx = 0;
    for (int i = 0; i < 9; i++)
        if (abs64(h->m[i]) > mx) mx = abs64(h->m[i]);
    return mx ? SILK_OK : SILK_ERR_RANGE;
}

/* Row . (u, v, 1) with the columns' exponents aligned to the largest. */
static int64_t row_apply(const int64_t *m, const int32_t *e, silk_vec2 p)
{
    int64_t t[3] = { m[0] * p.x, m[1] * p.y, m[2] * SILK_FX_ONE };
    int32_t emax = e[0] > e[1] ? e[0] : e[1];
    if (e[2] > emax) emax = e[2];
    int64_t sum = 0;
    for (int j = 0; j < 3; j++) {
        int s = emax - e[j];
        sum += s == 0 ? t[j] : s > 62 ? 0 : silk_shr_round64(t[j], s);
    }
    return sum;
}

int silk_h3_apply(const silk_h3 *h, silk_vec2 p, silk_vec2 *out)
{
    int64_t x = row_apply(h->m, h->e, p), y = row_apply(h->m + 3, h->e, p), w = row_apply(h->m + 6, h->e, p);
    int64_t d = row_apply(h->depth, h->de, p);
    if (w == 0 || d == 0 || ((w > 0) != (d > 0))) return -1;
    out->x = div_q16(x, w);
    out->y = div_q16(y, w);
    return 0;
}

static silk_status outline_alloc(silk_arena *a, uint32_t nloops, uint32_t npts, uint32_t **start, silk_vec2 **pt)
{
    *start = silk_arena_array_top(a, (size_t)nloops + 1, sizeof **start, SILK_MEM_FRAME);
    *pt = silk_arena_array_top(a, npts ? npts : 1, sizeof **pt, SILK_MEM_FRAME);
    return *start && *pt ? SILK_OK : SILK_ERR_NOMEM;
}

silk_status silk_outline_map(const silk_outline *in, const silk_h3 *h, silk_arena *a, silk_outline *out)
{
    uint32_t *start;
    silk_vec2 *pt;
    silk_status st = outline_alloc(a, in->nloops, in->npts, &start, &pt);
    if (st) return st;
    memcpy(start, in->start, ((size_t)in->nloops + 1) * sizeof *start);
    for (uint32_t i = 0; i < in->npts; i++)
        if (silk_h3_apply(h, in->pt[i], &pt[i])) return SILK_ERR_RANGE;
    out->nloops = in->nloops;
    out->npts = in->npts;
    out->start = start;
    out->pt = pt;
    return SILK_OK;
}

silk_status silk_outline_reproject(const silk_outline *in, const silk_silmap_cam *from, const silk_silmap_cam *to,
                                   silk_arena *a, silk_outline *out)
{
    /* in's offsets may be a map's (silk_silmap_outline): rebased here */
    uint32_t base = in->start[0], n = in->start[in->nloops] - base, *start;
    silk_vec2 *pt;
    silk_h3 h;
    silk_status st = silk_h3_between(from, to, NULL, NULL, &h);
    if (!st) st = outline_alloc(a, in->nloops, n, &start, &pt);
    if (st) return st;
    for (uint32_t i = 0; i <= in->nloops; i++) start[i] = in->start[i] - base;
    for (uint32_t i = 0; i < n; i++)
        if (silk_h3_apply(&h, in->pt[base + i], &pt[i])) return SILK_ERR_RANGE;
    out->nloops = in->nloops;
    out->npts = n;
    out->start = start;
    out->pt = pt;
    return SILK_OK;
}

/* ---- rectification ------------------------------------------------------------- */

/* Unit vector along an exact 64-bit vector. */
static int unit64(const int64_t v[3], silk_vec3 *out)
{
    int64_t t[3] = { v[0], v[1], v[2] };
    int32_t e = 0;
    norm_bits(t, 3, &e, 30);
    return silk_v3_normalize(silk_v3((silk_fx)t[0], (silk_fx)t[1], (silk_fx)t[2]), out);
}

silk_status silk_silmap_rectified(silk_vec3 pa, silk_vec3 pb, silk_vec3 centre, silk_fx focal,
                                  silk_silmap_cam *ra, silk_silmap_cam *rb)
{
    int64_t l[3] = { (int64_t)pb.x - pa.x, (int64_t)pb.y - pa.y, (int64_t)pb.z - pa.z };
    silk_vec3 x, z;
    if (!unit64(l, &x)) return SILK_ERR_ARG;
    /* towards the centre, square to the base line */
    silk_vec3 z0 = silk_v3_sub(centre, pa);
    int64_t s = silk_v3_dot64(z0, x);   /* Q32.32 */
    int64_t zz[3] = { ((int64_t)z0.x * 65536) - s * x.x / 65536, ((int64_t)z0.y * 65536) - s * x.y / 65536,
                      ((int64_t)z0.z * 65536) - s * x.z / 65536 };
    if (!unit64(zz, &z)) return SILK_ERR_ARG;
    silk_silmap_cam c;
    memset(&c, 0, sizeof c);
    c.right = x;
    c.fwd = z;
    c.up = silk_v3_cross(x, z);
    c.focal = focal;
    c.eye = pa;
    *ra = c;
    c.eye = pb;
    *rb = c;
    return SILK_OK;
}

/* ---- linear interpolation of two rectified outlines (sections 5.2, 5.3) --------- */

/* A non-horizontal edge, top (smaller y) first. */
typedef struct ledge { silk_fx y0, y1, x0, x1; } ledge;

/* x on the line through (y0, x0) and (y1, x1) at y. */
static silk_fx line_x(silk_fx y0, silk_fx x0, silk_fx y1, silk_fx x1, silk_fx y)
{
    if (y == y0) return x0;
    if (y == y1) return x1;
    return silk_fx_sat((int64_t)x0 + silk_fx_muldiv(silk_fx_sub(x1, x0), silk_fx_sub(y, y0), silk_fx_sub(y1, y0)));
}

/* Heapsort (no recursion, no extra memory) by a silk_fx key. */
typedef silk_fx (*sort_key)(const void *);

static void swap_bytes(uint8_t *a, uint8_t *b, size_t n)
{
    while (n--) {
        uint8_t t = *a;
        *a++ = *b;
        *b++ = t;
    }
}

static void sift_down(uint8_t *v, size_t size, uint32_t r, uint32_t n, sort_key key)
{
    for (;;) {
        uint32_t c = 2 * r + 1;
        if (c >= n) return;
        if (c + 1 < n && key(v + (c + 1) * size) > key(v + c * size)) c++;
        if (key(v + r * size) >= key(v + c * size)) return;
        swap_bytes(v + r * size, v + c * size, size);
        r = c;
    }
}

static void heap_sort(void *base, uint32_t n, size_t size, sort_key key)
{
    uint8_t *v = base;
    for (uint32_t i = n / 2; i-- > 0;) sift_down(v, size, i, n, key);
    for (uint32_t end = n; end-- > 1;) {
        swap_bytes(v, v + end * size, size);
        sift_down(v, size, 0, end, key);
    }
}

static silk_fx key_fx(const void *p) { return *(const silk_fx *)p; }
static silk_fx key_edge_top(const void *p) { return ((const ledge *)p)->y0; }

static uint32_t collect_edges(const silk_outline *o, ledge *e)
{
    uint32_t n = 0;
    for (uint32_t l = 0; l < o->nloops; l++) {
        uint32_t s = o->start[l], t = o->start[l + 1];
        for (uint32_t i = s; i < t; i++) {
            silk_vec2 p = o->pt[i], q = o->pt[i + 1 < t ? i + 1 : s];
            if (p.y == q.y) continue;
            if (p.y < q.y) e[n] = (ledge){ p.y, q.y, p.x, q.x };
            else e[n] = (ledge){ q.y, p.y, q.x, p.x };
            n++;
        }
    }
    heap_sort(e, n, sizeof *e, key_edge_top);
    return n;
}

/* A segment of x over the band [ya, yb]: its ends. */
typedef struct seg { silk_fx a, b; } seg;
typedef struct trap { seg l, r; } trap;

#define LERP_MAX_TRAPS 16            /* pairs of intervals per band united exactly */
#define LERP_MAX_LINES (2 * LERP_MAX_TRAPS)
#define LERP_SEAM ((silk_fx)64)      /* 1/1024 px: intervals this close are one */

/* One outline's active edges on the way down. */
typedef struct sweep {
    const ledge *e;
    uint32_t n, next, nact, nint;
    uint32_t *act;
    seg *x;                          /* the active edges' ends on the band, sorted */
} sweep;

static void sweep_band(sweep *s, silk_fx ya, silk_fx yb)
{
    uint32_t k = 0;
    for (uint32_t i = 0; i < s->nact; i++)
        if (s->e[s->act[i]].y1 > ya) s->act[k++] = s->act[i];
    s->nact = k;
    while (s->next < s->n && s->e[s->next].y0 <= ya) {
        if (s->e[s->next].y1 > ya) s->act[s->nact++] = s->next;
        s->next++;
    }
    for (uint32_t i = 0; i < s->nact; i++) {
        uint32_t id = s->act[i];
        const ledge *d = &s->e[id];
        seg v = { line_x(d->y0, d->x0, d->y1, d->x1, ya), line_x(d->y0, d->x0, d->y1, d->x1, yb) };
        /* insertion by the middle: edges do not cross inside a band.  The
         * active list keeps the order found, so the next band, whose edges
         * are mostly the same in the same order, sorts in about linear time */
        uint32_t j = i;
        while (j > 0 && (int64_t)s->x[j - 1].a + s->x[j - 1].b > (int64_t)v.a + v.b) {
            s->x[j] = s->x[j - 1];
            s->act[j] = s->act[j - 1];
            j--;
        }
        s->x[j] = v;
        s->act[j] = id;
    }
    /* intervals under the parity rule; two that meet (an edge shared by
     * two pieces of an interpolated outline) are one, and empty ones are
     * none, so that the seams do not count as intervals */
    uint32_t n = 0;
    for (uint32_t i = 0; i + 1 < s->nact; i += 2) {
        seg l = s->x[i], r = s->x[i + 1];
        if (l.a >= r.a && l.b >= r.b) continue;
        if (n && l.a - s->x[2 * n - 1].a <= LERP_SEAM && l.b - s->x[2 * n - 1].b <= LERP_SEAM) {
            s->x[2 * n - 1] = r;
            continue;
        }
        s->x[2 * n] = l;
        s->x[2 * n + 1] = r;
        n++;
    }
    s->nint = n;
}

static silk_fx lerp_fx(silk_fx p, silk_fx q, silk_fx t)
{
    return silk_fx_sat((int64_t)p + silk_shr_round64(((int64_t)q - p) * t, 16));
}

/* Section 5.3 for one interval of each view, (al, ar) seen from a and
 * (bl, br) from b, at alpha from a to b.  In rectified cameras a point at
 * depth z seen at x from the eye at alpha is seen at x + alpha t from a
 * and at x - (1 - alpha) t from b, t = focal * baseline / z > 0.  The two
 * wedges meet in front of the eyes for t in (max(0, al - br), ar - bl);
 * the interval seen is from the least left end over those t to the
 * largest right end.  Where the least lies inside, at t = al - bl, it is
 * the paper's (1 - alpha) al + alpha bl, likewise on the right.  0 when the
 * wedges do not meet in front (l = r then, where they come closest). */
static int pair_span(silk_fx al, silk_fx ar, silk_fx bl, silk_fx br, silk_fx alpha, silk_fx *l, silk_fx *r)
{
    int64_t t0 = (int64_t)al - br, t1 = (int64_t)ar - bl;
    if (t0 < 0) t0 = 0;
    silk_fx beta = SILK_FX_ONE - alpha;
    if (t1 <= t0) {
        *l = *r = lerp_fx(lerp_fx(al, bl, alpha), lerp_fx(ar, br, alpha), SILK_FX_HALF);
        return 0;
    }
    int64_t tl = (int64_t)al - bl, tr = (int64_t)ar - br;
    tl = tl < t0 ? t0 : tl > t1 ? t1 : tl;
    tr = tr < t0 ? t0 : tr > t1 ? t1 : tr;
    int64_t l1 = (int64_t)al - silk_shr_round64(alpha * tl, 16), l2 = (int64_t)bl + silk_shr_round64(beta * tl, 16);
    int64_t r1 = (int64_t)ar - silk_shr_round64(alpha * tr, 16), r2 = (int64_t)br + silk_shr_round64(beta * tr, 16);
    *l = silk_fx_sat(l1 > l2 ? l1 : l2);
    *r = silk_fx_sat(r1 < r2 ? r1 : r2);
    return 1;
}

static silk_fx seg_at(const seg *s, silk_fx ya, silk_fx yb, silk_fx y) { return line_x(ya, s->a, yb, s->b, y); }

/* Emit the union of the band's trapezoids as quadrilaterals; returns how
 * many (pt NULL: count only). */
static uint32_t unite_band(const trap *t, uint32_t nt, silk_fx ya, silk_fx yb, silk_vec2 *pt)
{
    silk_fx cut[2 + LERP_MAX_LINES * (LERP_MAX_LINES - 1) / 2];
    uint32_t nc = 0;
    cut[nc++] = ya;
    cut[nc++] = yb;
    /* where two sides cross inside the band, the order of the sides changes */
    const seg *lines = &t[0].l;      /* l, r, l, r, ... */
    uint32_t nl = 2 * nt;
    for (uint32_t i = 0; i < nl; i++)
        for (uint32_t j = i + 1; j < nl; j++) {
            int64_t da = (int64_t)lines[i].a - lines[j].a, db = (int64_t)lines[i].b - lines[j].b;
            if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
                int64_t y = ya + ((int64_t)yb - ya) * da / (da - db);
                if (y > ya && y < yb) cut[nc++] = (silk_fx)y;
            }
        }
    heap_sort(cut, nc, sizeof *cut, key_fx);
    uint32_t nq = 0;
    trap sub[LERP_MAX_TRAPS];
    for (uint32_t c = 0; c + 1 < nc; c++) {
        silk_fx y0 = cut[c], y1 = cut[c + 1];
        if (y1 == y0) continue;
        for (uint32_t i = 0; i < nt; i++) {
            trap s = { { seg_at(&t[i].l, ya, yb, y0), seg_at(&t[i].l, ya, yb, y1) },
                       { seg_at(&t[i].r, ya, yb, y0), seg_at(&t[i].r, ya, yb, y1) } };
            uint32_t j = i;
            while (j > 0 && (int64_t)sub[j - 1].l.a + sub[j - 1].l.b > (int64_t)s.l.a + s.l.b) {
                sub[j] = sub[j - 1];
                j--;
            }
            sub[j] = s;
        }
        trap cur = sub[0];
        for (uint32_t i = 1; i <= nt; i++) {
            if (i < nt && (int64_t)sub[i].l.a + sub[i].l.b <= (int64_t)cur.r.a + cur.r.b) {
                if ((int64_t)sub[i].r.a + sub[i].r.b > (int64_t)cur.r.a + cur.r.b) cur.r = sub[i].r;
                continue;
            }
            if (cur.l.a == cur.r.a && cur.l.b == cur.r.b) {
                if (i < nt) cur = sub[i];
                continue;
            }
            if (pt) {
                silk_vec2 *q = &pt[4 * nq];
                q[0] = (silk_vec2){ cur.l.a, y0 };
                q[1] = (silk_vec2){ cur.r.a, y0 };
                q[2] = (silk_vec2){ cur.r.b, y1 };
                q[3] = (silk_vec2){ cur.l.b, y1 };
            }
            nq++;
            if (i < nt) cur = sub[i];
        }
    }
    return nq;
}

typedef struct lerp_ctx {
    sweep sa, sb;
    const silk_fx *ys;
    uint32_t nys;
    silk_fx alpha;
} lerp_ctx;

static uint32_t lerp_pass(lerp_ctx *c, silk_vec2 *pt)
{
    c->sa.next = c->sa.nact = c->sb.next = c->sb.nact = 0;
    uint32_t nq = 0;
    trap t[LERP_MAX_TRAPS];
    for (uint32_t k = 0; k + 1 < c->nys; k++) {
        silk_fx ya = c->ys[k], yb = c->ys[k + 1];
        sweep_band(&c->sa, ya, yb);
        sweep_band(&c->sb, ya, yb);
        uint32_t na = c->sa.nint, nb = c->sb.nint;
        if (!na || !nb) continue;
        uint32_t nt = 0;
        for (uint32_t i = 0; i < na; i++)
            for (uint32_t j = 0; j < nb; j++) {
                /* as many intervals on both sides: each its own clique,
                 * matched in order (section 5.3, "mutant pants"), so that a
                 * hole seen by both views stays open; otherwise the pants */
                if (na == nb && i != j) continue;
                const seg *al = &c->sa.x[2 * i], *ar = &c->sa.x[2 * i + 1];
                const seg *bl = &c->sb.x[2 * j], *br = &c->sb.x[2 * j + 1];
                silk_fx la, ra, lb, rb;
                int fa = pair_span(al->a, ar->a, bl->a, br->a, c->alpha, &la, &ra);
                int fb = pair_span(al->b, ar->b, bl->b, br->b, c->alpha, &lb, &rb);
                if (!fa && !fb) continue;
                trap q = { { la, lb }, { ra, rb } };
                if (nt < LERP_MAX_TRAPS) {
                    t[nt++] = q;
                    continue;
                }
                /* too many legs to unite exactly: the last one grows to hold
                 * the rest (larger than the visual hull's, never smaller) */
                trap *z = &t[LERP_MAX_TRAPS - 1];
                z->l.a = silk_fx_min(z->l.a, la);
                z->l.b = silk_fx_min(z->l.b, lb);
                z->r.a = silk_fx_max(z->r.a, ra);
                z->r.b = silk_fx_max(z->r.b, rb);
            }
        if (!nt) continue;
        uint32_t q = unite_band(t, nt, ya, yb, pt ? pt + 4 * nq : NULL);
        nq += q;
    }
    return nq;
}

silk_status silk_outline_lerp(const silk_outline *a, const silk_outline *b, silk_fx alpha, silk_arena *ar,
                              silk_outline *out)
{
    lerp_ctx c;
    memset(&c, 0, sizeof c);
    c.alpha = alpha;
    uint32_t n = a->npts + b->npts;
    silk_fx *ys = silk_arena_array_top(ar, n ? n : 1, sizeof *ys, SILK_MEM_FRAME);
    ledge *ea = silk_arena_array_top(ar, a->npts ? a->npts : 1, sizeof *ea, SILK_MEM_FRAME);
    ledge *eb = silk_arena_array_top(ar, b->npts ? b->npts : 1, sizeof *eb, SILK_MEM_FRAME);
    c.sa.act = silk_arena_array_top(ar, a->npts ? a->npts : 1, sizeof(uint32_t), SILK_MEM_FRAME);
    c.sb.act = silk_arena_array_top(ar, b->npts ? b->npts : 1, sizeof(uint32_t), SILK_MEM_FRAME);
    c.sa.x = silk_arena_array_top(ar, a->npts ? a->npts : 1, sizeof(seg), SILK_MEM_FRAME);
    c.sb.x = silk_arena_array_top(ar, b->npts ? b->npts : 1, sizeof(seg), SILK_MEM_FRAME);
    if (!ys || !ea || !eb || !c.sa.act || !c.sb.act || !c.sa.x || !c.sb.x) return SILK_ERR_NOMEM;
    for (uint32_t i = 0; i < a->npts; i++) ys[i] = a->pt[i].y;
    for (uint32_t i = 0; i < b->npts; i++) ys[a->npts + i] = b->pt[i].y;
    heap_sort(ys, n, sizeof *ys, key_fx);
    uint32_t nys = 0;
    for (uint32_t i = 0; i < n; i++)
        if (!nys || ys[i] != ys[nys - 1]) ys[nys++] = ys[i];
    c.ys = ys;
    c.nys = nys;
    c.sa.e = ea;
    c.sa.n = collect_edges(a, ea);
    c.sb.e = eb;
    c.sb.n = collect_edges(b, eb);

    uint32_t nq = lerp_pass(&c, NULL);
    if (nq > (UINT32_MAX - 1) / 4) return SILK_ERR_NOMEM;
    uint32_t *start;
    silk_vec2 *pt;
    silk_status st = outline_alloc(ar, nq, 4 * nq, &start, &pt);
    if (st) return st;
    lerp_pass(&c, pt);
    for (uint32_t i = 0; i <= nq; i++) start[i] = 4 * i;
    out->nloops = nq;
    out->npts = 4 * nq;
    out->start = start;
    out->pt = pt;
    return SILK_OK;
}

/* ---- the polytope triangle (section 4) ------------------------------------------ */

/* The ray's weights on triangle t: b_k proportional to det(d, a_k+1, a_k+2)
 * with a_k the corners relative to the centre (scaled together). */
static void ray_weights(const silk_silmap *m, uint32_t t, silk_vec3 d, int64_t w[3])
{
    int64_t a[9];
    int32_t e = 0;
    for (int k = 0; k < 3; k++) {
        silk_vec3 p = m->views[m->tri[3 * t + k]].cam.eye;
        a[3 * k] = (int64_t)p.x - m->centre.x;
        a[3 * k + 1] = (int64_t)p.y - m->centre.y;
        a[3 * k + 2] = (int64_t)p.z - m->centre.z;
    }
    norm_bits(a, 9, &e, 16);
    for (int k = 0; k < 3; k++) {
        const int64_t *p = &a[3 * ((k + 1) % 3)], *q = &a[3 * ((k + 2) % 3)];
        int64_t cx = p[1] * q[2] - p[2] * q[1], cy = p[2] * q[0] - p[0] * q[2], cz = p[0] * q[1] - p[1] * q[0];
        w[k] = d.x * cx + d.y * cy + d.z * cz;
    }
}

silk_status silk_silmap_locate(const silk_silmap *m, silk_vec3 eye, uint32_t hint, uint32_t *tri, silk_fx bary[3])
{
    if (!m->ntris) return SILK_ERR_EMPTY;
    if (hint >= m->ntris) hint = 0;
    int64_t dv[3] = { (int64_t)eye.x - m->centre.x, (int64_t)eye.y - m->centre.y, (int64_t)eye.z - m->centre.z };
    silk_vec3 d;
    if (!unit64(dv, &d)) {
        /* the eye at the centre: any direction will do, the hint's */
        int64_t s[3] = { 0, 0, 0 };
        for (int k = 0; k < 3; k++) {
            silk_vec3 p = m->views[m->tri[3 * hint + k]].cam.eye;
            s[0] += (int64_t)p.x - m->centre.x;
            s[1] += (int64_t)p.y - m->centre.y;
            s[2] += (int64_t)p.z - m->centre.z;
        }
        if (!unit64(s, &d)) return SILK_ERR_ARG;
    }
    int64_t w[3];
    uint32_t t = hint, found = UINT32_MAX;
    /* walk across the edge the ray lies beyond */
    for (uint32_t step = 0; step <= m->ntris && found == UINT32_MAX; step++) {
        ray_weights(m, t, d, w);
        int kmin = 0;
        for (int k = 1; k < 3; k++)
            if (w[k] < w[kmin]) kmin = k;
        if (w[kmin] >= 0 && w[0] + w[1] + w[2] > 0) found = t;
        else t = m->adj[3 * t + kmin];
        if (t >= m->ntris) break;
    }
    for (t = 0; t < m->ntris && found == UINT32_MAX; t++) {
        ray_weights(m, t, d, w);
        if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0 && w[0] + w[1] + w[2] > 0) found = t;
    }
    if (found == UINT32_MAX) return SILK_ERR_ARG;   /* not star-shaped about its centre */
    int64_t sum = w[0] + w[1] + w[2];
    bary[0] = div_q16(w[0], sum);
    bary[1] = div_q16(w[1], sum);
    bary[2] = SILK_FX_ONE - bary[0] - bary[1];
    if (bary[2] < 0) {
        bary[1] += bary[2];
        bary[2] = 0;
    }
    *tri = found;
    return SILK_OK;
}

/* ---- the whole interpolation (section 5) ----------------------------------------- */

uint32_t silk_silmap_bytes(const silk_silmap *m)
{
    return m->nviews * (uint32_t)sizeof(silk_silmap_view) + m->ntris * 6 * (uint32_t)sizeof(uint32_t) +
           (m->nloops + 1) * (uint32_t)sizeof(uint32_t) + m->npts * (uint32_t)sizeof(silk_vec2);
}

silk_outline silk_silmap_outline(const silk_silmap *m, uint32_t view)
{
    const silk_silmap_view *v = &m->views[view];
    silk_outline o = { v->nloops, m->loop_start[v->first_loop + v->nloops] - m->loop_start[v->first_loop],
                       m->loop_start + v->first_loop, m->pts };
    return o;
}

void silk_silmap_cam_of_view(const silk_view *v, silk_silmap_cam *c)
{
    memset(c, 0, sizeof *c);
    c->eye = v->cam.eye;
    c->right = v->right;
    c->up = v->upv;
    c->fwd = v->forward;
    c->focal = v->pixels_per_unit;
    c->cx = silk_fx_from_int(v->cam.width) / 2;
    c->cy = silk_fx_from_int(v->cam.height) / 2;
    c->ortho = v->cam.ortho;
}

/* An outline of a map view: loop offsets are the map's, so rebase them. */
static silk_status view_outline(const silk_silmap *m, uint32_t view, silk_arena *a, silk_outline *o)
{
    silk_outline src = silk_silmap_outline(m, view);
    uint32_t *start = silk_arena_array_top(a, (size_t)src.nloops + 1, sizeof *start, SILK_MEM_FRAME);
    if (!start) return SILK_ERR_NOMEM;
    uint32_t base = src.start[0];
    for (uint32_t i = 0; i <= src.nloops; i++) start[i] = src.start[i] - base;
    o->nloops = src.nloops;
    o->npts = src.npts;
    o->start = start;
    o->pt = m->pts + base;
    return SILK_OK;
}

/* Rectify outlines a (seen by ca) and b (seen by cb) for the pair and
 * interpolate at alpha; the result's camera is *ce. */
static silk_status lin_interp(const silk_outline *a, const silk_silmap_cam *ca, const silk_outline *b,
                              const silk_silmap_cam *cb, silk_vec3 centre, silk_fx alpha, silk_arena *ar,
                              silk_outline *out, silk_silmap_cam *ce)
{
    silk_silmap_cam ra, rb;
    silk_h3 h;
    silk_outline a2, b2;
    silk_status st = silk_silmap_rectified(ca->eye, cb->eye, centre, ca->focal, &ra, &rb);
    if (!st) st = silk_h3_between(ca, &ra, NULL, NULL, &h);
    if (!st) st = silk_outline_map(a, &h, ar, &a2);
    if (!st) st = silk_h3_between(cb, &rb, NULL, NULL, &h);
    if (!st) st = silk_outline_map(b, &h, ar, &b2);
    if (!st) st = silk_outline_lerp(&a2, &b2, alpha, ar, out);
    if (st) return st;
    *ce = ra;
    ce->eye = silk_v3_lerp(ca->eye, cb->eye, alpha);
    return SILK_OK;
}

silk_status silk_silmap_interp(const silk_silmap *m, const silk_view *cur, uint32_t hint, silk_arena *a,
                               silk_outline *out, silk_silmap_frame *info, silk_error *err)
{
    static const char name[] = "silhouette map";
    silk_silmap_cam cc;
    silk_silmap_cam_of_view(cur, &cc);
    /* an orthographic eye is a direction: the viewer is at -forward */
    silk_vec3 eye = cc.ortho ? silk_v3_sub(m->centre, cc.fwd) : cc.eye;
    uint32_t t;
    silk_fx b[3];
    silk_status st = silk_silmap_locate(m, eye, hint, &t, b);
    if (st) return silk_fail(err, st, name, 0, "no polytope triangle holds the eye's direction");
    /* section 5.1: the closest edge is opposite the smallest weight */
    int k3 = 0;
    for (int k = 1; k < 3; k++)
        if (b[k] < b[k3]) k3 = k;
    int k1 = (k3 + 1) % 3, k2 = (k3 + 2) % 3;
    uint32_t v1 = m->tri[3 * t + k1], v2 = m->tri[3 * t + k2], v3 = m->tri[3 * t + k3];
    int64_t b12 = (int64_t)b[k1] + b[k2];
    silk_fx alpha12 = b12 > 0 ? div_q16(b[k2], b12) : 0, alpha3 = b[k3];

    silk_outline s1, s2, s3, se, st_;
    silk_silmap_cam ce, ct;
    const silk_silmap_cam *c1 = &m->views[v1].cam, *c2 = &m->views[v2].cam, *c3 = &m->views[v3].cam;
    st = view_outline(m, v1, a, &s1);
    if (!st) st = view_outline(m, v2, a, &s2);
    if (!st) st = view_outline(m, v3, a, &s3);
    if (!st) st = lin_interp(&s1, c1, &s2, c2, m->centre, alpha12, a, &se, &ce);
    if (!st) {
        if (alpha3 > 0) st = lin_interp(&se, &ce, &s3, c3, m->centre, alpha3, a, &st_, &ct);
        else {
            st_ = se;
            ct = ce;
        }
    }
    /* section 5: the plane through the centre parallel to the triangle */
    silk_h3 h;
    silk_vec3 n = { 0, 0, 0 };
    if (!st) {
        silk_vec3 p1 = c1->eye, p2 = c2->eye, p3 = c3->eye;
        int64_t u[3] = { (int64_t)p2.x - p1.x, (int64_t)p2.y - p1.y, (int64_t)p2.z - p1.z };
        int64_t v[3] = { (int64_t)p3.x - p1.x, (int64_t)p3.y - p1.y, (int64_t)p3.z - p1.z };
        int32_t e = 0;
        int64_t uv[6] = { u[0], u[1], u[2], v[0], v[1], v[2] };
        norm_bits(uv, 6, &e, 24);
        int64_t c[3] = { uv[1] * uv[5] - uv[2] * uv[4], uv[2] * uv[3] - uv[0] * uv[5], uv[0] * uv[4] - uv[1] * uv[3] };
        if (!unit64(c, &n)) st = SILK_ERR_ARG;
        else if (silk_v3_dot64(n, silk_v3_sub(p1, m->centre)) < 0) n = silk_v3_neg(n);
    }
    if (!st) st = silk_h3_between(&ct, &cc, &n, &m->centre, &h);
    if (!st) st = silk_outline_map(&st_, &h, a, out);
    if (st == SILK_ERR_NOMEM)
        return silk_fail(err, st, name, 0, "the arena is too small for the interpolated outline");
    if (st) return silk_fail(err, st, name, 0, "the outline's plane is not in front of the camera");
    if (info) {
        info->tri = t;
        info->views[0] = v1;
        info->views[1] = v2;
        info->views[2] = v3;
        info->alpha12 = alpha12;
        info->alpha3 = alpha3;
        info->vt = ct;
    }
    return SILK_OK;
}
