/*
 * lines.c - pen-and-ink lines: the outline of what a frame draws, as
 * polylines of vertex records for silk_raster_line.
 *
 * SMOOTH mode (paper III-D and III-A): each silhouette segment S(t) of eq. 5
 * through its n+1 samples of eq. 8 (A, the interior samples, B), and each
 * visible feature segment through its end vertices and its edge chain.
 * The records are copies of the ones the re-meshed triangles use, so a line
 * runs exactly along the triangle edges that make the drawn outline: at
 * the silhouette it is the boundary of the rendered object, bit for bit.
 * The outline also runs where no segment is: along a mesh edge the surface
 * folds over (the two triangles on it face opposite ways), round a cone's
 * apex.  So after the vertex stage the contour of the drawn triangles -
 * every side shared by two triangles that face opposite ways on screen,
 * the records matched by their clip positions - is added as silhouette
 * lines (silk_lines_contour).
 *
 * The polygonal outline of the coarse mesh, FLAT mode's outline and, on
 * request, a comparison in any mode: every edge between a front-facing and
 * a back-facing triangle (the face-based silhouette) and every feature
 * edge next to a front-facing triangle, corner to corner.
 *
 * Which parts show is left to the depth test of silk_raster_line against
 * the drawn surface.  Its own bias is not enough here: next to a
 * silhouette the surface is seen edge-on, so a triangle that ends on the
 * line can be much nearer than the line half a pixel away from it, and
 * the line would break up.  So each line vertex is lifted towards the eye
 * by what the triangles through it rise over one pixel (their depth slope,
 * at most their depth extent): a polygon offset scaled by slope, as
 * glPolygonOffset does, but only by the triangles the line lies on (where
 * one of them is narrower than a pixel, as the slivers re-meshing fans
 * from a vertex to the silhouette samples are, by the triangles beyond
 * it, on which the line's pixels lie); and
 * by 1/LINE_NEAR of its depth, for the surface half a pixel inside a
 * silhouette, whose depth rises like the square root of the distance from
 * it, faster than any triangle's slope at the line.
 */
#include <string.h>
#include "lines.h"
#include "remesh.h"

/* Room for nlines polylines over nrec records, from the top of the arena. */
static int lines_alloc(silk_arena *a, silk_frame_geom *g, uint32_t nlines, uint64_t nrec)
{
    g->nlines = g->nline_vrec = 0;
    if (nrec > UINT32_MAX || nlines == UINT32_MAX) return 0;
    g->line_vrec = silk_arena_array_top(a, (size_t)nrec, sizeof *g->line_vrec, SILK_MEM_FRAME);
    g->line_src = silk_arena_array_top(a, (size_t)nrec, sizeof *g->line_src, SILK_MEM_FRAME);
    g->line_start = silk_arena_array_top(a, (size_t)nlines + 1, sizeof *g->line_start, SILK_MEM_FRAME);
    g->line_feature = silk_arena_array_top(a, nlines, 1, SILK_MEM_FRAME);
    if (!g->line_vrec || !g->line_src || !g->line_start || !g->line_feature) return 0;
    g->line_start[0] = 0;
    return 1;
}

static void line_point(silk_frame_geom *g, const silk_vrec *r, uint32_t src)
{
    g->line_src[g->nline_vrec] = src;
    g->line_vrec[g->nline_vrec++] = *r;
}

/* Record i of the frame, as a line point. */
static void line_rec(silk_frame_geom *g, uint32_t i) { line_point(g, &g->vrec[i], i); }

static void line_end(silk_frame_geom *g, int feature)
{
    g->line_feature[g->nlines++] = (uint8_t)feature;
    g->line_start[g->nlines] = g->nline_vrec;
}

/* Which point record r is: records at a mesh vertex (its corners, moved
 * as one) are one point, keyed by the vertex; any other record is its own. */
static uint32_t point_key(const silk_mesh *m, const silk_frame_geom *g, uint32_t r)
{
    const silk_vrec *v = &g->vrec[r];
    if (g->rec_key) return g->rec_key[r];
    if ((v->kind == SILK_VREC_CORNER || v->kind == SILK_VREC_MOVED) && v->a / 3 < m->ntris && silk_mesh_corner(m, v->a) < m->nverts)
        return silk_mesh_corner(m, v->a);
    return m->nverts + r;
}

/* ---- SMOOTH mode ------------------------------------------------------------- */

/* The sides on each carrying edge, in the plan's order (triangle by
 * triangle): at[side0[w] + i] is 3t+k of edge w's side i. */
static uint32_t *edge_sides(const silk_sil_frame *f, uint32_t **side0)
{
    const silk_mesh *m = f->m;
    uint32_t *at = silk_arena_array_top(f->a, f->nsides, sizeof *at, SILK_MEM_FRAME);
    uint32_t *n = silk_arena_array_top(f->a, f->nedges, sizeof *n, SILK_MEM_FRAME);
    uint32_t *s0 = silk_arena_array_top(f->a, f->nedges, sizeof *s0, SILK_MEM_FRAME);
    if (!at || !n || !s0) return NULL;
    memset(n, 0, (size_t)f->nedges * sizeof *n);
    for (uint32_t w = 0, k = 0; w < f->nedges; k += f->edges[w++].nsides) s0[w] = k;
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (!silk_sil_tri_ok(m, t)) continue;
        for (uint32_t k = 0; k < 3; k++) {
            uint32_t w = silk_sil_slot(f, silk_mesh_tri_edge(m, t, k));
            if (w != SILK_SIL_NONE) at[s0[w] + n[w]++] = 3 * t + k;
        }
    }
    *side0 = s0;
    return at;
}

/* The first record of side c's (3t+k) chain in the stored frame g. */
static uint32_t side_rec(const silk_sil_frame *f, const silk_frame_geom *g, uint32_t c)
{
    return silk_remesh_corner_rec(f, c / 3, c % 3, g->part_rec[c / 3]) + 1;
}

/* Which point each record of g is (g->rec_key, for silk_lines_lift): a
 * mesh vertex for its corners; for the copies of an edge's point made by
 * sides with the same normals and uvs, the first such side's record; any
 * other record is its own point. */
static int point_keys(const silk_sil_frame *f, silk_frame_geom *g, const uint32_t *at, const uint32_t *side0)
{
    const silk_mesh *m = f->m;
    uint32_t *key = silk_arena_array_top(f->a, g->nvrec, sizeof *key, SILK_MEM_FRAME);
    if (!key) return 0;
    g->rec_key = NULL;
    for (uint32_t r = 0; r < g->nvrec; r++) key[r] = point_key(m, g, r);
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        for (uint32_t i = 0; e->nchain && i < e->nsides; i++) {
            silk_sil_side s, o;
            uint32_t c = at[side0[w] + i], own = c;
            silk_sil_side_attrs(m, c / 3, c % 3, silk_mesh_edge_v0(m, e->edge), &s);
            for (uint32_t j = 0; j < i; j++) {
                own = at[side0[w] + j];
                silk_sil_side_attrs(m, own / 3, own % 3, silk_mesh_edge_v0(m, e->edge), &o);
                if (o.n0 == s.n0 && o.n1 == s.n1 && o.uv0 == s.uv0 && o.uv1 == s.uv1) break;
                own = c;
            }
            uint32_t rec = side_rec(f, g, c), first = side_rec(f, g, own);
            for (uint32_t j = 0; j < e->nchain; j++) key[rec + j] = m->nverts + first + j;
        }
    }
    g->rec_key = key;
    return 1;
}

silk_status silk_lines_smooth(const silk_sil_frame *f, silk_frame_geom *g)
{
    const silk_mesh *m = f->m;
    uint32_t nlines = f->nsegs;
    uint64_t nrec = f->seg_samples + 2 * (uint64_t)f->nsegs;
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        if (!e->sampled || !e->nsides) continue;
        nlines++;
        nrec += 2 + e->nchain;
    }
    uint32_t *side0 = NULL, *at = edge_sides(f, &side0);
    if (!at || !point_keys(f, g, at, side0) || !lines_alloc(f->a, g, nlines, nrec)) return SILK_ERR_NOMEM;

    /* Each silhouette segment through A, its samples and B: the records
     * of its triangle's share (the samples follow the boundary). */
    for (uint32_t t = 0; t < m->ntris; t++) {
        silk_sil_seg s;
        if (!(f->tri_state[t] & SILK_TS_SIL) || !silk_remesh_seg(f, t, &s)) continue;
        uint32_t rec[3];
        silk_remesh_seg_recs(f, t, g->part_rec[t], rec);
        line_rec(g, rec[0]);
        for (uint32_t j = 1; j < s.n; j++) line_rec(g, rec[2] + j - 1);
        line_rec(g, rec[1]);
        line_end(g, 0);
    }
    /* Each visible feature edge through its ends and its chain, as its
     * first side has them; one that needed no samples is drawn straight
     * between its corners, and so is its line. */
    for (uint32_t w = 0; w < f->nedges; w++) {
        const silk_sil_edge *e = &f->edges[w];
        if (!e->sampled || !e->nsides) continue;
        uint32_t c = at[side0[w]], t = c / 3, k = c % 3, k1 = (k + 1) % 3;
        int fwd = silk_mesh_corner(m, c) == silk_mesh_edge_v0(m, e->edge);
        uint32_t r0 = silk_remesh_corner_rec(f, t, k, g->part_rec[t]);
        uint32_t r1 = silk_remesh_corner_rec(f, t, k1, g->part_rec[t]);
        line_rec(g, fwd ? r0 : r1);
        for (uint32_t j = 0; j < e->nchain; j++) line_rec(g, r0 + 1 + j);
        line_rec(g, fwd ? r1 : r0);
        line_end(g, 1);
    }
    return SILK_OK;
}

/* ---- the coarse mesh's outline -------------------------------------------------- */

/* What edge e is in the outline: 0 nothing, 1 silhouette, 2 feature.  A
 * feature edge is a feature line even where it is also the silhouette, as
 * in SMOOTH mode, where it is drawn on its feature curve. */
static int edge_kind(const silk_mesh *m, const uint8_t *front, uint32_t e)
{
    const silk_edge ed_ = silk_mesh_edge(m, e), *ed = &ed_;
    uint32_t t0 = ed->t[0], t1 = ed->t[1];
    int f0 = t0 < m->ntris && front[t0], f1 = t1 < m->ntris && front[t1];
    if ((ed->flags & SILK_EDGE_FEATURE) && (f0 || f1)) return 2;
    if (t0 < m->ntris && t1 < m->ntris && f0 != f1) return 1;
    return 0;
}

/* The CORNER record at mesh vertex vtx of triangle t: 3t+k, or NO_SRC. */
static uint32_t corner_of(const silk_mesh *m, uint32_t t, silk_index vtx)
{
    for (uint32_t k = 0; k < 3; k++)
        if (silk_mesh_corner(m, 3 * t + k) == vtx) return 3 * t + k;
    return SILK_LINE_NO_SRC;
}

silk_status silk_lines_polygonal(silk_arena *a, const silk_mesh *m, const silk_view *v, int on_mesh,
                                 silk_frame_geom *g)
{
    g->nlines = g->nline_vrec = 0;
    if (!m->packed.base && (!m->edge || !m->tri)) return SILK_OK;
    uint8_t *front = silk_arena_array_top(a, m->ntris, 1, SILK_MEM_FRAME);
    if (!front) return SILK_ERR_NOMEM;
    for (uint32_t t = 0; t < m->ntris; t++) front[t] = (uint8_t)silk_sil_tri_front(m, v, t);
    uint32_t nlines = 0;
    silk_mesh_edges it;
    silk_edge ed_, *ed = &ed_;
    for (silk_index e = silk_mesh_edges_first(m, &it, ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, ed))
        nlines += edge_kind(m, front, e) != 0;
    if (!lines_alloc(a, g, nlines, 2 * (uint64_t)nlines)) return SILK_ERR_NOMEM;
    /* silhouettes first, so that feature lines are drawn over them, as in SMOOTH mode */
    for (int pass = 1; pass <= 2; pass++)
    for (silk_index e = silk_mesh_edges_first(m, &it, ed); e != SILK_NO_INDEX; e = silk_mesh_edges_next(m, &it, ed)) {
        if (edge_kind(m, front, e) != pass) continue;
        /* the corners of a front-facing triangle where there is one */
        uint32_t t = ed->t[0] < m->ntris && front[ed->t[0]] ? ed->t[0] : ed->t[1];
        if (t >= m->ntris) t = ed->t[0];
        uint32_t c0 = corner_of(m, t, ed->v[0]), c1 = corner_of(m, t, ed->v[1]);
        if (c0 == SILK_LINE_NO_SRC || c1 == SILK_LINE_NO_SRC) continue;
        silk_vrec r;
        memset(&r, 0, sizeof r);
        r.kind = SILK_VREC_CORNER;
        r.a = c0;
        line_point(g, &r, on_mesh ? c0 : SILK_LINE_NO_SRC);
        r.a = c1;
        line_point(g, &r, on_mesh ? c1 : SILK_LINE_NO_SRC);
        line_end(g, pass == 2);
    }
    return SILK_OK;
}

/* ---- lifting lines off the surface they lie on ------------------------------------ */

/* Screen position in 1/256 px and depth (w - z) / w in 2^-24, or 0 when
 * the point is behind the eye or so far off screen that its triangle can be
 * skipped (it is clipped away wherever it matters). */
typedef struct spt { int64_t x, y, d; } spt;

#define GUARD 64   /* clip x, y within +-GUARD w */
#define LINE_NEAR 128   /* lines are drawn this fraction of their depth nearer */

static int screen_point(const silk_vertex_out *o, int width, int height, spt *p)
{
    int64_t w = o->clip.w, x = o->clip.x, y = o->clip.y, z = o->clip.z;
    if (w <= 0 || x > GUARD * w || -x > GUARD * w || y > GUARD * w || -y > GUARD * w) return 0;
    p->x = (x * width * 128) / w + (int64_t)width * 128;
    p->y = (int64_t)height * 128 - (y * height * 128) / w;
    p->d = (w - z) * ((int64_t)1 << 24) / w;   /* [0, 2^25] inside the clip volume; w - z < 0 beyond it */
    if (p->d > (1 << 26)) p->d = 1 << 26;
    if (p->d < -(1 << 26)) p->d = -(1 << 26);
    return 1;
}

/* What triangle abc rises over one pixel in depth (2^-24): the size of its
 * depth gradient, over-estimated by |gx| + |gy|; a triangle seen exactly
 * edge-on gives INT64_MAX. */
static int64_t depth_slope(const spt *a, const spt *b, const spt *c)
{
    int64_t bx = b->x - a->x, by = b->y - a->y, cx = c->x - a->x, cy = c->y - a->y;
    int64_t bd = b->d - a->d, cd = c->d - a->d;
    /* |coordinates| < 2^28 (1/256 px, within the guard band), |depth| <
     * 2^27: every product below 2^56 */
    int64_t area2 = (int64_t)silk_abs64(bx * cy - cx * by);
    int64_t gx = (int64_t)silk_abs64(bd * cy - cd * by), gy = (int64_t)silk_abs64(cd * bx - bd * cx);
    /* per 1/256 px: (gx + gy) / area2; per pixel 256 times that.  A sliver
     * below 1/256 px^2 counts as edge-on. */
    if (area2 < 256) return INT64_MAX;
    return (gx + gy) / (area2 >> 8);
}

/* Whether triangle abc is narrower than a pixel: twice its area under 256
 * times (1/256 px) its longest side, measured |dx| + |dy| (generous by
 * at most sqrt 2). */
static int sliver(const spt *a, const spt *b, const spt *c)
{
    const spt *p[3] = { a, b, c };
    int64_t side = 0;
    for (int i = 0; i < 3; i++) {
        int64_t l = (int64_t)silk_abs64(p[(i + 1) % 3]->x - p[i]->x) + (int64_t)silk_abs64(p[(i + 1) % 3]->y - p[i]->y);
        if (l > side) side = l;
    }
    int64_t area2 = (int64_t)silk_abs64((b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y));
    return area2 < 256 * side;
}

/* Triangle k of g: its corners' points and screen points; 0 when a
 * record is out of range or a corner is off screen (see screen_point). */
static int tri_points(const silk_mesh *m, const silk_frame_geom *g, const silk_vertex_out *out, int width, int height,
                      uint32_t k, uint32_t c[3], spt p[3])
{
    const uint32_t *t = &g->tri[3 * k];
    for (int j = 0; j < 3; j++) {
        if (t[j] >= g->nvrec || !screen_point(&out[t[j]], width, height, &p[j])) return 0;
        c[j] = point_key(m, g, t[j]);
    }
    return 1;
}

uint32_t *silk_lines_lift(silk_arena *a, const silk_mesh *m, const silk_frame_geom *g, const silk_vertex_out *out,
                          int width, int height)
{
    if (!g->nline_vrec || !out || !g->line_src || g->nvrec > UINT32_MAX - m->nverts) return NULL;
    uint32_t nkeys = m->nverts + g->nvrec;
    uint32_t *lift = silk_arena_array_top(a, g->nline_vrec, sizeof *lift, SILK_MEM_FRAME);
    /* the line vertices at each point: first[key], then same[i] */
    uint32_t *first = silk_arena_array_top(a, nkeys, sizeof *first, SILK_MEM_FRAME);
    uint32_t *same = silk_arena_array_top(a, g->nline_vrec, sizeof *same, SILK_MEM_FRAME);
    /* each point's own lift, line or not */
    uint32_t *own = silk_arena_array_top(a, nkeys, sizeof *own, SILK_MEM_FRAME);
    if (!lift || !first || !same || !own) return NULL;
    memset(first, 0xFF, (size_t)nkeys * sizeof *first);
    memset(own, 0, (size_t)nkeys * sizeof *own);
    for (uint32_t i = 0; i < g->nline_vrec; i++) {
        uint32_t r = g->line_src[i];
        same[i] = SILK_LINE_NO_SRC;
        if (r >= g->nvrec) continue;
        uint32_t key = point_key(m, g, r);
        same[i] = first[key];
        first[key] = i;
    }
    /* Every point by the triangles through it. */
    for (uint32_t k = 0; k < g->ntri; k++) {
        uint32_t c[3];
        spt p[3];
        if (!tri_points(m, g, out, width, height, k, c, p)) continue;
        int64_t slope = depth_slope(&p[0], &p[1], &p[2]);
        for (int j = 0; j < 3; j++) {
            /* one pixel of slope, but never more than the triangle rises */
            int64_t rise = 0;
            for (int i = 0; i < 3; i++)
                if (p[i].d - p[j].d > rise) rise = p[i].d - p[j].d;
            int64_t l = slope < rise ? slope : rise;
            if (l > UINT32_MAX) l = UINT32_MAX;
            if ((uint32_t)l > own[c[j]]) own[c[j]] = (uint32_t)l;
        }
    }
    for (uint32_t i = 0; i < g->nline_vrec; i++)
        lift[i] = g->line_src[i] < g->nvrec ? own[point_key(m, g, g->line_src[i])] : 0;
    /* A line point on a triangle narrower than a pixel (the re-meshing fans
     * such slivers from a mesh vertex to the silhouette samples): the
     * line's pixels lie on the triangles beyond the sliver, which rise past
     * its corners, so the line is lifted as far as they are and by what
     * the sliver rises to them. */
    for (uint32_t k = 0; k < g->ntri; k++) {
        uint32_t c[3];
        spt p[3];
        if (!tri_points(m, g, out, width, height, k, c, p) || !sliver(&p[0], &p[1], &p[2])) continue;
        for (int j = 0; j < 3; j++) {
            int64_t l = 0;
            for (int i = 0; i < 3; i++)
                if (i != j && p[i].d - p[j].d + own[c[i]] > l) l = p[i].d - p[j].d + own[c[i]];
            if (l > UINT32_MAX) l = UINT32_MAX;
            for (uint32_t i = first[c[j]]; i != SILK_LINE_NO_SRC; i = same[i])
                if ((uint32_t)l > lift[i]) lift[i] = (uint32_t)l;
        }
    }
    return lift;
}

void silk_lines_apply_lift(silk_vertex_out *o, uint32_t lift)
{
    /* depth (w - z) / w grows by lift / 2^24: z falls by lift w / 2^24;
     * and by a further 1/LINE_NEAR of itself, for the surface next to a
     * silhouette, whose depth rises like a square root of the distance
     * from it: half a pixel inside, the triangles there are nearer than
     * their slope at the line says */
    int64_t dz = silk_shr_round64((int64_t)lift * o->clip.w, 24) + ((int64_t)o->clip.w - o->clip.z) / LINE_NEAR;
    o->clip.z = silk_fx_sat((int64_t)o->clip.z - dz);
}

/* ---- the contour of the drawn triangles --------------------------------------------- */

/* Records are matched by where the vertex stage put them: the records of
 * one point (a vertex's corners, the copies of an edge point on the two
 * sides of a crease) have the same clip position, bit for bit. */
typedef struct rec_pos {
    silk_vec4 c;
    uint32_t r;
} rec_pos;

static int pos_cmp(const rec_pos *a, const rec_pos *b)
{
    if (a->c.x != b->c.x) return a->c.x < b->c.x ? -1 : 1;
    if (a->c.y != b->c.y) return a->c.y < b->c.y ? -1 : 1;
    if (a->c.z != b->c.z) return a->c.z < b->c.z ? -1 : 1;
    if (a->c.w != b->c.w) return a->c.w < b->c.w ? -1 : 1;
    return 0;
}

/* Sorting orders: by the key, then by the place in the input, so the order
 * is the same on every libc (and no qsort is linked into a device). */
static int pos_before(const void *pa, const void *pb)
{
    const rec_pos *a = pa, *b = pb;
    int c = pos_cmp(a, b);
    return c ? c < 0 : a->r < b->r;
}

/* One side of a drawn triangle: its two points (smaller first), its
 * records, which way its triangle faces on screen (+1, -1; 0 unknown), and
 * its place in the input (3 t + side). */
typedef struct half_edge {
    uint32_t k0, k1, r0, r1, at;
    int32_t facing;
} half_edge;

static int half_cmp(const half_edge *a, const half_edge *b)
{
    if (a->k0 != b->k0) return a->k0 < b->k0 ? -1 : 1;
    if (a->k1 != b->k1) return a->k1 < b->k1 ? -1 : 1;
    return 0;
}

static int half_before(const void *pa, const void *pb)
{
    const half_edge *a = pa, *b = pb;
    int c = half_cmp(a, b);
    return c ? c < 0 : a->at < b->at;
}

static void swap_bytes(uint8_t *a, uint8_t *b, size_t size)
{
    for (size_t i = 0; i < size; i++) {
        uint8_t x = a[i];
        a[i] = b[i];
        b[i] = x;
    }
}

/* Heapsort of n elements of size bytes by the strict order `before`: no
 * memory beyond the array, O(n log n) always. */
static void heap_sort(void *base, uint32_t n, size_t size, int (*before)(const void *, const void *))
{
    uint8_t *b = base;
    for (uint32_t end = n, start = n / 2; end > 1;) {
        if (start > 0) start--;
        else swap_bytes(b, b + (size_t)--end * size, size);
        for (uint32_t i = start;;) {
            uint32_t c = 2 * i + 1;
            if (c >= end) break;
            if (c + 1 < end && before(b + (size_t)c * size, b + (size_t)(c + 1) * size)) c++;
            if (!before(b + (size_t)i * size, b + (size_t)c * size)) break;
            swap_bytes(b + (size_t)i * size, b + (size_t)c * size, size);
            i = c;
        }
    }
}

/* Which way triangle t of g faces on screen: +1, -1, or 0 (edge-on, or a
 * corner behind the eye or far outside the view). */
static int32_t screen_facing(const silk_frame_geom *g, const silk_vertex_out *out, uint32_t t, int width, int height)
{
    const uint32_t *c = &g->tri[3 * t];
    spt p[3];
    for (int k = 0; k < 3; k++)
        if (!screen_point(&out[c[k]], width, height, &p[k])) return 0;
    int64_t area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    return area2 > 0 ? 1 : area2 < 0 ? -1 : 0;
}

silk_status silk_lines_contour(silk_arena *a, silk_frame_geom *g, const silk_vertex_out *out, int width, int height)
{
    if (!g->nlines) return SILK_OK;
    if (g->ntri > UINT32_MAX / 3) return SILK_ERR_NOMEM;
    uint32_t nhalf = 3 * g->ntri;
    rec_pos *pos = silk_arena_array_top(a, g->nvrec, sizeof *pos, SILK_MEM_FRAME);
    uint32_t *id = silk_arena_array_top(a, g->nvrec, sizeof *id, SILK_MEM_FRAME);
    half_edge *h = silk_arena_array_top(a, nhalf, sizeof *h, SILK_MEM_FRAME);
    if (!pos || !id || !h) return SILK_ERR_NOMEM;

    /* Each record's point: the first record at its position. */
    for (uint32_t r = 0; r < g->nvrec; r++) {
        pos[r].c = out[r].clip;
        pos[r].r = r;
    }
    heap_sort(pos, g->nvrec, sizeof *pos, pos_before);
    for (uint32_t i = 0; i < g->nvrec; i++) id[pos[i].r] = i && !pos_cmp(&pos[i - 1], &pos[i]) ? id[pos[i - 1].r] : i;

    for (uint32_t t = 0; t < g->ntri; t++) {
        int32_t facing = screen_facing(g, out, t, width, height);
        for (uint32_t j = 0; j < 3; j++) {
            half_edge *e = &h[3 * t + j];
            e->r0 = g->tri[3 * t + j];
            e->r1 = g->tri[3 * t + (j + 1) % 3];
            e->at = 3 * t + j;
            uint32_t ka = id[e->r0], kb = id[e->r1];
            e->k0 = ka < kb ? ka : kb;
            e->k1 = ka < kb ? kb : ka;
            e->facing = facing;
        }
    }
    heap_sort(h, nhalf, sizeof *h, half_before);

    /* A side shared by exactly two triangles facing opposite ways is on
     * the contour. */
    uint32_t ncont = 0;
    for (uint32_t i = 0; i + 1 < nhalf; i++) {
        const half_edge *e = &h[i], *o = &h[i + 1];
        int two = !half_cmp(e, o) && (i + 2 >= nhalf || half_cmp(o, &h[i + 2])) && (i == 0 || half_cmp(&h[i - 1], e));
        if (two && e->k0 != e->k1 && e->facing * o->facing < 0)
            h[ncont++] = *e;
    }

    /* The lines again: the silhouette lines, the contour, the feature lines. */
    silk_frame_geom old = *g;
    if (!lines_alloc(a, g, old.nlines + ncont, (uint64_t)old.nline_vrec + 2 * (uint64_t)ncont)) {
        *g = old;
        return SILK_ERR_NOMEM;
    }
    for (uint8_t feature = 0; feature < 2; feature++) {
        for (uint32_t i = 0; i < old.nlines; i++) {
            if (old.line_feature[i] != feature) continue;
            for (uint32_t j = old.line_start[i]; j < old.line_start[i + 1]; j++)
                line_point(g, &old.line_vrec[j], old.line_src[j]);
            line_end(g, feature);
        }
        for (uint32_t i = 0; !feature && i < ncont; i++) {
            line_rec(g, h[i].r0);
            line_rec(g, h[i].r1);
            line_end(g, 0);
        }
    }
    return SILK_OK;
}
