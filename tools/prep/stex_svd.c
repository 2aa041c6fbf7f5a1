/*
 * stex_svd.c - SVD compression of silhouette texture angles (stex_svd.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "silk/siltex.h"
#include "stex_svd.h"

void jacobi_eigen(double *a, int n, double *vals, double *vecs)
{
    double v[STEX_SVD_MAX_N * STEX_SVD_MAX_N] = { 0 };
    int order[STEX_SVD_MAX_N];
    for (int i = 0; i < n; i++) v[i * n + i] = 1;
    for (int sweep = 0; sweep < 100; sweep++) {
        double off = 0, diag = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) *(i == j ? &diag : &off) += a[i * n + j] * a[i * n + j];
        if (off <= 1e-24 * diag || off == 0) break;
        for (int p = 0; p < n; p++)
            for (int q = p + 1; q < n; q++) {
                double apq = a[p * n + q];
                if (apq == 0) continue;
                /* the rotation that zeroes a[p][q] (Golub & Van Loan 8.4) */
                double tau = (a[q * n + q] - a[p * n + p]) / (2 * apq);
                double t = (tau >= 0 ? 1 : -1) / (fabs(tau) + sqrt(1 + tau * tau));
                double c = 1 / sqrt(1 + t * t), s = t * c;
                for (int r = 0; r < n; r++) {
                    double arp = a[r * n + p], arq = a[r * n + q];
                    a[r * n + p] = c * arp - s * arq;
                    a[r * n + q] = s * arp + c * arq;
                }
                for (int r = 0; r < n; r++) {
                    double apr = a[p * n + r], aqr = a[q * n + r];
                    a[p * n + r] = c * apr - s * aqr;
                    a[q * n + r] = s * apr + c * aqr;
                }
                for (int r = 0; r < n; r++) {
                    double vrp = v[r * n + p], vrq = v[r * n + q];
                    v[r * n + p] = c * vrp - s * vrq;
                    v[r * n + q] = s * vrp + c * vrq;
                }
            }
    }
    /* selection sort of the eigenvalues, descending; eigenvector j is column j of v */
    for (int i = 0; i < n; i++) order[i] = i;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (a[order[j] * n + order[j]] > a[order[i] * n + order[i]]) {
                int s = order[i];
                order[i] = order[j];
                order[j] = s;
            }
    for (int i = 0; i < n; i++) {
        vals[i] = a[order[i] * n + order[i]];
        for (int r = 0; r < n; r++) vecs[i * n + r] = v[r * n + order[i]];
    }
}

size_t stex_svd_bytes(int k, int e, uint32_t ntexels)
{
    return 2 * (size_t)k + 4 * (size_t)e + 2 * (size_t)e * k + (size_t)ntexels * e;
}

void stex_svd_free(stex_svd *c)
{
    free(c->mean);
    free(c->s);
    free(c->v);
    free(c->w);
    memset(c, 0, sizeof *c);
}

int stex_svd_compress(const uint8_t *angles, const uint8_t *used, uint32_t ntexels, int k, int e, stex_svd *out)
{
    memset(out, 0, sizeof *out);
    out->k = k, out->e = e, out->ntexels = ntexels;
    out->mean = calloc((size_t)k, sizeof *out->mean);
    out->s = calloc((size_t)e, sizeof *out->s);
    out->v = calloc((size_t)e * k, sizeof *out->v);
    out->w = calloc((size_t)ntexels * e + 1, sizeof *out->w);
    double *mean = calloc((size_t)k, sizeof *mean), *cov = calloc((size_t)k * k, sizeof *cov);
    double *vals = calloc((size_t)k, sizeof *vals), *vecs = calloc((size_t)k * k, sizeof *vecs);
    double *wr = calloc((size_t)ntexels * e + 1, sizeof *wr), *row = calloc((size_t)k, sizeof *row);
    int rc = -1;
    if (!out->mean || !out->s || !out->v || !out->w || !mean || !cov || !vals || !vecs || !wr || !row) goto done;
    uint32_t n = 0;
    for (uint32_t t = 0; t < ntexels; t++)
        if (used[t]) {
            n++;
            for (int i = 0; i < k; i++) mean[i] += angles[(size_t)t * k + i];
        }
    for (int i = 0; i < k; i++) {
        mean[i] = n ? mean[i] / n : 0;
        out->mean[i] = (int16_t)lround(mean[i] * 16);
        mean[i] = out->mean[i] / 16.0;   /* the stored mean, so the weights make up for its rounding */
    }
    for (uint32_t t = 0; t < ntexels; t++) {
        if (!used[t]) continue;
        for (int i = 0; i < k; i++) row[i] = angles[(size_t)t * k + i] - mean[i];
        for (int i = 0; i < k; i++)
            for (int j = i; j < k; j++) cov[i * k + j] += row[i] * row[j];
    }
    for (int i = 0; i < k; i++)
        for (int j = 0; j < i; j++) cov[i * k + j] = cov[j * k + i];
    jacobi_eigen(cov, k, vals, vecs);
    for (int j = 0; j < e; j++) {
        /* a fixed sign (largest component positive), so equal inputs give equal files */
        int big = 0;
        for (int i = 1; i < k; i++)
            if (fabs(vecs[j * k + i]) > fabs(vecs[j * k + big])) big = i;
        double sign = vecs[j * k + big] < 0 ? -1 : 1;
        for (int i = 0; i < k; i++) out->v[j * k + i] = (int16_t)lround(sign * vecs[j * k + i] * 16384);
    }
    /* weights: projections on the stored (rounded) eigenfunctions, then each
     * eigenfunction's weights scaled to fill -127..127 */
    for (uint32_t t = 0; t < ntexels; t++) {
        if (!used[t]) continue;
        for (int i = 0; i < k; i++) row[i] = angles[(size_t)t * k + i] - mean[i];
        for (int j = 0; j < e; j++) {
            double sum = 0;
            for (int i = 0; i < k; i++) sum += row[i] * out->v[j * k + i] / 16384.0;
            wr[(size_t)t * e + j] = sum;
        }
    }
    for (int j = 0; j < e; j++) {
        double big = 0;
        for (uint32_t t = 0; t < ntexels; t++) big = fmax(big, fabs(wr[(size_t)t * e + j]));
        long s = lround(big / 127 * 65536);
        out->s[j] = (int32_t)(s < 1 ? 1 : s);
        for (uint32_t t = 0; t < ntexels; t++) {
            long w = lround(wr[(size_t)t * e + j] * 65536 / out->s[j]);
            out->w[(size_t)t * e + j] = (int8_t)(w > 127 ? 127 : w < -127 ? -127 : w);
        }
    }
    rc = 0;
done:
    free(mean), free(cov), free(vals), free(vecs), free(wr), free(row);
    if (rc) stex_svd_free(out);
    return rc;
}

/* The compressed angles as the STEX section lays them out, seen by st as
 * the renderer sees them (the little-endian mean, scale and basis in buf,
 * the weights where they are), so the host reconstructs with the
 * renderer's code. */
#define AS_SECTION_BYTES (2 * STEX_SVD_MAX_N + 4 * STEX_SVD_MAX_N + 2 * STEX_SVD_MAX_N * STEX_SVD_MAX_N)
static void as_section(const int16_t *mean, const int32_t *s, const int16_t *v, const int8_t *w, int k, int e,
                       uint8_t buf[AS_SECTION_BYTES], silk_siltex *st)
{
    memset(st, 0, sizeof *st);
    st->flags = SILK_STEX_COMPRESSED, st->k = (uint32_t)k, st->e = (uint32_t)e;
    uint8_t *p = buf;
    st->mean = p;
    for (int i = 0; i < k; i++, p += 2) p[0] = (uint8_t)mean[i], p[1] = (uint8_t)((uint16_t)mean[i] >> 8);
    st->scale = p;
    for (int j = 0; j < e; j++, p += 4)
        for (int b = 0; b < 4; b++) p[b] = (uint8_t)((uint32_t)s[j] >> (8 * b));
    st->basis = p;
    for (int i = 0; i < e * k; i++, p += 2) p[0] = (uint8_t)v[i], p[1] = (uint8_t)((uint16_t)v[i] >> 8);
    st->weights = (const uint8_t *)w;
}

uint8_t stex_svd_angle(const int16_t *mean, const int32_t *s, const int16_t *v, const int8_t *w, int k, int e, int i)
{
    uint8_t buf[AS_SECTION_BYTES];
    silk_siltex st;
    as_section(mean, s, v, w, k, e, buf, &st);
    return (uint8_t)silk_siltex_q(&st, 0, (uint32_t)i);
}

void stex_svd_expand(const stex_svd *c, uint8_t *angles)
{
    uint8_t buf[AS_SECTION_BYTES];
    silk_siltex st;
    as_section(c->mean, c->s, c->v, c->w, c->k, c->e, buf, &st);
    for (uint32_t t = 0; t < c->ntexels; t++)
        for (int i = 0; i < c->k; i++) angles[(size_t)t * c->k + i] = (uint8_t)silk_siltex_q(&st, t, (uint32_t)i);
}
