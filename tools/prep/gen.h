/*
 * gen.h - analytic test meshes for `silk gen`: UV sphere, torus, capped cone,
 * capped cylinder, torus knot.  Host-side (double precision).
 *
 * Every mesh is closed, manifold and oriented outward (counter-clockwise seen
 * from outside), and every vertex lies on the analytic surface up to double
 * rounding.  The axis of revolution is +y, as in ../shared/meshes.
 */
#ifndef SILK_GEN_H
#define SILK_GEN_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef enum gen_shape {
    GEN_SPHERE = 0,
    GEN_TORUS,
    GEN_CONE,
    GEN_CYLINDER,
    GEN_KNOT,
    GEN_SHAPE_COUNT
} gen_shape;

typedef struct gen_params {
    gen_shape shape;
    int segments;      /* around the y axis; for the knot, along the curve */
    int bands;         /* sphere: pole to pole; torus, knot: around the tube;
                          cone, cylinder: rows of the side */
    double radius;     /* sphere, cone (base), cylinder */
    double height;     /* cone (apex at y = height), cylinder (y in [0, height]) */
    double R, r;       /* torus: major and minor radius; knot: the torus it winds on */
    double tube;       /* knot: radius of the tube around the curve */
    int p, q;          /* knot: p turns around the y axis, q turns through the hole */
    int uv;            /* sphere, torus: write texture coordinates (vt) too */
} gen_params;

typedef struct gen_mesh {
    uint32_t nverts, ntris;
    double *pos;       /* 3 * nverts */
    uint32_t *tri;     /* 3 * ntris, 0-based */
} gen_mesh;

/* Largest mesh `silk gen` writes. */
#define GEN_MAX_TRIS 4000000u

const char *gen_shape_name(gen_shape s);
/* GEN_SHAPE_COUNT when name is not a shape. */
gen_shape gen_shape_from_name(const char *name);

/* The documented defaults: sphere 10 x 11 (200 triangles), torus 24 x 12
 * (576), cone 35 segments (70), cylinder 24 segments (96), knot (2,3) with
 * 64 x 8 (1024). */
void gen_defaults(gen_shape s, gen_params *p);

/* NULL when p describes a mesh gen_build can make, else a message such as
 * "--r must be smaller than --R (the torus would intersect itself)". */
const char *gen_check(const gen_params *p, char *buf, size_t n);

/* Build the mesh (malloc'd; gen_free releases it).  p must pass gen_check.
 * Returns 0, or -1 when out of memory. */
int gen_build(const gen_params *p, gen_mesh *m);
void gen_free(gen_mesh *m);

/* Wavefront OBJ: a comment with the command that reproduces it, then v
 * lines (%.9g) and f lines (1-based).  Returns 0, or -1 on a write error. */
int gen_write_obj(const gen_mesh *m, const gen_params *p, FILE *f);
/* gen_build and gen_write_obj into memory: the OBJ text (malloc'd, *len
 * bytes), or NULL when p fails gen_check or memory runs out. */
char *gen_obj_text(const gen_params *p, size_t *len);

/* A texture to go with --uv: size x size RGB888 pixels (rgb holds size *
 * size * 3 bytes) of squares x squares warm and cool squares, each with a
 * darker line along its top and left sides, so that orientation and any
 * seam show. */
void gen_checker(uint8_t *rgb, int size, int squares);

/* Point of the knot's centre curve at parameter t in [0, 2 pi). */
void gen_knot_curve(const gen_params *p, double t, double out[3]);

#endif
