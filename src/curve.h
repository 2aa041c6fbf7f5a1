/*
 * curve.h - internal: the curve constructions of paper section III, as pure
 * functions of fixed-point vectors (implemented in curve.c).  Everything the
 * per-frame stages and the load-time feature stage build is a silk_curve
 * (silk/hal.h): a cubic Hermite curve, eq. 5.
 */
#ifndef SILK_CURVE_H
#define SILK_CURVE_H

#include "silk/silk.h"

/* Eq. 4: dir scaled to length 2|chord| / (1 + cos theta), theta the angle
 * between dir and chord, so that the Hermite curve over chord with this end
 * tangent approximates a circular arc.  dir need not be unit.  A zero dir
 * gives the chord itself (theta = 0: a straight line), a zero chord the zero
 * vector, and 1 + cos theta near 0 the clamp below; never overflows.
 * Within 1 ulp + 2^-27 of the result's length of the exact value
 * (tests/core/test_curve.c). */
silk_vec3 silk_arc_tangent(silk_vec3 dir, silk_vec3 chord);

/* The bulge bound, applied by silk_arc_tangent and silk_bridge after eq. 4
 * and its clamp: the tangent length L is cut to |chord| / (SILK_BULGE_DIV
 * sin theta) where eq. 4 would give more.  The Hermite curve's Bezier
 * control points p0 + t0/3 and p1 - t1/3 then lie within |chord| / 6 of the
 * chord's line, exactly the most a PN triangle's edge control points can
 * (|chord| sin 2phi / 6, phi the normal's tilt towards the chord, at most
 * 1/6 at 45 degrees), and every point of the curve lies within 3/4 of that,
 * |chord| / 8, of the chord's line (the cubic's offset 3u(1-u)((1-u)d0 +
 * u d1) is at most 3/4 max(d0, d1)).  Eq. 4 is left as it is up to
 * theta = 2 atan(1/4) = 28.07 degrees: circular arcs of up to 56 degrees,
 * whose sagitta is 1/8 of their chord, are still followed exactly; wider
 * ones are flattened to that height instead of bulging to a half disc. */
#define SILK_BULGE_DIV 2

/* The clamp of eq. 4: L <= SILK_ARC_MAX_RATIO * |chord|, reached when
 * cos theta <= -1/2 (theta >= 120 degrees, an arc of 240 degrees).  A bridge
 * never gets there (its tangents are the chord projected onto a plane, so
 * theta <= 90 degrees and L <= 2|chord|); only feature tangents at hairpin
 * turns do, and a longer tangent would make the cubic loop.  With model
 * coordinates within +-SILK_COORD_MAX, |chord| <= 2048 sqrt 3 and so
 * L < 14200, well inside Q16.16; beyond that the tangent is shortened as a
 * whole to fit, keeping its direction.  Must be <= 4 (curve.c's bounds). */
#define SILK_ARC_MAX_RATIO 4

/* The tilt bound of silk_bridge, for normals that are estimates (computed
 * at load from the faces around each vertex, silk_mesh.normals_used): each
 * end normal's lean along the chord (n.chord / |chord|, the sine of the
 * tangent's angle to the chord) is cut to at most the other end's plus
 * 1 / SILK_TILT_SLACK (3.6 degrees), so that one normal averaged across a
 * rounded-off crease does not bow a straight edge.  Normals from the file
 * (a modeller's, or fitted to the detailed surface by silk prepare) are
 * taken as they are: there a one-sided lean is the surface's. */
#define SILK_TILT_SLACK 16

/* Eqs. 2-5: the silhouette bridge over p0->p1 with unit normals n0, n1:
 * tangent directions are the chord projected onto each end's tangent plane
 * (eqs. 2, 3), after the tilt bound above where tilt_bound is set; lengths
 * from eq. 4.  Fills p0, p1, t0, t1, n0, n1 of out;
 * uv0/uv1 are left as they are.  The normals are renormalised inside, so a
 * few ulps off unit length do not matter; a zero normal, or a chord along
 * the normal, gives a straight tangent (the chord); p0 == p1 gives zero
 * tangents.  p1 - p0 is taken in 64 bits, so any two Q16.16 points work. */
void silk_bridge(silk_vec3 p0, silk_vec3 n0, silk_vec3 p1, silk_vec3 n1, int tilt_bound, silk_curve *out);

/* Whether mesh m's bridges take the tilt bound: its normals were not the file's. */
static inline int silk_tilt_bound(const silk_mesh *m) { return m->normals_used != SILK_NORMALS_FILE; }

/* Eqs. 6-7: the parameter u in [0,1] where the linearly interpolated normal
 * (1-u)n0 + u n1 is perpendicular to the linearly interpolated view
 * direction (1-u)d0 + u d1.  Parallel projection passes d0 == d1.  When the
 * signs of n0.d0 and n1.d1 differ, the result is the unique root in [0,1]
 * (quadratic solved without cancellation, checked and corrected by the exact
 * sign of h on a 2^-17 grid: the root rounded to nearest, measured within
 * 0.5 ulp); otherwise the end with the smaller |n.d| is returned.  n.d
 * exactly 0 at an end returns that end (u = 0 first).  Swapping the ends
 * gives 1 - u within 1 ulp.  d may be long (towards a far eye): any Q16.16
 * inputs are safe. */
silk_fx silk_silhouette_param(silk_vec3 n0, silk_vec3 d0, silk_vec3 n1, silk_vec3 d1);

/* Eq. 8: n_s = ceil( sqrt(h * r / e) / 2 ), r = sqrt((1 - cos_alpha)/2),
 * h the projected size of the segment in pixels (silhouette.c says which
 * size), e the tolerance in pixels.  Decided in integers as the least n with
 * 4 n^2 e >= h r (r to 2^-24).  At least 1 (also for h <= 0 or cos_alpha
 * >= 1), capped at SILK_MAX_SAMPLES (also for e <= 0). */
#define SILK_MAX_SAMPLES 64
uint32_t silk_sample_count(silk_fx h_px, silk_fx cos_alpha, silk_fx tol_px);

/* Sample i of n (0 <= i <= n) along a curve sampled with n equal intervals
 * (eq. 8): the parameter i/n, rounded once.  Silhouette segments and
 * feature segments are sampled alike. */
static inline silk_fx silk_sample_param(uint32_t i, uint32_t n)
{
    return silk_fx_sat(((int64_t)i * SILK_FX_ONE + n / 2) / n);
}

#endif
