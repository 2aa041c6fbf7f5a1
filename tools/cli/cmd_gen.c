/*
 * cmd_gen.c - `silk gen SHAPE [params] -o OUT.obj`: write one of the analytic
 * meshes of gen.c as OBJ, atomically ("-o -" writes to stdout).
 */
#include <ctype.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "prep/gen.h"
#include "platform/platform.h"

/* Which parameters each shape takes: bit s for gen_shape s (a row's mask). */
#define ALL ((1u << GEN_SHAPE_COUNT) - 1)
#define BIT(s) (1u << (s))

typedef struct gen_args {
    const char *out;
    gen_params p;              /* the values given (the shape's defaults fill the rest) */
} gen_args;

#define F(member) CLI_FIELD(gen_args, member)
static const cli_opt gen_rows[] = {
    { .name = "--output", .alt = "-o", .group = "", .kind = CLI_OUTPUT, .meta = "OUT.obj", F(out),
      .help = "the file to write (written atomically); - for stdout" },
    { .name = "--uv", .mask = BIT(GEN_SPHERE) | BIT(GEN_TORUS), .kind = CLI_FLAG, F(p.uv),
      .help = "sphere, torus: texture coordinates too, u around the y axis and v pole to pole (sphere) or around "
              "the tube" },
    { .name = "--segments", .group = "Parameters (the shapes above take them)", .mask = ALL, .kind = CLI_INT,
      .meta = "N", .lo = 3, .hi = 100000, F(p.segments),
      .help = "around the y axis (the knot: along the curve)" },
    { .name = "--bands", .mask = ALL, .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 100000, F(p.bands),
      .help = "sphere: pole to pole; torus, knot: around the tube; cone, cylinder: rows of the side" },
    { .name = "--radius", .mask = BIT(GEN_SPHERE) | BIT(GEN_CONE) | BIT(GEN_CYLINDER), .kind = CLI_REAL, .meta = "X",
      .lo = 0, .hi = 1024, F(p.radius), .help = "sphere, cone (its base), cylinder" },
    { .name = "--height", .mask = BIT(GEN_CONE) | BIT(GEN_CYLINDER), .kind = CLI_REAL, .meta = "X", .lo = 0,
      .hi = 1024, F(p.height), .help = "cone (apex at y = height), cylinder (y from 0 to height)" },
    { .name = "--R", .mask = BIT(GEN_TORUS) | BIT(GEN_KNOT), .kind = CLI_REAL, .meta = "X", .lo = 0, .hi = 1024,
      F(p.R), .help = "torus: the major radius; knot: the torus it winds on" },
    { .name = "--r", .mask = BIT(GEN_TORUS) | BIT(GEN_KNOT), .kind = CLI_REAL, .meta = "X", .lo = 0, .hi = 1024,
      F(p.r), .help = "torus: the tube's radius; knot: the torus it winds on" },
    { .name = "--tube", .mask = BIT(GEN_KNOT), .kind = CLI_REAL, .meta = "X", .lo = 0, .hi = 1024, F(p.tube),
      .help = "knot: the radius of the tube around the curve" },
    { .name = "--p", .mask = BIT(GEN_KNOT), .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 50, F(p.p),
      .help = "knot: turns around the y axis" },
    { .name = "--q", .mask = BIT(GEN_KNOT), .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 50, F(p.q),
      .help = "knot: turns through the hole" },
    { .name = NULL },
};
#undef F

/* The shapes with their parameters' defaults and triangles, from gen.c. */
static void gen_more(FILE *f)
{
    gen_params p[GEN_SHAPE_COUNT];
    uint32_t tris[GEN_SHAPE_COUNT];
    for (int k = 0; k < GEN_SHAPE_COUNT; k++) {
        gen_defaults((gen_shape)k, &p[k]);
        gen_mesh m;
        tris[k] = gen_build(&p[k], &m) == 0 ? m.ntris : 0;
        if (tris[k]) gen_free(&m);
    }
    const gen_params *s = &p[GEN_SPHERE], *t = &p[GEN_TORUS], *c = &p[GEN_CONE], *y = &p[GEN_CYLINDER],
                     *k = &p[GEN_KNOT];
    fprintf(f,
            "\n"
            "shapes and their parameters (defaults in brackets):\n"
            "  sphere    UV sphere, poles at +-y:  --radius [%g]\n"
            "            --segments around [%d], --bands pole to pole [%d]  -> %u triangles\n"
            "  torus     around the y axis:  --R major radius [%g], --r tube radius [%g]\n"
            "            --segments around y [%d], --bands around the tube [%d]  -> %u\n"
            "  cone      apex (0,H,0), base disc at y=0 with a sharp rim:  --radius [%g]\n"
            "            --height [%g], --segments [%d], --bands side rows [%d]  -> %u\n"
            "  cylinder  y from 0 to H, capped, sharp rims:  --radius [%g], --height [%g]\n"
            "            --segments [%d], --bands side rows [%d]  -> %u\n"
            "  knot      (p,q) torus knot, a tube around the curve on the torus R, r:\n"
            "            --p [%d] --q [%d] --R [%g] --r [%g] --tube [%g]\n"
            "            --segments along the curve [%d], --bands around the tube [%d]  -> %u\n",
            s->radius, s->segments, s->bands, tris[GEN_SPHERE], t->R, t->r, t->segments, t->bands, tris[GEN_TORUS],
            c->radius, c->height, c->segments, c->bands, tris[GEN_CONE], y->radius, y->height, y->segments, y->bands,
            tris[GEN_CYLINDER], k->p, k->q, k->R, k->r, k->tube, k->segments, k->bands, tris[GEN_KNOT]);
}

const cli_command cmd_gen_spec = {
    .name = "gen",
    .usage = "usage: silk gen SHAPE [parameters] -o OUT.obj\n",
    .about =
        "Write a closed, outward-oriented analytic mesh as OBJ, every vertex on the\n"
        "exact surface.  The axis of revolution is y.\n",
    .more = gen_more,
    .examples =
        "  silk gen sphere -o sphere.obj\n"
        "  silk gen torus --segments 48 --bands 24 -o torus.obj\n"
        "  silk gen knot --p 3 --q 5 --tube 0.15 --segments 160 -o knot.obj\n"
        "  silk gen sphere --uv --segments 24 --bands 16 -o globe.obj\n",
    .sets = { { gen_rows, ALL, sizeof(gen_args), NULL, NULL } },
    .nsets = 1,
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

int cmd_gen(int argc, char **argv)
{
    gen_args ga;
    memset(&ga, 0, sizeof ga);
    cli_args args;
    void *bases[] = { &ga };
    int rc = cli_parse(&cmd_gen_spec, bases, argc, argv, &args);
    gen_shape shape = GEN_SHAPE_COUNT;
    if (!rc && args.npos == 0) rc = cli_fail(CLI_EXIT_USAGE, "gen: which shape? (sphere, torus, cone, cylinder or knot)");
    if (!rc && args.npos > 1) rc = cli_fail(CLI_EXIT_USAGE, "gen: one shape at a time (got %s and %s)", args.pos[0], args.pos[1]);
    if (!rc && (shape = gen_shape_from_name(args.pos[0])) == GEN_SHAPE_COUNT)
        rc = cli_fail(CLI_EXIT_USAGE, "gen: unknown shape \"%s\" (sphere, torus, cone, cylinder or knot)", args.pos[0]);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    if (rc) return rc;
    /* the shape's defaults, and the parameters given over them */
    gen_params p;
    gen_defaults(shape, &p);
    for (int k = 0; k < args.ngiven; k++) {
        const cli_opt *o = args.given[k];
        if (o->mask && !(o->mask & BIT(shape)))
            return cli_fail(CLI_EXIT_USAGE, "gen: %s does not apply to a %s", o->name, gen_shape_name(shape));
        size_t in_p = o->off - offsetof(gen_args, p);
        if (o->off >= offsetof(gen_args, p)) memcpy((char *)&p + in_p, (const char *)&ga.p + in_p, o->size);
    }
    const char *out = ga.out;
    if (!out) return cli_fail(CLI_EXIT_USAGE, "gen: no output given (-o OUT.obj)");
    if (strcmp(out, "-") != 0 && !has_obj_extension(out))
        return cli_fail(CLI_EXIT_USAGE, "gen: %s: the output must be a .obj file", out);
    char why[160];
    if (gen_check(&p, why, sizeof why)) return cli_fail(CLI_EXIT_USAGE, "gen %s: %s", gen_shape_name(shape), why);

    gen_mesh m;
    if (gen_build(&p, &m) != 0) return cli_fail(CLI_EXIT_INPUT, "gen: out of memory");
    rc = write_mesh(&m, &p, out);
    gen_free(&m);
    return rc;
}
