/*
 * cli.c - option parsing and scene setup shared by `silk render` and
 * `silk info`: strict number parsing with range checks, the load and camera
 * options, the arena sized from the file, and the default camera that frames
 * the model (a 3/4 view from front-right-above; see cli_camera).
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "progress.h"
#include "platform/platform.h"

int cli_fail(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("silk: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

/* ---- numbers ------------------------------------------------------------------ */

/* strtod accepts leading blanks, hex floats, "inf" and "nan"; a command line
 * number may only be decimal: [+-] digits [. digits] [e [+-] digits]. */
static int plain_decimal(const char *s)
{
    if (*s == '+' || *s == '-') s++;
    if (!isdigit((unsigned char)*s) && !(*s == '.' && isdigit((unsigned char)s[1]))) return 0;
    for (; *s; s++)
        if (!isdigit((unsigned char)*s) && !strchr(".eE+-", *s)) return 0;
    return 1;
}

static int parse_double(const char *s, const char **end, double *out)
{
    char *e;
    errno = 0;
    double v = strtod(s, &e);
    if (e == s || errno == ERANGE || !isfinite(v)) return -1;
    *out = v;
    *end = e;
    return 0;
}

int cli_parse_double(const char *opt, const char *s, double lo, double hi, double *out)
{
    const char *end;
    double v;
    if (!plain_decimal(s) || parse_double(s, &end, &v) != 0 || *end)
        return cli_fail(-1, "%s: \"%s\" is not a number", opt, s);
    if (!(v >= lo && v <= hi)) return cli_fail(-1, "%s must be between %g and %g (got %s)", opt, lo, hi, s);
    *out = v;
    return 0;
}

int cli_parse_long(const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    const char *d = (*s == '-' || *s == '+') ? s + 1 : s;
    long v = strtol(s, &end, 10);
    if (!isdigit((unsigned char)*d) || *end) return cli_fail(-1, "%s: \"%s\" is not an integer", opt, s);
    if (errno == ERANGE || v < lo || v > hi)
        return cli_fail(-1, "%s must be between %ld and %ld (got %s)", opt, lo, hi, s);
    *out = v;
    return 0;
}

int cli_parse_vec3(const char *opt, const char *s, double lim, double out[3])
{
    char buf[256];
    if (strlen(s) >= sizeof buf) return cli_fail(-1, "%s must be x,y,z (three numbers)", opt);
    strcpy(buf, s);
    char *p = buf;
    for (int k = 0; k < 3; k++) {
        char *comma = strchr(p, ',');
        if ((k < 2) != (comma != NULL)) return cli_fail(-1, "%s must be x,y,z (three numbers), got \"%s\"", opt, s);
        if (comma) *comma = 0;
        const char *end;
        if (!plain_decimal(p) || parse_double(p, &end, &out[k]) != 0 || *end)
            return cli_fail(-1, "%s must be x,y,z (three numbers), got \"%s\"", opt, s);
        if (fabs(out[k]) > lim) return cli_fail(-1, "%s: coordinates must be within +-%g (got %s)", opt, lim, s);
        p = comma ? comma + 1 : p;
    }
    return 0;
}

int cli_parse_size(const char *opt, const char *s, int *w, int *h)
{
    char *x, *end;
    if (!isdigit((unsigned char)*s)) goto bad;
    errno = 0;
    long a = strtol(s, &x, 10);
    if ((*x != 'x' && *x != 'X') || !isdigit((unsigned char)x[1])) goto bad;
    long b = strtol(x + 1, &end, 10);
    if (*end || errno == ERANGE) goto bad;
    if (a < 1 || b < 1 || a > CLI_MAX_SIDE || b > CLI_MAX_SIDE)
        return cli_fail(-1, "%s: width and height must be 1 to %d pixels (got %s)", opt, CLI_MAX_SIDE, s);
    *w = (int)a;
    *h = (int)b;
    return 0;
bad:
    return cli_fail(-1, "%s must be WIDTHxHEIGHT, e.g. 640x480 (got \"%s\")", opt, s);
}

int cli_parse_rgb(const char *opt, const char *s, uint32_t *rgb)
{
    const char *p = s;
    if (*p == '#') p++;
    else if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) p += 2;
    uint32_t v = 0;
    int n = 0;
    for (; isxdigit((unsigned char)*p); p++, n++) {
        int c = tolower((unsigned char)*p);
        v = v * 16 + (uint32_t)(isdigit(c) ? c - '0' : c - 'a' + 10);
    }
    if (*p || n != 6) return cli_fail(-1, "%s must be a colour RRGGBB in hex, e.g. ffffff (got \"%s\")", opt, s);
    *rgb = v;
    return 0;
}

int cli_parse_bytes(const char *opt, const char *s, size_t *out)
{
    char *end;
    if (!isdigit((unsigned char)*s)) goto bad;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    unsigned long long mul = 1;
    switch (*end) {
    case 'k': case 'K': mul = 1ull << 10; end++; break;
    case 'm': case 'M': mul = 1ull << 20; end++; break;
    case 'g': case 'G': mul = 1ull << 30; end++; break;
    default: break;
    }
    if (*end || errno == ERANGE) goto bad;
    const unsigned long long lo = 4096, hi = 1ull << 32;   /* 4 KiB .. 4 GiB */
    if (v > hi / mul || v * mul < lo || v * mul > hi || v * mul > (unsigned long long)SIZE_MAX)
        return cli_fail(-1, "%s must be between 4K and 4G bytes (got %s)", opt, s);
    *out = (size_t)(v * mul);
    return 0;
bad:
    return cli_fail(-1, "%s must be a byte count such as 65536, 512K or 64M (got \"%s\")", opt, s);
}

/* ---- arguments ------------------------------------------------------------------ */

int cli_is(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == 0 || (arg[n] == '=' && name[0] == '-'));
}

const char *cli_value(int argc, char **argv, int *i)
{
    const char *arg = argv[*i];
    const char *eq = strchr(arg, '=');
    if (arg[0] == '-' && eq) return eq + 1;
    if (*i + 1 >= argc) {
        cli_fail(-1, "%s needs a value", arg);
        return NULL;
    }
    return argv[++*i];
}

int cli_parse_choice(const char *opt, const char *s, const char *a, const char *b, int *out)
{
    *out = strcmp(s, b) == 0;
    if (*out || strcmp(s, a) == 0) return 0;
    return cli_fail(-1, "%s must be %s or %s (got \"%s\")", opt, a, b, s);
}

int cli_help(const char *arg, void (*help)(FILE *))
{
    if (strcmp(arg, "--help") != 0 && strcmp(arg, "-h") != 0) return 0;
    help(stdout);
    return 1;
}

int cli_scene_arg(cli_scene_opts *o, int argc, char **argv, int *i, int *rc)
{
    int r = cli_scene_option(o, argc, argv, i);
    if (r < 0) *rc = CLI_EXIT_USAGE;
    return r != 0;
}

int cli_unknown_option(const char *cmd, const char *arg)
{
    return cli_fail(CLI_EXIT_USAGE, "%s: unknown option %s (try silk %s --help)", cmd, arg, cmd);
}

int cli_mesh_arg(const char *cmd, const char *arg, const char **mesh_path)
{
    if (arg[0] == '-' && arg[1]) return cli_unknown_option(cmd, arg);
    if (*mesh_path) return cli_fail(CLI_EXIT_USAGE, "%s: one mesh at a time (got %s and %s)", cmd, *mesh_path, arg);
    *mesh_path = arg;
    return 0;
}

void cli_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(f, "\\%c", *p);
        else if (*p < 0x20) fprintf(f, "\\u%04x", *p);
        else fputc(*p, f);
    }
    fputc('"', f);
}

const char *cli_input_name(const char *path)
{
    return silk_path_is_stdio(path) ? SILK_STDIN_NAME : path;
}

int cli_parse_modes(const char *opt, const char *list, cli_mode *out, int max, int *n)
{
    *n = 0;
    for (const char *p = list;;) {
        size_t len = strcspn(p, ",");
        cli_mode *m = &out[*n];
        if (*n == max) return cli_fail(-1, "%s: at most %d modes (got \"%s\")", opt, max, list);
        if (len == 0 || len >= sizeof m->name) goto bad;
        memcpy(m->name, p, len);
        m->name[len] = 0;
        /* "MODE-noaa": the mode without anti-aliased outlines */
        static const char noaa[] = "-noaa";
        size_t base = len;
        m->aa_off = len > strlen(noaa) && strcmp(m->name + len - strlen(noaa), noaa) == 0;
        if (m->aa_off) base -= strlen(noaa);
        char mode_name[sizeof m->name];
        memcpy(mode_name, m->name, base);
        mode_name[base] = 0;
        if (silk_mode_parse(mode_name, &m->mode, &m->level) != 0) goto bad;
        for (int k = 0; k < *n; k++)
            if (strcmp(out[k].name, m->name) == 0) return cli_fail(-1, "%s: %s is listed twice", opt, m->name);
        ++*n;
        if (!p[len]) return 0;
        p += len + 1;
        continue;
    bad:
        return cli_fail(-1, "%s: \"%.*s\" is not a mode: list flat, smooth, blend, pn, pnL (L 1..%u), clip or siltex "
                        "separated "
                        "by commas (MODE-noaa: without anti-aliasing)", opt, (int)len, p, SILK_PN_MAX_LEVEL);
    }
}

/* The option's name without "=value", for messages. */
static const char *opt_name(const char *arg, char *buf, size_t n)
{
    size_t k = strcspn(arg, "=");
    if (k >= n) k = n - 1;
    memcpy(buf, arg, k);
    buf[k] = 0;
    return buf;
}

/* ---- scene options ------------------------------------------------------------- */

void cli_scene_opts_default(cli_scene_opts *o)
{
    memset(o, 0, sizeof *o);
    silk_load_opts_default(&o->load);
    o->width = SILK_BOARD_WIDTH;
    o->height = SILK_BOARD_HEIGHT;
    o->fmt = SILK_BOARD_FORMAT;
    o->fov = CLI_DEFAULT_FOV;
    o->groups = CLI_OPT_ALL;
    o->orient_note = 1;
    silk_render_opts_default(&o->render);
}

/* Which group each scene option belongs to; a command takes only the groups
 * in its cli_scene_opts.groups, so an option it would ignore is refused.
 * Options not listed here are load options, taken by every command. */
static const struct {
    const char *name;
    unsigned group;
} option_group[] = {
    { "--eye", CLI_OPT_CAMERA },          { "--target", CLI_OPT_CAMERA },     { "--up", CLI_OPT_CAMERA },
    { "--fov", CLI_OPT_CAMERA },          { "--ortho", CLI_OPT_CAMERA },      { "--yaw", CLI_OPT_CAMERA },
    { "--pitch", CLI_OPT_CAMERA },        { "--up-axis", CLI_OPT_CAMERA },    { "--size", CLI_OPT_FRAME },
    { "--format", CLI_OPT_FRAME },        { "--mode", CLI_OPT_MODE },         { "--tolerance", CLI_OPT_MODE },
    { "--level", CLI_OPT_MODE },          { "--pn-normals", CLI_OPT_MODE },   { "--beta", CLI_OPT_MODE },
    { "--bg", CLI_OPT_LOOK },             { "--wire", CLI_OPT_LOOK },         { "--lines", CLI_OPT_LOOK },
    { "--lines-polygonal", CLI_OPT_LOOK }, { "--color", CLI_OPT_LOOK },       { "--ambient", CLI_OPT_LOOK },
    { "--specular", CLI_OPT_LOOK },       { "--shininess", CLI_OPT_LOOK },    { "--light", CLI_OPT_LOOK },
    { "--aa", CLI_OPT_LOOK },
    { "--texture", CLI_OPT_LOOK },        { "--texture-format", CLI_OPT_LOOK }, { "--texture-filter", CLI_OPT_LOOK },
    { "--texture-wrap", CLI_OPT_LOOK },
};

static unsigned group_of(const char *arg)
{
    size_t n = strcspn(arg, "=");
    for (size_t i = 0; i < sizeof option_group / sizeof option_group[0]; i++)
        if (strlen(option_group[i].name) == n && strncmp(arg, option_group[i].name, n) == 0)
            return option_group[i].group;
    return CLI_OPT_LOAD;
}

/* A material colour (components in [0, 1]) as 0xRRGGBB. */
static uint32_t v3_to_rgb(silk_vec3 c)
{
    silk_fx v[3] = { c.x, c.y, c.z };
    uint32_t rgb = 0;
    for (int k = 0; k < 3; k++) rgb = rgb << 8 | (uint32_t)lround(cli_fx_to_double(v[k]) * 255);
    return rgb;
}

void cli_print_scene_help(FILE *f, unsigned groups)
{
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    silk_phong ph;
    silk_phong_default(&ph, NULL);
    if (groups & CLI_OPT_LOAD)
        fprintf(f,
            "\n"
            "Mesh loading (MESH - reads standard input; the format is told by the content):\n"
            "  --scale S            multiply coordinates by S while reading (exact decimal;\n"
            "                       model coordinates must end up within +-1024)\n"
            "  --crease DEG         dihedral angle above which an edge is a sharp feature\n"
            "                       (0..180, default %g)\n"
            "  --normals auto|compute|file  shading normals: auto (default) the file's\n"
            "                       where every corner has one, computed otherwise;\n"
            "                       compute always computed; file the same as auto\n"
            "  --orient fix|keep    fix (default): wind the triangles consistently and\n"
            "                       closed surfaces outward; keep: the file's winding\n"
            "  --visibility auto|brute|gauss  visibility of normals: auto builds the\n"
            "                       Gaussian-sphere hierarchy at load and uses it where it\n"
            "                       pays (default); brute tests every normal; gauss always\n"
            "                       uses the hierarchy\n"
            "  --arena BYTES        the one memory block silk may use (e.g. 512K, 64M);\n"
            "                       default: sized from the file and the image, grown if short\n"
            "  --quiet              no progress line on a terminal\n",
            cli_fx_to_double(SILK_DEFAULT_CREASE_DEG));
    if (groups & CLI_OPT_CAMERA)
        fprintf(f,
            "Camera (default: the whole model, seen from front-right-above):\n"
            "  --eye x,y,z          eye position (default: placed so the model fits the view)\n"
            "  --target x,y,z       point looked at (default: centre of the bounding box)\n"
            "  --up x,y,z           up direction (default: the up axis)\n"
            "  --up-axis y|z        the model's up axis (default y; z for Z-up exports, whose\n"
            "                       front is then -y)\n"
            "  --yaw DEG            orbit the eye DEG degrees about the up axis through the\n"
            "                       target, to the viewer's right (the model turns left)\n"
            "  --pitch DEG          orbit the eye DEG degrees up (-90..90; the elevation stops\n"
            "                       at straight above or below)\n"
            "  --fov DEG            perspective, vertical field of view (%g..%g, default %g)\n"
            "  --ortho H|auto       orthographic, H = half the view height in model units;\n"
            "                       auto fits the model\n",
            cli_fx_to_double(SILK_FOV_MIN), cli_fx_to_double(SILK_FOV_MAX), CLI_DEFAULT_FOV);
    if (groups & (CLI_OPT_FRAME | CLI_OPT_MODE)) fprintf(f, "Frame:\n");
    if (groups & CLI_OPT_FRAME)
        fprintf(f,
            "  --size WxH           image size in pixels, 1..%d each (default %dx%d)\n"
            "  --format rgb888|rgb565  pixel format silk renders in (default %s)\n",
            CLI_MAX_SIDE, SILK_BOARD_WIDTH, SILK_BOARD_HEIGHT,
            SILK_BOARD_FORMAT == SILK_PIX_RGB565 ? "rgb565" : "rgb888");
    if (groups & CLI_OPT_MODE)
        fprintf(f,
            "  --mode flat|smooth|pn|pnL|blend  coarse mesh as it is, smoothed silhouettes\n"
            "                       (default), PN triangles (pnL: at level L), or\n"
            "                       silhouetteness blending (Dyken & Reimers); docs/methods.md\n"
            "  --tolerance PX       silhouette sampling tolerance in pixels, 0.25..4 (%g)\n"
            "  --level L            pn: segments per triangle side, 1..%u (default %u)\n"
            "  --pn-normals quadratic|linear  pn: normal patch (default quadratic)\n"
            "  --beta B             blend: silhouetteness transition, 0..1 (default %g)\n",
            cli_fx_to_double(ro.tolerance_px), SILK_PN_MAX_LEVEL, (unsigned)ro.level, cli_fx_to_double(ro.blend_beta));
    if (groups & CLI_OPT_LOOK)
        fprintf(f,
            "Look (docs/viewer.md, \"Material and light\"):\n"
            "  --bg RRGGBB|none     background colour in hex (default %06x); none: a PNG\n"
            "                       with alpha: the object's coverage of each pixel\n"
            "  --aa on|off|outline  anti-aliased outlines (flat, smooth, clip and siltex\n"
            "                       without lines) and creases (flat and smooth;\n"
            "                       outline: the outlines only) (default on)\n"
            "  --wire               draw the edges; triangles added by smoothing in red\n"
            "  --lines over|only    pen-and-ink outlines over the shading or alone: the\n"
            "                       smoothed silhouette and visible feature curves (smooth),\n"
            "                       the mesh's silhouette and feature edges (flat), the\n"
            "                       texture's silhouettes, interior ones too (siltex)\n"
            "  --lines-polygonal    the coarse mesh's silhouette and feature edges in any\n"
            "                       mode (pn and blend draw lines only so; alone: --lines over)\n"
            "  --color RRGGBB       the object's colour (default %06x)\n"
            "  --ambient A          light everywhere, 0..1 (default %.2f)\n"
            "  --specular S         strength of the highlights, 0..1 (default %.2f)\n"
            "  --shininess N        sharpness of the highlights, 1..256 (default %d)\n"
            "  --light [point:]x,y,z[:RRGGBB]  a white (or RRGGBB) light instead of the\n"
            "                       default two: directional from direction x,y,z (model\n"
            "                       axes, towards the light), or with point: at position\n"
            "                       x,y,z; repeat for up to %d lights\n"
            "  --texture FILE.png   map the image over the mesh's texture coordinates (an\n"
            "                       OBJ's material texture, map_Kd, is used without it);\n"
            "                       --texture checker[:N]: a built-in N x N (256) image of\n"
            "                       8 x 8 squares\n"
            "  --texture-format rgb888|rgb565|pal8   how the texels are stored (rgb888;\n"
            "                       pal8: the image's colours if it has at most 256, else a\n"
            "                       fixed palette of 252)\n"
            "  --texture-filter bilinear|nearest  within a mipmap level and between\n"
            "                       levels (bilinear), or the nearest texel of the nearest\n"
            "                       level\n"
            "  --texture-wrap repeat|clamp   beyond the texture's edges (repeat)\n",
            (unsigned)ro.bg_rgb, (unsigned)v3_to_rgb(ph.mat.color), cli_fx_to_double(ph.mat.ambient),
            cli_fx_to_double(ph.mat.specular), ph.mat.shininess, SILK_MAX_LIGHTS);
}

static int parse_fx(const char *opt, const char *s, double lo, double hi, silk_fx *out)
{
    double v;
    if (cli_parse_double(opt, s, lo, hi, &v) != 0) return -1;
    *out = cli_fx_from_double(v);
    return 0;
}

/* --light [point:]x,y,z[:RRGGBB] */
static int parse_light(const char *s, cli_light *l)
{
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
    return 0;
}

/* The texture options: 1 when arg is one (r: 0, -1 after a bad value's
 * message, -2 without a value), else 0. */
static int texture_option(cli_scene_opts *o, const char *arg, const char *opt, int argc, char **argv, int *i, int *r)
{
    static const char *const opts[] = { "--texture", "--texture-format", "--texture-filter", "--texture-wrap" };
    int k = 0, c;
    while (k < 4 && !cli_is(arg, opts[k])) k++;
    if (k == 4) return 0;
    const char *v = cli_value(argc, argv, i);
    if (!v) {
        *r = -2;
        return 1;
    }
    cli_texture_opts *t = &o->look.texture;
    *r = 0;
    if (k == 0) {
        o->look.texture_path = v;
    } else if (k == 1) {
        if (strcmp(v, "rgb888") == 0) t->format = SILK_TEX_RGB888;
        else if (strcmp(v, "rgb565") == 0) t->format = SILK_TEX_RGB565;
        else if (strcmp(v, "pal8") == 0) t->format = SILK_TEX_PAL8;
        else *r = cli_fail(-1, "%s must be rgb888, rgb565 or pal8 (got \"%s\")", opt, v);
    } else if (k == 2) {
        if (!(*r = cli_parse_choice(opt, v, "bilinear", "nearest", &c))) t->filter = c ? SILK_TEX_NEAREST : SILK_TEX_BILINEAR;
    } else if (!(*r = cli_parse_choice(opt, v, "repeat", "clamp", &c))) {
        t->wrap = c ? SILK_TEX_CLAMP : SILK_TEX_REPEAT;
    }
    return 1;
}

int cli_texture_arg(cli_scene_opts *o, int argc, char **argv, int *i, int *rc)
{
    char name[40];
    int r = 0;
    const char *arg = argv[*i];
    if (!texture_option(o, arg, opt_name(arg, name, sizeof name), argc, argv, i, &r)) return 0;
    if (r) *rc = CLI_EXIT_USAGE;
    return 1;
}

void cli_texture_args_text(const cli_scene_opts *o, char *buf, size_t n)
{
    const cli_texture_opts *t = &o->look.texture;
    static const char *const fmt[] = { "", " --texture-format rgb565", " --texture-format pal8" };
    snprintf(buf, n, "--texture %s%s%s%s", o->look.texture_path ? o->look.texture_path : "",
             (unsigned)t->format < 3 ? fmt[t->format] : "", t->filter == SILK_TEX_NEAREST ? " --texture-filter nearest" : "",
             t->wrap == SILK_TEX_CLAMP ? " --texture-wrap clamp" : "");
}

int cli_scene_option(cli_scene_opts *o, int argc, char **argv, int *i)
{
    char name[40];
    const char *arg = argv[*i], *opt = opt_name(arg, name, sizeof name), *v;
    int r = 0, c;
    if (!(group_of(arg) & o->groups)) return 0;   /* not this command's: it says "unknown option" */
#define VALUE() do { if (!(v = cli_value(argc, argv, i))) return -1; } while (0)
    if (cli_is(arg, "--quiet")) {
        o->quiet = 1;
    } else if (cli_is(arg, "--scale")) {
        VALUE();
        const char *end;
        silk_decimal d;
        int pr = plain_decimal(v) ? silk_decimal_parse(v, &end, &d) : -1;
        if (pr != 0 || *end || d.mant <= 0)
            return cli_fail(-1, "--scale must be a positive decimal number, e.g. 0.01 (got \"%s\")", v);
        o->load.scale = d;
    } else if (cli_is(arg, "--crease")) {
        VALUE();
        r = parse_fx(opt, v, 0, 180, &o->load.crease_deg);
    } else if (cli_is(arg, "--normals")) {
        VALUE();
        if (strcmp(v, "auto") == 0) o->load.normals = SILK_NORMALS_AUTO;
        else if (strcmp(v, "compute") == 0) o->load.normals = SILK_NORMALS_COMPUTE;
        else if (strcmp(v, "file") == 0) o->load.normals = SILK_NORMALS_FILE;
        else r = cli_fail(-1, "%s must be auto, compute or file (got \"%s\")", opt, v);
    } else if (cli_is(arg, "--orient")) {
        VALUE();
        if (!(r = cli_parse_choice(opt, v, "fix", "keep", &c))) o->load.orient = c ? SILK_ORIENT_KEEP : SILK_ORIENT_FIX;
    } else if (cli_is(arg, "--visibility")) {
        VALUE();
        if (strcmp(v, "auto") == 0) o->vis_brute = 0, o->render.visibility = SILK_VIS_AUTO;
        else if (strcmp(v, "brute") == 0) o->vis_brute = 1, o->render.visibility = SILK_VIS_BRUTE;
        else if (strcmp(v, "gauss") == 0) o->vis_brute = 0, o->render.visibility = SILK_VIS_GAUSS;
        else return cli_fail(-1, "--visibility must be auto, brute or gauss (got \"%s\")", v);
    } else if (cli_is(arg, "--arena")) {
        VALUE();
        r = cli_parse_bytes(opt, v, &o->arena_bytes);
    } else if (cli_is(arg, "--eye")) {
        VALUE();
        r = cli_parse_vec3(opt, v, CLI_MAX_COORD, o->eye);
        o->have_eye = 1;
    } else if (cli_is(arg, "--target")) {
        VALUE();
        r = cli_parse_vec3(opt, v, CLI_MAX_COORD, o->target);
        o->have_target = 1;
    } else if (cli_is(arg, "--up")) {
        VALUE();
        r = cli_parse_vec3(opt, v, CLI_MAX_COORD, o->up);
        if (!r && o->up[0] == 0 && o->up[1] == 0 && o->up[2] == 0)
            return cli_fail(-1, "--up must not be the zero vector");
        o->have_up = 1;
    } else if (cli_is(arg, "--fov")) {
        VALUE();
        r = cli_parse_double(opt, v, cli_fx_to_double(SILK_FOV_MIN), cli_fx_to_double(SILK_FOV_MAX), &o->fov);
        o->ortho = 0;
    } else if (cli_is(arg, "--ortho")) {
        VALUE();
        o->ortho = 1;
        o->ortho_auto = strcmp(v, "auto") == 0;
        if (!o->ortho_auto) {
            r = cli_parse_double(opt, v, 0, CLI_MAX_COORD, &o->ortho_half);
            if (!r && o->ortho_half < 1.0 / 256)
                return cli_fail(-1, "--ortho must be a positive half height of at least 1/256, or auto (got %s)", v);
        }
    } else if (cli_is(arg, "--size")) {
        VALUE();
        r = cli_parse_size(opt, v, &o->width, &o->height);
    } else if (cli_is(arg, "--format")) {
        VALUE();
        if (!(r = cli_parse_choice(opt, v, "rgb888", "rgb565", &c))) o->fmt = c ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
    } else if (cli_is(arg, "--mode")) {
        VALUE();
        uint32_t level;
        if (silk_mode_parse(v, &o->render.mode, &level) != 0)
            return cli_fail(-1, "--mode must be flat, smooth, pn, pnL (L 1..%u), blend, clip or siltex (got \"%s\")",
                            SILK_PN_MAX_LEVEL, v);
        if (level) o->render.level = level;
    } else if (cli_is(arg, "--level")) {
        VALUE();
        long l;
        r = cli_parse_long(opt, v, 1, SILK_PN_MAX_LEVEL, &l);
        if (!r) o->render.level = (uint32_t)l;
    } else if (cli_is(arg, "--pn-normals")) {
        VALUE();
        if (!(r = cli_parse_choice(opt, v, "quadratic", "linear", &c)))
            o->render.pn_normals = c ? SILK_PN_LINEAR : SILK_PN_QUADRATIC;
    } else if (cli_is(arg, "--beta")) {
        VALUE();
        r = parse_fx(opt, v, 0, 1, &o->render.blend_beta);
    } else if (cli_is(arg, "--tolerance")) {
        VALUE();
        r = parse_fx(opt, v, 0.25, 4, &o->render.tolerance_px);
    } else if (cli_is(arg, "--bg")) {
        VALUE();
        o->bg_none = strcmp(v, "none") == 0;
        if (!o->bg_none) r = cli_parse_rgb(opt, v, &o->render.bg_rgb);
    } else if (cli_is(arg, "--aa")) {
        VALUE();
        if (strcmp(v, "outline") == 0) o->render.aa = 2;   /* what a board built with -DSILK_NO_AA_CREASE draws */
        else if (strcmp(v, "on") == 0 || strcmp(v, "off") == 0) o->render.aa = strcmp(v, "on") == 0;
        else r = cli_fail(-1, "%s must be on, off or outline (got \"%s\")", opt, v);
    } else if (strcmp(arg, "--wire") == 0) {
        o->render.wire = 1;
    } else if (cli_is(arg, "--lines")) {
        VALUE();
        if (!(r = cli_parse_choice(opt, v, "over", "only", &c))) o->render.lines = c ? SILK_LINES_ONLY : SILK_LINES_OVER;
    } else if (strcmp(arg, "--lines-polygonal") == 0) {
        o->render.lines_polygonal = 1;
        if (!o->render.lines) o->render.lines = SILK_LINES_OVER;
    } else if (cli_is(arg, "--yaw")) {
        VALUE();
        r = cli_parse_double(opt, v, -360, 360, &o->yaw);
    } else if (cli_is(arg, "--pitch")) {
        VALUE();
        r = cli_parse_double(opt, v, -90, 90, &o->pitch);
    } else if (cli_is(arg, "--up-axis")) {
        VALUE();
        if (!(r = cli_parse_choice(opt, v, "y", "z", &c))) o->up_axis_z = c;
    } else if (cli_is(arg, "--color")) {
        VALUE();
        r = cli_parse_rgb(opt, v, &o->look.color);
        o->look.have_color = 1;
    } else if (cli_is(arg, "--ambient")) {
        VALUE();
        r = cli_parse_double(opt, v, 0, 1, &o->look.ambient);
        o->look.have_ambient = 1;
    } else if (cli_is(arg, "--specular")) {
        VALUE();
        r = cli_parse_double(opt, v, 0, 1, &o->look.specular);
        o->look.have_specular = 1;
    } else if (cli_is(arg, "--shininess")) {
        VALUE();
        long n;
        r = cli_parse_long(opt, v, 1, 256, &n);
        o->look.shininess = (int)n;
    } else if (texture_option(o, arg, opt, argc, argv, i, &r)) {
        if (r == -2) return -1;
    } else if (cli_is(arg, "--light")) {
        VALUE();
        if (o->look.nlights == SILK_MAX_LIGHTS) return cli_fail(-1, "--light: at most %d lights", SILK_MAX_LIGHTS);
        r = parse_light(v, &o->look.light[o->look.nlights]);
        o->look.nlights++;
    } else {
        return 0;
    }
#undef VALUE
    return r ? -1 : 1;
}

/* ---- camera --------------------------------------------------------------------- */

double cli_fx_to_double(silk_fx v) { return v / 65536.0; }

silk_fx cli_fx_from_double(double v) { return (silk_fx)llround(v * 65536.0); }

static silk_vec3 to_v3(const double v[3])
{
    return silk_v3(cli_fx_from_double(v[0]), cli_fx_from_double(v[1]), cli_fx_from_double(v[2]));
}

static double len3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* The default framing, written out in docs/architecture.md:
 *   c = centre of the bounding box, r = the largest distance of a vertex
 *   from c (so the sphere (c, r) holds the whole model), R = 1.05 r;
 *   d = (cos el sin az, sin el, cos el cos az) with az = 30, el = 20 degrees:
 *   the eye is in front (+z), to the right (+x) and above (+y);
 *   perspective: eye = target + d * (R / sin(f/2) + |target - c|), f the
 *   smaller of the vertical and horizontal fields of view, so the sphere
 *   (c, R) just fits; orthographic: eye = target + d * (2R + |target - c|),
 *   and --ortho auto takes the half height that fits the sphere (c, R);
 *   up = +y, or -z when the view is within 1 degree of vertical;
 *   znear/zfar bracket the sphere as seen from the eye. */
double cli_mesh_radius(const silk_mesh *m, double c[3])
{
    double lo[3] = { cli_fx_to_double(m->bbox_min.x), cli_fx_to_double(m->bbox_min.y), cli_fx_to_double(m->bbox_min.z) };
    double hi[3] = { cli_fx_to_double(m->bbox_max.x), cli_fx_to_double(m->bbox_max.y), cli_fx_to_double(m->bbox_max.z) };
    for (int k = 0; k < 3; k++) c[k] = (lo[k] + hi[k]) / 2;
    double r2 = 0;
    for (uint32_t i = 0; i < m->nverts; i++) {
        double d[3] = { cli_fx_to_double(m->pos[i].x) - c[0], cli_fx_to_double(m->pos[i].y) - c[1],
                        cli_fx_to_double(m->pos[i].z) - c[2] };
        double q = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (q > r2) r2 = q;
    }
    double r = 1.05 * sqrt(r2);
    return r > 0 ? r : 1;
}

/* The model's frame: U its up axis, F its front (where the default camera
 * looks from), R = U x F its right.  Y-up: U = +y, F = +z, R = +x; Z-up
 * (--up-axis z, as Blender exports): U = +z, F = -y, R = +x. */
static void model_frame(const cli_scene_opts *o, double U[3], double F[3], double R[3])
{
    static const double y_up[3][3] = { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } };
    static const double z_up[3][3] = { { 0, 0, 1 }, { 0, -1, 0 }, { 1, 0, 0 } };
    const double (*f)[3] = o->up_axis_z ? z_up : y_up;
    memcpy(U, f[0], 3 * sizeof *U);
    memcpy(F, f[1], 3 * sizeof *F);
    memcpy(R, f[2], 3 * sizeof *R);
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The direction from the target towards the eye at azimuth az (from F
 * towards R) and elevation el (towards U), radians. */
static void orbit_dir(const double U[3], const double F[3], const double R[3], double az, double el, double d[3])
{
    for (int k = 0; k < 3; k++) d[k] = cos(el) * (cos(az) * F[k] + sin(az) * R[k]) + sin(el) * U[k];
}

void cli_orbit_dir(const cli_scene_opts *o, double az_deg, double el_deg, double d[3])
{
    double U[3], F[3], R[3];
    model_frame(o, U, F, R);
    orbit_dir(U, F, R, az_deg * CLI_DEG, el_deg * CLI_DEG, d);
}

void cli_orbit_angles(const cli_scene_opts *o, const double d[3], double *az_deg, double *el_deg)
{
    double U[3], F[3], R[3], len = len3(d);
    model_frame(o, U, F, R);
    *el_deg = len > 0 ? asin(fmax(-1, fmin(1, dot3(d, U) / len))) / CLI_DEG : 0;
    *az_deg = atan2(dot3(d, R), dot3(d, F)) / CLI_DEG;
}

void cli_up_axis(const cli_scene_opts *o, double up[3])
{
    double F[3], R[3];
    model_frame(o, up, F, R);
}

int cli_camera(const cli_scene_opts *o, const silk_mesh *m, silk_camera *cam)
{
    const double deg = CLI_DEG;
    double c[3];
    double r = cli_mesh_radius(m, c);
    double aspect = (double)o->width / o->height;
    double U[3], F[3], R[3];
    model_frame(o, U, F, R);

    double target[3], eye[3], up[3];
    memcpy(up, U, sizeof up);
    for (int k = 0; k < 3; k++) target[k] = o->have_target ? o->target[k] : c[k];
    double off[3] = { target[0] - c[0], target[1] - c[1], target[2] - c[2] };
    double half_v = o->fov * deg / 2, half_h = atan(tan(half_v) * aspect);
    double half = half_v < half_h ? half_v : half_h;
    if (o->have_eye) {
        memcpy(eye, o->eye, sizeof eye);
        if (o->yaw != 0 || o->pitch != 0) {
            /* the given eye's azimuth and elevation about the target, turned */
            double d[3] = { eye[0] - target[0], eye[1] - target[1], eye[2] - target[2] }, dist = len3(d);
            if (dist > 0) {
                double el = asin(fmax(-1, fmin(1, dot3(d, U) / dist))), az = atan2(dot3(d, R), dot3(d, F));
                el = fmax(-90 * deg, fmin(90 * deg, el + o->pitch * deg));
                orbit_dir(U, F, R, az + o->yaw * deg, el, d);
                for (int k = 0; k < 3; k++) eye[k] = target[k] + d[k] * dist;
            }
        }
    } else {
        double az = (CLI_VIEW_AZIMUTH + o->yaw) * deg, el = (CLI_VIEW_ELEVATION + o->pitch) * deg;
        if (el > 90 * deg) el = 90 * deg;
        if (el < -90 * deg) el = -90 * deg;
        double d[3];
        orbit_dir(U, F, R, az, el, d);
        double dist = (o->ortho ? 2 * r : r / sin(half)) + len3(off);
        for (int k = 0; k < 3; k++) eye[k] = target[k] + d[k] * dist;
    }
    double view[3] = { target[0] - eye[0], target[1] - eye[1], target[2] - eye[2] };
    double vlen = len3(view);
    if (o->have_up) {
        memcpy(up, o->up, sizeof up);
    } else if (vlen > 0 && fabs(dot3(view, U)) > cos(1 * deg) * vlen) {
        /* looking along the up axis: the screen's up is away from the front */
        for (int k = 0; k < 3; k++) up[k] = -F[k];
    }
    for (int k = 0; k < 3; k++)
        if (fabs(eye[k]) > CLI_MAX_COORD)
            return cli_fail(CLI_EXIT_USAGE,
                            "the model cannot be framed in a %dx%d view with --fov %g: the eye would be beyond "
                            "+-%g; give --eye or a wider --fov",
                            o->width, o->height, o->fov, CLI_MAX_COORD);

    /* Everything visible lies within the sphere around c; no closer than a
     * thousandth of the far distance, so depth keeps its resolution. */
    double ec[3] = { c[0] - eye[0], c[1] - eye[1], c[2] - eye[2] };
    double zfar = (len3(ec) + r) * 1.01;
    double znear = len3(ec) - r * 1.01;
    if (znear < zfar / 1000) znear = zfar / 1000;
    if (znear < 1.0 / 256) znear = 1.0 / 256;
    if (znear > 4096) znear = 4096;   /* the projection keeps 2 znear in Q16.16 */
    if (zfar > 30000) zfar = 30000;
    if (!(zfar > znear)) zfar = znear * 2;

    memset(cam, 0, sizeof *cam);
    cam->eye = to_v3(eye);
    cam->target = to_v3(target);
    cam->up = to_v3(up);
    cam->ortho = o->ortho;
    cam->fov_deg = cli_fx_from_double(o->fov);
    double oh = o->ortho_auto ? (aspect < 1 ? r / aspect : r) : o->ortho_half;
    if (oh > CLI_MAX_COORD) oh = CLI_MAX_COORD;
    cam->ortho_half_height = cli_fx_from_double(o->ortho ? oh : 1.0);
    cam->znear = cli_fx_from_double(znear);
    cam->zfar = cli_fx_from_double(zfar);
    cam->width = o->width;
    cam->height = o->height;
    return 0;
}

/* ---- scene ----------------------------------------------------------------------- */

void cli_orient_note(const char *path, const silk_mesh *m)
{
    if (m->nreoriented_tris)
        fprintf(stderr, "silk: note: %s: %lu triangles turned round for a consistent, outward winding%s "
                "(--orient keep leaves them)\n",
                path, (unsigned long)m->nreoriented_tris,
                m->nnonorientable_tris ? "; others are on a non-orientable surface, left as they are" : "");
    else if (m->nnonorientable_tris)
        fprintf(stderr, "silk: note: %s: %lu triangles are on a non-orientable surface; left as in the file\n",
                path, (unsigned long)m->nnonorientable_tris);
}

/* Bytes the arena gets when --arena is not given.  Measured on the shared
 * OBJ meshes (docs/memory.md): the loaded mesh takes about 3x its file, a
 * smooth frame's scratch up to about 7x (240 bytes per triangle); 16x
 * leaves room for both and for the loader's scratch.  Binary PLY is denser
 * than OBJ, so the estimate can be short: then the caller doubles it. */
static size_t auto_arena_bytes(size_t file_len, size_t raster)
{
    const size_t per_file_byte = 16, slack = (size_t)1 << 20;
    if (file_len > (SIZE_MAX / 4 - raster - slack) / per_file_byte) return SIZE_MAX / 4;
    return file_len * per_file_byte + raster + slack;
}

static size_t raster_bytes(const cli_scene_opts *o)
{
    size_t px = (size_t)o->width * (size_t)o->height;
    /* siltex's anti-aliased outline draws the hull's front faces into a
     * frame of its own: RGB888, depth and a stencil bit (src/render.c) */
    size_t outline = o->render.mode == SILK_MODE_SILTEX && o->render.aa && o->render.lines == SILK_LINES_NONE
                         ? px * (3 + sizeof(uint32_t)) + px / 8 + 64 * (size_t)o->width
                         : 0;
    return px * silk_pixfmt_bytes(o->fmt) + px * sizeof(uint32_t) + (o->bg_none ? px : 0) + outline + 64;
}

/* One load of m's file into an arena of size bytes; nothing printed. */
static silk_status load_into(cli_mesh *m, const silk_load_opts *lo, int vis, size_t size, silk_error *err)
{
    free(m->buf);
    if (!(m->buf = malloc(size)))
        return silk_fail(err, SILK_ERR_NOMEM, m->name, 0, "cannot allocate an arena of %zu bytes", size);
    silk_arena_init(&m->arena, m->buf, size);
    silk_status st = silk_load_mesh(m->file, m->file_len, m->name, lo, &m->arena, &m->mesh, err);
    if (st == SILK_OK && vis) st = silk_vis_build(&m->mesh, NULL, &m->arena, err);
    return st;
}

/* The arena the model needs to load (with its visibility hierarchy): the
 * peak of a load into a larger arena, which is the exact minimum (both
 * ends of the arena are counted together).  0 if no arena up to 64 times
 * the given one loads it. */
static size_t load_bytes_needed(const cli_mesh *m, const silk_load_opts *lo, int vis, size_t given)
{
    cli_mesh probe = *m;
    probe.buf = NULL;
    size_t size = auto_arena_bytes(m->file_len, 0), need = 0;
    if (size < 2 * given) size = 2 * given;
    for (int attempt = 0; attempt < 6 && size < SIZE_MAX / 4; attempt++, size *= 2) {
        silk_error err;
        silk_status st = load_into(&probe, lo, vis, size, &err);
        if (st == SILK_OK) need = probe.arena.peak;
        if (st != SILK_ERR_NOMEM) break;
    }
    free(probe.buf);
    return need;
}

/* silk_file_read, but standard input is read once and kept: a command that
 * loads again into a larger arena gets the same bytes the second time. */
static silk_status read_input(const char *path, uint8_t **data, size_t *len, silk_error *err)
{
    static uint8_t *stdin_data;
    static size_t stdin_len;
    if (!silk_path_is_stdio(path)) return silk_file_read(path, data, len, err);
    if (!stdin_data) {
        silk_status st = silk_file_read(path, &stdin_data, &stdin_len, err);
        if (st != SILK_OK) return st;
    }
    /* a copy with the reader's trailing NUL, freed by the caller as usual */
    if (!(*data = malloc(stdin_len + 1))) return silk_fail(err, SILK_ERR_IO, SILK_STDIN_NAME, 0, "out of memory");
    memcpy(*data, stdin_data, stdin_len + 1);
    *len = stdin_len;
    return SILK_OK;
}

int cli_mesh_load(cli_mesh *m, const char *path, const silk_load_opts *lo, int vis, size_t fixed, size_t extra,
                  int doublings, int quiet)
{
    memset(m, 0, sizeof *m);
    m->path = path;
    m->name = cli_input_name(path);
    silk_error err;
    if (read_input(path, &m->file, &m->file_len, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);

    /* Large files take a while to parse: say so on a terminal. */
    progress pr;
    char label[160];
    snprintf(label, sizeof label, "loading %s (%.0f MB)", m->name, m->file_len / 1e6);
    progress_start(&pr, quiet || m->file_len < CLI_PROGRESS_FILE_BYTES, label);
    progress_note(&pr, "parsing");

    size_t size = fixed;
    if (!size) {
        size = auto_arena_bytes(m->file_len, extra);
        for (int k = 0; k < doublings && size < SIZE_MAX / 4; k++) size *= 2;
    }
    /* Without a fixed size, an arena that proves too small is doubled and
     * the mesh loaded again: the estimate is a guess, the limit is not. */
    silk_status st;
    for (int attempt = 0;; attempt++) {
        st = load_into(m, lo, vis, size, &err);
        if (st != SILK_ERR_NOMEM || fixed || attempt >= 4 || size > SIZE_MAX / 4) break;
        size *= 2;
        progress_note(&pr, "parsing again in a larger arena");
    }
    progress_end(&pr);
    if (st == SILK_ERR_NOMEM && fixed) {
        size_t need = load_bytes_needed(m, lo, vis, size);
        if (need)
            return cli_fail(CLI_EXIT_INPUT, "%s: arena too small: loading needs %zu bytes, --arena gives %zu", m->name,
                            need, size);
        return cli_fail(CLI_EXIT_INPUT, "%s (the arena has %zu bytes; raise --arena)", err.msg, size);
    }
    if (st != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

void cli_mesh_free(cli_mesh *m)
{
    free(m->buf);
    free(m->file);
    memset(m, 0, sizeof *m);
}

int cli_silmap(const uint8_t *file, size_t len, const char *name, silk_silmap *out)
{
    silk_error err;
    if (!silk_is_model(file, len))
        return cli_fail(CLI_EXIT_INPUT, "%s: clip mode draws a prepared model (silk prepare FINE -o MODEL.silk "
                        "--triangles N), not a mesh file", name);
    if (silk_model_silmap(file, len, name, out, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

int cli_siltex(const uint8_t *file, size_t len, const char *name, silk_siltex *out)
{
    silk_error err;
    if (!silk_is_model(file, len))
        return cli_fail(CLI_EXIT_INPUT, "%s: siltex mode draws a prepared model (silk prepare FINE -o MODEL.silk "
                        "--siltex), not a mesh file", name);
    if (silk_model_siltex(file, len, name, out, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

int cli_scene_load(cli_scene *s, cli_scene_opts *o)
{
    memset(s, 0, sizeof *s);
    cli_mesh lm;
    silk_load_opts lo = o->load;
    int clip = o->render.mode == SILK_MODE_CLIP, siltex = o->render.mode == SILK_MODE_SILTEX;
    if (clip || siltex) lo.part = SILK_PART_HULL;
    int rc = cli_mesh_load(&lm, o->mesh_path, &lo, !o->vis_brute, o->arena_bytes, raster_bytes(o),
                           o->arena_doublings, o->quiet);
    /* the scene takes over the file and the arena */
    s->file = lm.file;
    s->file_len = lm.file_len;
    s->arena_buf = lm.buf;
    s->arena = lm.arena;
    s->mesh = lm.mesh;
    if (!rc && clip) rc = cli_silmap(s->file, s->file_len, cli_input_name(o->mesh_path), &s->silmap);
    if (rc) return rc;
    if (clip) o->render.silmap = &s->silmap;
    if (!rc && siltex) rc = cli_siltex(s->file, s->file_len, cli_input_name(o->mesh_path), &s->siltex);
    if (rc) return rc;
    if (siltex) o->render.siltex = &s->siltex;
    s->load_bytes = s->arena.bottom;
    if (o->orient_note) cli_orient_note(cli_input_name(o->mesh_path), &s->mesh);

    silk_error err;
    rc = cli_camera(o, &s->mesh, &s->cam);
    if (rc) return rc;
    if (silk_view_init(&s->view, &s->cam, &err) != SILK_OK)
        return cli_fail(CLI_EXIT_USAGE, "%s", err.msg);

    size_t px = (size_t)o->width * (size_t)o->height;
    uint8_t *color = silk_arena_array(&s->arena, px, silk_pixfmt_bytes(o->fmt), SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&s->arena, px, sizeof(uint32_t), SILK_MEM_RASTER);
    if (!color || !depth)
        return cli_fail(CLI_EXIT_INPUT, "the arena (%zu bytes) has no room for a %dx%d frame (%zu bytes); raise --arena",
                        s->arena.size, o->width, o->height, raster_bytes(o));
    silk_target_init(&s->target, o->width, o->height, 0, o->height, o->fmt, color, depth);
    /* --bg none with anti-aliased outlines: the renderer writes the coverage */
    if (o->bg_none && o->render.aa && o->render.lines == SILK_LINES_NONE &&
        !(s->target.alpha = silk_arena_array(&s->arena, px, 1, SILK_MEM_RASTER)))
        return cli_fail(CLI_EXIT_INPUT, "the arena (%zu bytes) has no room for the alpha channel; raise --arena",
                        s->arena.size);
    rc = cli_material_load(&s->material, o->mesh_path, s->file, s->file_len, &s->mesh, o->look.texture_path,
                           &o->look.texture, o->quiet);
    if (rc) return rc;
    cli_scene_phong(s, o, &s->view, &s->phong);
    silk_hal_phong(&s->hal, &s->phong);
    return 0;
}

/* ---- look and output -------------------------------------------------------------- */

static silk_vec3 rgb_to_v3(uint32_t rgb)
{
    double c[3] = { ((rgb >> 16) & 255) / 255.0, ((rgb >> 8) & 255) / 255.0, (rgb & 255) / 255.0 };
    return to_v3(c);
}

void cli_phong(const cli_scene_opts *o, const silk_view *view, silk_phong *p)
{
    silk_phong_default(p, view);
    const cli_look *l = &o->look;
    if (l->have_color) p->mat.color = rgb_to_v3(l->color);
    if (l->have_ambient) p->mat.ambient = cli_fx_from_double(l->ambient);
    if (l->have_specular) p->mat.specular = cli_fx_from_double(l->specular);
    if (l->shininess) p->mat.shininess = l->shininess;
    if (l->nlights) {
        p->nlights = l->nlights;
        for (int i = 0; i < l->nlights; i++) {
            const cli_light *li = &l->light[i];
            double v[3] = { li->v[0], li->v[1], li->v[2] }, n = li->point ? 1 : len3(v);
            p->lights[i].kind = li->point ? SILK_LIGHT_POINT : SILK_LIGHT_DIRECTIONAL;
            for (int k = 0; k < 3; k++) v[k] /= n;
            p->lights[i].vec = to_v3(v);
            p->lights[i].color = rgb_to_v3(li->rgb);
        }
    }
}

void cli_scene_phong(const cli_scene *s, const cli_scene_opts *o, const silk_view *view, silk_phong *p)
{
    cli_phong(o, view, p);
    cli_material_apply(&s->material, &s->mesh, o->look.have_color, o->look.have_specular, o->look.shininess != 0, p);
    /* a silhouette texture's colour map, like a texture, is the colour (unless --color) */
    if (o->render.mode == SILK_MODE_SILTEX && s->siltex.color && !o->look.have_color)
        p->mat.color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
}

cli_alpha cli_alpha_for(const cli_scene_opts *o)
{
    if (!o->bg_none) return CLI_ALPHA_NONE;
    return o->render.lines == SILK_LINES_ONLY ? CLI_ALPHA_COLOUR : CLI_ALPHA_COVERAGE;
}

int cli_write_image(const silk_target *t, const char *path, silk_image_format fmt, cli_alpha alpha, uint32_t bg_rgb)
{
    silk_error err;
    if (!silk_path_is_stdio(path)) fmt = silk_image_format_for_path(path);
    else if (fmt == SILK_IMAGE_NONE) fmt = SILK_IMAGE_PNG;
    if (!alpha) {
        if (silk_image_write_as(t, path, fmt, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        return 0;
    }
    if (fmt != SILK_IMAGE_PNG)
        return cli_fail(CLI_EXIT_USAGE, "%s: --bg none needs a PNG (PPM has no alpha channel)",
                        silk_path_is_stdio(path) ? SILK_STDOUT_NAME : path);
    size_t n = (size_t)t->width * (size_t)t->height;
    uint8_t *a = malloc(n ? n : 1), *row = malloc((size_t)t->width * 3);
    if (!a || !row) {
        free(a), free(row);
        return cli_fail(CLI_EXIT_INPUT, "out of memory for the alpha channel");
    }
    uint8_t bg[3] = { (uint8_t)(bg_rgb >> 16), (uint8_t)(bg_rgb >> 8), (uint8_t)bg_rgb };
    for (int y = 0; y < t->height; y++) {
        /* covered: the surface wrote depth there, or something (a line drawn
         * alone) changed the background colour */
        silk_target_row_rgb888(t, y, row);
        for (int x = 0; x < t->width; x++) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            int depth = alpha == CLI_ALPHA_COVERAGE && t->depth && t->depth[i] != 0;   /* cleared to 0, the farthest */
            if (alpha == CLI_ALPHA_COVERAGE && t->alpha) a[i] = t->alpha[i];
            else a[i] = depth || memcmp(row + 3 * x, bg, 3) != 0 ? 255 : 0;
        }
    }
    silk_status st = silk_png_write_alpha(t, a, path, &err);
    free(a), free(row);
    return st == SILK_OK ? 0 : cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
}

void cli_scene_free(cli_scene *s)
{
    cli_material_free(&s->material);
    free(s->arena_buf);
    free(s->file);
    memset(s, 0, sizeof *s);
}
