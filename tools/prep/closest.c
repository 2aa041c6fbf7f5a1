/*
 * closest.c - point-to-mesh distance through a box hierarchy (closest.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "closest.h"
#include "vec3.h"

#define LEAF_TRIS 4

double point_tri_d2(const double *p, const double *a, const double *b, const double *c)
{
    double q[3];
    return point_tri_closest(p, a, b, c, q);
}

double point_tri_closest(const double *p, const double *a, const double *b, const double *c, double *q)
{
    double ab[3], ac[3], ap[3];
    sub3(b, a, ab), sub3(c, a, ac), sub3(p, a, ap);
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap), v, w;
    if (d1 <= 0 && d2 <= 0) { memcpy(q, a, 3 * sizeof *q); goto out; }
    double bp[3];
    sub3(p, b, bp);
    double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3) { memcpy(q, b, 3 * sizeof *q); goto out; }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        for (int k = 0; k < 3; k++) q[k] = a[k] + v * ab[k];
        goto out;
    }
    double cp[3];
    sub3(p, c, cp);
    double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6) { memcpy(q, c, 3 * sizeof *q); goto out; }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 / (d2 - d6);
        for (int k = 0; k < 3; k++) q[k] = a[k] + w * ac[k];
        goto out;
    }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; k++) q[k] = b[k] + w * (c[k] - b[k]);
        goto out;
    }
    double den = 1 / (va + vb + vc);
    v = vb * den, w = vc * den;
    for (int k = 0; k < 3; k++) q[k] = a[k] + ab[k] * v + ac[k] * w;
out:;
    double d[3];
    sub3(p, q, d);
    return dot3(d, d);
}

static double centroid(const cp_tree *t, uint32_t f, int axis)
{
    const uint32_t *v = &t->tri[3 * f];
    return t->pos[3 * v[0] + axis] + t->pos[3 * v[1] + axis] + t->pos[3 * v[2] + axis];
}

static int axis_g;
static const cp_tree *tree_g;
static int by_centroid(const void *a, const void *b)
{
    double x = centroid(tree_g, *(const uint32_t *)a, axis_g), y = centroid(tree_g, *(const uint32_t *)b, axis_g);
    return x < y ? -1 : x > y;
}

/* Node n over order[first .. first+count): its box, then its children. */
static void build(cp_tree *t, uint32_t n, uint32_t first, uint32_t count)
{
    cp_node *nd = &t->node[n];
    for (int k = 0; k < 3; k++) nd->lo[k] = INFINITY, nd->hi[k] = -INFINITY;
    double clo[3] = { INFINITY, INFINITY, INFINITY }, chi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (uint32_t i = first; i < first + count; i++)
        for (int c = 0; c < 3; c++) {
            const double *p = &t->pos[3 * t->tri[3 * t->order[i] + c]];
            for (int k = 0; k < 3; k++) {
                if (p[k] < nd->lo[k]) nd->lo[k] = p[k];
                if (p[k] > nd->hi[k]) nd->hi[k] = p[k];
            }
        }
    if (count <= LEAF_TRIS) {
        nd->first = first;
        nd->count = count;
        return;
    }
    for (uint32_t i = first; i < first + count; i++)
        for (int k = 0; k < 3; k++) {
            double c = centroid(t, t->order[i], k);
            if (c < clo[k]) clo[k] = c;
            if (c > chi[k]) chi[k] = c;
        }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    axis_g = axis;
    tree_g = t;
    qsort(&t->order[first], count, sizeof *t->order, by_centroid);
    uint32_t left = t->nnodes;
    t->nnodes += 2;
    nd->first = left;
    nd->count = 0;
    build(t, left, first, count / 2);
    build(t, left + 1, first + count / 2, count - count / 2);
}

int cp_build(cp_tree *t, const double *pos, const uint32_t *tri, uint32_t ntris)
{
    memset(t, 0, sizeof *t);
    t->pos = pos;
    t->tri = tri;
    t->order = malloc((ntris ? ntris : 1) * sizeof *t->order);
    t->node = malloc((2 * (size_t)ntris + 1) * sizeof *t->node);
    if (!t->order || !t->node) {
        cp_free(t);
        return -1;
    }
    for (uint32_t i = 0; i < ntris; i++) t->order[i] = i;
    t->nnodes = 1;
    build(t, 0, 0, ntris);
    return 0;
}

static double box_d2(const cp_node *n, const double p[3])
{
    double s = 0;
    for (int k = 0; k < 3; k++) {
        double d = p[k] < n->lo[k] ? n->lo[k] - p[k] : p[k] > n->hi[k] ? p[k] - n->hi[k] : 0;
        s += d * d;
    }
    return s;
}

double cp_dist2(const cp_tree *t, const double p[3]) { return cp_nearest(t, p, NULL); }

double cp_nearest(const cp_tree *t, const double p[3], uint32_t *tri)
{
    uint32_t stack[128];
    int sp = 0;
    double best = INFINITY;
    stack[sp++] = 0;
    while (sp > 0) {
        const cp_node *n = &t->node[stack[--sp]];
        if (box_d2(n, p) >= best) continue;
        if (n->count) {
            for (uint32_t i = n->first; i < n->first + n->count; i++) {
                const uint32_t *v = &t->tri[3 * t->order[i]];
                double d = point_tri_d2(p, &t->pos[3 * v[0]], &t->pos[3 * v[1]], &t->pos[3 * v[2]]);
                if (d < best) {
                    best = d;
                    if (tri) *tri = t->order[i];
                }
            }
        } else if (sp + 2 <= 128) {
            /* the nearer child last, so it is searched first */
            double a = box_d2(&t->node[n->first], p), b = box_d2(&t->node[n->first + 1], p);
            stack[sp++] = a < b ? n->first + 1 : n->first;
            stack[sp++] = a < b ? n->first : n->first + 1;
        }
    }
    return best;
}

void cp_free(cp_tree *t)
{
    free(t->order);
    free(t->node);
    memset(t, 0, sizeof *t);
}
