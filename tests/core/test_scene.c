/*
 * test_scene.c - several objects in one frame (silk/scene.h, src/scene.c).
 *
 * A torus tilted towards the camera and a sphere a little over half its
 * size pushed through its tube, so that each hides the other somewhere
 * (their depths interleave), shaded in two materials: smooth and smooth,
 * flat and smooth, and over a background painted by the under callback.
 * Each frame is drawn whole and in bands of 1, 7 and 16 rows (the bands
 * must give the whole frame's bytes, every outline pixel anti-aliased) and
 * compared with its reference image, tests/golden/scene-*.png
 * (tests/support/golden.h; `make golden` rewrites them).
 *
 * Also: the placement against a floating-point reference (a vertex of the
 * placed mesh projected through silk_place_view lands where the world
 * point projects, within 1/16 pixel); a scene of one object where it is
 * is silk_render's frame byte for byte, whole and in bands; each object
 * hides the other somewhere; the frame drawn in exactly its
 * silk_frame_stats.frame_bytes gives the same bytes; double-buffered
 * bands; and the refusals (no objects, a mirror, a zero scale, stages of
 * the caller's own moved, an under callback that stops the frame).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "tools/prep/gen.h"
#include "support/golden.h"
#include "support/testmesh.h"
#include "support/testframe.h"

#define W 160
#define H 120
#define BG 0xF4F1EAu
#define ARENA_BYTES (8u << 20)

static silk_fx d2fx(double v) { return (silk_fx)llround(v * 65536.0); }

static int gen_fixture(tm_fixture *f, gen_shape shape)
{
    gen_params p;
    gen_mesh gm;
    gen_defaults(shape, &p);
    if (shape == GEN_TORUS) {
        p.R = 1; p.r = 0.35; p.segments = 24; p.bands = 12;
    } else {
        p.radius = 1; p.segments = 10; p.bands = 11;
    }
    if (gen_build(&p, &gm) != 0) return 0;
    int ok = tm_fixture_input(f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(f) == SILK_OK;
    gen_free(&gm);
    return ok;
}

static tm_fixture torus, sphere;
static uint8_t *arena_buf;

static const double EYE[3] = { 0.9, 1.7, 4.3 }, TARGET[3] = { 0.25, 0, 0 };

static silk_camera camera(void)
{
    silk_camera c;
    memset(&c, 0, sizeof c);
    c.eye = silk_v3(d2fx(EYE[0]), d2fx(EYE[1]), d2fx(EYE[2]));
    c.target = silk_v3(d2fx(TARGET[0]), d2fx(TARGET[1]), d2fx(TARGET[2]));
    c.up = silk_v3(0, SILK_FX_ONE, 0);
    c.fov_deg = SILK_FX_C(40, 1);
    c.znear = SILK_FX_C(1, 2);
    c.zfar = SILK_FX_C(20, 1);
    c.width = W;
    c.height = H;
    return c;
}

/* The torus (pitch 62, yaw -20 degrees) and the sphere (scale 0.55) through its tube. */
static void place_torus(silk_place *p)
{
    silk_place_identity(p);
    silk_place_euler(p, SILK_FX_C(-20, 1), SILK_FX_C(62, 1), 0);
    p->pos = silk_v3(SILK_FX_C(-1, 5), 0, 0);
}

static void place_sphere(silk_place *p)
{
    silk_place_identity(p);
    silk_place_euler(p, SILK_FX_C(30, 1), 0, SILK_FX_C(10, 1));
    p->pos = silk_v3(SILK_FX_C(8, 10), SILK_FX_C(1, 10), SILK_FX_C(1, 10));
    p->scale = SILK_FX_C(55, 100);
}

typedef struct two {
    silk_view view;
    silk_phong warm, cool;
    silk_object obj[2];
    silk_scene scene;
} two;

static void two_init(two *s, silk_mode torus_mode, silk_mode sphere_mode)
{
    silk_camera c = camera();
    silk_error err;
    CHECK(silk_view_init(&s->view, &c, &err) == SILK_OK);
    silk_phong_default(&s->warm, &s->view);
    s->warm.mat.color = silk_v3(SILK_FX_C(88, 100), SILK_FX_C(60, 100), SILK_FX_C(36, 100));
    silk_phong_default(&s->cool, &s->view);
    silk_object_init(&s->obj[0], &torus.m, &s->warm);
    place_torus(&s->obj[0].place);
    s->obj[0].opts.mode = torus_mode;
    silk_object_init(&s->obj[1], &sphere.m, &s->cool);
    place_sphere(&s->obj[1].place);
    s->obj[1].opts.mode = sphere_mode;
    silk_scene_init(&s->scene, s->obj, 2);
    s->scene.bg_rgb = BG;
}

/* The under callback: a vertical gradient with a darker 8-pixel grid, a
 * function of the frame's position alone. */
static int paint_under(void *user, silk_target *t)
{
    (void)user;
    for (int y = t->y0; y < t->y0 + t->rows; y++)
        for (int x = 0; x < t->width; x++) {
            uint32_t g = (uint32_t)(200 - y * 80 / t->height);
            if (x % 8 == 0 || y % 8 == 0) g -= 40;
            silk_target_put(t, x, y, g << 16 | g << 8 | 0xE0);
        }
    return 0;
}

static int stop_under(void *user, silk_target *t)
{
    int *calls = user;
    (void)t;
    return ++*calls > 0;   /* the first band */
}

/* The frame whole into a fresh RGB888 target (buffers on the heap). */
static silk_status draw_whole(silk_arena *a, const silk_scene *s, const silk_view *v, uint8_t *color,
                              silk_frame_stats *st, silk_error *err)
{
    uint32_t *depth = malloc((size_t)W * H * sizeof *depth);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
    silk_status r = silk_render_scene(a, s, v, &t, st, err);
    free(depth);
    return r;
}

static silk_status draw_bands(silk_arena *a, const silk_scene *s, const silk_view *v, int rows, uint8_t *frame,
                              silk_frame_stats *st, silk_error *err)
{
    uint8_t *color = malloc((size_t)W * rows * 3);
    uint32_t *depth = malloc((size_t)W * rows * sizeof *depth);
    silk_target band;
    silk_target_init(&band, W, H, 0, rows, SILK_PIX_RGB888, color, depth);
    tf_collect c = { .frame = frame, .max_rows = rows };
    silk_sink sink = { .band = tf_collect_band, .user = &c };
    silk_status r = silk_render_scene_bands(a, s, v, &band, &sink, st, err);
    CHECKF(r != SILK_OK || (c.next_row == H && !c.bad), "bands: next row %d, bad %d", c.next_row, c.bad);
    CHECK(band.rows == rows && band.y0 == 0 && band.color == color);
    free(color);
    free(depth);
    return r;
}

/* The scene whole, against its reference, and in bands of 1, 7 and 16 rows. */
static void check_scene(const silk_scene *s, const silk_view *v, const char *name)
{
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    silk_frame_stats st;
    size_t bytes = (size_t)W * H * 3;
    uint8_t *whole = malloc(bytes), *banded = malloc(bytes);
    CHECKF(draw_whole(&a, s, v, whole, &st, &err) == SILK_OK, "%s: %s", name, err.msg);
    CHECKF(st.aa_aliased == 0 && !st.fell_back, "%s: %u aliased, fell back %d", name, st.aa_aliased, st.fell_back);
    CHECK(a.top == 0);
    silk_target t;
    silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, whole, NULL);
    char msg[256];
    /* the references are the host's anti-aliasing (a board's configuration
     * without it, or without creases, draws other outline pixels: its bands
     * must still give its whole frame) */
    if (SILK_AA && SILK_AA_CREASES) CHECKF(golden_compare(&t, name, msg, sizeof msg), "%s", msg);
    static const int heights[] = { 1, 7, 16 };
    for (int k = 0; k < 3; k++) {
        memset(banded, 0, bytes);
        silk_frame_stats bs;
        CHECKF(draw_bands(&a, s, v, heights[k], banded, &bs, &err) == SILK_OK, "%s: %s", name, err.msg);
        size_t diff = 0;
        for (size_t i = 0; i < bytes; i++) diff += banded[i] != whole[i];
        CHECKF(diff == 0, "%s: bands of %d rows: %zu bytes differ from the whole frame", name, heights[k], diff);
        CHECKF(bs.aa_aliased == 0, "%s: bands of %d: %u aliased", name, heights[k], bs.aa_aliased);
        CHECK(bs.tris_drawn == st.tris_drawn && bs.silhouette_tris == st.silhouette_tris);
    }
    free(whole);
    free(banded);
}

TEST(scene_two_smooth)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    check_scene(&s.scene, &s.view, "scene-two-smooth");
}

TEST(scene_two_flat_smooth)
{
    two s;
    two_init(&s, SILK_MODE_FLAT, SILK_MODE_SMOOTH);
    check_scene(&s.scene, &s.view, "scene-two-flat-smooth");
}

TEST(scene_under_callback)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    s.scene.under = paint_under;
    check_scene(&s.scene, &s.view, "scene-under");
}

/* Each object alone, then both: where both cover a pixel, the scene shows
 * the torus at some and the sphere at others (the depth is shared), and
 * everywhere else the one that covers it. */
TEST(scene_depth_interleaves)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    for (int i = 0; i < 2; i++) s.obj[i].opts.aa = 0;   /* whole pixels: each is one object's or the background's */
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    size_t bytes = (size_t)W * H * 3;
    uint8_t *img[3];
    for (int k = 0; k < 3; k++) {
        img[k] = malloc(bytes);
        silk_scene one = s.scene;
        if (k < 2) {
            one.objects = &s.obj[k];
            one.nobjects = 1;
        }
        CHECKF(draw_whole(&a, &one, &s.view, img[k], NULL, &err) == SILK_OK, "%s", err.msg);
    }
    long both = 0, torus_wins = 0, sphere_wins = 0, wrong = 0;
    for (size_t p = 0; p < bytes; p += 3) {
        int in[2];
        for (int k = 0; k < 2; k++)
            in[k] = img[k][p] != (BG >> 16) || img[k][p + 1] != ((BG >> 8) & 255) || img[k][p + 2] != (BG & 255);
        int is_t = !memcmp(img[2] + p, img[0] + p, 3), is_s = !memcmp(img[2] + p, img[1] + p, 3);
        if (in[0] && in[1]) {
            both++;
            torus_wins += is_t && !is_s;
            sphere_wins += is_s && !is_t;
            wrong += !is_t && !is_s;
        } else if (in[0] || in[1]) {
            wrong += !(in[0] ? is_t : is_s);
        }
    }
    CHECKF(both > 200 && torus_wins > 50 && sphere_wins > 50, "overlap %ld: torus in front at %ld, sphere at %ld",
           both, torus_wins, sphere_wins);
    CHECKF(wrong == 0, "%ld pixels are neither object's as drawn alone", wrong);
    for (int k = 0; k < 3; k++) free(img[k]);
}

/* The world point pos + s R p of a placed vertex p, projected in doubles
 * through the camera, and the vertex through silk_place_view. */
static void project_double(const silk_camera *c, const double q[3], double px[2])
{
    double f[3], r[3], u[3], up[3] = { 0, 1, 0 }, n;
    for (int i = 0; i < 3; i++) f[i] = TARGET[i] - EYE[i];
    n = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++) f[i] /= n;
    r[0] = f[1] * up[2] - f[2] * up[1]; r[1] = f[2] * up[0] - f[0] * up[2]; r[2] = f[0] * up[1] - f[1] * up[0];
    n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int i = 0; i < 3; i++) r[i] /= n;
    u[0] = r[1] * f[2] - r[2] * f[1]; u[1] = r[2] * f[0] - r[0] * f[2]; u[2] = r[0] * f[1] - r[1] * f[0];
    double d[3] = { q[0] - EYE[0], q[1] - EYE[1], q[2] - EYE[2] };
    double x = d[0] * r[0] + d[1] * r[1] + d[2] * r[2], y = d[0] * u[0] + d[1] * u[1] + d[2] * u[2],
           z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    double t = tan(40.0 / 2 * 3.14159265358979323846 / 180);
    px[0] = (x / (z * t * c->width / c->height) + 1) * c->width / 2;
    px[1] = (1 - y / (z * t)) * c->height / 2;
}

TEST(scene_place_against_doubles)
{
    silk_camera c = camera();
    silk_view v, ov;
    silk_error err;
    CHECK(silk_view_init(&v, &c, &err) == SILK_OK);
    silk_place pl[2];
    place_torus(&pl[0]);
    place_sphere(&pl[1]);
    const tm_fixture *fx[2] = { &torus, &sphere };
    double worst = 0;
    for (int k = 0; k < 2; k++) {
        CHECKF(silk_place_view(&v, &pl[k], &ov, &err) == SILK_OK, "%s", err.msg);
        const silk_mesh *m = &fx[k]->m;
        for (uint32_t i = 0; i < m->nverts; i++) {
            double p[3] = { m->pos[i].x / 65536.0, m->pos[i].y / 65536.0, m->pos[i].z / 65536.0 }, q[3], ref[2];
            double s = pl[k].scale / 65536.0;
            for (int r = 0; r < 3; r++)
                q[r] = (&pl[k].pos.x)[r] / 65536.0 +
                       s * (pl[k].rot[r][0] / 65536.0 * p[0] + pl[k].rot[r][1] / 65536.0 * p[1] +
                            pl[k].rot[r][2] / 65536.0 * p[2]);
            project_double(&c, q, ref);
            silk_vec2 px;
            CHECK(silk_view_project(&ov, m->pos[i], &px));
            double e = hypot(px.x / 65536.0 - ref[0], px.y / 65536.0 - ref[1]);
            if (e > worst) worst = e;
        }
    }
    CHECKF(worst < 1.0 / 16, "worst %.4f px from the double reference", worst);
    /* the rotation made by silk_place_euler is orthonormal to 1/4096 */
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double d = 0;
                for (int l = 0; l < 3; l++) d += pl[k].rot[i][l] / 65536.0 * (pl[k].rot[j][l] / 65536.0);
                CHECKF(fabs(d - (i == j)) < 1.0 / 4096, "rows %d %d: %.6f", i, j, d);
            }
}

/* One object where it is: silk_render's bytes, whole and in bands. */
TEST(scene_one_is_render)
{
    static const silk_mode modes[] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH };
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    silk_view v;
    double dir[3] = { 0.4, 0.5, 1 };
    CHECK(tf_view_around_size(&torus.m, dir, 3, 0, W, H, &v));
    silk_phong ph;
    silk_phong_default(&ph, &v);
    silk_hal h;
    silk_hal_phong(&h, &ph);
    size_t bytes = (size_t)W * H * 3;
    uint8_t *ref = malloc(bytes), *got = malloc(bytes);
    uint32_t *depth = malloc((size_t)W * H * sizeof *depth);
    for (int k = 0; k < 2; k++) {
        silk_object ob;
        silk_object_init(&ob, &torus.m, &ph);
        ob.opts.mode = modes[k];
        silk_scene s;
        silk_scene_init(&s, &ob, 1);
        silk_render_opts o = ob.opts;
        silk_target t;
        silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, ref, depth);
        silk_frame_stats rs, ss;
        CHECK(silk_render(&a, &torus.m, &v, &h, &o, &t, &rs, &err) == SILK_OK);
        CHECKF(draw_whole(&a, &s, &v, got, &ss, &err) == SILK_OK, "%s", err.msg);
        CHECKF(!memcmp(ref, got, bytes), "%s: the scene of one object differs from silk_render", silk_mode_name(modes[k]));
        CHECK(rs.tris_drawn == ss.tris_drawn && rs.samples == ss.samples);
        memset(got, 0, bytes);
        CHECKF(draw_bands(&a, &s, &v, 7, got, &ss, &err) == SILK_OK, "%s", err.msg);
        CHECKF(!memcmp(ref, got, bytes), "%s: the scene of one object in bands differs", silk_mode_name(modes[k]));
        /* also with the caller's own stages (the default ones, given as a HAL) */
        ob.phong = NULL;
        ob.hal = &h;
        CHECKF(draw_whole(&a, &s, &v, got, &ss, &err) == SILK_OK, "%s", err.msg);
        CHECK(!memcmp(ref, got, bytes));
    }
    free(ref);
    free(got);
    free(depth);
}

/* Drawn in an arena of the frame's need exactly: the same bytes. */
TEST(scene_frame_bytes)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    silk_frame_stats st, st2;
    size_t bytes = (size_t)W * H * 3;
    uint8_t *ref = malloc(bytes), *got = malloc(bytes);
    CHECK(draw_whole(&a, &s.scene, &s.view, ref, &st, &err) == SILK_OK);
    CHECK(st.frame_bytes > 0);
    /* the meshes live in their fixtures: the arena holds the frame alone */
    silk_arena small;
    silk_arena_init(&small, arena_buf, st.frame_bytes);
    CHECKF(draw_whole(&small, &s.scene, &s.view, got, &st2, &err) == SILK_OK, "%s", err.msg);
    CHECKF(!memcmp(ref, got, bytes) && st2.aa_aliased == 0 && !st2.fell_back,
           "in %zu bytes: %s, %u aliased, fell back %d", st.frame_bytes, memcmp(ref, got, bytes) ? "differs" : "same",
           st2.aa_aliased, st2.fell_back);
    printf("scene frame: %zu bytes of arena (two objects, %dx%d)\n", st.frame_bytes, W, H);
    free(ref);
    free(got);
}

typedef struct late_sink {
    tf_collect c;
    const uint8_t *busy;   /* the buffer being sent, one band late */
    int waits;
} late_sink;

static int late_band(void *user, const silk_target *t)
{
    late_sink *s = user;
    s->busy = t->color;
    return tf_collect_band(&s->c, t);
}

static int late_wait(void *user, const uint8_t *color)
{
    late_sink *s = user;
    if (color == s->busy) s->waits++;
    s->busy = NULL;
    return 0;
}

TEST(scene_double_buffered)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    size_t bytes = (size_t)W * H * 3;
    uint8_t *ref = malloc(bytes), *got = calloc(1, bytes), *c0 = malloc(W * 16 * 3), *c1 = malloc(W * 16 * 3);
    uint32_t *depth = malloc(W * 16 * sizeof *depth);
    CHECK(draw_whole(&a, &s.scene, &s.view, ref, NULL, &err) == SILK_OK);
    silk_target band;
    silk_target_init(&band, W, H, 0, 16, SILK_PIX_RGB888, c0, depth);
    late_sink ls = { .c = { .frame = got, .max_rows = 16 } };
    silk_sink sink = { .band = late_band, .user = &ls, .color2 = c1, .wait = late_wait };
    CHECKF(silk_render_scene_bands(&a, &s.scene, &s.view, &band, &sink, NULL, &err) == SILK_OK, "%s", err.msg);
    CHECK(!memcmp(ref, got, bytes));
    CHECKF(ls.waits == 0, "%d bands drawn into the buffer being sent", ls.waits);
    free(ref); free(got); free(c0); free(c1); free(depth);
}

TEST(scene_refusals)
{
    two s;
    two_init(&s, SILK_MODE_SMOOTH, SILK_MODE_SMOOTH);
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_error err;
    uint8_t *img = malloc((size_t)W * H * 3);
    silk_scene none = s.scene;
    none.nobjects = 0;
    CHECK(draw_whole(&a, &none, &s.view, img, NULL, &err) == SILK_ERR_ARG);
    silk_place keep = s.obj[1].place;
    s.obj[1].place.rot[2][2] = -s.obj[1].place.rot[2][2];   /* a mirror */
    s.obj[1].place.rot[2][0] = -s.obj[1].place.rot[2][0];
    s.obj[1].place.rot[2][1] = -s.obj[1].place.rot[2][1];
    CHECK(draw_whole(&a, &s.scene, &s.view, img, NULL, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "rotation") != NULL, "%s", err.msg);
    s.obj[1].place = keep;
    s.obj[1].place.scale = 0;
    CHECK(draw_whole(&a, &s.scene, &s.view, img, NULL, &err) == SILK_ERR_ARG);
    s.obj[1].place = keep;
    silk_hal h;
    silk_hal_phong(&h, &s.cool);
    s.obj[1].phong = NULL;
    s.obj[1].hal = &h;
    CHECK(draw_whole(&a, &s.scene, &s.view, img, NULL, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "identity") != NULL, "%s", err.msg);
    s.obj[1].phong = &s.cool;
    int calls = 0;
    s.scene.under = stop_under;
    s.scene.under_user = &calls;
    CHECK(draw_whole(&a, &s.scene, &s.view, img, NULL, &err) == SILK_ERR_IO);
    CHECK(a.top == 0);
    free(img);
}

/* Without SILK_SCENES the entry points refuse, in one line. */
TEST(scene_unbuilt)
{
    if (check_built(SILK_SCENES, "SILK_SCENES")) return;
}

int main(void)
{
    if (!SILK_SCENES) {   /* a board's configuration without them: every test says it is skipped */
        RUN(scene_unbuilt);
        return check_done();
    }
    arena_buf = malloc(ARENA_BYTES);
    tm_fixture_init(&torus, 4u << 20);
    tm_fixture_init(&sphere, 4u << 20);
    if (!gen_fixture(&torus, GEN_TORUS) || !gen_fixture(&sphere, GEN_SPHERE)) {
        fprintf(stderr, "test_scene: the meshes could not be built\n");
        return 1;
    }
    RUN(scene_place_against_doubles);
    RUN(scene_one_is_render);
    RUN(scene_two_smooth);
    RUN(scene_two_flat_smooth);
    RUN(scene_under_callback);
    RUN(scene_depth_interleaves);
    RUN(scene_frame_bytes);
    RUN(scene_double_buffered);
    RUN(scene_refusals);
    golden_summary();
    tm_fixture_free(&torus);
    tm_fixture_free(&sphere);
    free(arena_buf);
    return check_done();
}
