/*
 * man.c - the manual page silk.1 in man(7) roff, from the help texts (see
 * man.h), the very text `silk help COMMAND` prints from the option tables.  Each help text goes in as printed, between .nf and .fi, with the
 * characters roff would read as requests or escapes escaped: a backslash as
 * \e, a minus as \- (so options copy as ASCII hyphen-minus), and \& before a
 * line that starts with a dot or a quote.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>

#include "man.h"
#include "opt.h"

/* One character of help text as roff. */
static void put_roff(FILE *out, int c, int line_start)
{
    if (line_start && (c == '.' || c == '\'')) fputs("\\&", out);
    if (c == '\\') fputs("\\e", out);
    else if (c == '-') fputs("\\-", out);
    else fputc(c, out);
}

void man_begin(FILE *out, const char *version)
{
    fprintf(out,
            ".\\\" silk.1 - made by `silk help --man` from the text of `silk help`.\n"
            ".TH SILK 1 \"\" \"silk %s\" \"User Commands\"\n"
            ".SH NAME\n"
            "silk \\- smooth silhouettes for coarse triangle meshes, in fixed point, in software\n",
            version);
}

void man_heading(FILE *out, const char *level, const char *title)
{
    fprintf(out, ".%s ", level);
    for (const char *p = title; *p; p++) put_roff(out, (unsigned char)*p, 0);
    fputc('\n', out);
}

int man_help_block(FILE *out, void (*text)(FILE *f), const struct cli_command *c)
{
    FILE *tmp = tmpfile();
    if (!tmp) return 1;
    if (text) text(tmp);
    else cli_help_print(tmp, c);
    int bad = ferror(tmp) != 0;
    rewind(tmp);
    fputs(".nf\n", out);
    int ch, start = 1;
    while ((ch = fgetc(tmp)) != EOF) {
        put_roff(out, ch, start);
        start = ch == '\n';
    }
    if (!start) fputc('\n', out);
    fputs(".fi\n", out);
    fclose(tmp);
    return bad;
}

void man_end(FILE *out)
{
    fputs(".SH LICENSE\n"
          "MIT; see the file LICENSE that comes with silk.\n"
          ".SH SEE ALSO\n"
          "README.md and docs/ (installed in share/doc/silk): the library, the render\n"
          "modes, the file formats, memory, small devices and the measurements.\n",
          out);
}
