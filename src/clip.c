/*
 * clip.c - silhouette clipping (Gu, Gortler, Hoppe et al., "Silhouette
 * Mapping", section 8.1) and its anti-aliased outline (section 8.3).
 *
 * The outer hull holds the detailed model, so its image holds the detailed
 * model's; the silhouette map (silmap_interp.c, section 5) gives the
 * detailed model's outline for the current eye as closed polygons.  The
 * paper draws that polygon into the stencil buffer as a triangle fan with
 * the stencil inverted per fragment, which leaves a pixel set where an odd
 * number of triangles cover it: the parity rule.  Here the polygon is
 * scan-converted directly under the same rule, one band of rows at a time,
 * into one bit per pixel, and the rasterizer discards the hull's fragments
 * where the bit is clear (silk_target.mask).
 *
 * Anti-aliasing (section 8.3): the paper draws the polygon's edges as
 * anti-aliased lines over the clipped hull.  Here each pixel's coverage by
 * the polygon is computed on four sub-scan-lines, exactly in x (1/64 pixel
 * steps); the stencil then holds every pixel the polygon touches, and a
 * pixel covered only partly is blended between the hull drawn there and
 * what lies behind the outline.  The map's outline is the whole model's,
 * so behind it there is only the background: with an alpha plane (a PNG
 * with --bg none) the coverage is the pixel's alpha and its colour the
 * hull's, blended with nothing.  Without anti-aliasing the
 * stencil holds the pixels whose centre is inside, the rasterizer's rule.
 *
 * Integers only; all memory is the arena's top, released with the frame.
 */
#include <string.h>
#include "clip.h"

#define SUBROWS 4                      /* sub-scan-lines per row */
#define FULL 256                       /* coverage of a whole pixel, after rounding */
#define SUB_FULL ((uint32_t)SUBROWS << 16) /* the same, as accumulated: 1/65536 pixel per unit and sub-scan-line */
#define PX_LIMIT ((silk_fx)16384 << 16) /* outline points clamped to +-2^14 pixels */

static silk_fx clamp_px(silk_fx v) { return v < -PX_LIMIT ? -PX_LIMIT : v > PX_LIMIT ? PX_LIMIT : v; }

static int32_t clamp_row(int32_t r, int height) { return r < 0 ? 0 : r > height - 1 ? height - 1 : r; }

silk_status silk_clip_prepare(silk_clip *c, silk_arena *a, const silk_silmap *map, const silk_view *v,
                              uint32_t hint, int band_rows, int antialias, silk_error *err)
{
    silk_outline o;
    silk_silmap_frame info;
    silk_status st = silk_silmap_interp(map, v, hint, a, &o, &info, err);
    if (st) return st;
    st = silk_clip_outline(c, a, &o, v->cam.width, v->cam.height, band_rows, antialias, err);
    c->info = info;
    return st;
}

silk_status silk_clip_outline(silk_clip *c, silk_arena *a, const silk_outline *out, int width, int height,
                              int band_rows, int antialias, silk_error *err)
{
    memset(c, 0, sizeof *c);
    c->width = width;
    c->height = height;
    c->antialias = antialias;
    c->active_row = -1;
    const silk_outline o = *out;
    c->npts = o.npts;
    const int h = c->height;
    size_t np = o.npts ? o.npts : 1, nl = o.nloops ? o.nloops : 1;
    c->edge = silk_arena_array_top(a, np, sizeof *c->edge, SILK_MEM_FRAME);
    c->loop = silk_arena_array_top(a, nl, sizeof *c->loop, SILK_MEM_FRAME);
    c->row_start = silk_arena_array_top(a, (size_t)h + 2, sizeof *c->row_start, SILK_MEM_FRAME);
    c->active = silk_arena_array_top(a, nl, sizeof *c->active, SILK_MEM_FRAME);
    c->xs = silk_arena_array_top(a, np, sizeof *c->xs, SILK_MEM_FRAME);
    c->cov = silk_arena_array_top(a, (size_t)c->width + 1, sizeof *c->cov, SILK_MEM_FRAME);
    c->mask_rows = band_rows < h ? band_rows : h;
    c->mask = silk_arena_array_top(a, (size_t)c->mask_rows * (((size_t)c->width + 7) / 8), 1, SILK_MEM_FRAME);
    c->partial = antialias ? silk_arena_array_top(a, (size_t)c->mask_rows * (size_t)c->width, 1, SILK_MEM_FRAME) : NULL;
    silk_clip_loop *tmp = silk_arena_array_top(a, nl, sizeof *tmp, SILK_MEM_FRAME);
    if (!c->edge || !c->loop || !c->row_start || !c->active || !c->xs || !c->cov || !c->mask || !tmp ||
        (antialias && !c->partial))
        return silk_fail(err, SILK_ERR_NOMEM, "clip", 0, "the arena is too small for the silhouette stencil");

    /* every loop's non-horizontal edges with their slopes (one division
     * per edge, none per scan line) and the rows the loop reaches */
    const silk_fx ymax = silk_fx_from_int(h);
    uint32_t ne = 0, nloop = 0;
    memset(c->row_start, 0, ((size_t)h + 2) * sizeof *c->row_start);
    for (uint32_t l = 0; l < o.nloops; l++) {
        uint32_t s = o.start[l], e = o.start[l + 1], first = ne;
        silk_fx lo = PX_LIMIT, hi = -PX_LIMIT;
        for (uint32_t i = s; i < e; i++) {
            silk_vec2 p = o.pt[i], q = o.pt[i + 1 < e ? i + 1 : s];
            p.x = clamp_px(p.x), p.y = clamp_px(p.y), q.x = clamp_px(q.x), q.y = clamp_px(q.y);
            if (p.y == q.y) continue;
            if (q.y < p.y) {
                silk_vec2 t = p;
                p = q;
                q = t;
            }
            int64_t slope = (((int64_t)q.x - p.x) * 65536) / ((int64_t)q.y - p.y);
            const int64_t smax = (int64_t)1 << 31;
            c->edge[ne++] = (silk_clip_edge){ p.y, q.y, p.x,
                                              (int32_t)(slope > smax - 1 ? smax - 1 : slope < -smax ? -smax : slope) };
            lo = silk_fx_min(lo, p.y);
            hi = silk_fx_max(hi, q.y);
        }
        if (ne == first || hi <= 0 || lo >= ymax) {
            ne = first;
            continue;
        }
        silk_clip_loop L = { first, ne - first, clamp_row(silk_fx_floor(lo), h), clamp_row(silk_fx_floor(hi), h) };
        tmp[nloop++] = L;
        c->row_start[L.row0 + 1]++;
    }
    /* loops by first row: a counting sort (stable, no comparisons) */
    for (int r = 0; r <= h; r++) c->row_start[r + 1] += c->row_start[r];
    for (uint32_t i = 0; i < nloop; i++) c->loop[c->row_start[tmp[i].row0]++] = tmp[i];
    for (int r = h; r > 0; r--) c->row_start[r] = c->row_start[r - 1];
    c->row_start[0] = 0;
    c->nedges = ne;
    c->nloops = nloop;
    return SILK_OK;
}

/* The loops that reach row y into c->active: from the previous row's when
 * rows come in order, else from all loops that start at or above it. */
static void advance(silk_clip *c, int y)
{
    uint32_t n = 0;
    if (c->active_row >= 0 && y == c->active_row + 1) {
        for (uint32_t k = 0; k < c->nactive; k++)
            if (c->loop[c->active[k]].row1 >= y) c->active[n++] = c->active[k];
        for (uint32_t i = c->row_start[y]; i < c->row_start[y + 1]; i++) c->active[n++] = i;
    } else {
        for (uint32_t i = 0; i < c->row_start[y + 1]; i++)
            if (c->loop[i].row1 >= y) c->active[n++] = i;
    }
    c->nactive = n;
    c->active_row = y;
}

/* One loop's crossings with scan line ys, sorted (a loop of the
 * interpolated outline is a quadrilateral: two at most). */
static uint32_t crossings(const silk_clip *c, const silk_clip_loop *L, silk_fx ys, silk_fx *xs)
{
    uint32_t n = 0;
    for (uint32_t k = 0; k < L->n; k++) {
        const silk_clip_edge *e = &c->edge[L->first + k];
        if (ys < e->y0 || ys >= e->y1) continue;
        /* |ys - y0| < 2^31, |slope| <= 2^31: the product fits */
        silk_fx x = (silk_fx)(e->x0 + ((((int64_t)ys - e->y0) * e->slope) >> 16));
        uint32_t j = n++;
        for (; j > 0 && xs[j - 1] > x; j--) xs[j] = xs[j - 1];
        xs[j] = x;
    }
    return n & ~1u;
}

/* Row y's coverage of every pixel into c->cov (0..FULL).  The loops are
 * disjoint (silmap_interp.h), so their coverages add: each loop's spans
 * under the parity rule, summed, with no sorting across loops. */
static void row_coverage(silk_clip *c, int y)
{
    const silk_fx wmax = silk_fx_from_int(c->width);
    memset(c->cov, 0, (size_t)c->width * sizeof *c->cov);
    for (uint32_t a = 0; a < c->nactive; a++) {
        const silk_clip_loop *L = &c->loop[c->active[a]];
        for (int k = 0; k < SUBROWS; k++) {
            silk_fx ys = silk_fx_from_int(y) + (silk_fx)((2 * k + 1) << 13);
            uint32_t n = crossings(c, L, ys, c->xs);
            for (uint32_t i = 0; i < n; i += 2) {
                silk_fx xl = silk_fx_clamp(c->xs[i], 0, wmax), xr = silk_fx_clamp(c->xs[i + 1], 0, wmax);
                if (xr <= xl) continue;
                int32_t il = silk_fx_floor(xl), ir = silk_fx_floor(xr);
                /* exact lengths, so that spans meeting inside a pixel add up to it */
                if (il == ir) {
                    c->cov[il] += (uint32_t)(xr - xl);
                    continue;
                }
                c->cov[il] += (uint32_t)(silk_fx_from_int(il + 1) - xl);
                for (int32_t x = il + 1; x < ir; x++) c->cov[x] += 1u << 16;
                if (ir < c->width) c->cov[ir] += (uint32_t)(xr - silk_fx_from_int(ir));
            }
        }
    }
    /* to 0..FULL, rounded: what is within 1/512 pixel of empty or whole is */
    for (int x = 0; x < c->width; x++) {
        uint32_t w = (c->cov[x] + (SUB_FULL / FULL / 2)) / (SUB_FULL / FULL);
        c->cov[x] = w > FULL ? FULL : w;
    }
}

/* Row y's pixels whose centres are inside into bits (the rasterizer's
 * rule: a centre exactly on a left end is inside, on a right end not). */
static void row_centres(silk_clip *c, int y, uint8_t *bits)
{
    silk_fx ys = silk_fx_from_int(y) + SILK_FX_HALF;
    for (uint32_t a = 0; a < c->nactive; a++) {
        uint32_t n = crossings(c, &c->loop[c->active[a]], ys, c->xs);
        for (uint32_t i = 0; i < n; i += 2) {
            /* first centre x + 1/2 >= xl, last centre < xr */
            int64_t l = ((int64_t)c->xs[i] - SILK_FX_HALF + 0xFFFF) >> 16;
            int64_t r = ((int64_t)c->xs[i + 1] - SILK_FX_HALF + 0xFFFF) >> 16;
            if (l < 0) l = 0;
            if (r > c->width) r = c->width;
            for (int64_t x = l; x < r; x++) bits[x >> 3] |= (uint8_t)(1u << (x & 7));
        }
    }
}

void silk_clip_stencil(silk_clip *c, silk_target *t)
{
    size_t stride = ((size_t)c->width + 7) / 8;
    int rows = t->rows < c->mask_rows ? t->rows : c->mask_rows;
    memset(c->mask, 0, (size_t)rows * stride);
    for (int r = 0; r < rows; r++) {
        int y = t->y0 + r;
        uint8_t *bits = c->mask + (size_t)r * stride;
        advance(c, y);
        if (c->antialias) {
            uint8_t *part = c->partial + (size_t)r * (size_t)c->width;
            row_coverage(c, y);
            for (int x = 0; x < c->width; x++) {
                if (c->cov[x]) bits[x >> 3] |= (uint8_t)(1u << (x & 7));
                part[x] = c->cov[x] < FULL ? (uint8_t)c->cov[x] : 0;
            }
        } else {
            row_centres(c, y, bits);
        }
        for (int x = 0, in = 0; x < c->width; x++) {
            int b = bits[x >> 3] >> (x & 7) & 1;
            c->spans += (uint32_t)(b && !in);
            in = b;
        }
    }
    t->mask = c->mask;
}

/* The coverage w (of FULL) as an alpha, 0..255. */
static uint32_t alpha_of(uint32_t w) { return (w * 255 + FULL / 2) / FULL; }

/* b over a with alpha al per channel, rounded: the colour b with alpha al
 * laid over a (a PNG's alpha) gives the same. */
static uint32_t mix(uint32_t a, uint32_t b, uint32_t al)
{
    uint32_t out = 0;
    for (int s = 0; s < 24; s += 8) out |= (((b >> s & 255) * al + (a >> s & 255) * (255 - al) + 127) / 255) << s;
    return out;
}

void silk_clip_antialias(silk_clip *c, silk_target *t, uint32_t bg_rgb)
{
    if (!c->antialias) return;
    int rows = t->rows < c->mask_rows ? t->rows : c->mask_rows;
    for (int r = 0; r < rows; r++) {
        int y = t->y0 + r;
        const uint8_t *part = c->partial + (size_t)r * (size_t)c->width;
        const uint32_t *zrow = t->depth ? t->depth + (size_t)r * (size_t)t->width : NULL;
        for (int x = 0; x < c->width; x++) {
            uint32_t w = part[x];
            if (w == 0) continue;
            uint32_t drawn = silk_target_get(t, x, y);
            /* nothing drawn there (the hull fell short of the outline): background stays */
            if (zrow ? zrow[x] == 0 : drawn == (bg_rgb & 0xFFFFFF)) continue;
            /* with an alpha plane the coverage is the alpha and the colour the hull's own */
            if (t->alpha) t->alpha[(size_t)r * (size_t)t->width + (size_t)x] = (uint8_t)alpha_of(w);
            else silk_target_put(t, x, y, mix(bg_rgb, drawn, alpha_of(w)));
        }
    }
}
