/*
 * measure.h - the measurement subcommands of the silk tool: `silk diff`
 * (tools/cmd_diff.c), `silk simplify` (tools/cmd_simplify.c) and the
 * render-mode benchmark that `silk bench` runs without --visibility
 * (tools/cmd_bench_modes.c).  Each takes argv[0] = its name and returns the
 * exit status, like the commands in cli.h.
 */
#ifndef SILK_MEASURE_H
#define SILK_MEASURE_H

int cmd_diff(int argc, char **argv);
int cmd_simplify(int argc, char **argv);
int cmd_prepare(int argc, char **argv);
int cmd_bench_modes(int argc, char **argv);

#endif
