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
#include "measure.h"
#include "model_file.h"
#include "simplify.h"
#include "surface.h"
#include "../platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk prepare FINE -o MODEL.silk --triangles N [options]\n"
            "\n"
            "Make the detailed mesh FINE (OBJ, PLY) into a prepared model: a coarse mesh of\n"
            "N triangles whose vertices are vertices of FINE (so they lie on its surface)\n"
            "and whose normals are FINE's normals there, split along feature edges - the\n"
            "mesh smooth mode draws best.  flat, smooth, pn and blend draw it; every silk\n"
            "command that takes a mesh takes MODEL.silk.  Written atomically.  Prints:\n"
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

static int prepare(const char *in, const char *out, const simp_opts *so, silk_decimal scale, int fit)
{
    simp_mesh m, fine = { 0 };
    surf_normals sn = { 0 };
    simp_stats st;
    simp_topology topo;
    fit_stats fs = { 0, 0, 0 };
    int closed = 0, rc;
    size_t bytes = 0;
    if ((rc = simplify_load(in, scale, &m, &closed)) != 0) {
        simp_free(&m);
        return rc;
    }
    if (simp_copy(&m, &fine) != 0 || simp_run(&m, so, &st) != 0 || simp_topology_check(&m, &topo) != 0 ||
        surf_normals_compute(&fine, &m, so->crease_deg, &sn) != 0)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while preparing", in);
    else if (fit && fit_normals(&fine, &m, &sn, &fs) != 0)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while fitting normals", in);
    else if (closed && (topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts || topo.misoriented_edges))
        rc = cli_fail(CLI_EXIT_INPUT, "%s: the coarse mesh is not a closed manifold; not written", in);
    else if ((rc = write_model(&m, &sn, out, &bytes)) == 0) {
        printf("prepare %s %s triangles=%u vertices=%u normals=%u bytes=%zu", in, out, m.ntris, m.nverts,
               sn.nnormals, bytes);
        if (fit) printf(" fitted=%u fit_rms_before=%.3g fit_rms_after=%.3g", fs.moved, sqrt(fs.before), sqrt(fs.after));
        printf("\n");
        if (m.ntris > so->target_tris + so->target_tris / 50)
            fprintf(stderr, "silk: warning: %s: stopped at %u triangles: every further collapse would break the "
                            "surface\n", in, m.ntris);
    }
    simp_free(&m);
    simp_free(&fine);
    surf_normals_free(&sn);
    return rc;
}

int cmd_prepare(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    long target = -1;
    simp_opts so;
    simp_opts_default(&so, 0);
    so.subset = 1;
    silk_decimal scale = { 1, 0 };
    int rc = 0, fit = 0;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i], *v;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        } else if (cli_is(a, "--triangles")) {
            if (!(v = cli_value(argc, argv, &i)) || cli_parse_long("--triangles", v, 4, 100000000, &target))
                rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--crease")) {
            if (!(v = cli_value(argc, argv, &i)) || cli_parse_double("--crease", v, 0, 180, &so.crease_deg))
                rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--feature-weight")) {
            if (!(v = cli_value(argc, argv, &i)) || cli_parse_double("--feature-weight", v, 0, 1e6, &so.feature_weight))
                rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--fit") == 0) {
            fit = 1;
        } else if (cli_is(a, "--scale")) {
            const char *end;
            if (!(v = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
            else if (silk_decimal_parse(v, &end, &scale) != 0 || *end || scale.mant <= 0)
                rc = cli_fail(CLI_EXIT_USAGE, "--scale must be a positive decimal number, e.g. 0.01 (got \"%s\")", v);
        } else if (cli_is(a, "-o") || cli_is(a, "--output")) {
            if (!(out = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (a[0] == '-' && a[1]) {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: unknown option %s (try silk prepare --help)", a);
        } else if (!in) {
            in = a;
        } else {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: one input (got a second, %s; the output goes after -o)", a);
        }
    }
    if (!rc && !in) rc = cli_fail(CLI_EXIT_USAGE, "prepare: give FINE (silk prepare FINE -o MODEL.silk --triangles N)");
    if (!rc && !out) rc = cli_fail(CLI_EXIT_USAGE, "prepare: -o MODEL.silk is needed");
    if (!rc && target < 0) rc = cli_fail(CLI_EXIT_USAGE, "prepare: --triangles N is needed");
    if (rc) return rc;
    so.target_tris = (uint32_t)target;
    if (silk_file_same(in, out)) return cli_fail(CLI_EXIT_USAGE, "prepare: the output would overwrite the input %s", in);
    rc = prepare(in, out, &so, scale, fit);
    if (rc) silk_file_remove_stale(out);
    return rc;
}
