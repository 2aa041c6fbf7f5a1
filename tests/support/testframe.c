/*
 * testframe.c - test support: views, hand-run frames and crack checks
 * (see testframe.h).
 */
#include "testframe.h"
#include "testvec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double tf_bounds(const silk_mesh *m, double c[3])
{
    double r = 0;
    for (int i = 0; i < 3; i++) {
        double lo = fx2d((&m->bbox_min.x)[i]), hi = fx2d((&m->bbox_max.x)[i]);
        c[i] = (lo + hi) / 2;
        r += (hi - lo) * (hi - lo) / 4;
    }
    return sqrt(r);
}

int tf_view_around(const silk_mesh *m, const double dir[3], double dist, int ortho, silk_view *v)
{
    return tf_view_around_size(m, dir, dist, ortho, 512, 512, v);
}

int tf_view_around_size(const silk_mesh *m, const double dir[3], double dist, int ortho, int w, int h,
                        silk_view *v)
{
    double c[3], r = tf_bounds(m, c);
    double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(d2fx(c[0] + dir[0] / len * dist * r), d2fx(c[1] + dir[1] / len * dist * r),
                      d2fx(c[2] + dir[2] / len * dist * r));
    cam.target = silk_v3(d2fx(c[0]), d2fx(c[1]), d2fx(c[2]));
    cam.up = fabs(dir[1] / len) > 0.9 ? silk_v3(SILK_FX_ONE, 0, 0) : silk_v3(0, SILK_FX_ONE, 0);
    cam.ortho = ortho;
    cam.fov_deg = SILK_FX_C(45, 1);
    cam.ortho_half_height = d2fx(r * 1.2);
    cam.znear = d2fx(r * 0.01);
    cam.zfar = d2fx(r * (dist + 4));
    cam.width = w;
    cam.height = h;
    silk_error err;
    if (silk_view_init(v, &cam, &err) != SILK_OK) {
        fprintf(stderr, "view: %s\n", err.msg);
        return 0;
    }
    return 1;
}

int tf_collect_band(void *user, const silk_target *t)
{
    tf_collect *c = user;
    size_t bpp = silk_pixfmt_bytes(t->fmt), row = (size_t)t->width * bpp;
    if (t->y0 != c->next_row || t->rows < 1 || t->rows > c->max_rows || t->y0 + t->rows > t->height) c->bad++;
    for (int y = 0; y < t->rows && t->y0 + y < t->height; y++)
        memcpy(c->frame + (size_t)(t->y0 + y) * row, t->color + (size_t)y * t->stride, row);
    c->next_row = t->y0 + t->rows;
    c->bands++;
    return c->stop_after && c->bands >= c->stop_after;
}

silk_status tf_render_bands(silk_arena *a, const silk_mesh *m, const silk_view *v, const silk_hal *h,
                            const silk_render_opts *o, silk_pixfmt fmt, int rows, tf_collect *c,
                            silk_frame_stats *stats, silk_error *err)
{
    int w = v->cam.width, hgt = v->cam.height;
    size_t bpp = silk_pixfmt_bytes(fmt);
    silk_arena_mark mk = silk_arena_top_mark(a);
    uint8_t *bc = silk_arena_alloc_top(a, (size_t)rows * (size_t)w * bpp, SILK_MEM_RASTER);
    uint32_t *bd = silk_arena_array_top(a, (size_t)rows * (size_t)w, sizeof *bd, SILK_MEM_RASTER);
    if (!bc || !bd) {
        silk_arena_top_release(a, &mk);
        return silk_fail(err, SILK_ERR_NOMEM, NULL, 0, "no room for a band of %d rows", rows);
    }
    silk_target band;
    silk_target_init(&band, w, hgt, 0, rows, fmt, bc, bd);
    c->next_row = c->bands = c->bad = 0;
    c->max_rows = rows;
    silk_sink sink = { .band = tf_collect_band, .user = c };
    silk_status st = silk_render_bands(a, m, v, h, o, &band, &sink, stats, err);
    if (band.rows != rows || band.y0 != 0) c->bad++;
    silk_arena_top_release(a, &mk);
    return st;
}

int tf_run_frame(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tol, silk_sil_frame *f,
                 silk_frame_geom *g, silk_frame_stats *st)
{
    static silk_sil_cursor cur;   /* the plan's readers' memos: one frame's at a time */
    memset(f, 0, sizeof *f);
    f->cur = &cur;
    memset(g, 0, sizeof *g);
    memset(st, 0, sizeof *st);
    f->a = a; f->m = m; f->v = v; f->tol = tol; f->vis = SILK_VIS_BRUTE;
    if (silk_sil_find(f) != SILK_OK || silk_remesh_plan(f) != SILK_OK) return 0;
    if (!silk_perturb_alloc(f) || !silk_perturb(f)) return 0;
    if (!silk_remesh_store(f, g)) return 0;
    silk_remesh_stats(f, st);
    return 1;
}

silk_sil_seg *tf_segs(const silk_sil_frame *f)
{
    silk_sil_seg *s = f->nsegs ? malloc(f->nsegs * sizeof *s) : NULL;
    uint32_t n = 0;
    for (uint32_t t = 0; s && t < f->m->ntris && n < f->nsegs; t++)
        if ((f->tri_state[t] & SILK_TS_SIL) && silk_remesh_seg(f, t, &s[n])) n++;
    return s;
}

uint32_t tf_side_rec(const silk_sil_frame *f, const silk_frame_geom *g, uint32_t t, uint32_t k)
{
    return silk_remesh_corner_rec(f, t, k, g->part_rec[t]) + 1;
}

/* Six bit patterns: a directed edge (two positions), or a position and its normal. */
typedef struct dedge { int32_t k[6]; } dedge;

static int cmp_dedge(const void *pa, const void *pb)
{
    const dedge *a = pa, *b = pb;
    for (int i = 0; i < 6; i++)
        if (a->k[i] != b->k[i]) return a->k[i] < b->k[i] ? -1 : 1;
    return 0;
}

uint32_t tf_crack_check(const silk_mesh *m, const silk_frame_geom *g, uint32_t *checked)
{
    silk_geom geom = { .mesh = m, .curves = g->curve, .offsets = g->offset, .patches = g->patch };
    silk_vec3 *pos = malloc(sizeof *pos * (g->nvrec ? g->nvrec : 1));
    dedge *e = malloc(sizeof *e * 3 * (g->ntri ? g->ntri : 1));
    for (uint32_t i = 0; i < g->nvrec; i++) {
        silk_vertex_attr at;
        silk_vrec_eval(&geom, &g->vrec[i], &at);
        pos[i] = at.pos;
    }
    uint32_t n = 0, bad = 0;
    for (uint32_t t = 0; t < g->ntri; t++)
        for (int k = 0; k < 3; k++) {
            silk_vec3 a = pos[g->tri[3 * t + k]], b = pos[g->tri[3 * t + (k + 1) % 3]];
            dedge x = { { a.x, a.y, a.z, b.x, b.y, b.z } };
            if (v3_eq(a, b)) bad++;
            e[n++] = x;
        }
    qsort(e, n, sizeof *e, cmp_dedge);
    for (uint32_t i = 0; i < n; i++) {
        if ((i > 0 && cmp_dedge(&e[i - 1], &e[i]) == 0) || (i + 1 < n && cmp_dedge(&e[i + 1], &e[i]) == 0)) {
            bad++;
            continue;
        }
        dedge r = { { e[i].k[3], e[i].k[4], e[i].k[5], e[i].k[0], e[i].k[1], e[i].k[2] } };
        if (!bsearch(&r, e, n, sizeof *e, cmp_dedge)) bad++;
    }
    free(pos);
    free(e);
    *checked = n;
    return bad;
}

uint32_t tf_normal_seams(const silk_mesh *m, const silk_frame_geom *g)
{
    silk_geom geom = { .mesh = m, .curves = g->curve, .offsets = g->offset, .patches = g->patch };
    dedge *pn = malloc(sizeof *pn * (g->nvrec ? g->nvrec : 1));
    for (uint32_t i = 0; i < g->nvrec; i++) {
        silk_vertex_attr at;
        silk_vrec_eval(&geom, &g->vrec[i], &at);
        dedge x = { { at.pos.x, at.pos.y, at.pos.z, at.normal.x, at.normal.y, at.normal.z } };
        pn[i] = x;
    }
    qsort(pn, g->nvrec, sizeof *pn, cmp_dedge);
    uint32_t seams = 0;
    for (uint32_t i = 1; i < g->nvrec; i++)
        if (memcmp(pn[i].k, pn[i - 1].k, 3 * sizeof(int32_t)) == 0 && cmp_dedge(&pn[i], &pn[i - 1]) != 0) seams++;
    free(pn);
    return seams;
}
