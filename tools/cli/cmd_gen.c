/*
 * cmd_gen.c - `silk gen SHAPE [params] -o OUT.obj`: write one of the analytic
 * meshes of gen.c as OBJ, atomically ("-o -" writes to stdout).
 */
#include <ctype.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "prep/gen.h"
#include "platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk gen SHAPE [parameters] -o OUT.obj\n"
            "\n"
            "Write a closed, outward-oriented analytic mesh as OBJ, every vertex on the\n"
            "exact surface.  The axis of revolution is y.\n"
            "\n"
            "shapes and their parameters (defaults in brackets):\n"
            "  sphere    UV sphere, poles at +-y:  --radius [1]\n"
            "            --segments around [10], --bands pole to pole [11]  -> 200 triangles\n"
            "  torus     around the y axis:  --R major radius [1], --r tube radius [0.4]\n"
            "            --segments around y [24], --bands around the tube [12]  -> 576\n"
            "  cone      apex (0,H,0), base disc at y=0 with a sharp rim:  --radius [1]\n"
            "            --height [1.5], --segments [35], --bands side rows [1]  -> 70\n"
            "  cylinder  y from 0 to H, capped, sharp rims:  --radius [1], --height [2]\n"
            "            --segments [24], --bands side rows [1]  -> 96\n"
            "  knot      (p,q) torus knot, a tube around the curve on the torus R, r:\n"
            "            --p [2] --q [3] --R [1] --r [0.4] --tube [0.25]\n"
            "            --segments along the curve [64], --bands around the tube [8]  -> 1024\n"
            "\n"
            "  --uv                  sphere, torus: texture coordinates too, u around the y\n"
            "                        axis and v pole to pole (sphere) or around the tube\n"
            "  -o, --output OUT.obj  the file to write (written atomically); - for stdout\n"
            "\n"
            "examples:\n"
            "  silk gen sphere -o sphere.obj\n"
            "  silk gen torus --segments 48 --bands 24 -o torus.obj\n"
            "  silk gen knot --p 3 --q 5 --tube 0.15 --segments 160 -o knot.obj\n"
            "  silk gen sphere --uv --segments 24 --bands 16 -o globe.obj\n");
}

/* Which parameters each shape takes: bit s for gen_shape s. */
#define ALL ((1u << GEN_SHAPE_COUNT) - 1)
#define BIT(s) (1u << (s))

typedef struct gen_option {
    const char *name;
    unsigned shapes;
    int is_int;
    double lo, hi;
    size_t offset;             /* into gen_params */
} gen_option;

static const gen_option gen_options[] = {
    { "--segments", ALL, 1, 3, 100000, offsetof(gen_params, segments) },
    { "--bands", ALL, 1, 1, 100000, offsetof(gen_params, bands) },
    { "--radius", BIT(GEN_SPHERE) | BIT(GEN_CONE) | BIT(GEN_CYLINDER), 0, 0, 1024, offsetof(gen_params, radius) },
    { "--height", BIT(GEN_CONE) | BIT(GEN_CYLINDER), 0, 0, 1024, offsetof(gen_params, height) },
    { "--R", BIT(GEN_TORUS) | BIT(GEN_KNOT), 0, 0, 1024, offsetof(gen_params, R) },
    { "--r", BIT(GEN_TORUS) | BIT(GEN_KNOT), 0, 0, 1024, offsetof(gen_params, r) },
    { "--tube", BIT(GEN_KNOT), 0, 0, 1024, offsetof(gen_params, tube) },
    { "--p", BIT(GEN_KNOT), 1, 1, 50, offsetof(gen_params, p) },
    { "--q", BIT(GEN_KNOT), 1, 1, 50, offsetof(gen_params, q) },
};

static int has_obj_extension(const char *path)
{
    size_t n = strlen(path);
    if (n < 4) return 0;
    const char *e = path + n - 4;
    return e[0] == '.' && tolower((unsigned char)e[1]) == 'o' && tolower((unsigned char)e[2]) == 'b' &&
           tolower((unsigned char)e[3]) == 'j';
}

static int write_mesh(const gen_mesh *m, const gen_params *p, const char *out)
{
    silk_error err;
    if (strcmp(out, "-") == 0) {
        if (gen_write_obj(m, p, stdout) != 0 || fflush(stdout) != 0)
            return cli_fail(CLI_EXIT_INPUT, "stdout: cannot write");
        return 0;
    }
    silk_outfile f;
    if (silk_outfile_open(&f, out, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    if (gen_write_obj(m, p, f.fp) != 0) {
        silk_outfile_abort(&f);
        return cli_fail(CLI_EXIT_INPUT, "%s: cannot write", out);
    }
    if (silk_outfile_commit(&f, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    return 0;
}

/* Returns the exit status, or -1 after --help.  A failed run leaves OUT as
 * it was (written atomically). */
static int gen(int argc, char **argv)
{
    const char *out = NULL;
    if (argc < 2) return cli_fail(CLI_EXIT_USAGE, "gen: which shape? (sphere, torus, cone, cylinder or knot)");
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        help(stdout);
        return -1;
    }
    gen_shape shape = gen_shape_from_name(argv[1]);
    if (shape == GEN_SHAPE_COUNT)
        return cli_fail(CLI_EXIT_USAGE, "gen: unknown shape \"%s\" (sphere, torus, cone, cylinder or knot)", argv[1]);
    gen_params p;
    gen_defaults(shape, &p);

    for (int i = 2; i < argc; i++) {
        const char *a = argv[i], *v;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return -1;
        }
        if (cli_is(a, "-o") || cli_is(a, "--output")) {
            if (!(out = cli_value(argc, argv, &i))) return CLI_EXIT_USAGE;
            continue;
        }
        if (cli_is(a, "--uv")) {
            if (shape != GEN_SPHERE && shape != GEN_TORUS)
                return cli_fail(CLI_EXIT_USAGE, "gen: --uv does not apply to a %s", gen_shape_name(shape));
            p.uv = 1;
            continue;
        }
        const gen_option *g = NULL;
        for (size_t k = 0; k < sizeof gen_options / sizeof gen_options[0]; k++)
            if (cli_is(a, gen_options[k].name)) g = &gen_options[k];
        if (!g) return cli_unknown_option("gen", a);
        if (!(g->shapes & BIT(shape)))
            return cli_fail(CLI_EXIT_USAGE, "gen: %s does not apply to a %s", g->name, gen_shape_name(shape));
        if (!(v = cli_value(argc, argv, &i))) return CLI_EXIT_USAGE;
        char *field = (char *)&p + g->offset;
        if (g->is_int) {
            long n;
            if (cli_parse_long(g->name, v, (long)g->lo, (long)g->hi, &n) != 0) return CLI_EXIT_USAGE;
            *(int *)field = (int)n;
        } else {
            double d;
            if (cli_parse_double(g->name, v, g->lo, g->hi, &d) != 0) return CLI_EXIT_USAGE;
            *(double *)field = d;
        }
    }
    if (!out) return cli_fail(CLI_EXIT_USAGE, "gen: no output given (-o OUT.obj)");
    if (strcmp(out, "-") != 0 && !has_obj_extension(out))
        return cli_fail(CLI_EXIT_USAGE, "gen: %s: the output must be a .obj file", out);
    char why[160];
    if (gen_check(&p, why, sizeof why)) return cli_fail(CLI_EXIT_USAGE, "gen %s: %s", gen_shape_name(shape), why);

    gen_mesh m;
    if (gen_build(&p, &m) != 0) return cli_fail(CLI_EXIT_INPUT, "gen: out of memory");
    int rc = write_mesh(&m, &p, out);
    gen_free(&m);
    return rc;
}

int cmd_gen(int argc, char **argv)
{
    int rc = gen(argc, argv);
    return rc < 0 ? 0 : rc;   /* -1: --help */
}
