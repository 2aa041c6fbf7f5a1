/*
 * scene_opts.c - the scene options every command that draws or loads a mesh
 * takes (cli_scene_opts, cli.h): loading, the camera, the frame, the mode,
 * the look and the texture, as one option table (opt.h).  A command takes
 * the parts it uses (CLI_OPT_*) and its parser refuses the others.
 */
#include <math.h>
#include <string.h>

#include "cli.h"
#include "opt.h"

void cli_scene_opts_default(cli_scene_opts *o)
{
    memset(o, 0, sizeof *o);
    silk_load_opts_default(&o->load);
    o->width = SILK_BOARD_WIDTH;
    o->height = SILK_BOARD_HEIGHT;
    o->fmt = SILK_BOARD_FORMAT;
    o->fov = CLI_DEFAULT_FOV;
    o->orient_note = 1;
    silk_render_opts_default(&o->render);
    /* The look as silk_phong_default has it; a field is used only when its
     * option was given (have_*), so a material's own values stay. */
    silk_phong ph;
    silk_phong_default(&ph, NULL);
    const silk_fx c[3] = { ph.mat.color.x, ph.mat.color.y, ph.mat.color.z };
    for (int k = 0; k < 3; k++) o->look.color = o->look.color << 8 | (uint32_t)lround(cli_fx_to_double(c[k]) * 255);
    o->look.ambient = cli_fx_to_double(ph.mat.ambient);
    o->look.specular = cli_fx_to_double(ph.mat.specular);
    o->look.shininess = ph.mat.shininess;
}

void cli_scene_defaults(void *base) { cli_scene_opts_default(base); }

/* What follows from the options once all are read. */
int cli_scene_finish(void *base)
{
    cli_scene_opts *o = base;
    o->vis_brute = o->render.visibility == SILK_VIS_BRUTE;
    /* the polygonal outline alone means lines over the shading */
    if (o->render.lines_polygonal && o->render.lines == SILK_LINES_NONE) o->render.lines = SILK_LINES_OVER;
    if (o->have_up && o->up[0] == 0 && o->up[1] == 0 && o->up[2] == 0)
        return cli_fail(CLI_EXIT_USAGE, "--up must not be the zero vector");
    return 0;
}

/* ---- values that are more than their kind ------------------------------------------- */

static int parse_fov(const cli_opt *r, const char *v, void *base)
{
    cli_scene_opts *o = base;
    if (cli_parse_double(r->name, v, r->lo, r->hi, &o->fov)) return -1;
    o->ortho = 0;   /* the last of --fov and --ortho counts */
    return 0;
}

static int parse_ortho(const cli_opt *r, const char *v, void *base)
{
    cli_scene_opts *o = base;
    o->ortho = 1;
    o->ortho_auto = strcmp(v, "auto") == 0;
    if (o->ortho_auto) return 0;
    if (cli_parse_double(r->name, v, 0, CLI_MAX_COORD, &o->ortho_half)) return -1;
    if (o->ortho_half < 1.0 / 256)
        return cli_fail(-1, "--ortho must be a positive half height of at least 1/256, or auto (got %s)", v);
    return 0;
}

static int parse_mode(const cli_opt *r, const char *v, void *base)
{
    (void)r;
    cli_scene_opts *o = base;
    uint32_t level;
    if (silk_mode_parse(v, &o->render.mode, &level) != 0)
        return cli_fail(-1, "--mode must be flat, smooth, pn, pnL (L 1..%u), blend, clip or siltex (got \"%s\")",
                        SILK_PN_MAX_LEVEL, v);
    if (level) o->render.level = level;
    return 0;
}

int cli_parse_bg(const cli_opt *r, const char *v, void *base)
{
    cli_scene_opts *o = base;
    o->bg_none = strcmp(v, "none") == 0;
    return o->bg_none ? 0 : cli_parse_rgb(r->name, v, &o->render.bg_rgb);
}

/* --light [point:]x,y,z[:RRGGBB], up to SILK_MAX_LIGHTS of them. */
static int parse_light(const cli_opt *r, const char *s, void *base)
{
    (void)r;
    cli_scene_opts *o = base;
    if (o->look.nlights == SILK_MAX_LIGHTS) return cli_fail(-1, "--light: at most %d lights", SILK_MAX_LIGHTS);
    cli_light *l = &o->look.light[o->look.nlights];
    char buf[256];
    if (strlen(s) >= sizeof buf) return cli_fail(-1, "--light is too long");
    strcpy(buf, s);
    char *p = buf, *colour;
    memset(l, 0, sizeof *l);
    l->rgb = 0xFFFFFF;
    if (strncmp(p, "point:", 6) == 0) {
        l->point = 1;
        p += 6;
    } else if (strncmp(p, "dir:", 4) == 0) {
        p += 4;
    }
    if ((colour = strchr(p, ':')) != NULL) {
        *colour++ = 0;
        if (cli_parse_rgb("--light", colour, &l->rgb)) return -1;
    }
    if (cli_parse_vec3("--light", p, CLI_MAX_COORD, l->v)) return -1;
    if (!l->point && l->v[0] == 0 && l->v[1] == 0 && l->v[2] == 0)
        return cli_fail(-1, "--light: a direction must not be 0,0,0 (got \"%s\")", s);
    o->look.nlights++;
    return 0;
}

/* ---- the table ------------------------------------------------------------------- */

#define F(member) CLI_FIELD(cli_scene_opts, member)
#define SEEN(member) CLI_SEEN(cli_scene_opts, member)
#define XSTR(x) STR(x)
#define STR(x) #x

static const int normals_v[] = { SILK_NORMALS_AUTO, SILK_NORMALS_COMPUTE, SILK_NORMALS_FILE };
static const int orient_v[] = { SILK_ORIENT_FIX, SILK_ORIENT_KEEP };
static const int vis_v[] = { SILK_VIS_AUTO, SILK_VIS_BRUTE, SILK_VIS_GAUSS };
static const int format_v[] = { SILK_PIX_RGB888, SILK_PIX_RGB565 };
static const int pn_v[] = { SILK_PN_QUADRATIC, SILK_PN_LINEAR };
static const int aa_v[] = { 1, 0, 2 };   /* outline: what a board built with SILK_AA_CREASES 0 draws */
static const int lines_v[] = { SILK_LINES_OVER, SILK_LINES_ONLY };
static const int texfmt_v[] = { SILK_TEX_RGB888, SILK_TEX_RGB565, SILK_TEX_PAL8 };
static const int filter_v[] = { SILK_TEX_BILINEAR, SILK_TEX_NEAREST };
static const int wrap_v[] = { SILK_TEX_REPEAT, SILK_TEX_CLAMP };

const cli_opt cli_scene_rows[] = {
    { .name = "--scale", .group = "Mesh loading (MESH - reads standard input; the format is told by the content)",
      .mask = CLI_OPT_LOAD, .kind = CLI_DECIMAL, .meta = "S", F(load.scale),
      .help = "multiply coordinates by S while reading (exact decimal; model coordinates must end up within "
              "+-1024)" },
    { .name = "--crease", .mask = CLI_OPT_LOAD, .kind = CLI_FX, .meta = "DEG", .lo = 0, .hi = 180, F(load.crease_deg),
      .help = "dihedral angle above which an edge is a sharp feature (%R, default %D)" },
    { .name = "--normals", .mask = CLI_OPT_LOAD, .kind = CLI_CHOICE, .choices = "auto|compute|file",
      .values = normals_v, F(load.normals),
      .help = "shading normals: auto (default) the file's where every corner has one, computed otherwise; compute "
              "always computed; file the same as auto" },
    { .name = "--orient", .mask = CLI_OPT_LOAD, .kind = CLI_CHOICE, .choices = "fix|keep", .values = orient_v,
      F(load.orient),
      .help = "fix (default): wind the triangles consistently and closed surfaces outward; keep: the file's "
              "winding" },
    { .name = "--visibility", .mask = CLI_OPT_LOAD, .kind = CLI_CHOICE, .choices = "auto|brute|gauss",
      .values = vis_v, F(render.visibility),
      .help = "visibility of normals: auto builds the Gaussian-sphere hierarchy at load and uses it where it pays "
              "(default); brute tests every normal; gauss always uses the hierarchy" },
    { .name = "--arena", .mask = CLI_OPT_LOAD, .kind = CLI_BYTES, .meta = "BYTES", F(arena_bytes),
      .help = "the one memory block silk may use (e.g. 512K, 64M); default: sized from the file and the image, "
              "grown if short" },
    { .name = "--quiet", .mask = CLI_OPT_LOAD, .kind = CLI_FLAG, F(quiet), .help = "no progress line on a terminal" },

    { .name = "--eye", .group = "Camera (default: the whole model, seen from front-right-above)",
      .mask = CLI_OPT_CAMERA, .kind = CLI_VEC3, .meta = "x,y,z", .hi = CLI_MAX_COORD, F(eye), SEEN(have_eye),
      .help = "eye position (default: placed so the model fits the view)" },
    { .name = "--target", .mask = CLI_OPT_CAMERA, .kind = CLI_VEC3, .meta = "x,y,z", .hi = CLI_MAX_COORD, F(target),
      SEEN(have_target), .help = "point looked at (default: centre of the bounding box)" },
    { .name = "--up", .mask = CLI_OPT_CAMERA, .kind = CLI_VEC3, .meta = "x,y,z", .hi = CLI_MAX_COORD, F(up),
      SEEN(have_up), .help = "up direction (default: the up axis)" },
    { .name = "--up-axis", .mask = CLI_OPT_CAMERA, .kind = CLI_CHOICE, .choices = "y|z", F(up_axis_z),
      .help = "the model's up axis (default y; z for Z-up exports, whose front is then -y)" },
    { .name = "--yaw", .mask = CLI_OPT_CAMERA, .kind = CLI_REAL, .meta = "DEG", .lo = -360, .hi = 360, F(yaw),
      .help = "orbit the eye DEG degrees (%R) about the up axis through the target, to the viewer's right (the "
              "model turns left)" },
    { .name = "--pitch", .mask = CLI_OPT_CAMERA, .kind = CLI_REAL, .meta = "DEG", .lo = -90, .hi = 90, F(pitch),
      .help = "orbit the eye DEG degrees up (%R; the elevation stops at straight above or below)" },
    { .name = "--fov", .mask = CLI_OPT_CAMERA, .kind = CLI_REAL, .meta = "DEG", .lo = SILK_FOV_MIN / 65536.0,
      .hi = SILK_FOV_MAX / 65536.0, F(fov), .parse = parse_fov,
      .help = "perspective, vertical field of view (%R, default %D)" },
    { .name = "--ortho", .mask = CLI_OPT_CAMERA, .kind = CLI_CUSTOM, .meta = "H|auto", .parse = parse_ortho,
      .help = "orthographic, H = half the view height in model units; auto fits the model" },

    { .name = "--size", .group = "Frame", .mask = CLI_OPT_FRAME, .kind = CLI_SIZE, .meta = "WxH", .lo = 1,
      .hi = CLI_MAX_SIDE, F(width), .off2 = offsetof(cli_scene_opts, height),
      .help = "image size in pixels, %R each (default %D)" },
    { .name = "--format", .mask = CLI_OPT_FRAME, .kind = CLI_CHOICE, .choices = "rgb888|rgb565", .values = format_v,
      F(fmt), .help = "pixel format silk renders in (default %D)" },

    { .name = "--mode", .group = "Mode (docs/methods.md)", .mask = CLI_OPT_MODE, .kind = CLI_CUSTOM,
      .meta = "flat|smooth|pn|pnL|blend|clip|siltex", .parse = parse_mode,
      .help = "the coarse mesh as it is, smoothed silhouettes (default), PN triangles (pnL: at level L), "
              "silhouetteness blending (Dyken & Reimers), or a prepared model's outer hull drawn through the "
              "detailed model's silhouette map (clip) or silhouette texture (siltex)" },
    { .name = "--tolerance", .mask = CLI_OPT_MODE, .kind = CLI_FX, .meta = "PX", .lo = 0.25, .hi = 4,
      F(render.tolerance_px), .help = "smooth and blend: silhouette sampling tolerance in pixels (%R, default %D)" },
    { .name = "--level", .mask = CLI_OPT_MODE, .kind = CLI_INT, .meta = "L", .lo = 1, .hi = SILK_PN_MAX_LEVEL,
      F(render.level), .help = "pn: segments per triangle side (%R, default %D)" },
    { .name = "--pn-normals", .mask = CLI_OPT_MODE, .kind = CLI_CHOICE, .choices = "quadratic|linear",
      .values = pn_v, F(render.pn_normals), .help = "pn: normal patch (default %D)" },
    { .name = "--beta", .mask = CLI_OPT_MODE, .kind = CLI_FX, .meta = "B", .lo = 0, .hi = 1, F(render.blend_beta),
      .help = "blend: silhouetteness transition (%R, default %D)" },

    { .name = "--bg", .group = "Look (docs/viewer.md, \"Material and light\")", .mask = CLI_OPT_LOOK,
      .kind = CLI_RGB, .meta = "RRGGBB|none", F(render.bg_rgb), .parse = cli_parse_bg,
      .help = "background colour in hex (default %D); none: a PNG with alpha: the object's coverage of each pixel" },
    { .name = "--aa", .mask = CLI_OPT_LOOK, .kind = CLI_CHOICE, .choices = "on|off|outline", .values = aa_v,
      F(render.aa),
      .help = "anti-aliased outlines (flat, smooth, clip and siltex without lines) and creases (flat and smooth; "
              "outline: the outlines only; default %D)" },
    { .name = "--wire", .mask = CLI_OPT_LOOK, .kind = CLI_FLAG, F(render.wire),
      .help = "draw the edges; triangles added by smoothing in red" },
    { .name = "--lines", .mask = CLI_OPT_LOOK, .kind = CLI_CHOICE, .choices = "over|only", .values = lines_v,
      F(render.lines),
      .help = "pen-and-ink outlines over the shading or alone: the smoothed silhouette and visible feature curves "
              "(smooth), the mesh's silhouette and feature edges (flat), the texture's silhouettes, interior ones "
              "too (siltex)" },
    { .name = "--lines-polygonal", .mask = CLI_OPT_LOOK, .kind = CLI_FLAG, F(render.lines_polygonal),
      .help = "the coarse mesh's silhouette and feature edges in any mode but clip (pn and blend draw lines only "
              "so; alone: --lines over)" },
    { .name = "--color", .mask = CLI_OPT_LOOK, .kind = CLI_RGB, .meta = "RRGGBB", F(look.color),
      SEEN(look.have_color), .help = "the object's colour (default %D)" },
    { .name = "--ambient", .mask = CLI_OPT_LOOK, .kind = CLI_REAL, .meta = "A", .lo = 0, .hi = 1, F(look.ambient),
      SEEN(look.have_ambient), .help = "light everywhere (%R, default %D)" },
    { .name = "--specular", .mask = CLI_OPT_LOOK, .kind = CLI_REAL, .meta = "S", .lo = 0, .hi = 1,
      F(look.specular), SEEN(look.have_specular), .help = "strength of the highlights (%R, default %D)" },
    { .name = "--shininess", .mask = CLI_OPT_LOOK, .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 256,
      F(look.shininess), SEEN(look.have_shininess), .help = "sharpness of the highlights (%R, default %D)" },
    { .name = "--light", .mask = CLI_OPT_LOOK, .kind = CLI_CUSTOM, .meta = "[point:]x,y,z[:RRGGBB]",
      .parse = parse_light,
      .help = "a white (or RRGGBB) light instead of the default two: directional from direction x,y,z (model "
              "axes, towards the light), or with point: at position x,y,z; repeat for up to "
              XSTR(SILK_MAX_LIGHTS) " lights" },

    { .name = "--texture", .group = "Texture (docs/formats.md)", .mask = CLI_OPT_TEXTURE, .kind = CLI_TEXT,
      .meta = "FILE.png", F(look.texture_path),
      .help = "map the image over the mesh's texture coordinates (an OBJ's material texture, map_Kd, is used "
              "without it); --texture checker[:N]: a built-in N-by-N (256) image of 8-by-8 squares" },
    { .name = "--texture-format", .mask = CLI_OPT_TEXTURE, .kind = CLI_CHOICE, .choices = "rgb888|rgb565|pal8",
      .values = texfmt_v, F(look.texture.format),
      .help = "how the texels are stored (%D; pal8: the image's colours if it has at most 256, else a fixed "
              "palette of 252)" },
    { .name = "--texture-filter", .mask = CLI_OPT_TEXTURE, .kind = CLI_CHOICE, .choices = "bilinear|nearest",
      .values = filter_v, F(look.texture.filter),
      .help = "within a mipmap level and between levels (bilinear), or the nearest texel of the nearest level" },
    { .name = "--texture-wrap", .mask = CLI_OPT_TEXTURE, .kind = CLI_CHOICE, .choices = "repeat|clamp",
      .values = wrap_v, F(look.texture.wrap), .help = "beyond the texture's edges (%D)" },
    { .name = NULL },
};

void cli_texture_args_text(const cli_scene_opts *o, char *buf, size_t n)
{
    const cli_texture_opts *t = &o->look.texture;
    static const char *const fmt[] = { "", " --texture-format rgb565", " --texture-format pal8" };
    snprintf(buf, n, "--texture %s%s%s%s", o->look.texture_path ? o->look.texture_path : "",
             (unsigned)t->format < 3 ? fmt[t->format] : "", t->filter == SILK_TEX_NEAREST ? " --texture-filter nearest" : "",
             t->wrap == SILK_TEX_CLAMP ? " --texture-wrap clamp" : "");
}
