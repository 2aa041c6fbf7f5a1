/*
 * test_fixed.c - the fixed-point library against a double-precision
 * reference.  Each property test draws >= 100000 inputs over the whole
 * documented range (edge values, tiny and huge magnitudes included), checks
 * a stated worst error in ulp (1 ulp = 2^-16) and prints the worst error it
 * measured; docs/fixed-point.md quotes these numbers.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "silk/fixed.h"

#define N_RANDOM 200000
#define ULP 65536.0
/* slack for the double reference's own rounding (|x| < 2^31 ulp, 2^-53 relative) */
#define REF_EPS 1e-6

static double fx_d(silk_fx a) { return a / ULP; }

/* the ideal result in ulp, clamped like silk_fx_sat */
static double sat_ulp(double v)
{
    if (v > SILK_FX_MAX) return SILK_FX_MAX;
    if (v < SILK_FX_MIN) return SILK_FX_MIN;
    return v;
}

static const silk_fx edge_values[] = {
    0, 1, -1, 2, -2, 3, 255, 256, 32767, 32768, -32768, 65535, 65536, -65536, 65537,
    98304, 131072, -131072, 1 << 20, -(1 << 20), 1 << 24, 1 << 30, -(1 << 30),
    SILK_FX_MAX, SILK_FX_MIN, SILK_FX_MAX - 1, SILK_FX_MIN + 1, 23170 << 16, 181 << 16,
};
#define N_EDGE ((int)(sizeof edge_values / sizeof edge_values[0]))

/* Any silk_fx: a quarter uniform over the whole range, half log-uniform in
 * magnitude (1 ulp .. 32768), a quarter edge values. */
static silk_fx rand_fx(void)
{
    unsigned long long r = check_rand64();
    switch (r & 3) {
    case 0:
        return (silk_fx)floor(check_uniform(SILK_FX_MIN, (double)SILK_FX_MAX + 1.0));
    case 1:
    case 2: {
        double mag = floor(pow(2.0, check_uniform(0.0, 31.0)));
        return (silk_fx)((r & 4) ? -mag : mag);
    }
    default:
        return edge_values[(r >> 8) % N_EDGE];
    }
}

/* A magnitude-limited silk_fx: |v| < 2^bits ulp, log-uniform. */
static silk_fx rand_fx_bits(double bits)
{
    double mag = floor(pow(2.0, check_uniform(0.0, bits)));
    return (silk_fx)((check_rand64() & 1) ? -mag : mag);
}

/* (Draws one per statement: the order of arguments and initialisers is
 * unspecified, and the sequence must not depend on the compiler.) */
static silk_vec3 rand_v3_bits(double bits)
{
    silk_fx x = rand_fx_bits(bits);
    silk_fx y = rand_fx_bits(bits);
    silk_fx z = rand_fx_bits(bits);
    return silk_v3(x, y, z);
}

static silk_vec3 rand_v3_any(void)
{
    silk_fx x = rand_fx();
    silk_fx y = rand_fx();
    silk_fx z = rand_fx();
    return silk_v3(x, y, z);
}

static silk_vec3 rand_v3(void)
{
    /* one common scale for the three components, so directions vary widely */
    silk_vec3 v = rand_v3_bits(check_uniform(1.0, 31.0));
    if ((check_rand64() & 7) == 0) v.x = 0;
    return v;
}

/* ---- arithmetic ---------------------------------------------------------- */

TEST(test_mul)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = rand_fx(), b = rand_fx();
        double ref = sat_ulp((double)a * (double)b / ULP);
        double err = fabs(silk_fx_mul(a, b) - ref);
        if (err > worst) worst = err;
    }
    printf("  mul: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_fx_mul(SILK_FX_C(3, 2), SILK_FX_C(-5, 2)) == SILK_FX_C(-15, 4));
    CHECK(silk_fx_mul(1, SILK_FX_HALF) == 1);     /* 0.5 ulp: away from zero */
    CHECK(silk_fx_mul(-1, SILK_FX_HALF) == -1);
}

TEST(test_div)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = rand_fx(), b = rand_fx();
        if (b == 0) continue;
        double ref = sat_ulp((double)a * ULP / (double)b);
        double err = fabs(silk_fx_div(a, b) - ref);
        if (err > worst) worst = err;
    }
    printf("  div: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_fx_div(SILK_FX_ONE, 3 * SILK_FX_ONE) == 21845);
    CHECK(silk_fx_div(2 * SILK_FX_ONE, 3 * SILK_FX_ONE) == 43691);
    CHECK(silk_fx_div(-2 * SILK_FX_ONE, 3 * SILK_FX_ONE) == -43691);
}

TEST(test_muldiv)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = rand_fx(), b = rand_fx(), c = rand_fx();
        if (c == 0) continue;
        double ref = sat_ulp((double)a * (double)b / (double)c);
        double err = fabs(silk_fx_muldiv(a, b, c) - ref);
        if (err > worst) worst = err;
    }
    printf("  muldiv: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    /* the product's low bits survive: (1 ulp * 1 ulp) / 1 ulp == 1 ulp */
    CHECK(silk_fx_muldiv(1, 1, 1) == 1);
    CHECK(silk_fx_muldiv(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MAX) == SILK_FX_MAX);
}

TEST(test_recip)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = rand_fx();
        if (a == 0) continue;
        double ref = sat_ulp(ULP * ULP / (double)a);
        double err = fabs(silk_fx_recip(a) - ref);
        if (err > worst) worst = err;
    }
    printf("  recip: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_fx_recip(SILK_FX_C(1, 4)) == 4 * SILK_FX_ONE);
}

TEST(test_saturation)
{
    const silk_fx MX = SILK_FX_MAX, MN = SILK_FX_MIN, ONE = SILK_FX_ONE;
    CHECK(silk_fx_add(MX, 1) == MX);
    CHECK(silk_fx_add(MX, MX) == MX);
    CHECK(silk_fx_add(MN, -1) == MN);
    CHECK(silk_fx_sub(MN, 1) == MN);
    CHECK(silk_fx_sub(MX, MN) == MX);
    CHECK(silk_fx_sub(MN, MX) == MN);
    CHECK(silk_fx_mul(MX, 2 * ONE) == MX);
    CHECK(silk_fx_mul(MN, 2 * ONE) == MN);
    CHECK(silk_fx_mul(MX, MN) == MN);
    CHECK(silk_fx_mul(MN, MN) == MX);
    CHECK(silk_fx_mul(200 * ONE, 200 * ONE) == MX);
    CHECK(silk_fx_mul(-200 * ONE, 200 * ONE) == MN);
    CHECK(silk_fx_div(1000 * ONE, 1) == MX);
    CHECK(silk_fx_div(-1000 * ONE, 1) == MN);
    CHECK(silk_fx_div(MX, -1) == MN);
    CHECK(silk_fx_div(5, 0) == MX);
    CHECK(silk_fx_div(-5, 0) == MN);
    CHECK(silk_fx_div(0, 0) == 0);
    CHECK(silk_fx_muldiv(ONE, ONE, 0) == MX);
    CHECK(silk_fx_muldiv(-ONE, ONE, 0) == MN);
    CHECK(silk_fx_muldiv(0, ONE, 0) == 0);
    CHECK(silk_fx_muldiv(MX, MX, 1) == MX);
    CHECK(silk_fx_muldiv(MX, MN, 1) == MN);
    CHECK(silk_fx_recip(0) == MX);
    CHECK(silk_fx_recip(1) == MX);
    CHECK(silk_fx_recip(-1) == MN);
    CHECK(silk_fx_from_int(40000) == MX);
    CHECK(silk_fx_from_int(-40000) == MN);
    CHECK(silk_fx_rsqrt(0) == MX);
    CHECK(silk_fx_rsqrt(-ONE) == MX);
    CHECK(silk_fx_sqrt(-ONE) == 0);
    /* INT32_MIN is outside the range but must not wrap either */
    CHECK(silk_fx_mul(INT32_MIN, ONE) == MN);
    CHECK(silk_fx_div(INT32_MIN, ONE) == MN);
    CHECK(silk_fx_div(INT32_MIN, -ONE) == MX);

    silk_vec3 big = silk_v3(MX, MX, MX), nbig = silk_v3(MN, MN, MN);
    silk_vec3 s = silk_v3_add(big, big);
    CHECK(s.x == MX && s.y == MX && s.z == MX);
    s = silk_v3_sub(nbig, big);
    CHECK(s.x == MN && s.y == MN && s.z == MN);
    CHECK(silk_v3_length(big) == MX);
    /* dot64 is exact while the sum fits int64: two full-size terms do */
    CHECK(silk_v3_dot(silk_v3(MX, MX, 0), silk_v3(MX, MX, 0)) == MX);
    CHECK(silk_v3_dot(silk_v3(MX, MN, 0), silk_v3(MX, MX, 0)) == 0);
    silk_vec3 c = silk_v3_cross(silk_v3(MX, 0, 0), silk_v3(0, MX, 0));
    CHECK(c.x == 0 && c.y == 0 && c.z == MX);
    c = silk_v3_cross(silk_v3(MX, MN, 0), silk_v3(MX, MX, 0));     /* z = MX*MX + MX*MX */
    CHECK(c.z == MX);
    c = silk_v3_cross(silk_v3(INT32_MIN, INT32_MIN, 0), silk_v3(INT32_MIN, INT32_MAX, 0));
    CHECK(c.z == MN);
    silk_vec3 l = silk_v3_lerp(silk_v3(0, 0, 0), big, 4 * ONE);  /* extrapolation */
    CHECK(l.x == MX && l.y == MX && l.z == MX);
    l = silk_v3_lerp(big, nbig, 4 * ONE);
    CHECK(l.x == MN && l.y == MN && l.z == MN);
    l = silk_v3_lerp(nbig, big, MN);
    CHECK(l.x == MN);
}

/* ---- square roots -------------------------------------------------------- */

TEST(test_sqrt)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = silk_fx_abs(rand_fx());
        double ref = sqrt(fx_d(a)) * ULP;
        double err = fabs(silk_fx_sqrt(a) - ref);
        if (err > worst) worst = err;
    }
    /* every input in the first 2^20 ulp, where sqrt is steepest */
    for (silk_fx a = 0; a < (1 << 20); a++) {
        double err = fabs(silk_fx_sqrt(a) - sqrt(fx_d(a)) * ULP);
        if (err > worst) worst = err;
    }
    printf("  sqrt: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_fx_sqrt(0) == 0);
    CHECK(silk_fx_sqrt(SILK_FX_ONE) == SILK_FX_ONE);
    CHECK(silk_fx_sqrt(4 * SILK_FX_ONE) == 2 * SILK_FX_ONE);
    CHECK(silk_fx_sqrt(1) == 256);
    CHECK(silk_fx_sqrt(SILK_FX_MAX) == 11863283);   /* sqrt(32768) * 65536 = 11863283.2 */
}

TEST(test_rsqrt)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = silk_fx_abs(rand_fx());
        if (a == 0) continue;
        double ref = ULP / sqrt(fx_d(a));
        double err = fabs(silk_fx_rsqrt(a) - ref);
        if (err > worst) worst = err;
    }
    /* the per-pixel case: squared lengths of interpolated unit normals, 0.25 .. 1.5 */
    for (silk_fx a = SILK_FX_ONE / 4; a < SILK_FX_C(3, 2); a++) {
        double err = fabs(silk_fx_rsqrt(a) - ULP / sqrt(fx_d(a)));
        if (err > worst) worst = err;
    }
    printf("  rsqrt: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_fx_rsqrt(SILK_FX_ONE) == SILK_FX_ONE);
    CHECK(silk_fx_rsqrt(4 * SILK_FX_ONE) == SILK_FX_HALF);
    CHECK(silk_fx_rsqrt(1) == 256 * SILK_FX_ONE);
    CHECK(silk_fx_rsqrt(SILK_FX_MAX) == 362);
}

static int isqrt32_ok(uint32_t v, uint32_t r)
{
    return (uint64_t)r * r <= v && ((uint64_t)r + 1) * ((uint64_t)r + 1) > v;
}

static int isqrt64_ok(uint64_t v, uint32_t r)
{
    /* r^2 <= v < (r+1)^2, without overflowing at r = 2^32 - 1 */
    if ((uint64_t)r * r > v) return 0;
    if (r == UINT32_MAX) return 1;
    return ((uint64_t)r + 1) * ((uint64_t)r + 1) > v;
}

/* silk_udiv64_32 against the plain 64-bit division: random divisors of
 * every length with random numerators below d 2^32, the quotients the
 * rasterizer asks for (2^61 / d, its depths and reciprocals), and the cases
 * where a quotient digit's estimate needs both corrections. */
static int udiv_ok(uint64_t n, uint32_t d)
{
    uint32_t r = 0xDEADBEEF, q = silk_udiv64_32(n, d, &r);
    return q == n / d && r == n % d && silk_udiv64_32(n, d, NULL) == q;
}

TEST(test_udiv64_32)
{
    long bad = 0, n_checked = 0;
    for (int i = 0; i < 4 * N_RANDOM; i++) {
        unsigned long long r = check_rand64();
        uint32_t d = (uint32_t)(check_rand64() >> (32 + (r & 31)));
        if (d == 0) d = 1;
        uint64_t hi = (uint64_t)(check_rand64() >> 32) % d;          /* n >> 32 < d */
        uint64_t n = hi << 32 | (uint32_t)check_rand64();
        n >>= (r >> 8) & 63;                                      /* short numerators too */
        bad += !udiv_ok(n, d);
        bad += !udiv_ok((uint64_t)d * (uint32_t)(r >> 32), d);    /* exact multiples */
        bad += !udiv_ok((uint64_t)d * (uint32_t)(r >> 32) - 1 + (d == 1 && !(r >> 32)), d);
        bad += !udiv_ok(((uint64_t)d << 32) - 1, d);              /* the largest quotient */
        if (d >= (1u << 29)) bad += !udiv_ok((uint64_t)1 << 61, d);
        n_checked += 5;
    }
    /* divisors just above and below the 16-bit digit boundaries, where the
     * digit estimate is furthest off */
    const uint32_t ds[] = { 1, 2, 3, 0xFFFF, 0x10000, 0x10001, 0x7FFF8000, 0x80000000u, 0x80000001u,
                            0x8000FFFFu, 0xFFFF0000u, 0xFFFF0001u, 0xFFFFFFFFu, 0x40000000, 0x7FFFFFFF };
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++)
        for (uint32_t k = 0; k < 4096; k++) {
            uint64_t top = ((uint64_t)ds[i] << 32) - 1;
            bad += !udiv_ok(top - (uint64_t)k * 0x10001u * 0x10001u % (top + 1), ds[i]);
            bad += !udiv_ok((uint64_t)k << 32 | (0xFFFFFFFFu - k), ds[i]) * (k < ds[i]);
            n_checked += 2;
        }
    printf("  udiv64_32: %ld of %ld wrong (bound 0: exact)\n", bad, n_checked);
    CHECK(bad == 0);
}

/* silk_shr_round64 (without a branch on a 64-bit host) against the
 * rounding it states: halves away from zero, -f(x) == f(-x); values of
 * every length and sign, halves and their neighbours. */
TEST(test_shr_round64)
{
    long bad = 0, n_checked = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        unsigned long long r = check_rand64();
        int s = 1 + (int)(r % 62);
        int64_t mag = (int64_t)(check_rand64() >> (2 + (r >> 8) % 62)), half = (int64_t)1 << (s - 1);
        int64_t vs[4] = { mag, -mag, (mag >> s << s) + half, -((mag >> s << s) + half) };
        for (int k = 0; k < 4; k++) {
            int64_t v = vs[k] - (k >= 2 && (r >> 20 & 1)), a = v < 0 ? -v : v;
            int64_t want = (a + half) >> s;   /* a + half < 2^62 */
            bad += silk_shr_round64(v, s) != (v < 0 ? -want : want);
            n_checked++;
        }
    }
    printf("  shr_round64: %ld of %ld wrong (bound 0: exact)\n", bad, n_checked);
    CHECK(bad == 0);
}

/* silk_udiv64_cpu32 (the 32-bit processor's silk_udiv64) against the plain
 * 64-bit division: divisors of every length up to 64 bits, numerators of
 * every length, quotients above 2^32 (the two-step route) and the edges
 * of each route. */
TEST(test_udiv64_cpu32)
{
    long bad = 0, n_checked = 0;
    for (int i = 0; i < 4 * N_RANDOM; i++) {
        unsigned long long r = check_rand64();
        uint64_t d = check_rand64() >> (r & 63), n = check_rand64() >> ((r >> 6) & 63);
        if (d == 0) d = 1;
        const uint64_t ns[] = { n, d * (n >> 32), d * (n >> 32) - 1, ((d & 0xFFFFFFFFu) << 32) - 1,
                                (d & 0xFFFFFFFFu) << 32, UINT64_MAX, (uint64_t)1 << 61 };
        for (size_t j = 0; j < sizeof ns / sizeof ns[0]; j++) bad += silk_udiv64_cpu32(ns[j], d) != ns[j] / d;
        n_checked += (long)(sizeof ns / sizeof ns[0]);
    }
    const uint64_t ds[] = { 1, 3, 0xFFFF, 0x10000, 0x7FFFFFFF, 0xFFFFFFFFu, 0x100000000ull, 0x100000001ull };
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++)
        for (uint64_t k = 0; k < 4096; k++) {
            const uint64_t ns[] = { k, (ds[i] << 32) - 1 - k, (ds[i] << 32) + k, UINT64_MAX - k, k << 32 | k };
            for (size_t j = 0; j < sizeof ns / sizeof ns[0]; j++) bad += silk_udiv64_cpu32(ns[j], ds[i]) != ns[j] / ds[i];
            n_checked += (long)(sizeof ns / sizeof ns[0]);
        }
    printf("  udiv64_cpu32: %ld of %ld wrong (bound 0: exact)\n", bad, n_checked);
    CHECK(bad == 0);
}

TEST(test_isqrt)
{
    int bad32 = 0, bad64 = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        unsigned long long r = check_rand64();
        uint32_t v32 = (uint32_t)(r >> (r & 31));
        uint64_t v64 = (uint64_t)check_rand64() >> (r >> 58);
        uint32_t k = (uint32_t)(check_rand64() >> 32);
        uint64_t sq = (uint64_t)k * k;
        if (!isqrt32_ok(v32, silk_isqrt32(v32))) bad32++;
        if (!isqrt64_ok(v64, silk_isqrt64(v64))) bad64++;
        /* perfect squares and their neighbours */
        if (silk_isqrt64(sq) != k) bad64++;
        if (k && silk_isqrt64(sq - 1) != k - 1) bad64++;
        if (silk_isqrt32((uint32_t)(k >> 16) * (k >> 16)) != k >> 16) bad32++;
        /* against the double reference too (exact below 2^52) */
        if (v64 < (UINT64_C(1) << 52) && silk_isqrt64(v64) != (uint32_t)floor(sqrt((double)v64))) bad64++;
    }
    for (uint32_t v = 0; v < (1u << 20); v++)
        if (!isqrt32_ok(v, silk_isqrt32(v))) bad32++;
    printf("  isqrt32: %d wrong, isqrt64: %d wrong (bound 0: exact floor)\n", bad32, bad64);
    CHECK(bad32 == 0);
    CHECK(bad64 == 0);
    CHECK(silk_isqrt32(UINT32_MAX) == 65535);
    CHECK(silk_isqrt64(UINT64_MAX) == UINT32_MAX);
    CHECK(silk_isqrt64(UINT64_C(0xFFFFFFFE00000001)) == UINT32_MAX);   /* (2^32-1)^2 */
    CHECK(silk_isqrt64(UINT64_C(0xFFFFFFFE00000000)) == UINT32_MAX - 1);
    CHECK(silk_isqrt64(0) == 0 && silk_isqrt32(0) == 0 && silk_isqrt32(1) == 1);
}

/* The exact-rounding criteria, in integers, over every positive input when
 * SILK_EXHAUSTIVE=1 (about half a minute), else every 127th. */
TEST(test_sqrt_rsqrt_all)
{
    const char *env = getenv("SILK_EXHAUSTIVE");
    uint32_t step = (env && *env == '1') ? 1 : 127;
    long bad_s = 0, bad_r = 0, bad_i = 0, n = 0;
    const uint64_t lim = UINT64_C(1) << 50;
    for (uint32_t a = 1; a < UINT32_C(0x80000000); a += step, n++) {
        uint64_t s = (uint64_t)silk_fx_sqrt((silk_fx)a), v = (uint64_t)a << 16;
        if (!(s * s - s < v && v <= s * s + s)) bad_s++;
        uint64_t r = (uint64_t)silk_fx_rsqrt((silk_fx)a);
        if (!((2 * r - 1) * (2 * r - 1) * a <= lim && (2 * r + 1) * (2 * r + 1) * a > lim)) bad_r++;
        uint32_t w = a * 2;                    /* w and w + 1 cover [2, 2^32) */
        if (!isqrt32_ok(w, silk_isqrt32(w)) || !isqrt32_ok(w + 1, silk_isqrt32(w + 1))) bad_i++;
    }
    printf("  sqrt/rsqrt/isqrt32 over %ld inputs (step %u): %ld / %ld / %ld not exactly rounded\n",
           n, step, bad_s, bad_r, bad_i);
    CHECK(bad_s == 0 && bad_r == 0 && bad_i == 0);
}

/* ---- trigonometry -------------------------------------------------------- */

TEST(test_sincos)
{
    double worst_s = 0, worst_c = 0, worst_pyth = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        /* half over the whole range, half within a few turns */
        silk_fx a = (i & 1) ? rand_fx() : (silk_fx)floor(check_uniform(-8.0, 8.0) * ULP);
        silk_fx s, c;
        silk_fx_sincos(a, &s, &c);
        double es = fabs(s - sin(fx_d(a)) * ULP), ec = fabs(c - cos(fx_d(a)) * ULP);
        if (es > worst_s) worst_s = es;
        if (ec > worst_c) worst_c = ec;
        double p = fabs(((double)s * s + (double)c * c) / (ULP * ULP) - 1.0) * ULP;
        if (p > worst_pyth) worst_pyth = p;
    }
    printf("  sincos: worst sin %.4f, cos %.4f ulp (bound 0.51); |s^2+c^2-1| %.3f ulp\n",
           worst_s, worst_c, worst_pyth);
    CHECKF(worst_s <= 0.51, "sin worst %.4f", worst_s);
    CHECKF(worst_c <= 0.51, "cos worst %.4f", worst_c);
    CHECKF(worst_pyth <= 2.0, "pythagoras %.4f", worst_pyth);
    silk_fx s = 1, c = 1;
    silk_fx_sincos(0, &s, &c);
    CHECK(s == 0 && c == SILK_FX_ONE);
    silk_fx_sincos(SILK_FX_PI, &s, &c);
    CHECK(s == 0 && c == -SILK_FX_ONE);
    silk_fx_sincos(SILK_FX_C(1, 2), &s, NULL);   /* either output may be NULL */
    CHECK(s == 31420);                           /* sin(0.5) * 65536 = 31419.5... */
    silk_fx_sincos(SILK_FX_C(1, 2), NULL, &c);
    CHECK(c == 57513);
}

TEST(test_sincos_deg)
{
    double worst = 0;
    const double d2r = 3.14159265358979323846 / 180.0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx a = (i & 1) ? rand_fx() : (silk_fx)floor(check_uniform(-720.0, 720.0) * ULP);
        silk_fx s, c;
        silk_fx_sincos_deg(a, &s, &c);
        double r = fmod(fx_d(a), 360.0) * d2r;   /* fmod is exact */
        double e = fmax(fabs(s - sin(r) * ULP), fabs(c - cos(r) * ULP));
        if (e > worst) worst = e;
    }
    printf("  sincos_deg: worst %.4f ulp (bound 0.51)\n", worst);
    CHECKF(worst <= 0.51, "worst %.4f", worst);
    static const int deg[] = { 0, 90, 180, 270, 360, -90, -180, 450, 32760, -32760 };
    for (int i = 0; i < (int)(sizeof deg / sizeof deg[0]); i++) {
        silk_fx s, c;
        silk_fx_sincos_deg(deg[i] * SILK_FX_ONE, &s, &c);
        int q = ((deg[i] % 360) + 360) % 360 / 90;
        static const int es[4] = { 0, 1, 0, -1 }, ec[4] = { 1, 0, -1, 0 };
        CHECKF(s == es[q] * SILK_FX_ONE && c == ec[q] * SILK_FX_ONE, "%d deg: %d %d", deg[i], s, c);
    }
    silk_fx s, c;
    silk_fx_sincos_deg(30 * SILK_FX_ONE, &s, &c);
    CHECK(s == SILK_FX_HALF);
    CHECK(c == 56756);                           /* sqrt(3)/2 * 65536 = 56755.8 */
}

TEST(test_atan2)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx y, x;
        if (i & 1) { y = rand_fx(); x = rand_fx(); }
        else { double b = check_uniform(1.0, 31.0); y = rand_fx_bits(b); x = rand_fx_bits(b); }
        double err = fabs(silk_fx_atan2(y, x) - atan2((double)y, (double)x) * ULP);
        if (err > worst) worst = err;
    }
    printf("  atan2: worst %.4f ulp (bound 0.51)\n", worst);
    CHECKF(worst <= 0.51, "worst %.4f", worst);
    CHECK(silk_fx_atan2(0, 0) == 0);
    CHECK(silk_fx_atan2(0, -SILK_FX_ONE) == SILK_FX_PI);
    CHECK(silk_fx_atan2(0, SILK_FX_ONE) == 0);
    CHECK(silk_fx_atan2(SILK_FX_ONE, 0) == 102944);             /* pi/2 */
    CHECK(silk_fx_atan2(-SILK_FX_ONE, 0) == -102944);
    CHECK(silk_fx_atan2(SILK_FX_ONE, SILK_FX_ONE) == 51472);    /* pi/4 = 51471.85 */
    CHECK(silk_fx_atan2(-1, -SILK_FX_MAX) == -SILK_FX_PI);
    CHECK(silk_fx_atan2(SILK_FX_MAX, SILK_FX_MIN) == 154416);   /* 3pi/4 = 154415.56 */
}

TEST(test_acos)
{
    /* every input in [-1, 1]: 131073 values */
    double worst = 0;
    for (silk_fx x = -SILK_FX_ONE; x <= SILK_FX_ONE; x++) {
        double err = fabs(silk_fx_acos(x) - acos(fx_d(x)) * ULP);
        if (err > worst) worst = err;
    }
    printf("  acos: worst %.4f ulp over all of [-1, 1] (bound 0.51)\n", worst);
    CHECKF(worst <= 0.51, "worst %.4f", worst);
    CHECK(silk_fx_acos(SILK_FX_ONE) == 0);
    CHECK(silk_fx_acos(-SILK_FX_ONE) == SILK_FX_PI);
    CHECK(silk_fx_acos(0) == 102944);
    CHECK(silk_fx_acos(SILK_FX_ONE - 1) == 362);  /* sqrt(2^-15) rad: the steep end */
    CHECK(silk_fx_acos(5 * SILK_FX_ONE) == 0);    /* clamped */
    CHECK(silk_fx_acos(SILK_FX_MIN) == SILK_FX_PI);
}

/* ---- vectors ------------------------------------------------------------- */

TEST(test_cross)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_vec3 a = rand_v3(), b = rand_v3();
        silk_vec3 c = silk_v3_cross(a, b);
        /* the double products are rounded relative 2^-53: allow for that */
        double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
        double ref[3] = { (ay * bz - az * by) / ULP, (az * bx - ax * bz) / ULP, (ax * by - ay * bx) / ULP };
        double mag[3] = { fabs(ay * bz) + fabs(az * by), fabs(az * bx) + fabs(ax * bz), fabs(ax * by) + fabs(ay * bx) };
        silk_fx got[3] = { c.x, c.y, c.z };
        for (int k = 0; k < 3; k++) {
            double err = fabs(got[k] - sat_ulp(ref[k])) - mag[k] / ULP * 0x1p-52;
            if (err > worst) worst = err;
        }
    }
    printf("  cross: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    silk_vec3 z = silk_v3_cross(silk_v3(SILK_FX_ONE, 0, 0), silk_v3(0, SILK_FX_ONE, 0));
    CHECK(z.x == 0 && z.y == 0 && z.z == SILK_FX_ONE);
}

TEST(test_length)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_vec3 a = (i & 1) ? rand_v3() : rand_v3_any();
        double x = a.x, y = a.y, z = a.z;
        double err = fabs(silk_v3_length(a) - sat_ulp(sqrt(x * x + y * y + z * z)));
        if (err > worst) worst = err;
    }
    printf("  length: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
    CHECK(silk_v3_length(silk_v3(3 * SILK_FX_ONE, 4 * SILK_FX_ONE, 0)) == 5 * SILK_FX_ONE);
    CHECK(silk_v3_length(silk_v3(1, 1, 1)) == 2);       /* sqrt(3) ulp = 1.73 */
    CHECK(silk_v3_length(silk_v3(0, 0, 0)) == 0);
}

TEST(test_normalize)
{
    double worst = 0, worst_len = 0;
    int bad_ret = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_vec3 a;
        switch (i % 4) {
        case 0: a = rand_v3_bits(3); break;      /* a few ulp */
        case 1: a = rand_v3_any(); break;        /* up to huge */
        default: a = rand_v3(); break;
        }
        silk_vec3 n;
        int ok = silk_v3_normalize(a, &n);
        if (a.x == 0 && a.y == 0 && a.z == 0) {
            if (ok != 0 || n.x || n.y || n.z) bad_ret++;
            continue;
        }
        if (ok != 1) bad_ret++;
        /* silk_unit_fx: silk_unit64's bits from 32-bit products, INT32_MIN too */
        int32_t f[3];
        int64_t u[3];
        silk_fx bx = (i & 1023) == 7 ? INT32_MIN : a.x;
        if (silk_unit_fx(bx, a.y, a.z, f) != silk_unit64(bx, a.y, a.z, u) || f[0] != u[0] || f[1] != u[1] ||
            f[2] != u[2])
            bad_ret++;
        double x = a.x, y = a.y, z = a.z, l = sqrt(x * x + y * y + z * z);
        double e = fmax(fabs(n.x - x / l * ULP), fmax(fabs(n.y - y / l * ULP), fabs(n.z - z / l * ULP)));
        if (e > worst) worst = e;
        double nx = n.x, ny = n.y, nz = n.z;
        double el = fabs(sqrt(nx * nx + ny * ny + nz * nz) - ULP);
        if (el > worst_len) worst_len = el;
    }
    printf("  normalize: worst %.6f ulp per component (bound 0.501), |len-1| %.4f ulp (bound 0.87)\n",
           worst, worst_len);
    CHECK(bad_ret == 0);
    CHECKF(worst <= 0.501, "worst %.6f", worst);
    CHECKF(worst_len <= 0.87, "len %.4f", worst_len);
    silk_vec3 n;
    CHECK(silk_v3_normalize(silk_v3(1, 0, 0), &n) == 1 && n.x == SILK_FX_ONE && n.y == 0 && n.z == 0);
    CHECK(silk_v3_normalize(silk_v3(0, 0, -1), &n) == 1 && n.z == -SILK_FX_ONE);
    CHECK(silk_v3_normalize(silk_v3(1, 1, 1), &n) == 1 && n.x == 37837 && n.y == 37837 && n.z == 37837);
    CHECK(silk_v3_normalize(silk_v3(SILK_FX_MAX, SILK_FX_MAX, 0), &n) == 1 && n.x == 46341 && n.y == 46341);
    CHECK(silk_v3_normalize(silk_v3(INT32_MIN, 0, 0), &n) == 1 && n.x == -SILK_FX_ONE);
    CHECK(silk_v3_normalize(silk_v3(0, 0, 0), &n) == 0 && n.x == 0 && n.y == 0 && n.z == 0);
}

TEST(test_lerp)
{
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_vec3 a = rand_v3(), b = rand_v3();
        silk_fx t = (i & 1) ? (silk_fx)floor(check_uniform(0, ULP + 1)) : rand_fx();
        silk_vec3 r = silk_v3_lerp(a, b, t);
        double td = fx_d(t);
        double e = fmax(fabs(r.x - sat_ulp(a.x + ((double)b.x - a.x) * td)),
                   fmax(fabs(r.y - sat_ulp(a.y + ((double)b.y - a.y) * td)),
                        fabs(r.z - sat_ulp(a.z + ((double)b.z - a.z) * td))));
        if (e > worst) worst = e;
        silk_vec3 r0 = silk_v3_lerp(a, b, 0), r1 = silk_v3_lerp(a, b, SILK_FX_ONE);
        CHECK(r0.x == a.x && r0.y == a.y && r0.z == a.z);
        CHECK(r1.x == b.x && r1.y == b.y && r1.z == b.z);
    }
    printf("  lerp: worst %.6f ulp (bound 0.5)\n", worst);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
}

/* ---- decimal text -------------------------------------------------------- */

static int parse_is(const char *s, int want_ret, silk_fx want, int want_len)
{
    const char *end = NULL;
    silk_fx v = 12345;
    int ret = silk_fx_parse(s, &end, &v);
    if (ret != want_ret) { fprintf(stderr, "  \"%s\": returned %d, want %d\n", s, ret, want_ret); return 0; }
    if (ret == 0 && v != want) { fprintf(stderr, "  \"%s\": %d, want %d\n", s, v, want); return 0; }
    if (ret == -1 && end != s) { fprintf(stderr, "  \"%s\": end moved on error\n", s); return 0; }
    if (ret != -1 && end - s != want_len) {
        fprintf(stderr, "  \"%s\": consumed %d, want %d\n", s, (int)(end - s), want_len);
        return 0;
    }
    return 1;
}

TEST(test_parse_good)
{
    const silk_fx ONE = SILK_FX_ONE;
    CHECK(parse_is("0", 0, 0, 1));
    CHECK(parse_is("-0", 0, 0, 2));
    CHECK(parse_is("1", 0, ONE, 1));
    CHECK(parse_is("+7", 0, 7 * ONE, 2));
    CHECK(parse_is("-12.5", 0, -819200, 5));
    CHECK(parse_is("3e-2", 0, 1966, 4));                /* 1966.08 */
    CHECK(parse_is(".5", 0, ONE / 2, 2));
    CHECK(parse_is("-.5", 0, -ONE / 2, 3));
    CHECK(parse_is("5.", 0, 5 * ONE, 2));
    CHECK(parse_is("1E+03", 0, 1000 * ONE, 5));
    CHECK(parse_is("1e3x", 0, 1000 * ONE, 3));          /* stops at the first non-number */
    CHECK(parse_is("1.5 2", 0, 3 * ONE / 2, 3));
    CHECK(parse_is("1..2", 0, ONE, 2));
    CHECK(parse_is("0x10", 0, 0, 1));
    CHECK(parse_is("2.5e0/", 0, 5 * ONE / 2, 5));
    CHECK(parse_is("0007.25000", 0, 29 * ONE / 4, 10));
    /* rounding to nearest, halves away from zero */
    CHECK(parse_is("0.00000762939453125", 0, 1, 19));   /* exactly 0.5 ulp */
    CHECK(parse_is("-0.00000762939453125", 0, -1, 20));
    CHECK(parse_is("0.0000076293945312", 0, 0, 18));    /* just below 0.5 ulp */
    CHECK(parse_is("0.0000228881835937", 0, 1, 18));    /* just below 1.5 ulp */
    CHECK(parse_is("0.00002288818359375", 0, 2, 19));   /* exactly 1.5 ulp */
    CHECK(parse_is("3.14159265358979323846264338327950288", 0, SILK_FX_PI, 37));
    /* the ends of the range: SILK_FX_MAX = 32767.9999847..., MIN is -MAX */
    CHECK(parse_is("32767.99998", 0, SILK_FX_MAX, 11));
    CHECK(parse_is("32767.9999923", 0, SILK_FX_MAX, 13));   /* MAX + 0.495 ulp */
    CHECK(parse_is("-32767.9999923", 0, SILK_FX_MIN, 14));
    CHECK(parse_is("32767.9999924", -2, 0, 13));            /* MAX + 0.502 ulp */
    CHECK(parse_is("32768", -2, 0, 5));
    CHECK(parse_is("-32768", -2, 0, 6));
    CHECK(parse_is("1e400", -2, 0, 5));
    CHECK(parse_is("-1e99999999999", -2, 0, 14));
    CHECK(parse_is("1e-400", 0, 0, 6));                     /* tiny rounds to 0 */
    CHECK(parse_is("1e-99999999999", 0, 0, 14));
    CHECK(parse_is("1e99999999999999999999999999999", -2, 0, 31));   /* no overflow in the exponent */
    CHECK(parse_is("-1e-99999999999999999999999999999", 0, 0, 33));
    CHECK(parse_is("0e999", 0, 0, 5));
    /* more than 18 significant digits: the rest are dropped but counted */
    CHECK(parse_is("1000000000000000000000e-18", 0, 1000 * ONE, 26));
    CHECK(parse_is("123456789012345678901234567890e-25", 0, 809086412, 34)); /* 12345.67890... */
    CHECK(parse_is("0.000000000000000000000000000001e30", 0, ONE, 35));
    CHECK(parse_is("99999999999999999999999999999999999999999999", -2, 0, 44));
    CHECK(parse_is("0.99999999999999999999999999999999999999999999", 0, ONE, 46));
}

TEST(test_parse_bad)
{
    static const char *bad[] = {
        "", ".", "-", "+", "-.", "nan", "NaN", "inf", "-inf", "Infinity", "e5", ".e5", "-e5",
        "1e", "1e+", "1E-", "1.5e", "1ex", "abc", "--1", "+-1", " 1", "\t1", "x1",
    };
    for (int i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
        CHECKF(parse_is(bad[i], -1, 0, 0), "\"%s\"", bad[i]);
        silk_decimal d = { 77, 7 };
        const char *end = NULL;
        CHECKF(silk_decimal_parse(bad[i], &end, &d) == -1 && end == bad[i] && d.mant == 77,
               "decimal \"%s\"", bad[i]);
    }
    silk_fx v;
    CHECK(silk_fx_parse("2", NULL, &v) == 0 && v == 2 * SILK_FX_ONE);   /* end may be NULL */
}

/* Random decimal strings against strtod (the nearest double, then exact
 * scaling by 2^16 and rounding). */
TEST(test_parse_random)
{
    double worst = 0;
    int bad_ret = 0;
    char buf[64];
    for (int i = 0; i < N_RANDOM; i++) {
        double mag = pow(10.0, check_uniform(-7.0, 4.6));
        double v = (check_rand64() & 1) ? -mag : mag;
        int prec = (int)(check_rand64() % 20);
        if (i & 1) snprintf(buf, sizeof buf, "%.*e", prec, v);
        else snprintf(buf, sizeof buf, "%.*f", prec, v);
        double ref = strtod(buf, NULL) * ULP;
        silk_fx got;
        const char *end;
        int ret = silk_fx_parse(buf, &end, &got);
        int fits = fabs(ref) < (double)SILK_FX_MAX + 0.5;
        if (ret != (fits ? 0 : -2) || *end != '\0') { bad_ret++; continue; }
        if (!fits) continue;
        double err = fabs(got - ref);
        if (err > worst) worst = err;
    }
    printf("  parse: worst %.6f ulp against strtod (bound 0.5)\n", worst);
    CHECK(bad_ret == 0);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
}

TEST(test_format)
{
    char buf[16];
    CHECK(strcmp(silk_fx_format(0, buf), "0") == 0);
    CHECK(strcmp(silk_fx_format(SILK_FX_ONE, buf), "1") == 0);
    CHECK(strcmp(silk_fx_format(-SILK_FX_HALF, buf), "-0.5") == 0);
    CHECK(strcmp(silk_fx_format(1, buf), "0.00002") == 0);
    CHECK(strcmp(silk_fx_format(-1, buf), "-0.00002") == 0);
    CHECK(strcmp(silk_fx_format(SILK_FX_PI, buf), "3.14159") == 0);
    CHECK(strcmp(silk_fx_format(-819200, buf), "-12.5") == 0);
    CHECK(strcmp(silk_fx_format(SILK_FX_MAX, buf), "32767.99998") == 0);
    CHECK(strcmp(silk_fx_format(SILK_FX_MIN, buf), "-32767.99998") == 0);
    CHECK(strcmp(silk_fx_format(SILK_FX_ONE - 1, buf), "0.99998") == 0);
    CHECK(strcmp(silk_fx_format(INT32_MIN, buf), "-32768") == 0);
    /* 5 decimals are within 0.33 ulp: text -> value is the identity */
    int bad = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx v = rand_fx(), back = 0;
        silk_fx_format(v, buf);
        double dv = strtod(buf, NULL);
        if (strlen(buf) > 12 || silk_fx_parse(buf, NULL, &back) != 0 || back != v ||
            fabs(dv - fx_d(v)) > 0.5e-5 + 1e-9)
            bad++;
    }
    printf("  format: %d of %d failed to round-trip\n", bad, N_RANDOM);
    CHECK(bad == 0);
}

TEST(test_decimal)
{
    silk_decimal d, e;
    const char *end;
    CHECK(silk_decimal_parse("-12.500", &end, &d) == 0 && d.mant == -125 && d.exp10 == -1 && *end == 0);
    CHECK(silk_decimal_parse("1000", &end, &d) == 0 && d.mant == 1 && d.exp10 == 3);
    CHECK(silk_decimal_parse("0.000", &end, &d) == 0 && d.mant == 0 && d.exp10 == 0);
    CHECK(silk_decimal_parse("1e400", &end, &d) == 0 && d.mant == 1 && d.exp10 == 400);
    CHECK(silk_decimal_parse("1e401", &end, &d) == -2);
    CHECK(silk_decimal_parse("1e-401", &end, &d) == -2);
    CHECK(silk_decimal_parse("0e-999", &end, &d) == 0 && d.mant == 0);
    CHECK(silk_decimal_parse("123456789012345678999", &end, &d) == 0 &&
          d.mant == INT64_C(123456789012345678) && d.exp10 == 3);     /* 18 digits kept */
    CHECK(silk_decimal_parse("0.00123456789012345678999", &end, &d) == 0 &&
          d.mant == INT64_C(123456789012345678) && d.exp10 == -20);

    /* scale factors: 0.001 and 1000 */
    silk_decimal milli, kilo, x;
    silk_fx f;
    silk_decimal_parse("0.001", NULL, &milli);
    silk_decimal_parse("1000", NULL, &kilo);
    silk_decimal_parse("1234.5678", NULL, &x);
    d = silk_decimal_mul(x, milli);
    CHECK(d.mant == 12345678 && d.exp10 == -7);
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 80909);               /* 1.2345678 * 65536 = 80908.64 */
    d = silk_decimal_mul(silk_decimal_mul(x, milli), kilo);
    CHECK(d.mant == 12345678 && d.exp10 == -4);
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 80908635);            /* 1234.5678 * 65536 = 80908635.34 */
    CHECK(silk_decimal_to_fx(silk_decimal_mul(x, kilo), &f) == -2);   /* 1234567.8 */
    /* scaling before rounding keeps what rounding first would lose */
    silk_decimal_parse("0.00001", NULL, &x);
    CHECK(silk_decimal_to_fx(silk_decimal_mul(x, kilo), &f) == 0 && f == 655);   /* 0.01 */
    CHECK(silk_fx_mul(1 * SILK_FX_ONE, 1000 * SILK_FX_ONE) != 655);              /* (for contrast) */

    /* 18-digit products round to 18 digits */
    d.mant = INT64_C(999999999999999999); d.exp10 = 0;
    e = silk_decimal_mul(d, d);        /* 10^36 - 2 10^18 + 1 */
    CHECK(e.mant == INT64_C(999999999999999998) && e.exp10 == 18);
    d.mant = -INT64_C(999999999999999999); d.exp10 = -18;
    e = silk_decimal_mul(d, d);
    CHECK(e.mant == INT64_C(999999999999999998) && e.exp10 == -18);
    d.mant = INT64_C(500000000000000001); d.exp10 = 0;
    e.mant = 3; e.exp10 = 0;
    e = silk_decimal_mul(d, e);        /* 1500000000000000003: the 19th digit 3 rounds down */
    CHECK(e.mant == 15 && e.exp10 == 17);
    d.mant = INT64_C(500000000000000005); d.exp10 = 0;
    e.mant = -3; e.exp10 = 0;
    e = silk_decimal_mul(d, e);        /* -1500000000000000015: 5 rounds away from zero */
    CHECK(e.mant == -INT64_C(150000000000000002) && e.exp10 == 1);
    d.mant = INT64_C(1999999999999999999); d.exp10 = 0;    /* 19 digits in, as a caller may */
    e.mant = 5; e.exp10 = -3;
    e = silk_decimal_mul(d, e);        /* 9999999999999999995e-3: rounds up to 10^19 e-3 */
    CHECK(e.mant == 1 && e.exp10 == 16);
    d.mant = 0; d.exp10 = 5;
    e = silk_decimal_mul(d, milli);
    CHECK(e.mant == 0 && e.exp10 == 0);

    /* to_fx at the edges */
    d.mant = 32767; d.exp10 = 0;
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 32767 * SILK_FX_ONE);
    d.mant = 32768; d.exp10 = 0;
    CHECK(silk_decimal_to_fx(d, &f) == -2);
    d.mant = -1; d.exp10 = 30;
    CHECK(silk_decimal_to_fx(d, &f) == -2);
    d.mant = INT64_C(999999999999999999); d.exp10 = -40;
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 0);
    d.mant = INT64_C(999999999999999999); d.exp10 = -14;   /* 9999.99... */
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 10000 * SILK_FX_ONE);
    d.mant = INT64_MIN + 1; d.exp10 = -15;                  /* -9223.37... beyond 18 digits still works */
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == -604462910);
    d.mant = INT64_MAX; d.exp10 = -23;                      /* 6.04 ulp */
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 6);
    d.mant = INT64_MAX; d.exp10 = -26;                      /* 0.006 ulp */
    CHECK(silk_decimal_to_fx(d, &f) == 0 && f == 0);

    /* random products against double */
    double worst_rel = 0;
    int bad = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        /* one draw per statement: the order is then fixed */
        silk_decimal a, b;
        a.mant = (int64_t)(check_rand64() % UINT64_C(1000000000000000000));
        a.exp10 = (int32_t)(check_rand64() % 41) - 20;
        unsigned sh = (unsigned)(check_rand64() % 64);       /* mantissas of every length */
        b.mant = (int64_t)((check_rand64() >> sh) % UINT64_C(1000000000000000000));
        b.exp10 = (int32_t)(check_rand64() % 41) - 20;
        if (check_rand64() & 1) a.mant = -a.mant;
        silk_decimal p = silk_decimal_mul(a, b);
        if (p.mant >= INT64_C(1000000000000000000) || p.mant <= -INT64_C(1000000000000000000) ||
            (p.mant != 0 && p.mant % 10 == 0) || (p.mant == 0 && (a.mant && b.mant))) { bad++; continue; }
        if (!a.mant || !b.mant) continue;
        /* compare mantissas only: the double reference is 2^-53 relative */
        long double ref = (long double)a.mant * (long double)b.mant;
        long double got = (long double)p.mant * powl(10.0L, (long double)(p.exp10 - a.exp10 - b.exp10));
        double rel = (double)fabsl(got / ref - 1.0L);
        if (rel > worst_rel) worst_rel = rel;
    }
    /* rounding to 18 digits: half a unit of the 18th, <= 5e-18; the long
     * double reference adds a few LDBL_EPSILON */
    double bound = 5e-18 * (1 + 1e-15) + 4 * LDBL_EPSILON;
    printf("  decimal_mul: worst relative error %.4g (bound %.4g)\n", worst_rel, bound);
    CHECK(bad == 0);
    CHECKF(worst_rel <= bound, "rel %.4g", worst_rel);

    /* to_fx against double over the fx range */
    double worst = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        int digits = 1 + (int)(check_rand64() % 18);
        int64_t m = (int64_t)(check_rand64() % (uint64_t)pow(10.0, digits));
        int32_t ex = (int32_t)(-digits - 6 + (int)(check_rand64() % 11));
        silk_decimal dd = { (check_rand64() & 1) ? -m : m, ex };
        char s[64];
        snprintf(s, sizeof s, "%llde%d", (long long)dd.mant, (int)dd.exp10);
        double ref = strtod(s, NULL) * ULP;
        int fits = fabs(ref) < (double)SILK_FX_MAX + 0.5;
        silk_fx got = 0;
        if (silk_decimal_to_fx(dd, &got) != (fits ? 0 : -2)) { bad++; continue; }
        if (fits && fabs(got - ref) > worst) worst = fabs(got - ref);
    }
    printf("  decimal_to_fx: worst %.6f ulp (bound 0.5)\n", worst);
    CHECK(bad == 0);
    CHECKF(worst <= 0.5 + REF_EPS, "worst %.6f", worst);
}

/* Not a test: nanoseconds per call, for docs/fixed-point.md. */
static void bench(void)
{
    enum { N = 2000000 };
    volatile silk_fx sink = 0;
    uint32_t acc = 0;
    clock_t t0 = clock();
    for (int i = 0; i < N; i++) acc += silk_fx_rsqrt(SILK_FX_ONE / 2 + (i & 0xFFFF));
    clock_t t1 = clock();
    for (int i = 0; i < N; i++) acc += silk_fx_sqrt(SILK_FX_ONE / 2 + (i & 0xFFFFF));
    clock_t t2 = clock();
    for (int i = 0; i < N; i++) { silk_fx s, c; silk_fx_sincos(i, &s, &c); acc += (uint32_t)(s + c); }
    clock_t t3 = clock();
    for (int i = 0; i < N; i++) { silk_vec3 n; silk_v3_normalize(silk_v3(i, 3 * i + 1, 77), &n); acc += n.x; }
    clock_t t4 = clock();
    sink = (silk_fx)(acc & 0xFFFF);
    (void)sink;
    double k = 1e9 / CLOCKS_PER_SEC / N;
    printf("  bench: rsqrt %.1f ns, sqrt %.1f ns, sincos %.1f ns, normalize %.1f ns per call\n",
           (t1 - t0) * k, (t2 - t1) * k, (t3 - t2) * k, (t4 - t3) * k);
}

int main(void)
{
    RUN(test_mul);
    RUN(test_div);
    RUN(test_muldiv);
    RUN(test_recip);
    RUN(test_saturation);
    RUN(test_sqrt);
    RUN(test_rsqrt);
    RUN(test_udiv64_32);
    RUN(test_udiv64_cpu32);
    RUN(test_shr_round64);
    RUN(test_isqrt);
    RUN(test_sqrt_rsqrt_all);
    RUN(test_sincos);
    RUN(test_sincos_deg);
    RUN(test_atan2);
    RUN(test_acos);
    RUN(test_cross);
    RUN(test_length);
    RUN(test_normalize);
    RUN(test_lerp);
    RUN(test_parse_good);
    RUN(test_parse_bad);
    RUN(test_parse_random);
    RUN(test_format);
    RUN(test_decimal);
    bench();
    return check_done();
}
