/*
 * fit.c - fitted normals (fit.h): coordinate descent of each vertex normal
 * on how far the curves over its edges stray from the detailed surface.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "closest.h"
#include "fit.h"
#include "vec3.h"

/* The tangent of curve.c's silk_bridge at an end with unit normal n over
 * chord c: the chord projected onto the tangent plane (eqs. 2-3), eq. 4's
 * length with its clamp, and the bulge bound (src/curve.h). */
static void bridge_tangent(const double c[3], const double n[3], double t[3])
{
    double lc = len3(c);
    if (!(lc > 0)) {
        t[0] = t[1] = t[2] = 0;
        return;
    }
    double cn = dot3(c, n), d[3] = { c[0] - cn * n[0], c[1] - cn * n[1], c[2] - cn * n[2] };
    double ld = len3(d);
    if (!(ld > 1e-12 * lc)) memcpy(d, c, sizeof d), ld = lc;
    double cth = dot3(d, c) / (ld * lc), sth = sqrt(fmax(0, 1 - cth * cth));
    double L = 2 * lc / fmax(1 + cth, 0.5);
    if (sth > 0) L = fmin(L, lc / (2 * sth));
    for (int k = 0; k < 3; k++) t[k] = d[k] * L / ld;
}

/* Squared distances from the detailed surface of the curve p0 -> p1 at
 * u = 1/4, 1/2, 3/4, plus (FIT_NORMAL_WEIGHT |chord|)^2 times the squared
 * difference between the normal interpolated there (eq. 6) and the normal
 * of the nearest detailed triangle, summed. */
static double curve_cost(const cp_tree *tree, const double *p0, const double *n0, const double *p1, const double *n1)
{
    double c[3], t0[3], t1[3];
    sub3(p1, p0, c);
    bridge_tangent(c, n0, t0);
    bridge_tangent(c, n1, t1);
    double s = 0;
    for (int i = 1; i <= 3; i++) {
        double u = i / 4.0, u2 = u * u, u3 = u2 * u;
        double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2, q[3];
        for (int k = 0; k < 3; k++) q[k] = h00 * p0[k] + h10 * t0[k] + h01 * p1[k] + h11 * t1[k];
        uint32_t ft = 0;
        s += cp_nearest(tree, q, &ft);
        {
            double fn[3], m[3];
            const uint32_t *v = &tree->tri[3 * ft];
            tri_normal(&tree->pos[3 * v[0]], &tree->pos[3 * v[1]], &tree->pos[3 * v[2]], fn);
            double l = len3(fn);
            if (l > 0) {
                for (int k = 0; k < 3; k++) m[k] = (1 - u) * n0[k] + u * n1[k];
                double lm = len3(m), e[3];
                for (int k = 0; k < 3; k++) e[k] = m[k] / lm - fn[k] / l;
                s += FIT_NORMAL_WEIGHT * FIT_NORMAL_WEIGHT * dot3(c, c) * dot3(e, e);
            }
        }
    }
    return s;
}

typedef struct fit_ctx {
    const simp_mesh *c;
    surf_normals *sn;
    const cp_tree *tree;
    const uint32_t *cstart, *vcorner;
} fit_ctx;

/* The cost of vertex v's normal being n: the curves over its edges, in
 * every triangle around it (so an edge counts once per side). */
static double vertex_cost(const fit_ctx *x, uint32_t v, const double *n)
{
    double s = 0;
    for (uint32_t i = x->cstart[v]; i < x->cstart[v + 1]; i++) {
        uint32_t c = x->vcorner[i], base = c - c % 3;
        for (uint32_t j = 1; j <= 2; j++) {
            uint32_t o = base + (c % 3 + j) % 3;
            s += curve_cost(x->tree, &x->c->pos[3 * v], n, &x->c->pos[3 * x->c->tri[o]],
                            &x->sn->normal[3 * x->sn->tri_normal[o]]);
        }
    }
    return s;
}

static void normalize3(double *n)
{
    double l = len3(n);
    n[0] /= l, n[1] /= l, n[2] /= l;
}

int fit_normals(const simp_mesh *fine, const simp_mesh *coarse, surf_normals *sn, fit_stats *st)
{
    memset(st, 0, sizeof *st);
    size_t nc = 3 * (size_t)coarse->ntris;
    cp_tree tree;
    uint32_t *cstart = calloc((size_t)coarse->nverts + 1, sizeof *cstart), *vcorner = calloc(nc ? nc : 1, sizeof *vcorner);
    double *orig = malloc((sn->nnormals ? sn->nnormals : 1) * 3 * sizeof *orig);
    if (!cstart || !vcorner || !orig || cp_build(&tree, fine->pos, fine->tri, fine->ntris)) {
        free(cstart), free(vcorner), free(orig);
        return -1;
    }
    memcpy(orig, sn->normal, sn->nnormals * 3 * sizeof *orig);
    for (size_t i = 0; i < nc; i++) cstart[coarse->tri[i] + 1]++;
    for (uint32_t v = 0; v < coarse->nverts; v++) cstart[v + 1] += cstart[v];
    for (size_t i = 0; i < nc; i++) vcorner[cstart[coarse->tri[i]]++] = (uint32_t)i;
    for (uint32_t v = coarse->nverts; v > 0; v--) cstart[v] = cstart[v - 1];
    cstart[0] = 0;
    fit_ctx x = { coarse, sn, &tree, cstart, vcorner };
    const double cos_max = cos(FIT_MAX_DEG * 3.14159265358979323846 / 180);

    double total0 = 0, total1 = 0;
    uint32_t samples = 0;
    for (uint32_t v = 0; v < coarse->nverts; v++) {
        total0 += vertex_cost(&x, v, &sn->normal[3 * sn->tri_normal[vcorner[cstart[v]]]]);
        samples += 6 * (cstart[v + 1] - cstart[v]);
    }
    static const double steps[] = { 0.2, 0.1, 0.05, 0.025, 0.012 };
    for (int sweep = 0; sweep < 2; sweep++)
        for (uint32_t v = 0; v < coarse->nverts; v++) {
            uint32_t g = sn->tri_normal[vcorner[cstart[v]]], split = 0;
            for (uint32_t i = cstart[v]; i < cstart[v + 1]; i++) split |= sn->tri_normal[vcorner[i]] != g;
            if (split || cstart[v + 1] == cstart[v]) continue;
            double *n = &sn->normal[3 * g], *o = &orig[3 * g];
            /* two directions in the original tangent plane */
            double e1[3], e2[3], a[3] = { 1, 0, 0 };
            if (fabs(o[0]) > 0.9) a[0] = 0, a[1] = 1;
            cross3(o, a, e1);
            normalize3(e1);
            cross3(o, e1, e2);
            double best = vertex_cost(&x, v, n);
            for (size_t s = 0; s < sizeof steps / sizeof steps[0]; s++) {
                int improved = 1;
                while (improved) {
                    improved = 0;
                    for (int d = 0; d < 4; d++) {
                        const double *e = d < 2 ? e1 : e2;
                        double sg = d % 2 ? -steps[s] : steps[s], m[3];
                        for (int k = 0; k < 3; k++) m[k] = n[k] + sg * e[k];
                        normalize3(m);
                        if (dot3(m, o) < cos_max) continue;
                        double cst = vertex_cost(&x, v, m);
                        if (cst < best * (1 - 1e-9)) {
                            best = cst;
                            memcpy(n, m, sizeof m);
                            improved = 1;
                        }
                    }
                }
            }
        }
    for (uint32_t g = 0; g < sn->nnormals; g++) st->moved += dot3(&sn->normal[3 * g], &orig[3 * g]) < 1 - 1e-12;
    for (uint32_t v = 0; v < coarse->nverts; v++)
        total1 += vertex_cost(&x, v, &sn->normal[3 * sn->tri_normal[vcorner[cstart[v]]]]);
    st->before = samples ? total0 / samples : 0;
    st->after = samples ? total1 / samples : 0;
    cp_free(&tree);
    free(cstart), free(vcorner), free(orig);
    return 0;
}
