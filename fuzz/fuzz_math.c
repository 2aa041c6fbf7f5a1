/*
 * fuzz_math.c - libFuzzer harness for the fixed-point arithmetic every
 * stage is built on, fed arbitrary values within each function's documented
 * input range (docs/overflow.md): Q16.16 scalars and vectors (silk/fixed.h),
 * decimal parsing, the curve constructions of paper eqs. 2-8 (src/curve.c),
 * Hermite and patch evaluation, the camera (src/camera.c), and the
 * rasterizer fed clip-space triangles and lines directly, as a user vertex
 * stage may (src/raster.c).  The sanitizers stop at any signed overflow or
 * shift out of range; the checks below catch wrapped or out-of-range
 * results:
 *   - products, quotients and square roots within one ulp of the exact
 *     value, saturated where it does not fit;
 *   - unit vectors of unit length, angles within their range;
 *   - eq. 4 tangents along their direction and clamped; eq. 6-7 parameters
 *     in [0, 1]; eq. 8 counts in [1, SILK_MAX_SAMPLES];
 *   - a triangle inside the clip volume never shades a pixel twice.
 *
 * Input: one selector byte, then the operands (see each case).
 */
#include <math.h>
#include "fuzz.h"
#include "../src/curve.h"

/* A silk_fx from 4 input bytes: INT32_MIN, outside the symmetric range,
 * becomes SILK_FX_MIN. */
static silk_fx fx_in(fuzz_bytes *b)
{
    int32_t v = (int32_t)fuzz_u32(b);
    return v < SILK_FX_MIN ? SILK_FX_MIN : v;
}

/* Values that sit near the interesting edges more often than uniform bits:
 * the selector picks a scale, the rest a signed mantissa. */
static silk_fx fx_scaled(fuzz_bytes *b)
{
    uint32_t sel = fuzz_u8(b);
    int32_t m = fuzz_i16(b);
    switch (sel & 7) {
    case 0: return m;                                   /* a few ulps */
    case 1: return m * 2;                               /* near zero */
    case 2: return silk_fx_sat((int64_t)m * 256);        /* around 1 */
    case 3: return silk_fx_sat((int64_t)m * 65536);      /* the integers */
    case 4: return m < 0 ? SILK_FX_MIN - m : SILK_FX_MAX - m;   /* near the limits */
    default: return fx_in(b);
    }
}

static silk_vec3 v3_in(fuzz_bytes *b) { return silk_v3(fx_scaled(b), fx_scaled(b), fx_scaled(b)); }

static double dbl(silk_fx v) { return v / 65536.0; }

static double len3(silk_vec3 v) { return sqrt(dbl(v.x) * dbl(v.x) + dbl(v.y) * dbl(v.y) + dbl(v.z) * dbl(v.z)); }

/* |got - exact| <= 1 ulp, or both at the same saturation limit. */
static void near_exact(silk_fx got, double exact, const char *what)
{
    double lim = SILK_FX_MAX / 65536.0;
    if (exact >= lim) fuzz_expect(got == SILK_FX_MAX, "%s: %d, want saturation at +max", what, got);
    else if (exact <= -lim) fuzz_expect(got == SILK_FX_MIN, "%s: %d, want saturation at -max", what, got);
    else fuzz_expect(fabs(dbl(got) - exact) <= 1.0001 / 65536, "%s: %.8f, want %.8f", what, dbl(got), exact);
}

static void scalars(fuzz_bytes *b)
{
    silk_fx x = fx_scaled(b), y = fx_scaled(b), z = fx_scaled(b);
    near_exact(silk_fx_mul(x, y), dbl(x) * dbl(y), "mul");
    near_exact(silk_fx_add(x, y), dbl(x) + dbl(y), "add");
    near_exact(silk_fx_sub(x, y), dbl(x) - dbl(y), "sub");
    if (y) near_exact(silk_fx_div(x, y), dbl(x) / dbl(y), "div");
    else fuzz_expect(silk_fx_div(x, 0) == (x > 0 ? SILK_FX_MAX : x < 0 ? SILK_FX_MIN : 0), "div by 0");
    if (z) near_exact(silk_fx_muldiv(x, y, z), (double)x * y / z / 65536.0, "muldiv");
    if (x) near_exact(silk_fx_recip(x), 1 / dbl(x), "recip");
    silk_fx ax = silk_fx_abs(x);
    near_exact(silk_fx_sqrt(ax), sqrt(dbl(ax)), "sqrt");
    if (ax > 0) {
        silk_fx r = silk_fx_rsqrt(ax);
        double want = 1 / sqrt(dbl(ax));
        fuzz_expect(want >= 32767.99 ? r == SILK_FX_MAX : fabs(dbl(r) - want) <= 2.0 / 65536 + want * 1e-9,
                    "rsqrt(%d) = %d", ax, r);
    }
    fuzz_expect(silk_isqrt64((uint64_t)fuzz_u32(b) << 32 | fuzz_u32(b)) <= 0xFFFFFFFFu, "isqrt64");
    silk_fx s, c;
    silk_fx_sincos(x, &s, &c);
    double n = dbl(s) * dbl(s) + dbl(c) * dbl(c);
    fuzz_expect(fabs(n - 1) < 1e-3, "sin^2 + cos^2 = %.6f for %d", n, x);
    silk_fx_sincos_deg(y, &s, &c);
    fuzz_expect(fabs(dbl(s) * dbl(s) + dbl(c) * dbl(c) - 1) < 1e-3, "sincos_deg(%d)", y);
    silk_fx a = silk_fx_atan2(x, y);
    fuzz_expect(a >= -SILK_FX_PI - 1 && a <= SILK_FX_PI + 1, "atan2 = %d", a);
    a = silk_fx_acos(z);
    fuzz_expect(a >= 0 && a <= SILK_FX_PI + 1, "acos = %d", a);
    (void)silk_fx_round(x);
    (void)silk_fx_floor(x);
    char buf[32];
    silk_fx back;
    const char *end;
    fuzz_expect(silk_fx_parse(silk_fx_format(x, buf), &end, &back) == 0 && *end == '\0', "format %d: %s", x, buf);
    fuzz_expect(back - x <= 1 && x - back <= 1, "format %d -> %s -> %d", x, buf, back);
}

static void math_text(fuzz_bytes *b)
{
    char s[64];
    size_t n = 0;
    while (n < sizeof s - 1 && b->at < b->n) s[n++] = (char)fuzz_u8(b);
    s[n] = '\0';
    silk_fx v;
    const char *end = NULL;
    int r = silk_fx_parse(s, &end, &v);
    fuzz_expect(r == 0 || r == -1 || r == -2, "parse returned %d", r);
    if (r == 0) fuzz_expect(end > s && end <= s + n, "parse end outside the text");
    silk_decimal dec, dec2;
    r = silk_decimal_parse(s, &end, &dec);
    if (r == 0) {
        fuzz_expect(dec.mant < 1000000000000000000LL && dec.mant > -1000000000000000000LL, "decimal mantissa");
        silk_decimal p = silk_decimal_mul(dec, dec);
        (void)silk_decimal_to_fx(p, &v);
        if (silk_decimal_parse(end, &end, &dec2) == 0) (void)silk_decimal_to_fx(silk_decimal_mul(dec, dec2), &v);
    }
}

static void vectors(fuzz_bytes *b)
{
    silk_vec3 p = v3_in(b), q = v3_in(b), u;
    silk_vec3 c = silk_v3_cross(p, q);
    (void)c;
    silk_fx l = silk_v3_length(p);
    near_exact(l, len3(p), "length");
    if (silk_v3_normalize(p, &u)) fuzz_expect(fabs(len3(u) - 1) < 4e-5, "normalize: length %.7f", len3(u));
    else fuzz_expect(p.x == 0 && p.y == 0 && p.z == 0, "normalize refused a nonzero vector");
    silk_fx t = (silk_fx)(fuzz_u32(b) % (SILK_FX_ONE + 1));
    (void)silk_v3_lerp(p, q, t);
    /* dot products: exact while one side is within +-16384 (fixed.h) */
    silk_vec3 small = silk_v3(p.x / 2, p.y / 2, p.z / 2);
    int64_t d64 = silk_v3_dot64(small, q);
    /* long double holds each product and the sum exactly (64-bit mantissa) */
    long double want = (long double)small.x * q.x + (long double)small.y * q.y + (long double)small.z * q.z;
    fuzz_expect((long double)d64 == want, "dot64 not exact");
    (void)silk_v3_dot(small, q);
}

static void curves(fuzz_bytes *b)
{
    silk_vec3 p0 = v3_in(b), p1 = v3_in(b), n0 = v3_in(b), n1 = v3_in(b);
    silk_vec3 t = silk_arc_tangent(n0, p1);
    double lc = len3(p1), lt = len3(t);
    /* clamped at SILK_ARC_MAX_RATIO |chord| (or shortened to fit Q16.16) */
    fuzz_expect(lt <= SILK_ARC_MAX_RATIO * lc * (1 + 1e-6) + 2e-4, "arc tangent %.4f for a chord of %.4f", lt, lc);
    if (lt > 1e-2 && len3(n0) > 1e-2) {
        double cosang = (dbl(t.x) * dbl(n0.x) + dbl(t.y) * dbl(n0.y) + dbl(t.z) * dbl(n0.z)) / (lt * len3(n0));
        fuzz_expect(cosang > 0.999, "arc tangent turned away from its direction (cos %.6f)", cosang);
    }
    silk_curve cv;
    memset(&cv, 0, sizeof cv);
    silk_bridge(p0, n0, p1, n1, fuzz_u8(b) & 1, &cv);   /* with or without the tilt bound */
    fuzz_expect(cv.p0.x == p0.x && cv.p1.z == p1.z, "bridge ends moved");
    for (int k = 0; k <= 4; k++) (void)silk_hermite_point(&cv, SILK_FX_ONE * k / 4);
    (void)silk_hermite_point(&cv, fx_in(b));
    silk_vec3 d0 = v3_in(b), d1 = v3_in(b);
    silk_fx u = silk_silhouette_param(n0, d0, n1, d1);
    fuzz_expect(u >= 0 && u <= SILK_FX_ONE, "silhouette parameter %d", u);
    uint32_t ns = silk_sample_count(fx_in(b), fx_in(b), fx_in(b));
    fuzz_expect(ns >= 1 && ns <= SILK_MAX_SAMPLES, "sample count %u", ns);
    silk_patch pt;
    for (int k = 0; k < 10; k++) pt.b[k] = v3_in(b);
    for (int k = 0; k < 6; k++) pt.n[k] = v3_in(b);
    for (int k = 0; k < 3; k++) pt.uv[k].x = fx_in(b), pt.uv[k].y = fx_in(b);
    silk_vertex_attr at;
    silk_patch_eval(&pt, fuzz_u32(b), &at);
    uint32_t n = 1 + fuzz_u8(b) % SILK_PATCH_MAX_DIV, i = fuzz_u8(b) % (n + 1), j = fuzz_u8(b) % (n + 1 - i);
    silk_patch_eval(&pt, SILK_PATCH_POINT(i, j, n), &at);
}

static void math_camera(fuzz_bytes *b)
{
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = v3_in(b);
    cam.target = v3_in(b);
    cam.up = v3_in(b);
    cam.ortho = fuzz_u8(b) & 1;
    cam.fov_deg = fx_scaled(b);
    cam.ortho_half_height = fx_scaled(b);
    cam.znear = fx_scaled(b);
    cam.zfar = fx_scaled(b);
    cam.width = fuzz_i16(b);
    cam.height = fuzz_i16(b);
    silk_view v;
    silk_error err;
    silk_status st = silk_view_init(&v, &cam, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, "camera");
        return;
    }
    for (int k = 0; k < 4; k++) {
        silk_vec3 p = v3_in(b);
        silk_vec2 px;
        (void)silk_view_clip(&v, p);
        (void)silk_mat4_apply_point(&v.viewproj, p);
        (void)silk_view_project(&v, p, &px);
        (void)silk_view_to_eye(&v, p);
    }
}

/* The varyings are interpolated whether or not a stage reads them (and
 * with nvaryings <= 0 there are none to read). */
static uint32_t math_fragment(const silk_hal *h, const silk_fx *var)
{
    (void)h;
    (void)var;
    return 0x808080;
}

static void math_raster(fuzz_bytes *b)
{
    int width = 1 + (int)(fuzz_u32(b) % SILK_MAX_DIM), height = 1 + (int)(fuzz_u32(b) % SILK_MAX_DIM);
    int rows = 1 + (int)(fuzz_u8(b) % 4), y0 = (int)(fuzz_u32(b) % (uint32_t)height);
    silk_pixfmt fmt = fuzz_u8(b) & 1 ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
    size_t px = (size_t)width * rows;
    /* zeroed: rows of the band past the frame's last row are never touched */
    uint8_t *color = calloc(px, 3);
    uint32_t *depth = calloc(px, sizeof *depth);
    uint16_t *writes = calloc(px, sizeof *writes);
    silk_target t;
    silk_target_init(&t, width, height, y0, rows, fmt, color, depth);
    t.writes = writes;
    silk_target_clear(&t, fuzz_u32(b));
    silk_hal h;
    memset(&h, 0, sizeof h);
    h.fragment = math_fragment;
    h.nvaryings = (int)(fuzz_u8(b) % (SILK_MAX_VARYINGS + 2)) - 1;
    silk_vertex_out v[3];
    for (int k = 0; k < 3; k++) {
        v[k].clip.x = fx_scaled(b);
        v[k].clip.y = fx_scaled(b);
        v[k].clip.z = fx_scaled(b);
        v[k].clip.w = fx_scaled(b);
        for (int j = 0; j < SILK_MAX_VARYINGS; j++) v[k].var[j] = fx_in(b);
    }
    silk_raster_triangle(&t, &h, &v[0], &v[1], &v[2]);
    /* A triangle inside the clip volume is one triangle on screen: no pixel
     * twice.  A clipped one is a polygon whose snapped corners can cross
     * when it is a sliver (raster.c, raster_polygon): that may shade a
     * pixel of it twice, with its own colour, so it is not checked. */
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        const silk_vec4 *c = &v[k].clip;
        int64_t w = c->w;
        inside &= w >= 16 && (int64_t)c->z >= -w && c->z <= w && 2 * w >= c->x && 2 * w >= -(int64_t)c->x &&
                  2 * w >= c->y && 2 * w >= -(int64_t)c->y;
    }
    for (size_t i = 0; inside && i < px; i++)
        fuzz_expect(writes[i] <= 1, "pixel %zu of the band shaded %u times", i, writes[i]);
    silk_raster_line(&t, &v[0], &v[1], 0x123456);
    silk_raster_line(&t, &v[2], &v[2], 0x654321);
    free(color);
    free(depth);
    free(writes);
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_bytes b = { data, size, 0 };
    switch (fuzz_u8(&b) % 6) {
    case 0: scalars(&b); break;
    case 1: math_text(&b); break;
    case 2: vectors(&b); break;
    case 3: curves(&b); break;
    case 4: math_camera(&b); break;
    default: math_raster(&b); break;
    }
    return 0;
}
