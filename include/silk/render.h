/*
 * silk/render.h - one frame, start to finish.
 *
 * silk_render() runs the per-frame pipeline: visibility -> silhouette
 * triangles -> bridges, points, segments -> adaptive sampling -> re-meshing
 * and perturbation (mode SMOOTH), or the coarse mesh as it is (mode FLAT),
 * or one of the two reference methods (modes PN and BLEND, docs/methods.md);
 * then the HAL's vertex stage over the vertex records, and the rasterizer
 * over every triangle for the target's band.  FLAT and SMOOTH frames without
 * lines are streamed: only the silhouette plan is kept, and each input
 * triangle's records are rebuilt and evaluated when a band needs them (same
 * pixels, a fraction of the memory: docs/small-devices.md).  Per-frame
 * memory comes from the top of the arena and is released before it returns.
 * A device build may leave PN and BLEND out (SILK_REFERENCE_MODES 0), and
 * the pen-and-ink lines and wire (SILK_LINES 0): silk/config.h.
 */
#ifndef SILK_RENDER_H
#define SILK_RENDER_H

#include <stddef.h>
#include "fixed.h"
#include "arena.h"
#include "error.h"
#include "mesh.h"
#include "camera.h"
#include "raster.h"
#include "hal.h"
#include "visibility.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_mode {
    SILK_MODE_FLAT = 0,      /* the coarse mesh as it is, Phong shaded */
    SILK_MODE_SMOOTH = 1,    /* silhouette smoothing (paper section III) */
    SILK_MODE_PN = 2,        /* PN triangles (Vlachos et al. 2001), uniformly tessellated */
    SILK_MODE_BLEND = 3,     /* silhouetteness blending (Dyken & Reimers), docs/methods.md */
    SILK_MODE_CLIP = 4,      /* the outer hull clipped to the detailed model's silhouette (docs/clipping.md) */
    SILK_MODE_SILTEX = 5     /* the outer hull drawn through a silhouette texture (docs/siltex.md) */
} silk_mode;

/* The normal patch of PN mode: Vlachos' quadratic one, or the corner
 * normals interpolated linearly (paper section V compares both). */
typedef enum silk_pn_normals { SILK_PN_QUADRATIC = 0, SILK_PN_LINEAR = 1 } silk_pn_normals;

/* PN mode's level L: every patch side is cut into L segments, so a patch
 * becomes L*L triangles over (L+1)(L+2)/2 points; level 1 is the coarse mesh. */
#define SILK_PN_MAX_LEVEL 32u

/* Pen-and-ink lines (src/lines.c): in SMOOTH mode the sampled silhouette
 * segments and the visible feature curves, exactly as the re-meshed surface
 * runs along them, and the contour of the drawn triangles (every side
 * between two that face opposite ways), so the whole outline is drawn; in
 * FLAT mode, or with lines_polygonal in any mode, the
 * coarse mesh's silhouette edges (between a front- and a back-facing
 * triangle) and its feature edges next to a front-facing triangle.  PN and
 * BLEND draw patches that bulge over those edges, so there lines without
 * lines_polygonal are SILK_ERR_ARG.  Lines are depth-tested against the
 * drawn surface, so hidden parts stay hidden. */
typedef enum silk_lines {
    SILK_LINES_NONE = 0,
    SILK_LINES_OVER = 1,     /* over the shaded surface */
    SILK_LINES_ONLY = 2      /* the surface only hides lines: lines on the background */
} silk_lines;

/* Where a frame's time goes, for profiling on a device (docs/small-devices.md,
 * "Speed on the device").  Optional: with render_opts.clock set, the
 * renderer reads clock->now(clock->user), any free-running counter that
 * counts up and wraps, before and after each piece of a stage and adds the
 * difference to ticks[stage], counting the pieces in pieces[stage] (so the
 * reads' own cost can be taken off).  The caller zeroes ticks and pieces.
 * Timed: the visibility test and the silhouette plan of a SMOOTH frame drawn
 * share by share (FLAT and SMOOTH without lines), every share's emission and
 * vertex stage, and the rasterizer with the band clears (the fragment stage
 * runs inside it; a HAL wrapper can time that alone).  Without a clock
 * (NULL, the default) nothing is read. */
typedef enum silk_stage {
    SILK_STAGE_VISIBILITY = 0, /* which normals face the eye (III-B) */
    SILK_STAGE_PLAN = 1,       /* silhouette plan: triangles, points, sampling, perturbation */
    SILK_STAGE_EMIT = 2,       /* each input triangle's share: records, curves, triangles */
    SILK_STAGE_VERTEX = 3,     /* the HAL's vertex stage over the share's records */
    SILK_STAGE_RASTER = 4,     /* clears, spans, depth; the fragment stage included */
    SILK_STAGE_COUNT = 5
} silk_stage;

typedef struct silk_stage_clock {
    uint32_t (*now)(void *user);
    void *user;
    uint32_t ticks[SILK_STAGE_COUNT];
    uint32_t pieces[SILK_STAGE_COUNT];
} silk_stage_clock;

/* "visibility", "plan", "emit", "vertex", "raster"; "?" for anything else. */
const char *silk_stage_name(silk_stage s);

typedef struct silk_render_opts {
    silk_mode mode;
    silk_fx tolerance_px;    /* e of eq. 8, 0.25 .. 4 (BLEND: the chord tolerance of its edges) */
    silk_vis_method visibility; /* how SMOOTH finds the front-facing normals */
    int wire;                /* draw edges; triangles added by re-meshing in red */
    uint32_t wire_rgb, wire_new_rgb;
    uint32_t bg_rgb;
    uint32_t level;          /* PN: segments per patch side, 1..SILK_PN_MAX_LEVEL */
    silk_pn_normals pn_normals; /* PN: quadratic or linear normals */
    silk_fx blend_beta;      /* BLEND: width of the transition of eq. 2, 0..1 (0: binary) */
    silk_lines lines;        /* outlines: none (default), over the shading, or alone */
    int lines_polygonal;     /* the coarse mesh's polygonal outline even in SMOOTH mode */
    uint32_t line_rgb;       /* silhouette lines */
    uint32_t line_feature_rgb; /* feature lines */
    silk_stage_clock *clock; /* per-stage timing, or NULL (above) */
    /* The most bytes of the arena the vertex cache may take (src/render.c:
     * with the default vertex stage, each mesh vertex is evaluated once per
     * frame instead of once per triangle corner).  It takes at most half of
     * what the frame leaves and at least 64 slots of 72 bytes (80 in a
     * flat frame, which keeps each vertex's screen position too), else
     * nothing; the pixels are the same either way.  The anti-aliased
     * outline's memo of which way each triangle faces (2 bits per
     * triangle) and, in a flat frame of a closed mesh, its outline
     * candidates (1 bit per triangle) come out of the same budget.
     * Default SIZE_MAX; a device whose RAM budget is
     * tight sets what it can spare, 0 for none (and may leave the code
     * out: SILK_VERTEX_CACHE 0, silk/config.h). */
    size_t vertex_cache_bytes;
    /* CLIP: the model's silhouette map (silk_model_silmap), the polytope
     * triangle to start looking for the eye from (the last frame's
     * silk_frame_stats.clip_tri); aa below anti-aliases its outline too */
    const struct silk_silmap *silmap;
    uint32_t silmap_hint;
    int aa;                  /* anti-aliased outlines (default 1; FLAT, SMOOTH and CLIP frames without lines),
                                and visible creases in FLAT and SMOOTH; 2: the outlines only */
    /* SILTEX: the model's silhouette texture (silk_model_siltex); the mesh
     * drawn is the model's hull, the HAL's stages shade it */
    const struct silk_siltex *siltex;
} silk_render_opts;

void silk_render_opts_default(silk_render_opts *o);
/* "flat", "smooth", "pn", "blend", "clip", "siltex"; "?" for anything else. */
const char *silk_mode_name(silk_mode mode);
/* The inverse (src/mode.c): a name silk_mode_name returns, or "pnL" for PN
 * triangles at level L (1..SILK_PN_MAX_LEVEL, no leading zero).  Sets *mode
 * and *level (0 when the name gives none) and returns 0, or returns -1 and
 * leaves both alone. */
int silk_mode_parse(const char *name, silk_mode *mode, uint32_t *level);

typedef struct silk_frame_stats {
    uint32_t silhouette_tris, bridges, samples, tris_drawn, moved_vertices;
    uint32_t flat_segments;  /* SMOOTH: concave silhouette segments the perturbation could not unblock
                                safely (perturb.c), so the coarse mesh's outline is drawn there instead
                                of a curve; counted by host builds only (a board's frame has the same
                                pixels and reports 0) */
    size_t frame_bytes;      /* per-frame arena bytes at the frame's peak */
    int fell_back;           /* 1 if the arena ran out and part of the frame was drawn unsmoothed */
    uint32_t clip_tri;       /* CLIP: the polytope triangle the eye was found in */
    uint32_t clip_points;    /* CLIP: vertices of the interpolated outline polygon */
    uint32_t clip_spans;     /* CLIP: runs of stencil pixels over the frame's rows */
    uint32_t aa_aliased;     /* outline pixels left aliased: a band's pixel list (about 3 x (width + rows))
                                was full, or the arena had no room for it (then at least 1).  Only when it
                                is 0 for both are a banded frame and the whole frame the same bytes. */
} silk_frame_stats;

silk_status silk_render(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                        const silk_render_opts *o, silk_target *t, silk_frame_stats *stats,
                        silk_error *err);

/* Band rendering for devices without a frame buffer: band's buffers hold
 * band->rows lines of band->width pixels (band->height is the frame height);
 * the frame is drawn band by band from the top, each finished band handed to
 * sink->band (as an SPI display driver takes it).  The per-frame silhouette
 * work runs once per frame, not once per band; a streamed frame rebuilds,
 * per band, only the triangles that reach into it (stored frames go through
 * the vertex stage once).  Pixels are identical to silk_render()'s.
 *
 * Double-buffered bands, for a sink that sends a band while the next one is
 * drawn (a DMA transfer to an SPI panel, platform/panel/silk_panel.h): give
 * color2, a second colour buffer of band->rows * band->stride bytes, and
 * wait.  The bands are then drawn into band->color and color2 in turn
 * (the first band of every frame into band->color), and before the
 * renderer draws into either it calls wait(user, buffer), which returns 0
 * once the sink has finished reading that buffer (at once when it is not
 * being sent), or non-zero to stop the frame (SILK_ERR_IO).  band() may
 * then return as soon as the transfer has started.  The call returns after
 * handing over the last band, which may still be in transfer: the sink's
 * own flush (silk_panel_flush) waits for it.  Only the colour is double
 * buffered: the depth buffer (and alpha, if any) is the renderer's again
 * when band() returns.  color2 and wait go together (one alone is
 * SILK_ERR_ARG); both NULL, the default of a sink set up as { .band = f, .user = u },
 * is one buffer, which the sink is done with when band() returns. */
typedef struct silk_sink {
    /* return 0 to go on, non-zero to stop the frame (reported as SILK_ERR_IO) */
    int (*band)(void *user, const silk_target *band);
    void *user;
    uint8_t *color2;                                  /* the second colour buffer, or NULL */
    int (*wait)(void *user, const uint8_t *color);    /* that buffer free: 0 to go on */
} silk_sink;

silk_status silk_render_bands(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                              const silk_render_opts *o, silk_target *band, const silk_sink *sink,
                              silk_frame_stats *stats, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
