/*
 * silk/arena.h - the only memory the core ever uses.
 *
 * The caller hands silk one byte buffer.  Persistent data (the mesh, its
 * adjacency, precomputed curves, the visibility hierarchy, raster lines) is
 * taken from the bottom and lives until the arena is reset; per-frame scratch
 * is taken from the top and released as a whole with silk_arena_top_release().
 * The two ends meet in the middle, so one buffer serves both and a frame that
 * needs more scratch simply fails with SILK_ERR_NOMEM instead of crashing.
 * Every allocation names a purpose, so a report can say where each byte went.
 */
#ifndef SILK_ARENA_H
#define SILK_ARENA_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_purpose {
    SILK_MEM_MESH = 0,     /* positions, normals, uvs, triangle indices */
    SILK_MEM_ADJACENCY,    /* edges and triangle->edge links */
    SILK_MEM_FEATURES,     /* precomputed feature segments */
    SILK_MEM_VISIBILITY,   /* Gaussian-sphere hierarchy */
    SILK_MEM_RASTER,       /* colour and depth lines */
    SILK_MEM_FRAME,        /* per-frame silhouette work and re-meshing */
    SILK_MEM_LOAD,         /* scratch used only while loading */
    SILK_MEM_COUNT
} silk_purpose;

typedef struct silk_arena {
    uint8_t *base;
    size_t size;
    size_t bottom;                      /* bytes used from the bottom */
    size_t top;                         /* bytes used from the top */
    size_t peak;                        /* high-water mark of bottom + top */
    size_t top_peak;                    /* high-water mark of top alone (reset by the caller per frame) */
    size_t used[SILK_MEM_COUNT];        /* bytes held now, per purpose (both ends) */
    size_t top_used[SILK_MEM_COUNT];    /* the part of used[] held at the top */
    size_t peak_used[SILK_MEM_COUNT];   /* high-water mark per purpose */
    size_t failed_request;              /* size of the last request that did not fit */
} silk_arena;

/* A saved top-of-arena position; release returns the top to it. */
typedef struct silk_arena_mark {
    size_t top;
    size_t top_used[SILK_MEM_COUNT];
} silk_arena_mark;

#define SILK_ARENA_ALIGN 8

void  silk_arena_init(silk_arena *a, void *buf, size_t size);
/* Zero-filled, SILK_ARENA_ALIGN-aligned; NULL when it does not fit (and
 * a->failed_request records how much was asked for). n == 0 gives a valid
 * non-NULL pointer. */
void *silk_arena_alloc(silk_arena *a, size_t n, silk_purpose p);
void *silk_arena_alloc_top(silk_arena *a, size_t n, silk_purpose p);
/* count*size with overflow check */
void *silk_arena_array(silk_arena *a, size_t count, size_t size, silk_purpose p);
void *silk_arena_array_top(silk_arena *a, size_t count, size_t size, silk_purpose p);
/* silk_arena_array_top without the zero fill: for a table whose user
 * writes each byte before reading it (render.c's vertex cache, what the
 * plan keeps for speed: megabytes a frame on a fine mesh, where the fill
 * would cost as much as a tenth of its frame) */
void *silk_arena_array_top_unfilled(silk_arena *a, size_t count, size_t size, silk_purpose p);
silk_arena_mark silk_arena_top_mark(const silk_arena *a);
void  silk_arena_top_release(silk_arena *a, const silk_arena_mark *m);
size_t silk_arena_free_bytes(const silk_arena *a);
const char *silk_purpose_name(silk_purpose p);

#ifdef __cplusplus
}
#endif

#endif
