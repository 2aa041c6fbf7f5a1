/*
 * viewer.h - the desktop viewer behind `silk view MESH`: a camera orbiting
 * one loaded mesh, the render settings its keys change (mode, tolerance,
 * wireframe, silhouette and feature lines, projection), and a status line
 * drawn into the frame.
 *
 * tools/cli/cmd_view.c holds all of it and needs no window system (so
 * `--benchmark` and `--events` run anywhere); tools/view/viewer_sdl.c, built when
 * SDL2 is present, turns SDL's mouse, wheel, key and resize events into the
 * calls below and shows each frame in a window.  docs/viewer.md.
 */
#ifndef SILK_TOOLS_VIEWER_H
#define SILK_TOOLS_VIEWER_H

#include <stdint.h>
#include "cli/cli.h"

/* Keys: printable ones as their character ('1'..'4', 'm', 'w', 'l', 'c',
 * '+', '-', '[', ']', 'o', 's', 'h', ' ', 'r', 'q'), the rest as these. */
enum { VIEWER_KEY_LEFT = 256, VIEWER_KEY_RIGHT, VIEWER_KEY_UP, VIEWER_KEY_DOWN };

#define VIEWER_ORBIT_DEG_PER_PX 0.4   /* mouse drag: degrees per pixel */
#define VIEWER_ZOOM_STEP 1.1          /* one wheel notch */
#define VIEWER_SPIN_DEG 2.0           /* per frame while spinning */

typedef struct viewer {
    cli_scene_opts o;          /* the command line; o.width/height is the first window size */
    cli_scene s;               /* the mesh in its arena */
    int doublings;             /* the arena has been doubled this often after a frame fell back */
    const char *shot_pattern;  /* screenshot names (sheet.h patterns) */
    int shots;                 /* screenshots taken */

    /* The orbit: the eye at dist from target, azimuth az from +z towards
     * +x, elevation el above the xz plane; +y is up. */
    double centre[3], radius;  /* bounding sphere, for limits and near/far */
    double target[3], az, el, dist;
    double home[6];            /* target, az, el, dist of the first view (key r) */
    int ortho;

    silk_render_opts ro;
    int hud, spin, quit;

    int w, h;                  /* the frame (the window's client area) */
    uint8_t *color;            /* heap, re-created on resize */
    uint32_t *depth;
    silk_target t;
    silk_view view;
    silk_phong phong;
    silk_hal hal;

    int dirty;                 /* the frame no longer shows the state */
    long frames;               /* frames rendered */
    silk_frame_stats stats;
    double render_ms;          /* silk_render alone */
    double frame_ms;           /* render + status line */
    double present_ms;         /* the last copy to the window (set by the SDL loop) */
} viewer;

/* Load o->mesh_path and set up a w x h frame from the default camera.
 * Returns 0, or an exit code after printing the error; viewer_close is
 * safe either way. */
int viewer_open(viewer *v, const cli_scene_opts *o, const char *shot_pattern);
void viewer_close(viewer *v);

/* New frame size (the window was resized): the buffers are made again. */
int viewer_resize(viewer *v, int w, int h);

/* Input.  Each marks the frame dirty. */
int viewer_key(viewer *v, int key);                   /* 0, or an exit code (a failed screenshot) */
void viewer_orbit(viewer *v, double dx_px, double dy_px);
void viewer_pan(viewer *v, double dx_px, double dy_px);
void viewer_zoom(viewer *v, double notches);           /* > 0: closer */

/* Render the frame if it is dirty (or spinning): silk_render, then the
 * status line.  0, or an exit code. */
int viewer_frame(viewer *v);

/* Write the frame as shown (rendering it first if dirty) to path, or to
 * the next name of the screenshot pattern when path is NULL; prints
 * "silk view: saved PATH (...)" on stdout. */
int viewer_screenshot(viewer *v, const char *path);

/* The status line of the current frame. */
void viewer_status(const viewer *v, char *buf, size_t n);

/* viewer_sdl.c: the window loop; returns the exit status.  frames > 0:
 * quit after that many frames, saving the last one as a screenshot. */
int viewer_run_sdl(viewer *v, long frames);

#endif
