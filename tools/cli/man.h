/*
 * man.h - `silk help --man`: the manual page silk.1, made from the very text
 * `silk --help` and `silk help COMMAND` print, so the two cannot disagree.
 * The Makefile writes build/silk.1 with it and `make install` installs that.
 */
#ifndef SILK_MAN_H
#define SILK_MAN_H

#include <stdio.h>

struct cli_command;

/* The page's title block and NAME section. */
void man_begin(FILE *out, const char *version);
/* A section (".SH") or subsection (".SS") heading. */
void man_heading(FILE *out, const char *level, const char *title);
/* A help text as a block of lines kept as they are: what text(f) prints,
 * or else the command's help (cli_help_print).  Returns 0, or 1 when the
 * text cannot be captured. */
int man_help_block(FILE *out, void (*text)(FILE *f), const struct cli_command *c);
/* LICENSE and SEE ALSO. */
void man_end(FILE *out);

#endif
