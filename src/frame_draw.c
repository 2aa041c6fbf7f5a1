/*
 * frame_draw.c - one band of a frame: the background, CLIP's stencil, the
 * triangles part by part (with a depth pass first where triangles are
 * large, docs/raster.md), --wire's edges, the pen-and-ink lines.
 */
#include "render_frame.h"

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

/* The part in g into t: pass -1 its triangles' depth alone, pass 0 its
 * triangles; passes 1 and 2 (--wire) the edges of the original triangles,
 * then of the added ones, so their red stays on top.  won: the part's
 * depth_wins bits (frame_fast.c), or NULL. */
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
    int placed = SILK_PLACE_ONCE && pass <= 0 && f->parts == FRAME_SHARES && f->cache && g->nvrec <= PART_XY;
    /* the test pays where triangles are small (as silk_draw_frame's depth pass
     * is made only where they are large): elsewhere most of them reach a
     * pixel, and silk_raster_placed finds the others as cheaply */
    int ask = (uint64_t)f->geom.mesh->ntris * 16 > (uint64_t)t->width * t->height;
    int32_t (*kxy)[2] = SILK_KEEP_SHARES && placed ? f->fast->kxy : NULL;
    if (kxy) xy = kxy;   /* a kept share: placed there, once a frame */
    for (uint32_t i = 0; placed && !(kxy && *f->fast->kxy_ready) && i < g->nvrec; i++)
        if (!silk_raster_place(t, &f->cache[i].clip, xy[i])) xy[i][0] = VC_OUTSIDE;
    if (kxy) *f->fast->kxy_ready = 1;
    for (uint32_t i = 0; i < g->ntri; i++) {
        uint32_t k = t->depth_equal ? g->ntri - 1 - i : i;   /* see silk_draw_frame */
        const uint32_t *c = &g->tri[3 * k];
        int added = g->tri_added && g->tri_added[k];
        uint32_t bit = 1u << (k < 31 ? k : 31);   /* depth_wins */
        int wins = SILK_DEPTH_WINS && won;
        if (wins && pass == 0 && !(*won & bit)) continue;
        if (SILK_DEPTH_WINS) t->drew = 0;
        if (placed && xy[c[0]][0] != VC_OUTSIDE && xy[c[1]][0] != VC_OUTSIDE && xy[c[2]][0] != VC_OUTSIDE) {
            const int32_t *p[3] = { xy[c[0]], xy[c[1]], xy[c[2]] };
            if (wins && pass < 0 && silk_fast_back_last(f, t, p, c, (uint32_t)(won - f->fast->won), bit)) continue;
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
void silk_draw_frame(frame *f, const silk_render_opts *o, silk_target *t)
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
    uint64_t ntri = f->parts == FRAME_SHARES ? f->geom.mesh->ntris : f->g.ntri;
    /* (not in SILTEX, whose fragment stage decides which pixels take a depth) */
    int depth_first = t->depth && o->lines != SILK_LINES_ONLY && ntri * 16 <= (uint64_t)t->width * t->height &&
                      !SILTEX_FRAME(f) && (f->parts != FRAME_SHARES || t->rows >= t->height) &&
                      !(SILK_SCENES && f->after);   /* scene.c: its shading pass would take pixels another object ties in depth */
    uint32_t *wins = NULL;   /* depth_wins, where there is a depth pass */
    if (SILK_DRAW_DIRECT && x->vc_xy && !x->xy_ready) silk_fast_place_vertices(f, t);
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
                int drawn = silk_fast_draw_direct(f, t, pass < 0 ? NULL : f->hal, k);
                silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
                if (drawn) {
                    if (won) *won |= (uint32_t)t->drew;   /* depth_wins: one triangle (shading pass: set already) */
                    continue;
                }
            }
            frame_part(f, k);
            t->cull_back = pass <= 0 && f->cull && (!f->smooth || f->plain);   /* --wire draws every edge */
            /* SILTEX: a back face of the hull is seen from inside it, where
             * no visibility function was made: hull behind shows instead */
            t->cull_back |= pass <= 0 && SILTEX_FRAME(f);
            t0 = silk_stage_start(f->clock);
            draw_tris(f, o, t, pass, won);
            silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
        }
        if (SILK_BACK_FACES_LAST && x->nback) {   /* the depth pass's back faces put off (silk_fast_back_last) */
            t0 = silk_stage_start(f->clock);
            silk_fast_back_draw(f, t);
            silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
        }
    }
    t->depth_equal = t->cull_back = 0;
    if (CLIP_FRAME(f)) t->mask = NULL;   /* silk_outline_draw anti-aliases its outline */
    if (SILK_LINES && o->lines) draw_lines(f, o, t);
}

/* SILTEX: the hull's front faces into s, every part that reaches its
 * rows, as silk_draw_frame draws them (back faces culled): through stage h, or
 * depth alone (h NULL). */
void silk_draw_hull(frame *f, const silk_render_opts *o, silk_target *s, const silk_hal *h)
{
    if (!SILK_SILTEX_MODE) return;   /* (then silk_draw_frame is draw_tris' one caller) */
    const silk_hal *shade = f->hal;
    for (uint32_t k = 0; k < f->nparts; k++) {
        if (part_misses(f, k, s->y0, s->y0 + s->rows - 1)) continue;
        frame_part(f, k);
        s->cull_back = 1;
        uint32_t t0 = silk_stage_start(f->clock);
        f->hal = h ? h : shade;   /* the same vertex stage: the part's output stands */
        draw_tris(f, o, s, h ? 0 : -1, NULL);
        f->hal = shade;
        silk_stage_stop(f->clock, SILK_STAGE_RASTER, t0);
    }
    s->cull_back = 0;
}
