/*
 * arena.c - the double-ended arena (see silk/arena.h).
 *
 * Persistent data grows up from the bottom, per-frame scratch grows down from
 * the top.  Nothing is freed individually: a frame releases its scratch by
 * returning the top to a mark, which also takes the released bytes off the
 * per-purpose counts, so the report after a frame still adds up.
 */
#include <string.h>
#include "silk/arena.h"
#include "compiler.h"

static size_t align_up(size_t n)
{
    return (n + (SILK_ARENA_ALIGN - 1)) & ~(size_t)(SILK_ARENA_ALIGN - 1);
}

void silk_arena_init(silk_arena *a, void *buf, size_t size)
{
    memset(a, 0, sizeof *a);
    /* Start on an aligned address so every block is aligned. */
    uintptr_t p = (uintptr_t)buf;
    size_t skip = (size_t)((SILK_ARENA_ALIGN - (p % SILK_ARENA_ALIGN)) % SILK_ARENA_ALIGN);
    if (buf == NULL || size < skip) {
        a->base = NULL;
        a->size = 0;
        return;
    }
    a->base = (uint8_t *)buf + skip;
    a->size = (size - skip) & ~(size_t)(SILK_ARENA_ALIGN - 1);
}

SILK_ALWAYS_INLINE static inline void account(silk_arena *a, size_t n, silk_purpose p)
{
    a->used[p] += n;
    if (a->used[p] > a->peak_used[p]) a->peak_used[p] = a->used[p];
    if (a->bottom + a->top > a->peak) a->peak = a->bottom + a->top;
}

/* Every allocation gets at least one aligned unit, so a zero-size request
 * still returns a distinct, valid pointer. */
SILK_ALWAYS_INLINE static inline int reserve(silk_arena *a, size_t n, size_t *out)
{
    if (n > a->size) { a->failed_request = n; return 0; }
    size_t m = align_up(n ? n : 1);
    if (m > a->size - a->bottom - a->top) { a->failed_request = n; return 0; }
    *out = m;
    return 1;
}

void *silk_arena_alloc(silk_arena *a, size_t n, silk_purpose p)
{
    size_t m;
    if ((unsigned)p >= SILK_MEM_COUNT || !reserve(a, n, &m)) return NULL;
    uint8_t *r = a->base + a->bottom;
    a->bottom += m;
    account(a, m, p);
    memset(r, 0, m);
    return r;
}

/* n bytes from the top, m of them taken; not zero-filled.  (It and the
 * two above inline in every caller, as with one caller each: a board links
 * silk_arena_alloc_top alone of take_top's callers.) */
SILK_ALWAYS_INLINE static inline uint8_t *take_top(silk_arena *a, size_t n, silk_purpose p, size_t *m)
{
    if ((unsigned)p >= SILK_MEM_COUNT || !reserve(a, n, m)) return NULL;
    a->top += *m;
    a->top_used[p] += *m;
    if (a->top > a->top_peak) a->top_peak = a->top;
    account(a, *m, p);
    return a->base + a->size - a->top;
}

void *silk_arena_alloc_top(silk_arena *a, size_t n, silk_purpose p)
{
    size_t m;
    uint8_t *r = take_top(a, n, p, &m);
    if (r) memset(r, 0, m);
    return r;
}

static int mul_ok(size_t count, size_t size, size_t *out)
{
    if (size && count > (size_t)-1 / size) return 0;
    *out = count * size;
    return 1;
}

void *silk_arena_array(silk_arena *a, size_t count, size_t size, silk_purpose p)
{
    size_t n;
    if (!mul_ok(count, size, &n)) { a->failed_request = (size_t)-1; return NULL; }
    return silk_arena_alloc(a, n, p);
}

void *silk_arena_array_top(silk_arena *a, size_t count, size_t size, silk_purpose p)
{
    size_t n;
    if (!mul_ok(count, size, &n)) { a->failed_request = (size_t)-1; return NULL; }
    return silk_arena_alloc_top(a, n, p);
}

void *silk_arena_array_top_unfilled(silk_arena *a, size_t count, size_t size, silk_purpose p)
{
    size_t n, m;
    if (!mul_ok(count, size, &n)) { a->failed_request = (size_t)-1; return NULL; }
    return take_top(a, n, p, &m);
}

silk_arena_mark silk_arena_top_mark(const silk_arena *a)
{
    silk_arena_mark m;
    m.top = a->top;
    memcpy(m.top_used, a->top_used, sizeof m.top_used);
    return m;
}

void silk_arena_top_release(silk_arena *a, const silk_arena_mark *m)
{
    if (m->top > a->top) return;  /* a stale mark: releasing would grow the top */
    a->top = m->top;
    /* Only the top's share of each purpose goes: bottom allocations made
     * since the mark (a mesh loaded while scratch was held) stay counted. */
    for (int p = 0; p < SILK_MEM_COUNT; p++) {
        size_t freed = a->top_used[p] >= m->top_used[p] ? a->top_used[p] - m->top_used[p] : 0;
        a->top_used[p] -= freed;
        a->used[p] -= freed;
    }
}

size_t silk_arena_free_bytes(const silk_arena *a)
{
    return a->size - a->bottom - a->top;
}

const char *silk_purpose_name(silk_purpose p)
{
    static const char *const names[SILK_MEM_COUNT] = {
        "mesh", "adjacency", "features", "visibility", "raster", "frame", "load"
    };
    return (unsigned)p < SILK_MEM_COUNT ? names[p] : "?";
}
