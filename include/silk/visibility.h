/*
 * silk/visibility.h - which shading normals face the viewer (paper III-B).
 *
 * A normal N at vertex V is visible when N.(E - V) >= 0 in perspective, or
 * N.D >= 0 in parallel projection, with D the direction towards the viewer
 * (-forward).  The sign is taken from an exact 64-bit dot product, so the
 * brute pass is the reference; the Gaussian-sphere hierarchy must agree with
 * it bit for bit.
 */
#ifndef SILK_VISIBILITY_H
#define SILK_VISIBILITY_H

#include <stddef.h>
#include <stdint.h>
#include "fixed.h"
#include "arena.h"
#include "error.h"
#include "mesh.h"
#include "camera.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_vis_method {
    SILK_VIS_AUTO = 0,     /* the faster of the two for this mesh size */
    SILK_VIS_BRUTE = 1,    /* one dot product per normal */
    SILK_VIS_GAUSS = 2     /* hierarchy over the Gaussian sphere (needs mesh->vis) */
} silk_vis_method;

typedef struct silk_vis_stats {
    uint32_t normals, cell_decided, one_by_one, cells_visited;
} silk_vis_stats;

/* visible[i] = 1 if mesh normal i faces the viewer, else 0 (nnormals bytes).
 * Scratch, if any, comes from the top of the arena and is released. */
silk_status silk_visibility(const silk_mesh *m, const silk_view *v, silk_vis_method method,
                            uint8_t *visible, silk_arena *a, silk_vis_stats *stats);

/* One normal, exactly as the brute pass decides it. */
int silk_normal_visible(const silk_mesh *m, const silk_view *v, uint32_t normal_index);

/* The brute pass alone: one exact dot product per normal, no scratch. */
void silk_visibility_brute(const silk_mesh *m, const silk_view *v, uint8_t *visible);

/* ---- the Gaussian-sphere hierarchy (src/gauss.c, docs/visibility.md) ------
 *
 * Every normal N at vertex V becomes the point V' = (N, w), w = -N.(V-C)/s,
 * of S^2 x [-1,1], which is S^3 in coordinates (latitude, longitude, w)
 * (C is the centre of the model, s a power of two >= every |N.(V-C)|).  A
 * view is E' = (E - C, s) in perspective and E' = (-forward, 0) in parallel
 * projection, and the normal is visible iff E'.V' >= 0, i.e. N.(E-V) >= 0.
 * Cells are boxes in (latitude, longitude, w) with eight corners; a level
 * halves latitude and longitude, and w where the normals spread in it (up to
 * eight children).  Their lat/long part is the four-corner cell of the
 * paper's Gaussian sphere, so one tree serves both projections.
 *
 * silk_vis_build renumbers the mesh's normals (normal, normal_vertex,
 * tri_normal) so that every cell's normals are one contiguous range: a
 * decided cell is one memset.  Nodes are in depth-first order, indices
 * only, no pointers: the array can live in flash. */
typedef struct silk_vis_node {
    int16_t c[3];          /* centre of the cell's lat/long cap, Q2.14 */
    uint16_t r;            /* radius, Q2.14: |N - c| <= r for the whole cell and every member */
    int16_t w0, w1;        /* the cell's w interval, Q2.14 */
    uint32_t first;        /* first normal of the cell */
    uint32_t skip;         /* node after this subtree (== own index + 1 for a leaf) */
} silk_vis_node;

typedef struct silk_vis {
    uint32_t nnodes;       /* the subtree of node i holds normals node[i].first .. node[i.skip].first - 1 */
    uint32_t nnormals;     /* nodes past the end count as starting at nnormals */
    uint32_t depth;        /* deepest level used (root = 0) */
    uint32_t leaf_max;     /* cells with at most this many normals are not split */
    silk_vec3 centre;      /* C */
    int32_t scale_log2;    /* s = 2^scale_log2 in Q16.16 units */
    uint32_t widened;      /* cells whose radius had to grow to hold a member: 0 means the
                              geometric bound alone covers every normal (see the tests) */
    const silk_vis_node *node;
} silk_vis;

typedef struct silk_vis_opts {
    uint32_t max_depth;    /* 1..10, 0 = chosen from the mesh size */
    uint32_t leaf_max;     /* 0 = default */
} silk_vis_opts;

/* Build the hierarchy for m at load time and set m->vis (purpose
 * VISIBILITY; scratch from the arena top, released).  Renumbers m's
 * normals (see above).  opts may be NULL.  Fails cleanly on a bad mesh or a
 * full arena; the hierarchy takes at most 8 bytes per normal. */
silk_status silk_vis_build(silk_mesh *m, const silk_vis_opts *opts, silk_arena *a, silk_error *err);

/* Bytes the hierarchy takes (struct + nodes), for `silk info`; 0 for NULL. */
size_t silk_vis_bytes(const silk_vis *v);

/* The hierarchy pass: fails (SILK_ERR_ARG) when m->vis is NULL or stale. */
silk_status silk_visibility_gauss(const silk_mesh *m, const silk_view *v, uint8_t *visible,
                                  silk_vis_stats *stats);

/* The ball bound of one lat/long cell of the given level (for the tests and
 * docs): centre c (Q16.16, unit) and radius r (Q16.16) with |X - c| <= r for
 * every unit X of the cell, bulging latitude arcs included.  Returns 0 for an
 * out-of-range cell. */
int silk_vis_cell_ball(uint32_t level, uint32_t lat, uint32_t lon, silk_vec3 *c, silk_fx *r);

/* SILK_VIS_AUTO uses the hierarchy (when built) from this many normals on;
 * the break-even measured with `silk bench --visibility`, docs/visibility.md. */
#define SILK_VIS_AUTO_PERSPECTIVE 240u
#define SILK_VIS_AUTO_PARALLEL    256u

#ifdef __cplusplus
}
#endif

#endif
