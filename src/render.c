/*
 * render.c - one frame from the mode's geometry to pixels: silk_render
 * (the whole frame, or one band of it) and silk_render_bands (every band,
 * each handed to the sink).
 *
 * The silhouette stages (smooth.c) or the plain coarse mesh (flat.c) produce
 * vertex records and triangles over them.  Each record goes through the HAL's
 * vertex stage exactly once, so a vertex shared by many triangles reaches the
 * rasterizer with the same bits in all of them (no cracks); then every
 * triangle is rasterized into the target's band, and --wire draws the edges on
 * top, then the pen-and-ink lines (lines.c) if asked for (frame_draw.c).  All
 * per-frame memory is taken from the top of the arena and released before
 * returning, so frames can be rendered forever from one arena.
 *
 * FLAT, SMOOTH and CLIP frames without lines, and SILTEX's, are drawn share
 * by share instead (frame_shares.c): nothing but the silhouette plan is
 * kept, and each input triangle's share of the frame is rebuilt whenever a
 * band needs it.  The other files of the frame (render_frame.h) cull what
 * cannot show (frame_cull.c), keep what the arena has room for to go
 * faster (frame_fast.c) and anti-alias the outlines (frame_aa.c).
 *
 * What a build draws is its options' (silk/config.h, the mode table
 * below): a device that draws only FLAT and SMOOTH frames leaves out PN and
 * BLEND (SILK_REFERENCE_MODES 0), the lines and --wire (SILK_LINES 0; with
 * both every frame is drawn share by share, so the stored frame's code goes
 * too), CLIP, SILTEX, the anti-aliased outlines and texture sampling, and
 * asking for what is left out is SILK_ERR_ARG.  A build without the
 * shortcuts (SILK_SHORTCUTS 0) leaves out frame_fast.c's code and has no
 * frame_fast.
 */
#include "render_frame.h"
#include "frame_steps.h"

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

/* The modes: a name, and the build option that leaves one out where this
 * build does (NULL: it is built in). */
static const struct mode_row {
    const char *name;
    const char *left_out;
} modes[] = {
    [SILK_MODE_FLAT] = { "flat", NULL },
    [SILK_MODE_SMOOTH] = { "smooth", NULL },
    [SILK_MODE_PN] = { "pn", SILK_REFERENCE_MODES ? NULL : "SILK_REFERENCE_MODES" },
    [SILK_MODE_BLEND] = { "blend", SILK_REFERENCE_MODES ? NULL : "SILK_REFERENCE_MODES" },
    [SILK_MODE_CLIP] = { "clip", SILK_CLIP_MODE ? NULL : "SILK_CLIP_MODE" },
    [SILK_MODE_SILTEX] = { "siltex", SILK_SILTEX_MODE ? NULL : "SILK_SILTEX_MODE" },
};
#define NMODES (sizeof modes / sizeof modes[0])

const char *silk_mode_name(silk_mode mode)
{
    return (unsigned)mode < NMODES ? modes[mode].name : "?";
}

/* f, its mesh and stages set (f->geom.mesh, f->hal), drawn share by share
 * (frame_shares.c): SMOOTH's plan where it fits (else the coarse mesh's
 * shares, as a stored frame falls back), room for one share. */
static silk_status shares_prepare(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o,
                                  silk_frame_stats *stats, silk_error *err)
{
    const silk_mesh *m = f->geom.mesh;
    f->nparts = m->ntris;
    f->parts = FRAME_SHARES;
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
            f->smooth = silk_frame_smooth_plan(a, m, v, o->tolerance_px, o->visibility, f->clock, &f->sil, &f->cur,
                                               &f->g) &&
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

/* CLIP: the hull drawn as flat draws a mesh, through the stencil of the
 * outline interpolated from the silhouette map (clip.c), band_rows high. */
static silk_status clip_prepare(frame *f, silk_arena *a, const silk_view *v,
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
    st = shares_prepare(f, a, v, o, stats, err);
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
    f->hal = &sx->hal;
    return shares_prepare(f, a, v, o, stats, err);
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
    else   /* (frame_prepare refuses the modes a build leaves out) */
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
    f->parts = FRAME_STORED;
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
    f->hal = h;
    f->geom.mesh = m;
    if ((unsigned)o->mode >= NMODES)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown mode %d", (int)o->mode);
    if (modes[o->mode].left_out)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: %s mode is not built in (%s 0)", modes[o->mode].name,
                         modes[o->mode].left_out);
    /* A compact model without its corner table (silk pack --flat) has no
     * edges: smooth frames are its flat ones, and what follows edges cannot
     * be drawn. */
    if (m->packed.base && !m->nedges && (o->lines || o->wire || (o->mode != SILK_MODE_FLAT && o->mode != SILK_MODE_SMOOTH)))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0,
                         "silk_render: the model has no edges (packed for flat frames only): %s", o->lines || o->wire
                         ? "no lines or wire" : "flat and smooth frames only");
    if (SILK_CLIP_MODE && o->mode == SILK_MODE_CLIP) return clip_prepare(f, a, v, o, band_rows, stats, err);
    if (SILK_SILTEX_MODE && o->mode == SILK_MODE_SILTEX) return siltex_prepare(f, sx, a, m, v, h, o, stats, err);
    if (silk_shares_wanted(o)) return shares_prepare(f, a, v, o, stats, err);
    if (SILK_STORED_FRAMES) return stored_prepare(f, a, m, v, h, o, stats, err);
    return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: lines and wire are not built in (SILK_LINES 0)");
}

/* What siltex_outline takes for a band of t at most: colour, depth and
 * mask over its rows and their two aprons. */
static size_t siltex_outline_bytes(const silk_target *t)
{
    size_t w = (size_t)t->width, rows = (size_t)t->rows + 2, al = SILK_ARENA_ALIGN - 1;
    return ((w * rows * 3 + al) & ~al) + ((w * rows * sizeof(uint32_t) + al) & ~al) + ((rows * ((w + 7) / 8) + al) & ~al);
}

/* What silk_outline_draw's silk_aa_begin takes for a band of t, or 0 where the
 * frame draws no outline.  What the frame keeps for speed comes from what
 * the arena has beyond it (silk_fast_spare), so that a frame given exactly its need
 * (silk_frame_stats.frame_bytes) draws every outline pixel. */
static size_t outline_reserve(const frame *f, const silk_render_opts *o, const silk_target *t)
{
    if (!SILK_AA || CLIP_FRAME(f) || !silk_outline_wanted(f, o, t)) return 0;
    size_t bytes = silk_aa_bytes(t, f->smooth ? f->sil.max_recs : 3);
    if (SILTEX_FRAME(f)) bytes += siltex_outline_bytes(t);
    return bytes;
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
    if (f->smooth) f->tan_bytes = silk_sil_keep_tangents(&f->sil, silk_fast_spare(f, a));
}

/* What a prepared frame may add for speed: back faces culled where they
 * cannot show, then the vertex cache and the kept tangents from what the
 * arena has left (the frame's need is its high-water before them); then,
 * for bands, the rows each part reaches (silk_cull_rows). */
static void frame_extras(frame *f, silk_arena *a, const silk_hal *h, const silk_render_opts *o, const silk_target *t)
{
    f->peak_before = a->top_peak;
    size_t reserve = outline_reserve(f, o, t);
    f->reserve = SILK_SCENES && f->reserve > reserve ? f->reserve : reserve;   /* (scene.c: every object's outline at once) */
    /* (each under its option: a build without it makes no call) */
    if (SILK_VERTEX_CACHE) silk_fast_vertex_cache(f, a, o);
    if (SILK_DRAW_DIRECT && f->fast->vc_xy) silk_fast_place_vertices(f, t);   /* now: silk_cull_back_faces reads what it found */
    f->cull = silk_cull_back_faces(f, h, o);
    if (SILK_AA && SILK_VERTEX_CACHE) silk_outline_facing(f, a, o);
    keep_tangents(f, a);
    if (SILK_DEPTH_WINS) silk_fast_depth_wins(f, a, o, t);
    if (SILK_KEEP_SHARES) silk_fast_keep_shares(f, a, o);
    if (SILK_SCENES) silk_cull_rows(f, o, t);   /* (bands only: a whole frame has no f->rows) */
}

/* The top of the arena the frame needed since mark: its high-water, the
 * vertex cache and the kept tangents not counted (silk_fast_vertex_cache,
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
        frame_extras(&f, a, h, o, t);
        silk_draw_frame(&f, o, t);
        if (SILK_AA || SILK_CLIP_MODE) silk_outline_draw(&f, a, v, o, t, stats);
        else silk_aa_alpha(t);   /* (a build without outlines: no call of six arguments) */
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
        frame_extras(&f, a, h, o, band);
        if (!SILK_SCENES) silk_cull_rows(&f, o, band);   /* (frame_extras' own with scenes: scene.c's steps call it) */
    }
    /* With two colour buffers the bands alternate, each drawn once the sink
     * says it has done sending it (render.h). */
    uint8_t *const color0 = band->color;
    for (int y0 = 0, k = 0; st == SILK_OK && y0 < band->height; y0 += rows, k ^= 1) {
        band->color = k && sink->color2 ? sink->color2 : color0;
        if (!sink->wait || !sink->wait(sink->user, band->color)) {
            band->y0 = y0;
            band->rows = band->height - y0 < rows ? band->height - y0 : rows;
            silk_draw_frame(&f, o, band);
            if (SILK_AA || SILK_CLIP_MODE) silk_outline_draw(&f, a, v, o, band, stats);
            else silk_aa_alpha(band);
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
 * silk_render's own steps, each exposed as it is: only silk_draw_frame's clear
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
    (void)m;
    frame_extras(&s->f, a, h, o, band);
}

void silk_frame_step_draw(silk_frame_step *s, const silk_render_opts *o, silk_target *t)
{
    silk_draw_frame(&s->f, o, t);
}

int silk_frame_step_outline_kind(const silk_frame_step *s, const silk_render_opts *o, const silk_target *t)
{
    if (CLIP_FRAME(&s->f)) return 2;
    return SILK_AA && silk_outline_wanted(&s->f, o, t);
}

void silk_frame_step_outline(silk_frame_step *s, silk_arena *a, const silk_view *v, const silk_render_opts *o,
                             silk_aa *aa, silk_frame_stats *stats)
{
    if (SILK_SCENES && SILK_AA) silk_outline_walk(&s->f, a, v, o, aa, stats);   /* (compiled away without them) */
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
