/*
 * silk/scene.h - several objects in one frame.
 *
 * A scene is a list of objects, each a mesh (a prepared model's too) with
 * its own placement in the world (rotation, translation and uniform scale,
 * in fixed point), its own material and lights (silk_phong) or stages
 * (silk_hal), and its own options (mode, tolerance, outlines): one frame
 * draws them all with one depth test, whole (silk_render_scene) or band
 * by band (silk_render_scene_bands), with the same pixels either way.
 *
 * How: rotation, translation and uniform scale keep angles, so an object
 * is drawn in its own frame, by the camera and the lights taken into it
 * (the eye, target and up, the near and far planes divided by the scale,
 * the lights' directions turned): its silhouette plan and shading are
 * silk_render's, unchanged, and the depth it writes is the world's (in
 * perspective 2 znear / w, which the scale divides out).  An object
 * placed where it is (silk_place_identity) is drawn with the caller's view
 * itself, so a scene of one such object is silk_render's frame, byte for
 * byte.  Each band is cleared to bg_rgb, or painted by the caller's under
 * callback (a background, a GUI's screen), then every object is drawn into
 * it, then the anti-aliased outlines of all of them are worked out from
 * the band so drawn and written at once (aa: they blend with what lies
 * behind, another object or the background).  2D over the objects is the
 * sink's to draw: it is handed every finished band.
 *
 * Memory: everything comes from the top of the arena and is released
 * before the call returns; silk_frame_stats.frame_bytes is the scene's
 * need (every object's plan at once, the outlines of a band).
 */
#ifndef SILK_SCENE_H
#define SILK_SCENE_H

#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* world = pos + scale * rot * p for a point p of the mesh.  rot's rows
 * are Q16.16 and orthonormal with determinant +1 (within 1/256: no
 * mirror, which would turn the mesh inside out); scale > 0. */
typedef struct silk_place {
    silk_fx rot[3][3];
    silk_vec3 pos;
    silk_fx scale;
} silk_place;

/* No rotation, at the origin, scale 1: the mesh where it is. */
void silk_place_identity(silk_place *p);
/* rot from angles in degrees: yaw about y, then pitch about x, then roll
 * about z, applied to the mesh in the order roll, pitch, yaw
 * (rot = Ry(yaw) Rx(pitch) Rz(roll)); pos and scale are left alone. */
void silk_place_euler(silk_place *p, silk_fx yaw_deg, silk_fx pitch_deg, silk_fx roll_deg);

/* The view an object so placed is drawn through (silk_render's for its
 * mesh alone): v's camera taken into the object's frame, v itself for the
 * identity.  SILK_ERR_ARG when p is not a rotation with a positive scale,
 * SILK_ERR_RANGE when the camera there leaves silk_view_init's ranges. */
silk_status silk_place_view(const silk_view *v, const silk_place *p, silk_view *out, silk_error *err);

typedef struct silk_object {
    const silk_mesh *mesh;
    silk_place place;
    /* Its material and lights in world terms (the lights are turned with
     * the object; p->view is not read): the default Phong stages.  Or
     * NULL and hal, stages of the caller's own, which draw the mesh as
     * they are given it: then place must be the identity (SILK_ERR_ARG
     * otherwise). */
    const silk_phong *phong;
    const silk_hal *hal;
    /* mode, tolerance, outlines and the rest, as for silk_render; bg_rgb is
     * the scene's, and CLIP's outline blends with it */
    silk_render_opts opts;
} silk_object;

/* The band under the objects: paint rows band->y0 .. y0 + rows - 1 of the
 * frame into band->color (silk_target_put, or the bytes straight).  It is
 * called for each band, and for the single rows above and below a band
 * that anti-aliased outlines read (band->rows 1), so it must paint a row
 * the same whatever band it is asked in: a function of the frame's
 * position.  The depth is already the farthest.  Return 0 to go on,
 * non-zero to stop the frame (SILK_ERR_IO). */
typedef int (*silk_under_fn)(void *user, silk_target *band);

typedef struct silk_scene {
    const silk_object *objects;
    uint32_t nobjects;           /* 1 .. SILK_SCENE_MAX_OBJECTS, drawn in this order */
    uint32_t bg_rgb;             /* the clear colour, where under is NULL */
    silk_under_fn under;         /* or NULL */
    void *under_user;
} silk_scene;

#define SILK_SCENE_MAX_OBJECTS 256u

/* An object of mesh m where it is (silk_place_identity), shaded by p,
 * with silk_render_opts_default's options. */
void silk_object_init(silk_object *o, const silk_mesh *m, const silk_phong *p);
/* A scene of n objects over white, no under callback. */
void silk_scene_init(silk_scene *s, const silk_object *objects, uint32_t n);

/* The scene through view v into t (the whole frame), or band by band into
 * band and on to sink, as silk_render and silk_render_bands (silk/render.h:
 * double-buffered bands too).  stats (may be NULL) adds up the objects'
 * counts; fell_back is set when any object fell back. */
silk_status silk_render_scene(silk_arena *a, const silk_scene *s, const silk_view *v, silk_target *t,
                              silk_frame_stats *stats, silk_error *err);
silk_status silk_render_scene_bands(silk_arena *a, const silk_scene *s, const silk_view *v, silk_target *band,
                                    const silk_sink *sink, silk_frame_stats *stats, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
