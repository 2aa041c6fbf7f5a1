/*
 * png_read.h - read a PNG file into 8-bit RGB, for the host tools that
 * compare renders (`silk diff`, the tests).  Platform code: libpng and
 * malloc, never linked into the core.
 */
#ifndef SILK_PNG_READ_H
#define SILK_PNG_READ_H

#include <stdint.h>
#include "silk/error.h"

/* Largest image silk_png_read accepts, in pixels (a 16384 x 16384 frame). */
#define SILK_PNG_READ_MAX_PIXELS ((uint64_t)1 << 28)

/* Read path into a malloc'd buffer of width*height R, G, B bytes, rows top
 * to bottom (free it with free()).  Grey, palette and 16-bit images are
 * converted; an alpha channel is composited onto black.  Errors name the
 * file: "a.png: not a PNG file", "a.png: cannot read: libpng: ...". */
silk_status silk_png_read(const char *path, uint8_t **rgb, int *width, int *height, silk_error *err);

#endif
