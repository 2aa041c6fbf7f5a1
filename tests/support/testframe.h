/*
 * testframe.h - test support for the per-frame stages (src/frame.h,
 * src/plan.h): a view around a mesh, the smooth-silhouette stages
 * run by hand so that the test can inspect the internal frame, and the
 * watertightness checks of a frame's output geometry.
 */
#ifndef SILK_TESTFRAME_H
#define SILK_TESTFRAME_H

#include <stdint.h>
#include "silk/silk.h"
#include "src/frame.h"
#include "src/plan.h"
#include "src/remesh.h"
#include "src/perturb.h"

/* Looking at the centre of the mesh's bounding box from direction dir
 * (any length), dist bounding radii away: 512 x 512, 45 degrees, or a
 * parallel view 1.2 radii high.  Returns 0 when silk_view_init refuses. */
/* The centre of m's bounding box into c; returns half its diagonal. */
double tf_bounds(const silk_mesh *m, double c[3]);
int tf_view_around(const silk_mesh *m, const double dir[3], double dist, int ortho, silk_view *v);
/* The same at w x h pixels (tf_view_around is 512 x 512). */
int tf_view_around_size(const silk_mesh *m, const double dir[3], double dist, int ortho, int w, int h,
                        silk_view *v);

/* A silk_sink that copies each band into a whole frame (frame: the band's
 * width x height pixels, rows top to bottom) and records how they came:
 * the row the next band must start at, the bands seen, the bands out of
 * order or taller than max_rows; with stop_after non-zero it stops the
 * frame after that many bands. */
typedef struct tf_collect {
    uint8_t *frame;
    int next_row, max_rows, bands, bad, stop_after;
} tf_collect;
int tf_collect_band(void *user, const silk_target *t);

/* silk_render_bands at the view's size in bands of `rows` rows, whose
 * buffers (exactly `rows` lines, so that an overrun shows under ASan) come
 * from the top of the arena and are released after, collected into c
 * (c->frame must hold the whole frame; the other fields are reset).  A
 * band target not restored by the call counts as a bad band. */
silk_status tf_render_bands(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                            const silk_render_opts *o, silk_pixfmt fmt, int rows, tf_collect *c,
                            silk_frame_stats *stats, silk_error *err);

/* The stages exactly as silk_frame_smooth runs them when memory suffices
 * (brute-force visibility), keeping the internal frame for inspection.
 * Returns 0 when a stage fails. */
/* The silhouette segments of plan f in triangle order (f->nsegs of them,
 * silk_remesh_seg), malloc'd; NULL when there are none. */
silk_sil_seg *tf_segs(const silk_sil_frame *f);
/* The first record of side k's chain of triangle t in a stored frame g. */
uint32_t tf_side_rec(const silk_sil_frame *f, const silk_frame_geom *g, uint32_t t, uint32_t k);

int tf_run_frame(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tol, silk_sil_frame *f,
                 silk_frame_geom *g, silk_frame_stats *st);

/* Evaluates every record as the vertex stage would, and checks that every
 * directed edge of every output triangle occurs once and its reverse once,
 * by the bits of the evaluated positions: a closed surface with no crack
 * and no T-junction.  Returns the number of edges that fail (and the
 * number checked in *checked). */
uint32_t tf_crack_check(const silk_mesh *m, const silk_frame_geom *g, uint32_t *checked);

/* Records at the same position must carry the same normal where the mesh
 * has one normal per vertex (no split normals): smooth shading across the
 * patches, bit for bit.  Returns the number of positions where they differ. */
uint32_t tf_normal_seams(const silk_mesh *m, const silk_frame_geom *g);

#endif
