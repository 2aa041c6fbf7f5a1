/*
 * flat.c - the coarse mesh as it is: one CORNER vertex record per triangle
 * corner (the records of paper Fig. 16 with no re-meshing at all).  This is
 * FLAT mode, the reference SMOOTH mode is compared against, and what every
 * mode falls back to when the arena runs out (silk_frame_fall_back).  Like
 * SMOOTH's (remesh.c), its emitter makes one input triangle's share at a
 * time: a stored frame is every share appended into one buffer, and the
 * renderer may instead rebuild one share whenever a band needs it.
 */
#include <string.h>
#include "frame.h"

silk_status silk_frame_flat_room(silk_arena *a, uint32_t ntris, size_t extra_bytes, void **extra,
                                 silk_frame_geom *g, silk_error *err)
{
    memset(g, 0, sizeof *g);
    if (ntris > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, "frame", 0, "too many triangles (%lu)", (unsigned long)ntris);
    uint32_t n = 3 * ntris;
    size_t free_bytes = silk_arena_free_bytes(a);
    g->vrec = silk_arena_array_top(a, n, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, n, sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, ntris, 1, SILK_MEM_FRAME);
    if (extra) *extra = silk_arena_array_top(a, 1, extra_bytes, SILK_MEM_FRAME);
    if (!g->vrec || !g->tri || !g->tri_added || (extra && !*extra)) {
        /* the least any frame can do with: these arrays, aligned as the
         * arena hands them out */
        const uint64_t bytes[4] = { (uint64_t)n * sizeof *g->vrec, (uint64_t)n * sizeof *g->tri, ntris,
                                    extra ? extra_bytes : 0 };
        uint64_t need = 0;
        for (int i = 0; i < 4; i++) need += (bytes[i] + SILK_ARENA_ALIGN - 1) & ~(uint64_t)(SILK_ARENA_ALIGN - 1);
        return silk_fail(err, SILK_ERR_NOMEM, "frame", 0,
                         "arena too small for the frame: even the unsmoothed frame needs %llu bytes, %llu are free",
                         (unsigned long long)need, (unsigned long long)free_bytes);
    }
    return SILK_OK;
}

void silk_frame_flat_emit_tri(silk_frame_geom *g, uint32_t t)
{
    /* Records come zero-filled from the arena (silk_frame_flat_room) and
     * only this emitter writes them: kind CORNER, b 0, t 0; only the corner
     * index is set. */
    for (uint32_t k = 0; k < 3; k++) {
        g->vrec[g->nvrec].a = 3 * t + k;
        g->tri[3 * g->ntri + k] = g->nvrec++;
    }
    g->ntri++;
}

silk_status silk_frame_flat(silk_arena *a, const silk_mesh *m, silk_frame_geom *g, silk_error *err)
{
    silk_status st = silk_frame_flat_room(a, m->ntris, 0, NULL, g, err);
    if (st != SILK_OK) return st;
    for (uint32_t t = 0; t < m->ntris; t++) silk_frame_flat_emit_tri(g, t);
    return SILK_OK;
}

/* The one fall-back of every mode: what was allocated since mark is
 * released and the coarse mesh drawn instead, counted as such. */
silk_status silk_frame_fall_back(silk_arena *a, const silk_mesh *m, const silk_arena_mark *mark,
                                 silk_frame_geom *g, silk_frame_stats *stats, silk_error *err)
{
    silk_arena_top_release(a, mark);
    silk_status st = silk_frame_flat(a, m, g, err);
    if (st != SILK_OK) return st;
    silk_frame_stats_fell_back(stats, g->ntri);
    return SILK_OK;
}

void silk_frame_stats_fell_back(silk_frame_stats *stats, uint32_t tris_drawn)
{
    if (!stats) return;
    stats->silhouette_tris = stats->bridges = stats->samples = stats->moved_vertices = 0;
    stats->flat_segments = 0;
    stats->tris_drawn = tris_drawn;
    silk_frame_fell_short(stats);
}

/* The one flag for a frame that is less than was asked for, drawn coarse or
 * with lines left out or unlifted: a caller that retries with a larger
 * arena gets all of it. */
void silk_frame_fell_short(silk_frame_stats *stats)
{
    if (stats) stats->fell_back = 1;
}
