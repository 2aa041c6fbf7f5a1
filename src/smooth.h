/*
 * smooth.h - internal: running the SMOOTH stages (smooth.c) for a frame
 * drawn one input triangle's share at a time.  silk_frame_smooth, the stored frame, is declared in frame.h.  Not
 * installed.
 */
#ifndef SILK_SMOOTH_H
#define SILK_SMOOTH_H

#include "plan.h"

/* The plan of a frame into f and room for one input triangle's
 * share in local, all from the top of the arena (the caller releases it;
 * silk_remesh_stats gives the frame's counts).  tolerance_px > 0 (the
 * caller checks it).  clock, when not NULL, times the visibility test.
 * The caller sets f->keep, NULL or where the plan may keep its segments,
 * edge tangents and rank for speed with keep->room the most it may take
 * (silk_remesh_keep; 0: nothing kept).  Returns 0 when it does not fit:
 * then nothing is left allocated and the caller draws the coarse mesh, or
 * asks again with room 0 when something was kept (keep->kept_bytes).
 * cur is the cursor of those who read the plan (f->cur): the emitter's. */
int silk_frame_smooth_plan(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tolerance_px,
                           silk_vis_method vis, silk_stage_clock *clock, silk_sil_frame *f, silk_sil_cursor *cur,
                           silk_frame_geom *local);

#endif
