/*
 * scene.c - test support: small scenes from doubles (see scene.h).
 */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void ts_mesh_free(ts_mesh *m)
{
    free(m->v);
    free(m->f);
    memset(m, 0, sizeof *m);
}

uint32_t ts_vertex(ts_mesh *m, double x, double y, double z)
{
    if (m->nv == m->cap_v) {
        m->cap_v = m->cap_v ? 2 * m->cap_v : 64;
        m->v = realloc(m->v, (size_t)m->cap_v * 3 * sizeof *m->v);
        if (!m->v) abort();
    }
    m->v[3 * m->nv] = x;
    m->v[3 * m->nv + 1] = y;
    m->v[3 * m->nv + 2] = z;
    return m->nv++;
}

void ts_tri(ts_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    if (m->nf == m->cap_f) {
        m->cap_f = m->cap_f ? 2 * m->cap_f : 64;
        m->f = realloc(m->f, (size_t)m->cap_f * 3 * sizeof *m->f);
        if (!m->f) abort();
    }
    m->f[3 * m->nf] = a;
    m->f[3 * m->nf + 1] = b;
    m->f[3 * m->nf + 2] = c;
    m->nf++;
}

void ts_sphere(ts_mesh *m, int segs, int bands, double r, double cx, double cy, double cz)
{
    const double pi = 3.14159265358979323846;
    uint32_t top = ts_vertex(m, cx, cy + r, cz), first = m->nv;
    for (int b = 1; b < bands; b++) {
        double th = pi * b / bands;
        for (int s = 0; s < segs; s++) {
            double ph = 2 * pi * s / segs;
            ts_vertex(m, cx + r * sin(th) * cos(ph), cy + r * cos(th), cz - r * sin(th) * sin(ph));
        }
    }
    uint32_t bottom = ts_vertex(m, cx, cy - r, cz);
#define RING(b, s) (first + (uint32_t)((b) - 1) * (uint32_t)segs + (uint32_t)((s) % segs))
    for (int s = 0; s < segs; s++) {
        ts_tri(m, top, RING(1, s), RING(1, s + 1));
        ts_tri(m, bottom, RING(bands - 1, s + 1), RING(bands - 1, s));
        for (int b = 1; b + 1 < bands; b++) {
            ts_tri(m, RING(b, s), RING(b + 1, s), RING(b + 1, s + 1));
            ts_tri(m, RING(b, s), RING(b + 1, s + 1), RING(b, s + 1));
        }
    }
#undef RING
}

double ts_fx2d(silk_fx v) { return v / 65536.0; }

silk_fx ts_d2fx(double v)
{
    double s = floor(v * 65536.0 + 0.5);
    if (s > 2147483647.0) s = 2147483647.0;
    if (s < -2147483647.0) s = -2147483647.0;
    return (silk_fx)s;
}

silk_status ts_build(const ts_mesh *m, silk_arena *a, silk_mesh *out, silk_error *err)
{
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = m->nv;
    in.ntris = m->nf;
    in.pos = silk_arena_array(a, m->nv ? m->nv : 1, sizeof *in.pos, SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 3 * (size_t)(m->nf ? m->nf : 1), sizeof *in.tri, SILK_MEM_MESH);
    if (!in.pos || !in.tri) return silk_fail(err, SILK_ERR_NOMEM, "test", 0, "arena too small for the input");
    for (uint32_t i = 0; i < m->nv; i++)
        in.pos[i] = silk_v3(ts_d2fx(m->v[3 * i]), ts_d2fx(m->v[3 * i + 1]), ts_d2fx(m->v[3 * i + 2]));
    for (uint32_t i = 0; i < 3 * m->nf; i++) in.tri[i] = m->f[i];
    silk_load_opts o;
    silk_load_opts_default(&o);
    return silk_mesh_build(&in, "test", &o, a, out, err);
}

silk_camera ts_camera(const double eye[3], const double target[3], double fov_deg, double znear, double zfar,
                      int width, int height)
{
    silk_camera c;
    memset(&c, 0, sizeof c);
    c.eye = silk_v3(ts_d2fx(eye[0]), ts_d2fx(eye[1]), ts_d2fx(eye[2]));
    c.target = silk_v3(ts_d2fx(target[0]), ts_d2fx(target[1]), ts_d2fx(target[2]));
    /* +y up, unless the view is (nearly) vertical */
    double d[3] = { target[0] - eye[0], target[1] - eye[1], target[2] - eye[2] };
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    c.up = len > 0 && fabs(d[1]) > 0.99 * len ? silk_v3(0, 0, -SILK_FX_ONE) : silk_v3(0, SILK_FX_ONE, 0);
    c.ortho = fov_deg <= 0;
    c.fov_deg = c.ortho ? SILK_FX_C(45, 1) : ts_d2fx(fov_deg);
    c.ortho_half_height = c.ortho ? ts_d2fx(-fov_deg) : SILK_FX_ONE;
    c.znear = ts_d2fx(znear);
    c.zfar = ts_d2fx(zfar);
    c.width = width;
    c.height = height;
    return c;
}

silk_status ts_render(silk_arena *a, const silk_mesh *m, const silk_camera *cam, const silk_render_opts *o,
                      ts_image *img, silk_frame_stats *stats, silk_error *err)
{
    silk_view view;
    silk_status st = silk_view_init(&view, cam, err);
    if (st != SILK_OK) return st;
    if (img->width != cam->width || img->height != cam->height || !img->rgb) {
        ts_image_free(img);
        img->width = cam->width;
        img->height = cam->height;
        img->rgb = malloc((size_t)cam->width * cam->height * 3);
        img->depth = malloc((size_t)cam->width * cam->height * sizeof *img->depth);
        if (!img->rgb || !img->depth) abort();
    }
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &view);
    silk_hal_phong(&hal, &phong);
    silk_target t;
    silk_target_init(&t, cam->width, cam->height, 0, cam->height, SILK_PIX_RGB888, img->rgb, img->depth);
    silk_render_opts ro;
    if (o) ro = *o;
    else silk_render_opts_default(&ro);
    ro.bg_rgb = TS_BG;
    return silk_render(a, m, &view, &hal, &ro, &t, stats, err);
}

void ts_image_free(ts_image *img)
{
    free(img->rgb);
    free(img->depth);
    memset(img, 0, sizeof *img);
}

int ts_covered(const ts_image *img, int x, int y)
{
    const uint8_t *p = img->rgb + ((size_t)y * img->width + x) * 3;
    return !(p[0] == 0xFF && p[1] == 0 && p[2] == 0);
}

long ts_count_covered(const ts_image *img)
{
    long n = 0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) n += ts_covered(img, x, y);
    return n;
}

long ts_count_differ(const ts_image *a, const ts_image *b)
{
    long n = 0;
    for (int y = 0; y < a->height && y < b->height; y++)
        for (int x = 0; x < a->width && x < b->width; x++) n += ts_covered(a, x, y) != ts_covered(b, x, y);
    return n;
}
