/*
 * mask.c - silhouette comparison of two renders (docs/measurements.md):
 * object masks, boundary pixels, outline length by the Cauchy-Crofton
 * formula, and the Hausdorff distance of two boundaries through an exact
 * Euclidean distance transform (Felzenszwalb & Huttenlocher 2012, in
 * integers, so the distances are exact for any image size).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "mask.h"

void mask_from_rgb(const uint8_t *rgb, size_t stride, int w, int h, uint32_t bg, uint8_t *mask)
{
    uint8_t r = (uint8_t)(bg >> 16), g = (uint8_t)(bg >> 8), b = (uint8_t)bg;
    for (int y = 0; y < h; y++) {
        const uint8_t *p = rgb + (size_t)y * stride;
        uint8_t *m = mask + (size_t)y * w;
        for (int x = 0; x < w; x++, p += 3) m[x] = p[0] != r || p[1] != g || p[2] != b;
    }
}

uint64_t mask_boundary(const uint8_t *m, int w, int h, uint8_t *b)
{
    uint64_t n = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int edge = m[i] && ((x > 0 && !m[i - 1]) || (x + 1 < w && !m[i + 1]) || (y > 0 && !m[i - w]) ||
                                (y + 1 < h && !m[i + w]));
            b[i] = (uint8_t)edge;
            n += (uint64_t)edge;
        }
    return n;
}

/* Crofton: length = 1/2 * integral over all lines of the number of
 * crossings.  Lines through the pixel centres in four directions, pi/4
 * apart; a pair of neighbouring centres on one line that disagree is a
 * crossing.  Horizontal and vertical lines are 1 px apart, diagonal ones
 * 1/sqrt(2): length = pi/8 * (n_h + n_v + (n_d + n_a) / sqrt(2)). */
double mask_outline_length(const uint8_t *m, int w, int h)
{
    uint64_t nh = 0, nv = 0, nd = 0, na = 0;
    for (int y = 0; y < h; y++) {
        const uint8_t *row = m + (size_t)y * w, *below = y + 1 < h ? row + w : NULL;
        for (int x = 0; x < w; x++) {
            if (x + 1 < w) nh += row[x] != row[x + 1];
            if (!below) continue;
            nv += row[x] != below[x];
            if (x + 1 < w) nd += row[x] != below[x + 1];
            if (x > 0) na += row[x] != below[x - 1];
        }
    }
    return CLI_PI / 8 * ((double)(nh + nv) + (double)(nd + na) / sqrt(2.0));
}

/* One row of the transform: d[x] = min over q of (x - q)^2 + f[q], f[q] ==
 * MASK_FAR for no feature.  The lower envelope of the parabolas: parabola k
 * has its vertex at v[k] with height f[k], and its interval starts at the
 * fraction zn[k] / zd[k] (zd > 0), compared by cross-multiplication so no
 * rounding can pick a wrong parabola. */
static void edt_row(uint32_t *d, int w, int *v, uint32_t *f, int64_t *zn, int64_t *zd)
{
    int k = -1;
    for (int q = 0; q < w; q++) {
        if (d[q] == MASK_FAR) continue;
        int64_t fq = (int64_t)d[q] + (int64_t)q * q;
        int64_t num = 0, den = 1;
        while (k >= 0) {
            num = fq - ((int64_t)f[k] + (int64_t)v[k] * v[k]);
            den = 2 * (int64_t)(q - v[k]);
            /* the new parabola is lowest wherever parabola k was: drop k
             * (z[0] is minus infinity, so the first one always stays) */
            if (k > 0 && num * zd[k] <= zn[k] * den) {
                k--;
                continue;
            }
            break;
        }
        k++;
        v[k] = q;
        f[k] = d[q];
        zn[k] = num;
        zd[k] = den;
    }
    if (k < 0) return;   /* no feature in the row: it stays MASK_FAR */
    int j = 0;
    for (int x = 0; x < w; x++) {
        while (j < k && zn[j + 1] < (int64_t)x * zd[j + 1]) j++;
        int64_t dx = x - v[j];
        d[x] = (uint32_t)(dx * dx + f[j]);
    }
}

int mask_distance2(const uint8_t *feature, int w, int h, uint32_t *d2)
{
    int *v = malloc((size_t)w * sizeof *v);
    uint32_t *f = malloc((size_t)w * sizeof *f);
    int64_t *zn = malloc((size_t)w * sizeof *zn), *zd = malloc((size_t)w * sizeof *zd);
    int32_t *last = malloc((size_t)w * sizeof *last);
    if (!v || !f || !zn || !zd || !last) {
        free(v), free(f), free(zn), free(zd), free(last);
        return -1;
    }
    /* Columns: the vertical distance to the nearest feature above, then
     * below, row by row so the passes stream through memory. */
    for (int x = 0; x < w; x++) last[x] = -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (feature[i]) last[x] = y;
            d2[i] = last[x] < 0 ? MASK_FAR : (uint32_t)(y - last[x]);
        }
    for (int x = 0; x < w; x++) last[x] = -1;
    for (int y = h - 1; y >= 0; y--)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (feature[i]) last[x] = y;
            if (last[x] >= 0 && (d2[i] == MASK_FAR || (uint32_t)(last[x] - y) < d2[i]))
                d2[i] = (uint32_t)(last[x] - y);
            if (d2[i] != MASK_FAR) d2[i] *= d2[i];
        }
    for (int y = 0; y < h; y++) edt_row(d2 + (size_t)y * w, w, v, f, zn, zd);
    free(v), free(f), free(zn), free(zd), free(last);
    return 0;
}

/* Largest squared distance from a pixel of `from` to the set the transform
 * d2 was computed for. */
static uint32_t farthest2(const uint8_t *from, const uint32_t *d2, size_t n)
{
    uint32_t worst = 0;
    for (size_t i = 0; i < n; i++)
        if (from[i] && d2[i] > worst) worst = d2[i];
    return worst;
}

int mask_compare(const uint8_t *a, const uint8_t *b, int w, int h, mask_stats *st)
{
    memset(st, 0, sizeof *st);
    st->width = w;
    st->height = h;
    size_t n = (size_t)w * h;
    for (size_t i = 0; i < n; i++) {
        st->pixels_a += a[i] != 0;
        st->pixels_b += b[i] != 0;
        st->only_a += a[i] && !b[i];
        st->only_b += !a[i] && b[i];
    }
    st->differing = st->only_a + st->only_b;
    st->length_a = mask_outline_length(a, w, h);
    if (st->differing == 0) st->mean_px = 0;
    else st->mean_px = st->length_a > 0 ? (double)st->differing / st->length_a : INFINITY;

    uint8_t *ba = malloc(n ? n : 1), *bb = malloc(n ? n : 1);
    uint32_t *d2 = malloc((n ? n : 1) * sizeof *d2);
    int rc = -1;
    if (!ba || !bb || !d2) goto done;
    st->boundary_a = mask_boundary(a, w, h, ba);
    st->boundary_b = mask_boundary(b, w, h, bb);
    if (!st->boundary_a && !st->boundary_b) {
        st->hausdorff_px = 0;
    } else if (!st->boundary_a || !st->boundary_b) {
        st->hausdorff_px = INFINITY;
    } else {
        if (mask_distance2(bb, w, h, d2)) goto done;
        uint32_t worst = farthest2(ba, d2, n);
        if (mask_distance2(ba, w, h, d2)) goto done;
        uint32_t other = farthest2(bb, d2, n);
        st->hausdorff_px = sqrt((double)(worst > other ? worst : other));
    }
    rc = 0;
done:
    free(ba);
    free(bb);
    free(d2);
    return rc;
}

void mask_diff_image(const uint8_t *a, const uint8_t *b, int w, int h, uint8_t *rgb)
{
    size_t n = (size_t)w * h;
    for (size_t i = 0; i < n; i++) {
        uint32_t c = a[i] ? (b[i] ? MASK_RGB_BOTH : MASK_RGB_ONLY_A) : (b[i] ? MASK_RGB_ONLY_B : MASK_RGB_NONE);
        rgb[3 * i] = (uint8_t)(c >> 16);
        rgb[3 * i + 1] = (uint8_t)(c >> 8);
        rgb[3 * i + 2] = (uint8_t)c;
    }
}
