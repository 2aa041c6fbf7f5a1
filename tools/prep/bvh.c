/*
 * bvh.c - ray casting through the box hierarchy of closest.c (bvh.h).
 */
#include <math.h>

#include "bvh.h"
#include "vec3.h"

double ray_tri(const double o[3], const double d[3], const double *a, const double *b, const double *c)
{
    double e1[3], e2[3], pv[3], tv[3], qv[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(d, e2, pv);
    double det = dot3(e1, pv);
    if (det == 0) return INFINITY;
    double inv = 1 / det;
    sub3(o, a, tv);
    double u = dot3(tv, pv) * inv;
    if (u < 0 || u > 1) return INFINITY;
    cross3(tv, e1, qv);
    double v = dot3(d, qv) * inv;
    if (v < 0 || u + v > 1) return INFINITY;
    return dot3(e2, qv) * inv;
}

/* Entry distance of the ray into the node's box, INFINITY when it misses
 * the box within (tmin, tmax). */
static double box_enter(const cp_node *n, const double o[3], const double inv[3], double tmin, double tmax)
{
    for (int k = 0; k < 3; k++) {
        double t0 = (n->lo[k] - o[k]) * inv[k], t1 = (n->hi[k] - o[k]) * inv[k];
        if (t0 > t1) { double s = t0; t0 = t1; t1 = s; }
        /* inv = +-inf and a zero numerator give NaN: the ray runs in the slab's plane */
        if (t0 == t0 && t0 > tmin) tmin = t0;
        if (t1 == t1 && t1 < tmax) tmax = t1;
        if (tmin > tmax) return INFINITY;
    }
    return tmin;
}

double bvh_ray(const cp_tree *t, const double o[3], const double d[3], double tmin, double tmax, uint32_t skip,
               uint32_t *tri)
{
    double inv[3] = { 1 / d[0], 1 / d[1], 1 / d[2] }, best = tmax;
    int found = 0;
    uint32_t stack[128];
    int sp = 0;
    if (!t->nnodes || box_enter(&t->node[0], o, inv, tmin, best) == INFINITY) return INFINITY;
    stack[sp++] = 0;
    while (sp > 0) {
        const cp_node *n = &t->node[stack[--sp]];
        if (box_enter(n, o, inv, tmin, best) == INFINITY) continue;
        if (n->count) {
            for (uint32_t i = n->first; i < n->first + n->count; i++) {
                uint32_t f = t->order[i];
                if (f == skip) continue;
                const uint32_t *v = &t->tri[3 * f];
                double h = ray_tri(o, d, &t->pos[3 * v[0]], &t->pos[3 * v[1]], &t->pos[3 * v[2]]);
                if (h > tmin && h < best) {
                    best = h;
                    found = 1;
                    if (tri) *tri = f;
                }
            }
        } else if (sp + 2 <= 128) {
            double a = box_enter(&t->node[n->first], o, inv, tmin, best);
            double b = box_enter(&t->node[n->first + 1], o, inv, tmin, best);
            /* the nearer child last, so it is searched first */
            if (a != INFINITY && b != INFINITY) {
                stack[sp++] = a < b ? n->first + 1 : n->first;
                stack[sp++] = a < b ? n->first : n->first + 1;
            } else if (a != INFINITY) {
                stack[sp++] = n->first;
            } else if (b != INFINITY) {
                stack[sp++] = n->first + 1;
            }
        }
    }
    return found ? best : INFINITY;
}
