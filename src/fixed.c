/*
 * fixed.c - Q16.16 arithmetic that is not inline in silk/fixed.h: division,
 * square roots, trigonometry, decimal parsing and formatting, and the vector
 * operations built on them.  No paper equation of its own: these are the
 * lengths, unit vectors and angles every stage of section III needs (acos
 * for the angle-weighted normals of III-B, length and division for the
 * tangent lengths of eq. 4, rsqrt to renormalise interpolated normals).
 *
 * Integer only.  Every result is rounded to nearest (halves away from zero)
 * and saturated to +-SILK_FX_MAX; docs/fixed-point.md gives the measured
 * worst error of each function.
 */
#include <stddef.h>
#include "silk/fixed.h"
#include "compiler.h"

/* ---- small integer helpers -------------------------------------------------- */

static int clz64(uint64_t x)            /* x != 0 */
{
    return (x >> 32) ? silk_clz32((uint32_t)(x >> 32)) : 32 + silk_clz32((uint32_t)x);
}


/* INT32_MIN is outside the symmetric silk_fx range; mapping it to SILK_FX_MIN
 * keeps every product below 2^62 and every negation defined. */
static silk_fx fx_clean(silk_fx a) { return a < SILK_FX_MIN ? SILK_FX_MIN : a; }

/* Two's-complement reading of a 64-bit pattern without implementation-defined
 * conversions. */
static int64_t u64_to_s64(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(~u) - 1;
}

/* Round-to-nearest product of two Q30 numbers. */
static int64_t mul_q30(int64_t a, int64_t b) { return silk_shr_round64(a * b, 30); }

/* ---- division --------------------------------------------------------------- */

/* n/d rounded half away from zero and saturated; d == 0 gives the sign of n
 * times SILK_FX_MAX. */
static silk_fx div_round_sat(int64_t n, int64_t d)
{
    if (d == 0) return n > 0 ? SILK_FX_MAX : (n < 0 ? SILK_FX_MIN : 0);
    uint64_t un = silk_abs64(n), ud = silk_abs64(d);
    uint64_t q = silk_udiv64(un + ud / 2, ud);
    if (q > (uint64_t)SILK_FX_MAX) q = (uint64_t)SILK_FX_MAX;
    return ((n < 0) != (d < 0)) ? -(silk_fx)q : (silk_fx)q;
}

/* Knuth's algorithm D for two digits of 16 bits (Hacker's Delight, divlu):
 * d is normalised so its top bit is set, then each quotient digit is
 * estimated from the top digit of d and corrected at most twice. */
uint32_t silk_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem)
{
    int s = silk_clz32(d);
    d <<= s;
    uint64_t ns = n << s;                        /* n < d 2^32: nothing leaves the top */
    uint32_t hi = (uint32_t)(ns >> 32), lo = (uint32_t)ns;
    uint32_t dh = d >> 16, dl = d & 0xFFFF, q[2];
    for (int i = 0; i < 2; i++) {
        uint32_t digit = i ? lo & 0xFFFF : lo >> 16;
        uint32_t qd = hi / dh, rh = hi - qd * dh;
        while (qd > 0xFFFF || qd * dl > (rh << 16 | digit)) {
            qd--;
            rh += dh;
            if (rh > 0xFFFF) break;
        }
        q[i] = qd;
        hi = (hi << 16 | digit) - qd * d;        /* the partial remainder, < d */
    }
    if (rem) *rem = hi >> s;
    return q[0] << 16 | q[1];
}

uint64_t silk_udiv64_cpu32(uint64_t n, uint64_t d)
{
    if (d >> 32) return n / d;
    uint32_t d32 = (uint32_t)d, hi = (uint32_t)(n >> 32);
    if (!hi) return (uint32_t)n / d32;
    if (hi < d32) return silk_udiv64_32(n, d32, NULL);
    /* the high word's quotient, then the rest: (hi % d) 2^32 + lo < d 2^32 */
    return (uint64_t)(hi / d32) << 32 | silk_udiv64_32((uint64_t)(hi % d32) << 32 | (uint32_t)n, d32, NULL);
}

silk_fx silk_fx_div(silk_fx a, silk_fx b) { return div_round_sat((int64_t)a * 65536, b); }

silk_fx silk_fx_muldiv(silk_fx a, silk_fx b, silk_fx c) { return div_round_sat((int64_t)a * b, c); }

silk_fx silk_fx_recip(silk_fx a) { return div_round_sat((int64_t)1 << 32, a); }

/* ---- square roots ----------------------------------------------------------- */

/* 1/sqrt(M) in Q16 at the centre of each of 192 slices of M in [1, 4):
 * slice i covers [i/64, (i+1)/64) for i = 64..255. */
const uint16_t silk_rsqrt_seed[192] = {
    65281, 64781, 64292, 63814, 63347, 62889, 62442, 62004, 61575, 61154, 60742, 60339,
    59943, 59555, 59175, 58801, 58435, 58075, 57722, 57376, 57035, 56700, 56372, 56049,
    55731, 55419, 55112, 54810, 54513, 54221, 53933, 53650, 53371, 53097, 52826, 52560,
    52298, 52040, 51785, 51535, 51288, 51044, 50804, 50567, 50333, 50103, 49876, 49652,
    49430, 49212, 48997, 48784, 48574, 48367, 48163, 47961, 47761, 47564, 47370, 47178,
    46988, 46800, 46615, 46432, 46251, 46072, 45895, 45720, 45547, 45376, 45207, 45040,
    44875, 44711, 44550, 44390, 44232, 44075, 43920, 43767, 43615, 43465, 43316, 43169,
    43024, 42879, 42737, 42595, 42456, 42317, 42180, 42044, 41910, 41776, 41644, 41514,
    41384, 41256, 41129, 41003, 40878, 40754, 40631, 40510, 40390, 40270, 40152, 40035,
    39919, 39803, 39689, 39576, 39464, 39352, 39242, 39133, 39024, 38916, 38810, 38704,
    38599, 38494, 38391, 38289, 38187, 38086, 37986, 37887, 37788, 37690, 37593, 37497,
    37401, 37307, 37213, 37119, 37027, 36935, 36843, 36753, 36663, 36573, 36485, 36397,
    36309, 36222, 36136, 36051, 35966, 35882, 35798, 35715, 35632, 35550, 35469, 35388,
    35307, 35228, 35148, 35070, 34991, 34914, 34837, 34760, 34684, 34608, 34533, 34458,
    34384, 34310, 34237, 34164, 34092, 34020, 33949, 33878, 33807, 33737, 33668, 33599,
    33530, 33461, 33393, 33326, 33259, 33192, 33126, 33060, 32994, 32929, 32864, 32800,
};

/* For m in [2^30, 2^32), i.e. M = m/2^30 in [1, 4): 1/sqrt(M) in Q31.  The
 * table gives 9 bits; two Newton steps y' = y(3 - M y^2)/2 bring it within
 * 2.6 units of 2^-31 (measured over all m), and callers finish with an exact
 * integer correction. */
static uint32_t rsqrt_q31(uint32_t m)
{
    uint32_t y = (uint32_t)silk_rsqrt_seed[(m >> 24) - 64] << 15;
    for (int i = 0; i < 2; i++) {
        uint32_t y2 = (uint32_t)(((uint64_t)y * y) >> 32);          /* Q30 */
        uint32_t my2 = (uint32_t)(((uint64_t)m * y2) >> 30);       /* Q30, ~1 */
        y = (uint32_t)(((uint64_t)y * (3u * (1u << 30) - my2)) >> 31);
    }
    return y;
}

uint32_t silk_isqrt32(uint32_t v)
{
    if (v == 0) return 0;
    int e = silk_clz32(v) & ~1;              /* even, so sqrt(2^e) is a shift */
    uint32_t m = v << e;
    /* sqrt(v) = 2^15 sqrt(M) / 2^(e/2) and sqrt(M) = M / sqrt(M) */
    uint64_t r = ((uint64_t)m * rsqrt_q31(m)) >> (46 + e / 2);
    while (r * r > v) r--;
    while ((r + 1) * (r + 1) <= v) r++;
    return (uint32_t)r;
}

uint32_t silk_isqrt64(uint64_t v)
{
    if (v >> 32 == 0) return silk_isqrt32((uint32_t)v);
    int e = clz64(v) & ~1;
    uint32_t m = (uint32_t)((v << e) >> 32);
    uint32_t y = rsqrt_q31(m);
    uint64_t r = ((uint64_t)m * y) >> (30 + e / 2);
    /* 32 bits of m and y leave r a few units off; one Newton step on the
     * residual, sqrt(v) - r ~ (v - r^2) / (2 sqrt v) with 1/(2 sqrt v) =
     * y 2^(e/2 - 63), brings it to +-1 for the final exact steps. */
    if (r > 0xFFFFFFFFu) r = 0xFFFFFFFFu;
    int64_t d = u64_to_s64(v - r * r);                      /* |d| < 2^38 */
    r = (uint64_t)((int64_t)r + silk_shr_round64(d * (int64_t)(y >> 16), 47 - e / 2));
    if (r > 0xFFFFFFFFu) r = 0xFFFFFFFFu;
    while (r * r > v) r--;
    while (r < 0xFFFFFFFFu && (r + 1) * (r + 1) <= v) r++;
    return (uint32_t)r;
}

/* round(sqrt(v)): r is right when r^2 - r < v <= r^2 + r (there are no
 * ties).  silk_fx_sqrt below uses the same test. */
static uint32_t isqrt64_round(uint64_t v)
{
    uint64_t r = silk_isqrt64(v);
    return (uint32_t)(v - r * r > r ? r + 1 : r);
}

silk_fx silk_fx_sqrt(silk_fx a)
{
    if (a <= 0) return 0;
    int e = silk_clz32((uint32_t)a) & ~1;
    uint32_t m = (uint32_t)a << e;
    uint64_t v = (uint64_t)a << 16;     /* sqrt(a / 2^16) * 2^16 = sqrt(a * 2^16) */
    int sh = 38 + e / 2;
    uint64_t r = ((uint64_t)m * rsqrt_q31(m) + ((uint64_t)1 << (sh - 1))) >> sh;
    /* r is within 1 of round(sqrt(v)) (checked for every input, see
     * docs/fixed-point.md); make it exact without branches.  r >= 256. */
    r += v > r * r + r;
    r -= v <= r * r - r;
    return (silk_fx)r;
}

silk_fx silk_fx_rsqrt(silk_fx a)
{
    if (a <= 0) return SILK_FX_MAX;
    int e = silk_clz32((uint32_t)a) & ~1;
    uint32_t m = (uint32_t)a << e;
    /* result 2^24 / sqrt(a) = 2^(9 + e/2) / sqrt(M) */
    int sh = 22 - e / 2;
    uint64_t r = (rsqrt_q31(m) + ((uint64_t)1 << (sh - 1))) >> sh;
    /* r is within 1 of the rounded result (checked for every input); the
     * exact test is (r - 1/2)^2 a <= 2^48 < (r + 1/2)^2 a, times 4.  Without
     * branches: this runs per pixel and mispredictions would double its cost. */
    const uint64_t lim = (uint64_t)1 << 50;
    r += (2 * r + 1) * (2 * r + 1) * (uint64_t)a <= lim;
    r -= (2 * r - 1) * (2 * r - 1) * (uint64_t)a > lim;
    return (silk_fx)r;
}

/* ---- trigonometry ----------------------------------------------------------- */

/* 2^64 per turn: an angle becomes a phase whose wrap-around is the period, so
 * range reduction is one multiplication modulo 2^64, exact to 2^-34 turns for
 * every input. */
#define PHASE_PER_RAD_Q16 UINT64_C(44798133900177)   /* 2^48 / (2 pi) */
#define PHASE_PER_DEG_Q16 UINT64_C(781874935307)     /* 2^48 / 360 */

#define TWO_PI_Q30  (2 * SILK_PI_Q30)
#define HALF_PI_Q30 (SILK_PI_Q30 / 2)
#define QUARTER_PI_Q30 ((SILK_PI_Q30 + 2) / 4)
#define TAN_PI_8_Q30   INT64_C(444758426)

/* sin and cos of a phase (Q64 turns).  Reduced to the nearest quarter turn,
 * |x| <= pi/4, where Taylor series to x^9 / x^10 are exact to 2e-9 and the
 * Q30 arithmetic adds a few 2^-30. */
static void sincos_phase(uint64_t phase, silk_fx *s, silk_fx *c)
{
    uint64_t q = (phase + ((uint64_t)1 << 61)) >> 62;
    int64_t f = u64_to_s64(phase - (q << 62));                      /* [-2^61, 2^61) */
    int64_t x = silk_shr_round64(silk_shr_round64(f, 32) * TWO_PI_Q30, 32); /* Q30 rad */
    int64_t x2 = mul_q30(x, x);

    int64_t p = 2959;                               /* 1/9! in Q30 */
    p = 213044 - mul_q30(x2, p);                    /* 1/7! */
    p = 8947849 - mul_q30(x2, p);                   /* 1/5! */
    p = 178956971 - mul_q30(x2, p);                 /* 1/3! */
    p = (INT64_C(1) << 30) - mul_q30(x2, p);
    int64_t sv = mul_q30(x, p);

    p = 296;                                        /* 1/10! */
    p = 26631 - mul_q30(x2, p);                     /* 1/8! */
    p = 1491308 - mul_q30(x2, p);                   /* 1/6! */
    p = 44739243 - mul_q30(x2, p);                  /* 1/4! */
    p = 536870912 - mul_q30(x2, p);                 /* 1/2! */
    int64_t cv = (INT64_C(1) << 30) - mul_q30(x2, p);

    silk_fx si = (silk_fx)silk_shr_round64(sv, 14);
    silk_fx co = (silk_fx)silk_shr_round64(cv, 14);
    silk_fx rs, rc;
    switch (q & 3) {
    case 0: rs = si; rc = co; break;
    case 1: rs = co; rc = -si; break;
    case 2: rs = -si; rc = -co; break;
    default: rs = -co; rc = si; break;
    }
    if (s) *s = rs;
    if (c) *c = rc;
}

void silk_fx_sincos(silk_fx rad, silk_fx *s, silk_fx *c)
{
    sincos_phase((uint64_t)(int64_t)rad * PHASE_PER_RAD_Q16, s, c);
}

void silk_fx_sincos_deg(silk_fx deg, silk_fx *s, silk_fx *c)
{
    sincos_phase((uint64_t)(int64_t)deg * PHASE_PER_DEG_Q16, s, c);
}

/* atan(u) for |u| <= tan(pi/8), Q30: the series to u^15 leaves < 2e-8. */
static int64_t atan_q30(int64_t u)
{
    static const int32_t inv_odd[8] = {   /* 1/(2k+1) in Q30 */
        1073741824, 357913941, 214748365, 153391689,
        119304647, 97612893, 82595525, 71582788,
    };
    int64_t u2 = mul_q30(u, u);
    int64_t p = inv_odd[7];
    for (int k = 6; k >= 0; k--) p = inv_odd[k] - mul_q30(u2, p);
    return mul_q30(u, p);
}

/* Angle of (x, y) in Q30 radians for |x|, |y| <= 2^31 in any common scale.
 * The octant is folded away, then angles above pi/8 use
 * atan(t) = pi/4 + atan((t - 1) / (t + 1)) so the series argument stays small. */
static int64_t atan2_q30(int64_t y, int64_t x)
{
    uint64_t ay = silk_abs64(y), ax = silk_abs64(x);
    if (ax == 0 && ay == 0) return 0;
    uint64_t lo = ay < ax ? ay : ax, hi = ay < ax ? ax : ay;
    int64_t a;
    if (lo << 30 <= hi * (uint64_t)TAN_PI_8_Q30) {
        a = (int64_t)(((lo << 30) + hi / 2) / hi);
        a = atan_q30(a);
    } else {
        uint64_t d = lo + hi;
        a = -(int64_t)((((hi - lo) << 30) + d / 2) / d);
        a = QUARTER_PI_Q30 + atan_q30(a);
    }
    if (ay > ax) a = HALF_PI_Q30 - a;
    if (x < 0) a = SILK_PI_Q30 - a;
    return y < 0 ? -a : a;
}

silk_fx silk_fx_atan2(silk_fx y, silk_fx x)
{
    return (silk_fx)silk_shr_round64(atan2_q30(y, x), 14);
}

silk_fx silk_fx_acos(silk_fx x)
{
    x = silk_fx_clamp(x, -SILK_FX_ONE, SILK_FX_ONE);
    /* acos x = atan2(sqrt(1 - x^2), x), both sides in Q31 so that the steep
     * ends near +-1 keep their precision: (1-x)(1+x) is exact in Q32. */
    uint64_t one_minus_x2 = (uint64_t)(SILK_FX_ONE - x) * (uint64_t)(SILK_FX_ONE + x);
    int64_t sy = isqrt64_round(one_minus_x2 << 30);
    return (silk_fx)silk_shr_round64(atan2_q30(sy, (int64_t)x * 32768), 14);
}

/* ---- decimal text ----------------------------------------------------------- */

#define DEC_DIGITS 18
#define DEC_LIMIT UINT64_C(1000000000000000000)   /* 10^18 */
#define DEC_EXP_MAX 400

/* A 128-bit unsigned integer for the few places where 18 digits times 18
 * digits, or 18 digits times 2^17, must stay exact. */
typedef struct u128 { uint64_t hi, lo; } u128;

static u128 mul_64x64(uint64_t a, uint64_t b)
{
    uint64_t al = (uint32_t)a, ah = a >> 32, bl = (uint32_t)b, bh = b >> 32;
    uint64_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint64_t mid = (ll >> 32) + (uint32_t)lh + (uint32_t)hl;
    u128 r;
    r.lo = (mid << 32) | (uint32_t)ll;
    r.hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
    return r;
}

/* x /= 10 (floor); returns the remainder. */
static unsigned div10_u128(u128 *x)
{
    uint32_t limb[4] = { (uint32_t)(x->hi >> 32), (uint32_t)x->hi,
                         (uint32_t)(x->lo >> 32), (uint32_t)x->lo };
    uint64_t rem = 0;
    for (int i = 0; i < 4; i++) {
        uint64_t cur = (rem << 32) | limb[i];
        limb[i] = (uint32_t)(cur / 10);
        rem = cur % 10;
    }
    x->hi = ((uint64_t)limb[0] << 32) | limb[1];
    x->lo = ((uint64_t)limb[2] << 32) | limb[3];
    return (unsigned)rem;
}

static int is_digit(char c) { return (unsigned)(c - '0') < 10u; }

/* The shared scanner: sign, digits, '.', digits, exponent.  Keeps the first
 * 18 significant digits (truncating the rest, whose count still moves the
 * exponent) and returns 0, or -1 when the text is not a number.  The
 * mantissa comes back without trailing zeros; zero is 0 * 10^0. */
static int scan_decimal(const char *s, const char **end, int *neg, uint64_t *mant, int64_t *exp)
{
    const char *p = s;
    uint64_t m = 0;
    int64_t e = 0;
    int ndigits = 0, nsig = 0, frac = 0;

    *neg = (*p == '-');
    if (*p == '+' || *p == '-') p++;
    for (;; p++) {
        if (*p == '.' && !frac) { frac = 1; continue; }
        if (!is_digit(*p)) break;
        int d = *p - '0';
        ndigits++;
        if (m == 0 && d == 0) {
            e -= frac;                      /* leading zero: not significant */
        } else if (nsig < DEC_DIGITS) {
            m = m * 10 + (uint64_t)d;
            nsig++;
            e -= frac;
        } else {
            e += !frac;                     /* dropped digit left of the point */
        }
    }
    if (ndigits == 0) return -1;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        int eneg = (*q == '-');
        if (*q == '+' || *q == '-') q++;
        if (!is_digit(*q)) return -1;
        int64_t ev = 0;
        for (; is_digit(*q); q++)
            if (ev < 1000000) ev = ev * 10 + (*q - '0');   /* beyond that it is out of range anyway */
        e += eneg ? -ev : ev;
        p = q;
    }
    while (m != 0 && m % 10 == 0) { m /= 10; e++; }
    if (m == 0) e = 0;
    *mant = m;
    *exp = e;
    if (end) *end = p;
    return 0;
}

int silk_decimal_parse(const char *s, const char **end, silk_decimal *out)
{
    int neg;
    uint64_t m;
    int64_t e;
    if (end) *end = s;
    if (scan_decimal(s, end, &neg, &m, &e) != 0) return -1;
    if (e > DEC_EXP_MAX || e < -DEC_EXP_MAX) return -2;
    out->mant = neg ? -(int64_t)m : (int64_t)m;
    out->exp10 = (int32_t)e;
    return 0;
}

silk_decimal silk_decimal_mul(silk_decimal a, silk_decimal b)
{
    silk_decimal r = { 0, 0 };
    if (a.mant == 0 || b.mant == 0) return r;
    u128 p = mul_64x64(silk_abs64(a.mant), silk_abs64(b.mant));
    int64_t e = (int64_t)a.exp10 + b.exp10;
    unsigned last = 0;
    while (p.hi != 0 || p.lo >= DEC_LIMIT) { last = div10_u128(&p); e++; }
    uint64_t m = p.lo + (last >= 5);         /* the first dropped digit rounds */
    while (m % 10 == 0) { m /= 10; e++; }    /* also takes a carry to 10^18 back to 1 */
    /* keep the exponent far from int32 overflow; such values are out of any range */
    if (e > INT32_MAX / 2) e = INT32_MAX / 2;
    if (e < -(INT32_MAX / 2)) e = -(INT32_MAX / 2);
    r.mant = ((a.mant < 0) != (b.mant < 0)) ? -(int64_t)m : (int64_t)m;
    r.exp10 = (int32_t)e;
    return r;
}

/* round(m * 10^e * 2^16): 0 and *q, or -2 when it exceeds
 * SILK_FX_MAX. */
static int decimal_to_q16(uint64_t m, int64_t e, uint32_t *q)
{
    if (m == 0) { *q = 0; return 0; }
    if (e >= 0) {
        for (; e > 0; e--) {
            if (m > 32767) return -2;
            m *= 10;
        }
        if (m > 32767) return -2;
        *q = (uint32_t)(m << 16);
        return 0;
    }
    if (e < -40) { *q = 0; return 0; }      /* 2^64 * 2^16 / 10^40 is far below 0.5 ulp */
    /* floor(2 m 2^16 / 10^k), then halve with rounding: a chain of floor
     * divisions equals one floor division, so the result is exact. */
    u128 n = mul_64x64(m, (uint64_t)1 << 17);
    for (; e < 0 && n.hi != 0; e++) div10_u128(&n);
    if (n.hi != 0) return -2;
    uint64_t f = n.lo;
    for (; e < 0; e++) f /= 10;
    f = (f + 1) >> 1;
    if (f > (uint64_t)SILK_FX_MAX) return -2;
    *q = (uint32_t)f;
    return 0;
}

int silk_decimal_to_fx(silk_decimal d, silk_fx *out)
{
    uint32_t q;
    if (decimal_to_q16(silk_abs64(d.mant), d.exp10, &q) != 0) return -2;
    *out = d.mant < 0 ? -(silk_fx)q : (silk_fx)q;
    return 0;
}

int silk_fx_parse(const char *s, const char **end, silk_fx *out)
{
    int neg;
    uint64_t m;
    int64_t e;
    uint32_t q;
    if (end) *end = s;
    if (scan_decimal(s, end, &neg, &m, &e) != 0) return -1;
    if (decimal_to_q16(m, e, &q) != 0) return -2;
    *out = neg ? -(silk_fx)q : (silk_fx)q;
    return 0;
}

char *silk_fx_format(silk_fx v, char *buf)
{
    char *p = buf;
    int64_t a = v;
    if (a < 0) { *p++ = '-'; a = -a; }
    /* 5 decimals are within 0.33 ulp, so parsing the text gives v back */
    uint32_t ip = (uint32_t)(a >> 16);
    uint32_t dec = (uint32_t)(((a & 0xFFFF) * 100000 + 32768) >> 16);
    if (dec == 100000) { ip++; dec = 0; }
    char tmp[12];
    int n = 0;
    do { tmp[n++] = (char)('0' + ip % 10); ip /= 10; } while (ip);
    while (n) *p++ = tmp[--n];
    if (dec) {
        *p++ = '.';
        for (uint32_t div = 10000; div && dec; div /= 10) {
            *p++ = (char)('0' + dec / div);
            dec %= div;
        }
    }
    *p = '\0';
    return buf;
}

/* ---- vectors ---------------------------------------------------------------- */

/* a*b - c*d in Q16.16, from exact 64-bit products (inputs cleaned, so the
 * difference stays below 2^63). */
static silk_fx cross_term(silk_fx a, silk_fx b, silk_fx c, silk_fx d)
{
    int64_t v = (int64_t)fx_clean(a) * fx_clean(b) - (int64_t)fx_clean(c) * fx_clean(d);
    return silk_fx_sat(silk_shr_round64(v, 16));
}

silk_vec3 silk_v3_cross(silk_vec3 a, silk_vec3 b)
{
    return silk_v3(cross_term(a.y, b.z, a.z, b.y),
                   cross_term(a.z, b.x, a.x, b.z),
                   cross_term(a.x, b.y, a.y, b.x));
}

silk_fx silk_v3_length(silk_vec3 a)
{
    uint64_t x = silk_abs64(a.x), y = silk_abs64(a.y), z = silk_abs64(a.z);
    uint32_t r = isqrt64_round(x * x + y * y + z * z);     /* < 3 * 2^62: fits */
    return r > (uint32_t)SILK_FX_MAX ? SILK_FX_MAX : (silk_fx)r;
}

int silk_unit_fx(silk_fx x, silk_fx y, silk_fx z, int32_t out[3])
{
    uint32_t ux = x < 0 ? 0u - (uint32_t)x : (uint32_t)x, uy = y < 0 ? 0u - (uint32_t)y : (uint32_t)y,
             uz = z < 0 ? 0u - (uint32_t)z : (uint32_t)z;
    uint64_t ss = (uint64_t)ux * ux + (uint64_t)uy * uy + (uint64_t)uz * uz;
    if (ss == 0) { out[0] = out[1] = out[2] = 0; return 0; }
    int rs;
    uint32_t r = silk_rsqrt_ss(ss, &rs);
    uint64_t half = (uint64_t)1 << (rs - 1);
    int32_t nx = (int32_t)(((uint64_t)ux * r + half) >> rs), ny = (int32_t)(((uint64_t)uy * r + half) >> rs),
            nz = (int32_t)(((uint64_t)uz * r + half) >> rs);
    out[0] = x < 0 ? -nx : nx;
    out[1] = y < 0 ? -ny : ny;
    out[2] = z < 0 ? -nz : nz;
    return 1;
}

int silk_v3_normalize(silk_vec3 a, silk_vec3 *out)
{
    /* silk_unit64's work (silk/fixed.h): rescaling shifts ss left by an
     * even e to [2^62, 2^64), which scales the vector by 2^(e/2), so a
     * vector of 1-ulp components keeps as many bits as a huge one; then
     * 1/sqrt(ss) from the top 32 bits with relative error below 3e-9: 2e-4
     * ulp on a unit component. */
    int32_t u[3];
    int ok = silk_unit_fx(fx_clean(a.x), fx_clean(a.y), fx_clean(a.z), u);
    *out = silk_v3(u[0], u[1], u[2]);
    return ok;
}

silk_vec3 silk_v3_lerp(silk_vec3 a, silk_vec3 b, silk_fx t)
{
    return silk_v3(silk_fx_sat(a.x + silk_shr_round64(((int64_t)b.x - a.x) * t, 16)),
                   silk_fx_sat(a.y + silk_shr_round64(((int64_t)b.y - a.y) * t, 16)),
                   silk_fx_sat(a.z + silk_shr_round64(((int64_t)b.z - a.z) * t, 16)));
}
