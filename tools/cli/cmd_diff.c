/*
 * cmd_diff.c - `silk diff A.png B.png [--bg RRGGBB] [-o DIFF.png]`: how far
 * the silhouette of render B is from that of render A (the reference), by
 * the object masks (pixel != background) of the two images.  The metrics
 * (tools/image/mask.c) are defined in docs/measurements.md.  One line on stdout:
 *   diff A B differing=N boundary=N mean_px=X hausdorff_px=X
 * or, with --json, one JSON object with the same values.  A and B are PNG
 * or PPM files, told apart by their content.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "image/mask.h"
#include "platform/platform.h"
#include "platform/png_read.h"

typedef struct diff_args {
    uint32_t bg;
    const char *out;
    int json;
} diff_args;

static void diff_defaults(void *base)
{
    diff_args *a = base;
    memset(a, 0, sizeof *a);
    a->bg = 0xFFFFFF;
}

#define F(member) CLI_FIELD(diff_args, member)
static const cli_opt diff_rows[] = {
    { .name = "--bg", .group = "", .kind = CLI_RGB, .meta = "RRGGBB", F(bg),
      .help = "background colour of both images (default %D, the background of silk render)" },
    { .name = "--output", .alt = "-o", .kind = CLI_OUTPUT, .meta = "DIFF.png", F(out),
      .help = "picture of the differences: both grey, only A red, only B blue, neither white (a PNG, written "
              "atomically)" },
    { .name = "--json", .kind = CLI_FLAG, F(json),
      .help = "the result as one JSON object (docs/formats.md): {\"schema\": \"silk-diff/1\", \"a\", \"b\", "
              "\"width\", \"height\", \"differing\", \"boundary\", \"mean_px\", \"hausdorff_px\"}, with null for inf" },
    { .name = NULL },
};
#undef F

const cli_command cmd_diff_spec = {
    .name = "diff",
    .usage = "usage: silk diff A.png B.png [--bg RRGGBB] [-o DIFF.png] [--json]\n",
    .about =
        "Compare the silhouettes of two renders of the same size (PNG or PPM; - reads\n"
        "one from standard input).  A pixel belongs to the object when it differs from\n"
        "the background colour (a transparent pixel counts as background); A is the\n"
        "reference.  Prints one line:\n"
        "  diff A B differing=N boundary=N mean_px=X hausdorff_px=X\n"
        "  differing     pixels that are object in one image and background in the other\n"
        "  boundary      length of A's outline in pixels (Cauchy-Crofton estimate)\n"
        "  mean_px       differing / boundary: the mean distance between the outlines\n"
        "  hausdorff_px  Hausdorff distance between the boundary pixels of A and B\n"
        "                (exact Euclidean; inf when only one image has an object)\n",
    .examples =
        "  (the same camera for both: the default one frames each mesh by its own\n"
        "  bounding box)\n"
        "  silk render bunny-fine.obj -o fine.png --mode flat --eye 1.5,1.2,3.5 --target 0,0,0\n"
        "  silk render bunny-500.obj -o smooth.png --eye 1.5,1.2,3.5 --target 0,0,0\n"
        "  silk diff fine.png smooth.png -o diff.png\n",
    .sets = { { diff_rows, 0, sizeof(diff_args), diff_defaults, NULL } },
    .nsets = 1,
};

/* "inf" instead of printf's platform-dependent spelling. */
static void print_px(const char *name, double v)
{
    if (v > 1e300) printf(" %s=inf", name);
    else printf(" %s=%.3f", name, v);
}

static void json_px(const char *name, double v, const char *end)
{
    if (v > 1e300) printf("\"%s\": null%s", name, end);
    else printf("\"%s\": %.6g%s", name, v, end);
}

static int diff(const char *pa, const char *pb, uint32_t bg, const char *out, int json)
{
    uint8_t *ra = NULL, *rb = NULL, *ma = NULL, *mb = NULL;
    int wa, ha, wb, hb, rc = 0;
    silk_error err;
    if (silk_image_read(pa, bg, &ra, &wa, &ha, &err) != SILK_OK ||
        silk_image_read(pb, bg, &rb, &wb, &hb, &err) != SILK_OK) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        goto done;
    }
    if (wa != wb || ha != hb) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s is %dx%d but %s is %dx%d: compare renders of the same size", pa, wa, ha,
                      pb, wb, hb);
        goto done;
    }
    size_t n = (size_t)wa * ha;
    ma = malloc(n);
    mb = malloc(n);
    if (!ma || !mb) {
        rc = cli_fail(CLI_EXIT_INPUT, "out of memory for %dx%d masks", wa, ha);
        goto done;
    }
    mask_from_rgb(ra, (size_t)wa * 3, wa, ha, bg, ma);
    mask_from_rgb(rb, (size_t)wb * 3, wb, hb, bg, mb);
    mask_stats st;
    if (mask_compare(ma, mb, wa, ha, &st) != 0) {
        rc = cli_fail(CLI_EXIT_INPUT, "out of memory comparing %dx%d images", wa, ha);
        goto done;
    }
    if (out) {
        /* the picture reuses A's pixels */
        mask_diff_image(ma, mb, wa, ha, ra);
        silk_target t;
        silk_target_init(&t, wa, ha, 0, ha, SILK_PIX_RGB888, ra, NULL);
        if (silk_png_write(&t, out, &err) != SILK_OK) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
            goto done;
        }
    }
    if (json) {
        printf("{\"schema\": \"silk-diff/1\", \"a\": ");
        cli_json_string(stdout, cli_input_name(pa));
        printf(", \"b\": ");
        cli_json_string(stdout, cli_input_name(pb));
        printf(", \"width\": %d, \"height\": %d, \"differing\": %llu, \"boundary\": %.0f, ", wa, ha,
               (unsigned long long)st.differing, st.length_a);
        json_px("mean_px", st.mean_px, ", ");
        json_px("hausdorff_px", st.hausdorff_px, "}\n");
    } else {
        printf("diff %s %s differing=%llu boundary=%.0f", pa, pb, (unsigned long long)st.differing, st.length_a);
        print_px("mean_px", st.mean_px);
        print_px("hausdorff_px", st.hausdorff_px);
        printf("\n");
    }
done:
    free(ra), free(rb), free(ma), free(mb);
    return rc;
}

int cmd_diff(int argc, char **argv)
{
    diff_args da;
    diff_defaults(&da);
    cli_args args;
    void *bases[] = { &da };
    int rc = cli_parse(&cmd_diff_spec, bases, argc, argv, &args);
    const char *files[2] = { args.npos > 0 ? args.pos[0] : NULL, args.npos > 1 ? args.pos[1] : NULL };
    if (!rc && args.npos > 2) rc = cli_fail(CLI_EXIT_USAGE, "diff: two images only (got a third, %s)", args.pos[2]);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    const char *out = da.out;
    if (!rc && !files[1]) rc = cli_fail(CLI_EXIT_USAGE, "diff: two images needed (silk diff A.png B.png)");
    if (!rc && silk_path_is_stdio(files[0]) && silk_path_is_stdio(files[1]))
        rc = cli_fail(CLI_EXIT_USAGE, "diff: only one image can come from standard input");
    if (!rc && out && silk_path_is_stdio(out))
        rc = cli_fail(CLI_EXIT_USAGE, "diff: -o -: standard output carries the result; give a file name");
    if (!rc && out && !silk_path_is_stdio(out) && silk_image_format_for_path(out) != SILK_IMAGE_PNG)
        rc = cli_fail(CLI_EXIT_USAGE, "diff: %s: the picture of the differences is a PNG (use .png)", out);
    /* A failed run leaves OUT as it was (written atomically). */
    if (!rc) rc = diff(files[0], files[1], da.bg, out, da.json);
    return rc;
}
