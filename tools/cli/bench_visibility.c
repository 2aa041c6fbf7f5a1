/*
 * bench_visibility.c - `silk bench --visibility MESH...`: the cost of one frame's
 * visibility (paper III-B) by the brute pass and by the Gaussian-sphere
 * hierarchy, on each mesh, from 36 views around it, in perspective and
 * parallel projection.
 *
 * One line per mesh and projection:
 *   visibility MESH parallel|perspective normals=N brute_ns=N gauss_ns=N cell_decided=N auto_ns=N
 * Times are ns per frame, the median over the views of the best of a few
 * timed batches (the machine is shared; the minimum is the least disturbed).
 * brute_ns is measured on the mesh as loaded, before silk_vis_build
 * renumbers its normals; gauss_ns and auto_ns after.  cell_decided is the
 * median number of normals a cell decided at once.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>

#include "cli.h"
#include "commands.h"
#include "progress.h"
#include "platform/platform.h"

#define BENCH_VIEWS 36

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk bench --visibility [options] MESH...\n"
            "\n"
            "Time the per-frame visibility of every shading normal: the brute pass\n"
            "(one dot product per normal) against the Gaussian-sphere hierarchy, from\n"
            "%d views around each mesh, perspective and parallel.  One line per mesh\n"
            "and projection:\n"
            "  visibility MESH PROJ normals=N brute_ns=N gauss_ns=N cell_decided=N auto_ns=N\n"
            "(ns per frame, medians over the views).  Then the hierarchy's size and build\n"
            "time on a line starting with '#'.\n"
            "\n"
            "options:\n"
            "  --visibility       the visibility benchmark (the only one so far)\n"
            "  --batches N        timed batches per view and method, best kept [5]\n"
            "  --depth N          hierarchy depth 1..10 [from the mesh size]\n"
            "  --leaf N           largest cell not split [default of the library]\n"
            "  --only brute|gauss run one method only, 36 views x batches frames (for\n"
            "                     callgrind: valgrind --tool=callgrind silk bench ...)\n"
            "  --projection perspective|parallel   only this projection [both]\n"
            "  --quiet            no progress line on a terminal\n",
            BENCH_VIEWS);
}

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* View k of the 36: azimuth in steps of 10 degrees, elevation swinging
 * between -50 and +50, the eye at 3 bounding radii from the centre. */
static void bench_view(const silk_mesh *m, int k, int ortho, silk_view *v)
{
    double c[3], r = 0;
    double lo[3] = { cli_fx_to_double(m->bbox_min.x), cli_fx_to_double(m->bbox_min.y), cli_fx_to_double(m->bbox_min.z) };
    double hi[3] = { cli_fx_to_double(m->bbox_max.x), cli_fx_to_double(m->bbox_max.y), cli_fx_to_double(m->bbox_max.z) };
    for (int i = 0; i < 3; i++) {
        c[i] = (lo[i] + hi[i]) / 2;
        r += (hi[i] - lo[i]) * (hi[i] - lo[i]);
    }
    r = sqrt(r) / 2;
    double az = k * 10.0 * CLI_DEG, el = 50.0 * sin(k * 0.7) * CLI_DEG;
    double d[3] = { cos(el) * sin(az), sin(el), cos(el) * cos(az) };
    memset(v, 0, sizeof *v);
    v->cam.ortho = ortho;
    v->cam.eye = silk_v3(cli_fx_from_double(c[0] + 3 * r * d[0]), cli_fx_from_double(c[1] + 3 * r * d[1]),
                         cli_fx_from_double(c[2] + 3 * r * d[2]));
    v->cam.target = silk_v3(cli_fx_from_double(c[0]), cli_fx_from_double(c[1]), cli_fx_from_double(c[2]));
    v->forward = silk_v3(cli_fx_from_double(-d[0]), cli_fx_from_double(-d[1]), cli_fx_from_double(-d[2]));
}

typedef struct bench_opts {
    int batches;
    silk_vis_opts vis;
    int only;                  /* 0 all, SILK_VIS_BRUTE or SILK_VIS_GAUSS */
    int proj;                  /* bit 0: perspective, bit 1: parallel */
    int quiet;                 /* no progress line */
} bench_opts;

/* Projection p (0 perspective, 1 parallel) is to be measured. */
static int want(const bench_opts *o, int p) { return o->proj >> p & 1; }

/* Best ns per frame over the batches; a batch repeats the frame until it
 * has run for at least 50 us. */
static double time_frame(const silk_mesh *m, const silk_view *v, silk_vis_method method, uint8_t *vis,
                         silk_arena *a, int batches, silk_vis_stats *st)
{
    int reps = 1;
    double best = 1e300;
    for (int b = 0; b < batches; b++) {
        double t0 = now_ns();
        for (int i = 0; i < reps; i++) silk_visibility(m, v, method, vis, a, st);
        double t = now_ns() - t0;
        if (t < 50e3 && reps < (1 << 20)) {   /* too short to time: grow, and do not count it */
            reps *= 2;
            b--;
            continue;
        }
        if (t / reps < best) best = t / reps;
    }
    return best;
}

static int bench_mesh(const char *path, const bench_opts *o)
{
    /* 16 MiB on top of the mesh for the visibility hierarchy's build */
    cli_mesh lm;
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    int rc = cli_mesh_load(&lm, path, &lo, 0, 0, (size_t)16 << 20, 0, 1);
    if (rc) {
        cli_mesh_free(&lm);
        return rc;
    }
    silk_arena a = lm.arena;
    silk_mesh m = lm.mesh;
    progress pr;
    char label[96];
    snprintf(label, sizeof label, "bench --visibility %s", lm.name);
    progress_start(&pr, o->quiet, label);
    uint8_t *vis = malloc(m.nnormals + 1);
    double brute[2][BENCH_VIEWS], gauss[2][BENCH_VIEWS], autot[2][BENCH_VIEWS], decided[2][BENCH_VIEWS];
    double visited[2][BENCH_VIEWS], onebyone[2][BENCH_VIEWS];
    silk_view v;
    silk_vis_stats st;
    if (o->only != SILK_VIS_GAUSS)
        for (int p = 0; p < 2; p++)
            for (int k = 0; k < BENCH_VIEWS && want(o, p); k++) {
                progress_update(&pr, p * BENCH_VIEWS + k, 4 * BENCH_VIEWS);
                bench_view(&m, k, p, &v);
                brute[p][k] = o->only ? 0 : time_frame(&m, &v, SILK_VIS_BRUTE, vis, &a, o->batches, NULL);
                if (o->only)
                    for (int b = 0; b < o->batches; b++) silk_visibility(&m, &v, SILK_VIS_BRUTE, vis, &a, NULL);
            }
    if (o->only == SILK_VIS_BRUTE) goto done;

    silk_error err;
    memset(&err, 0, sizeof err);
    double t0 = now_ns();
    silk_status s = silk_vis_build(&m, &o->vis, &a, &err);
    double build_ms = (now_ns() - t0) / 1e6;
    if (s != SILK_OK) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: %s", path, err.msg);
        goto done;
    }
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < BENCH_VIEWS && want(o, p); k++) {
            progress_update(&pr, (2 + p) * BENCH_VIEWS + k, 4 * BENCH_VIEWS);
            bench_view(&m, k, p, &v);
            if (o->only) {
                for (int b = 0; b < o->batches; b++) silk_visibility(&m, &v, SILK_VIS_GAUSS, vis, &a, NULL);
                continue;
            }
            gauss[p][k] = time_frame(&m, &v, SILK_VIS_GAUSS, vis, &a, o->batches, &st);
            decided[p][k] = st.cell_decided;
            visited[p][k] = st.cells_visited;
            onebyone[p][k] = st.one_by_one;
            autot[p][k] = time_frame(&m, &v, SILK_VIS_AUTO, vis, &a, o->batches, NULL);
        }
    if (o->only) goto done;
    for (int p = 1; p >= 0; p--)
        if (want(o, p))
            printf("visibility %s %s normals=%u brute_ns=%.0f gauss_ns=%.0f cell_decided=%.0f auto_ns=%.0f\n", path,
                   p ? "parallel" : "perspective", m.nnormals, median(brute[p], BENCH_VIEWS),
                   median(gauss[p], BENCH_VIEWS), median(decided[p], BENCH_VIEWS), median(autot[p], BENCH_VIEWS));
    for (int p = 1; p >= 0; p--)
        if (want(o, p))
            printf("# %s %s cells_visited=%.0f one_by_one=%.0f\n", path, p ? "parallel" : "perspective",
                   median(visited[p], BENCH_VIEWS), median(onebyone[p], BENCH_VIEWS));
    printf("# %s triangles=%u nodes=%u depth=%u leaf_max=%u bytes=%zu bytes_per_normal=%.2f build_ms=%.1f\n", path,
           m.ntris, m.vis->nnodes, m.vis->depth, m.vis->leaf_max, silk_vis_bytes(m.vis),
           m.nnormals ? (double)m.vis->nnodes * sizeof(silk_vis_node) / m.nnormals : 0.0, build_ms);
    fflush(stdout);
done:
    progress_end(&pr);
    free(vis);
    cli_mesh_free(&lm);
    return rc;
}

int bench_visibility(int argc, char **argv)
{
    bench_opts o;
    memset(&o, 0, sizeof o);
    o.batches = 5;
    o.proj = 3;
    int visibility = 0, first_mesh = 0;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        long n;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            help(stdout);
            return 0;
        } else if (cli_is(arg, "--visibility")) {
            visibility = 1;
        } else if (strcmp(arg, "--quiet") == 0) {
            o.quiet = 1;
        } else if (cli_is(arg, "--batches")) {
            const char *val = cli_value(argc, argv, &i);
            if (!val || cli_parse_long("--batches", val, 1, 1000, &n)) return CLI_EXIT_USAGE;
            o.batches = (int)n;
        } else if (cli_is(arg, "--depth")) {
            const char *val = cli_value(argc, argv, &i);
            if (!val || cli_parse_long("--depth", val, 1, 10, &n)) return CLI_EXIT_USAGE;
            o.vis.max_depth = (uint32_t)n;
        } else if (cli_is(arg, "--leaf")) {
            const char *val = cli_value(argc, argv, &i);
            if (!val || cli_parse_long("--leaf", val, 1, 1 << 20, &n)) return CLI_EXIT_USAGE;
            o.vis.leaf_max = (uint32_t)n;
        } else if (cli_is(arg, "--only")) {
            const char *val = cli_value(argc, argv, &i);
            if (!val) return CLI_EXIT_USAGE;
            if (strcmp(val, "brute") == 0) o.only = SILK_VIS_BRUTE;
            else if (strcmp(val, "gauss") == 0) o.only = SILK_VIS_GAUSS;
            else return cli_fail(CLI_EXIT_USAGE, "--only must be brute or gauss, not '%s'", val);
        } else if (cli_is(arg, "--projection")) {
            const char *val = cli_value(argc, argv, &i);
            if (!val) return CLI_EXIT_USAGE;
            if (strcmp(val, "perspective") == 0) o.proj = 1;
            else if (strcmp(val, "parallel") == 0) o.proj = 2;
            else return cli_fail(CLI_EXIT_USAGE, "--projection must be perspective or parallel, not '%s'", val);
        } else if (arg[0] == '-' && arg[1]) {
            return cli_fail(CLI_EXIT_USAGE, "bench: unknown option '%s' (see silk bench --help)", arg);
        } else if (!first_mesh) {
            first_mesh = i;
        }
    }
    if (!visibility) return cli_fail(CLI_EXIT_USAGE, "bench: say what to measure: --visibility");
    if (!first_mesh) return cli_fail(CLI_EXIT_USAGE, "bench: no mesh given");
    int rc = 0;
    for (int i = first_mesh; i < argc; i++) {
        const char *arg = argv[i];
        if (arg[0] == '-' && arg[1]) {
            /* skip options and their values, parsed above */
            if (!strchr(arg, '=') && !cli_is(arg, "--visibility") && strcmp(arg, "--quiet") != 0) i++;
            continue;
        }
        int r = bench_mesh(arg, &o);
        if (r) rc = r;
    }
    return rc;
}
