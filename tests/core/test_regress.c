/*
 * test_regress.c - every input the fuzz harnesses ever found a problem
 * with (tests/regress/HARNESS/, see tests/regress/README.md), run again
 * through the same harness code, plus the malformed-input corpus
 * tests/bad/ through the OBJ, PLY, STL, prepared-model and compact-model
 * harnesses.
 *
 * The harnesses (fuzz/fuzz_*.c) are compiled in here without libFuzzer,
 * each under its own entry name; their checks abort with a "fuzz: ..."
 * line on a wrong answer, so a regression shows up as a crash of this
 * program (under `make test`'s sanitizer run too) with the file named
 * just before it.  Run from the repository root (tests/run.sh does).
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <string.h>
#include "check.h"

#define FUZZ_ENTRY fuzz_obj_entry
#include "fuzz/fuzz_obj.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_ply_entry
#include "fuzz/fuzz_ply.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_stl_entry
#include "fuzz/fuzz_stl.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_pack_entry
#include "fuzz/fuzz_pack.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_render_entry
#include "fuzz/fuzz_render.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_math_entry
#include "fuzz/fuzz_math.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_ppm_entry
#include "fuzz/fuzz_ppm.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_model_entry
#include "fuzz/fuzz_model.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_siltex_entry
#include "fuzz/fuzz_siltex.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_compact_entry
#include "fuzz/fuzz_compact.c"
#undef FUZZ_ENTRY

typedef int (*entry_fn)(const uint8_t *data, size_t size);

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int has_suffix(const char *s, const char *suf)
{
    size_t n = strlen(s), k = strlen(suf);
    return n >= k && strcmp(s + n - k, suf) == 0;
}

/* Runs every file of dir whose name ends in suffix ("" for all but the
 * .expected and README files) through fn; returns how many ran. */
static int run_dir(const char *dir, const char *suffix, entry_fn fn)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    char *names[1024];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 1024) {
        if (e->d_name[0] == '.' || has_suffix(e->d_name, ".expected") || has_suffix(e->d_name, ".md")) continue;
        if (*suffix && !has_suffix(e->d_name, suffix)) continue;
        names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmp_names);
    int ran = 0;
    for (int i = 0; i < n; i++) {
        char path[1200];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        free(names[i]);
        FILE *f = fopen(path, "rb");
        CHECKF(f != NULL, "cannot open %s", path);
        if (!f) continue;
        fseek(f, 0, SEEK_END);
        long len = ftell(f);
        fseek(f, 0, SEEK_SET);
        /* exactly len bytes on the heap, as libFuzzer hands them over */
        uint8_t *buf = malloc(len > 0 ? (size_t)len : 1);
        size_t got = len > 0 ? fread(buf, 1, (size_t)len, f) : 0;
        fclose(f);
        CHECKF(len >= 0 && got == (size_t)len, "cannot read %s", path);
        fprintf(stderr, "  %s\n", path);    /* names the input if the harness aborts */
        CHECKF(fn(buf, got) == 0, "%s", path);
        free(buf);
        ran++;
    }
    return ran;
}

TEST(regress_obj)
{
    int n = run_dir("tests/regress/obj", "", fuzz_obj_entry);
    int bad = run_dir("tests/bad", ".obj", fuzz_obj_entry);
    CHECKF(bad >= 10, "only %d OBJ files in tests/bad (run from the repository root)", bad);
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

TEST(regress_ply)
{
    int n = run_dir("tests/regress/ply", "", fuzz_ply_entry);
    int bad = run_dir("tests/bad", ".ply", fuzz_ply_entry);
    CHECKF(bad >= 10, "only %d PLY files in tests/bad", bad);
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

TEST(regress_stl)
{
    int n = run_dir("tests/regress/stl", "", fuzz_stl_entry);
    int bad = run_dir("tests/bad", ".stl", fuzz_stl_entry);
    CHECKF(bad >= 10, "only %d STL files in tests/bad", bad);
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

TEST(regress_pack)
{
    int n = run_dir("tests/regress/pack", "", fuzz_pack_entry);
    CHECKF(n >= 1, "no inputs in tests/regress/pack");
    printf("  %d regression inputs\n", n);
}

TEST(regress_render)
{
    int n = run_dir("tests/regress/render", "", fuzz_render_entry);
    CHECKF(n >= 1, "no inputs in tests/regress/render");
    printf("  %d regression inputs\n", n);
}

TEST(regress_math)
{
    int n = run_dir("tests/regress/math", "", fuzz_math_entry);
    CHECKF(n >= 1, "no inputs in tests/regress/math");
    printf("  %d regression inputs\n", n);
}

TEST(regress_ppm)
{
    int n = run_dir("tests/regress/ppm", "", fuzz_ppm_entry);
    CHECKF(n >= 5, "%d inputs", n);
}

TEST(regress_model)
{
    int n = run_dir("tests/regress/model", "", fuzz_model_entry);
    int bad = run_dir("tests/bad", ".silk", fuzz_model_entry);
    CHECKF(bad >= 10, "only %d prepared models in tests/bad", bad);
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

TEST(regress_siltex)
{
    int n = run_dir("tests/regress/siltex", "", fuzz_siltex_entry);
    int bad = run_dir("tests/bad", ".silk", fuzz_siltex_entry);
    CHECKF(n >= 1, "no inputs in tests/regress/siltex");
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

TEST(regress_compact)
{
    int n = run_dir("tests/regress/compact", "", fuzz_compact_entry);
    int bad = run_dir("tests/bad", ".slkc", fuzz_compact_entry);
    CHECKF(n >= 1, "no inputs in tests/regress/compact");
    CHECKF(bad >= 10, "only %d compact models in tests/bad", bad);
    printf("  %d regression inputs, %d malformed files\n", n, bad);
}

int main(void)
{
    RUN(regress_obj);
    RUN(regress_ply);
    RUN(regress_stl);
    RUN(regress_pack);
    RUN(regress_render);
    RUN(regress_math);
    RUN(regress_ppm);
    RUN(regress_model);
    RUN(regress_siltex);
    RUN(regress_compact);
    return check_done();
}
