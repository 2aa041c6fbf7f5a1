/*
 * test_curve.c - the curve mathematics of paper section III (src/curve.c)
 * against double-precision references computed here from the same Q16.16
 * inputs: eq. 4 (silk_arc_tangent), eqs. 2-5 (silk_bridge), eqs. 6-7
 * (silk_silhouette_param), eq. 8 (silk_sample_count); then what the
 * constructions are for: a bridge over two points of a circle stays on the
 * circle, the silhouette parameter on a sphere lands on the true
 * silhouette, and it moves continuously with the eye.
 *
 * Errors are in ulps of Q16.16 (2^-16).  The fixed-point code keeps about
 * 30 significant bits internally, so a result's error is at most about one
 * rounding plus 2^-27 of its own size (in ulps) - the bounds below say so.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "src/curve.h"
#include "support/testvec.h"

#define ULP (1.0 / 65536.0)
#define PI 3.14159265358979323846
#define N_RANDOM 100000

/* Saturating, and halves rounded up: not testvec.h's d2fx. */
static silk_fx fx(double v)
{
    double r = floor(v * 65536.0 + 0.5);
    if (r > SILK_FX_MAX) r = SILK_FX_MAX;
    if (r < SILK_FX_MIN) r = SILK_FX_MIN;
    return (silk_fx)r;
}
static silk_vec3 fx3(dvec v) { return silk_v3(fx(v.x), fx(v.y), fx(v.z)); }
static double maxabs(dvec a) { return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z))); }

/* A length spread over many scales: 2^-14 .. 2^11 units. */
static double rand_scale(void) { return pow(2.0, check_uniform(-14, 11)); }

/* Component error of a fixed-point vector against a double one, in ulps. */
static double err_ulp(silk_vec3 got, dvec want)
{
    return maxabs(dsub(dv(got), want)) / ULP;
}

/* ---- eq. 4 reference -------------------------------------------------------- */

static dvec ref_arc_tangent(dvec dir, dvec chord)
{
    double lc = dlen(chord), ld = dlen(dir);
    if (lc == 0) return dmk(0, 0, 0);
    if (ld == 0) return chord;
    double cth = ddot(dir, chord) / (ld * lc), sth = dlen(dcross(dir, chord)) / (ld * lc);
    double den = fmax(1 + cth, 2.0 / SILK_ARC_MAX_RATIO);
    double L = 2 * lc / den;
    if (sth > 0) L = fmin(L, lc / (SILK_BULGE_DIV * sth));   /* the bulge bound */
    dvec t = dscale(dir, L / ld);
    double m = maxabs(t), lim = SILK_FX_MAX / 65536.0;
    return m > lim ? dscale(t, lim / m) : t;
}

/* Bound: one rounding, the 30-bit internal precision, and the rounding of
 * the input directions (tiny vectors carry few bits: a dir of a few ulps has
 * a direction known only to ~1/|dir|). */
static double arc_bound(dvec want) { return 1.0 + maxabs(want) / ULP * 0x1p-27; }

TEST(arc_tangent_random)
{
    double worst = 0, worst_ratio = 0;
    int bad = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        dvec chord = dscale(rand_unit(), rand_scale());
        dvec dir;
        int kind = i % 4;
        if (kind == 0) dir = rand_unit();                                /* any angle */
        else if (kind == 1) dir = dadd(dnorm(chord), dscale(rand_unit(), 0.3)); /* near the chord */
        else if (kind == 2) dir = dadd(dscale(dnorm(chord), -1), dscale(rand_unit(), 0.05)); /* backwards */
        else dir = dcross(chord, rand_unit());                            /* perpendicular */
        dir = dscale(dnorm(dir), rand_scale());
        silk_vec3 fd = fx3(dir), fc = fx3(chord);
        dvec want = ref_arc_tangent(dv(fd), dv(fc));
        silk_vec3 got = silk_arc_tangent(fd, fc);
        double e = err_ulp(got, want);
        /* dir shorter than 2^-10 is a handful of ulps: its rounding to Q16.16
         * already turned it, but the reference uses the same rounded input,
         * so the bound holds as it is. */
        if (e > worst) worst = e;
        if (e / arc_bound(want) > worst_ratio) worst_ratio = e / arc_bound(want);
        if (e > arc_bound(want)) {
            if (bad++ < 5)
                CHECKF(0, "dir (%g %g %g) chord (%g %g %g): got (%g %g %g) want (%.9g %.9g %.9g)",
                       dir.x, dir.y, dir.z, chord.x, chord.y, chord.z, fx2d(got.x), fx2d(got.y),
                       fx2d(got.z), want.x, want.y, want.z);
        }
    }
    CHECKF(bad == 0, "%d of %d beyond 1 ulp + 2^-27 relative", bad, N_RANDOM);
    printf("  arc_tangent: worst %.3f ulp, at most %.2f of the bound (%d inputs)\n", worst, worst_ratio, N_RANDOM);
}

TEST(arc_tangent_special)
{
    silk_vec3 c = silk_v3(SILK_FX_ONE, 0, 0);
    /* theta = 0: a straight line, L = |chord|. */
    silk_vec3 t = silk_arc_tangent(silk_v3(5, 0, 0), c);
    CHECKF(t.x == SILK_FX_ONE && t.y == 0 && t.z == 0, "%d %d %d", t.x, t.y, t.z);
    /* theta = 90 degrees: eq. 4's semicircle (L = 2|chord|) is cut by the
     * bulge bound to L = |chord| / 2. */
    t = silk_arc_tangent(silk_v3(0, 3 * SILK_FX_ONE, 0), c);
    CHECKF(t.x == 0 && t.y == SILK_FX_ONE / 2 && t.z == 0, "%d %d %d", t.x, t.y, t.z);
    /* theta = 60 degrees: eq. 4 says 4/3, the bound 1 / (2 sin 60) = 0.577. */
    t = silk_arc_tangent(silk_v3(SILK_FX_ONE, fx(sqrt(3.0)), 0), c);
    CHECKF(abs(t.x - fx(0.5 / sqrt(3.0))) <= 1 && abs(t.y - fx(0.5)) <= 1, "%d %d", t.x, t.y);
    /* theta = 20 degrees: eq. 4 as it is, 2 / (1 + cos 20). */
    t = silk_arc_tangent(fx3(dmk(cos(20 * PI / 180), sin(20 * PI / 180), 0)), c);
    CHECKF(fabs(dlen(dv(t)) - 2 / (1 + cos(20 * PI / 180))) < 4 * ULP, "len %.9g", dlen(dv(t)));
    /* dir == 0: the chord. */
    silk_vec3 ch = silk_v3(123456, -7, 99);
    t = silk_arc_tangent(silk_v3(0, 0, 0), ch);
    CHECK(t.x == ch.x && t.y == ch.y && t.z == ch.z);
    /* chord == 0: zero tangent, whatever dir. */
    t = silk_arc_tangent(silk_v3(1, 2, 3), silk_v3(0, 0, 0));
    CHECK(t.x == 0 && t.y == 0 && t.z == 0);
    /* pointing backwards: clamped at SILK_ARC_MAX_RATIO |chord| where the
     * bulge bound leaves it longer (within 7 degrees of straight back),
     * continuously. */
    t = silk_arc_tangent(silk_v3(-SILK_FX_ONE, 0, 0), c);
    CHECKF(t.x == -SILK_ARC_MAX_RATIO * SILK_FX_ONE && t.y == 0 && t.z == 0, "%d", t.x);
    t = silk_arc_tangent(silk_v3(-SILK_FX_ONE, 1, 0), c);     /* dir turned by 2^-16 rad */
    CHECKF(t.x == -SILK_ARC_MAX_RATIO * SILK_FX_ONE && t.y == SILK_ARC_MAX_RATIO, "%d %d", t.x, t.y);
    double th = 175.0 * PI / 180;
    t = silk_arc_tangent(fx3(dmk(cos(th), sin(th), 0)), c);
    CHECKF(fabs(dlen(dv(t)) - SILK_ARC_MAX_RATIO) < 4 * ULP, "len %.9g", dlen(dv(t)));
    th = 119.0 * PI / 180;
    t = silk_arc_tangent(fx3(dmk(cos(th), sin(th), 0)), c);
    CHECKF(fabs(dlen(dv(t)) - 0.5 / sin(th)) < 4 * ULP, "len %.9g", dlen(dv(t)));
    /* 1-ulp vectors. */
    t = silk_arc_tangent(silk_v3(0, 1, 0), silk_v3(2, 0, 0));
    CHECKF(t.x == 0 && t.y == 1 && t.z == 0, "%d %d %d", t.x, t.y, t.z);
    t = silk_arc_tangent(silk_v3(0, SILK_FX_MAX, 0), silk_v3(1, 1, 0));
    CHECKF(t.x == 0 && t.y == 1, "%d %d", t.x, t.y);
    /* The largest chords: the result is shortened as a whole, never wraps
     * and keeps its direction. */
    silk_vec3 big = silk_v3(SILK_FX_MAX, SILK_FX_MAX, -SILK_FX_MAX);
    t = silk_arc_tangent(silk_v3(SILK_FX_MIN, 0, 0), big);
    dvec want = ref_arc_tangent(dv(silk_v3(SILK_FX_MIN, 0, 0)), dv(big));
    CHECKF(err_ulp(t, want) <= arc_bound(want), "(%d %d %d)", t.x, t.y, t.z);
    CHECK(t.x == SILK_FX_MIN);
    t = silk_arc_tangent(silk_v3(INT32_MIN, INT32_MIN, INT32_MIN), silk_v3(INT32_MIN, 5, INT32_MIN));
    CHECK(t.x < 0 && t.y < 0 && t.z < 0);
    /* Model-range chords never reach the shortening: the longest chord of
     * the +-1024 box with the largest tangent. */
    silk_vec3 diag = silk_v3(2048 * SILK_FX_ONE - 1, 2048 * SILK_FX_ONE - 1, 2048 * SILK_FX_ONE - 1);
    t = silk_arc_tangent(silk_v3_neg(diag), diag);
    CHECKF(fabs(dlen(dv(t)) - 4 * dlen(dv(diag))) < 8 * ULP * 4 * 2048, "len %.9g", dlen(dv(t)));
}

/* ---- eqs. 2-5 reference ----------------------------------------------------- */

static void ref_bridge(dvec p0, dvec n0, dvec p1, dvec n1, dvec *t0, dvec *t1, double *cond)
{
    dvec c = dsub(p1, p0);
    dvec m0 = dnorm(n0), m1 = dnorm(n1);
    /* the tilt bound (curve.h): each end's lean along the chord at most
     * the other's plus |chord| / SILK_TILT_SLACK */
    double l0 = dlen(n0) ? ddot(c, m0) : 0, l1 = dlen(n1) ? ddot(c, m1) : 0;
    double cap0 = fabs(l1) + dlen(c) / SILK_TILT_SLACK, cap1 = fabs(l0) + dlen(c) / SILK_TILT_SLACK;
    l0 = fmax(-cap0, fmin(cap0, l0));
    l1 = fmax(-cap1, fmin(cap1, l1));
    dvec a = dsub(c, dscale(m0, l0));
    dvec b = dsub(c, dscale(m1, l1));
    /* How much a rounding of the chord turns the projected direction. */
    double la = dlen(a), lb = dlen(b);
    *cond = dlen(c) / fmax(fmin(la, lb), 1e-300);
    if (la == 0 || dlen(n0) == 0) a = c;
    if (lb == 0 || dlen(n1) == 0) b = c;
    *t0 = ref_arc_tangent(a, c);
    *t1 = ref_arc_tangent(b, c);
}

TEST(bridge_random)
{
    double worst = 0, worst_ratio = 0;
    int bad = 0, n = 0;
    for (int i = 0; n < N_RANDOM; i++) {
        dvec p0 = dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), 1024);
        dvec c;
        int kind = i % 3;
        if (kind == 0) c = dscale(rand_unit(), rand_scale());                       /* any edge */
        else if (kind == 1) c = dsub(dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), 1024), p0); /* huge */
        else c = dscale(rand_unit(), pow(2.0, check_uniform(-14, -6)));             /* tiny */
        dvec p1 = dadd(p0, c);
        if (maxabs(p1) > 1024) continue;
        /* Normals as on a surface: roughly across the edge, sometimes tilted
         * far towards it. */
        dvec e = dnorm(c);
        dvec side = dnorm(dcross(e, rand_unit()));
        double tilt0 = check_uniform(-1.2, 1.2), tilt1 = check_uniform(-1.2, 1.2);
        if (i % 10 == 0) tilt0 = check_uniform(-1.55, 1.55);
        dvec n0 = dadd(dscale(side, cos(tilt0)), dscale(e, sin(tilt0)));
        dvec n1 = dadd(dscale(dnorm(dadd(side, dscale(rand_unit(), 0.3))), cos(tilt1)), dscale(e, sin(tilt1)));
        n1 = dnorm(n1);
        silk_vec3 fp0 = fx3(p0), fp1 = fx3(p1), fn0 = fx3(n0), fn1 = fx3(n1);
        silk_curve cv;
        memset(&cv, 0x55, sizeof cv);
        silk_bridge(fp0, fn0, fp1, fn1, 1, &cv);
        dvec t0, t1;
        double cond;
        ref_bridge(dv(fp0), dv(fn0), dv(fp1), dv(fn1), &t0, &t1, &cond);
        double e0 = err_ulp(cv.t0, t0), e1 = err_ulp(cv.t1, t1);
        double b0 = 1.0 + maxabs(t0) / ULP * 0x1p-27 * cond;
        double b1 = 1.0 + maxabs(t1) / ULP * 0x1p-27 * cond;
        n++;
        if (fmax(e0, e1) > worst) worst = fmax(e0, e1);
        if (fmax(e0 / b0, e1 / b1) > worst_ratio) worst_ratio = fmax(e0 / b0, e1 / b1);
        int ends_ok = cv.p0.x == fp0.x && cv.p0.y == fp0.y && cv.p0.z == fp0.z && cv.p1.x == fp1.x &&
                      cv.n0.x == fn0.x && cv.n1.z == fn1.z && cv.uv0.x == 0x55555555;
        if (e0 > b0 || e1 > b1 || !ends_ok) {
            if (bad++ < 5)
                CHECKF(0, "p0 (%g %g %g) chord (%g %g %g): errors %.2f %.2f ulp (bounds %.2f %.2f), ends %d",
                       p0.x, p0.y, p0.z, c.x, c.y, c.z, e0, e1, b0, b1, ends_ok);
        }
    }
    CHECKF(bad == 0, "%d of %d bridges beyond the bound", bad, n);
    printf("  bridge: worst tangent error %.3f ulp, at most %.2f of the bound (%d bridges)\n", worst, worst_ratio, n);
}

TEST(bridge_special)
{
    silk_curve cv;
    silk_vec3 p = silk_v3(SILK_FX_ONE, 2 * SILK_FX_ONE, 3), nz = silk_v3(0, 0, SILK_FX_ONE);
    /* Zero-length edge: zero tangents, the end points kept. */
    silk_bridge(p, nz, p, nz, 1, &cv);
    CHECK(cv.t0.x == 0 && cv.t0.y == 0 && cv.t0.z == 0 && cv.t1.x == 0 && cv.t1.y == 0 && cv.t1.z == 0);
    CHECK(cv.p0.x == p.x && cv.p1.y == p.y);
    /* Edge in the tangent planes: both tangents are the chord. */
    silk_vec3 q = silk_v3(3 * SILK_FX_ONE, 2 * SILK_FX_ONE, 3);
    silk_bridge(p, nz, q, nz, 1, &cv);
    CHECK(cv.t0.x == 2 * SILK_FX_ONE && cv.t0.y == 0 && cv.t0.z == 0);
    CHECK(cv.t1.x == 2 * SILK_FX_ONE && cv.t1.y == 0 && cv.t1.z == 0);
    /* Edge along a normal: no tangent plane direction, straight chord; at
     * the other end the chord lies in the tangent plane. */
    silk_vec3 r = silk_v3(p.x, p.y, p.z + SILK_FX_ONE);
    silk_bridge(p, nz, r, silk_v3(SILK_FX_ONE, 0, 0), 1, &cv);
    CHECK(cv.t0.x == 0 && cv.t0.y == 0 && cv.t0.z == SILK_FX_ONE);
    CHECK(cv.t1.x == 0 && cv.t1.y == 0 && cv.t1.z == SILK_FX_ONE);
    /* A quarter circle: from (1,0,0) with normal x to (0,1,0) with normal y,
     * both tangents at 45 degrees to the chord: eq. 4's 2 sqrt 2 / (1 +
     * sqrt .5) cut by the bulge bound to sqrt 2 / (2 sin 45) = 1. */
    silk_bridge(silk_v3(SILK_FX_ONE, 0, 0), silk_v3(SILK_FX_ONE, 0, 0), silk_v3(0, SILK_FX_ONE, 0),
                silk_v3(0, SILK_FX_ONE, 0), 1, &cv);
    double lq = 1;
    CHECKF(cv.t0.x == 0 && abs(cv.t0.y - fx(lq)) <= 1 && cv.t0.z == 0, "%d %d", cv.t0.x, cv.t0.y);
    CHECKF(abs(cv.t1.x + fx(lq)) <= 1 && cv.t1.y == 0 && cv.t1.z == 0, "%d %d", cv.t1.x, cv.t1.y);
    /* A zero normal is treated as "no information": the chord. */
    silk_bridge(p, silk_v3(0, 0, 0), q, nz, 1, &cv);
    CHECK(cv.t0.x == 2 * SILK_FX_ONE && cv.t0.y == 0);
    /* Points at opposite corners of the whole Q16.16 range: no overflow,
     * tangents shortened to fit, along the chord projected. */
    silk_vec3 lo = silk_v3(SILK_FX_MIN, SILK_FX_MIN, SILK_FX_MIN), hi = silk_v3(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MAX);
    silk_bridge(lo, nz, hi, nz, 1, &cv);
    CHECKF(cv.t0.x == SILK_FX_MAX && cv.t0.y == SILK_FX_MAX && cv.t0.z == 0, "%d %d %d", cv.t0.x, cv.t0.y, cv.t0.z);
    silk_bridge(hi, silk_v3(INT32_MIN, INT32_MIN, 0), lo, silk_v3(SILK_FX_MIN, SILK_FX_MIN, 0), 1, &cv);
    CHECKF(cv.t0.x == 0 && cv.t0.y == 0 && cv.t0.z == SILK_FX_MIN, "%d %d %d", cv.t0.x, cv.t0.y, cv.t0.z);
    CHECKF(cv.t1.x == 0 && cv.t1.y == 0 && cv.t1.z == SILK_FX_MIN, "%d %d %d", cv.t1.x, cv.t1.y, cv.t1.z);
}

/* Hermite point of eq. 5 in double. */
static dvec hermite(dvec p0, dvec p1, dvec t0, dvec t1, double u)
{
    double u2 = u * u, u3 = u2 * u;
    double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return dadd(dadd(dscale(p0, h00), dscale(t0, h10)), dadd(dscale(p1, h01), dscale(t1, h11)));
}

/* Largest distance of a Hermite curve from the circle (centre ctr, unit
 * plane normal nrm, radius R), over 65 points. */
static double circle_deviation(dvec p0, dvec p1, dvec t0, dvec t1, dvec ctr, dvec nrm, double R)
{
    double dev = 0;
    for (int s = 0; s <= 64; s++) {
        dvec rel = dsub(hermite(p0, p1, t0, t1, s / 64.0), ctr);
        double off = ddot(rel, nrm);
        double d = hypot(dlen(dsub(rel, dscale(nrm, off))) - R, off);
        if (d > dev) dev = d;
    }
    return dev;
}

/* Eq. 4's purpose: a bridge between two points of a circle, with the
 * circle's normals, follows the arc.  Two bounds: the construction itself
 * (in double, from exact inputs) is the classic cubic arc, off by at most
 * 2.73e-4 R at 90 degrees, falling as the sixth power of the angle (1.1e-6 R
 * at 36 degrees);
 * and the fixed-point bridge is that good up to its inputs' rounding - a
 * normal rounded to Q16.16 turns the tangent by up to ~2^-16 rad, which
 * moves the curve by at most 4/27 of the tangent length times that angle. */
TEST(bridge_follows_circle)
{
    static const double radii[] = { 0.01, 0.3, 1, 25, 700 };
    /* up to 2 atan(1/4) = 56.1 degrees, where the bulge bound starts */
    static const double arcs[] = { 5, 20, 36, 48, 56 };
    double worst_excess = 0, worst_own[5] = { 0 };
    for (int ri = 0; ri < 5; ri++)
        for (int ai = 0; ai < 5; ai++)
            for (int k = 0; k < 40; k++) {
                double R = radii[ri], alpha = arcs[ai] * PI / 180;
                /* A random plane through a random centre. */
                dvec ctr = dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), 1024 - 1.5 * R);
                dvec ax = rand_unit(), ay = dnorm(dcross(ax, rand_unit()));
                ax = dnorm(dcross(ay, ax));
                dvec nrm = dcross(ax, ay);
                double a0 = check_uniform(0, 2 * PI);
                dvec r0 = dadd(dscale(ax, cos(a0)), dscale(ay, sin(a0)));
                dvec r1 = dadd(dscale(ax, cos(a0 + alpha)), dscale(ay, sin(a0 + alpha)));
                dvec v0 = dadd(ctr, dscale(r0, R)), v1 = dadd(ctr, dscale(r1, R));
                /* the construction in double, exact inputs */
                dvec e0, e1;
                double cond;
                ref_bridge(v0, r0, v1, r1, &e0, &e1, &cond);
                double own = circle_deviation(v0, v1, e0, e1, ctr, nrm, R);
                double own_bound = 2.75e-4 * pow(arcs[ai] / 90, 6) * R + 1e-12;
                if (own / R > worst_own[ai]) worst_own[ai] = own / R;
                CHECKF(own <= own_bound, "R %g arc %g: the double construction is off by %.3g R", R,
                       arcs[ai], own / R);
                /* the fixed-point bridge */
                silk_vec3 fn0 = fx3(r0), fn1 = fx3(r1);
                silk_curve cv;
                silk_bridge(fx3(v0), fn0, fx3(v1), fn1, 1, &cv);
                double dev = circle_deviation(dv(cv.p0), dv(cv.p1), dv(cv.t0), dv(cv.t1), ctr, nrm, R);
                double turn0 = dlen(dsub(dnorm(dv(fn0)), r0)), turn1 = dlen(dsub(dnorm(dv(fn1)), r1));
                double quant = 4.0 / 27 * (dlen(e0) * turn0 + dlen(e1) * turn1) + 4 * ULP;
                if (dev - own > worst_excess) worst_excess = dev - own;
                CHECKF(dev <= own + quant, "R %g arc %g: deviation %.3g (construction %.3g, rounding allowance %.3g)",
                       R, arcs[ai], dev, own, quant);
            }
    printf("  circle: construction off by %.2g %.2g %.2g %.2g %.2g R at 5 20 36 48 56 degrees;\n"
           "          fixed point adds at most %.2f ulp\n",
           worst_own[0], worst_own[1], worst_own[2], worst_own[3], worst_own[4], worst_excess / ULP);
}

/* Largest distance of a Hermite curve from its chord's line, over 129 points. */
static double chord_deviation(dvec p0, dvec p1, dvec t0, dvec t1)
{
    dvec e = dnorm(dsub(p1, p0));
    double dev = 0;
    for (int s = 0; s <= 128; s++) {
        dvec rel = dsub(hermite(p0, p1, t0, t1, s / 128.0), p0);
        double d = dlen(dsub(rel, dscale(e, ddot(rel, e))));
        if (d > dev) dev = d;
    }
    return dev;
}

/* The bulge bound (curve.h): every bridge and every arc tangent curve stays
 * within |chord| / 8 of the chord's line, whatever the normals - in double
 * from the reference construction, and in fixed point up to the rounding of
 * its tangents (4/27 of their error each, plus the end points').  A PN
 * triangle's edge curve over the same edge and normals (control points
 * p + (chord - (chord.n) n) / 3, Vlachos et al.) has the same bound, and
 * reaches it: the rule takes smooth mode's curves no further out than PN
 * triangles' may go.  Arcs of up to 56 degrees are untouched (see
 * bridge_follows_circle); a semicircle is flattened to |chord| / 8. */
TEST(bulge_bound)
{
    double worst_ref = 0, worst_fx = 0, worst_pn = 0;
    int bad = 0;
    for (int i = 0; i < 20000; i++) {
        dvec p0 = dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), 500);
        dvec c = dscale(rand_unit(), pow(2.0, check_uniform(-6, 9)));
        dvec p1 = dadd(p0, c);
        dvec n0 = rand_unit(), n1 = i % 2 ? rand_unit() : dnorm(dadd(n0, dscale(rand_unit(), 0.5)));
        silk_vec3 fp0 = fx3(p0), fp1 = fx3(p1), fn0 = fx3(n0), fn1 = fx3(n1);
        dvec c_fx = dsub(dv(fp1), dv(fp0));
        double lc = dlen(c_fx);
        if (lc == 0) continue;
        dvec t0, t1;
        double cond;
        ref_bridge(dv(fp0), dv(fn0), dv(fp1), dv(fn1), &t0, &t1, &cond);
        double dref = chord_deviation(dv(fp0), dv(fp1), t0, t1);
        silk_curve cv;
        silk_bridge(fp0, fn0, fp1, fn1, 1, &cv);
        double dfx = chord_deviation(dv(cv.p0), dv(cv.p1), dv(cv.t0), dv(cv.t1));
        double slack = 4.0 / 27 * (dlen(dsub(dv(cv.t0), t0)) + dlen(dsub(dv(cv.t1), t1))) + 2 * ULP;
        /* the PN edge curve as a Hermite curve: tangents 3 (b1 - p0), 3 (p1 - b2) */
        dvec m0 = dnorm(dv(fn0)), m1 = dnorm(dv(fn1));
        dvec pn0 = dsub(c_fx, dscale(m0, ddot(c_fx, m0))), pn1 = dsub(c_fx, dscale(m1, ddot(c_fx, m1)));
        double dpn = chord_deviation(dv(fp0), dv(fp1), pn0, pn1);
        if (dref / lc > worst_ref) worst_ref = dref / lc;
        if (dfx / lc > worst_fx) worst_fx = dfx / lc;
        if (dpn / lc > worst_pn) worst_pn = dpn / lc;
        if (dref > lc / 8 * (1 + 1e-12) || dfx > lc / 8 + slack || dpn > lc / 8 * (1 + 1e-12)) {
            if (bad++ < 5)
                CHECKF(0, "chord %g: deviations %.6g (double) %.6g (fixed) %.6g (PN) of the chord, bound 1/8", lc,
                       dref / lc, dfx / lc, dpn / lc);
        }
    }
    CHECKF(bad == 0, "%d curves beyond |chord| / 8", bad);
    CHECKF(worst_ref > 0.124 && worst_pn > 0.124, "the bound is reached: %.4f %.4f", worst_ref, worst_pn);
    /* feature curves: eq. 4 tangents from any directions */
    int bad_arc = 0;
    for (int i = 0; i < 20000; i++) {
        dvec c = dscale(rand_unit(), pow(2.0, check_uniform(-6, 9)));
        silk_vec3 fc = fx3(c);
        dvec cc = dv(fc);
        if (dlen(cc) == 0) continue;
        silk_vec3 ta = silk_arc_tangent(fx3(rand_unit()), fc), tb = silk_arc_tangent(fx3(rand_unit()), fc);
        double d = chord_deviation(dmk(0, 0, 0), cc, dv(ta), dv(tb));
        bad_arc += d > dlen(cc) / 8 + 4 * ULP;
    }
    CHECKF(bad_arc == 0, "%d feature curves beyond |chord| / 8", bad_arc);
    /* a semicircle (feature tangents at right angles to the chord) is
     * flattened to exactly |chord| / 8, from eq. 4's |chord| / 2 */
    silk_vec3 ch = silk_v3(2 * SILK_FX_ONE, 0, 0);
    silk_vec3 ta = silk_arc_tangent(silk_v3(0, SILK_FX_ONE, 0), ch), tb = silk_arc_tangent(silk_v3(0, -SILK_FX_ONE, 0), ch);
    double d = chord_deviation(dmk(0, 0, 0), dv(ch), dv(ta), dv(tb));
    CHECKF(fabs(d - 2.0 / 8) < 4 * ULP, "semicircle: %.9g", d);
    printf("  bulge: worst deviation / chord %.5f (double), %.5f (fixed point), PN edge curves %.5f; bound 0.125\n",
           worst_ref, worst_fx, worst_pn);
}

/* ---- eqs. 6-7 reference ----------------------------------------------------- */

/* Root of h(u) = A(1-u)^2 + B u(1-u) + C u^2 on [0,1] by bisection in long
 * double, with A, B, C exact (62-bit products, 64-bit sums). */
static long double ref_silhouette_u(silk_vec3 n0, silk_vec3 d0, silk_vec3 n1, silk_vec3 d1, long double *slope)
{
    long double A = (long double)n0.x * d0.x + (long double)n0.y * d0.y + (long double)n0.z * d0.z;
    long double C = (long double)n1.x * d1.x + (long double)n1.y * d1.y + (long double)n1.z * d1.z;
    long double B = (long double)n1.x * d0.x + (long double)n1.y * d0.y + (long double)n1.z * d0.z +
                    (long double)n0.x * d1.x + (long double)n0.y * d1.y + (long double)n0.z * d1.z;
    *slope = 0;
    if (A == 0) return 0;
    if (C == 0) return 1;
    if ((A < 0) == (C < 0)) return fabsl(A) <= fabsl(C) ? 0 : 1;
    long double lo = 0, hi = 1;
    for (int i = 0; i < 80; i++) {
        long double m = (lo + hi) / 2;
        long double h = A * (1 - m) * (1 - m) + B * m * (1 - m) + C * m * m;
        if ((h < 0) == (A < 0)) lo = m;
        else hi = m;
    }
    long double u = (lo + hi) / 2;
    /* |h'(u)| relative to the coefficients: how well the root is defined. */
    long double mx = fmaxl(fabsl(A), fmaxl(fabsl(B), fabsl(C)));
    *slope = fabsl(-2 * A * (1 - u) + B * (1 - 2 * u) + 2 * C * u) / mx;
    return u;
}

/* A view direction: towards an eye far away, close by, or parallel. */
static dvec rand_eye(dvec at, int kind)
{
    if (kind == 0) return dadd(at, dscale(rand_unit(), check_uniform(1.05, 4)));     /* close */
    if (kind == 1) return dadd(at, dscale(rand_unit(), check_uniform(4, 60)));       /* usual */
    return dadd(at, dscale(rand_unit(), check_uniform(1000, 16000)));               /* far */
}

/* Root error bound in ulps: half an ulp of rounding plus the coefficients'
 * reduction to 28 bits (2^-28 of the largest, moved by 1/h'), capped by
 * what an ill-conditioned root can be off anyway. */
static double param_bound(double slope) { return 0.5 + 1e-6 + 65536.0 * 0x1p-27 / fmax(slope, 1e-30); }

TEST(silhouette_param_random)
{
    double worst = 0, worst_wellcond = 0;
    int bad = 0, n = 0, ill = 0;
    while (n < N_RANDOM) {
        int kind = n % 6;
        dvec p0 = dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), check_uniform(1, 1000));
        dvec p1 = dadd(p0, dscale(rand_unit(), pow(2.0, check_uniform(-12, 4))));
        if (maxabs(p1) > 1024) continue;
        dvec n0 = rand_unit(), n1 = dnorm(dadd(n0, dscale(rand_unit(), check_uniform(0, 1.5))));
        dvec d0, d1;
        if (kind < 3) {
            dvec e = rand_eye(p0, kind);
            if (maxabs(e) > 32000) continue;
            d0 = dsub(e, p0);
            d1 = dsub(e, p1);
        } else {
            d0 = d1 = rand_unit();                        /* parallel projection */
        }
        if (kind == 4) {
            /* near-tangent: the silhouette just inside an end */
            dvec v = dnorm(d0);
            double eps = pow(10.0, check_uniform(-7, -2)) * (check_rand64() & 1 ? 1 : -1);
            n0 = dnorm(dadd(dsub(n0, dscale(v, ddot(n0, v))), dscale(v, eps)));
        }
        if (kind == 5) {
            /* h(u) = a (u - r0)(u - r1) with r0 in [0,1] and r1 just outside:
             * nearly a double root, the ill-conditioned case.  With n0 = x and
             * n1 = y, A = d0.x, C = d1.y and B = d0.y + d1.x set h freely. */
            double gap = pow(10.0, check_uniform(-7, -1));
            double r0 = 1 - gap * check_uniform(0, 1), r1 = 1 + gap * check_uniform(0, 1);
            if (check_rand64() & 1) { r0 = 1 - r0; r1 = 1 - r1; }
            double a = pow(2.0, check_uniform(-4, 12)) * (check_rand64() & 1 ? 1 : -1);
            double pc = a * r0 * r1, pb = -a * (r0 + r1), pa = a;
            double A = pc, C = pa + pb + pc, B = pb + 2 * pc;
            if (fmax(fabs(A), fmax(fabs(B), fabs(C))) > 30000) continue;
            n0 = dmk(1, 0, 0);
            n1 = dmk(0, 1, 0);
            d0 = dmk(A, B / 2, 0);
            d1 = dmk(B / 2, C, 0);
        }
        silk_vec3 fn0 = fx3(n0), fn1 = fx3(n1), fd0 = fx3(d0), fd1 = fx3(d1);
        long double slope;
        long double want = ref_silhouette_u(fn0, fd0, fn1, fd1, &slope);
        silk_fx got = silk_silhouette_param(fn0, fd0, fn1, fd1);
        double e = fabs((double)(got - want * 65536.0L));
        if (got < 0 || got > SILK_FX_ONE) e = 1e9;
        n++;
        if (e > worst) worst = e;
        if (slope > 0.01 && e > worst_wellcond) worst_wellcond = e;
        if (slope > 0 && slope < 0.01) ill++;
        double bound = slope > 0 ? param_bound((double)slope) : 0.5 + 1e-6;
        if (e > bound) {
            if (bad++ < 5)
                CHECKF(0, "kind %d: got %d want %.6Lf ulp (slope %.3Lg)", kind, got, want * 65536, slope);
        }
    }
    CHECKF(bad == 0, "%d of %d silhouette parameters beyond the bound", bad, n);
    CHECKF(worst_wellcond <= 1.0, "worst %.3f ulp where |h'| > 0.01 max coefficient", worst_wellcond);
    printf("  silhouette_param: worst %.3f ulp (%.3f ulp where well conditioned; %d ill-conditioned of %d)\n",
           worst, worst_wellcond, ill, n);
}

TEST(silhouette_param_special)
{
    silk_vec3 nx = silk_v3(SILK_FX_ONE, 0, 0), ny = silk_v3(0, SILK_FX_ONE, 0);
    silk_vec3 d = silk_v3(SILK_FX_ONE, SILK_FX_ONE, 0);
    silk_vec3 nmx = silk_v3(-SILK_FX_ONE, 0, 0);
    /* linear case (parallel projection, opposite normals): u = 1/2 */
    CHECK(silk_silhouette_param(nx, d, nmx, d) == SILK_FX_HALF);
    /* exactly zero at an end: that end */
    CHECK(silk_silhouette_param(silk_v3(0, 0, SILK_FX_ONE), d, nmx, d) == 0);
    CHECK(silk_silhouette_param(nx, d, silk_v3(0, 0, SILK_FX_ONE), d) == SILK_FX_ONE);
    CHECK(silk_silhouette_param(silk_v3(0, 0, SILK_FX_ONE), d, silk_v3(0, 0, -SILK_FX_ONE), d) == 0);
    /* same sign at both ends: the end nearer perpendicular */
    CHECK(silk_silhouette_param(nx, silk_v3(1, 0, 0), ny, d) == 0);
    CHECK(silk_silhouette_param(nx, d, ny, silk_v3(0, 5, 0)) == SILK_FX_ONE);
    CHECK(silk_silhouette_param(nmx, d, silk_v3(0, -2, 0), silk_v3(0, SILK_FX_ONE, 0)) == SILK_FX_ONE);
    /* 1-ulp changes of sign at the ends */
    silk_fx u = silk_silhouette_param(nx, silk_v3(-1, SILK_FX_ONE, 0), nx, silk_v3(1, SILK_FX_ONE, 0));
    CHECKF(u == SILK_FX_HALF, "%d", u);
    /* the root at 1 - 2^-20: rounds to one */
    u = silk_silhouette_param(nx, silk_v3(-((1 << 20) - 1), 0, 0), nx, silk_v3(1, 0, 0));
    CHECKF(u == SILK_FX_ONE, "%d", u);
    /* extreme magnitudes: no overflow, a result in [0,1] matching the reference */
    silk_vec3 big0 = silk_v3(SILK_FX_MAX, SILK_FX_MIN, SILK_FX_MAX), big1 = silk_v3(SILK_FX_MIN, SILK_FX_MAX, SILK_FX_MIN);
    silk_vec3 m0 = silk_v3(INT32_MIN, INT32_MIN, 0), m1 = silk_v3(SILK_FX_MAX, SILK_FX_MAX, 7);
    long double slope;
    long double want = ref_silhouette_u(m0, big0, m1, big1, &slope);
    u = silk_silhouette_param(m0, big0, m1, big1);
    CHECKF(fabsl(u - want * 65536) <= param_bound((double)slope), "%d vs %Lf", u, want * 65536);
    /* the two orientations of an edge agree: u and 1 - u */
    int asym = 0;
    for (int i = 0; i < 20000; i++) {
        dvec p0 = rand_unit(), p1 = dadd(p0, dscale(rand_unit(), 0.3));
        dvec e = rand_eye(p0, i % 3);
        silk_vec3 a = fx3(rand_unit()), b = fx3(rand_unit());
        silk_vec3 da = fx3(dsub(e, p0)), db = fx3(dsub(e, p1));
        silk_fx f = silk_silhouette_param(a, da, b, db), g = silk_silhouette_param(b, db, a, da);
        if (abs(f + g - SILK_FX_ONE) > 1) asym++;
    }
    CHECKF(asym == 0, "%d edges where the two orientations differ by more than 1 ulp", asym);
}

/* The silhouette parameter of a bridge on a sphere against the true
 * silhouette: the contour circle where the sphere's normal is perpendicular
 * to the view direction.  The error is the distance on the sphere from the
 * point S(u) (projected radially) to the contour, relative to the edge:
 * eq. 6's linear normal and eq. 7's linear view direction make S(u) an
 * approximation, tiny in parallel projection and larger with the eye close.
 * (Along the bridge the error can look larger where the edge runs nearly
 * along the contour, but there every point of the edge is near it.) */
TEST(silhouette_on_sphere)
{
    double worst[2] = { 0, 0 }, worst_far = 0;
    int n = 0;
    while (n < 20000) {
        double R = pow(10.0, check_uniform(-1, 2));
        dvec ctr = dscale(rand_unit(), check_uniform(0, 1000 - 12 * R));
        int persp = n % 2, near = n % 4 < 2;
        dvec view = rand_unit();                           /* direction towards the eye */
        double dist = R * (near ? check_uniform(1.5, 4) : check_uniform(4, 10));
        dvec eye = dadd(ctr, dscale(view, dist));
        /* two points on the sphere on either side of the silhouette, an edge
         * of up to 36 degrees as on the 10-segment UV sphere */
        double ang = check_uniform(2, 36) * PI / 180;
        dvec q0 = rand_unit();
        dvec axis = dnorm(dcross(q0, rand_unit()));
        dvec q1 = dadd(dscale(q0, cos(ang)), dscale(dcross(axis, q0), sin(ang)));
        dvec v0 = dadd(ctr, dscale(q0, R)), v1 = dadd(ctr, dscale(q1, R));
        dvec dd0 = persp ? dsub(eye, v0) : view, dd1 = persp ? dsub(eye, v1) : view;
        if ((ddot(q0, dd0) < 0) == (ddot(q1, dd1) < 0)) continue;   /* not across the silhouette */
        silk_vec3 fn0 = fx3(q0), fn1 = fx3(q1);
        silk_curve cv;
        silk_bridge(fx3(v0), fn0, fx3(v1), fn1, 1, &cv);
        silk_fx u = silk_silhouette_param(fn0, fx3(dd0), fn1, fx3(dd1));
        dvec S = hermite(dv(cv.p0), dv(cv.p1), dv(cv.t0), dv(cv.t1), fx2d(u));
        double contour = persp ? acos(R / dist) : PI / 2;          /* angle from the view axis */
        double at = acos(fmax(-1, fmin(1, ddot(dnorm(dsub(S, ctr)), view))));
        double err = R * fabs(at - contour) / (R * ang);
        n++;
        if (err > worst[persp]) worst[persp] = err;
        if (persp && !near && err > worst_far) worst_far = err;
    }
    /* measured: 0.0057 (parallel), 0.0095 (perspective, eye 4-10 radii
     * away), 0.043 (eye 1.5-4 radii away) of the edge length */
    CHECKF(worst[0] <= 0.01, "parallel: %.4f of the edge", worst[0]);
    CHECKF(worst[1] <= 0.1, "perspective: %.4f of the edge", worst[1]);
    printf("  sphere silhouette point: off the contour by at most %.4f (parallel), %.4f (perspective; %.4f with the eye\n"
           "  4-10 radii from the centre) of the edge length, %d edges\n", worst[0], worst[1], worst_far, n);
}

/* Small change of eye, small change of u: sweep the eye along a line in
 * tiny steps and compare each step of u with the reference's step. */
TEST(silhouette_param_continuity)
{
    double worst = 0;
    int bad = 0;
    for (int trial = 0; trial < 200; trial++) {
        dvec p0 = dscale(rand_unit(), check_uniform(0, 500)), p1 = dadd(p0, dscale(rand_unit(), check_uniform(0.01, 3)));
        dvec n0 = rand_unit(), n1 = dnorm(dadd(n0, dscale(rand_unit(), check_uniform(0.2, 1.5))));
        silk_vec3 fn0 = fx3(n0), fn1 = fx3(n1), fp0 = fx3(p0), fp1 = fx3(p1);
        dvec e0 = dadd(p0, dscale(rand_unit(), check_uniform(2, 50)));
        dvec step = dscale(rand_unit(), 1e-3 * dlen(dsub(e0, p0)));
        long double prev_want = -1, slope;
        silk_fx prev_got = -1;
        for (int k = 0; k < 400; k++) {
            silk_vec3 fe = fx3(dadd(e0, dscale(step, k)));
            silk_vec3 d0 = silk_v3_sub(fe, fp0), d1 = silk_v3_sub(fe, fp1);
            long double want = ref_silhouette_u(fn0, d0, fn1, d1, &slope);
            silk_fx got = silk_silhouette_param(fn0, d0, fn1, d1);
            int crossing = slope > 0;                 /* a silhouette on this edge */
            if (crossing && prev_got >= 0 && prev_want >= 0) {
                double dgot = got - prev_got, dwant = (double)((want - prev_want) * 65536);
                double e = fabs(dgot - dwant);
                if (e > worst) worst = e;
                if (e > 2 * param_bound((double)slope) && bad++ < 5)
                    CHECKF(0, "trial %d step %d: u moved %.1f ulp, reference %.1f", trial, k, dgot, dwant);
            }
            prev_got = crossing ? got : -1;
            prev_want = crossing ? want : -1;
        }
    }
    CHECK(bad == 0);
    printf("  continuity: worst step difference %.3f ulp\n", worst);
}

/* ---- eq. 8 ------------------------------------------------------------------ */

TEST(sample_count_random)
{
    int bad = 0, near_boundary = 0, capped = 0;
    for (int i = 0; i < N_RANDOM; i++) {
        silk_fx h = (i % 4 == 0) ? (silk_fx)(check_rand64() % (uint64_t)SILK_FX_MAX) + 1
                                 : fx(pow(2.0, check_uniform(-10, 10)));
        silk_fx c = fx(check_uniform(-1, 1));
        if (i % 3 == 0) c = fx(1 - pow(10.0, check_uniform(-4.8, 0)));  /* nearly flat */
        silk_fx e = fx(check_uniform(0.25, 4));
        double r = sqrt((1 - fx2d(c)) / 2);
        double x = sqrt(fx2d(h) * r / fx2d(e)) / 2;
        double want = ceil(x);
        if (want < 1) want = 1;
        if (want > SILK_MAX_SAMPLES) { want = SILK_MAX_SAMPLES; capped++; }
        uint32_t got = silk_sample_count(h, c, e);
        if ((double)got != want) {
            /* r is rounded to 24 bits: only a value within 1e-6 of an integer may go either way */
            if (fabs(x - floor(x + 0.5)) < 1e-6 * x + 1e-9) { near_boundary++; continue; }
            if (bad++ < 5) CHECKF(0, "h %g cos %g e %g: got %u want %g (x %.9g)", fx2d(h), fx2d(c), fx2d(e), got, want, x);
        }
    }
    CHECKF(bad == 0, "%d wrong sample counts", bad);
    CHECK(capped > 1000);
    printf("  sample_count: exact on %d inputs (%d within 1e-6 of a step, %d capped)\n", N_RANDOM, near_boundary, capped);
}

TEST(sample_count_special)
{
    silk_fx one = SILK_FX_ONE;
    CHECK(silk_sample_count(0, 0, one) == 1);
    CHECK(silk_sample_count(-5, 0, one) == 1);
    CHECK(silk_sample_count(100 * one, one, one) == 1);             /* straight: no curvature */
    CHECK(silk_sample_count(100 * one, 2 * one, one) == 1);         /* cos clamped */
    CHECK(silk_sample_count(100 * one, 0, 0) == SILK_MAX_SAMPLES);  /* no tolerance */
    CHECK(silk_sample_count(100 * one, 0, -one) == SILK_MAX_SAMPLES);
    CHECK(silk_sample_count(SILK_FX_MAX, -one, 1) == SILK_MAX_SAMPLES);
    /* exact steps: h r / e = 4 n^2 gives n, a hair more gives n + 1.  cos = -1
     * makes r = 1. */
    CHECK(silk_sample_count(16 * one, -one, one) == 2);
    CHECK(silk_sample_count(16 * one + 1, -one, one) == 3);
    CHECK(silk_sample_count(4 * one, -one, one) == 1);
    CHECK(silk_sample_count(4 * one + 1, -one, one) == 2);
    /* cos = 0: r = sqrt(1/2); h = 8 sqrt 2 ~ 11.3137 gives h r = 8 -> sqrt(8)/2 = 1.41 -> 2 */
    CHECK(silk_sample_count(fx(8 * sqrt(2.0)), 0, one) == 2);
    /* the paper's range of e: 0.5 .. 2 px, a 100 px-high segment over a
     * 36-degree arc */
    double r = sin(18 * PI / 180);
    CHECK(silk_sample_count(100 * one, fx(cos(36 * PI / 180)), one / 2) == (uint32_t)ceil(sqrt(100 * r / 0.5) / 2));
    CHECK(silk_sample_count(100 * one, fx(cos(36 * PI / 180)), 2 * one) == (uint32_t)ceil(sqrt(100 * r / 2) / 2));
}

/* The tilt bound (curve.h): a straight edge whose normal leans along it at
 * one end only - a vertex normal averaged across a rounded-off crease, as
 * at the corners of a wing nut's rim - gives a nearly straight bridge: the
 * lean is cut to the other end's (none) plus 1/16, so the curve stays
 * within (4/27) |chord| / 16 < |chord| / 96 of its chord, where eqs. 2-4
 * alone bow it out by up to 6% of its length at a 24-degree lean.  Without
 * the bound (normals from a file) a bridge is eqs. 2-4's.  Circular
 * arcs, whose ends lean alike, keep their tangents (bridge_follows_circle). */
TEST(tilt_bound)
{
    int bad = 0, bad_free = 0;
    double worst = 0, worst_free = 0;
    for (int i = 0; i < 20000; i++) {
        dvec p0 = dscale(dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1)), 500);
        dvec c = dscale(rand_unit(), pow(2.0, check_uniform(-4, 8)));
        dvec e = dnorm(c), side = dnorm(dcross(e, rand_unit()));
        double lean = check_uniform(5, 60) * PI / 180 * (i % 2 ? 1 : -1);
        dvec n0 = side, n1 = dadd(dscale(side, cos(lean)), dscale(e, sin(lean)));
        silk_vec3 fp0 = fx3(p0), fp1 = fx3(dadd(p0, c));
        double lc = dlen(dsub(dv(fp1), dv(fp0)));
        silk_curve cv;
        silk_bridge(fp0, fx3(n0), fp1, fx3(n1), 1, &cv);
        double d = chord_deviation(dv(cv.p0), dv(cv.p1), dv(cv.t0), dv(cv.t1)) / lc;
        /* eqs. 2-4 and the bulge bound without the tilt bound, for the record */
        dvec a = dsub(c, dscale(n1, ddot(c, n1)));
        double free_dev = chord_deviation(dmk(0, 0, 0), c, ref_arc_tangent(c, c), ref_arc_tangent(a, c)) / dlen(c);
        if (d > worst) worst = d;
        if (free_dev > worst_free) worst_free = free_dev;
        /* normals from a file are taken as they are: eqs. 2-4 alone */
        silk_curve cf;
        silk_bridge(fp0, fx3(n0), fp1, fx3(n1), 0, &cf);
        double df = chord_deviation(dv(cf.p0), dv(cf.p1), dv(cf.t0), dv(cf.t1)) / lc;
        if (fabs(df - free_dev) > 1e-3 + 16 * ULP / lc && bad_free++ < 5)
            CHECKF(0, "chord %g, lean %.1f degrees, no tilt bound: %.4g of the chord, eqs. 2-4 give %.4g", lc,
                   lean * 180 / PI, df, free_dev);
        if (d > 1.0 / 96 + 8 * ULP / lc && bad++ < 5)
            CHECKF(0, "chord %g, lean %.1f degrees: the curve leaves its chord by %.4g of its length", lc,
                   lean * 180 / PI, d);
    }
    CHECKF(bad == 0, "%d one-sided bridges bow out more than |chord| / 96", bad);
    CHECKF(bad_free == 0, "%d bridges without the bound differ from eqs. 2-4", bad_free);
    CHECKF(worst_free > 0.05, "without the bound they would: %.4f", worst_free);
    printf("  tilt bound: one-sided leans of 5-60 degrees bow a bridge out by at most %.4f of its chord "
           "(%.4f without the bound)\n", worst, worst_free);
}

int main(void)
{
    RUN(arc_tangent_random);
    RUN(arc_tangent_special);
    RUN(bridge_random);
    RUN(bridge_special);
    RUN(bridge_follows_circle);
    RUN(bulge_bound);
    RUN(tilt_bound);
    RUN(silhouette_param_random);
    RUN(silhouette_param_special);
    RUN(silhouette_on_sphere);
    RUN(silhouette_param_continuity);
    RUN(sample_count_random);
    RUN(sample_count_special);
    return check_done();
}
