/*
 * flat.c - the coarse mesh as it is: one CORNER vertex record per triangle
 * corner (the records of paper Fig. 16 with no re-meshing at all).  This is
 * FLAT mode, and the reference SMOOTH mode is compared against.
 */
#include "smooth.h"

silk_status silk_frame_flat(silk_arena *a, const silk_mesh *m, silk_frame_geom *g, silk_error *err)
{
    if (m->ntris > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, "frame", 0, "too many triangles (%lu)",
                         (unsigned long)m->ntris);
    uint32_t n = 3 * m->ntris;
    g->vrec = silk_arena_array_top(a, n, sizeof *g->vrec, SILK_MEM_FRAME);
    g->tri = silk_arena_array_top(a, n, sizeof *g->tri, SILK_MEM_FRAME);
    g->tri_added = silk_arena_array_top(a, m->ntris, 1, SILK_MEM_FRAME);
    if (!g->vrec || !g->tri || !g->tri_added)
        return silk_fail(err, SILK_ERR_NOMEM, "frame", 0,
                         "arena too small for the frame (%lu more bytes needed)",
                         (unsigned long)a->failed_request);
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
