/*
 * cmd_prepare.c - `silk prepare FINE -o MODEL.silk --triangles N`: a
 * detailed mesh made into a prepared model (silk/model.h): the coarse mesh
 * smooth mode wants - simplified by subset placement so every vertex lies
 * on the detailed surface (tools/simplify.c), with the detailed surface's
 * normals there, split along feature edges (tools/surface.c) - in fixed
 * point, in one checked binary file (tools/model_file.c).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fit.h"
#include "commands.h"
#include "model_file.h"
#include "simplify.h"
#include "surface.h"
#include "../platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk prepare FINE -o MODEL.silk --triangles N [options]\n"
            "\n"
            "Make the detailed mesh FINE (OBJ, PLY or STL; - for standard input) into a\n"
            "prepared model: a coarse mesh of N triangles whose vertices are vertices of\n"
            "FINE (so they lie on its surface) and whose normals are FINE's normals there,\n"
            "split along feature edges - the mesh smooth mode draws best.  flat, smooth, pn\n"
            "and blend draw it; every silk command that takes a mesh takes MODEL.silk.\n"
            "Written atomically.  Prints:\n"
            "  prepare FINE MODEL triangles=N vertices=N normals=N bytes=N\n"
            "\n"
            "options:\n"
            "  -o, --output FILE   the prepared model (.silk)\n"
            "  --triangles N       triangles of the coarse mesh (at least 4)\n"
            "  --crease DEG        dihedral angle above which an edge is a feature [60]\n"
            "  --feature-weight W  weight of the feature constraint planes, 0..1e6 [100]\n"
            "  --fit               move each normal (up to 30 degrees) so that the curves\n"
            "                      smooth mode builds over its edges follow FINE closer\n"
            "  --scale S           multiply coordinates by S while reading (as silk render)\n"
            "  --quiet             no progress line on a terminal\n"
            "\n"
            "example:\n"
            "  silk prepare bunny-fine.obj -o bunny.silk --triangles 500\n");
}

static silk_fx to_fx(double x) { return (silk_fx)llround(x * 65536.0); }

/* The coarse mesh and its normals as a prepared model at path. */
static int write_model(const simp_mesh *m, const surf_normals *sn, const char *path, size_t *bytes)
{
    silk_vec3 *pos = malloc((m->nverts ? m->nverts : 1) * sizeof *pos);
    silk_vec3 *nrm = malloc((sn->nnormals ? sn->nnormals : 1) * sizeof *nrm);
    model_out mo = { 0 };
    int rc = 0;
    if (!pos || !nrm) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", path);
        goto done;
    }
    /* Input vertices were Q16.16 already: these round trips are exact. */
    for (uint32_t i = 0; i < m->nverts; i++)
        pos[i] = silk_v3(to_fx(m->pos[3 * i]), to_fx(m->pos[3 * i + 1]), to_fx(m->pos[3 * i + 2]));
    for (uint32_t i = 0; i < sn->nnormals; i++)
        nrm[i] = silk_v3(to_fx(sn->normal[3 * i]), to_fx(sn->normal[3 * i + 1]), to_fx(sn->normal[3 * i + 2]));
    silk_error err;
    size_t len;
    uint8_t *probe;
    if (model_add_mesh(&mo, m->nverts, pos, sn->nnormals, nrm, m->ntris, m->tri, sn->tri_normal) ||
        !(probe = model_bytes(&mo, &len))) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", path);
        goto done;
    }
    free(probe);
    *bytes = len;
    if (model_write(&mo, path, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
done:
    model_free(&mo);
    free(pos);
    free(nrm);
    return rc;
}

static int prepare(const char *in, const char *out, const simp_opts *so, silk_decimal scale, int quiet, int fit)
{
    simp_result r;
    fit_stats fs = { 0, 0, 0 };
    size_t bytes = 0;
    int rc = simplify_pipeline(in, so, scale, quiet, "prepare", &r);
    if (rc == 0 && fit && fit_normals(&r.fine, &r.mesh, &r.normals, &fs) != 0)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while fitting normals", in);
    if (rc == 0 && (rc = write_model(&r.mesh, &r.normals, out, &bytes)) == 0) {
        printf("prepare %s %s triangles=%u vertices=%u normals=%u bytes=%zu", in, out, r.mesh.ntris, r.mesh.nverts,
               r.normals.nnormals, bytes);
        if (fit) printf(" fitted=%u fit_rms_before=%.3g fit_rms_after=%.3g", fs.moved, sqrt(fs.before), sqrt(fs.after));
        printf("\n");
        simplify_warn_short(in, &r.mesh, so->target_tris);
    }
    simp_result_free(&r);
    return rc;
}

int cmd_prepare(int argc, char **argv)
{
    const char *in = NULL;
    simp_args args = { NULL, -1, { 1, 0 }, 0 };
    simp_opts so;
    simp_opts_default(&so, 0);
    so.subset = 1;
    int rc = 0, fit = 0, k;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        } else if ((k = simp_common_option(argc, argv, &i, &args)) != 0 || (k = simplify_option(argc, argv, &i, &so)) != 0) {
            if (k < 0) rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--fit") == 0) {
            fit = 1;
        } else if (a[0] == '-' && a[1]) {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: unknown option %s (try silk prepare --help)", a);
        } else if (!in) {
            in = a;
        } else {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: one input (got a second, %s; the output goes after -o)", a);
        }
    }
    if (!rc && !in) rc = cli_fail(CLI_EXIT_USAGE, "prepare: give FINE (silk prepare FINE -o MODEL.silk --triangles N)");
    if (!rc && !args.out) rc = cli_fail(CLI_EXIT_USAGE, "prepare: -o MODEL.silk is needed");
    if (!rc && args.target < 0) rc = cli_fail(CLI_EXIT_USAGE, "prepare: --triangles N is needed");
    if (rc) return rc;
    so.target_tris = (uint32_t)args.target;
    if (silk_file_same(in, args.out))
        return cli_fail(CLI_EXIT_USAGE, "prepare: the output would overwrite the input %s", in);
    /* A failed run leaves OUT as it was (written atomically), as every command. */
    return prepare(in, args.out, &so, args.scale, args.quiet, fit);
}
