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

/* Parts: `silk bench --visibility-pass` (tools/cli/bench_visibility.c) and
 * `silk bench --grid` (tools/cli/bench_grid.c). */
int bench_visibility(int argc, char **argv);
int bench_grid(int argc, char **argv);

/* Each command's options and help (opt.h), for `silk help`. */
struct cli_command;
extern const struct cli_command cmd_render_spec, cmd_info_spec, cmd_gen_spec, cmd_bench_spec, cmd_bench_visibility_spec,
    cmd_bench_grid_spec,
    cmd_simplify_spec, cmd_prepare_spec, cmd_diff_spec, cmd_pack_spec, cmd_view_spec, cmd_profile_spec,
    cmd_hull_spec;

#endif
