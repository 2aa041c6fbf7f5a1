/*
 * png_read.c - PNG to 8-bit RGB through libpng's simplified API (which
 * reports errors in the image struct, so no setjmp is needed here).
 *
 * The file is read whole with silk_file_read first, so a missing or
 * unreadable file gets the same message as a missing mesh.
 */
#include <stdlib.h>
#include <string.h>
#include <png.h>

#include "platform.h"
#include "png_read.h"

silk_status silk_png_read(const char *path, uint8_t **rgb, int *width, int *height, silk_error *err)
{
    *rgb = NULL;
    *width = *height = 0;
    uint8_t *data;
    size_t len;
    silk_status s = silk_file_read(path, &data, &len, err);
    if (s != SILK_OK) return s;

    static const uint8_t magic[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    if (len < sizeof magic || memcmp(data, magic, sizeof magic) != 0) {
        free(data);
        return silk_fail(err, SILK_ERR_PARSE, path, 0, "not a PNG file");
    }

    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&img, data, len)) {
        s = silk_fail(err, SILK_ERR_PARSE, path, 0, "cannot read: libpng: %s", img.message);
        png_image_free(&img);
        free(data);
        return s;
    }
    if ((uint64_t)img.width * img.height > SILK_PNG_READ_MAX_PIXELS) {
        s = silk_fail(err, SILK_ERR_RANGE, path, 0, "image of %ux%u pixels is too large (at most %llu pixels)",
                      (unsigned)img.width, (unsigned)img.height, (unsigned long long)SILK_PNG_READ_MAX_PIXELS);
        png_image_free(&img);
        free(data);
        return s;
    }
    img.format = PNG_FORMAT_RGB;
    size_t bytes = (size_t)img.width * img.height * 3;
    uint8_t *out = malloc(bytes ? bytes : 1);
    if (!out) {
        png_image_free(&img);
        free(data);
        return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory for a %ux%u image", (unsigned)img.width,
                         (unsigned)img.height);
    }
    /* background NULL: alpha is composited onto black */
    int ok = png_image_finish_read(&img, NULL, out, 0, NULL);
    free(data);
    if (!ok) {
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
