/*
 * render.c - one frame: per-frame geometry, vertex stage, rasterizer.
 *
 * The silhouette stages (smooth.c) or the plain coarse mesh (flat.c) produce
 * vertex records and triangles over them.  Each record goes through the HAL's
 * vertex stage exactly once, so a vertex shared by many triangles reaches the
 * rasterizer with the same bits in all of them (no cracks); then every
 * triangle is rasterized into the target's band, and --wire draws the edges on
 * top, then the pen-and-ink lines (lines.c) if asked for.  All per-frame memory is taken from the top of the arena and released
 * before returning, so frames can be rendered forever from one arena.
 */
#include <string.h>
#include "smooth.h"

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
}

const char *silk_mode_name(silk_mode mode)
{
    switch (mode) {
    case SILK_MODE_FLAT: return "flat";
    case SILK_MODE_SMOOTH: return "smooth";
    case SILK_MODE_PN: return "pn";
    case SILK_MODE_BLEND: return "blend";
    }
    return "?";
}

/* A frame ready to rasterize: geometry plus the vertex stage's output. */
typedef struct frame {
    const silk_hal *hal;
    silk_geom geom;
    silk_frame_geom g;
    silk_vertex_out *cache;   /* NULL when the arena could not hold it */
    silk_vertex_out *line_cache;   /* the same for the lines' records */
} frame;

/* Vertex stage output for record i: from the cache when the frame could
 * afford one, else recomputed (same bits either way: the stage is a pure
 * function of the record). */
static const silk_vertex_out *vertex_out(const frame *f, uint32_t i, silk_vertex_out *tmp)
{
    if (f->cache) return &f->cache[i];
    f->hal->vertex(f->hal, &f->geom, &f->g.vrec[i], tmp);
    return tmp;
}

static const silk_vertex_out *line_out(const frame *f, uint32_t i, silk_vertex_out *tmp)
{
    if (f->line_cache) return &f->line_cache[i];
    f->hal->vertex(f->hal, &f->geom, &f->g.line_vrec[i], tmp);
    return tmp;
}

static silk_status frame_prepare(frame *f, silk_arena *a, const silk_mesh *m, const silk_view *v,
                                 const silk_hal *h, const silk_render_opts *o,
                                 silk_frame_stats *stats, silk_error *err)
{
    if (!a || !m || !v || !h || !o || !h->vertex || !h->fragment)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: missing argument");
    if ((unsigned)o->lines > SILK_LINES_ONLY)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown lines setting %d", (int)o->lines);
    memset(f, 0, sizeof *f);
    f->hal = h;
    silk_status st;
    /* The smooth curves exist only in SMOOTH mode; the others outline the coarse mesh. */
    int smooth_lines = o->lines && !o->lines_polygonal && o->mode == SILK_MODE_SMOOTH;
    if (o->mode == SILK_MODE_SMOOTH)
        st = silk_frame_smooth_lines(a, m, v, o->tolerance_px, o->visibility, smooth_lines, &f->g, stats, err);
    else if (o->mode == SILK_MODE_FLAT)
        st = silk_frame_flat(a, m, &f->g, err);
    else if (o->mode == SILK_MODE_PN)
        st = silk_frame_pn(a, m, o->level, o->pn_normals, &f->g, stats, err);
    else if (o->mode == SILK_MODE_BLEND)
        st = silk_frame_blend(a, m, v, o->blend_beta, o->tolerance_px, &f->g, stats, err);
    else
        st = silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render: unknown mode %d", (int)o->mode);
    if (st != SILK_OK) return st;
    if (o->lines && !smooth_lines && silk_lines_polygonal(a, m, v, &f->g) != SILK_OK) {
        f->g.nlines = f->g.nline_vrec = 0;
        stats->fell_back = 1;
    }

    f->geom.mesh = m;
    f->geom.curves = f->g.curve;
    f->geom.offsets = f->g.offset;
    f->geom.patches = f->g.patch;
    /* Without room for the cache the frame is still drawn, only slower. */
    f->cache = silk_arena_array_top(a, f->g.nvrec, sizeof *f->cache, SILK_MEM_FRAME);
    if (f->cache)
        for (uint32_t i = 0; i < f->g.nvrec; i++) h->vertex(h, &f->geom, &f->g.vrec[i], &f->cache[i]);
    f->line_cache = silk_arena_array_top(a, f->g.nline_vrec, sizeof *f->line_cache, SILK_MEM_FRAME);
    if (f->line_cache)
        for (uint32_t i = 0; i < f->g.nline_vrec; i++)
            h->vertex(h, &f->geom, &f->g.line_vrec[i], &f->line_cache[i]);
    stats->tris_drawn = f->g.ntri;
    return SILK_OK;
}

static void draw_wire(const frame *f, const silk_render_opts *o, silk_target *t)
{
    const silk_frame_geom *g = &f->g;
    silk_vertex_out tmp[2];
    /* Original triangles first, so the red of re-meshed ones stays on top. */
    for (int pass = 0; pass < 2; pass++)
        for (uint32_t k = 0; k < g->ntri; k++) {
            int added = g->tri_added && g->tri_added[k];
            if (added != pass) continue;
            const uint32_t *c = &g->tri[3 * k];
            for (int e = 0; e < 3; e++)
                silk_raster_line(t, vertex_out(f, c[e], &tmp[0]), vertex_out(f, c[(e + 1) % 3], &tmp[1]),
                                 added ? o->wire_new_rgb : o->wire_rgb);
        }
}

static void frame_draw(const frame *f, const silk_render_opts *o, silk_target *t)
{
    const silk_frame_geom *g = &f->g;
    silk_vertex_out tmp[3];
    silk_target_clear(t, o->bg_rgb);
    /* Lines alone: the surface is drawn into the depth buffer only, to hide them. */
    const silk_hal *shade = o->lines == SILK_LINES_ONLY ? NULL : f->hal;
    for (uint32_t k = 0; k < g->ntri; k++) {
        const uint32_t *c = &g->tri[3 * k];
        silk_raster_triangle(t, shade, vertex_out(f, c[0], &tmp[0]), vertex_out(f, c[1], &tmp[1]),
                             vertex_out(f, c[2], &tmp[2]));
    }
    if (o->wire) draw_wire(f, o, t);
    for (uint32_t i = 0; o->lines && i < g->nlines; i++) {
        uint32_t rgb = g->line_feature[i] ? o->line_feature_rgb : o->line_rgb;
        for (uint32_t j = g->line_start[i]; j + 1 < g->line_start[i + 1]; j++)
            silk_raster_line(t, line_out(f, j, &tmp[0]), line_out(f, j + 1, &tmp[1]), rgb);
    }
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
    silk_status st = frame_prepare(&f, a, m, v, h, o, stats, err);
    if (st == SILK_OK) frame_draw(&f, o, t);
    stats->frame_bytes = a->top_peak - mark.top;
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
    if (!a || !band || !sink || !sink->band || band->rows < 1 || band->height < 1)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_bands: missing argument");
    if (check_frame_size(band, err) != SILK_OK) return SILK_ERR_RANGE;

    silk_arena_mark mark = silk_arena_top_mark(a);
    a->top_peak = a->top;
    frame f;
    silk_status st = frame_prepare(&f, a, m, v, h, o, stats, err);
    const int rows = band->rows;
    for (int y0 = 0; st == SILK_OK && y0 < band->height; y0 += rows) {
        band->y0 = y0;
        band->rows = band->height - y0 < rows ? band->height - y0 : rows;
        frame_draw(&f, o, band);
        if (sink->band(sink->user, band))
            st = silk_fail(err, SILK_ERR_IO, NULL, 0, "output sink stopped at row %d", y0);
    }
    band->y0 = 0;
    band->rows = rows;
    stats->frame_bytes = a->top_peak - mark.top;
    silk_arena_top_release(a, &mark);
    return st;
}
