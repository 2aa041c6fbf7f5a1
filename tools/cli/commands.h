/*
 * commands.h - the subcommands of the silk tool, one per tools/cmd_NAME.c,
 * and the parts of a command that live in a file of their own.  Each takes
 * argv[0] = its name and returns the exit status (0, CLI_EXIT_INPUT or
 * CLI_EXIT_USAGE, tools/cli/cli.h).
 */
#ifndef SILK_COMMANDS_H
#define SILK_COMMANDS_H

int cmd_render(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_gen(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_simplify(int argc, char **argv);
int cmd_prepare(int argc, char **argv);
int cmd_diff(int argc, char **argv);
int cmd_pack(int argc, char **argv);
int cmd_view(int argc, char **argv);
int cmd_profile(int argc, char **argv);
int cmd_hull(int argc, char **argv);

/* Parts: `silk bench --visibility` (tools/cli/bench_visibility.c) and the
 * framebuffer side of `silk view` (tools/view/view_fb.c). */
int bench_visibility(int argc, char **argv);
int view_fb(int argc, char **argv);

#endif
