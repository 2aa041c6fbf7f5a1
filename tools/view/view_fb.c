/*
 * view_fb.c - `silk view MESH --fb /dev/fb0`: the model turning on a
 * Linux framebuffer until Ctrl-C, rendered in bands straight into the
 * screen memory (silk_render_bands() with the platform/fb.h sink), as a
 * device without a second frame buffer would.
 *
 * `--fb-file PATH --fb-geometry WxHxBPP` does the same into a file-backed
 * framebuffer (the same code apart from the ioctls): how the tests and a
 * headless machine use it.  `view` is one subcommand for every display:
 * cmd_view (tools/cli/cmd_view.c) hands --fb / --fb-file here and keeps the
 * window (SDL) for itself.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "viewer.h"
#include "platform/fb.h"

/* Board defaults (boards/linux-fb/board.mk): the device and the band height. */
#ifndef SILK_BOARD_BAND_ROWS
#define SILK_BOARD_BAND_ROWS 32
#endif

#define VIEW_DEFAULT_SPIN 3.0     /* degrees the model turns per frame */

static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk view MESH --fb DEVICE [options]\n"
            "       silk view MESH --fb-file PATH --fb-geometry WxHxBPP [options]\n"
            "\n"
            "Show MESH turning on a Linux framebuffer until Ctrl-C, rendered in bands of\n"
            "--rows lines straight into the screen (no frame buffer of silk's own).\n"
            "\n"
            "  --fb DEVICE          a framebuffer device, e.g. /dev/fb0: size and pixel\n"
            "                       format from the device (16, 24 or 32 bits per pixel)%s%s%s\n"
            "  --fb-file PATH       a file-backed framebuffer instead (created or truncated)\n"
            "  --fb-geometry WxHxBPP  its size and bits per pixel (16, 24 or 32)\n"
            "  --frames N           stop after N frames (default: run until Ctrl-C)\n"
            "  --spin DEG           degrees the model turns per frame (default %g)\n"
            "  --rows N             band height in rows (default %d)\n"
            "\n"
            "The frame fills the screen unless --size is given (then it is centred);\n"
            "it is rendered in RGB565 on a 16-bit screen, RGB888 otherwise, unless --format\n"
            "says otherwise.\n",
#ifdef SILK_BOARD_FB
            "\n                       (default on this board: ", SILK_BOARD_FB, ")",
#else
            "", "", "",
#endif
            VIEW_DEFAULT_SPIN, SILK_BOARD_BAND_ROWS);
    cli_print_scene_help(f, CLI_OPT_ALL);
    fprintf(f,
            "\n"
            "examples:\n"
            "  silk view bunny.obj --fb /dev/fb0\n"
            "  silk view bunny.obj --fb-file /tmp/fb.raw --fb-geometry 320x240x16 --frames 10\n");
}

static int parse_geometry(const char *s, int *w, int *h, int *bpp)
{
    char *end;
    long v[3];
    const char *p = s;
    for (int k = 0; k < 3; k++) {
        if (*p < '0' || *p > '9') goto bad;
        v[k] = strtol(p, &end, 10);
        if (k < 2 && *end != 'x') goto bad;
        p = end + (k < 2);
    }
    if (*end) goto bad;
    if (v[0] < 1 || v[1] < 1 || v[0] > CLI_MAX_SIDE || v[1] > CLI_MAX_SIDE)
        return cli_fail(-1, "--fb-geometry: width and height must be 1 to %d (got %s)", CLI_MAX_SIDE, s), -1;
    if (v[2] != 16 && v[2] != 24 && v[2] != 32)
        return cli_fail(-1, "--fb-geometry: bits per pixel must be 16, 24 or 32 (got %s)", s), -1;
    *w = (int)v[0];
    *h = (int)v[1];
    *bpp = (int)v[2];
    return 0;
bad:
    return cli_fail(-1, "--fb-geometry must be WIDTHxHEIGHTxBPP, e.g. 320x240x16 (got \"%s\")", s), -1;
}

typedef struct view_opts {
    const char *fb_dev, *fb_file;
    int geo_w, geo_h, geo_bpp, have_geo;
    long frames;               /* 0: until a signal */
    double spin;
    long rows;
    int have_size, have_format;
} view_opts;

/* The camera turned by deg about the up axis through the target: the
 * scene's --yaw plus deg (cli_camera), so --eye, --pitch and --up-axis hold. */
static int turn_camera(const cli_scene_opts *o, const silk_mesh *m, double deg, silk_camera *cam)
{
    cli_scene_opts t = *o;
    t.yaw = fmod(o->yaw + deg, 360);
    return cli_camera(&t, m, cam);
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int run_fb(cli_scene_opts *o, const view_opts *v)
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
    int rows = v->rows < o->height ? (int)v->rows : o->height;
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
        rc = turn_camera(o, &s.mesh, (double)frames * v->spin, &cam);
        if (rc) break;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
            break;
        }
        cli_scene_phong(&s, o, &view, &s.phong);
        silk_hal_phong(&s.hal, &s.phong);
        silk_frame_stats fs;
        if (silk_render_bands(&s.arena, &s.mesh, &view, &s.hal, &o->render, &band, &sink, &fs, &err) != SILK_OK)
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

int view_fb(int argc, char **argv)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    view_opts v;
    memset(&v, 0, sizeof v);
    v.spin = VIEW_DEFAULT_SPIN;
    v.rows = SILK_BOARD_BAND_ROWS;
    int rc = 0;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i], *val;
        if (cli_help(a, help)) return 0;
        if (cli_is(a, "--size")) v.have_size = 1;
        if (cli_is(a, "--format")) v.have_format = 1;
        if (cli_scene_arg(&o, argc, argv, &i, &rc)) continue;
        if (cli_is(a, "--fb")) {
            if (!(v.fb_dev = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--fb-file")) {
            if (!(v.fb_file = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--fb-geometry")) {
            if (!(val = cli_value(argc, argv, &i)) || parse_geometry(val, &v.geo_w, &v.geo_h, &v.geo_bpp) != 0)
                rc = CLI_EXIT_USAGE;
            v.have_geo = 1;
        } else if (cli_is(a, "--frames")) {
            if (!(val = cli_value(argc, argv, &i)) || cli_parse_long("--frames", val, 1, 100000000, &v.frames) != 0)
                rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--spin")) {
            if (!(val = cli_value(argc, argv, &i)) || cli_parse_double("--spin", val, -360, 360, &v.spin) != 0)
                rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--rows")) {
            if (!(val = cli_value(argc, argv, &i)) || cli_parse_long("--rows", val, 1, CLI_MAX_SIDE, &v.rows) != 0)
                rc = CLI_EXIT_USAGE;
        } else {
            rc = cli_mesh_arg("view", a, &o.mesh_path);
        }
    }
    if (rc) return rc;
    if (!o.mesh_path) return cli_fail(CLI_EXIT_USAGE, "view: no mesh given (silk view MESH --fb /dev/fb0)");
    if (o.bg_none) return cli_fail(CLI_EXIT_USAGE, "view: --bg none is for images (silk render); give a colour");
    if (v.fb_dev && v.fb_file) return cli_fail(CLI_EXIT_USAGE, "view: give --fb or --fb-file, not both");
    if (v.fb_file && !v.have_geo)
        return cli_fail(CLI_EXIT_USAGE, "view: --fb-file needs --fb-geometry WxHxBPP, e.g. 320x240x16");
    if (v.have_geo && !v.fb_file)
        return cli_fail(CLI_EXIT_USAGE, "view: --fb-geometry is for --fb-file (a device has its own)");
#ifdef SILK_BOARD_FB
    if (!v.fb_dev && !v.fb_file) v.fb_dev = SILK_BOARD_FB;
#endif
    if (!v.fb_dev && !v.fb_file)
        return cli_fail(CLI_EXIT_USAGE,
                        "view: no display: give --fb DEVICE or --fb-file PATH --fb-geometry WxHxBPP");
    return run_fb(&o, &v);
}
