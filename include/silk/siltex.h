/*
 * silk/siltex.h - silhouette textures (Wu, Wei, Wang, Guo, "Silhouette
 * Texture", sections 3.3-3.5): every texel of an atlas over a coarse outer
 * hull stores, for each of K azimuths about a centre direction C, the
 * angular distance phi from C to the edge of the view directions along
 * which the detailed model is seen through that hull point.  The fragment
 * stage draws a hull pixel only when its view direction lies inside that
 * single-lobed region (eq. 4), so the hull shows the detailed model's
 * outline, interior silhouettes included.
 *
 * The texture is read where it lies (the model's bytes, in flash on a
 * device): silk_model_siltex (silk/model.h) checks the STEX section and
 * points a silk_siltex into it; nothing is copied.  docs/formats.md "STEX"
 * has the byte layout, docs/siltex.md how it is drawn.  Fixed point only;
 * no trigonometric function per pixel (tables of atan, cos and sin).
 */
#ifndef SILK_SILTEX_H
#define SILK_SILTEX_H

#include <stdint.h>
#include "fixed.h"
#include "hal.h"
#include "texture.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SILK_STEX_VERSION 1
#define SILK_STEX_COMPRESSED 1u    /* flags bit 0: the angles as a mean, eigenfunctions and weights (sec. 3.5) */
#define SILK_STEX_COLOR 2u         /* flags bit 1: a colour map follows the normal map */
#define SILK_STEX_HEAD_BYTES 32
#define SILK_STEX_MIN_DIM 8
#define SILK_STEX_MAX_DIM 4096
#define SILK_STEX_MIN_K 4
#define SILK_STEX_MAX_K 64

/* A checked STEX section.  The arrays are the section's bytes, read as
 * little-endian wherever they are (no alignment needed). */
typedef struct silk_siltex {
    uint32_t flags;
    uint32_t w, h;               /* atlas size in texels */
    uint32_t k;                  /* azimuth samples per texel */
    uint32_t e;                  /* eigenfunctions (compressed), else 0 */
    uint32_t nverts, ntris;      /* the hull's */
    uint32_t error_ppm, multi_lobe_ppm;   /* the host's report (eq. 3 error, texels not single-lobed) */
    uint32_t bytes;              /* the section's size */
    const uint8_t *frame;        /* per hull vertex: C, then T, 3 x int16 Q1.14 each */
    const uint8_t *uv;           /* per triangle corner: u, v as uint16 in 1/16 texel */
    const uint8_t *angles;       /* uncompressed: w*h*k bytes q, phi = q pi / 255 */
    const uint8_t *mean;         /* compressed: k int16 (q x 16) */
    const uint8_t *scale;        /* compressed: e int32 Q16.16 */
    const uint8_t *basis;        /* compressed: e*k int16 Q1.14, eigenfunction j at j*k + i */
    const uint8_t *weights;      /* compressed: w*h*e int8 */
    const uint8_t *normal;       /* w*h octahedral normals, int8 x, y */
    const uint8_t *color;        /* w*h RGB888, or NULL */
    const uint8_t *hull_tri;     /* the HULL section's 3*ntris uint32 corners (whose order the uvs follow) */
} silk_siltex;

/* q (0..255) of azimuth sample i of texel t = y*w + x: the stored byte, or
 * the compressed form's reconstruction
 *   mean[i]/16 + sum_j weight[t][j] scale[j] basis[j][i] / 2^30,
 * exact in 64 bits, rounded to nearest and clamped to 0..255.  The host's
 * encoder calls this too, so the error it reports is the runtime's. */
uint32_t silk_siltex_q(const silk_siltex *st, uint32_t t, uint32_t i);

/* ---- the lookup (eq. 4), stage by stage: exposed for the tests ---------------- */

/* The azimuth of (x, y), atan2(y, x) in [0, 2 pi), as a fraction of a turn
 * in Q0.20 (2^20 = one turn): the octant folded away, then a 257-entry
 * table of atan(r), r in [0, 1], interpolated.  (0, 0) gives 0. */
uint32_t silk_siltex_azimuth(int64_t x, int64_t y);

/* cos(phi) in Q2.30 for phi = q pi / 255 given as q in Q8.16 (0 .. 255 <<
 * 16): cos and sin tables at whole q, then cos(a + h) = cos a cos h -
 * sin a sin h with h below one step by its Taylor terms. */
int32_t silk_siltex_cos(uint32_t q16);

/* acos(c) for c in Q2.30 (clamped to [-1, 1]), as q in Q8.16 (phi = q pi
 * / 255): the table of silk_siltex_cos searched, linear between its
 * entries. */
uint32_t silk_siltex_acos(int64_t c);

/* The texel frame at a point: c and t the hull's C and T interpolated
 * (any length), into unit C, T' = normalize(T - (T.C) C) and B = C x T'
 * (Q16.16).  0 when C is zero; a T along C is replaced by an axis. */
int silk_siltex_frame(const silk_fx c[3], const silk_fx t[3], int64_t C[3], int64_t T[3], int64_t B[3]);

/* phi at atlas point (u, v) (Q16.16 texels, texel (x, y)'s centre at
 * x + 1/2, y + 1/2) and azimuth az (Q0.20 turns): bilinear over the four
 * texel centres around it (indices clamped to the atlas), linear between
 * the two azimuth samples around az.  q units in Q8.16. */
uint32_t silk_siltex_phi(const silk_siltex *st, silk_fx u, silk_fx v, uint32_t az);

/* Eq. 4: whether the detailed model is seen at atlas point (u, v) with
 * interpolated C and T along unit view direction d (Q16.16, from the eye
 * into the surface): d.C >= cos(phi(theta)), theta the azimuth of d in
 * the frame (T', B). */
int silk_siltex_visible(const silk_siltex *st, silk_fx u, silk_fx v, const silk_fx c[3], const silk_fx t[3],
                        const int64_t d[3]);

/* The normal map's unit normal at (u, v): the four texels around it
 * decoded, blended bilinearly, normalised; Q16.16. */
void silk_siltex_normal(const silk_siltex *st, silk_fx u, silk_fx v, int64_t n[3]);

/* ---- drawing: the HAL stages of siltex mode ----------------------------------- */

/* What the stages read: the texture, the stage that shades (the default
 * Phong stage, whose vertex stage also places the hull's vertices) and
 * the view (the eye, or the direction of an orthographic view). */
typedef struct silk_siltex_stage {
    const silk_siltex *tex;
    const silk_hal *shade;
    const silk_view *view;
    /* Silhouette lines (paper section 4, eq. 5): 0 none, 1 over the
     * shading, 2 alone (the surface drawn in bg_rgb, hiding lines behind
     * it).  A pixel is a line pixel where |acos(d.C) - phi| <= w: w =
     * line_q (q units, Q16) in an orthographic view, line_q times the eye
     * depth (Q16.16 units) in perspective (silk_siltex_line_width). */
    int lines;
    uint32_t line_rgb, bg_rgb;
    int64_t line_q;
    /* Filled by silk_siltex_hal from tex: the colour map as a bilinear,
     * clamped RGB888 texture (unused when tex has none). */
    silk_texture color_map;
} silk_siltex_stage;

/* line_q for lines about 2 px wide where the lobe's edge is crossed at a
 * distance `reach` (model units) from the hull: half a line's width in
 * pixels over the pixels a unit of distance takes, divided by reach. */
int64_t silk_siltex_line_width(const silk_view *view, silk_fx reach);

/* Stages that draw the hull (the mesh of the HULL section, CORNER records)
 * through the texture: varyings position (3), atlas point (2), C (3), T
 * (3); the fragment stage returns SILK_FRAGMENT_DISCARD where eq. 4 says
 * the detailed model is not seen, else shades with the normal map's normal
 * and the colour map's colour (silk_hal_phong_tinted).  silk_render does
 * this itself in SILK_MODE_SILTEX.  It fills s->color_map from s->tex, so
 * set s->tex first. */
void silk_siltex_hal(silk_hal *h, silk_siltex_stage *s);

/* The same stages with a fragment stage that returns, in place of a
 * colour, how far the pixel lies from eq. 4's threshold: the angle
 * acos(d.C) - phi (q units in Q8.16, positive where the pixel is not
 * drawn) as the 24-bit code SILK_SILTEX_MARGIN_ZERO + angle / 4, clamped to
 * 0 .. 2 ZERO - 1: at most ZERO exactly where silk_siltex_hal's stage
 * draws the pixel.  It never discards.  silk_render
 * draws the hull's front faces through it, near the outline only, for
 * siltex mode's anti-aliased outline (src/aa.c). */
#define SILK_SILTEX_MARGIN_ZERO 0x800000u
void silk_siltex_margin_hal(silk_hal *h, silk_siltex_stage *s);

/* Bytes the section takes in the model (what flash holds for it). */
static inline uint32_t silk_siltex_bytes(const silk_siltex *st) { return st->bytes; }

#ifdef __cplusplus
}
#endif

#endif
