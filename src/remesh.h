/*
 * remesh.h - internal: silhouette segments, sampling and re-meshing
 * (remesh.c): the plan's segments and costs, and the emission of vertex
 * records from the plan.  Not installed.
 */
#ifndef SILK_REMESH_H
#define SILK_REMESH_H

#include "plan.h"

silk_status silk_remesh_plan(silk_sil_frame *f);     /* segments, counts, components, costs */
/* The silhouette segment of silhouette triangle t (what plan stores in
 * segs[] in STORED mode); 0 when a silhouette point is missing. */
int  silk_remesh_seg(const silk_sil_frame *f, uint32_t t, silk_sil_seg *s);
uint32_t silk_remesh_near_bound(const silk_sil_frame *f);   /* perturbation slots needed */
int  silk_remesh_alloc(silk_sil_frame *f, silk_frame_geom *g);   /* 0 when it does not fit */
void silk_remesh_emit(silk_sil_frame *f, silk_frame_geom *g, silk_frame_stats *stats);
/* STREAM mode: room for one input triangle's share in local (0 when it
 * does not fit), that share (local's arrays refilled, its records refer to
 * local->curve and f->offset), and the frame's counts. */
int  silk_remesh_stream_alloc(silk_sil_frame *f, silk_frame_geom *local);
void silk_remesh_emit_tri(silk_sil_frame *f, silk_frame_geom *local, uint32_t t);
void silk_remesh_stream_stats(const silk_sil_frame *f, silk_frame_stats *stats);

#endif
