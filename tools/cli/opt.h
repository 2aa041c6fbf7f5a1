/*
 * opt.h - the options of the silk command, one table per command.
 *
 * Every option is written down once, in a row of a cli_opt table: its name
 * (and another spelling), the help group it is listed under, its kind (what
 * its value is and how it is checked), its range, the field it sets and
 * its help text.  One parser (cli_parse) reads a command line against a
 * command's tables, so every option takes "--opt value" and "--opt=value"
 * and every value is checked the same way for every command; one printer
 * (cli_help_print) writes the command's help from the same rows, with the
 * range and the default of each value taken from the table and from the
 * defaults the command really starts from, and `silk help --man` makes the
 * manual page of that text.  `silk help --options CMD` lists the rows for
 * scripts (tests/cli/cli_options.sh checks help, parser and table agree).
 *
 * A row's field is an offset into the struct the command parses into
 * (cli_optset.size bytes, filled with its defaults first), so a table is
 * plain data; what a value means beyond its kind (a list of modes, a
 * repeated --eye, an option that sets two fields) is a parse function of
 * the row.
 */
#ifndef SILK_CLI_OPT_H
#define SILK_CLI_OPT_H

#include <stddef.h>
#include <stdio.h>

typedef enum cli_kind {
    CLI_FLAG,          /* no value: the int field becomes 1 */
    CLI_INT,           /* an integer in [lo, hi]: the field is an integer type of any size */
    CLI_REAL,          /* a decimal number in [lo, hi]: double */
    CLI_FX,            /* the same as Q16.16: silk_fx */
    CLI_CHOICE,        /* one of the words of choices ("fix|keep"): the field (an integer or enum) gets
                          values[k], or k without values */
    CLI_TEXT,          /* any text: const char * pointing into argv */
    CLI_OUTPUT,        /* a file to write, "-" for standard output: const char *; the folder it goes
                          into must exist */
    CLI_DIR,           /* a folder to write files into: const char *; made when missing (its parent
                          must exist) */
    CLI_SIZE,          /* WIDTHxHEIGHT, 1..SILK_MAX_DIM each: two ints, at off and off2 */
    CLI_RGB,           /* RRGGBB in hex: uint32_t */
    CLI_VEC3,          /* x,y,z, each within +-hi: double[3] */
    CLI_BYTES,         /* a byte count, 65536, 512K, 64M (4K..4G): size_t */
    CLI_DECIMAL,       /* an exact positive decimal number: silk_decimal */
    CLI_CUSTOM         /* parse() says: lists, repeated options, options that set several fields */
} cli_kind;

struct cli_opt;
/* A custom value: v the value (NULL for a custom flag), base the struct.
 * 0, or -1 after a one-line error naming the option. */
typedef int (*cli_parse_fn)(const struct cli_opt *o, const char *v, void *base);

typedef struct cli_opt {
    const char *name;          /* "--size"; a row with NULL ends the table */
    const char *alt;           /* another spelling ("-o" for --output), or NULL */
    const char *group;         /* the help heading it starts; NULL: under the row before's */
    unsigned mask;             /* which of the set's parts it belongs to (cli_optset.mask); 0: always */
    cli_kind kind;             /* the field's: how a value is checked and the default shown */
    const char *meta;          /* its value in the help ("WxH"); NULL: the choices, or "N" / "X" */
    double lo, hi;             /* INT, REAL, FX: the range; VEC3: the largest coordinate */
    const char *choices;       /* CHOICE: the words, "a|b|c" */
    const int *values;         /* CHOICE: the value of each word; NULL: 0, 1, 2, ... */
    size_t off, size;          /* the field: offset and size (CLI_FIELD) */
    size_t off2;               /* SIZE: the height's offset */
    size_t seen;               /* 1 + offset of an int set to 1 when the option is given; 0: none */
    cli_parse_fn parse;        /* the value's parser instead of the kind's (CUSTOM: always; a CUSTOM
                                  row without meta is a flag, parse gets NULL) */
    const char *help;          /* wrapped by the printer; %D is the default, %R the range "lo..hi",
                                  %% a percent sign */
} cli_opt;

/* A row's field (member of struct type) and its seen flag, for a
 * designated initializer: { .name = "--crease", CLI_FIELD(T, crease), ... }. */
#define CLI_FIELD(type, member) .off = offsetof(type, member), .size = sizeof(((type *)0)->member)
#define CLI_SEEN(type, member) .seen = offsetof(type, member) + 1

/* One struct's options: the table, which of its parts this command takes
 * (rows whose mask meets it, and rows of mask 0), how to make the struct
 * with the command's defaults (for the help's defaults), and what to do
 * when the command line is read (fields that follow from others, checks
 * across options; 0 or an exit status after the error; may be NULL). */
typedef struct cli_optset {
    const cli_opt *opts;
    unsigned mask;
    size_t size;
    void (*defaults)(void *base);
    int (*finish)(void *base);
} cli_optset;

#define CLI_MAX_SETS 3

/* A command: its help text around the options, and their sets.  usage is
 * the "usage:" lines; about the paragraphs under them; more, when set,
 * prints what the text needs computed after them; examples the lines
 * under "examples:".  The help is usage, about, more, the options by
 * group, examples. */
typedef struct cli_command {
    const char *name;          /* "render", "bench --visibility-pass" */
    const char *usage, *about, *examples;
    void (*more)(FILE *f);
    cli_optset sets[CLI_MAX_SETS];   /* the first nsets */
    int nsets;
    /* Options that have another name now: pairs of old and new names, NULL
     * after the last; the old name is an unknown option whose error says
     * the new one. */
    const char *const *renamed;
    /* When set, each argument that is not an option goes here, in order,
     * with the first set's struct (0, or an exit status after the error),
     * instead of into cli_args.pos: for commands whose arguments mix with
     * options that add to the same list (silk bench MESH --pair C:F). */
    int (*positional)(const char *arg, void *base);
} cli_command;

/* What the command line held besides its options. */
#define CLI_MAX_GIVEN 256
typedef struct cli_args {
    int npos;
    const char **pos;          /* the other arguments in order ("-" among them); cli_args_free */
    int ngiven;
    const cli_opt *given[CLI_MAX_GIVEN];   /* the options given, in order (the first CLI_MAX_GIVEN) */
} cli_args;

/* cli_parse's result for --help or -h: the help is printed on stdout. */
#define CLI_HELP (-1)

/* Parse argv[1..] (argv[0] is the command's name) into bases[k], the
 * struct of set k, which the caller has filled with its defaults.  An
 * argument that starts with '-' (not "-" alone) is an option, in either
 * spelling, as "--opt value" or "--opt=value"; after "--" every argument is
 * positional.  Returns 0, CLI_HELP, or CLI_EXIT_USAGE after a one-line
 * error ("CMD: unknown option --x (try silk CMD --help)", "--size needs a
 * value", the value's own).  cli_args_free releases args either way. */
int cli_parse(const cli_command *c, void *const *bases, int argc, char **argv, cli_args *args);
void cli_args_free(cli_args *args);

/* Whether an option of the command line was given (by row). */
int cli_given(const cli_args *a, const char *name);

/* The help: usage, about, more, the options by group with ranges and
 * defaults, the examples. */
void cli_help_print(FILE *f, const cli_command *c);

/* The rows for scripts, one line each: COMMAND NAME ALT KIND META LO HI
 * CHOICES GROUP, tab-separated, "-" where empty. */
void cli_options_print(FILE *f, const cli_command *c);

#endif
