/*
 * frame_aa.c - the anti-aliased outlines over a band just drawn: CLIP's
 * (clip.c), and aa.c's for the frames drawn share by share (SILTEX's from
 * eq. 4 itself): which shares hold an outline, each rebuilt once more or its
 * one triangle taken from the vertex cache, the rows next to the band drawn
 * first for its edge pixels to blend with, and the room a band's outline
 * takes, which the frame's shortcuts leave free.
 */
#include "render_frame.h"

int silk_outline_wanted(const frame *f, const silk_render_opts *o, const silk_target *t)
{
    return SILK_AA && o->aa && !o->wire && f->parts == FRAME_SHARES && t->depth && !(SILTEX_FRAME(f) && o->lines);
}

/* The outline's memo of which way each input triangle faces
 * (silk_aa.facing), under the same budget as the vertex cache and, like
 * it, not part of the frame's need (and left out with its code,
 * SILK_VERTEX_CACHE 0): without it each triangle's facing is worked out
 * up to four times a band, with the same answers. */
void silk_outline_facing(frame *f, silk_arena *a, const silk_render_opts *o)
{
    if (!SILK_AA || !SILK_VERTEX_CACHE) return;
    size_t n = ((size_t)f->geom.mesh->ntris + 3) / 4, free0 = silk_arena_free_bytes(a), room = silk_fast_spare(f, a),
           budget = o->vertex_cache_bytes > f->vc_bytes ? o->vertex_cache_bytes - f->vc_bytes : 0;
    if (!o->aa || o->wire || f->parts != FRAME_SHARES || CLIP_FRAME(f) || n + SILK_ARENA_ALIGN > budget ||
        n + SILK_ARENA_ALIGN > room / 2)
        return;
    f->facing = silk_arena_array_top(a, n, 1, SILK_MEM_FRAME);   /* zeroed: nothing known yet */
    if (!f->facing) return;
    /* A closed mesh: the outline's candidates for all bands at once
     * (silk_aa_candidates), a bit a triangle, when the budget has room too */
    size_t nc = ((size_t)f->geom.mesh->ntris + 7) / 8;
    if (SILK_AA_CANDIDATES && f->geom.mesh->closed_outward && n + nc + 2 * SILK_ARENA_ALIGN <= budget &&
        n + nc + 2 * SILK_ARENA_ALIGN <= room / 2)
        f->fast->cand = silk_arena_array_top(a, nc, 1, SILK_MEM_FRAME);
    f->vc_bytes += free0 - silk_arena_free_bytes(a);
}

/* The outline of input triangle k drawn as it is (direct_ok) without
 * building its share: silk_aa_share reads of such a share its one
 * triangle of three records and their clip coordinates, which
 * silk_fast_place_vertices has worked out.  0 when they are not placed or a corner
 * has no vertex (then the share is built). */
static int aa_direct(frame *f, silk_aa *aa, const silk_view *v, uint32_t k)
{
    const silk_mesh *m = f->geom.mesh;
    const frame_fast *x = f->fast;
    if (!x->vc_xy || !x->xy_ready || !direct_ok(f, k)) return 0;
    silk_vertex_out out[3];   /* the clip coordinates alone: the rest is not read */
    uint32_t tri[3] = { 0, 1, 2 };
    silk_frame_geom g;
    memset(&g, 0, sizeof g);
    g.tri = tri;
    g.ntri = 1;
    g.nvrec = 3;
    for (uint32_t i = 0; i < 3; i++) {
        uint32_t p = silk_mesh_corner(m, 3 * k + i);
        if (p >= m->nverts) return 0;
        out[i].clip = x->vc_clip[p];
    }
    silk_aa_share(aa, m, v, &g, out, k);
    return 1;
}

/* The first outline candidate (fast->cand) after k, or nparts. */
static uint32_t cand_after(const frame *f, uint32_t k)
{
    const uint8_t *cand = f->fast->cand;
    while (++k < f->nparts)
        if (!cand[k / 8]) k |= 7;   /* eight at once, as silk_outline_draw skips them */
        else if (cand[k / 8] >> (k % 8) & 1) return k;
    return f->nparts;
}

/* A host's prefetch for aa_direct, asked at candidate k: the outline's
 * candidates lie scattered over the mesh, so each reads its corners and
 * sides (silk_aa_share reads the sides' edges) from memory no cache
 * holds; the next candidate's clip coordinates and edges and the one
 * after's corners are fetched while k's outline is worked out (some two
 * thousand instructions).  It reads nothing itself but the next
 * candidate's corners and sides, fetched at the candidate before; next
 * keeps the two candidates after the last k asked (none: UINT32_MAX).
 * (Inline: gcc takes a call that only prefetches for one without effect,
 * and drops it.) */
SILK_ALWAYS_INLINE static inline void aa_prefetch(const frame *f, uint32_t k, uint32_t next[2])
{
    const silk_mesh *m = f->geom.mesh;
    if (next[0] == k) next[0] = next[1];   /* found at the candidate before */
    else next[0] = cand_after(f, k);
    uint32_t c1 = next[0], c2 = next[1] = c1 < f->nparts ? cand_after(f, c1) : f->nparts;
    if (c2 < f->nparts) {
        if (m->tri) SILK_PREFETCH(&m->tri[3 * (size_t)c2]);
        if (m->tri_edge) SILK_PREFETCH(&m->tri_edge[3 * (size_t)c2]);
    }
    for (uint32_t i = 0; c1 < f->nparts && i < 3; i++) {
        uint32_t p = silk_mesh_corner(m, 3 * (size_t)c1 + i), e = m->tri_edge ? m->tri_edge[3 * (size_t)c1 + i] : SILK_NO_INDEX;
        if (p < m->nverts) SILK_PREFETCH(&f->fast->vc_clip[p]);
        if (e < m->nedges) SILK_PREFETCH(&m->edge[e]);   /* (tri_edge: a mesh in arrays) */
    }
}

/* SILTEX's outline over aa's band (aa.c, silk_aa_margin): the hull's
 * front faces drawn again, depth alone, over the band's rows and its
 * aprons'; where the pixels drawn from a front face meet those that show
 * what lies behind it, the front faces once more through the margin stage
 * (siltex.c), only there; then those pixels blended by their coverage.  0
 * when the arena has no room for it (siltex_outline_bytes: what the
 * renderer leaves free for it). */
static int siltex_outline(frame *f, silk_arena *a, const silk_render_opts *o, silk_aa *aa)
{
    const silk_target *t = aa->t;
    int y0 = t->y0 > 0 ? t->y0 - 1 : 0, y1 = t->y0 + t->rows < t->height ? t->y0 + t->rows + 1 : t->height;
    size_t w = (size_t)t->width, rows = (size_t)(y1 - y0);
    /* unfilled: the clear writes them */
    uint8_t *c = silk_arena_array_top_unfilled(a, w * rows, 3, SILK_MEM_FRAME);
    uint32_t *d = silk_arena_array_top_unfilled(a, w * rows, sizeof *d, SILK_MEM_FRAME);
    uint8_t *mask = silk_arena_array_top_unfilled(a, rows, (w + 7) / 8, SILK_MEM_FRAME);
    if (!c || !d || !mask) return 0;
    silk_target s;
    silk_target_init(&s, t->width, t->height, y0, (int)rows, SILK_PIX_RGB888, c, d);
    silk_target_clear(&s, 0);
    silk_draw_hull(f, o, &s, NULL);
    if (silk_aa_margin_mask(aa, &s, mask)) {
        silk_hal margin;
        silk_siltex_margin_hal(&margin, &f->siltex->stage);
        s.depth_equal = 1;   /* the front faces alone */
        silk_draw_hull(f, o, &s, &margin);
        silk_aa_margin(aa, &s);
    }
    return 1;
}

/* The outlines of the shares that can hold one (FLAT's and SMOOTH's, aa.c)
 * over aa's band t: each candidate's share rebuilt once more, or its one
 * triangle as drawn straight from the vertex cache. */
static void aa_shares(frame *f, silk_aa *aa, const silk_view *v, const silk_target *t)
{
    frame_fast *x = f->fast;
    const uint8_t *cand = SILK_AA_CANDIDATES ? x->cand : NULL;   /* silk_aa_candidates', or NULL */
    if (cand && !x->cand_ready) {
        silk_aa_candidates(aa, f->geom.mesh, v, x->cand);
        x->cand_ready = 1;
    }
    uint32_t next[2] = { UINT32_MAX, UINT32_MAX };   /* aa_prefetch's */
    for (uint32_t k = 0; k < f->nparts; k++) {
        if (cand && !cand[k / 8]) {   /* eight triangles at once: most have no outline side */
            k |= 7;
            continue;
        }
        if (part_misses(f, k, t->y0 - 1, t->y0 + t->rows)) continue;
        if (cand ? !(cand[k / 8] >> (k % 8) & 1) : !silk_aa_candidate(aa, f->geom.mesh, v, aa->sil, k)) continue;
        if (SILK_DRAW_DIRECT && cand && x->vc_xy && x->xy_ready && !f->smooth) aa_prefetch(f, k, next);
        if (SILK_DRAW_DIRECT && aa_direct(f, aa, v, k)) continue;
        frame_part(f, k);
        silk_aa_share(aa, f->geom.mesh, v, &f->g, f->cache, k);
    }
}

/* Anti-aliased outlines over band t, just drawn: CLIP's (clip.c: the
 * map's outline, whatever the build), and those of aa.c (a build with
 * SILK_AA 0 leaves them out: about 3.0 KiB of Cortex-M3 code and a band's
 * worth of scratch): of the frames drawn share by share (FLAT and SMOOTH
 * without lines, and SILTEX's, from eq. 4 itself), not under --wire's
 * edges.  The shares that can hold an outline are rebuilt once more; a
 * band that is not the whole frame first draws the rows next to it, which
 * its edge pixels blend with. */
void silk_outline_walk(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_aa *aa,
                       silk_frame_stats *stats)
{
    aa->facing = f->facing;
    aa->creases = o->aa == 1;
    if (SILTEX_FRAME(f)) {   /* the hull's edges are not its outline: eq. 4's edge is */
        if (!siltex_outline(f, a, o, aa)) stats->aa_aliased++;
    } else {
        aa->sil = f->smooth ? &f->sil : NULL;
        aa->hal = f->hal;
        aa->geom = &f->geom;
        aa_shares(f, aa, v, aa->t);
    }
}

void silk_outline_draw(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_target *t,
                     silk_frame_stats *stats)
{
    if (CLIP_FRAME(f)) {
        silk_aa_alpha(t);
        silk_clip_antialias(f->clip, t, o->bg_rgb);
        return;
    }
    if (!SILK_AA) {
        silk_aa_alpha(t);
        return;
    }
    silk_aa aa;
    silk_arena_mark mark = silk_arena_top_mark(a);
    int wanted = silk_outline_wanted(f, o, t);
    if (!wanted || !silk_aa_begin(&aa, a, t, f->smooth ? f->sil.max_recs : 3)) {
        if (wanted) stats->aa_aliased++;
        silk_aa_alpha(t);
        silk_arena_top_release(a, &mark);
        return;
    }
    for (int i = 0; i < 2; i++)
        if (aa.apron[i].rows) silk_draw_frame(f, o, &aa.apron[i]);
    silk_outline_walk(f, a, v, o, &aa, stats);
    silk_aa_finish(&aa);   /* pixels it had no room for are left aliased */
    stats->aa_aliased += aa.dropped;
    silk_arena_top_release(a, &mark);
}
