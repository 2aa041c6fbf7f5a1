/*
 * cmd_profile.c - `silk profile MESH --board NAME`: where every byte goes on
 * a board, as a table, a CSV file and one summary line.
 *
 * A firmware board (boards/NAME/board.mk sets BOARD_RULES, e.g.
 * mps2-an385) is measured on the real thing: the firmware for MESH is built
 * (`make BOARD=NAME BOARD_MESHES=MESH firmware`) and run (BOARD_RUN, i.e.
 * QEMU), and reports its own arena high-water marks by purpose and its
 * stack high-water mark from stack painting; flash and static RAM come from
 * the linker's map file, input section by input section: the core's code
 * by module, the scene, platform code, libc, libgcc, and the packed model by
 * kind.  A host board (host, linux-fb) is measured in-process instead: the
 * mesh is loaded into the arena as the tool does, and the frames are
 * rendered in the board's bands; code size is `size` of the core's objects.
 *
 * The views are those of `silk pack --views N` (BOARD_VIEWS, default 3), each
 * in flat and smooth mode.  The last line is
 *   footprint BOARD MESH ram_total_bytes=N code_bytes=N model_bytes=N
 * with ram_total = static RAM + arena high-water + stack high-water (the
 * band buffers are in the arena), code = flash other than the model.
 *
 * Runs from the source tree (it reads boards/ and calls make).
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* ---- boards/NAME/board.mk ----------------------------------------------------- */

#define BOARD_VARS 64

typedef struct board {
    char name[64];
    int n;
    char key[BOARD_VARS][48];
    char val[BOARD_VARS][512];
} board;

static const char *board_get(const board *b, const char *key)
{
    for (int i = b->n - 1; i >= 0; i--)
        if (strcmp(b->key[i], key) == 0) return b->val[i];
    return NULL;
}

static long board_long(const board *b, const char *key, long dflt)
{
    const char *v = board_get(b, key);
    char *end;
    if (!v || !*v) return dflt;
    long r = strtol(v, &end, 10);
    return *end ? dflt : r;
}

/* $(NAME) replaced by earlier variables (and BOARD); other text kept. */
static void expand(const board *b, const char *in, char *out, size_t n)
{
    size_t k = 0;
    while (*in && k + 1 < n) {
        const char *close;
        if (in[0] == '$' && in[1] == '(' && (close = strchr(in, ')'))) {
            char name[48];
            size_t len = (size_t)(close - in - 2);
            if (len < sizeof name) {
                memcpy(name, in + 2, len);
                name[len] = 0;
                const char *v = strcmp(name, "BOARD") == 0 ? b->name : board_get(b, name);
                for (; v && *v && k + 1 < n; v++) out[k++] = *v;
                in = close + 1;
                continue;
            }
        }
        out[k++] = *in++;
    }
    out[k] = 0;
}

static char *trim(char *s)
{
    while (isspace((unsigned char)*s)) s++;
    size_t n = strlen(s);
    while (n && isspace((unsigned char)s[n - 1])) s[--n] = 0;
    return s;
}

/* The simple assignments of a board.mk: NAME := / ?= / = value, with
 * backslash continuations; conditionals and rules are not read. */
static int board_load(board *b, const char *name)
{
    memset(b, 0, sizeof *b);
    snprintf(b->name, sizeof b->name, "%s", name);
    char path[256];
    snprintf(path, sizeof path, "boards/%s/board.mk", name);
    FILE *f = fopen(path, "r");
    if (!f) return cli_fail(CLI_EXIT_USAGE, "profile: %s: %s (run from the silk source tree; boards are the "
                                            "directories of boards/)", path, strerror(errno));
    char line[2048], part[512];
    line[0] = 0;
    while (fgets(part, sizeof part, f)) {
        char *hash = strchr(part, '#');
        if (hash) *hash = 0;
        char *p = trim(part);
        size_t len = strlen(p);
        int more = len && p[len - 1] == '\\';
        if (more) p[len - 1] = 0;
        if (strlen(line) + strlen(p) + 2 < sizeof line) {
            strcat(line, " ");
            strcat(line, p);
        }
        if (more) continue;
        char *op = strstr(line, "=");
        if (op && op > line && b->n < BOARD_VARS) {
            char *key_end = op;
            if (op[-1] == ':' || op[-1] == '?' || op[-1] == '+') key_end--;
            *key_end = 0;
            char *key = trim(line), *val = trim(op + 1);
            int ok = *key && strlen(key) < sizeof b->key[0];
            for (char *c = key; *c; c++)
                if (!isalnum((unsigned char)*c) && *c != '_' && *c != '.') ok = 0;
            if (ok) {
                snprintf(b->key[b->n], sizeof b->key[0], "%s", key);
                expand(b, val, b->val[b->n], sizeof b->val[0]);
                b->n++;
            }
        }
        line[0] = 0;
    }
    fclose(f);
    return 0;
}

/* ---- the report ------------------------------------------------------------- */

typedef struct report {
    FILE *csv;
    const char *board, *mesh;
} report;

static void row(report *r, const char *area, const char *item, size_t bytes, const char *note)
{
    printf("  %-34s %9zu  %s\n", item, bytes, note ? note : "");
    if (r->csv) fprintf(r->csv, "%s,%s,%zu\n", area, item, bytes);
}

static void heading(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static void heading(const char *fmt, ...)
{
    va_list ap;
    putchar('\n');
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
}

/* The model name make uses: the mesh file's base name without extension. */
static void model_name(const char *mesh, char *out, size_t n)
{
    const char *b = strrchr(mesh, '/');
    b = b ? b + 1 : mesh;
    snprintf(out, n, "%s", b);
    char *dot = strrchr(out, '.');
    if (dot && dot != out) *dot = 0;
}

/* Run a shell command, its output (stdout and stderr) into buf. */
static int run(const char *cmd, char *buf, size_t n, size_t *len)
{
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    size_t k = 0, got;
    char tmp[4096];
    while ((got = fread(tmp, 1, sizeof tmp, p)) > 0) {
        size_t c = got < n - 1 - k ? got : n - 1 - k;
        memcpy(buf + k, tmp, c);
        k += c;
    }
    buf[k] = 0;
    if (len) *len = k;
    int st = pclose(p);
    return st;
}

/* A value "key=N" on a report line. */
static long field(const char *line, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, " %s=", key);
    const char *p = strstr(line, pat);
    return p ? strtol(p + strlen(pat), NULL, 10) : -1;
}

/* Shell words are passed in single quotes; refuse the one character that
 * cannot be. */
static int quotable(const char *s)
{
    return strchr(s, '\'') == NULL;
}

/* ---- the map file -------------------------------------------------------------- */

enum { SEC_TEXT, SEC_RODATA, SEC_DATA, SEC_BSS, SEC_NKIND };

#define MAX_MODULES 128

typedef struct module {
    char name[64];
    size_t bytes[SEC_NKIND];
} module;

static const char *const model_kinds[][2] = {
    /* packed array (fwmodel_X) -> kind, as `silk pack` names them */
    { "pos", "positions" },        { "normal", "normals" },        { "normal_vertex", "normals" },
    { "tri_normal", "normals" },   { "uv", "uvs" },                { "tri_uv", "uvs" },
    { "tri", "triangles" },        { "tri_edge", "edges" },        { "edge", "edges" },
    { "vert_edge_start", "vertex edges" }, { "vert_edge", "vertex edges" }, { "edge_feature", "features" },
    { "feature", "features" },     { "vis_node", "visibility" },   { "vis", "visibility" },
    { "cameras", "cameras" },
};
enum { NMODEL_KINDS = sizeof model_kinds / sizeof model_kinds[0] };

typedef struct flash_map {
    module mod[MAX_MODULES];
    int nmod;
    size_t model[NMODEL_KINDS];
    size_t fill;                   /* alignment padding in flash */
} flash_map;

static module *module_get(flash_map *m, const char *name)
{
    for (int i = 0; i < m->nmod; i++)
        if (strcmp(m->mod[i].name, name) == 0) return &m->mod[i];
    if (m->nmod == MAX_MODULES) return &m->mod[MAX_MODULES - 1];
    module *r = &m->mod[m->nmod++];
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%s", name);
    return r;
}

/* "…/libsilk.a(raster.o)" -> "core raster", and so on. */
static void module_of(const char *file, char *out, size_t n)
{
    const char *paren = strchr(file, '(');
    const char *base = strrchr(file, '/');
    base = base ? base + 1 : file;
    char member[64] = "";
    if (paren) {
        snprintf(member, sizeof member, "%s", paren + 1);
        char *e = strchr(member, ')');
        if (e) *e = 0;
        e = strrchr(member, '.');
        if (e) *e = 0;
    }
    if (strstr(file, "libsilk.a(")) snprintf(out, n, "core %s", member);
    else if (strstr(file, "libc_nano.a(") || strstr(file, "libc.a(")) snprintf(out, n, "libc");
    else if (strstr(file, "libgcc.a(")) snprintf(out, n, "libgcc");
    else if (strstr(file, "libnosys.a(")) snprintf(out, n, "libnosys");
    else if (strstr(base, "fw_main")) snprintf(out, n, "scene fw_main");
    else {
        snprintf(out, n, "platform %s", base);
        char *e = strrchr(out, '.');
        if (e) *e = 0;
    }
}

static int model_kind(const char *section)
{
    const char *p = strstr(section, "fwmodel_");
    if (!p || strncmp(section, ".rodata", 7) != 0) return -1;
    p += strlen("fwmodel_");
    for (int k = 0; k < NMODEL_KINDS; k++)
        if (strcmp(p, model_kinds[k][0]) == 0) return k;
    return -1;
}

static void account(flash_map *m, const char *out_sec, const char *in_sec, size_t size, const char *file)
{
    int kind;
    if (strcmp(out_sec, ".bss") == 0) kind = SEC_BSS;
    else if (strcmp(out_sec, ".data") == 0) kind = SEC_DATA;
    else if (strncmp(in_sec, ".text", 5) == 0) kind = SEC_TEXT;
    else kind = SEC_RODATA;   /* .rodata, .vectors, .ARM.exidx */
    int mk = model_kind(in_sec);
    if (mk >= 0) {
        m->model[mk] += size;
        return;
    }
    char name[64];
    module_of(file, name, sizeof name);
    module_get(m, name)->bytes[kind] += size;
}

/* Input sections of the loaded output sections, from GNU ld's -Map. */
static int map_read(const char *path, flash_map *m)
{
    memset(m, 0, sizeof *m);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[1024], out_sec[64] = "", pending[256] = "";
    int in_map = 0;
    while (fgets(line, sizeof line, f)) {
        if (!in_map) {
            in_map = strncmp(line, "Linker script and memory map", 28) == 0;
            continue;
        }
        if (line[0] == '.') {
            sscanf(line, "%63s", out_sec);
            pending[0] = 0;
            continue;
        }
        if (line[0] != ' ') {
            pending[0] = 0;
            continue;
        }
        int wanted = strcmp(out_sec, ".text") == 0 || strcmp(out_sec, ".ARM.exidx") == 0 ||
                     strcmp(out_sec, ".data") == 0 || strcmp(out_sec, ".bss") == 0;
        char a[256], b[64], c[64], d[512];
        int nt = sscanf(line, "%255s %63s %63s %511s", a, b, c, d);
        if (nt >= 1 && strcmp(a, "*fill*") == 0) {
            if (nt >= 3 && wanted && strcmp(out_sec, ".bss") != 0) m->fill += strtoul(c, NULL, 16);
            continue;
        }
        if (nt == 1 && a[0] == '.') {           /* long name: the rest is on the next line */
            snprintf(pending, sizeof pending, "%s", a);
            continue;
        }
        if (pending[0] && nt == 3 && strncmp(a, "0x", 2) == 0 && strncmp(b, "0x", 2) == 0) {
            if (wanted) account(m, out_sec, pending, strtoul(b, NULL, 16), c);
            pending[0] = 0;
            continue;
        }
        pending[0] = 0;
        if (nt == 4 && a[0] == '.' && strncmp(b, "0x", 2) == 0 && strncmp(c, "0x", 2) == 0 && wanted)
            account(m, out_sec, a, strtoul(c, NULL, 16), d);
    }
    fclose(f);
    return in_map ? 0 : -1;
}

static int cmp_module(const void *x, const void *y)
{
    const module *p = x, *q = y;
    return strcmp(p->name, q->name);
}

/* ---- a firmware board ---------------------------------------------------------- */

typedef struct fw_figures {
    long frames, fell_back, smooth_fell_back;
    long arena_size, arena_peak, band_buffers;
    long purpose_peak[SILK_MEM_COUNT];
    long stack_size, stack_used, static_other, data, bss;
    long ram_total, ram_budget;
    int ok;
} fw_figures;

static void parse_fw_report(const char *text, fw_figures *f)
{
    memset(f, 0, sizeof *f);
    for (int p = 0; p < SILK_MEM_COUNT; p++) f->purpose_peak[p] = -1;
    const char *line = text;
    while (line && *line) {
        const char *nl = strchr(line, '\n');
        char buf[512];
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        if (len >= sizeof buf) len = sizeof buf - 1;
        memcpy(buf, line, len);
        buf[len] = 0;
        if (strncmp(buf, "fw frame=", 9) == 0) {
            f->frames++;
            if (field(buf, "fell_back") == 1) {
                f->fell_back++;
                if (strstr(buf, " mode=smooth ")) f->smooth_fell_back++;
            }
        } else if (strncmp(buf, "fw arena size=", 14) == 0) {
            f->arena_size = field(buf, "size");
            f->arena_peak = field(buf, "peak");
            f->band_buffers = field(buf, "band_buffers");
        } else if (strncmp(buf, "fw arena_purpose ", 17) == 0) {
            const char *nm = strstr(buf, " name=");
            for (int p = 0; nm && p < SILK_MEM_COUNT; p++) {
                const char *pn = silk_purpose_name((silk_purpose)p);
                size_t k = strlen(pn);
                if (strncmp(nm + 6, pn, k) == 0 && nm[6 + k] == ' ') f->purpose_peak[p] = field(buf, "peak");
            }
        } else if (strncmp(buf, "fw stack ", 9) == 0) {
            f->stack_size = field(buf, "size");
            f->stack_used = field(buf, "used");
        } else if (strncmp(buf, "fw static ", 10) == 0) {
            f->data = field(buf, "data");
            f->bss = field(buf, "bss");
            f->static_other = field(buf, "other");
        } else if (strncmp(buf, "fw ram ", 7) == 0) {
            f->ram_total = field(buf, "total");
            f->ram_budget = field(buf, "budget");
        } else if (strcmp(buf, "fw result=ok") == 0) {
            f->ok = 1;
        }
        line = nl ? nl + 1 : NULL;
    }
}

/* .text of the whole core library for the board, linked or not. */
static size_t lib_total_text(const board *b, const char *bdir)
{
    const char *cross = board_get(b, "BOARD_CROSS");
    char cmd[1024];
    static char out[1 << 15];
    snprintf(cmd, sizeof cmd, "%ssize -t '%s/fw/libsilk.a' 2>/dev/null", cross ? cross : "", bdir);
    if (run(cmd, out, sizeof out, NULL) != 0) return 0;
    const char *tot = strstr(out, "(TOTALS)");
    if (!tot) return 0;
    while (tot > out && tot[-1] != '\n') tot--;
    return strtoul(tot, NULL, 10);
}

static int profile_firmware(const board *b, const char *mesh, int build, const char *csv_path, int check)
{
    const char *bdir = board_get(b, "BUILD");
    const char *runcmd = board_get(b, "BOARD_RUN");
    char name[128], dir[512], cmd[2048];
    model_name(mesh, name, sizeof name);
    if (!bdir || !runcmd) return cli_fail(CLI_EXIT_USAGE, "profile: boards/%s/board.mk sets no BUILD or BOARD_RUN", b->name);
    if (!quotable(mesh)) return cli_fail(CLI_EXIT_USAGE, "profile: the mesh path may not contain a quote");
    snprintf(dir, sizeof dir, "%s/fw/%s", bdir, name);

    static char out[1 << 16];
    if (build) {
        snprintf(cmd, sizeof cmd, "make -s BOARD='%s' BOARD_MESHES='%s' firmware 2>&1", b->name, mesh);
        if (run(cmd, out, sizeof out, NULL) != 0) {
            fputs(out, stderr);
            return cli_fail(CLI_EXIT_INPUT, "profile: building the firmware failed (%s)", cmd);
        }
    }
    snprintf(cmd, sizeof cmd, "timeout 300 %s '%s/fw.elf' -append '%s/frame' 2>&1", runcmd, dir, dir);
    int st = run(cmd, out, sizeof out, NULL);
    char rpath[600];
    snprintf(rpath, sizeof rpath, "%s/report.txt", dir);
    FILE *rf = fopen(rpath, "w");
    if (rf) {
        fputs(out, rf);
        fclose(rf);
    }
    fw_figures fw;
    parse_fw_report(out, &fw);
    if (st != 0 || !fw.ok) {
        fputs(out, stderr);
        return cli_fail(CLI_EXIT_INPUT, "profile: the firmware did not run to the end (%s)", cmd);
    }
    flash_map fm;
    char mpath[600];
    snprintf(mpath, sizeof mpath, "%s/fw.map", dir);
    if (map_read(mpath, &fm) != 0) return cli_fail(CLI_EXIT_INPUT, "profile: cannot read the map file %s", mpath);
    qsort(fm.mod, (size_t)fm.nmod, sizeof fm.mod[0], cmp_module);

    report r = { NULL, b->name, mesh };
    if (csv_path && !(r.csv = fopen(csv_path, "w")))
        return cli_fail(CLI_EXIT_INPUT, "profile: %s: %s", csv_path, strerror(errno));
    if (r.csv) fprintf(r.csv, "area,item,bytes\n");

    long flash_budget = board_long(b, "BOARD_FLASH_BYTES", 0);
    printf("silk profile: %s on %s (%s)\n", mesh, b->name, dir);
    printf("frame %sx%s, bands of %ld rows; %ld frames rendered (flat and smooth from %ld views)\n",
           board_get(b, "BOARD_WIDTH") ? board_get(b, "BOARD_WIDTH") : "?",
           board_get(b, "BOARD_HEIGHT") ? board_get(b, "BOARD_HEIGHT") : "?", board_long(b, "BOARD_BAND_ROWS", 0),
           fw.frames, fw.frames / 2);

    heading("FLASH (bytes; from %s)", mpath);
    size_t core_text = 0, core_ro = 0, code = 0, model = 0, data_init = 0;
    for (int i = 0; i < fm.nmod; i++) {
        const module *md = &fm.mod[i];
        size_t t = md->bytes[SEC_TEXT], ro = md->bytes[SEC_RODATA], d = md->bytes[SEC_DATA];
        if (!t && !ro && !d) continue;
        char note[96];
        snprintf(note, sizeof note, "code %zu, constants %zu%s", t, ro, d ? ", .data image" : "");
        row(&r, "flash", md->name, t + ro + d, note);
        if (strncmp(md->name, "core ", 5) == 0) {
            core_text += t;
            core_ro += ro;
        }
        code += t + ro;
        data_init += d;
    }
    row(&r, "flash", "alignment padding", fm.fill, NULL);
    code += fm.fill + data_init;
    printf("  model (silk pack):\n");
    const char *last = "";
    for (int k = 0; k < NMODEL_KINDS; k++) {
        model += fm.model[k];
        if (strcmp(model_kinds[k][1], last) == 0) continue;
        last = model_kinds[k][1];
        size_t sum = 0;
        for (int j = k; j < NMODEL_KINDS; j++)
            if (strcmp(model_kinds[j][1], last) == 0) sum += fm.model[j];
        char item[64];
        snprintf(item, sizeof item, "model %s", last);
        if (sum) row(&r, "flash", item, sum, NULL);
    }
    printf("  %-34s %9zu  (limit 48 KiB = 49152: %s)\n", "core code (.text of libsilk)", core_text,
           core_text <= 49152 ? "ok" : "OVER");
    printf("  %-34s %9zu\n", "core constants (.rodata)", core_ro);
    size_t lib_text = lib_total_text(b, bdir);
    if (lib_text)
        printf("  %-34s %9zu  (every module, loaders too: `size` of fw/libsilk.a)\n", "core library .text", lib_text);
    row(&r, "flash", "code total", code, "everything but the model");
    row(&r, "flash", "model total", model, NULL);
    char note[96];
    snprintf(note, sizeof note, "of %ld (%s)", flash_budget, code + model <= (size_t)flash_budget ? "fits" : "OVER");
    row(&r, "flash", "flash total", code + model, flash_budget ? note : NULL);

    heading("RAM (bytes; measured by the firmware under %s)", strtok(strcpy(cmd, runcmd), " "));
    row(&r, "ram", "static .data", (size_t)fw.data, "libc state");
    row(&r, "ram", "static .bss besides the arena", (size_t)(fw.bss - fw.arena_size), NULL);
    snprintf(note, sizeof note, "high-water of %ld reserved", fw.arena_size);
    row(&r, "ram", "arena", (size_t)fw.arena_peak, note);
    for (int p = 0; p < SILK_MEM_COUNT; p++) {
        if (fw.purpose_peak[p] <= 0) continue;
        char item[64];
        snprintf(item, sizeof item, "  arena %s", silk_purpose_name((silk_purpose)p));
        row(&r, "ram", item, (size_t)fw.purpose_peak[p],
            p == SILK_MEM_RASTER ? "band buffers: colour + depth" : p == SILK_MEM_FRAME ? "per-frame scratch, peak" : NULL);
    }
    snprintf(note, sizeof note, "painted high-water of %ld reserved", fw.stack_size);
    row(&r, "ram", "stack", (size_t)fw.stack_used, note);
    snprintf(note, sizeof note, "of %ld budget (%s)", fw.ram_budget, fw.ram_total <= fw.ram_budget ? "fits" : "OVER");
    row(&r, "ram", "ram total", (size_t)fw.ram_total, note);
    if (fw.fell_back)
        printf("\n  %ld of %ld frames fell back (%ld smooth): the arena could not hold their per-frame\n"
               "  scratch, so part or all of the frame was drawn unsmoothed; see docs/small-devices.md.\n",
               fw.fell_back, fw.frames, fw.smooth_fell_back);
    if (r.csv) {
        fprintf(r.csv, "frames,fell_back,%ld\n", fw.fell_back);
        if (fclose(r.csv) != 0) return cli_fail(CLI_EXIT_INPUT, "profile: %s: write failed", csv_path);
        printf("\ncsv: %s\n", csv_path);
    }
    printf("footprint %s %s ram_total_bytes=%ld code_bytes=%zu model_bytes=%zu\n", b->name, name, fw.ram_total, code,
           model);
    if (check && (fw.fell_back || fw.ram_total > fw.ram_budget || core_text > 49152))
        return cli_fail(CLI_EXIT_INPUT, "profile: %s does not meet its budget (%ld frames fell back)", b->name,
                        fw.fell_back);
    return 0;
}

/* ---- a host board: measured in-process ---------------------------------------------- */

static int band_none(void *user, const silk_target *t)
{
    (void)user;
    (void)t;
    return 0;
}

/* `size` of the core's objects in the board's build: .text by module. */
static size_t host_core_text(const board *b, report *r)
{
    const char *bdir = board_get(b, "BUILD");
    const char *cross = board_get(b, "BOARD_CROSS");
    char cmd[1024];
    static char out[1 << 15];
    snprintf(cmd, sizeof cmd, "%ssize %s/obj/src/*.o 2>/dev/null", cross ? cross : "", bdir ? bdir : "build");
    if (run(cmd, out, sizeof out, NULL) != 0) return 0;
    size_t total = 0;
    for (char *line = strtok(out, "\n"); line; line = strtok(NULL, "\n")) {
        unsigned long text, data, bss;
        char file[512];
        if (sscanf(line, "%lu %lu %lu %*s %*s %511s", &text, &data, &bss, file) != 4) continue;
        char item[96], *base = strrchr(file, '/');
        snprintf(item, sizeof item, "core %.80s", base ? base + 1 : file);
        char *dot = strrchr(item, '.');
        if (dot) *dot = 0;
        row(r, "code", item, text, NULL);
        total += text;
    }
    return total;
}

static int profile_host(const board *b, const char *mesh, const char *csv_path, int check)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    o.mesh_path = mesh;
    o.width = (int)board_long(b, "BOARD_WIDTH", o.width);
    o.height = (int)board_long(b, "BOARD_HEIGHT", o.height);
    const char *fmt = board_get(b, "BOARD_FORMAT");
    if (fmt) o.fmt = strcmp(fmt, "SILK_PIX_RGB565") == 0 ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
    int rows = (int)board_long(b, "BOARD_BAND_ROWS", o.height);
    if (rows < 1 || rows > o.height) rows = o.height;
    int views = (int)board_long(b, "BOARD_VIEWS", 3);
    if (views < 1 || views > 16) views = 3;

    cli_scene s;
    int rc = cli_scene_load(&s, &o);
    if (rc) {
        cli_scene_free(&s);
        return rc;
    }
    /* The tool's full-frame target is not what the board uses: bands are. */
    size_t bpp = silk_pixfmt_bytes(o.fmt), band_bytes = (size_t)rows * (size_t)o.width * (bpp + sizeof(uint32_t));
    /* On a host the band buffers come from the heap, so the arena's sizing
     * stays the tool's; they are counted as the board would hold them. */
    uint8_t *color = malloc((size_t)rows * o.width * bpp);
    uint32_t *depth = malloc((size_t)rows * o.width * sizeof *depth);
    if (!color || !depth) {
        free(color);
        free(depth);
        cli_scene_free(&s);
        return cli_fail(CLI_EXIT_INPUT, "profile: out of memory for the band buffers");
    }
    silk_target band;
    silk_target_init(&band, o.width, o.height, 0, rows, o.fmt, color, depth);
    silk_sink sink = { band_none, NULL };
    silk_camera c0;
    rc = cli_camera(&o, &s.mesh, &c0);
    size_t frame_peak = 0;
    long fell = 0;
    /* Frame scratch is measured from here; the load-time peaks are kept apart. */
    size_t load_peak[SILK_MEM_COUNT];
    memcpy(load_peak, s.arena.peak_used, sizeof load_peak);
    for (int k = 0; !rc && k < views; k++) {
        double a = 2 * CLI_PI * k / views;
        double t[3] = { cli_fx_to_double(c0.target.x), cli_fx_to_double(c0.target.y), cli_fx_to_double(c0.target.z) };
        double d[3] = { cli_fx_to_double(c0.eye.x) - t[0], cli_fx_to_double(c0.eye.y) - t[1],
                        cli_fx_to_double(c0.eye.z) - t[2] };
        o.eye[0] = t[0] + d[0] * cos(a) + d[2] * sin(a);
        o.eye[1] = t[1] + (k % 2 ? -d[1] : d[1]);
        o.eye[2] = t[2] - d[0] * sin(a) + d[2] * cos(a);
        o.have_eye = 1;
        silk_camera cam;
        silk_view view;
        silk_error err;
        if ((rc = cli_camera(&o, &s.mesh, &cam)) != 0) break;
        if (silk_view_init(&view, &cam, &err) != SILK_OK) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
            break;
        }
        silk_phong_default(&s.phong, &view);
        silk_hal_phong(&s.hal, &s.phong);
        for (int mode = 0; mode < 2 && !rc; mode++) {
            silk_render_opts ro = o.render;
            ro.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
            silk_frame_stats fs;
            if (silk_render_bands(&s.arena, &s.mesh, &view, &s.hal, &ro, &band, &sink, &fs, &err) != SILK_OK)
                rc = cli_fail(CLI_EXIT_INPUT, "%s: %s", mesh, err.msg);
            if (fs.frame_bytes > frame_peak) frame_peak = fs.frame_bytes;
            fell += fs.fell_back;
        }
    }
    free(color);
    free(depth);
    if (rc) {
        cli_scene_free(&s);
        return rc;
    }
    report r = { NULL, b->name, mesh };
    if (csv_path && !(r.csv = fopen(csv_path, "w"))) {
        cli_scene_free(&s);
        return cli_fail(CLI_EXIT_INPUT, "profile: %s: %s", csv_path, strerror(errno));
    }
    if (r.csv) fprintf(r.csv, "area,item,bytes\n");
    printf("silk profile: %s on %s (measured in this process)\n", mesh, b->name);
    printf("frame %dx%d, bands of %d rows; %d frames rendered (flat and smooth from %d views)\n", o.width, o.height,
           rows, 2 * views, views);
    heading("CODE (bytes; `size` of the core's objects in %s)", board_get(b, "BUILD") ? board_get(b, "BUILD") : "build");
    size_t code = host_core_text(b, &r);
    row(&r, "code", "core code total", code, code ? NULL : "(objects not found: build the board first)");

    heading("MESH (bytes; loaded into the arena: a host has no flash)");
    silk_mesh_bytes mb;
    silk_mesh_bytes_used(&s.mesh, &mb);
    size_t vis = silk_vis_bytes(s.mesh.vis);
    row(&r, "model", "model positions", mb.positions, NULL);
    row(&r, "model", "model normals", mb.normals, NULL);
    if (mb.uvs) row(&r, "model", "model uvs", mb.uvs, NULL);
    row(&r, "model", "model triangles", mb.triangles, NULL);
    row(&r, "model", "model edges", mb.edges, NULL);
    row(&r, "model", "model vertex edges", mb.vertex_edges, NULL);
    row(&r, "model", "model features", mb.features, NULL);
    row(&r, "model", "model visibility", vis, NULL);
    size_t model = mb.total + vis;
    row(&r, "model", "model total", model, NULL);

    heading("RAM (bytes; arena high-water marks by purpose)");
    size_t load_only = 0;
    for (int p = 0; p < SILK_MEM_COUNT; p++) {
        size_t v = p == SILK_MEM_RASTER ? band_bytes : p == SILK_MEM_FRAME ? frame_peak : load_peak[p];
        if (!v) continue;
        char item[64];
        snprintf(item, sizeof item, p == SILK_MEM_RASTER ? "band buffers" : "arena %s",
                 silk_purpose_name((silk_purpose)p));
        row(&r, "ram", item, v,
            p == SILK_MEM_RASTER ? "colour + depth"
            : p == SILK_MEM_FRAME ? "per-frame scratch, peak"
            : p == SILK_MEM_LOAD  ? "while loading only"
                                  : NULL);
        if (p == SILK_MEM_LOAD) load_only = v;
    }
    /* Loading scratch is released before the first frame. */
    size_t persistent = s.load_bytes;
    size_t total = persistent + band_bytes + frame_peak;
    if (load_only > band_bytes + frame_peak) total = persistent + load_only;
    row(&r, "ram", "stack", 0, "not measured on a host");
    row(&r, "ram", "ram total", total, "mesh + band buffers + frame peak");
    if (fell) printf("\n  %ld frames fell back (the arena ran out)\n", fell);
    if (r.csv) {
        fprintf(r.csv, "frames,fell_back,%ld\n", fell);
        if (fclose(r.csv) != 0) {
            cli_scene_free(&s);
            return cli_fail(CLI_EXIT_INPUT, "profile: %s: write failed", csv_path);
        }
        printf("\ncsv: %s\n", csv_path);
    }
    char name[128];
    model_name(mesh, name, sizeof name);
    printf("footprint %s %s ram_total_bytes=%zu code_bytes=%zu model_bytes=%zu\n", b->name, name, total, code, model);
    cli_scene_free(&s);
    if (check && fell) return cli_fail(CLI_EXIT_INPUT, "profile: %ld frames fell back", fell);
    return 0;
}

/* ---- the command ----------------------------------------------------------------- */

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk profile MESH [--board NAME] [--csv FILE] [--no-build] [--check]\n"
            "\n"
            "Where every byte goes when board NAME (boards/NAME/board.mk) renders MESH:\n"
            "flash (code by module, the packed model by kind) and RAM (static data, the\n"
            "arena by purpose with high-water marks, band buffers, stack high-water), as\n"
            "a table, a CSV file and a last line\n"
            "  footprint BOARD MESH ram_total_bytes=N code_bytes=N model_bytes=N\n"
            "A firmware board (mps2-an385) is built for MESH and run under QEMU, and\n"
            "measures itself; a host board (host, linux-fb) is measured in this process.\n"
            "Run it from the silk source tree.\n"
            "\n"
            "  --board NAME         the board (default mps2-an385)\n"
            "  --csv FILE           where the CSV goes (default: BUILD/profile-MESH.csv)\n"
            "  --no-build           use the firmware already built\n"
            "  --check              exit 1 when the board's budget is not met (a frame fell\n"
            "                       back, RAM over budget, core code over 48 KiB)\n"
            "\n"
            "examples:\n"
            "  silk profile ../shared/meshes/bunny-500.obj --board mps2-an385\n"
            "  make profile PROFILE_MESH=../shared/meshes/knot-480.obj\n");
}

int cmd_profile(int argc, char **argv)
{
    const char *mesh = NULL, *board_name = "mps2-an385", *csv = NULL;
    int build = 1, check = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        }
        if (cli_is(a, "--board")) {
            if (!(board_name = cli_value(argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (cli_is(a, "--csv")) {
            if (!(csv = cli_value(argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(a, "--no-build") == 0) {
            build = 0;
        } else if (strcmp(a, "--check") == 0) {
            check = 1;
        } else if (cli_mesh_arg("profile", a, &mesh)) {
            return CLI_EXIT_USAGE;
        }
    }
    if (!mesh) return cli_fail(CLI_EXIT_USAGE, "profile: no mesh given (silk profile MESH --board NAME)");
    for (const char *c = board_name; *c; c++)
        if (!isalnum((unsigned char)*c) && *c != '-' && *c != '_')
            return cli_fail(CLI_EXIT_USAGE, "profile: bad board name \"%s\"", board_name);
    FILE *mf = fopen(mesh, "rb");
    if (!mf) return cli_fail(CLI_EXIT_INPUT, "%s: cannot open: %s", mesh, strerror(errno));
    fclose(mf);
    board b;
    int rc = board_load(&b, board_name);
    if (rc) return rc;
    char name[128], csv_default[768];
    model_name(mesh, name, sizeof name);
    const char *bdir = board_get(&b, "BUILD");
    snprintf(csv_default, sizeof csv_default, "%s/profile-%s.csv", bdir ? bdir : "build", name);
    if (!csv) csv = csv_default;
    if (board_get(&b, "BOARD_RULES")) return profile_firmware(&b, mesh, build, csv, check);
    return profile_host(&b, mesh, csv, check);
}
