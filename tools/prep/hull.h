/*
 * hull.h - progressive outer and inner hulls (Gu, Gortler, Hoppe et al.,
 * "Silhouette Mapping", Harvard TR-1-99, section 7): a coarse mesh that
 * contains the detailed one.
 *
 * Edge collapses that only ever move the surface outward: the merged
 * vertex lies outside (or on) the plane of every face around the edge
 * before the collapse, placed by a linear program (tools/prep/lp.c) that
 * minimises the volume the collapse adds; an edge with no such point is
 * not collapsed.  Then the winding number of every point of space only
 * grows, so each mesh of the sequence holds the one before it, down to the
 * detailed mesh (positive winding rule).  The inner hull is the same run on
 * the mesh turned inside out.  Host-side, double precision.
 */
#ifndef SILK_TOOLS_HULL_H
#define SILK_TOOLS_HULL_H

#include <stdint.h>

#include "simplify.h"

typedef struct hull_opts {
    uint32_t target_tris;    /* stop at this many triangles or fewer */
    int inner;               /* 1: the inner hull */
    /* Merged vertices are placed on this grid (silk's Q16.16 step, 1/65536,
     * by default) and at least this far outside every plane they must not
     * cross, so the hull still holds the detailed mesh once its coordinates
     * are fixed point.  0: no grid, and a margin of 1e-9 of the mesh's size. */
    double grid;
} hull_opts;

/* Outer hull, the Q16.16 grid. */
void hull_opts_default(hull_opts *o, uint32_t target_tris);

typedef struct hull_stats {
    uint32_t tris_in, tris_out, verts_out;
    uint32_t collapses;
    uint32_t refused_infeasible;   /* no point outside every plane (per attempt) */
    uint32_t refused_topology;     /* link condition, degree (per attempt) */
    uint32_t refused_shape;        /* a triangle would turn over (per attempt) */
    uint32_t lps;                  /* linear programs solved */
    double volume_in, volume_out;
} hull_stats;

/* What each hull vertex stands for on the detailed surface (section 7,
 * "closest point"): every vertex of the detailed mesh stands for itself,
 * with its area-weighted normal; a merged vertex for what its closest point
 * on the faces around the edge before the collapse stands for, interpolated
 * there.  malloc'd, 3 doubles per output vertex; hull_fine_free. */
typedef struct hull_fine {
    double *point;           /* near the detailed surface */
    double *normal;          /* unit, outward */
} hull_fine;
void hull_fine_free(hull_fine *f);

/* Replace m (closed, manifold, consistently oriented with outward normals:
 * the caller checks) by its hull, and fill fine (unless NULL) for its
 * vertices.  Returns 0, or -1 when out of memory (m is then unchanged).  It
 * stops early only when every remaining collapse is refused; stats tell how
 * far it got. */
int hull_run(simp_mesh *m, const hull_opts *o, hull_stats *st, hull_fine *fine);

/* The volume m encloses (positive for outward normals). */
double hull_volume(const simp_mesh *m);

#endif
