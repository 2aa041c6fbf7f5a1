/*
 * cmd_simplify.c - `silk simplify IN OUT --triangles N`: a coarse mesh from
 * a fine one by quadric-error edge collapse (tools/simplify.c), written as
 * OBJ.  The input is read by silk's own loader (so every format and every
 * error message is the renderer's), its Q16.16 positions widened to double.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "measure.h"
#include "simplify.h"
#include "surface.h"
#include "../platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk simplify IN OUT.obj --triangles N [options]\n"
            "\n"
            "Simplify the mesh IN (OBJ, PLY, STL or .silk) to N triangles by quadric-error\n"
            "edge collapse (Garland-Heckbert) and write OUT as OBJ (atomically; - for\n"
            "stdout).\n"
            "Boundary and crease edges are kept where possible; a closed manifold input\n"
            "gives a closed manifold output (no collapse that breaks the surface or turns\n"
            "a triangle over).  Prints one line:\n"
            "  simplify IN OUT triangles=N vertices=N target=N collapses=N feature_edges=N\n"
            "\n"
            "options:\n"
            "  --triangles N       the triangle count to reach (at least 4)\n"
            "  --crease DEG        dihedral angle above which an edge is a feature [60]\n"
            "  --feature-weight W  weight of the feature constraint planes, 0..1e6 [100]\n"
            "  --for flat|smooth   flat: quadric-optimal vertex placement [default];\n"
            "                      smooth: the mesh smooth mode wants: every vertex stays a\n"
            "                      vertex of IN (on its surface), and OUT carries IN's\n"
            "                      normals there (vn), split along feature edges\n"
            "  --scale S           multiply coordinates by S while reading (as silk render)\n"
            "\n"
            "example:\n"
            "  silk simplify bunny-fine.obj bunny-500.obj --triangles 500\n");
}

/* The mesh as silk loads it, positions widened to double (simplify.h). */
int simp_load(const char *path, silk_decimal scale, simp_mesh *out, int *closed_manifold)
{
    uint8_t *data;
    size_t len;
    silk_error err;
    memset(out, 0, sizeof *out);
    if (silk_file_read(path, &data, &len, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    lo.scale = scale;
    size_t size = len * 16 + ((size_t)4 << 20);
    void *buf = NULL;
    silk_arena a;
    silk_mesh m;
    silk_status st = SILK_ERR_NOMEM;
    for (int attempt = 0; attempt < 5 && st == SILK_ERR_NOMEM; attempt++, size *= 2) {
        free(buf);
        if (!(buf = malloc(size))) break;
        silk_arena_init(&a, buf, size);
        st = silk_load_mesh(data, len, path, &lo, &a, &m, &err);
    }
    free(data);
    int rc = 0;
    if (!buf) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", path);
    else if (st != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    else {
        out->nverts = m.nverts;
        out->ntris = m.ntris;
        out->pos = malloc(3 * (size_t)(m.nverts ? m.nverts : 1) * sizeof *out->pos);
        out->tri = malloc(3 * (size_t)(m.ntris ? m.ntris : 1) * sizeof *out->tri);
        if (!out->pos || !out->tri) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", path);
        } else {
            for (uint32_t i = 0; i < m.nverts; i++) {
                out->pos[3 * i] = cli_fx_to_double(m.pos[i].x);
                out->pos[3 * i + 1] = cli_fx_to_double(m.pos[i].y);
                out->pos[3 * i + 2] = cli_fx_to_double(m.pos[i].z);
            }
            for (size_t i = 0; i < 3 * (size_t)m.ntris; i++) out->tri[i] = (uint32_t)m.tri[i];
            *closed_manifold = m.nboundary_edges == 0 && m.nnonmanifold_edges == 0;
        }
    }
    free(buf);
    return rc;
}

int simp_write_obj(const simp_mesh *m, const double *normals, const char *path, const char *comment)
{
    return simp_write_obj_corners(m, normals, normals ? m->nverts : 0, normals ? m->tri : NULL, path, comment);
}

int simp_write_obj_corners(const simp_mesh *m, const double *normals, uint32_t nnormals, const uint32_t *tri_normal,
                           const char *path, const char *comment)
{
    silk_outfile o;
    silk_error err;
    FILE *f = stdout;
    int to_stdout = strcmp(path, "-") == 0;
    if (!to_stdout) {
        if (silk_outfile_open(&o, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
        f = o.fp;
    }
    fprintf(f, "# %s: %u triangles, %u vertices\n", comment, m->ntris, m->nverts);
    for (uint32_t i = 0; i < m->nverts; i++)
        fprintf(f, "v %.9g %.9g %.9g\n", m->pos[3 * i], m->pos[3 * i + 1], m->pos[3 * i + 2]);
    if (normals)
        for (uint32_t i = 0; i < nnormals; i++)
            fprintf(f, "vn %.6f %.6f %.6f\n", normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    for (uint32_t i = 0; i < m->ntris; i++) {
        const uint32_t *t = &m->tri[3 * i], *n = normals ? &tri_normal[3 * i] : NULL;
        if (normals)
            fprintf(f, "f %u//%u %u//%u %u//%u\n", t[0] + 1, n[0] + 1, t[1] + 1, n[1] + 1, t[2] + 1, n[2] + 1);
        else
            fprintf(f, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    if (to_stdout) return fflush(stdout) == 0 ? 0 : cli_fail(CLI_EXIT_INPUT, "cannot write to stdout");
    if (silk_outfile_commit(&o, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

int simp_common_option(int argc, char **argv, int *i, simp_args *args)
{
    const char *a = argv[*i], *v, *end;
    if (cli_is(a, "--triangles")) {
        if (!(v = cli_value(argc, argv, i)) || cli_parse_long("--triangles", v, 4, 100000000, &args->target)) return -1;
    } else if (cli_is(a, "--scale")) {
        if (!(v = cli_value(argc, argv, i))) return -1;
        if (silk_decimal_parse(v, &end, &args->scale) != 0 || *end || args->scale.mant <= 0) {
            cli_fail(CLI_EXIT_USAGE, "--scale must be a positive decimal number, e.g. 0.01 (got \"%s\")", v);
            return -1;
        }
    } else if (cli_is(a, "-o") || cli_is(a, "--output")) {
        if (!(args->out = cli_value(argc, argv, i))) return -1;
    } else {
        return 0;
    }
    return 1;
}

int simplify_pipeline(const char *in, const simp_opts *so, silk_decimal scale, simp_result *r)
{
    memset(r, 0, sizeof *r);
    int closed = 0, rc;
    simp_topology topo;
    if ((rc = simp_load(in, scale, &r->mesh, &closed)) != 0) return rc;
    if (so->subset && simp_copy(&r->mesh, &r->fine) != 0) return cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    if (simp_run(&r->mesh, so, &r->stats) != 0 || simp_topology_check(&r->mesh, &topo) != 0 ||
        (so->subset && surf_normals_compute(&r->fine, &r->mesh, so->crease_deg, &r->normals) != 0))
        return cli_fail(CLI_EXIT_INPUT, "%s: out of memory while simplifying", in);
    if (closed && (topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts || topo.misoriented_edges))
        /* the checks in simplify.c should make this impossible */
        return cli_fail(CLI_EXIT_INPUT, "%s: the result is not a closed manifold (%u boundary, %u non-manifold edges, "
                        "%u non-manifold vertices, %u misoriented edges); not written",
                        in, topo.boundary_edges, topo.nonmanifold_edges, topo.nonmanifold_verts, topo.misoriented_edges);
    return 0;
}

void simplify_warn_short(const char *in, const simp_mesh *m, uint32_t target)
{
    if (m->ntris > target + target / 50)
        fprintf(stderr, "silk: warning: %s: stopped at %u triangles: every further collapse would break the "
                        "surface\n", in, m->ntris);
}

void simp_result_free(simp_result *r)
{
    simp_free(&r->mesh);
    simp_free(&r->fine);
    surf_normals_free(&r->normals);
}

int simplify_option(int argc, char **argv, int *i, simp_opts *so)
{
    const char *a = argv[*i], *v;
    if (cli_is(a, "--crease")) {
        if (!(v = cli_value(argc, argv, i)) || cli_parse_double("--crease", v, 0, 180, &so->crease_deg)) return -1;
    } else if (cli_is(a, "--feature-weight")) {
        if (!(v = cli_value(argc, argv, i)) || cli_parse_double("--feature-weight", v, 0, 1e6, &so->feature_weight))
            return -1;
    } else {
        return 0;
    }
    return 1;
}

static int simplify(const char *in, const char *out, const simp_opts *so, silk_decimal scale)
{
    simp_result r;
    char comment[1024];
    snprintf(comment, sizeof comment, "silk simplify %s --triangles %u%s", in, so->target_tris,
             so->subset ? " --for smooth" : "");
    int rc = simplify_pipeline(in, so, scale, &r);
    if (rc == 0 && (rc = so->subset ? simp_write_obj_corners(&r.mesh, r.normals.normal, r.normals.nnormals,
                                                              r.normals.tri_normal, out, comment)
                                    : simp_write_obj(&r.mesh, NULL, out, comment)) == 0) {
        if (strcmp(out, "-") != 0)
            printf("simplify %s %s triangles=%u vertices=%u target=%u collapses=%u feature_edges=%u\n", in, out,
                   r.mesh.ntris, r.mesh.nverts, so->target_tris, r.stats.collapses, r.stats.feature_edges);
        simplify_warn_short(in, &r.mesh, so->target_tris);
    }
    simp_result_free(&r);
    return rc;
}

int cmd_simplify(int argc, char **argv)
{
    const char *in = NULL;
    simp_args args = { NULL, -1, { 1, 0 } };
    simp_opts so;
    simp_opts_default(&so, 0);
    int rc = 0, k;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i], *v;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        } else if ((k = simp_common_option(argc, argv, &i, &args)) != 0) {
            if (k < 0) rc = CLI_EXIT_USAGE;
        } else if ((k = simplify_option(argc, argv, &i, &so)) != 0) {
            if (k < 0) rc = CLI_EXIT_USAGE;
        } else if (cli_is(a, "--for")) {
            if (!(v = cli_value(argc, argv, &i))) rc = CLI_EXIT_USAGE;
            else if (strcmp(v, "smooth") == 0) so.subset = 1;
            else if (strcmp(v, "flat") == 0) so.subset = 0;
            else rc = cli_fail(CLI_EXIT_USAGE, "--for must be flat or smooth (got \"%s\")", v);
        } else if (a[0] == '-' && a[1]) {
            rc = cli_fail(CLI_EXIT_USAGE, "simplify: unknown option %s (try silk simplify --help)", a);
        } else if (!in) {
            in = a;
        } else if (!args.out) {
            args.out = a;
        } else {
            rc = cli_fail(CLI_EXIT_USAGE, "simplify: one input and one output (got a third, %s)", a);
        }
    }
    if (!rc && (!in || !args.out))
        rc = cli_fail(CLI_EXIT_USAGE, "simplify: give IN and OUT (silk simplify IN OUT --triangles N)");
    if (!rc && args.target < 0) rc = cli_fail(CLI_EXIT_USAGE, "simplify: --triangles N is needed");
    so.target_tris = (uint32_t)args.target;
    if (rc) return rc;
    /* A failed run leaves OUT as it was (written atomically). */
    return simplify(in, args.out, &so, args.scale);
}
