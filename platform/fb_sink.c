/*
 * fb_sink.c - render bands straight into a Linux framebuffer (fb.h).
 *
 * Opening reads the geometry and the pixel format (from the device's
 * ioctls, or as given for a file), checks them and maps the screen memory;
 * from there the device and a file-backed framebuffer share every line.
 * Each band's rows are converted pixel by pixel: RGB565 is first widened by
 * bit replication (as the image writers do), then every channel is cut to
 * its field's length and shifted to its offset, so a 16-bit RGB565
 * framebuffer receives the rendered bytes unchanged.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#if defined(__linux__)
#include <linux/fb.h>
#include <sys/ioctl.h>
#endif

#include "fb.h"

/* Largest framebuffer accepted (a 8192x8192 32-bit screen). */
#define FB_MAX_BYTES ((size_t)256 << 20)

silk_status silk_fb_info_default(silk_fb_info *info, int width, int height, int bpp, silk_error *err)
{
    memset(info, 0, sizeof *info);
    if (width < 1 || height < 1 || width > SILK_MAX_DIM || height > SILK_MAX_DIM)
        return silk_fail(err, SILK_ERR_ARG, "framebuffer", 0, "size %dx%d out of range (1..%d)", width, height,
                         SILK_MAX_DIM);
    info->xres = info->xres_virtual = (uint32_t)width;
    info->yres = info->yres_virtual = (uint32_t)height;
    info->bits_per_pixel = (uint32_t)bpp;
    info->line_length = (uint32_t)width * (uint32_t)(bpp / 8);
    if (bpp == 16) {
        info->red = (silk_fb_field){ 11, 5 };
        info->green = (silk_fb_field){ 5, 6 };
        info->blue = (silk_fb_field){ 0, 5 };
    } else if (bpp == 24 || bpp == 32) {
        info->red = (silk_fb_field){ 16, 8 };
        info->green = (silk_fb_field){ 8, 8 };
        info->blue = (silk_fb_field){ 0, 8 };
    } else {
        return silk_fail(err, SILK_ERR_ARG, "framebuffer", 0, "%d bits per pixel not supported (16, 24 or 32)", bpp);
    }
    return SILK_OK;
}

static int field_ok(const silk_fb_field *f, uint32_t bpp)
{
    return f->length >= 1 && f->length <= 8 && f->offset < bpp && f->offset + f->length <= bpp;
}

/* Everything the sink relies on, checked once so band writes need no checks. */
static silk_status check_info(const silk_fb_info *i, const char *name, silk_error *err)
{
    uint32_t bpp = i->bits_per_pixel;
    if (bpp != 16 && bpp != 24 && bpp != 32)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "%u bits per pixel not supported (16, 24 or 32)", bpp);
    if (!field_ok(&i->red, bpp) || !field_ok(&i->green, bpp) || !field_ok(&i->blue, bpp))
        return silk_fail(err, SILK_ERR_ARG, name, 0, "unsupported pixel layout (red %u/%u green %u/%u blue %u/%u)",
                         i->red.offset, i->red.length, i->green.offset, i->green.length, i->blue.offset,
                         i->blue.length);
    if (i->xres < 1 || i->yres < 1 || i->xres > SILK_MAX_DIM || i->yres > SILK_MAX_DIM)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "screen size %ux%u out of range", i->xres, i->yres);
    if (i->xoffset > i->xres_virtual || i->xres > i->xres_virtual - i->xoffset || i->yoffset > i->yres_virtual ||
        i->yres > i->yres_virtual - i->yoffset)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "visible area %ux%u+%u+%u outside the virtual %ux%u", i->xres,
                         i->yres, i->xoffset, i->yoffset, i->xres_virtual, i->yres_virtual);
    if ((uint64_t)i->line_length < (uint64_t)i->xres_virtual * (bpp / 8))
        return silk_fail(err, SILK_ERR_ARG, name, 0, "line length %u shorter than %u pixels", i->line_length,
                         i->xres_virtual);
    if ((uint64_t)i->line_length * i->yres_virtual > FB_MAX_BYTES)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "framebuffer larger than %zu bytes", FB_MAX_BYTES);
    return SILK_OK;
}

/* The shared second half of both opens: check, size, map. */
static silk_status fb_map(silk_fb *fb, const silk_fb_info *info, silk_error *err)
{
    silk_status st = check_info(info, fb->name, err);
    if (st != SILK_OK) return st;
    fb->info = *info;
    fb->mem_len = (size_t)info->line_length * info->yres_virtual;
    void *p = mmap(NULL, fb->mem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fb->fd, 0);
    if (p == MAP_FAILED) return silk_fail(err, SILK_ERR_IO, fb->name, 0, "cannot map: %s", strerror(errno));
    fb->mem = p;
    return SILK_OK;
}

static void fb_reset(silk_fb *fb, const char *name)
{
    memset(fb, 0, sizeof *fb);
    fb->fd = -1;
    snprintf(fb->name, sizeof fb->name, "%s", name);
}

static silk_status fail_closed(silk_fb *fb, silk_status st)
{
    silk_fb_close(fb, NULL);
    return st;
}

silk_status silk_fb_open(silk_fb *fb, const char *device, silk_error *err)
{
    fb_reset(fb, device);
#if defined(__linux__)
    fb->fd = open(device, O_RDWR);
    if (fb->fd < 0) return silk_fail(err, SILK_ERR_IO, device, 0, "cannot open: %s", strerror(errno));
    struct fb_var_screeninfo var;
    struct fb_fix_screeninfo fix;
    if (ioctl(fb->fd, FBIOGET_VSCREENINFO, &var) != 0 || ioctl(fb->fd, FBIOGET_FSCREENINFO, &fix) != 0)
        return fail_closed(fb, silk_fail(err, SILK_ERR_IO, device, 0, "not a framebuffer: %s", strerror(errno)));
    if (fix.type != FB_TYPE_PACKED_PIXELS || fix.visual != FB_VISUAL_TRUECOLOR)
        return fail_closed(fb, silk_fail(err, SILK_ERR_ARG, device, 0,
                                         "not a packed true-colour framebuffer (type %u, visual %u)", fix.type,
                                         fix.visual));
    silk_fb_info info = {
        .xres = var.xres, .yres = var.yres, .xres_virtual = var.xres_virtual, .yres_virtual = var.yres_virtual,
        .xoffset = var.xoffset, .yoffset = var.yoffset, .bits_per_pixel = var.bits_per_pixel,
        .line_length = fix.line_length, .red = { var.red.offset, var.red.length },
        .green = { var.green.offset, var.green.length }, .blue = { var.blue.offset, var.blue.length },
    };
    /* The driver may map less than the virtual screen (smem_len). */
    if ((uint64_t)info.line_length * info.yres_virtual > fix.smem_len && info.line_length)
        info.yres_virtual = fix.smem_len / info.line_length;
    silk_status st = fb_map(fb, &info, err);
    return st == SILK_OK ? st : fail_closed(fb, st);
#else
    return silk_fail(err, SILK_ERR_IO, device, 0, "framebuffer devices need Linux (use a file-backed framebuffer)");
#endif
}

silk_status silk_fb_open_file(silk_fb *fb, const char *path, const silk_fb_info *info, silk_error *err)
{
    fb_reset(fb, path);
    silk_status st = check_info(info, path, err);
    if (st != SILK_OK) return st;
    fb->fd = open(path, O_RDWR | O_CREAT | O_TRUNC, 0644);
    if (fb->fd < 0) return silk_fail(err, SILK_ERR_IO, path, 0, "cannot create: %s", strerror(errno));
    /* ftruncate zero-fills: a black screen, as a device starts. */
    if (ftruncate(fb->fd, (off_t)((size_t)info->line_length * info->yres_virtual)) != 0)
        return fail_closed(fb, silk_fail(err, SILK_ERR_IO, path, 0, "cannot size: %s", strerror(errno)));
    fb->file_backed = 1;
    st = fb_map(fb, info, err);
    return st == SILK_OK ? st : fail_closed(fb, st);
}

silk_status silk_fb_close(silk_fb *fb, silk_error *err)
{
    silk_status st = SILK_OK;
    if (fb->mem) {
        /* A device shows what was stored; a file needs writing back. */
        if (fb->file_backed && msync(fb->mem, fb->mem_len, MS_SYNC) != 0)
            st = silk_fail(err, SILK_ERR_IO, fb->name, 0, "cannot write back: %s", strerror(errno));
        munmap(fb->mem, fb->mem_len);
    }
    if (fb->fd >= 0 && close(fb->fd) != 0 && st == SILK_OK)
        st = silk_fail(err, SILK_ERR_IO, fb->name, 0, "close failed: %s", strerror(errno));
    fb->mem = NULL;
    fb->fd = -1;
    return st;
}

static uint32_t channel(uint32_t v8, const silk_fb_field *f)
{
    return (v8 >> (8 - f->length)) << f->offset;
}

uint32_t silk_fb_pixel(const silk_fb_info *info, uint32_t rgb)
{
    return channel((rgb >> 16) & 255u, &info->red) | channel((rgb >> 8) & 255u, &info->green) |
           channel(rgb & 255u, &info->blue);
}

static void store(uint8_t *p, uint32_t v, uint32_t bytes)
{
    /* Framebuffers are little-endian on every Linux machine that has one. */
    for (uint32_t k = 0; k < bytes; k++) p[k] = (uint8_t)(v >> (8 * k));
}

/* The address of visible pixel (x, y). */
static uint8_t *at(const silk_fb *fb, uint32_t x, uint32_t y)
{
    const silk_fb_info *i = &fb->info;
    return fb->mem + (size_t)(y + i->yoffset) * i->line_length + (size_t)(x + i->xoffset) * (i->bits_per_pixel / 8);
}

void silk_fb_fill(silk_fb *fb, uint32_t rgb)
{
    if (!fb->mem) return;
    uint32_t v = silk_fb_pixel(&fb->info, rgb), bytes = fb->info.bits_per_pixel / 8;
    for (uint32_t y = 0; y < fb->info.yres; y++)
        for (uint32_t x = 0; x < fb->info.xres; x++) store(at(fb, x, y), v, bytes);
}

/* Pixel x of a band row as 0xRRGGBB. */
static uint32_t band_rgb(const silk_target *t, const uint8_t *row, int x)
{
    if (t->fmt == SILK_PIX_RGB888) {
        const uint8_t *p = row + 3 * (size_t)x;
        return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
    }
    const uint8_t *p = row + 2 * (size_t)x;
    uint32_t v = (uint32_t)p[0] | (uint32_t)p[1] << 8;
    uint32_t r = v >> 11, g = (v >> 5) & 63u, b = v & 31u;
    return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 | (b << 3 | b >> 2);
}

int silk_fb_band(void *user, const silk_target *band)
{
    silk_fb *fb = user;
    if (!fb->mem || !band->color) return 0;
    const silk_fb_info *i = &fb->info;
    uint32_t bytes = i->bits_per_pixel / 8;
    for (int r = 0; r < band->rows; r++) {
        int64_t sy = (int64_t)fb->origin_y + band->y0 + r;
        if (band->y0 + r >= band->height || sy < 0 || sy >= (int64_t)i->yres) continue;
        const uint8_t *row = band->color + (size_t)r * band->stride;
        for (int x = 0; x < band->width; x++) {
            int64_t sx = (int64_t)fb->origin_x + x;
            if (sx < 0 || sx >= (int64_t)i->xres) continue;
            store(at(fb, (uint32_t)sx, (uint32_t)sy), silk_fb_pixel(i, band_rgb(band, row, x)), bytes);
        }
    }
    fb->bands++;
    return 0;
}
