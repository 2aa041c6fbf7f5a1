/*
 * ppm_read.c - binary PPM (netpbm's P6) from memory into 8-bit RGB: a text
 * header "P6 WIDTH HEIGHT MAXVAL" (blanks and # comments between the
 * fields, one blank after the last), then WIDTH*HEIGHT*3 bytes.  No libpng,
 * so fuzz/fuzz_ppm.c builds it with the core alone.
 */
#include <stdlib.h>

#include "png_read.h"

/* A header number: blanks and # comments before it, then decimal digits. */
static int ppm_number(const uint8_t *d, size_t len, size_t *i, unsigned long *out)
{
    for (;;) {
        while (*i < len && (d[*i] == ' ' || d[*i] == '\t' || d[*i] == '\n' || d[*i] == '\r')) ++*i;
        if (*i < len && d[*i] == '#') {
            while (*i < len && d[*i] != '\n') ++*i;
            continue;
        }
        break;
    }
    if (*i >= len || d[*i] < '0' || d[*i] > '9') return -1;
    unsigned long v = 0;
    while (*i < len && d[*i] >= '0' && d[*i] <= '9') {
        v = v * 10 + (unsigned long)(d[*i] - '0');
        if (v > 1000000) return -1;
        ++*i;
    }
    *out = v;
    return 0;
}

silk_status silk_ppm_parse(const uint8_t *data, size_t len, const char *name, uint8_t **rgb, int *width,
                           int *height, silk_error *err)
{
    *rgb = NULL;
    *width = *height = 0;
    if (len < 2 || data[0] != 'P' || data[1] != '6')
        return silk_fail(err, SILK_ERR_PARSE, name, 0, "not a binary PPM file (P6)");
    size_t i = 2;
    unsigned long w, h, maxval;
    if (ppm_number(data, len, &i, &w) || ppm_number(data, len, &i, &h) || ppm_number(data, len, &i, &maxval))
        return silk_fail(err, SILK_ERR_PARSE, name, 0, "PPM header is not \"P6 WIDTH HEIGHT MAXVAL\"");
    if (w < 1 || h < 1 || (uint64_t)w * h > SILK_PNG_READ_MAX_PIXELS)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "PPM of %lux%lu pixels: width and height must be positive "
                         "and the image at most %llu pixels", w, h, (unsigned long long)SILK_PNG_READ_MAX_PIXELS);
    if (maxval < 1 || maxval > 255)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "PPM maxval %lu: only 8-bit PPM (maxval 1..255) is read",
                         maxval);
    if (i >= len || !(data[i] == ' ' || data[i] == '\t' || data[i] == '\n' || data[i] == '\r'))
        return silk_fail(err, SILK_ERR_PARSE, name, 0, "PPM header must end with one blank before the pixels");
    i++;
    size_t bytes = (size_t)w * h * 3;
    if (len - i < bytes)
        return silk_fail(err, SILK_ERR_PARSE, name, 0, "PPM of %lux%lu pixels is cut short (%zu of %zu pixel bytes)",
                         w, h, len - i, bytes);
    uint8_t *out = malloc(bytes);
    if (!out) return silk_fail(err, SILK_ERR_IO, name, 0, "out of memory for a %lux%lu image", w, h);
    for (size_t k = 0; k < bytes; k++) {
        unsigned v = data[i + k];
        if (v > maxval) {
            free(out);
            return silk_fail(err, SILK_ERR_PARSE, name, 0, "PPM sample %u is above maxval %lu", v, maxval);
        }
        out[k] = (uint8_t)(maxval == 255 ? v : (v * 255 + maxval / 2) / maxval);
    }
    *rgb = out;
    *width = (int)w;
    *height = (int)h;
    return SILK_OK;
}

