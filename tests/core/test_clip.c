/*
 * test_clip.c - clip mode's stencil and anti-aliased outline (src/clip.c,
 * paper sections 8.1 and 8.3) against a double-precision reference written
 * here: for polygons made of disjoint convex loops (as the interpolated
 * outline is), the pixel-centre stencil equals the parity rule evaluated in
 * double at every centre not within 1e-3 px of an edge, and the coverage
 * blended into each pixel is within 0.25 of the exact area of the polygon
 * inside the pixel (Sutherland-Hodgman clipping in double; four sub-scan-
 * lines misjudge a horizontal edge inside a pixel by up to 1/8 of it, and a
 * pixel may hold two); fully covered pixels keep exactly what was drawn,
 * untouched ones the background.
 * Bands of any height give the bytes of the whole frame.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "src/clip.h"

#define W 64
#define H 48
#define NLOOPS 12

/* Disjoint convex quadrilaterals: loop k lies in rows [4k - 1, 4k + 3)
 * (some reaching outside the frame), its sides slanted at random. */
static void make_loops(unsigned seed, double pts[NLOOPS][4][2])
{
    srand(seed);
    for (int k = 0; k < NLOOPS; k++) {
        double y0 = 4.0 * k - 1 + 0.37 * rand() / RAND_MAX, y1 = 4.0 * k + 2.9 - 0.41 * rand() / RAND_MAX;
        double xl0 = -5 + 40.0 * rand() / RAND_MAX, xl1 = xl0 + 10.0 * rand() / RAND_MAX - 5;
        double xr0 = xl0 + 0.3 + 30.0 * rand() / RAND_MAX, xr1 = xl1 + 0.3 + 35.0 * rand() / RAND_MAX;
        double q[4][2] = { { xl0, y0 }, { xr0, y0 }, { xr1, y1 }, { xl1, y1 } };
        memcpy(pts[k], q, sizeof q);
    }
}

static int inside(double p[NLOOPS][4][2], double x, double y, double *near)
{
    int in = 0;
    *near = 1e9;
    for (int k = 0; k < NLOOPS; k++)
        for (int i = 0; i < 4; i++) {
            double *a = p[k][i], *b = p[k][(i + 1) % 4];
            double dx = b[0] - a[0], dy = b[1] - a[1], len = sqrt(dx * dx + dy * dy);
            double t = ((x - a[0]) * dx + (y - a[1]) * dy) / (len * len);
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double d = hypot(x - a[0] - t * dx, y - a[1] - t * dy);
            if (d < *near) *near = d;
            if ((a[1] <= y) != (b[1] <= y) && x < a[0] + (y - a[1]) * dx / dy) in = !in;
        }
    return in;
}

/* Area of convex polygon q (n points) inside the unit pixel at (px, py). */
static double clipped_area(double q[4][2], int px, int py)
{
    double buf[2][16][2];
    int n = 4;
    memcpy(buf[0], q, 4 * sizeof q[0]);
    double lim[4] = { px, px + 1, py, py + 1 };
    int cur = 0;
    for (int side = 0; side < 4; side++) {
        int axis = side / 2, keep_ge = side % 2 == 0, m = 0;
        double (*in)[2] = buf[cur], (*out)[2] = buf[1 - cur];
        for (int i = 0; i < n; i++) {
            double *a = in[i], *b = in[(i + 1) % n];
            int ia = keep_ge ? a[axis] >= lim[side] : a[axis] <= lim[side];
            int ib = keep_ge ? b[axis] >= lim[side] : b[axis] <= lim[side];
            if (ia) memcpy(out[m++], a, sizeof out[0]);
            if (ia != ib) {
                double t = (lim[side] - a[axis]) / (b[axis] - a[axis]);
                out[m][0] = a[0] + t * (b[0] - a[0]);
                out[m][1] = a[1] + t * (b[1] - a[1]);
                m++;
            }
        }
        n = m;
        cur = 1 - cur;
    }
    double s = 0;
    for (int i = 0; i < n; i++) s += buf[cur][i][0] * buf[cur][(i + 1) % n][1] - buf[cur][(i + 1) % n][0] * buf[cur][i][1];
    return fabs(s) / 2;
}

static void to_outline(double p[NLOOPS][4][2], uint32_t *start, silk_vec2 *pt, silk_outline *o)
{
    for (int k = 0; k < NLOOPS; k++) {
        start[k] = 4 * (uint32_t)k;
        for (int i = 0; i < 4; i++)
            pt[4 * k + i] = (silk_vec2){ (silk_fx)lround(p[k][i][0] * 65536), (silk_fx)lround(p[k][i][1] * 65536) };
    }
    start[NLOOPS] = 4 * NLOOPS;
    *o = (silk_outline){ NLOOPS, 4 * NLOOPS, start, pt };
}

/* One random polygon: its loops in double and as a Q16.16 outline. */
typedef struct poly {
    double p[NLOOPS][4][2];
    uint32_t start[NLOOPS + 1];
    silk_vec2 pt[4 * NLOOPS];
    silk_outline o;
} poly;

static void make_poly(unsigned seed, poly *q)
{
    make_loops(seed, q->p);
    to_outline(q->p, q->start, q->pt, &q->o);
}

/* The frame as clip mode leaves it when the hull covers everything in
 * black: stencil, "draw" where it lets through, anti-alias. */
static void draw(const silk_outline *o, int aa, int band, uint8_t *out)
{
    static uint8_t mem[1 << 20];
    silk_arena a;
    silk_arena_init(&a, mem, sizeof mem);
    silk_clip c;
    silk_error err;
    CHECK(silk_clip_outline(&c, &a, o, W, H, band, aa, &err) == SILK_OK);
    uint8_t color[W * H * 3];
    uint32_t depth[W * H];
    for (int y0 = 0; y0 < H; y0 += band) {
        int rows = H - y0 < band ? H - y0 : band;
        silk_target t;
        silk_target_init(&t, W, H, y0, rows, SILK_PIX_RGB888, color, depth);
        silk_target_clear(&t, 0xFFFFFF);
        silk_clip_stencil(&c, &t);
        for (int r = 0; r < rows; r++)
            for (int x = 0; x < W; x++)
                if (t.mask[r * ((W + 7) / 8) + x / 8] >> (x % 8) & 1) {
                    silk_target_put(&t, x, y0 + r, 0x000000);
                    depth[r * W + x] = 1;
                }
        t.mask = NULL;
        silk_clip_antialias(&c, &t, 0xFFFFFF);
        for (int r = 0; r < rows; r++)
            for (int x = 0; x < W; x++) out[(y0 + r) * W + x] = (uint8_t)(silk_target_get(&t, x, y0 + r) >> 16);
    }
}

TEST(centres_follow_the_parity_rule)
{
    for (unsigned seed = 1; seed <= 20; seed++) {
        static poly q;
        make_poly(seed, &q);
        uint8_t img[W * H];
        draw(&q.o, 0, H, img);
        int bad = 0, checked = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double near;
                int in = inside(q.p, x + 0.5, y + 0.5, &near);
                if (near < 1e-3) continue;
                checked++;
                bad += in != (img[y * W + x] == 0);
            }
        CHECKF(bad == 0, "seed %u: %d of %d pixel centres on the wrong side", seed, bad, checked);
    }
}

TEST(coverage_is_the_area_inside_each_pixel)
{
    double worst = 0;
    for (unsigned seed = 1; seed <= 20; seed++) {
        static poly q;
        make_poly(seed, &q);
        uint8_t img[W * H];
        draw(&q.o, 1, H, img);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double area = 0;
                for (int k = 0; k < NLOOPS; k++) area += clipped_area(q.p[k], x, y);
                double got = (255 - img[y * W + x]) / 255.0;
                if (fabs(got - area) > worst) worst = fabs(got - area);
                CHECKF(fabs(got - area) <= 0.25, "seed %u pixel %d,%d: coverage %.3f, area %.3f", seed, x, y, got, area);
                if (area == 0) CHECKF(img[y * W + x] == 255, "seed %u pixel %d,%d: touched outside", seed, x, y);
                if (area > 1 - 1e-9) CHECKF(img[y * W + x] == 0, "seed %u pixel %d,%d: inside but blended", seed, x, y);
            }
    }
    printf("  largest coverage error: %.3f of a pixel\n", worst);
}

TEST(bands_give_the_whole_frame)
{
    static poly q;
    make_poly(7, &q);
    for (int aa = 0; aa < 2; aa++) {
        uint8_t whole[W * H], banded[W * H];
        draw(&q.o, aa, H, whole);
        for (int band = 1; band <= 17; band += 4) {
            draw(&q.o, aa, band, banded);
            CHECKF(memcmp(whole, banded, sizeof whole) == 0, "antialias %d, bands of %d rows differ", aa, band);
        }
    }
}

int main(void)
{
    RUN(centres_follow_the_parity_rule);
    RUN(coverage_is_the_area_inside_each_pixel);
    RUN(bands_give_the_whole_frame);
    return check_done();
}
