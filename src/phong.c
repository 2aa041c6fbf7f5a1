/*
 * phong.c - the default HAL stages: a vertex stage that evaluates a vertex
 * record and transforms it to clip space, and a per-pixel Phong fragment
 * stage (ambient + Lambert diffuse + Phong specular (R.V)^n) with the
 * interpolated normal renormalised at every pixel.
 *
 * Not a paper equation: the paper renders with standard OpenGL lighting.
 * The varyings are world position (3) and normal (3), then, only when a
 * texture or vertex colours are in use, uv (2) and colour (3): the
 * rasterizer interpolates h->nvaryings of them, so an untextured frame pays
 * nothing for them.  Lighting is done in world space, so nothing needs the
 * inverse view matrix.  A texel (texture.c) and the vertex colour multiply
 * the material colour, i.e. the ambient and diffuse terms.
 */
#include <string.h>
#include "frame.h"
#include "phong_parts.h"
#include "silk/hal.h"
#include "silk/texture.h"
#include "compiler.h"

enum { VAR_POS = 0, VAR_NORMAL = 3, VAR_COUNT = 6, VAR_UV = 6, VAR_RGB = 8, VAR_UV_COUNT = 8, VAR_RGB_COUNT = 11 };
_Static_assert(VAR_COUNT == SILK_PHONG_PLAIN_NVAR, "the rasterizer's plain case interpolates the default stage's varyings");

/* The fragment stage's words on a 32-bit processor, where a 64-bit product
 * is three instructions (SILK_CPU32), and on a 64-bit host, where nothing
 * needs widening: ucomp, a unit vector's components (made by silk_unit_fx
 * there, out of line: the code it takes counts; by silk_unit64 here, the
 * same bits inline), and uword, pow_unit's (one multiply instruction a
 * product there). */
#if SILK_CPU32
typedef int32_t ucomp;
typedef uint32_t uword;
#define unit_fx silk_unit_fx
#else
typedef int64_t ucomp;
typedef uint64_t uword;
#define unit_fx silk_unit64
#endif

/* Channel c (the low 8 bits) to Q16.16 in [0, 1]: c * 65536 / 255 rounded
 * is c * 257 + (c + 127) / 255, exact at 0 and 255. */
static silk_fx byte_to_fx(uint32_t c)
{
    c &= 0xff;
    return (silk_fx)(c * 257 + (c + 127) / 255);
}

/* Where the vertex stage puts position pos: its clip coordinates. */
static silk_vec4 clip_of(const silk_phong *p, silk_vec3 pos)
{
    if (p->view) return silk_view_clip(p->view, pos);
    /* no camera: positions are taken as clip coordinates already */
    silk_vec4 c = { pos.x, pos.y, pos.z, SILK_FX_ONE };
    return c;
}

/* The vertex stage's varyings for attributes a. */
static inline void varyings_of(const silk_vertex_attr *a, silk_vertex_out *out)
{
    out->var[VAR_POS + 0] = a->pos.x;
    out->var[VAR_POS + 1] = a->pos.y;
    out->var[VAR_POS + 2] = a->pos.z;
    out->var[VAR_NORMAL + 0] = a->normal.x;
    out->var[VAR_NORMAL + 1] = a->normal.y;
    out->var[VAR_NORMAL + 2] = a->normal.z;
    out->var[VAR_UV] = a->uv.x;
    out->var[VAR_UV + 1] = a->uv.y;
    for (int k = 0; k < 3; k++) out->var[VAR_RGB + k] = byte_to_fx(a->rgb >> (16 - 8 * k));
    for (int k = VAR_RGB_COUNT; k < SILK_MAX_VARYINGS; k++) out->var[k] = 0;   /* not interpolated */
}

static void phong_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r,
                         silk_vertex_out *out)
{
    silk_vertex_attr a;
    silk_vrec_eval(g, r, &a);
    out->clip = clip_of((const silk_phong *)h->uniforms, a.pos);
    varyings_of(&a, out);
}

/* x^n for x in [0, 1] (Q16.16) by repeated squaring: at most 2 log2(n)
 * products, each rounded; x <= 1 keeps every product within 32 bits by 32
 * bits. */
static int64_t pow_unit(int64_t x, int n)
{
    /* x^n <= 2^-n rounds to zero for x <= 1/2 and n > 16: most pixels */
    if (x <= SILK_FX_HALF && n > 16) return 0;
    uword r = SILK_FX_ONE, ux = (uword)x;
    while (n > 0) {
        if (n & 1) r = ((uint64_t)r * ux + SILK_FX_HALF) >> 16;
        n >>= 1;
        if (n) ux = ((uint64_t)ux * ux + SILK_FX_HALF) >> 16;
    }
    return (int64_t)r;
}

/* v, with the compiler's knowledge of its range forgotten: knowing that a
 * 64-bit value fits 32 bits, gcc drops the narrowing and multiplies in 64
 * bits again (three instructions on a 32-bit processor instead of one). */
static inline int32_t opaque32(int32_t v)
{
    SILK_OPAQUE32(v);
    return v;
}

/* a b for factors within 32 bits (as every one of the fragment stage's is,
 * by the ranges stated where they are formed): one multiply instruction on
 * a 32-bit processor, the same product as the 64-bit one, which is a
 * single instruction on a 64-bit host. */
static inline int64_t mul32(int64_t a, int64_t b)
{
    if (SILK_CPU32) return (int64_t)opaque32((int32_t)a) * opaque32((int32_t)b);
    return a * b;
}

/* (inline: three per shaded pixel and light, a call would cost as much) */
SILK_ALWAYS_INLINE static inline int64_t dot32(const ucomp *a, const ucomp *b)
{
    return mul32(a[0], b[0]) + mul32(a[1], b[1]) + mul32(a[2], b[2]);
}

/* Q16.16 channel in [0, 1] (clamped) to 0..255, rounded. */
static uint32_t to_byte(int64_t c)
{
    c = c < 0 ? 0 : (c > SILK_FX_ONE ? SILK_FX_ONE : c);
    return (uint32_t)((c * 255 + SILK_FX_HALF) >> 16);
}

static int64_t sat31(int64_t v) { return v > SILK_FX_MAX ? SILK_FX_MAX : (v < SILK_FX_MIN ? SILK_FX_MIN : v); }

/* One channel: base (ambient + diffuse D) + specular S, each light sum
 * saturated as a silk_fx; every product of two values below 2^31. */
static uint32_t channel(const silk_material *m, silk_fx base, silk_fx spec, int64_t d, int64_t s)
{
    int64_t lit = sat31(m->ambient + ((m->diffuse * sat31(d)) >> 16));
    return to_byte(((base * lit) >> 16) + ((spec * sat31(s)) >> 16));
}

/* The per-pixel work runs on plain integers: N and V are unit vectors
 * (silk_unit_fx), so every product below is bounded where it is formed and
 * needs no saturation, and has factors within 32 bits (mul32: one multiply
 * instruction on a 32-bit processor); only the dot products round.  The error is a
 * few ulp of Q16.16, far below one level of an 8-bit channel
 * (tests/core/test_phong.c compares with a double-precision Phong).  R.V is
 * 2 (N.L)(N.V) - L.V, so the mirror direction R is never formed. */
static uint32_t shade(const silk_phong *p, const silk_fx *var, const int64_t *base);
static inline uint32_t shade_in(const silk_phong *p, const silk_fx *var, const int64_t *base, int plain);

static uint32_t phong_fragment(const silk_hal *h, const silk_fx *var)
{
    const silk_phong *p = (const silk_phong *)h->uniforms;
    const silk_material *m = &p->mat;
    /* the material colour times the texel and the vertex colour */
    int64_t base[3] = { m->color.x, m->color.y, m->color.z };
    if (SILK_TEXTURES && p->texture) {   /* a build without textures draws textured models in their material colour */
        uint32_t tex = silk_texture_sample(p->texture, var[VAR_UV], var[VAR_UV + 1], var[h->nvaryings],
                                           var[h->nvaryings + 1]);
        for (int k = 0; k < 3; k++) base[k] = (base[k] * byte_to_fx(tex >> (16 - 8 * k))) >> 16;
    }
    if (p->vertex_colors && h->nvaryings >= VAR_RGB_COUNT)
        for (int k = 0; k < 3; k++) {
            int64_t c = var[VAR_RGB + k];
            base[k] = (base[k] * (c < 0 ? 0 : (c > SILK_FX_ONE ? SILK_FX_ONE : c))) >> 16;
        }
    return shade(p, var, base);
}

uint32_t silk_hal_phong_tinted(const silk_hal *h, const silk_fx *var, uint32_t rgb)
{
    if (h->fragment != phong_fragment) return h->fragment(h, var);
    const silk_phong *p = (const silk_phong *)h->uniforms;
    int64_t base[3] = { p->mat.color.x, p->mat.color.y, p->mat.color.z };
    for (int k = 0; k < 3; k++) base[k] = (base[k] * byte_to_fx(rgb >> (16 - 8 * k))) >> 16;
    return shade(p, var, base);
}

/* silk_v3_sub(eye, position var[0..2]), the same bits, without the
 * saturation where the differences are within [-2^30, 2^30), as a
 * camera's always are. */
static inline silk_vec3 eye_minus(silk_vec3 eye, const silk_fx *var)
{
    int64_t dx = (int64_t)eye.x - var[VAR_POS], dy = (int64_t)eye.y - var[VAR_POS + 1],
            dz = (int64_t)eye.z - var[VAR_POS + 2];
    const int64_t q = (int64_t)1 << 30;
    if (((uint64_t)(dx + q) | (uint64_t)(dy + q) | (uint64_t)(dz + q)) >> 31 == 0)
        return silk_v3((silk_fx)dx, (silk_fx)dy, (silk_fx)dz);
    return silk_v3_sub(eye, silk_v3(var[VAR_POS], var[VAR_POS + 1], var[VAR_POS + 2]));
}

/* Light li's diffuse and specular parts at a pixel (position var[0..2],
 * unit normal n and view vector v, N.V = ndv), added to the sums of
 * diffuse (dr, dg, db) and specular (sr, sg, sb) light; plain as for
 * shade_in. */
SILK_ALWAYS_INLINE static inline void light_in(const silk_phong *p, const silk_light *li, const silk_fx *var, const ucomp *n,
                            const ucomp *v, int64_t ndv, int64_t *dr, int64_t *dg, int64_t *db, int64_t *sr,
                            int64_t *sg, int64_t *sb, int plain)
{
    const silk_material *m = &p->mat;
    ucomp l[3] = { li->vec.x, li->vec.y, li->vec.z };
    if (!plain && li->kind == SILK_LIGHT_POINT) {
        silk_vec3 dl = silk_v3_sub(li->vec, silk_v3(var[VAR_POS], var[VAR_POS + 1], var[VAR_POS + 2]));
        if (!unit_fx(dl.x, dl.y, dl.z, l)) return;
    }
    int64_t ndl = (dot32(n, l) + SILK_FX_HALF) >> 16;   /* |N| = 1, |l_i| < 2^31 */
    if (ndl <= 0) return;
    if (ndl > SILK_FX_MAX) ndl = SILK_FX_MAX;
    int64_t rdv = ((2 * mul32(ndl, ndv)) >> 16) - (dot32(l, v) >> 16);
    /* plain: pow_unit's first test without the call */
    int64_t s = rdv > 0 && !(plain && rdv <= SILK_FX_HALF && m->shininess > 16)
                    ? pow_unit(rdv < SILK_FX_ONE ? rdv : SILK_FX_ONE, m->shininess) : 0;
    *dr += mul32(ndl, li->color.x) >> 16;
    *dg += mul32(ndl, li->color.y) >> 16;
    *db += mul32(ndl, li->color.z) >> 16;
    if (!s) return;   /* most pixels are outside the highlight (pow_unit) */
    *sr += mul32(s, li->color.x) >> 16;
    *sg += mul32(s, li->color.y) >> 16;
    *sb += mul32(s, li->color.z) >> 16;
}

/* Phong at position and normal var[0..5] with ambient and diffuse colour base. */
static uint32_t shade(const silk_phong *p, const silk_fx *var, const int64_t *base)
{
    return shade_in(p, var, base, 0);
}

/* shade's work; plain: the caller knows that p is in the usual case
 * silk_hal_phong_plain describes, so the tests that case settles fold away
 * (the same bits: each test's other branch is one the case never takes). */
SILK_ALWAYS_INLINE static inline uint32_t shade_in(const silk_phong *p, const silk_fx *var, const int64_t *base, int plain)
{
    const silk_material *m = &p->mat;
    ucomp v[3], n[3];                    /* unit vectors: components within +-2^16 (and a little) */
    if (plain || (p->view && !p->view->cam.ortho)) {
        silk_vec3 d = plain ? eye_minus(p->view->cam.eye, var)
                            : silk_v3_sub(p->view->cam.eye, silk_v3(var[VAR_POS], var[VAR_POS + 1], var[VAR_POS + 2]));
        if (!unit_fx(d.x, d.y, d.z, v)) {
            v[0] = -p->view->forward.x, v[1] = -p->view->forward.y, v[2] = -p->view->forward.z;
        }
    } else if (p->view) {
        v[0] = -p->view->forward.x, v[1] = -p->view->forward.y, v[2] = -p->view->forward.z;
    } else {
        v[0] = 0, v[1] = 0, v[2] = SILK_FX_ONE;
    }
    /* A zero normal (opposite normals interpolated) faces the viewer. */
    if (!unit_fx(var[VAR_NORMAL], var[VAR_NORMAL + 1], var[VAR_NORMAL + 2], n))
        n[0] = v[0], n[1] = v[1], n[2] = v[2];
    /* Two-sided: a normal facing away from the eye is mirrored in the plane
     * perpendicular to V (its component along V changes sign).  Not plain
     * negation: near a silhouette the interpolated normals of front faces
     * face slightly away, and negating them would flip the lighting there
     * from one pixel to the next; the mirror is continuous at N.V = 0 and
     * is -N for a surface seen squarely from behind.  A reflection keeps N
     * a unit vector. */
    int64_t ndv = (dot32(n, v) + SILK_FX_HALF) >> 16;
    if (p->two_sided && ndv < 0) {
        for (int k = 0; k < 3; k++) n[k] = (ucomp)(n[k] - (mul32(2 * ndv, v[k]) >> 16));
        ndv = -ndv;
    }

    /* light reaching the surface, per channel: diffuse and specular parts */
    int64_t dr = 0, dg = 0, db = 0, sr = 0, sg = 0, sb = 0;
    if (plain) {   /* two lights: no loop */
        light_in(p, &p->lights[0], var, n, v, ndv, &dr, &dg, &db, &sr, &sg, &sb, plain);
        light_in(p, &p->lights[1], var, n, v, ndv, &dr, &dg, &db, &sr, &sg, &sb, plain);
    } else {
        int nl = p->nlights < 0 ? 0 : (p->nlights > SILK_MAX_LIGHTS ? SILK_MAX_LIGHTS : p->nlights);
        for (int i = 0; i < nl; i++) light_in(p, &p->lights[i], var, n, v, ndv, &dr, &dg, &db, &sr, &sg, &sb, plain);
    }

    int64_t spec = m->specular;
    /* Usual case, one test: every light sum and material term in [0, 16):
     * then every product has factors below 2^21, no sum can leave the
     * range, and only the final clamp to 1 remains.  The material terms
     * and base are silk_fx values, so their low 32 bits tell. */
    uint64_t all = (uint64_t)(dr | dg | db | sr | sg | sb) |
                   (plain ? 0u : (uint32_t)(spec | m->ambient | m->diffuse | base[0] | base[1] | base[2] |
                                            m->specular_color.x | m->specular_color.y | m->specular_color.z));
    if (all < ((uint64_t)1 << 20)) {
        /* every sum below is under 2^30: 32-bit arithmetic */
        int32_t amb = m->ambient, dif = m->diffuse, hr = 0, hg = 0, hb = 0;
        if (sr | sg | sb) {   /* a highlight (about half the pixels have none) */
            hr = (int32_t)(mul32(mul32(spec, m->specular_color.x) >> 16, sr) >> 16);
            hg = (int32_t)(mul32(mul32(spec, m->specular_color.y) >> 16, sg) >> 16);
            hb = (int32_t)(mul32(mul32(spec, m->specular_color.z) >> 16, sb) >> 16);
        }
        uint32_t cr = (uint32_t)(mul32(base[0], amb + (int32_t)(mul32(dif, dr) >> 16)) >> 16) + (uint32_t)hr;
        uint32_t cg = (uint32_t)(mul32(base[1], amb + (int32_t)(mul32(dif, dg) >> 16)) >> 16) + (uint32_t)hg;
        uint32_t cb = (uint32_t)(mul32(base[2], amb + (int32_t)(mul32(dif, db) >> 16)) >> 16) + (uint32_t)hb;
        uint32_t c[3] = { cr < SILK_FX_ONE ? cr : SILK_FX_ONE, cg < SILK_FX_ONE ? cg : SILK_FX_ONE,
                          cb < SILK_FX_ONE ? cb : SILK_FX_ONE };
        return ((c[0] * 255 + SILK_FX_HALF) >> 16) << 16 | ((c[1] * 255 + SILK_FX_HALF) >> 16) << 8 |
               ((c[2] * 255 + SILK_FX_HALF) >> 16);
    }
    return channel(m, (silk_fx)base[0], silk_fx_mul(m->specular, m->specular_color.x), dr, sr) << 16 |
           channel(m, (silk_fx)base[1], silk_fx_mul(m->specular, m->specular_color.y), dg, sg) << 8 |
           channel(m, (silk_fx)base[2], silk_fx_mul(m->specular, m->specular_color.z), db, sb);
}

const silk_phong *silk_hal_phong_plain(const silk_hal *h)
{
    if (!SILK_PHONG_PLAIN) return NULL;   /* (a build without the shortcut has no such case) */
    if (h->fragment != phong_fragment || h->nvaryings != VAR_COUNT) return NULL;
    const silk_phong *p = (const silk_phong *)h->uniforms;
    const silk_material *m = &p->mat;
    if (SILK_TEXTURES && p->texture) return NULL;
    if (!p->view || p->view->cam.ortho || p->nlights != 2 || p->lights[0].kind == SILK_LIGHT_POINT ||
        p->lights[1].kind == SILK_LIGHT_POINT)
        return NULL;
    /* shade's usual-case test, the part that does not change from pixel to pixel */
    uint32_t all = (uint32_t)(m->specular | m->ambient | m->diffuse | m->color.x | m->color.y | m->color.z |
                              m->specular_color.x | m->specular_color.y | m->specular_color.z);
    return all < ((uint32_t)1 << 20) ? p : NULL;
}

uint32_t silk_phong_plain_fragment(const silk_phong *p, const silk_fx *var)
{
    if (!SILK_PHONG_PLAIN) return 0;   /* (never called there: silk_hal_phong_plain is NULL) */
    const int64_t base[3] = { p->mat.color.x, p->mat.color.y, p->mat.color.z };
    return shade_in(p, var, base, 1);
}

int silk_hal_vertex_by_attrs(const silk_hal *h)
{
    return h->vertex == phong_vertex;
}

silk_vec4 silk_hal_vertex_clip(const silk_hal *h, silk_vec3 pos)
{
    silk_vec4 none = { 0, 0, 0, 0 };
    return SILK_DRAW_DIRECT ? clip_of((const silk_phong *)h->uniforms, pos) : none;   /* (only its caller's) */
}

void silk_hal_vertex_varyings(const silk_geom *g, const silk_vrec *r, silk_vertex_out *out)
{
    if (!SILK_DRAW_DIRECT) return;   /* (only its caller's) */
    silk_vertex_attr a;
    silk_vrec_eval(g, r, &a);
    varyings_of(&a, out);
}

const silk_view *silk_hal_vertex_view(const silk_hal *h)
{
    return h->vertex == phong_vertex && h->uniforms ? ((const silk_phong *)h->uniforms)->view : NULL;
}

void silk_hal_phong(silk_hal *h, const silk_phong *p)
{
    h->vertex = phong_vertex;
    h->fragment = phong_fragment;
    h->nvaryings = p->vertex_colors ? VAR_RGB_COUNT : (p->texture ? VAR_UV_COUNT : VAR_COUNT);
    h->uniforms = p;
    h->footprint_var = SILK_TEXTURES && p->texture ? VAR_UV + 1 : 0;   /* (a build without textures samples none) */
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
