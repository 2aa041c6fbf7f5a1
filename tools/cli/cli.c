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
#include <sys/stat.h>

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

int cli_parse_decimal(const char *opt, const char *s, silk_decimal *out)
{
    const char *end;
    silk_decimal d;
    if (!plain_decimal(s) || silk_decimal_parse(s, &end, &d) != 0 || *end || d.mant <= 0)
        return cli_fail(-1, "%s must be a positive decimal number, e.g. 0.01 (got \"%s\")", opt, s);
    *out = d;
    return 0;
}

/* The directory part of path ("." when it has none). */
static void dir_of(const char *path, char *buf, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (!slash) snprintf(buf, n, ".");
    else if (slash == path) snprintf(buf, n, "/");
    else snprintf(buf, n, "%.*s", (int)(slash - path), path);
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int cli_check_output_dir(const char *opt, const char *path)
{
    char dir[4096];
    dir_of(path, dir, sizeof dir);
    if (is_dir(dir)) return 0;
    return cli_fail(-1, "%s %s: the directory %s does not exist", opt, path, dir);
}

int cli_check_dir(const char *opt, const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0) return S_ISDIR(st.st_mode) ? 0 : cli_fail(-1, "%s %s: not a directory", opt, path);
    char dir[4096], parent[4096];
    snprintf(dir, sizeof dir, "%s", path);
    for (size_t n = strlen(dir); n > 1 && dir[n - 1] == '/'; n--) dir[n - 1] = 0;
    dir_of(dir, parent, sizeof parent);
    if (is_dir(parent)) return 0;
    return cli_fail(-1, "%s %s: the directory %s does not exist", opt, path, parent);
}

int cli_make_dir(const char *path)
{
    if (is_dir(path) || mkdir(path, 0777) == 0) return 0;
    return cli_fail(CLI_EXIT_INPUT, "%s: cannot make the directory: %s", path, strerror(errno));
}

int cli_one_mesh(const char *cmd, int npos, const char *const *pos, const char *usage, const char **mesh_path)
{
    if (npos == 0) return cli_fail(CLI_EXIT_USAGE, "%s: no mesh given (%s)", cmd, usage);
    if (npos > 1) return cli_fail(CLI_EXIT_USAGE, "%s: one mesh at a time (got %s and %s)", cmd, pos[0], pos[1]);
    *mesh_path = pos[0];
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
        double d[3] = { cli_fx_to_double(silk_mesh_pos(m, i).x) - c[0], cli_fx_to_double(silk_mesh_pos(m, i).y) - c[1],
                        cli_fx_to_double(silk_mesh_pos(m, i).z) - c[2] };
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

/* The largest distance of a vertex of m from c, 5% to spare. */
static double reach_of(const silk_mesh *m, const double c[3])
{
    double r2 = 0;
    for (uint32_t i = 0; i < m->nverts; i++) {
        double d[3] = { cli_fx_to_double(silk_mesh_pos(m, i).x) - c[0], cli_fx_to_double(silk_mesh_pos(m, i).y) - c[1],
                        cli_fx_to_double(silk_mesh_pos(m, i).z) - c[2] };
        r2 = fmax(r2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    return 1.05 * sqrt(r2);
}

int cli_camera(const cli_scene_opts *o, const silk_mesh *m, const silk_mesh *also, silk_camera *cam)
{
    const double deg = CLI_DEG;
    double c[3];
    double r = cli_mesh_radius(m, c);
    /* near and far bracket also's vertices too */
    double reach = also ? fmax(r, reach_of(also, c)) : r;
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

    /* Everything visible lies within reach of c; no closer than a
     * thousandth of the far distance, so depth keeps its resolution. */
    double ec[3] = { c[0] - eye[0], c[1] - eye[1], c[2] - eye[2] };
    double zfar = (len3(ec) + reach) * 1.01;
    double znear = len3(ec) - reach * 1.01;
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
    int siltex = o->render.mode == SILK_MODE_SILTEX || (o->modes >> SILK_MODE_SILTEX & 1u);
    size_t outline = siltex && o->render.aa && o->render.lines == SILK_LINES_NONE
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

/* The hull (with its hierarchy unless brute visibility), the map and the
 * texture of the prepared model in s->file that the modes need: needed
 * ones are an error when missing, wanted ones (parts_if_any) not. */
static int load_parts(cli_scene *s, const cli_scene_opts *o, const char *name, int clip, int siltex)
{
    int any = o->parts_if_any && silk_is_model(s->file, s->file_len);
    if (!clip && !siltex && !any) return 0;
    silk_error err;
    silk_load_opts lo = o->load;
    lo.part = SILK_PART_HULL;
    int rc = 0;
    if (clip && !silk_is_model(s->file, s->file_len)) return cli_silmap(s->file, s->file_len, name, &s->silmap);
    if (siltex && !silk_is_model(s->file, s->file_len)) return cli_siltex(s->file, s->file_len, name, &s->siltex);
    silk_status st = silk_load_model(s->file, s->file_len, name, &lo, &s->arena, &s->hull, &err);
    if (st == SILK_OK && !o->vis_brute) st = silk_vis_build(&s->hull, NULL, &s->arena, &err);
    if (st == SILK_ERR_NOMEM) return cli_fail(CLI_EXIT_INPUT, "%s (the arena has %zu bytes; raise --arena)", err.msg,
                                              s->arena.size);
    if (st != SILK_OK) return clip || siltex ? cli_fail(CLI_EXIT_INPUT, "%s", err.msg) : 0;
    s->have_hull = 1;
    silk_model m;
    silk_model_section sec;
    int has_map = 1, has_tex = 1;
    if (silk_model_open(s->file, s->file_len, name, &m, &err) == SILK_OK) {
        has_map = silk_model_find(&m, SILK_SECTION_SMAP, &sec);
        has_tex = silk_model_find(&m, SILK_SECTION_STEX, &sec);
    }
    if (clip || (any && has_map)) {
        rc = cli_silmap(s->file, s->file_len, name, &s->silmap);
        s->have_silmap = rc == 0;
        if (rc && clip) return rc;
    }
    if (siltex || (any && has_tex)) {
        rc = cli_siltex(s->file, s->file_len, name, &s->siltex);
        s->have_siltex = rc == 0;
        if (rc && siltex) return rc;
    }
    return 0;
}

static int wants(const cli_scene_opts *o, silk_mode m) { return o->render.mode == m || (o->modes >> m & 1u); }
static int hull_mode(silk_mode m) { return m == SILK_MODE_CLIP || m == SILK_MODE_SILTEX; }

int cli_scene_load(cli_scene *s, cli_scene_opts *o)
{
    memset(s, 0, sizeof *s);
    cli_mesh lm;
    const char *name = cli_input_name(o->mesh_path);
    int clip = wants(o, SILK_MODE_CLIP), siltex = wants(o, SILK_MODE_SILTEX);
    silk_load_opts lo = o->load;
    int hull_only = o->only_drawn && hull_mode(o->render.mode);
    if (hull_only) lo.part = SILK_PART_HULL;
    int rc = cli_mesh_load(&lm, o->mesh_path, &lo, !o->vis_brute, o->arena_bytes, raster_bytes(o),
                           o->arena_doublings, o->quiet);
    /* the scene takes over the file and the arena */
    s->file = lm.file;
    s->file_len = lm.file_len;
    s->arena_buf = lm.buf;
    s->arena = lm.arena;
    s->mesh = lm.mesh;
    if (!rc && hull_only) {
        /* the one mesh is the hull: only the map or texture besides */
        if (clip) rc = cli_silmap(s->file, s->file_len, name, &s->silmap);
        if (siltex) rc = cli_siltex(s->file, s->file_len, name, &s->siltex);
        s->have_silmap = clip && !rc;
        s->have_siltex = siltex && !rc;
    } else if (!rc) {
        rc = load_parts(s, o, name, clip, siltex);
    }
    if (rc) return rc;
    s->load_bytes = s->arena.bottom;
    if (o->orient_note) cli_orient_note(name, &s->mesh);

    silk_error err;
    rc = cli_scene_camera(s, o, &s->cam);
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
    cli_scene_phong(s, o, o->render.mode, &s->view, &s->phong);
    silk_hal_phong(&s->hal, &s->phong);
    return 0;
}

const silk_mesh *cli_scene_mesh(const cli_scene *s, silk_mode mode)
{
    return hull_mode(mode) && s->have_hull ? &s->hull : &s->mesh;
}

void cli_scene_render_opts(const cli_scene *s, silk_render_opts *ro)
{
    ro->silmap = ro->mode == SILK_MODE_CLIP && s->have_silmap ? &s->silmap : NULL;
    ro->siltex = ro->mode == SILK_MODE_SILTEX && s->have_siltex ? &s->siltex : NULL;
}

int cli_scene_camera(const cli_scene *s, const cli_scene_opts *o, silk_camera *cam)
{
    return cli_camera(o, &s->mesh, s->have_hull ? &s->hull : NULL, cam);
}

int cli_mode_check(const char *cmd, silk_mode mode, const silk_render_opts *ro)
{
    if (!ro->lines) return 0;
    if (mode == SILK_MODE_CLIP)
        return cli_fail(CLI_EXIT_USAGE, "%s: clip mode draws no lines (its outline is the silhouette map's); leave out "
                        "--lines and --lines-polygonal", cmd);
    if ((mode == SILK_MODE_PN || mode == SILK_MODE_BLEND) && !ro->lines_polygonal)
        return cli_fail(CLI_EXIT_USAGE, "%s: %s mode draws only the coarse mesh's outline: --lines-polygonal instead "
                        "of --lines", cmd, silk_mode_name(mode));
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
    if (l->have_shininess) p->mat.shininess = l->shininess;
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

void cli_scene_phong(const cli_scene *s, const cli_scene_opts *o, silk_mode mode, const silk_view *view,
                     silk_phong *p)
{
    cli_phong(o, view, p);
    cli_material_apply(&s->material, cli_scene_mesh(s, mode), o->look.have_color, o->look.have_specular,
                       o->look.have_shininess, p);
    /* a silhouette texture's colour map, like a texture, is the colour (unless --color) */
    if (mode == SILK_MODE_SILTEX && s->have_siltex && s->siltex.color && !o->look.have_color)
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
