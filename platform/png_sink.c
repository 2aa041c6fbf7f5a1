/*
 * png_sink.c - write a render target as an 8-bit RGB PNG through libpng,
 * or as RGBA with an alpha channel the caller gives (the object's coverage).
 *
 * libpng reports errors by longjmp; the handler below keeps its message so
 * the caller gets one line ("out.png: cannot write: libpng: Write Error")
 * and the temporary file is removed, never a half-written PNG left behind.
 */
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <png.h>

#include "platform.h"

typedef struct png_sink_ctx {
    char msg[120];
} png_sink_ctx;

static void on_png_error(png_structp png, png_const_charp msg)
{
    png_sink_ctx *ctx = png_get_error_ptr(png);
    if (ctx) {
        strncpy(ctx->msg, msg ? msg : "unknown error", sizeof ctx->msg - 1);
        ctx->msg[sizeof ctx->msg - 1] = 0;
    }
    png_longjmp(png, 1);
}

/* Warnings are not failures; the tool prints nothing for them. */
static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* The libpng part, separate so that nothing the caller owns is live across
 * setjmp except through the arguments. */
static int write_png_stream(FILE *fp, const silk_target *t, const uint8_t *alpha, uint8_t *row, png_sink_ctx *ctx)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, on_png_error, on_png_warning);
    if (!png) {
        strcpy(ctx->msg, "cannot initialise libpng");
        return 0;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        strcpy(ctx->msg, "cannot initialise libpng");
        return 0;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return 0;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)t->width, (png_uint_32)t->height, 8,
                 alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < t->height; y++) {
        if (alpha) {
            /* RGB widened in place from the back, so row holds 4 bytes a pixel */
            const uint8_t *a = alpha + (size_t)y * (size_t)t->width;
            silk_target_row_rgb888(t, y, row);
            for (int x = t->width - 1; x >= 0; x--) {
                size_t i = (size_t)x;
                row[4 * i + 3] = a[i];
                row[4 * i + 2] = row[3 * i + 2];
                row[4 * i + 1] = row[3 * i + 1];
                row[4 * i + 0] = row[3 * i + 0];
            }
            png_write_row(png, row);
        } else if (t->fmt == SILK_PIX_RGB888) {
            png_write_row(png, t->color + (size_t)y * t->stride);
        } else {
            silk_target_row_rgb888(t, y, row);
            png_write_row(png, row);
        }
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 1;
}

static silk_status png_write(const silk_target *t, const uint8_t *alpha, const char *path, silk_error *err)
{
    silk_status s = silk_image_check_target(t, path, err);
    if (s != SILK_OK) return s;
    if ((png_uint_32)t->width > PNG_UINT_31_MAX || (png_uint_32)t->height > PNG_UINT_31_MAX)
        return silk_fail(err, SILK_ERR_ARG, path, 0, "image too large for PNG");
    uint8_t *row = malloc((size_t)t->width * 4);
    if (!row) return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory");

    silk_outfile o;
    s = silk_outfile_open(&o, path, err);
    if (s == SILK_OK) {
        png_sink_ctx ctx = { { 0 } };
        if (write_png_stream(o.fp, t, alpha, row, &ctx)) {
            s = silk_outfile_commit(&o, err);
        } else {
            silk_outfile_abort(&o);
            s = silk_fail(err, SILK_ERR_IO, o.path, 0, "cannot write: libpng: %s", ctx.msg);
        }
    }
    free(row);
    return s;
}

silk_status silk_png_write(const silk_target *t, const char *path, silk_error *err)
{
    return png_write(t, NULL, path, err);
}

silk_status silk_png_write_alpha(const silk_target *t, const uint8_t *alpha, const char *path, silk_error *err)
{
    return png_write(t, alpha, path, err);
}
