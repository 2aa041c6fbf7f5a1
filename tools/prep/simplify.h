/*
 * simplify.h - mesh simplification by quadric-error edge collapse
 * (Garland & Heckbert 1997) for `silk simplify`: make the coarse meshes the
 * renderer is meant for from fine ones.  Host-side, double precision.
 *
 * Feature edges (boundary edges, and creases whose dihedral angle exceeds
 * crease_deg) add constraint planes through the edge, perpendicular to its
 * faces, to their end points' quadrics, so collapses keep them in place
 * where they can.  A collapse is refused when it would break the surface:
 * the link condition, vertex degrees of at least 3, no triangle turned
 * over or squashed to a sliver, and a closed edge never pinching two
 * boundary vertices together.  A closed manifold input stays closed and
 * manifold; every collapse then removes exactly two triangles.
 *
 * With subset placement (simp_opts.subset, `silk simplify --for smooth`)
 * an edge collapses onto whichever end has the smaller quadric error, never
 * to a new point: every output vertex is an input vertex, so it lies on
 * the detailed surface exactly and simp_mesh.origin names it there.
 */
#ifndef SILK_TOOLS_SIMPLIFY_H
#define SILK_TOOLS_SIMPLIFY_H

#include <stdint.h>
#include "silk/fixed.h"

#include "silk/silk.h"

typedef struct simp_mesh {
    uint32_t nverts, ntris;
    double *pos;             /* 3 * nverts, malloc'd */
    uint32_t *tri;           /* 3 * ntris, malloc'd, counter-clockwise from outside */
    uint32_t *origin;        /* after simp_run: each vertex's index in the input, malloc'd */
} simp_mesh;

typedef struct simp_opts {
    uint32_t target_tris;    /* stop at this many triangles or fewer */
    double crease_deg;       /* dihedral angle above which an edge is a feature */
    double feature_weight;   /* constraint planes' weight against the faces' (area-weighted) */
    int subset;              /* collapse only onto one of the edge's ends (vertices stay input vertices) */
    /* called after each collapse with the triangles left (may be NULL) */
    void (*progress)(void *user, uint32_t tris_in, uint32_t tris_left);
    void *progress_user;
} simp_opts;

/* crease 60 degrees (as silk's loader), feature weight 100. */
void simp_opts_default(simp_opts *o, uint32_t target_tris);

typedef struct simp_stats {
    uint32_t tris_in, tris_out, verts_in, verts_out;
    uint32_t feature_edges;  /* boundary and crease edges of the input */
    uint32_t collapses;
    uint32_t refused_topology, refused_shape;   /* link/degree, flip/sliver (counted per attempt) */
} simp_stats;

/* Simplify m in place: pos and tri are replaced by compacted arrays.
 * Returns 0, or -1 when out of memory (m is then unchanged).  Fewer
 * collapses than asked for happen only when every remaining one would
 * break the surface; stats tell how far it got. */
int simp_run(simp_mesh *m, const simp_opts *o, simp_stats *st);

/* Topology of a triangle mesh, for the checks: edges with one face
 * (boundary), with three or more (non-manifold), pairs of faces using an
 * edge in the same direction (inconsistent orientation), vertices whose
 * faces do not form one fan (non-manifold vertices), and faces with a
 * repeated vertex.  Returns 0, or -1 when out of memory. */
typedef struct simp_topology {
    uint32_t edges, boundary_edges, nonmanifold_edges, misoriented_edges;
    uint32_t nonmanifold_verts, degenerate_tris, unused_verts;
    int euler;               /* V - E + F */
} simp_topology;
int simp_topology_check(const simp_mesh *m, simp_topology *t);

/* A copy of m's positions and triangles (origin left NULL): 0, or -1 when
 * out of memory. */
int simp_copy(const simp_mesh *m, simp_mesh *out);
void simp_free(simp_mesh *m);

/* The command's input and output (tools/cli/cmd_simplify.c), shared by the
 * commands that make meshes from meshes.  simp_load: the mesh as silk's
 * loader reads it (every format, every error message; "-" is standard
 * input, a progress line for a large file unless quiet), coordinates times
 * scale, widened to double, and whether it is closed and manifold; 0 or an
 * exit code after printing the error.  simp_write_mesh: ascii PLY when path
 * ends in .ply ("comment COMMENT", x y z and, unless normals is NULL, nx ny
 * nz per vertex), else OBJ with the comment line "# COMMENT: N triangles, N
 * vertices" and the normals as "vn" lines (faces "f a//a ..."); atomically,
 * "-" for stdout; 0 or an exit code after printing the error. */
int simp_load(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold);
/* The same, and the vertex colours (0xRRGGBB each, malloc'd) in *color, or
 * NULL when the file has none. */
int simp_load_colors(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold,
                     uint32_t **color);
int simp_write_mesh(const simp_mesh *m, const double *normals, const char *path, const char *comment);
/* OBJ with nnormals normals and the normal of each corner named by
 * tri_normal (3 per triangle): faces "f a//n ..." (PLY has one normal per
 * vertex, so normals split along feature edges are written as OBJ only). */
int simp_write_obj_corners(const simp_mesh *m, const double *normals, uint32_t nnormals, const uint32_t *tri_normal,
                           const char *path, const char *comment);

/* Their common options: --triangles N (4..1e8), --scale S, -o/--output OUT,
 * --quiet.
 * simp_common_option: 1 when argv[*i] is one of them (consumed with its
 * value, *i advanced), 0 when not, -1 after printing a usage error. */
typedef struct simp_args {
    const char *out;           /* NULL: not given */
    long target;               /* -1: not given */
    silk_decimal scale;        /* {1, 0}: none */
    int quiet;                 /* --quiet: no progress line */
} simp_args;
int simp_common_option(int argc, char **argv, int *i, simp_args *args);


#endif
