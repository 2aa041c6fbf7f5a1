/*
 * stex_build.c - visibility functions, their single-lobe encoding and the
 * STEX section (stex_build.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "closest.h"
#include "cli/progress.h"
#include "stex_build.h"
#include "vec3.h"

#define PI 3.14159265358979323846
#define STEP (PI / 255)          /* one angle unit */
#define MARCH 4                  /* units per step of the march before halving */
#define CHUNK 64                 /* texels a thread takes at a time */

void stex_opts_default(stex_opts *o)
{
    o->atlas = 128;
    o->angles = 12;
    o->svd = 0;
    o->samples = 512;
    o->threads = 2;
    o->quiet = 0;
}

typedef struct ctx {
    const simp_mesh *fine, *hull;
    const uint32_t *fine_color;  /* or NULL */
    stex *s;
    cp_tree fine_tree, hull_tree;
    double *fine_vn;         /* fine's vertex normals */
    double *hull_fn;         /* hull's unit face normals */
    uint32_t *ntrue;         /* per texel: true samples */
    double eps;              /* hull hits nearer than this are p's own neighbourhood */
    int phase;
    size_t next, done, total;
    pthread_mutex_t lock;
    progress pr;
} ctx;

static void normalize3(double *v)
{
    double l = len3(v);
    if (l > 0) v[0] /= l, v[1] /= l, v[2] /= l;
}

/* The hull point of texel t. */
static void texel_point(const ctx *c, size_t t, double p[3])
{
    const double *b = &c->s->atlas.bary[3 * t];
    const uint32_t *v = &c->hull->tri[3 * (size_t)c->s->atlas.tri[t]];
    for (int k = 0; k < 3; k++)
        p[k] = b[0] * c->hull->pos[3 * v[0] + k] + b[1] * c->hull->pos[3 * v[1] + k] + b[2] * c->hull->pos[3 * v[2] + k];
}

/* Eq. 2 for the point p of hull triangle f. */
static int vf(const ctx *c, const double p[3], uint32_t f, const double d[3])
{
    if (dot3(d, &c->hull_fn[3 * f]) >= 0) return 0;
    double dh = bvh_ray(&c->hull_tree, p, d, c->eps, INFINITY, f, NULL);
    double dm = bvh_ray(&c->fine_tree, p, d, 0, dh, BVH_NO_TRI, NULL);
    return dm < dh;
}

/* The detailed surface's normal at the point of its triangle ft nearest p,
 * octahedral, and its colour there (rgb, when fine has colours). */
static void sample_surface(const ctx *c, const double p[3], uint32_t ft, int8_t out[2], uint8_t *rgb)
{
    const uint32_t *v = &c->fine->tri[3 * (size_t)ft];
    const double *a = &c->fine->pos[3 * v[0]], *b = &c->fine->pos[3 * v[1]], *cc = &c->fine->pos[3 * v[2]];
    double q[3], n[3] = { 0, 0, 0 }, w[3], e0[3], e1[3], e2[3], x[3];
    point_tri_closest(p, a, b, cc, q);
    /* barycentric weights of q from the sub-triangle areas */
    sub3(b, q, e0), sub3(cc, q, e1), cross3(e0, e1, x), w[0] = len3(x);
    sub3(cc, q, e0), sub3(a, q, e2), cross3(e0, e2, x), w[1] = len3(x);
    sub3(a, q, e0), sub3(b, q, e1), cross3(e0, e1, x), w[2] = len3(x);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) n[k] += w[i] * c->fine_vn[3 * v[i] + k];
    normalize3(n);
    if (rgb) {
        double sum = w[0] + w[1] + w[2];
        for (int ch = 0; ch < 3; ch++) {
            double x = 0;
            for (int i = 0; i < 3; i++) x += w[i] * (double)((c->fine_color[v[i]] >> (16 - 8 * ch)) & 0xff);
            rgb[ch] = (uint8_t)lround(sum > 0 ? x / sum : (c->fine_color[v[0]] >> (16 - 8 * ch)) & 0xff);
        }
    }
    double s = fabs(n[0]) + fabs(n[1]) + fabs(n[2]), ox = n[0] / s, oy = n[1] / s;
    if (n[2] < 0) {
        double tx = (1 - fabs(oy)) * (ox < 0 ? -1 : 1), ty = (1 - fabs(ox)) * (oy < 0 ? -1 : 1);
        ox = tx, oy = ty;
    }
    out[0] = (int8_t)lround(ox * 127), out[1] = (int8_t)lround(oy * 127);
}

/* Phase 0 for texel t: the normal, VF at every sample direction. */
static void texel_sample(ctx *c, size_t t)
{
    stex *s = c->s;
    double p[3];
    uint32_t f = (uint32_t)s->atlas.tri[t];
    texel_point(c, t, p);
    uint32_t ft = 0;
    cp_nearest(&c->fine_tree, p, &ft);
    sample_surface(c, p, ft, &s->normal[2 * t], s->colour ? &s->colour[3 * t] : NULL);
    uint8_t *bits = &s->vf[t * (size_t)((s->nsamples + 7) / 8)];
    for (int i = 0; i < s->nsamples; i++) {
        const double *d = &s->samples[3 * i];
        if (!vf(c, p, f, d)) continue;
        bits[i / 8] |= (uint8_t)(1u << (i % 8));
        c->ntrue[t]++;
    }
}

/* Direction at angle a from C along the great circle of unit u (u . C = 0). */
static void along(const double *C, const double *u, double a, double d[3])
{
    for (int k = 0; k < 3; k++) d[k] = cos(a) * C[k] + sin(a) * u[k];
}

/* Phase 1 for texel t: the K angles from the frame at its point. */
static void texel_encode(ctx *c, size_t t)
{
    stex *s = c->s;
    double p[3];
    const double *C = &s->basis[9 * t], *T = C + 3, *B = C + 6;
    uint32_t f = (uint32_t)s->atlas.tri[t];
    uint8_t *q = &s->angles[t * (size_t)s->k];
    texel_point(c, t, p);
    if (c->ntrue[t] == 0) return;    /* no true direction: 0 everywhere */
    /* q where the detailed surface is seen along C, when it is: the point
     * drawn at p from the middle of its lobe, which the nearest point is
     * not where the hull spans a hollow (under an arm) */
    uint32_t ft = BVH_NO_TRI;
    double dh = bvh_ray(&c->hull_tree, p, C, c->eps, INFINITY, f, NULL);
    double dm = bvh_ray(&c->fine_tree, p, C, 0, dh, BVH_NO_TRI, &ft);
    if (dm < dh && dot3(C, &c->hull_fn[3 * f]) < 0) {
        double q[3] = { p[0] + dm * C[0], p[1] + dm * C[1], p[2] + dm * C[2] };
        sample_surface(c, q, ft, &s->normal[2 * t], s->colour ? &s->colour[3 * t] : NULL);
    }
    int multi = 0;
    for (int k = 0; k < s->k; k++) {
        double th = 2 * PI * k / s->k, u[3], d[3];
        for (int i = 0; i < 3; i++) u[i] = cos(th) * T[i] + sin(th) * B[i];
        /* unit j is tested at (j - 1/2) steps: the first false one is the
         * boundary rounded, plus one unit, since the lookup's chords
         * between azimuths and texels fall inside a rounded lobe */
        int lo = -1, hi = -1;        /* last true, first false */
        for (int j = 0; hi < 0 && lo < 254; j = j + MARCH < 254 ? j + MARCH : 254) {
            along(C, u, (j - 0.5) * STEP, d);
            if (vf(c, p, f, d)) lo = j;
            else hi = j;
        }
        if (hi < 0) {                /* true up to the last unit: all round */
            q[k] = 255;
            continue;
        }
        while (hi - lo > 1) {
            int mid = (lo + hi) / 2;
            along(C, u, (mid - 0.5) * STEP, d);
            if (vf(c, p, f, d)) lo = mid;
            else hi = mid;
        }
        if (hi == 0) multi = 1;
        /* single-lobed: false on to where the great circle leaves f's
         * inward side.  Else (C false, or true again further on) the lobe
         * reaches as far as draws the most true and the least false
         * directions along the circle (sin-weighted: their solid angle), so
         * a lobe beside C is drawn rather than dropped. */
        double score = 0, best = 0;
        int reach = hi;
        for (int j = hi + MARCH; j <= 255; j += MARCH) {
            along(C, u, (j + 0.5) * STEP, d);
            if (dot3(d, &c->hull_fn[3 * f]) >= 0) break;
            int seen = vf(c, p, f, d);
            multi |= seen;
            score += (seen ? 1 : -1) * sin((j + 0.5) * STEP);
            if (score > best) best = score, reach = j + MARCH / 2 < 255 ? j + MARCH / 2 : 255;
        }
        q[k] = (uint8_t)reach;
    }
    s->multi[t] = (uint8_t)multi;
}

typedef struct job {
    ctx *c;
    int draws;               /* this thread draws the progress line */
} job;

static void *worker(void *arg)
{
    job *j = arg;
    ctx *c = j->c;
    size_t n = (size_t)c->s->atlas.w * c->s->atlas.h;
    for (;;) {
        pthread_mutex_lock(&c->lock);
        size_t first = c->next;
        c->next += CHUNK;
        pthread_mutex_unlock(&c->lock);
        if (first >= n) break;
        size_t last = first + CHUNK < n ? first + CHUNK : n;
        for (size_t t = first; t < last; t++) {
            if (c->s->atlas.tri[t] < 0) continue;
            if (c->phase == 0) texel_sample(c, t);
            else texel_encode(c, t);
        }
        pthread_mutex_lock(&c->lock);
        c->done += last - first;
        double done = (double)c->done;
        pthread_mutex_unlock(&c->lock);
        if (j->draws) progress_update(&c->pr, (double)c->phase * n + done, 2.0 * n);
    }
    return NULL;
}

#define MAX_THREADS 16

/* One phase over every texel in use, on the calling thread and threads - 1 more. */
static void run_phase(ctx *c, int phase, int threads)
{
    pthread_t th[MAX_THREADS];
    job jobs[MAX_THREADS];
    int ok[MAX_THREADS] = { 0 };
    c->phase = phase, c->next = 0, c->done = 0;
    if (threads > MAX_THREADS) threads = MAX_THREADS;
    for (int i = 1; i < threads; i++) {
        jobs[i] = (job){ c, 0 };
        ok[i] = pthread_create(&th[i], NULL, worker, &jobs[i]) == 0;
    }
    jobs[0] = (job){ c, 1 };
    worker(&jobs[0]);
    for (int i = 1; i < threads; i++)
        if (ok[i]) pthread_join(th[i], NULL);
}

/* Area-weighted vertex normals (unit) and unit face normals of m. */
static void mesh_normals(const simp_mesh *m, double *vn, double *fn)
{
    memset(vn, 0, 3 * (size_t)m->nverts * sizeof *vn);
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *v = &m->tri[3 * (size_t)f];
        double n[3];
        tri_normal(&m->pos[3 * v[0]], &m->pos[3 * v[1]], &m->pos[3 * v[2]], n);
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++) vn[3 * v[i] + k] += n[k];
        normalize3(n);
        if (fn) memcpy(&fn[3 * (size_t)f], n, sizeof n);
    }
    for (uint32_t i = 0; i < m->nverts; i++) normalize3(&vn[3 * (size_t)i]);
}

/* Directions spread evenly over the sphere (a Fibonacci spiral). */
static void sphere_samples(int n, double *d)
{
    double golden = PI * (3 - sqrt(5.0));
    for (int i = 0; i < n; i++) {
        double z = 1 - (2 * i + 1.0) / n, r = sqrt(1 - z * z), a = golden * i;
        d[3 * i] = r * cos(a), d[3 * i + 1] = r * sin(a), d[3 * i + 2] = z;
    }
}

static int16_t q14(double x)
{
    long v = lround(x * 16384);
    return (int16_t)(v > 32767 ? 32767 : v < -32767 ? -32767 : v);
}

/* T for C: the axis least along C, made perpendicular. */
static void axis_tangent(const double C[3], double T[3])
{
    int a = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(C[k]) < fabs(C[a])) a = k;
    double e[3] = { 0, 0, 0 };
    e[a] = 1;
    for (int k = 0; k < 3; k++) T[k] = e[k] - C[a] * C[k];
    normalize3(T);
}

/* C and T at every hull vertex (section 3.3): C the mean of the mean true
 * directions of the texels around the vertex, each weighted by its
 * barycentric weight there, so that C interpolated over a triangle follows
 * its texels' lobes (where no texel around it sees the detailed mesh: the
 * mean true direction of VF at the vertex itself among VERTEX_SAMPLES
 * directions, no hull triangle its own there; else inward along the vertex
 * normal), then turned into every triangle around the vertex (inward());
 * T carried over the hull breadth first, each vertex taking its visited
 * neighbours' T turned into its own tangent plane.  Stored rounded to
 * Q1.14. */
#define VERTEX_SAMPLES 4096

/* C of vertex v turned, where it can be, to point into every hull triangle
 * around v (C.n below -INWARD for each), so that C interpolated anywhere
 * on those triangles points into them too: a C out of a point's own
 * triangle is false there, and the lobe about it holds nothing. */
#define INWARD 0.25
static void inward(const simp_mesh *h, const double *fn, uint32_t v, double C[3])
{
    for (int pass = 0; pass < 8; pass++) {
        int moved = 0;
        for (uint32_t f = 0; f < h->ntris; f++) {
            const uint32_t *t = &h->tri[3 * (size_t)f];
            if (t[0] != v && t[1] != v && t[2] != v) continue;
            double a = dot3(C, &fn[3 * (size_t)f]) + INWARD;
            if (a <= 0) continue;
            for (int k = 0; k < 3; k++) C[k] -= a * fn[3 * (size_t)f + k];
            normalize3(C);
            moved = 1;
        }
        if (!moved) break;
    }
}
static int vertex_frames(ctx *c, const double *hull_vn)
{
    const simp_mesh *h = c->hull;
    stex *s = c->s;
    double *dirs = malloc(3 * VERTEX_SAMPLES * sizeof *dirs), *Cv = calloc(3 * (size_t)h->nverts + 1, sizeof *Cv);
    double *Tv = calloc(3 * (size_t)h->nverts + 1, sizeof *Tv);
    uint32_t *start = calloc((size_t)h->nverts + 2, sizeof *start), *adj = malloc(6 * (size_t)h->ntris * sizeof *adj + 1);
    uint32_t *queue = malloc(((size_t)h->nverts + 1) * sizeof *queue), *fillp = calloc((size_t)h->nverts + 1, sizeof *fillp);
    uint8_t *seen = calloc((size_t)h->nverts + 1, 1), *set = calloc((size_t)h->nverts + 1, 1);
    int rc = -1;
    if (!dirs || !Cv || !Tv || !start || !adj || !queue || !fillp || !seen || !set) goto done;
    sphere_samples(VERTEX_SAMPLES, dirs);
    size_t nt = (size_t)s->atlas.w * s->atlas.h, row = (size_t)(s->nsamples + 7) / 8;
    for (size_t t = 0; t < nt; t++) {
        if (s->atlas.tri[t] < 0 || !s->atlas.inside[t] || c->ntrue[t] == 0) continue;
        double m[3] = { 0, 0, 0 };
        for (int i = 0; i < s->nsamples; i++)
            if ((s->vf[t * row + i / 8] >> (i % 8)) & 1)
                for (int k = 0; k < 3; k++) m[k] += s->samples[3 * i + k];
        normalize3(m);
        const uint32_t *v = &h->tri[3 * (size_t)s->atlas.tri[t]];
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++) Cv[3 * (size_t)v[i] + k] += s->atlas.bary[3 * t + i] * m[k];
    }
    for (uint32_t i = 0; i < h->nverts; i++) {
        double *C = &Cv[3 * (size_t)i];
        const double *p = &h->pos[3 * (size_t)i];
        int cast = len3(C) < 1e-9;   /* no texel near it sees the model */
        for (int j = 0; cast && j < VERTEX_SAMPLES; j++) {
            const double *d = &dirs[3 * j];
            double dh = bvh_ray(&c->hull_tree, p, d, c->eps, INFINITY, BVH_NO_TRI, NULL);
            if (bvh_ray(&c->fine_tree, p, d, 0, dh, BVH_NO_TRI, NULL) < dh)
                for (int k = 0; k < 3; k++) C[k] += d[k];
        }
        if (len3(C) < 1e-9)
            for (int k = 0; k < 3; k++) C[k] = -hull_vn[3 * (size_t)i + k];
        normalize3(C);
        inward(h, c->hull_fn, i, C);
        for (int k = 0; k < 3; k++) s->frame[6 * (size_t)i + k] = q14(C[k]);
        for (int k = 0; k < 3; k++) C[k] = s->frame[6 * (size_t)i + k] / 16384.0;
        normalize3(C);
    }
    /* vertex neighbours, both ways round every edge */
    for (uint32_t f = 0; f < h->ntris; f++)
        for (int e = 0; e < 3; e++) start[h->tri[3 * (size_t)f + e] + 1] += 2;
    for (uint32_t i = 0; i < h->nverts; i++) start[i + 1] += start[i];
    for (uint32_t f = 0; f < h->ntris; f++)
        for (int e = 0; e < 3; e++) {
            uint32_t a = h->tri[3 * (size_t)f + e], b = h->tri[3 * (size_t)f + (e + 1) % 3];
            adj[start[a] + fillp[a]++] = b;
            adj[start[b] + fillp[b]++] = a;
        }
    for (uint32_t seed = 0; seed < h->nverts; seed++) {
        if (seen[seed]) continue;
        uint32_t head = 0, tail = 0;
        queue[tail++] = seed;
        seen[seed] = 1;
        while (head < tail) {
            uint32_t v = queue[head++];
            double *C = &Cv[3 * (size_t)v], *T = &Tv[3 * (size_t)v], sum[3] = { 0, 0, 0 };
            for (uint32_t j = start[v]; j < start[v + 1]; j++) {
                uint32_t o = adj[j];
                if (set[o])
                    for (int k = 0; k < 3; k++) sum[k] += Tv[3 * (size_t)o + k];
                else if (!seen[o])
                    seen[o] = 1, queue[tail++] = o;
            }
            double along_c = dot3(sum, C);
            for (int k = 0; k < 3; k++) sum[k] -= along_c * C[k];
            if (len3(sum) > 1e-6) {
                memcpy(T, sum, sizeof sum);
                normalize3(T);
            } else {
                axis_tangent(C, T);
            }
            set[v] = 1;
            for (int k = 0; k < 3; k++) s->frame[6 * (size_t)v + 3 + k] = q14(T[k]);
        }
    }
    rc = 0;
done:
    free(dirs), free(Cv), free(Tv), free(start), free(adj), free(queue), free(fillp), free(seen), free(set);
    return rc;
}

/* C, T', B at texel t's point from the stored vertex frames (the renderer's
 * rule, docs/formats.md). */
static void texel_basis(stex *s, const simp_mesh *h, size_t t)
{
    double *C = &s->basis[9 * t], *T = C + 3, *B = C + 6;
    const double *b = &s->atlas.bary[3 * t];
    const uint32_t *v = &h->tri[3 * (size_t)s->atlas.tri[t]];
    for (int k = 0; k < 3; k++) {
        C[k] = T[k] = 0;
        for (int i = 0; i < 3; i++) {
            C[k] += b[i] * s->frame[6 * (size_t)v[i] + k] / 16384.0;
            T[k] += b[i] * s->frame[6 * (size_t)v[i] + 3 + k] / 16384.0;
        }
    }
    normalize3(C);
    double tc = dot3(T, C);
    for (int k = 0; k < 3; k++) T[k] -= tc * C[k];
    if (len3(T) < 1e-9) axis_tangent(C, T);
    normalize3(T);
    cross3(C, T, B);
}

double stex_phi(const stex *s, const uint8_t *angles, size_t t, const double d[3])
{
    const double *C = &s->basis[9 * t], *T = C + 3, *B = C + 6;
    double th = atan2(dot3(d, B), dot3(d, T));
    if (th < 0) th += 2 * PI;
    double x = th * s->k / (2 * PI);
    int k0 = (int)floor(x);
    double f = x - k0;
    k0 %= s->k;
    const uint8_t *q = &angles[t * (size_t)s->k];
    return ((1 - f) * q[k0] + f * q[(k0 + 1) % s->k]) * STEP;
}

double stex_error(const stex *s, const uint8_t *angles)
{
    size_t nt = (size_t)s->atlas.w * s->atlas.h, row = (size_t)(s->nsamples + 7) / 8;
    double sum = 0;
    uint32_t n = 0;
    for (size_t t = 0; t < nt; t++) {
        if (s->atlas.tri[t] < 0 || !s->atlas.inside[t]) continue;
        const uint8_t *bits = &s->vf[t * row];
        int wrong = 0;
        for (int i = 0; i < s->nsamples; i++) {
            const double *d = &s->samples[3 * i];
            double z = dot3(d, &s->basis[9 * t]);
            int drawn = acos(z > 1 ? 1 : z < -1 ? -1 : z) <= stex_phi(s, angles, t, d);
            wrong += drawn != ((bits[i / 8] >> (i % 8)) & 1);
        }
        sum += (double)wrong / s->nsamples;
        n++;
    }
    return n ? sum / n : 0;
}

double stex_psnr(const stex *s, const uint8_t *angles)
{
    size_t nt = (size_t)s->atlas.w * s->atlas.h;
    double se = 0, n = 0;
    for (size_t t = 0; t < nt; t++) {
        if (s->atlas.tri[t] < 0) continue;
        for (int k = 0; k < s->k; k++) {
            double d = (double)angles[t * s->k + k] - s->angles[t * s->k + k];
            se += d * d;
            n++;
        }
    }
    return se > 0 ? 10 * log10(255.0 * 255.0 / (se / n)) : INFINITY;
}

int stex_build(const simp_mesh *fine, const uint32_t *fine_color, const simp_mesh *hull, const stex_opts *o, stex *s)
{
    memset(s, 0, sizeof *s);
    ctx c;
    memset(&c, 0, sizeof c);
    c.fine = fine, c.fine_color = fine_color, c.hull = hull, c.s = s;
    int rc = stex_atlas_build(hull, o->atlas, o->atlas, &s->atlas);
    if (rc) return rc;
    size_t nt = (size_t)o->atlas * o->atlas, row = (size_t)(o->samples + 7) / 8;
    s->k = o->angles, s->nsamples = o->samples, s->nverts = hull->nverts, s->ntris = hull->ntris;
    s->frame = calloc(6 * (size_t)hull->nverts + 1, sizeof *s->frame);
    s->angles = calloc(nt * o->angles, 1);
    s->normal = calloc(2 * nt, 1);
    s->basis = calloc(9 * nt, sizeof *s->basis);
    s->samples = malloc(3 * (size_t)o->samples * sizeof *s->samples);
    s->vf = calloc(nt * row, 1);
    s->multi = calloc(nt, 1);
    s->colour = fine_color ? calloc(3 * nt, 1) : NULL;
    c.fine_vn = malloc(3 * (size_t)fine->nverts * sizeof *c.fine_vn + 1);
    c.hull_fn = malloc(3 * (size_t)hull->ntris * sizeof *c.hull_fn + 1);
    double *hull_vn = malloc(3 * (size_t)hull->nverts * sizeof *hull_vn + 1);
    c.ntrue = calloc(nt, sizeof *c.ntrue);
    rc = -1;
    if (!s->frame || !s->angles || !s->normal || !s->basis || !s->samples || !s->vf || !s->multi || (fine_color && !s->colour) || !c.fine_vn ||
        !c.hull_fn || !hull_vn || !c.ntrue)
        goto done;
    if (cp_build(&c.fine_tree, fine->pos, fine->tri, fine->ntris)) goto done;
    if (cp_build(&c.hull_tree, hull->pos, hull->tri, hull->ntris)) goto done;
    mesh_normals(fine, c.fine_vn, NULL);
    mesh_normals(hull, hull_vn, c.hull_fn);
    sphere_samples(o->samples, s->samples);
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = hull->pos[k];
    for (uint32_t i = 0; i < hull->nverts; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], hull->pos[3 * i + k]), hi[k] = fmax(hi[k], hull->pos[3 * i + k]);
    double diag[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
    c.eps = 1e-7 * len3(diag);
    pthread_mutex_init(&c.lock, NULL);
    progress_start(&c.pr, o->quiet, "siltex");
    run_phase(&c, 0, o->threads);
    if (vertex_frames(&c, hull_vn) == 0) {
        for (size_t t = 0; t < nt; t++)
            if (s->atlas.tri[t] >= 0) texel_basis(s, hull, t);
        run_phase(&c, 1, o->threads);
        rc = 0;
    }
    progress_end(&c.pr);
    pthread_mutex_destroy(&c.lock);
    if (rc == 0) {
        uint32_t multi = 0;
        for (size_t t = 0; t < nt; t++)
            if (s->atlas.tri[t] >= 0 && s->atlas.inside[t]) s->texels_in++, multi += s->multi[t];
        s->multi_share = s->texels_in ? (double)multi / s->texels_in : 0;
        s->error = stex_error(s, s->angles);
    }
done:
    cp_free(&c.fine_tree);
    cp_free(&c.hull_tree);
    free(c.fine_vn), free(c.hull_fn), free(hull_vn), free(c.ntrue);
    if (rc) stex_free(s);
    return rc;
}

void stex_free(stex *s)
{
    stex_atlas_free(&s->atlas);
    free(s->frame), free(s->angles), free(s->normal), free(s->basis), free(s->samples), free(s->vf), free(s->multi), free(s->colour);
    memset(s, 0, sizeof *s);
}

static uint8_t *put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8);
    return p + 2;
}

static uint8_t *put32(uint8_t *p, uint32_t v)
{
    return put16(put16(p, v & 0xffff), v >> 16);
}

size_t stex_section_bytes(const stex *s, int svd_e)
{
    size_t nt = (size_t)s->atlas.w * s->atlas.h;
    size_t n = 32 + 12 * (size_t)s->nverts + 12 * (size_t)s->ntris;
    if (svd_e) n += stex_svd_bytes(s->k, svd_e, (uint32_t)nt), n += n & 1;
    else n += nt * s->k;
    n += 2 * nt;
    if (s->colour) n += 3 * nt;
    return (n + 3) & ~(size_t)3;
}

uint8_t *stex_section(const stex *s, const stex_svd *svd, double error, size_t *size)
{
    size_t nt = (size_t)s->atlas.w * s->atlas.h;
    *size = stex_section_bytes(s, svd ? svd->e : 0);
    uint8_t *b = calloc(*size, 1), *p = b;
    if (!b) return NULL;
    p = put32(p, STEX_VERSION);
    p = put32(p, (svd ? STEX_FLAG_SVD : 0) | (s->colour ? STEX_FLAG_COLOUR : 0));
    p = put16(p, (uint32_t)s->atlas.w), p = put16(p, (uint32_t)s->atlas.h);
    p = put16(p, (uint32_t)s->k), p = put16(p, svd ? (uint32_t)svd->e : 0);
    p = put32(p, s->nverts), p = put32(p, s->ntris);
    p = put32(p, (uint32_t)lround(error * 1e6)), p = put32(p, (uint32_t)lround(s->multi_share * 1e6));
    for (size_t i = 0; i < 6 * (size_t)s->nverts; i++) p = put16(p, (uint16_t)s->frame[i]);
    for (size_t i = 0; i < 6 * (size_t)s->ntris; i++) p = put16(p, s->atlas.uv[i]);
    if (svd) {
        for (int i = 0; i < svd->k; i++) p = put16(p, (uint16_t)svd->mean[i]);
        for (int i = 0; i < svd->e; i++) p = put32(p, (uint32_t)svd->s[i]);
        for (int i = 0; i < svd->e * svd->k; i++) p = put16(p, (uint16_t)svd->v[i]);
        for (size_t i = 0; i < nt * svd->e; i++) *p++ = (uint8_t)svd->w[i];
        if ((p - b) & 1) p++;
    } else {
        memcpy(p, s->angles, nt * s->k);
        p += nt * s->k;
    }
    for (size_t i = 0; i < 2 * nt; i++) *p++ = (uint8_t)s->normal[i];
    if (s->colour) memcpy(p, s->colour, 3 * nt);
    return b;
}
