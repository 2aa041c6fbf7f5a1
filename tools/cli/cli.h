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
#include "src/silmap_interp.h"
#include "silk/siltex.h"
#include "material.h"
#include "platform/platform.h"

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

/* Files from this size on show a progress line while they load. */
#define CLI_PROGRESS_FILE_BYTES ((size_t)4 << 20)

/* The tools' one pi, and degrees to radians. */
#define CLI_PI 3.14159265358979323846
#define CLI_DEG (CLI_PI / 180)

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
/* s as one of two words: *out 0 for a, 1 for b ("OPT must be A or B"). */
int cli_parse_choice(const char *opt, const char *s, const char *a, const char *b, int *out);
int cli_parse_double(const char *opt, const char *s, double lo, double hi, double *out);
int cli_parse_vec3(const char *opt, const char *s, double lim, double out[3]);
int cli_parse_size(const char *opt, const char *s, int *w, int *h);
int cli_parse_rgb(const char *opt, const char *s, uint32_t *rgb);
int cli_parse_bytes(const char *opt, const char *s, size_t *out);

/* A list of render modes (--modes flat,smooth,pn3): each name as
 * silk_mode_parse reads it (level 0 where the name gives none), at most
 * max of them, none twice. */
typedef struct cli_mode {
    char name[16];
    silk_mode mode;
    uint32_t level;
    int aa_off;                /* the name ends in "-noaa": anti-aliasing off */
} cli_mode;
int cli_parse_modes(const char *opt, const char *list, cli_mode *out, int max, int *n);

/* Argument walking with "--opt value" and "--opt=value".  cli_value returns
 * the value of the option at argv[*i] and advances *i, or prints "OPT needs
 * a value" and returns NULL.  cli_is(arg, name) matches "name" and "name=..". */
int cli_is(const char *arg, const char *name);
const char *cli_value(int argc, char **argv, int *i);

/* The groups of scene options; a command takes those it uses (the groups
 * field of cli_scene_opts) and refuses the others as unknown. */
#define CLI_OPT_LOAD 1u        /* --scale --crease --normals --visibility --arena --quiet */
#define CLI_OPT_CAMERA 2u      /* --eye --target --up --up-axis --yaw --pitch --fov --ortho */
#define CLI_OPT_FRAME 4u       /* --size --format */
#define CLI_OPT_MODE 8u        /* --mode --tolerance --level --pn-normals --beta */
#define CLI_OPT_LOOK 16u       /* --bg --wire --lines --lines-polygonal, material and lights */
#define CLI_OPT_ALL 31u

/* --light [point:]x,y,z[:RRGGBB] */
typedef struct cli_light {
    int point;                 /* 0: directional, v the direction towards the light */
    double v[3];
    uint32_t rgb;
} cli_light;

/* Material and lights; what is not given keeps silk_phong_default's value. */
typedef struct cli_look {
    int have_color, have_ambient, have_specular;
    uint32_t color;
    double ambient, specular;
    int shininess;             /* 0: the default */
    int nlights;               /* 0: the default two lights */
    cli_light light[SILK_MAX_LIGHTS];
    const char *texture_path;  /* --texture: NULL for the OBJ material's map_Kd, if any */
    cli_texture_opts texture;  /* --texture-format, --texture-filter, --texture-wrap */
} cli_look;

/* Everything `silk render` and `silk info` read from the command line
 * besides their own few options. */
typedef struct cli_scene_opts {
    const char *mesh_path;     /* "-": standard input */
    unsigned groups;           /* CLI_OPT_*: the options this command takes */
    silk_load_opts load;
    int width, height;
    silk_pixfmt fmt;
    int have_eye, have_target, have_up;
    double eye[3], target[3], up[3];
    double yaw, pitch;         /* degrees the eye orbits right and up */
    int up_axis_z;             /* 1: the model's up is +z and its front -y */
    int ortho;                 /* 1: orthographic */
    int ortho_auto;            /* --ortho auto: half height from the model */
    double fov;                /* degrees, perspective */
    double ortho_half;         /* world units, orthographic */
    silk_render_opts render;
    int bg_none;               /* --bg none: alpha from the object's coverage */
    cli_look look;
    int quiet;                 /* --quiet: no progress line */
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

/* The help text of the scene options in groups (CLI_OPT_*), for the
 * subcommands' --help. */
void cli_print_scene_help(FILE *f, unsigned groups);

/* The Phong stages for a view: silk_phong_default, then o's material and
 * lights. */
void cli_phong(const cli_scene_opts *o, const silk_view *view, silk_phong *p);

/* What the alpha channel of an image shows (--bg none). */
typedef enum cli_alpha {
    CLI_ALPHA_NONE = 0,        /* no alpha channel */
    CLI_ALPHA_COVERAGE,        /* 255 where the surface wrote depth or the colour is not bg_rgb */
    CLI_ALPHA_COLOUR           /* 255 where the colour is not bg_rgb (--lines only: the surface is hidden) */
} cli_alpha;

/* The alpha the scene options ask for. */
cli_alpha cli_alpha_for(const cli_scene_opts *o);

/* Write t to path: PNG or PPM by the extension, or fmt for "-" (standard
 * output; SILK_IMAGE_NONE means PNG); with alpha, a PNG whose alpha channel
 * is 255 on the object and 0 elsewhere.  Returns 0 or an exit code after
 * printing the error. */
int cli_write_image(const silk_target *t, const char *path, silk_image_format fmt, cli_alpha alpha, uint32_t bg_rgb);

/* A mesh file read whole and loaded into an arena of its own. */
typedef struct cli_mesh {
    const char *path;          /* as given; "-" is standard input */
    const char *name;          /* for messages: the path, or SILK_STDIN_NAME */
    uint8_t *file;
    size_t file_len;
    void *buf;
    silk_arena arena;
    silk_mesh mesh;
} cli_mesh;

/* Read path ("-": standard input) and load it, with the visibility
 * hierarchy if vis, into an arena of exactly `fixed` bytes, or (fixed 0)
 * of 16 bytes per file byte + extra + 1 MiB, times 2^doublings, doubled
 * up to four more times while loading runs short of it.  A progress line
 * on a terminal for large files unless quiet.  Returns 0 or an exit code
 * after printing the error; cli_mesh_free releases everything either way. */
int cli_mesh_load(cli_mesh *m, const char *path, const silk_load_opts *lo, int vis, size_t fixed, size_t extra,
                  int doublings, int quiet);
void cli_mesh_free(cli_mesh *m);

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
    silk_silmap silmap;        /* clip mode: the model's silhouette map, in file */
    silk_siltex siltex;        /* siltex mode: the model's silhouette texture, in file */
    cli_material material;     /* the OBJ material, the texture */
} cli_scene;

/* One line on stderr when loading turned triangles round, or found a
 * surface it could not orient (silk_mesh.nreoriented_tris, ...). */
void cli_orient_note(const char *path, const silk_mesh *m);

/* Read and load the mesh (with the orientation note unless o->orient_note
 * is 0), allocate the arena, set up the camera, the target (colour and
 * depth from the arena, purpose RASTER) and the Phong stages.  In clip
 * mode the mesh is the model's hull and o->render.silmap points at the
 * scene's silhouette map, in siltex mode o->render.siltex at its
 * silhouette texture.
 * Returns 0, or an exit code after printing the error; cli_scene_free
 * releases everything either way. */
int cli_scene_load(cli_scene *s, cli_scene_opts *o);

/* The silhouette map of the prepared model in file (clip mode); 0 or an
 * exit code after a one-line error. */
int cli_silmap(const uint8_t *file, size_t len, const char *name, silk_silmap *out);
/* The same for the silhouette texture (siltex mode). */
int cli_siltex(const uint8_t *file, size_t len, const char *name, silk_siltex *out);
/* cli_phong, then the scene's material, texture and vertex colours. */
void cli_scene_phong(const cli_scene *s, const cli_scene_opts *o, const silk_view *view, silk_phong *p);
void cli_scene_free(cli_scene *s);

/* The camera for o and the loaded mesh: the options where given, the default
 * framing (docs/architecture.md, "Default camera") where not.  Returns 0 or
 * an exit code after printing the error. */
int cli_camera(const cli_scene_opts *o, const silk_mesh *m, silk_camera *cam);

/* The orbit about the target in o's model frame (--up-axis): the direction
 * from the target towards the eye at azimuth az (from the front towards the
 * right) and elevation el, in degrees; the angles of a direction d; the up
 * axis.  cli_camera places the default eye at az 30 + yaw, el 20 + pitch. */
void cli_orbit_dir(const cli_scene_opts *o, double az_deg, double el_deg, double d[3]);
void cli_orbit_angles(const cli_scene_opts *o, const double d[3], double *az_deg, double *el_deg);
void cli_up_axis(const cli_scene_opts *o, double up[3]);

/* Q16.16 to double, for printing; double to Q16.16, rounded to nearest
 * (the caller checks the range). */
double cli_fx_to_double(silk_fx v);
silk_fx cli_fx_from_double(double v);

/* The centre of the mesh's bounding box (into c) and the radius about it
 * that holds every vertex, 5% to spare; 1 for a mesh of one point. */
double cli_mesh_radius(const silk_mesh *m, double c[3]);

/* The head of every command's option loop.  cli_help: whether arg is
 * --help or -h, after printing help(stdout) (the command then exits 0).
 * cli_scene_arg: whether argv[*i] was a scene option of o (consumed; *rc
 * set to CLI_EXIT_USAGE when its value was bad).  cli_unknown_option: the
 * usage error for an option no one took. */
int cli_help(const char *arg, void (*help)(FILE *));
int cli_scene_arg(cli_scene_opts *o, int argc, char **argv, int *i, int *rc);
/* --texture FILE, --texture-format, --texture-filter, --texture-wrap into
 * o->look (for commands without the look options): 1 when argv[*i] was one
 * of them (*rc set to CLI_EXIT_USAGE when its value was bad), else 0. */
int cli_texture_arg(cli_scene_opts *o, int argc, char **argv, int *i, int *rc);
/* Those options as a command line gives them, for a header to record. */
void cli_texture_args_text(const cli_scene_opts *o, char *buf, size_t n);
int cli_unknown_option(const char *cmd, const char *arg);

/* An argument of `silk CMD` that no option took: the one mesh (*mesh_path),
 * or the usage error of an unknown option or a second mesh.  Returns 0 or
 * CLI_EXIT_USAGE. */
int cli_mesh_arg(const char *cmd, const char *arg, const char **mesh_path);

/* s as a JSON string, quoted and escaped. */
void cli_json_string(FILE *f, const char *s);

/* The name of an input for messages: path, or SILK_STDIN_NAME for "-". */
const char *cli_input_name(const char *path);

#endif
