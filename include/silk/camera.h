/*
 * silk/camera.h - viewing: lookAt, perspective or orthographic projection.
 *
 * OpenGL conventions: the camera looks down its -z axis, clip space is
 * x,y,z in [-w, w], pixel (0,0) is the top-left pixel and is sampled at its
 * centre (0.5, 0.5).  Matrices are row-major Q16.16 and act on column vectors.
 * The perspective frustum's far plane is at infinity (clip z = w - 2 znear),
 * so zfar bounds orthographic views only; docs/raster.md gives the ranges.
 */
#ifndef SILK_CAMERA_H
#define SILK_CAMERA_H

#include "fixed.h"
#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct silk_mat4 { silk_fx m[4][4]; } silk_mat4;

typedef struct silk_camera {
    silk_vec3 eye, target, up;
    int ortho;                 /* 0: perspective, 1: orthographic */
    silk_fx fov_deg;           /* vertical field of view (perspective), (0, 180) */
    silk_fx ortho_half_height; /* half the view height in world units (orthographic) */
    silk_fx znear, zfar;       /* distances along the view axis, 0 < znear < zfar */
    int width, height;         /* viewport in pixels */
} silk_camera;

/* What the per-frame stages need, derived once per frame. */
typedef struct silk_view {
    silk_camera cam;
    silk_mat4 view;            /* world -> eye */
    silk_mat4 proj;            /* eye -> clip */
    silk_mat4 viewproj;        /* world -> clip */
    silk_vec3 forward;         /* unit view direction (eye -> target) */
    silk_vec3 right, upv;      /* unit camera axes in world space */
    silk_fx pixels_per_unit;   /* screen pixels per world unit at distance 1 (persp) or anywhere (ortho) */
    int32_t rot24[3][3];       /* rows right, upv, -forward in Q8.24: silk_view_clip's rotation */
} silk_view;

silk_status silk_view_init(silk_view *v, const silk_camera *cam, silk_error *err);

/* World -> clip for the renderer: proj * (R * (p - eye)) with the
 * difference and the rotation done in 64 bits and rounded once, so points
 * far from the origin keep their precision (the 4x4 viewproj has the
 * translation rounded into it).  The Phong vertex stage uses this. */
silk_vec4 silk_view_clip(const silk_view *v, silk_vec3 p);

/* Supported input ranges (docs/raster.md): fov in [SILK_FOV_MIN, SILK_FOV_MAX]
 * degrees, znear in [SILK_ZNEAR_MIN, SILK_ZNEAR_MAX] (clip z = w - 2 znear
 * must fit Q16.16), ortho_half_height >= SILK_ZNEAR_MIN, width and height
 * in [1, SILK_MAX_DIM], |P - eye| < 32768 for drawn points. */
#define SILK_FOV_MIN    SILK_FX_C(1, 1)
#define SILK_FOV_MAX    SILK_FX_C(179, 1)
#define SILK_ZNEAR_MIN  SILK_FX_C(1, 1024)
#define SILK_ZNEAR_MAX  SILK_FX_C(16383, 1)
#define SILK_MAX_DIM    8192

/* Transform a point (w = 1) to clip space. */
silk_vec4 silk_mat4_apply_point(const silk_mat4 *m, silk_vec3 p);
silk_vec3 silk_mat4_apply_dir(const silk_mat4 *m, silk_vec3 d);   /* w = 0, upper 3x3 */
silk_mat4 silk_mat4_mul(const silk_mat4 *a, const silk_mat4 *b);
silk_mat4 silk_mat4_identity(void);

/* Project a world point to pixel coordinates (x right, y down, Q16.16) and
 * return 1, or return 0 when it lies behind the near plane. */
int silk_view_project(const silk_view *v, silk_vec3 p, silk_vec2 *px);

/* Direction used for visibility: for perspective E - P (towards the eye), for
 * orthographic -forward (constant).  Not normalised. */
silk_vec3 silk_view_to_eye(const silk_view *v, silk_vec3 p);

#ifdef __cplusplus
}
#endif

#endif
