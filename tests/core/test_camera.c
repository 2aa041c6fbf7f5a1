/*
 * test_camera.c - the view: validation, projection against a double
 * reference (perspective and orthographic, near and far from the origin),
 * the 4x4 matrix helpers, and the direction towards the eye.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static silk_fx fxd(double v) { return (silk_fx)llround(v * 65536.0); }
static double dfx(silk_fx v) { return v / 65536.0; }

static silk_camera cam(void)
{
    silk_camera c;
    memset(&c, 0, sizeof c);
    c.eye = silk_v3(fxd(3), fxd(2), fxd(5));
    c.target = silk_v3(0, 0, 0);
    c.up = silk_v3(0, SILK_FX_ONE, 0);
    c.fov_deg = SILK_FX_C(45, 1);
    c.ortho_half_height = SILK_FX_C(3, 2);
    c.znear = SILK_FX_C(1, 10);
    c.zfar = SILK_FX_C(100, 1);
    c.width = 640;
    c.height = 480;
    return c;
}

/* ---- the double reference --------------------------------------------------- */

typedef struct dview { double e[3], r[3], u[3], f[3], sx, sy; int ortho, w, h; double n, fa; } dview;

static void dnorm(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) v[k] /= l;
}

static void dcross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static void dview_init(dview *d, const silk_camera *c)
{
    double t[3] = { dfx(c->target.x), dfx(c->target.y), dfx(c->target.z) };
    double up[3] = { dfx(c->up.x), dfx(c->up.y), dfx(c->up.z) };
    d->e[0] = dfx(c->eye.x); d->e[1] = dfx(c->eye.y); d->e[2] = dfx(c->eye.z);
    for (int k = 0; k < 3; k++) d->f[k] = t[k] - d->e[k];
    dnorm(d->f);
    dcross(d->f, up, d->r);
    dnorm(d->r);
    dcross(d->r, d->f, d->u);
    d->ortho = c->ortho;
    d->w = c->width;
    d->h = c->height;
    d->n = dfx(c->znear);
    d->fa = dfx(c->zfar);
    d->sy = c->ortho ? 1 / dfx(c->ortho_half_height) : 1 / tan(dfx(c->fov_deg) * M_PI / 360);
    d->sx = d->sy * c->height / c->width;
}

/* pixel position (x right, y down) and eye depth of world point p */
static void dproject(const dview *d, const double p[3], double *px, double *py, double *depth)
{
    double q[3] = { p[0] - d->e[0], p[1] - d->e[1], p[2] - d->e[2] };
    double ex = q[0] * d->r[0] + q[1] * d->r[1] + q[2] * d->r[2];
    double ey = q[0] * d->u[0] + q[1] * d->u[1] + q[2] * d->u[2];
    double ez = q[0] * d->f[0] + q[1] * d->f[1] + q[2] * d->f[2];   /* distance along the view */
    double nx = d->sx * ex / (d->ortho ? 1 : ez), ny = d->sy * ey / (d->ortho ? 1 : ez);
    *px = (nx + 1) / 2 * d->w;
    *py = (1 - ny) / 2 * d->h;
    *depth = ez;
}

/* ---- tests ---------------------------------------------------------------------- */

TEST(validation)
{
    silk_view v;
    silk_error err;
    struct { const char *what; silk_status code; const char *msg; } cases[] = {
        { "eye==target", SILK_ERR_ARG, "same point" },
        { "up zero", SILK_ERR_ARG, "up vector is zero" },
        { "up parallel", SILK_ERR_ARG, "parallel" },
        { "fov 0", SILK_ERR_ARG, "field of view" },
        { "fov 180", SILK_ERR_ARG, "field of view" },
        { "fov 0.5", SILK_ERR_RANGE, "field of view" },
        { "znear 0", SILK_ERR_ARG, "znear" },
        { "zfar<znear", SILK_ERR_ARG, "znear < zfar" },
        { "znear tiny", SILK_ERR_RANGE, "znear" },
        { "width 0", SILK_ERR_ARG, "smaller than 1x1" },
        { "height -3", SILK_ERR_ARG, "smaller than 1x1" },
        { "huge", SILK_ERR_RANGE, "larger than" },
        { "ortho 0", SILK_ERR_RANGE, "half height" },
        { "aspect", SILK_ERR_RANGE, "scale" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        silk_camera c = cam();
        switch (i) {
        case 0: c.target = c.eye; break;
        case 1: c.up = silk_v3(0, 0, 0); break;
        case 2: c.up = silk_v3(fxd(-3), fxd(-2), fxd(-5)); break;
        case 3: c.fov_deg = 0; break;
        case 4: c.fov_deg = SILK_FX_C(180, 1); break;
        case 5: c.fov_deg = SILK_FX_C(1, 2); break;
        case 6: c.znear = 0; break;
        case 7: c.zfar = c.znear; break;
        case 8: c.znear = 10; break;
        case 9: c.width = 0; break;
        case 10: c.height = -3; break;
        case 11: c.width = SILK_MAX_DIM + 1; break;
        case 12: c.ortho = 1; c.ortho_half_height = 0; break;
        case 13: c.fov_deg = SILK_FX_C(2, 1); c.width = 1; c.height = 8000; break;
        }
        memset(&err, 0, sizeof err);
        silk_status st = silk_view_init(&v, &c, &err);
        CHECKF(st == cases[i].code, "%s: status %d", cases[i].what, (int)st);
        CHECKF(err.code == cases[i].code && strstr(err.msg, cases[i].msg) && strncmp(err.msg, "camera: ", 8) == 0,
               "%s: message \"%s\"", cases[i].what, err.msg);
    }
    /* almost parallel but not quite (1 degree) is fine */
    silk_camera c = cam();
    c.eye = silk_v3(0, fxd(5), 0);
    c.up = silk_v3(fxd(sin(M_PI / 180)), fxd(cos(M_PI / 180)), 0);
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    CHECK(silk_view_init(NULL, &c, &err) == SILK_ERR_ARG);
}

/* Random cameras and points: pixel positions agree with the double
 * reference to a small fraction of a pixel. */
TEST(project_vs_double)
{
    double worst[2] = { 0, 0 };
    int behind_ok = 1;
    for (int trial = 0; trial < 4000; trial++) {
        silk_camera c = cam();
        c.ortho = trial & 1;
        double R = check_uniform(2, 50);
        double a = check_uniform(0, 2 * M_PI), e = check_uniform(-1.4, 1.4);
        double ctr[3] = { check_uniform(-500, 500), check_uniform(-500, 500), check_uniform(-500, 500) };
        c.target = silk_v3(fxd(ctr[0]), fxd(ctr[1]), fxd(ctr[2]));
        c.eye = silk_v3(fxd(ctr[0] + R * cos(e) * cos(a)), fxd(ctr[1] + R * sin(e)), fxd(ctr[2] + R * cos(e) * sin(a)));
        c.fov_deg = fxd(check_uniform(10, 120));
        c.ortho_half_height = fxd(R * check_uniform(0.2, 1));
        c.width = (int)(check_rand64() % 2000) + 16;
        c.height = (int)(check_rand64() % 2000) + 16;
        silk_view v;
        silk_error err;
        if (silk_view_init(&v, &c, &err) != SILK_OK) { CHECKF(0, "%s", err.msg); continue; }
        dview d;
        dview_init(&d, &c);
        for (int k = 0; k < 20; k++) {
            /* a point in the view: along the view direction, spread sideways */
            double dist = check_uniform(0.2, 1.5) * R;
            double p[3];
            for (int j = 0; j < 3; j++)
                p[j] = dfx(c.eye.x) * (j == 0) + dfx(c.eye.y) * (j == 1) + dfx(c.eye.z) * (j == 2) + d.f[j] * dist +
                       d.r[j] * check_uniform(-0.4, 0.4) * dist + d.u[j] * check_uniform(-0.3, 0.3) * dist;
            silk_vec3 q = silk_v3(fxd(p[0]), fxd(p[1]), fxd(p[2]));
            for (int j = 0; j < 3; j++) p[j] = (j == 0 ? q.x : j == 1 ? q.y : q.z) / 65536.0;
            double px, py, depth;
            dproject(&d, p, &px, &py, &depth);
            silk_vec2 s;
            int vis = silk_view_project(&v, q, &s);
            if (depth < d.n * 1.001) { if (vis && depth < d.n * 0.999) behind_ok = 0; continue; }
            if (!vis) { CHECKF(0, "point at depth %g not projected", depth); continue; }
            /* allowed: two Q16.16 ulps of eye space as seen on screen, plus the
             * rounding of the projection scale sy to Q16.16 (relative 2^-17 / sy,
             * growing towards the image border), plus 0.002 px */
            double ulp_px = (c.ortho ? 1 : 1 / depth) * dfx(v.pixels_per_unit) / 65536;
            double sy = dfx(v.proj.m[1][1]), off = fmax(fabs(px - c.width / 2.0), fabs(py - c.height / 2.0));
            double allowed = 0.002 + 2 * ulp_px + (c.ortho ? 0 : off * 0.5 / 65536 / sy);
            double err = fmax(fabs(dfx(s.x) - px), fabs(dfx(s.y) - py)) / allowed;
            if (err > worst[c.ortho]) worst[c.ortho] = err;
        }
    }
    printf("  worst projection error / allowed: perspective %.2f, orthographic %.2f\n", worst[0], worst[1]);
    CHECKF(worst[0] <= 1 && worst[1] <= 1, "projection error %g / %g of the allowed", worst[0], worst[1]);
    CHECK(behind_ok);
}

/* The eye 20000 units away from a model near 1000: the subtraction before the
 * rotation keeps the model's precision. */
TEST(far_eye)
{
    silk_camera c = cam();
    c.target = silk_v3(fxd(1000), fxd(-1000), fxd(1000));
    c.eye = silk_v3(fxd(1000 + 12000), fxd(-1000 + 9000), fxd(1000 + 12000));
    c.fov_deg = fxd(2);
    c.znear = fxd(1);
    c.zfar = fxd(30000);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    dview d;
    dview_init(&d, &c);
    double worst = 0;
    for (int k = 0; k < 2000; k++) {
        silk_vec3 q = silk_v3(c.target.x + fxd(check_uniform(-20, 20)), c.target.y + fxd(check_uniform(-20, 20)),
                              c.target.z + fxd(check_uniform(-20, 20)));
        double p[3] = { dfx(q.x), dfx(q.y), dfx(q.z) }, px, py, depth;
        dproject(&d, p, &px, &py, &depth);
        silk_vec2 s;
        CHECK(silk_view_project(&v, q, &s));
        worst = fmax(worst, fmax(fabs(dfx(s.x) - px), fabs(dfx(s.y) - py)));
    }
    printf("  eye 21000 units away, fov 2 degrees: worst error %.4f px\n", worst);
    CHECKF(worst < 0.2, "far eye: %g px", worst);
}

/* Clip coordinates follow the documented projection (far plane at infinity
 * for perspective: z = w - 2 znear), and the 4x4 viewproj agrees with them. */
TEST(clip_space)
{
    for (int ortho = 0; ortho < 2; ortho++) {
        silk_camera c = cam();
        c.ortho = ortho;
        silk_view v;
        CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
        dview d;
        dview_init(&d, &c);
        double worst = 0, worst_m = 0;
        for (int k = 0; k < 1000; k++) {
            silk_vec3 q = silk_v3(fxd(check_uniform(-3, 3)), fxd(check_uniform(-3, 3)), fxd(check_uniform(-3, 3)));
            silk_vec4 a = silk_view_clip(&v, q), b = silk_mat4_apply_point(&v.viewproj, q);
            double p[3] = { dfx(q.x), dfx(q.y), dfx(q.z) }, px, py, depth;
            dproject(&d, p, &px, &py, &depth);
            /* clip x, y back from the double pixel position */
            double w = ortho ? 1 : depth, cx = (px / c.width * 2 - 1) * w, cy = (1 - py / c.height * 2) * w;
            worst = fmax(worst, fmax(fabs(dfx(a.x) - cx), fabs(dfx(a.y) - cy)));
            if (ortho) {
                CHECK(a.w == SILK_FX_ONE);
                double z = (-2 * -depth - (d.fa + d.n)) / (d.fa - d.n);
                worst = fmax(worst, fabs(dfx(a.z) - z));
            } else {
                CHECK(a.z == a.w - 2 * c.znear);
                worst = fmax(worst, fabs(dfx(a.w) - depth));
            }
            /* the matrix path rounds more but must agree closely */
            worst_m = fmax(worst_m, fmax(fmax(fabs(dfx(a.x) - dfx(b.x)), fabs(dfx(a.y) - dfx(b.y))),
                                         fmax(fabs(dfx(a.z) - dfx(b.z)), fabs(dfx(a.w) - dfx(b.w)))));
        }
        printf("  %s clip coordinates: %.2f ulp from double, viewproj matrix within %.1f ulp\n",
               ortho ? "orthographic" : "perspective", worst * 65536, worst_m * 65536);
        CHECKF(worst < 2.0 / 65536, "ortho %d: clip error %g", ortho, worst);
        CHECKF(worst_m < 16.0 / 65536, "ortho %d: matrix path differs by %g", ortho, worst_m);
    }
}

TEST(to_eye_and_axes)
{
    silk_camera c = cam();
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_vec3 p = silk_v3(fxd(1), fxd(-2), fxd(0.5));
    silk_vec3 d = silk_view_to_eye(&v, p);
    CHECK(d.x == c.eye.x - p.x && d.y == c.eye.y - p.y && d.z == c.eye.z - p.z);
    /* axes: unit, orthogonal, right-handed (right x up = -forward) */
    silk_vec3 ax[3] = { v.right, v.upv, v.forward };
    for (int i = 0; i < 3; i++) {
        CHECKF(llabs(silk_v3_dot64(ax[i], ax[i]) - ((int64_t)1 << 32)) < ((int64_t)1 << 18), "axis %d not unit", i);
        for (int j = i + 1; j < 3; j++) CHECKF(llabs(silk_v3_dot64(ax[i], ax[j])) < ((int64_t)1 << 18), "axes %d %d", i, j);
    }
    silk_vec3 x = silk_v3_cross(v.right, v.upv);
    CHECK(abs(x.x + v.forward.x) < 8 && abs(x.y + v.forward.y) < 8 && abs(x.z + v.forward.z) < 8);
    /* the target projects to the image centre */
    silk_vec2 s;
    CHECK(silk_view_project(&v, c.target, &s));
    CHECKF(abs(s.x - 320 * 65536) < 64 && abs(s.y - 240 * 65536) < 64, "target at (%g, %g)", dfx(s.x), dfx(s.y));
    c.ortho = 1;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    d = silk_view_to_eye(&v, p);
    CHECK(d.x == -v.forward.x && d.y == -v.forward.y && d.z == -v.forward.z);
    /* pixels per unit: ortho height 2 * 1.5 units over 480 pixels */
    CHECKF(abs(v.pixels_per_unit - 160 * 65536) < 4, "ortho pixels per unit %g", dfx(v.pixels_per_unit));
    /* a point behind the eye does not project */
    c.ortho = 0;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    CHECK(!silk_view_project(&v, silk_v3(fxd(6), fxd(4), fxd(10)), &s));
    CHECKF(fabs(dfx(v.pixels_per_unit) - 240 / tan(M_PI / 8)) < 0.01, "perspective pixels per unit %g",
           dfx(v.pixels_per_unit));
}

TEST(matrices)
{
    silk_mat4 I = silk_mat4_identity();
    double worst = 0;
    for (int trial = 0; trial < 2000; trial++) {
        silk_mat4 a, b;
        double da[4][4], db[4][4];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                a.m[i][j] = fxd(check_uniform(-40, 40));
                b.m[i][j] = fxd(check_uniform(-40, 40));
                da[i][j] = dfx(a.m[i][j]);
                db[i][j] = dfx(b.m[i][j]);
            }
        silk_mat4 c = silk_mat4_mul(&a, &b), ai = silk_mat4_mul(&a, &I);
        CHECK(memcmp(&ai, &a, sizeof a) == 0);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                double s = 0;
                for (int k = 0; k < 4; k++) s += da[i][k] * db[k][j];
                worst = fmax(worst, fabs(dfx(c.m[i][j]) - s));
            }
        silk_vec3 p = silk_v3(fxd(check_uniform(-500, 500)), fxd(check_uniform(-500, 500)), fxd(check_uniform(-500, 500)));
        silk_vec4 q = silk_mat4_apply_point(&a, p);
        silk_vec3 r = silk_mat4_apply_dir(&a, p);
        double pv[4] = { dfx(p.x), dfx(p.y), dfx(p.z), 1 }, qv[4] = { dfx(q.x), dfx(q.y), dfx(q.z), dfx(q.w) };
        double rv[3] = { dfx(r.x), dfx(r.y), dfx(r.z) };
        for (int i = 0; i < 4; i++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += da[i][k] * pv[k];
            if (fabs(s) < 32767) worst = fmax(worst, fabs(qv[i] - s));
            else CHECKF((s > 0) == (qv[i] > 0) && fabs(qv[i]) > 32767, "no saturation: %g vs %g", qv[i], s);
            if (i < 3) {
                s -= da[i][3];
                if (fabs(s) < 32767) worst = fmax(worst, fabs(rv[i] - s));
                else CHECKF((s > 0) == (rv[i] > 0), "dir sign flipped");
            }
        }
    }
    CHECKF(worst <= 0.5 / 65536 + 1e-12, "matrix error %g (more than half an ulp)", worst);
    /* extremes saturate instead of wrapping */
    silk_mat4 big;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) big.m[i][j] = SILK_FX_MAX;
    silk_mat4 sq = silk_mat4_mul(&big, &big);
    CHECK(sq.m[0][0] == SILK_FX_MAX && sq.m[3][3] == SILK_FX_MAX);
    for (int j = 0; j < 4; j++) big.m[1][j] = SILK_FX_MIN;
    sq = silk_mat4_mul(&big, &big);
    CHECK(sq.m[1][0] == SILK_FX_MIN);
    silk_vec4 q = silk_mat4_apply_point(&big, silk_v3(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MAX));
    CHECK(q.x == SILK_FX_MAX && q.y == SILK_FX_MIN);
}

int main(void)
{
    RUN(validation);
    RUN(project_vs_double);
    RUN(far_eye);
    RUN(clip_space);
    RUN(to_eye_and_axes);
    RUN(matrices);
    return check_done();
}
