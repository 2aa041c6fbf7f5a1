/*
 * aa.c - anti-aliased outlines: each pixel an outline of the drawn surface
 * crosses gets the surface's coverage of it, computed from the outline
 * itself, and is blended with what lies behind.
 *
 * In FLAT and SMOOTH mode the outline is geometry silk already has, not
 * something found in the image: in SMOOTH mode the silhouette segment of every silhouette
 * triangle (the Hermite curve of eq. 5, drawn as chords between its
 * samples of eq. 8); in FLAT mode (and for the triangles SMOOTH leaves as
 * they are, unless next to a silhouette triangle) every mesh edge between
 * a front- and a back-facing triangle (the face-based silhouette), and
 * every edge against nothing.  Interior pixels are never visited: the
 * cost is a walk along the outline.  (SILTEX's, below, is found in the
 * band.)
 *
 * Coverage.  Along a side whose x extent is the larger, each pixel column
 * whose centre the side spans is crossed at height y_e; the pixel the
 * crossing falls in is covered by the side's inside over the part of it
 * on that side, 1 - frac(y_e) or frac(y_e) (the area of the pixel column
 * cut by a straight outline, exact unless it crosses a pixel corner within
 * the column, where it is off by at most 1/8); the pixels further in are
 * covered, those further out not.  Sides steeper than 45 degrees walk rows
 * the same way.  The rasterizer draws a silhouette segment as chords
 * between its samples, which lie inside the curve by up to the sampling
 * tolerance (eq. 8), and where the re-meshed triangle's two parts do not
 * fold along the segment on screen (they face the same way) the drawn
 * outline is a side next to the chord; so along a chord the crossing is
 * taken from the curve itself, eq. 5 evaluated at SUBDIV - 1 parameters
 * between the chord's samples and projected by the vertex stage (a
 * polyline within 1/16 of the chord's distance from the curve), and every
 * pixel from the chord's two to the one the curve crosses, and two more
 * each way along a row for a steep side (the outline drawn where the
 * parts do not fold; a band reads only one row past its own), gets the
 * curve's coverage, except that a pixel drawn covered keeps at least half:
 * where the curve lies inside the geometry drawn by more than that, the
 * pixel's outside would be two pixels away, and a pixel emptied there
 * next to one that cannot be leaves a notch in the outline.  Straight
 * sides are the outline as it is.  Positions are the rasterizer's own subpixel ones
 * (silk_raster_point), 1/16 pixel, so a coverage within 1/32 of empty or
 * full is taken as empty or full; from a curve, within 1/10 (the Hermite
 * curve follows the surface's true outline to about a tenth of a pixel).
 *
 * Blending.  A pixel the outline covers otherwise than drawn becomes
 * coverage x inside + (1 - coverage) x outside, read from the pixel and its
 * neighbour across the outline (a post-process blend as in geometric
 * post-process anti-aliasing, Persson 2011): a pixel holding the surface
 * (its depth within a tolerance of the outline's) is the inside and the
 * one beyond it the outside; a pixel holding what lies behind (or
 * nothing) is the outside and the one within it the inside.  Where the
 * neighbour is not what is needed (the surface two pixels past the curve,
 * or nothing within it) the pixel is left as drawn.  With an alpha plane
 * (a PNG with --bg none) an empty pixel has alpha 0 and weighs nothing in
 * the colour, so alpha is the coverage and the colour the surface's.  A
 * pixel nearer than the outline by more than the tolerance (the depth
 * range of the side's triangle, or of a silhouette triangle's whole share,
 * and 1/64) is something in front of it: the outline is hidden there and
 * the pixel left alone; an empty pixel next to such a one takes its colour
 * (two outlines meet there).
 *
 * Creases.  A visible crease, a feature edge between two front-facing
 * triangles, is walked the same way (in SMOOTH its feature curve, eq. 1-4,
 * between its samples, eq. 8; else the mesh edge), but both sides are
 * faces: each is drawn up to the chord, so the pixels the chord leaves on
 * either side give the two colours, and a pixel the curve covers otherwise
 * than drawn is blended from them when it and both hold the surface.
 * A build with SILK_AA_CREASES 0 (and silk_render_opts.aa = 2) leaves
 * creases aliased.
 *
 * SILTEX.  The outline is where eq. 4 of the silhouette texture starts
 * discarding the hull's front faces, inside their triangles: no geometry
 * holds it, so it is found in the band, where a pixel showing the front
 * face (its depth there is the front faces', drawn again alone) meets one
 * showing what lies behind it or nothing, and measured by the test itself:
 * the front faces drawn once more through siltex.c's margin stage at those
 * pixels and their neighbours give the angle acos(d.C) - phi, negative
 * where drawn.  An outline pixel's coverage is the part of it where that
 * angle, linear across the pixel with its slopes to the neighbours, is
 * negative (the box filter of a straight edge, exact), and it is blended
 * with its neighbour across the outline as above.
 *
 * Every new value is computed from the band as drawn and written only when
 * all outlines are walked, so no pixel reads another's blended value; the
 * rows just above and below a band are drawn into an apron for the pixels
 * next to a band edge.  So a pixel's value depends on the frame alone and
 * bands give the frame's bytes, in RGB565 as in RGB888.  All integer.
 */
#include <string.h>
#include "aa.h"
#include "raster_place.h"
#include "phong_parts.h"
#include "compiler.h"
#include "remesh.h"
#include "silk/siltex.h"

#define LIMIT ((int64_t)1 << 24)   /* subpixel coordinates walked (far past the guard band; differences fit 32 bits) */
#define FRAC  4096                 /* crossing positions in 1/FRAC pixel */
#define SNAP  (FRAC / 32)          /* coverage this close to 0 or 1 is 0 or 1: below what 1/16-pixel records place */
#define SNAP_CURVE (FRAC / 10)     /* the same from a silhouette segment: below how close it follows the surface */
#define SUBDIV SILK_AA_SUBDIV

static int64_t floor_div(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }  /* d > 0 */

static int64_t absl(int64_t v) { return v < 0 ? -v : v; }

static silk_aa_pt point(const silk_target *t, const silk_vertex_out *o)
{
    silk_aa_pt p = { 0, 0, 0, 0 };
    int64_t x, y;
    if (o->clip.w <= 0) return p;
    silk_raster_point(t, o, &x, &y, &p.d);
    p.ok = absl(x) < LIMIT && absl(y) < LIMIT;
    if (p.ok) {
        p.x = (int32_t)x;
        p.y = (int32_t)y;
    }
    return p;
}

/* Record r of geometry g on screen, through the vertex stage.  Only the
 * position of the stage's output counts here, and the default stage's is
 * the record's position through its view (phong.c): for a point of a
 * curve (eq. 5) that alone is worked out, not its normal, uv and colour
 * (where the build writes out its usual cases, SILK_FAST_CASES; the same
 * bits). */
static silk_aa_pt place(silk_aa *aa, const silk_geom *g, const silk_vrec *r)
{
    const silk_view *v;
    if (SILK_FAST_CASES && r->kind == SILK_VREC_CURVE && g->curves && (v = silk_hal_vertex_view(aa->hal))) {
        /* silk_vrec_eval's position */
        aa->out->clip = silk_view_clip(v, silk_hermite_point(&g->curves[r->a], silk_fx_clamp(r->t, 0, SILK_FX_ONE)));
        return point(aa->t, aa->out);
    }
    aa->hal->vertex(aa->hal, g, r, aa->out);
    return point(aa->t, aa->out);
}

/* (b - a) x (c - a) on screen */
static int64_t area2(const silk_aa_pt *a, const silk_aa_pt *b, const silk_aa_pt *c)
{
    return (int64_t)(b->x - a->x) * (c->y - a->y) - (int64_t)(b->y - a->y) * (c->x - a->x);
}

#define AL(n) (((size_t)(n) + SILK_ARENA_ALIGN - 1) & ~(size_t)(SILK_ARENA_ALIGN - 1))

/* The one block silk_aa_begin takes, before its pixel list: aprons rows
 * of colour and depth, then a projected point per record, the side
 * walk's, one vertex-stage output and one curve, each part aligned. */
static size_t fixed_bytes(size_t w, size_t bpp, int aprons, uint32_t max_recs)
{
    return (size_t)aprons * (AL(w * bpp) + AL(w * sizeof(uint32_t))) + AL(max_recs * sizeof(silk_aa_pt)) +
           AL(SILK_AA_WALK * sizeof(silk_aa_pt)) + AL(sizeof(silk_vertex_out)) + AL(sizeof(silk_curve));
}

/* An outline crosses a band about once per row or column it spans: room
 * for three times the band's width and height (a knot at 640x480 needs
 * 2.4 times). */
static size_t px_wanted(size_t w, int rows)
{
    return 3 * (w + (size_t)rows);
}

SILK_ALWAYS_INLINE   /* into each: a board without scenes has silk_aa_begin alone, with nobj 1 */
static inline int aa_begin(silk_aa *aa, silk_arena *a, silk_target *t, uint32_t max_recs, uint32_t nobj)
{
    memset(aa, 0, sizeof *aa);
    aa->t = t;
    size_t bpp = silk_pixfmt_bytes(t->fmt), w = (size_t)t->width;
    int y[2] = { t->y0 - 1, t->y0 + t->rows }, aprons = 0;   /* none outside the frame */
    for (int i = 0; i < 2; i++) aprons += y[i] >= 0 && y[i] < t->height;
    size_t fixed = fixed_bytes(w, bpp, aprons, max_recs), free_bytes = silk_arena_free_bytes(a);
    if (free_bytes < fixed) return 0;
    /* the pixel list: what is wanted, or what is left (the rest is left
     * aliased, and counted); the renderer leaves silk_aa_bytes free */
    size_t want = px_wanted(w, t->rows) * nobj, room = (free_bytes - fixed) / sizeof *aa->px;
    aa->cap = (uint32_t)(want < room ? want : room);
    uint8_t *p = silk_arena_alloc_top(a, fixed + aa->cap * sizeof *aa->px, SILK_MEM_FRAME);
    if (!p) return 0;
    for (int i = 0; i < 2; i++) {
        if (y[i] < 0 || y[i] >= t->height) continue;
        silk_target_init(&aa->apron[i], t->width, t->height, y[i], 1, t->fmt, p, (uint32_t *)(void *)(p + AL(w * bpp)));
        p += AL(w * bpp) + AL(w * sizeof(uint32_t));
    }
    aa->npt = max_recs;
    aa->pt = (silk_aa_pt *)(void *)p;
    /* a side's scratch from the arena, not the stack: the walk is the deepest call of a frame */
    aa->walk = (silk_aa_pt *)(void *)(p += AL(max_recs * sizeof(silk_aa_pt)));
    aa->out = (silk_vertex_out *)(void *)(p += AL(SILK_AA_WALK * sizeof(silk_aa_pt)));
    aa->curve = (silk_curve *)(void *)(p += AL(sizeof(silk_vertex_out)));
    aa->px = (silk_aa_px *)(void *)(p + AL(sizeof(silk_curve)));
    return 1;
}

int silk_aa_begin(silk_aa *aa, silk_arena *a, silk_target *t, uint32_t max_recs)
{
    return aa_begin(aa, a, t, max_recs, 1);
}

int silk_aa_begin_n(silk_aa *aa, silk_arena *a, silk_target *t, uint32_t max_recs, uint32_t nobj)
{
    return aa_begin(aa, a, t, max_recs, nobj);
}

SILK_ALWAYS_INLINE
static inline size_t aa_bytes(const silk_target *t, uint32_t max_recs, uint32_t nobj)
{
    size_t w = (size_t)t->width;
    return fixed_bytes(w, silk_pixfmt_bytes(t->fmt), 2, max_recs) +
           AL(px_wanted(w, t->rows) * nobj * sizeof(silk_aa_px));
}

size_t silk_aa_bytes(const silk_target *t, uint32_t max_recs)
{
    return aa_bytes(t, max_recs, 1);
}

size_t silk_aa_bytes_n(const silk_target *t, uint32_t max_recs, uint32_t nobj)
{
    return aa_bytes(t, max_recs, nobj);
}
#undef AL

/* Pixel (x, y) of the band or its aprons: colour and depth; 0 if neither has it. */
static int fetch(const silk_aa *aa, int x, int y, uint32_t *rgb, uint32_t *d)
{
    const silk_target *s = aa->t;
    if (y < s->y0 || y >= s->y0 + s->rows) s = &aa->apron[y < s->y0 ? 0 : 1];
    if (!s->rows || y < s->y0 || y >= s->y0 + s->rows || x < 0 || x >= s->width)
        return 0;
    *rgb = silk_target_get(s, x, y);
    *d = s->depth[(size_t)(y - s->y0) * (size_t)s->width + (size_t)x];
    return 1;
}

/* Pixel (x, y) becomes cov / FRAC of colour ci over co, ai and ao saying
 * whether each holds anything (alpha plane only: an empty pixel has no
 * colour and weighs nothing). */
static void blend(silk_aa *aa, int x, int y, uint32_t cov, uint32_t ci, uint32_t co, uint32_t ai, uint32_t ao)
{
    const silk_target *t = aa->t;
    uint32_t c8 = (cov * 255 + FRAC / 2) / FRAC;
    if (!t->alpha) ai = ao = 255;
    uint32_t wi = c8 * ai, wo = (255 - c8) * ao, sum = wi + wo, rgb = 2 * cov > FRAC ? ci : co;
    if (sum) {
        rgb = 0;
        for (int s = 16; s >= 0; s -= 8)
            rgb |= ((wi * ((ci >> s) & 255) + wo * ((co >> s) & 255) + sum / 2) / sum) << s;
    }
    if (aa->npx == aa->cap) {
        aa->dropped++;
        return;
    }
    silk_aa_px *p = &aa->px[aa->npx++];
    p->x = (uint16_t)x;
    p->y = (uint16_t)y;
    p->argb = ((sum + 127) / 255) << 24 | rgb;
}

/* Pixel r of column c (rows across the walk; steep: the roles of x and y
 * swapped), which the outline covers by cov / FRAC, its inside towards r +
 * dir.  What a pixel holds, by its depth against the outline's, ds: the
 * surface (within tol of it), something behind it or nothing (further),
 * or something in front (nearer than ds + tol: the outline is hidden
 * there and the pixel left alone).  The pixel is the surface's colour
 * over what lies behind, the two taken from it and its neighbour across
 * the outline: a pixel holding the surface is the inside, the one beyond
 * it (r - dir) the outside; a pixel holding what is behind is the
 * outside, the one within (r + dir) the inside.  Only neighbours, so the
 * rows a band reads are its own and its aprons; where the neighbour is
 * not what is needed (the surface two pixels past the outline, or not
 * within it) the pixel is left as drawn. */
static void crossing(silk_aa *aa, int steep, int c, int r, int dir, uint32_t cov, int64_t ds, int64_t tol, int cut)
{
    const silk_target *t = aa->t;
    int x = steep ? r : c, y = steep ? c : r;
    if (y < t->y0 || y >= t->y0 + t->rows || x < 0 || x >= t->width) return;
    uint32_t cr, dr, cn, dn;
    if (!fetch(aa, x, y, &cr, &dr)) return;
    int sr = (int64_t)dr > ds + tol ? 2 : (int64_t)dr + tol >= ds;   /* 2: in front, 1: the surface, 0: behind */
    /* a curve may thin a pixel drawn covered to half, not empty it (see side()) */
    if (sr == 1 && cut == 2 && cov < FRAC / 2) cov = FRAC / 2;
    if (sr == 2 || cov == (sr ? FRAC : 0) || (sr && !cut)) return;   /* hidden, as drawn, or kept */
    int n = sr ? r - dir : r + dir;
    if (!fetch(aa, steep ? n : c, steep ? c : n, &cn, &dn)) return;
    int sn = (int64_t)dn > ds + tol ? 2 : (int64_t)dn + tol >= ds;
    /* an empty pixel shows the outline is not hidden there: something in
     * front of the surface next to it (where two outlines meet) lends its colour */
    if ((sn == 2 && (sr || dr)) || sn == sr) return;
    if (sr) blend(aa, x, y, cov, cr, cn, 255, dn ? 255 : 0);
    else blend(aa, x, y, cov, cn, cr, 255, dr ? 255 : 0);
}

/* Pixel r of column c next to a crease (see side()), which the face on
 * the inside (towards r + dir) covers by cov / FRAC.  Both faces are
 * drawn up to the chord: the pixel the chord leaves inside, ri, holds the
 * inside's colour and the one before it the outside's.  The pixel becomes
 * the two blended by the coverage when it and both of those hold the
 * surface (depths within tol of the crease's: nothing in front hides it). */
static void crease_px(silk_aa *aa, int steep, int c, int64_t r, int64_t ri, int dir, uint32_t cov, int64_t ds,
                      int64_t tol)
{
    const silk_target *t = aa->t;
    int64_t rr[3] = { r, ri, ri - dir };
    uint32_t rgb[3], d;
    int x = steep ? (int)r : c, y = steep ? c : (int)r;
    if (cov == ((r - ri) * dir >= 0 ? FRAC : 0) || y < t->y0 || y >= t->y0 + t->rows || x < 0 || x >= t->width)
        return;   /* as drawn, or not the band's */
    /* across rows, only where both colour pixels are next to it: a band
     * reads one row past its own, and a frame must not depend on its bands */
    if (!steep && (r - ri > 1 || ri - r > 1 || r - (ri - dir) > 1 || (ri - dir) - r > 1)) return;
    for (int i = 0; i < 3; i++)
        if (!fetch(aa, steep ? (int)rr[i] : c, steep ? c : (int)rr[i], &rgb[i], &d) || !d ||
            (int64_t)d > ds + tol || (int64_t)d + tol < ds)
            return;
    blend(aa, x, y, cov, rgb[1], rgb[2], 255, 255);
}

/* Where a through b crosses u = uc, in 1/FRAC pixels across (a.x <= uc < b.x). */
static int64_t cross_at(const silk_aa_pt *a, const silk_aa_pt *b, int32_t uc)
{
    return (int64_t)a->y * (FRAC / SILK_RASTER_SUB) +
           floor_div((int64_t)(uc - a->x) * (b->y - a->y) * (FRAC / SILK_RASTER_SUB), b->x - a->x);
}

/* Walk side p-q, whose inside is the side of it `in` lies on; tol: how
 * far from the side's depth its surface may be seen (tolerance()).  The
 * rasterizer drew the chord p-q; with mid (SUBDIV - 1 points from p to q)
 * the outline is the curve through them, and the pixels between the two
 * get the curve's coverage too, their colours from the drawn pixels next
 * to the chord.  curve: 0 a straight side, 1 a silhouette segment, 2 a
 * crease (the two sides are faces, each pixel blended by crease_px). */
/* The pixel centres a side walks, lo .. hi - 1 along u (x, or y when
 * steep) for a walk from u = a to u = b > a: those in [a, b), of the
 * band's rows or the frame's columns. */
static void walk_range(const silk_target *t, int steep, int32_t a, int32_t b, int64_t *lo, int64_t *hi)
{
    int64_t ulo = steep ? t->y0 : 0, uhi = steep ? t->y0 + t->rows : t->width;   /* only the band's rows matter */
    *lo = floor_div(a + SILK_RASTER_SUB / 2 - 1, SILK_RASTER_SUB);
    *hi = floor_div(b + SILK_RASTER_SUB / 2 - 1, SILK_RASTER_SUB);
    if (*lo < ulo) *lo = ulo;
    if (*hi > uhi) *hi = uhi;
}

/* Whether side() from p to q walks any pixel: a chord shorter than a
 * pixel often passes between centres, and then the curve's points along
 * it are not needed. */
static int walks_any(const silk_target *t, const silk_aa_pt *p, const silk_aa_pt *q)
{
    int steep = absl(q->y - p->y) > absl(q->x - p->x);
    int32_t a = steep ? p->y : p->x, b = steep ? q->y : q->x;
    int64_t lo, hi;
    if (a == b) return 0;
    walk_range(t, steep, a < b ? a : b, a < b ? b : a, &lo, &hi);
    return lo < hi;
}

static void side(silk_aa *aa, silk_aa_pt p, silk_aa_pt q, const silk_aa_pt *in, int64_t tol, const silk_aa_pt *mid,
                 int curve)
{
    int64_t cross = area2(&p, &q, in);
    if (!cross) return;
    silk_aa_pt *k = aa->walk;
    k[0] = p;
    k[SUBDIV] = q;
    for (int j = 1; mid && j < SUBDIV; j++) k[j] = mid[j - 1];
    /* u along the walk (x, or y when steep), v across; then p before q */
    int steep = absl(q.y - p.y) > absl(q.x - p.x);
    if (steep)
        for (int j = 0; j <= SUBDIV; j++) {
            int32_t s = k[j].x;
            k[j].x = k[j].y, k[j].y = s;
        }
    /* the inside is towards +v when (cross > 0) == (u grows from p to q), the opposite walking y */
    int dir = ((cross > 0) == (k[SUBDIV].x > k[0].x)) != steep ? 1 : -1;
    if (k[SUBDIV].x < k[0].x)
        for (int j = 0; j < SUBDIV / 2; j++) {
            silk_aa_pt s = k[j];
            k[j] = k[SUBDIV - j], k[SUBDIV - j] = s;
        }
    /* the curve is followed where it runs along u as the chord does */
    for (int j = 0; mid && j < SUBDIV; j++)
        if (k[j + 1].x < k[j].x) mid = NULL;
    p = k[0];
    q = k[SUBDIV];
    const silk_target *t = aa->t;
    int32_t du = q.x - p.x, dd = (int32_t)(q.d >> 1) - (int32_t)(p.d >> 1);   /* depth to 31 bits */
    if (!du) return;
    int64_t lo, hi;
    walk_range(t, steep, p.x, q.x, &lo, &hi);
    int j = 0;
    for (int64_t c = lo; c < hi; c++) {
        int32_t uc = (int32_t)c * SILK_RASTER_SUB + SILK_RASTER_SUB / 2, U = uc - p.x;
        /* the chord, as drawn: the pixel it leaves inside, and the one outside */
        int64_t ve = cross_at(&p, &q, uc), rc = floor_div(ve, FRAC), fc = ve - rc * FRAC;
        int here = 2 * (dir > 0 ? FRAC - fc : fc) > FRAC;
        int64_t ri = here ? rc : rc + dir, ro = ri - dir;
        /* the outline: where it crosses, and every pixel it covers otherwise than drawn */
        int64_t vk = ve;
        if (mid) {
            while (k[j + 1].x <= uc) j++;
            vk = cross_at(&k[j], &k[j + 1], uc);
        }
        int64_t rk = floor_div(vk, FRAC), fk = vk - rk * FRAC;
        int64_t ds = 2 * ((int64_t)(p.d >> 1) + (int64_t)dd * U / du);
        uint32_t snap = curve == 1 || (curve && mid) ? SNAP_CURVE : SNAP;
        /* every pixel from the chord's two to the curve's, whose coverage
         * may differ from what was drawn, and along a curve two more each
         * way: where the share's parts do not fold the outline drawn is a
         * side off the chord, and each of its pixels near the curve takes
         * the curve's coverage (left out, one would stand out of the line) */
        int64_t r0 = ri < ro ? ri : ro, r1 = r0 + 1;
        if (rk < r0 && curve) r0 = rk;
        if (rk > r1 && curve) r1 = rk;
        if (curve == 1 && steep) r0 -= 2, r1 += 2;   /* along its row: a band reads one row past its own */
        for (int64_t r = r0; r <= r1; r++) {
            /* covered: the part of the pixel on the inside */
            uint32_t cov = (uint32_t)(r == rk ? (dir > 0 ? FRAC - fk : fk) : (r - rk) * dir > 0 ? FRAC : 0);
            cov = cov < snap ? 0 : cov > FRAC - snap ? FRAC : cov;
            if (SILK_AA_CREASES && curve == 2) {
                crease_px(aa, steep, (int)c, r, ri, dir, cov, ds, tol);
                continue;
            }
            crossing(aa, steep, (int)c, (int)r, dir, cov, ds, tol, curve ? 2 : r == ri);
        }
    }
}

/* How far from a side's depth the surface of its triangle a b c may be
 * seen: the triangle's depth range (near a silhouette the surface is seen
 * edge-on and rises steeply from the side) and 1/64 of the depth. */
static int64_t tolerance(const silk_aa_pt *a, const silk_aa_pt *b, const silk_aa_pt *c)
{
    uint32_t lo = a->d, hi = a->d;
    const silk_aa_pt *p[2] = { b, c };
    for (int i = 0; i < 2; i++) {
        if (p[i]->d < lo) lo = p[i]->d;
        if (p[i]->d > hi) hi = p[i]->d;
    }
    return (int64_t)(hi - lo) + hi / 64;
}

/* Side a-b of a triangle a b c (walked when all three are placed). */
static void tri_side(silk_aa *aa, const silk_aa_pt *a, const silk_aa_pt *b, const silk_aa_pt *c, const silk_aa_pt *mid)
{
    if (a->ok && b->ok && c->ok) side(aa, *a, *b, c, tolerance(a, b, c), mid, 0);
}

/* silk_sil_tri_front, through aa->facing when there is one: the outline
 * test asks it of a triangle once for itself and once for each neighbour. */
static inline int memo_front(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint32_t t)
{
    uint8_t *b = &aa->facing[t / 4];
    unsigned sh = 2 * (t % 4);
    if (!(*b >> sh & 2)) *b = (uint8_t)(*b | (2u | (unsigned)silk_sil_tri_front(m, v, t)) << sh);
    return *b >> sh & 1;
}

static int tri_front(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint32_t t)
{
    return aa->facing ? memo_front(aa, m, v, t) : silk_sil_tri_front(m, v, t);
}

/* FLAT's rule for side k of input triangle t. */
static int coarse_outline(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint32_t t, int k, int front)
{
    silk_index e = silk_mesh_tri_edge(m, t, k);   /* a packed mesh has no tri_edge */
    if (e >= silk_mesh_edge_bound(m)) return 0;
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    uint32_t nb = ed->t[0] == t ? ed->t[1] : ed->t[0];
    if (nb == SILK_NO_INDEX || nb >= m->ntris) return 1;
    /* SMOOTH: an edge of a silhouette triangle lies within its segment's curve, which is walked instead */
    if (aa->sil && aa->sil->tri_state && (aa->sil->tri_state[nb] & SILK_TS_SIL)) return 0;
    return front && !tri_front(aa, m, v, nb);
}

/* Whether side k of input triangle t is a visible crease walked from t: a
 * feature edge between t and a triangle after it, both facing the eye. */
static int crease(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint32_t t, int k, int front)
{
    silk_index e = silk_mesh_tri_edge(m, t, k);
    if (!front || e >= silk_mesh_edge_bound(m) || !silk_edge_has_feature((const silk_edge[]){ silk_mesh_edge(m, e) })) return 0;
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    uint32_t nb = ed->t[0] == t ? ed->t[1] : ed->t[0];
    return nb != SILK_NO_INDEX && nb < m->ntris && nb > t && tri_front(aa, m, v, nb);
}

/* Point u of curve c (NULL: corner record `corner`) through the vertex stage. */
static silk_aa_pt crease_point(silk_aa *aa, const silk_curve *c, silk_fx u, uint32_t corner)
{
    silk_geom og = *aa->geom;
    silk_vrec r = { SILK_VREC_CORNER, corner, 0, 0 };
    if (c) {
        *aa->curve = *c;
        og.curves = aa->curve;
        r.kind = SILK_VREC_CURVE, r.a = 0, r.t = u;
    }
    return place(aa, &og, &r);
}

/* Crease side k of input triangle t: the chords the two faces are drawn
 * up to, each pixel they cross blended by the faces' coverage of it.  In
 * SMOOTH a sampled feature edge is its feature segment's curve (eq. 1-4)
 * drawn as chords between its samples (eq. 8), each followed as SUBDIV
 * chords of the curve; otherwise the mesh edge.  The inside is t's, where
 * its third corner lies; the depth tolerance t's range (tolerance()). */
static void crease_walk(silk_aa *aa, uint32_t t, int k)
{
    silk_aa_pt a = crease_point(aa, NULL, 0, 3 * t + (uint32_t)k), b = crease_point(aa, NULL, 0, 3 * t + (k + 1) % 3),
               in = crease_point(aa, NULL, 0, 3 * t + (k + 2) % 3);
    if (!a.ok || !b.ok || !in.ok) return;
    int64_t tol = tolerance(&a, &b, &in);
    const silk_sil_edge *e = aa->sil ? silk_sil_side_edge(aa->sil, t, (uint32_t)k) : NULL;
    if (!e || !e->sampled || !e->nfeat) {
        side(aa, a, b, &in, tol, NULL, 2);
        return;
    }
    silk_curve c;
    silk_sil_edge_curve(aa->sil, e, &c);
    silk_aa_pt *mid = aa->walk + SUBDIV + 1;
    silk_fx ua = 0;
    for (uint32_t i = 0; i <= e->nchain; i++) {
        silk_fx ub = i < e->nchain ? aa->sil->chain[e->chain0 + i] : SILK_FX_ONE;
        silk_aa_pt p = crease_point(aa, &c, ua, 0), q = crease_point(aa, &c, ub, 0);
        int ok = p.ok && q.ok;
        for (int j = 1; ok && j < SUBDIV; j++) {
            mid[j - 1] = crease_point(aa, &c, ua + (silk_fx)(((int64_t)ub - ua) * j / SUBDIV), 0);
            ok = mid[j - 1].ok;
        }
        if (ok) side(aa, p, q, &in, tol, mid, 2);
        ua = ub;
    }
}

/* tri_front with the memo's answer read in place (the candidate test asks
 * it of every triangle and its neighbours every band). */
static inline int tri_front_known(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint32_t t)
{
    unsigned b = aa->facing ? (unsigned)aa->facing[t / 4] >> 2 * (t % 4) : 0;
    return b & 2 ? (int)(b & 1) : tri_front(aa, m, v, t);
}

int silk_aa_candidate(silk_aa *aa, const silk_mesh *m, const silk_view *v, const silk_sil_frame *f, uint32_t t)
{
    if (f && f->tri_state && (f->tri_state[t] & SILK_TS_SIL)) return 1;
    if (!SILK_AA_CREASES) {   /* coarse_outline's rule alone */
        int front = tri_front(aa, m, v, t);
        for (int k = 0; k < 3; k++)
            if (coarse_outline(aa, m, v, t, k, front)) return 1;
        return 0;
    }
    int front = tri_front_known(aa, m, v, t);
    /* A triangle facing away from the eye has an outline side only against
     * nothing, which a closed mesh has none of (orient.c): half of such a
     * mesh is done with here (where the usual cases are written out; a
     * board keeps the code bytes). */
    if (SILK_FAST_CASES && !front && m->closed_outward) return 0;
    /* coarse_outline's and crease's rules at once (asked of every triangle
     * every band): each side's edge looked up once, its neighbour's facing
     * asked once, and only where t faces the eye */
    for (int k = 0; k < 3; k++) {
        silk_index e = silk_mesh_tri_edge(m, t, (uint32_t)k);
        if (e >= silk_mesh_edge_bound(m)) continue;
        const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
        uint32_t nb = ed->t[0] == t ? ed->t[1] : ed->t[0];
        if (nb == SILK_NO_INDEX || nb >= m->ntris) return 1;
        if (!front) continue;
        int walked = aa->sil && aa->sil->tri_state && (aa->sil->tri_state[nb] & SILK_TS_SIL);
        int feature = aa->creases && nb > t && silk_edge_has_feature(ed);
        if (walked && !feature) continue;
        if (tri_front_known(aa, m, v, nb) ? feature : !walked) return 1;
    }
    return 0;
}

void silk_aa_candidates(silk_aa *aa, const silk_mesh *m, const silk_view *v, uint8_t *cand)
{
    if (!SILK_AA_CANDIDATES) return;   /* (only its caller's) */
    silk_sil_tri_fronts(m, v, aa->facing);   /* every facing, in mesh order */
    memset(cand, 0, ((size_t)m->ntris + 7) / 8);
    const int creases = SILK_AA_CREASES ? aa->creases : 0;
    /* Closed: each edge is a side of its two triangles and of no other, so
     * silk_aa_candidate's rule per side is a rule per edge, and a
     * triangle facing away has no outline side.  SMOOTH: a silhouette
     * triangle is one, and a side against one is walked as its segment's
     * curve instead, unless it is a crease. */
    const uint8_t *ts = aa->sil ? aa->sil->tri_state : NULL;
    /* in locals: a byte stored into cand could alias them all */
    const uint8_t *facing = aa->facing;
    const uint32_t ntris = m->ntris;
    silk_mesh_edges it;
    silk_edge edv, *ed = &edv;
    for (silk_index e = silk_mesh_edges_first(m, &it, ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, ed)) {
        uint32_t t0 = ed->t[0], t1 = ed->t[1];
        if (t0 >= ntris || t1 >= ntris) continue;
        int f0 = facing[t0 / 4] >> 2 * (t0 % 4) & 1, f1 = facing[t1 / 4] >> 2 * (t1 % 4) & 1;   /* known */
        uint32_t mark = f0 != f1 ? (ts && (ts[f0 ? t1 : t0] & SILK_TS_SIL) ? SILK_NO_INDEX : f0 ? t0 : t1)   /* an outline side */
                        : f0 && creases && silk_edge_has_feature(ed) ? (t0 < t1 ? t0 : t1)   /* a crease, from its first triangle */
                        : SILK_NO_INDEX;
        if (mark != SILK_NO_INDEX) cand[mark / 8] = (uint8_t)(cand[mark / 8] | 1u << (mark % 8));
    }
    for (uint32_t t = 0; ts && t < m->ntris; t++)
        if (ts[t] & SILK_TS_SIL) cand[t / 8] = (uint8_t)(cand[t / 8] | 1u << (t % 8));
}

/* Where a share's silhouette segment is: its curve among the share's
 * curves, and the records of its ends A and B (the samples between are
 * records on the curve itself). */
typedef struct seg_at {
    uint32_t curve, a, b;
    uint32_t first;          /* the record of its first interior sample */
    const silk_vertex_out *out;   /* the share's vertex-stage output, placed into aa->pt as needed */
} seg_at;

/* Record rec's parameter on the segment's curve; 0 if it is not on it. */
static int seg_param(const seg_at *s, const silk_frame_geom *g, uint32_t rec, silk_fx *u)
{
    const silk_vrec *r = &g->vrec[rec];
    if (rec == s->a || rec == s->b) *u = rec == s->a ? 0 : SILK_FX_ONE;
    else if (r->kind == SILK_VREC_CURVE && r->a == s->curve) *u = r->t;
    else return 0;
    return 1;
}

/* The segment's curve between records ra and rb, SUBDIV - 1 points from
 * ra's end, projected by the vertex stage; 0 where the side is not one of
 * its chords. */
static int seg_points(silk_aa *aa, const seg_at *s, const silk_frame_geom *g, uint32_t ra, uint32_t rb,
                      silk_aa_pt *mid)
{
    silk_fx ua, ub;
    if (!s || !seg_param(s, g, ra, &ua) || !seg_param(s, g, rb, &ub) || ua == ub) return 0;
    for (int j = 1; j < SUBDIV; j++) {
        silk_vrec r = { SILK_VREC_CURVE, s->curve, 0, ua + (silk_fx)(((int64_t)ub - ua) * j / SUBDIV) };
        mid[j - 1] = place(aa, aa->geom, &r);
        if (!mid[j - 1].ok) return 0;
    }
    return 1;
}

/* Where the segment's outside is on screen, (ox, oy) from A, and the
 * share's depth tolerance; 0 when A or its outside is not placed. */
static int seg_outward(silk_aa *aa, const silk_frame_geom *g, const seg_at *s, int32_t *ox, int32_t *oy, int64_t *tol)
{
    /* A moved out along its normal by a sixteenth of the segment, projected */
    const silk_curve *c = &aa->geom->curves[s->curve];
    silk_curve *o = aa->curve;
    *o = *c;
    o->p1 = o->p0 = silk_v3_add(c->p0, silk_v3_scale(c->n0, silk_v3_length(silk_v3_sub(c->p1, c->p0)) / 16));
    o->t0 = o->t1 = silk_v3(0, 0, 0);
    silk_geom og = *aa->geom;
    og.curves = o;
    silk_vrec r = { SILK_VREC_CURVE, 0, 0, 0 };
    silk_aa_pt n = place(aa, &og, &r);
    const silk_aa_pt *m = &aa->pt[s->a];
    *ox = n.x - m->x;
    *oy = n.y - m->y;
    if (!m->ok || !n.ok || (!*ox && !*oy)) return 0;
    uint32_t lo = UINT32_MAX, hi = 0;
    for (uint32_t i = 0; i < g->nvrec; i++) {
        aa->pt[i] = point(aa->t, &s->out[i]);   /* every record: the chords' again, the same */
        if (!aa->pt[i].ok) continue;
        if (aa->pt[i].d < lo) lo = aa->pt[i].d;
        if (aa->pt[i].d > hi) hi = aa->pt[i].d;
    }
    *tol = (int64_t)(hi - lo) + hi / 64;   /* A is placed: lo <= hi */
    return 1;
}

/* Silhouette triangle t's share: its segment walked chord by chord with
 * the curve's coverage, whether or not the share's two parts fold there on
 * screen (where they face the same way, the outline drawn is a side next
 * to the chord rather than the chord), and no other side of the share
 * (those lie within the curve).  The inside is away from where the
 * normal at A points on screen (it is perpendicular to the view there,
 * and the surface lies behind a visible outline).  The depth tolerance is
 * the whole share's range: the pixels next to the outline hold any of its
 * triangles. */
static void seg_walk(silk_aa *aa, const silk_frame_geom *g, const seg_at *s)
{
    /* the outside and the tolerance once a chord walks a pixel: a segment
     * of a fine mesh often walks none */
    int32_t ox = 0, oy = 0;
    int64_t tol = 0;
    int placed = 0;
    /* the samples: A, the records on the curve after the share's boundary, B */
    uint32_t a = s->a, b = s->first;
    silk_aa_pt *mid = aa->walk + SUBDIV + 1;
    aa->pt[a] = point(aa->t, &s->out[a]);   /* the chords' ends as they come; the rest only once placed */
    for (int last = 0; !last; a = b++) {
        last = b >= g->nvrec || g->vrec[b].kind != SILK_VREC_CURVE || g->vrec[b].a != s->curve;
        if (last) b = s->b;
        if (!placed) aa->pt[b] = point(aa->t, &s->out[b]);
        const silk_aa_pt *p = &aa->pt[a], *q = &aa->pt[b];
        if (!p->ok || !q->ok || !walks_any(aa->t, p, q)) continue;   /* side() would walk no pixel */
        if (!placed && !(placed = seg_outward(aa, g, s, &ox, &oy, &tol))) return;
        silk_aa_pt in = { (int32_t)(((int64_t)p->x + q->x) / 2 - ox), (int32_t)(((int64_t)p->y + q->y) / 2 - oy), 0, 1 };
        side(aa, *p, *q, &in, tol, seg_points(aa, s, g, a, b, mid) ? mid : NULL, 1);
    }
}

void silk_aa_share(silk_aa *aa, const silk_mesh *m, const silk_view *v, const silk_frame_geom *g,
                   const silk_vertex_out *out, uint32_t t)
{
    if (g->nvrec > aa->npt) return;
    for (int k = 0; SILK_AA_CREASES && aa->creases && k < 3; k++)
        if (crease(aa, m, v, t, k, tri_front(aa, m, v, t))) crease_walk(aa, t, k);
    const uint32_t *tri = g->tri;
    if (g->ntri == 1) {
        /* t as it is (one triangle is never re-meshed): its records are its corners 0, 1, 2 */
        for (uint32_t i = 0; i < g->nvrec; i++) aa->pt[i] = point(aa->t, &out[i]);
        int front = tri_front(aa, m, v, t);
        for (int k = 0; k < 3; k++)
            if (coarse_outline(aa, m, v, t, k, front))
                tri_side(aa, &aa->pt[tri[k]], &aa->pt[tri[(k + 1) % 3]], &aa->pt[tri[(k + 2) % 3]], NULL);
        return;
    }
    seg_at at;
    uint32_t rec[3];
    if (aa->sil && (aa->sil->tri_state[t] & SILK_TS_SIL) && silk_remesh_seg_at(aa->sil, t, rec, &at.curve)) {
        at.a = rec[0];
        at.b = rec[1];
        at.first = rec[2];
        at.out = out;
        seg_walk(aa, g, &at);
    }
}

/* Row y's depths as drawn (the band's or an apron's), *dk, and the hull's
 * front faces' in s, *dh; 0 when either has no such row. */
static int depth_rows(const silk_aa *aa, const silk_target *s, int y, const uint32_t **dk, const uint32_t **dh)
{
    const silk_target *t = aa->t;
    if (y < t->y0 || y >= t->y0 + t->rows) t = &aa->apron[y < aa->t->y0 ? 0 : 1];
    if (!t->rows || y < t->y0 || y >= t->y0 + t->rows || y < s->y0 || y >= s->y0 + s->rows) return 0;
    *dk = t->depth + (size_t)(y - t->y0) * (size_t)t->width;
    *dh = s->depth + (size_t)(y - s->y0) * (size_t)s->width;
    return 1;
}

/* Whether the pixel shows the hull's front face: drawn there, at its depth. */
static inline int front_at(const uint32_t *dk, const uint32_t *dh, int x) { return dh[x] && dk[x] == dh[x]; }

/* Whether pixel x of a row (dk, dh; the rows above and below, u and l, or
 * NULL) is on the outline: on the hull, with a neighbour across the change
 * between front face shown and not. */
static inline int on_outline(const uint32_t *dk, const uint32_t *dh, const uint32_t *uk, const uint32_t *uh,
                             const uint32_t *lk, const uint32_t *lh, int x, int width)
{
    if (!dh[x]) return 0;
    int f = dk[x] == dh[x];
    return (x > 0 && front_at(dk, dh, x - 1) != f) || (x + 1 < width && front_at(dk, dh, x + 1) != f) ||
           (uk && front_at(uk, uh, x) != f) || (lk && front_at(lk, lh, x) != f);
}

static void mask_set(silk_target *s, uint8_t *mask, int x, int y)
{
    if (x < 0 || x >= s->width || y < s->y0 || y >= s->y0 + s->rows) return;
    mask[(size_t)(y - s->y0) * (((size_t)s->width + 7) / 8) + (size_t)(x >> 3)] |= (uint8_t)(1u << (x & 7));
}

uint32_t silk_aa_margin_mask(silk_aa *aa, silk_target *s, uint8_t *mask)
{
    if (!SILK_SILTEX_MODE) return 0;   /* (only its caller's, render.c's SILTEX frames) */
    const silk_target *t = aa->t;
    memset(mask, 0, (size_t)s->rows * (((size_t)s->width + 7) / 8));
    s->mask = mask;
    uint32_t n = 0;
    for (int y = t->y0; y < t->y0 + t->rows; y++) {
        const uint32_t *dk, *dh, *uk = NULL, *uh = NULL, *lk = NULL, *lh = NULL;
        if (!depth_rows(aa, s, y, &dk, &dh)) continue;
        if (!depth_rows(aa, s, y - 1, &uk, &uh)) uk = NULL;
        if (!depth_rows(aa, s, y + 1, &lk, &lh)) lk = NULL;
        for (int x = 0; x < t->width; x++) {
            if (!on_outline(dk, dh, uk, uh, lk, lh, x, t->width)) continue;
            n++;
            mask_set(s, mask, x, y);
            mask_set(s, mask, x - 1, y);
            mask_set(s, mask, x + 1, y);
            mask_set(s, mask, x, y - 1);
            mask_set(s, mask, x, y + 1);
        }
    }
    return n;
}

/* The margin at (x, y) as s holds it (silk_siltex_margin_hal's code less
 * its zero); 0 where the margin stage drew nothing there. */
static int margin_at(const silk_target *s, int x, int y, int64_t *m)
{
    if (x < 0 || x >= s->width || y < s->y0 || y >= s->y0 + s->rows) return 0;
    size_t r = (size_t)(y - s->y0), i = r * (size_t)s->width + (size_t)x;
    if (!s->depth[i] || !(s->mask[r * (((size_t)s->width + 7) / 8) + (size_t)(x >> 3)] >> (x & 7) & 1)) return 0;
    *m = (int64_t)silk_target_get(s, x, y) - SILK_SILTEX_MARGIN_ZERO;
    return 1;
}

/* The field's change per pixel along one axis at a pixel where it is m,
 * from the neighbours a (before) and b (after) that have it (ha, hb):
 * from the one across the outline alone (the two values bracket the
 * crossing, and the field bends where phi's texels change), else
 * central, else one-sided, else 0. */
static int64_t slope(int ha, int64_t a, int64_t m, int hb, int64_t b)
{
    int xa = ha && (a <= 0) != (m <= 0), xb = hb && (b <= 0) != (m <= 0);
    if (xa != xb) return xa ? m - a : b - m;
    return ha && hb ? (b - a) / 2 : hb ? b - m : ha ? m - a : 0;
}

/* The part of a pixel, in 1/FRAC, where the linear field m + gx x + gy y
 * (x, y over [-1/2, 1/2]) is negative: the box filter of a straight edge,
 * exact (the field's distribution over the pixel is a trapezoid). */
static uint32_t box_cover(int64_t m, int64_t gx, int64_t gy)
{
    int64_t a = absl(gx), b = absl(gy);
    if (a < b) {
        int64_t s = a;
        a = b, b = s;
    }
    if (!a) return m <= 0 ? FRAC : 0;
    int64_t d2 = -2 * m, s2 = a + b, t2 = a - b;   /* twice the distances: d, the half width and the flat top's */
    if (d2 <= -s2) return 0;
    if (d2 >= s2) return FRAC;
    while (s2 >= (int64_t)1 << 21) {   /* |d2| < s2: every product below fits 64 bits */
        a >>= 1, b >>= 1, d2 = floor_div(d2, 2);
        s2 = a + b, t2 = a - b;
    }
    int64_t c;
    if (d2 < -t2) c = (d2 + s2) * (d2 + s2) * FRAC / (8 * a * b);
    else if (d2 > t2) c = FRAC - (s2 - d2) * (s2 - d2) * FRAC / (8 * a * b);
    else c = (a + d2) * FRAC / (2 * a);
    return (uint32_t)(c < 0 ? 0 : (c > FRAC ? FRAC : c));
}

/* Outline pixel (x, y) of the band: the front face's coverage of it from
 * the margin there and its slope (the field linear over the pixel), the
 * surface's colour over what lies behind, the two taken from it and its
 * neighbour across the outline (the way the margin grows: the outside),
 * along the axis it grows faster on, else the other: as crossing() does. */
static void margin_px(silk_aa *aa, const silk_target *s, int x, int y, int front)
{
    int64_t m, a = 0, b = 0, c = 0, e = 0;
    if (!margin_at(s, x, y, &m) || front != (m <= 0)) return;
    int ha = margin_at(s, x - 1, y, &a), hb = margin_at(s, x + 1, y, &b);
    int hc = margin_at(s, x, y - 1, &c), he = margin_at(s, x, y + 1, &e);
    int64_t gx = slope(ha, a, m, hb, b), gy = slope(hc, c, m, he, e);
    uint32_t cov = box_cover(m, gx, gy);
    cov = cov < SNAP ? 0 : cov > FRAC - SNAP ? FRAC : cov;
    if (cov == (front ? FRAC : 0)) return;   /* as drawn */
    uint32_t cr, dr, cn, dn;
    if (!fetch(aa, x, y, &cr, &dr)) return;
    for (int k = 0; k < 2; k++) {
        int xfirst = (absl(gx) >= absl(gy)) == !k;
        int64_t g = xfirst ? gx : gy;
        if (!g) continue;
        int dir = (g > 0) == front ? 1 : -1;   /* front: towards the outside; else towards the inside */
        int nx = xfirst ? x + dir : x, ny = xfirst ? y : y + dir;
        const uint32_t *nk, *nh;
        if (!depth_rows(aa, s, ny, &nk, &nh) || nx < 0 || nx >= s->width || front_at(nk, nh, nx) == front ||
            !fetch(aa, nx, ny, &cn, &dn))
            continue;
        if (front) blend(aa, x, y, cov, cr, cn, 255, dn ? 255 : 0);
        else blend(aa, x, y, cov, cn, cr, 255, dr ? 255 : 0);
        return;
    }
}

void silk_aa_margin(silk_aa *aa, const silk_target *s)
{
    if (!SILK_SILTEX_MODE) return;   /* (the same) */
    const silk_target *t = aa->t;
    size_t stride = ((size_t)s->width + 7) / 8;
    for (int y = t->y0; y < t->y0 + t->rows; y++) {
        const uint32_t *dk, *dh, *uk = NULL, *uh = NULL, *lk = NULL, *lh = NULL;
        if (!depth_rows(aa, s, y, &dk, &dh)) continue;
        if (!depth_rows(aa, s, y - 1, &uk, &uh)) uk = NULL;
        if (!depth_rows(aa, s, y + 1, &lk, &lh)) lk = NULL;
        const uint8_t *bits = s->mask + (size_t)(y - s->y0) * stride;
        for (int x = 0; x < t->width; x++) {
            if (!bits[x >> 3]) {   /* eight pixels at once: most are nowhere near the outline */
                x |= 7;
                continue;
            }
            if (bits[x >> 3] >> (x & 7) & 1 && on_outline(dk, dh, uk, uh, lk, lh, x, t->width))
                margin_px(aa, s, x, y, front_at(dk, dh, x));
        }
    }
}

void silk_aa_alpha(silk_target *t)
{
    if (!t->alpha) return;
    size_t n = (size_t)t->rows * (size_t)t->width;
    for (size_t i = 0; i < n; i++) t->alpha[i] = t->depth && t->depth[i] ? 255 : 0;
}

void silk_aa_finish(silk_aa *aa)
{
    silk_target *t = aa->t;
    silk_aa_alpha(t);
    for (uint32_t i = 0; i < aa->npx; i++) {
        const silk_aa_px *p = &aa->px[i];
        silk_target_put(t, p->x, p->y, p->argb & 0xFFFFFF);
        if (t->alpha) t->alpha[(size_t)(p->y - t->y0) * (size_t)t->width + p->x] = (uint8_t)(p->argb >> 24);
    }
}
