/*
 * render_scene.h - `silk render A B ...`: several meshes in one picture
 * (render_scene.c), each placed, tinted and drawn in a mode of its own by
 * options that name it by its place on the command line (1 for the first
 * mesh): --place N:X,Y,Z[:YAW,PITCH,ROLL[:SCALE]], --tint N:RRGGBB,
 * --mode-of N:MODE.  Every other option is the scene's or every object's.
 */
#ifndef SILK_CLI_RENDER_SCENE_H
#define SILK_CLI_RENDER_SCENE_H

#include "cli.h"

#define CLI_SCENE_MAX 16

typedef struct cli_object {
    int given;                 /* named by any option: must be one of the meshes */
    int have_place;
    double pos[3], turn[3], scale;   /* world units; yaw, pitch, roll in degrees */
    int have_tint;
    uint32_t tint;
    int have_mode;
    cli_mode mode;
} cli_object;

/* The per-object options' parsers: VALUE is N:..., into objs[N - 1]. */
int cli_parse_place(const char *opt, const char *value, cli_object *objs);
int cli_parse_tint(const char *opt, const char *value, cli_object *objs);
int cli_parse_mode_of(const char *opt, const char *value, cli_object *objs);

/* The n meshes at paths placed by objs into one image at out (render's
 * checks of the options done); 0 or the exit code, the error printed. */
int cli_render_scene(cli_scene_opts *o, const char *out, silk_image_format out_fmt, int n, const char *const *paths,
                     const cli_object *objs);

#endif
