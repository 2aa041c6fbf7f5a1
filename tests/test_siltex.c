/*
 * test_siltex.c - silhouette textures at run time (src/siltex.c) against
 * double-precision references written here: the azimuth, cos(phi), the
 * texel frame, the interpolated lookup and eq. 4, the compressed form's
 * reconstruction; the loader on an analytic model (tests/support/stexgen.c);
 * frames of siltex mode: bands equal to the whole frame, the outline of a
 * sphere against its exact outline, the anti-aliased outline against a
 * supersampled frame, one sphere in front of another.
 *
 *   test_siltex --write FILE [two|tiny|tiny-compressed]   write the analytic model (for
 *                                         the command's tests, tests/bad and
 *                                         the fuzz seeds)
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "silk/siltex.h"
#include "support/exact_silhouette.h"
#include "support/scene.h"
#include "support/stexgen.h"
#include "support/testframe.h"
#include "../platform/platform.h"

#define PI 3.14159265358979323846

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double rnd(void)   /* uniform in [0, 1) */
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}
static void rnd_unit(double v[3])
{
    double n;
    do {
        for (int k = 0; k < 3; k++) v[k] = 2 * rnd() - 1;
        n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    } while (n < 0.1 || n > 1);
    for (int k = 0; k < 3; k++) v[k] /= n;
}
static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static silk_fx fx(double v) { return (silk_fx)lround(v * 65536); }

TEST(azimuth_matches_atan2)
{
    double worst = 0;
    for (int i = 0; i < 200000; i++) {
        double s = pow(2, 40 * rnd() - 4);   /* from 1/16 to 2^36 */
        int64_t x = (int64_t)llround((2 * rnd() - 1) * s), y = (int64_t)llround((2 * rnd() - 1) * s);
        if (i < 8) x = (i & 1) ? 0 : (i & 2 ? 5 : -5), y = (i & 4) ? 7 : -7;   /* the axes */
        if (x == 0 && y == 0) continue;
        double ref = atan2((double)y, (double)x);
        if (ref < 0) ref += 2 * PI;
        double got = silk_siltex_azimuth(x, y) * 2 * PI / 1048576.0, e = fabs(got - ref);
        if (e > PI) e = 2 * PI - e;
        if (e > worst) worst = e;
    }
    CHECKF(worst < 1e-5, "azimuth error %.3g rad", worst);
    CHECK(silk_siltex_azimuth(0, 0) == 0);
    CHECK(silk_siltex_azimuth(1, 0) == 0);
    CHECK(silk_siltex_azimuth(0, 1) == 1u << 18);
    CHECK(silk_siltex_azimuth(-1, 0) == 1u << 19);
    CHECK(silk_siltex_azimuth(0, -1) == 3u << 18);
    printf("azimuth: largest error %.2g rad\n", worst);
}

TEST(cos_matches)
{
    double worst = 0;
    for (uint32_t q16 = 0; q16 <= 255u << 16; q16 += 97) {
        double ref = cos(q16 / 65536.0 * PI / 255), e = fabs(silk_siltex_cos(q16) / 1073741824.0 - ref);
        if (e > worst) worst = e;
    }
    CHECKF(worst < 4e-9, "cos error %.3g", worst);
    CHECK(silk_siltex_cos(0) == 1 << 30);
    CHECK(silk_siltex_cos(255u << 16) == -(1 << 30));
    printf("cos: largest error %.2g\n", worst);
}

TEST(acos_matches)
{
    double worst = 0;
    for (int64_t c = -(1 << 30); c <= 1 << 30; c += 4099) {
        double ref = acos(c / 1073741824.0) * 255 / PI, e = fabs(silk_siltex_acos(c) / 65536.0 - ref);
        /* the ends, where acos is steepest, are linear over one table step */
        if (fabs(c / 1073741824.0) < cos(PI / 255) && e > worst) worst = e;
    }
    CHECKF(worst < 4e-3, "acos error %.3g q", worst);   /* 5e-5 rad */
    CHECK(silk_siltex_acos(1 << 30) == 0 && silk_siltex_acos(-(1 << 30)) == 255u << 16);
    CHECK(silk_siltex_acos((int64_t)1 << 31) == 0 && silk_siltex_acos(-((int64_t)1 << 31)) == 255u << 16);
    /* the inverse of silk_siltex_cos */
    uint32_t off = 0;
    for (uint32_t q16 = 1u << 16; q16 < 254u << 16; q16 += 101) {
        uint32_t back = silk_siltex_acos(silk_siltex_cos(q16));
        uint32_t d = back > q16 ? back - q16 : q16 - back;
        off = d > off ? d : off;
    }
    CHECKF(off <= 256, "acos(cos(q)) off by %u / 65536 q", off);
    printf("acos: largest error %.2g q inside the end steps; acos(cos(q)) within %u / 65536 q\n", worst, off);
}

/* A random hull frame: C and T unit (T across C), perturbed as
 * interpolation does (shorter, not quite across). */
static void rnd_frame(double c[3], double t[3], silk_fx cf[3], silk_fx tf[3])
{
    double a[3];
    rnd_unit(c);
    rnd_unit(a);
    t[0] = c[1] * a[2] - c[2] * a[1];
    t[1] = c[2] * a[0] - c[0] * a[2];
    t[2] = c[0] * a[1] - c[1] * a[0];
    double n = sqrt(dot(t, t)), sc = 0.7 + 0.3 * rnd(), st = 0.7 + 0.3 * rnd();
    for (int k = 0; k < 3; k++) {
        t[k] = t[k] / n + 0.05 * (2 * rnd() - 1) * c[k];
        cf[k] = fx(c[k] * sc);
        tf[k] = fx(t[k] * st);
    }
}

/* The reference frame (C, T', B) from the same inputs. */
static void ref_frame(const silk_fx cf[3], const silk_fx tf[3], double C[3], double T[3], double B[3])
{
    double c[3] = { cf[0] / 65536.0, cf[1] / 65536.0, cf[2] / 65536.0 }, t[3] = { tf[0] / 65536.0, tf[1] / 65536.0,
                                                                                    tf[2] / 65536.0 };
    double n = sqrt(dot(c, c));
    for (int k = 0; k < 3; k++) C[k] = c[k] / n;
    double tc = dot(t, C);
    for (int k = 0; k < 3; k++) T[k] = t[k] - tc * C[k];
    n = sqrt(dot(T, T));
    for (int k = 0; k < 3; k++) T[k] /= n;
    B[0] = C[1] * T[2] - C[2] * T[1];
    B[1] = C[2] * T[0] - C[0] * T[2];
    B[2] = C[0] * T[1] - C[1] * T[0];
}

TEST(frame_matches)
{
    double worst = 0;
    for (int i = 0; i < 20000; i++) {
        double c[3], t[3], C[3], T[3], B[3];
        silk_fx cf[3], tf[3];
        int64_t Cg[3], Tg[3], Bg[3];
        rnd_frame(c, t, cf, tf);
        ref_frame(cf, tf, C, T, B);
        CHECK(silk_siltex_frame(cf, tf, Cg, Tg, Bg));
        for (int k = 0; k < 3; k++) {
            double e = fmax(fabs(Cg[k] / 65536.0 - C[k]), fmax(fabs(Tg[k] / 65536.0 - T[k]), fabs(Bg[k] / 65536.0 - B[k])));
            if (e > worst) worst = e;
        }
    }
    CHECKF(worst < 1e-4, "frame error %.3g", worst);
    /* a T along C still gives a frame */
    silk_fx c[3] = { 0, 0, SILK_FX_ONE }, t[3] = { 0, 0, SILK_FX_ONE };
    int64_t C[3], T[3], B[3];
    CHECK(silk_siltex_frame(c, t, C, T, B) && llabs(T[2]) < 2 && llabs(B[2]) < 2);
    silk_fx z[3] = { 0, 0, 0 };
    CHECK(!silk_siltex_frame(z, t, C, T, B));
}

/* ---- lookups over a texture in memory ------------------------------------------- */

enum { TW = 9, TH = 8 };

typedef struct mem_tex {
    silk_siltex st;
    uint8_t angles[TW * TH * SILK_STEX_MAX_K];
    uint8_t normal[2 * TW * TH];
} mem_tex;

static void mem_tex_init(mem_tex *m, uint32_t k)
{
    memset(m, 0, sizeof *m);
    m->st.w = TW;
    m->st.h = TH;
    m->st.k = k;
    m->st.angles = m->angles;
    m->st.normal = m->normal;
    for (size_t i = 0; i < sizeof m->angles; i++) m->angles[i] = (uint8_t)(20 + rnd() * 200);
}

/* phi in q units: bilinear over the texel centres (clamped) x linear in azimuth */
static double ref_phi(const mem_tex *m, double u, double v, double theta)
{
    double fx_ = u - 0.5, fy = v - 0.5, x0 = floor(fx_), y0 = floor(fy), wx = fx_ - x0, wy = fy - y0;
    double s = theta / (2 * PI) * m->st.k, k0 = floor(s), f = s - k0;
    int i0 = (int)k0 % (int)m->st.k, i1 = (i0 + 1) % (int)m->st.k;
    double acc = 0;
    for (int j = 0; j < 4; j++) {
        int x = (int)x0 + (j & 1), y = (int)y0 + (j >> 1);
        x = x < 0 ? 0 : (x >= TW ? TW - 1 : x);
        y = y < 0 ? 0 : (y >= TH ? TH - 1 : y);
        const uint8_t *q = &m->angles[(y * TW + x) * m->st.k];
        double p = q[i0] * (1 - f) + q[i1] * f;
        acc += p * ((j & 1) ? wx : 1 - wx) * ((j >> 1) ? wy : 1 - wy);
    }
    return acc;
}

TEST(phi_interpolates)
{
    double worst = 0;
    for (int i = 0; i < 50000; i++) {
        mem_tex m;
        if (i % 1000 == 0) mem_tex_init(&m, 4 + (uint32_t)(rnd() * 61));
        static mem_tex keep;
        if (i % 1000 == 0) keep = m;
        double u = -1 + rnd() * (TW + 2), v = -1 + rnd() * (TH + 2), theta = rnd() * 2 * PI;
        uint32_t az = (uint32_t)(theta / (2 * PI) * 1048576) & 0xFFFFF;
        double ref = ref_phi(&keep, u, v, az * 2 * PI / 1048576.0);
        double got = silk_siltex_phi(&keep.st, fx(u), fx(v), az) / 65536.0, e = fabs(got - ref);
        if (e > worst) worst = e;
    }
    CHECKF(worst < 0.01, "phi error %.3g q", worst);
    printf("phi: largest error %.2g q\n", worst);
}

TEST(visible_matches_eq4)
{
    static mem_tex m;
    long wrong = 0, close = 0, seen = 0;
    for (int i = 0; i < 100000; i++) {
        if (i % 5000 == 0) mem_tex_init(&m, 4 + (uint32_t)(rnd() * 61));
        double c[3], t[3], C[3], T[3], B[3], d[3];
        silk_fx cf[3], tf[3];
        rnd_frame(c, t, cf, tf);
        ref_frame(cf, tf, C, T, B);
        /* directions near the lobe's edge as often as not */
        if (i & 1) {
            rnd_unit(d);
        } else {
            double a = rnd() * PI, th = rnd() * 2 * PI;
            for (int k = 0; k < 3; k++) d[k] = cos(a) * C[k] + sin(a) * (cos(th) * T[k] + sin(th) * B[k]);
        }
        int64_t dg[3];
        silk_fx df[3] = { fx(d[0]), fx(d[1]), fx(d[2]) };
        silk_unit64(df[0], df[1], df[2], dg);
        double dd[3] = { dg[0] / 65536.0, dg[1] / 65536.0, dg[2] / 65536.0 };
        double u = rnd() * TW, v = rnd() * TH;
        double theta = atan2(dot(dd, B), dot(dd, T));
        if (theta < 0) theta += 2 * PI;
        double phi = ref_phi(&m, fx(u) / 65536.0, fx(v) / 65536.0, theta) * PI / 255;
        double ang = acos(fmax(-1, fmin(1, dot(dd, C))));
        int ref = ang <= phi, got = silk_siltex_visible(&m.st, fx(u), fx(v), cf, tf, dg);
        seen += ref;
        /* the fixed-point frame and azimuth move the edge by about 1e-4 rad */
        if (got != ref) {
            if (fabs(ang - phi) < 5e-4) close++;
            else wrong++;
        }
    }
    CHECKF(wrong == 0, "%ld of 100000 decided wrongly away from the edge (%ld at it)", wrong, close);
    CHECK(seen > 20000 && seen < 80000);
    printf("eq. 4: %ld of 100000 directions within 5e-4 rad of the edge decided the other way\n", close);
}

TEST(compressed_reconstruction)
{
    enum { K = 13, E = 5, N = 40 };
    static uint8_t mean[2 * K], scale[4 * E], basis[2 * E * K], weights[N * E];
    long wrong = 0;
    for (int round = 0; round < 200; round++) {
        int16_t mv[K], bv[E * K];
        int32_t sv[E];
        int8_t wv[N * E];
        for (int i = 0; i < K; i++) mv[i] = (int16_t)(rnd() * 4095);
        for (int j = 0; j < E; j++) sv[j] = (int32_t)((rnd() * 2 - 1) * (round % 2 ? 2147483647.0 : 200000.0));
        for (int i = 0; i < E * K; i++) bv[i] = (int16_t)((rnd() * 2 - 1) * 32767);
        for (int i = 0; i < N * E; i++) wv[i] = (int8_t)((rnd() * 2 - 1) * 127);
        for (int i = 0; i < K; i++) mean[2 * i] = (uint8_t)mv[i], mean[2 * i + 1] = (uint8_t)((uint16_t)mv[i] >> 8);
        for (int j = 0; j < E; j++)
            for (int b = 0; b < 4; b++) scale[4 * j + b] = (uint8_t)((uint32_t)sv[j] >> (8 * b));
        for (int i = 0; i < E * K; i++) basis[2 * i] = (uint8_t)bv[i], basis[2 * i + 1] = (uint8_t)((uint16_t)bv[i] >> 8);
        memcpy(weights, wv, sizeof weights);
        silk_siltex st;
        memset(&st, 0, sizeof st);
        st.flags = SILK_STEX_COMPRESSED;
        st.k = K;
        st.e = E;
        st.mean = mean;
        st.scale = scale;
        st.basis = basis;
        st.weights = weights;
        for (uint32_t t = 0; t < N; t++)
            for (uint32_t i = 0; i < K; i++) {
                double r = mv[i] / 16.0;
                for (int j = 0; j < E; j++) r += (double)wv[t * E + j] * sv[j] * bv[j * K + i] / 1073741824.0;
                double q = floor(r + 0.5);
                q = q < 0 ? 0 : (q > 255 ? 255 : q);
                if (fabs(r - floor(r) - 0.5) > 1e-6 && silk_siltex_q(&st, t, i) != (uint32_t)q) wrong++;
            }
    }
    CHECKF(wrong == 0, "%ld reconstructions differ from the double sum", wrong);
}

/* ---- the analytic model ------------------------------------------------------------ */

TEST(loads_analytic_model)
{
    stexgen_opts o;
    stexgen_defaults(&o);
    for (int e = 0; e <= 1; e++) {
        o.eigen = e;
        o.color = e;
        size_t len;
        uint8_t *file = stexgen_model(&o, &len);
        CHECK(file != NULL);
        if (!file) return;
        silk_siltex st;
        silk_error err;
        silk_status s = silk_model_siltex(file, len, "sphere.silk", &st, &err);
        CHECKF(s == SILK_OK, "%s", err.msg);
        CHECK(st.ntris == 320 && st.k == 8 && st.e == (uint32_t)e && (st.color != NULL) == e);
        /* every texel's q is asin(r / |p|) at some hull point: between 1/R and 1 */
        uint32_t lo = 255, hi = 0;
        for (uint32_t t = 0; s == SILK_OK && t < st.w * st.h; t++)
            for (uint32_t i = 0; i < st.k && (t / st.w / 6) * 18 + t % st.w / 6 < st.ntris; i++) {   /* cells in use */
                uint32_t q = silk_siltex_q(&st, t, i);
                lo = q < lo ? q : lo;
                hi = q > hi ? q : hi;
            }
        CHECKF(lo >= (uint32_t)floor(asin(1 / 1.06) * 255 / PI) && hi <= 128, "q in %u..%u", lo, hi);
        free(file);
    }
}

typedef struct scene {
    uint8_t *file;
    size_t len;
    void *buf;
    silk_arena a;
    silk_mesh hull;
    silk_siltex st;
} scene;

static void scene_close(scene *s)
{
    free(s->file);
    free(s->buf);
}

/* The model of o loaded: its hull and texture.  0 (a failed check, the
 * scene closed) when that fails. */
static int scene_open(scene *s, const stexgen_opts *o)
{
    memset(s, 0, sizeof *s);
    s->file = stexgen_model(o, &s->len);
    s->buf = malloc(64u << 20);
    silk_error err = { SILK_OK, 0, "out of memory" };
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    lo.part = SILK_PART_HULL;
    int ok = s->file && s->buf;
    if (ok) silk_arena_init(&s->a, s->buf, 64u << 20);
    ok = ok && silk_load_model(s->file, s->len, "spheres.silk", &lo, &s->a, &s->hull, &err) == SILK_OK &&
         silk_model_siltex(s->file, s->len, "spheres.silk", &s->st, &err) == SILK_OK;
    CHECKF(ok, "the analytic model: %s", err.msg);
    if (!ok) scene_close(s);
    return ok;
}

static void render_opts(silk_render_opts *ro, const silk_siltex *st)
{
    silk_render_opts_default(ro);
    ro->mode = SILK_MODE_SILTEX;
    ro->siltex = st;
}

/* The siltex outline of one sphere's hull against the sphere's exact
 * outline, perspective and orthographic, from several sides. */
TEST(outline_matches_sphere)
{
    stexgen_opts o;
    stexgen_defaults(&o);
    scene s;
    if (!scene_open(&s, &o)) return;
    enum { W = 320, H = 240 };
    ts_image img = { 0, 0, NULL, NULL };
    unsigned char *mine = malloc(W * H), *exact = malloc(W * H);
    double worst = 0, sum = 0;
    int nviews = 0;
    for (int i = 0; i < 6; i++) {
        double dir[3], eye[3], tgt[3] = { 0.05, -0.03, 0.02 };
        rnd_unit(dir);
        double dist = 3 + 2 * rnd();
        for (int k = 0; k < 3; k++) eye[k] = tgt[k] + dist * dir[k];
        int ortho = i % 2;
        silk_camera cam = ts_camera(eye, tgt, ortho ? -1.3 : 40, dist - 2, dist + 2, W, H);
        silk_render_opts ro;
        render_opts(&ro, &s.st);
        ro.aa = 0;   /* eq. 4's own outline: pixel centres */
        silk_error err;
        silk_status st = ts_render(&s.a, &s.hull, &cam, &ro, &img, NULL, &err);
        CHECKF(st == SILK_OK, "%s", err.msg);
        for (int p = 0; p < W * H; p++) mine[p] = ts_covered(&img, p % W, p / W) != 0;
        es_camera ec;
        es_camera_from_silk(&ec, &cam);
        es_shape sph = es_sphere(0, 0, 0, 1.0);
        es_mask(&ec, &sph, exact);
        es_points pts = { 0, 0, NULL, NULL };
        es_stats stt;
        CHECK(es_silhouette_points(&ec, &sph, exact, &pts) > 0);
        CHECK(es_compare(mine, exact, &pts, W, H, &stt) == 0);
        if (stt.max_abs_offset > worst) worst = stt.max_abs_offset;
        sum += stt.mean_abs_offset;
        nviews++;
        es_points_free(&pts);
    }
    /* a perfect rasterization of the exact outline is within 0.5 px */
    CHECKF(worst <= 1.0, "the outline is %.2f px from the sphere's", worst);
    printf("siltex outline of the sphere: mean %.3f px, largest %.3f px from the exact outline (%d views, %dx%d)\n",
           sum / nviews, worst, nviews, W, H);
    free(mine);
    free(exact);
    ts_image_free(&img);
    scene_close(&s);
}

static void two_spheres(stexgen_opts *o);

/* A frame of the model at w x h from direction dir (as
 * tf_view_around_size frames it), anti-aliased or not, into rgb (w h 3
 * bytes), depth and alpha (w h bytes, or NULL: none).  0 on failure. */
static int stex_frame(const scene *s, const double dir[3], int ortho, int w, int h, int aa, uint8_t *rgb,
                      uint32_t *depth, uint8_t *alpha)
{
    silk_view v;
    if (!tf_view_around_size(&s->hull, dir, 2.4, ortho, w, h, &v)) return 0;
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    render_opts(&ro, &s->st);
    ro.aa = aa;
    silk_target t;
    silk_target_init(&t, w, h, 0, h, SILK_PIX_RGB888, rgb, depth);
    t.alpha = alpha;
    silk_arena a = s->a;
    silk_error err;
    silk_frame_stats fs;
    silk_status st = silk_render(&a, &s->hull, &v, &hal, &ro, &t, &fs, &err);
    CHECKF(st == SILK_OK && fs.aa_aliased == 0, "%s (%u pixels left aliased)", st ? err.msg : "", fs.aa_aliased);
    return st == SILK_OK;
}

/* The anti-aliased outline (eq. 4's margin, src/aa.c) against the same
 * frame drawn 4 x 4 times larger without it, whose blocks average 16
 * samples of eq. 4 a pixel: over the pixels the two differ on or the
 * large frame covers partly, the mean error of the alpha (one sphere: the
 * outline against the background) and of the colour laid over the
 * background (two spheres: the near one's outline over the far one too),
 * with and without anti-aliasing. */
TEST(outline_antialiased)
{
    enum { W = 160, H = 120, N = 4 };
    const double dirs[4][3] = { { 0.47, 0.342, 0.814 }, { -0.6, 0.2, 0.3 }, { 0.1, -0.8, 0.4 }, { 0.9, 0.1, -0.3 } };
    uint8_t *rgb[2], *alpha[2], *big = malloc(W * H * N * N * 3);
    uint32_t *depth = malloc(W * H * sizeof *depth), *bigd = malloc(W * H * N * N * sizeof *bigd);
    for (int k = 0; k < 2; k++) {
        rgb[k] = malloc(W * H * 3);
        alpha[k] = malloc(W * H);
    }
    for (int two = 0; two <= 1; two++) {
        stexgen_opts o;
        if (two) two_spheres(&o);
        else stexgen_defaults(&o);
        scene s;
        if (!scene_open(&s, &o)) break;
        double err[2] = { 0, 0 }, worst = 0;
        long n = 0, over_half = 0;
        for (int view = 0; view < 4; view++) {
            int ortho = view % 2, ok = stex_frame(&s, dirs[view], ortho, W * N, H * N, 0, big, bigd, NULL);
            for (int k = 0; k < 2; k++) ok = ok && stex_frame(&s, dirs[view], ortho, W, H, !k, rgb[k], depth, alpha[k]);
            if (!ok) break;
            for (int p = 0; p < W * H; p++) {
                int x = p % W, y = p / W, cover = 0;
                double mean[3] = { 0, 0, 0 };
                for (int j = 0; j < N * N; j++) {
                    size_t q = (size_t)(y * N + j / N) * W * N + (size_t)(x * N + j % N);
                    cover += bigd[q] != 0;
                    for (int c = 0; c < 3; c++) mean[c] += big[3 * q + c] / (double)(N * N);
                }
                double ref = cover * 255.0 / (N * N), e[2];
                int edge = (cover > 0 && cover < N * N) || alpha[0][p] != alpha[1][p];
                for (int k = 0; k < 2; k++) {
                    e[k] = 0;
                    if (!two) e[k] = fabs(alpha[k][p] - ref);
                    else   /* laid over the background, white */
                        for (int c = 0; c < 3; c++)
                            e[k] += fabs((alpha[k][p] * rgb[k][3 * p + c] + (255 - alpha[k][p]) * 255) / 255.0 - mean[c]) / 3;
                    if (two && fabs(rgb[1][3 * p] - mean[0]) + fabs(rgb[1][3 * p + 1] - mean[1]) > 4) edge = 1;
                }
                if (!edge) continue;
                n++;
                err[0] += e[0];
                err[1] += e[1];
                over_half += e[0] > 128;
                worst = e[0] > worst ? e[0] : worst;
            }
        }
        CHECK(n > 300);
        if (n) err[0] /= n, err[1] /= n;
        CHECKF(err[0] <= 0.25 * err[1], "%s: mean error %.2f anti-aliased, %.2f without", two ? "colour" : "alpha",
               err[0], err[1]);
        CHECKF(over_half == 0, "%ld pixels off by more than half", over_half);
        printf("siltex anti-aliased outline, %s, 4 views at %dx%d against 4x4 supersampling: %ld pixels, mean error "
               "%.2f of 255 (%.2f without anti-aliasing), largest %.0f\n",
               two ? "two spheres, colour" : "sphere, alpha", W, H, n, err[0], err[1], worst);
        scene_close(&s);
    }
    for (int k = 0; k < 2; k++) {
        free(rgb[k]);
        free(alpha[k]);
    }
    free(big);
    free(bigd);
    free(depth);
}

static void two_spheres(stexgen_opts *o)
{
    stexgen_defaults(o);
    o->nspheres = 2;
    o->c[1][0] = 1.2;
    o->c[1][1] = 0.3;
    o->c[1][2] = -1.6;
    o->r[1] = 0.8;
    o->R[1] = 0.85;
    o->color = 1;
}

/* The two spheres seen with the near one in front of the far one,
 * 320 x 240, rendered into img (lines as asked); the exact masks of both
 * spheres into ma and mb (W * H bytes each).  0 when it failed. */
enum { OW = 320, OH = 240 };
static int render_overlap(const scene *s, silk_lines lines, ts_image *img, unsigned char *ma, unsigned char *mb)
{
    double eye[3] = { 0.3, 0.2, 6 }, tgt[3] = { 0.6, 0.15, -0.8 };
    silk_camera cam = ts_camera(eye, tgt, 40, 2, 12, OW, OH);
    silk_render_opts ro;
    render_opts(&ro, &s->st);
    ro.lines = lines;
    ro.line_rgb = 0x000000;
    ro.bg_rgb = 0xFFFFFF;
    silk_error err;
    silk_arena a = s->a;
    silk_status st = ts_render(&a, &s->hull, &cam, &ro, img, NULL, &err);
    CHECKF(st == SILK_OK, "%s", err.msg);
    es_camera ec;
    es_camera_from_silk(&ec, &cam);
    es_shape sa = es_sphere(0, 0, 0, 1.0), sb = es_sphere(1.2, 0.3, -1.6, 0.8);
    es_mask(&ec, &sa, ma);
    es_mask(&ec, &sb, mb);
    return st == SILK_OK;
}

/* One sphere in front of another: where the front hull's pixels are
 * killed, the hull behind shows, so the mask is the union of both
 * spheres' exact masks (the interior silhouette where they overlap). */
TEST(interior_silhouette)
{
    stexgen_opts o;
    two_spheres(&o);
    scene s;
    if (!scene_open(&s, &o)) return;
    enum { W = OW, H = OH };
    ts_image img = { 0, 0, NULL, NULL };
    long off = 0, both = 0, behind_seen = 0;
    unsigned char *ma = malloc(W * H), *mb = malloc(W * H), *mine = malloc(W * H), *exact = malloc(W * H);
    render_overlap(&s, SILK_LINES_NONE, &img, ma, mb);
    for (int p = 0; p < W * H; p++) {
        exact[p] = ma[p] | mb[p];
        mine[p] = ts_covered(&img, p % W, p / W) != 0;
        both += ma[p] && mb[p];
    }
    double hd = es_boundary_hausdorff(mine, exact, W, H);
    /* pixels of the far sphere seen through the near hull (inside the near
     * hull's screen area, outside the near sphere): drawn */
    for (int p = 0; p < W * H; p++) {
        off += mine[p] != exact[p];
        behind_seen += mb[p] && !ma[p] && mine[p];
    }
    CHECKF(both > 500, "the spheres overlap in %ld pixels", both);
    CHECKF(hd <= 1.5, "the outline is %.2f px from the exact one", hd);
    CHECK(behind_seen > 1000);
    printf("two spheres: %ld pixels overlap, %ld differ from the exact union, boundary distance %.2f px\n", both, off,
           hd);
    free(ma);
    free(mb);
    free(mine);
    free(exact);
    ts_image_free(&img);
    scene_close(&s);
}

TEST(bands_equal_frame)
{
    stexgen_opts o;
    two_spheres(&o);
    o.eigen = 1;
    scene s;
    if (!scene_open(&s, &o)) return;
    for (int ortho = 0; ortho <= 1; ortho++) {
        const double dir[3] = { 0.47, 0.342, 0.814 };
        silk_view v;
        CHECK(tf_view_around_size(&s.hull, dir, 2.2, ortho, 200, 150, &v));
        silk_phong ph;
        silk_hal hal;
        silk_phong_default(&ph, &v);
        silk_hal_phong(&hal, &ph);
        silk_render_opts ro;
        render_opts(&ro, &s.st);
        size_t bytes = 200 * 150 * 3;
        uint8_t *whole = malloc(bytes), *band = malloc(bytes);
        uint32_t *depth = malloc(200 * 150 * 4);
        silk_target t;
        silk_target_init(&t, 200, 150, 0, 150, SILK_PIX_RGB888, whole, depth);
        silk_error err;
        silk_frame_stats fs;
        CHECKF(silk_render(&s.a, &s.hull, &v, &hal, &ro, &t, &fs, &err) == SILK_OK, "%s", err.msg);
        long drawn = 0;
        for (size_t i = 0; i < bytes; i += 3) drawn += whole[i] != 0xFF || whole[i + 1] != 0xFF;
        CHECK(drawn > 2000);
        int rows[2] = { 16, 1 };
        ro.lines = ortho ? SILK_LINES_OVER : SILK_LINES_NONE;   /* with the lines of eq. 5 too */
        CHECKF(silk_render(&s.a, &s.hull, &v, &hal, &ro, &t, &fs, &err) == SILK_OK, "%s", err.msg);
        for (int k = 0; k < 2; k++) {
            tf_collect c = { band, 0, 0, 0, 0, 0 };
            CHECK(tf_render_bands(&s.a, &s.hull, &v, &hal, &ro, SILK_PIX_RGB888, rows[k], &c, NULL, &err) == SILK_OK);
            CHECKF(memcmp(band, whole, bytes) == 0, "bands of %d rows differ (%s)", rows[k], ortho ? "ortho" : "persp");
        }
        free(whole);
        free(band);
        free(depth);
    }
    scene_close(&s);
}

/* Silhouette lines (eq. 5) alone: every line pixel lies near the exact
 * outline of one sphere or the other (the interior silhouette of the near
 * one over the far one among them), and every point of the exact outline
 * has a line pixel near it; the bands give the whole frame. */
TEST(lines_follow_outlines)
{
    stexgen_opts o;
    two_spheres(&o);
    scene s;
    if (!scene_open(&s, &o)) return;
    enum { W = OW, H = OH };
    ts_image img = { 0, 0, NULL, NULL };
    unsigned char *ma = malloc(W * H), *mb = malloc(W * H), *vis = malloc(W * H);
    render_overlap(&s, SILK_LINES_ONLY, &img, ma, mb);
    /* the exact outlines as drawn: a's whole outline, b's where a does not hide it */
    for (int p = 0; p < W * H; p++) vis[p] = (unsigned char)(ma[p] ? 2 : mb[p] ? 1 : 0);
    long lines = 0, far = 0, edges = 0, missed = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const uint8_t *c = &img.rgb[3 * (y * W + x)];
            int line = c[0] == 0 && c[1] == 0 && c[2] == 0;
            /* near an edge of vis: within 2 px of a pixel of another value */
            int near = 0, edge = 0;
            for (int dy = -2; dy <= 2; dy++)
                for (int dx = -2; dx <= 2; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
                    if (vis[yy * W + xx] != vis[y * W + x]) {
                        near = 1;
                        if (dx * dx + dy * dy <= 1 && vis[y * W + x] > vis[yy * W + xx]) edge = 1;
                    }
                }
            lines += line;
            far += line && !near;
            if (edge) {
                int found = 0;
                for (int dy = -2; dy <= 2 && !found; dy++)
                    for (int dx = -2; dx <= 2 && !found; dx++) {
                        int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
                        const uint8_t *q = &img.rgb[3 * (yy * W + xx)];
                        found = q[0] == 0 && q[1] == 0 && q[2] == 0;
                    }
                edges++;
                missed += !found;
            }
        }
    CHECKF(lines > 300, "%ld line pixels", lines);
    CHECKF(far * 50 <= lines, "%ld of %ld line pixels more than 2 px from an outline", far, lines);
    CHECKF(missed * 50 <= edges, "%ld of %ld outline pixels without a line within 2 px", missed, edges);
    printf("lines: %ld pixels, %ld away from the outlines; %ld of %ld outline pixels without a line near\n", lines,
           far, missed, edges);
    free(ma);
    free(mb);
    free(vis);
    ts_image_free(&img);
    scene_close(&s);
}

TEST(refuses_wrong_input)
{
    stexgen_opts o;
    stexgen_defaults(&o);
    scene s;
    if (!scene_open(&s, &o)) return;
    silk_view v;
    const double dir[3] = { 0, 0, 1 };
    CHECK(tf_view_around_size(&s.hull, dir, 2.2, 0, 64, 48, &v));
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    render_opts(&ro, NULL);
    uint8_t color[64 * 48 * 3];
    uint32_t depth[64 * 48];
    silk_target t;
    silk_target_init(&t, 64, 48, 0, 48, SILK_PIX_RGB888, color, depth);
    silk_error err;
    CHECK(silk_render(&s.a, &s.hull, &v, &hal, &ro, &t, NULL, &err) == SILK_ERR_ARG && strstr(err.msg, "texture"));
    /* a model without the section */
    silk_siltex st;
    CHECK(silk_model_siltex(s.file, 40, "x.silk", &st, &err) == SILK_ERR_PARSE);
    scene_close(&s);
}

int main(int argc, char **argv)
{
    if (argc >= 3 && !strcmp(argv[1], "--write")) {
        stexgen_opts o;
        if (argc > 3 && !strcmp(argv[3], "two")) {
            two_spheres(&o);
        } else {
            stexgen_defaults(&o);
            if (argc > 3 && !strncmp(argv[3], "tiny", 4)) o.level = 0, o.cell = 4, o.k = 4, o.R[0] = 1.3;
            if (argc > 3 && !strcmp(argv[3], "tiny-compressed")) o.eigen = 1, o.color = 1;
        }
        size_t len;
        uint8_t *file = stexgen_model(&o, &len);
        FILE *f = file ? fopen(argv[2], "wb") : NULL;
        int ok = f && fwrite(file, 1, len, f) == len;
        if (f) ok &= fclose(f) == 0;
        free(file);
        if (!ok) fprintf(stderr, "test_siltex: cannot write %s\n", argv[2]);
        return ok ? 0 : 1;
    }
    RUN(azimuth_matches_atan2);
    RUN(cos_matches);
    RUN(acos_matches);
    RUN(frame_matches);
    RUN(phi_interpolates);
    RUN(visible_matches_eq4);
    RUN(compressed_reconstruction);
    RUN(loads_analytic_model);
    RUN(outline_matches_sphere);
    RUN(outline_antialiased);
    RUN(interior_silhouette);
    RUN(bands_equal_frame);
    RUN(lines_follow_outlines);
    RUN(refuses_wrong_input);
    return check_done();
}
