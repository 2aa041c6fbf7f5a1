/*
 * view_fb.c - `silk view MESH --fb /dev/fb0`: the model turning on a
 * Linux framebuffer until Ctrl-C, rendered in bands straight into the
 * screen memory (silk_render_bands() with the platform/fb.h sink), as a
 * device without a second frame buffer would.
 *
 * `--fb-file PATH --fb-geometry WxHxBPP` does the same into a file-backed
 * framebuffer (the same code apart from the ioctls): how the tests and a
 * headless machine use it.  `view` is one subcommand for every display:
 * cmd_view (tools/cli/cmd_view.c) reads the command line and hands --fb /
 * --fb-file here, keeping the window (SDL) for itself.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "viewer.h"
#include "platform/fb.h"

static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

/* The camera turned by deg about the up axis through the target: the
 * scene's --yaw plus deg (cli_camera), so --eye, --pitch and --up-axis hold. */
static int turn_camera(const cli_scene_opts *o, const cli_scene *s, double deg, silk_camera *cam)
{
    cli_scene_opts t = *o;
    t.yaw = fmod(o->yaw + deg, 360);
    return cli_scene_camera(s, &t, cam);
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

int view_fb(cli_scene_opts *o, const view_fb_opts *v)
{
    silk_fb fb;
    silk_error err;
    silk_status st;
    if (v->fb_file) {
        silk_fb_info info;
        st = silk_fb_info_default(&info, v->geo_w, v->geo_h, v->geo_bpp, &err);
        if (st == SILK_OK) st = silk_fb_open_file(&fb, v->fb_file, &info, &err);
    } else {
        st = silk_fb_open(&fb, v->fb_dev, &err);
    }
    if (st != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);

    if (!v->have_size) {
        o->width = (int)fb.info.xres;
        o->height = (int)fb.info.yres;
    }
    if (!v->have_format) o->fmt = fb.info.bits_per_pixel == 16 ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
    fb.origin_x = ((int)fb.info.xres - o->width) / 2;
    fb.origin_y = ((int)fb.info.yres - o->height) / 2;

    cli_scene s;
    int rc = cli_scene_load(&s, o);
    int rows = v->rows ? v->rows : VIEW_FB_ROWS;
    if (rows > o->height) rows = o->height;
    size_t px = (size_t)rows * (size_t)o->width;
    uint8_t *color = rc ? NULL : malloc(px * silk_pixfmt_bytes(o->fmt));
    uint32_t *depth = rc ? NULL : malloc(px * sizeof *depth);
    if (!rc && (!color || !depth)) rc = cli_fail(CLI_EXIT_INPUT, "out of memory for a band of %d rows", rows);

    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);

    silk_fb_fill(&fb, o->render.bg_rgb);
    silk_target band;
    if (!rc) silk_target_init(&band, o->width, o->height, 0, rows, o->fmt, color, depth);
    silk_sink sink = { .band = silk_fb_band, .user = &fb };
    long frames = 0;
    double t0 = now_ms();
    for (; !rc && !stop_requested && (v->frames == 0 || frames < v->frames); frames++) {
        silk_camera cam;
        silk_view view;
        rc = turn_camera(o, &s, (double)frames * (v->spin ? v->spin : VIEW_FB_SPIN), &cam);
        if (rc) break;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
            break;
        }
        cli_scene_phong(&s, o, o->render.mode, &view, &s.phong);
        silk_hal_phong(&s.hal, &s.phong);
        silk_frame_stats fs;
        silk_render_opts ro = o->render;
        cli_scene_render_opts(&s, &ro);
        if (silk_render_bands(&s.arena, cli_scene_mesh(&s, ro.mode), &view, &s.hal, &ro, &band, &sink, &fs, &err) !=
            SILK_OK)
            rc = cli_fail(CLI_EXIT_INPUT, "%s: %s", o->mesh_path, err.msg);
    }
    double ms = now_ms() - t0;
    free(color);
    free(depth);
    cli_scene_free(&s);
    if (silk_fb_close(&fb, &err) != SILK_OK && !rc) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    if (!rc)
        printf("silk view: %ld frames of %dx%d in bands of %d rows, %.2f ms per frame\n", frames, o->width,
               o->height, rows, frames ? ms / (double)frames : 0.0);
    return rc;
}

