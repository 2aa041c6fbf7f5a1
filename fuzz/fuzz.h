/*
 * fuzz.h - what the libFuzzer harnesses in fuzz/ share: the checks that
 * turn a wrong answer (not only a crash) into a finding.
 *
 * A harness calls fuzz_expect() for every property it checks; a failed one
 * prints what went wrong and aborts, which libFuzzer reports as a crash and
 * saves the input.  Harnesses run on the host and may use malloc; the core
 * they drive gets its memory from an arena as always.
 */
#ifndef SILK_FUZZ_H
#define SILK_FUZZ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "silk/silk.h"

/* The entry point: libFuzzer's, unless tests/test_regress.c, which runs
 * every harness in one program, names each one itself. */
#ifndef FUZZ_ENTRY
#define FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

#define fuzz_expect(cond, ...)                                                    \
    do {                                                                          \
        if (!(cond)) {                                                            \
            fprintf(stderr, "fuzz: %s:%d: %s: ", __FILE__, __LINE__, #cond);      \
            fprintf(stderr, __VA_ARGS__);                                         \
            fputc('\n', stderr);                                                  \
            abort();                                                              \
        }                                                                         \
    } while (0)

/* A failed call must leave one clean line: non-empty, no newline, starting
 * with the name it was given (or a stage name when there is no input name),
 * and a code that is an error. */
static inline void fuzz_check_error(silk_status st, const silk_error *err, const char *name)
{
    fuzz_expect(st != SILK_OK, "not an error");
    fuzz_expect(err->code == st, "err.code %d but returned %d", (int)err->code, (int)st);
    const char *nul = memchr(err->msg, '\0', sizeof err->msg);
    fuzz_expect(nul && nul > err->msg, "message empty or not terminated");
    fuzz_expect(strchr(err->msg, '\n') == NULL, "message has a newline: \"%s\"", err->msg);
    if (name) fuzz_expect(strncmp(err->msg, name, strlen(name)) == 0, "message \"%s\" does not name %s", err->msg, name);
}

/* The arena as the loader found it: a failed load takes nothing. */
static inline void fuzz_check_arena_empty(const silk_arena *a)
{
    fuzz_expect(a->bottom == 0 && a->top == 0, "arena not restored: bottom %zu top %zu", a->bottom, a->top);
    for (int p = 0; p < SILK_MEM_COUNT; p++)
        fuzz_expect(a->used[p] == 0, "purpose %s still holds %zu bytes", silk_purpose_name((silk_purpose)p),
                    a->used[p]);
}

/* Little-endian reads from the fuzz input, zero past its end. */
typedef struct fuzz_bytes {
    const uint8_t *p;
    size_t n, at;
} fuzz_bytes;

static inline uint32_t fuzz_u8(fuzz_bytes *b)
{
    return b->at < b->n ? b->p[b->at++] : 0;
}

static inline int32_t fuzz_i16(fuzz_bytes *b)
{
    uint32_t lo = fuzz_u8(b), hi = fuzz_u8(b);
    return (int32_t)(int16_t)(uint16_t)(lo | hi << 8);
}

static inline uint32_t fuzz_u32(fuzz_bytes *b)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) v |= fuzz_u8(b) << (8 * i);
    return v;
}

#endif
