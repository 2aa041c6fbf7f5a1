/*
 * man.h - `silk help --man`: the manual page silk.1, made from the very text
 * `silk --help` and `silk help COMMAND` print, so the two cannot disagree.
 * The Makefile writes build/silk.1 with it and `make install` installs that.
 */
#ifndef SILK_MAN_H
#define SILK_MAN_H

#include <stdio.h>

/* A help printer: writes its text to stdout and returns 0 (the subcommands'
 * entry points called with { NAME, "--help" } are such printers). */
typedef int (*man_help_fn)(int argc, char **argv);

/* The page's title block and NAME section. */
void man_begin(FILE *out, const char *version);
/* A section (".SH") or subsection (".SS") heading. */
void man_heading(FILE *out, const char *level, const char *title);
/* What help(2, { name, "--help" }) prints, as a block of lines kept as they
 * are.  Returns help's status, or 1 when its output cannot be captured. */
int man_help_block(FILE *out, man_help_fn help, const char *name);
/* LICENSE and SEE ALSO. */
void man_end(FILE *out);

#endif
