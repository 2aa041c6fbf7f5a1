/*
 * ppm_sink.c - write a render target as binary PPM (P6, 8 bits per channel),
 * the image format that needs no library.  Also the pixel-format widening
 * both sinks share.
 */
#include <stdlib.h>

#include "platform.h"

void silk_target_row_rgb888(const silk_target *t, int y, uint8_t *out)
{
    const uint8_t *p = t->color + (size_t)y * t->stride;
    if (t->fmt == SILK_PIX_RGB888) {
        for (size_t i = 0; i < (size_t)t->width * 3; i++) out[i] = p[i];
        return;
    }
    for (int x = 0; x < t->width; x++, p += 2, out += 3) {
        unsigned v = (unsigned)p[0] | (unsigned)p[1] << 8;
        unsigned r = v >> 11, g = (v >> 5) & 63u, b = v & 31u;
        /* Bit replication maps full scale to 255 exactly, unlike a shift. */
        out[0] = (uint8_t)(r << 3 | r >> 2);
        out[1] = (uint8_t)(g << 2 | g >> 4);
        out[2] = (uint8_t)(b << 3 | b >> 2);
    }
}

silk_status silk_image_check_target(const silk_target *t, const char *path, silk_error *err)
{
    if (!t || !t->color || t->width < 1 || t->height < 1)
        return silk_fail(err, SILK_ERR_ARG, path, 0, "no image to write");
    if (t->y0 != 0 || t->rows != t->height)
        return silk_fail(err, SILK_ERR_ARG, path, 0, "image writers need the full frame (band %d+%d of %d rows)",
                         t->y0, t->rows, t->height);
    if (t->fmt != SILK_PIX_RGB888 && t->fmt != SILK_PIX_RGB565)
        return silk_fail(err, SILK_ERR_ARG, path, 0, "unknown pixel format %d", (int)t->fmt);
    return SILK_OK;
}

silk_status silk_ppm_write(const silk_target *t, const char *path, silk_error *err)
{
    silk_status s = silk_image_check_target(t, path, err);
    if (s != SILK_OK) return s;
    uint8_t *row = malloc((size_t)t->width * 3);
    if (!row) return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory");

    silk_outfile o;
    s = silk_outfile_open(&o, path, err);
    if (s == SILK_OK) {
        fprintf(o.fp, "P6\n%d %d\n255\n", t->width, t->height);
        for (int y = 0; y < t->height; y++) {
            silk_target_row_rgb888(t, y, row);
            if (fwrite(row, 3, (size_t)t->width, o.fp) != (size_t)t->width) break;
        }
        /* A short fwrite leaves the stream's error flag set; commit reports it. */
        s = silk_outfile_commit(&o, err);
    }
    free(row);
    return s;
}
