/*
 * hull.c - progressive hulls by constrained edge collapse ("Silhouette
 * Mapping", section 7; see hull.h).
 *
 * For an edge (u, v), F is the set of faces around u or v.  The merged
 * vertex w must satisfy n_f . (w - a_f) >= margin for every f in F (n_f
 * the unit normal, a_f a corner): outside every plane, so the faces after
 * the collapse, with F turned over, bound the added volume, and winding
 * numbers only grow (section 7, "Progressive hull construction").  The
 * volume the mesh encloses after the collapse is linear in w: sum over the
 * surviving faces (w, b, c) of w . (b x c) / 6, so a linear program
 * (tools/prep/lp.c) finds the w of least added volume, inside a box around the
 * edge's neighbourhood that keeps it bounded and local.  The added volume
 * is also the collapse's cost (the paper's choice).
 *
 * Collapses wait in a heap with lazy updates: an entry is dropped when an
 * end point has changed since it was priced (stamps), and priced again
 * when it comes up, since its neighbours may have moved; if it got dearer
 * it goes back in.  Refused collapses are tried again once the heap runs
 * dry, as the neighbourhood may have changed.  The surface stays a closed
 * manifold: the link condition, degrees of at least 3, no face turned over.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hull.h"
#include "lp.h"

enum { MAX_RING = 192 };   /* faces around an edge; a busier edge is refused */

void hull_opts_default(hull_opts *o, uint32_t target_tris)
{
    o->target_tris = target_tris;
    o->inner = 0;
    o->grid = 1.0 / 65536;
}

static void sub(const double *a, const double *b, double *r) { r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2]; }
static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

double hull_volume(const simp_mesh *m)
{
    double v = 0;
    for (uint32_t f = 0; f < m->ntris; f++) {
        const uint32_t *t = &m->tri[3 * f];
        double bc[3];
        cross(&m->pos[3 * t[1]], &m->pos[3 * t[2]], bc);
        v += dot(&m->pos[3 * t[0]], bc);
    }
    return v / 6;
}

/* ---- state ------------------------------------------------------------------ */

typedef struct faces { uint32_t *f, n, cap; } faces;   /* the faces at a vertex */

typedef struct entry {
    double cost;
    uint32_t u, v, su, sv;     /* the edge, and its ends' stamps when priced */
} entry;

typedef struct hull {
    const hull_opts *o;
    hull_stats *st;
    uint32_t nv, nt, alive;
    double *pos, margin;
    double *fp, *fn;           /* what each vertex stands for: point and normal on the detailed surface */
    uint32_t *tri, *stamp, *mark, gen;
    uint8_t *vdead, *tdead;
    faces *vf;
    entry *heap, *later;       /* the queue; refused collapses */
    size_t nheap, capheap, nlater, caplater;
    uint32_t *ring, nring, *nbr, nnbr, capnbr;   /* scratch */
} hull;

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    void *q = realloc(*p, c * size);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int faces_add(faces *l, uint32_t f)
{
    if (l->n == l->cap) {
        size_t cap = l->cap;
        if (grow((void **)&l->f, &cap, (size_t)l->n + 1, sizeof *l->f)) return -1;
        l->cap = (uint32_t)cap;
    }
    l->f[l->n++] = f;
    return 0;
}

static void faces_del(faces *l, uint32_t f)
{
    for (uint32_t i = 0; i < l->n; i++)
        if (l->f[i] == f) {
            l->f[i] = l->f[--l->n];
            return;
        }
}

/* ---- the heap (a binary min-heap on cost) ------------------------------------ */

static int heap_add(hull *h, const entry *e)
{
    if (grow((void **)&h->heap, &h->capheap, h->nheap + 1, sizeof *h->heap)) return -1;
    size_t i = h->nheap++;
    for (; i > 0 && h->heap[(i - 1) / 2].cost > e->cost; i = (i - 1) / 2) h->heap[i] = h->heap[(i - 1) / 2];
    h->heap[i] = *e;
    return 0;
}

static entry heap_take(hull *h)
{
    entry top = h->heap[0], last = h->heap[--h->nheap];
    size_t i = 0, k;
    while ((k = 2 * i + 1) < h->nheap) {
        if (k + 1 < h->nheap && h->heap[k + 1].cost < h->heap[k].cost) k++;
        if (!(h->heap[k].cost < last.cost)) break;
        h->heap[i] = h->heap[k];
        i = k;
    }
    if (h->nheap) h->heap[i] = last;
    return top;
}

/* ---- neighbourhoods ------------------------------------------------------------ */

static int has(const hull *h, uint32_t f, uint32_t x)
{
    const uint32_t *t = &h->tri[3 * f];
    return t[0] == x || t[1] == x || t[2] == x;
}

/* The faces around u or v, each once, into h->ring; -1 if too many. */
static int gather_ring(hull *h, uint32_t u, uint32_t v)
{
    h->nring = 0;
    for (int side = 0; side < 2; side++) {
        const faces *l = &h->vf[side ? v : u];
        for (uint32_t i = 0; i < l->n; i++) {
            if (side && has(h, l->f[i], u)) continue;   /* listed with u */
            if (h->nring == MAX_RING) return -1;
            h->ring[h->nring++] = l->f[i];
        }
    }
    return 0;
}

/* The vertices sharing a face with x into h->nbr, marked with a new
 * generation.  0 or -1. */
static int neighbours(hull *h, uint32_t x)
{
    h->nnbr = 0;
    h->gen++;
    const faces *l = &h->vf[x];
    for (uint32_t i = 0; i < l->n; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t y = h->tri[3 * l->f[i] + k];
            if (y == x || h->mark[y] == h->gen) continue;
            h->mark[y] = h->gen;
            size_t cap = h->capnbr;
            if (grow((void **)&h->nbr, &cap, (size_t)h->nnbr + 1, sizeof *h->nbr)) return -1;
            h->capnbr = (uint32_t)cap;
            h->nbr[h->nnbr++] = y;
        }
    return 0;
}

enum { OK = 0, STALE, REFUSE_TOPOLOGY, REFUSE_INFEASIBLE, REFUSE_SHAPE, NOMEM };

/* The link condition: u and v share exactly the two neighbours opposite
 * their edge, and the collapse leaves every vertex of degree 3 or more. */
static int topology(hull *h, uint32_t u, uint32_t v)
{
    uint32_t opp[2], k = 0;
    const faces *l = &h->vf[u];
    for (uint32_t i = 0; i < l->n; i++) {
        const uint32_t *t = &h->tri[3 * l->f[i]];
        if (!has(h, l->f[i], v)) continue;
        if (k == 2) return REFUSE_TOPOLOGY;
        opp[k++] = t[0] != u && t[0] != v ? t[0] : t[1] != u && t[1] != v ? t[1] : t[2];
    }
    if (k != 2) return STALE;
    if (h->vf[opp[0]].n <= 3 || h->vf[opp[1]].n <= 3) return REFUSE_TOPOLOGY;
    if (h->vf[u].n + h->vf[v].n - 4 < 3 || h->alive <= 4) return REFUSE_TOPOLOGY;
    if (neighbours(h, u)) return NOMEM;
    uint32_t gen_u = h->gen;
    const faces *lv = &h->vf[v];
    for (uint32_t i = 0; i < lv->n; i++)
        for (int j = 0; j < 3; j++) {
            uint32_t y = h->tri[3 * lv->f[i] + j];
            if (y == v || h->mark[y] != gen_u) continue;
            if (y != opp[0] && y != opp[1]) return REFUSE_TOPOLOGY;
        }
    return OK;
}

/* Where the merged vertex of (u, v) goes (into w) and the volume it adds
 * (into *cost): OK, REFUSE_INFEASIBLE or REFUSE_SHAPE. */
static int place(hull *h, uint32_t u, uint32_t v, double w[3], double *cost)
{
    if (gather_ring(h, u, v)) return REFUSE_INFEASIBLE;
    const double *pu = &h->pos[3 * u], *pv = &h->pos[3 * v];
    /* Work about the edge's middle: the planes' offsets stay small. */
    double o[3] = { (pu[0] + pv[0]) / 2, (pu[1] + pv[1]) / 2, (pu[2] + pv[2]) / 2 };
    lp_halfspace hs[MAX_RING];
    double c[3] = { 0, 0, 0 }, lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    double before = 0;
    for (uint32_t i = 0; i < h->nring; i++) {
        const uint32_t *t = &h->tri[3 * h->ring[i]];
        double p[3][3], e1[3], e2[3], n[3], bc[3];
        for (int k = 0; k < 3; k++) {
            sub(&h->pos[3 * t[k]], o, p[k]);
            for (int j = 0; j < 3; j++) {
                if (p[k][j] < lo[j]) lo[j] = p[k][j];
                if (p[k][j] > hi[j]) hi[j] = p[k][j];
            }
        }
        sub(p[1], p[0], e1);
        sub(p[2], p[0], e2);
        cross(e1, e2, n);
        double l = sqrt(dot(n, n));
        if (!(l > 0)) return REFUSE_SHAPE;   /* a degenerate face has no side */
        for (int k = 0; k < 3; k++) hs[i].a[k] = n[k] / l;
        hs[i].b = dot(hs[i].a, p[0]) + h->margin;
        cross(p[1], p[2], bc);
        before += dot(p[0], bc);
        /* after: (w, b, c) for the faces that stay, b, c in turn after the
         * vertex the collapse moves */
        int at_u = has(h, h->ring[i], u), at_v = has(h, h->ring[i], v);
        if (at_u && at_v) continue;
        int k = t[0] == (at_u ? u : v) ? 0 : t[1] == (at_u ? u : v) ? 1 : 2;
        cross(p[(k + 1) % 3], p[(k + 2) % 3], bc);
        for (int j = 0; j < 3; j++) c[j] += bc[j];
    }
    double ext = 0;
    for (int j = 0; j < 3; j++) ext = fmax(ext, hi[j] - lo[j]);
    for (int j = 0; j < 3; j++) lo[j] -= ext + 4 * h->margin, hi[j] += ext + 4 * h->margin;
    h->st->lps++;
    /* the solver's random order seeded by the edge: the same neighbourhood
     * always gives the same point */
    uint64_t rng = ((uint64_t)u << 32 ^ v) * 0x9E3779B97F4A7C15ull | 1;
    if (lp3_solve(hs, (int)h->nring, c, lo, hi, h->margin / 64, &rng, w) != LP_OK) return REFUSE_INFEASIBLE;
    for (int j = 0; j < 3; j++) {
        w[j] += o[j];
        if (h->o->grid > 0) w[j] = nearbyint(w[j] / h->o->grid) * h->o->grid;
    }
    /* What the solver and the grid made of it, checked: outside every plane,
     * and no face that stays turned over. */
    double after = 0, wl[3];
    sub(w, o, wl);
    for (uint32_t i = 0; i < h->nring; i++) {
        const uint32_t *t = &h->tri[3 * h->ring[i]];
        double p[3][3];
        for (int k = 0; k < 3; k++) sub(&h->pos[3 * t[k]], o, p[k]);
        double n[3], e1[3], e2[3], d[3];
        sub(p[1], p[0], e1);
        sub(p[2], p[0], e2);
        cross(e1, e2, n);
        sub(wl, p[0], d);
        if (dot(n, d) < 0) return REFUSE_INFEASIBLE;
        int at_u = has(h, h->ring[i], u), at_v = has(h, h->ring[i], v);
        if (at_u && at_v) continue;
        int k = t[0] == (at_u ? u : v) ? 0 : t[1] == (at_u ? u : v) ? 1 : 2;
        double m[3], bc[3];
        memcpy(p[k], wl, sizeof wl);
        sub(p[1], p[0], e1);
        sub(p[2], p[0], e2);
        cross(e1, e2, m);
        if (!(dot(m, n) > 0)) return REFUSE_SHAPE;
        cross(p[1], p[2], bc);
        after += dot(p[0], bc);
    }
    *cost = fmax(0, (after - before) / 6);
    return OK;
}

static int price(hull *h, uint32_t u, uint32_t v, entry *e)
{
    double w[3];
    e->u = u, e->v = v, e->su = h->stamp[u], e->sv = h->stamp[v];
    return place(h, u, v, w, &e->cost);
}

static int refuse(hull *h, const entry *e, int why)
{
    if (why == REFUSE_TOPOLOGY) h->st->refused_topology++;
    else if (why == REFUSE_SHAPE) h->st->refused_shape++;
    else h->st->refused_infeasible++;
    if (grow((void **)&h->later, &h->caplater, h->nlater + 1, sizeof *h->later)) return -1;
    h->later[h->nlater++] = *e;
    return 0;
}

/* Price edge (u, v) and queue it, or set it aside if refused.  0 or -1. */
static int offer(hull *h, uint32_t u, uint32_t v)
{
    entry e;
    int r = price(h, u, v, &e);
    return r == OK ? heap_add(h, &e) : refuse(h, &e, r);
}

/* The barycentric coordinates of the point of triangle abc closest to p
 * (by regions: Ericson, Real-Time Collision Detection 5.1.5) into l; the
 * squared distance. */
static double closest_on_tri(const double *p, const double *a, const double *b, const double *c, double l[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    sub(b, a, ab), sub(c, a, ac), sub(p, a, ap), sub(p, b, bp), sub(p, c, cp);
    double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp), d6 = dot(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2, t;
    if (d1 <= 0 && d2 <= 0) l[0] = 1, l[1] = 0, l[2] = 0;
    else if (d3 >= 0 && d4 <= d3) l[0] = 0, l[1] = 1, l[2] = 0;
    else if (d6 >= 0 && d5 <= d6) l[0] = 0, l[1] = 0, l[2] = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) t = d1 / (d1 - d3), l[0] = 1 - t, l[1] = t, l[2] = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) t = d2 / (d2 - d6), l[0] = 1 - t, l[1] = 0, l[2] = t;
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        t = (d4 - d3) / ((d4 - d3) + (d5 - d6)), l[0] = 0, l[1] = 1 - t, l[2] = t;
    else {
        double den = 1 / (va + vb + vc);
        l[1] = vb * den, l[2] = vc * den, l[0] = 1 - l[1] - l[2];
    }
    double q[3];
    for (int k = 0; k < 3; k++) q[k] = l[0] * a[k] + l[1] * b[k] + l[2] * c[k] - p[k];
    return dot(q, q);
}

/* What the merged vertex at w stands for: interpolated at its closest
 * point on the faces around (u, v), before the collapse, into p and n. */
static void stand_for(hull *h, uint32_t u, uint32_t v, const double w[3], double p[3], double n[3])
{
    double best = INFINITY, l[3], bl[3] = { 1, 0, 0 };
    uint32_t bf = h->vf[u].f[0];
    gather_ring(h, u, v);   /* place() has found it no larger than MAX_RING */
    for (uint32_t i = 0; i < h->nring; i++) {
        const uint32_t *t = &h->tri[3 * h->ring[i]];
        double d = closest_on_tri(w, &h->pos[3 * t[0]], &h->pos[3 * t[1]], &h->pos[3 * t[2]], l);
        if (d < best) best = d, bf = h->ring[i], memcpy(bl, l, sizeof l);
    }
    const uint32_t *t = &h->tri[3 * bf];
    for (int k = 0; k < 3; k++) {
        p[k] = n[k] = 0;
        for (int j = 0; j < 3; j++) p[k] += bl[j] * h->fp[3 * t[j] + k], n[k] += bl[j] * h->fn[3 * t[j] + k];
    }
    double len = sqrt(dot(n, n));
    if (len > 0)
        for (int k = 0; k < 3; k++) n[k] /= len;
}

/* Merge v into u at w (the one with more faces keeps its index). */
static int collapse(hull *h, uint32_t u, uint32_t v, const double w[3])
{
    if (h->vf[v].n > h->vf[u].n) {
        uint32_t t = u;
        u = v, v = t;
    }
    double fp[3], fn[3];
    stand_for(h, u, v, w, fp, fn);
    memcpy(&h->fp[3 * u], fp, sizeof fp);
    memcpy(&h->fn[3 * u], fn, sizeof fn);
    memcpy(&h->pos[3 * u], w, 3 * sizeof *w);
    h->stamp[u]++;
    h->stamp[v]++;
    h->vdead[v] = 1;
    faces *lv = &h->vf[v];
    for (uint32_t i = 0; i < lv->n; i++) {
        uint32_t f = lv->f[i], *t = &h->tri[3 * f];
        if (has(h, f, u)) {
            h->tdead[f] = 1;
            h->alive--;
            for (int k = 0; k < 3; k++)
                if (t[k] != v) faces_del(&h->vf[t[k]], f);
        } else {
            for (int k = 0; k < 3; k++)
                if (t[k] == v) t[k] = u;
            if (faces_add(&h->vf[u], f)) return -1;
        }
    }
    free(lv->f);
    memset(lv, 0, sizeof *lv);
    h->st->collapses++;
    if (neighbours(h, u)) return -1;
    for (uint32_t i = 0; i < h->nnbr; i++)
        if (offer(h, u, h->nbr[i])) return -1;
    return 0;
}

static int run(hull *h)
{
    for (uint32_t u = 0; u < h->nv; u++) {
        if (neighbours(h, u)) return -1;
        for (uint32_t i = 0; i < h->nnbr; i++)
            if (h->nbr[i] > u && offer(h, u, h->nbr[i])) return -1;
    }
    uint32_t progress = 1;
    while (h->alive > h->o->target_tris) {
        if (h->nheap == 0) {
            /* Refused collapses may be possible now; stop when a whole
             * round of them brings nothing. */
            if (h->nlater == 0 || !progress) break;
            progress = 0;
            size_t n = h->nlater;
            entry *old = h->later;
            h->later = NULL, h->nlater = 0, h->caplater = 0;
            int rc = 0;
            for (size_t i = 0; i < n && !rc; i++) {
                const entry *e = &old[i];
                /* an end point that changed has had its edges offered since */
                if (!h->vdead[e->u] && !h->vdead[e->v] && e->su == h->stamp[e->u] && e->sv == h->stamp[e->v])
                    rc = offer(h, e->u, e->v);
            }
            free(old);
            if (rc) return -1;
            continue;
        }
        entry e = heap_take(h);
        if (h->vdead[e.u] || h->vdead[e.v] || e.su != h->stamp[e.u] || e.sv != h->stamp[e.v]) continue;
        int r = topology(h, e.u, e.v);
        if (r == NOMEM) return -1;
        if (r == STALE) continue;
        double w[3], cost;
        if (r == OK) r = place(h, e.u, e.v, w, &cost);
        if (r != OK) {
            if (refuse(h, &e, r)) return -1;
            continue;
        }
        if (cost > e.cost * (1 + 1e-9) + 1e-300) {   /* its neighbours moved: dearer now */
            e.cost = cost;
            if (heap_add(h, &e)) return -1;
            continue;
        }
        if (collapse(h, e.u, e.v, w)) return -1;
        progress++;
    }
    return 0;
}

static void flip(simp_mesh *m)
{
    for (uint32_t f = 0; f < m->ntris; f++) {
        uint32_t t = m->tri[3 * f + 1];
        m->tri[3 * f + 1] = m->tri[3 * f + 2];
        m->tri[3 * f + 2] = t;
    }
}

static void hull_free(hull *h)
{
    if (h->vf)
        for (uint32_t i = 0; i < h->nv; i++) free(h->vf[i].f);
    free(h->vf), free(h->pos), free(h->fp), free(h->fn), free(h->tri), free(h->stamp), free(h->mark), free(h->vdead), free(h->tdead);
    free(h->heap), free(h->later), free(h->ring), free(h->nbr);
}

static int hull_init(hull *h, const simp_mesh *m, const hull_opts *o, hull_stats *st)
{
    memset(h, 0, sizeof *h);
    h->o = o, h->st = st;
    h->nv = m->nverts, h->nt = m->ntris, h->alive = m->ntris;
    size_t nv = h->nv ? h->nv : 1, nt = h->nt ? h->nt : 1;
    h->pos = malloc(3 * nv * sizeof *h->pos);
    h->tri = malloc(3 * nt * sizeof *h->tri);
    h->stamp = calloc(nv, sizeof *h->stamp);
    h->mark = calloc(nv, sizeof *h->mark);
    h->vdead = calloc(nv, 1);
    h->tdead = calloc(nt, 1);
    h->vf = calloc(nv, sizeof *h->vf);
    h->ring = malloc(MAX_RING * sizeof *h->ring);
    h->fp = malloc(3 * nv * sizeof *h->fp);
    h->fn = calloc(3 * nv, sizeof *h->fn);
    if (!h->pos || !h->tri || !h->stamp || !h->mark || !h->vdead || !h->tdead || !h->vf || !h->ring || !h->fp || !h->fn)
        return -1;
    memcpy(h->pos, m->pos, 3 * (size_t)h->nv * sizeof *h->pos);
    memcpy(h->fp, m->pos, 3 * (size_t)h->nv * sizeof *h->fp);
    /* the detailed mesh's area-weighted vertex normals, outward even for the
     * inner hull (whose input is turned over) */
    for (uint32_t f = 0; f < h->nt; f++) {
        const uint32_t *t = &m->tri[3 * f];
        double e1[3], e2[3], n[3];
        sub(&m->pos[3 * t[1]], &m->pos[3 * t[0]], e1);
        sub(&m->pos[3 * t[2]], &m->pos[3 * t[0]], e2);
        cross(e1, e2, n);
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) h->fn[3 * t[k] + j] += o->inner ? -n[j] : n[j];
    }
    for (uint32_t i = 0; i < h->nv; i++) {
        double l = sqrt(dot(&h->fn[3 * i], &h->fn[3 * i]));
        if (l > 0)
            for (int k = 0; k < 3; k++) h->fn[3 * i + k] /= l;
    }
    memcpy(h->tri, m->tri, 3 * (size_t)h->nt * sizeof *h->tri);
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, size = 0;
    for (uint32_t i = 0; i < h->nv; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], h->pos[3 * i + k]), hi[k] = fmax(hi[k], h->pos[3 * i + k]);
    for (int k = 0; k < 3; k++) size = fmax(size, hi[k] - lo[k]);
    h->margin = o->grid > 0 ? o->grid : 1e-9 * size;
    for (uint32_t f = 0; f < h->nt; f++)
        for (int k = 0; k < 3; k++)
            if (faces_add(&h->vf[h->tri[3 * f + k]], f)) return -1;
    return 0;
}

void hull_fine_free(hull_fine *f)
{
    free(f->point);
    free(f->normal);
    memset(f, 0, sizeof *f);
}

int hull_run(simp_mesh *m, const hull_opts *o, hull_stats *st, hull_fine *fine)
{
    if (fine) memset(fine, 0, sizeof *fine);
    memset(st, 0, sizeof *st);
    st->tris_in = m->ntris;
    st->volume_in = st->volume_out = hull_volume(m);
    if (o->inner) flip(m);   /* the outer hull of the mesh turned inside out */
    hull h;
    int rc = -1;
    if (hull_init(&h, m, o, st) || run(&h)) goto done;
    uint32_t *remap = malloc((h.nv ? h.nv : 1) * sizeof *remap);
    double *pos = malloc(3 * (size_t)(h.nv ? h.nv : 1) * sizeof *pos);
    uint32_t *tri = malloc(3 * (size_t)(h.alive ? h.alive : 1) * sizeof *tri);
    if (fine) {
        fine->point = malloc(3 * (size_t)(h.nv ? h.nv : 1) * sizeof *fine->point);
        fine->normal = malloc(3 * (size_t)(h.nv ? h.nv : 1) * sizeof *fine->normal);
    }
    if (!remap || !pos || !tri || (fine && (!fine->point || !fine->normal))) {
        free(remap), free(pos), free(tri);
        if (fine) hull_fine_free(fine);
        goto done;
    }
    /* The live vertices in their old order, then the live faces. */
    uint32_t nv = 0, nt = 0;
    for (uint32_t i = 0; i < h.nv; i++) {
        remap[i] = nv;
        if (h.vdead[i] || h.vf[i].n == 0) continue;
        if (fine) {
            memcpy(&fine->point[3 * nv], &h.fp[3 * i], 3 * sizeof *pos);
            memcpy(&fine->normal[3 * nv], &h.fn[3 * i], 3 * sizeof *pos);
        }
        memcpy(&pos[3 * nv++], &h.pos[3 * i], 3 * sizeof *pos);
    }
    for (uint32_t f = 0; f < h.nt; f++) {
        if (h.tdead[f]) continue;
        for (int k = 0; k < 3; k++) tri[3 * nt + k] = remap[h.tri[3 * f + k]];
        nt++;
    }
    free(remap);
    free(m->pos), free(m->tri);
    m->pos = pos, m->tri = tri, m->nverts = nv, m->ntris = nt;
    st->tris_out = nt, st->verts_out = nv;
    rc = 0;
done:
    if (o->inner) flip(m);
    if (rc == 0) st->volume_out = hull_volume(m);
    hull_free(&h);
    return rc;
}
