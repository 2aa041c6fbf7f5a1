/*
 * cmd_simplify.c - `silk simplify IN OUT --triangles N`: a coarse mesh from
 * a fine one by quadric-error edge collapse (tools/prep/simplify.c), written as
 * OBJ, or as ascii PLY when OUT ends in .ply.  The input is read by silk's
 * own loader (so every format and every error message is the renderer's),
 * its Q16.16 positions widened to double.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "progress.h"
#include "meshcmd.h"
#include "platform/platform.h"

/* ---- the options simplify, hull and prepare share (meshcmd.h) --------------------------- */

void simp_args_default(void *base)
{
    simp_args *a = base;
    simp_opts so;
    simp_opts_default(&so, 0);
    a->target = -1;
    a->scale = (silk_decimal){ 1, 0 };
    a->quiet = 0;
    a->crease_deg = so.crease_deg;
    a->feature_weight = so.feature_weight;
}

#define F(member) CLI_FIELD(simp_args, member)
const cli_opt simp_rows[] = {
    { .name = "--triangles", .mask = SIMP_OPT_COMMON, .kind = CLI_INT, .meta = "N", .lo = 4, .hi = 100000000,
      F(target), .help = "the triangle count to reach (at least 4)" },
    { .name = "--crease", .mask = SIMP_OPT_SHAPE, .kind = CLI_REAL, .meta = "DEG", .lo = 0, .hi = 180, F(crease_deg),
      .help = "dihedral angle above which an edge is a feature (%R, default %D)" },
    { .name = "--feature-weight", .mask = SIMP_OPT_SHAPE, .kind = CLI_REAL, .meta = "W", .lo = 0, .hi = 1e6,
      F(feature_weight), .help = "weight of the feature constraint planes (%R, default %D)" },
    { .name = "--scale", .mask = SIMP_OPT_COMMON, .kind = CLI_DECIMAL, .meta = "S", F(scale),
      .help = "multiply coordinates by S while reading (as silk render)" },
    { .name = "--quiet", .mask = SIMP_OPT_COMMON, .kind = CLI_FLAG, F(quiet), .help = "no progress line on a terminal" },
    { .name = NULL },
};
#undef F

int simp_one_input(const char *cmd, int npos, const char *const *pos, const char *usage, const char **in)
{
    if (npos == 0) return cli_fail(CLI_EXIT_USAGE, "%s: give FINE (%s)", cmd, usage);
    if (npos > 1)
        return cli_fail(CLI_EXIT_USAGE, "%s: one input (got a second, %s; the output goes after -o)", cmd, pos[1]);
    *in = pos[0];
    return 0;
}

/* ---- silk simplify ------------------------------------------------------------------------ */

typedef struct simplify_args {
    const char *out;
    int subset;                /* --for smooth */
} simplify_args;

static const cli_opt simplify_rows[] = {
    { .name = "--output", .alt = "-o", .group = "options", .kind = CLI_OUTPUT, .meta = "OUT",
      CLI_FIELD(simplify_args, out), .help = "OUT as an option instead of the second argument" },
    { .name = "--for", .kind = CLI_CHOICE, .choices = "flat|smooth", CLI_FIELD(simplify_args, subset),
      .help = "flat: quadric-optimal vertex placement [default]; smooth: the mesh smooth mode wants: every vertex "
              "stays a vertex of IN (on its surface), and OUT carries IN's normals there (vn), split along feature "
              "edges (OBJ only)" },
    { .name = NULL },
};

const cli_command cmd_simplify_spec = {
    .name = "simplify",
    .usage = "usage: silk simplify IN OUT.obj|OUT.ply --triangles N [options]\n",
    .about =
        "Simplify the mesh IN (OBJ, PLY, STL or .silk; - for standard input) to N\n"
        "triangles by quadric-error edge collapse (Garland-Heckbert) and write OUT\n"
        "atomically: as ascii PLY when its name ends in .ply, else as OBJ (- for\n"
        "standard output).\n"
        "Boundary and crease edges are kept where possible; a closed manifold input\n"
        "gives a closed manifold output (no collapse that breaks the surface or turns\n"
        "a triangle over).  Prints one line:\n"
        "  simplify IN OUT triangles=N vertices=N target=N collapses=N feature_edges=N\n",
    .examples =
        "  silk simplify bunny-fine.obj bunny-500.obj --triangles 500\n"
        "  silk simplify bunny-fine.obj bunny-500.ply --triangles 500\n",
    .sets = { { simplify_rows, 0, sizeof(simplify_args), NULL, NULL }, SIMP_SET(SIMP_OPT_COMMON | SIMP_OPT_SHAPE) },
    .nsets = 2,
};

/* The mesh as silk loads it, positions widened to double (meshcmd.h). */
int simp_load(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold)
{
    return simp_load_colors(path, scale, quiet, out, closed_manifold, NULL);
}

int simp_load_colors(const char *path, silk_decimal scale, int quiet, simp_mesh *out, int *closed_manifold,
                     uint32_t **color)
{
    memset(out, 0, sizeof *out);
    if (color) *color = NULL;
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    lo.scale = scale;
    cli_mesh lm;
    int rc = cli_mesh_load(&lm, path, &lo, 0, 0, 0, 0, quiet);
    const silk_mesh *m = &lm.mesh;
    if (!rc) {
        out->nverts = m->nverts;
        out->ntris = m->ntris;
        out->pos = malloc(3 * (size_t)(m->nverts ? m->nverts : 1) * sizeof *out->pos);
        out->tri = malloc(3 * (size_t)(m->ntris ? m->ntris : 1) * sizeof *out->tri);
        if (!out->pos || !out->tri) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", lm.name);
        } else {
            for (uint32_t i = 0; i < m->nverts; i++) {
                silk_vec3 p = silk_mesh_pos(m, i);   /* a compact model's too */
                out->pos[3 * i] = cli_fx_to_double(p.x);
                out->pos[3 * i + 1] = cli_fx_to_double(p.y);
                out->pos[3 * i + 2] = cli_fx_to_double(p.z);
            }
            for (uint32_t i = 0; i < 3 * m->ntris; i++) out->tri[i] = (uint32_t)silk_mesh_corner(m, i);
            if (color && m->color && (*color = malloc((m->nverts ? m->nverts : 1) * sizeof **color)) != NULL)
                memcpy(*color, m->color, m->nverts * sizeof **color);
            *closed_manifold = m->nboundary_edges == 0 && m->nnonmanifold_edges == 0;
        }
    }
    cli_mesh_free(&lm);
    return rc;
}

/* PLY for a name ending in .ply (any case), OBJ for anything else. */
static int wants_ply(const char *path)
{
    size_t n = strlen(path);
    if (n < 4 || path[n - 4] != '.') return 0;
    char ext[4];
    for (int k = 0; k < 3; k++) ext[k] = (char)(path[n - 3 + k] | 0x20);
    ext[3] = 0;
    return strcmp(ext, "ply") == 0;
}

/* OBJ or PLY; normals, when given, are nnormals and tri_normal names each
 * corner's (NULL: the vertex's own; PLY has only that). */
static int write_mesh(const simp_mesh *m, const double *normals, uint32_t nnormals, const uint32_t *tri_normal,
                      const char *path, const char *comment)
{
    silk_outfile o;
    silk_error err;
    int ply = wants_ply(path);
    if (silk_outfile_open(&o, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    FILE *f = o.fp;
    if (ply) {
        fprintf(f, "ply\nformat ascii 1.0\ncomment %s\nelement vertex %u\n"
                   "property float x\nproperty float y\nproperty float z\n", comment, m->nverts);
        if (normals) fprintf(f, "property float nx\nproperty float ny\nproperty float nz\n");
        fprintf(f, "element face %u\nproperty list uchar int vertex_indices\nend_header\n", m->ntris);
    } else {
        fprintf(f, "# %s: %u triangles, %u vertices\n", comment, m->ntris, m->nverts);
    }
    for (uint32_t i = 0; i < m->nverts; i++) {
        fprintf(f, ply ? "%.9g %.9g %.9g" : "v %.9g %.9g %.9g\n", m->pos[3 * i], m->pos[3 * i + 1], m->pos[3 * i + 2]);
        if (ply && normals) fprintf(f, " %.6f %.6f %.6f", normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
        if (ply) fputc('\n', f);
    }
    if (normals && !ply)
        for (uint32_t i = 0; i < nnormals; i++)
            fprintf(f, "vn %.6f %.6f %.6f\n", normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    for (uint32_t i = 0; i < m->ntris; i++) {
        const uint32_t *t = &m->tri[3 * i], *n = tri_normal ? &tri_normal[3 * i] : t;
        if (ply)
            fprintf(f, "3 %u %u %u\n", t[0], t[1], t[2]);
        else if (normals)
            fprintf(f, "f %u//%u %u//%u %u//%u\n", t[0] + 1, n[0] + 1, t[1] + 1, n[1] + 1, t[2] + 1, n[2] + 1);
        else
            fprintf(f, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    if (silk_outfile_commit(&o, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

int simp_write_mesh(const simp_mesh *m, const double *normals, const char *path, const char *comment)
{
    return write_mesh(m, normals, normals ? m->nverts : 0, NULL, path, comment);
}

int simp_write_obj_corners(const simp_mesh *m, const double *normals, uint32_t nnormals, const uint32_t *tri_normal,
                           const char *path, const char *comment)
{
    return write_mesh(m, normals, nnormals, tri_normal, path, comment);
}

static void on_collapse(void *user, uint32_t tris_in, uint32_t tris_left)
{
    const simp_opts *so = ((const simp_opts **)user)[0];
    progress *p = ((progress **)user)[1];
    /* the work is the triangles removed on the way to the target */
    double todo = (double)tris_in - so->target_tris;
    progress_update(p, (double)tris_in - tris_left, todo > 0 ? todo : 1);
}

int simplify_pipeline(const char *in, const simp_opts *so_in, silk_decimal scale, int quiet, const char *what,
                      simp_result *r)
{
    memset(r, 0, sizeof *r);
    int closed = 0, rc;
    simp_topology topo;
    const char *name = cli_input_name(in);
    if ((rc = simp_load_colors(in, scale, quiet, &r->mesh, &closed, so_in->subset ? &r->fine_color : NULL)) != 0)
        return rc;
    if (so_in->subset && simp_copy(&r->mesh, &r->fine) != 0) return cli_fail(CLI_EXIT_INPUT, "%s: out of memory", name);
    simp_opts so = *so_in;
    progress pr;
    progress_start(&pr, quiet, what);
    void *user[2] = { (void *)so_in, &pr };
    so.progress = on_collapse;
    so.progress_user = user;
    int run = simp_run(&r->mesh, &so, &r->stats);
    progress_end(&pr);
    if (run != 0 || simp_topology_check(&r->mesh, &topo) != 0 ||
        (so.subset && surf_normals_compute(&r->fine, &r->mesh, so.crease_deg, &r->normals) != 0))
        return cli_fail(CLI_EXIT_INPUT, "%s: out of memory while simplifying", name);
    if (closed && (topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts || topo.misoriented_edges))
        /* the checks in simplify.c should make this impossible */
        return cli_fail(CLI_EXIT_INPUT, "%s: the result is not a closed manifold (%u boundary, %u non-manifold edges, "
                        "%u non-manifold vertices, %u misoriented edges); not written",
                        name, topo.boundary_edges, topo.nonmanifold_edges, topo.nonmanifold_verts,
                        topo.misoriented_edges);
    return 0;
}

void simplify_warn_short(const char *in, const simp_mesh *m, uint32_t target)
{
    if (m->ntris > target + target / 50)
        fprintf(stderr, "silk: warning: %s: stopped at %u triangles: every further collapse would break the "
                        "surface\n", cli_input_name(in), m->ntris);
}

void simp_result_free(simp_result *r)
{
    simp_free(&r->mesh);
    simp_free(&r->fine);
    surf_normals_free(&r->normals);
    free(r->fine_color);
}

static int simplify(const char *in, const char *out, const simp_opts *so, silk_decimal scale, int quiet)
{
    simp_result r;
    char comment[1024];
    snprintf(comment, sizeof comment, "silk simplify %s --triangles %u%s", cli_input_name(in), so->target_tris,
             so->subset ? " --for smooth" : "");
    int rc = simplify_pipeline(in, so, scale, quiet, "simplify", &r);
    if (rc == 0 && (rc = so->subset ? simp_write_obj_corners(&r.mesh, r.normals.normal, r.normals.nnormals,
                                                              r.normals.tri_normal, out, comment)
                                    : simp_write_mesh(&r.mesh, NULL, out, comment)) == 0) {
        if (!silk_path_is_stdio(out))
            printf("simplify %s %s triangles=%u vertices=%u target=%u collapses=%u feature_edges=%u\n", in, out,
                   r.mesh.ntris, r.mesh.nverts, so->target_tris, r.stats.collapses, r.stats.feature_edges);
        simplify_warn_short(in, &r.mesh, so->target_tris);
    }
    simp_result_free(&r);
    return rc;
}

int cmd_simplify(int argc, char **argv)
{
    simplify_args sa = { NULL, 0 };
    simp_args args;
    simp_args_default(&args);
    cli_args ca;
    void *bases[] = { &sa, &args };
    int rc = cli_parse(&cmd_simplify_spec, bases, argc, argv, &ca);
    const char *in = ca.npos > 0 ? ca.pos[0] : NULL;
    if (!rc && ca.npos > 1 && sa.out)
        rc = cli_fail(CLI_EXIT_USAGE, "simplify: one input and one output (got %s and -o %s)", ca.pos[1], sa.out);
    if (!rc && ca.npos > 2) rc = cli_fail(CLI_EXIT_USAGE, "simplify: one input and one output (got a third, %s)", ca.pos[2]);
    if (!rc && ca.npos > 1) {
        sa.out = ca.pos[1];
        if (!silk_path_is_stdio(sa.out) && cli_check_output_dir("simplify", sa.out)) rc = CLI_EXIT_INPUT;
    }
    cli_args_free(&ca);
    if (rc == CLI_HELP) return 0;
    if (!rc && (!in || !sa.out))
        rc = cli_fail(CLI_EXIT_USAGE, "simplify: give IN and OUT (silk simplify IN OUT --triangles N)");
    if (!rc && args.target < 0) rc = cli_fail(CLI_EXIT_USAGE, "simplify: --triangles N is needed");
    if (!rc && sa.subset && wants_ply(sa.out))
        rc = cli_fail(CLI_EXIT_USAGE, "simplify: --for smooth writes OBJ (its normals are split along feature edges, "
                      "which PLY cannot hold); name OUT .obj");
    if (rc) return rc;
    simp_opts so;
    simp_opts_default(&so, (uint32_t)args.target);
    so.subset = sa.subset;
    so.crease_deg = args.crease_deg;
    so.feature_weight = args.feature_weight;
    /* A failed run leaves OUT as it was (written atomically). */
    return simplify(in, sa.out, &so, args.scale, args.quiet);
}
