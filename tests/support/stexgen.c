/*
 * stexgen.c - analytic silhouette textures for the tests (stexgen.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "stexgen.h"
#include "silk/silk.h"
#include "silk/siltex.h"
#include "../../tools/prep/model_file.h"

void stexgen_defaults(stexgen_opts *o)
{
    memset(o, 0, sizeof *o);
    o->nspheres = 1;
    o->r[0] = 1.0;
    o->R[0] = 1.06;
    o->level = 2;
    o->cell = 6;
    o->k = 8;
}

typedef struct ico {
    double *v;        /* unit directions */
    uint32_t *f;
    uint32_t nv, nf;
} ico;

static uint32_t midpoint(ico *m, uint32_t *key, uint32_t *nkeyp, uint32_t a, uint32_t b)
{
    uint32_t nkey = *nkeyp;
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    for (uint32_t i = 0; i < nkey; i++)
        if (key[3 * i] == lo && key[3 * i + 1] == hi) return key[3 * i + 2];
    double *p = &m->v[3 * m->nv], n = 0;
    for (int k = 0; k < 3; k++) {
        p[k] = m->v[3 * a + k] + m->v[3 * b + k];
        n += p[k] * p[k];
    }
    for (int k = 0; k < 3; k++) p[k] /= sqrt(n);
    key[3 * nkey] = lo;
    key[3 * nkey + 1] = hi;
    key[3 * nkey + 2] = m->nv;
    *nkeyp = nkey + 1;
    return m->nv++;
}

/* The icosahedron split level times, outward and counter-clockwise. */
static int icosphere(int level, ico *m)
{
    const double t = (1 + sqrt(5.0)) / 2;
    const double v0[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
                               { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
    const uint32_t f0[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
                                 { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                                 { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
                                 { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
    uint32_t maxf = 20u << (2 * level), maxv = 10 * (1u << (2 * level)) + 2;
    m->v = malloc(3 * sizeof(double) * maxv);
    m->f = malloc(3 * sizeof(uint32_t) * maxf);
    uint32_t *nf = malloc(3 * sizeof(uint32_t) * maxf), *key = malloc(3 * sizeof(uint32_t) * 3 * maxf);
    if (!m->v || !m->f || !nf || !key) {
        free(nf);
        free(key);
        return -1;
    }
    for (int i = 0; i < 12; i++) {
        double n = sqrt(v0[i][0] * v0[i][0] + v0[i][1] * v0[i][1] + v0[i][2] * v0[i][2]);
        for (int k = 0; k < 3; k++) m->v[3 * i + k] = v0[i][k] / n;
    }
    memcpy(m->f, f0, sizeof f0);
    m->nv = 12;
    m->nf = 20;
    for (int l = 0; l < level; l++) {
        uint32_t nkey = 0, n = 0;
        for (uint32_t i = 0; i < m->nf; i++) {
            uint32_t a = m->f[3 * i], b = m->f[3 * i + 1], c = m->f[3 * i + 2];
            uint32_t ab = midpoint(m, key, &nkey, a, b), bc = midpoint(m, key, &nkey, b, c),
                     ca = midpoint(m, key, &nkey, c, a);
            const uint32_t q[4][3] = { { a, ab, ca }, { b, bc, ab }, { c, ca, bc }, { ab, bc, ca } };
            memcpy(&nf[3 * n], q, sizeof q);
            n += 4;
        }
        memcpy(m->f, nf, 3 * sizeof(uint32_t) * n);
        m->nf = n;
    }
    free(nf);
    free(key);
    return 0;
}

static void wr16(uint8_t *p, uint32_t v) { p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); }
static void wr32(uint8_t *p, uint32_t v) { wr16(p, v); wr16(p + 2, v >> 16); }
static int16_t q14(double x) { return (int16_t)lround(x * 16384); }

/* Octahedral code of unit n, int8 -127..127 (docs/formats.md "STEX"). */
static void octa(const double n[3], uint8_t out[2])
{
    double s = fabs(n[0]) + fabs(n[1]) + fabs(n[2]), x = n[0] / s, y = n[1] / s;
    if (n[2] < 0) {
        double ox = (1 - fabs(y)) * (x < 0 ? -1 : 1), oy = (1 - fabs(x)) * (y < 0 ? -1 : 1);
        x = ox;
        y = oy;
    }
    out[0] = (uint8_t)(int8_t)lround(x * 127);
    out[1] = (uint8_t)(int8_t)lround(y * 127);
}

uint8_t *stexgen_model(const stexgen_opts *o, size_t *len)
{
    if (o->nspheres < 1 || o->nspheres > 2 || o->cell < 4 || o->k < SILK_STEX_MIN_K || o->k > SILK_STEX_MAX_K ||
        o->eigen < 0 || o->eigen > o->k || o->level < 0 || o->level > 4)
        return NULL;
    ico s;
    if (icosphere(o->level, &s)) return NULL;
    uint32_t nv = s.nv * (uint32_t)o->nspheres, nt = s.nf * (uint32_t)o->nspheres;
    double *pos = malloc(3 * sizeof(double) * nv), *nrm = malloc(3 * sizeof(double) * nv);
    uint32_t *tri = malloc(3 * sizeof(uint32_t) * nt);
    uint32_t cols = 1;
    while (cols * cols < nt) cols++;
    uint32_t S = (uint32_t)o->cell, W = cols * S, rows = (nt + cols - 1) / cols, H = rows * S, K = (uint32_t)o->k,
             E = (uint32_t)o->eigen;
    if (H < 8) H = 8;
    if (W < 8) W = 8;
    uint64_t texels = (uint64_t)W * H;
    size_t angles = E ? 2 * K + 4 * E + 2 * E * K + texels * E : texels * K;
    size_t size = SILK_STEX_HEAD_BYTES + 12 * (size_t)nv + 12 * (size_t)nt + angles;
    size += size & 1 && E;
    size_t normal_at = size;
    size += 2 * texels + (o->color ? 3 * texels : 0);
    size = (size + 3) & ~(size_t)3;
    uint8_t *st = calloc(1, size), *q = malloc(texels);
    uint8_t *out = NULL;
    if (!pos || !nrm || !tri || !st || !q) goto done;
    for (uint32_t i = 0; i < nv; i++) {
        int b = i >= s.nv;
        const double *d = &s.v[3 * (i - b * s.nv)];
        for (int k = 0; k < 3; k++) {
            pos[3 * i + k] = o->c[b][k] + o->R[b] * d[k];
            nrm[3 * i + k] = d[k];
        }
    }
    for (uint32_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) tri[3 * t + k] = s.f[3 * (t % s.nf) + k] + (t >= s.nf ? s.nv : 0);
    wr32(st, SILK_STEX_VERSION);
    wr32(st + 4, (E ? SILK_STEX_COMPRESSED : 0) | (o->color ? SILK_STEX_COLOR : 0));
    wr16(st + 8, W);
    wr16(st + 10, H);
    wr16(st + 12, K);
    wr16(st + 14, E);
    wr32(st + 16, nv);
    wr32(st + 20, nt);
    uint8_t *fr = st + SILK_STEX_HEAD_BYTES, *uv = fr + 12 * (size_t)nv, *ang = uv + 12 * (size_t)nt;
    for (uint32_t i = 0; i < nv; i++) {
        /* C inward; T across it, from the axis C is least along */
        double c[3] = { -nrm[3 * i], -nrm[3 * i + 1], -nrm[3 * i + 2] }, a[3] = { 0, 0, 0 }, t[3];
        int m = fabs(c[0]) < fabs(c[1]) ? (fabs(c[0]) < fabs(c[2]) ? 0 : 2) : (fabs(c[1]) < fabs(c[2]) ? 1 : 2);
        a[m] = 1;
        t[0] = a[1] * c[2] - a[2] * c[1];
        t[1] = a[2] * c[0] - a[0] * c[2];
        t[2] = a[0] * c[1] - a[1] * c[0];
        double n = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (int k = 0; k < 3; k++) {
            wr16(fr + 12 * (size_t)i + 2 * k, (uint16_t)q14(c[k]));
            wr16(fr + 12 * (size_t)i + 6 + 2 * k, (uint16_t)q14(t[k] / n));
        }
    }
    for (uint32_t t = 0; t < nt; t++) {
        uint32_t x0 = (t % cols) * S, y0 = (t / cols) * S;
        const uint32_t cu[3] = { x0 + 1, x0 + S - 1, x0 + 1 }, cv[3] = { y0 + 1, y0 + 1, y0 + S - 1 };
        for (int k = 0; k < 3; k++) {
            wr16(uv + 12 * (size_t)t + 4 * k, 16 * cu[k]);
            wr16(uv + 12 * (size_t)t + 4 * k + 2, 16 * cv[k]);
        }
        int b = t >= s.nf;
        for (uint32_t y = y0; y < y0 + S && y < H; y++)
            for (uint32_t x = x0; x < x0 + S && x < W; x++) {
                /* the texel centre's point of the triangle, the nearest one */
                double a1 = (x + 0.5 - (x0 + 1)) / (S - 2), a2 = (y + 0.5 - (y0 + 1)) / (S - 2);
                if (a1 + a2 > 1) {
                    double e = (a1 + a2 - 1) / 2;
                    a1 -= e;
                    a2 -= e;
                }
                a1 = a1 < 0 ? 0 : (a1 > 1 ? 1 : a1);
                a2 = a2 < 0 ? 0 : (a2 > 1 ? 1 : a2);
                if (a1 + a2 > 1) a2 = 1 - a1;
                double p[3], rho = 0;
                for (int k = 0; k < 3; k++) {
                    p[k] = (1 - a1 - a2) * pos[3 * tri[3 * t] + k] + a1 * pos[3 * tri[3 * t + 1] + k] +
                           a2 * pos[3 * tri[3 * t + 2] + k] - o->c[b][k];
                    rho += p[k] * p[k];
                }
                rho = sqrt(rho);
                for (int k = 0; k < 3; k++) p[k] /= rho;
                size_t ti = (size_t)y * W + x;
                long qq = lround(asin(o->r[b] / rho) * 255 / 3.14159265358979323846);
                q[ti] = (uint8_t)(qq < 0 ? 0 : (qq > 255 ? 255 : qq));
                octa(p, st + normal_at + 2 * ti);
                if (o->color)
                    for (int k = 0; k < 3; k++)
                        st[normal_at + 2 * texels + 3 * ti + k] = (uint8_t)lround(127.5 + 127.5 * p[k]);
            }
    }
    if (!E) {
        for (size_t ti = 0; ti < texels; ti++) memset(ang + ti * K, q[ti], K);
    } else {
        /* rank one: the mean row 1/16 q below the smallest q; one
         * eigenfunction, 1 at every azimuth, scale 1 q per weight step */
        uint32_t lo = 255;
        for (size_t ti = 0; ti < texels; ti++) lo = q[ti] < lo ? q[ti] : lo;
        uint8_t *mean = ang, *scale = mean + 2 * K, *basis = scale + 4 * E, *w = basis + 2 * E * K;
        for (uint32_t i = 0; i < K; i++) wr16(mean + 2 * i, 16 * lo);
        wr32(scale, 65536);
        for (uint32_t i = 0; i < K; i++) wr16(basis + 2 * i, 16384);
        for (size_t ti = 0; ti < texels; ti++) w[ti * E] = (uint8_t)(int8_t)(q[ti] - lo > 127 ? 127 : q[ti] - lo);
    }
    model_out mo;
    memset(&mo, 0, sizeof mo);
    if (model_add_mesh_doubles(&mo, SILK_SECTION_HULL, 0, nv, pos, nv, nrm, nt, tri, NULL) == 0 &&
        model_add(&mo, SILK_SECTION_STEX, 0, st, size) == 0)
        out = model_bytes(&mo, len);
    model_free(&mo);
done:
    free(s.v);
    free(s.f);
    free(pos);
    free(nrm);
    free(tri);
    free(st);
    free(q);
    return out;
}
