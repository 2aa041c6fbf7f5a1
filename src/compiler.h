/*
 * compiler.h - internal: what the core asks of the compiler beyond C11, in
 * one place.  gcc and clang have all of it; with another compiler each is
 * its plain C11 meaning (no attribute, no hint), with the same results.
 * Not installed.
 */
#ifndef SILK_COMPILER_H
#define SILK_COMPILER_H

#include <stdint.h>
#include "silk/config.h"

#if defined(__GNUC__)
/* inline wherever it is called: a call would cost as much as the work */
#define SILK_ALWAYS_INLINE __attribute__((always_inline))
/* never inline: its locals stay off the caller's stack frame */
#define SILK_NOINLINE __attribute__((noinline))
/* fetch p's cache line ahead of its use */
#define SILK_PREFETCH(p) __builtin_prefetch(p)
/* v, with what the compiler knows of its range forgotten (v in a register) */
#define SILK_OPAQUE32(v) __asm__("" : "+r"(v))
#else
#define SILK_ALWAYS_INLINE
#define SILK_NOINLINE
#define SILK_PREFETCH(p) ((void)(p))
#define SILK_OPAQUE32(v) ((void)(v))
#endif

/* Inline everywhere on a 64-bit host; left to the compiler on a 32-bit
 * part, where the code bytes count (SILK_CPU32).  And the other way round:
 * out of line on a 32-bit part, so that its caller's loop keeps its values
 * in the few registers there are. */
#if !SILK_CPU32
#define SILK_HOST_INLINE SILK_ALWAYS_INLINE inline
#define SILK_CPU32_NOINLINE
#else
#define SILK_HOST_INLINE
#define SILK_CPU32_NOINLINE SILK_NOINLINE
#endif

/* Inline everywhere where the build writes out its usual cases
 * (SILK_FAST_CASES: a host); left to the compiler on a board. */
#if SILK_FAST_CASES
#define SILK_FAST_INLINE SILK_ALWAYS_INLINE
#else
#define SILK_FAST_INLINE
#endif

/* The number of bits of v: 0 for 0, else 1 + the place of its highest set bit. */
static inline int silk_bitlen64(uint64_t v)
{
#if defined(__GNUC__)
    return v ? 64 - __builtin_clzll(v) : 0;
#else
    int n = 0;
    while (v >= 256) { v >>= 8; n += 8; }
    while (v) { v >>= 1; n++; }
    return n;
#endif
}

/* The leading zero bits of x, x != 0. */
static inline int silk_clz32(uint32_t x)
{
#if defined(__GNUC__)
    return __builtin_clz(x);
#else
    int n = 0;
    while (!(x & 0x80000000u)) { x <<= 1; n++; }
    return n;
#endif
}

#endif
