/*
 * silk/render.h - one frame, start to finish.
 *
 * silk_render() runs the per-frame pipeline: visibility -> silhouette
 * triangles -> bridges, points, segments -> adaptive sampling -> re-meshing
 * and perturbation (mode SMOOTH), or the coarse mesh as it is (mode FLAT);
 * then the HAL's vertex stage over every vertex record once, and the
 * rasterizer over every triangle for the target's band.  Per-frame memory
 * comes from the top of the arena and is released before it returns.
 */
#ifndef SILK_RENDER_H
#define SILK_RENDER_H

#include "fixed.h"
#include "arena.h"
#include "error.h"
#include "mesh.h"
#include "camera.h"
#include "raster.h"
#include "hal.h"

typedef enum silk_mode {
    SILK_MODE_FLAT = 0,      /* the coarse mesh as it is, Phong shaded */
    SILK_MODE_SMOOTH = 1     /* silhouette smoothing (paper section III) */
} silk_mode;

typedef struct silk_render_opts {
    silk_mode mode;
    silk_fx tolerance_px;    /* e of eq. 8, 0.25 .. 4 */
    int wire;                /* draw edges; triangles added by re-meshing in red */
    uint32_t wire_rgb, wire_new_rgb;
    uint32_t bg_rgb;
} silk_render_opts;

void silk_render_opts_default(silk_render_opts *o);

typedef struct silk_frame_stats {
    uint32_t silhouette_tris, bridges, samples, tris_drawn, moved_vertices;
    size_t frame_bytes;      /* per-frame arena bytes at the frame's peak */
    int fell_back;           /* 1 if the arena ran out and part of the frame was drawn unsmoothed */
} silk_frame_stats;

silk_status silk_render(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                        const silk_render_opts *o, silk_target *t, silk_frame_stats *stats,
                        silk_error *err);

/* Band rendering for devices without a frame buffer: band's buffers hold
 * band->rows lines of band->width pixels (band->height is the frame height);
 * the frame is drawn band by band from the top, each finished band handed to
 * sink->band (as an SPI display driver takes it).  The per-frame silhouette
 * work and the vertex stage run once per frame, not once per band; only the
 * rasterizer runs per band.  Pixels are identical to silk_render()'s. */
typedef struct silk_sink {
    /* return 0 to go on, non-zero to stop the frame (reported as SILK_ERR_IO) */
    int (*band)(void *user, const silk_target *band);
    void *user;
} silk_sink;

silk_status silk_render_bands(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                              const silk_render_opts *o, silk_target *band, const silk_sink *sink,
                              silk_frame_stats *stats, silk_error *err);

#endif
