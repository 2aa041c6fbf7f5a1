/*
 * frame_shares.c - frames drawn share by share (FLAT, SMOOTH and CLIP
 * without lines, and SILTEX's hull).
 *
 * A FLAT or SMOOTH frame without lines is never stored.  The silhouette plan
 * (plan.h: carrying edges, their points, the perturbation) is made once
 * per frame; an input triangle's share of the frame - its records, curves
 * and triangles, what a stored frame holds for it, in the same order - is
 * rebuilt and put through the vertex stage whenever a band needs it, so the
 * pixels are the stored frame's.  The memory is the plan's, a few dozen
 * bytes per carrying edge, instead of some 200 bytes of records, indices and
 * vertex cache per input triangle: what lets a 64 KiB part draw smooth
 * frames (docs/small-devices.md).  With several bands, a first pass notes
 * the rows each input triangle can reach, and a band rebuilds only the
 * triangles that reach into it (frame_cull.c).
 */
#include "render_frame.h"

static void corner_cached(const frame *f, const silk_vrec *r, silk_vertex_out *out)
{
    uint32_t s = corner_slot(f, r->a, r, NULL);
    if (s != UINT32_MAX) *out = f->fast->vc[s];
    else f->hal->vertex(f->hal, &f->geom, r, out);
}

/* Input triangle t's share into g, through the vertex stage into cache. */
void silk_shares_part(frame *f, uint32_t t)
{
    silk_frame_geom *g = &f->g;
    uint32_t t0 = silk_stage_start(f->clock);
    if (SILK_KEEP_SHARES && silk_fast_kept_view(f, t)) {   /* built before: the same records, the same output */
        silk_stage_stop(f->clock, SILK_STAGE_EMIT, t0);
        return;
    }
    g->nvrec = g->ntri = g->ncurve = 0;
    if (f->smooth) silk_remesh_emit_tri(&f->sil, g, t);
    else silk_frame_flat_emit_tri(g, t);
    silk_stage_stop(f->clock, SILK_STAGE_EMIT, t0);
    t0 = silk_stage_start(f->clock);
    /* in locals: the stores into the cache could alias f's and g's fields */
    const silk_vrec *r = g->vrec;
    silk_vertex_out *out = f->cache;
    uint32_t n = g->nvrec;
    int plain = g->ntri == 1, cached = VERTEX_CACHED(f);
    for (uint32_t i = 0; i < n; i++) {
        int corner = r[i].kind == SILK_VREC_CORNER;
        plain &= corner;
        if (cached && corner) corner_cached(f, &r[i], &out[i]);
        else f->hal->vertex(f->hal, &f->geom, &r[i], &out[i]);
    }
    f->plain = (uint8_t)plain;
    silk_stage_stop(f->clock, SILK_STAGE_VERTEX, t0);
    if (SILK_KEEP_SHARES) silk_fast_kept_store(f, t);
}
