/*
 * cmd_bench.c - `silk bench MESH... [--pair COARSE:FINE]...`: the
 * render modes side by side, as in the paper's Table I.  For every mesh,
 * from N views along a camera path around it, in orthographic and
 * perspective projection, and for every mode (flat, smooth, blend, PN at
 * level L): triangles drawn per frame, time per frame, and the silhouette
 * error against the fine mesh drawn flat from the same camera, measured
 * with the same mask comparison as `silk diff` (tools/image/mask.c).  The camera
 * path and every metric are defined in docs/measurements.md.
 *
 * Output: one line per mesh, mode and projection on stdout, and on request
 * a CSV file, the same rows as JSON, a Markdown table and a bar chart
 * (tools/image/plot.c).  `silk bench --visibility-pass` is the visibility benchmark
 * (tools/cli/bench_visibility.c).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "prep/compact_enc.h"
#include "commands.h"
#include "image/mask.h"
#include "image/plot.h"
#include "progress.h"
#include "platform/platform.h"

#define MAX_MODES 16
#define MAX_VIEWS 360
#define PROJ_ORTHO 0
#define PROJ_PERSP 1
/* The camera path: view k of N has azimuth 30 + 360 k / N degrees and
 * elevation 20 cos(2 pi k / N), so view 0 is the default camera of
 * `silk render`. */
#define PATH_ELEVATION 20.0

static const char *const proj_name[2] = { "ortho", "perspective" };

typedef struct bench_cfg {
    int views, reps, width, height;
    int proj_mask;             /* bit PROJ_ORTHO, bit PROJ_PERSP */
    cli_mode mode[MAX_MODES];   /* "pn" is given its level: "pn3" */
    int nmodes;
    silk_fx tolerance;
    uint32_t bg;
    const char *csv, *json, *md, *plot, *plot_bytes, *dump;
    int quiet;
    int visibility;            /* --visibility-pass: the other benchmark (bench_visibility.c) */
    int grid;                  /* --grid: the robustness grid (bench_grid.c) */
    /* The meshes in the order given: coarse[i] and, for a --pair, fine[i]
     * (NULL without) and the pair's own modes; argc of room each. */
    int n;
    const char **coarse, **fine, **pair_modes;
    char **pair_buf;
} bench_cfg;

/* One row of the table: a mesh, a mode (or the fine reference), a projection. */
typedef struct row {
    char mesh[64];
    char mode[16];
    uint32_t level;
    int proj;
    int has_error;             /* a fine mesh was given */
    int fell_back;             /* some frame ran out of arena */
    uint32_t tris_in;
    double drawn;              /* mean over the views */
    double ms;                 /* median over the views of the best of reps */
    double err_mean;           /* mean over the views of mean_px */
    double err_max;            /* largest Hausdorff distance of any view */
    double err_worst_mean;     /* largest mean_px of any view */
    double hausdorff_mean;     /* mean over the views of the Hausdorff distance */
    double outside, inside;    /* err_mean split: pixels only in the mode's / only in the reference's mask */
    size_t arena_peak;         /* arena high-water mark over the views */
    size_t bytes;              /* the model's data a device keeps in flash (model_bytes) */
} row;

typedef struct row_list {
    row *r;
    int n, cap;
} row_list;

typedef struct loaded {
    const char *path;
    char name[64];
    void *buf;
    silk_arena arena;
    silk_mesh mesh;
    uint8_t *file;             /* the hull of a prepared model: the file, which holds its map */
    size_t file_len;
    silk_silmap silmap;
    silk_siltex siltex;
    struct loaded *hull;       /* clip and siltex mode's mesh, map and texture, when a mode needs them */
} loaded;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    if (n == 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* ---- options -------------------------------------------------------------------- */

/* --modes: the shared parser; a plain "pn" is PN at the library's level. */
static int parse_modes(const char *list, bench_cfg *c)
{
    if (cli_parse_modes("--modes", list, c->mode, MAX_MODES, &c->nmodes)) return -1;
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    for (int m = 0; m < c->nmodes; m++) {
        cli_mode *x = &c->mode[m];
        if (x->mode != SILK_MODE_PN || x->level) continue;
        x->level = ro.level;
        snprintf(x->name, sizeof x->name, "pn%u", (unsigned)x->level);
        for (int k = 0; k < c->nmodes; k++)
            if (k != m && strcmp(c->mode[k].name, x->name) == 0)
                return cli_fail(-1, "--modes: %s is listed twice", x->name);
    }
    return 0;
}

/* A pair's own mode list (COARSE:FINE=MODES) as a mask over --modes: each
 * must be one of them; without a list, all of them. */
static int pair_mode_mask(const char *list, const bench_cfg *c, uint32_t *mask)
{
    *mask = 0;
    if (!list) {
        *mask = (1u << c->nmodes) - 1;
        return 0;
    }
    cli_mode own[MAX_MODES];
    int n;
    if (cli_parse_modes("--pair", list, own, MAX_MODES, &n)) return CLI_EXIT_USAGE;
    for (int k = 0; k < n; k++) {
        int m = 0;
        while (m < c->nmodes && strcmp(c->mode[m].name, own[k].name) != 0) m++;
        if (m == c->nmodes) return cli_fail(CLI_EXIT_USAGE, "--pair: mode %s is not one of --modes", own[k].name);
        *mask |= 1u << m;
    }
    return 0;
}

/* ---- the command's options ---------------------------------------------------------- */

static int opt_modes(const cli_opt *o, const char *v, void *base)
{
    (void)o;
    return parse_modes(v, base);
}

/* --pair COARSE:FINE[=MODES] */
static int opt_pair(const cli_opt *o, const char *v, void *base)
{
    (void)o;
    bench_cfg *c = base;
    char *buf = malloc(strlen(v) + 1);
    if (!buf) return cli_fail(CLI_EXIT_INPUT, "out of memory");
    strcpy(buf, v);
    c->pair_buf[c->n] = buf;
    char *eq = strrchr(buf, '=');   /* the pair's own modes */
    if (eq) *eq = 0;
    char *colon = strrchr(buf, ':');
    if (!colon || colon == buf || !colon[1] || (eq && !eq[1]))
        return cli_fail(-1, "--pair must be COARSE:FINE or COARSE:FINE=MODES (got \"%s\")", v);
    *colon = 0;
    c->coarse[c->n] = buf;
    c->pair_modes[c->n] = eq ? eq + 1 : NULL;
    c->fine[c->n++] = colon + 1;
    return 0;
}

static int bench_positional(const char *arg, void *base)
{
    bench_cfg *c = base;
    c->coarse[c->n++] = arg;
    return 0;
}

static int opt_plot(const cli_opt *o, const char *v, void *base)
{
    if (silk_image_format_for_path(v) != SILK_IMAGE_PNG)
        return cli_fail(-1, "%s: %s: the chart is a PNG (use .png)", o->name, v);
    if (cli_check_output_dir(o->name, v)) return CLI_EXIT_INPUT;
    *(const char **)((char *)base + o->off) = v;
    return 0;
}

static void bench_defaults(void *base)
{
    bench_cfg *c = base;
    memset(c, 0, sizeof *c);
    c->views = 12;
    c->reps = 3;
    c->width = 640;
    c->height = 480;
    c->proj_mask = 3;
    c->bg = 0xFFFFFF;
    parse_modes("flat,smooth,blend,pn2,pn3", c);
}

#define F(member) CLI_FIELD(bench_cfg, member)
static const int proj_v[] = { 1 << PROJ_ORTHO, 1 << PROJ_PERSP, 3, 1 << PROJ_ORTHO };
static const cli_opt bench_rows[] = {
    { .name = "--pair", .group = "options", .kind = CLI_CUSTOM, .meta = "COARSE:FINE", .parse = opt_pair,
      .help = "a coarse mesh and its fine reference (repeatable); COARSE:FINE=MODES draws that pair in those of "
              "--modes only" },
    { .name = "--views", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = MAX_VIEWS, F(views),
      .help = "views per projection along the camera path (%R, default %D)" },
    { .name = "--size", .kind = CLI_SIZE, .meta = "WxH", .lo = 1, .hi = CLI_MAX_SIDE, F(width),
      .off2 = offsetof(bench_cfg, height), .help = "image size (default %D)" },
    { .name = "--modes", .kind = CLI_CUSTOM, .meta = "LIST", .parse = opt_modes,
      .help = "comma-separated: flat, smooth, blend, clip, siltex, pnL (PN triangles at level L, as --level of "
              "silk render); MODE-noaa: without anti-aliased outlines (default flat,smooth,blend,pn2,pn3)" },
    { .name = "--projection", .kind = CLI_CHOICE, .choices = "ortho|perspective|both|parallel", .values = proj_v,
      F(proj_mask), .help = "(default both; parallel: the same as ortho)" },
    { .name = "--reps", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 1000, F(reps),
      .help = "timed renders per view, the fastest kept (%R, default %D)" },
    { .name = "--tolerance", .kind = CLI_FX, .meta = "PX", .lo = 0.25, .hi = 4, F(tolerance),
      .help = "smooth and blend sampling tolerance (%R; default: the library's)" },
    { .name = "--bg", .kind = CLI_RGB, .meta = "RRGGBB", F(bg),
      .help = "background colour; the object is every other pixel (default %D)" },
    { .name = "--csv", .group = "Output", .kind = CLI_OUTPUT, .meta = "FILE", F(csv), .help = "the table as CSV" },
    { .name = "--json", .kind = CLI_OUTPUT, .meta = "FILE", F(json),
      .help = "the same rows as a JSON array (docs/formats.md); - for standard output, which then holds only the "
              "JSON" },
    { .name = "--md", .kind = CLI_OUTPUT, .meta = "FILE", F(md),
      .help = "the table as Markdown, with smooth mode's goals checked" },
    { .name = "--plot", .kind = CLI_OUTPUT, .meta = "FILE.png", F(plot), .parse = opt_plot,
      .help = "bar chart of frame time and silhouette error per mode" },
    { .name = "--plot-bytes", .kind = CLI_OUTPUT, .meta = "FILE.png", F(plot_bytes), .parse = opt_plot,
      .help = "silhouette error against the model's bytes in flash, a line per mode through the pairs' coarse "
              "meshes" },
    { .name = "--dump", .kind = CLI_DIR, .meta = "DIR", F(dump),
      .help = "every rendered view as DIR/MESH-PROJ-VIEW-MODE.png (DIR is made when missing)" },
    { .name = "--quiet", .kind = CLI_FLAG, F(quiet), .help = "no progress line on a terminal" },
    { .name = "--visibility-pass", .kind = CLI_FLAG, F(visibility),
      .help = "the visibility benchmark instead (silk bench --visibility-pass --help)" },
    { .name = "--grid", .kind = CLI_FLAG, F(grid),
      .help = "smooth outlines over a grid of views instead (silk bench --grid --help)" },
    { .name = NULL },
};
#undef F

/* The scene option --visibility chooses how visible normals are found. */
static const char *const bench_renamed[] = { "--visibility", "--visibility-pass", NULL };

const cli_command cmd_bench_spec = {
    .name = "bench",
    .usage =
        "usage: silk bench [options] MESH... [--pair COARSE:FINE]...\n"
        "       silk bench --visibility-pass MESH...   (visibility benchmark, see its --help)\n"
        "       silk bench --grid COARSE[:FINE]...   (smooth outlines over a grid of views, see its --help)\n",
    .about =
        "Render every mesh in every mode from N views around it, orthographic and\n"
        "perspective, and report per mode: triangles in, triangles drawn per frame,\n"
        "milliseconds per frame, and - for a --pair - the silhouette error against\n"
        "the fine mesh drawn flat from the same camera (as silk diff measures it).\n"
        "One line per mesh, mode and projection:\n"
        "  bench MESH MODE PROJ triangles=N drawn=N ms=X fps=X error_mean_px=X error_max_px=X arena_bytes=N bytes=N\n"
        "docs/measurements.md defines the camera path and every number.\n",
    .examples = "  silk bench --pair bunny-500.obj:bunny-fine.obj --views 8 --md out.md\n",
    .sets = { { bench_rows, 0, sizeof(bench_cfg), bench_defaults, NULL } },
    .nsets = 1,
    .positional = bench_positional,
    .renamed = bench_renamed,
};

/* ---- meshes and cameras ------------------------------------------------------------ */

static void mesh_name(const char *path, char *out, size_t n)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t len = strcspn(base, ".");
    if (len == 0) len = strlen(base);
    if (len >= n) len = n - 1;
    memcpy(out, base, len);
    out[len] = 0;
}

/* Load with room for the per-frame scratch on top: 8 MiB times 2^grow
 * besides the mesh (cli_mesh_load doubles it while the mesh does not fit).
 * The hull comes with the silhouette map (clip) and texture (siltex) the
 * modes want. */
static int load_mesh(loaded *l, const char *path, int vis, int grow, silk_model_part part, int clip, int siltex)
{
    memset(l, 0, sizeof *l);
    l->path = path;
    mesh_name(path, l->name, sizeof l->name);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    lo.part = part;
    cli_mesh lm;
    int rc = cli_mesh_load(&lm, path, &lo, vis, 0, (size_t)8 << 20, grow, 1);
    /* the arena is all a bench keeps, and the hull's map */
    l->buf = lm.buf;
    l->arena = lm.arena;
    l->mesh = lm.mesh;
    if (part == SILK_PART_HULL) {
        l->file = lm.file;
        l->file_len = lm.file_len;
        if (!rc && clip) rc = cli_silmap(lm.file, lm.file_len, lm.name, &l->silmap);
        if (!rc && siltex) rc = cli_siltex(lm.file, lm.file_len, lm.name, &l->siltex);
    } else {
        free(lm.file);
    }
    return rc;
}

static void unload(loaded *l)
{
    if (l->hull) {
        unload(l->hull);
        free(l->hull);
    }
    free(l->file);
    free(l->buf);
    memset(l, 0, sizeof *l);
}

/* View k of the path around m, framed as silk render frames the model (the
 * sphere around it just fits), so view 0 is silk render's default camera. */
static int path_camera(const silk_mesh *m, const silk_mesh *also, const bench_cfg *c, int k, int proj,
                       silk_camera *cam)
{
    const double deg = CLI_DEG;
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    o.width = c->width;
    o.height = c->height;
    o.ortho = proj == PROJ_ORTHO;
    o.ortho_auto = o.ortho;

    double ctr[3];
    double r = cli_mesh_radius(m, ctr);
    double half_v = o.fov * deg / 2, half_h = atan(tan(half_v) * c->width / c->height);
    double half = half_v < half_h ? half_v : half_h;
    double dist = o.ortho ? 2 * r : r / sin(half);
    double t = 2 * CLI_PI * k / c->views;
    double az = CLI_VIEW_AZIMUTH * deg + t, el = PATH_ELEVATION * deg * cos(t);
    double dir[3] = { cos(el) * sin(az), sin(el), cos(el) * cos(az) };
    o.have_eye = 1;
    for (int i = 0; i < 3; i++) o.eye[i] = ctr[i] + dir[i] * dist;
    return cli_camera(&o, m, also, cam);
}

/* ---- measuring ----------------------------------------------------------------------- */

typedef struct frame_buf {
    silk_target target;
    uint8_t *color;
    uint32_t *depth;
    uint8_t *mask, *ref;       /* this frame's mask, the fine mesh's */
} frame_buf;

/* One mode (or the fine mesh) in one projection, summed over the views. */
typedef struct acc {
    double ms[MAX_VIEWS];
    double drawn, err_mean, err_max, err_worst_mean, hausdorff, outside, inside;
    size_t peak;
    int views, fell_back, failed;
} acc;

typedef struct ctx {
    const bench_cfg *cfg;
    progress pr;               /* over the views of one mesh, both projections */
    frame_buf fb;
    silk_phong phong;
    silk_hal hal;
} ctx;

static int dump_frame(const ctx *x, const char *mesh, int proj, int k, const char *mode)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s-%s-%02d-%s.png", x->cfg->dump, mesh, proj_name[proj], k, mode);
    silk_error err;
    if (silk_png_write(&x->fb.target, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

/* Render once for the statistics and the mask, then reps more times for
 * the clock; the arena's high-water mark is taken over all of them. */
static int measure(ctx *x, loaded *l, const silk_view *v, const silk_render_opts *ro, acc *a, int k)
{
    silk_frame_stats st;
    silk_error err;
    silk_arena *ar = &l->arena;
    ar->peak = ar->bottom + ar->top;
    memset(&st, 0, sizeof st);
    /* clip mode's error is that of its stencil, siltex mode's that of eq. 4
     * (pixel centres, as every mode draws them); their time includes the
     * anti-aliased outline */
    silk_render_opts shown = *ro;
    if (ro->mode == SILK_MODE_CLIP || ro->mode == SILK_MODE_SILTEX) shown.aa = 0;
    if (silk_render(ar, &l->mesh, v, &x->hal, &shown, &x->fb.target, &st, &err) != SILK_OK) {
        a->failed = 1;
        return cli_fail(CLI_EXIT_INPUT, "bench: %s: %s", l->path, err.msg);
    }
    a->drawn += st.tris_drawn;
    a->fell_back |= st.fell_back;
    double best = INFINITY;
    silk_frame_stats ignored;
    for (int r = 0; r < x->cfg->reps; r++) {
        double t0 = now_ms();
        silk_render(ar, &l->mesh, v, &x->hal, ro, &x->fb.target, &ignored, &err);
        double t = now_ms() - t0;
        if (t < best) best = t;
    }
    a->ms[k] = best;
    if (ar->peak > a->peak) a->peak = ar->peak;
    a->views++;
    mask_from_rgb(x->fb.color, x->fb.target.stride, x->cfg->width, x->cfg->height, x->cfg->bg, x->fb.mask);
    return 0;
}

static void add_error(acc *a, const mask_stats *ms)
{
    a->err_mean += ms->mean_px;
    a->hausdorff += ms->hausdorff_px;
    if (ms->length_a > 0) {
        a->outside += (double)ms->only_b / ms->length_a;
        a->inside += (double)ms->only_a / ms->length_a;
    }
    if (ms->hausdorff_px > a->err_max) a->err_max = ms->hausdorff_px;
    if (ms->mean_px > a->err_worst_mean) a->err_worst_mean = ms->mean_px;
}

/* What a device keeps in flash to draw the model in a mode: the mesh the
 * mode draws as `silk pack` writes it - the compact model (--flat for flat
 * frames, with its corner table for the others), or where the mesh cannot
 * be compact its arrays (without tri_edge and edge_feature, which the
 * renderer derives; the optional visibility hierarchy left out) - and the
 * prepared file's silhouette data: the map (SMAP) for clip mode, the
 * texture (STEX) for siltex mode.
 * docs/measurements.md, "bytes". */
static size_t model_bytes(const loaded *l, silk_mode mode)
{
    size_t n;
    compact_opts co = compact_opts_default();
    co.adjacency = mode != SILK_MODE_FLAT;
    uint8_t *cm = NULL;
    char why[200];
    if (!l->mesh.packed.base && compact_encode(&l->mesh, &co, &cm, &n, why, sizeof why) == 0) {
        free(cm);
    } else {
        silk_mesh packed = l->mesh;
        packed.tri_edge = NULL;
        packed.edge_feature = NULL;
        silk_mesh_bytes mb;
        silk_mesh_bytes_used(&packed, &mb);
        n = l->mesh.packed.base ? l->file_len : mb.total;
    }
    silk_model m;
    silk_model_section sec;
    silk_error err;
    uint32_t type = mode == SILK_MODE_CLIP ? SILK_SECTION_SMAP : mode == SILK_MODE_SILTEX ? SILK_SECTION_STEX : 0;
    if (type && l->file && silk_model_open(l->file, l->file_len, l->name, &m, &err) == SILK_OK &&
        silk_model_find(&m, type, &sec))
        n += sec.size;
    return n;
}

static int push_row(row_list *L, const loaded *l, const char *mode, uint32_t level, int proj, int has_error, acc *a,
                    size_t bytes)
{
    if (L->n == L->cap) {
        int cap = L->cap ? 2 * L->cap : 32;
        row *r = realloc(L->r, (size_t)cap * sizeof *r);
        if (!r) return cli_fail(CLI_EXIT_INPUT, "out of memory");
        L->r = r;
        L->cap = cap;
    }
    row *r = &L->r[L->n++];
    memset(r, 0, sizeof *r);
    snprintf(r->mesh, sizeof r->mesh, "%s", l->name);
    snprintf(r->mode, sizeof r->mode, "%s", mode);
    r->level = level;
    r->proj = proj;
    r->has_error = has_error;
    r->fell_back = a->fell_back;
    r->tris_in = l->mesh.ntris;
    int n = a->views;
    r->drawn = a->drawn / n;
    r->ms = median(a->ms, n);
    r->err_mean = has_error ? a->err_mean / n : NAN;
    r->err_max = has_error ? a->err_max : NAN;
    r->err_worst_mean = has_error ? a->err_worst_mean : NAN;
    r->hausdorff_mean = has_error ? a->hausdorff / n : NAN;
    r->outside = has_error ? a->outside / n : NAN;
    r->inside = has_error ? a->inside / n : NAN;
    r->arena_peak = a->peak;
    r->bytes = bytes;
    return 0;
}

static void print_row(const row *r)
{
    printf("bench %s %s %s triangles=%u drawn=%.0f ms=%.3f fps=%.1f", r->mesh, r->mode, proj_name[r->proj],
           r->tris_in, r->drawn, r->ms, 1000 / r->ms);
    if (r->has_error) printf(" error_mean_px=%.3f error_max_px=%.3f", r->err_mean, r->err_max);
    printf(" arena_bytes=%zu bytes=%zu%s\n", r->arena_peak, r->bytes, r->fell_back ? " fell_back=1" : "");
    fflush(stdout);
}

/* All modes of one coarse mesh (and its fine reference, if any), one
 * projection: view by view, the fine mesh first, then every mode. */
static int bench_proj(ctx *x, loaded *coarse, loaded *fine, uint32_t modes, int proj, acc *mode_acc, acc *fine_acc)
{
    const bench_cfg *c = x->cfg;
    int rc = 0;
    int nproj = c->proj_mask == 3 ? 2 : 1, before = c->proj_mask == 3 ? proj : 0;
    for (int k = 0; k < c->views; k++) {
        progress_update(&x->pr, before * c->views + k, nproj * c->views);
        silk_camera cam;
        silk_view view;
        silk_error err;
        /* one camera for every mode, near and far bracketing the hull too */
        int r = path_camera(&coarse->mesh, coarse->hull ? &coarse->hull->mesh : NULL, c, k, proj, &cam);
        if (r) return r;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s: %s", coarse->path, err.msg);
        silk_phong_default(&x->phong, &view);   /* the benchmark's look is fixed */
        silk_hal_phong(&x->hal, &x->phong);

        silk_render_opts ro;
        silk_render_opts_default(&ro);
        ro.bg_rgb = c->bg;
        if (c->tolerance) ro.tolerance_px = c->tolerance;
        if (fine) {
            ro.mode = SILK_MODE_FLAT;
            if ((r = measure(x, fine, &view, &ro, fine_acc, k)) != 0) return r;
            memcpy(x->fb.ref, x->fb.mask, (size_t)c->width * c->height);
            if (c->dump && (r = dump_frame(x, coarse->name, proj, k, "fine")) != 0) return r;
        }
        for (int m = 0; m < c->nmodes; m++) {
            acc *a = &mode_acc[m];
            if (a->failed || !(modes >> m & 1)) continue;
            ro.mode = c->mode[m].mode;
            ro.aa = !c->mode[m].aa_off;
            if (c->mode[m].level) ro.level = c->mode[m].level;
            loaded *drawn = coarse;
            if (ro.mode == SILK_MODE_CLIP || ro.mode == SILK_MODE_SILTEX) {
                drawn = coarse->hull;
                ro.silmap = &drawn->silmap;
                ro.siltex = &drawn->siltex;
            }
            if (measure(x, drawn, &view, &ro, a, k) != 0) {
                rc = CLI_EXIT_INPUT;   /* reported; the other modes go on */
                continue;
            }
            if (fine) {
                mask_stats ms;
                if (mask_compare(x->fb.ref, x->fb.mask, c->width, c->height, &ms) != 0)
                    return cli_fail(CLI_EXIT_INPUT, "out of memory comparing masks");
                add_error(a, &ms);
            }
            if (c->dump && (r = dump_frame(x, coarse->name, proj, k, c->mode[m].name)) != 0) return r;
        }
    }
    return rc;
}

static int bench_mesh(ctx *x, const char *coarse_path, const char *fine_path, uint32_t modes, row_list *rows)
{
    const bench_cfg *c = x->cfg;
    int rc = 0;
    for (int grow = 0;; grow += 2) {
        loaded coarse, fine;
        memset(&fine, 0, sizeof fine);
        rc = 0;
        if ((rc = load_mesh(&coarse, coarse_path, 1, grow, SILK_PART_COARSE, 0, 0)) != 0) {
            unload(&coarse);
            return rc;
        }
        int clip = 0, siltex = 0;
        for (int m = 0; m < c->nmodes; m++) {
            clip |= (modes >> m & 1) && c->mode[m].mode == SILK_MODE_CLIP;
            siltex |= (modes >> m & 1) && c->mode[m].mode == SILK_MODE_SILTEX;
        }
        if ((clip || siltex) && (!(coarse.hull = malloc(sizeof *coarse.hull)) ||
                                 (rc = load_mesh(coarse.hull, coarse_path, 0, grow, SILK_PART_HULL, clip, siltex)) != 0)) {
            if (!coarse.hull) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
            unload(&coarse);
            return rc;
        }
        if (fine_path && (rc = load_mesh(&fine, fine_path, 0, 0, SILK_PART_COARSE, 0, 0)) != 0) {
            unload(&coarse);
            unload(&fine);
            return rc;
        }
        int first = rows->n, fell_back = 0;
        char label[96];
        snprintf(label, sizeof label, "bench %s", coarse.name);
        progress_start(&x->pr, c->quiet, label);
        acc *mode_acc = malloc(MAX_MODES * sizeof *mode_acc), fine_acc;
        if (!mode_acc) {
            unload(&coarse);
            unload(&fine);
            return cli_fail(CLI_EXIT_INPUT, "out of memory");
        }
        for (int proj = 0; proj < 2 && rc != CLI_EXIT_USAGE; proj++) {
            if (!(c->proj_mask >> proj & 1)) continue;
            memset(mode_acc, 0, MAX_MODES * sizeof *mode_acc);
            memset(&fine_acc, 0, sizeof fine_acc);
            int r = bench_proj(x, &coarse, fine_path ? &fine : NULL, modes, proj, mode_acc, &fine_acc);
            if (r) rc = r;
            if (r && fine_acc.views < c->views && fine_path) break;   /* could not even draw the reference */
            for (int m = 0; m < c->nmodes; m++) {
                if (!(modes >> m & 1) || mode_acc[m].failed || mode_acc[m].views < c->views) continue;
                fell_back |= mode_acc[m].fell_back;
                int hull = c->mode[m].mode == SILK_MODE_CLIP || c->mode[m].mode == SILK_MODE_SILTEX;
                size_t bytes = model_bytes(hull ? coarse.hull : &coarse, c->mode[m].mode);
                if (push_row(rows, &coarse, c->mode[m].name, c->mode[m].level, proj, fine_path != NULL, &mode_acc[m],
                             bytes))
                    rc = CLI_EXIT_INPUT;
            }
            if (fine_path && fine_acc.views == c->views) {
                /* the reference itself: error 0 by definition */
                fine_acc.err_mean = fine_acc.err_max = fine_acc.err_worst_mean = fine_acc.hausdorff = 0;
                fine_acc.outside = fine_acc.inside = 0;
                if (push_row(rows, &fine, "fine", 0, proj, 1, &fine_acc, model_bytes(&fine, SILK_MODE_FLAT)))
                    rc = CLI_EXIT_INPUT;
                else snprintf(rows->r[rows->n - 1].mesh, sizeof rows->r[0].mesh, "%s", coarse.name);
            }
        }
        progress_end(&x->pr);
        free(mode_acc);
        unload(&coarse);
        unload(&fine);
        /* Numbers from frames that ran short of arena are not the mode's:
         * measure again with a larger arena. */
        if (fell_back && grow < 6) {
            rows->n = first;
            continue;
        }
        if (!(c->json && silk_path_is_stdio(c->json)))
            for (int i = first; i < rows->n; i++) print_row(&rows->r[i]);
        if (fell_back)
            fprintf(stderr, "silk: warning: bench: %s: frames ran out of arena even at %zu x the default\n",
                    coarse_path, (size_t)1 << grow);
        return rc;
    }
}

/* ---- output ---------------------------------------------------------------------------- */

static void csv_num(FILE *f, double v, const char *fmt)
{
    fputc(',', f);
    if (!isnan(v)) {
        if (isinf(v)) fputs("inf", f);
        else fprintf(f, fmt, v);
    }
}

static int write_csv(const char *path, const row_list *L, const bench_cfg *c)
{
    silk_outfile o;
    silk_error err;
    if (silk_outfile_open(&o, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    FILE *f = o.fp;
    fprintf(f, "mesh,mode,level,projection,triangles_in,triangles_drawn,ms_per_frame,error_mean_px,error_max_px,"
               "arena_peak_bytes,fps,views,width,height,error_worst_view_mean_px,hausdorff_mean_px,error_outside_px,"
               "error_inside_px,fell_back,bytes\n");
    for (int i = 0; i < L->n; i++) {
        const row *r = &L->r[i];
        fprintf(f, "%s,%s,", r->mesh, r->mode);
        if (r->level) fprintf(f, "%u", r->level);
        fprintf(f, ",%s,%u", proj_name[r->proj], r->tris_in);
        csv_num(f, r->drawn, "%.1f");
        csv_num(f, r->ms, "%.4f");
        csv_num(f, r->err_mean, "%.4f");
        csv_num(f, r->err_max, "%.4f");
        fprintf(f, ",%zu", r->arena_peak);
        csv_num(f, 1000 / r->ms, "%.1f");
        fprintf(f, ",%d,%d,%d", c->views, c->width, c->height);
        csv_num(f, r->err_worst_mean, "%.4f");
        csv_num(f, r->hausdorff_mean, "%.4f");
        csv_num(f, r->outside, "%.4f");
        csv_num(f, r->inside, "%.4f");
        fprintf(f, ",%d,%zu\n", r->fell_back, r->bytes);
    }
    if (silk_outfile_commit(&o, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

/* The CSV's rows and columns as a JSON array of objects; numbers that are
 * not known (no fine mesh) or not finite are null. */
static void json_num(FILE *f, const char *name, double v, const char *fmt)
{
    fprintf(f, ", \"%s\": ", name);
    if (isnan(v) || isinf(v)) fputs("null", f);
    else fprintf(f, fmt, v);
}

static int write_json(const char *path, const row_list *L, const bench_cfg *c)
{
    silk_outfile o;
    silk_error err;
    if (silk_outfile_open(&o, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    FILE *f = o.fp;
    fputs("[", f);
    for (int i = 0; i < L->n; i++) {
        const row *r = &L->r[i];
        fprintf(f, "%s\n  {\"schema\": \"silk-bench/1\", \"mesh\": ", i ? "," : "");
        cli_json_string(f, r->mesh);
        fprintf(f, ", \"mode\": ");
        cli_json_string(f, r->mode);
        if (r->level) fprintf(f, ", \"level\": %u", r->level);
        else fputs(", \"level\": null", f);
        fprintf(f, ", \"projection\": \"%s\", \"triangles_in\": %u", proj_name[r->proj], r->tris_in);
        json_num(f, "triangles_drawn", r->drawn, "%.1f");
        json_num(f, "ms_per_frame", r->ms, "%.4f");
        json_num(f, "error_mean_px", r->err_mean, "%.4f");
        json_num(f, "error_max_px", r->err_max, "%.4f");
        fprintf(f, ", \"arena_peak_bytes\": %zu", r->arena_peak);
        json_num(f, "fps", 1000 / r->ms, "%.1f");
        fprintf(f, ", \"views\": %d, \"width\": %d, \"height\": %d", c->views, c->width, c->height);
        json_num(f, "error_worst_view_mean_px", r->err_worst_mean, "%.4f");
        json_num(f, "hausdorff_mean_px", r->hausdorff_mean, "%.4f");
        json_num(f, "error_outside_px", r->outside, "%.4f");
        json_num(f, "error_inside_px", r->inside, "%.4f");
        fprintf(f, ", \"fell_back\": %s, \"bytes\": %zu}", r->fell_back ? "true" : "false", r->bytes);
    }
    fputs(L->n ? "\n]\n" : "]\n", f);
    if (silk_outfile_commit(&o, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

static const row *find_row(const row_list *L, const char *mesh, const char *mode, int proj)
{
    for (int i = 0; i < L->n; i++)
        if (strcmp(L->r[i].mesh, mesh) == 0 && strcmp(L->r[i].mode, mode) == 0 && L->r[i].proj == proj) return &L->r[i];
    return NULL;
}

/* "a / b" of two projections' values, or the one there is. */
static void md_pair(FILE *f, const row *o, const row *p, double (*get)(const row *), const char *fmt)
{
    char a[32] = "", b[32] = "";
    if (o) snprintf(a, sizeof a, fmt, get(o));
    if (p) snprintf(b, sizeof b, fmt, get(p));
    fprintf(f, " %s%s%s |", a, o && p ? " / " : "", b);
}

static double get_drawn(const row *r) { return r->drawn; }
static double get_ms(const row *r) { return r->ms; }
static double get_fps(const row *r) { return 1000 / r->ms; }
static double get_err_mean(const row *r) { return r->err_mean; }
static double get_err_max(const row *r) { return r->err_max; }
static double get_outside(const row *r) { return r->outside; }

/* The mean over the projections measured of a row's value. */
static double both(const row_list *L, const char *mesh, const char *mode, double (*get)(const row *))
{
    double s = 0;
    int n = 0;
    for (int p = 0; p < 2; p++) {
        const row *r = find_row(L, mesh, mode, p);
        if (r) s += get(r), n++;
    }
    return n ? s / n : NAN;
}

/* What smooth mode aims for against flat and PN level 3, checked on the
 * numbers measured: for each mesh with a fine reference and the modes
 * involved. */
static void md_checks(FILE *f, const row_list *L)
{
    int header = 0;
    for (int i = 0; i < L->n; i++) {
        const row *r = &L->r[i];
        if (strcmp(r->mode, "smooth") != 0 || !r->has_error) continue;
        const row *other = find_row(L, r->mesh, "smooth", PROJ_ORTHO + PROJ_PERSP - r->proj);
        if (other && other < r) continue;   /* one line per mesh, at its first smooth row */
        double s_err = both(L, r->mesh, "smooth", get_err_mean), f_err = both(L, r->mesh, "flat", get_err_mean);
        double p_err = both(L, r->mesh, "pn3", get_err_mean);
        double s_drawn = both(L, r->mesh, "smooth", get_drawn), p_drawn = both(L, r->mesh, "pn3", get_drawn);
        if (!header) {
            fprintf(f, "\n### Smooth mode against flat and PN level 3\n\n"
                       "Mean silhouette error and triangles drawn, averaged over both projections.\n"
                       "Smooth mode aims for: error <= 0.5 x flat's, error <= PN3's, and\n"
                       "triangles <= 0.25 x PN3's.\n\n"
                       "| mesh | smooth / flat error | smooth / PN3 error | smooth / PN3 triangles | all three met |\n"
                       "|---|---|---|---|---|\n");
            header = 1;
        }
        fprintf(f, "| %s |", r->mesh);
        int ok = 1, known = 1;
        double ratio[3] = { s_err / f_err, s_err / p_err, s_drawn / p_drawn }, limit[3] = { 0.5, 1.0, 0.25 };
        for (int k = 0; k < 3; k++) {
            if (isnan(ratio[k]) || isinf(ratio[k])) {
                fprintf(f, " n/a |");
                known = 0;
                continue;
            }
            int met = ratio[k] <= limit[k];
            ok &= met;
            fprintf(f, " %.2f (%s) |", ratio[k], met ? "met" : "NOT met");
        }
        fprintf(f, " %s |\n", known ? (ok ? "yes" : "no") : "n/a");
    }
}

static int write_md(const char *path, const row_list *L, const bench_cfg *c)
{
    silk_outfile o;
    silk_error err;
    if (silk_outfile_open(&o, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    FILE *f = o.fp;
    fprintf(f,
            "## silk bench: render modes\n\n"
            "%dx%d pixels, %d views per projection along the camera path of docs/measurements.md,\n"
            "time = median over the views of the fastest of %d renders (one core, this machine).\n"
            "Error = silhouette of the mode against the fine mesh drawn flat from the same camera:\n"
            "mean = differing pixels / outline length, averaged over the views;\n"
            "max = the largest Hausdorff distance between the outlines in any view.\n"
            "Pairs are orthographic / perspective.  Arena = high-water mark of the mesh, its\n"
            "visibility hierarchy and the frame's scratch (the frame buffer is not in it).\n"
            "Flash = the model's data a device keeps in flash for the mode: the mesh it draws\n"
            "and, for clip and siltex modes, the silhouette map or texture.\n"
            "Outside = the share of the differing pixels that the mode covers and the fine mesh\n"
            "does not (the rest is fine mesh the mode misses).\n"
            "Mode `fine` is the reference mesh itself, drawn flat.\n\n"
            "| mesh | triangles | mode | drawn | ms | fps | error mean px | outside | error max px | arena KiB | flash KiB |\n"
            "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
            c->width, c->height, c->views, c->reps);
    for (int i = 0; i < L->n; i++) {
        const row *r = &L->r[i];
        /* one line per mesh and mode: skip the second projection's row */
        int seen = 0;
        for (int j = 0; j < i; j++)
            if (strcmp(L->r[j].mesh, r->mesh) == 0 && strcmp(L->r[j].mode, r->mode) == 0) seen = 1;
        if (seen) continue;
        const row *ro = find_row(L, r->mesh, r->mode, PROJ_ORTHO), *rp = find_row(L, r->mesh, r->mode, PROJ_PERSP);
        size_t peak = 0;
        if (ro && ro->arena_peak > peak) peak = ro->arena_peak;
        if (rp && rp->arena_peak > peak) peak = rp->arena_peak;
        fprintf(f, "| %s | %u | %s%s |", r->mesh, r->tris_in, r->mode, r->fell_back ? " (fell back)" : "");
        md_pair(f, ro, rp, get_drawn, "%.0f");
        md_pair(f, ro, rp, get_ms, "%.2f");
        md_pair(f, ro, rp, get_fps, "%.0f");
        if (r->has_error) {
            double out = both(L, r->mesh, r->mode, get_outside), all = both(L, r->mesh, r->mode, get_err_mean);
            md_pair(f, ro, rp, get_err_mean, "%.2f");
            if (all > 0) fprintf(f, " %.0f%% |", 100 * out / all);
            else fprintf(f, " - |");
            md_pair(f, ro, rp, get_err_max, "%.1f");
        } else {
            fprintf(f, " - | - | - |");
        }
        fprintf(f, " %.0f | %.1f |\n", peak / 1024.0, r->bytes / 1024.0);
    }
    md_checks(f, L);
    if (silk_outfile_commit(&o, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

static uint32_t mode_rgb(const char *name, int i)
{
    if (strcmp(name, "flat") == 0) return 0x8C8C8C;
    if (strcmp(name, "smooth") == 0) return 0x2A7AB0;
    if (strcmp(name, "blend") == 0) return 0x3AA05A;
    if (strcmp(name, "pn1") == 0) return 0xF0C060;
    if (strcmp(name, "pn2") == 0) return 0xE0A030;
    if (strcmp(name, "pn3") == 0) return 0xC0502A;
    static const uint32_t other[] = { 0x8E5AB0, 0xB05A8E, 0x5AB0A8, 0x705030 };
    return other[i % 4];
}

static int write_plot(const char *path, const row_list *L, const bench_cfg *c)
{
    const char *groups[256];
    int ng = 0;
    for (int i = 0; i < L->n && ng < 256; i++) {
        int seen = 0;
        for (int g = 0; g < ng; g++) seen |= strcmp(groups[g], L->r[i].mesh) == 0;
        if (!seen) groups[ng++] = L->r[i].mesh;
    }
    if (!ng) return cli_fail(CLI_EXIT_INPUT, "%s: nothing was measured, no chart", path);
    const char *series[MAX_MODES];
    uint32_t rgb[MAX_MODES];
    for (int m = 0; m < c->nmodes; m++) {
        series[m] = c->mode[m].name;
        rgb[m] = mode_rgb(series[m], m);
    }
    double *ms = malloc(sizeof(double) * (size_t)ng * c->nmodes), *er = malloc(sizeof(double) * (size_t)ng * c->nmodes);
    if (!ms || !er) {
        free(ms), free(er);
        return cli_fail(CLI_EXIT_INPUT, "out of memory");
    }
    for (int g = 0; g < ng; g++)
        for (int m = 0; m < c->nmodes; m++) {
            ms[g * c->nmodes + m] = both(L, groups[g], series[m], get_ms);
            const row *r = find_row(L, groups[g], series[m], PROJ_ORTHO);
            if (!r) r = find_row(L, groups[g], series[m], PROJ_PERSP);
            er[g * c->nmodes + m] = r && r->has_error ? both(L, groups[g], series[m], get_err_mean) : NAN;
        }
    char title[128], note[256];
    snprintf(title, sizeof title, "silk bench: %dx%d, %d views x %s", c->width, c->height, c->views,
             c->proj_mask == 3 ? "2 projections" : proj_name[c->proj_mask == 1 ? PROJ_ORTHO : PROJ_PERSP]);
    snprintf(note, sizeof note, "values: mean over the projections; time: median over the views of the fastest "
                                "of %d renders", c->reps);
    plot_panel panels[2] = {
        { "time per frame", "ms per frame", ms },
        { "silhouette error against the fine mesh", "mean error, px", er },
    };
    plot_chart chart = { title, note, ng, c->nmodes, 2, groups, series, rgb, panels };
    silk_error err;
    silk_status s = plot_write_png(&chart, path, &err);
    free(ms), free(er);
    if (s != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

/* Error against bytes: a series per mode (and the fine meshes drawn flat),
 * a point per coarse mesh, in the order of their bytes. */
static int write_plot_bytes(const char *path, const row_list *L, const bench_cfg *c)
{
    int ns = c->nmodes + 1, cap = L->n ? L->n : 1;
    plot_series series[MAX_MODES + 1];
    double *x = malloc(sizeof(double) * (size_t)cap * ns), *y = malloc(sizeof(double) * (size_t)cap * ns);
    const char **label = malloc(sizeof(char *) * (size_t)cap * ns);
    if (!x || !y || !label) {
        free(x), free(y), free(label);
        return cli_fail(CLI_EXIT_INPUT, "out of memory");
    }
    for (int m = 0; m < ns; m++) {
        const char *mode = m < c->nmodes ? c->mode[m].name : "fine";
        double *sx = x + (size_t)m * cap, *sy = y + (size_t)m * cap;
        const char **sl = label + (size_t)m * cap;
        int n = 0;
        for (int i = 0; i < L->n; i++) {
            const row *r = &L->r[i], *first = find_row(L, r->mesh, mode, PROJ_ORTHO);
            if (strcmp(r->mode, mode) != 0 || !r->has_error) continue;
            if (!first) first = find_row(L, r->mesh, mode, PROJ_PERSP);
            if (first != r) continue;          /* one point per mesh */
            int k = n++;                       /* insertion by bytes */
            for (; k > 0 && sx[k - 1] > (double)r->bytes; k--) sx[k] = sx[k - 1], sy[k] = sy[k - 1], sl[k] = sl[k - 1];
            sx[k] = (double)r->bytes;
            sy[k] = both(L, r->mesh, mode, get_err_mean);
            sl[k] = m < c->nmodes ? r->mesh : NULL;
        }
        series[m] = (plot_series){ m < c->nmodes ? mode : "detailed mesh, flat",
                                   m < c->nmodes ? mode_rgb(mode, m) : 0x202020u, n, sx, sy, sl };
    }
    char title[128], note[256];
    snprintf(title, sizeof title, "silk bench: silhouette error against model bytes, %dx%d", c->width, c->height);
    snprintf(note, sizeof note, "error: mean over %d views x %s; bytes: the mesh drawn and its silhouette data, "
             "as a device keeps them in flash", c->views,
             c->proj_mask == 3 ? "2 projections" : proj_name[c->proj_mask == 1 ? PROJ_ORTHO : PROJ_PERSP]);
    plot_xy chart = { title, note, "model bytes in flash, KiB", "mean error, px", 1024, ns, series };
    silk_error err;
    silk_status st = plot_xy_write_png(&chart, path, &err);
    free(x), free(y), free(label);
    if (st != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

/* ---- the command ------------------------------------------------------------------------ */

int cmd_bench(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--visibility-pass") == 0) return bench_visibility(argc, argv);
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--grid") == 0) return bench_grid(argc, argv);

    bench_cfg c;
    bench_defaults(&c);
    c.coarse = calloc((size_t)argc, sizeof *c.coarse);
    c.fine = calloc((size_t)argc, sizeof *c.fine);
    c.pair_buf = calloc((size_t)argc, sizeof *c.pair_buf);
    c.pair_modes = calloc((size_t)argc, sizeof *c.pair_modes);
    uint32_t *mode_mask = calloc((size_t)argc, sizeof *mode_mask);
    int rc = 0, n = 0;
    const char **coarse = c.coarse, **fine = c.fine;
    cli_args args = { 0, NULL, 0, { NULL } };
    void *bases[] = { &c };
    if (!c.coarse || !c.fine || !c.pair_buf || !c.pair_modes || !mode_mask) {
        rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
        goto done;
    }
    rc = cli_parse(&cmd_bench_spec, bases, argc, argv, &args);
    if (rc == CLI_HELP) {
        rc = 0;
        goto done;
    }
    n = c.n;
    if (!rc && n == 0) rc = cli_fail(CLI_EXIT_USAGE, "bench: no mesh given (silk bench MESH... or --pair COARSE:FINE)");
    for (int i = 0; i < n && !rc; i++) rc = pair_mode_mask(c.pair_modes[i], &c, &mode_mask[i]);
    if (!rc && c.dump) rc = cli_make_dir(c.dump);
    if (rc) goto done;

    ctx x;
    memset(&x, 0, sizeof x);
    x.cfg = &c;
    size_t px = (size_t)c.width * c.height;
    x.fb.color = malloc(px * 3);
    x.fb.depth = malloc(px * sizeof *x.fb.depth);
    x.fb.mask = malloc(px);
    x.fb.ref = malloc(px);
    row_list rows = { NULL, 0, 0 };
    if (!x.fb.color || !x.fb.depth || !x.fb.mask || !x.fb.ref) {
        rc = cli_fail(CLI_EXIT_INPUT, "out of memory for a %dx%d frame", c.width, c.height);
    } else {
        silk_target_init(&x.fb.target, c.width, c.height, 0, c.height, SILK_PIX_RGB888, x.fb.color, x.fb.depth);
        for (int i = 0; i < n; i++) {
            int r = bench_mesh(&x, coarse[i], fine[i], mode_mask[i], &rows);
            if (r) rc = r;
        }
        if (c.csv && rows.n) rc |= write_csv(c.csv, &rows, &c);
        if (c.json) rc |= write_json(c.json, &rows, &c);
        if (c.md && rows.n) rc |= write_md(c.md, &rows, &c);
        if (c.plot && rows.n) rc |= write_plot(c.plot, &rows, &c);
        if (c.plot_bytes && rows.n) rc |= write_plot_bytes(c.plot_bytes, &rows, &c);
        if (rc) rc = CLI_EXIT_INPUT;
    }
    free(rows.r);
    free(x.fb.color), free(x.fb.depth), free(x.fb.mask), free(x.fb.ref);
done:
    if (c.pair_buf)
        for (int i = 0; i < argc; i++) free(c.pair_buf[i]);
    free(c.pair_buf), free(c.coarse), free(c.fine), free(c.pair_modes), free(mode_mask), cli_args_free(&args);
    return rc;
}
