/*
 * silk/hal.h - the hardware-abstraction layer: a vertex stage and a fragment
 * stage behind function pointers, as on a GPU.
 *
 * The per-frame silhouette work does not emit finished positions.  It emits
 * compact vertex records (paper Fig. 16): "corner k of triangle t", "point t
 * on curve c", "vertex v moved by offset o", or, in the PN and BLEND modes,
 * "point (i,j,k)/n of cubic patch p".  The vertex stage evaluates a
 * record into a position, normal and texture coordinate and transforms it to
 * clip space; the fragment stage shades.  A device with a real GPU can take
 * over both stages without touching the rest of silk.
 */
#ifndef SILK_HAL_H
#define SILK_HAL_H

#include <stdint.h>
#include "fixed.h"
#include "mesh.h"
#include "camera.h"
#include "raster.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A cubic Hermite curve (paper eq. 5) with normals, texture coordinates
 * and vertex colours interpolated linearly along it (eq. 6). */
typedef struct silk_curve {
    silk_vec3 p0, p1;        /* end points */
    silk_vec3 t0, t1;        /* end tangents */
    silk_vec3 n0, n1;        /* unit normals at the ends */
    silk_vec2 uv0, uv1;
    uint32_t rgb0, rgb1;     /* vertex colours 0xRRGGBB at the ends (white without them) */
} silk_curve;

typedef enum silk_vrec_kind {
    SILK_VREC_CORNER = 0,    /* a: triangle*3 + corner of the mesh */
    SILK_VREC_CURVE = 1,     /* a: curve index, t: parameter in [0,1] */
    SILK_VREC_MOVED = 2,     /* a: triangle*3 + corner, b: offset index */
    SILK_VREC_PATCH = 3      /* a: patch index, b: SILK_PATCH_POINT(i, j, n) */
} silk_vrec_kind;

typedef struct silk_vrec {
    uint32_t kind;           /* silk_vrec_kind */
    uint32_t a, b;
    silk_fx t;
} silk_vrec;

/* A cubic triangular Bezier patch with a quadratic normal patch and linear
 * texture coordinates: PN triangles (Vlachos et al. 2001) and the blended
 * patches of Dyken & Reimers.  With barycentric weights (u, v, w) on
 * corners 0, 1, 2:
 *   S(u,v,w) = sum_{i+j+k=3} 3!/(i!j!k!) b_ijk u^i v^j w^k
 *   N(u,v,w) = normalize( sum_{i+j+k=2} n_ijk u^i v^j w^k )   (no multinomial
 *              factors: Vlachos' form, n110 is a unit vector)
 * b300, b030, b003 are the corners; b210 and b120 lie on side 0 (corner 0 ->
 * 1) near corners 0 and 1, b021, b012 on side 1, b102, b201 on side 2. */
enum { SILK_B300, SILK_B030, SILK_B003, SILK_B210, SILK_B120, SILK_B021, SILK_B012, SILK_B102,
       SILK_B201, SILK_B111 };
enum { SILK_N200, SILK_N020, SILK_N002, SILK_N110, SILK_N011, SILK_N101 };

typedef struct silk_patch {
    silk_vec3 b[10];         /* control points, SILK_B300 .. SILK_B111 */
    silk_vec3 n[6];          /* normal coefficients, SILK_N200 .. SILK_N101 */
    silk_vec2 uv[3];         /* at the corners */
    uint32_t rgb[3];         /* vertex colours at the corners */
} silk_patch;

/* The point of a patch with barycentric coordinates (i, j, n-i-j) / n, as
 * the b field of a SILK_VREC_PATCH record; 1 <= n <= SILK_PATCH_MAX_DIV. */
#define SILK_PATCH_MAX_DIV 255u
#define SILK_PATCH_POINT(i, j, n) ((uint32_t)(i) | (uint32_t)(j) << 8 | (uint32_t)(n) << 16)

/* What records refer to in one frame. */
typedef struct silk_geom {
    const silk_mesh *mesh;
    const silk_curve *curves;
    const silk_vec3 *offsets;
    const silk_patch *patches;
} silk_geom;

typedef struct silk_vertex_attr {
    silk_vec3 pos, normal;
    silk_vec2 uv;
    uint32_t rgb;            /* vertex colour 0xRRGGBB; 0xFFFFFF when the mesh has none */
} silk_vertex_attr;

/* (1-t) a + t b per 8-bit channel of two 0xRRGGBB colours, rounded; t in
 * [0, 1].  A pure function of its arguments, so both triangles that share
 * a point get the same colour there. */
uint32_t silk_rgb_lerp(uint32_t a, uint32_t b, silk_fx t);

/* Evaluate a record: Hermite position, linearly interpolated (then
 * normalised) normal and uv.  Stages call this; it is the only place that
 * knows the record layout. */
void silk_vrec_eval(const silk_geom *g, const silk_vrec *r, silk_vertex_attr *out);
/* Point of a Hermite curve at t (eq. 5). */
silk_vec3 silk_hermite_point(const silk_curve *c, silk_fx t);
/* Point, normal and uv of a patch at a SILK_PATCH_POINT (src/pn.c).  Exact
 * integer sums rounded once, so a point on a side depends only on that
 * side's four control points: patches that share them meet bit for bit.  A
 * malformed point gives zeros. */
void silk_patch_eval(const silk_patch *p, uint32_t point, silk_vertex_attr *out);

/* What a fragment stage returns to leave the pixel as it was: no colour,
 * no depth written (a discarded fragment lets what lies behind show). */
#define SILK_FRAGMENT_DISCARD 0xFFFFFFFFu

typedef struct silk_hal {
    void (*vertex)(const struct silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out);
    /* var: the interpolated varyings; returns 0xRRGGBB, or SILK_FRAGMENT_DISCARD */
    uint32_t (*fragment)(const struct silk_hal *h, const silk_fx *var);
    int nvaryings;
    const void *uniforms;
    /* 0: off.  k > 0: varyings k-1 and k are texture coordinates (u, v);
     * the rasterizer measures how far they move from a pixel to its right
     * and lower neighbours and passes max |du| in var[nvaryings] and max |dv|
     * in var[nvaryings + 1] (Q16.16 per pixel), for choosing a mipmap level
     * (silk/texture.h); the fragment stage's array has room for both. */
    int footprint_var;
} silk_hal;

/* ---- the default stages: Phong ---------------------------------------------- */

#define SILK_MAX_LIGHTS 4

typedef enum silk_light_kind { SILK_LIGHT_DIRECTIONAL = 0, SILK_LIGHT_POINT = 1 } silk_light_kind;

typedef struct silk_light {
    silk_light_kind kind;
    silk_vec3 vec;           /* directional: unit direction towards the light; point: position */
    silk_vec3 color;         /* linear RGB, 1.0 = full */
} silk_light;

typedef struct silk_material {
    silk_vec3 color;         /* base colour, components in [0,1] */
    silk_fx ambient, diffuse, specular;
    int shininess;           /* Phong exponent, 1..256 */
    silk_vec3 specular_color;
} silk_material;

typedef struct silk_phong {
    const silk_view *view;
    silk_light lights[SILK_MAX_LIGHTS];
    int nlights;
    silk_material mat;
    int two_sided;           /* light back faces with the flipped normal */
    /* Texture and vertex colours multiply the base colour (the ambient and
     * diffuse terms, not the highlight).  texture: NULL for none, else
     * sampled at the mesh's uvs; vertex_colors: use the mesh's colours. */
    const struct silk_texture *texture;
    int vertex_colors;
} silk_phong;

/* varyings: world position (3), normal (3), then with a texture or vertex
 * colours uv (2), then with vertex colours r, g, b (3, Q16.16 in [0, 1]).
 * Call silk_hal_phong after setting texture and vertex_colors. */
void silk_phong_default(silk_phong *p, const silk_view *view); /* a key light and a fill light */
void silk_hal_phong(silk_hal *h, const silk_phong *p);
/* The fragment stage of h (silk_hal_phong's) at varyings position and
 * normal alone, with rgb (0xRRGGBB) in place of the texture and vertex
 * colour; a stage of the caller's own is called as it is. */
uint32_t silk_hal_phong_tinted(const silk_hal *h, const silk_fx *var, uint32_t rgb);

#ifdef __cplusplus
}
#endif

#endif
