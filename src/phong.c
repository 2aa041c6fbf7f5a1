/*
 * phong.c - the default HAL stages: a vertex stage that evaluates a vertex
 * record and transforms it to clip space, and a per-pixel Phong fragment
 * stage (ambient + Lambert diffuse + Phong specular (R.V)^n) with the
 * interpolated normal renormalised at every pixel.
 *
 * Not a paper equation: the paper renders with standard OpenGL lighting.
 * The varyings are world position (3), normal (3) and uv (2); lighting is
 * done in world space, so nothing needs the inverse view matrix.
 */
#include <string.h>
#include "silk/hal.h"

enum { VAR_POS = 0, VAR_NORMAL = 3, VAR_UV = 6, VAR_COUNT = 8 };

static void phong_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r,
                         silk_vertex_out *out)
{
    const silk_phong *p = (const silk_phong *)h->uniforms;
    silk_vertex_attr a;
    silk_vrec_eval(g, r, &a);
    memset(out, 0, sizeof *out);
    if (p->view) {
        out->clip = silk_view_clip(p->view, a.pos);
    } else {
        /* no camera: positions are taken as clip coordinates already */
        out->clip.x = a.pos.x;
        out->clip.y = a.pos.y;
        out->clip.z = a.pos.z;
        out->clip.w = SILK_FX_ONE;
    }
    out->var[VAR_POS + 0] = a.pos.x;
    out->var[VAR_POS + 1] = a.pos.y;
    out->var[VAR_POS + 2] = a.pos.z;
    out->var[VAR_NORMAL + 0] = a.normal.x;
    out->var[VAR_NORMAL + 1] = a.normal.y;
    out->var[VAR_NORMAL + 2] = a.normal.z;
    out->var[VAR_UV + 0] = a.uv.x;
    out->var[VAR_UV + 1] = a.uv.y;
}

/* x^n for x in [0, 1] by repeated squaring: at most 2 log2(n) products. */
static silk_fx pow_int(silk_fx x, int n)
{
    silk_fx r = SILK_FX_ONE;
    while (n > 0) {
        if (n & 1) r = silk_fx_mul(r, x);
        n >>= 1;
        if (n) x = silk_fx_mul(x, x);
    }
    return r;
}

/* Q16.16 channel in [0, 1] (clamped) to 0..255, rounded. */
static uint32_t to_byte(silk_fx c)
{
    c = silk_fx_clamp(c, 0, SILK_FX_ONE);
    return (uint32_t)(((int64_t)c * 255 + SILK_FX_HALF) >> 16);
}

static uint32_t phong_fragment(const silk_hal *h, const silk_fx *var)
{
    const silk_phong *p = (const silk_phong *)h->uniforms;
    const silk_material *m = &p->mat;
    silk_vec3 pos = silk_v3(var[VAR_POS], var[VAR_POS + 1], var[VAR_POS + 2]);
    silk_vec3 n, v;

    if (p->view && !p->view->cam.ortho) {
        if (!silk_v3_normalize(silk_v3_sub(p->view->cam.eye, pos), &v)) v = silk_v3_neg(p->view->forward);
    } else if (p->view) {
        v = silk_v3_neg(p->view->forward);
    } else {
        v = silk_v3(0, 0, SILK_FX_ONE);
    }
    /* A zero normal (opposite normals interpolated) faces the viewer. */
    if (!silk_v3_normalize(silk_v3(var[VAR_NORMAL], var[VAR_NORMAL + 1], var[VAR_NORMAL + 2]), &n))
        n = v;
    /* Two-sided: a normal facing away from the eye is mirrored in the plane
     * perpendicular to V (its component along V changes sign).  Not plain
     * negation: near a silhouette the interpolated normals of front faces
     * face slightly away, and negating them would flip the lighting there
     * from one pixel to the next; the mirror is continuous at N.V = 0 and
     * is -N for a surface seen squarely from behind. */
    silk_fx ndv = silk_v3_dot(n, v);
    if (p->two_sided && ndv < 0) n = silk_v3_sub(n, silk_v3_scale(v, 2 * ndv));

    /* light reaching the surface, per channel: diffuse and specular parts */
    int64_t dif[3] = { 0, 0, 0 }, spe[3] = { 0, 0, 0 };
    int nl = p->nlights < 0 ? 0 : (p->nlights > SILK_MAX_LIGHTS ? SILK_MAX_LIGHTS : p->nlights);
    for (int i = 0; i < nl; i++) {
        const silk_light *li = &p->lights[i];
        silk_vec3 l = li->vec;
        if (li->kind == SILK_LIGHT_POINT && !silk_v3_normalize(silk_v3_sub(li->vec, pos), &l)) continue;
        silk_fx ndl = silk_v3_dot(n, l);
        if (ndl <= 0) continue;
        /* R = 2 (N.L) N - L, the mirror direction of L */
        silk_vec3 r = silk_v3_sub(silk_v3_scale(n, 2 * ndl), l);
        silk_fx rdv = silk_v3_dot(r, v);
        silk_fx s = rdv > 0 ? pow_int(silk_fx_min(rdv, SILK_FX_ONE), m->shininess) : 0;
        silk_fx lc[3] = { li->color.x, li->color.y, li->color.z };
        for (int k = 0; k < 3; k++) {
            dif[k] += silk_fx_mul(ndl, lc[k]);
            spe[k] += silk_fx_mul(s, lc[k]);
        }
    }

    silk_fx base[3] = { m->color.x, m->color.y, m->color.z };
    silk_fx sc[3] = { m->specular_color.x, m->specular_color.y, m->specular_color.z };
    uint32_t rgb = 0;
    for (int k = 0; k < 3; k++) {
        silk_fx lit = silk_fx_add(m->ambient, silk_fx_mul(m->diffuse, silk_fx_sat(dif[k])));
        silk_fx c = silk_fx_add(silk_fx_mul(base[k], lit),
                                silk_fx_mul(silk_fx_mul(m->specular, sc[k]), silk_fx_sat(spe[k])));
        rgb = (rgb << 8) | to_byte(c);
    }
    return rgb;
}

void silk_hal_phong(silk_hal *h, const silk_phong *p)
{
    h->vertex = phong_vertex;
    h->fragment = phong_fragment;
    h->nvaryings = VAR_COUNT;
    h->uniforms = p;
}

/* Unit direction a*right + b*up + c*back in camera terms (back = towards
 * the viewer), coefficients in Q16.16. */
static silk_vec3 camera_dir(const silk_view *view, silk_fx a, silk_fx b, silk_fx c)
{
    silk_vec3 right = silk_v3(SILK_FX_ONE, 0, 0), up = silk_v3(0, SILK_FX_ONE, 0),
              back = silk_v3(0, 0, SILK_FX_ONE);
    if (view) {
        right = view->right;
        up = view->upv;
        back = silk_v3_neg(view->forward);
    }
    silk_vec3 d = silk_v3_add(silk_v3_add(silk_v3_scale(right, a), silk_v3_scale(up, b)),
                              silk_v3_scale(back, c));
    silk_vec3 u;
    silk_v3_normalize(d, &u);
    return u;
}

void silk_phong_default(silk_phong *p, const silk_view *view)
{
    memset(p, 0, sizeof *p);
    p->view = view;
    p->two_sided = 1;
    p->nlights = 2;
    /* key: warm white from the upper left, in front of the object */
    p->lights[0].kind = SILK_LIGHT_DIRECTIONAL;
    p->lights[0].vec = camera_dir(view, SILK_FX_C(-5, 10), SILK_FX_C(6, 10), SILK_FX_C(7, 10));
    p->lights[0].color = silk_v3(SILK_FX_C(100, 100), SILK_FX_C(97, 100), SILK_FX_C(92, 100));
    /* fill: dim and cool, from the lower right, so the shadow side keeps its
     * form; weak enough that its highlight does not read as a second sun */
    p->lights[1].kind = SILK_LIGHT_DIRECTIONAL;
    p->lights[1].vec = camera_dir(view, SILK_FX_C(6, 10), SILK_FX_C(-5, 10), SILK_FX_C(3, 10));
    p->lights[1].color = silk_v3(SILK_FX_C(20, 100), SILK_FX_C(22, 100), SILK_FX_C(26, 100));
    /* light grey-blue */
    p->mat.color = silk_v3(SILK_FX_C(66, 100), SILK_FX_C(72, 100), SILK_FX_C(82, 100));
    p->mat.ambient = SILK_FX_C(14, 100);
    p->mat.diffuse = SILK_FX_C(85, 100);
    p->mat.specular = SILK_FX_C(35, 100);
    p->mat.shininess = 24;
    p->mat.specular_color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
}
