/*
 * png_read.c - PNG to 8-bit RGB through libpng's simplified API (which
 * reports errors in the image struct, so no setjmp is needed here), and
 * silk_image_read, which tells PNG from PPM (platform/ppm_read.c).
 *
 * The file is read whole with silk_file_read first, so a missing or
 * unreadable file gets the same message as a missing mesh.
 */
#include <stdlib.h>
#include <string.h>
#include <png.h>

#include "platform.h"
#include "png_read.h"

static const uint8_t png_magic[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };

static silk_status png_decode(const uint8_t *data, size_t len, const char *path, uint32_t bg_rgb, uint8_t **rgb,
                              int *width, int *height, silk_error *err)
{
    silk_status s;
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&img, data, len)) {
        s = silk_fail(err, SILK_ERR_PARSE, path, 0, "cannot read: libpng: %s", img.message);
        png_image_free(&img);
        return s;
    }
    if ((uint64_t)img.width * img.height > SILK_PNG_READ_MAX_PIXELS) {
        s = silk_fail(err, SILK_ERR_RANGE, path, 0, "image of %ux%u pixels is too large (at most %llu pixels)",
                      (unsigned)img.width, (unsigned)img.height, (unsigned long long)SILK_PNG_READ_MAX_PIXELS);
        png_image_free(&img);
        return s;
    }
    img.format = PNG_FORMAT_RGB;
    size_t bytes = (size_t)img.width * img.height * 3;
    uint8_t *out = malloc(bytes ? bytes : 1);
    if (!out) {
        png_image_free(&img);
        return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory for a %ux%u image", (unsigned)img.width,
                         (unsigned)img.height);
    }
    png_color bg = { (png_byte)(bg_rgb >> 16), (png_byte)(bg_rgb >> 8), (png_byte)bg_rgb };
    if (!png_image_finish_read(&img, &bg, out, 0, NULL)) {
        s = silk_fail(err, SILK_ERR_PARSE, path, 0, "cannot read: libpng: %s", img.message);
        png_image_free(&img);
        free(out);
        return s;
    }
    *rgb = out;
    *width = (int)img.width;
    *height = (int)img.height;
    png_image_free(&img);
    return SILK_OK;
}

silk_status silk_image_read(const char *path, uint32_t bg_rgb, uint8_t **rgb, int *width, int *height,
                            silk_error *err)
{
    *rgb = NULL;
    *width = *height = 0;
    uint8_t *data;
    size_t len;
    silk_status s = silk_file_read(path, &data, &len, err);
    if (s != SILK_OK) return s;
    s = silk_image_decode(data, len, silk_path_is_stdio(path) ? SILK_STDIN_NAME : path, bg_rgb, rgb, width, height,
                          err);
    free(data);
    return s;
}

silk_status silk_image_decode(const uint8_t *data, size_t len, const char *name, uint32_t bg_rgb, uint8_t **rgb,
                              int *width, int *height, silk_error *err)
{
    *rgb = NULL;
    *width = *height = 0;
    if (len >= sizeof png_magic && memcmp(data, png_magic, sizeof png_magic) == 0)
        return png_decode(data, len, name, bg_rgb, rgb, width, height, err);
    if (len >= 2 && data[0] == 'P' && data[1] == '6') return silk_ppm_parse(data, len, name, rgb, width, height, err);
    return silk_fail(err, SILK_ERR_PARSE, name, 0, "not a PNG or binary PPM image");
}

silk_status silk_png_read(const char *path, uint8_t **rgb, int *width, int *height, silk_error *err)
{
    *rgb = NULL;
    *width = *height = 0;
    uint8_t *data;
    size_t len;
    silk_status s = silk_file_read(path, &data, &len, err);
    if (s != SILK_OK) return s;
    const char *name = silk_path_is_stdio(path) ? SILK_STDIN_NAME : path;
    if (len < sizeof png_magic || memcmp(data, png_magic, sizeof png_magic) != 0)
        s = silk_fail(err, SILK_ERR_PARSE, name, 0, "not a PNG file");
    else
        s = png_decode(data, len, name, 0, rgb, width, height, err);   /* alpha onto black */
    free(data);
    return s;
}
