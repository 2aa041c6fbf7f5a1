/*
 * aa.h - internal: anti-aliased outlines (aa.c).  Not installed.
 *
 * After a band is drawn, each outline of the frame (silhouette segments,
 * and the coarse mesh's silhouette edges) re-weights the pixels it crosses
 * by the surface's coverage of them.  render.c drives it: silk_aa_begin for the
 * band, silk_aa_share for every input triangle's share that can hold an
 * outline (silk_aa_candidate), silk_aa_finish to write the pixels.
 */
#ifndef SILK_AA_H
#define SILK_AA_H

#include "plan.h"

/* The curve between two samples is followed as SILK_AA_SUBDIV chords. */
#define SILK_AA_SUBDIV 4
#define SILK_AA_WALK (2 * SILK_AA_SUBDIV)   /* its SILK_AA_SUBDIV + 1 points, and the SILK_AA_SUBDIV - 1 between */

/* One outline pixel's new value, computed from the band as drawn and
 * written only when every outline has been walked. */
typedef struct silk_aa_px {
    uint16_t x, y;
    uint32_t argb;          /* coverage << 24 | 0xRRGGBB */
} silk_aa_px;

/* A record on screen as the rasterizer places it. */
typedef struct silk_aa_pt {
    int32_t x, y;           /* 1/SILK_RASTER_SUB pixels (32 bits: the products are single multiplies) */
    uint32_t d;             /* depth, larger is nearer */
    int ok;                 /* w > 0 and within the guard band */
} silk_aa_pt;

typedef struct silk_aa {
    silk_target *t;               /* the band */
    silk_target apron[2];         /* the rows just above and below it, as drawn (rows 0: none) */
    silk_aa_pt *pt;   uint32_t npt;   /* per record of one share */
    silk_aa_pt *walk;             /* scratch for one side: the points of the curve walked (SILK_AA_WALK) */
    silk_vertex_out *out;         /* scratch: one point of a curve through the vertex stage */
    silk_curve *curve;            /* scratch: a point off a silhouette segment (its normal on screen) */
    /* SMOOTH frames (set by the caller after silk_aa_begin; sil NULL otherwise): the
     * plan, which says where a share's silhouette segment is, and the vertex stage
     * h with the frame's geom, which projects points of its curve */
    const silk_sil_frame *sil;
    const silk_hal *hal;
    const silk_geom *geom;
    silk_aa_px *px;   uint32_t npx, cap;
    uint32_t dropped;             /* outline pixels left aliased: no room in px */
    /* Which way the frame's input triangles face, 2 bits each (known,
     * front), filled as asked; NULL: computed every time (same answers).
     * The caller owns it: it holds for the whole frame, every band. */
    uint8_t *facing;
    int creases;                  /* visible creases blended too (set by the caller) */
} silk_aa;

/* Room from the top of the arena for band t: the pending pixels, max_recs
 * projected records, and (when t is not the whole frame) the two apron rows,
 * which the caller then draws (aa->apron[i], rows 1).  0 when it does not
 * fit (the band is then left aliased). */
int silk_aa_begin(silk_aa *aa, silk_arena *a, silk_target *t, uint32_t max_recs);
/* The most silk_aa_begin takes for a band of t's width, rows and format
 * (both aprons counted): what the renderer leaves free for it when it keeps
 * things for speed, and what silk_budget_frame counts. */
size_t silk_aa_bytes(const silk_target *t, uint32_t max_recs);
/* Both for the outlines of nobj objects drawn into one band (scene.c): a
 * pixel list nobj times as long. */
int silk_aa_begin_n(silk_aa *aa, silk_arena *a, silk_target *t, uint32_t max_recs, uint32_t nobj);
size_t silk_aa_bytes_n(const silk_target *t, uint32_t max_recs, uint32_t nobj);

/* Whether input triangle t's share can hold an outline side: a side of t
 * against nothing or between a front- and a back-facing triangle, or (with
 * a SMOOTH plan f) a silhouette triangle, whose segment is an outline. */
int silk_aa_candidate(silk_aa *aa, const silk_mesh *m, const silk_view *v, const silk_sil_frame *f, uint32_t t);

/* silk_aa_candidate for every input triangle of a frame (aa->sil: the
 * SMOOTH plan, or NULL) of a closed mesh (silk_mesh.closed_outward) at once: bit t of cand (ntris
 * bits) set where it says 1, from one pass over the edges instead of three
 * sides a triangle, and aa->facing (which must be there) filled for every
 * triangle.  The answers do not change from band to band.  Only with
 * SILK_AA_CANDIDATES. */
void silk_aa_candidates(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint8_t *cand);

/* The outline sides of input triangle t's share g (out: its vertex-stage
 * output per record), walked over the band: a share that is t as it is
 * (FLAT, or untouched by SMOOTH) by the rule of silk_aa_candidate (in
 * SMOOTH not the sides against a silhouette triangle); a silhouette
 * triangle's share along its silhouette segment, every chord, with the
 * coverage of the segment's curve (eq. 5). */
void silk_aa_share(silk_aa *aa, const silk_mesh *m, const silk_view *v, const silk_frame_geom *g,
                   const silk_vertex_out *out, uint32_t t);

/* SILTEX: the outline where the hull's front faces stop being drawn
 * (eq. 4).  s is a target over the band's rows and its aprons' holding the
 * depth of the hull's front faces alone (culled back faces, no discard).
 * silk_aa_margin_mask sets the bits of mask (s's stencil, which s->mask
 * then points at) where eq. 4's margin is needed: every pixel of the band
 * on the hull next to one across the change between showing the front
 * face and not (the outline pixels), and their four neighbours; it returns
 * how many outline pixels there are.  The caller then draws the front
 * faces through silk_siltex_margin_hal into s where its stencil says
 * (depth_equal), and silk_aa_margin blends each outline pixel by the front
 * face's coverage of it, from the margin there and its slope to the
 * neighbours (the margin taken as linear over the pixel). */
uint32_t silk_aa_margin_mask(silk_aa *aa, silk_target *s, uint8_t *mask);
void silk_aa_margin(silk_aa *aa, const silk_target *s);

/* Write the pending pixels (and t->alpha, when the target has one). */
void silk_aa_finish(silk_aa *aa);

/* t->alpha, when there is one, from the depth buffer alone: 255 where the
 * surface was drawn, else 0 (frames without anti-aliasing). */
void silk_aa_alpha(silk_target *t);

#endif
