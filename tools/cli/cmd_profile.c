/*
 * cmd_profile.c - `silk profile MESH`: where every byte of RAM goes when the
 * board this silk was built for renders MESH, measured in this process, as
 * a table, a CSV file and one summary line.
 *
 * The board's settings (frame size, pixel format, band rows, views) come
 * from boards/NAME/board.mk through the compiler flags of the build, so the
 * command needs no source tree.  The mesh is loaded into the arena as the
 * tool does, and the frames are rendered in the board's bands from the views
 * of `silk pack --views N` (BOARD_VIEWS, default 3), each in flat and smooth
 * mode.  The last line is
 *   footprint BOARD MESH ram_total_bytes=N model_bytes=N fell_back_frames=N
 * (frames that fell back to flat for lack of arena are also said above it).
 *
 * A firmware board (mps2-an385) is measured on the firmware itself, by
 * `make profile` (tools/scripts/profile_fw.sh reads its linker map and its report
 * under QEMU); that is the Makefile's work, not this command's.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* The board this silk was built for (the Makefile passes them from
 * boards/$(BOARD)/board.mk). */
#ifndef SILK_BOARD_NAME
#define SILK_BOARD_NAME "host"
#endif
#ifndef SILK_BOARD_BAND_ROWS
#define SILK_BOARD_BAND_ROWS SILK_BOARD_HEIGHT
#endif
#ifndef SILK_BOARD_VIEWS
#define SILK_BOARD_VIEWS 3
#endif

/* ---- the report ------------------------------------------------------------- */

typedef struct report {
    FILE *csv;                 /* NULL: the table only */
} report;

static void row(report *r, const char *area, const char *item, size_t bytes, const char *note)
{
    printf("  %-34s %9zu  %s\n", item, bytes, note ? note : "");
    if (r->csv) fprintf(r->csv, "%s,%s,%zu\n", area, item, bytes);
}

static void heading(const char *title)
{
    printf("\n%s\n", title);
}

/* The model name make uses: the mesh file's base name without extension. */
static void model_name(const char *mesh, char *out, size_t n)
{
    const char *b = strrchr(mesh, '/');
    b = b ? b + 1 : mesh;
    snprintf(out, n, "%s", b);
    char *dot = strrchr(out, '.');
    if (dot && dot != out) *dot = 0;
}

/* ---- measured in this process ----------------------------------------------------- */

static int band_none(void *user, const silk_target *t)
{
    (void)user;
    (void)t;
    return 0;
}

/* What the frames needed: the largest per-frame scratch, and how many fell
 * back. */
typedef struct frame_figures {
    size_t frame_peak;
    long fell;
} frame_figures;

/* SILK_BOARD_VIEWS views around the model, each in flat and smooth mode,
 * rendered in the board's bands into `band`. */
static int render_views(cli_scene_opts *o, cli_scene *s, silk_target *band, frame_figures *ff)
{
    silk_sink sink = { .band = band_none, .user = NULL };
    silk_camera c0;
    int rc = cli_camera(o, &s->mesh, NULL, &c0);
    int views = SILK_BOARD_VIEWS;
    for (int k = 0; !rc && k < views; k++) {
        double a = 2 * CLI_PI * k / views;
        double t[3] = { cli_fx_to_double(c0.target.x), cli_fx_to_double(c0.target.y), cli_fx_to_double(c0.target.z) };
        double d[3] = { cli_fx_to_double(c0.eye.x) - t[0], cli_fx_to_double(c0.eye.y) - t[1],
                        cli_fx_to_double(c0.eye.z) - t[2] };
        o->eye[0] = t[0] + d[0] * cos(a) + d[2] * sin(a);
        o->eye[1] = t[1] + (k % 2 ? -d[1] : d[1]);
        o->eye[2] = t[2] - d[0] * sin(a) + d[2] * cos(a);
        o->have_eye = 1;
        silk_camera cam;
        silk_view view;
        silk_error err;
        if ((rc = cli_camera(o, &s->mesh, NULL, &cam)) != 0) break;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        silk_phong_default(&s->phong, &view);
        silk_hal_phong(&s->hal, &s->phong);
        int clip = o->render.mode == SILK_MODE_CLIP, siltex = o->render.mode == SILK_MODE_SILTEX;
        for (int mode = 0; mode < 2 && !rc; mode++) {
            silk_render_opts ro = o->render;
            ro.mode = clip || siltex ? o->render.mode : mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
            if (clip && mode) ro.aa = 0;   /* both kinds of stencil */
            cli_scene_render_opts(s, &ro);
            silk_frame_stats fs;
            if (silk_render_bands(&s->arena, &s->mesh, &view, &s->hal, &ro, band, &sink, &fs, &err) != SILK_OK)
                return cli_fail(CLI_EXIT_INPUT, "%s: %s", o->mesh_path, err.msg);
            if (fs.frame_bytes > ff->frame_peak) ff->frame_peak = fs.frame_bytes;
            ff->fell += fs.fell_back;
        }
    }
    return rc;
}

/* The tables, the CSV and the footprint line. */
static int print_report(const cli_scene *s, const cli_scene_opts *o, int rows, size_t band_bytes,
                        const size_t *load_peak, const frame_figures *ff, const char *csv_path)
{
    const char *mesh = o->mesh_path;
    report r = { NULL };
    if (csv_path && !(r.csv = fopen(csv_path, "w")))
        return cli_fail(CLI_EXIT_INPUT, "profile: %s: %s", csv_path, strerror(errno));
    if (r.csv) fprintf(r.csv, "area,item,bytes\n");
    printf("silk profile: %s on %s (measured in this process)\n", mesh, SILK_BOARD_NAME);
    int clip = o->render.mode == SILK_MODE_CLIP, siltex = o->render.mode == SILK_MODE_SILTEX;
    printf("frame %dx%d, bands of %d rows; %d frames rendered (%s from %d views)\n", o->width, o->height, rows,
           2 * SILK_BOARD_VIEWS, clip ? "clip, anti-aliased and not," : siltex ? "siltex, twice each" : "flat and smooth",
           SILK_BOARD_VIEWS);

    heading("MESH (bytes; loaded into the arena: a host has no flash)");
    silk_mesh_bytes mb;
    silk_mesh_bytes_used(&s->mesh, &mb);
    size_t vis = silk_vis_bytes(s->mesh.vis);
    row(&r, "model", "model positions", mb.positions, NULL);
    row(&r, "model", "model normals", mb.normals, NULL);
    if (mb.uvs) row(&r, "model", "model uvs", mb.uvs, NULL);
    if (mb.colors) row(&r, "model", "model colours", mb.colors, NULL);
    row(&r, "model", "model triangles", mb.triangles, NULL);
    row(&r, "model", "model edges", mb.edges, NULL);
    row(&r, "model", "model vertex edges", mb.vertex_edges, NULL);
    row(&r, "model", "model features", mb.features, NULL);
    row(&r, "model", "model visibility", vis, NULL);
    size_t model = mb.total + vis;
    row(&r, "model", "model total", model, NULL);
    if (clip) {
        heading("FLASH (bytes; read in place from the model file)");
        row(&r, "flash", "silhouette map", silk_silmap_bytes(&s->silmap), "views, polytope, outlines");
    }
    if (siltex) {
        heading("FLASH (bytes; read in place from the model file)");
        row(&r, "flash", "silhouette texture", silk_siltex_bytes(&s->siltex), "C and T, atlas points, angles, maps");
    }

    heading("RAM (bytes; arena high-water marks by purpose)");
    size_t load_only = 0;
    for (int p = 0; p < SILK_MEM_COUNT; p++) {
        size_t v = p == SILK_MEM_RASTER ? band_bytes : p == SILK_MEM_FRAME ? ff->frame_peak : load_peak[p];
        if (!v) continue;
        char item[64];
        snprintf(item, sizeof item, p == SILK_MEM_RASTER ? "band buffers" : "arena %s",
                 silk_purpose_name((silk_purpose)p));
        row(&r, "ram", item, v,
            p == SILK_MEM_RASTER ? "colour + depth"
            : p == SILK_MEM_FRAME ? "per-frame scratch, peak"
            : p == SILK_MEM_LOAD  ? "while loading only"
                                  : NULL);
        if (p == SILK_MEM_LOAD) load_only = v;
    }
    /* Loading scratch is released before the first frame. */
    size_t total = s->load_bytes + band_bytes + ff->frame_peak;
    if (load_only > band_bytes + ff->frame_peak) total = s->load_bytes + load_only;
    if (clip) row(&r, "ram", "stencil", (size_t)rows * (((size_t)o->width + 7) / 8), "one band's bits, in the frame peak");
    row(&r, "ram", "stack", 0, "not measured on a host");
    row(&r, "ram", "ram total", total, "mesh + band buffers + frame peak");
    if (ff->fell) printf("\n  %ld frames fell back (the arena ran out)\n", ff->fell);
    if (r.csv) {
        fprintf(r.csv, "frames,fell_back,%ld\n", ff->fell);
        if (fclose(r.csv) != 0) return cli_fail(CLI_EXIT_INPUT, "profile: %s: write failed", csv_path);
        printf("\ncsv: %s\n", csv_path);
    }
    char name[128];
    model_name(mesh, name, sizeof name);
    printf("footprint %s %s ram_total_bytes=%zu model_bytes=%zu fell_back_frames=%ld\n", SILK_BOARD_NAME, name, total,
           model, ff->fell);
    return 0;
}

static int profile(const char *mesh, const char *csv_path, int check, int hull_mode)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);   /* the board's frame size and format */
    o.mesh_path = mesh;
    o.only_drawn = 1;             /* a device holds only the mesh it draws */
    if (hull_mode) o.render.mode = (silk_mode)hull_mode;
    int rows = SILK_BOARD_BAND_ROWS < 1 || SILK_BOARD_BAND_ROWS > o.height ? o.height : SILK_BOARD_BAND_ROWS;

    cli_scene s;
    int rc = cli_scene_load(&s, &o);
    if (rc) {
        cli_scene_free(&s);
        return rc;
    }
    /* The tool's full-frame target is not what the board uses: bands are.
     * On a host the band buffers come from the heap, so the arena's sizing
     * stays the tool's; they are counted as the board would hold them. */
    size_t bpp = silk_pixfmt_bytes(o.fmt), band_bytes = (size_t)rows * (size_t)o.width * (bpp + sizeof(uint32_t));
    uint8_t *color = malloc((size_t)rows * o.width * bpp);
    uint32_t *depth = malloc((size_t)rows * o.width * sizeof *depth);
    frame_figures ff = { 0, 0 };
    /* Frame scratch is measured from here; the load-time peaks are kept apart. */
    size_t load_peak[SILK_MEM_COUNT];
    memcpy(load_peak, s.arena.peak_used, sizeof load_peak);
    if (!color || !depth) {
        rc = cli_fail(CLI_EXIT_INPUT, "profile: out of memory for the band buffers");
    } else {
        silk_target band;
        silk_target_init(&band, o.width, o.height, 0, rows, o.fmt, color, depth);
        rc = render_views(&o, &s, &band, &ff);
    }
    free(color);
    free(depth);
    if (!rc) rc = print_report(&s, &o, rows, band_bytes, load_peak, &ff, csv_path);
    cli_scene_free(&s);
    if (!rc && check && ff.fell) rc = cli_fail(CLI_EXIT_INPUT, "profile: %ld frames fell back", ff.fell);
    return rc;
}

/* ---- the command ----------------------------------------------------------------- */

typedef struct profile_args {
    const char *csv;
    int check, mode;           /* mode 0, or SILK_MODE_CLIP or SILK_MODE_SILTEX */
} profile_args;

static int parse_board(const cli_opt *o, const char *v, void *base)
{
    (void)o, (void)base;
    if (strcmp(v, SILK_BOARD_NAME) != 0)
        return cli_fail(-1, "profile: this silk was built for board %s; for %s run `make profile PROFILE_BOARD=%s` in "
                        "the silk sources", SILK_BOARD_NAME, v, v);
    return 0;
}

/* --mode as every command reads it; profile takes the two hull modes. */
static int parse_mode(const cli_opt *o, const char *v, void *base)
{
    silk_mode m;
    uint32_t level;
    if (silk_mode_parse(v, &m, &level) != 0 || (m != SILK_MODE_CLIP && m != SILK_MODE_SILTEX))
        return cli_fail(-1, "%s must be clip or siltex (got \"%s\"; flat and smooth are profiled without it)", o->name,
                        v);
    ((profile_args *)base)->mode = (int)m;
    return 0;
}

static const cli_opt profile_rows[] = {
    { .name = "--board", .group = "", .kind = CLI_CUSTOM, .meta = "NAME", .parse = parse_board,
      .help = "the board; only " SILK_BOARD_NAME " (the one built for)" },
    { .name = "--csv", .kind = CLI_OUTPUT, .meta = "FILE", CLI_FIELD(profile_args, csv),
      .help = "the table as CSV (area,item,bytes) too" },
    { .name = "--check", .kind = CLI_FLAG, CLI_FIELD(profile_args, check),
      .help = "exit 1 when a frame fell back (the arena ran out)" },
    { .name = "--mode", .kind = CLI_CUSTOM, .meta = "clip|siltex", .parse = parse_mode,
      .help = "profile clip mode instead of flat and smooth (a prepared model's hull and map: the map's flash bytes, "
              "the stencil's RAM), or siltex mode (its hull and silhouette texture: the texture's flash bytes)" },
    { .name = NULL },
};

static void profile_more(FILE *f)
{
    fprintf(f, "This board: " SILK_BOARD_NAME ", %dx%d, bands of %d rows; %d views around the model, each flat and\n"
            "smooth, rendered in this process.  A firmware board (mps2-an385) measures itself\n"
            "under QEMU, with its flash: run `make profile PROFILE_BOARD=NAME` in the silk\n"
            "sources for it.\n", SILK_BOARD_WIDTH, SILK_BOARD_HEIGHT, SILK_BOARD_BAND_ROWS, SILK_BOARD_VIEWS);
}

const cli_command cmd_profile_spec = {
    .name = "profile",
    .usage = "usage: silk profile MESH [--board " SILK_BOARD_NAME "] [--csv FILE] [--check] [--mode clip|siltex]\n",
    .about =
        "Where every byte of RAM goes when the board this silk was built for renders\n"
        "MESH: the mesh in the arena by part, the arena by purpose with high-water\n"
        "marks and the band buffers, as a table, a CSV file and a last line\n"
        "  footprint BOARD MESH ram_total_bytes=N model_bytes=N fell_back_frames=N\n",
    .examples =
        "  silk profile ../shared/meshes/bunny-500.obj\n"
        "  make profile PROFILE_BOARD=mps2-an385 PROFILE_MESH=../shared/meshes/knot-480.obj\n",
    .more = profile_more,
    .sets = { { profile_rows, 0, sizeof(profile_args), NULL, NULL } },
    .nsets = 1,
};

int cmd_profile(int argc, char **argv)
{
    profile_args pa = { NULL, 0, 0 };
    cli_args args;
    void *bases[] = { &pa };
    const char *mesh = NULL;
    int rc = cli_parse(&cmd_profile_spec, bases, argc, argv, &args);
    if (!rc) rc = cli_one_mesh("profile", args.npos, args.pos, "silk profile MESH", &mesh);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    if (rc) return rc;
    return profile(mesh, pa.csv, pa.check, pa.mode);
}
