/*
 * cmd_render.c - `silk render MESH -o OUT.png`: load a mesh, render one frame
 * with silk_render() through the default Phong stages, write PNG or PPM.
 * Series of frames: --turntable N views around the model (one numbered file
 * each, or one contact sheet with --sheet), --modes to compare render modes
 * side by side, --zoom for a close-up of the silhouette.
 *
 * The output is written atomically, and when the command fails a file left
 * at OUT by an earlier run is removed, so OUT exists afterwards only if this
 * run produced it.  MESH "-" is standard input, OUT "-" standard output.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "progress.h"
#include "image/sheet.h"
#include "opt.h"
#include "render_scene.h"
#include "platform/platform.h"

/* Frame series: --turntable, --modes, --sheet, --zoom. */
#define SERIES_MAX_VIEWS 360
#define SERIES_MAX_MODES 8

typedef struct series {
    int views;                       /* --turntable N; 1 without */
    int nmodes;                      /* 0: the one --mode of the scene options */
    cli_mode mode[SERIES_MAX_MODES];
    int sheet;
    double zoom;                     /* --zoom Z; 0 without */
    int pixels;                      /* --pixels N: cells drawn N times smaller, magnified N times; 1 without */
} series;

/* render's own options; the scene options are cli_scene_opts. */
typedef struct render_args {
    const char *out;
    silk_image_format out_fmt;       /* --image-format, for -o - */
    int compare;
    int ssaa;                        /* 1: without */
    series se;
    int use_series;                  /* a series option was given */
    cli_object obj[CLI_SCENE_MAX];   /* several meshes: --place, --tint, --mode-of (render_scene.c) */
} render_args;

static void render_defaults(void *base)
{
    render_args *r = base;
    memset(r, 0, sizeof *r);
    r->ssaa = 1;
    r->se.views = 1;
    r->se.pixels = 1;
}

static int parse_modes(const cli_opt *o, const char *v, void *base)
{
    render_args *r = base;
    return cli_parse_modes(o->name, v, r->se.mode, SERIES_MAX_MODES, &r->se.nmodes);
}

/* The options of one of several meshes (render_scene.c). */
static int parse_place(const cli_opt *o, const char *v, void *base)
{
    return cli_parse_place(o->name, v, ((render_args *)base)->obj);
}

static int parse_tint(const cli_opt *o, const char *v, void *base)
{
    return cli_parse_tint(o->name, v, ((render_args *)base)->obj);
}

static int parse_mode_of(const cli_opt *o, const char *v, void *base)
{
    return cli_parse_mode_of(o->name, v, ((render_args *)base)->obj);
}

#define F(member) CLI_FIELD(render_args, member)
#define SERIES CLI_SEEN(render_args, use_series)
static const int image_fmt_v[] = { SILK_IMAGE_PNG, SILK_IMAGE_PPM };
static const cli_opt render_rows[] = {
    { .name = "--output", .alt = "-o", .group = "", .kind = CLI_OUTPUT, .meta = "OUT", F(out),
      .help = "the image to write (.png or .ppm), atomically; - is standard output" },
    { .name = "--image-format", .kind = CLI_CHOICE, .choices = "png|ppm", .values = image_fmt_v, F(out_fmt),
      .help = "the format for -o - (default png)" },
    { .name = "--compare", .kind = CLI_FLAG, F(compare),
      .help = "flat and the mode of --mode (default smooth) side by side: an image twice as wide" },
    { .name = "--ssaa", .kind = CLI_INT, .meta = "N", .lo = 2, .hi = 8, F(ssaa),
      .help = "reference picture: draw N x N times larger (%R) without anti-aliasing and average each N x N block "
              "(alpha: the share of the block the object covers)" },
    { .name = "--place", .group = "Several meshes in one picture (MESH MESH ...)", .kind = CLI_CUSTOM,
      .meta = "N:X,Y,Z[:YAW,PITCH,ROLL[:SCALE]]", .parse = parse_place,
      .help = "put mesh N (1: the first on the command line) at X,Y,Z in the world, turned by YAW about y, then "
              "PITCH about x, ROLL about z (degrees, applied roll first), SCALE times its size; the default camera "
              "frames every mesh so placed" },
    { .name = "--tint", .kind = CLI_CUSTOM, .meta = "N:RRGGBB", .parse = parse_tint,
      .help = "mesh N's base colour (else --color, else its material's)" },
    { .name = "--mode-of", .kind = CLI_CUSTOM, .meta = "N:MODE", .parse = parse_mode_of,
      .help = "mesh N's mode (else --mode), e.g. 2:flat" },
    { .name = "--turntable", .group = "Series (docs/viewer.md)", .kind = CLI_INT, .meta = "N", .lo = 1,
      .hi = SERIES_MAX_VIEWS, F(se.views), SERIES,
      .help = "N views around the model (%R), turning about the up axis from the first view; OUT holds the frame "
              "number, e.g. -o out/turn_%%03d.png, unless --sheet" },
    { .name = "--modes", .kind = CLI_CUSTOM, .meta = "LIST", SERIES, .parse = parse_modes,
      .help = "render modes to compare, e.g. flat,smooth,blend,pn (pnL: PN triangles at level L; clip and siltex: a "
              "prepared model's; MODE-noaa: without anti-aliasing); needs --sheet for more than one" },
    { .name = "--sheet", .kind = CLI_FLAG, F(se.sheet), SERIES,
      .help = "one contact sheet at OUT: the modes side by side, the views in rows, each labelled with mode and "
              "triangles drawn" },
    { .name = "--zoom", .kind = CLI_REAL, .meta = "Z", .lo = 1, .hi = 64, F(se.zoom), SERIES,
      .help = "close-up, Z times (%R) magnified around a point of the silhouette (the rightmost silhouette "
              "triangle)" },
    { .name = "--pixels", .kind = CLI_INT, .meta = "N", .lo = 2, .hi = 16, F(se.pixels), SERIES,
      .help = "with --sheet: draw each cell N times smaller (%R) and magnify it N times, pixel by pixel, to show its "
              "pixels" },
    { .name = NULL },
};
#undef F

const cli_command cmd_render_spec = {
    .name = "render",
    .usage = "usage: silk render MESH [MESH ...] -o OUT.png|OUT.ppm [options]\n",
    .about =
        "Render MESH (OBJ, PLY, STL or a prepared .silk model; - for standard input)\n"
        "to an image; the format follows OUT's extension.  The default camera frames\n"
        "the model's mesh in every mode (a prepared model's coarse mesh: clip and\n"
        "siltex draw its hull from the same view).  Several meshes draw one picture\n"
        "with one depth: each placed by --place, coloured by --tint, in --mode-of.\n",
    .examples =
        "  silk render sphere.obj -o sphere.png\n"
        "  silk render bunny.obj -o bunny.png --size 1024x768 --mode flat --wire\n"
        "  silk render torus.obj -o t.ppm --eye 0,3,3 --ortho 1.6 --format rgb565\n"
        "  silk render bunny.obj -o bunny.png --yaw 90 --pitch 30 --color e0a040 --bg none\n"
        "  silk render bunny.obj -o lit.png --light -1,1,1 --light point:2,0,2:ff8040\n"
        "  silk gen sphere -o - | silk render - -o - > sphere.png\n"
        "  silk render bunny.obj --turntable 36 -o out/turn_%03d.png\n"
        "  silk render bunny.obj --modes flat,smooth,blend,pn --sheet -o modes.png --size 320x240\n"
        "  silk render bunny.silk --modes flat,smooth,clip,siltex --sheet -o modes.png --size 320x240\n"
        "  silk render torus.obj sphere.obj -o two.png --place 2:0.8,0.1,0.1:30,0,10:0.55 --tint 2:8090c0\n",
    .sets = { { render_rows, 0, sizeof(render_args), render_defaults, NULL }, CLI_SCENE_SET(CLI_OPT_ALL) },
    .nsets = 2,
};

/* Copy a w x h frame into columns [x0, x0+w) of a wider image. */
static void blit(const silk_target *src, uint8_t *dst, size_t dst_stride, int x0)
{
    size_t bpp = silk_pixfmt_bytes(src->fmt);
    for (int y = 0; y < src->height; y++)
        memcpy(dst + (size_t)y * dst_stride + (size_t)x0 * bpp, src->color + (size_t)y * src->stride,
               (size_t)src->width * bpp);
}

/* One line when the arena left outline pixels without anti-aliasing
 * (silk_frame_stats.aa_aliased). */
static void aliased_warning(void)
{
    fprintf(stderr, "silk: warning: the arena ran short for anti-aliasing; part of the outline is left aliased\n");
}

/* --ssaa: the n x n blocks of big (the scene drawn n times larger) averaged
 * into small; with alpha (--bg none) each block's colour is the mean of
 * its covered samples and its alpha their share. */
static int ssaa_reduce(const silk_target *big, int n, silk_target *small, uint8_t **alpha, int with_alpha)
{
    size_t bpp = silk_pixfmt_bytes(big->fmt), w = (size_t)(big->width / n), h = (size_t)(big->height / n);
    uint8_t *px = malloc(w * h * bpp);
    *alpha = with_alpha ? malloc(w * h) : NULL;
    if (!px || (with_alpha && !*alpha)) {
        free(px);
        free(*alpha);
        return cli_fail(CLI_EXIT_INPUT, "out of memory for the --ssaa image");
    }
    silk_target_init(small, (int)w, (int)h, 0, (int)h, big->fmt, px, NULL);
    for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++) {
            uint32_t sum[3] = { 0, 0, 0 }, k = 0, covered = 0;
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    size_t bx = x * (size_t)n + (size_t)i, by = y * (size_t)n + (size_t)j;
                    int in = big->depth[by * (size_t)big->width + bx] != 0;
                    covered += in;
                    if (with_alpha && !in) continue;
                    uint32_t rgb = silk_target_get(big, (int)bx, (int)by);
                    for (int c = 0; c < 3; c++) sum[c] += (rgb >> (16 - 8 * c)) & 255;
                    k++;
                }
            uint32_t rgb = 0;
            for (int c = 0; k && c < 3; c++) rgb |= (sum[c] + k / 2) / k << (16 - 8 * c);
            silk_target_put(small, (int)x, (int)y, rgb);
            if (with_alpha) (*alpha)[y * w + x] = (uint8_t)((covered * 255 + (uint32_t)(n * n) / 2) / (uint32_t)(n * n));
        }
    small->alpha = *alpha;
    return 0;
}

static int render(cli_scene_opts *o, const char *out, silk_image_format out_fmt, int compare, int ssaa)
{
    /* Without --arena: when the frame ran out of scratch and fell back to
     * unsmoothed triangles, double the arena and render again. */
    for (int attempt = 0;; attempt++) {
        cli_scene s;
        o->arena_doublings = attempt;
        int rc = cli_scene_load(&s, o);
        if (rc) {
            cli_scene_free(&s);
            return rc;
        }
        silk_error err;
        silk_frame_stats stats;
        int fell_back = 0;
        uint32_t aliased = 0;
        uint8_t *wide = NULL;
        size_t bpp = silk_pixfmt_bytes(o->fmt), wide_stride = 2 * (size_t)o->width * bpp;
        silk_render_opts ro = o->render;
        for (int pass = 0; pass < (compare ? 2 : 1); pass++) {
            /* --compare: flat, then the mode, each with its own look */
            ro.mode = compare && pass == 0 ? SILK_MODE_FLAT : o->render.mode;
            cli_scene_render_opts(&s, &ro);
            silk_phong phong;
            silk_hal hal;
            cli_scene_phong(&s, o, ro.mode, &s.view, &phong);
            silk_hal_phong(&hal, &phong);
            silk_status st = silk_render(&s.arena, cli_scene_mesh(&s, ro.mode), &s.view, &hal, &ro, &s.target, &stats,
                                         &err);
            if (st != SILK_OK) {
                free(wide);
                cli_scene_free(&s);
                return cli_fail(CLI_EXIT_INPUT, "%s: %s", cli_input_name(o->mesh_path), err.msg);
            }
            fell_back |= stats.fell_back;
            aliased += stats.aa_aliased;
            if (compare) {
                if (!wide && !(wide = malloc(wide_stride * (size_t)o->height))) {
                    cli_scene_free(&s);
                    return cli_fail(CLI_EXIT_INPUT, "out of memory for the --compare image");
                }
                blit(&s.target, wide, wide_stride, pass * o->width);
            }
        }
        if (fell_back && !o->arena_bytes && attempt < 4) {
            free(wide);
            cli_scene_free(&s);
            continue;
        }
        silk_target image = s.target;
        if (compare) {
            image.width = 2 * o->width;
            image.color = wide;
            image.stride = wide_stride;
            image.depth = NULL;
            image.writes = NULL;
        }
        uint8_t *alpha = NULL;
        if (ssaa > 1) {
            int xrc = ssaa_reduce(&s.target, ssaa, &image, &alpha, o->bg_none);
            if (xrc) {
                cli_scene_free(&s);
                return xrc;
            }
        }
        int wrc = cli_write_image(&image, out, out_fmt, cli_alpha_for(o), o->render.bg_rgb);
        if (ssaa > 1) free(image.color);
        free(alpha);
        free(wide);
        cli_scene_free(&s);
        if (wrc) return wrc;
        if (fell_back)
            fprintf(stderr, "silk: warning: the arena ran out during the frame; part of it is not smoothed\n");
        else if (aliased)
            aliased_warning();
        return 0;
    }
}

/* ---- frame series ----------------------------------------------------------------- */

static void v3_to_double(silk_vec3 v, double d[3])
{
    d[0] = cli_fx_to_double(v.x);
    d[1] = cli_fx_to_double(v.y);
    d[2] = cli_fx_to_double(v.z);
}

/* The close-up: the same eye, looking at the corner of a silhouette
 * triangle (one whose corner normals disagree about facing the eye, paper
 * III-B) that lies farthest right on screen, with the view zoom times
 * narrower.  Without silhouette triangles, the rightmost vertex. */
static int zoom_camera(const cli_scene *s, double zoom, silk_camera *cam)
{
    silk_view v;
    silk_error err;
    if (silk_view_init(&v, cam, &err) != SILK_OK) return cli_fail(CLI_EXIT_USAGE, "%s", err.msg);
    const silk_mesh *m = &s->mesh;   /* the point every mode's close-up looks at */
    for (int pass = 0; pass < 2; pass++) {
        silk_fx best = SILK_FX_MIN;
        for (uint32_t t = 0; t < m->ntris; t++) {
            int vis[3];
            for (int k = 0; k < 3; k++) vis[k] = silk_normal_visible(m, &v, silk_mesh_corner_normal(m, 3 * t + k));
            if (pass == 0 && vis[0] == vis[1] && vis[1] == vis[2]) continue;
            for (int k = 0; k < 3; k++) {
                silk_vec2 px;
                silk_vec3 p = silk_mesh_pos(m, silk_mesh_corner(m, 3 * t + k));
                if (silk_view_project(&v, p, &px) && px.x > best) {
                    best = px.x;
                    cam->target = p;
                }
            }
        }
        if (best != SILK_FX_MIN) break;
    }
    if (cam->ortho) {
        cam->ortho_half_height = cli_fx_from_double(cli_fx_to_double(cam->ortho_half_height) / zoom);
        if (cam->ortho_half_height < SILK_ZNEAR_MIN)
            return cli_fail(CLI_EXIT_USAGE, "--zoom %g: the view would be smaller than 1/1024 model units", zoom);
    } else {
        const double deg = CLI_DEG;
        double fov = 2 * atan(tan(cli_fx_to_double(cam->fov_deg) * deg / 2) / zoom) / deg;
        if (fov < cli_fx_to_double(SILK_FOV_MIN))
            return cli_fail(CLI_EXIT_USAGE, "--zoom %g: the field of view would be %.2f degrees (at least %g)", zoom, fov,
                            cli_fx_to_double(SILK_FOV_MIN));
        cam->fov_deg = cli_fx_from_double(fov);
    }
    return 0;
}

/* View k of the series: the scene's camera turned k/views of a full turn
 * about its up axis through the target (Rodrigues' rotation), with near and
 * far planes placed again by cli_camera. */
static int series_view(const cli_scene_opts *o, const cli_scene *s, const series *se, int k, silk_view *v)
{
    silk_camera cam = s->cam;
    if (k > 0) {
        double e[3], t[3], u[3], d[3], r[3];
        v3_to_double(cam.eye, e);
        v3_to_double(cam.target, t);
        v3_to_double(cam.up, u);
        double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int i = 0; i < 3; i++) {
            u[i] /= ul;
            d[i] = e[i] - t[i];
        }
        double a = 2 * CLI_PI * k / se->views, c = cos(a), sn = sin(a);
        double ud = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
        double x[3] = { u[1] * d[2] - u[2] * d[1], u[2] * d[0] - u[0] * d[2], u[0] * d[1] - u[1] * d[0] };
        for (int i = 0; i < 3; i++) r[i] = d[i] * c + x[i] * sn + u[i] * ud * (1 - c);
        cli_scene_opts turned = *o;
        turned.have_eye = turned.have_target = turned.have_up = 1;
        turned.yaw = turned.pitch = 0;   /* the first view has them */
        for (int i = 0; i < 3; i++) {
            turned.eye[i] = t[i] + r[i];
            turned.target[i] = t[i];
            turned.up[i] = u[i];
        }
        int rc = cli_scene_camera(s, &turned, &cam);
        if (rc) return rc;
    }
    if (se->zoom > 1) {
        int rc = zoom_camera(s, se->zoom, &cam);
        if (rc) return rc;
    }
    silk_error err;
    if (silk_view_init(v, &cam, &err) != SILK_OK) return cli_fail(CLI_EXIT_USAGE, "%s", err.msg);
    return 0;
}

/* The label under a cell: mode and triangles drawn, then what else tells
 * the frames apart.  Short enough for a 240 pixel cell at font scale 2
 * (20 characters); what all cells share is in the title. */
static void cell_label(const series *se, const silk_render_opts *ro, const silk_frame_stats *st, int k,
                       char *buf, size_t n)
{
    char mode[16], more[64];
    if (ro->mode == SILK_MODE_PN) snprintf(mode, sizeof mode, "pn%u", (unsigned)ro->level);
    else snprintf(mode, sizeof mode, "%s%s", silk_mode_name(ro->mode), ro->aa ? "" : "-noaa");
    if (se->views > 1)
        snprintf(more, sizeof more, "view %d/%d +%g deg", k + 1, se->views, 360.0 * k / se->views);
    else if (ro->mode == SILK_MODE_SMOOTH)
        snprintf(more, sizeof more, "%u silhouette", (unsigned)st->silhouette_tris);
    else if (ro->mode == SILK_MODE_BLEND)
        snprintf(more, sizeof more, "beta %g", cli_fx_to_double(ro->blend_beta));
    else if (ro->mode == SILK_MODE_PN)
        snprintf(more, sizeof more, "%s normals", ro->pn_normals == SILK_PN_LINEAR ? "linear" : "quadratic");
    else if (ro->mode == SILK_MODE_CLIP)
        snprintf(more, sizeof more, "hull, map");
    else if (ro->mode == SILK_MODE_SILTEX)
        snprintf(more, sizeof more, "hull, texture");
    else
        snprintf(more, sizeof more, "coarse mesh");
    snprintf(buf, n, "%s  %u tris\n%s", mode, (unsigned)st->tris_drawn, more);
}

static void sheet_title(const cli_scene_opts *o, const series *se, char *buf, size_t n)
{
    const char *name = cli_input_name(o->mesh_path), *base = strrchr(name, '/');
    base = base ? base + 1 : name;
    snprintf(buf, n, "%s  %dx%d %s, tol %g px%s", base, o->width, o->height, o->ortho ? "ortho" : "perspective",
             cli_fx_to_double(o->render.tolerance_px), o->render.wire ? ", wireframe" : "");
    if (se->zoom > 1) snprintf(buf + strlen(buf), n - strlen(buf), ", close-up x%g", se->zoom);
    if (se->pixels > 1) snprintf(buf + strlen(buf), n - strlen(buf), ", pixels x%d", se->pixels);
}

/* frame magnified n times, pixel by pixel, into big (its buffer malloc'd
 * once by the caller: n * n times frame's). */
static void magnify(const silk_target *frame, int n, silk_target *big)
{
    for (int y = 0; y < big->height; y++)
        for (int x = 0; x < big->width; x++) silk_target_put(big, x, y, silk_target_get(frame, x / n, y / n));
}

/* Render every view and mode of the series from the loaded scene s: into
 * one sheet, or each frame into its own file (*written counts them). */
static int series_frames(const cli_scene_opts *o, const char *out, silk_image_format out_fmt, const series *se,
                         cli_scene *s, int *fell_back, uint32_t *aliased, int *written)
{
    int nmodes = se->nmodes ? se->nmodes : 1, cols, rows, rc = 0;
    if (nmodes > 1) {
        cols = nmodes;
        rows = se->views;
    } else {
        for (cols = 1; cols * cols < se->views; cols++) {}
        rows = (se->views + cols - 1) / cols;
    }
    sheet sh;
    memset(&sh, 0, sizeof sh);
    if (se->sheet) {
        char title[200];
        sheet_title(o, se, title, sizeof title);
        silk_error err;
        if (sheet_init(&sh, cols, rows, o->width * se->pixels, o->height * se->pixels, title, &err) != SILK_OK) {
            sheet_free(&sh);
            return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        }
    }
    silk_target big;
    uint8_t *big_px = NULL;
    if (se->pixels > 1) {
        size_t bytes = (size_t)o->width * o->height * se->pixels * se->pixels * silk_pixfmt_bytes(o->fmt);
        if (!(big_px = malloc(bytes))) {
            sheet_free(&sh);
            return cli_fail(CLI_EXIT_INPUT, "out of memory for the --pixels cells");
        }
        silk_target_init(&big, o->width * se->pixels, o->height * se->pixels, 0, o->height * se->pixels, o->fmt, big_px,
                         NULL);
    }
    progress pr;
    progress_start(&pr, o->quiet, "render");
    for (int k = 0; k < se->views && !rc; k++) {
        progress_update(&pr, k, se->views);
        silk_view view;
        if ((rc = series_view(o, s, se, k, &view)) != 0) break;
        for (int m = 0; m < nmodes && !rc; m++) {
            silk_render_opts ro = o->render;
            if (se->nmodes) {
                ro.mode = se->mode[m].mode;
                if (se->mode[m].aa_off) ro.aa = 0;
                if (se->mode[m].level) ro.level = se->mode[m].level;
            }
            cli_scene_render_opts(s, &ro);
            silk_phong phong;
            silk_hal hal;
            cli_scene_phong(s, o, ro.mode, &view, &phong);
            silk_hal_phong(&hal, &phong);
            silk_error err;
            silk_frame_stats st;
            if (silk_render(&s->arena, cli_scene_mesh(s, ro.mode), &view, &hal, &ro, &s->target, &st, &err) != SILK_OK) {
                rc = cli_fail(CLI_EXIT_INPUT, "%s: %s", cli_input_name(o->mesh_path), err.msg);
                break;
            }
            *fell_back |= st.fell_back;
            *aliased += st.aa_aliased;
            if (se->sheet) {
                char label[160];
                cell_label(se, &ro, &st, k, label, sizeof label);
                int c = nmodes > 1 ? m : k % cols, r = nmodes > 1 ? k : k / cols;
                if (big_px) magnify(&s->target, se->pixels, &big);
                sheet_put(&sh, c, r, big_px ? &big : &s->target, label);
                continue;
            }
            /* One view: OUT as given, even with a '%' in it. */
            char path[4096];
            if (se->views > 1 && pattern_path(out, k, path, sizeof path) != 0) {
                rc = cli_fail(CLI_EXIT_USAGE, "render: output name too long: %s", out);
                break;
            }
            if ((rc = cli_write_image(&s->target, se->views > 1 ? path : out, out_fmt, cli_alpha_for(o),
                                      o->render.bg_rgb)) != 0)
                break;
            ++*written;
        }
    }
    progress_end(&pr);
    if (se->sheet && !rc) {
        rc = cli_write_image(&sh.img, out, out_fmt, CLI_ALPHA_NONE, 0);
    }
    free(big_px);
    sheet_free(&sh);
    return rc;
}

static int render_series(cli_scene_opts *o, const char *out, silk_image_format out_fmt, const series *se)
{
    for (int attempt = 0;; attempt++) {
        cli_scene s;
        o->arena_doublings = attempt;
        int rc = cli_scene_load(&s, o);
        int fell_back = 0, written = 0;
        uint32_t aliased = 0;
        if (!rc) rc = series_frames(o, out, out_fmt, se, &s, &fell_back, &aliased, &written);
        cli_scene_free(&s);
        /* As in render(): a frame that ran out of scratch means a larger
         * arena and the whole series again. */
        if (!rc && fell_back && !o->arena_bytes && attempt < 4) continue;
        if (rc && se->views > 1 && !se->sheet) {
            char path[4096];
            for (int k = 0; k < written; k++)
                if (pattern_path(out, k, path, sizeof path) == 0) silk_file_remove_stale(path);
        }
        if (!rc && fell_back)
            fprintf(stderr, "silk: warning: the arena ran out during a frame; part of it is not smoothed\n");
        else if (!rc && aliased)
            aliased_warning();
        return rc;
    }
}

/* Several meshes in one picture: the checks of a single frame, then
 * render_scene.c. */
static int render_several(cli_scene_opts *o, const render_args *r, int n, const char *const *paths)
{
    if (!r->out) return cli_fail(CLI_EXIT_USAGE, "render: no output given (-o OUT.png or OUT.ppm)");
    if (!silk_path_is_stdio(r->out) && silk_image_format_for_path(r->out) == SILK_IMAGE_NONE)
        return cli_fail(CLI_EXIT_USAGE, "render: %s: unknown image format (use .png or .ppm)", r->out);
    if (r->compare || r->use_series || r->ssaa > 1)
        return cli_fail(CLI_EXIT_USAGE, "render: several meshes draw one frame (not --compare, --ssaa or a series)");
    int rc = cli_mode_check("render", o->render.mode, &o->render);
    if (rc) return rc;
    return cli_render_scene(o, r->out, r->out_fmt, n, paths, r->obj);
}

int cmd_render(int argc, char **argv)
{
    cli_scene_opts o;
    render_args r;
    cli_scene_opts_default(&o);
    render_defaults(&r);
    cli_args args;
    void *bases[] = { &r, &o };
    int rc = cli_parse(&cmd_render_spec, bases, argc, argv, &args);
    int several = !rc && args.npos > 1;
    if (several) rc = render_several(&o, &r, args.npos, args.pos);   /* render_scene.c */
    else if (!rc) rc = cli_one_mesh("render", args.npos, args.pos, "silk render MESH -o OUT.png", &o.mesh_path);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    if (rc || several) return rc;
    for (int i = 0; i < CLI_SCENE_MAX; i++)
        if (r.obj[i].given)
            return cli_fail(CLI_EXIT_USAGE, "render: --place, --tint and --mode-of are for several meshes (MESH MESH "
                            "...)");
    series *se = &r.se;
    const char *out = r.out;
    silk_image_format out_fmt = r.out_fmt;
    int compare = r.compare, use_series = r.use_series;
    long ssaa = r.ssaa;
    for (int m = 0; m < se->nmodes; m++) o.modes |= 1u << se->mode[m].mode;

    if (!out) rc = cli_fail(CLI_EXIT_USAGE, "render: no output given (-o OUT.png or OUT.ppm)");
    if (!rc && !silk_path_is_stdio(out) && silk_image_format_for_path(out) == SILK_IMAGE_NONE)
        rc = cli_fail(CLI_EXIT_USAGE, "render: %s: unknown image format (use .png or .ppm)", out);
    if (!rc && out_fmt && !silk_path_is_stdio(out) && out_fmt != silk_image_format_for_path(out))
        rc = cli_fail(CLI_EXIT_USAGE, "render: --image-format is for -o - (%s names its format)", out);
    if (!rc && o.bg_none && (compare || se->sheet))
        rc = cli_fail(CLI_EXIT_USAGE, "render: --bg none is for single frames (not --compare or --sheet)");
    if (!rc && silk_path_is_stdio(out) && se->views > 1 && !se->sheet)
        rc = cli_fail(CLI_EXIT_USAGE, "render: --turntable writes one file per view; -o - needs --sheet");
    if (!rc && compare && o.render.mode == SILK_MODE_FLAT)
        rc = cli_fail(CLI_EXIT_USAGE, "render: --compare puts flat beside the mode of --mode; give another mode than "
                      "flat (or --modes flat,... --sheet)");
    if (!rc && use_series) {
        if (compare)
            rc = cli_fail(CLI_EXIT_USAGE, "render: --compare is flat|MODE in one image; for a series use --modes flat,MODE --sheet");
        else if (se->nmodes > 1 && !se->sheet)
            rc = cli_fail(CLI_EXIT_USAGE, "render: --modes with %d modes needs --sheet (they go side by side into one image)", se->nmodes);
        else if (se->views > 1 && !se->sheet && pattern_check(out) != 1)
            rc = cli_fail(CLI_EXIT_USAGE, "render: --turntable %d writes %d images: -o needs one frame number such as "
                          "turn_%%03d.png (or use --sheet for one image)", se->views, se->views);
    }
    /* every mode drawn must take the line options */
    if (!rc) rc = cli_mode_check("render", o.render.mode, &o.render);
    if (!rc && compare) rc = cli_mode_check("render", SILK_MODE_FLAT, &o.render);
    for (int m = 0; !rc && m < se->nmodes; m++) rc = cli_mode_check("render", se->mode[m].mode, &o.render);
    /* A failed run leaves OUT as it was: images are written atomically, and
     * an earlier run's image stays. */
    if (!rc && se->pixels > 1 && !se->sheet) rc = cli_fail(CLI_EXIT_USAGE, "render: --pixels magnifies the cells of a --sheet");
    if (!rc && se->pixels > 1 && (o.width < se->pixels || o.height < se->pixels))
        rc = cli_fail(CLI_EXIT_USAGE, "render: --pixels %d: the cells of %dx%d would be smaller than a pixel", se->pixels,
                      o.width, o.height);
    if (!rc && se->pixels > 1) {
        /* the cells drawn that much smaller; the sheet keeps --size */
        o.width /= se->pixels;
        o.height /= se->pixels;
    }
    if (!rc && ssaa > 1 && (compare || use_series))
        rc = cli_fail(CLI_EXIT_USAGE, "render: --ssaa is for single frames (not --compare or a series)");
    if (!rc && ssaa > 1 && ((long)o.width * ssaa > SILK_MAX_DIM || (long)o.height * ssaa > SILK_MAX_DIM))
        rc = cli_fail(CLI_EXIT_USAGE, "render: --ssaa %ld draws %ldx%ld, more than %dx%d", ssaa, o.width * ssaa,
                      o.height * ssaa, SILK_MAX_DIM, SILK_MAX_DIM);
    if (!rc && ssaa > 1) {
        /* the scene n times larger, aliased; reduced after the frame */
        o.width *= (int)ssaa;
        o.height *= (int)ssaa;
        o.render.aa = 0;
    }
    if (!rc) rc = use_series ? render_series(&o, out, out_fmt, se) : render(&o, out, out_fmt, compare, (int)ssaa);
    return rc;
}
