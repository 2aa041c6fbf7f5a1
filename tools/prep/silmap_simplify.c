/*
 * silmap_simplify.c - silhouette map simplification (paper, section 6).
 *
 * A half-edge collapse u -> v drops view u: the triangles around u that
 * do not hold v get v in u's place, the two that hold both go.  It is
 * refused when it breaks the link condition (u and v may share only the
 * two neighbours across their edge) or turns a new triangle's orientation
 * about the centre over, which is what keeps the polytope star-shaped:
 * every triangle counter-clockwise seen from the centre's outside means the
 * rays from the centre still meet exactly one.  Its cost is the worst error
 * (silmap_simplify.h) of the views that the changed triangles now predict:
 * u and the views dropped before whose directions fall in them.  Costs are
 * kept per directed edge and priced again when a collapse changes the
 * neighbourhood of either end.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "silmap_simplify.h"

void silmap_fill(const silk_outline *o, int w, int h, uint8_t *img)
{
    memset(img, 0, (size_t)w * h);
    double *xs = malloc(((size_t)o->npts + 1) * sizeof *xs);
    if (!xs) return;
    for (int y = 0; y < h; y++) {
        double yc = y + 0.5;
        uint32_t n = 0;
        for (uint32_t l = 0; l < o->nloops; l++)
            for (uint32_t i = o->start[l]; i < o->start[l + 1]; i++) {
                silk_vec2 p = o->pt[i], q = o->pt[i + 1 < o->start[l + 1] ? i + 1 : o->start[l]];
                double py = p.y / 65536.0, qy = q.y / 65536.0, px = p.x / 65536.0, qx = q.x / 65536.0;
                if ((py <= yc) == (qy <= yc)) continue;
                /* insertion keeps the row's few crossings sorted */
                double x = px + (yc - py) * (qx - px) / (qy - py);
                uint32_t j = n++;
                while (j > 0 && xs[j - 1] > x) {
                    xs[j] = xs[j - 1];
                    j--;
                }
                xs[j] = x;
            }
        for (uint32_t k = 0; k + 1 < n; k += 2)
            for (int x = (int)fmax(0, ceil(xs[k] - 0.5)); x < w && x + 0.5 < xs[k + 1]; x++) img[y * w + x] = 1;
    }
    free(xs);
}

typedef struct simp {
    const silmap *m;
    silmap_fixed f;
    uint32_t nviews;
    uint32_t *tri, ntris;          /* the current polytope */
    uint8_t *alive;
    uint8_t **truth;               /* each view's own outline, drawn in the camera it is predicted for */
    silk_view *cur;                /* that camera */
    uint32_t *perimeter;
    uint8_t *img;
    uint8_t *arena_buf;
    size_t arena_bytes;
    uint32_t evaluations;
} simp;

static silk_fx fx(double v) { return (silk_fx)floor(v * 65536 + 0.5); }

static double det3(const double *a, const double *b, const double *c)
{
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* The camera view w is predicted in, and its own outline drawn there. */
static int setup_view(simp *s, uint32_t w)
{
    const silmap_camera *c = &s->m->views[w].cam;
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = (silk_vec3){ fx(c->eye[0]), fx(c->eye[1]), fx(c->eye[2]) };
    cam.target = (silk_vec3){ fx(c->eye[0] + c->fwd[0]), fx(c->eye[1] + c->fwd[1]), fx(c->eye[2] + c->fwd[2]) };
    cam.up = (silk_vec3){ fx(c->up[0]), fx(c->up[1]), fx(c->up[2]) };
    cam.fov_deg = fx(2 * atan(c->res / 2.0 / c->focal) * 180 / 3.14159265358979323846);
    cam.znear = fx(s->m->radius * 0.01);
    cam.zfar = fx(s->m->radius * 100);
    cam.width = cam.height = c->res;
    silk_error err;
    if (silk_view_init(&s->cur[w], &cam, &err)) return -1;
    silk_silmap_cam cc;
    silk_silmap_cam_of_view(&s->cur[w], &cc);
    silk_h3 h;
    silk_arena a;
    silk_arena_init(&a, s->arena_buf, s->arena_bytes);
    silk_outline own = silk_silmap_outline(&s->f.map, w), mapped;
    uint32_t *start = silk_arena_array_top(&a, own.nloops + 1, sizeof *start, SILK_MEM_FRAME);
    if (!start) return -1;
    for (uint32_t i = 0; i <= own.nloops; i++) start[i] = own.start[i] - own.start[0];
    silk_outline rebased = { own.nloops, own.npts, start, own.pt + own.start[0] };
    if (silk_h3_between(&s->f.map.views[w].cam, &cc, NULL, NULL, &h) || silk_outline_map(&rebased, &h, &a, &mapped))
        return -1;
    int res = c->res;
    s->truth[w] = malloc((size_t)res * res);
    if (!s->truth[w]) return -1;
    silmap_fill(&mapped, res, res, s->truth[w]);
    uint32_t per = 0;
    const uint8_t *t = s->truth[w];
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++) {
            if (x + 1 < res) per += t[y * res + x] != t[y * res + x + 1];
            if (y + 1 < res) per += t[y * res + x] != t[(y + 1) * res + x];
        }
    s->perimeter[w] = per ? per : 1;
    return 0;
}

/* View w predicted by the polytope (tri, ntris): its error in pixels, or
 * HUGE_VAL when the interpolation fails. */
static double view_error(simp *s, const uint32_t *tri, uint32_t ntris, uint32_t w)
{
    silmap_polytope p = { s->nviews, ntris, s->m->poly.dir, (uint32_t *)tri };
    uint32_t *adj = silmap_adjacency(&p);
    if (!adj) return HUGE_VAL;
    silk_silmap mm = s->f.map;
    mm.tri = tri;
    mm.ntris = ntris;
    mm.adj = adj;
    silk_arena a;
    silk_arena_init(&a, s->arena_buf, s->arena_bytes);
    silk_outline out;
    silk_error err;
    s->evaluations++;
    silk_status st = silk_silmap_interp(&mm, &s->cur[w], 0, &a, &out, NULL, &err);
    free(adj);
    if (st) return HUGE_VAL;
    int res = s->m->views[w].cam.res;
    silmap_fill(&out, res, res, s->img);
    uint32_t bad = 0;
    for (int i = 0; i < res * res; i++) bad += s->img[i] != s->truth[w][i];
    return (double)bad / s->perimeter[w];
}

/* Does the ray from the centre along view w's direction meet triangle t? */
static int dir_in_tri(const simp *s, const uint32_t *t, uint32_t w)
{
    const double *d = &s->m->poly.dir[3 * w];
    const double *a = &s->m->poly.dir[3 * t[0]], *b = &s->m->poly.dir[3 * t[1]], *c = &s->m->poly.dir[3 * t[2]];
    return det3(d, b, c) >= 0 && det3(a, d, c) >= 0 && det3(a, b, d) >= 0;
}

/* The polytope after collapsing u into v, in out (room for ntris); its
 * triangle count, or 0 when the collapse is refused. */
static uint32_t collapse(const simp *s, uint32_t u, uint32_t v, uint32_t *out)
{
    /* link condition: u and v share exactly two neighbours */
    uint32_t shared = 0;
    uint8_t *nu = calloc(s->nviews, 1);
    if (!nu) return 0;
    for (uint32_t t = 0; t < s->ntris; t++) {
        const uint32_t *q = &s->tri[3 * t];
        if (q[0] == u || q[1] == u || q[2] == u)
            for (int k = 0; k < 3; k++) nu[q[k]] = 1;
    }
    uint8_t *nv = calloc(s->nviews, 1);
    if (!nv) {
        free(nu);
        return 0;
    }
    for (uint32_t t = 0; t < s->ntris; t++) {
        const uint32_t *q = &s->tri[3 * t];
        if (q[0] == v || q[1] == v || q[2] == v)
            for (int k = 0; k < 3; k++) nv[q[k]] = 1;
    }
    for (uint32_t i = 0; i < s->nviews; i++) shared += i != u && i != v && nu[i] && nv[i];
    int adjacent = nu[v];
    free(nu);
    free(nv);
    if (!adjacent || shared != 2) return 0;
    uint32_t n = 0;
    for (uint32_t t = 0; t < s->ntris; t++) {
        const uint32_t *q = &s->tri[3 * t];
        int hu = q[0] == u || q[1] == u || q[2] == u, hv = q[0] == v || q[1] == v || q[2] == v;
        if (hu && hv) continue;
        uint32_t *r = &out[3 * n++];
        for (int k = 0; k < 3; k++) r[k] = q[k] == u ? v : q[k];
        if (hu) {
            const double *dir = s->m->poly.dir;
            if (!(det3(&dir[3 * r[0]], &dir[3 * r[1]], &dir[3 * r[2]]) > 1e-12)) return 0;
        }
    }
    return n;
}

/* The cost of collapsing u into v: the worst error among the views the
 * changed triangles now predict. */
static double collapse_cost(simp *s, uint32_t u, uint32_t v, uint32_t *scratch)
{
    uint32_t n = collapse(s, u, v, scratch);
    if (!n) return HUGE_VAL;
    double worst = 0;
    for (uint32_t w = 0; w < s->nviews && worst < HUGE_VAL; w++) {
        if (w != u && s->alive[w]) continue;
        int affected = w == u;
        for (uint32_t t = 0; t < n && !affected; t++) {
            const uint32_t *q = &scratch[3 * t];
            if ((q[0] == v || q[1] == v || q[2] == v) && dir_in_tri(s, q, w)) affected = 1;
        }
        if (affected) worst = fmax(worst, view_error(s, scratch, n, w));
    }
    return worst;
}

/* A new map holding the kept views and the polytope's triangles. */
static int subset(const silmap *m, const uint8_t *alive, const uint32_t *tri, uint32_t ntris, silmap *out)
{
    memset(out, 0, sizeof *out);
    out->params = m->params;
    memcpy(out->centre, m->centre, sizeof out->centre);
    out->radius = m->radius;
    uint32_t *index = malloc(m->poly.nviews * sizeof *index), n = 0;
    if (!index) return -1;
    for (uint32_t i = 0; i < m->poly.nviews; i++) index[i] = alive[i] ? n++ : UINT32_MAX;
    out->poly.nviews = n;
    out->poly.ntris = ntris;
    out->poly.dir = malloc(3 * n * sizeof *out->poly.dir);
    out->poly.tri = malloc(3 * (size_t)ntris * sizeof *out->poly.tri);
    out->views = calloc(n, sizeof *out->views);
    if (!out->poly.dir || !out->poly.tri || !out->views) {
        free(index);
        silmap_free(out);
        return -1;
    }
    for (uint32_t t = 0; t < 3 * ntris; t++) out->poly.tri[t] = index[tri[t]];
    for (uint32_t i = 0; i < m->poly.nviews; i++) {
        if (!alive[i]) continue;
        uint32_t j = index[i];
        memcpy(&out->poly.dir[3 * j], &m->poly.dir[3 * i], 3 * sizeof(double));
        silmap_view *v = &out->views[j];
        *v = m->views[i];
        v->outline.start = NULL;
        v->outline.pt = NULL;
        const silmap_contours *c = &m->views[i].outline;
        v->outline.start = malloc((c->nloops + 1) * sizeof *v->outline.start);
        v->outline.pt = malloc(2 * (size_t)(c->npts ? c->npts : 1) * sizeof *v->outline.pt);
        if (!v->outline.start || !v->outline.pt) {
            free(index);
            silmap_free(out);
            return -1;
        }
        memcpy(v->outline.start, c->start, (c->nloops + 1) * sizeof *c->start);
        memcpy(v->outline.pt, c->pt, 2 * (size_t)c->npts * sizeof *c->pt);
    }
    free(index);
    return 0;
}

int silmap_simplify_map(const silmap *m, double max_error, uint32_t min_views, silmap *out,
                        silmap_simplify_stats *stats)
{
    simp s;
    memset(&s, 0, sizeof s);
    memset(stats, 0, sizeof *stats);
    memset(out, 0, sizeof *out);
    s.m = m;
    s.nviews = m->poly.nviews;
    if (min_views < 4) min_views = 4;
    if (silmap_export(m, &s.f)) return -1;
    int res = m->params.res;
    s.arena_bytes = (size_t)1 << 24;
    s.arena_buf = malloc(s.arena_bytes);
    s.tri = malloc(3 * (size_t)m->poly.ntris * sizeof *s.tri);
    uint32_t *scratch = malloc(3 * (size_t)m->poly.ntris * sizeof *scratch);
    s.alive = malloc(s.nviews);
    s.truth = calloc(s.nviews, sizeof *s.truth);
    s.cur = calloc(s.nviews, sizeof *s.cur);
    s.perimeter = calloc(s.nviews, sizeof *s.perimeter);
    s.img = malloc((size_t)res * res);
    double *cost = malloc((size_t)s.nviews * s.nviews * sizeof *cost);
    uint8_t *dirty = malloc((size_t)s.nviews * s.nviews);
    int rc = -1;
    if (!s.arena_buf || !s.tri || !scratch || !s.alive || !s.truth || !s.cur || !s.perimeter || !s.img || !cost ||
        !dirty)
        goto done;
    memcpy(s.tri, m->poly.tri, 3 * (size_t)m->poly.ntris * sizeof *s.tri);
    s.ntris = m->poly.ntris;
    memset(s.alive, 1, s.nviews);
    memset(dirty, 1, (size_t)s.nviews * s.nviews);
    for (uint32_t w = 0; w < s.nviews; w++)
        if (setup_view(&s, w)) goto done;
    uint32_t alive = s.nviews;
    stats->views_before = s.nviews;
    stats->bytes_before = silk_silmap_bytes(&s.f.map);
    while (alive > min_views) {
        double best = HUGE_VAL;
        uint32_t bu = 0, bv = 0;
        for (uint32_t t = 0; t < s.ntris; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t u = s.tri[3 * t + k], v = s.tri[3 * t + (k + 1) % 3];
                for (int dir = 0; dir < 2; dir++) {
                    uint32_t a = dir ? v : u, b = dir ? u : v;
                    size_t e = (size_t)a * s.nviews + b;
                    if (dirty[e]) {
                        cost[e] = collapse_cost(&s, a, b, scratch);
                        dirty[e] = 0;
                    }
                    if (cost[e] < best) best = cost[e], bu = a, bv = b;
                }
            }
        if (!(best <= max_error)) break;
        uint32_t n = collapse(&s, bu, bv, scratch);
        memcpy(s.tri, scratch, 3 * (size_t)n * sizeof *s.tri);
        s.ntris = n;
        s.alive[bu] = 0;
        alive--;
        stats->error = fmax(stats->error, best);
        /* the neighbourhood of v changed: price its edges and its
         * neighbours' edges again */
        uint8_t *near = calloc(s.nviews, 1);
        if (!near) goto done;
        for (uint32_t t = 0; t < s.ntris; t++) {
            const uint32_t *q = &s.tri[3 * t];
            if (q[0] == bv || q[1] == bv || q[2] == bv)
                for (int k = 0; k < 3; k++) near[q[k]] = 1;
        }
        for (uint32_t a = 0; a < s.nviews; a++)
            for (uint32_t b = 0; b < s.nviews; b++)
                if (near[a] || near[b]) dirty[(size_t)a * s.nviews + b] = 1;
        free(near);
    }
    if (subset(m, s.alive, s.tri, s.ntris, out)) goto done;
    silmap_fixed g;
    if (silmap_export(out, &g)) {
        silmap_free(out);
        goto done;
    }
    stats->views_after = out->poly.nviews;
    stats->bytes_after = silk_silmap_bytes(&g.map);
    silmap_fixed_free(&g);
    rc = 0;
done:
    stats->evaluations = s.evaluations;
    if (s.truth)
        for (uint32_t w = 0; w < s.nviews; w++) free(s.truth[w]);
    free(s.truth);
    free(s.cur);
    free(s.perimeter);
    free(s.img);
    free(s.alive);
    free(s.tri);
    free(scratch);
    free(s.arena_buf);
    free(cost);
    free(dirty);
    silmap_fixed_free(&s.f);
    return rc;
}
