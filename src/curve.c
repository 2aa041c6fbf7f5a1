/*
 * curve.c - the curve constructions of paper section III in integer
 * arithmetic: the tangent length that makes a Hermite curve follow a
 * circular arc (eq. 4), the silhouette bridge over a mesh edge (eqs. 2-5),
 * the silhouette point on a bridge (eqs. 6-7) and the adaptive sample count
 * of a silhouette segment (eq. 8).
 *
 * Inputs and results are Q16.16, but a bridge over a long edge has tangents
 * of thousands of units whose direction must still be right to the last
 * ulp, and a view direction to a far eye is 10^4 times longer than a unit
 * normal.  So the vector work runs on "wide" vectors: int64 components times
 * a power of two, scaled so that the largest component has W_BITS (30)
 * significant bits.  A product of two such components and a sum of three
 * products then fit in an int64, and every length and ratio keeps about 30
 * bits - far more than the 16 fractional bits of the result.
 *
 * The bulge bound (curve.h, SILK_BULGE_DIV): eq. 4 follows a circle, and
 * a circle over a chord whose end tangents turn far from it is a dome
 * reaching half the chord's length away from it - on a coarse mesh that
 * is a visible bulge past the outline.  The tangent is shortened so that
 * its Bezier control point (t / 3 from the end) stays within |chord| / 6
 * of the chord's line, the furthest a PN triangle's edge control point
 * (Vlachos et al.) can be; the curve then stays within |chord| / 8 of it.
 *
 * Overflow policy: eq. 4's length 2|chord|/(1 + cos theta) grows without
 * bound as the tangent turns back along the chord.  It is clamped at
 * SILK_ARC_MAX_RATIO * |chord| (see curve.h); a result that still does not
 * fit Q16.16 is shortened as a whole, keeping its direction.
 */
#include "curve.h"
#include "compiler.h"

#define W_BITS 30

_Static_assert(SILK_ARC_MAX_RATIO >= 2 && SILK_ARC_MAX_RATIO <= 4, "curve.c bounds assume a clamp ratio in [2, 4]");

/* A vector (c[0], c[1], c[2]) * 2^e, in ulps of Q16.16. */
typedef struct wvec {
    int64_t c[3];
    int e;
} wvec;


static uint64_t max3_abs(const int64_t c[3])
{
    uint64_t m = silk_abs64(c[0]);
    if (silk_abs64(c[1]) > m) m = silk_abs64(c[1]);
    if (silk_abs64(c[2]) > m) m = silk_abs64(c[2]);
    return m;
}

/* v * 2^s for s >= 0, written as a product: a left shift of a negative
 * value is undefined in C. */
static int64_t mul_pow2(int64_t v, int s) { return v * ((int64_t)1 << s); }

/* Rounded v / d, d > 0, halves away from zero (symmetric in the sign of v). */
static int64_t div_round(int64_t v, int64_t d)
{
    uint64_t q = silk_udiv64(silk_abs64(v) + (uint64_t)d / 2, (uint64_t)d);
    return v >= 0 ? (int64_t)q : -(int64_t)q;
}

/* Square root rounded to nearest: r*r <= v < (r+1)^2, and r+1 when v is past
 * the midpoint (r + 1/2)^2 = r^2 + r + 1/4. */
static uint64_t sqrt_round(uint64_t v)
{
    uint64_t r = silk_isqrt64(v);
    return v - r * r > r ? r + 1 : r;
}

/* The wide form of (x, y, z) * 2^e.  Exact unless the largest component
 * has more than W_BITS bits, in which case it is rounded to W_BITS. */
static wvec wide(int64_t x, int64_t y, int64_t z, int e)
{
    wvec w = { { x, y, z }, e };
    uint64_t m = max3_abs(w.c);
    if (m == 0) { w.e = 0; return w; }
    int s = silk_bitlen64(m) - W_BITS;
    for (int k = 0; k < 3; k++)
        w.c[k] = s > 0 ? silk_shr_round64(w.c[k], s) : mul_pow2(w.c[k], -s);
    w.e = e + s;
    return w;
}

static int wide_is_zero(const wvec *w) { return (w->c[0] | w->c[1] | w->c[2]) == 0; }

/* Mantissa dot product; its scale is 2^(a.e + b.e).  |.| < 3 * 2^60. */
static int64_t wdot(const wvec *a, const wvec *b)
{
    return a->c[0] * b->c[0] + a->c[1] * b->c[1] + a->c[2] * b->c[2];
}

/* Mantissa length, in [2^29, 2^31) for a nonzero wide vector. */
static int64_t wlen(const wvec *a) { return (int64_t)sqrt_round((uint64_t)wdot(a, a)); }

/* (c[0], c[1], c[2]) * 2^e as Q16.16, rounded; |c| < 2^40 and e <= 8, as
 * the tangents below are (mantissas < 2^35, e > 0 only for chords longer
 * than 2^14 units).  A vector too long for Q16.16 is shortened as a whole
 * to the longest that fits, so the overflow never turns it. */
static silk_vec3 to_fx(const int64_t c[3], int e)
{
    int64_t r[3];
    for (int k = 0; k < 3; k++)
        r[k] = e >= 0 ? mul_pow2(c[k], e) : silk_shr_round64(c[k], -e > 62 ? 62 : -e);
    uint64_t m = max3_abs(r);
    if (m > (uint64_t)SILK_FX_MAX) {
        int s = silk_bitlen64(m) - 31;                    /* so that r * SILK_FX_MAX fits */
        if (s > 0) {
            for (int k = 0; k < 3; k++) r[k] = silk_shr_round64(r[k], s);
            m = max3_abs(r);
        }
        for (int k = 0; k < 3; k++) r[k] = r[k] * SILK_FX_MAX / (int64_t)m;
    }
    return silk_v3((silk_fx)r[0], (silk_fx)r[1], (silk_fx)r[2]);
}

/* Eq. 4 on wide vectors, both nonzero: dir's direction with length
 * 2|chord| / (1 + cos theta), clamped at SILK_ARC_MAX_RATIO * |chord|, as
 * Q16.16.  *lcp is wlen(chord), which a bridge's two ends share. */
static silk_vec3 arc_tangent_wide(const wvec *dir, const wvec *chord, const int64_t *lcp)
{
    int64_t ld = wlen(dir), lc = *lcp;                 /* < 2^31 each */
    int64_t prod = ld * lc;                            /* |dir||chord|, < 3 * 2^60 */
    /* 1 + cos theta = (prod + dir.chord) / prod: a sum, not a difference,
     * everywhere it is not clamped, so no cancellation. */
    int64_t den = prod + wdot(dir, chord);
    int64_t den_min = prod * 2 / SILK_ARC_MAX_RATIO;   /* 1 + cos theta >= 2 / max ratio */
    if (den < den_min) den = den_min;
    /* g = 1 / (1 + cos theta) in Q30, from 31-bit operands so that
     * prod << 30 fits. */
    int s = silk_bitlen64((uint64_t)den) - 31;
    if (s > 0) {
        den = silk_shr_round64(den, s);
        prod = silk_shr_round64(prod, s);
    }
    int64_t g = div_round(mul_pow2(prod, 30), den);    /* <= 2^30 * max ratio / 2 */
    /* The bulge bound: L sin theta <= |chord| / SILK_BULGE_DIV (curve.h),
     * i.e. g <= 2^30 / (2 SILK_BULGE_DIV sin theta), sin theta =
     * |dir x chord| / (|dir||chord|).  The cross product's components are
     * < 2^61; taken to 2^-30 their squares sum below 2^64. */
    int64_t cr[3] = { dir->c[1] * chord->c[2] - dir->c[2] * chord->c[1],
                      dir->c[2] * chord->c[0] - dir->c[0] * chord->c[2],
                      dir->c[0] * chord->c[1] - dir->c[1] * chord->c[0] };
    uint64_t cr2 = 0;
    for (int k = 0; k < 3; k++) {
        int64_t q = silk_shr_round64(cr[k], 30);
        cr2 += (uint64_t)(q * q);
    }
    /* A 64-bit host skips the square root where the cap cannot bind, as
     * across a fine mesh's edges: x = round(sqrt(cr2)) <= 2^h for
     * cr2 < 2^2h, and the cap div_round(ld lc, 2 D x) is at least g exactly
     * when ld lc >= x D (2g - 1), D = SILK_BULGE_DIV (g > 0 here). */
    uint64_t gd = (uint64_t)SILK_BULGE_DIV * (uint64_t)(2 * g - 1);
    int h = (silk_bitlen64(cr2) + 1) / 2;
    if (SILK_CPU32 || silk_bitlen64(gd) + h > 63 || (gd << h) > (uint64_t)(ld * lc)) {
        int64_t cross30 = (int64_t)sqrt_round(cr2);    /* |dir x chord| / 2^30, < 2^33 */
        if (cross30 > 0) {
            int64_t cap = div_round(ld * lc, cross30 * 2 * SILK_BULGE_DIV);
            if (g > cap) g = cap;
        }
    }
    int64_t len = silk_shr_round64(lc * g, 29);        /* 2|chord| g, in chord's scale */
    int64_t t[3];
    for (int k = 0; k < 3; k++) t[k] = div_round(dir->c[k] * len, ld);
    return to_fx(t, chord->e);
}

silk_vec3 silk_arc_tangent(silk_vec3 dir, silk_vec3 chord)
{
    wvec c = wide(chord.x, chord.y, chord.z, 0);
    if (wide_is_zero(&c)) return silk_v3(0, 0, 0);
    wvec d = wide(dir.x, dir.y, dir.z, 0);
    if (wide_is_zero(&d)) return chord;               /* no direction: theta = 0, L = |chord| */
    int64_t lc = wlen(&c);
    return arc_tangent_wide(&d, &c, &lc);
}

/* The tilt bound (curve.h): a bridge whose end normals lean along the chord
 * by very different amounts is no circular arc (eq. 4 assumes one: equal
 * angles at both ends).  Where the normals were averaged from the faces
 * around each vertex it is, on a coarse mesh, usually a normal averaged
 * across a rounded-off crease at one end of an edge that is straight in
 * the surface, and eqs. 2-3 would bow the whole edge out by that end's lean
 * (a wing seen edge-on, by up to a tenth of its length).  So each end's
 * lean towards the chord, n.chord, is cut to at most the other end's plus
 * |chord| / SILK_TILT_SLACK before it is taken off the chord: the ends of a
 * circular arc lean alike and keep theirs, a one-sided lean gives a nearly
 * straight curve. */
void silk_bridge(silk_vec3 p0, silk_vec3 n0, silk_vec3 p1, silk_vec3 n1, int tilt_bound, silk_curve *out)
{
    out->p0 = p0;
    out->p1 = p1;
    out->n0 = n0;
    out->n1 = n1;
    silk_vec3 *t[2] = { &out->t0, &out->t1 };
    /* The chord in 64 bits: p1 - p0 may not fit Q16.16. */
    wvec c = wide((int64_t)p1.x - p0.x, (int64_t)p1.y - p0.y, (int64_t)p1.z - p0.z, 0);
    if (wide_is_zero(&c)) {
        out->t0 = out->t1 = silk_v3(0, 0, 0);
        return;
    }
    int64_t lc = wlen(&c);
    /* Eqs. 2-3: the chord projected onto the plane of each end's normal,
     * normalised here (to Q30: a normal a few ulps off unit length still
     * gives a tangent in its plane), along = chord.u taken off.  A zero
     * normal leaves the chord itself. */
    int64_t u[2][3], along[2];
    for (int i = 0; i < 2; i++) {
        silk_vec3 n = i ? n1 : n0;
        wvec w = wide(n.x, n.y, n.z, 0);
        int64_t len = wlen(&w);
        for (int k = 0; k < 3; k++) u[i][k] = len ? div_round(mul_pow2(w.c[k], 30), len) : 0;
        along[i] = silk_shr_round64(c.c[0] * u[i][0] + c.c[1] * u[i][1] + c.c[2] * u[i][2], 30);
    }
    for (int i = 0; i < 2; i++) {
        int64_t cap = silk_abs64(along[1 - i]) + lc / SILK_TILT_SLACK;
        if (tilt_bound && along[i] > cap) along[i] = cap;
        if (tilt_bound && along[i] < -cap) along[i] = -cap;
        int64_t d[3];
        for (int k = 0; k < 3; k++) d[k] = c.c[k] - silk_shr_round64(along[i] * u[i][k], 30);
        wvec w = wide(d[0], d[1], d[2], c.e);
        if (wide_is_zero(&w)) w = c;                   /* a chord along the normal: the chord */
        *t[i] = arc_tangent_wide(&w, &c, &lc);
    }
}

/* ---- eqs. 6-7: the silhouette parameter ----------------------------------- */

/* Coefficients are reduced to at most COEF_BITS bits so that h can be
 * evaluated exactly on the 2^-17 grid: |h| * 2^34 <= 2^COEF_BITS * 2^34. */
#define COEF_BITS 28
#define GRID_BITS 17

/* 2^34 h(j / 2^17) for h(u) = A (1-u)^2 + B u (1-u) + C u^2, exact: the
 * three terms are bounded by 2^28 (k + j)^2 = 2^62 together. */
static int64_t h_at(int64_t A, int64_t B, int64_t C, int64_t j)
{
    int64_t k = ((int64_t)1 << GRID_BITS) - j;
    return A * k * k + B * j * k + C * j * j;
}

/* The largest component magnitude of two vectors as one shift: both get
 * the same scale, which keeps (1-u) a + u b's zero where it is. */
static int common_shift(silk_vec3 a, silk_vec3 b)
{
    int64_t ca[3] = { a.x, a.y, a.z }, cb[3] = { b.x, b.y, b.z };
    uint64_t m = max3_abs(ca);
    if (max3_abs(cb) > m) m = max3_abs(cb);
    int s = silk_bitlen64(m) - W_BITS;
    return s > 0 ? s : 0;
}

/* v / 2^s rounded, for s >= 0 (silk_shr_round64 needs s >= 1). */
static int64_t shr_round0(int64_t v, int s) { return s ? silk_shr_round64(v, s) : v; }

static int64_t dot_shifted(silk_vec3 a, int sa, silk_vec3 b, int sb)
{
    return shr_round0(a.x, sa) * shr_round0(b.x, sb) + shr_round0(a.y, sa) * shr_round0(b.y, sb) +
           shr_round0(a.z, sa) * shr_round0(b.z, sb);
}

/* Whether the root rounds to k or below: h((k + 1/2) / 2^16) >= 0. */
static int root_at_or_below(int64_t A, int64_t B, int64_t C, int64_t k)
{
    return k >= SILK_FX_ONE || h_at(A, B, C, 2 * k + 1) >= 0;
}

/* Rounded n / d for any nonzero d. */
static int64_t div_round_signed(int64_t n, int64_t d)
{
    return d < 0 ? div_round(-n, -d) : div_round(n, d);
}

silk_fx silk_silhouette_param(silk_vec3 n0, silk_vec3 d0, silk_vec3 n1, silk_vec3 d1)
{
    /* h(u) = D(u).N(u) in Bernstein form: A = d0.n0, C = d1.n1 (the two
     * visibility tests), B = d0.n1 + d1.n0.  Exact in int64: after the
     * shifts every component has at most 30 bits. */
    int sd = common_shift(d0, d1), sn = common_shift(n0, n1);
    int64_t A = dot_shifted(d0, sd, n0, sn);
    int64_t C = dot_shifted(d1, sd, n1, sn);
    int64_t B = dot_shifted(d0, sd, n1, sn) + dot_shifted(d1, sd, n0, sn);

    if (A == 0) return 0;
    if (C == 0) return SILK_FX_ONE;
    if ((A < 0) == (C < 0)) return silk_abs64(A) <= silk_abs64(C) ? 0 : SILK_FX_ONE;
    if (A > 0) { A = -A; B = -B; C = -C; }            /* h rises through its root */

    /* One common scale for the coefficients.  Rounding must not lose the
     * sign change at the ends, so A stays <= -1 and C >= 1. */
    uint64_t m = silk_abs64(A);
    if (silk_abs64(B) > m) m = silk_abs64(B);
    if (silk_abs64(C) > m) m = silk_abs64(C);
    int s = silk_bitlen64(m) - COEF_BITS;
    if (s > 0) {
        A = silk_shr_round64(A, s);
        B = silk_shr_round64(B, s);
        C = silk_shr_round64(C, s);
        if (A == 0) A = -1;
        if (C == 0) C = 1;
    }

    /* First guess: the stable quadratic formula on a u^2 + b u + c, which
     * takes no difference of nearly equal terms: q = -(b + sign(b) sqrt(disc))/2,
     * roots c/q and q/a.  Working with 2q keeps it integral.  Only a
     * speed-up: the search below finds the same root from any guess, so a
     * board, whose square root and divisions are library calls of about
     * the cost of the search's 17 steps, keeps the code bytes instead
     * (SILK_FAST_CASES) and starts from the middle. */
    int64_t guess = -1;
    if (SILK_FAST_CASES) {
        int64_t a = A - B + C, b = B - 2 * A, c = A;   /* |a|, |b| <= 3 * 2^28 */
        int64_t disc = b * b - 4 * a * c;              /* >= 0: h changes sign on [0,1] */
        int64_t sq = disc > 0 ? (int64_t)silk_isqrt64((uint64_t)disc) : 0;
        int64_t q2 = b >= 0 ? -(b + sq) : sq - b;
        if (q2 != 0) {
            int64_t r = div_round_signed(mul_pow2(2 * c, 16), q2);      /* c / q */
            if (r >= 0 && r <= SILK_FX_ONE) guess = r;
        }
        if (guess < 0 && a != 0) {
            int64_t r = div_round_signed(mul_pow2(q2, 15), a);          /* q / a */
            if (r >= 0 && r <= SILK_FX_ONE) guess = r;
        }
    }
    if (guess < 0) guess = SILK_FX_HALF;

    /* The answer is the smallest k with h((k + 1/2) / 2^16) >= 0: the root
     * rounded to nearest.  h's sign on the 2^-17 grid is exact, so the guess
     * is checked there, with its neighbour, and corrected by bisection when
     * rounding of the coefficients or the square root put it off.
     * Invariant: lo is too small, hi is large enough. */
    int64_t lo = -1, hi = SILK_FX_ONE;
    if (root_at_or_below(A, B, C, guess)) hi = guess;
    else lo = guess;
    int64_t next = hi == guess ? guess - 1 : guess + 1;
    if (next > lo && next < hi) {
        if (root_at_or_below(A, B, C, next)) hi = next;
        else lo = next;
    }
    while (hi - lo > 1) {
        int64_t mid = lo + (hi - lo) / 2;
        if (root_at_or_below(A, B, C, mid)) hi = mid;
        else lo = mid;
    }
    return (silk_fx)hi;
}

/* ---- eq. 8: samples per silhouette segment -------------------------------- */

uint32_t silk_sample_count(silk_fx h_px, silk_fx cos_alpha, silk_fx tol_px)
{
    if (h_px <= 0) return 1;
    if (tol_px <= 0) return SILK_MAX_SAMPLES;
    silk_fx c = silk_fx_clamp(cos_alpha, -SILK_FX_ONE, SILK_FX_ONE);
    /* r = sqrt((1 - cos alpha) / 2) in Q24: (1 - c)/2 * 2^48 = (ONE - c) * 2^31. */
    uint64_t r24 = sqrt_round((uint64_t)(SILK_FX_ONE - c) << 31);
    uint64_t num = (uint64_t)h_px * r24;              /* h r in Q40, < 2^55 */
    /* n_s = ceil(sqrt(h r / e) / 2) is the least n with 4 n^2 e >= h r. */
    uint64_t x24 = silk_udiv64(num, (uint64_t)tol_px);           /* h r / e in Q24, floored: exact for the test below */
    uint64_t cap = (uint64_t)4 * SILK_MAX_SAMPLES * SILK_MAX_SAMPLES << 24;
    if (x24 >= cap) return SILK_MAX_SAMPLES;
    uint64_t n = (silk_isqrt64(x24) >> 13) + 1;       /* sqrt(x)/2, from Q12 */
    while (n > 1 && ((4 * (n - 1) * (n - 1)) << 24) >= x24) n--;
    while (((4 * n * n) << 24) < x24) n++;
    return (uint32_t)n;
}
