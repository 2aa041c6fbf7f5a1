/*
 * remesh.h - internal: silhouette segments, sampling and re-meshing
 * (remesh.c): what the frame costs, and the one emitter of vertex records
 * and triangles from the plan.  Not installed.
 */
#ifndef SILK_REMESH_H
#define SILK_REMESH_H

#include "plan.h"

silk_status silk_remesh_plan(silk_sil_frame *f);     /* segments counted, costs */
/* Before silk_remesh_plan, when room (the most it may take) and the arena
 * allow: every carrying edge's tangents kept (silk_sil_keep_tangents) and
 * room for every silhouette triangle's segment, which silk_remesh_plan
 * keeps as it makes them and silk_remesh_seg then reads instead of
 * rebuilding (the same bits).  Returns the bytes taken (0: none; counted
 * in f->keep->kept_bytes; f->keep must be there).  Only with
 * SILK_KEEP_SEGMENTS. */
size_t silk_remesh_keep(silk_sil_frame *f, size_t room);
/* Where silhouette triangle t's segment is kept (f->keep->seg_tri), or
 * SILK_SIL_NONE (always, without SILK_KEEP_SEGMENTS). */
uint32_t silk_remesh_kept_index(const silk_sil_frame *f, uint32_t t);
/* The silhouette segment of silhouette triangle t; 0 when a silhouette
 * point is missing (silhouette.c gives every silhouette triangle both). */
int  silk_remesh_seg(const silk_sil_frame *f, uint32_t t, silk_sil_seg *s);
/* Room in g for recs records, tris triangles and curves curves (f->max_*
 * for one share, f->store_* and f->out_tris for a whole frame), and the
 * emitter's scratch; 0 when it does not fit. */
int  silk_remesh_alloc(silk_sil_frame *f, silk_frame_geom *g, uint64_t recs, uint64_t tris, uint64_t curves);
/* Input triangle t's share of the frame, appended to g (records, curves,
 * triangles; its records refer to g->curve and f->offset). */
void silk_remesh_emit_tri(const silk_sil_frame *f, silk_frame_geom *g, uint32_t t);
/* A stored frame: every input triangle's share appended into g (from the
 * top of the arena), g->part_rec saying where each starts; 0 when it does
 * not fit. */
int  silk_remesh_store(silk_sil_frame *f, silk_frame_geom *g);
/* The record of corner k in t's share, its share starting at record base;
 * side k's chain follows it, in the edge's order. */
uint32_t silk_remesh_corner_rec(const silk_sil_frame *f, uint32_t t, uint32_t k, uint32_t base);
/* The records of silhouette triangle t's segment in its share (starting
 * at record base): rec[0] A, rec[1] B, rec[2] its first interior sample. */
void silk_remesh_seg_recs(const silk_sil_frame *f, uint32_t t, uint32_t base, uint32_t rec[3]);
/* Where silhouette triangle t's segment is in its share (records from
 * 0): rec as silk_remesh_seg_recs gives them, *curve its curve (emitted
 * after one curve per side of t that carries points); 0 when t has no
 * segment (silk_remesh_seg would fail: the share is then not cut by one). */
int silk_remesh_seg_at(const silk_sil_frame *f, uint32_t t, uint32_t rec[3], uint32_t *curve);
void silk_remesh_stats(const silk_sil_frame *f, silk_frame_stats *stats);   /* the frame's counts */

#endif
