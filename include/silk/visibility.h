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

#endif
