/*
 * man.c - the manual page silk.1 in man(7) roff, from the help texts (see
 * man.h).  Each help text goes in as printed, between .nf and .fi, with the
 * characters roff would read as requests or escapes escaped: a backslash as
 * \e, a minus as \- (so options copy as ASCII hyphen-minus), and \& before a
 * line that starts with a dot or a quote.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <unistd.h>

#include "man.h"

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

int man_help_block(FILE *out, man_help_fn help, const char *name)
{
    /* The help printers write to stdout: point stdout at a temporary file
     * while one runs. */
    FILE *tmp = tmpfile();
    if (!tmp || fflush(stdout) != 0) return 1;
    int saved = dup(STDOUT_FILENO);
    if (saved < 0 || dup2(fileno(tmp), STDOUT_FILENO) < 0) {
        fclose(tmp);
        return 1;
    }
    char *argv[] = { (char *)name, "--help", NULL };
    int rc = help(2, argv);
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    rewind(tmp);
    fputs(".nf\n", out);
    int c, start = 1;
    while ((c = fgetc(tmp)) != EOF) {
        put_roff(out, c, start);
        start = c == '\n';
    }
    if (!start) fputc('\n', out);
    fputs(".fi\n", out);
    fclose(tmp);
    return rc;
}

void man_end(FILE *out)
{
    fputs(".SH LICENSE\n"
          "MIT; see the file LICENSE that comes with silk.\n"
          ".SH SEE ALSO\n"
          "README.md and docs/ in the silk sources: the library, the render modes, the\n"
          "file formats, memory, small devices and the measurements.\n",
          out);
}
