/*
 * smooth.c - one frame of silhouette smoothing (paper section III, Fig. 7):
 * the plan - visibility and silhouette triangles, bridges and silhouette
 * points (silhouette.c), segments and what they cost (remesh.c), vertex
 * perturbation (perturb.c) - and then the emission (remesh.c), one input
 * triangle's share at a time (silk_frame_smooth_plan keeps the plan and
 * room for one share, what the renderer uses) or stored for the whole
 * frame (silk_frame_smooth, for lines and for callers that want the
 * geometry; plan.h).
 *
 * Memory runs out gracefully, the same way for every frame: a plan (or a
 * stored frame's output) that does not fit turns the frame into the coarse
 * mesh (silk_frame_fall_back, flat.c), stats->fell_back is set and the frame
 * is still drawn.
 */
#include <string.h>
#include "smooth.h"
#include "remesh.h"
#include "perturb.h"
#include "lines.h"

silk_status silk_frame_smooth(silk_arena *a, const silk_mesh *m, const silk_view *v,
                              silk_fx tolerance_px, silk_vis_method vis,
                              silk_frame_geom *g, silk_frame_stats *stats, silk_error *err)
{
    return silk_frame_smooth_lines(a, m, v, tolerance_px, vis, 0, g, stats, err);
}

/* The plan of a frame (silhouette.c, remesh.c, perturb.c) into f, from the
 * top of the arena, and the perturbation; 0 when it does not fit. */
static int make_plan(silk_sil_frame *f, silk_sil_cursor *cur, silk_arena *a, const silk_mesh *m, const silk_view *v,
                     silk_fx tolerance_px, silk_vis_method vis, silk_stage_clock *clock)
{
    silk_sil_keep *keep = SILK_SIL_KEEPS ? f->keep : NULL;   /* the caller's, the one field it sets */
    memset(f, 0, sizeof *f);
    if (keep) {
        size_t room = keep->room;
        memset(keep, 0, sizeof *keep);
        keep->room = room;
        f->keep = keep;
    }
    f->cur = cur;
    f->clock = clock;
    f->a = a;
    f->m = m;
    f->v = v;
    f->tol = tolerance_px;
    f->vis = vis;
    if (silk_sil_find(f) != SILK_OK) return 0;
    if (SILK_KEEP_SEGMENTS && keep) silk_remesh_keep(f, keep->room > keep->kept_bytes ? keep->room - keep->kept_bytes : 0);
    return silk_remesh_plan(f) == SILK_OK && silk_perturb_alloc(f) && silk_perturb(f);
}

silk_status silk_frame_smooth_lines(silk_arena *a, const silk_mesh *m, const silk_view *v,
                                    silk_fx tolerance_px, silk_vis_method vis, int lines,
                                    silk_frame_geom *g, silk_frame_stats *stats, silk_error *err)
{
    if (!a || !m || !v || !g)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_smooth: missing argument");
    if (tolerance_px <= 0)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_smooth: tolerance must be positive");
    memset(g, 0, sizeof *g);
    if (stats) stats->fell_back = 0;

    silk_arena_mark mark = silk_arena_top_mark(a);
    silk_sil_frame f;
    silk_sil_cursor cur;   /* the emitter's, for the frame it stores */
    f.keep = NULL;   /* a stored frame keeps nothing for speed */
    if (!make_plan(&f, &cur, a, m, v, tolerance_px, vis, NULL) || !silk_remesh_store(&f, g)) {
        silk_status st = silk_frame_fall_back(a, m, &mark, g, stats, err);
        if (st == SILK_OK && lines && silk_lines_polygonal(a, m, v, 1, g) != SILK_OK) silk_frame_fell_short(stats);
        return st;
    }
    silk_remesh_stats(&f, stats);
    if (lines && silk_lines_smooth(&f, g) != SILK_OK) silk_frame_fell_short(stats);
    return SILK_OK;
}

int silk_frame_smooth_plan(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tolerance_px,
                           silk_vis_method vis, silk_stage_clock *clock, silk_sil_frame *f, silk_sil_cursor *cur,
                           silk_frame_geom *local)
{
    silk_arena_mark mark = silk_arena_top_mark(a);
    if (make_plan(f, cur, a, m, v, tolerance_px, vis, clock) && silk_remesh_alloc(f, local, f->max_recs, f->max_tris, f->max_curves))
        return 1;
    silk_arena_top_release(a, &mark);
    return 0;
}
