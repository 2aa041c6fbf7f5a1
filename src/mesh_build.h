/*
 * mesh_build.h - internal: the stages silk_mesh_build() runs after the edge
 * adjacency is in place (see mesh_build.c), and the small helpers they share.
 *
 *   mesh_build.c  edges, triangle->edge and vertex->edge links, degenerate
 *                 triangles, bounding box; then calls the two stages below
 *   orient.c      consistent, outward triangle winding (before the normals)
 *   normals.c     crease / smoothing-group flags and the split shading
 *                 normals (paper III-B, Fig. 8)
 *   features.c    feature polylines and their Hermite tangents (paper III-A)
 */
#ifndef SILK_MESH_BUILD_H
#define SILK_MESH_BUILD_H

#include "silk/mesh.h"

/* Exact cross product (p1-p0) x (p2-p0) of triangle t, in Q32.32.  Exact
 * because |coordinate| <= SILK_COORD_MAX keeps every product below 2^56.
 * All zero exactly when the triangle has zero area. */
void silk_tri_cross64(const silk_mesh *m, uint32_t t, int64_t c[3]);

/* Unit vector in the direction of an int64 vector of any scale (the scale
 * is irrelevant: it is shifted into 32 bits first).  Returns 0 and leaves
 * *out as the zero vector for the zero vector. */
int silk_v3_normalize64(const int64_t v[3], silk_vec3 *out);

/* Eq. 4's Hermite tangent along unit direction d over chord, or the chord
 * itself when d is within 2^-10 of it (straight stays straight). */
silk_vec3 silk_feature_tangent(silk_vec3 d, silk_vec3 chord);

/* The feature segment of edge e of a compact model (compact.c): its LIST
 * record's tangents.  0 when it has none. */
int silk_compact_feature_seg(const silk_mesh *m, silk_index e, silk_feature_seg *out);

/* Needs m->pos, tri, edge (with BOUNDARY / NONMANIFOLD flags), tri_edge.
 * Flips triangles (tri, tri_edge and in's uv / file normal corners) so that
 * each component is wound consistently and each closed one outward; counts
 * them in m->nreoriented_tris and m->nnonorientable_tris.  Top scratch,
 * released by the caller. */
silk_status silk_orient(const silk_mesh_input *in, const char *name, silk_arena *a, silk_mesh *m, silk_error *err);

/* Needs m->pos, tri, edge (with BOUNDARY / NONMANIFOLD / DEGENERATE flags),
 * tri_edge.  Adds CREASE and GROUPS flags to m->edge[] and fills normal,
 * normal_vertex, nnormals and tri_normal.  Scratch comes from the top of
 * the arena and is released before it returns. */
silk_status silk_build_normals(const silk_mesh_input *in, const silk_load_opts *opts,
                               const char *name, silk_arena *a, silk_mesh *m, silk_error *err);

/* Needs the final edge flags and vert_edge links.  Fills nfeature_edges,
 * edge_feature and feature (purpose FEATURES). */
silk_status silk_build_features(const char *name, silk_arena *a, silk_mesh *m, silk_error *err);

#endif
