/*
 * cmd_hull.c - `silk hull FINE -o HULL.obj --triangles N [--inner]`: a
 * coarse mesh that contains the detailed one (the outer hull) or lies
 * inside it (the inner hull), by the constrained edge collapses of
 * tools/prep/hull.c, written as OBJ (or PLY for a .ply name).  The input is read
 * by silk's own loader (simp_load, tools/cli/cmd_simplify.c).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "prep/hull.h"
#include "platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk hull FINE -o HULL.obj --triangles N [options]\n"
            "\n"
            "Make a coarse outer hull of the closed mesh FINE (OBJ, PLY or STL; - for\n"
            "standard input): a mesh of N\n"
            "triangles that contains every point of FINE, by edge collapses that only\n"
            "ever move the surface outward, each placed to add the least volume.  With\n"
            "--inner, the inner hull: a mesh inside FINE.  Vertices lie on silk's fixed-\n"
            "point grid, so the hull holds FINE as the renderer loads it.  Writes HULL.obj\n"
            "(atomically; - for stdout) with a normal per vertex, the detailed surface's\n"
            "where the vertex stands for it (silk render --normals file shades with them),\n"
            "and prints one line:\n"
            "  hull FINE HULL.obj triangles=N vertices=N target=N collapses=N volume=X (+P%%)\n"
            "It stops above N when no collapse that keeps the hull is left (a warning).\n"
            "\n"
            "options:\n"
            "  -o, --output HULL.obj  the hull, as OBJ (ascii PLY for a .ply name)\n"
            "  --triangles N          the triangle count to reach (at least 4)\n"
            "  --inner                the inner hull instead of the outer\n"
            "  --scale S              multiply coordinates by S while reading (as silk render)\n"
            "  --quiet                no progress line on a terminal\n"
            "\n"
            "example:\n"
            "  silk hull bunny-fine.obj -o bunny-hull-500.obj --triangles 500\n");
}

static int hull(const char *in, const char *out, const hull_opts *ho, const simp_args *args)
{
    simp_mesh m;
    int closed = 0, rc;
    if ((rc = simp_load(in, args->scale, args->quiet, &m, &closed)) != 0) {
        simp_free(&m);
        return rc;
    }
    simp_topology topo;
    hull_stats st;
    hull_fine fine = { NULL, NULL };
    if (simp_topology_check(&m, &topo) != 0) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    else if (!closed || topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts ||
             topo.misoriented_edges || topo.degenerate_tris)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: a hull needs a closed, manifold, consistently oriented mesh (%u boundary, "
                      "%u non-manifold, %u misoriented edges, %u non-manifold vertices, %u degenerate triangles)",
                      in, topo.boundary_edges, topo.nonmanifold_edges, topo.misoriented_edges, topo.nonmanifold_verts,
                      topo.degenerate_tris);
    else if (!(hull_volume(&m) > 0))
        rc = cli_fail(CLI_EXIT_INPUT, "%s: the faces point inward (the enclosed volume is not positive); a hull "
                      "needs them counter-clockwise seen from outside", in);
    else if (hull_run(&m, ho, &st, &fine) != 0) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while making the hull", in);
    else if (simp_topology_check(&m, &topo) != 0) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    else if (topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts || topo.misoriented_edges)
        /* the link condition in hull.c should make this impossible */
        rc = cli_fail(CLI_EXIT_INPUT, "%s: the hull is not a closed manifold; not written", in);
    else {
        char comment[1024];
        snprintf(comment, sizeof comment, "silk hull %s --triangles %u%s", in, ho->target_tris,
                 ho->inner ? " --inner" : "");
        if ((rc = simp_write_mesh(&m, fine.normal, out, comment)) == 0) {
            if (strcmp(out, "-") != 0)
                printf("hull %s %s triangles=%u vertices=%u target=%u collapses=%u volume=%.6g (%+.1f%%)\n", in, out,
                       m.ntris, m.nverts, ho->target_tris, st.collapses, st.volume_out,
                       100 * (st.volume_out / st.volume_in - 1));
            if (m.ntris > ho->target_tris + ho->target_tris / 50)
                fprintf(stderr, "silk: warning: %s: stopped at %u triangles: no further collapse keeps the %s hull\n",
                        in, m.ntris, ho->inner ? "inner" : "outer");
        }
    }
    simp_free(&m);
    hull_fine_free(&fine);
    return rc;
}

int cmd_hull(int argc, char **argv)
{
    const char *in = NULL;
    simp_args args = { NULL, -1, { 1, 0 }, 0 };
    hull_opts ho;
    hull_opts_default(&ho, 0);
    int rc = 0, k;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        if (cli_help(a, help)) return 0;
        if ((k = simp_common_option(argc, argv, &i, &args)) != 0) {
            if (k < 0) rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--inner") == 0) {
            ho.inner = 1;
        } else if (a[0] == '-' && a[1]) {
            rc = cli_unknown_option("hull", a);
        } else if (!in) {
            in = a;
        } else {
            rc = cli_fail(CLI_EXIT_USAGE, "hull: one input mesh (got a second, %s; the output goes after -o)", a);
        }
    }
    if (!rc && !in) rc = cli_fail(CLI_EXIT_USAGE, "hull: give the mesh (silk hull FINE -o HULL.obj --triangles N)");
    if (!rc && !args.out) rc = cli_fail(CLI_EXIT_USAGE, "hull: -o HULL.obj is needed");
    if (!rc && args.target < 0) rc = cli_fail(CLI_EXIT_USAGE, "hull: --triangles N is needed");
    ho.target_tris = (uint32_t)args.target;
    /* A failed run leaves OUT as it was (written atomically). */
    if (!rc) rc = hull(in, args.out, &ho, &args);
    return rc;
}
