/*
 * test_overflow.c - the overflow policy of docs/overflow.md, case by case:
 * every place where a fixed-point value could leave Q16.16 or an int64
 * intermediate could wrap is driven to its limit here, and the result must
 * be the documented one (saturated, rescaled, clamped, skipped or a clear
 * error), never a wrapped value, a crash or undefined behaviour (the
 * sanitizer run of `make test` builds this with UBSan, which stops at any
 * signed overflow).
 *
 * Where a scene can be scaled, the test renders it at the limit and again
 * at an ordinary scale and compares the coverage: perspective projection
 * does not change when the model, the eye and the near plane scale
 * together, so any difference beyond rounding is an overflow.
 */
#include <math.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "support/scene.h"
#include "src/curve.h"

#define ARENA_BYTES ((size_t)32 << 20)
static unsigned char arena_mem[ARENA_BYTES];

static silk_arena fresh_arena(void)
{
    silk_arena a;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    return a;
}

/* Renders a sphere of radius r at centre c seen from c + (0, 0, 4r) with
 * znear r/2, in the given mode; returns the status. */
static silk_status sphere_view(double r, const double c[3], silk_mode mode, int size, ts_image *img,
                               silk_frame_stats *stats)
{
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 16, 12, r, c[0], c[1], c[2]);
    silk_mesh m;
    silk_error err;
    silk_status st = ts_build(&tm, &a, &m, &err);
    ts_mesh_free(&tm);
    if (st != SILK_OK) {
        fprintf(stderr, "build: %s\n", err.msg);
        return st;
    }
    if (silk_vis_build(&m, NULL, &a, &err) != SILK_OK) return SILK_ERR_NOMEM;
    double eye[3] = { c[0] + 0.3 * r, c[1] + 0.5 * r, c[2] + 4 * r };
    silk_camera cam = ts_camera(eye, c, 40, r / 2, 8 * r, size, size);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = mode;
    st = ts_render(&a, &m, &cam, &o, img, stats, &err);
    if (st != SILK_OK) fprintf(stderr, "render: %s\n", err.msg);
    return st;
}

/* A model at the coordinate limit (radius 1000, SILK_COORD_MAX 1024), one
 * at the size limit (1/32: its box diagonal is just above SILK_SIZE_MIN)
 * and one far from the origin, against the unit sphere at the origin. */
TEST(scale_limits)
{
    static const struct { double r, c[3]; long max_differ; } cases[] = {
        { 1000, { 0, 0, 0 }, 2 },                 /* coordinates up to 1000 */
        { 0.03125, { 0, 0, 0 }, 4 },             /* 2048 ulps of radius */
        { 1, { 1000, -1000, 1000 }, 2 },          /* far from the origin */
        { 0.25, { -1023, 1023, -1023 }, 2 },      /* far, and small */
    };
    const double origin[3] = { 0, 0, 0 };
    for (int mode = 0; mode < 4; mode++) {
        if (!ts_mode_built(mode)) continue;
        ts_image ref = { 0 };
        silk_frame_stats rs;
        CHECK(sphere_view(1, origin, (silk_mode)mode, 96, &ref, &rs) == SILK_OK);
        long cov = ts_count_covered(&ref);
        CHECKF(cov > 1000, "reference covers only %ld pixels", cov);
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            ts_image img = { 0 };
            silk_frame_stats st;
            CHECK(sphere_view(cases[i].r, cases[i].c, (silk_mode)mode, 96, &img, &st) == SILK_OK);
            long d = ts_count_differ(&ref, &img);
            CHECKF(d <= cases[i].max_differ, "mode %d, radius %g at (%g,%g,%g): %ld of %ld pixels differ", mode,
                   cases[i].r, cases[i].c[0], cases[i].c[1], cases[i].c[2], d, cov);
            CHECKF(!st.fell_back, "mode %d case %zu fell back", mode, i);
            ts_image_free(&img);
        }
        ts_image_free(&ref);
    }
}

/* The eye as far as the CLI lets it go (16384) from a model at the
 * coordinate limit, against the same view at 1/1000 of the size; and
 * beyond the working range (points more than 32767 units from the eye),
 * where eye space saturates: the frame is still drawn, without undefined
 * behaviour, but not promised right. */
TEST(far_eye)
{
    ts_image ref = { 0 }, img = { 0 };
    silk_error err;
    for (int big = 0; big < 2; big++) {
        double s = big ? 1000 : 1;
        silk_arena a = fresh_arena();
        ts_mesh tm = { 0 };
        ts_sphere(&tm, 16, 12, s, 0, 0, 0);
        silk_mesh m;
        CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
        ts_mesh_free(&tm);
        const double eye[3] = { 0, 0.4 * s, 16.384 * s }, target[3] = { 0, 0, 0 };
        silk_camera cam = ts_camera(eye, target, 8, 15 * s, 18 * s, 96, 96);
        CHECK(ts_render(&a, &m, &cam, NULL, big ? &img : &ref, NULL, &err) == SILK_OK);
        if (big) {
            long d = ts_count_differ(&ref, &img), cov = ts_count_covered(&ref);
            CHECKF(cov > 1000 && d <= 2, "%ld of %ld pixels differ", d, cov);
            const double beyond[3] = { 0, 0, 32000 };
            cam = ts_camera(beyond, target, 8, 16000, 32767, 96, 96);
            for (int mode = 0; mode < 4; mode++) {
                if (!ts_mode_built(mode)) continue;
                silk_render_opts o;
                silk_render_opts_default(&o);
                o.mode = (silk_mode)mode;
                CHECK(ts_render(&a, &m, &cam, &o, &img, NULL, &err) == SILK_OK);
            }
        }
    }
    ts_image_free(&ref);
    ts_image_free(&img);
}

/* Coordinates: exactly +-1024 loads, one ulp-sized step beyond does not,
 * with the error the CLI shows; a model too small is refused likewise. */
TEST(coordinate_limits)
{
    silk_arena a = fresh_arena();
    silk_mesh m;
    silk_error err;
    const char *at = "v -1024 -1024 -1024\nv 1024 -1024 -1024\nv -1024 1024 1024\nf 1 2 3\n";
    CHECK(silk_load_obj(at, strlen(at), "at.obj", NULL, &a, &m, &err) == SILK_OK);
    CHECK(m.bbox_max.x == SILK_COORD_MAX && m.bbox_min.x == -SILK_COORD_MAX);

    a = fresh_arena();
    const char *beyond = "v -1024 -1024 -1024\nv 1024.00002 -1024 -1024\nv -1024 1024 1024\nf 1 2 3\n";
    CHECK(silk_load_obj(beyond, strlen(beyond), "beyond.obj", NULL, &a, &m, &err) == SILK_ERR_RANGE);
    CHECKF(strcmp(err.msg, "beyond.obj:2: coordinate 1024.00002 is outside the fixed-point range (+-1024); "
                           "scale the model with --scale 0.1") == 0, "got \"%s\"", err.msg);

    /* Through --scale: 1 km in millimetres is fine once scaled by 0.001. */
    a = fresh_arena();
    const char *mm = "v 0 0 0\nv 1000000 0 0\nv 0 1000000 0\nf 1 2 3\n";
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 1;
    o.scale.exp10 = -3;
    CHECK(silk_load_obj(mm, strlen(mm), "mm.obj", &o, &a, &m, &err) == SILK_OK);
    CHECK(m.bbox_max.x == SILK_FX_C(1000, 1));

    a = fresh_arena();
    const char *tiny = "v 0 0 0\nv 0.03 0 0\nv 0 0.03 0\nf 1 2 3\n";
    CHECK(silk_load_obj(tiny, strlen(tiny), "tiny.obj", NULL, &a, &m, &err) == SILK_ERR_RANGE);
    CHECKF(strstr(err.msg, "too small for fixed-point precision") != NULL, "got \"%s\"", err.msg);

    /* silk_mesh_build checks the range itself for meshes not read from text. */
    a = fresh_arena();
    ts_mesh tm = { 0 };
    ts_tri(&tm, ts_vertex(&tm, 0, 0, 0), ts_vertex(&tm, 1025, 0, 0), ts_vertex(&tm, 0, 1, 0));
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_ERR_RANGE);
    CHECKF(strstr(err.msg, "outside the fixed-point range") != NULL, "got \"%s\"", err.msg);
    ts_mesh_free(&tm);
}

/* The eye exactly on a vertex, on an edge, in a face's plane: every mode
 * draws (the vertex itself is behind the near plane and clipped). */
TEST(eye_on_geometry)
{
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 12, 8, 1, 0, 0, 0);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_OK);
    size_t bottom = a.bottom;
    silk_vec3 v = m.pos[5], e0 = m.pos[m.edge[7].v[0]], e1 = m.pos[m.edge[7].v[1]], pole = m.pos[0];
    double eyes[4][3] = {
        { ts_fx2d(v.x), ts_fx2d(v.y), ts_fx2d(v.z) },                              /* a vertex */
        { ts_fx2d(e0.x / 2 + e1.x / 2), ts_fx2d(e0.y / 2 + e1.y / 2),
          ts_fx2d(e0.z / 2 + e1.z / 2) },                                          /* near an edge's middle */
        { 3 * ts_fx2d(pole.x), 3 * ts_fx2d(pole.y), 3 * ts_fx2d(pole.z) },         /* outside, over the pole */
        { 0, 0, 0 },                                                               /* the centre */
    };
    const double targets[2][3] = { { 0, 0, 0 }, { 3, 0.5, -2 } };
    ts_image img = { 0 };
    for (int e = 0; e < 4; e++)
        for (int t = 0; t < 2; t++) {
            if (e == 3 && t == 0) continue;
            for (int mode = 0; mode < 4; mode++) {
                if (!ts_mode_built(mode)) continue;
                silk_camera cam = ts_camera(eyes[e], targets[t], 60, 1.0 / 1024, 20, 48, 40);
                silk_render_opts o;
                silk_render_opts_default(&o);
                o.mode = (silk_mode)mode;
                o.wire = TS_WIRE_BUILT;
                silk_frame_stats st;
                silk_status s = ts_render(&a, &m, &cam, &o, &img, &st, &err);
                CHECKF(s == SILK_OK, "eye %d target %d mode %d: %s", e, t, mode, err.msg);
                CHECK(a.top == 0 && a.bottom == bottom);
                if (e == 3) CHECKF(ts_count_covered(&img) == 48 * 40, "inside the sphere every pixel is surface");
            }
        }
    ts_image_free(&img);
}

/* A floor crossing the near plane and passing behind the eye: clipped at
 * the near plane, it covers everything below the horizon and nothing above,
 * with a vertex exactly at the near plane and one exactly in the eye's
 * plane (w = 0). */
TEST(near_plane)
{
    const double znear = 0.25;
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    uint32_t p0 = ts_vertex(&tm, -500, -1, -znear), p1 = ts_vertex(&tm, 500, -1, -znear);
    uint32_t p2 = ts_vertex(&tm, 500, -1, -1000), p3 = ts_vertex(&tm, -500, -1, -1000);
    uint32_t q0 = ts_vertex(&tm, -500, -1, 0), q1 = ts_vertex(&tm, 500, -1, 0);
    uint32_t r0 = ts_vertex(&tm, -500, -1, 900), r1 = ts_vertex(&tm, 500, -1, 900);
    ts_tri(&tm, p0, p1, p2);
    ts_tri(&tm, p0, p2, p3);
    ts_tri(&tm, q0, q1, p1);
    ts_tri(&tm, q0, p1, p0);
    ts_tri(&tm, r0, r1, q1);
    ts_tri(&tm, r0, q1, q0);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    const double eye[3] = { 0, 0, 0 }, target[3] = { 0, 0, -1 };
    ts_image img = { 0 };
    for (int mode = 0; mode < 4; mode++) {
        if (!ts_mode_built(mode)) continue;
        silk_camera cam = ts_camera(eye, target, 90, znear, 2000, 64, 64);
        silk_render_opts o;
        silk_render_opts_default(&o);
        o.mode = (silk_mode)mode;
        CHECK(ts_render(&a, &m, &cam, &o, &img, NULL, &err) == SILK_OK);
        /* the far edge at z = -1000 is 1/1000 below the horizon: row 32.03 */
        long above = 0, below = 0;
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++) {
                if (y < 32) above += ts_covered(&img, x, y);
                if (y >= 33) below += !ts_covered(&img, x, y);
            }
        CHECKF(above == 0 && below == 0, "mode %d: %ld pixels above the horizon, %ld holes below", mode, above,
               below);
    }
    ts_image_free(&img);
}

/* 179 degrees: supported (SILK_FOV_MAX); projections stay within the
 * rounding of the scale sy = cot(89.5 deg) = 0.0087 to Q16.16; beyond it a
 * clear error. */
TEST(fov_179)
{
    silk_camera cam;
    const double eye[3] = { 0, 0, 0 }, target[3] = { 0, 0, -1 };
    cam = ts_camera(eye, target, 179, 0.01, 100, 512, 512);
    silk_view v;
    silk_error err;
    CHECK(SILK_FOV_MAX == SILK_FX_C(179, 1));
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    double sy = 1 / tan(179.0 / 2 * 3.14159265358979323846 / 180);
    double worst = 0;
    for (int i = 0; i < 2000; i++) {
        double p[3] = { check_uniform(-100, 100), check_uniform(-100, 100), -check_uniform(0.02, 99) };
        silk_vec2 px;
        silk_vec3 q = silk_v3(ts_d2fx(p[0]), ts_d2fx(p[1]), ts_d2fx(p[2]));
        if (!silk_view_project(&v, q, &px)) continue;
        double qd[3] = { ts_fx2d(q.x), ts_fx2d(q.y), ts_fx2d(q.z) };
        double rx = (qd[0] * sy / -qd[2] + 1) * 256, ry = (1 - qd[1] * sy / -qd[2]) * 256;
        if (fabs(rx - 256) > 1024 || fabs(ry - 256) > 1024) continue;    /* far off the image */
        /* the scale has 2^-17 / sy relative error: up to 0.12 px at 256 px
         * from the centre */
        double bound = 0.01 + (fabs(rx - 256) + fabs(ry - 256)) * (1.0 / 131072) / sy;
        double e = fmax(fabs(ts_fx2d(px.x) - rx), fabs(ts_fx2d(px.y) - ry));
        if (e / bound > worst) worst = e / bound;
    }
    CHECKF(worst <= 1, "projection error %.3g of its bound", worst);

    cam.fov_deg = SILK_FX_C(1795, 10);
    CHECK(silk_view_init(&v, &cam, &err) == SILK_ERR_RANGE);
    CHECKF(strcmp(err.msg, "camera: field of view must be in [1, 179] degrees for fixed point") == 0, "got \"%s\"",
           err.msg);
    cam.fov_deg = SILK_FX_C(180, 1);
    CHECK(silk_view_init(&v, &cam, &err) == SILK_ERR_ARG);

    /* A floor seen at 179 degrees: the horizon is the middle row. */
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    uint32_t f0 = ts_vertex(&tm, -1000, -1, 1000), f1 = ts_vertex(&tm, 1000, -1, 1000);
    uint32_t f2 = ts_vertex(&tm, 1000, -1, -1000), f3 = ts_vertex(&tm, -1000, -1, -1000);
    ts_tri(&tm, f0, f1, f2);
    ts_tri(&tm, f0, f2, f3);
    silk_mesh m;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    ts_image img = { 0 };
    cam = ts_camera(eye, target, 179, 0.001, 3000, 64, 64);
    CHECK(ts_render(&a, &m, &cam, NULL, &img, NULL, &err) == SILK_OK);
    long above = 0, below = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            if (y < 32) above += ts_covered(&img, x, y);
            else below += ts_covered(&img, x, y);
        }
    CHECKF(above == 0 && below == 32 * 64, "above %ld, below %ld of %d", above, below, 32 * 64);
    ts_image_free(&img);

    /* An aspect ratio the scale cannot hold at this width is refused. */
    cam = ts_camera(eye, target, 179, 0.01, 100, 8192, 1);
    CHECK(silk_view_init(&v, &cam, &err) == SILK_ERR_RANGE);
    CHECKF(strstr(err.msg, "aspect ratio") != NULL, "got \"%s\"", err.msg);
}

/* 16384 x 16384 is refused by the camera and by the renderer (the target),
 * with the sizes in the message; 8192 is the largest side, and a frame of
 * that width renders (as a band of rows, to keep the test small). */
TEST(image_size)
{
    const double eye[3] = { 0, 0, 3 }, target[3] = { 0, 0, 0 };
    silk_camera cam = ts_camera(eye, target, 40, 0.5, 10, 16384, 16384);
    silk_view v;
    silk_error err;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_ERR_RANGE);
    CHECKF(strcmp(err.msg, "camera: image size 16384x16384 is larger than 8192x8192") == 0, "got \"%s\"", err.msg);

    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 12, 8, 1, 0, 0, 0);
    silk_mesh m;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    cam = ts_camera(eye, target, 40, 0.5, 10, 8192, 8192);
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &v);
    silk_hal_phong(&hal, &phong);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.bg_rgb = TS_BG;

    /* the middle row of the 8192 x 8192 frame */
    uint8_t *row = malloc(8192 * 3);
    uint32_t *depth = malloc(8192 * sizeof *depth);
    silk_target t;
    silk_target_init(&t, 8192, 8192, 4096, 1, SILK_PIX_RGB888, row, depth);
    CHECK(silk_render(&a, &m, &v, &hal, &o, &t, NULL, &err) == SILK_OK);
    int first = -1, last = -1;
    for (int x = 0; x < 8192; x++)
        if (!(row[3 * x] == 0xFF && row[3 * x + 1] == 0 && row[3 * x + 2] == 0)) {
            if (first < 0) first = x;
            last = x;
        }
    /* a unit sphere 3 away under 40 degrees: half width 4096 * tan(asin(1/3)) / tan(20 deg) */
    double half = 4096 * tan(asin(1.0 / 3)) / tan(20 * 3.14159265358979323846 / 180);
    CHECKF(first >= 0 && fabs((last - first + 1) - 2 * half) < 0.02 * 2 * half, "row covers %d..%d, want %.0f px",
           first, last, 2 * half);

    /* a target wider than SILK_MAX_DIM is refused, not silently left blank */
    silk_target big;
    silk_target_init(&big, 16384, 16384, 0, 1, SILK_PIX_RGB888, row, depth);
    silk_status st = silk_render(&a, &m, &v, &hal, &o, &big, NULL, &err);
    CHECK(st == SILK_ERR_RANGE);
    CHECKF(st != SILK_OK && strstr(err.msg, "16384x16384") != NULL, "got \"%s\"", err.msg);
    free(row);
    free(depth);
}

/* Eq. 4 as 1 + cos theta -> 0: the tangent is clamped at
 * SILK_ARC_MAX_RATIO |chord| (or shorter, by the bulge bound) and keeps
 * its direction; the longest chord
 * the coordinate range allows still fits Q16.16. */
TEST(tangent_length)
{
    silk_vec3 chord = silk_v3(SILK_FX_C(2048, 1), SILK_FX_C(2048, 1), SILK_FX_C(2048, 1));
    double lc = sqrt(3.0) * 2048;
    silk_vec3 dirs[] = { silk_v3_neg(chord), silk_v3(-SILK_FX_ONE, -SILK_FX_ONE, -SILK_FX_ONE + 1),
                         silk_v3(-1, -1, -1), silk_v3(SILK_FX_MIN, SILK_FX_MIN, SILK_FX_MAX) };
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; i++) {
        silk_vec3 t = silk_arc_tangent(dirs[i], chord);
        double l = sqrt(pow(ts_fx2d(t.x), 2) + pow(ts_fx2d(t.y), 2) + pow(ts_fx2d(t.z), 2));
        double dl = sqrt(pow(ts_fx2d(dirs[i].x), 2) + pow(ts_fx2d(dirs[i].y), 2) + pow(ts_fx2d(dirs[i].z), 2));
        double cosang = (ts_fx2d(t.x) * ts_fx2d(dirs[i].x) + ts_fx2d(t.y) * ts_fx2d(dirs[i].y) +
                         ts_fx2d(t.z) * ts_fx2d(dirs[i].z)) / (l * dl);
        double cos_theta = (ts_fx2d(dirs[i].x) + ts_fx2d(dirs[i].y) + ts_fx2d(dirs[i].z)) * 2048 / (dl * lc);
        double want = 1 + cos_theta <= 2.0 / SILK_ARC_MAX_RATIO ? SILK_ARC_MAX_RATIO * lc : 2 * lc / (1 + cos_theta);
        double sin_theta = sqrt(fmax(0, 1 - cos_theta * cos_theta));
        if (sin_theta > 0) want = fmin(want, lc / (SILK_BULGE_DIV * sin_theta));   /* the bulge bound */
        CHECKF(fabs(l - want) < 1e-3 * want, "dir %zu: length %.3f, want %.3f", i, l, want);
        CHECKF(cosang > 1 - 1e-9, "dir %zu: turned (cos %.12f)", i, cosang);
    }
    /* a bridge over the longest edge, normals facing each other along it */
    silk_curve c;
    silk_vec3 p0 = silk_v3(-SILK_COORD_MAX, -SILK_COORD_MAX, -SILK_COORD_MAX);
    silk_vec3 p1 = silk_v3(SILK_COORD_MAX, SILK_COORD_MAX, SILK_COORD_MAX);
    silk_vec3 n = silk_v3(SILK_FX_C(57735, 100000), SILK_FX_C(57735, 100000), -SILK_FX_C(57735, 100000));
    silk_bridge(p0, n, p1, silk_v3_neg(n), 1, &c);
    CHECK(c.p0.x == p0.x && c.p1.z == p1.z);
    for (int k = 0; k <= 16; k++) {
        silk_vec3 q = silk_hermite_point(&c, SILK_FX_ONE * k / 16);
        CHECKF(abs(q.x) < SILK_FX_MAX && abs(q.y) < SILK_FX_MAX && abs(q.z) < SILK_FX_MAX,
               "point %d of the longest bridge saturated", k);
    }
}

/* Eq. 8 for a segment spanning a huge projected length: capped at
 * SILK_MAX_SAMPLES, monotone up to the cap, never wrapped. */
TEST(sample_count)
{
    uint32_t prev = 0;
    for (int64_t h = 1; h <= SILK_FX_MAX; h = h * 3 + 1) {
        uint32_t n = silk_sample_count((silk_fx)h, -SILK_FX_ONE, SILK_FX_C(1, 4));
        CHECKF(n >= prev && n >= 1 && n <= SILK_MAX_SAMPLES, "h %lld: %u after %u", (long long)h, n, prev);
        prev = n;
    }
    CHECK(silk_sample_count(SILK_FX_MAX, -SILK_FX_ONE, 1) == SILK_MAX_SAMPLES);
    CHECK(silk_sample_count(SILK_FX_MAX, SILK_FX_MIN, SILK_FX_C(1, 4)) == SILK_MAX_SAMPLES);
    CHECK(silk_sample_count(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_C(1, 4)) == 1);

    /* in a frame: a sphere filling a 1024-pixel view at the finest tolerance */
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 8, 6, 1000, 0, 0, 0);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    const double eye[3] = { 0, 0, 1100 }, target[3] = { 0, 0, 0 };
    silk_camera cam = ts_camera(eye, target, 170, 1, 4000, 1024, 1024);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.tolerance_px = SILK_FX_C(1, 4);
    ts_image img = { 0 };
    silk_frame_stats st;
    CHECK(ts_render(&a, &m, &cam, &o, &img, &st, &err) == SILK_OK);
    CHECKF(st.silhouette_tris > 0 && st.samples <= SILK_MAX_SAMPLES * (st.silhouette_tris + st.bridges),
           "%u samples for %u silhouette triangles", st.samples, st.silhouette_tris);
    ts_image_free(&img);
}

/* Screen coordinates, edge functions and depth at the largest frame: a
 * triangle far bigger than the view (clipped to the guard band), at the
 * far end of the depth range, covers every pixel of every row it can
 * reach; one behind it never shows.  The target is one band of rows, so
 * the 8192-wide frame costs no memory. */
TEST(raster_extremes)
{
    uint8_t *row = malloc(8192 * 3);
    uint32_t *depth = malloc(8192 * sizeof *depth);
    silk_hal hal;
    memset(&hal, 0, sizeof hal);
    static const int rows_at[] = { 0, 1, 4095, 4096, 8190, 8191 };
    for (size_t r = 0; r < sizeof rows_at / sizeof rows_at[0]; r++) {
        silk_target t;
        silk_target_init(&t, 8192, 8192, rows_at[r], 1, SILK_PIX_RGB888, row, depth);
        silk_target_clear(&t, TS_BG);
        /* clip coordinates up to the Q16.16 limit, w = 1 and w tiny */
        silk_vertex_out a, b, c;
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        memset(&c, 0, sizeof c);
        a.clip = (silk_vec4){ SILK_FX_MIN, SILK_FX_MIN, SILK_FX_ONE - 2, SILK_FX_ONE };
        b.clip = (silk_vec4){ SILK_FX_MAX, SILK_FX_MIN, SILK_FX_ONE - 2, SILK_FX_ONE };
        c.clip = (silk_vec4){ 0, SILK_FX_MAX, SILK_FX_ONE - 2, SILK_FX_ONE };
        silk_raster_triangle(&t, &hal, &a, &b, &c);
        long holes = 0;
        for (int x = 0; x < 8192; x++) holes += row[3 * x] == 0xFF && row[3 * x + 1] == 0 && row[3 * x + 2] == 0;
        /* with no fragment stage the colour stays; depth shows coverage */
        holes = 0;
        for (int x = 0; x < 8192; x++) holes += depth[x] == 0;
        CHECKF(holes == 0, "row %d: %ld pixels not covered", rows_at[r], holes);
        uint32_t d0 = depth[0];
        /* the same triangle pushed back must fail the depth test everywhere */
        a.clip.z = b.clip.z = c.clip.z = SILK_FX_ONE - 1;
        silk_raster_triangle(&t, &hal, &a, &b, &c);
        CHECK(depth[0] == d0);
        /* w near zero (just in front of the eye) with huge x, y */
        silk_vertex_out p = a, q = b, s = c;
        p.clip = (silk_vec4){ SILK_FX_MIN, 3, -15, 17 };
        q.clip = (silk_vec4){ SILK_FX_MAX, -SILK_FX_MAX, 15, 17 };
        s.clip = (silk_vec4){ 1, SILK_FX_MAX, 16, 17 };
        silk_raster_triangle(&t, &hal, &p, &q, &s);
        silk_raster_line(&t, &p, &q, 0);
        silk_raster_line(&t, &a, &c, 0);
    }
    free(row);
    free(depth);
}

/* Projection of points at the near plane with large offsets: saturated
 * pixel coordinates, no wrap; behind the eye: not projected. */
TEST(project_near_eye)
{
    const double eye[3] = { 0, 0, 0 }, target[3] = { 0, 0, -1 };
    silk_camera cam = ts_camera(eye, target, 1, 1.0 / 1024, 30000, 8192, 8192);
    silk_view v;
    silk_error err;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    silk_vec2 px;
    silk_vec3 p = silk_v3(SILK_FX_C(1024, 1), -SILK_FX_C(1024, 1), -SILK_ZNEAR_MIN);
    CHECK(silk_view_project(&v, p, &px) == 1);
    CHECK(px.x == SILK_FX_MAX && px.y == SILK_FX_MAX);
    p.x = -p.x;
    p.y = -p.y;
    CHECK(silk_view_project(&v, p, &px) == 1);
    CHECK(px.x == SILK_FX_MIN && px.y == SILK_FX_MIN);
    p.z = 1;
    CHECK(silk_view_project(&v, p, &px) == 0);
    /* clip coordinates of the same points: saturated, w exact */
    silk_vec4 c = silk_view_clip(&v, silk_v3(SILK_FX_C(1024, 1), 0, -SILK_ZNEAR_MIN));
    CHECK(c.x == SILK_FX_MAX && c.w == SILK_ZNEAR_MIN);
    /* orthographic: the same clamp on both sides */
    cam.ortho = 1;
    cam.ortho_half_height = SILK_ZNEAR_MIN;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    p = silk_v3(SILK_FX_C(1024, 1), -SILK_FX_C(1024, 1), -SILK_FX_ONE);
    CHECK(silk_view_project(&v, p, &px) == 1 && px.x == SILK_FX_MAX && px.y == SILK_FX_MAX);
    p = silk_v3(-SILK_FX_C(1024, 1), SILK_FX_C(1024, 1), -SILK_FX_ONE);
    CHECK(silk_view_project(&v, p, &px) == 1 && px.x == SILK_FX_MIN && px.y == SILK_FX_MIN);
    cam.ortho = 0;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    /* the farthest point the camera promises: 32767 units away */
    c = silk_view_clip(&v, silk_v3(0, 0, -SILK_FX_C(32767, 1)));
    CHECK(c.w == SILK_FX_C(32767, 1));
}

/* Normals: the angle-weighted sum at a vertex with very many triangles
 * (a fan of 100 000 around one vertex) stays exact in its Q32.32 sum. */
TEST(normal_accumulation)
{
    const int n = 100000;
    silk_arena a = fresh_arena();
    ts_mesh tm = { 0 };
    uint32_t centre = ts_vertex(&tm, 0, 0, 0), prev = ts_vertex(&tm, 1, 0, 0);
    for (int i = 1; i <= n; i++) {
        double ang = 2 * 3.14159265358979323846 * i / n;
        uint32_t cur = i == n ? 1 : ts_vertex(&tm, cos(ang) * 1000, sin(ang) * 1000, 0);
        ts_tri(&tm, centre, prev, cur);
        prev = cur;
    }
    silk_mesh m;
    silk_error err;
    silk_status st = ts_build(&tm, &a, &m, &err);
    ts_mesh_free(&tm);
    CHECKF(st == SILK_OK, "%s", err.msg);
    if (st != SILK_OK) return;
    silk_vec3 nc = m.normal[m.tri_normal[0]];
    CHECKF(nc.x == 0 && nc.y == 0 && nc.z == SILK_FX_ONE, "centre normal %d %d %d", nc.x, nc.y, nc.z);
}

int main(void)
{
    RUN(scale_limits);
    RUN(far_eye);
    RUN(coordinate_limits);
    RUN(eye_on_geometry);
    RUN(near_plane);
    RUN(fov_179);
    RUN(image_size);
    RUN(tangent_length);
    RUN(sample_count);
    RUN(raster_extremes);
    RUN(project_near_eye);
    RUN(normal_accumulation);
    return check_done();
}
