/*
 * bench_grid.c - `silk bench --grid COARSE[:FINE]...`: is smooth mode's
 * outline ever visibly worse than the mesh it smooths?  Each mesh is drawn
 * from a grid of views about silk render's default framing (24 yaws every
 * 15 degrees x pitches -60, -30, 0, 30, 60 by default; 320x240, outlines
 * not anti-aliased), flat and smooth, and its detailed model (FINE) flat
 * from the same camera.  Per view, from the three object masks:
 *
 *   lost    pixels at least 3 px inside both the flat object and the
 *           detailed one (distance from the pixel centre to the nearest
 *           background pixel centre) that smooth leaves uncovered: a notch,
 *           a bite or a tear where the two references agree there is
 *           surface.  Without FINE, inside the flat object alone.
 *   hole    the largest enclosed background region of the smooth frame (not
 *           connected to the image border), counted in the pixels of it
 *           that lie 3 px inside both references as lost pixels do (a real
 *           hole, the torus's, grows or shrinks along its rim: not that).
 *   bulge   how far smooth's object reaches outside flat's: the largest
 *           distance in px from a smooth pixel to the nearest flat pixel.
 *   excess  the same outside both flat's and the detailed object.
 *
 * The worst views of each mesh are printed with the `silk render` command
 * that shows them.  The views are drawn by as many threads as --threads
 * (default: the processors online), each with its own copy of the meshes
 * and its own frame; the results do not depend on the threads.  Defined in
 * docs/measurements.md ("The robustness grid").
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "commands.h"
#include "opt.h"
#include "image/mask.h"
#include "progress.h"
#include "platform/platform.h"

#define GRID_MAX_PITCHES 16
#define GRID_MAX_THREADS 16
#define GRID_INSIDE_PX 3           /* "lying 3 px or more inside" */

typedef struct grid_cfg {
    int yaws, npitch;
    double pitch[GRID_MAX_PITCHES];
    int width, height, threads, worst;
    silk_fx tolerance;           /* 0: the library's default */
    long max_lost, max_hole;     /* -1: not checked */
    const char *md, *csv, *dump;
    int quiet;
    int grid;                    /* --grid: what `silk bench` dispatches on */
} grid_cfg;

/* What one view measured. */
typedef struct grid_view {
    double yaw, pitch;
    uint32_t lost, hole, hole_px;   /* lost pixels; the largest hole; all hole pixels */
    double bulge, excess;
    uint32_t flat_segments;      /* concave segments left to the coarse outline (silk_frame_stats) */
    int box[4];                  /* x0, y0, x1, y1 of the lost pixels (x1 < x0: none) */
    int fell_back, failed;
} grid_view;

/* One mesh's grid: the views, handed out to the threads one at a time. */
typedef struct grid_job {
    const grid_cfg *cfg;
    const char *coarse, *fine;
    grid_view *views;
    int nviews;
    int next, done;              /* under lock */
    int rc;
    pthread_mutex_t lock;
    progress pr;
} grid_job;

/* ---- one view --------------------------------------------------------------------- */

/* A thread's frame and scratch: the three masks and the distance maps. */
typedef struct grid_frame {
    silk_target target;
    uint8_t *color;
    uint32_t *depth;
    uint8_t *flat, *smooth, *fine, *tmp;
    uint32_t *d_flat, *d_fine, *d_out, *queue;
} grid_frame;

static int frame_alloc(grid_frame *f, int w, int h)
{
    size_t px = (size_t)w * h;
    memset(f, 0, sizeof *f);
    f->color = malloc(3 * px);
    f->depth = malloc(px * sizeof *f->depth);
    f->flat = malloc(px), f->smooth = malloc(px), f->fine = malloc(px), f->tmp = malloc(px);
    f->d_flat = malloc(px * 4), f->d_fine = malloc(px * 4), f->d_out = malloc(px * 4), f->queue = malloc(px * 4);
    if (!f->color || !f->depth || !f->flat || !f->smooth || !f->fine || !f->tmp || !f->d_flat || !f->d_fine ||
        !f->d_out || !f->queue)
        return -1;
    silk_target_init(&f->target, w, h, 0, h, SILK_PIX_RGB888, f->color, f->depth);
    return 0;
}

static void frame_free(grid_frame *f)
{
    free(f->color), free(f->depth), free(f->flat), free(f->smooth), free(f->fine), free(f->tmp);
    free(f->d_flat), free(f->d_fine), free(f->d_out), free(f->queue);
}

/* Draw m in mode into f's target; the object mask is where depth was
 * written (cleared to 0), so no colour can be mistaken for the background. */
static int draw(grid_frame *f, cli_mesh *m, const silk_view *v, silk_mode mode, silk_fx tol, uint8_t *mask,
                silk_frame_stats *st)
{
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;
    ro.aa = 0;
    if (tol) ro.tolerance_px = tol;
    silk_error err;
    if (silk_render(&m->arena, &m->mesh, v, &hal, &ro, &f->target, st, &err) != SILK_OK)
        return cli_fail(CLI_EXIT_INPUT, "bench --grid: %s: %s", m->name, err.msg);
    size_t px = (size_t)f->target.width * f->target.height;
    for (size_t i = 0; i < px; i++) mask[i] = f->depth[i] != 0;
    return 0;
}

/* d2[i]: squared distance from pixel i to the nearest pixel where m[i]
 * equals want. */
static int distance_to(const uint8_t *m, uint8_t want, int w, int h, uint8_t *tmp, uint32_t *d2)
{
    size_t px = (size_t)w * h;
    for (size_t i = 0; i < px; i++) tmp[i] = m[i] == want;
    return mask_distance2(tmp, w, h, d2);
}

/* The enclosed background regions of s (4-connected, not reaching the
 * image border): the largest and the total, counted in pixels where
 * cover[i] is set. */
static void holes(const uint8_t *s, const uint8_t *cover, int w, int h, uint8_t *seen, uint32_t *queue, uint32_t *largest,
                  uint32_t *total)
{
    size_t px = (size_t)w * h;
    memset(seen, 0, px);
    *largest = *total = 0;
    for (int pass = 0; pass < 2; pass++)   /* 0: what the border reaches; 1: the rest, region by region */
        for (size_t start = 0; start < px; start++) {
            int x0 = (int)(start % w), y0 = (int)(start / w);
            int border = x0 == 0 || y0 == 0 || x0 == w - 1 || y0 == h - 1;
            if (s[start] || seen[start] || (pass == 0 && !border)) continue;
            size_t head = 0, tail = 0;
            uint32_t n = 0;
            queue[tail++] = (uint32_t)start;
            seen[start] = 1;
            while (head < tail) {
                uint32_t i = queue[head++];
                int x = (int)(i % w), y = (int)(i / w);
                n += cover[i];
                const int nx[4] = { x - 1, x + 1, x, x }, ny[4] = { y, y, y - 1, y + 1 };
                for (int k = 0; k < 4; k++) {
                    if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
                    uint32_t j = (uint32_t)ny[k] * w + nx[k];
                    if (!s[j] && !seen[j]) {
                        seen[j] = 1;
                        queue[tail++] = j;
                    }
                }
            }
            if (pass == 1) {
                *total += n;
                if (n > *largest) *largest = n;
            }
        }
}

/* View gv's camera: silk render's default framing of the coarse mesh
 * turned by its yaw and pitch, as `silk render --yaw --pitch` makes it. */
static int view_of(const grid_cfg *c, const cli_mesh *coarse, const grid_view *gv, silk_view *view)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    o.width = c->width;
    o.height = c->height;
    o.yaw = gv->yaw;
    o.pitch = gv->pitch;
    silk_camera cam;
    silk_error err;
    int rc = cli_camera(&o, &coarse->mesh, NULL, &cam);
    if (!rc && silk_view_init(view, &cam, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s: %s", coarse->name, err.msg);
    return rc;
}

static int measure_view(const grid_cfg *c, grid_frame *f, cli_mesh *coarse, cli_mesh *fine, grid_view *gv)
{
    int w = c->width, h = c->height;
    size_t px = (size_t)w * h;
    silk_view view;
    int rc = view_of(c, coarse, gv, &view);
    if (rc) return rc;
    silk_frame_stats st;
    memset(&st, 0, sizeof st);
    if ((rc = draw(f, coarse, &view, SILK_MODE_FLAT, 0, f->flat, &st)) != 0) return rc;
    memset(&st, 0, sizeof st);
    if ((rc = draw(f, coarse, &view, SILK_MODE_SMOOTH, c->tolerance, f->smooth, &st)) != 0) return rc;
    gv->fell_back = st.fell_back;
    gv->flat_segments = st.flat_segments;
    if (fine && (rc = draw(f, fine, &view, SILK_MODE_FLAT, 0, f->fine, &st)) != 0) return rc;
    if (!fine) memcpy(f->fine, f->flat, px);

    /* inside: squared distance to the nearest background pixel */
    if (distance_to(f->flat, 0, w, h, f->tmp, f->d_flat) || distance_to(f->fine, 0, w, h, f->tmp, f->d_fine))
        return cli_fail(CLI_EXIT_INPUT, "out of memory");
    const uint32_t in2 = GRID_INSIDE_PX * GRID_INSIDE_PX;
    gv->lost = 0;
    gv->box[0] = gv->box[1] = INT32_MAX;
    gv->box[2] = gv->box[3] = -1;
    for (size_t i = 0; i < px; i++)
        if (!f->smooth[i] && f->flat[i] && f->fine[i] && f->d_flat[i] >= in2 && f->d_fine[i] >= in2) {
            int x = (int)(i % w), y = (int)(i / w);
            gv->lost++;
            if (x < gv->box[0]) gv->box[0] = x;
            if (y < gv->box[1]) gv->box[1] = y;
            if (x > gv->box[2]) gv->box[2] = x;
            if (y > gv->box[3]) gv->box[3] = y;
        }

    /* outside: squared distance to the nearest flat pixel, then to the nearest of either */
    if (distance_to(f->flat, 1, w, h, f->tmp, f->d_out)) return cli_fail(CLI_EXIT_INPUT, "out of memory");
    uint32_t b2 = 0, e2 = 0;
    for (size_t i = 0; i < px; i++)
        if (f->smooth[i] && !f->flat[i] && f->d_out[i] != MASK_FAR && f->d_out[i] > b2) b2 = f->d_out[i];
    for (size_t i = 0; i < px; i++) f->tmp[i] = f->flat[i] | f->fine[i];
    if (mask_distance2(f->tmp, w, h, f->d_out)) return cli_fail(CLI_EXIT_INPUT, "out of memory");
    for (size_t i = 0; i < px; i++)
        if (f->smooth[i] && !f->tmp[i] && f->d_out[i] != MASK_FAR && f->d_out[i] > e2) e2 = f->d_out[i];
    gv->bulge = sqrt((double)b2);
    gv->excess = sqrt((double)e2);

    for (size_t i = 0; i < px; i++) f->tmp[i] = f->flat[i] && f->fine[i] && f->d_flat[i] >= in2 && f->d_fine[i] >= in2;
    holes(f->smooth, f->tmp, w, h, (uint8_t *)f->d_out, f->queue, &gv->hole, &gv->hole_px);
    return 0;
}

/* ---- the threads ------------------------------------------------------------------ */

/* One thread's copies of the meshes, with room for a frame's scratch
 * besides each as silk bench gives it.  0, or an exit status after the
 * error. */
static int grid_load(const grid_job *j, cli_mesh *coarse, cli_mesh *fine)
{
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    memset(fine, 0, sizeof *fine);
    int rc = cli_mesh_load(coarse, j->coarse, &lo, 1, 0, (size_t)8 << 20, 0, 1);
    if (!rc && j->fine) rc = cli_mesh_load(fine, j->fine, &lo, 0, 0, (size_t)8 << 20, 0, 1);
    return rc;
}

/* Views handed out one at a time until none are left or one failed. */
static void grid_views(grid_job *j, cli_mesh *coarse, cli_mesh *fine, int rc)
{
    const grid_cfg *c = j->cfg;
    grid_frame f;
    memset(&f, 0, sizeof f);
    if (!rc && frame_alloc(&f, c->width, c->height)) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
    for (;;) {
        pthread_mutex_lock(&j->lock);
        if (rc && !j->rc) j->rc = rc;
        int k = j->rc ? j->nviews : j->next++;
        if (k < j->nviews) progress_update(&j->pr, j->done, j->nviews);
        pthread_mutex_unlock(&j->lock);
        if (k >= j->nviews) break;
        rc = measure_view(c, &f, coarse, j->fine ? fine : NULL, &j->views[k]);
        if (rc) j->views[k].failed = 1;
        pthread_mutex_lock(&j->lock);
        j->done++;
        pthread_mutex_unlock(&j->lock);
    }
    frame_free(&f);
}

static void *grid_worker(void *arg)
{
    grid_job *j = arg;
    cli_mesh coarse, fine;
    grid_views(j, &coarse, &fine, grid_load(j, &coarse, &fine));
    cli_mesh_free(&coarse);
    cli_mesh_free(&fine);
    return NULL;
}

static int threads_for(const grid_cfg *c, int nviews)
{
    long n = c->threads;
    if (n <= 0) n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > GRID_MAX_THREADS) n = GRID_MAX_THREADS;
    if (n > nviews) n = nviews;
    return (int)n;
}

static int run_job(grid_job *j)
{
    pthread_t th[GRID_MAX_THREADS];
    int n = threads_for(j->cfg, j->nviews), started = 0;
    pthread_mutex_init(&j->lock, NULL);
    char label[160];
    snprintf(label, sizeof label, "grid %s", j->coarse);
    progress_start(&j->pr, j->cfg->quiet, label);
    /* this thread's meshes first: a file that cannot be read is said once */
    cli_mesh coarse, fine;
    int rc = grid_load(j, &coarse, &fine);
    for (int i = 1; i < n && !rc; i++)
        if (pthread_create(&th[started], NULL, grid_worker, j) == 0) started++;
    if (!rc) grid_views(j, &coarse, &fine, 0);
    else j->rc = rc;
    for (int i = 0; i < started; i++) pthread_join(th[i], NULL);
    cli_mesh_free(&coarse);
    cli_mesh_free(&fine);
    progress_end(&j->pr);
    pthread_mutex_destroy(&j->lock);
    return j->rc;
}

/* ---- pictures of the worst views -------------------------------------------------- */

/* View v as DIR/MESH-yYAW-pPITCH.png: flat, smooth and the detailed model
 * side by side (shaded, as measured), cropped round the lost pixels (the
 * whole frame when none) and magnified; smooth's lost pixels red. */
static int dump_view(const grid_cfg *c, cli_mesh *coarse, cli_mesh *fine, const char *name, const grid_view *v)
{
    int w = c->width, h = c->height, rc = 0;
    size_t px = (size_t)w * h;
    grid_frame f;
    uint8_t *shot[3] = { NULL, NULL, NULL }, *out = NULL;
    if (frame_alloc(&f, w, h)) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
    silk_view view;
    silk_error err;
    silk_frame_stats st;
    if (!rc) rc = view_of(c, coarse, v, &view);
    const silk_mode mode[3] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH, SILK_MODE_FLAT };
    uint8_t *mask[3] = { f.flat, f.smooth, f.fine };
    for (int i = 0; i < 3 && !rc; i++) {
        cli_mesh *m = i == 2 && fine ? fine : coarse;
        if (!(shot[i] = malloc(3 * px))) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
        else if ((rc = draw(&f, m, &view, mode[i], i == 1 ? c->tolerance : 0, mask[i], &st)) == 0)
            memcpy(shot[i], f.color, 3 * px);
    }
    /* the crop: the lost pixels and 24 px round them, at least 96 x 72 */
    int x0 = 0, y0 = 0, x1 = w - 1, y1 = h - 1;
    if (v->box[2] >= v->box[0]) {
        int cx = (v->box[0] + v->box[2]) / 2, cy = (v->box[1] + v->box[3]) / 2;
        int hw = (v->box[2] - v->box[0]) / 2 + 24, hh = (v->box[3] - v->box[1]) / 2 + 24;
        if (hw < 48) hw = 48;
        if (hh < 36) hh = 36;
        x0 = cx - hw < 0 ? 0 : cx - hw, x1 = cx + hw >= w ? w - 1 : cx + hw;
        y0 = cy - hh < 0 ? 0 : cy - hh, y1 = cy + hh >= h ? h - 1 : cy + hh;
    }
    int cw = x1 - x0 + 1, ch = y1 - y0 + 1, s = cw <= 110 ? 3 : cw <= 170 ? 2 : 1, gap = 4;
    int ow = 3 * cw * s + 2 * gap, oh = ch * s;
    if (!rc && !(out = malloc(3 * (size_t)ow * oh))) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
    if (!rc) {
        memset(out, 255, 3 * (size_t)ow * oh);
        for (int i = 0; i < 3; i++)
            for (int y = 0; y < oh; y++)
                for (int x = 0; x < cw * s; x++) {
                    size_t src = (size_t)(y0 + y / s) * w + (x0 + x / s);
                    uint8_t *d = &out[3 * ((size_t)y * ow + i * (cw * s + gap) + x)];
                    memcpy(d, &shot[i][3 * src], 3);
                    if (i == 1 && !f.smooth[src] && f.flat[src] && f.fine[src]) {
                        /* not covered by smooth where both references are: red where lost counts it */
                        d[0] = 224, d[1] = 30, d[2] = 30;
                    }
                }
        silk_target t;
        silk_target_init(&t, ow, oh, 0, oh, SILK_PIX_RGB888, out, NULL);
        char path[4096];
        snprintf(path, sizeof path, "%s/%s-y%g-p%g.png", c->dump, name, v->yaw, v->pitch);
        if (silk_png_write(&t, path, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    }
    for (int i = 0; i < 3; i++) free(shot[i]);
    free(out);
    frame_free(&f);
    return rc;
}

/* ---- reporting -------------------------------------------------------------------- */

/* Worse first: more lost pixels, then a larger hole, then a larger excess. */
static int view_worse(const grid_view *a, const grid_view *b)
{
    if (a->lost != b->lost) return a->lost > b->lost;
    if (a->hole != b->hole) return a->hole > b->hole;
    return a->excess > b->excess;
}

typedef struct grid_sum {
    int views, lost10, hole_views, fell_back;
    uint32_t lost_max, hole_max, flat_segments;
    double bulge_max, excess_max;
} grid_sum;

static void summarise(const grid_view *v, int n, grid_sum *s)
{
    memset(s, 0, sizeof *s);
    for (int i = 0; i < n; i++) {
        s->views++;
        s->lost10 += v[i].lost >= 10;
        s->hole_views += v[i].hole > 2;
        s->fell_back += v[i].fell_back;
        s->flat_segments += v[i].flat_segments;
        if (v[i].lost > s->lost_max) s->lost_max = v[i].lost;
        if (v[i].hole > s->hole_max) s->hole_max = v[i].hole;
        if (v[i].bulge > s->bulge_max) s->bulge_max = v[i].bulge;
        if (v[i].excess > s->excess_max) s->excess_max = v[i].excess;
    }
}

/* The indices of the k worst views, worst first. */
static int worst_views(const grid_view *v, int n, int k, int *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        int p;
        if (m < k) p = m++;
        else if (k > 0 && view_worse(&v[i], &v[out[k - 1]])) p = k - 1;
        else continue;
        while (p > 0 && view_worse(&v[i], &v[out[p - 1]])) {
            out[p] = out[p - 1];
            p--;
        }
        out[p] = i;
    }
    return m;
}

static void render_command(char *buf, size_t n, const grid_cfg *c, const char *path, const grid_view *v)
{
    snprintf(buf, n, "silk render %s -o view.png --yaw %g --pitch %g --size %dx%d --aa off --compare", path, v->yaw,
             v->pitch, c->width, c->height);
}

static void mesh_label(const char *path, char *out, size_t n)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    snprintf(out, n, "%s", base);
    char *dot = strrchr(out, '.');
    if (dot && dot != out) *dot = 0;
}

/* ---- the command ------------------------------------------------------------------ */

static int parse_pitches(const char *s, grid_cfg *c)
{
    c->npitch = 0;
    while (*s) {
        char *end;
        double p = strtod(s, &end);
        if (end == s || (*end && *end != ',') || !(p >= -90 && p <= 90) || c->npitch == GRID_MAX_PITCHES)
            return cli_fail(-1, "--pitches must be up to %d comma-separated degrees in -90..90", GRID_MAX_PITCHES);
        c->pitch[c->npitch++] = p;
        s = *end ? end + 1 : end;
    }
    return c->npitch ? 0 : cli_fail(-1, "--pitches needs at least one pitch");
}

static int opt_pitches(const cli_opt *o, const char *v, void *base)
{
    (void)o;
    return parse_pitches(v, base);
}

static void grid_defaults(void *base)
{
    grid_cfg *c = base;
    memset(c, 0, sizeof *c);
    c->yaws = 24;
    c->width = 320;
    c->height = 240;
    c->worst = 3;
    c->max_lost = c->max_hole = -1;
    parse_pitches("-60,-30,0,30,60", c);
}

#define F(member) CLI_FIELD(grid_cfg, member)
static const cli_opt grid_rows[] = {
    { .name = "--grid", .group = "options", .kind = CLI_FLAG, F(grid),
      .help = "the robustness grid (instead of the render modes' benchmark)" },
    { .name = "--yaws", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 360, F(yaws),
      .help = "yaws, every 360/N degrees from the default view (%R, default %D)" },
    { .name = "--pitches", .kind = CLI_CUSTOM, .meta = "LIST", .parse = opt_pitches,
      .help = "comma-separated pitches in degrees, -90..90 (default -60,-30,0,30,60)" },
    { .name = "--size", .kind = CLI_SIZE, .meta = "WxH", F(width), .off2 = offsetof(grid_cfg, height),
      .help = "image size (default 320x240)" },
    { .name = "--tolerance", .kind = CLI_FX, .meta = "PX", .lo = 0.25, .hi = 4, F(tolerance),
      .help = "smooth mode's sampling tolerance (%R; default: the library's)" },
    { .name = "--threads", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = GRID_MAX_THREADS, F(threads),
      .help = "threads drawing the views (%R; default: the processors online)" },
    { .name = "--worst", .kind = CLI_INT, .meta = "N", .lo = 0, .hi = 1000, F(worst),
      .help = "worst views printed per mesh (%R, default %D)" },
    { .name = "--max-lost", .kind = CLI_INT, .meta = "N", .lo = 0, .hi = 100000000, F(max_lost),
      .help = "fail (exit 1) when a view loses more than N pixels" },
    { .name = "--max-hole", .kind = CLI_INT, .meta = "N", .lo = 0, .hi = 100000000, F(max_hole),
      .help = "fail (exit 1) when a view has a hole of more than N pixels" },
    { .name = "--md", .kind = CLI_OUTPUT, .meta = "FILE", F(md), .help = "the summary and the worst views as Markdown" },
    { .name = "--csv", .kind = CLI_OUTPUT, .meta = "FILE", F(csv), .help = "every view as a CSV row" },
    { .name = "--dump", .kind = CLI_DIR, .meta = "DIR", F(dump),
      .help = "each worst view as DIR/MESH-yYAW-pPITCH.png: flat, smooth (lost pixels red) and the detailed model, "
              "magnified (DIR is made when missing)" },
    { .name = "--quiet", .kind = CLI_FLAG, F(quiet), .help = "no progress line on a terminal" },
    { .name = NULL },
};
#undef F

const cli_command cmd_bench_grid_spec = {
    .name = "bench --grid",
    .usage = "usage: silk bench --grid [options] COARSE[:FINE]...\n",
    .about =
        "Draw each coarse mesh flat and smooth from a grid of views about silk\n"
        "render's default framing, and its detailed model FINE flat from the same\n"
        "camera, and count per view what smooth mode gets visibly wrong:\n"
        "  lost    pixels at least 3 px inside both the flat and the detailed object\n"
        "          (the flat one alone without FINE) that smooth leaves uncovered\n"
        "  hole    the largest enclosed background region of the smooth frame, in\n"
        "          its pixels that lie 3 px inside both objects (a subset of lost)\n"
        "  bulge   how far (px) smooth reaches outside flat's object\n"
        "  excess  the same outside both flat's and the detailed object\n"
        "One line per mesh, then its worst views, each with the silk render command\n"
        "that shows it:\n"
        "  grid MESH views=N lost10=N lost_max=N hole_views=N hole_max=N bulge_max=X excess_max=X flat_segments=N\n"
        "  grid-view MESH yaw=Y pitch=P lost=N hole=N bulge=X excess=X: silk render ...\n"
        "docs/measurements.md defines the grid and every number.\n",
    .examples = "  silk bench --grid bunny-500.obj:bunny-fine.obj --max-lost 9 --max-hole 2\n",
    .sets = { { grid_rows, 0, sizeof(grid_cfg), grid_defaults, NULL } },
    .nsets = 1,
};

int bench_grid(int argc, char **argv)
{
    grid_cfg c;
    grid_defaults(&c);
    cli_args args;
    void *bases[] = { &c };
    int rc = cli_parse(&cmd_bench_grid_spec, bases, argc, argv, &args);
    if (!rc && args.npos == 0) rc = cli_fail(CLI_EXIT_USAGE, "bench --grid: no mesh given (silk bench --grid COARSE[:FINE]...)");
    if (rc) {
        cli_args_free(&args);
        return rc == CLI_HELP ? 0 : rc;
    }
    const char **paths = args.pos;
    int n = args.npos;

    silk_outfile md, csv;
    silk_error err;
    int have_md = 0, have_csv = 0;
    if (c.md) {
        if (silk_outfile_open(&md, c.md, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        else have_md = 1;
    }
    if (!rc && c.csv) {
        if (silk_outfile_open(&csv, c.csv, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        else have_csv = 1;
    }
    if (have_csv)
        fprintf(csv.fp, "mesh,yaw,pitch,lost,hole,hole_px,bulge_px,excess_px,flat_segments,fell_back,lost_x0,lost_y0,lost_x1,lost_y1\n");
    if (have_md)
        fprintf(md.fp,
                "| mesh | views | views losing 10+ px | most lost | views with a hole > 2 px | largest hole | "
                "bulge px | excess px | flat chains |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    int nviews = c.yaws * c.npitch, failed_check = 0;
    char **worst_md = calloc((size_t)n, sizeof *worst_md);
    grid_view *views = malloc((size_t)nviews * sizeof *views);
    int *worst = malloc((size_t)(c.worst + 1) * sizeof *worst);
    if (!views || !worst || !worst_md) rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
    for (int m = 0; m < n && !rc; m++) {
        char *spec = strdup(paths[m]), *colon = spec ? strrchr(spec, ':') : NULL;
        if (!spec) {
            rc = cli_fail(CLI_EXIT_INPUT, "out of memory");
            break;
        }
        if (colon) *colon = 0;
        grid_job j;
        memset(&j, 0, sizeof j);
        j.cfg = &c;
        j.coarse = spec;
        j.fine = colon && colon[1] ? colon + 1 : NULL;
        j.views = views;
        j.nviews = nviews;
        memset(views, 0, (size_t)nviews * sizeof *views);
        for (int p = 0; p < c.npitch; p++)
            for (int y = 0; y < c.yaws; y++) {
                views[p * c.yaws + y].yaw = 360.0 * y / c.yaws;
                views[p * c.yaws + y].pitch = c.pitch[p];
            }
        int r = run_job(&j);
        if (r) {
            rc = r;
            free(spec);
            break;
        }
        char name[128];
        mesh_label(spec, name, sizeof name);
        grid_sum s;
        summarise(views, nviews, &s);
        printf("grid %s views=%d lost10=%d lost_max=%u hole_views=%d hole_max=%u bulge_max=%.1f excess_max=%.1f "
               "flat_segments=%u%s\n",
               name, s.views, s.lost10, s.lost_max, s.hole_views, s.hole_max, s.bulge_max, s.excess_max, s.flat_segments,
               s.fell_back ? " fell_back=1" : "");
        int k = worst_views(views, nviews, c.worst, worst);
        size_t cap = 512 * (size_t)(k + 1), used = 0;
        worst_md[m] = malloc(cap);
        cli_mesh dc, df;
        memset(&dc, 0, sizeof dc);
        memset(&df, 0, sizeof df);
        if (c.dump && k > 0) {
            silk_load_opts lo;
            silk_load_opts_default(&lo);
            r = cli_mesh_load(&dc, spec, &lo, 1, 0, (size_t)8 << 20, 0, 1);
            if (!r && j.fine) r = cli_mesh_load(&df, j.fine, &lo, 0, 0, (size_t)8 << 20, 0, 1);
            for (int i = 0; i < k && !r; i++) r = dump_view(&c, &dc, j.fine ? &df : NULL, name, &views[worst[i]]);
            if (r) rc = r;
        }
        cli_mesh_free(&dc);
        cli_mesh_free(&df);
        for (int i = 0; i < k; i++) {
            const grid_view *v = &views[worst[i]];
            char cmd[1024];
            render_command(cmd, sizeof cmd, &c, spec, v);
            printf("grid-view %s yaw=%g pitch=%g lost=%u hole=%u bulge=%.1f excess=%.1f: %s\n", name, v->yaw, v->pitch,
                   v->lost, v->hole, v->bulge, v->excess, cmd);
            if (worst_md[m] && used < cap)
                used += (size_t)snprintf(worst_md[m] + used, cap - used, "| %s | %g | %g | %u | %u | %.1f | `%s` |\n",
                                         name, v->yaw, v->pitch, v->lost, v->hole, v->excess, cmd);
        }
        for (int i = 0; i < nviews; i++) {
            const grid_view *v = &views[i];
            if ((c.max_lost >= 0 && v->lost > (uint32_t)c.max_lost) || (c.max_hole >= 0 && v->hole > (uint32_t)c.max_hole)) {
                char cmd[1024];
                render_command(cmd, sizeof cmd, &c, spec, v);
                fprintf(stderr, "silk: bench --grid: %s: yaw %g pitch %g loses %u px, hole %u px: %s\n", name, v->yaw,
                        v->pitch, v->lost, v->hole, cmd);
                failed_check = 1;
            }
            if (have_csv)
                fprintf(csv.fp, "%s,%g,%g,%u,%u,%u,%.2f,%.2f,%u,%d,%d,%d,%d,%d\n", name, v->yaw, v->pitch, v->lost, v->hole,
                        v->hole_px, v->bulge, v->excess, v->flat_segments, v->fell_back, v->lost ? v->box[0] : -1,
                        v->lost ? v->box[1] : -1, v->lost ? v->box[2] : -1, v->lost ? v->box[3] : -1);
        }
        if (have_md)
            fprintf(md.fp, "| %s | %d | %d | %u | %d | %u | %.1f | %.1f | %u |\n", name, s.views, s.lost10, s.lost_max,
                    s.hole_views, s.hole_max, s.bulge_max, s.excess_max, s.flat_segments);
        fflush(stdout);
        free(spec);
    }
    if (have_md && !rc) {
        fprintf(md.fp, "\nThe worst views (lost pixels, then the hole, then the excess):\n\n"
                       "| mesh | yaw | pitch | lost | hole | excess px | shown by |\n|---|---:|---:|---:|---:|---:|---|\n");
        for (int m = 0; m < n; m++)
            if (worst_md[m]) fputs(worst_md[m], md.fp);
    }
    for (int m = 0; m < n; m++) free(worst_md[m]);
    free(worst_md), free(views), free(worst);
    cli_args_free(&args);
    if (have_md) {
        if (rc) silk_outfile_abort(&md);
        else if (silk_outfile_commit(&md, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    }
    if (have_csv) {
        if (rc) silk_outfile_abort(&csv);
        else if (silk_outfile_commit(&csv, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    }
    if (!rc && failed_check) rc = CLI_EXIT_INPUT;
    return rc;
}
