/*
 * cli.h - what the subcommands of the silk tool share: one-line errors with
 * the exit codes (2: usage, 1: input), strict number parsing, and the scene
 * options of `silk render` and `silk info` (load options, camera, frame),
 * including the default camera that frames the model.
 *
 * Tools run on the host and may use double; values reach the core as Q16.16
 * only after a range check.
 */
#ifndef SILK_CLI_H
#define SILK_CLI_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "silk/silk.h"

#define CLI_EXIT_INPUT 1      /* a file, a mesh or a render failed */
#define CLI_EXIT_USAGE 2      /* a bad option or value */

/* Largest image side and eye/target coordinate the tool accepts. */
#define CLI_MAX_SIDE SILK_MAX_DIM
#define CLI_MAX_COORD 16384.0

/* Host board defaults (boards/host/board.mk passes them as -D flags). */
#ifndef SILK_BOARD_WIDTH
#define SILK_BOARD_WIDTH 640
#endif
#ifndef SILK_BOARD_HEIGHT
#define SILK_BOARD_HEIGHT 480
#endif
#ifndef SILK_BOARD_FORMAT
#define SILK_BOARD_FORMAT SILK_PIX_RGB888
#endif

/* The default camera: vertical field of view, and the direction from the
 * model towards the eye, 30 degrees to the right of +z and 20 degrees up. */
#define CLI_DEFAULT_FOV 35.0
#define CLI_VIEW_AZIMUTH 30.0
#define CLI_VIEW_ELEVATION 20.0

/* "silk: " + message + newline on stderr; returns code. */
int cli_fail(int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Parsers: 0 on success; on failure they print the error (naming opt) and
 * return -1.  Numbers must be complete ("12x" is not 12), finite and in
 * [lo, hi]. */
int cli_parse_long(const char *opt, const char *s, long lo, long hi, long *out);
int cli_parse_double(const char *opt, const char *s, double lo, double hi, double *out);
int cli_parse_vec3(const char *opt, const char *s, double lim, double out[3]);
int cli_parse_size(const char *opt, const char *s, int *w, int *h);
int cli_parse_rgb(const char *opt, const char *s, uint32_t *rgb);
int cli_parse_bytes(const char *opt, const char *s, size_t *out);

/* Argument walking with "--opt value" and "--opt=value".  cli_value returns
 * the value of the option at argv[*i] and advances *i, or prints "OPT needs
 * a value" and returns NULL.  cli_is(arg, name) matches "name" and "name=..". */
int cli_is(const char *arg, const char *name);
const char *cli_value(int argc, char **argv, int *i);

/* Everything `silk render` and `silk info` read from the command line
 * besides their own few options. */
typedef struct cli_scene_opts {
    const char *mesh_path;
    silk_load_opts load;
    int width, height;
    silk_pixfmt fmt;
    int have_eye, have_target, have_up;
    double eye[3], target[3], up[3];
    int ortho;                 /* 1: orthographic */
    int ortho_auto;            /* --ortho auto: half height from the model */
    double fov;                /* degrees, perspective */
    double ortho_half;         /* world units, orthographic */
    silk_render_opts render;
    int vis_brute;             /* 1: no Gaussian-sphere hierarchy, every normal tested */
    size_t arena_bytes;        /* 0: from the file size */
    int arena_doublings;       /* without --arena: start from the estimate times 2^this */
    int orient_note;           /* 1 (default): say on stderr when the load turned triangles round */
} cli_scene_opts;

void cli_scene_opts_default(cli_scene_opts *o);

/* Consume argv[*i] if it is a scene option (advancing *i past its value):
 * returns 1 if consumed, 0 if not a scene option, -1 after printing an
 * error. */
int cli_scene_option(cli_scene_opts *o, int argc, char **argv, int *i);

/* The help text of the scene options, for the subcommands' --help. */
void cli_print_scene_help(FILE *f);

/* A loaded mesh in its arena, a view of it, a target in the same arena. */
typedef struct cli_scene {
    uint8_t *file;
    size_t file_len;
    void *arena_buf;
    silk_arena arena;
    silk_mesh mesh;
    silk_camera cam;
    silk_view view;
    silk_target target;
    silk_phong phong;
    silk_hal hal;
    size_t load_bytes;         /* arena bottom after loading the mesh */
} cli_scene;

/* One line on stderr when loading turned triangles round, or found a
 * surface it could not orient (silk_mesh.nreoriented_tris, ...). */
void cli_orient_note(const char *path, const silk_mesh *m);

/* Read and load the mesh (with the orientation note unless o->orient_note
 * is 0), allocate the arena, set up the camera, the target (colour and
 * depth from the arena, purpose RASTER) and the Phong stages.
 * Returns 0, or an exit code after printing the error; cli_scene_free
 * releases everything either way. */
int cli_scene_load(cli_scene *s, const cli_scene_opts *o);
void cli_scene_free(cli_scene *s);

/* The camera for o and the loaded mesh: the options where given, the default
 * framing (docs/architecture.md, "Default camera") where not.  Returns 0 or
 * an exit code after printing the error. */
int cli_camera(const cli_scene_opts *o, const silk_mesh *m, silk_camera *cam);

/* Q16.16 to double, for printing. */
double cli_fx_to_double(silk_fx v);

/* The centre of the mesh's bounding box (into c) and the radius about it
 * that holds every vertex, 5% to spare; 1 for a mesh of one point. */
double cli_mesh_radius(const silk_mesh *m, double c[3]);

/* An argument of `silk CMD` that no option took: the one mesh (*mesh_path),
 * or the usage error of an unknown option or a second mesh.  Returns 0 or
 * CLI_EXIT_USAGE. */
int cli_mesh_arg(const char *cmd, const char *arg, const char **mesh_path);

/* The subcommands: argv[0] is the subcommand's name; they return the exit
 * status. */
int cmd_render(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_gen(int argc, char **argv);
int cmd_bench(int argc, char **argv);   /* tools/cmd_bench.c */

#endif
