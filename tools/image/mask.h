/*
 * mask.h - comparing the silhouettes of two renders: object masks, their
 * outlines, and how far apart the outlines are.  Used by `silk diff` and by
 * `silk bench` (the error of a mode against the fine mesh), so both report
 * the same numbers.  Host-side; docs/measurements.md defines every metric.
 *
 * A mask is one byte per pixel, 1 for the object, 0 for the background,
 * rows top to bottom, width*height bytes.
 */
#ifndef SILK_TOOLS_MASK_H
#define SILK_TOOLS_MASK_H

#include <stddef.h>
#include <stdint.h>

typedef struct mask_stats {
    int width, height;
    uint64_t pixels_a, pixels_b;       /* object pixels of each mask */
    uint64_t only_a, only_b;           /* object in one mask only */
    uint64_t differing;                /* only_a + only_b */
    uint64_t boundary_a, boundary_b;   /* boundary pixels of each mask */
    double length_a;                   /* outline length of A in px (Crofton estimate) */
    double mean_px;                    /* differing / length_a: mean distance between the outlines */
    double hausdorff_px;               /* Hausdorff distance of the two boundary pixel sets */
} mask_stats;

/* mask[i] = 1 where the pixel differs from bg (0xRRGGBB); rgb holds rows of
 * 3*w bytes, stride bytes apart. */
void mask_from_rgb(const uint8_t *rgb, size_t stride, int w, int h, uint32_t bg, uint8_t *mask);

/* Boundary pixels: object pixels with a 4-neighbour inside the image that is
 * background.  Sets b[i] to 1 for those, 0 elsewhere; returns their number. */
uint64_t mask_boundary(const uint8_t *m, int w, int h, uint8_t *b);

/* Length of the mask's outline in pixels, by the Cauchy-Crofton formula
 * over the pixel-centre lattice in four directions (0, 45, 90, 135
 * degrees): within about 5% of the true length for a straight edge of any
 * orientation.  The image border is not part of the outline. */
double mask_outline_length(const uint8_t *m, int w, int h);

/* Exact squared Euclidean distance from every pixel to the nearest pixel
 * with feature[i] != 0 (Felzenszwalb-Huttenlocher, two 1-D passes), or
 * MASK_FAR when there is none.  Returns 0, or -1 when out of memory. */
#define MASK_FAR UINT32_MAX
int mask_distance2(const uint8_t *feature, int w, int h, uint32_t *d2);

/* Compare A (the reference) with B.  mean_px is 0 when nothing differs and
 * infinite when A has no outline but pixels differ; hausdorff_px is
 * infinite when exactly one of the masks has boundary pixels.  Returns 0,
 * or -1 when out of memory. */
int mask_compare(const uint8_t *a, const uint8_t *b, int w, int h, mask_stats *st);

/* The picture of the differences, 3*w*h bytes of RGB: in both masks grey,
 * only in A red, only in B blue, in neither white. */
#define MASK_RGB_BOTH   0xB4B4B4u
#define MASK_RGB_ONLY_A 0xE01E1Eu
#define MASK_RGB_ONLY_B 0x1E46E0u
#define MASK_RGB_NONE   0xFFFFFFu
void mask_diff_image(const uint8_t *a, const uint8_t *b, int w, int h, uint8_t *rgb);

#endif
