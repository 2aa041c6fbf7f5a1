/*
 * opt.c - the one option parser and the one help printer of the silk
 * command, both driven by the commands' cli_opt tables (opt.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "opt.h"

#define HELP_WIDTH 79          /* the help's lines */
#define HELP_COLUMN 23         /* where an option's text starts */

/* ---- rows ------------------------------------------------------------------------ */

static int row_in(const cli_opt *o, unsigned mask) { return o->mask == 0 || (o->mask & mask) != 0; }

/* Whether the row takes a value on the command line. */
static int takes_value(const cli_opt *o)
{
    return o->kind != CLI_FLAG && !(o->kind == CLI_CUSTOM && !o->meta);
}

static int spelled(const char *s, size_t n, const char *name)
{
    return name && strlen(name) == n && strncmp(s, name, n) == 0;
}

/* Whether row o of set k is the command's: in the set's mask, and not
 * shadowed by a row of the same name in an earlier set (a command's own
 * --eye replaces the scene options'). */
static int row_of(const cli_command *c, int k, const cli_opt *o)
{
    if (!row_in(o, c->sets[k].mask)) return 0;
    for (int j = 0; j < k; j++)
        for (const cli_opt *p = c->sets[j].opts; p->name; p++)
            if (row_in(p, c->sets[j].mask) && strcmp(p->name, o->name) == 0) return 0;
    return 1;
}

static const cli_opt *find_row(const cli_command *c, const char *s, size_t n, int *set)
{
    for (int k = 0; k < c->nsets; k++)
        for (const cli_opt *o = c->sets[k].opts; o->name; o++)
            if (row_of(c, k, o) && (spelled(s, n, o->name) || spelled(s, n, o->alt))) {
                *set = k;
                return o;
            }
    return NULL;
}

/* The command's own name for messages: "bench" of "bench --visibility-pass". */
static void short_name(const cli_command *c, char *buf, size_t n)
{
    size_t k = strcspn(c->name, " ");
    snprintf(buf, n, "%.*s", (int)k, c->name);
}

/* ---- fields ------------------------------------------------------------------------ */

static void put_int(void *field, size_t size, long long v)
{
    int8_t a = (int8_t)v;
    int16_t b = (int16_t)v;
    int32_t c = (int32_t)v;
    int64_t d = (int64_t)v;
    switch (size) {
    case 1: memcpy(field, &a, 1); break;
    case 2: memcpy(field, &b, 2); break;
    case 4: memcpy(field, &c, 4); break;
    default: memcpy(field, &d, 8); break;
    }
}

static long long get_int(const void *field, size_t size)
{
    int8_t a;
    int16_t b;
    int32_t c;
    int64_t d;
    switch (size) {
    case 1: memcpy(&a, field, 1); return a;
    case 2: memcpy(&b, field, 2); return b;
    case 4: memcpy(&c, field, 4); return c;
    default: memcpy(&d, field, 8); return d;
    }
}

/* Word k of "a|b|c" into buf; 0 when there is none. */
static int choice_word(const char *choices, int k, char *buf, size_t n)
{
    const char *p = choices;
    for (int i = 0; i < k; i++) {
        p = strchr(p, '|');
        if (!p) return 0;
        p++;
    }
    size_t len = strcspn(p, "|");
    snprintf(buf, n, "%.*s", (int)len, p);
    return 1;
}

static int choice_value(const cli_opt *o, int k) { return o->values ? o->values[k] : k; }

/* "a, b or c" for a message. */
static void choice_list(const char *choices, char *buf, size_t n)
{
    char w[64];
    buf[0] = 0;
    int count = 0;
    while (choice_word(choices, count, w, sizeof w)) count++;
    for (int k = 0; k < count; k++) {
        choice_word(choices, k, w, sizeof w);
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", k == 0 ? "" : k == count - 1 ? " or " : ", ", w);
    }
}

static int parse_choice(const cli_opt *o, const char *opt, const char *v, void *field)
{
    char w[64], list[256];
    for (int k = 0; choice_word(o->choices, k, w, sizeof w); k++)
        if (strcmp(w, v) == 0) {
            put_int(field, o->size, choice_value(o, k));
            return 0;
        }
    choice_list(o->choices, list, sizeof list);
    return cli_fail(-1, "%s must be %s (got \"%s\")", opt, list, v);
}

/* One value of row o, spelled opt, into base.  0, or an exit status after
 * the error. */
static int set_value(const cli_opt *o, const char *opt, const char *v, void *base)
{
    char *field = (char *)base + o->off;
    int r = 0;
    switch (o->parse ? CLI_CUSTOM : o->kind) {
    case CLI_FLAG:
        put_int(field, o->size, 1);
        break;
    case CLI_INT: {
        long n;
        if ((r = cli_parse_long(opt, v, (long)o->lo, (long)o->hi, &n)) == 0) put_int(field, o->size, n);
        break;
    }
    case CLI_REAL:
        r = cli_parse_double(opt, v, o->lo, o->hi, (double *)field);
        break;
    case CLI_FX: {
        double d;
        if ((r = cli_parse_double(opt, v, o->lo, o->hi, &d)) == 0) *(silk_fx *)field = cli_fx_from_double(d);
        break;
    }
    case CLI_CHOICE:
        r = parse_choice(o, opt, v, field);
        break;
    case CLI_TEXT:
        *(const char **)field = v;
        break;
    case CLI_OUTPUT:
        if (!silk_path_is_stdio(v) && cli_check_output_dir(opt, v) != 0) return CLI_EXIT_INPUT;
        *(const char **)field = v;
        break;
    case CLI_DIR:
        if (cli_check_dir(opt, v) != 0) return CLI_EXIT_INPUT;
        *(const char **)field = v;
        break;
    case CLI_SIZE:
        r = cli_parse_size(opt, v, (int *)field, (int *)((char *)base + o->off2));
        break;
    case CLI_RGB:
        r = cli_parse_rgb(opt, v, (uint32_t *)field);
        break;
    case CLI_VEC3:
        r = cli_parse_vec3(opt, v, o->hi, (double *)field);
        break;
    case CLI_BYTES:
        r = cli_parse_bytes(opt, v, (size_t *)field);
        break;
    case CLI_DECIMAL:
        r = cli_parse_decimal(opt, v, (silk_decimal *)field);
        break;
    case CLI_CUSTOM:
        r = o->parse(o, v, base);
        break;
    }
    if (r) return r > 0 ? r : CLI_EXIT_USAGE;
    if (o->seen) *(int *)((char *)base + o->seen - 1) = 1;
    return 0;
}

/* ---- the parser ------------------------------------------------------------------- */

int cli_parse(const cli_command *c, void *const *bases, int argc, char **argv, cli_args *args)
{
    char me[32];
    short_name(c, me, sizeof me);
    args->npos = 0;
    args->ngiven = 0;
    if (!(args->pos = calloc((size_t)argc + 1, sizeof *args->pos))) return cli_fail(CLI_EXIT_INPUT, "out of memory");
    int positional = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!positional && strcmp(a, "--") == 0) {
            positional = 1;
            continue;
        }
        if (positional || a[0] != '-' || a[1] == 0) {
            int r = c->positional ? c->positional(a, bases[0]) : (args->pos[args->npos++] = a, 0);
            if (r) return r;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            cli_help_print(stdout, c);
            return CLI_HELP;
        }
        size_t n = strcspn(a, "=");
        const char *eq = a[n] ? a + n + 1 : NULL;
        char opt[64];
        snprintf(opt, sizeof opt, "%.*s", (int)(n < sizeof opt ? n : sizeof opt - 1), a);
        int set = 0;
        const cli_opt *o = find_row(c, a, n, &set);
        if (!o) {
            for (const char *const *r = c->renamed; r && r[0]; r += 2)
                if (strcmp(r[0], opt) == 0)
                    return cli_fail(CLI_EXIT_USAGE, "%s: unknown option %s (it is %s now; try silk %s --help)", me, opt,
                                    r[1], c->name);
            return cli_fail(CLI_EXIT_USAGE, "%s: unknown option %s (try silk %s --help)", me, opt, c->name);
        }
        const char *v = NULL;
        if (!takes_value(o)) {
            if (eq) return cli_fail(CLI_EXIT_USAGE, "%s takes no value (got %s)", opt, a);
        } else if (eq) {
            v = eq;
        } else if (i + 1 < argc) {
            v = argv[++i];
        } else {
            return cli_fail(CLI_EXIT_USAGE, "%s needs a value", opt);
        }
        int r = set_value(o, opt, v, bases[set]);
        if (r) return r;
        if (args->ngiven < CLI_MAX_GIVEN) args->given[args->ngiven++] = o;
    }
    for (int k = 0; k < c->nsets; k++) {
        int r = c->sets[k].finish ? c->sets[k].finish(bases[k]) : 0;
        if (r) return r;
    }
    return 0;
}

void cli_args_free(cli_args *args)
{
    free(args->pos);
    args->pos = NULL;
}

int cli_given(const cli_args *a, const char *name)
{
    for (int k = 0; k < a->ngiven; k++)
        if (strcmp(a->given[k]->name, name) == 0) return 1;
    return 0;
}

/* ---- the help --------------------------------------------------------------------- */

static void range_text(const cli_opt *o, char *buf, size_t n)
{
    if (o->kind == CLI_INT) snprintf(buf, n, "%lld..%lld", (long long)o->lo, (long long)o->hi);
    else snprintf(buf, n, "%.15g..%.15g", o->lo, o->hi);
}

/* The default value of row o in the defaults struct d, as the command line
 * would give it. */
static void default_text(const cli_opt *o, const void *d, char *buf, size_t n)
{
    const char *field = (const char *)d + o->off;
    const char *s;
    char w[64];
    buf[0] = 0;
    switch (o->kind) {
    case CLI_INT:
        snprintf(buf, n, "%lld", get_int(field, o->size));
        break;
    case CLI_REAL:   /* four digits: a default held in Q16.16 shows as written */
        snprintf(buf, n, "%.4g", *(const double *)field);
        break;
    case CLI_FX:
        snprintf(buf, n, "%.4g", cli_fx_to_double(*(const silk_fx *)field));
        break;
    case CLI_CHOICE:
        for (int k = 0; choice_word(o->choices, k, w, sizeof w); k++)
            if (choice_value(o, k) == get_int(field, o->size)) {
                snprintf(buf, n, "%s", w);
                break;
            }
        break;
    case CLI_TEXT: case CLI_OUTPUT: case CLI_DIR:
        s = *(const char *const *)field;
        snprintf(buf, n, "%s", s ? s : "none");
        break;
    case CLI_SIZE:
        snprintf(buf, n, "%dx%d", *(const int *)field, *(const int *)((const char *)d + o->off2));
        break;
    case CLI_RGB:
        snprintf(buf, n, "%06x", (unsigned)*(const uint32_t *)field);
        break;
    case CLI_BYTES:
        snprintf(buf, n, "%zu", *(const size_t *)field);
        break;
    default:
        break;
    }
}

/* The help text with %D and %R filled in. */
static void fill(const cli_opt *o, const void *d, char *out, size_t n)
{
    size_t k = 0;
    for (const char *p = o->help ? o->help : ""; *p && k + 1 < n; p++) {
        char tmp[128];
        const char *ins = NULL;
        if (p[0] == '%' && p[1] == 'D') default_text(o, d, tmp, sizeof tmp), ins = tmp;
        else if (p[0] == '%' && p[1] == 'R') range_text(o, tmp, sizeof tmp), ins = tmp;
        else if (p[0] == '%' && p[1] == '%') ins = "%";
        if (ins) {
            p++;
            k += (size_t)snprintf(out + k, n - k, "%s", ins);
            if (k >= n) k = n - 1;
        } else {
            out[k++] = *p;
        }
    }
    out[k] = 0;
}

/* text from column col (the cursor is there), wrapped at HELP_WIDTH with
 * later lines at HELP_COLUMN; '\n' in text starts a new line. */
static void wrap(FILE *f, const char *text, int col)
{
    int fresh = 1;   /* no word on this line yet */
    for (const char *p = text; *p;) {
        if (*p == '\n') {
            fprintf(f, "\n%*s", HELP_COLUMN, "");
            col = HELP_COLUMN;
            fresh = 1;
            p++;
            continue;
        }
        size_t word = strcspn(p, " \n");
        if (!fresh && col + 1 + (int)word > HELP_WIDTH) {
            fprintf(f, "\n%*s", HELP_COLUMN, "");
            col = HELP_COLUMN;
            fresh = 1;
        }
        if (!fresh) {
            fputc(' ', f);
            col++;
        }
        fprintf(f, "%.*s", (int)word, p);
        col += (int)word;
        fresh = 0;
        p += word;
        while (*p == ' ') p++;
    }
    fputc('\n', f);
}

static const char *meta_of(const cli_opt *o)
{
    if (o->meta) return o->meta;
    if (o->kind == CLI_CHOICE) return o->choices;
    if (o->kind == CLI_FLAG || o->kind == CLI_CUSTOM) return NULL;
    return o->kind == CLI_INT ? "N" : "X";
}

static void print_row(FILE *f, const cli_opt *o, const void *d)
{
    char lead[160], text[2048];
    const char *meta = meta_of(o);
    if (o->alt && o->alt[1] != '-')   /* "-o, --output": a short spelling first */
        snprintf(lead, sizeof lead, "  %s, %s%s%s", o->alt, o->name, meta ? " " : "", meta ? meta : "");
    else
        snprintf(lead, sizeof lead, "  %s%s%s", o->name, meta ? " " : "", meta ? meta : "");
    fill(o, d, text, sizeof text);
    int col = (int)strlen(lead);
    fputs(lead, f);
    if (col <= HELP_COLUMN - 2) {
        fprintf(f, "%*s", HELP_COLUMN - col, "");
        col = HELP_COLUMN;
    } else {
        fputs("  ", f);
        col += 2;
    }
    wrap(f, text, col);
}

void cli_help_print(FILE *f, const cli_command *c)
{
    fputs(c->usage, f);
    if (c->about) fprintf(f, "\n%s", c->about);
    if (c->more) c->more(f);
    int first = 1;
    for (int k = 0; k < c->nsets; k++) {
        const cli_optset *s = &c->sets[k];
        void *d = calloc(1, s->size ? s->size : 1);
        if (d && s->defaults) s->defaults(d);
        const char *heading = NULL;   /* a group's, kept when its first row is shadowed */
        for (const cli_opt *o = s->opts; o->name; o++) {
            if (o->group && row_in(o, s->mask)) heading = o->group;
            if (!row_of(c, k, o)) continue;
            if (heading || first) fprintf(f, "\n%s%s", heading ? heading : "", heading && *heading ? ":\n" : "");
            heading = NULL;
            first = 0;
            print_row(f, o, d);
        }
        free(d);
    }
    if (c->examples) fprintf(f, "\nexamples:\n%s", c->examples);
}

static const char *const kind_name[] = { "flag", "int", "real", "real", "choice", "text", "output", "dir",
                                         "size", "rgb", "vec3", "bytes", "decimal", "custom" };

void cli_options_print(FILE *f, const cli_command *c)
{
    const char *group = "-";
    for (int k = 0; k < c->nsets; k++)
        for (const cli_opt *o = c->sets[k].opts; o->name; o++) {
            if (o->group && row_in(o, c->sets[k].mask)) group = *o->group ? o->group : "-";
            if (!row_of(c, k, o)) continue;
            const char *meta = meta_of(o);
            char lo[32] = "-", hi[32] = "-";
            if (o->kind == CLI_INT || o->kind == CLI_REAL || o->kind == CLI_FX) {
                snprintf(lo, sizeof lo, "%.17g", o->lo);
                snprintf(hi, sizeof hi, "%.17g", o->hi);
            }
            fprintf(f, "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", c->name, o->name, o->alt ? o->alt : "-",
                    kind_name[o->kind], meta ? meta : "-", lo, hi, o->choices ? o->choices : "-", group);
        }
}
