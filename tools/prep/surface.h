/*
 * surface.h - the detailed surface's shading normals at the vertices of a
 * coarse mesh simplified from it by subset placement (simplify.h,
 * simp_opts.subset), for `silk simplify --for smooth` and `silk prepare`.
 * Host-side, double precision.
 *
 * Smooth mode rebuilds the outline from the coarse vertices and their
 * normals (paper section III-C, eqs. 2-4); normals averaged from a few
 * coarse faces point where the coarse facets do, not where the detailed
 * surface does.  Every coarse vertex is a vertex of the detailed mesh, so
 * its normal here is the angle-weighted normal of the detailed mesh at that
 * very point (Thurmer & Wuthrich, as section III-B), split where the coarse
 * mesh has a feature edge: the corners around a coarse vertex fall into
 * groups joined through non-feature edges (the loader's rule, with the
 * crease angle raised by SURF_CREASE_MARGIN_DEG so that every split the
 * file carries is an edge silk's loader also flags, whatever its rounding),
 * and each fine face around the vertex lends its normal to the group whose
 * coarse faces it faces most nearly.
 */
#ifndef SILK_TOOLS_SURFACE_H
#define SILK_TOOLS_SURFACE_H

#include <stdint.h>
#include "simplify.h"

#define SURF_CREASE_MARGIN_DEG 1.0

typedef struct surf_normals {
    uint32_t nnormals;
    double *normal;          /* 3 * nnormals unit vectors, malloc'd */
    uint32_t *tri_normal;    /* 3 * ntris of the coarse mesh: the normal of each corner, malloc'd */
} surf_normals;

/* coarse->origin must name each coarse vertex in fine (simp_run with
 * subset placement).  crease_deg: the loader's crease angle (60 unless the
 * user chose another).  Returns 0, or -1 when out of memory. */
int surf_normals_compute(const simp_mesh *fine, const simp_mesh *coarse, double crease_deg, surf_normals *out);
void surf_normals_free(surf_normals *n);

/* What `silk simplify` and `silk prepare` share (tools/cli/cmd_simplify.c). */
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
/* The simplification's options both commands take besides
 * simp_common_option's: --crease, --feature-weight.  1 when argv[*i] is one
 * of them (consumed with its value), 0 when not, -1 after a usage error. */
int simplify_option(int argc, char **argv, int *i, simp_opts *so);

#endif
