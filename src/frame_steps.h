/*
 * frame_steps.h - internal: one object's frame in steps, for a frame of
 * several objects (scene.c).  Not installed; render.c defines them from
 * its own stages, so an object of a scene is drawn exactly as
 * silk_render() draws a mesh alone, only into a band the scene cleared or
 * painted, with the depth every object shares.
 *
 * The order, per frame: prepare every object (its plan: visibility,
 * silhouette), then its extras (what it keeps for speed, from what the
 * arena has left), then per band: the band cleared or painted, every
 * object drawn into it, every object's outline walked into one silk_aa
 * (aa.h) begun over it, and the outline's pixels written once.  Each step
 * takes the object's own view, HAL and options, as silk_render() does.
 */
#ifndef SILK_FRAME_STEPS_H
#define SILK_FRAME_STEPS_H

#include "silk/silk.h"
#include "aa.h"

typedef struct silk_frame_step silk_frame_step;   /* render.c's frame, with what its build keeps */

/* Prepare one object's frame for band (its rows: the whole frame, or the
 * band height of silk_render_bands) with the frame's memory from the top
 * of the arena; after: some object is drawn before it into the same
 * depth.  *out is set even on failure (NULL only when its memory did not
 * fit); the caller releases the arena. */
silk_status silk_frame_step_prepare(silk_frame_step **out, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                    const silk_hal *h, const silk_render_opts *o, const silk_target *band, int after,
                                    silk_frame_stats *stats, silk_error *err);
/* The records of the object's largest share (silk_aa_begin's max_recs). */
uint32_t silk_frame_step_max_recs(const silk_frame_step *f);
/* What the frame keeps for speed, leaving reserve bytes free (at least
 * its own outline's: silk_aa_bytes_n's for every object's at once), and
 * the rows its parts reach for bands. */
void silk_frame_step_extras(silk_frame_step *f, silk_arena *a, const silk_mesh *m, const silk_hal *h,
                            const silk_render_opts *o, silk_target *band, size_t reserve);
/* The object's triangles (and lines) into t, which is not cleared. */
void silk_frame_step_draw(silk_frame_step *f, const silk_render_opts *o, silk_target *t);
/* 1 when its outline is walked into a silk_aa over t (FLAT, SMOOTH and
 * SILTEX frames drawn share by share, with aa), 2 when it is CLIP's own
 * (silk_frame_step_clip_aa), else 0. */
int silk_frame_step_outline_kind(const silk_frame_step *f, const silk_render_opts *o, const silk_target *t);
void silk_frame_step_outline(silk_frame_step *f, silk_arena *a, const silk_view *v, const silk_render_opts *o,
                             silk_aa *aa, silk_frame_stats *stats);
void silk_frame_step_clip_aa(silk_frame_step *f, const silk_render_opts *o, silk_target *t);
/* The arena's top high-water before the extras, and the bytes the extras
 * took: the frame's need leaves those out (silk_frame_stats.frame_bytes). */
void silk_frame_step_need(const silk_frame_step *f, size_t *peak_before, size_t *extra_bytes);
/* CLIP: runs of stencil pixels drawn (silk_frame_stats.clip_spans). */
uint32_t silk_frame_step_clip_spans(const silk_frame_step *f);

#endif
