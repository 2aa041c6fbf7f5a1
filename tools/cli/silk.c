/*
 * silk.c - the `silk` command: main and the dispatch to its subcommands
 * (render, info, gen, view, bench, diff, prepare, simplify, hull, pack,
 * profile, help),
 * each in its own cmd_*.c file.
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "man.h"

typedef struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *synopsis, *summary;
} command;

static const command commands[] = {
    { "render", cmd_render, "render MESH -o OUT.png", "render a mesh (OBJ, PLY, STL, .silk) to PNG or PPM" },
    { "info", cmd_info, "info MESH", "counts, memory use and per-frame statistics" },
    { "gen", cmd_gen, "gen SHAPE -o OUT.obj", "write a sphere, torus, cone, cylinder or knot" },
    { "bench", cmd_bench, "bench MESH...", "time and silhouette error per render mode; --visibility" },
    { "prepare", cmd_prepare, "prepare FINE -o MODEL.silk --triangles N",
      "a detailed mesh made into a prepared model for silk" },
    { "simplify", cmd_simplify, "simplify IN OUT --triangles N", "fewer triangles, by quadric edge collapse" },
    { "hull", cmd_hull, "hull FINE -o HULL.obj", "a coarse mesh around FINE (--triangles N; --inner)" },
    { "diff", cmd_diff, "diff A.png B.png", "how far apart the silhouettes of two renders are" },
    { "pack", cmd_pack, "pack MESH -o MODEL.h", "the loaded mesh as C arrays for flash" },
    { "view", cmd_view, "view MESH [--fb /dev/fb0]", "look at it: a window (mouse, keys) or a framebuffer" },
    { "profile", cmd_profile, "profile MESH", "where every byte of RAM goes on this board" },
};
enum { NCOMMANDS = sizeof commands / sizeof commands[0] };

static void usage(FILE *f)
{
    fprintf(f,
            "silk %s - smooth silhouettes for coarse triangle meshes (fixed point, software)\n"
            "\n"
            "usage: silk COMMAND [options]\n"
            "\n"
            "commands:\n",
            SILK_VERSION);
    for (int i = 0; i < NCOMMANDS; i++) fprintf(f, "  silk %-27s %s\n", commands[i].synopsis, commands[i].summary);
    fprintf(f,
            "\n"
            "  silk help COMMAND                every option of one command (or COMMAND --help)\n"
            "  silk help --man                  all of this help as a manual page (silk.1)\n"
            "  silk --version                   the version\n"
            "\n"
            "Exit status: 0 success, 1 bad input (a file, a mesh, a failed write),\n"
            "2 bad usage (an unknown option or a value out of range).\n");
}

static int overview(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    usage(stdout);
    return 0;
}

/* `silk help --man`: this help and every command's as one manual page. */
static int man_page(void)
{
    man_begin(stdout, SILK_VERSION);
    man_heading(stdout, "SH", "DESCRIPTION");
    int rc = man_help_block(stdout, overview, "silk");
    man_heading(stdout, "SH", "COMMANDS");
    for (int i = 0; i < NCOMMANDS; i++) {
        char title[64];
        snprintf(title, sizeof title, "silk %s", commands[i].name);
        man_heading(stdout, "SS", title);
        rc |= man_help_block(stdout, commands[i].run, commands[i].name);
    }
    man_end(stdout);
    if (fflush(stdout) != 0) return cli_fail(CLI_EXIT_INPUT, "stdout: cannot write");
    return rc ? cli_fail(CLI_EXIT_INPUT, "help --man: a command's help failed") : 0;
}

static const command *find(const char *name)
{
    for (int i = 0; i < NCOMMANDS; i++)
        if (strcmp(commands[i].name, name) == 0) return &commands[i];
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    const char *name = argv[1];
    if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(name, "--version") == 0) {
        printf("silk %s\n", SILK_VERSION);
        return 0;
    }
    if (strcmp(name, "help") == 0) {
        if (argc < 3) {
            usage(stdout);
            return 0;
        }
        if (strcmp(argv[2], "--man") == 0) return man_page();
        const command *c = find(argv[2]);
        if (!c) return cli_fail(CLI_EXIT_USAGE, "unknown command \"%s\" (try silk --help)", argv[2]);
        char *help_argv[] = { argv[2], "--help", NULL };
        return c->run(2, help_argv);
    }
    const command *c = find(name);
    if (!c) return cli_fail(CLI_EXIT_USAGE, "unknown command \"%s\" (try silk --help)", name);
    return c->run(argc - 1, argv + 1);
}
