/*
 * check.h - the test harness: every test_*.c under tests/ is its own program.
 *
 *   TEST(name) { CHECK(x == 1); CHECKF(err < 2, "err %g", err); }
 *   int main(void) { RUN(name); return check_done(); }
 *
 * A test passes when none of its checks fail.  check_done() prints
 * "N passed, N failed" for this program; tests/run.sh adds them up.
 *
 * A test that asks for the shared reference meshes (check_meshes_dir())
 * where there are none is skipped: its checks no longer count, and
 * check_done() names the skipped tests on one line.  So is a test of what
 * the core was built without (check_built(SILK_LINES, "SILK_LINES"), an
 * option of silk/config.h: `make test` builds the core's tests in every
 * board's configuration too).
 */
#ifndef SILK_CHECK_H
#define SILK_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int check_tests_passed, check_tests_failed, check_cur_failed, check_cur_skipped, check_tests_skipped;
static int check_tests_unbuilt;
static const char *check_cur_name = "";
static char check_skipped_names[512], check_unbuilt_names[512];

#define TEST(name) static void name(void)

#define CHECKF(cond, ...)                                                          \
    do {                                                                           \
        if (!(cond) && !check_cur_skipped) {                                       \
            check_cur_failed++;                                                    \
            fprintf(stderr, "FAIL %s (%s:%d): %s: ", check_cur_name, __FILE__,     \
                    __LINE__, #cond);                                              \
            fprintf(stderr, __VA_ARGS__);                                          \
            fputc('\n', stderr);                                                   \
        }                                                                          \
    } while (0)

#define CHECK(cond) CHECKF(cond, "%s", "")

#define RUN(name)                                                                  \
    do {                                                                           \
        check_cur_name = #name;                                                    \
        check_cur_failed = 0;                                                      \
        check_cur_skipped = 0;                                                     \
        name();                                                                    \
        if (check_cur_skipped) check_note_skipped(#name, check_cur_skipped);       \
        else if (check_cur_failed) { check_tests_failed++; printf("not ok %s\n", #name); } \
        else { check_tests_passed++; printf("ok %s\n", #name); }                   \
        fflush(stdout);                                                            \
    } while (0)

/* Path of the shared reference meshes (../shared/meshes by default, or
 * $SILK_MESHES).  Where it does not exist, the current test is skipped. */
static inline const char *check_meshes_dir(void)
{
    const char *d = getenv("SILK_MESHES");
    struct stat st;
    if (!d) d = "../shared/meshes";
    if (stat(d, &st) != 0 || !S_ISDIR(st.st_mode)) check_cur_skipped = 1;
    return d;
}

/* Whether the core was built with option (silk/config.h's value, named
 * what): where not, the current test is skipped (1: it may go on, and
 * nothing it checks counts; best to return). */
static inline int check_built(int option, const char *what)
{
    if (option) return 1;
    if (!check_cur_skipped) {
        size_t n = strlen(check_unbuilt_names);
        if (n + strlen(check_cur_name) + strlen(what) + 6 < sizeof check_unbuilt_names)
            snprintf(check_unbuilt_names + n, sizeof check_unbuilt_names - n, "%s%s (%s)", n ? ", " : "",
                     check_cur_name, what);
    }
    check_cur_skipped = 2;
    return 0;
}

/* At the top of main(): a program whose every test needs option (a mode
 * silk/config.h may leave out) runs none where the core is built without
 * it, and says so. */
#define CHECK_PROGRAM_NEEDS(option)                                                           \
    do {                                                                                      \
        if (!(option)) {                                                                      \
            printf("skip: the core is built without %s, which every test here needs\n", #option); \
            return check_done();                                                              \
        }                                                                                     \
    } while (0)

static inline void check_note_skipped(const char *name, int why)
{
    size_t n = strlen(check_skipped_names);
    if (why == 2) {
        check_tests_unbuilt++;
        return;
    }
    check_tests_skipped++;
    if (n + strlen(name) + 3 < sizeof check_skipped_names)
        snprintf(check_skipped_names + n, sizeof check_skipped_names - n, "%s%s", n ? ", " : "", name);
}

static inline int check_done(void)
{
    if (check_tests_unbuilt)
        printf("skip: the core is built without what %d test%s need%s: %s\n", check_tests_unbuilt,
               check_tests_unbuilt == 1 ? "" : "s", check_tests_unbuilt == 1 ? "s" : "", check_unbuilt_names);
    if (check_tests_skipped) {
        const char *d = getenv("SILK_MESHES");
        printf("skip: %s is missing, so %d test%s that read the shared meshes did not run: %s\n",
               d ? d : "../shared/meshes", check_tests_skipped, check_tests_skipped == 1 ? "" : "s",
               check_skipped_names);
    }
    printf("%d passed, %d failed\n", check_tests_passed, check_tests_failed);
    return check_tests_failed ? 1 : 0;
}

/* Deterministic random numbers for property tests (xorshift64*). */
static unsigned long long check_rng_state = 0x9E3779B97F4A7C15ull;
static inline unsigned long long check_rand64(void)
{
    unsigned long long x = check_rng_state;
    x ^= x >> 12; x ^= x << 25; x ^= x >> 27;
    check_rng_state = x;
    return x * 0x2545F4914F6CDD1Dull;
}
/* uniform in [lo, hi) */
static inline double check_uniform(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(check_rand64() >> 11) / 9007199254740992.0);
}


#endif
