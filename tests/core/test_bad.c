/*
 * test_bad.c - the malformed-input corpus in tests/bad/ (OBJ, PLY, STL and
 * files of formats silk does not read), through the library: every file
 * must fail to load with exactly the line its NAME.expected gives (less
 * the CLI's "silk: " prefix), leave the arena as it was, and do so under
 * the sanitizers without reading outside the buffer.
 * tests/cli/cli_bad.sh checks the same files through the `silk` command.
 * Run from the repository root (tests/run.sh does).
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "support/testmesh.h"

#define BAD_DIR "tests/bad"

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

TEST(corpus)
{
    DIR *d = opendir(BAD_DIR);
    CHECKF(d != NULL, "cannot open %s (run from the repository root)", BAD_DIR);
    if (!d) return;
    char *names[512];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 512) {
        /* every case but the script that writes them */
        size_t l = strlen(e->d_name);
        if (e->d_name[0] != '.' && !(l > 9 && !strcmp(e->d_name + l - 9, ".expected")) &&
            !(l > 3 && !strcmp(e->d_name + l - 3, ".py")))
            names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmp_names);

    size_t arena_size = 8u << 20;
    unsigned char *mem = malloc(arena_size);
    int checked = 0, objs = 0, plys = 0, stls = 0, others = 0, unbuilt = 0;
    for (int i = 0; i < n; i++) {
        char path[600], expected_path[640], name[600];
        snprintf(path, sizeof path, "%s/%s", BAD_DIR, names[i]);
        if (!SILK_SILTEX_MODE && !strncmp(names[i], "model-stex-", 11)) {   /* a core without siltex skips STEX */
            unbuilt++;
            free(names[i]);
            continue;
        }
        snprintf(expected_path, sizeof expected_path, "%s.expected", path);
        size_t len, elen;
        char *data = tm_read_file(path, &len);
        char *expected = tm_read_file(expected_path, &elen);
        CHECKF(data && expected, "%s: missing file or .expected", path);
        if (!data || !expected) { free(data); free(expected); continue; }
        /* one line, "silk: " + the message */
        CHECKF(elen > 7 && expected[elen - 1] == '\n' && memchr(expected, '\n', elen - 1) == NULL &&
               !strncmp(expected, "silk: ", 6), "%s: .expected must be one line starting with 'silk: '", path);
        if (elen) expected[elen - 1] = '\0';

        /* exactly len bytes on the heap, so that ASan sees any overread */
        char *exact = malloc(len ? len : 1);
        memcpy(exact, data, len);
        snprintf(name, sizeof name, "%s", path);
        silk_arena a;
        silk_mesh m;
        silk_error err;
        memset(&err, 0, sizeof err);
        silk_arena_init(&a, mem, arena_size);
        silk_status st = silk_load_mesh(exact, len, name, NULL, &a, &m, &err);
        CHECKF(st != SILK_OK, "%s: loaded, but should fail", path);
        CHECKF(strcmp(err.msg, expected + 6) == 0, "%s:\n     got  \"%s\"\n     want \"%s\"", names[i], err.msg,
               expected + 6);
        CHECKF(a.bottom == 0 && a.top == 0, "%s: arena not restored", path);
        checked++;
        size_t nl = strlen(names[i]);
        if (!strcmp(names[i] + nl - 4, ".obj")) objs++;
        else if (!strcmp(names[i] + nl - 4, ".ply")) plys++;
        else if (!strcmp(names[i] + nl - 4, ".stl")) stls++;
        else others++;
        free(exact);
        free(data);
        free(expected);
        free(names[i]);
    }
    free(mem);
    CHECKF(checked >= 40, "only %d malformed files", checked);
    CHECKF(objs >= 10 && plys >= 10 && stls >= 10 && others >= 10, "%d OBJ, %d PLY, %d STL and %d other files",
           objs, plys, stls, others);
    printf("  %d malformed files (%d OBJ, %d PLY, %d STL, %d of other formats)\n", checked, objs, plys, stls, others);
    if (unbuilt) printf("  %d silhouette texture sections left out: the core is built without SILK_SILTEX_MODE\n", unbuilt);
}

/* The corpus is not all: every .expected has its file. */
TEST(no_orphans)
{
    DIR *d = opendir(BAD_DIR);
    if (!d) return;
    struct dirent *e;
    int orphans = 0;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (l > 9 && !strcmp(e->d_name + l - 9, ".expected")) {
            char path[600];
            snprintf(path, sizeof path, "%s/%.*s", BAD_DIR, (int)(l - 9), e->d_name);
            FILE *f = fopen(path, "rb");
            if (!f) { orphans++; fprintf(stderr, "no file for %s\n", e->d_name); }
            else fclose(f);
        }
    }
    closedir(d);
    CHECK(orphans == 0);
}

int main(void)
{
    RUN(corpus);
    RUN(no_orphans);
    return check_done();
}
