/*
 * simplify.c - quadric-error edge collapse (Garland & Heckbert, "Surface
 * simplification using quadric error metrics", SIGGRAPH 1997).
 *
 * Every vertex carries the sum of the squared-distance quadrics of the
 * planes of its faces (weighted by area) and, along feature edges, of
 * constraint planes through the edge (weighted by feature_weight times the
 * squared edge length, so both scale alike).  The cheapest edge is
 * collapsed to the point that minimises the summed quadric, if that keeps
 * the surface a manifold without turned-over triangles; then the costs of
 * the edges around the new vertex are recomputed.  The heap is lazy: every
 * vertex has a stamp that changes when it moves, and an entry whose stamps
 * are old is dropped when it comes up.  Refused collapses are tried again
 * once the heap runs dry, since their neighbourhood may have changed.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "simplify.h"
#include "vec3.h"

void simp_opts_default(simp_opts *o, uint32_t target_tris)
{
    o->target_tris = target_tris;
    o->crease_deg = 60;
    o->feature_weight = 100;
    o->subset = 0;
    o->progress = NULL;
    o->progress_user = NULL;
}

void simp_free(simp_mesh *m)
{
    free(m->pos);
    free(m->tri);
    free(m->origin);
    memset(m, 0, sizeof *m);
}

int simp_copy(const simp_mesh *m, simp_mesh *out)
{
    memset(out, 0, sizeof *out);
    out->pos = malloc(3 * (size_t)(m->nverts ? m->nverts : 1) * sizeof *out->pos);
    out->tri = malloc(3 * (size_t)(m->ntris ? m->ntris : 1) * sizeof *out->tri);
    if (!out->pos || !out->tri) {
        simp_free(out);
        return -1;
    }
    memcpy(out->pos, m->pos, 3 * (size_t)m->nverts * sizeof *out->pos);
    memcpy(out->tri, m->tri, 3 * (size_t)m->ntris * sizeof *out->tri);
    out->nverts = m->nverts;
    out->ntris = m->ntris;
    return 0;
}

/* ---- quadrics --------------------------------------------------------------- */

/* The symmetric 4x4 matrix, upper triangle: 00 01 02 03 11 12 13 22 23 33. */
typedef struct quadric { double a[10]; } quadric;

/* q += w * (p p^T) for the plane p = (n, d): n.x + d = 0, |n| = 1. */
static void q_add_plane(quadric *q, const double n[3], double d, double w)
{
    const double p[4] = { n[0], n[1], n[2], d };
    int k = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i; j < 4; j++) q->a[k++] += w * p[i] * p[j];
}

static void q_add(quadric *q, const quadric *r)
{
    for (int k = 0; k < 10; k++) q->a[k] += r->a[k];
}

/* v^T Q v for v = (x, y, z, 1): the weighted sum of squared distances. */
static double q_eval(const quadric *q, const double x[3])
{
    const double *a = q->a;
    return a[0] * x[0] * x[0] + 2 * a[1] * x[0] * x[1] + 2 * a[2] * x[0] * x[2] + 2 * a[3] * x[0] +
           a[4] * x[1] * x[1] + 2 * a[5] * x[1] * x[2] + 2 * a[6] * x[1] + a[7] * x[2] * x[2] + 2 * a[8] * x[2] +
           a[9];
}

/* The minimiser of q: solve A x = -b by Cramer's rule; 0 when A is too
 * close to singular (a flat or straight neighbourhood) to trust. */
static int q_minimum(const quadric *q, double x[3])
{
    const double *a = q->a;
    double m00 = a[0], m01 = a[1], m02 = a[2], m11 = a[4], m12 = a[5], m22 = a[7];
    double b0 = -a[3], b1 = -a[6], b2 = -a[8];
    double c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
    double det = m00 * c00 + m01 * c01 + m02 * c02;
    double tr = (m00 + m11 + m22) / 3;
    if (!(fabs(det) > 1e-10 * tr * tr * tr)) return 0;
    double c11 = m00 * m22 - m02 * m02, c12 = m01 * m02 - m00 * m12, c22 = m00 * m11 - m01 * m01;
    x[0] = (c00 * b0 + c01 * b1 + c02 * b2) / det;
    x[1] = (c01 * b0 + c11 * b1 + c12 * b2) / det;
    x[2] = (c02 * b0 + c12 * b1 + c22 * b2) / det;
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

/* 1 for an equilateral triangle, 0 for a degenerate one. */
static double tri_quality(const double *a, const double *b, const double *c)
{
    double n[3], e[3], s = 0;
    tri_normal(a, b, c, n);
    sub3(b, a, e), s += dot3(e, e);
    sub3(c, b, e), s += dot3(e, e);
    sub3(a, c, e), s += dot3(e, e);
    return s > 0 ? 2 * sqrt(3.0) * len3(n) / s : 0;
}

/* ---- growable arrays ------------------------------------------------------------ */

typedef struct ulist { uint32_t *v; uint32_t n, cap; } ulist;

static int ulist_push(ulist *l, uint32_t x)
{
    if (l->n == l->cap) {
        uint32_t cap = l->cap ? 2 * l->cap : 8;
        uint32_t *v = realloc(l->v, cap * sizeof *v);
        if (!v) return -1;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = x;
    return 0;
}

static void ulist_remove(ulist *l, uint32_t x)
{
    for (uint32_t i = 0; i < l->n; i++)
        if (l->v[i] == x) {
            l->v[i] = l->v[--l->n];
            return;
        }
}

/* ---- the heap of candidate collapses -------------------------------------------- */

typedef struct cand {
    double cost;
    double w[3];               /* where the merged vertex goes */
    uint32_t u, v;             /* the edge */
    uint32_t su, sv;           /* the end points' stamps when it was priced */
} cand;

typedef struct heap { cand *c; size_t n, cap; } heap;

static int heap_push(heap *h, const cand *c)
{
    if (h->n == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 1024;
        cand *p = realloc(h->c, cap * sizeof *p);
        if (!p) return -1;
        h->c = p;
        h->cap = cap;
    }
    size_t i = h->n++;
    while (i > 0 && h->c[(i - 1) / 2].cost > c->cost) {
        h->c[i] = h->c[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->c[i] = *c;
    return 0;
}

static cand heap_pop(heap *h)
{
    cand top = h->c[0], last = h->c[--h->n];
    size_t i = 0;
    for (;;) {
        size_t k = 2 * i + 1;
        if (k >= h->n) break;
        if (k + 1 < h->n && h->c[k + 1].cost < h->c[k].cost) k++;
        if (h->c[k].cost >= last.cost) break;
        h->c[i] = h->c[k];
        i = k;
    }
    if (h->n) h->c[i] = last;
    return top;
}

/* ---- state ------------------------------------------------------------------------ */

typedef struct state {
    const simp_opts *o;
    simp_stats *st;
    uint32_t nv, nt, alive_tris;
    double *pos;
    uint32_t *tri;
    quadric *q;
    ulist *vf;                 /* faces of each vertex */
    uint32_t *stamp;
    uint8_t *vdead, *tdead;
    uint32_t *mark, gen;       /* vertex marks for set operations */
    heap h;
    cand *deferred;            /* refused collapses, tried again later */
    size_t ndef, capdef;
    ulist nu, nv_, tmp;        /* scratch neighbour lists */
} state;

static int tri_has(const state *s, uint32_t f, uint32_t x)
{
    const uint32_t *t = &s->tri[3 * f];
    return t[0] == x || t[1] == x || t[2] == x;
}

/* The vertices sharing a face with x (x itself excluded). */
static int neighbours(state *s, uint32_t x, ulist *out)
{
    out->n = 0;
    s->gen++;
    for (uint32_t i = 0; i < s->vf[x].n; i++) {
        const uint32_t *t = &s->tri[3 * s->vf[x].v[i]];
        for (int k = 0; k < 3; k++)
            if (t[k] != x && s->mark[t[k]] != s->gen) {
                s->mark[t[k]] = s->gen;
                if (ulist_push(out, t[k])) return -1;
            }
    }
    return 0;
}

/* Faces of edge (x, y). */
static uint32_t edge_faces(const state *s, uint32_t x, uint32_t y)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->vf[x].n; i++) n += tri_has(s, s->vf[x].v[i], y);
    return n;
}

/* A vertex with an edge that has one face. */
static int on_boundary(state *s, uint32_t x)
{
    if (neighbours(s, x, &s->tmp)) return -1;
    for (uint32_t i = 0; i < s->tmp.n; i++)
        if (edge_faces(s, x, s->tmp.v[i]) == 1) return 1;
    return 0;
}

/* Price the collapse of edge (u, v): the quadric minimum, unless it is
 * unreliable or far from the edge, else the best of the ends and middle. */
static void price(const state *s, uint32_t u, uint32_t v, cand *c)
{
    quadric q = s->q[u];
    q_add(&q, &s->q[v]);
    const double *pu = &s->pos[3 * u], *pv = &s->pos[3 * v];
    double mid[3] = { (pu[0] + pv[0]) / 2, (pu[1] + pv[1]) / 2, (pu[2] + pv[2]) / 2 }, e[3], x[3], d[3];
    sub3(pv, pu, e);
    double best = INFINITY;
    if (!s->o->subset && q_minimum(&q, x)) {
        sub3(x, mid, d);
        if (len3(d) <= len3(e)) {
            best = q_eval(&q, x);
            memcpy(c->w, x, sizeof x);
        }
    }
    const double *opt[3] = { pu, pv, mid };
    for (int k = 0; k < (s->o->subset ? 2 : 3); k++) {
        double cost = q_eval(&q, opt[k]);
        if (cost < best) {
            best = cost;
            memcpy(c->w, opt[k], sizeof c->w);
        }
    }
    c->cost = best > 0 ? best : 0;
    c->u = u;
    c->v = v;
    c->su = s->stamp[u];
    c->sv = s->stamp[v];
}

static int push_edge(state *s, uint32_t u, uint32_t v)
{
    cand c;
    price(s, u, v, &c);
    return heap_push(&s->h, &c);
}

enum { OK = 0, STALE, REFUSE_TOPOLOGY, REFUSE_SHAPE, NOMEM };

/* Would collapsing edge (u, v) to w keep the surface a manifold with no
 * triangle turned over or squashed? */
static int check(state *s, const cand *c)
{
    uint32_t u = c->u, v = c->v;
    uint32_t opp[2], k = 0;
    for (uint32_t i = 0; i < s->vf[u].n; i++) {
        const uint32_t f = s->vf[u].v[i], *t = &s->tri[3 * f];
        if (!tri_has(s, f, v)) continue;
        if (k == 2) return REFUSE_TOPOLOGY;   /* a non-manifold edge */
        opp[k++] = t[0] != u && t[0] != v ? t[0] : t[1] != u && t[1] != v ? t[1] : t[2];
    }
    if (k == 0) return STALE;

    /* Link condition: the common neighbours of u and v are exactly the
     * vertices opposite the edge. */
    if (neighbours(s, u, &s->nu) || neighbours(s, v, &s->nv_)) return NOMEM;
    s->gen++;
    for (uint32_t i = 0; i < s->nu.n; i++) s->mark[s->nu.v[i]] = s->gen;
    uint32_t common = 0;
    for (uint32_t i = 0; i < s->nv_.n; i++) {
        uint32_t x = s->nv_.v[i];
        if (s->mark[x] != s->gen) continue;
        common++;
        if (x != opp[0] && (k < 2 || x != opp[1])) return REFUSE_TOPOLOGY;
    }
    if (common != k) return REFUSE_TOPOLOGY;

    int bu = on_boundary(s, u), bv = on_boundary(s, v);
    if (bu < 0 || bv < 0) return NOMEM;
    if (k == 2 && bu && bv) return REFUSE_TOPOLOGY;   /* would pinch two boundary loops */
    uint32_t deg_w = s->nu.n - 1 + s->nv_.n - 1 - common;
    if (deg_w < (uint32_t)(bu || bv ? 2 : 3)) return REFUSE_TOPOLOGY;
    for (uint32_t i = 0; i < k; i++) {
        int bx = on_boundary(s, opp[i]);
        if (bx < 0) return NOMEM;
        if (neighbours(s, opp[i], &s->tmp)) return NOMEM;
        if (s->tmp.n - 1 < (uint32_t)(bx ? 2 : 3)) return REFUSE_TOPOLOGY;
    }

    /* Shape: the faces that stay must keep their side and some area. */
    for (int side = 0; side < 2; side++) {
        uint32_t x = side ? v : u;
        for (uint32_t i = 0; i < s->vf[x].n; i++) {
            uint32_t f = s->vf[x].v[i];
            if (tri_has(s, f, side ? u : v)) continue;   /* removed by the collapse */
            const uint32_t *t = &s->tri[3 * f];
            const double *p[3], *np[3];
            for (int j = 0; j < 3; j++) {
                p[j] = &s->pos[3 * t[j]];
                np[j] = t[j] == x ? c->w : p[j];
            }
            double n0[3], n1[3];
            tri_normal(p[0], p[1], p[2], n0);
            tri_normal(np[0], np[1], np[2], n1);
            double l0 = len3(n0), l1 = len3(n1);
            if (!(l1 > 0) || dot3(n0, n1) < 0.2 * l0 * l1) return REFUSE_SHAPE;
            double q1 = tri_quality(np[0], np[1], np[2]);
            if (q1 < 0.05 && q1 < tri_quality(p[0], p[1], p[2])) return REFUSE_SHAPE;
        }
    }
    return OK;
}

/* Merge v into u at w: faces on the edge die, v's other faces move to u,
 * and every edge at u is priced again. */
static int collapse(state *s, const cand *c)
{
    uint32_t u = c->u, v = c->v;
    if (s->o->subset) {
        /* the survivor is the end the edge collapses onto, so it keeps its
         * identity (and its place on the input surface) */
        if (memcmp(c->w, &s->pos[3 * v], sizeof c->w) == 0) {
            u = c->v;
            v = c->u;
        }
    } else if (s->vf[v].n > s->vf[u].n) {   /* keep the vertex with more faces: less to move */
        uint32_t t = u;
        u = v;
        v = t;
    }
    memcpy(&s->pos[3 * u], c->w, sizeof c->w);
    q_add(&s->q[u], &s->q[v]);
    s->stamp[u]++;
    s->vdead[v] = 1;
    for (uint32_t i = 0; i < s->vf[v].n; i++) {
        uint32_t f = s->vf[v].v[i], *t = &s->tri[3 * f];
        if (tri_has(s, f, u)) {
            s->tdead[f] = 1;
            s->alive_tris--;
            for (int k = 0; k < 3; k++)
                if (t[k] != v) ulist_remove(&s->vf[t[k]], f);
        } else {
            for (int k = 0; k < 3; k++)
                if (t[k] == v) t[k] = u;
            if (ulist_push(&s->vf[u], f)) return -1;
        }
    }
    free(s->vf[v].v);
    memset(&s->vf[v], 0, sizeof s->vf[v]);
    s->st->collapses++;
    if (neighbours(s, u, &s->nu)) return -1;
    for (uint32_t i = 0; i < s->nu.n; i++)
        if (push_edge(s, u, s->nu.v[i])) return -1;
    return 0;
}

/* Face quadrics, then constraint planes along boundary and crease edges. */
static int init_quadrics(state *s)
{
    double cos_crease = cos(s->o->crease_deg * CLI_DEG);
    for (uint32_t f = 0; f < s->nt; f++) {
        const uint32_t *t = &s->tri[3 * f];
        double n[3];
        tri_normal(&s->pos[3 * t[0]], &s->pos[3 * t[1]], &s->pos[3 * t[2]], n);
        double l = len3(n);
        if (!(l > 0)) continue;
        for (int k = 0; k < 3; k++) n[k] /= l;
        double d = -dot3(n, &s->pos[3 * t[0]]);
        for (int k = 0; k < 3; k++) q_add_plane(&s->q[t[k]], n, d, l / 2);
    }
    for (uint32_t u = 0; u < s->nv; u++) {
        if (neighbours(s, u, &s->nu)) return -1;
        for (uint32_t i = 0; i < s->nu.n; i++) {
            uint32_t v = s->nu.v[i];
            if (v < u) continue;
            uint32_t faces[2], k = 0;
            for (uint32_t j = 0; j < s->vf[u].n && k < 3; j++)
                if (tri_has(s, s->vf[u].v[j], v)) {
                    if (k < 2) faces[k] = s->vf[u].v[j];
                    k++;
                }
            if (k > 2) continue;   /* non-manifold: its collapses are refused anyway */
            double nrm[2][3], e[3];
            for (uint32_t j = 0; j < k; j++) {
                const uint32_t *t = &s->tri[3 * faces[j]];
                tri_normal(&s->pos[3 * t[0]], &s->pos[3 * t[1]], &s->pos[3 * t[2]], nrm[j]);
            }
            int feature = k == 1 || dot3(nrm[0], nrm[1]) < cos_crease * len3(nrm[0]) * len3(nrm[1]);
            if (!feature) continue;
            s->st->feature_edges++;
            sub3(&s->pos[3 * v], &s->pos[3 * u], e);
            double el = len3(e);
            for (uint32_t j = 0; j < k; j++) {
                double m[3];
                cross3(e, nrm[j], m);
                double ml = len3(m);
                if (!(ml > 0)) continue;
                for (int c = 0; c < 3; c++) m[c] /= ml;
                double d = -dot3(m, &s->pos[3 * u]);
                q_add_plane(&s->q[u], m, d, s->o->feature_weight * el * el);
                q_add_plane(&s->q[v], m, d, s->o->feature_weight * el * el);
            }
        }
    }
    return 0;
}

static void state_free(state *s)
{
    if (s->vf)
        for (uint32_t i = 0; i < s->nv; i++) free(s->vf[i].v);
    free(s->vf), free(s->q), free(s->stamp), free(s->vdead), free(s->tdead), free(s->mark);
    free(s->h.c), free(s->deferred), free(s->nu.v), free(s->nv_.v), free(s->tmp.v);
    free(s->pos), free(s->tri);
}

static int defer(state *s, const cand *c)
{
    if (s->ndef == s->capdef) {
        size_t cap = s->capdef ? 2 * s->capdef : 256;
        cand *p = realloc(s->deferred, cap * sizeof *p);
        if (!p) return -1;
        s->deferred = p;
        s->capdef = cap;
    }
    s->deferred[s->ndef++] = *c;
    return 0;
}

static int run(state *s)
{
    if (init_quadrics(s)) return -1;
    for (uint32_t u = 0; u < s->nv; u++) {
        if (neighbours(s, u, &s->nu)) return -1;
        for (uint32_t i = 0; i < s->nu.n; i++)
            if (s->nu.v[i] > u && push_edge(s, u, s->nu.v[i])) return -1;
    }
    uint32_t since_retry = 0;
    while (s->alive_tris > s->o->target_tris) {
        if (s->h.n == 0) {
            /* Refused collapses may be fine now that their neighbourhood
             * changed; stop once a whole round brings nothing. */
            if (s->ndef == 0 || since_retry == 0) break;
            since_retry = 0;
            size_t n = s->ndef;
            s->ndef = 0;
            for (size_t i = 0; i < n; i++) {
                const cand *d = &s->deferred[i];
                if (!s->vdead[d->u] && !s->vdead[d->v] && push_edge(s, d->u, d->v)) return -1;
            }
            continue;
        }
        cand c = heap_pop(&s->h);
        if (s->vdead[c.u] || s->vdead[c.v] || c.su != s->stamp[c.u] || c.sv != s->stamp[c.v]) continue;
        int r = check(s, &c);
        if (r == NOMEM) return -1;
        if (r == STALE) continue;
        if (r != OK) {
            if (r == REFUSE_TOPOLOGY) s->st->refused_topology++;
            else s->st->refused_shape++;
            if (defer(s, &c)) return -1;
            continue;
        }
        if (collapse(s, &c)) return -1;
        since_retry++;
        if (s->o->progress) s->o->progress(s->o->progress_user, s->nt, s->alive_tris);
    }
    return 0;
}

/* Copy m into a fresh state with the vertex -> face lists; 0 or -1. */
static int state_init(state *s, const simp_mesh *m, const simp_opts *o, simp_stats *st)
{
    memset(s, 0, sizeof *s);
    s->o = o;
    s->st = st;
    s->nv = m->nverts;
    s->nt = m->ntris;
    s->alive_tris = m->ntris;
    size_t nv = s->nv ? s->nv : 1, nt = s->nt ? s->nt : 1;
    s->pos = malloc(3 * nv * sizeof *s->pos);
    s->tri = malloc(3 * nt * sizeof *s->tri);
    s->q = calloc(nv, sizeof *s->q);
    s->vf = calloc(nv, sizeof *s->vf);
    s->stamp = calloc(nv, sizeof *s->stamp);
    s->vdead = calloc(nv, 1);
    s->tdead = calloc(nt, 1);
    s->mark = calloc(nv, sizeof *s->mark);
    if (!s->pos || !s->tri || !s->q || !s->vf || !s->stamp || !s->vdead || !s->tdead || !s->mark) return -1;
    memcpy(s->pos, m->pos, 3 * (size_t)s->nv * sizeof *s->pos);
    memcpy(s->tri, m->tri, 3 * (size_t)s->nt * sizeof *s->tri);
    for (uint32_t f = 0; f < s->nt; f++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = s->tri[3 * f + k];
            /* a face listed once per distinct vertex */
            if ((k > 0 && x == s->tri[3 * f]) || (k > 1 && x == s->tri[3 * f + 1])) continue;
            if (ulist_push(&s->vf[x], f)) return -1;
        }
    return 0;
}

int simp_run(simp_mesh *m, const simp_opts *o, simp_stats *st)
{
    memset(st, 0, sizeof *st);
    st->tris_in = m->ntris;
    st->verts_in = m->nverts;
    state s;
    int rc = -1;
    size_t nv = m->nverts ? m->nverts : 1;
    if (state_init(&s, m, o, st)) goto done;
    if (run(&s)) goto done;

    /* Compact: live faces, and the vertices they use, in their old order. */
    uint32_t *remap = malloc(nv * sizeof *remap), *origin = malloc(nv * sizeof *origin);
    double *pos = malloc(3 * nv * sizeof *pos);
    uint32_t *tri = malloc(3 * (size_t)(s.alive_tris ? s.alive_tris : 1) * sizeof *tri);
    if (!remap || !origin || !pos || !tri) {
        free(remap), free(origin), free(pos), free(tri);
        goto done;
    }
    for (uint32_t i = 0; i < s.nv; i++) remap[i] = UINT32_MAX;
    uint32_t vn = 0, tn = 0;
    for (uint32_t f = 0; f < s.nt; f++) {
        if (s.tdead[f]) continue;
        for (int k = 0; k < 3; k++) {
            uint32_t x = s.tri[3 * f + k];
            if (remap[x] == UINT32_MAX) {
                remap[x] = vn;
                origin[vn] = x;
                memcpy(&pos[3 * vn], &s.pos[3 * x], 3 * sizeof *pos);
                vn++;
            }
            tri[3 * tn + k] = remap[x];
        }
        tn++;
    }
    free(remap);
    free(m->pos);
    free(m->tri);
    free(m->origin);
    m->origin = origin;
    m->pos = pos;
    m->tri = tri;
    m->nverts = vn;
    m->ntris = tn;
    st->verts_out = vn;
    st->tris_out = tn;
    rc = 0;
done:
    state_free(&s);
    return rc;
}

/* ---- topology check ------------------------------------------------------------- */

typedef struct half { uint32_t a, b, f; } half;   /* a < b; f: face, top bit = direction b->a */

static int half_cmp(const void *x, const void *y)
{
    const half *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return 0;
}

static uint32_t uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

int simp_topology_check(const simp_mesh *m, simp_topology *t)
{
    memset(t, 0, sizeof *t);
    size_t nh = 3 * (size_t)m->ntris;
    half *h = malloc((nh ? nh : 1) * sizeof *h);
    uint32_t *start = calloc((size_t)m->nverts + 1, sizeof *start);
    uint32_t *vf = malloc((nh ? nh : 1) * sizeof *vf), *parent = malloc((nh ? nh : 1) * sizeof *parent);
    if (!h || !start || !vf || !parent) {
        free(h), free(start), free(vf), free(parent);
        return -1;
    }
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *v = &m->tri[3 * f];
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) t->degenerate_tris++;
        for (int k = 0; k < 3; k++) {
            uint32_t a = v[k], b = v[(k + 1) % 3];
            h[3 * f + k] = a < b ? (half){ a, b, f } : (half){ b, a, f | 0x80000000u };
            start[v[k] + 1]++;
        }
    }
    qsort(h, nh, sizeof *h, half_cmp);
    for (size_t i = 0; i < nh;) {
        size_t j = i, fwd = 0;
        while (j < nh && h[j].a == h[i].a && h[j].b == h[i].b) fwd += !(h[j].f >> 31), j++;
        size_t n = j - i;
        t->edges++;
        if (n == 1) t->boundary_edges++;
        else if (n > 2) t->nonmanifold_edges++;
        else if (fwd != 1) t->misoriented_edges++;
        i = j;
    }
    /* Vertex fans: faces around v joined when they share an edge at v. */
    for (uint32_t v = 0; v < m->nverts; v++) start[v + 1] += start[v];
    uint32_t *fill = malloc(((size_t)m->nverts + 1) * sizeof *fill);
    if (!fill) {
        free(h), free(start), free(vf), free(parent);
        return -1;
    }
    memcpy(fill, start, ((size_t)m->nverts + 1) * sizeof *fill);
    for (uint32_t f = 0; f < m->ntris; f++)
        for (int k = 0; k < 3; k++) vf[fill[m->tri[3 * f + k]]++] = f;
    for (uint32_t v = 0; v < m->nverts; v++) {
        uint32_t a = start[v], b = start[v + 1];
        if (a == b) {
            t->unused_verts++;
            continue;
        }
        for (uint32_t i = a; i < b; i++) parent[i] = i;
        for (uint32_t i = a; i < b; i++)
            for (uint32_t j = i + 1; j < b; j++) {
                const uint32_t *p = &m->tri[3 * vf[i]], *q = &m->tri[3 * vf[j]];
                int shared = 0;   /* a vertex other than v in both faces */
                for (int x = 0; x < 3; x++)
                    for (int y = 0; y < 3; y++) shared |= p[x] != v && p[x] == q[y];
                if (shared) parent[uf_find(parent, i)] = uf_find(parent, j);
            }
        uint32_t roots = 0;
        for (uint32_t i = a; i < b; i++) roots += uf_find(parent, i) == i;
        if (roots > 1) t->nonmanifold_verts++;
    }
    t->euler = (int)(m->nverts - t->unused_verts) - (int)t->edges + (int)m->ntris;
    free(fill), free(h), free(start), free(vf), free(parent);
    return 0;
}
