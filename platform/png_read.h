/*
 * png_read.h - read a PNG or binary PPM file into 8-bit RGB, for the host
 * tools that compare renders (`silk diff`, the tests).  Platform code:
 * libpng and malloc, never linked into the core.
 */
#ifndef SILK_PNG_READ_H
#define SILK_PNG_READ_H

#include <stddef.h>
#include <stdint.h>
#include "silk/error.h"

/* Largest image silk_image_read accepts, in pixels (a 16384 x 16384 frame). */
#define SILK_PNG_READ_MAX_PIXELS ((uint64_t)1 << 28)

/* PNG or binary PPM (P6, maxval up to 255, scaled to 255), told apart by
 * their first bytes; "-" reads standard input.  Alpha is composited onto
 * bg_rgb (0xRRGGBB), so a transparent background reads as that colour;
 * grey, palette and 16-bit PNGs are converted.  Errors name the file:
 * "a.png: not a PNG or binary PPM image", "a.png: cannot read: libpng: ...". */
silk_status silk_image_read(const char *path, uint32_t bg_rgb, uint8_t **rgb, int *width, int *height,
                            silk_error *err);

/* The PPM part on bytes in memory (name for messages); exposed for the
 * fuzz harness. */
silk_status silk_ppm_parse(const uint8_t *data, size_t len, const char *name, uint8_t **rgb, int *width,
                           int *height, silk_error *err);

#endif
