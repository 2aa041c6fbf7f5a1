/*
 * test_texture.c - textures, texture coordinates and vertex colours.
 *
 *  - sampling (src/texture.c) against a double-precision reference written
 *    here: nearest and bilinear, repeat and clamp, the three texel formats,
 *    mipmap building and the level chosen from the footprint;
 *  - vertex colours from OBJ and PLY, and their range errors;
 *  - no seam on the re-meshed surface: a checker-textured globe (gen --uv)
 *    in smooth, PN and blend modes from several views; every point the
 *    vertex stage evaluates more than once (curve samples, patch points,
 *    corners, shared by the triangles on both sides of an edge) must get
 *    bit-identical texture coordinates each time (u may differ by exactly 1
 *    where the globe's own u = 0 seam runs);
 *  - no shimmer: a checker-textured quad seen at a grazing angle on a slow
 *    turntable (see shimmer below for the threshold).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "../tools/prep/gen.h"
#include "support/testmesh.h"
#include "support/testframe.h"

static double fxd(silk_fx v) { return v / 65536.0; }
static silk_fx dfx(double v) { return (silk_fx)lround(v * 65536.0); }
static int chan(uint32_t c, int k) { return (int)(c >> (16 - 8 * k) & 0xff); }

/* ---- sampling ------------------------------------------------------------------ */

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* Reference: texel (x, y) of level 0 under the wrap mode, as 0xRRGGBB. */
static uint32_t ref_texel(const uint8_t *rgb, int w, int h, int wrap, int x, int y)
{
    if (wrap == SILK_TEX_CLAMP) {
        x = x < 0 ? 0 : (x >= w ? w - 1 : x);
        y = y < 0 ? 0 : (y >= h ? h - 1 : y);
    } else {
        x = ((x % w) + w) % w;
        y = ((y % h) + h) % h;
    }
    const uint8_t *p = rgb + 3 * ((size_t)y * w + x);
    return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

/* Reference bilinear at (u, v), v up, texel centres at half integers; channel k. */
static double ref_bilinear(const uint8_t *rgb, int w, int h, int wrap, double u, double v, int k)
{
    double x = u * w - 0.5, y = (1 - v) * h - 0.5;
    int x0 = (int)floor(x), y0 = (int)floor(y);
    double fx = x - x0, fy = y - y0;
    double c00 = chan(ref_texel(rgb, w, h, wrap, x0, y0), k), c10 = chan(ref_texel(rgb, w, h, wrap, x0 + 1, y0), k);
    double c01 = chan(ref_texel(rgb, w, h, wrap, x0, y0 + 1), k), c11 = chan(ref_texel(rgb, w, h, wrap, x0 + 1, y0 + 1), k);
    return (c00 * (1 - fx) + c10 * fx) * (1 - fy) + (c01 * (1 - fx) + c11 * fx) * fy;
}

TEST(bilinear_and_nearest_match_reference)
{
    enum { W = 7, H = 5 };
    uint8_t px[W * H * 3];
    uint32_t seed = 7;
    for (size_t i = 0; i < sizeof px; i++) px[i] = (uint8_t)lcg(&seed);
    double worst = 0;
    int nearest_bad = 0;
    for (int wrap = 0; wrap < 2; wrap++)
        for (int i = 0; i < 4000; i++) {
            double u = (lcg(&seed) % 40000) / 10000.0 - 1.5, v = (lcg(&seed) % 40000) / 10000.0 - 1.5;
            silk_fx fu = dfx(u), fv = dfx(v);
            u = fxd(fu);
            v = fxd(fv);
            silk_texture t = { px, NULL, W, H, SILK_TEX_RGB888, 1, SILK_TEX_BILINEAR, (uint8_t)wrap };
            uint32_t got = silk_texture_sample(&t, fu, fv, 0, 0);
            for (int k = 0; k < 3; k++) {
                double e = fabs(chan(got, k) - ref_bilinear(px, W, H, wrap, u, v, k));
                if (e > worst) worst = e;
            }
            t.filter = SILK_TEX_NEAREST;
            uint32_t ref = ref_texel(px, W, H, wrap, (int)floor(u * W), (int)floor((1 - v) * H));
            nearest_bad += silk_texture_sample(&t, fu, fv, 0, 0) != ref;
        }
    CHECKF(worst <= 1, "bilinear is %.2f levels from the reference", worst);
    CHECKF(nearest_bad == 0, "%d nearest samples differ", nearest_bad);
}

TEST(formats_rgb565_and_paletted)
{
    /* one texel each: 565 widened by bit replication; a palette entry */
    uint8_t p565[2] = { 0x1f | 0x20, 0xf8 };     /* r = 31, g = 1, b = 31 */
    silk_texture t = { p565, NULL, 1, 1, SILK_TEX_RGB565, 1, SILK_TEX_NEAREST, SILK_TEX_REPEAT };
    CHECK(silk_texture_sample(&t, 0, 0, 0, 0) == 0xff04ff);
    uint32_t pal[256] = { 0 };
    pal[3] = 0x123456;
    uint8_t idx[1] = { 3 };
    silk_texture q = { idx, pal, 1, 1, SILK_TEX_PAL8, 1, SILK_TEX_BILINEAR, SILK_TEX_CLAMP };
    CHECK(silk_texture_sample(&q, SILK_FX_HALF, SILK_FX_HALF, 0, 0) == 0x123456);
    /* encoding: 565 rounds each channel (7/255 of green to 2/63), a palette
     * takes the nearest entry */
    const uint8_t rgb[6] = { 0xff, 0x07, 0xff, 0x10, 0x30, 0x50 };
    uint8_t two[4];
    silk_texture e = { two, NULL, 2, 1, SILK_TEX_RGB565, 1, SILK_TEX_NEAREST, SILK_TEX_CLAMP };
    silk_texture_encode(&e, two, rgb);
    CHECK(silk_texture_sample(&e, dfx(0.25), 0, 0, 0) == 0xff08ff);
    pal[9] = 0x103252;
    silk_texture_encode(&q, idx, rgb + 3);
    CHECK(idx[0] == 9);
}

TEST(mipmaps_average_and_levels_follow_the_footprint)
{
    /* 8 x 8 texels alternating black and white: every smaller level is grey */
    enum { N = 8 };
    uint8_t px[3 * (64 + 16 + 4 + 1)];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) memset(px + 3 * (y * N + x), ((x + y) & 1) ? 255 : 0, 3);
    silk_texture t = { px, NULL, N, N, SILK_TEX_RGB888, 0, SILK_TEX_BILINEAR, SILK_TEX_REPEAT };
    t.levels = (uint8_t)silk_texture_max_levels(N, N);
    CHECK(t.levels == 4);
    CHECK(silk_texture_bytes(SILK_TEX_RGB888, N, N, t.levels) == sizeof px);
    silk_texture_build_mipmaps(&t, px);
    int grey = 1;
    for (size_t i = 3 * 64; i < sizeof px; i++) grey &= px[i] == 128;
    CHECK(grey);
    /* at a texel centre: a footprint under one texel reads level 0, two
     * texels or more the grey levels, in between a blend */
    silk_fx u = dfx(0.5 / N), v = dfx(1 - 0.5 / N);   /* texel (0, 0): black */
    CHECK(silk_texture_sample(&t, u, v, 0, 0) == 0);
    CHECK(silk_texture_sample(&t, u, v, dfx(1.0 / N), 0) == 0);
    CHECK(silk_texture_sample(&t, u, v, dfx(2.0 / N), 0) == 0x808080);
    CHECK(silk_texture_sample(&t, u, v, 0, dfx(5.0 / N)) == 0x808080);
    uint32_t mid = silk_texture_sample(&t, u, v, dfx(1.42 / N), 0);   /* lambda = 1/2 */
    CHECKF(chan(mid, 0) >= 56 && chan(mid, 0) <= 72, "half-way between levels: %06x", (unsigned)mid);
}

/* ---- vertex colours ------------------------------------------------------------ */

static uint8_t arena_buf[1 << 20];

static silk_status load(const char *text, silk_mesh *m, silk_error *err, int ply)
{
    silk_arena a;
    silk_arena_init(&a, arena_buf, sizeof arena_buf);
    return ply ? silk_load_ply(text, strlen(text), "t.ply", NULL, &a, m, err)
               : silk_load_obj(text, strlen(text), "t.obj", NULL, &a, m, err);
}

TEST(vertex_colours_from_obj_and_ply)
{
    silk_mesh m;
    silk_error err;
    CHECK(load("v 0 0 0 1 0 0.5\nv 1 0 0 0 1 0\nv 0 1 0 0.2 0.4 0.6 1\nf 1 2 3\n", &m, &err, 0) == SILK_OK);
    CHECK(m.color && m.color[0] == 0xff0080 && m.color[1] == 0x00ff00 && m.color[2] == 0x336699);
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &m, &err, 0) == SILK_OK && m.color == NULL);
    CHECK(load("v 0 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &m, &err, 0) == SILK_OK && m.color == NULL);
    CHECK(load("v 0 0 0 2 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &m, &err, 0) == SILK_ERR_RANGE);
    CHECKF(strstr(err.msg, "t.obj:1: vertex colour 2") != NULL, "%s", err.msg);

    const char *ply_u8 = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                         "property uchar alpha\nelement face 1\nproperty list uchar int vertex_indices\n"
                         "end_header\n0 0 0 255 0 128 255\n1 0 0 0 255 0 9\n0 1 0 1 2 3 0\n3 0 1 2\n";
    CHECK(load(ply_u8, &m, &err, 1) == SILK_OK);
    CHECK(m.color && m.color[0] == 0xff0080 && m.color[1] == 0x00ff00 && m.color[2] == 0x010203);
    const char *ply_f = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nproperty float red\nproperty float green\nproperty float blue\n"
                        "element face 1\nproperty list uchar int vertex_indices\n"
                        "end_header\n0 0 0 1 0 0.5\n1 0 0 0 1 0\n0 1 0 0.2 0.4 1.5\n3 0 1 2\n";
    CHECK(load(ply_f, &m, &err, 1) == SILK_ERR_RANGE);
    CHECKF(strstr(err.msg, "vertex colour 1.5 is outside [0, 1]") != NULL, "%s", err.msg);
}

/* ---- no seam on the re-meshed surface ------------------------------------------- */

/* What the vertex stage saw: the clip position's bits and the uv. */
typedef struct seen { silk_fx key[4]; silk_fx u, v; uint32_t kind; } seen;

/* The vertex stage wrapped: the default one, then a note of what it saw. */
typedef struct seam_probe {
    void (*vertex)(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out);
    seen *s;
    size_t n, cap;
} seam_probe;

static seam_probe probe;

static void probe_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out)
{
    probe.vertex(h, g, r, out);
    silk_vertex_attr a;
    silk_vrec_eval(g, r, &a);
    if (probe.n == probe.cap) {
        probe.cap = probe.cap ? 2 * probe.cap : 4096;
        probe.s = realloc(probe.s, probe.cap * sizeof *probe.s);
    }
    seen *s = &probe.s[probe.n++];
    s->key[0] = a.pos.x, s->key[1] = a.pos.y, s->key[2] = a.pos.z, s->key[3] = 0;
    s->u = a.uv.x;
    s->v = a.uv.y;
    s->kind = r->kind;
}

static int cmp_seen(const void *a, const void *b)
{
    const seen *x = a, *y = b;
    for (int k = 0; k < 3; k++)
        if (x->key[k] != y->key[k]) return x->key[k] < y->key[k] ? -1 : 1;
    return 0;
}

static int globe(tm_fixture *f, int segments, int bands)
{
    gen_params p;
    gen_defaults(GEN_SPHERE, &p);
    p.segments = segments;
    p.bands = bands;
    p.uv = 1;
    size_t len;
    char *text = gen_obj_text(&p, &len);
    int ok = text && silk_load_obj(text, len, "globe", &f->opts, &f->a, &f->m, &f->err) == SILK_OK && f->m.uv;
    free(text);
    return ok;
}

TEST(no_uv_seam_where_remeshed_triangles_meet)
{
    tm_fixture f;
    tm_fixture_init(&f, 16u << 20);
    CHECK(globe(&f, 12, 9));
    static const double dirs[][3] = { { 0.47, 0.34, 0.81 }, { 0.9, 0.03, 0.43 }, { -0.3, -0.6, 0.7 } };
    static const silk_mode modes[] = { SILK_MODE_SMOOTH, SILK_MODE_PN, SILK_MODE_BLEND };
    for (size_t im = 0; im < 3; im++) {
        long shared = 0, curve_shared = 0, bad = 0;
        for (size_t iv = 0; iv < 3; iv++) {
            silk_view v;
            CHECK(tf_view_around_size(&f.m, dirs[iv], 2.2, 0, 160, 120, &v));
            silk_phong ph;
            silk_phong_default(&ph, &v);
            silk_hal h;
            silk_hal_phong(&h, &ph);
            probe.vertex = h.vertex;
            probe.n = 0;
            h.vertex = probe_vertex;
            silk_render_opts o;
            silk_render_opts_default(&o);
            o.mode = modes[im];
            o.vertex_cache_bytes = 0;   /* every share built, and through the probe, each time it is drawn */
            enum { PW = 160, PH = 120 };
            static uint8_t color[PW * PH * 3];
            static uint32_t depth[PW * PH];
            silk_target t;
            silk_target_init(&t, PW, PH, 0, PH, SILK_PIX_RGB888, color, depth);
            silk_target_clear(&t, 0);
            silk_error err;
            CHECK(silk_render(&f.a, &f.m, &v, &h, &o, &t, NULL, &err) == SILK_OK);
            qsort(probe.s, probe.n, sizeof *probe.s, cmp_seen);
            for (size_t i = 1; i < probe.n; i++) {
                const seen *a = &probe.s[i - 1], *b = &probe.s[i];
                if (cmp_seen(a, b) != 0) continue;
                /* the pole fans: gen gives the pole a u per triangle (the
                 * mean of its other two corners), so the sides from the pole
                 * carry different uvs in the mesh itself; not silk's seam */
                if (a->v <= dfx(1.0 / 9) || a->v >= dfx(1 - 1.0 / 9)) continue;
                shared++;
                if (a->kind != SILK_VREC_CORNER || b->kind != SILK_VREC_CORNER) curve_shared++;
                silk_fx du = a->u - b->u;
                if (a->v != b->v || (du != 0 && du != SILK_FX_ONE && du != -SILK_FX_ONE)) bad++;
            }
        }
        printf("mode %d: %ld points shared by two triangles (%ld of them new), %ld with different uvs\n",
               (int)modes[im], shared, curve_shared, bad);
        CHECKF(curve_shared > 100, "mode %d: only %ld shared new points", (int)modes[im], curve_shared);
        CHECKF(bad == 0, "mode %d: %ld of %ld shared points have different uvs", (int)modes[im], bad, shared);
    }
    free(probe.s);
    memset(&probe, 0, sizeof probe);
    tm_fixture_free(&f);
}

/* ---- no shimmer ----------------------------------------------------------------- */

/* A square of side 2 in the plane y = 0 with uvs 0..16 (a checker of 32 x
 * 32 one-texel squares repeated 16 x 16 times: detail far finer than the
 * pixels where the square recedes), 160 x 120 pixels, seen from 7 degrees
 * above its plane on a turntable that turns 0.25 degrees per frame, 12
 * frames.
 *
 * Differences are mean absolute differences per channel (0..255) over the
 * frame.  Flicker is how much more consecutive frames differ than the
 * supersampled reference frames do (4 x 4 samples a pixel, box-filtered:
 * the true change of the picture).  The threshold is half the difference
 * of the mipmapped frames from their references: the picture may not
 * flicker by more than half of what it is wrong by anyway.  Without mipmaps
 * the same frames must break it, or the test would prove nothing. */
enum { SW = 160, SH = 120, SS = 4, NFRAMES = 12 };
#define REPEAT 16

static void quad_mesh(tm_fixture *f)
{
    static const double pos[] = { -1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1 };
    static const uint32_t tri[] = { 0, 2, 1, 0, 3, 2 };
    CHECK(tm_fixture_input(f, pos, 4, tri, 2));
    f->in.uv = silk_arena_array(&f->a, 4, sizeof(silk_vec2), SILK_MEM_MESH);
    f->in.tri_uv = silk_arena_array(&f->a, 6, sizeof(silk_index), SILK_MEM_MESH);
    for (int k = 0; k < 4; k++) {
        f->in.uv[k].x = pos[3 * k] > 0 ? dfx(REPEAT) : 0;
        f->in.uv[k].y = pos[3 * k + 2] > 0 ? dfx(REPEAT) : 0;
    }
    memcpy(f->in.tri_uv, tri, sizeof tri);
    f->in.nuvs = 4;
    CHECK(tm_fixture_build(f) == SILK_OK);
}

/* Frame k at scale s (1, or SS for the reference, box-filtered down) as RGB888 SW x SH. */
static void shimmer_frame(tm_fixture *f, const silk_texture *tex, int k, int s, uint8_t *out)
{
    double a = (30 + 0.25 * k) * 3.14159265358979 / 180, e = 7 * 3.14159265358979 / 180;
    double dir[3] = { cos(a) * cos(e), sin(e), sin(a) * cos(e) };
    silk_view v;
    CHECK(tf_view_around_size(&f->m, dir, 1.6, 0, SW * s, SH * s, &v));
    silk_phong ph;
    silk_phong_default(&ph, &v);
    ph.mat.color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
    ph.texture = tex;
    silk_hal h;
    silk_hal_phong(&h, &ph);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = SILK_MODE_FLAT;
    size_t n = (size_t)SW * SH * s * s;
    uint8_t *color = malloc(n * 3);
    uint32_t *depth = malloc(n * sizeof *depth);
    silk_target t;
    silk_target_init(&t, SW * s, SH * s, 0, SH * s, SILK_PIX_RGB888, color, depth);
    silk_target_clear(&t, 0x808080);
    silk_error err;
    CHECK(silk_render(&f->a, &f->m, &v, &h, &o, &t, NULL, &err) == SILK_OK);
    for (int y = 0; y < SH; y++)
        for (int x = 0; x < SW; x++)
            for (int c = 0; c < 3; c++) {
                int sum = 0;
                for (int j = 0; j < s; j++)
                    for (int i = 0; i < s; i++) sum += color[3 * ((size_t)(y * s + j) * SW * s + x * s + i) + c];
                out[3 * ((size_t)y * SW + x) + c] = (uint8_t)((sum + s * s / 2) / (s * s));
            }
    free(color);
    free(depth);
}

static double mad(const uint8_t *a, const uint8_t *b)
{
    double s = 0;
    for (size_t i = 0; i < (size_t)SW * SH * 3; i++) s += abs((int)a[i] - (int)b[i]);
    return s / ((double)SW * SH * 3);
}

/* Mean frame-to-frame difference minus the reference's, and the mean
 * difference from the reference. */
static void shimmer_measure(tm_fixture *f, const silk_texture *tex, double *flicker, double *error)
{
    size_t fb = (size_t)SW * SH * 3;
    uint8_t *fr = malloc(fb * NFRAMES), *ref = malloc(fb * NFRAMES);
    for (int k = 0; k < NFRAMES; k++) {
        shimmer_frame(f, tex, k, 1, fr + k * fb);
        shimmer_frame(f, tex, k, SS, ref + k * fb);
    }
    double d = 0, dr = 0, e = 0;
    for (int k = 0; k < NFRAMES; k++) {
        e += mad(fr + k * fb, ref + k * fb) / NFRAMES;
        if (k) {
            d += mad(fr + k * fb, fr + (k - 1) * fb) / (NFRAMES - 1);
            dr += mad(ref + k * fb, ref + (k - 1) * fb) / (NFRAMES - 1);
        }
    }
    *flicker = d - dr;
    *error = e;
    free(fr);
    free(ref);
}

TEST(grazing_quad_does_not_shimmer)
{
    tm_fixture f;
    tm_fixture_init(&f, 64u << 20);
    quad_mesh(&f);
    enum { N = 32 };
    static uint8_t px[N * N * 3 * 2];
    gen_checker(px, N, N);
    silk_texture t = { px, NULL, N, N, SILK_TEX_RGB888, 0, SILK_TEX_BILINEAR, SILK_TEX_REPEAT };
    t.levels = (uint8_t)silk_texture_max_levels(N, N);
    silk_texture_build_mipmaps(&t, px);
    double flicker, error;
    shimmer_measure(&f, &t, &flicker, &error);
    double threshold = error / 2;
    printf("mipmapped: flicker %.3f, threshold %.3f (difference from the 4x4 supersampled frames %.3f)\n",
           flicker, threshold, error);
    CHECKF(flicker < threshold, "the quad flickers by %.3f, threshold %.3f", flicker, threshold);
    t.levels = 1;
    double flicker1, error1;
    shimmer_measure(&f, &t, &flicker1, &error1);
    printf("without mipmaps: flicker %.3f (difference from the supersampled frames %.3f)\n", flicker1, error1);
    CHECKF(flicker1 > threshold, "without mipmaps the quad should flicker (%.3f)", flicker1);
    tm_fixture_free(&f);
}

int main(void)
{
    RUN(bilinear_and_nearest_match_reference);
    RUN(formats_rgb565_and_paletted);
    RUN(mipmaps_average_and_levels_follow_the_footprint);
    RUN(vertex_colours_from_obj_and_ply);
    RUN(no_uv_seam_where_remeshed_triangles_meet);
    RUN(grazing_quad_does_not_shimmer);
    return check_done();
}
