/*
 * cmd_render.c - `silk render MESH -o OUT.png`: load a mesh, render one frame
 * with silk_render() through the default Phong stages, write PNG or PPM.
 *
 * The output is written atomically, and when the command fails a file left
 * at OUT by an earlier run is removed, so OUT exists afterwards only if this
 * run produced it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "../platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk render MESH -o OUT.png|OUT.ppm [options]\n"
            "\n"
            "Render MESH (OBJ or PLY) to an image; the format follows OUT's extension.\n"
            "\n"
            "  -o, --output OUT     the image to write (.png or .ppm); written atomically\n"
            "  --compare            flat and smooth side by side (an image twice as wide)\n");
    cli_print_scene_help(f);
    fprintf(f,
            "\n"
            "examples:\n"
            "  silk render sphere.obj -o sphere.png\n"
            "  silk render bunny.obj -o bunny.png --size 1024x768 --mode flat --wire\n"
            "  silk render torus.obj -o t.ppm --eye 0,3,3 --ortho 1.6 --format rgb565\n");
}

/* Copy a w x h frame into columns [x0, x0+w) of a wider image. */
static void blit(const silk_target *src, uint8_t *dst, size_t dst_stride, int x0)
{
    size_t bpp = silk_pixfmt_bytes(src->fmt);
    for (int y = 0; y < src->height; y++)
        memcpy(dst + (size_t)y * dst_stride + (size_t)x0 * bpp, src->color + (size_t)y * src->stride,
               (size_t)src->width * bpp);
}

static int render(cli_scene_opts *o, const char *out, int compare)
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
        uint8_t *wide = NULL;
        size_t bpp = silk_pixfmt_bytes(o->fmt), wide_stride = 2 * (size_t)o->width * bpp;
        silk_render_opts ro = o->render;
        for (int pass = 0; pass < (compare ? 2 : 1); pass++) {
            if (compare) ro.mode = pass == 0 ? SILK_MODE_FLAT : SILK_MODE_SMOOTH;
            silk_status st = silk_render(&s.arena, &s.mesh, &s.view, &s.hal, &ro, &s.target, &stats, &err);
            if (st != SILK_OK) {
                free(wide);
                cli_scene_free(&s);
                return cli_fail(CLI_EXIT_INPUT, "%s: %s", o->mesh_path, err.msg);
            }
            fell_back |= stats.fell_back;
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
        silk_status st = silk_image_write(&image, out, &err);
        free(wide);
        cli_scene_free(&s);
        if (st != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        if (fell_back)
            fprintf(stderr, "silk: warning: the arena ran out during the frame; part of it is not smoothed\n");
        return 0;
    }
}

int cmd_render(int argc, char **argv)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    const char *out = NULL;
    int compare = 0, rc = 0;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        }
        int r = cli_scene_option(&o, argc, argv, &i);
        if (r < 0) rc = CLI_EXIT_USAGE;
        if (r != 0) continue;
        if (cli_is(a, "-o") || cli_is(a, "--output")) {
            if (!(out = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--compare") == 0) {
            compare = 1;
        } else if (a[0] == '-' && a[1]) {
            rc = cli_fail(CLI_EXIT_USAGE, "render: unknown option %s (try silk render --help)", a);
        } else if (o.mesh_path) {
            rc = cli_fail(CLI_EXIT_USAGE, "render: one mesh at a time (got %s and %s)", o.mesh_path, a);
        } else {
            o.mesh_path = a;
        }
    }
    if (!rc && !o.mesh_path) rc = cli_fail(CLI_EXIT_USAGE, "render: no mesh given (silk render MESH -o OUT.png)");
    if (!rc && !out) rc = cli_fail(CLI_EXIT_USAGE, "render: no output given (-o OUT.png or OUT.ppm)");
    if (!rc && silk_image_format_for_path(out) == SILK_IMAGE_NONE)
        rc = cli_fail(CLI_EXIT_USAGE, "render: %s: unknown image format (use .png or .ppm)", out);
    if (!rc) rc = render(&o, out, compare);

    /* An image at OUT after a failure would be an earlier run's (but never
     * remove the input: "silk render x.ppm -o x.ppm" fails to load it). */
    const char *stale = out ? out : cli_find_output(argc, argv);
    if (rc && stale && silk_image_format_for_path(stale) != SILK_IMAGE_NONE &&
        !(o.mesh_path && silk_file_same(stale, o.mesh_path)))
        silk_file_remove_stale(stale);
    return rc;
}
