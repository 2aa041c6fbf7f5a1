/*
 * test_aa.c - anti-aliased outlines (src/aa.c): the alpha channel of a
 * frame drawn with an alpha plane (a PNG with --bg none) against the exact
 * coverage of the analytic surface the coarse mesh samples.
 *
 * The sphere (radius 1, 200 triangles) and the torus (R = 1, r = 0.4, 576
 * triangles) of `silk gen`'s defaults are drawn at 256x256 from 8 views
 * (4 directions, perspective and orthographic; 2 under SILK_SAN=1), in SMOOTH mode (and FLAT, reported).
 * The exact coverage of each pixel is the fraction of 16 x 16 sub-sample
 * rays (tests/support/exact_silhouette.c, double precision) that meet the
 * analytic surface.  Reported over the pixels whose exact coverage is
 * strictly between 0 and 1 (edge pixels): mean and largest |alpha / 255 -
 * coverage|, their signed mean (the outline's bias), and how many other
 * pixels are not 0 or 255 as the exact coverage says; for smooth and flat,
 * anti-aliasing on and off, and smooth at a finer sampling tolerance.
 *
 * Checked for smooth mode with anti-aliasing, against the analytic
 * surface: mean error over the edge pixels <= MEAN_BOUND over all views;
 * no edge pixel off by more than MAX_BOUND; and every other pixel 0 or 255
 * as the exact coverage says.  Flat mode, --aa off and a finer sampling
 * tolerance are printed for comparison.  SILK_AA_DUMP=DIR writes each
 * smooth anti-aliased view as DIR/SHAPE-VIEW.ppm (red: alpha, green: the
 * exact coverage) and lists the pixels that miss.
 *
 * On real meshes (../shared/meshes, 6 views each) the anti-aliased frame
 * against the same frame drawn without (--aa off): no pixel drawn covered
 * is left under half covered, and no pixel whose 8 neighbours are drawn as
 * it is changes (SILK_AA_DUMP lists those).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "../tools/prep/gen.h"
#include "support/exact_silhouette.h"
#include "support/testmesh.h"
#include "support/testframe.h"

#define W 256
#define H 256
#define SUBS 16
#define MEAN_BOUND 0.08
#define MAX_BOUND 0.5

typedef struct aa_stats {
    long edge, edge_far, whole, whole_wrong;   /* pixels: exact coverage in (0, 1), those off by > MAX_BOUND; 0 or 1; those not 0/255 as it says */
    double sum, bias, max, whole_max; /* |alpha - coverage| (and signed) over edge pixels; over the wrong whole ones */
} aa_stats;

static int gen_mesh_fixture(tm_fixture *f, gen_shape s)
{
    gen_params p;
    gen_mesh gm;
    gen_defaults(s, &p);
    if (gen_build(&p, &gm) != 0) return 0;
    int ok = tm_fixture_input(f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(f) == SILK_OK;
    gen_free(&gm);
    return ok;
}

/* Exact coverage of every pixel, 0 .. SUBS * SUBS (that is, 0 .. 256). */
static void exact_coverage(const silk_view *v, const es_shape *s, uint16_t *cov)
{
    es_camera c;
    es_camera_from_silk(&c, &v->cam);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int n = 0;
            for (int j = 0; j < SUBS; j++)
                for (int i = 0; i < SUBS; i++) n += es_hit(&c, s, x + (i + 0.5) / SUBS, y + (j + 0.5) / SUBS);
            cov[y * W + x] = (uint16_t)n;
        }
}

/* The frame at w x h (at most 4W x 4H) into rgb and alpha. */
static int draw(tm_fixture *f, const silk_view *v, silk_mode mode, int aa, silk_fx tol, int w, int h, uint8_t *rgb,
                uint8_t *alpha)
{
    static uint32_t depth[16 * W * H];
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.mode = mode;
    o.aa = aa;
    if (tol) o.tolerance_px = tol;
    silk_target t;
    silk_target_init(&t, w, h, 0, h, SILK_PIX_RGB888, rgb, depth);
    t.alpha = alpha;
    silk_frame_stats st;
    silk_error err;
    return silk_render(&f->a, &f->m, v, &hal, &o, &t, &st, &err) == SILK_OK && !st.fell_back;
}

static int draw_alpha(tm_fixture *f, const silk_view *v, silk_mode mode, int aa, silk_fx tol, uint8_t *alpha)
{
    static uint8_t rgb[W * H * 3];
    return draw(f, v, mode, aa, tol, W, H, rgb, alpha);
}

static void compare(const uint16_t *cov, const uint8_t *alpha, aa_stats *s)
{
    for (int i = 0; i < W * H; i++) {
        double c = cov[i] / (double)(SUBS * SUBS), e = fabs(alpha[i] / 255.0 - c);
        if (cov[i] > 0 && cov[i] < SUBS * SUBS) {
            s->edge++;
            s->sum += e;
            s->bias += alpha[i] / 255.0 - c;
            if (e > s->max) s->max = e;
            s->edge_far += e > MAX_BOUND;
        } else {
            s->whole++;
            if (alpha[i] != (cov[i] ? 255 : 0)) {
                s->whole_wrong++;
                if (e > s->whole_max) s->whole_max = e;
            }
        }
    }
}

/* SILK_AA_DUMP (see the top): one view's picture and the pixels that miss. */
static void dump(const char *name, int view, const uint16_t *cov, const uint8_t *alpha)
{
    const char *dir = getenv("SILK_AA_DUMP");
    if (!dir) return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s-%d.ppm", dir, name, view);
    FILE *fp = fopen(path, "wb");
    if (!fp) return;
    fprintf(fp, "P6 %d %d 255\n", W, H);
    for (int i = 0; i < W * H; i++) {
        int c = cov[i] * 255 / (SUBS * SUBS);
        fputc(alpha[i], fp), fputc(c > 255 ? 255 : c, fp), fputc(0, fp);
        double e = fabs(alpha[i] / 255.0 - cov[i] / (double)(SUBS * SUBS));
        int whole = cov[i] == 0 || cov[i] == SUBS * SUBS;
        if (e > MAX_BOUND || (whole && alpha[i] != (cov[i] ? 255 : 0)))
            printf("%s view %d: (%d, %d) alpha %.3f exact %.3f%s\n", name, view, i % W, i / W, alpha[i] / 255.0,
                   cov[i] / (double)(SUBS * SUBS), whole ? " whole" : "");
    }
    fclose(fp);
}

static void report(const char *what, const aa_stats *s)
{
    printf("  %-26s edge pixels %5ld: mean error %.4f (signed %+.4f), max %.3f, %ld off by > %.1f; whole pixels: "
           "%ld not 0/255 as exact (max error %.3f)\n",
           what, s->edge, s->edge ? s->sum / s->edge : 0, s->edge ? s->bias / s->edge : 0, s->max, s->edge_far,
           MAX_BOUND, s->whole_wrong, s->whole_max);
}

TEST(alpha_is_coverage)
{
    static uint16_t cov[W * H];
    static uint8_t alpha[W * H];
    const double dirs[][3] = { { 0.3, 0.4, 1 }, { 1, 0.1, 0.2 }, { -0.5, 1, 0.6 }, { 0.1, -0.3, -1 } };
    const gen_shape shapes[] = { GEN_SPHERE, GEN_TORUS };
    /* under sanitizers (SILK_SAN=1) one direction, two views */
    size_t ndirs = getenv("SILK_SAN") ? 1 : sizeof dirs / sizeof dirs[0];
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        tm_fixture f;
        tm_fixture_init(&f, 16u << 20);
        if (!gen_mesh_fixture(&f, shapes[k])) {
            CHECK(0);
            tm_fixture_free(&f);
            continue;
        }
        const char *name = gen_shape_name(shapes[k]);
        es_shape exact = shapes[k] == GEN_SPHERE ? es_sphere(0, 0, 0, 1) : es_torus(0, 0, 0, 0, 1, 0, 1.0, 0.4);
        /* [mode][aa] */
        aa_stats an[2][2], fine = { 0 };
        memset(an, 0, sizeof an);
        for (size_t d = 0; d < ndirs; d++)
            for (int ortho = 0; ortho < 2; ortho++) {
                silk_view v;
                if (!tf_view_around_size(&f.m, dirs[d], 3, ortho, W, H, &v)) {
                    CHECK(0);
                    continue;
                }
                exact_coverage(&v, &exact, cov);
                CHECK(draw_alpha(&f, &v, SILK_MODE_SMOOTH, 1, SILK_FX_ONE / 4, alpha));
                compare(cov, alpha, &fine);
                for (int smooth = 0; smooth < 2; smooth++) {
                    silk_mode mode = smooth ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                    for (int aa = 0; aa < 2; aa++) {
                        CHECK(draw_alpha(&f, &v, mode, aa, 0, alpha));
                        compare(cov, alpha, &an[smooth][aa]);
                        if (smooth && aa) dump(name, (int)(2 * d) + ortho, cov, alpha);
                    }
                }
            }
        printf("%s, %zu views at %dx%d, alpha against the analytic surface (%dx%d rays per pixel):\n", name,
               2 * ndirs, W, H, SUBS, SUBS);
        const char *what[2][2] = { { "flat, aa off", "flat, aa on" }, { "smooth, aa off", "smooth, aa on" } };
        for (int m = 1; m >= 0; m--)
            for (int aa = 1; aa >= 0; aa--) report(what[m][aa], &an[m][aa]);
        report("smooth, aa on, tol 0.25 px", &fine);
        const aa_stats *on = &an[1][1], *off = &an[1][0];
        CHECKF(on->sum / on->edge <= MEAN_BOUND, "%s smooth: mean error %.4f with aa (%.4f without)", name,
               on->sum / on->edge, off->sum / off->edge);
        CHECKF(on->max <= MAX_BOUND && !on->edge_far, "%s smooth: %ld edge pixels off by more than %.1f, the worst "
               "by %.3f (%.3f without anti-aliasing)", name, on->edge_far, MAX_BOUND, on->max, off->max);
        CHECKF(!on->whole_wrong, "%s smooth: %ld pixels not 0/255 as the exact coverage says, the worst off by %.3f",
               name, on->whole_wrong, on->whole_max);
        tm_fixture_free(&f);
    }
}

/* The drawn geometry (--aa off) against the anti-aliased frame on real
 * meshes: a pixel drawn covered keeps at least half coverage (straight
 * sides are the drawn outline; a curve may thin such a pixel to half, no
 * more, so no pixel is emptied where the curve lies inside the geometry
 * drawn), and only the pixels next to the drawn outline change: one whose
 * 8 neighbours are drawn as it is keeps its value. */
TEST(drawn_outline_kept)
{
    static uint8_t on[W * H], off[W * H];
    static const char *const names[] = { "bunny-500", "armadillo-500", "dragon-500", "knot-480", "spot-500" };
    const double dirs[][3] = { { 0.3, 0.4, 1 }, { 1, 0.1, 0.2 }, { -0.5, 1, 0.6 } };
    size_t nnames = getenv("SILK_SAN") ? 1 : sizeof names / sizeof names[0];
    long thinned = 0, inner = 0, drawn = 0, lowest = 255;
    for (size_t k = 0; k < nnames; k++) {
        tm_fixture f;
        tm_fixture_init(&f, 32u << 20);
        if (!tm_fixture_read_shared(&f, names[k]) || tm_fixture_build(&f) != SILK_OK) {
            CHECKF(0, "cannot read %s", names[k]);
            tm_fixture_free(&f);
            continue;
        }
        for (size_t d = 0; d < sizeof dirs / sizeof dirs[0]; d++)
            for (int ortho = 0; ortho < 2; ortho++) {
                silk_view v;
                CHECK(tf_view_around_size(&f.m, dirs[d], 2.5, ortho, W, H, &v));
                CHECK(draw_alpha(&f, &v, SILK_MODE_SMOOTH, 1, 0, on));
                CHECK(draw_alpha(&f, &v, SILK_MODE_SMOOTH, 0, 0, off));
                for (int y = 0; y < H; y++)
                    for (int x = 0; x < W; x++) {
                        int i = y * W + x, same = 1;
                        for (int j = -1; j <= 1; j++)
                            for (int l = -1; l <= 1; l++)
                                if (y + j >= 0 && y + j < H && x + l >= 0 && x + l < W)
                                    same &= off[(y + j) * W + x + l] == off[i];
                        if (off[i]) {
                            drawn++;
                            if (on[i] < lowest) lowest = on[i];
                        }
                        thinned += off[i] && on[i] < 127;
                        if (same && on[i] != off[i]) {
                            inner++;
                            if (getenv("SILK_AA_DUMP"))
                                printf("%s view %zu: (%d, %d) alpha %d, drawn %d with its 8 neighbours\n", names[k],
                                       2 * d + (size_t)ortho, x, y, on[i], off[i]);
                        }
                    }
            }
        tm_fixture_free(&f);
    }
    printf("%zu meshes, 6 views each at %dx%d: %ld pixels drawn covered, the least alpha any keeps %ld; "
           "%ld under half; %ld changed among drawn neighbours\n", nnames, W, H, drawn, lowest, thinned, inner);
    CHECKF(!thinned, "%ld pixels drawn covered left under half covered (the least alpha %ld)", thinned, lowest);
    CHECKF(!inner, "%ld pixels changed whose 8 neighbours are drawn as they are", inner);
}

/* Creases: a cylinder's rims between its caps and its side, in SMOOTH
 * mode, against the same view drawn 4 x 4 times larger and averaged (what
 * `silk render --ssaa 4` draws).  The rim pixels are those whose 5 x 5
 * neighbourhood, drawn without anti-aliasing, is all surface and holds two
 * colours further apart than 40 in a channel.  Checked: every pixel the
 * anti-aliasing changes there lies, channel by channel, between the
 * colours of its 3 x 3 neighbourhood as drawn (a blend of the two faces);
 * the mean error along the rim is at most CREASE_BOUND, and below that of
 * the frame without anti-aliasing. */
#define CREASE_BOUND 2.0
TEST(crease_blends_faces)
{
    static uint8_t on[W * H * 3], off[W * H * 3], big[16 * W * H * 3], alpha[16 * W * H];
    const double dirs[][3] = { { 0.1, 1, 0.45 }, { 0.6, 1, -0.3 }, { 0.3, -1, 0.7 } };
    tm_fixture f;
    tm_fixture_init(&f, 32u << 20);
    if (!gen_mesh_fixture(&f, GEN_CYLINDER)) {
        CHECK(0);
        tm_fixture_free(&f);
        return;
    }
    long rim = 0, changed = 0, outside = 0;
    double err_on = 0, err_off = 0;
    for (size_t d = 0; d < sizeof dirs / sizeof dirs[0]; d++) {
        silk_view v, vb;
        CHECK(tf_view_around_size(&f.m, dirs[d], 3, 0, W, H, &v));
        CHECK(tf_view_around_size(&f.m, dirs[d], 3, 0, 4 * W, 4 * H, &vb));
        CHECK(draw(&f, &v, SILK_MODE_SMOOTH, 1, 0, W, H, on, alpha));
        CHECK(draw(&f, &v, SILK_MODE_SMOOTH, 0, 0, W, H, off, alpha));
        static uint8_t covered[W * H];
        for (int i = 0; i < W * H; i++) covered[i] = alpha[i] != 0;
        CHECK(draw(&f, &vb, SILK_MODE_SMOOTH, 0, 0, 4 * W, 4 * H, big, alpha));
        for (int y = 2; y < H - 2; y++)
            for (int x = 2; x < W - 2; x++) {
                int all = 1, lo[3] = { 255, 255, 255 }, hi[3] = { 0, 0, 0 }, jump = 0;
                for (int j = -2; j <= 2; j++)
                    for (int l = -2; l <= 2; l++) {
                        const uint8_t *q = &off[((y + j) * W + x + l) * 3];
                        all &= covered[(y + j) * W + x + l];
                        for (int c = 0; c < 3; c++)
                            if (j * j <= 1 && l * l <= 1) {
                                if (q[c] < lo[c]) lo[c] = q[c];
                                if (q[c] > hi[c]) hi[c] = q[c];
                            }
                    }
                for (int j = -2; all && j <= 2; j++)
                    for (int l = -2; l <= 2; l++)
                        for (int c = 0; c < 3; c++) {
                            int a = off[((y + j) * W + x + l) * 3 + c], b = off[(y * W + x) * 3 + c];
                            jump |= abs(a - b) > 40;
                        }
                if (!all || !jump) continue;
                rim++;
                const uint8_t *p = &on[(y * W + x) * 3], *q = &off[(y * W + x) * 3];
                changed += memcmp(p, q, 3) != 0;
                for (int c = 0; c < 3; c++) {
                    int sum = 0;
                    for (int j = 0; j < 4; j++)
                        for (int l = 0; l < 4; l++) sum += big[((4 * y + j) * 4 * W + 4 * x + l) * 3 + c];
                    double ref = sum / 16.0;
                    err_on += fabs(p[c] - ref) / 3;
                    err_off += fabs(q[c] - ref) / 3;
                    outside += p[c] < lo[c] || p[c] > hi[c];
                }
            }
    }
    tm_fixture_free(&f);
    printf("cylinder, %zu views at %dx%d: %ld rim pixels, %ld changed; mean error against 4x4 supersampling "
           "%.2f (%.2f without anti-aliasing); %ld channels outside their neighbours' range\n",
           sizeof dirs / sizeof dirs[0], W, H, rim, changed, err_on / (rim ? rim : 1), err_off / (rim ? rim : 1),
           outside);
    CHECK(rim > 0 && changed > 0);
    CHECKF(!outside, "%ld rim channels outside the colours of their 3 x 3 neighbourhood", outside);
    CHECKF(err_on / rim <= CREASE_BOUND && err_on < err_off, "rim mean error %.2f with aa, %.2f without",
           err_on / rim, err_off / rim);
}

int main(void)
{
    RUN(alpha_is_coverage);
    RUN(drawn_outline_kept);
    RUN(crease_blends_faces);
    return check_done();
}
