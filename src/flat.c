/*
 * flat.c - the coarse mesh as it is: one CORNER vertex record per triangle
 * corner (the records of paper Fig. 16 with no re-meshing at all).  This is
 * FLAT mode, and the reference SMOOTH mode is compared against.
 */
#include "frame.h"

silk_status silk_frame_flat(silk_arena *a, const silk_mesh *m, silk_frame_geom *g, silk_error *err)
{
    if (m->ntris > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, "frame", 0, "too many triangles (%lu)",
                         (unsigned long)m->ntris);
    uint32_t n = 3 * m->ntris;
    size_t free_bytes = silk_arena_free_bytes(a);
    g->vrec = silk_arena_array_top(a, n, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, n, sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, m->ntris, 1, SILK_MEM_FRAME);
    if (!g->vrec || !g->tri || !g->tri_added) {
        /* the least any frame can do with: these three arrays, aligned as
         * the arena hands them out */
        const uint64_t al = SILK_ARENA_ALIGN - 1;
        uint64_t need = (((uint64_t)n * sizeof *g->vrec + al) & ~al) + (((uint64_t)n * sizeof *g->tri + al) & ~al) +
                        (((uint64_t)m->ntris + al) & ~al);
        return silk_fail(err, SILK_ERR_NOMEM, "frame", 0,
                         "arena too small for the frame: even the unsmoothed frame needs %llu bytes, %llu are free",
                         (unsigned long long)need, (unsigned long long)free_bytes);
    }
    /* Records are zero-filled: kind CORNER, b 0, t 0; only the corner index is set. */
    for (uint32_t i = 0; i < n; i++) {
        g->vrec[i].a = i;
        g->tri[i] = i;
    }
    g->nvrec = n;
    g->ntri = m->ntris;
    g->curve = NULL; g->ncurve = 0;
    g->offset = NULL; g->noffset = 0;
    g->patch = NULL; g->npatch = 0;
    return SILK_OK;
}
