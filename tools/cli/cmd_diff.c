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

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk diff A.png B.png [--bg RRGGBB] [-o DIFF.png] [--json]\n"
            "\n"
            "Compare the silhouettes of two renders of the same size (PNG or PPM; - reads\n"
            "one from standard input).  A pixel belongs to the object when it differs from\n"
            "the background colour (a transparent pixel counts as background); A is the\n"
            "reference.  Prints one line:\n"
            "  diff A B differing=N boundary=N mean_px=X hausdorff_px=X\n"
            "  differing     pixels that are object in one image and background in the other\n"
            "  boundary      length of A's outline in pixels (Cauchy-Crofton estimate)\n"
            "  mean_px       differing / boundary: the mean distance between the outlines\n"
            "  hausdorff_px  Hausdorff distance between the boundary pixels of A and B\n"
            "                (exact Euclidean; inf when only one image has an object)\n"
            "\n"
            "  --bg RRGGBB           background colour of both images (default ffffff,\n"
            "                        the background of silk render)\n"
            "  -o, --output DIFF.png picture of the differences: both grey, only A red,\n"
            "                        only B blue, neither white (a PNG, written atomically)\n"
            "  --json                the result as one JSON object (docs/formats.md):\n"
            "                        {\"schema\": \"silk-diff/1\", \"a\", \"b\", \"width\", \"height\",\n"
            "                        \"differing\", \"boundary\", \"mean_px\", \"hausdorff_px\"}, with\n"
            "                        null for inf\n"
            "\n"
            "example (the same camera for both: the default one frames each mesh by\n"
            "its own bounding box):\n"
            "  silk render bunny-fine.obj -o fine.png --mode flat --eye 1.5,1.2,3.5 --target 0,0,0\n"
            "  silk render bunny-500.obj -o smooth.png --eye 1.5,1.2,3.5 --target 0,0,0\n"
            "  silk diff fine.png smooth.png -o diff.png\n");
}

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
    const char *files[2] = { NULL, NULL }, *out = NULL;
    int nfiles = 0, rc = 0, json = 0;
    uint32_t bg = 0xFFFFFF;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i], *v;
        if (cli_help(a, help)) return 0;
        if (cli_is(a, "--bg")) {
            if (!(v = cli_value(argc, argv, &i)) || cli_parse_rgb("--bg", v, &bg)) rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--json") == 0) {
            json = 1;
        } else if (cli_is(a, "-o") || cli_is(a, "--output")) {
            if (!(out = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (a[0] == '-' && a[1]) {
            rc = cli_unknown_option("diff", a);
        } else if (nfiles == 2) {
            rc = cli_fail(CLI_EXIT_USAGE, "diff: two images only (got a third, %s)", a);
        } else {
            files[nfiles++] = a;
        }
    }
    if (!rc && nfiles < 2) rc = cli_fail(CLI_EXIT_USAGE, "diff: two images needed (silk diff A.png B.png)");
    if (!rc && nfiles == 2 && silk_path_is_stdio(files[0]) && silk_path_is_stdio(files[1]))
        rc = cli_fail(CLI_EXIT_USAGE, "diff: only one image can come from standard input");
    if (!rc && out && silk_path_is_stdio(out))
        rc = cli_fail(CLI_EXIT_USAGE, "diff: -o -: standard output carries the result; give a file name");
    if (!rc && out && !silk_path_is_stdio(out) && silk_image_format_for_path(out) != SILK_IMAGE_PNG)
        rc = cli_fail(CLI_EXIT_USAGE, "diff: %s: the picture of the differences is a PNG (use .png)", out);
    /* A failed run leaves OUT as it was (written atomically). */
    if (!rc) rc = diff(files[0], files[1], bg, out, json);
    return rc;
}
