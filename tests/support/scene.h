/*
 * scene.h - test support: meshes built from double coordinates, a camera
 * from doubles, and one call that renders a mesh into a heap image with
 * the default Phong stages.  For the tests of hard input (test_overflow,
 * test_hard_geometry, test_exhaustion), which build many small scenes.
 *
 * Coordinates are rounded to Q16.16 once, in ts_build; the image is RGB888
 * with the background TS_BG, so "covered" means "not TS_BG": pure red,
 * which the default material never gives (its green and blue are at least
 * its ambient part).
 */
#ifndef TS_SCENE_H
#define TS_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "silk/silk.h"

#define TS_BG 0xFF0000u

/* Whether the core draws mode (silk/config.h: a board's configuration may
 * leave PN and BLEND out), and --wire's lines: the tests that render in
 * every mode leave out what the core was built without. */
static inline int ts_mode_built(int mode)
{
    return mode <= SILK_MODE_SMOOTH || (mode <= SILK_MODE_BLEND ? SILK_REFERENCE_MODES
                                        : mode == SILK_MODE_CLIP ? SILK_CLIP_MODE : SILK_SILTEX_MODE);
}
#define TS_WIRE_BUILT SILK_LINES

/* A growable triangle list: coordinates as doubles, corners 0-based. */
typedef struct ts_mesh {
    double *v;
    uint32_t *f;
    uint32_t nv, nf, cap_v, cap_f;
} ts_mesh;

void ts_mesh_free(ts_mesh *m);
uint32_t ts_vertex(ts_mesh *m, double x, double y, double z);
void ts_tri(ts_mesh *m, uint32_t a, uint32_t b, uint32_t c);
/* A UV sphere, poles on y, outward-facing: segs around, bands pole to pole. */
void ts_sphere(ts_mesh *m, int segs, int bands, double r, double cx, double cy, double cz);

/* silk_mesh_build over m (default load options) into the arena. */
silk_status ts_build(const ts_mesh *m, silk_arena *a, silk_mesh *out, silk_error *err);

double ts_fx2d(silk_fx v);
silk_fx ts_d2fx(double v);

/* Perspective (fov_deg > 0) or orthographic (fov_deg <= 0: half height -fov_deg) camera. */
silk_camera ts_camera(const double eye[3], const double target[3], double fov_deg, double znear, double zfar,
                      int width, int height);

typedef struct ts_image {
    int width, height;
    uint8_t *rgb;         /* width * height * 3 */
    uint32_t *depth;
} ts_image;

/* Allocates (or reuses, when the size matches) the image, clears it to
 * TS_BG and renders one frame with silk_render.  Returns its status. */
silk_status ts_render(silk_arena *a, const silk_mesh *m, const silk_camera *cam, const silk_render_opts *o,
                      ts_image *img, silk_frame_stats *stats, silk_error *err);
void ts_image_free(ts_image *img);
int ts_covered(const ts_image *img, int x, int y);
long ts_count_covered(const ts_image *img);
/* Pixels covered in one image and not in the other. */
long ts_count_differ(const ts_image *a, const ts_image *b);

#endif
