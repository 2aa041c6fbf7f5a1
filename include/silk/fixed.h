/*
 * silk/fixed.h - the fixed-point scalar and vector types every stage uses.
 *
 * silk_fx is Q16.16 in an int32_t, the same layout as OpenGL ES's GLfixed:
 * range [-32768, 32768), resolution 1/65536 (about 1.5e-5).  Products and
 * quotients go through 64-bit intermediates, round to nearest and saturate
 * to +-SILK_FX_MAX instead of wrapping, so an overflow shows up as a clamped
 * value, never as a sign flip.  docs/fixed-point.md lists each function's
 * range and its measured worst error.
 */
#ifndef SILK_FIXED_H
#define SILK_FIXED_H

#include <stdint.h>
#include "config.h"   /* SILK_CPU32 */

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t silk_fx;                   /* Q16.16 */

#define SILK_FX_SHIFT 16
#define SILK_FX_ONE   ((silk_fx)65536)
#define SILK_FX_HALF  ((silk_fx)32768)
#define SILK_FX_MAX   ((silk_fx)INT32_MAX)
#define SILK_FX_MIN   ((silk_fx)-INT32_MAX)  /* symmetric, so negation never overflows */
#define SILK_PI_Q30   INT64_C(3373259426)     /* pi in Q2.30: the one pi of the core */
#define SILK_FX_PI    ((silk_fx)((SILK_PI_Q30 + 8192) >> 14))   /* pi in Q16.16, 205887 */

/* Compile-time constants from integer ratios: SILK_FX_C(3, 2) is 1.5. */
#define SILK_FX_C(num, den) ((silk_fx)(((int64_t)(num) * 65536) / (den)))

typedef struct silk_vec2 { silk_fx x, y; } silk_vec2;
typedef struct silk_vec3 { silk_fx x, y, z; } silk_vec3;
typedef struct silk_vec4 { silk_fx x, y, z, w; } silk_vec4;

/* ---- scalar helpers (inline: they sit in every inner loop) ---------------- */

/* Clamp a 64-bit intermediate into the silk_fx range. */
static inline silk_fx silk_fx_sat(int64_t v)
{
    if (v > SILK_FX_MAX) return SILK_FX_MAX;
    if (v < SILK_FX_MIN) return SILK_FX_MIN;
    return (silk_fx)v;
}

static inline silk_fx silk_fx_from_int(int32_t i) { return silk_fx_sat((int64_t)i * 65536); }

/* Round to nearest integer (halves away from zero). */
static inline int32_t silk_fx_round(silk_fx a)
{
    return a >= 0 ? (int32_t)(((int64_t)a + 32768) >> 16) : -(int32_t)(((int64_t)-a + 32768) >> 16);
}

static inline int32_t silk_fx_floor(silk_fx a) { return (int32_t)(a >> 16); }

/* Shift a 64-bit value right by s with rounding to nearest (halves away from
 * zero), symmetric for negative values so that -f(x) == f(-x). */
static inline int64_t silk_shr_round64(int64_t v, int s)
{
    int64_t half = (int64_t)1 << (s - 1);
#if !SILK_CPU32
    /* the magnitude's rounding, negated by the sign's mask, without a
     * branch on a host: the sign goes either way call by call (curve
     * points, normals) and a mispredicted branch costs more */
    int64_t m = -(int64_t)(v < 0);
    return ((((v ^ m) - m + half) >> s) ^ m) - m;
#else
    return v >= 0 ? (v + half) >> s : -((-v + half) >> s);
#endif
}

static inline silk_fx silk_fx_add(silk_fx a, silk_fx b) { return silk_fx_sat((int64_t)a + b); }
static inline silk_fx silk_fx_sub(silk_fx a, silk_fx b) { return silk_fx_sat((int64_t)a - b); }

/* a*b, rounded to nearest, saturated.  Error <= 0.5 ulp. */
static inline silk_fx silk_fx_mul(silk_fx a, silk_fx b)
{
    return silk_fx_sat(silk_shr_round64((int64_t)a * b, 16));
}

/* a/b, rounded to nearest, saturated; b == 0 gives +-SILK_FX_MAX (0/0 gives 0). */
silk_fx silk_fx_div(silk_fx a, silk_fx b);

/* (a*b)/c with a 64-bit product, rounded, saturated: the one way to scale a
 * value by a ratio without losing the product's low bits. */
silk_fx silk_fx_muldiv(silk_fx a, silk_fx b, silk_fx c);

static inline silk_fx silk_fx_abs(silk_fx a) { return a < 0 ? -a : a; }
/* |v| for any int64_t, INT64_MIN included (hence unsigned). */
static inline uint64_t silk_abs64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }
static inline silk_fx silk_fx_min(silk_fx a, silk_fx b) { return a < b ? a : b; }
static inline silk_fx silk_fx_max(silk_fx a, silk_fx b) { return a > b ? a : b; }
static inline silk_fx silk_fx_clamp(silk_fx a, silk_fx lo, silk_fx hi)
{
    return a < lo ? lo : (a > hi ? hi : a);
}

silk_fx silk_fx_recip(silk_fx a);          /* 1/a, saturated */
silk_fx silk_fx_sqrt(silk_fx a);           /* a >= 0; negative input gives 0 */
silk_fx silk_fx_rsqrt(silk_fx a);          /* 1/sqrt(a), a > 0; a <= 0 gives SILK_FX_MAX */

/* floor(n / d) and its remainder for a quotient that fits 32 bits:
 * requires d > 0 and n >> 32 < d.  Exact, from two 32-by-16-bit divisions
 * (Knuth's algorithm D in base 2^16): a 32-bit processor without a 64-bit
 * divide (Cortex-M) pays a few dozen instructions instead of a library
 * call of several hundred. */
uint32_t silk_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem);

/* floor(n / d) for any d > 0, the same quotient as n / d: whenever d fits
 * 32 bits through silk_udiv64_32 (in two steps when the quotient does not
 * fit 32 bits either), otherwise the plain division.  For 32-bit
 * processors; silk_udiv64 picks it there and n / d elsewhere. */
uint64_t silk_udiv64_cpu32(uint64_t n, uint64_t d);

static inline uint64_t silk_udiv64(uint64_t n, uint64_t d)
{
#if SILK_CPU32
    return silk_udiv64_cpu32(n, d);
#else
    return n / d;
#endif
}

/* Integer square roots, exact floor. */
uint32_t silk_isqrt32(uint32_t v);
uint32_t silk_isqrt64(uint64_t v);

/* Trigonometry.  Angles in degrees (Q16.16) for the camera API, radians for
 * geometry.  Results in [-1, 1] as Q16.16. */
void silk_fx_sincos_deg(silk_fx deg, silk_fx *s, silk_fx *c);
void silk_fx_sincos(silk_fx rad, silk_fx *s, silk_fx *c);
silk_fx silk_fx_atan2(silk_fx y, silk_fx x);   /* radians in [-pi, pi] */
silk_fx silk_fx_acos(silk_fx x);               /* x clamped to [-1,1]; radians in [0, pi] */

/* Parse decimal text ("-12.5", "3e-2", ".5", "1E+03") into Q16.16, rounded to
 * nearest.  Returns 0 on success and sets *end past the number; returns -1 for
 * text that is not a number (including "nan", "inf") and -2 for a number
 * outside the silk_fx range.  No floating point is involved. */
int silk_fx_parse(const char *s, const char **end, silk_fx *out);

/* A decimal number m * 10^e with at most 18 significant digits in m: the
 * exact form of numbers read from text, so that scaling by a user factor
 * ("--scale 0.001") happens before rounding to Q16.16, not after. */
typedef struct silk_decimal { int64_t mant; int32_t exp10; } silk_decimal;

/* Same syntax and return values as silk_fx_parse (-2 only for exponents
 * beyond +-400). */
int silk_decimal_parse(const char *s, const char **end, silk_decimal *out);
silk_decimal silk_decimal_mul(silk_decimal a, silk_decimal b);   /* keeps 18 digits */
/* Round to Q16.16; returns 0, or -2 when |d| does not fit silk_fx. */
int silk_decimal_to_fx(silk_decimal d, silk_fx *out);

/* Format into buf (at least 16 bytes) with up to 5 decimals; returns buf. */
char *silk_fx_format(silk_fx v, char *buf);

/* ---- vectors --------------------------------------------------------------- */

static inline silk_vec3 silk_v3(silk_fx x, silk_fx y, silk_fx z)
{
    silk_vec3 r = { x, y, z };
    return r;
}
static inline silk_vec3 silk_v3_add(silk_vec3 a, silk_vec3 b)
{
    return silk_v3(silk_fx_add(a.x, b.x), silk_fx_add(a.y, b.y), silk_fx_add(a.z, b.z));
}
static inline silk_vec3 silk_v3_sub(silk_vec3 a, silk_vec3 b)
{
    return silk_v3(silk_fx_sub(a.x, b.x), silk_fx_sub(a.y, b.y), silk_fx_sub(a.z, b.z));
}
static inline silk_vec3 silk_v3_scale(silk_vec3 a, silk_fx s)
{
    return silk_v3(silk_fx_mul(a.x, s), silk_fx_mul(a.y, s), silk_fx_mul(a.z, s));
}
static inline silk_vec3 silk_v3_neg(silk_vec3 a) { return silk_v3(-a.x, -a.y, -a.z); }

/* Dot product as a Q32.32 int64: exact, no rounding.  It cannot overflow
 * while the three products sum below 2^63: always when either vector has
 * components within +-16384 (so for model coordinates and unit vectors),
 * but three near-full-range products can (3 * 2^62).  Use it whenever only
 * the sign or a ratio is needed. */
static inline int64_t silk_v3_dot64(silk_vec3 a, silk_vec3 b)
{
    return (int64_t)a.x * b.x + (int64_t)a.y * b.y + (int64_t)a.z * b.z;
}
/* Dot product in Q16.16, rounded, saturated. */
static inline silk_fx silk_v3_dot(silk_vec3 a, silk_vec3 b)
{
    return silk_fx_sat(silk_shr_round64(silk_v3_dot64(a, b), 16));
}
static inline int silk_v3_sign_dot(silk_vec3 a, silk_vec3 b)
{
    int64_t d = silk_v3_dot64(a, b);
    return (d > 0) - (d < 0);
}

silk_vec3 silk_v3_cross(silk_vec3 a, silk_vec3 b);     /* rounded, saturated */
silk_fx   silk_v3_length(silk_vec3 a);                 /* exact-rounded, saturated */
/* Unit vector in a's direction, accurate for any nonzero a (including
 * components of 1 ulp): it rescales before taking the length.  The zero
 * vector gives the zero vector; returns 0 then, 1 otherwise. */
int       silk_v3_normalize(silk_vec3 a, silk_vec3 *out);
/* 1/sqrt(M) in Q16 at the centre of each of 192 slices of M in [1, 4) (read-only). */
extern const uint16_t silk_rsqrt_seed[192];

/* 1/sqrt(ss) for a sum of squares ss > 0, the core of silk_unit64: ss
 * rescaled by an even shift, a table seed and two Newton steps (relative
 * error below 3e-9).  A component c of the vector becomes
 * (c r + 2^(rs-1)) >> rs. */
static inline uint32_t silk_rsqrt_ss(uint64_t ss, int *rs)
{
#if defined(__GNUC__)
    int e = __builtin_clzll(ss) & ~1;
#else
    int e = 0;
    while (!(ss << e >> 62)) e += 2;
#endif
    uint32_t m = (uint32_t)((ss << e) >> 32);
    uint32_t r = (uint32_t)silk_rsqrt_seed[(m >> 24) - 64] << 15;
    for (int i = 0; i < 2; i++) {       /* Newton: r' = r (3 - M r^2) / 2 */
        uint32_t r2 = (uint32_t)(((uint64_t)r * r) >> 32);
        uint32_t mr2 = (uint32_t)(((uint64_t)m * r2) >> 30);
        r = (uint32_t)(((uint64_t)r * (3u * (1u << 30) - mr2)) >> 31);
    }
    *rs = 46 - e / 2;
    return r;
}

/* Unit vector of (x, y, z), |components| < 2^31, in Q16.16 (the work of
 * silk_v3_normalize): silk_rsqrt_ss of the sum of squares, one product and
 * rounding shift per component.  Inline: fragment stages call it per
 * pixel.  Returns 0 (and a zero vector) for the zero vector. */
static inline int silk_unit64(int64_t x, int64_t y, int64_t z, int64_t out[3])
{
#if !SILK_CPU32
    /* The same bits without the sign-magnitude detour: squares of the
     * components as they are (modulo 2^64, as the magnitudes' would be),
     * and for c < 0, (c r + 2^(rs-1) - 1) >> rs (arithmetic shift: the
     * floor) is -((|c| r + 2^(rs-1)) >> rs), the magnitude's rounding
     * mirrored.  |c r| is about 2^rs: no overflow. */
    uint64_t ss = (uint64_t)x * (uint64_t)x + (uint64_t)y * (uint64_t)y + (uint64_t)z * (uint64_t)z;
    if (ss == 0) { out[0] = out[1] = out[2] = 0; return 0; }
    int rs;
    int64_t r = silk_rsqrt_ss(ss, &rs), half = (int64_t)1 << (rs - 1);
    out[0] = (x * r + half - (x < 0)) >> rs;
    out[1] = (y * r + half - (y < 0)) >> rs;
    out[2] = (z * r + half - (z < 0)) >> rs;
    return 1;
#else
    uint64_t ux = (uint64_t)(x < 0 ? -x : x), uy = (uint64_t)(y < 0 ? -y : y), uz = (uint64_t)(z < 0 ? -z : z);
    uint64_t ss = ux * ux + uy * uy + uz * uz;
    if (ss == 0) { out[0] = out[1] = out[2] = 0; return 0; }
    int rs;
    uint32_t r = silk_rsqrt_ss(ss, &rs);
    uint64_t half = (uint64_t)1 << (rs - 1);
    int64_t nx = (int64_t)((ux * r + half) >> rs), ny = (int64_t)((uy * r + half) >> rs),
            nz = (int64_t)((uz * r + half) >> rs);
    out[0] = x < 0 ? -nx : nx;
    out[1] = y < 0 ? -ny : ny;
    out[2] = z < 0 ? -nz : nz;
    return 1;
#endif
}

/* silk_unit64 of a silk_fx vector, the same bits from 32-by-32-bit
 * products: a 32-bit processor's single multiply instruction each, where
 * silk_unit64's 64-bit ones take three.  The default fragment stage's. */
int silk_unit_fx(silk_fx x, silk_fx y, silk_fx z, int32_t out[3]);

/* a + (b-a)*t */
silk_vec3 silk_v3_lerp(silk_vec3 a, silk_vec3 b, silk_fx t);

#ifdef __cplusplus
}
#endif

#endif
