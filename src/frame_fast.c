/*
 * frame_fast.c - what a frame keeps for speed where the arena has room
 * (silk/config.h's shortcuts that take arena: SILK_VERTEX_CACHE,
 * SILK_DRAW_DIRECT, SILK_KEEP_SHARES, SILK_DEPTH_WINS,
 * SILK_BACK_FACES_LAST): the vertex cache, each corner's vertex stage once
 * a frame; the triangles drawn as they are straight from it, each vertex
 * placed on the screen once a frame; the shares near the silhouette kept as
 * first built; which triangles of each share wrote a depth in the depth
 * pass, and the back faces it draws last.  None of it is part of a frame's
 * need (silk_frame_stats.frame_bytes), and each gives the same bits as the
 * frame without it: a build without the shortcuts leaves this file's code
 * out.
 */
#include "render_frame.h"

/* The vertex cache (corner_cached), from at most half of the arena left
 * once the frame has what it needs: a power of two slots, enough for every
 * normal of the mesh when there is room, else fewer (more misses, the same
 * bits), none below 64.  It is not part of the frame's need
 * (silk_frame_stats.frame_bytes): a frame without it is drawn the same. */
#define VCACHE_MAX 4096
void silk_fast_vertex_cache(frame *f, silk_arena *a, const silk_render_opts *o)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    if (!SILK_VERTEX_CACHE || f->parts != FRAME_SHARES || !silk_mesh_has_corner_normals(m) || !silk_hal_vertex_by_attrs(f->hal)) return;
    const size_t slot = sizeof *x->vc + 3 * sizeof *x->vc_tag, half = silk_fast_spare(f, a) / 2,
                 free0 = silk_arena_free_bytes(a);
    size_t room = half < o->vertex_cache_bytes ? half : o->vertex_cache_bytes;
    /* where each vertex of the mesh is placed (silk_fast_draw_direct: FLAT's
     * triangles, SMOOTH's away from the silhouette), when that fits with
     * the least cache */
    size_t xy = (size_t)m->nverts * (2 * sizeof *x->vc_xy + sizeof *x->vc_clip) + 2 * SILK_ARENA_ALIGN;
    if (!SILK_DRAW_DIRECT || xy + 64 * slot + 2 * SILK_ARENA_ALIGN > room) xy = 0;
    room -= xy;
    uint32_t n = 64;
    while (n < m->nnormals && n < VCACHE_MAX && (size_t)2 * n * slot + 2 * SILK_ARENA_ALIGN <= room) n *= 2;
    if ((size_t)n * slot + 2 * SILK_ARENA_ALIGN > room) return;
    /* unfilled: a slot is read only once its tag says it is written, a
     * vertex's place only once silk_fast_place_vertices has written every one */
    x->vc = silk_arena_array_top_unfilled(a, n, sizeof *x->vc, SILK_MEM_FRAME);
    x->vc_tag = silk_arena_array_top_unfilled(a, 3 * (size_t)n, sizeof *x->vc_tag, SILK_MEM_FRAME);
    if (!xy || !(x->vc_xy = silk_arena_array_top_unfilled(a, 2 * (size_t)m->nverts, sizeof *x->vc_xy, SILK_MEM_FRAME)) ||
        !(x->vc_clip = silk_arena_array_top_unfilled(a, m->nverts, sizeof *x->vc_clip, SILK_MEM_FRAME)))
        x->vc_xy = NULL;
    if (!x->vc || !x->vc_tag) {
        x->vc = NULL;
        x->vc_xy = NULL;
        return;
    }
    for (uint32_t i = 0; i < n; i++) x->vc_tag[3 * i] = UINT32_MAX;   /* empty: no normal index is UINT32_MAX */
    f->vc_bytes = free0 - silk_arena_free_bytes(a);
    x->vc_mask = n - 1;
}

/* A kept share: its counts and whether it is placed, then its records,
 * curves, vertex-stage output, triangles and their flags, each a multiple
 * of 4 bytes, then where its records are placed on the screen (frame_draw.c's draw_tris,
 * once a frame: the place depends on the frame's size alone). */
#define KEPT_HEAD 5
static size_t share_bytes(uint32_t nvrec, uint32_t ntri, uint32_t ncurve)
{
    return KEPT_HEAD * sizeof(uint32_t) + (size_t)nvrec * (sizeof(silk_vrec) + sizeof(silk_vertex_out) + 2 * sizeof(int32_t)) +
           (size_t)ncurve * sizeof(silk_curve) + (size_t)ntri * 3 * sizeof(uint32_t) + (((size_t)ntri + 3) & ~(size_t)3);
}

/* SMOOTH: room for the shares of the triangles on, carrying or moved by
 * the silhouette as they are first built (silk_shares_part), which a frame builds again for the depth pass
 * and for the anti-aliased outline: under the vertex cache's budget, from
 * half of what the arena has left beyond the outline's reserve, as many as
 * fit.  Not part of the frame's need either. */
void silk_fast_keep_shares(frame *f, silk_arena *a, const silk_render_opts *o)
{
    frame_fast *x = f->fast;
    uint32_t n = f->smooth ? f->geom.mesh->ntris : 0;   /* ks_at: per input triangle (share_kept) */
    if (!SILK_KEEP_SHARES || !n || n >= UINT32_MAX / 4) return;
    size_t free0 = silk_arena_free_bytes(a), reserve = 16 * SILK_ARENA_ALIGN, left = silk_fast_spare(f, a);
    size_t budget = o->vertex_cache_bytes > f->vc_bytes ? o->vertex_cache_bytes - f->vc_bytes : 0;
    size_t room = left > reserve ? (left - reserve) / 2 : 0, per = share_bytes(f->sil.max_recs, f->sil.max_tris,
                                                                                f->sil.max_curves);
    if (room > budget) room = budget;
    if (room < (size_t)n * sizeof *x->ks_at + per + 2 * SILK_ARENA_ALIGN) return;
    room -= (size_t)n * sizeof *x->ks_at + 2 * SILK_ARENA_ALIGN;
    /* all of them (the plan counted what the kept segments' hold; each adds
     * its counts and padding; the others' a few records each, on a side
     * or two carrying silhouette points or with a vertex moved), or what fits */
    const silk_sil_keep *k = f->sil.keep;
    uint64_t all = k ? (uint64_t)(sizeof(silk_vrec) + sizeof(silk_vertex_out) + 8) * k->kept_recs +
                       (uint64_t)sizeof(silk_curve) * k->kept_curves + 13 * k->kept_tris + 24 * (uint64_t)k->nseg_kept
                     : 0;
    for (uint32_t j = 0; j < n; j++)
        if (!(f->sil.tri_state[j] & SILK_TS_SIL) && !direct_ok(f, j)) all += share_bytes(8, 6, 2);
    size_t cap = all < room ? (size_t)all : room;
    x->ks_at = silk_arena_array_top(a, n, sizeof *x->ks_at, SILK_MEM_FRAME);   /* zeroed: none built */
    x->ks = silk_arena_array_top_unfilled(a, cap, 1, SILK_MEM_FRAME);   /* each share written before it is read */
    if (!x->ks_at || !x->ks) {
        x->ks = NULL;
        return;
    }
    x->ks_cap = cap;
    x->ks_used = 0;
    x->home = f->g;
    x->home_cache = f->cache;
    f->vc_bytes += free0 - silk_arena_free_bytes(a);
}

/* Copy the share just built, the frame's (g, cache), into kept memory p
 * (share_view reads it there). */
static void share_copy(frame *f, uint8_t *p)
{
    const silk_frame_geom *g = &f->g;
    uint32_t *n = (uint32_t *)(void *)p;
    n[0] = g->nvrec;
    n[1] = g->ntri;
    n[2] = g->ncurve;
    n[3] = f->plain;
    n[4] = 0;   /* not placed yet */
    const struct { const void *at; size_t bytes; } part[5] = {
        { g->vrec, g->nvrec * sizeof *g->vrec }, { g->curve, g->ncurve * sizeof *g->curve },
        { f->cache, g->nvrec * sizeof *f->cache }, { g->tri, 3 * (size_t)g->ntri * sizeof *g->tri },
        { g->tri_added, g->ntri } };
    p += KEPT_HEAD * sizeof(uint32_t);
    for (int i = 0; i < 5; i++) {
        memcpy(p, part[i].at, part[i].bytes);
        p += (part[i].bytes + 3) & ~(size_t)3;
    }
    f->fast->kxy = (int32_t(*)[2])(void *)p;
    f->fast->kxy_ready = &n[4];
}

/* The share kept at p as the frame's (g, cache) where it is, not copied
 * back (share_copy): nothing drawn writes them.  silk_fast_kept_view points them
 * home again before it builds one. */
static void share_view(frame *f, uint8_t *p)
{
    silk_frame_geom *g = &f->g;
    uint32_t *n = (uint32_t *)(void *)p;
    g->nvrec = n[0];
    g->ntri = n[1];
    g->ncurve = n[2];
    f->plain = (uint8_t)n[3];
    g->offset = f->sil.offset;
    g->noffset = f->sil.noffset;
    /* share_copy's order and padding (its parts hold 4-byte fields) */
    p += KEPT_HEAD * sizeof(uint32_t);
    g->vrec = (silk_vrec *)(void *)p;
    p += (g->nvrec * sizeof *g->vrec + 3) & ~(size_t)3;
    f->geom.curves = g->curve = (silk_curve *)(void *)p;   /* the vertex stage's and the outline's */
    p += (g->ncurve * sizeof *g->curve + 3) & ~(size_t)3;
    f->cache = (silk_vertex_out *)(void *)p;
    p += (g->nvrec * sizeof *f->cache + 3) & ~(size_t)3;
    g->tri = (uint32_t *)(void *)p;
    p += (3 * (size_t)g->ntri * sizeof *g->tri + 3) & ~(size_t)3;
    g->tri_added = p;
    f->fast->kxy = (int32_t(*)[2])(void *)(p + ((g->ntri + 3) & ~(size_t)3));
    f->fast->kxy_ready = &n[4];
}

/* Where input triangle t's share is kept: t, for every share silk_fast_draw_direct
 * does not draw (SILK_SIL_NONE: none, or a build without kept shares). */
static uint32_t share_kept(const frame *f, uint32_t t)
{
    return SILK_KEEP_SHARES && f->fast->ks && !direct_ok(f, t) ? t : SILK_SIL_NONE;
}

int silk_fast_kept_view(frame *f, uint32_t t)
{
    silk_frame_geom *g = &f->g;
    frame_fast *x = f->fast;
    uint32_t k = share_kept(f, t);
    if (k != SILK_SIL_NONE && x->ks_at[k]) {
        share_view(f, x->ks + x->ks_at[k] - 1);
        return 1;
    }
    if (x->ks) {
        x->kxy = NULL;   /* (share_copy: where this one is kept) */
        if (g->vrec != x->home.vrec) {   /* home from a kept share */
            g->vrec = x->home.vrec;
            g->tri = x->home.tri;
            g->tri_added = x->home.tri_added;
            f->geom.curves = g->curve = x->home.curve;
            f->cache = x->home_cache;
        }
    }
    return 0;
}

void silk_fast_kept_store(frame *f, uint32_t t)
{
    const silk_frame_geom *g = &f->g;
    frame_fast *x = f->fast;
    uint32_t k = share_kept(f, t);
    size_t bytes = share_bytes(g->nvrec, g->ntri, g->ncurve);
    if (k != SILK_SIL_NONE && x->ks_cap - x->ks_used >= bytes) {
        share_copy(f, x->ks + x->ks_used);
        x->ks_at[k] = (uint32_t)x->ks_used + 1;
        x->ks_used += bytes;
    }
}

/* A back face of a re-meshed part that the depth pass draws last
 * (silk_fast_back_last): where the rasterizer places its corners and their clip z
 * and w (all the depth needs), and which triangle of which part it is. */
typedef struct back_tri {
    int32_t xy[3][2];
    silk_fx z[3], w[3];
    uint32_t part, bit;
} back_tri;

/* SMOOTH: which triangles of each part wrote a depth in the depth pass,
 * bit j of won[k] for triangle j of part k (bit 31 for triangle 31 and
 * every later one), so that the shading pass skips those that did not:
 * a pixel is shaded by the first triangle drawn that is as near as its
 * depth, which wrote that depth when the depth pass drew it (the depth
 * test passes only the strictly nearer), so a triangle that wrote none
 * shades none (docs/raster.md).  Most are faces seen from behind - the
 * silhouette triangles' re-meshed parts are drawn both ways (silk_draw_frame)
 * - and faces hidden behind others; a part none of whose triangles wrote
 * is not even rebuilt.  (A fragment stage that discards could show a
 * triangle behind the discarded fragment at equal depth; none of silk's
 * stages that the depth pass draws with discards.)  4 bytes an input
 * triangle under the vertex cache's budget, only where silk_draw_frame makes a
 * depth pass; without the room every triangle is shaded as before. */
#define BACK_MAX 1024   /* back_tri entries at most: a coarse mesh's silhouette has a few hundred */
void silk_fast_depth_wins(frame *f, silk_arena *a, const silk_render_opts *o, const silk_target *t)
{
    if (!SILK_DEPTH_WINS) return;
    frame_fast *x = f->fast;
    uint64_t n = f->geom.mesh->ntris;
    size_t free0 = silk_arena_free_bytes(a), bytes = (size_t)n * sizeof *x->won + SILK_ARENA_ALIGN,
           budget = o->vertex_cache_bytes > f->vc_bytes ? o->vertex_cache_bytes - f->vc_bytes : 0;
    if (!f->smooth || n * 16 > (uint64_t)t->width * t->height || bytes > budget || bytes > silk_fast_spare(f, a) / 2) return;
    x->won = silk_arena_array_top(a, n, sizeof *x->won, SILK_MEM_FRAME);   /* each written in the depth pass */
    /* the back faces put off, from what is left of the budget and of half the arena */
    size_t left = budget - bytes, free1 = silk_fast_spare(f, a) / 2, cap = BACK_MAX;
    if (left > free1) left = free1;
    if (cap > left / sizeof *x->back) cap = left / sizeof *x->back;
    if (SILK_BACK_FACES_LAST && x->won && cap > 16 &&
        (x->back = silk_arena_array_top_unfilled(a, cap, sizeof *x->back, SILK_MEM_FRAME)))
        x->back_cap = (uint32_t)cap;
    f->vc_bytes += free0 - silk_arena_free_bytes(a);
}

/* The depth pass of a SMOOTH frame (depth_wins) puts off the back faces
 * of its re-meshed parts, drawn both ways (silk_draw_frame), until every other
 * triangle has written its depth (silk_fast_back_draw): then most of them are
 * behind and write none, and the shading pass skips them (and a part
 * none of whose triangles wrote is not rebuilt), where drawn in their turn
 * most wrote a depth the front faces took again.  The depth buffer is the
 * same (the nearest of all, in any order), and so is every pixel
 * shaded: the one fragment that shades a pixel is the first drawn of
 * those as near as its depth, so drawn before the others as near, and
 * each triangle put off notes a win wherever it is as near as what is
 * there (SILK_DEPTH_TIES), so it notes one wherever it may be that
 * fragment.  1 when the triangle at records c of part `part` is put off
 * (placed at p, facing away, and room for it; not where fragment writes
 * are counted, which putting off can raise). */
int silk_fast_back_last(frame *f, const silk_target *t, const int32_t *const p[3], const uint32_t c[3], uint32_t part,
                     uint32_t bit)
{
    frame_fast *x = f->fast;
    const int32_t *a = p[0], *b = p[1], *d = p[2];
    int64_t area = ((int64_t)b[0] - a[0]) * ((int64_t)d[1] - a[1]) - ((int64_t)d[0] - a[0]) * ((int64_t)b[1] - a[1]);
    if (!SILK_BACK_FACES_LAST || area <= 0 || t->cull_back || t->mask || t->writes || x->nback >= x->back_cap)
        return 0;   /* (y down: > 0 faces away) */
    back_tri *bt = &x->back[x->nback++];
    for (int i = 0; i < 3; i++) {
        bt->xy[i][0] = p[i][0];
        bt->xy[i][1] = p[i][1];
        bt->z[i] = f->cache[c[i]].clip.z;
        bt->w[i] = f->cache[c[i]].clip.w;
    }
    bt->part = part;
    bt->bit = bit;
    return 1;
}

/* The back faces silk_fast_back_last put off, into the depth buffer, each noting
 * its part's win. */
void silk_fast_back_draw(frame *f, silk_target *t)
{
    frame_fast *x = f->fast;
    silk_vertex_out v[3];
    memset(v, 0, sizeof v);
    const silk_vertex_out *pv[3] = { &v[0], &v[1], &v[2] };
    t->depth_equal = SILK_DEPTH_TIES;
    t->cull_back = 0;
    for (uint32_t i = 0; i < x->nback; i++) {
        const back_tri *bt = &x->back[i];
        const int32_t *p[3] = { bt->xy[0], bt->xy[1], bt->xy[2] };
        for (int j = 0; j < 3; j++) {
            v[j].clip.z = bt->z[j];
            v[j].clip.w = bt->w[j];
        }
        if (!silk_raster_reaches(t, p)) continue;
        t->drew = 0;
        silk_raster_placed(t, NULL, pv, p);
        if (t->drew) x->won[bt->part] |= bt->bit;
    }
    t->depth_equal = 0;
    x->nback = 0;
}

/* Every vertex of the mesh placed on the screen of t (vc_xy) for
 * silk_fast_draw_direct, once a frame, before its first triangle is drawn (vertices
 * that only triangles outside the band use are so few it is cheaper than
 * asking), and whether all lie in front of the near plane (all_before),
 * which silk_cull_back_faces would otherwise ask in a pass of its own.
 * The stage clock counts it as the rasterizer's, as silk_fast_draw_direct's vertex
 * stage: the vertex stage's pieces are the shares emitted. */
void silk_fast_place_vertices(frame *f, const silk_target *t)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    uint32_t t0 = silk_stage_start(f->clock);
    int before = 1;
    for (uint32_t p = 0; p < m->nverts; p++) {
        const silk_vec4 *c = &x->vc_clip[p];
        x->vc_clip[p] = silk_hal_vertex_clip(f->hal, silk_mesh_pos(m, p));
        before &= c->w > 0 && (int64_t)c->z + c->w > 0;   /* before_near's test */
        if (!silk_raster_place(t, c, &x->vc_xy[2 * p])) x->vc_xy[2 * p] = VC_OUTSIDE;
    }
    x->all_before = (uint8_t)before;
    x->xy_ready = 1;
    silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
}

/* Through the vertex cache (FLAT; SMOOTH away from the silhouette,
 * direct_ok): input triangle k drawn straight from the cache's slots
 * (shade: the fragment stage, or NULL for depth alone), its share never
 * built.  Each vertex of the mesh is placed on the screen once
 * a frame (silk_fast_place_vertices: silk_raster_place of the vertex stage's clip
 * position alone), so that the triangles the rasterizer would draw nothing of -
 * seen from behind, zero area, between pixel centres or outside the band,
 * most of a fine mesh's - cost a few comparisons and no vertex stage; the
 * others go to silk_raster_triangle with the bits the share would give
 * it.  0 when a corner has no usable vertex or is not cached (no usable
 * normal, or two corners in one slot): the caller then builds the share
 * as usual.  (The stage clock counts the vertex stage run here as the
 * rasterizer's: a clock per corner would cost more than the look-up.) */
int silk_fast_draw_direct(frame *f, silk_target *t, const silk_hal *shade, uint32_t k)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    /* written out (every triangle of the mesh comes here every band) */
    const silk_index tv[3] = { silk_mesh_corner(m, 3 * k), silk_mesh_corner(m, 3 * k + 1), silk_mesh_corner(m, 3 * k + 2) };
    const uint32_t nv = m->nverts;
    if (tv[0] >= nv || tv[1] >= nv || tv[2] >= nv) return 0;
    const int32_t *xy[3] = { &x->vc_xy[2 * (size_t)tv[0]], &x->vc_xy[2 * (size_t)tv[1]], &x->vc_xy[2 * (size_t)tv[2]] };
    int placed = (xy[0][0] != VC_OUTSIDE) & (xy[1][0] != VC_OUTSIDE) & (xy[2][0] != VC_OUTSIDE);
    t->cull_back = f->cull;   /* silk_draw_frame's rule for triangles drawn as they are */
    if (placed && !silk_raster_reaches(t, xy)) return 1;
    const silk_vertex_out *v[3];
    uint32_t s[3];
    for (uint32_t i = 0; i < 3; i++) {
        if ((s[i] = corner_slot(f, 3 * k + i, NULL, &x->vc_clip[silk_mesh_corner(m, 3 * k + i)])) == UINT32_MAX) return 0;
        v[i] = &x->vc[s[i]];
    }
    if (s[0] == s[1] || s[1] == s[2] || s[2] == s[0]) return 0;   /* a later corner may have taken an earlier's slot */
    if (placed) silk_raster_placed(t, shade, v, xy);
    else silk_raster_triangle(t, shade, v[0], v[1], v[2]);
    return 1;
}
