/*
 * test_mask.c - the silhouette comparison of `silk diff` and `silk bench`
 * (tools/image/mask.c): the distance transform and the Hausdorff distance equal a
 * brute-force double reference exactly, the outline length is within the
 * Crofton bound of the true length for discs and squares, and the mean
 * boundary error of two concentric discs is the gap between their radii.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "../tools/image/mask.c"

/* Brute force: squared distance to the nearest feature pixel. */
static uint32_t brute_d2(const uint8_t *f, int w, int h, int x, int y)
{
    uint32_t best = MASK_FAR;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++)
            if (f[j * w + i]) {
                uint32_t d = (uint32_t)((i - x) * (i - x) + (j - y) * (j - y));
                if (d < best) best = d;
            }
    return best;
}

static double brute_hausdorff(const uint8_t *a, const uint8_t *b, int w, int h)
{
    uint8_t *ba = malloc((size_t)w * h), *bb = malloc((size_t)w * h);
    mask_boundary(a, w, h, ba);
    mask_boundary(b, w, h, bb);
    double worst = 0;
    for (int pass = 0; pass < 2; pass++) {
        const uint8_t *from = pass ? bb : ba, *to = pass ? ba : bb;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                if (from[y * w + x]) {
                    double d = sqrt((double)brute_d2(to, w, h, x, y));
                    if (d > worst) worst = d;
                }
    }
    free(ba);
    free(bb);
    return worst;
}

/* A random mask of a few overlapping discs. */
static void blobs(uint8_t *m, int w, int h)
{
    memset(m, 0, (size_t)w * h);
    int n = 1 + (int)(check_rand64() % 4);
    for (int k = 0; k < n; k++) {
        double cx = check_uniform(0, w), cy = check_uniform(0, h), r = check_uniform(1, w / 2.0);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) m[y * w + x] = 1;
    }
}

TEST(distance_transform_is_exact)
{
    int bad = 0, cases = 0;
    for (int trial = 0; trial < 300; trial++) {
        int w = 1 + (int)(check_rand64() % 40), h = 1 + (int)(check_rand64() % 30);
        double density = trial % 3 == 0 ? 0.002 : trial % 3 == 1 ? 0.05 : 0.5;
        uint8_t *f = malloc((size_t)w * h);
        uint32_t *d2 = malloc((size_t)w * h * sizeof *d2);
        for (int i = 0; i < w * h; i++) f[i] = check_uniform(0, 1) < density;
        CHECK(mask_distance2(f, w, h, d2) == 0);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++, cases++)
                if (d2[y * w + x] != brute_d2(f, w, h, x, y)) bad++;
        free(f);
        free(d2);
    }
    CHECKF(bad == 0, "%d of %d distances differ from brute force", bad, cases);
}

TEST(hausdorff_is_exact)
{
    int bad = 0;
    for (int trial = 0; trial < 200; trial++) {
        int w = 8 + (int)(check_rand64() % 40), h = 8 + (int)(check_rand64() % 30);
        uint8_t *a = malloc((size_t)w * h), *b = malloc((size_t)w * h);
        blobs(a, w, h);
        blobs(b, w, h);
        mask_stats st;
        CHECK(mask_compare(a, b, w, h, &st) == 0);
        double ref = brute_hausdorff(a, b, w, h);
        if (st.boundary_a && st.boundary_b && st.hausdorff_px != ref) {
            if (bad++ < 5) fprintf(stderr, "  %dx%d: %.9g, brute force %.9g\n", w, h, st.hausdorff_px, ref);
        }
        free(a);
        free(b);
    }
    CHECKF(bad == 0, "%d comparisons differ from brute force", bad);
}

static void disc(uint8_t *m, int w, int h, double cx, double cy, double r)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) m[y * w + x] = (x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= r * r;
}

/* A square of side s centred at (c, c), turned by deg degrees. */
static void square(uint8_t *m, int w, int h, double c, double s, double deg)
{
    double t = deg * 3.14159265358979323846 / 180, co = cos(t), si = sin(t);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double dx = x + 0.5 - c, dy = y + 0.5 - c;
            double u = co * dx + si * dy, v = -si * dx + co * dy;
            m[y * w + x] = fabs(u) <= s / 2 && fabs(v) <= s / 2;
        }
}

TEST(outline_length)
{
    enum { W = 400, H = 400 };
    static uint8_t m[W * H];
    const double pi = 3.14159265358979323846;
    for (double r = 20; r <= 180; r += 40) {
        disc(m, W, H, 200.3, 199.6, r);
        double len = mask_outline_length(m, W, H);
        CHECKF(fabs(len / (2 * pi * r) - 1) < 0.02, "disc r=%g: length %g, true %g", r, len, 2 * pi * r);
    }
    /* Straight edges: the four-direction Crofton estimate is within
     * cos(pi/8)-type bounds, 0.948 .. 1.026 of the true length. */
    for (double deg = 0; deg < 90; deg += 7.5) {
        square(m, W, H, 200, 200, deg);
        double len = mask_outline_length(m, W, H), ratio = len / 800;
        CHECKF(ratio > 0.94 && ratio < 1.035, "square at %g degrees: length %g, true 800", deg, len);
    }
    /* The image border is not outline: a full image has none. */
    memset(m, 1, sizeof m);
    CHECK(mask_outline_length(m, W, H) == 0);
}

TEST(concentric_discs)
{
    enum { W = 400, H = 400 };
    static uint8_t a[W * H], b[W * H];
    for (double gap = 1; gap <= 5; gap += 2) {
        disc(a, W, H, 200, 200, 150);
        disc(b, W, H, 200, 200, 150 + gap);
        mask_stats st;
        CHECK(mask_compare(a, b, W, H, &st) == 0);
        CHECK(st.only_a == 0);
        CHECK(st.differing == st.only_b && st.only_b > 0);
        CHECKF(fabs(st.mean_px - gap) < 0.1, "gap %g: mean %g", gap, st.mean_px);
        CHECKF(fabs(st.hausdorff_px - gap) <= 1, "gap %g: hausdorff %g", gap, st.hausdorff_px);
        /* the comparison is symmetric in everything but the reference's length */
        mask_stats rev;
        CHECK(mask_compare(b, a, W, H, &rev) == 0);
        CHECK(rev.differing == st.differing && rev.only_a == st.only_b && rev.hausdorff_px == st.hausdorff_px);
    }
    /* a shift of the whole disc by d pixels: Hausdorff d exactly */
    disc(a, W, H, 200, 200, 100);
    disc(b, W, H, 207, 200, 100);
    mask_stats st;
    CHECK(mask_compare(a, b, W, H, &st) == 0);
    CHECKF(st.hausdorff_px == 7, "hausdorff %g", st.hausdorff_px);
}

TEST(degenerate_masks)
{
    enum { W = 31, H = 17 };
    uint8_t a[W * H], b[W * H];
    mask_stats st;
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    CHECK(mask_compare(a, b, W, H, &st) == 0);
    CHECK(st.differing == 0 && st.mean_px == 0 && st.hausdorff_px == 0);
    disc(b, W, H, 15, 8, 5);
    CHECK(mask_compare(a, b, W, H, &st) == 0);
    CHECK(st.differing == st.pixels_b && isinf(st.mean_px) && isinf(st.hausdorff_px));
    CHECK(mask_compare(b, b, W, H, &st) == 0);
    CHECK(st.differing == 0 && st.mean_px == 0 && st.hausdorff_px == 0 && st.length_a > 0);
    /* a single pixel: its own boundary */
    memset(a, 0, sizeof a);
    a[5 * W + 7] = 1;
    CHECK(mask_boundary(a, W, H, b) == 1 && b[5 * W + 7] == 1);
}

TEST(masks_and_pictures)
{
    enum { W = 4, H = 2 };
    uint8_t rgb[W * H * 3 + 6];   /* stride of 15 bytes: one pixel of padding */
    memset(rgb, 0xff, sizeof rgb);
    rgb[3] = 0xfe;                          /* (1,0): differs in red */
    rgb[15 + 9 + 2] = 0x00;                 /* (3,1): differs in blue */
    uint8_t m[W * H], ref[W * H] = { 0, 1, 0, 0, 0, 0, 0, 1 };
    mask_from_rgb(rgb, 15, W, H, 0xffffff, m);
    CHECK(memcmp(m, ref, sizeof m) == 0);
    uint8_t a[4] = { 1, 1, 0, 0 }, b[4] = { 1, 0, 1, 0 }, pic[12];
    mask_diff_image(a, b, 4, 1, pic);
    uint32_t want[4] = { MASK_RGB_BOTH, MASK_RGB_ONLY_A, MASK_RGB_ONLY_B, MASK_RGB_NONE };
    for (int i = 0; i < 4; i++)
        CHECK(((uint32_t)pic[3 * i] << 16 | (uint32_t)pic[3 * i + 1] << 8 | pic[3 * i + 2]) == want[i]);
}

int main(void)
{
    RUN(distance_transform_is_exact);
    RUN(hausdorff_is_exact);
    RUN(outline_length);
    RUN(concentric_discs);
    RUN(degenerate_masks);
    RUN(masks_and_pictures);
    return check_done();
}
