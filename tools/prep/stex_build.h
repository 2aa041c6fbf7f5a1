/*
 * stex_build.h - a silhouette texture for a hull (Wu, Wei, Wang, Guo,
 * "Silhouette Texture", section 3), host-side in double precision, for
 * `silk prepare --siltex` (docs/siltex.md; the bytes: the STEX section in
 * docs/formats.md).
 *
 * Over the atlas of tools/prep/stex_atlas.h, each texel stands for a point p of
 * the hull, on hull triangle f.  For p:
 *  - the normal map holds the detailed surface's normal at q (section
 *    3.1: D_p = q - p), the point of the detailed mesh seen from p along
 *    C (below), or where it is not seen, the point closest to p; the
 *    colour map its vertex colours interpolated there;
 *  - the visibility function (section 3.2, eq. 2): VF_p(d) is true when the
 *    ray from p along the viewing direction d meets the detailed mesh
 *    before any hull triangle but f (ray casting through tools/prep/bvh.h); a
 *    direction out of f (d.n_f >= 0) leaves the hull at once, so it is false
 *    without a ray;
 *  - the single-lobe encoding (section 3.3): at each hull vertex, C the
 *    mean of the mean true directions of the texels around it (weighted
 *    by their barycentric weights there), turned to point into every
 *    triangle around the vertex, and T perpendicular to it, carried from
 *    vertex to vertex over the hull so that neighbours agree; each texel
 *    then stores, at K azimuths of the frame interpolated at p (the
 *    renderer's rule), the angle from C along the azimuth's great circle
 *    to the first false direction, found by steps of 4 angle units (pi/255
 *    each) and halving, in those units, rounded and one unit out (the
 *    renderer's linear lookups cut a rounded cap's edge inward); where the
 *    circle turns true again (or C is false), the angle that draws the
 *    most true and the fewest false directions along it;
 *  - eq. 3: the share of the sampled directions where the stored function
 *    (eq. 4, linear between azimuths) differs from VF_p, averaged over the
 *    texels inside charts, and the share of those texels not single-lobed
 *    seen from C (C false, or true again past the first false direction
 *    along some azimuth).
 * Texels are shared out among threads.
 */
#ifndef SILK_TOOLS_STEX_BUILD_H
#define SILK_TOOLS_STEX_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "silk/model.h"
#include "simplify.h"
#include "stex_atlas.h"
#include "stex_svd.h"

/* The section's type, until the renderer's headers define it. */
#ifndef SILK_SECTION_STEX
#define SILK_SECTION_STEX SILK_SECTION_TYPE('S', 'T', 'E', 'X')
#endif
#define STEX_VERSION 1
#define STEX_FLAG_SVD 1u
#define STEX_FLAG_COLOUR 2u

typedef struct stex_opts {
    int atlas;               /* atlas width and height, texels [128] */
    int angles;              /* K azimuths [12] */
    int svd;                 /* E eigenfunctions; 0: angles stored whole [0] */
    int samples;             /* sphere directions per texel for C_p and eq. 3 [512] */
    int threads;             /* [2] */
    int quiet;               /* no progress line */
} stex_opts;

void stex_opts_default(stex_opts *o);

typedef struct stex {
    stex_atlas atlas;
    int k, nsamples;
    uint32_t nverts, ntris;
    int16_t *frame;          /* 6 per hull vertex: C then T, Q1.14 */
    uint8_t *angles;         /* w * h * k */
    int8_t *normal;          /* 2 per texel: octahedral */
    double *basis;           /* 9 per texel: C, T', B at the texel's point */
    double *samples;         /* 3 per sphere direction */
    uint8_t *vf;             /* (nsamples + 7) / 8 per texel: VF_p at each direction */
    uint8_t *multi;          /* per texel: not single-lobed seen from C */
    uint8_t *colour;         /* RGB per texel, or NULL: the detailed mesh has no colours */
    uint32_t texels_in;      /* texels inside charts */
    double error;            /* eq. 3, mean over the texels inside charts */
    double multi_share;      /* share of them not single-lobed */
} stex;

/* The silhouette texture of fine over its hull (both closed manifolds,
 * outward; the hull holds fine), with a colour map when fine_color (one
 * 0xRRGGBB per vertex of fine) is not NULL.  0; -1 when out of memory; -2
 * when the atlas cannot frame the hull's triangles. */
int stex_build(const simp_mesh *fine, const uint32_t *fine_color, const simp_mesh *hull, const stex_opts *o, stex *s);
void stex_free(stex *s);

/* Eq. 3 averaged over the texels inside charts, for the given angles
 * (w * h * k; s->angles or a reconstruction of them). */
double stex_error(const stex *s, const uint8_t *angles);
/* The PSNR (dB) of angles against s->angles over the texels in use. */
double stex_psnr(const stex *s, const uint8_t *angles);
/* The azimuth angle of texel t for direction d (unit), by eq. 4's lookup:
 * linear between azimuths.  Radians. */
double stex_phi(const stex *s, const uint8_t *angles, size_t t, const double d[3]);

/* The STEX section (malloc'd, *size bytes, padded to 4): angles whole, or
 * compressed by svd (not NULL); error is the eq. 3 figure for its header
 * (that of the angles as stored).  NULL when out of memory. */
uint8_t *stex_section(const stex *s, const stex_svd *svd, double error, size_t *size);
/* Its size without making it. */
size_t stex_section_bytes(const stex *s, int svd_e);

#endif
