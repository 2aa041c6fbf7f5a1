/*
 * fb.h - a Linux framebuffer as a silk_sink: each band silk_render_bands()
 * finishes is converted to the framebuffer's pixel format and stored
 * straight into the mapped screen memory, so no full frame is ever held.
 *
 * The geometry and pixel format come from the device (FBIOGET_VSCREENINFO,
 * FBIOGET_FSCREENINFO): 16, 24 or 32 bits per pixel with any red, green and
 * blue bit fields of up to 8 bits, rows line_length bytes apart, the visible
 * screen at (xoffset, yoffset) of the virtual one.  A file-backed
 * framebuffer (tests, headless machines) is given its geometry instead and
 * then goes through the same code: sized, mapped and written the same way.
 *
 * Host platform code (POSIX mmap; the device needs Linux), not the core.
 */
#ifndef SILK_FB_H
#define SILK_FB_H

#include <stddef.h>
#include <stdint.h>
#include "silk/camera.h"
#include "silk/error.h"
#include "silk/raster.h"

/* One colour channel: bits [offset, offset + length) of a pixel. */
typedef struct silk_fb_field {
    uint32_t offset, length;
} silk_fb_field;

/* What the sink needs of FBIOGET_VSCREENINFO / FBIOGET_FSCREENINFO. */
typedef struct silk_fb_info {
    uint32_t xres, yres;           /* visible pixels */
    uint32_t xres_virtual, yres_virtual;
    uint32_t xoffset, yoffset;     /* visible area within the virtual screen */
    uint32_t bits_per_pixel;       /* 16, 24 or 32 */
    uint32_t line_length;          /* bytes from one row to the next */
    silk_fb_field red, green, blue;
} silk_fb_info;

typedef struct silk_fb {
    silk_fb_info info;
    int fd;
    int file_backed;               /* 1: silk_fb_open_file */
    uint8_t *mem;                  /* the mapped screen (all virtual rows) */
    size_t mem_len;
    int origin_x, origin_y;        /* where the frame's pixel (0,0) goes on the visible screen */
    uint64_t bands;                /* bands written so far */
    char name[128];                /* for messages */
} silk_fb;

/* The usual layouts of a file-backed framebuffer: RGB565 (16), B,G,R bytes
 * (24) and XRGB8888 (32), little-endian, rows packed. */
silk_status silk_fb_info_default(silk_fb_info *info, int width, int height, int bpp, silk_error *err);

/* Open a framebuffer device such as /dev/fb0 (Linux). */
silk_status silk_fb_open(silk_fb *fb, const char *device, silk_error *err);

/* Create (or truncate) the file path as a framebuffer with this geometry,
 * zero-filled, and map it: the device path without the ioctls. */
silk_status silk_fb_open_file(silk_fb *fb, const char *path, const silk_fb_info *info, silk_error *err);

/* Write the mapped pixels back (msync) and release everything; safe on a
 * closed or never opened silk_fb.  Returns the msync/close result. */
silk_status silk_fb_close(silk_fb *fb, silk_error *err);

/* The silk_sink callback: user is the silk_fb.  Pixels of the band that fall
 * outside the visible screen are dropped.  Returns 0. */
int silk_fb_band(void *user, const silk_target *band);

/* One pixel 0xRRGGBB in the framebuffer's format (tests, clearing). */
uint32_t silk_fb_pixel(const silk_fb_info *info, uint32_t rgb);

/* Fill the visible screen with one colour. */
void silk_fb_fill(silk_fb *fb, uint32_t rgb);

#endif
