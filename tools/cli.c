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
#include "../platform/platform.h"

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

int cli_mesh_arg(const char *cmd, const char *arg, const char **mesh_path)
{
    if (arg[0] == '-' && arg[1]) return cli_fail(CLI_EXIT_USAGE, "%s: unknown option %s (try silk %s --help)", cmd, arg, cmd);
    if (*mesh_path) return cli_fail(CLI_EXIT_USAGE, "%s: one mesh at a time (got %s and %s)", cmd, *mesh_path, arg);
    *mesh_path = arg;
    return 0;
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
    o->orient_note = 1;
    silk_render_opts_default(&o->render);
}

void cli_print_scene_help(FILE *f)
{
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    fprintf(f,
            "\n"
            "Mesh loading:\n"
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
            "Camera (default: the whole model, seen from front-right-above):\n"
            "  --eye x,y,z          eye position (default: placed so the model fits the view)\n"
            "  --target x,y,z       point looked at (default: centre of the bounding box)\n"
            "  --up x,y,z           up direction (default 0,1,0)\n"
            "  --fov DEG            perspective, vertical field of view (%g..%g, default %g)\n"
            "  --ortho H|auto       orthographic, H = half the view height in model units;\n"
            "                       auto fits the model\n"
            "Frame:\n"
            "  --size WxH           image size in pixels, 1..%d each (default %dx%d)\n"
            "  --format rgb888|rgb565  pixel format silk renders in (default %s)\n"
            "  --mode flat|smooth|pn|blend  coarse mesh as it is, smoothed silhouettes\n"
            "                       (default), PN triangles, or silhouetteness blending\n"
            "                       (Dyken & Reimers); docs/methods.md\n"
            "  --tolerance PX       silhouette sampling tolerance in pixels, 0.25..4 (%g)\n"
            "  --level L            pn: segments per triangle side, 1..%u (default %u)\n"
            "  --pn-normals quadratic|linear  pn: normal patch (default quadratic)\n"
            "  --beta B             blend: silhouetteness transition, 0..1 (default %g)\n"
            "  --bg RRGGBB          background colour in hex (default %06x)\n"
            "  --wire               draw the edges; triangles added by smoothing in red\n"
            "  --lines over|only    pen-and-ink outlines over the shading or alone: the\n"
            "                       smoothed silhouette and visible feature curves (smooth),\n"
            "                       the mesh's silhouette and feature edges (flat)\n"
            "  --lines-polygonal    the coarse mesh's silhouette and feature edges in any\n"
            "                       mode (pn and blend draw lines only so; alone: --lines over)\n",
            cli_fx_to_double(SILK_DEFAULT_CREASE_DEG), cli_fx_to_double(SILK_FOV_MIN),
            cli_fx_to_double(SILK_FOV_MAX), CLI_DEFAULT_FOV, CLI_MAX_SIDE, SILK_BOARD_WIDTH, SILK_BOARD_HEIGHT,
            SILK_BOARD_FORMAT == SILK_PIX_RGB565 ? "rgb565" : "rgb888", cli_fx_to_double(ro.tolerance_px),
            SILK_PN_MAX_LEVEL, (unsigned)ro.level, cli_fx_to_double(ro.blend_beta), (unsigned)ro.bg_rgb);
}

static int parse_fx(const char *opt, const char *s, double lo, double hi, silk_fx *out)
{
    double v;
    if (cli_parse_double(opt, s, lo, hi, &v) != 0) return -1;
    *out = (silk_fx)llround(v * 65536.0);
    return 0;
}

int cli_scene_option(cli_scene_opts *o, int argc, char **argv, int *i)
{
    char name[40];
    const char *arg = argv[*i], *opt = opt_name(arg, name, sizeof name), *v;
    int r = 0;
#define VALUE() do { if (!(v = cli_value(argc, argv, i))) return -1; } while (0)
    if (cli_is(arg, "--scale")) {
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
        else return cli_fail(-1, "--normals must be auto, compute or file (got \"%s\")", v);
    } else if (cli_is(arg, "--orient")) {
        VALUE();
        if (strcmp(v, "fix") == 0) o->load.orient = SILK_ORIENT_FIX;
        else if (strcmp(v, "keep") == 0) o->load.orient = SILK_ORIENT_KEEP;
        else return cli_fail(-1, "--orient must be fix or keep (got \"%s\")", v);
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
        if (strcmp(v, "rgb888") == 0) o->fmt = SILK_PIX_RGB888;
        else if (strcmp(v, "rgb565") == 0) o->fmt = SILK_PIX_RGB565;
        else return cli_fail(-1, "--format must be rgb888 or rgb565 (got \"%s\")", v);
    } else if (cli_is(arg, "--mode")) {
        VALUE();
        if (strcmp(v, "flat") == 0) o->render.mode = SILK_MODE_FLAT;
        else if (strcmp(v, "smooth") == 0) o->render.mode = SILK_MODE_SMOOTH;
        else if (strcmp(v, "pn") == 0) o->render.mode = SILK_MODE_PN;
        else if (strcmp(v, "blend") == 0) o->render.mode = SILK_MODE_BLEND;
        else return cli_fail(-1, "--mode must be flat, smooth, pn or blend (got \"%s\")", v);
    } else if (cli_is(arg, "--level")) {
        VALUE();
        long l;
        r = cli_parse_long(opt, v, 1, SILK_PN_MAX_LEVEL, &l);
        if (!r) o->render.level = (uint32_t)l;
    } else if (cli_is(arg, "--pn-normals")) {
        VALUE();
        if (strcmp(v, "quadratic") == 0) o->render.pn_normals = SILK_PN_QUADRATIC;
        else if (strcmp(v, "linear") == 0) o->render.pn_normals = SILK_PN_LINEAR;
        else return cli_fail(-1, "--pn-normals must be quadratic or linear (got \"%s\")", v);
    } else if (cli_is(arg, "--beta")) {
        VALUE();
        r = parse_fx(opt, v, 0, 1, &o->render.blend_beta);
    } else if (cli_is(arg, "--tolerance")) {
        VALUE();
        r = parse_fx(opt, v, 0.25, 4, &o->render.tolerance_px);
    } else if (cli_is(arg, "--bg")) {
        VALUE();
        r = cli_parse_rgb(opt, v, &o->render.bg_rgb);
    } else if (strcmp(arg, "--wire") == 0) {
        o->render.wire = 1;
    } else if (cli_is(arg, "--lines")) {
        VALUE();
        if (strcmp(v, "over") == 0) o->render.lines = SILK_LINES_OVER;
        else if (strcmp(v, "only") == 0) o->render.lines = SILK_LINES_ONLY;
        else return cli_fail(-1, "--lines must be over or only (got \"%s\")", v);
    } else if (strcmp(arg, "--lines-polygonal") == 0) {
        o->render.lines_polygonal = 1;
        if (!o->render.lines) o->render.lines = SILK_LINES_OVER;
    } else {
        return 0;
    }
#undef VALUE
    return r ? -1 : 1;
}

/* ---- camera --------------------------------------------------------------------- */

double cli_fx_to_double(silk_fx v) { return v / 65536.0; }

static silk_fx to_fx(double v) { return (silk_fx)llround(v * 65536.0); }

static silk_vec3 to_v3(const double v[3]) { return silk_v3(to_fx(v[0]), to_fx(v[1]), to_fx(v[2])); }

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

int cli_camera(const cli_scene_opts *o, const silk_mesh *m, silk_camera *cam)
{
    const double deg = 3.14159265358979323846 / 180;
    double c[3];
    double r = cli_mesh_radius(m, c);
    double aspect = (double)o->width / o->height;

    double target[3], eye[3], up[3] = { 0, 1, 0 };
    for (int k = 0; k < 3; k++) target[k] = o->have_target ? o->target[k] : c[k];
    double off[3] = { target[0] - c[0], target[1] - c[1], target[2] - c[2] };
    double half_v = o->fov * deg / 2, half_h = atan(tan(half_v) * aspect);
    double half = half_v < half_h ? half_v : half_h;
    if (o->have_eye) {
        memcpy(eye, o->eye, sizeof eye);
    } else {
        double az = CLI_VIEW_AZIMUTH * deg, el = CLI_VIEW_ELEVATION * deg;
        double d[3] = { cos(el) * sin(az), sin(el), cos(el) * cos(az) };
        double dist = (o->ortho ? 2 * r : r / sin(half)) + len3(off);
        for (int k = 0; k < 3; k++) eye[k] = target[k] + d[k] * dist;
    }
    double view[3] = { target[0] - eye[0], target[1] - eye[1], target[2] - eye[2] };
    double vlen = len3(view);
    if (o->have_up) {
        memcpy(up, o->up, sizeof up);
    } else if (vlen > 0 && fabs(view[1]) > cos(1 * deg) * vlen) {
        up[1] = 0;
        up[2] = -1;
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
    cam->fov_deg = to_fx(o->fov);
    double oh = o->ortho_auto ? (aspect < 1 ? r / aspect : r) : o->ortho_half;
    if (oh > CLI_MAX_COORD) oh = CLI_MAX_COORD;
    cam->ortho_half_height = to_fx(o->ortho ? oh : 1.0);
    cam->znear = to_fx(znear);
    cam->zfar = to_fx(zfar);
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
    return px * silk_pixfmt_bytes(o->fmt) + px * sizeof(uint32_t) + 64;
}

/* The arena the model needs to load (with its visibility hierarchy): the
 * peak of a load into a larger arena, which is the exact minimum (both
 * ends of the arena are counted together).  0 if no arena up to 64 times
 * the given one loads it. */
static size_t load_bytes_needed(const cli_scene *s, const cli_scene_opts *o, size_t given)
{
    size_t size = auto_arena_bytes(s->file_len, 0);
    if (size < 2 * given) size = 2 * given;
    for (int attempt = 0; attempt < 6 && size < SIZE_MAX / 4; attempt++, size *= 2) {
        void *buf = malloc(size);
        if (!buf) return 0;
        silk_arena a;
        silk_mesh m;
        silk_error err;
        silk_arena_init(&a, buf, size);
        silk_status st = silk_load_mesh(s->file, s->file_len, o->mesh_path, &o->load, &a, &m, &err);
        if (st == SILK_OK && !o->vis_brute) st = silk_vis_build(&m, NULL, &a, &err);
        size_t peak = a.peak;
        free(buf);
        if (st == SILK_OK) return peak;
        if (st != SILK_ERR_NOMEM) return 0;
    }
    return 0;
}

int cli_scene_load(cli_scene *s, const cli_scene_opts *o)
{
    memset(s, 0, sizeof *s);
    silk_error err;
    if (silk_file_read(o->mesh_path, &s->file, &s->file_len, &err) != SILK_OK)
        return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);

    size_t size = o->arena_bytes;
    if (!size) {
        size = auto_arena_bytes(s->file_len, raster_bytes(o));
        for (int k = 0; k < o->arena_doublings && size < SIZE_MAX / 4; k++) size *= 2;
    }
    silk_status st;
    /* Without --arena, an arena that proves too small is doubled and the
     * mesh loaded again: the estimate is a guess, the limit is not. */
    for (int attempt = 0;; attempt++) {
        s->arena_buf = malloc(size);
        if (!s->arena_buf)
            return cli_fail(CLI_EXIT_INPUT, "cannot allocate an arena of %zu bytes", size);
        silk_arena_init(&s->arena, s->arena_buf, size);
        st = silk_load_mesh(s->file, s->file_len, o->mesh_path, &o->load, &s->arena, &s->mesh, &err);
        if (st == SILK_OK && !o->vis_brute) st = silk_vis_build(&s->mesh, NULL, &s->arena, &err);
        if (st != SILK_ERR_NOMEM || o->arena_bytes || attempt >= 4 || size > SIZE_MAX / 4) break;
        free(s->arena_buf);
        s->arena_buf = NULL;
        size *= 2;
    }
    if (st == SILK_ERR_NOMEM && o->arena_bytes) {
        size_t need = load_bytes_needed(s, o, size);
        if (need)
            return cli_fail(CLI_EXIT_INPUT, "%s: arena too small: loading needs %zu bytes, --arena gives %zu",
                            o->mesh_path, need, size);
        return cli_fail(CLI_EXIT_INPUT, "%s (the arena has %zu bytes; raise --arena)", err.msg, size);
    }
    if (st != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    s->load_bytes = s->arena.bottom;
    if (o->orient_note) cli_orient_note(o->mesh_path, &s->mesh);

    int rc = cli_camera(o, &s->mesh, &s->cam);
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
    silk_phong_default(&s->phong, &s->view);
    silk_hal_phong(&s->hal, &s->phong);
    return 0;
}

void cli_scene_free(cli_scene *s)
{
    free(s->arena_buf);
    free(s->file);
    memset(s, 0, sizeof *s);
}
