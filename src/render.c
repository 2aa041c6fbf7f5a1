/*
 * render.c - one frame: per-frame geometry, vertex stage, rasterizer.
 *
 * The silhouette stages (smooth.c) or the plain coarse mesh (flat.c) produce
 * vertex records and triangles over them.  Each record goes through the HAL's
 * vertex stage exactly once, so a vertex shared by many triangles reaches the
 * rasterizer with the same bits in all of them (no cracks); then every
 * triangle is rasterized into the target's band, and --wire draws the edges on
 * top, then the pen-and-ink lines (lines.c) if asked for.  All per-frame
 * memory is taken from the top of the arena and released before returning,
 * so frames can be rendered forever from one arena.
 *
 * FLAT and SMOOTH frames without lines are drawn share by share instead
 * (see "Frames drawn share by share" below): nothing but the silhouette plan
 * is kept, and each input triangle's share of the frame is rebuilt whenever
 * a band needs it.
 *
 * What a build draws is its options' (silk/config.h): a device that draws
 * only FLAT and SMOOTH frames leaves out PN and BLEND (SILK_REFERENCE_MODES
 * 0), the lines and --wire (SILK_LINES 0; with both every frame is drawn
 * share by share, so the stored frame's code goes too), CLIP, SILTEX,
 * the anti-aliased outlines (frame_aa) and texture sampling, and asking
 * for what is left out is SILK_ERR_ARG.  A build without the shortcuts
 * (SILK_SHORTCUTS 0) leaves out the code of those that spend arena for
 * speed, each of which a board's arena could not afford anyway: the
 * vertex cache and the triangles drawn straight from it (vertex_cache,
 * draw_direct), the kept shares (keep_shares), which triangles won a
 * depth (depth_wins) and the back faces drawn last (back_last), the
 * outline's candidates found once a frame, and what the SMOOTH plan keeps
 * (silk_remesh_keep, the carrying edges' rank).  What a frame keeps for
 * them is a frame_fast, which such a build does not have.
 */
#include <string.h>
#include "smooth.h"
#include "remesh.h"
#include "lines.h"
#include "stages.h"
#include "clip.h"
#include "aa.h"
#include "compiler.h"
#include "frame_steps.h"
#include "silk/siltex.h"

void silk_render_opts_default(silk_render_opts *o)
{
    o->mode = SILK_MODE_SMOOTH;
    o->tolerance_px = SILK_FX_HALF;
    o->visibility = SILK_VIS_AUTO;
    o->wire = 0;
    o->wire_rgb = 0x202020;
    o->wire_new_rgb = 0xE02020;
    o->bg_rgb = 0xFFFFFF;
    o->level = 3;
    o->pn_normals = SILK_PN_QUADRATIC;
    o->blend_beta = SILK_FX_C(1, 4);
    o->lines = SILK_LINES_NONE;
    o->lines_polygonal = 0;
    o->line_rgb = 0x000000;
    o->line_feature_rgb = 0x000000;
    o->silmap = NULL;
    o->silmap_hint = 0;
    o->siltex = NULL;
    o->aa = 1;
    o->clock = NULL;
    o->vertex_cache_bytes = SIZE_MAX;
}

const char *silk_stage_name(silk_stage s)
{
    switch (s) {
    case SILK_STAGE_VISIBILITY: return "visibility";
    case SILK_STAGE_PLAN: return "plan";
    case SILK_STAGE_EMIT: return "emit";
    case SILK_STAGE_VERTEX: return "vertex";
    case SILK_STAGE_RASTER: return "raster";
    case SILK_STAGE_COUNT: break;
    }
    return "?";
}

const char *silk_mode_name(silk_mode mode)
{
    switch (mode) {
    case SILK_MODE_FLAT: return "flat";
    case SILK_MODE_SMOOTH: return "smooth";
    case SILK_MODE_PN: return "pn";
    case SILK_MODE_BLEND: return "blend";
    case SILK_MODE_CLIP: return "clip";
    case SILK_MODE_SILTEX: return "siltex";
    }
    return "?";
}

/* What a frame keeps for speed where the arena has room, for the
 * shortcuts that take it (silk/config.h: SILK_VERTEX_CACHE,
 * SILK_DRAW_DIRECT, SILK_KEEP_SHARES, SILK_DEPTH_WINS, SILK_BACK_FACES_LAST,
 * SILK_AA_CANDIDATES, and the plan's SILK_KEEP_SEGMENTS and
 * SILK_CARRY_RANK): a field is NULL or 0 where it took none.  A build
 * without any of them has no frame_fast: silk_render's is compiled away,
 * and a small part's stack does not hold it (FRAME_FAST). */
typedef struct frame_fast {
    /* The vertex cache of a frame drawn share by share (vertex_cache),
     * or NULL: slot s holds the vertex stage's output for the corner
     * whose normal, vertex and uv are vc_tag[3s .. 3s+2]. */
    silk_vertex_out *vc;
    uint32_t *vc_tag;
    uint32_t vc_mask;
    uint8_t *cand;            /* closed mesh: silk_aa_candidates' bits, or NULL */
    uint8_t cand_ready;       /* made (by the first band's frame_aa) */
    /* SMOOTH: the shares that draw_direct does not draw as first built
     * (keep_shares): input triangle t's at ks + ks_at[t] - 1, ks_at[t] 0
     * until it is built */
    uint8_t *ks;
    uint32_t *ks_at;
    size_t ks_cap, ks_used;
    /* where g's arrays, the cache and the curves are when a share is built
     * (a kept share is read where it is kept: share_view) */
    silk_frame_geom home;
    silk_vertex_out *home_cache;
    /* the share in g as kept: where its records are placed, once *kxy_ready
     * (draw_tris); NULL when it is not kept */
    int32_t (*kxy)[2];
    uint32_t *kxy_ready;
    /* FLAT, and SMOOTH's input triangles drawn as they are (direct_ok):
     * where the rasterizer places the mesh's vertex p (position index),
     * vc_xy[2p .. 2p+1] (silk_raster_place), or VC_OUTSIDE (clipped), and
     * the vertex stage's clip coordinates of it, vc_clip[p], once xy_ready
     * (place_vertices); NULL when the triangles are not drawn straight from
     * the cache (draw_direct) */
    int32_t *vc_xy;
    silk_vec4 *vc_clip;
    uint8_t xy_ready;
    uint8_t all_before;       /* every vertex so placed lies in front of the near plane (before_near) */
    /* SMOOTH with a depth pass: per part, which of its triangles wrote a
     * depth in it (depth_wins), or NULL; and the back faces of its
     * re-meshed parts it draws last (back_last), room for back_cap */
    uint32_t *won;
    struct back_tri *back;
    uint32_t back_cap, nback;
    silk_sil_keep keep;       /* SMOOTH: what the plan keeps (silk_sil_frame.keep) */
} frame_fast;

/* Whether the build has a frame_fast: any of its shortcuts. */
#define FRAME_FAST (SILK_VERTEX_CACHE || SILK_DRAW_DIRECT || SILK_KEEP_SHARES || SILK_DEPTH_WINS || \
                    SILK_BACK_FACES_LAST || SILK_AA_CANDIDATES || SILK_SIL_KEEPS)

/* SILTEX: the hull drawn through the silhouette texture by these stages
 * (siltex.c), which kill the pixels where the detailed model is not seen.
 * silk_render's, compiled away without SILK_SILTEX_MODE. */
typedef struct frame_siltex {
    silk_hal hal;
    silk_siltex_stage stage;
} frame_siltex;

/* A frame ready to rasterize: geometry plus the vertex stage's output. */
typedef struct frame {
    const silk_hal *hal;
    silk_geom geom;
    silk_frame_geom g;
    silk_vertex_out *cache;   /* NULL when the arena could not hold it */
    silk_vertex_out *line_cache;   /* the same for the lines' records */
    uint32_t *line_lift;      /* per line record (lines.c), or NULL */
    /* A frame is drawn in nparts parts, part(f, k) filling g and cache
     * with part k: a frame drawn share by share has its input triangles'
     * shares, rebuilt one at a time; a stored frame is one part, all there. */
    uint32_t nparts;
    void (*part)(struct frame *f, uint32_t k);
    silk_stage_clock *clock;  /* per-stage timing, or NULL */
    uint8_t *rows;            /* per part: first and last row it can reach, in units of row_unit, or NULL */
    int row_unit;             /* rows a unit of rows[] spans (share_rows) */
    silk_clip *clip;          /* CLIP: the outline and its stencil (clip.c), else NULL */
    frame_siltex *siltex;     /* SILTEX: its stages, else NULL */
    frame_fast *fast;         /* what it keeps for speed, or NULL: a build without the shortcuts */
    uint8_t *facing;          /* silk_aa.facing for frame_aa, or NULL */
    size_t vc_bytes;          /* the arena the vertex cache, the facing memo and the rest of fast take */
    size_t tan_bytes;         /* the arena the kept edge tangents take (keep_tangents) */
    size_t peak_before;       /* the arena's top high-water before those */
    size_t reserve;           /* what a band's outline takes (outline_reserve): those leave it free */
    uint8_t smooth;           /* SMOOTH's plan made (else the coarse mesh's shares) */
    uint8_t cull;             /* back faces cannot show (back_faces_hidden) */
    uint8_t plain;            /* SMOOTH: the part drawn last is its input triangle as it is (bytes: the
                                 frame is on a small board's stack) */
    uint8_t in_scene;         /* one object of a scene (scene.c): the scene clears the band, not frame_draw */
    uint8_t after;            /* drawn after another object into the same depth: no depth pass (frame_draw) */
    silk_sil_frame sil;       /* SMOOTH: the plan (last: the fields above are read more often) */
} frame;

/* Whether f is a CLIP frame, a SILTEX one: never in a build without the mode. */
#define CLIP_FRAME(f) (SILK_CLIP_MODE && (f)->clip != NULL)
#define SILTEX_FRAME(f) (SILK_SILTEX_MODE && (f)->siltex != NULL)

/* Vertex stage output for record i: from the cache when the frame could
 * afford one, else recomputed (same bits either way: the stage is a pure
 * function of the record). */
static const silk_vertex_out *vertex_out(const frame *f, uint32_t i, silk_vertex_out *tmp)
{
    if (f->cache) return &f->cache[i];
    f->hal->vertex(f->hal, &f->geom, &f->g.vrec[i], tmp);
    return tmp;
}

/* Vertex i of the lines, lifted off the triangles it lies on. */
static void line_out(const frame *f, uint32_t i, silk_vertex_out *out)
{
    if (f->line_cache) *out = f->line_cache[i];
    else f->hal->vertex(f->hal, &f->geom, &f->g.line_vrec[i], out);
    silk_lines_apply_lift(out, f->line_lift ? f->line_lift[i] : 0);
}

/* ---- Frames drawn share by share ------------------------------------------------
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
 * triangles that reach into it. */

static int by_shares(const silk_render_opts *o)
{
    return o->lines == SILK_LINES_NONE &&
           (o->mode == SILK_MODE_FLAT || o->mode == SILK_MODE_SMOOTH || o->mode == SILK_MODE_CLIP);
}

static void share_part(frame *f, uint32_t t);

static silk_status shares_prepare(frame *f, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                  const silk_hal *h, const silk_render_opts *o, silk_frame_stats *stats,
                                  silk_error *err)
{
    f->nparts = m->ntris;
    f->part = share_part;
    f->hal = h;
    f->geom.mesh = m;
    if (o->mode == SILK_MODE_SMOOTH) {
        if (o->tolerance_px <= 0)
            return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_frame_smooth: tolerance must be positive");
        silk_arena_mark mark = silk_arena_top_mark(a);
        /* the plan's time without the visibility test's, which is inside it */
        uint32_t vis0 = f->clock ? f->clock->ticks[SILK_STAGE_VISIBILITY] : 0, t0 = silk_stage_start(f->clock);
        size_t peak0 = a->top_peak;
        silk_sil_keep *keep = SILK_SIL_KEEPS ? &f->fast->keep : NULL;
        if (keep) keep->room = o->vertex_cache_bytes;   /* silk_remesh_keep's budget: the vertex cache's */
        for (;;) {
            f->sil.keep = keep;
            f->smooth = silk_frame_smooth_plan(a, m, v, o->tolerance_px, o->visibility, f->clock, &f->sil, &f->g) &&
                        (f->cache = silk_arena_array_top(a, f->sil.max_recs, sizeof *f->cache, SILK_MEM_FRAME));
            if (!f->smooth && keep && keep->kept_bytes) {
                /* what the plan kept for speed took room the frame needs: again without */
                silk_arena_top_release(a, &mark);
                a->top_peak = peak0;
                keep->room = 0;
                continue;
            }
            break;
        }
        silk_stage_stop(f->clock, SILK_STAGE_PLAN, t0);
        if (f->clock) f->clock->ticks[SILK_STAGE_PLAN] -= f->clock->ticks[SILK_STAGE_VISIBILITY] - vis0;
        if (f->smooth) {
            silk_remesh_stats(&f->sil, stats);
            f->geom.curves = f->g.curve;
            f->geom.offsets = f->sil.offset;
            return SILK_OK;
        }
        /* the plan does not fit: the coarse mesh, as a stored frame falls back */
        silk_arena_top_release(a, &mark);
        f->cache = NULL;
        silk_frame_stats_fell_back(stats, m->ntris);
    }
    /* the coarse mesh, one input triangle's three CORNER records at a time */
    void *cache;
    silk_status st = silk_frame_flat_room(a, 1, 3 * sizeof *f->cache, &cache, &f->g, err);
    if (st != SILK_OK) return st;
    f->cache = cache;
    stats->tris_drawn = m->ntris;
    return SILK_OK;
}

/* The vertex stage for CORNER record r, through the vertex cache: the
 * default stage's output is a function of the corner's normal, vertex and
 * uv (silk_hal_vertex_by_attrs), so the corners of the six or so triangles
 * around a vertex are evaluated once, not once each.  The cache is
 * direct-mapped on the normal index: neighbouring triangles come close
 * together in a mesh, and a miss only costs the evaluation.  corner_slot
 * returns the slot holding the output for corner a (record r, or when r is
 * NULL the corner's own CORNER record, as silk_frame_flat_emit_tri makes
 * it), UINT32_MAX for a corner without a usable normal (not cached).
 * With clip not NULL, a miss takes the corner's clip coordinates from
 * there (draw_direct's, placed) and runs only the rest of the stage. */
#define VC_OUTSIDE INT32_MIN         /* vc_xy: outside a clip plane */
SILK_ALWAYS_INLINE   /* every corner of a streamed frame: inline in share_part, as a call it costs a tenth more */
static inline uint32_t corner_slot(const frame *f, uint32_t a, const silk_vrec *r, const silk_vec4 *clip)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    uint32_t n;
    if (a / 3 >= m->ntris || (n = m->tri_normal[a]) >= m->nnormals) return UINT32_MAX;
    uint32_t v = m->tri[a], uv = m->tri_uv ? m->tri_uv[a] : SILK_NO_INDEX;
    uint32_t s = n & x->vc_mask, *tag = &x->vc_tag[3 * s];
    if (tag[0] != n || tag[1] != v || tag[2] != uv) {
        const silk_vrec own = { SILK_VREC_CORNER, a, 0, 0 };
        if (SILK_DRAW_DIRECT && clip) {
            x->vc[s].clip = *clip;
            silk_hal_vertex_varyings(&f->geom, &own, &x->vc[s]);
        } else {
            f->hal->vertex(f->hal, &f->geom, r ? r : &own, &x->vc[s]);
        }
        tag[0] = n;
        tag[1] = v;
        tag[2] = uv;
    }
    return s;
}

static void corner_cached(const frame *f, const silk_vrec *r, silk_vertex_out *out)
{
    uint32_t s = corner_slot(f, r->a, r, NULL);
    if (s != UINT32_MAX) *out = f->fast->vc[s];
    else f->hal->vertex(f->hal, &f->geom, r, out);
}

/* Whether frame f has a vertex cache (vertex_cache). */
#define VERTEX_CACHED(f) (SILK_VERTEX_CACHE && (f)->fast->vc != NULL)

/* A kept share: its counts and whether it is placed, then its records,
 * curves, vertex-stage output, triangles and their flags, each a multiple
 * of 4 bytes, then where its records are placed on the screen (draw_tris,
 * once a frame: the place depends on the frame's size alone). */
#define KEPT_HEAD 5
static size_t share_bytes(uint32_t nvrec, uint32_t ntri, uint32_t ncurve)
{
    return KEPT_HEAD * sizeof(uint32_t) + (size_t)nvrec * (sizeof(silk_vrec) + sizeof(silk_vertex_out) + 2 * sizeof(int32_t)) +
           (size_t)ncurve * sizeof(silk_curve) + (size_t)ntri * 3 * sizeof(uint32_t) + (((size_t)ntri + 3) & ~(size_t)3);
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
 * back (share_copy): nothing drawn writes them.  share_part points them
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

static inline int direct_ok(const frame *f, uint32_t k);

/* Where input triangle t's share is kept: t, for every share draw_direct
 * does not draw (SILK_SIL_NONE: none, or a build without kept shares). */
static uint32_t share_kept(const frame *f, uint32_t t)
{
    return SILK_KEEP_SHARES && f->fast->ks && !direct_ok(f, t) ? t : SILK_SIL_NONE;
}

/* Input triangle t's share into g, through the vertex stage into cache. */
static void share_part(frame *f, uint32_t t)
{
    silk_frame_geom *g = &f->g;
    frame_fast *x = f->fast;
    uint32_t t0 = silk_stage_start(f->clock);
    uint32_t k = share_kept(f, t);
    if (k != SILK_SIL_NONE && x->ks_at[k]) {   /* built before: the same records, the same output */
        share_view(f, x->ks + x->ks_at[k] - 1);
        silk_stage_stop(f->clock, SILK_STAGE_EMIT, t0);
        return;
    }
    if (SILK_KEEP_SHARES && x->ks) {
        x->kxy = NULL;   /* (share_copy: where this one is kept) */
        if (g->vrec != x->home.vrec) {   /* home from a kept share */
            g->vrec = x->home.vrec;
            g->tri = x->home.tri;
            g->tri_added = x->home.tri_added;
            f->geom.curves = g->curve = x->home.curve;
            f->cache = x->home_cache;
        }
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
    size_t bytes = share_bytes(g->nvrec, g->ntri, g->ncurve);
    if (k != SILK_SIL_NONE && x->ks_cap - x->ks_used >= bytes) {
        share_copy(f, x->ks + x->ks_used);
        x->ks_at[k] = (uint32_t)x->ks_used + 1;
        x->ks_used += bytes;
    }
}

/* Whether frame_aa anti-aliases the outline of frame f in band t with
 * silk_aa_begin's scratch: not with wire, not a stored frame's, not where
 * there is no depth, not siltex's with lines (its fragment stage draws
 * them, aliased).  (Clip mode's is its own, clip.c.)  Not inlined:
 * frame_aa and outline_reserve share it. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int outline_wanted(const frame *f, const silk_render_opts *o, const silk_target *t)
{
    return SILK_AA && o->aa && !o->wire && f->part == share_part && t->depth && !(SILTEX_FRAME(f) && o->lines);
}

/* What siltex_outline takes for a band of t at most: colour, depth and
 * mask over its rows and their two aprons. */
static size_t siltex_outline_bytes(const silk_target *t)
{
    size_t w = (size_t)t->width, rows = (size_t)t->rows + 2, al = SILK_ARENA_ALIGN - 1;
    return ((w * rows * 3 + al) & ~al) + ((w * rows * sizeof(uint32_t) + al) & ~al) + ((rows * ((w + 7) / 8) + al) & ~al);
}

/* What frame_aa's silk_aa_begin takes for a band of t, or 0 where the
 * frame draws no outline.  What the frame keeps for speed comes from what
 * the arena has beyond it (spare), so that a frame given exactly its need
 * (silk_frame_stats.frame_bytes) draws every outline pixel. */
static size_t outline_reserve(const frame *f, const silk_render_opts *o, const silk_target *t)
{
    if (!SILK_AA || CLIP_FRAME(f) || !outline_wanted(f, o, t)) return 0;
    size_t bytes = silk_aa_bytes(t, f->smooth ? f->sil.max_recs : 3);
    if (SILTEX_FRAME(f)) bytes += siltex_outline_bytes(t);
    return bytes;
}

/* The arena free beyond the outline's reserve. */
static size_t spare(const frame *f, const silk_arena *a)
{
    size_t free_bytes = silk_arena_free_bytes(a);
    return free_bytes > f->reserve ? free_bytes - f->reserve : 0;
}

/* The vertex cache (corner_cached), from at most half of the arena left
 * once the frame has what it needs: a power of two slots, enough for every
 * normal of the mesh when there is room, else fewer (more misses, the same
 * bits), none below 64.  It is not part of the frame's need
 * (silk_frame_stats.frame_bytes): a frame without it is drawn the same. */
#define VCACHE_MAX 4096
static void vertex_cache(frame *f, silk_arena *a, const silk_render_opts *o)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    if (!SILK_VERTEX_CACHE || f->part != share_part || !m->tri_normal || !silk_hal_vertex_by_attrs(f->hal)) return;
    const size_t slot = sizeof *x->vc + 3 * sizeof *x->vc_tag, half = spare(f, a) / 2,
                 free0 = silk_arena_free_bytes(a);
    size_t room = half < o->vertex_cache_bytes ? half : o->vertex_cache_bytes;
    /* where each vertex of the mesh is placed (draw_direct: FLAT's
     * triangles, SMOOTH's away from the silhouette), when that fits with
     * the least cache */
    size_t xy = (size_t)m->nverts * (2 * sizeof *x->vc_xy + sizeof *x->vc_clip) + 2 * SILK_ARENA_ALIGN;
    if (!SILK_DRAW_DIRECT || xy + 64 * slot + 2 * SILK_ARENA_ALIGN > room) xy = 0;
    room -= xy;
    uint32_t n = 64;
    while (n < m->nnormals && n < VCACHE_MAX && (size_t)2 * n * slot + 2 * SILK_ARENA_ALIGN <= room) n *= 2;
    if ((size_t)n * slot + 2 * SILK_ARENA_ALIGN > room) return;
    /* unfilled: a slot is read only once its tag says it is written, a
     * vertex's place only once place_vertices has written every one */
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

/* The outline's memo of which way each input triangle faces
 * (silk_aa.facing), under the same budget as the vertex cache and, like
 * it, not part of the frame's need (and left out with its code,
 * SILK_VERTEX_CACHE 0): without it each triangle's facing is worked out
 * up to four times a band, with the same answers. */
static void facing_memo(frame *f, silk_arena *a, const silk_render_opts *o)
{
    if (!SILK_AA || !SILK_VERTEX_CACHE) return;
    size_t n = ((size_t)f->geom.mesh->ntris + 3) / 4, free0 = silk_arena_free_bytes(a), room = spare(f, a),
           budget = o->vertex_cache_bytes > f->vc_bytes ? o->vertex_cache_bytes - f->vc_bytes : 0;
    if (!o->aa || o->wire || f->part != share_part || CLIP_FRAME(f) || n + SILK_ARENA_ALIGN > budget ||
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

/* SMOOTH: the carrying edges' tangents kept (silk_sil_keep_tangents), as
 * many as fit the arena left once the frame has what it needs, its vertex
 * cache and the outline's reserve: 24 bytes an edge (a few KiB for all)
 * that spare remaking a bridge whenever an edge's curve is asked for, a
 * tenth to a sixth of a smooth frame's instructions.  Not part of the
 * frame's need either: a part without the room computes the same
 * tangents. */
static void keep_tangents(frame *f, silk_arena *a)
{
    if (f->smooth) f->tan_bytes = silk_sil_keep_tangents(&f->sil, spare(f, a));
}

/* SMOOTH: room for the shares of the triangles on, carrying or moved by
 * the silhouette as they are first built (share_part), which a frame builds again for the depth pass
 * and for the anti-aliased outline: under the vertex cache's budget, from
 * half of what the arena has left beyond the outline's reserve, as many as
 * fit.  Not part of the frame's need either. */
static void keep_shares(frame *f, silk_arena *a, const silk_render_opts *o)
{
    frame_fast *x = f->fast;
    uint32_t n = f->smooth ? f->geom.mesh->ntris : 0;   /* ks_at: per input triangle (share_kept) */
    if (!SILK_KEEP_SHARES || !n || n >= UINT32_MAX / 4) return;
    size_t free0 = silk_arena_free_bytes(a), reserve = 16 * SILK_ARENA_ALIGN, left = spare(f, a);
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

/* SMOOTH: which triangles of each part wrote a depth in the depth pass,
 * bit j of won[k] for triangle j of part k (bit 31 for triangle 31 and
 * every later one), so that the shading pass skips those that did not:
 * a pixel is shaded by the first triangle drawn that is as near as its
 * depth, which wrote that depth when the depth pass drew it (the depth
 * test passes only the strictly nearer), so a triangle that wrote none
 * shades none (docs/raster.md).  Most are faces seen from behind - the
 * silhouette triangles' re-meshed parts are drawn both ways (frame_draw)
 * - and faces hidden behind others; a part none of whose triangles wrote
 * is not even rebuilt.  (A fragment stage that discards could show a
 * triangle behind the discarded fragment at equal depth; none of silk's
 * stages that the depth pass draws with discards.)  4 bytes an input
 * triangle under the vertex cache's budget, only where frame_draw makes a
 * depth pass; without the room every triangle is shaded as before. */

/* A back face of a re-meshed part that the depth pass draws last
 * (back_last): where the rasterizer places its corners and their clip z
 * and w (all the depth needs), and which triangle of which part it is. */
typedef struct back_tri {
    int32_t xy[3][2];
    silk_fx z[3], w[3];
    uint32_t part, bit;
} back_tri;

#define BACK_MAX 1024   /* back_tri entries at most: a coarse mesh's silhouette has a few hundred */
static void depth_wins(frame *f, silk_arena *a, const silk_render_opts *o, const silk_target *t)
{
    if (!SILK_DEPTH_WINS) return;
    frame_fast *x = f->fast;
    uint64_t n = f->geom.mesh->ntris;
    size_t free0 = silk_arena_free_bytes(a), bytes = (size_t)n * sizeof *x->won + SILK_ARENA_ALIGN,
           budget = o->vertex_cache_bytes > f->vc_bytes ? o->vertex_cache_bytes - f->vc_bytes : 0;
    if (!f->smooth || n * 16 > (uint64_t)t->width * t->height || bytes > budget || bytes > spare(f, a) / 2) return;
    x->won = silk_arena_array_top(a, n, sizeof *x->won, SILK_MEM_FRAME);   /* each written in the depth pass */
    /* the back faces put off, from what is left of the budget and of half the arena */
    size_t left = budget - bytes, free1 = spare(f, a) / 2, cap = BACK_MAX;
    if (left > free1) left = free1;
    if (cap > left / sizeof *x->back) cap = left / sizeof *x->back;
    if (SILK_BACK_FACES_LAST && x->won && cap > 16 &&
        (x->back = silk_arena_array_top_unfilled(a, cap, sizeof *x->back, SILK_MEM_FRAME)))
        x->back_cap = (uint32_t)cap;
    f->vc_bytes += free0 - silk_arena_free_bytes(a);
}

/* The rows each input triangle can reach.  Everything drawn for it lies in
 * the screen triangles of its share's records, so between their highest and
 * lowest row; one row more on each side covers the rasterizer's rounding to
 * subpixels.  A record behind the eye plane (w <= 0) may reach anywhere.
 * f->rows is 2 bytes per input triangle, or NULL: without room for the rows
 * every band rebuilds every triangle: slower, the same pixels.  A byte
 * counts units of f->row_unit rows, the fewest that number a frame's rows
 * below 255 (one row up to 254 rows high, so on a small display the rows
 * are exact); the first and last unit are rounded outwards, so a band may
 * rebuild a triangle it does not need, never miss one.  The pair 255, 0
 * reaches no row. */
static int part_hidden(const frame *f, const silk_render_opts *o, const silk_target *band);

static void share_rows(frame *f, const silk_render_opts *o, const silk_target *band)
{
    uint32_t n = f->geom.mesh->ntris;
    int height = band->height;
    f->row_unit = height / 255 + 1;   /* 255 units more than the height: 255, 0 is past every band */
    for (uint32_t t = 0; f->rows && t < n; t++) {
        share_part(f, t);
        int64_t lo = height, hi = -1;
        if (part_hidden(f, o, band)) {                   /* no band draws it: none rebuilds it */
            f->rows[2 * t] = UINT8_MAX;
            f->rows[2 * t + 1] = 0;
            continue;
        }
        for (uint32_t i = 0; i < f->g.nvrec; i++) {
            const silk_vec4 *c = &f->cache[i].clip;
            if (c->w <= 0) {
                lo = 0;
                hi = height - 1;
                break;
            }
            int64_t y = silk_raster_row(c, height);
            if (y - 1 < lo) lo = y - 1;
            if (y + 1 > hi) hi = y + 1;
        }
        if (lo < 0) lo = 0;
        if (hi > height - 1) hi = height - 1;
        f->rows[2 * t] = lo <= hi ? (uint8_t)(lo / f->row_unit) : UINT8_MAX;   /* never reached: no band takes it */
        f->rows[2 * t + 1] = lo <= hi ? (uint8_t)(hi / f->row_unit) : 0;
    }
}

/* Whether the part just built draws nothing in any band: frame_draw culls
 * back faces for it (a plain share, or any share of a FLAT frame: one
 * triangle of corners) and silk_raster_culled says its triangle is culled
 * or outside the view.  Only where frame_draw is all that draws the parts
 * (no outline anti-aliasing, wire, lines, stencil or SILTEX), so that a
 * band need not rebuild it. */
static int part_hidden(const frame *f, const silk_render_opts *o, const silk_target *band)
{
    int aa = SILK_AA ? o->aa : 0;   /* (a build without them: o->aa draws nothing) */
    if (!f->cull || (f->smooth && !f->plain) || f->g.ntri != 1 || aa || o->wire || o->lines || SILTEX_FRAME(f) || CLIP_FRAME(f))
        return 0;
    const uint32_t *c = f->g.tri;
    return silk_raster_culled(band, &f->cache[c[0]], &f->cache[c[1]], &f->cache[c[2]]);
}

/* Whether part k can reach no row of y0 .. y1 (share_rows). */
static int part_misses(const frame *f, uint32_t k, int y0, int y1)
{
    if (!f->rows) return 0;
    int u = f->row_unit;
    return f->rows[2 * k] * u > y1 || f->rows[2 * k + 1] * u + u - 1 < y0;
}

/* A stored frame's one part is there already. */
static void stored_part(frame *f, uint32_t k)
{
    (void)f;
    (void)k;
}

/* CLIP: the hull drawn as flat draws a mesh, through the stencil of the
 * outline interpolated from the silhouette map (clip.c), band_rows high. */
static silk_status clip_prepare(frame *f, silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                                const silk_render_opts *o, int band_rows, silk_frame_stats *stats, silk_error *err)
{
    if (!o->silmap)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: clip mode needs the model's silhouette map");
    if (o->lines)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: no lines in clip mode (the outline is the map's)");
    f->clip = silk_arena_alloc_top(a, sizeof *f->clip, SILK_MEM_FRAME);
    if (!f->clip) return silk_fail(err, SILK_ERR_NOMEM, NULL, 0, "silk_render: the arena is full");
    silk_status st = silk_clip_prepare(f->clip, a, o->silmap, v, o->silmap_hint, band_rows, o->aa, err);
    if (st != SILK_OK) return st;
    stats->clip_tri = f->clip->info.tri;
    stats->clip_points = f->clip->npts;
    silk_clip *c = f->clip;
    st = shares_prepare(f, a, m, v, h, o, stats, err);
    f->clip = c;
    return st;
}

/* SILTEX: the hull drawn as flat draws a mesh, each pixel through eq. 4 of
 * the silhouette texture, by the stages of sx (siltex.c). */
static silk_status siltex_prepare(frame *f, frame_siltex *sx, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                  const silk_hal *h, const silk_render_opts *o, silk_frame_stats *stats,
                                  silk_error *err)
{
    if (!o->siltex)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: siltex mode needs the model's silhouette texture");
    if (o->siltex->ntris != m->ntris || o->siltex->nverts != m->nverts)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0,
                         "silk_render: the silhouette texture is for a hull of %lu triangles, the mesh has %lu",
                         (unsigned long)o->siltex->ntris, (unsigned long)m->ntris);
    f->siltex = sx;
    sx->stage.tex = o->siltex;
    sx->stage.shade = h;
    sx->stage.view = v;
    /* lines (eq. 5) sized for an edge crossed a sixteenth of the hull's
     * diagonal away from it */
    sx->stage.lines = (int)o->lines;
    sx->stage.line_rgb = o->line_rgb;
    sx->stage.bg_rgb = o->bg_rgb;
    sx->stage.line_q = silk_siltex_line_width(v, silk_v3_length(silk_v3_sub(m->bbox_max, m->bbox_min)) / 16);
    silk_siltex_hal(&sx->hal, &sx->stage);
    return shares_prepare(f, a, m, v, &sx->hal, o, stats, err);
}

/* A stored frame's geometry in f->g: the mode's frame (flat.c, smooth.c,
 * pn.c, blend.c), and the polygonal lines where asked for.  *smooth_lines:
 * whether its lines are the smooth curves, which only SMOOTH has (FLAT
 * outlines the coarse mesh it draws). */
static silk_status stored_geometry(frame *f, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                   const silk_render_opts *o, int *smooth_lines, silk_frame_stats *stats,
                                   silk_error *err)
{
    silk_status st;
    *smooth_lines = o->lines && !o->lines_polygonal && o->mode == SILK_MODE_SMOOTH;
    if (o->mode == SILK_MODE_SMOOTH)
        st = silk_frame_smooth_lines(a, m, v, o->tolerance_px, o->visibility, *smooth_lines, &f->g, stats, err);
    else if (o->mode == SILK_MODE_FLAT)
        st = silk_frame_flat(a, m, &f->g, err);
    else if (SILK_REFERENCE_MODES && o->mode == SILK_MODE_PN)
        st = silk_frame_pn(a, m, o->level, o->pn_normals, &f->g, stats, err);
    else if (SILK_REFERENCE_MODES && o->mode == SILK_MODE_BLEND)
        st = silk_frame_blend(a, m, v, o->blend_beta, o->tolerance_px, &f->g, stats, err);
    else if (o->mode == SILK_MODE_PN || o->mode == SILK_MODE_BLEND)
        st = silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: %s mode is not built in (SILK_REFERENCE_MODES 0)",
                       silk_mode_name(o->mode));
    else
        st = silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown mode %d", (int)o->mode);
    if (st == SILK_OK && o->lines && !*smooth_lines &&
        silk_lines_polygonal(a, m, v, o->mode == SILK_MODE_FLAT, &f->g) != SILK_OK)
        silk_frame_fell_short(stats);
    return st;
}

/* A stored frame (PN, BLEND, and FLAT and SMOOTH with lines): one part,
 * every record through the vertex stage once, and its lines. */
static silk_status stored_prepare(frame *f, silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                                  const silk_render_opts *o, silk_frame_stats *stats, silk_error *err)
{
    f->hal = h;
    f->nparts = 1;
    f->part = stored_part;
    int smooth_lines;
    silk_status st = stored_geometry(f, a, m, v, o, &smooth_lines, stats, err);
    if (st != SILK_OK) return st;

    f->geom.mesh = m;
    f->geom.curves = f->g.curve;
    f->geom.offsets = f->g.offset;
    f->geom.patches = f->g.patch;
    /* Without room for the cache the frame is still drawn, only slower. */
    f->cache = silk_arena_array_top(a, f->g.nvrec, sizeof *f->cache, SILK_MEM_FRAME);
    if (f->cache)
        for (uint32_t i = 0; i < f->g.nvrec; i++) h->vertex(h, &f->geom, &f->g.vrec[i], &f->cache[i]);
    /* Smooth lines: where the outline leaves the silhouette segments, the
     * contour of the drawn triangles closes it (it needs the vertex stage's
     * output; without room for it the frame says so). */
    if (smooth_lines && (!f->cache || silk_lines_contour(a, &f->g, f->cache, v->cam.width, v->cam.height) != SILK_OK))
        silk_frame_fell_short(stats);
    f->line_cache = silk_arena_array_top(a, f->g.nline_vrec, sizeof *f->line_cache, SILK_MEM_FRAME);
    if (f->line_cache)
        for (uint32_t i = 0; i < f->g.nline_vrec; i++)
            h->vertex(h, &f->geom, &f->g.line_vrec[i], &f->line_cache[i]);
    f->line_lift = silk_lines_lift(a, m, &f->g, f->cache, v->cam.width, v->cam.height);
    /* Without their lift (no room for it or for the vertex cache it reads)
     * lines sink into the surface they lie on: the frame says so, as one
     * that could not smooth does. */
    if (f->g.nline_vrec && f->g.line_src && !f->line_lift) silk_frame_fell_short(stats);
    stats->tris_drawn = f->g.ntri;
    return SILK_OK;
}

/* Frame f's geometry for options o, its parts ready to draw, with room for
 * what only some builds keep (silk_render's: fast for the shortcuts, sx
 * for SILTEX mode, NULL in a build without them).  Refused options are
 * SILK_ERR_ARG, and so is a mode the build leaves out. */
static silk_status frame_prepare(frame *f, frame_fast *fast, frame_siltex *sx, silk_arena *a, const silk_mesh *m,
                                 const silk_view *v, const silk_hal *h, const silk_render_opts *o, int band_rows,
                                 silk_frame_stats *stats, silk_error *err)
{
    memset(f, 0, sizeof *f);   /* first: frame_need reads it even when the frame is refused */
    f->fast = fast;
    if (fast) memset(fast, 0, sizeof *fast);
    if (!a || !m || !v || !h || !o || !h->vertex || !h->fragment)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: missing argument");
    if ((unsigned)o->lines > SILK_LINES_ONLY)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown lines setting %d", (int)o->lines);
    /* The patches of PN and BLEND bulge over the coarse mesh, so its edges
     * are not their outline: there only the polygonal lines, on request. */
    if (o->lines && !o->lines_polygonal && (o->mode == SILK_MODE_PN || o->mode == SILK_MODE_BLEND))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0,
                         "silk_render: lines follow the outline in flat and smooth mode only (%s mode: "
                         "polygonal lines, the coarse mesh's, only)", silk_mode_name(o->mode));
    if (!SILK_LINES && (o->lines || o->wire))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: lines and wire are not built in (SILK_LINES 0)");
    f->clock = o->clock;
    if (o->mode == SILK_MODE_CLIP)
        return SILK_CLIP_MODE ? clip_prepare(f, a, m, v, h, o, band_rows, stats, err)
                              : silk_fail(err, SILK_ERR_ARG, NULL, 0,
                                          "silk_render: clip mode is not built in (SILK_CLIP_MODE 0)");
    if (o->mode == SILK_MODE_SILTEX)
        return SILK_SILTEX_MODE ? siltex_prepare(f, sx, a, m, v, h, o, stats, err)
                                : silk_fail(err, SILK_ERR_ARG, NULL, 0,
                                            "silk_render: siltex mode is not built in (SILK_SILTEX_MODE 0)");
    if (by_shares(o)) return shares_prepare(f, a, m, v, h, o, stats, err);
    if (SILK_STORED_FRAMES) return stored_prepare(f, a, m, v, h, o, stats, err);
    if (o->mode == SILK_MODE_PN || o->mode == SILK_MODE_BLEND)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: %s mode is not built in (SILK_REFERENCE_MODES 0)",
                         silk_mode_name(o->mode));
    return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown mode %d", (int)o->mode);
}

/* Whether point p lies in front of the near plane as the rasterizer clips:
 * z >= -w (raster.c), strictly. */
static int before_near(const silk_view *v, silk_vec3 p)
{
    silk_vec4 c = silk_view_clip(v, p);
    return c.w > 0 && (int64_t)c.z + c.w > 0;
}

/* Whether the sphere about the bounding box's centre through the farthest
 * vertex lies in front of the near plane (eye depth znear, in perspective
 * and orthographic alike), by a margin far above the rounding of
 * silk_view_clip: then every vertex does, at a fraction of the cost of
 * transforming each. */
static int sphere_before_near(const silk_mesh *m, const silk_view *v)
{
    int64_t c[3] = { ((int64_t)m->bbox_min.x + m->bbox_max.x) / 2, ((int64_t)m->bbox_min.y + m->bbox_max.y) / 2,
                     ((int64_t)m->bbox_min.z + m->bbox_max.z) / 2 };
    uint64_t r2 = 0;   /* coordinates below 2^26: each square below 2^54 */
    for (uint32_t i = 0; i < m->nverts; i++) {
        int64_t dx = m->pos[i].x - c[0], dy = m->pos[i].y - c[1], dz = m->pos[i].z - c[2];
        uint64_t d2 = (uint64_t)(dx * dx) + (uint64_t)(dy * dy) + (uint64_t)(dz * dz);
        if (d2 > r2) r2 = d2;
    }
    int64_t r = (int64_t)silk_isqrt64(r2) + 1;
    const silk_vec3 *e = &v->cam.eye, *fw = &v->forward;
    int64_t depth = ((c[0] - e->x) * fw->x + (c[1] - e->y) * fw->y + (c[2] - e->z) * fw->z) >> 16;
    int64_t margin = (r >> 10) + (int64_t)(silk_abs64(depth) >> 10) + (v->cam.znear >> 10) + 256;
    return depth - r - margin > v->cam.znear;
}

/* Whether the frame's back faces cannot show, so the rasterizer may skip
 * them.  A closed surface wound outward (silk_mesh.closed_outward) seen
 * from outside hides its back faces behind its front faces: along any ray
 * from the eye the first crossing enters the solid, through a front face,
 * and is the nearest.  The rasterizer's snapped triangles still form a
 * closed surface in screen x, y and depth, so this holds pixel for pixel.
 * The eye is outside when the whole mesh lies in front of the near plane
 * (then also no triangle is cut open by it): its bounding box or the
 * sphere about the box's centre through the farthest vertex when that does
 * (a camera fitted to the bounding sphere may cut the box's corners), else
 * every vertex as the vertex stage projects it; the default vertex stage's
 * view tells where the mesh goes (a stage of the caller's own may move or
 * mirror it).  FLAT, and in SMOOTH frames drawn share by share only the
 * input triangles drawn as they are (frame_draw): SMOOTH re-meshes and
 * moves vertices near the silhouette, where the outline is made of both
 * sides, so those triangles are all drawn (skipping a re-meshed part seen
 * wholly from behind changed pixels of self-intersecting meshes, which a
 * board must draw as the host does); PN and BLEND bulge. */
static int back_faces_hidden(const frame *f, const silk_mesh *m, const silk_hal *h, const silk_render_opts *o)
{
    const silk_view *v = silk_hal_vertex_view(h);
    if (!m->closed_outward || !v || (o->mode != SILK_MODE_FLAT && f->part != share_part)) return 0;
    int corners_before = 1;   /* the bounding box's: then every vertex is */
    for (int i = 0; corners_before && i < 8; i++)
        corners_before = before_near(v, silk_v3(i & 1 ? m->bbox_max.x : m->bbox_min.x,
                                                i & 2 ? m->bbox_max.y : m->bbox_min.y,
                                                i & 4 ? m->bbox_max.z : m->bbox_min.z));
    if (corners_before) return 1;
    /* every vertex placed already (frame_extras): by the same stage, so the
     * answer of the loop below, without another pass over the mesh */
    if (SILK_DRAW_DIRECT && f->fast->xy_ready && f->hal == h) return f->fast->all_before;
    if (sphere_before_near(m, v)) return 1;
    for (uint32_t i = 0; i < m->nverts; i++)
        if (!before_near(v, m->pos[i])) return 0;
    return 1;
}

/* The depth pass of a SMOOTH frame (depth_wins) puts off the back faces
 * of its re-meshed parts, drawn both ways (frame_draw), until every other
 * triangle has written its depth (back_draw): then most of them are
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
static int back_last(frame *f, const silk_target *t, const int32_t *const p[3], const uint32_t c[3], uint32_t part,
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

/* The back faces back_last put off, into the depth buffer, each noting
 * its part's win. */
static void back_draw(frame *f, silk_target *t)
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

/* Pass 0: g's triangles.  Passes 1 and 2 (--wire): the edges of the
 * original triangles, then of the added ones, so their red stays on top. */
#define PART_XY 64   /* draw_tris: the most records of a share placed once */
static void draw_tris(frame *f, const silk_render_opts *o, silk_target *t, int pass, uint32_t *won)
{
    const silk_frame_geom *g = &f->g;
    silk_vertex_out tmp[3];
    /* Lines alone: the surface is drawn into the depth buffer only, to hide them. */
    const silk_hal *shade = (o->lines == SILK_LINES_ONLY && !SILTEX_FRAME(f)) || pass < 0 ? NULL : f->hal;   /* SILTEX: its stage draws its lines */
    /* A share's records placed on the screen once (silk_raster_place), not
     * once for each of its triangles at them (SILK_PLACE_ONCE): the
     * triangles that cover no pixel centre - most of a re-meshed part of a
     * fine mesh - are then known from the places alone
     * (silk_raster_reaches), all drawn with the bits silk_raster_triangle
     * would give them (silk_raster_placed); a triangle at a record outside
     * a clip plane goes to silk_raster_triangle as before. */
    int32_t own[PART_XY][2], (*xy)[2] = own;
    int placed = SILK_PLACE_ONCE && pass <= 0 && f->part == share_part && f->cache && g->nvrec <= PART_XY;
    /* the test pays where triangles are small (as frame_draw's depth pass
     * is made only where they are large): elsewhere most of them reach a
     * pixel, and silk_raster_placed finds the others as cheaply */
    int ask = (uint64_t)f->geom.mesh->ntris * 16 > (uint64_t)t->width * t->height;
    int32_t (*kxy)[2] = SILK_KEEP_SHARES && placed ? f->fast->kxy : NULL;
    if (kxy) xy = kxy;   /* a kept share: placed there, once a frame */
    for (uint32_t i = 0; placed && !(kxy && *f->fast->kxy_ready) && i < g->nvrec; i++)
        if (!silk_raster_place(t, &f->cache[i].clip, xy[i])) xy[i][0] = VC_OUTSIDE;
    if (kxy) *f->fast->kxy_ready = 1;
    for (uint32_t i = 0; i < g->ntri; i++) {
        uint32_t k = t->depth_equal ? g->ntri - 1 - i : i;   /* see frame_draw */
        const uint32_t *c = &g->tri[3 * k];
        int added = g->tri_added && g->tri_added[k];
        uint32_t bit = 1u << (k < 31 ? k : 31);   /* depth_wins */
        int wins = SILK_DEPTH_WINS && won;
        if (wins && pass == 0 && !(*won & bit)) continue;
        if (SILK_DEPTH_WINS) t->drew = 0;
        if (placed && xy[c[0]][0] != VC_OUTSIDE && xy[c[1]][0] != VC_OUTSIDE && xy[c[2]][0] != VC_OUTSIDE) {
            const int32_t *p[3] = { xy[c[0]], xy[c[1]], xy[c[2]] };
            if (wins && pass < 0 && back_last(f, t, p, c, (uint32_t)(won - f->fast->won), bit)) continue;
            if (!ask || silk_raster_reaches(t, p)) {
                const silk_vertex_out *v[3] = { &f->cache[c[0]], &f->cache[c[1]], &f->cache[c[2]] };
                silk_raster_placed(t, shade, v, p);
                if (wins && pass < 0 && t->drew) *won |= bit;
            }
            continue;
        }
        if (pass <= 0) {
            silk_raster_triangle(t, shade, vertex_out(f, c[0], &tmp[0]), vertex_out(f, c[1], &tmp[1]),
                                 vertex_out(f, c[2], &tmp[2]));
            if (wins && pass < 0 && t->drew) *won |= bit;
        } else if (SILK_LINES && added == pass - 1) {
            for (int e = 0; e < 3; e++)
                silk_raster_line(t, vertex_out(f, c[e], &tmp[0]), vertex_out(f, c[(e + 1) % 3], &tmp[1]),
                                 added ? o->wire_new_rgb : o->wire_rgb);
        }
    }
}

/* Every vertex of the mesh placed on the screen of t (vc_xy) for
 * draw_direct, once a frame, before its first triangle is drawn (vertices
 * that only triangles outside the band use are so few it is cheaper than
 * asking), and whether all lie in front of the near plane (all_before),
 * which back_faces_hidden would otherwise ask in a pass of its own.
 * The stage clock counts it as the rasterizer's, as draw_direct's vertex
 * stage: the vertex stage's pieces are the shares emitted. */
static void place_vertices(frame *f, const silk_target *t)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    uint32_t t0 = silk_stage_start(f->clock);
    int before = 1;
    for (uint32_t p = 0; p < m->nverts; p++) {
        const silk_vec4 *c = &x->vc_clip[p];
        x->vc_clip[p] = silk_hal_vertex_clip(f->hal, m->pos[p]);
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
 * a frame (place_vertices: silk_raster_place of the vertex stage's clip
 * position alone), so that the triangles the rasterizer would draw nothing of -
 * seen from behind, zero area, between pixel centres or outside the band,
 * most of a fine mesh's - cost a few comparisons and no vertex stage; the
 * others go to silk_raster_triangle with the bits the share would give
 * it.  0 when a corner has no usable vertex or is not cached (no usable
 * normal, or two corners in one slot): the caller then builds the share
 * as usual.  (The stage clock counts the vertex stage run here as the
 * rasterizer's: a clock per corner would cost more than the look-up.) */
static int draw_direct(frame *f, silk_target *t, const silk_hal *shade, uint32_t k)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    /* written out (every triangle of the mesh comes here every band) */
    const silk_index *tv = &m->tri[3 * (size_t)k];
    const uint32_t nv = m->nverts;
    if (tv[0] >= nv || tv[1] >= nv || tv[2] >= nv) return 0;
    const int32_t *xy[3] = { &x->vc_xy[2 * (size_t)tv[0]], &x->vc_xy[2 * (size_t)tv[1]], &x->vc_xy[2 * (size_t)tv[2]] };
    int placed = (xy[0][0] != VC_OUTSIDE) & (xy[1][0] != VC_OUTSIDE) & (xy[2][0] != VC_OUTSIDE);
    t->cull_back = f->cull;   /* frame_draw's rule for triangles drawn as they are */
    if (placed && !silk_raster_reaches(t, xy)) return 1;
    const silk_vertex_out *v[3];
    uint32_t s[3];
    for (uint32_t i = 0; i < 3; i++) {
        if ((s[i] = corner_slot(f, 3 * k + i, NULL, &x->vc_clip[m->tri[3 * k + i]])) == UINT32_MAX) return 0;
        v[i] = &x->vc[s[i]];
    }
    if (s[0] == s[1] || s[1] == s[2] || s[2] == s[0]) return 0;   /* a later corner may have taken an earlier's slot */
    if (placed) silk_raster_placed(t, shade, v, xy);
    else silk_raster_triangle(t, shade, v[0], v[1], v[2]);
    return 1;
}

/* Whether input triangle k may be drawn by draw_direct: in FLAT every one;
 * in SMOOTH one away from the silhouette, neither on it nor carrying its
 * points, with no vertex moved, whose share is its three CORNER records
 * (silk_remesh_emit_tri), drawn with back faces culled (frame_draw) as
 * draw_direct does. */
static inline int direct_ok(const frame *f, uint32_t k)
{
    if (!f->smooth) return 1;
    const silk_sil_frame *s = &f->sil;
    if (s->tri_state[k] & (SILK_TS_SIL | SILK_TS_CARRY)) return 0;
    const silk_index *tv = &f->geom.mesh->tri[3 * (size_t)k];
    const silk_plan_index *vo = s->vert_offset;
    return !vo || (vo[tv[0]] == SILK_PLAN_NONE && vo[tv[1]] == SILK_PLAN_NONE && vo[tv[2]] == SILK_PLAN_NONE);
}

/* The pen-and-ink lines over band t (lines.c), depth-tested. */
static void draw_lines(const frame *f, const silk_render_opts *o, silk_target *t)
{
    const silk_frame_geom *g = &f->g;
    silk_vertex_out tmp[2];
    for (uint32_t i = 0; i < g->nlines; i++) {
        uint32_t rgb = g->line_feature[i] ? o->line_feature_rgb : o->line_rgb;
        uint32_t j = g->line_start[i], end = g->line_start[i + 1];
        if (j == end) continue;
        line_out(f, j, &tmp[0]);
        for (; j + 1 < end; j++) {
            line_out(f, j + 1, &tmp[1]);
            silk_raster_line(t, &tmp[0], &tmp[1], rgb);
            tmp[0] = tmp[1];
        }
    }
}

/* The frame's triangles part by part (only the parts that reach into the
 * band), then the lines. */
static void frame_draw(frame *f, const silk_render_opts *o, silk_target *t)
{
    frame_fast *x = f->fast;
    uint32_t t0 = silk_stage_start(f->clock);
    if (!(SILK_SCENES && f->in_scene)) silk_target_clear(t, o->bg_rgb);   /* a scene's band is cleared or painted once, by scene.c */
    silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
    if (CLIP_FRAME(f)) silk_clip_stencil(f->clip, t);
    /* Pass -1 draws depth only; pass 0 then shades where a fragment is as
     * near as the nearest, so each pixel is shaded once (docs/raster.md).
     * In reverse order: of fragments at equal depth the first drawn keeps
     * the pixel, as in a single pass.  It doubles the per-triangle work, so
     * only where triangles are large (16 pixels on average or more), and
     * not in a band of a frame drawn share by share: there it would also
     * rebuild every share twice a band, which costs more than the shading
     * it spares (a smooth bunny-500 frame on the Cortex-M3 board: 47 M
     * instructions with it, 37 M without; docs/small-devices.md). */
    uint64_t ntri = f->part == share_part ? f->geom.mesh->ntris : f->g.ntri;
    /* (not in SILTEX, whose fragment stage decides which pixels take a depth) */
    int depth_first = t->depth && o->lines != SILK_LINES_ONLY && ntri * 16 <= (uint64_t)t->width * t->height &&
                      !SILTEX_FRAME(f) && (f->part != share_part || t->rows >= t->height) &&
                      !(SILK_SCENES && f->after);   /* scene.c: its shading pass would take pixels another object ties in depth */
    uint32_t *wins = NULL;   /* depth_wins, where there is a depth pass */
    if (SILK_DRAW_DIRECT && x->vc_xy && !x->xy_ready) place_vertices(f, t);
    if (SILK_DEPTH_WINS && depth_first) wins = x->won;
    for (int pass = depth_first ? -1 : 0; pass < (o->wire ? 3 : 1); pass++) {
        for (uint32_t i = 0; i < f->nparts; i++) {
            t->depth_equal = pass == 0 && depth_first;
            uint32_t k = t->depth_equal ? f->nparts - 1 - i : i;
            uint32_t *won = NULL;
            if (wins && pass <= 0) {
                won = &wins[k];
                if (pass < 0) *won = 0;
                else if (!*won) continue;   /* no pixel to shade: not rebuilt */
            }
            if (part_misses(f, k, t->y0, t->y0 + t->rows - 1)) continue;
            if (SILK_DRAW_DIRECT && pass <= 0 && x->vc_xy && (!f->smooth || direct_ok(f, k))) {
                t0 = silk_stage_start(f->clock);
                t->drew = 0;
                int drawn = draw_direct(f, t, pass < 0 ? NULL : f->hal, k);
                silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
                if (drawn) {
                    if (won) *won |= (uint32_t)t->drew;   /* depth_wins: one triangle (shading pass: set already) */
                    continue;
                }
            }
            f->part(f, k);
            t->cull_back = pass <= 0 && f->cull && (!f->smooth || f->plain);   /* --wire draws every edge */
            /* SILTEX: a back face of the hull is seen from inside it, where
             * no visibility function was made: hull behind shows instead */
            t->cull_back |= pass <= 0 && SILTEX_FRAME(f);
            t0 = silk_stage_start(f->clock);
            draw_tris(f, o, t, pass, won);
            silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
        }
        if (SILK_BACK_FACES_LAST && x->nback) {   /* the depth pass's back faces put off (back_last) */
            t0 = silk_stage_start(f->clock);
            back_draw(f, t);
            silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
        }
    }
    t->depth_equal = t->cull_back = 0;
    if (CLIP_FRAME(f)) t->mask = NULL;   /* frame_aa anti-aliases its outline */
    if (SILK_LINES && o->lines) draw_lines(f, o, t);
}

/* The outline of input triangle k drawn as it is (direct_ok) without
 * building its share: silk_aa_share reads of such a share its one
 * triangle of three records and their clip coordinates, which
 * place_vertices has worked out.  0 when they are not placed or a corner
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
        uint32_t p = m->tri[3 * k + i];
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
        if (!cand[k / 8]) k |= 7;   /* eight at once, as frame_aa skips them */
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
        SILK_PREFETCH(&m->tri[3 * (size_t)c2]);
        if (m->tri_edge) SILK_PREFETCH(&m->tri_edge[3 * (size_t)c2]);
    }
    for (uint32_t i = 0; c1 < f->nparts && i < 3; i++) {
        uint32_t p = m->tri[3 * (size_t)c1 + i], e = m->tri_edge ? m->tri_edge[3 * (size_t)c1 + i] : SILK_NO_INDEX;
        if (p < m->nverts) SILK_PREFETCH(&f->fast->vc_clip[p]);
        if (e < m->nedges) SILK_PREFETCH(&m->edge[e]);
    }
}

/* SILTEX: the hull's front faces into s, every part that reaches its
 * rows, as frame_draw draws them (back faces culled): through stage h, or
 * depth alone (h NULL). */
static void hull_draw(frame *f, const silk_render_opts *o, silk_target *s, const silk_hal *h)
{
    const silk_hal *shade = f->hal;
    for (uint32_t k = 0; k < f->nparts; k++) {
        if (part_misses(f, k, s->y0, s->y0 + s->rows - 1)) continue;
        f->part(f, k);
        s->cull_back = 1;
        uint32_t t0 = silk_stage_start(f->clock);
        f->hal = h ? h : shade;   /* the same vertex stage: the part's output stands */
        draw_tris(f, o, s, h ? 0 : -1, NULL);
        f->hal = shade;
        silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
    }
    s->cull_back = 0;
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
    hull_draw(f, o, &s, NULL);
    if (silk_aa_margin_mask(aa, &s, mask)) {
        silk_hal margin;
        silk_siltex_margin_hal(&margin, &f->siltex->stage);
        s.depth_equal = 1;   /* the front faces alone */
        hull_draw(f, o, &s, &margin);
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
        f->part(f, k);
        silk_aa_share(aa, f->geom.mesh, v, &f->g, f->cache, k);
    }
}

/* Frame f's outlines walked into aa, begun over the band just drawn
 * (frame_aa; scene.c walks every object's into one): its shares', or
 * SILTEX's found in the band. */
static void frame_outline(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_aa *aa,
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

/* Anti-aliased outlines over band t, just drawn: CLIP's (clip.c: the
 * map's outline, whatever the build), and those of aa.c (a build with
 * SILK_AA 0 leaves them out: about 3.0 KiB of Cortex-M3 code and a band's
 * worth of scratch): of the frames drawn share by share (FLAT and SMOOTH
 * without lines, and SILTEX's, from eq. 4 itself), not under --wire's
 * edges.  The shares that can hold an outline are rebuilt once more; a
 * band that is not the whole frame first draws the rows next to it, which
 * its edge pixels blend with. */
static void frame_aa(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_target *t,
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
    int wanted = outline_wanted(f, o, t);
    if (!wanted || !silk_aa_begin(&aa, a, t, f->smooth ? f->sil.max_recs : 3)) {
        if (wanted) stats->aa_aliased++;
        silk_aa_alpha(t);
        silk_arena_top_release(a, &mark);
        return;
    }
    for (int i = 0; i < 2; i++)
        if (aa.apron[i].rows) frame_draw(f, o, &aa.apron[i]);
    frame_outline(f, a, v, o, &aa, stats);
    silk_aa_finish(&aa);   /* pixels it had no room for are left aliased */
    stats->aa_aliased += aa.dropped;
    silk_arena_top_release(a, &mark);
}

/* What a prepared frame may add for speed: back faces culled where they
 * cannot show, then the vertex cache and the kept tangents from what the
 * arena has left (the frame's need is its high-water before them); then,
 * for bands, the rows each part reaches (share_rows). */
static void frame_extras(frame *f, silk_arena *a, const silk_mesh *m, const silk_hal *h, const silk_render_opts *o,
                         const silk_target *t)
{
    f->peak_before = a->top_peak;
    size_t reserve = outline_reserve(f, o, t);
    f->reserve = SILK_SCENES && f->reserve > reserve ? f->reserve : reserve;   /* (scene.c: every object's outline at once) */
    vertex_cache(f, a, o);
    if (SILK_DRAW_DIRECT && f->fast->vc_xy) place_vertices(f, t);   /* now: back_faces_hidden reads what it found */
    f->cull = back_faces_hidden(f, m, h, o);
    facing_memo(f, a, o);
    keep_tangents(f, a);
    depth_wins(f, a, o, t);
    keep_shares(f, a, o);
    if (SILK_SCENES) share_rows(f, o, t);   /* (bands only: a whole frame has no f->rows) */
}

/* The top of the arena the frame needed since mark: its high-water, the
 * vertex cache and the kept tangents not counted (vertex_cache,
 * keep_tangents: taken only from what is left).  The plan gives back
 * scratch as it goes, so its own peak may lie above everything taken
 * after it. */
static size_t frame_need(const frame *f, const silk_arena *a, const silk_arena_mark *mark)
{
    size_t after = a->top_peak - f->vc_bytes - f->tan_bytes;   /* >= mark->top */
    size_t need = after > f->peak_before ? after : f->peak_before;
    /* what the plan kept lies under everything taken after it (silk_remesh_keep) */
    const silk_sil_keep *k = SILK_SIL_KEEPS && f->fast ? &f->fast->keep : NULL;
    if (k && k->kept_bytes) {
        need -= k->kept_bytes;
        if (need < k->kept_need) need = k->kept_need;
    }
    return need - mark->top;
}

/* The rasterizer draws nothing into a frame larger than SILK_MAX_DIM (its
 * subpixel products are sized for it, docs/overflow.md); say so instead of
 * returning a blank image. */
static silk_status check_frame_size(const silk_target *t, silk_error *err)
{
    if (t->width < 1 || t->height < 1 || t->width > SILK_MAX_DIM || t->height > SILK_MAX_DIM)
        return silk_fail(err, SILK_ERR_RANGE, "target", 0, "image size %dx%d is outside 1x1 .. %dx%d", t->width,
                         t->height, SILK_MAX_DIM, SILK_MAX_DIM);
    return SILK_OK;
}

silk_status silk_render(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                        const silk_render_opts *o, silk_target *t, silk_frame_stats *stats,
                        silk_error *err)
{
    silk_frame_stats local;
    if (!stats) stats = &local;
    memset(stats, 0, sizeof *stats);
    if (!a || !t) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: missing argument");
    if (check_frame_size(t, err) != SILK_OK) return SILK_ERR_RANGE;

    silk_arena_mark mark = silk_arena_top_mark(a);
    a->top_peak = a->top;
    frame f;
    frame_fast fast;   /* (compiled away, off the stack, in a build without the shortcuts) */
    frame_siltex sx;   /* (the same without SILTEX mode) */
    silk_status st = frame_prepare(&f, FRAME_FAST ? &fast : NULL, SILK_SILTEX_MODE ? &sx : NULL, a, m, v, h, o,
                                   t->rows, stats, err);
    if (st == SILK_OK) {
        frame_extras(&f, a, m, h, o, t);
        frame_draw(&f, o, t);
        frame_aa(&f, a, v, o, t, stats);
        if (CLIP_FRAME(&f)) stats->clip_spans = f.clip->spans;
    }
    stats->frame_bytes = frame_need(&f, a, &mark);
    silk_arena_top_release(a, &mark);
    return st;
}

silk_status silk_render_bands(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                              const silk_render_opts *o, silk_target *band, const silk_sink *sink,
                              silk_frame_stats *stats, silk_error *err)
{
    silk_frame_stats local;
    if (!stats) stats = &local;
    memset(stats, 0, sizeof *stats);
    if (!a || !band || !sink || !sink->band || band->rows < 1 || band->height < 1 ||
        (sink->color2 == NULL) != (sink->wait == NULL))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_bands: missing argument (a second band buffer "
                         "needs the sink's wait)");
    if (check_frame_size(band, err) != SILK_OK) return SILK_ERR_RANGE;

    silk_arena_mark mark = silk_arena_top_mark(a);
    a->top_peak = a->top;
    frame f;
    frame_fast fast;   /* (compiled away, off the stack, in a build without the shortcuts) */
    frame_siltex sx;   /* (the same without SILTEX mode) */
    silk_status st = frame_prepare(&f, FRAME_FAST ? &fast : NULL, SILK_SILTEX_MODE ? &sx : NULL, a, m, v, h, o,
                                   band->rows, stats, err);
    const int rows = band->rows;
    if (st == SILK_OK && f.nparts > 1 && rows < band->height)
        f.rows = silk_arena_array_top(a, 2 * (size_t)f.nparts, sizeof *f.rows, SILK_MEM_FRAME);
    if (st == SILK_OK) {
        frame_extras(&f, a, m, h, o, band);
        if (!SILK_SCENES) share_rows(&f, o, band);   /* (frame_extras' own with scenes: scene.c's steps call it) */
    }
    /* With two colour buffers the bands alternate, each drawn once the sink
     * says it has done sending it (render.h). */
    uint8_t *const color0 = band->color;
    for (int y0 = 0, k = 0; st == SILK_OK && y0 < band->height; y0 += rows, k ^= 1) {
        band->color = k && sink->color2 ? sink->color2 : color0;
        if (!sink->wait || !sink->wait(sink->user, band->color)) {
            band->y0 = y0;
            band->rows = band->height - y0 < rows ? band->height - y0 : rows;
            frame_draw(&f, o, band);
            frame_aa(&f, a, v, o, band, stats);
            if (!sink->band(sink->user, band)) continue;
        }
        st = silk_fail(err, SILK_ERR_IO, NULL, 0, "output sink stopped at row %d", y0);
    }
    band->color = color0;
    band->y0 = 0;
    band->rows = rows;
    if (st == SILK_OK && CLIP_FRAME(&f)) stats->clip_spans = f.clip->spans;
    stats->frame_bytes = frame_need(&f, a, &mark);
    silk_arena_top_release(a, &mark);
    return st;
}

/* ---- One object's frame in steps (frame_steps.h, for scene.c) --------------------
 *
 * silk_render's own steps, each exposed as it is: only frame_draw's clear
 * (in_scene) and its depth pass for an object drawn after another (after)
 * differ, and the outline, which scene.c walks for every object at once. */

struct silk_frame_step {
    frame f;
    frame_fast fast;
    frame_siltex sx;
};

silk_status silk_frame_step_prepare(silk_frame_step **out, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                    const silk_hal *h, const silk_render_opts *o, const silk_target *band, int after,
                                    silk_frame_stats *stats, silk_error *err)
{
    silk_frame_step *s = *out = silk_arena_alloc_top(a, sizeof *s, SILK_MEM_FRAME);
    if (!s) return silk_fail(err, SILK_ERR_NOMEM, NULL, 0, "silk_render_scene: the arena is full");
    frame *f = &s->f;
    silk_status st = frame_prepare(f, FRAME_FAST ? &s->fast : NULL, SILK_SILTEX_MODE ? &s->sx : NULL, a, m, v, h, o,
                                   band->rows, stats, err);
    f->in_scene = 1;
    f->after = (uint8_t)(after != 0);
    if (st == SILK_OK && f->nparts > 1 && band->rows < band->height)   /* as silk_render_bands */
        f->rows = silk_arena_array_top(a, 2 * (size_t)f->nparts, sizeof *f->rows, SILK_MEM_FRAME);
    return st;
}

uint32_t silk_frame_step_max_recs(const silk_frame_step *s)
{
    return s->f.smooth ? s->f.sil.max_recs : 3;   /* as frame_aa's silk_aa_begin */
}

void silk_frame_step_extras(silk_frame_step *s, silk_arena *a, const silk_mesh *m, const silk_hal *h,
                            const silk_render_opts *o, silk_target *band, size_t reserve)
{
    s->f.reserve = reserve;
    frame_extras(&s->f, a, m, h, o, band);
}

void silk_frame_step_draw(silk_frame_step *s, const silk_render_opts *o, silk_target *t)
{
    frame_draw(&s->f, o, t);
}

int silk_frame_step_outline_kind(const silk_frame_step *s, const silk_render_opts *o, const silk_target *t)
{
    if (CLIP_FRAME(&s->f)) return 2;
    return SILK_AA && outline_wanted(&s->f, o, t);
}

void silk_frame_step_outline(silk_frame_step *s, silk_arena *a, const silk_view *v, const silk_render_opts *o,
                             silk_aa *aa, silk_frame_stats *stats)
{
    if (SILK_SCENES && SILK_AA) frame_outline(&s->f, a, v, o, aa, stats);   /* (compiled away without them) */
}

void silk_frame_step_clip_aa(silk_frame_step *s, const silk_render_opts *o, silk_target *t)
{
    if (CLIP_FRAME(&s->f)) silk_clip_antialias(s->f.clip, t, o->bg_rgb);
}

void silk_frame_step_need(const silk_frame_step *s, size_t *peak_before, size_t *extra_bytes)
{
    *peak_before = s->f.peak_before;
    *extra_bytes = s->f.vc_bytes + s->f.tan_bytes;
}

uint32_t silk_frame_step_clip_spans(const silk_frame_step *s)
{
    return CLIP_FRAME(&s->f) ? s->f.clip->spans : 0;
}
