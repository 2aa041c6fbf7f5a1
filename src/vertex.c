/*
 * vertex.c - vertex records (paper Fig. 16) evaluated into position, normal
 * texture coordinate and vertex colour: mesh corners, points on Hermite curves (eq. 5,
 * with the normal interpolated linearly along the curve as in eq. 6 and then
 * normalised), and perturbed vertices.
 *
 * Everything is a pure integer function of the record, so the same record
 * gives the same bits in every triangle that uses it: shared vertices of the
 * re-meshed surface meet exactly and the rasterizer sees no cracks.
 */
#include "silk/hal.h"

/* Fractional bits kept inside the Horner steps beyond Q16.16. */
#define HORNER_EXTRA 8

/* One coordinate of eq. 5 by Horner's rule on
 *   S(u) = a u^3 + b u^2 + c u + d,
 *   a = 2P0 - 2P1 + T0 + T1,  b = -(3P0 - 3P1 + 2T0 + T1),  c = T0,  d = P0,
 * with the coefficients exact in 64 bits and the running value kept with 8
 * extra fractional bits, so the three multiplications add up to well under
 * one ulp before the final rounding.  At u = 0 and u = 1 the result is P0
 * and P1 exactly (every step is then exact). */
static silk_fx hermite1(silk_fx p0, silk_fx p1, silk_fx t0, silk_fx t1, silk_fx u)
{
    int64_t a = 2 * (int64_t)p0 - 2 * (int64_t)p1 + t0 + t1;   /* < 2^34 */
    int64_t b = -(3 * (int64_t)p0 - 3 * (int64_t)p1 + 2 * (int64_t)t0 + t1);
    int64_t acc = a * (1 << HORNER_EXTRA);                      /* < 2^42 */
    /* acc * u < 2^58 as long as |acc| < 2^42, u <= 2^16 */
    acc = silk_shr_round64(acc * u, 16) + b * (1 << HORNER_EXTRA);
    acc = silk_shr_round64(acc * u, 16) + (int64_t)t0 * (1 << HORNER_EXTRA);
    acc = silk_shr_round64(acc * u, 16) + (int64_t)p0 * (1 << HORNER_EXTRA);
    return silk_fx_sat(silk_shr_round64(acc, HORNER_EXTRA));
}

silk_vec3 silk_hermite_point(const silk_curve *c, silk_fx t)
{
    t = silk_fx_clamp(t, 0, SILK_FX_ONE);
    return silk_v3(hermite1(c->p0.x, c->p1.x, c->t0.x, c->t1.x, t),
                   hermite1(c->p0.y, c->p1.y, c->t0.y, c->t1.y, t),
                   hermite1(c->p0.z, c->p1.z, c->t0.z, c->t1.z, t));
}

/* normalize((1-t) n0 + t n1), with the blend exact in 64 bits and scaled to
 * 30 significant bits before normalising, so that a short blend (normals
 * far apart) keeps its direction.  Returns 0 when the blend is zero. */
static int blend_normal(silk_vec3 n0, silk_vec3 n1, silk_fx t, silk_vec3 *out)
{
    int64_t s = SILK_FX_ONE - t;
    int64_t v[3] = { (int64_t)n0.x * s + (int64_t)n1.x * t, (int64_t)n0.y * s + (int64_t)n1.y * t,
                     (int64_t)n0.z * s + (int64_t)n1.z * t };
    int64_t m = 0;
    for (int k = 0; k < 3; k++) {
        int64_t a = v[k] < 0 ? -v[k] : v[k];
        if (a > m) m = a;
    }
    int sh = 0;
    while ((m >> sh) >= ((int64_t)1 << 30)) sh++;
    for (int k = 0; k < 3; k++) v[k] = sh ? silk_shr_round64(v[k], sh) : v[k];
    return silk_v3_normalize(silk_v3((silk_fx)v[0], (silk_fx)v[1], (silk_fx)v[2]), out);
}

static silk_fx lerp1(silk_fx a, silk_fx b, silk_fx t)
{
    return silk_fx_sat(a + silk_shr_round64(((int64_t)b - a) * t, 16));
}

uint32_t silk_rgb_lerp(uint32_t a, uint32_t b, silk_fx t)
{
    t = silk_fx_clamp(t, 0, SILK_FX_ONE);
    uint32_t out = 0;
    for (int sh = 0; sh <= 16; sh += 8) {
        int64_t ca = (a >> sh) & 0xff, cb = (b >> sh) & 0xff;
        out |= (uint32_t)(ca + silk_shr_round64((cb - ca) * t, 16)) << sh;
    }
    return out;
}

/* Corner a (= triangle * 3 + k) of the mesh; out of range gives zeros, so a
 * bad record draws a degenerate triangle instead of reading wild memory. */
static void corner(const silk_mesh *m, uint32_t a, silk_vertex_attr *out)
{
    if (!m || a / 3 >= m->ntris) return;
    silk_index v = silk_mesh_corner(m, a);
    if (v < m->nverts) {
        out->pos = silk_mesh_pos(m, v);
        if (m->color) out->rgb = m->color[v];
    }
    if (silk_mesh_has_corner_normals(m)) {
        silk_index n = silk_mesh_corner_normal(m, a);
        if (n < m->nnormals) out->normal = silk_mesh_normal(m, n);
    }
    if (m->uv && m->tri_uv) {
        silk_index t = m->tri_uv[a];
        if (t < m->nuvs) out->uv = m->uv[t];
    }
}

void silk_vrec_eval(const silk_geom *g, const silk_vrec *r, silk_vertex_attr *out)
{
    out->pos = silk_v3(0, 0, 0);
    out->normal = silk_v3(0, 0, 0);
    out->uv.x = out->uv.y = 0;
    out->rgb = 0xffffff;
    switch (r->kind) {
    case SILK_VREC_CORNER:
        corner(g->mesh, r->a, out);
        break;
    case SILK_VREC_CURVE: {
        if (!g->curves) break;
        const silk_curve *c = &g->curves[r->a];
        silk_fx t = silk_fx_clamp(r->t, 0, SILK_FX_ONE);
        out->pos = silk_hermite_point(c, t);
        /* eq. 6; opposite end normals cancel at one point: keep n0 there */
        if (!blend_normal(c->n0, c->n1, t, &out->normal)) out->normal = c->n0;
        out->uv.x = lerp1(c->uv0.x, c->uv1.x, t);
        out->uv.y = lerp1(c->uv0.y, c->uv1.y, t);
        out->rgb = silk_rgb_lerp(c->rgb0, c->rgb1, t);
        break;
    }
    case SILK_VREC_MOVED:
        corner(g->mesh, r->a, out);
        if (g->offsets) out->pos = silk_v3_add(out->pos, g->offsets[r->b]);
        break;
    case SILK_VREC_PATCH:   /* PN and BLEND modes (pn.c; a build without them makes no patches) */
        if (SILK_REFERENCE_MODES && g->patches) silk_patch_eval(&g->patches[r->a], r->b, out);
        break;
    default:
        break;
    }
}
