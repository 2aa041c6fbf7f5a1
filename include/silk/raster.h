/*
 * silk/raster.h - render targets and the scanline rasterizer.
 *
 * A target holds a band of rows [y0, y0+rows) of a width x height frame: the
 * whole frame when rows == height, or a strip when rendering in bands for a
 * device without a frame buffer.  Triangles arrive as clip-space vertices with
 * varyings (from the HAL's vertex stage) and leave as shaded pixels (from its
 * fragment stage).
 */
#ifndef SILK_RASTER_H
#define SILK_RASTER_H

#include <stddef.h>
#include <stdint.h>
#include "fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SILK_MAX_VARYINGS 11

typedef enum silk_pixfmt {
    SILK_PIX_RGB888 = 0,   /* 3 bytes per pixel: R, G, B */
    SILK_PIX_RGB565 = 1    /* 2 bytes per pixel, little-endian 0bRRRRRGGGGGGBBBBB */
} silk_pixfmt;

#define SILK_DEPTH_TIES 2   /* silk_target.depth_equal */

typedef struct silk_target {
    int width, height;       /* the whole frame */
    int y0, rows;            /* the band these buffers hold */
    silk_pixfmt fmt;
    uint8_t *color;          /* rows * stride bytes */
    size_t stride;           /* bytes per row */
    uint32_t *depth;         /* rows * width; larger is nearer: (w - z) / w in Q1.31, which is
                                2 znear / w in perspective (docs/raster.md); NULL: no depth test */
    uint8_t *alpha;          /* optional: rows * width coverage bytes, 0 (nothing) .. 255 (covered),
                                filled by silk_render; anti-aliased outlines make the in-betweens */
    uint16_t *writes;        /* optional (tests): rows * width counters of fragment writes */
    int depth_equal;         /* 0: draw where nearer than the depth buffer; 1: where as near, for the
                                shading pass after a depth-only pass (silk_render), so that each
                                pixel is shaded once; SILK_DEPTH_TIES (depth alone, builds with the
                                vertex cache): write where nearer, set drew where as near too */
    const uint8_t *mask;     /* optional stencil over the band (clip mode): rows of (width + 7) / 8 bytes,
                                bit x & 7 of byte x >> 3; triangles draw only where the bit is set */
    int cull_back;           /* 1: skip triangles seen from behind (clockwise on the screen after
                                snapping), set by silk_render where they cannot show */
    int drew;                /* set to 1 by every depth the rasterizer writes (builds with the vertex
                                cache): silk_render clears and reads it to learn which triangles of
                                its depth pass hold a pixel */
} silk_target;

/* Output of the vertex stage. */
typedef struct silk_vertex_out {
    silk_vec4 clip;                      /* clip-space position */
    silk_fx var[SILK_MAX_VARYINGS];      /* interpolated perspective-correctly */
} silk_vertex_out;

struct silk_hal;

size_t silk_pixfmt_bytes(silk_pixfmt f);
/* Set up a target over caller buffers; color must hold rows*width*bytes, depth rows*width. */
void silk_target_init(silk_target *t, int width, int height, int y0, int rows, silk_pixfmt fmt,
                      uint8_t *color, uint32_t *depth);
void silk_target_clear(silk_target *t, uint32_t rgb);  /* colour to rgb, depth to farthest */
void silk_target_put(silk_target *t, int x, int y, uint32_t rgb); /* y in frame rows; ignored outside band */
uint32_t silk_target_get(const silk_target *t, int x, int y);    /* as 0xRRGGBB */

/* Rasterize one triangle: near-plane clipping, subpixel precision, top-left
 * fill rule, perspective-correct varyings, depth test, then the HAL's
 * fragment stage.  Both windings are drawn.  h == NULL (or no fragment
 * stage) draws depth only.  Frames up to SILK_MAX_DIM (silk/camera.h) on a
 * side; docs/raster.md has every convention. */
void silk_raster_triangle(silk_target *t, const struct silk_hal *h,
                          const silk_vertex_out *a, const silk_vertex_out *b, const silk_vertex_out *c);

/* A one-pixel line between two clip-space points, depth-tested with a small
 * bias towards the viewer so that lines on the surface show; colour rgb. */
void silk_raster_line(silk_target *t, const silk_vertex_out *a, const silk_vertex_out *b, uint32_t rgb);

#ifdef __cplusplus
}
#endif

#endif
