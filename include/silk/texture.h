/*
 * silk/texture.h - textures: a pixel array in RGB565, RGB888 or 8-bit
 * paletted form, with its mipmap levels, sampled at a texture coordinate.
 *
 * A texture is plain data (pixels and an optional palette, no pointers into
 * the arena's bookkeeping), so it can live in the arena or in flash, as
 * `silk pack` writes it.  Decoding image files is the host's job
 * (platform/png_read.c); the core only samples.
 */
#ifndef SILK_TEXTURE_H
#define SILK_TEXTURE_H

#include <stddef.h>
#include <stdint.h>
#include "fixed.h"
#include "arena.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_texfmt {
    SILK_TEX_RGB888 = 0,     /* 3 bytes per texel: R, G, B */
    SILK_TEX_RGB565 = 1,     /* 2 bytes per texel, little-endian, as SILK_PIX_RGB565 */
    SILK_TEX_PAL8 = 2        /* 1 byte per texel: an index into palette[256] */
} silk_texfmt;

typedef enum silk_texfilter {
    SILK_TEX_BILINEAR = 0,   /* bilinear in a level, linear between two levels (trilinear) */
    SILK_TEX_NEAREST = 1     /* the nearest texel of the nearest level */
} silk_texfilter;

typedef enum silk_texwrap {
    SILK_TEX_REPEAT = 0,     /* u, v taken modulo 1 */
    SILK_TEX_CLAMP = 1       /* u, v clamped to the edge texels */
} silk_texwrap;

/* Level 0 is width x height texels, row 0 at the top of the image (v = 1),
 * so that OBJ/PLY coordinates (v = 0 at the bottom) map as in other tools.
 * Level k is max(1, width >> k) x max(1, height >> k), stored right after
 * level k-1, rows packed without padding. */
typedef struct silk_texture {
    const uint8_t *pixels;   /* every level */
    const uint32_t *palette; /* SILK_TEX_PAL8: 256 colours 0xRRGGBB; else NULL */
    uint16_t width, height;  /* level 0, 1 .. SILK_TEX_MAX_DIM */
    uint8_t format;          /* silk_texfmt */
    uint8_t levels;          /* 1 .. silk_texture_max_levels() */
    uint8_t filter;          /* silk_texfilter */
    uint8_t wrap;            /* silk_texwrap */
} silk_texture;

#define SILK_TEX_MAX_DIM 4096

size_t silk_texture_texel_bytes(silk_texfmt f);
/* Levels down to 1 x 1. */
int silk_texture_max_levels(int width, int height);
/* Bytes of pixels for `levels` levels (0 on a bad size or format). */
size_t silk_texture_bytes(silk_texfmt f, int width, int height, int levels);
/* Level 0 of pixels from rgb (width * height R, G, B bytes, rows top to
 * bottom) in t's format; a PAL8 texel takes the nearest palette entry. */
void silk_texture_encode(const silk_texture *t, uint8_t *pixels, const uint8_t *rgb);
/* Fill levels 1 .. levels-1 of pixels (level 0 already written) by 2x2
 * box filtering of the level above, in integers; a PAL8 level takes the
 * palette entry nearest to each average. */
void silk_texture_build_mipmaps(silk_texture *t, uint8_t *pixels);

/* The texel colour at (u, v) as 0xRRGGBB.  du, dv: how far u and v move
 * per pixel (Q16.16, as silk_hal.footprint_var gives them); they pick the
 * mipmap level (0 for level 0). */
uint32_t silk_texture_sample(const silk_texture *t, silk_fx u, silk_fx v, silk_fx du, silk_fx dv);

#ifdef __cplusplus
}
#endif

#endif
