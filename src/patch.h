/*
 * patch.h - internal: the cubic patches of the PN and BLEND modes.  Not
 * installed.
 *
 *   pn.c     edge curves (Dyken & Reimers eqs. 4-8), the patch of a
 *            triangle (PN triangles, Vlachos et al. 2001), its exact
 *            evaluation, and PN mode's uniform tessellation
 *   blend.c  silhouetteness (eqs. 1-2), patches blended by it, and BLEND
 *            mode's adaptive fans
 *
 * Crack-freeness rests on one rule: the boundary of a patch along mesh edge
 * e depends on e's data only (its end positions and, at each end, the
 * normals of the two triangles that meet at e), never on which triangle
 * asks.  The two patches on either side of e therefore get the same four
 * boundary control points, and silk_patch_eval sums exactly, so a point on
 * the shared side has the same bits in both.
 */
#ifndef SILK_PATCH_H
#define SILK_PATCH_H

#include "frame.h"

/* l_ij = (2 p_i + p_j) / 3, the inner control point of the straight edge
 * written as a cubic (eq. 6), rounded once. */
silk_vec3 silk_patch_lin(silk_vec3 pi, silk_vec3 pj);

/* c_ij of eqs. 7-8.  ns and nt are the unit normals at p_i of the two
 * triangles that meet at the edge (ns twice for an edge with one triangle).
 * Equal normals (a smooth end): l_ij projected onto the tangent plane of
 * ns, eq. 7, which is Vlachos' b210 = (2 P1 + P2 - w12 N1) / 3.  Different
 * normals (a feature end): l_ij projected onto the line where the two
 * tangent planes meet, eq. 8; parallel ones fall back to eq. 7.  Exact in
 * 64 bits and rounded once for positions within SILK_COORD_MAX. */
silk_vec3 silk_patch_edge_ctrl(silk_vec3 pi, silk_vec3 pj, silk_vec3 ns, silk_vec3 nt);

/* The edge curve of mesh edge e (eq. 4): c[0] is the inner control point
 * next to edge.v[0], c[1] the one next to edge.v[1]. */
void silk_patch_edge_curve(const silk_mesh *m, uint32_t e, silk_vec3 c[2]);

/* Vlachos' mid-side normal coefficient for the side a -> b:
 * N_a + N_b reflected in the plane perpendicular to b - a, normalised. */
silk_vec3 silk_patch_mid_normal(silk_vec3 pa, silk_vec3 pb, silk_vec3 na, silk_vec3 nb);

/* The patch of triangle t.  alpha[k] (Q16.16 in [0,1]) is the
 * silhouetteness of side k, the mesh edge tri_edge[3t+k]: its two inner
 * control points are l + alpha (c - l).  alpha NULL means 1 on every side:
 * the PN triangle.  b111 is the PN triangle's, from whatever the sides are. */
void silk_patch_build(const silk_mesh *m, uint32_t t, const silk_fx *alpha, silk_pn_normals normals,
                      silk_patch *p);

/* SILK_ERR_ARG unless m has what the patches read: positions, triangles,
 * shading normals and edges (every mesh silk_mesh_build made has). */
silk_status silk_patch_check_mesh(const silk_mesh *m, const char *who, silk_error *err);


/* ---- blend.c ---------------------------------------------------------------- */

/* Eqs. 1-2: the silhouetteness of an edge whose triangles have unit normals
 * ns and nt, seen along to_eye (from the edge midpoint towards the eye in
 * perspective, minus the view direction in parallel projection; any
 * length): f = (u.ns)(u.nt) with u = to_eye / |to_eye|, alpha = 1 for
 * f <= 0, 1 - f / beta for 0 < f <= beta, 0 beyond.  beta 0 is the binary
 * silhouette test. */
silk_fx silk_blend_alpha(silk_vec3 to_eye, silk_vec3 ns, silk_vec3 nt, silk_fx beta);

/* BLEND mode's refinement of edge e at silhouetteness alpha: the number of
 * segments n, 1..SILK_BLEND_MAX_SEGMENTS, that keeps the polygon through
 * the blended edge curve within tol_px pixels of it.  The curve is the
 * straight edge plus alpha D(t), so the polygon's error is at most
 * |D''|max / (8 n^2) = (3/4) alpha max(|2 d0 - d1|, |d0 - 2 d1|) / n^2 world
 * units (d0, d1 = c - l at the two ends), scaled to pixels at the depth of
 * the edge midpoint (never nearer than znear).  1 when alpha is 0. */
#define SILK_BLEND_MAX_SEGMENTS 32u
uint32_t silk_blend_segments(const silk_mesh *m, const silk_view *v, uint32_t e, silk_fx alpha,
                             silk_fx tol_px);

#endif
