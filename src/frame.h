/*
 * frame.h - internal: the frame contract, what every mode's stages hand to
 * the renderer (render.c), and the stages that make a whole frame's
 * geometry: flat.c, smooth.c, pn.c, blend.c.  Not installed; the public
 * entry point is silk_render().
 *
 * A frame's geometry is a list of vertex records (silk/hal.h) and triangles
 * over them.  In FLAT mode every triangle corner is a CORNER record; in SMOOTH
 * mode silhouette triangles and triangles with visible feature segments are
 * replaced by triangles through CURVE samples, and vertices next to concave
 * silhouette segments become MOVED records.
 */
#ifndef SILK_FRAME_H
#define SILK_FRAME_H

#include "silk/silk.h"

typedef struct silk_frame_geom {
    silk_vrec  *vrec;  uint32_t nvrec;
    uint32_t   *tri;   uint32_t ntri;    /* 3 per triangle, indices into vrec */
    uint8_t    *tri_added;               /* per triangle: 1 if made by re-meshing (drawn red by --wire) */
    silk_curve *curve; uint32_t ncurve;
    silk_vec3  *offset; uint32_t noffset;
    silk_patch *patch; uint32_t npatch;  /* PN and BLEND modes */
    uint32_t   *part_rec;                /* SMOOTH: input triangle t's records start at
                                            part_rec[t] (ntris + 1), or NULL */
    uint32_t   *rec_key;                 /* SMOOTH with lines: per record, which point it is
                                            (copies of one point share it; lines.c), or NULL */
    /* Pen-and-ink lines (lines.c), when asked for: line i is the polyline
     * through line_vrec[line_start[i] .. line_start[i+1]-1], a silhouette
     * line or a feature line (line_feature[i]).  Records of their own;
     * where a line runs along the triangles' edges they are copies of the
     * triangles' records, and line_src says which (else SILK_LINE_NO_SRC). */
    silk_vrec  *line_vrec; uint32_t nline_vrec;
    uint32_t   *line_src;                /* nline_vrec */
    uint32_t   *line_start;              /* nlines + 1 */
    uint8_t    *line_feature;            /* nlines */
    uint32_t    nlines;
} silk_frame_geom;

/* The coarse mesh as it is: one CORNER record per triangle corner. */
silk_status silk_frame_flat(silk_arena *a, const silk_mesh *m, silk_frame_geom *g, silk_error *err);
/* Room in g (from the top of the arena) for the shares of ntris input
 * triangles as they are, and when extra is not NULL extra_bytes more for
 * the caller in *extra; g is emptied (no share, no curves or patches).  SILK_ERR_NOMEM, saying what
 * the least frame needs, when it does not fit. */
silk_status silk_frame_flat_room(silk_arena *a, uint32_t ntris, size_t extra_bytes, void **extra,
                                 silk_frame_geom *g, silk_error *err);
/* Input triangle t's share of a FLAT frame appended to g: its three
 * CORNER records and one triangle over them. */
void silk_frame_flat_emit_tri(silk_frame_geom *g, uint32_t t);

/* The one policy for a frame that does not fit (flat.c): release the top
 * of the arena to mark, draw the coarse mesh into g, and say so in stats
 * (silk_frame_stats_fell_back).  Only when not even that fits is the
 * error returned. */
silk_status silk_frame_fall_back(silk_arena *a, const silk_mesh *m, const silk_arena_mark *mark,
                                 silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);
/* stats of a frame drawn as the coarse mesh (tris_drawn triangles): no
 * silhouette work counted, fell_back set.  stats may be NULL. */
void silk_frame_stats_fell_back(silk_frame_stats *stats, uint32_t tris_drawn);
/* What sets fell_back, for the coarse mesh and for lines that did not fit
 * (left out, or drawn without their lift).  stats may be NULL. */
void silk_frame_fell_short(silk_frame_stats *stats);

/* Paper section III for one view.  All arrays come from the top of the arena
 * (purpose FRAME); the caller releases them.  When the arena runs out part way,
 * the triangles not yet re-meshed are emitted as they are, stats->fell_back is
 * set and SILK_OK is returned. */
silk_status silk_frame_smooth(silk_arena *a, const silk_mesh *m, const silk_view *v,
                              silk_fx tolerance_px, silk_vis_method vis,
                              silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

/* silk_frame_smooth, and with lines non-zero also the lines of the frame
 * (lines.c): the sampled silhouette segments and visible feature curves
 * through the very records the triangles use.  When the frame falls back to
 * the coarse mesh, its polygonal lines instead. */
silk_status silk_frame_smooth_lines(silk_arena *a, const silk_mesh *m, const silk_view *v,
                                    silk_fx tolerance_px, silk_vis_method vis, int lines,
                                    silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

/* PN triangles (src/pn.c): every triangle's cubic patch, its sides cut
 * into level segments, with quadratic or linear normals.  View-independent.
 * Same contract as silk_frame_smooth: arrays from the top of the arena, and
 * when they do not fit the coarse mesh is emitted with stats->fell_back set. */
silk_status silk_frame_pn(silk_arena *a, const silk_mesh *m, uint32_t level, silk_pn_normals normals,
                          silk_frame_geom *g, silk_frame_stats *stats, silk_error *err);

/* Silhouetteness blending (src/blend.c, Dyken & Reimers): triangles whose
 * three edges have silhouetteness 0 stay as they are; the others become
 * patches blended between flat and PN by the silhouetteness of each edge,
 * drawn as a fan around the patch centre with each edge cut into as many
 * segments as tolerance_px needs.  Same contract as silk_frame_smooth. */
silk_status silk_frame_blend(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx beta,
                             silk_fx tolerance_px, silk_frame_geom *g, silk_frame_stats *stats,
                             silk_error *err);

#endif
