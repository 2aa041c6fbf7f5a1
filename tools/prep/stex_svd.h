/*
 * stex_svd.h - the SVD compression of a silhouette texture's angles (Wu,
 * Wei, Wang, Guo, "Silhouette Texture", section 3.5), with a mean row:
 * each texel's K angles are the mean plus a weighted sum of the E
 * eigenfunctions of the K x K covariance of the texels (the right singular
 * vectors of the centred matrix A, found by Jacobi rotations), in the
 * integer form of the STEX section (docs/formats.md): K x int16 mean (angle
 * steps x 16), E x int32 scale s (Q16.16 angle steps per weight step),
 * E x K int16 eigenfunctions (Q1.14), one int8 weight per texel and
 * eigenfunction.  Host-side, double precision.
 */
#ifndef SILK_TOOLS_STEX_SVD_H
#define SILK_TOOLS_STEX_SVD_H

#include <stddef.h>
#include <stdint.h>

typedef struct stex_svd {
    int k, e;
    uint32_t ntexels;
    int16_t *mean;           /* k */
    int32_t *s;              /* e */
    int16_t *v;              /* e * k: eigenfunction j at j * k + i */
    int8_t *w;               /* ntexels * e */
} stex_svd;

/* Angle i (0..k-1) of a texel whose weights are w (e of them): the
 * renderer's reconstruction, silk_siltex_q (silk/siltex.h),
 *   mean[i]/16 + sum_j w[j] s[j] v[j k + i] / 2^30,
 * rounded to nearest, clamped to 0..255. */
uint8_t stex_svd_angle(const int16_t *mean, const int32_t *s, const int16_t *v, const int8_t *w, int k, int e, int i);

/* Compress ntexels rows of k angles (row t at angles[t * k]); only rows
 * with used[t] set count towards the mean and covariance (the others get
 * zero weights).  1 <= e <= k.  0, or -1 when out of memory. */
int stex_svd_compress(const uint8_t *angles, const uint8_t *used, uint32_t ntexels, int k, int e, stex_svd *out);
/* The angles back (ntexels * k), by silk_siltex_q. */
void stex_svd_expand(const stex_svd *c, uint8_t *angles);
/* Bytes of the compressed angles in the section, before padding. */
size_t stex_svd_bytes(int k, int e, uint32_t ntexels);
void stex_svd_free(stex_svd *c);

/* Eigenvalues (descending) and unit eigenvectors (row j of vecs, n each)
 * of the symmetric n x n matrix a (destroyed), by cyclic Jacobi
 * rotations.  n <= STEX_SVD_MAX_N. */
#define STEX_SVD_MAX_N 64
void jacobi_eigen(double *a, int n, double *vals, double *vecs);

#endif
