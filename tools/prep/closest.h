/*
 * closest.h - distance from a point to a triangle mesh, through a bounding
 * volume hierarchy of its triangles (axis-aligned boxes, split at the
 * median of the longest axis).  Host-side, double precision; for `silk
 * prepare --fit` and the tests that measure how far one mesh lies from
 * another.
 */
#ifndef SILK_TOOLS_CLOSEST_H
#define SILK_TOOLS_CLOSEST_H

#include <stdint.h>

/* Squared distance from p to triangle abc (closest point by regions,
 * Ericson, Real-Time Collision Detection 5.1.5). */
double point_tri_d2(const double *p, const double *a, const double *b, const double *c);
/* The same, and the closest point itself in q. */
double point_tri_closest(const double *p, const double *a, const double *b, const double *c, double *q);

typedef struct cp_node {
    double lo[3], hi[3];
    uint32_t first, count;   /* leaf: triangles order[first .. first+count); inner: count 0, children first, first+1 */
} cp_node;

typedef struct cp_tree {
    const double *pos;       /* 3 per vertex, not owned */
    const uint32_t *tri;     /* 3 per triangle, not owned */
    uint32_t *order;         /* triangle indices, grouped by leaf */
    cp_node *node;
    uint32_t nnodes;
} cp_tree;

/* 0, or -1 when out of memory.  pos and tri must outlive the tree. */
int cp_build(cp_tree *t, const double *pos, const uint32_t *tri, uint32_t ntris);
/* Squared distance from p to the nearest triangle; its index in *tri when
 * tri is not NULL. */
double cp_dist2(const cp_tree *t, const double p[3]);
double cp_nearest(const cp_tree *t, const double p[3], uint32_t *tri);
void cp_free(cp_tree *t);

#endif
