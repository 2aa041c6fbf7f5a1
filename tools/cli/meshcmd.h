/*
 * meshcmd.h - what the commands that make meshes from meshes share (`silk
 * simplify`, `silk hull`, `silk prepare`; tools/cli/cmd_simplify.c): their
 * common options, the input loaded as silk's own loader reads it, OBJ and
 * PLY output, and the simplification with its checks.
 */
#ifndef SILK_CLI_MESHCMD_H
#define SILK_CLI_MESHCMD_H

#include <stdint.h>
#include "opt.h"
#include "prep/simplify.h"
#include "prep/surface.h"
#include "silk/fixed.h"

/* The common options (simp_rows): --triangles N (4..1e8, needed), --scale S,
 * --quiet (SIMP_OPT_COMMON); --crease DEG and --feature-weight W of the
 * simplification (SIMP_OPT_SHAPE). */
typedef struct simp_args {
    long target;               /* -1: not given */
    silk_decimal scale;        /* {1, 0}: none */
    int quiet;                 /* --quiet: no progress line */
    double crease_deg, feature_weight;
} simp_args;
#define SIMP_OPT_COMMON 1u
#define SIMP_OPT_SHAPE 2u
extern const cli_opt simp_rows[];
void simp_args_default(void *base);
#define SIMP_SET(mask) { simp_rows, (mask), sizeof(simp_args), simp_args_default, NULL }

/* simp_load: the mesh at path as silk's loader reads it (every format,
 * every error message; "-" is standard input, a progress line for a large
 * file unless quiet), coordinates times scale, widened to double, and
 * whether it is closed and manifold; 0 or an exit code after printing the
 * error.  simp_load_colors: the same, and the vertex colours (0xRRGGBB each,
 * malloc'd) in *color, or NULL when the file has none. */
int simp_load(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold);
int simp_load_colors(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold,
                     uint32_t **color);
/* Ascii PLY when path ends in .ply ("comment COMMENT", x y z and, unless
 * normals is NULL, nx ny nz per vertex), else OBJ with the comment line
 * "# COMMENT: N triangles, N vertices" and the normals as "vn" lines (faces
 * "f a//a ..."); atomically, "-" for stdout; 0 or an exit code after
 * printing the error. */
int simp_write_mesh(const simp_mesh *m, const double *normals, const char *path, const char *comment);
/* OBJ with nnormals normals and the normal of each corner named by
 * tri_normal (3 per triangle): faces "f a//n ..." (PLY has one normal per
 * vertex, so normals split along feature edges are written as OBJ only). */
int simp_write_obj_corners(const simp_mesh *m, const double *normals, uint32_t nnormals, const uint32_t *tri_normal,
                           const char *path, const char *comment);

/* What `silk simplify` and `silk prepare` share. */
typedef struct simp_result {
    simp_mesh mesh;          /* the simplified mesh */
    simp_mesh fine;          /* with subset placement: the input (mesh.origin indexes it) */
    surf_normals normals;    /* with subset placement: the detailed surface's normals */
    uint32_t *fine_color;    /* with subset placement: fine's vertex colours 0xRRGGBB, or NULL */
    simp_stats stats;
} simp_result;

/* Load IN, simplify it by so (a progress line named what unless quiet),
 * check that a closed manifold stays one and, with subset placement, take
 * the detailed surface's normals.  0, or the exit status after a one-line
 * error; r is to be freed either way. */
int simplify_pipeline(const char *in, const simp_opts *so, silk_decimal scale, int quiet, const char *what,
                      simp_result *r);
void simp_result_free(simp_result *r);
/* The warning when the target was not reached (every further collapse
 * would break the surface). */
void simplify_warn_short(const char *in, const simp_mesh *m, uint32_t target);

/* The one input of CMD (the output goes after -o): *in, or the usage error
 * for none or a second ("CMD: give FINE (USAGE)"). */
int simp_one_input(const char *cmd, int npos, const char *const *pos, const char *usage, const char **in);

#endif
