/*
 * silk/platform.h - host-side I/O around the core (libsilk_platform.a):
 * reading a whole file, writing an output atomically, and images: the PNG
 * (libpng) and binary PPM writers of a silk_target, and a PNG reader.  Not
 * part of the core: this code uses stdio, malloc and POSIX, so a device
 * port replaces it rather than links it.  `make install` installs it with
 * the library; `pkg-config --cflags --libs silk-platform` gives the flags
 * (the core's and libpng's included).
 *
 * Errors are reported like the core's: a silk_error whose message names the
 * file, e.g. "x.obj: cannot open: No such file or directory".
 */
#ifndef SILK_PLATFORM_H
#define SILK_PLATFORM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "silk/error.h"
#include "silk/raster.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest file silk_file_read accepts (meshes are read whole into memory). */
#define SILK_FILE_MAX ((size_t)1 << 30)

/* "-" stands for standard input where a file is read and for standard
 * output where one is written; messages then name them as below. */
#define SILK_STDIN_NAME "<stdin>"
#define SILK_STDOUT_NAME "<stdout>"
int silk_path_is_stdio(const char *path);

/* Read the whole file into a malloc'd buffer (free it with free()).  The
 * buffer has one extra NUL byte after the data, not counted in *len.  "-"
 * reads standard input to its end. */
silk_status silk_file_read(const char *path, uint8_t **data, size_t *len, silk_error *err);

/* The same for a file a model names (an OBJ's mtllib and map_Kd): read
 * only when it is a regular file (never a device, a pipe or a directory,
 * which could block or never end; opened without waiting for a writer) of
 * at most max bytes, checked before reading.  SILK_ERR_IO "PATH: not a
 * regular file" / "PATH: N bytes, more than MAX" otherwise. */
silk_status silk_file_read_regular(const char *path, size_t max, uint8_t **data, size_t *len, silk_error *err);

/* An output written atomically: the data goes to "PATH.tmpXXXXXX" in the
 * same directory, which replaces PATH by rename() only once everything was
 * written and flushed.  Until then PATH is untouched, and on any failure the
 * temporary file is removed, so a reader never sees a partial file. */
typedef struct silk_outfile {
    FILE *fp;              /* write here between open and commit */
    const char *path;      /* the final name (not copied: keep it alive) */
    char *tmp;             /* the temporary name; NULL when none exists */
    int direct;            /* writing straight to PATH: standard output, or a device or pipe */
} silk_outfile;

/* PATH "-" writes to standard output, and an existing PATH that is not a
 * regular file (/dev/null, a pipe) is written as it is: no temporary file
 * (a rename would replace the device), commit flushes. */
silk_status silk_outfile_open(silk_outfile *o, const char *path, silk_error *err);
/* Flush, sync, close and rename into place.  On failure the temporary file
 * is removed and PATH is left as it was. */
silk_status silk_outfile_commit(silk_outfile *o, silk_error *err);
/* Close and remove the temporary file; harmless after commit or twice. */
void silk_outfile_abort(silk_outfile *o);

/* Remove PATH if it is a regular file (never a directory, a device or "-"): the
 * tool removes the frames a failed series wrote this way.  Returns 1 if a
 * file was removed. */
int silk_file_remove_stale(const char *path);

/* 1 if both paths name the same existing file (device and inode). */
int silk_file_same(const char *a, const char *b);

/* ---- images ---------------------------------------------------------------- */

typedef enum silk_image_format {
    SILK_IMAGE_NONE = 0,   /* not a known image extension */
    SILK_IMAGE_PNG,
    SILK_IMAGE_PPM
} silk_image_format;

/* From the extension of path, case-insensitive: ".png" or ".ppm". */
silk_image_format silk_image_format_for_path(const char *path);

/* Row y (0-based, within the target's band) of t as 8-bit R, G, B triples
 * (3 * t->width bytes); RGB565 is widened by bit replication, so 0x1f maps
 * to 0xff and 0 to 0. */
void silk_target_row_rgb888(const silk_target *t, int y, uint8_t *out);

/* What both sinks check before creating anything: a full frame in a known
 * pixel format. */
silk_status silk_image_check_target(const silk_target *t, const char *path, silk_error *err);

/* Write a full-frame target (y0 == 0, rows == height) atomically. */
silk_status silk_png_write(const silk_target *t, const char *path, silk_error *err);
silk_status silk_ppm_write(const silk_target *t, const char *path, silk_error *err);
/* A PNG with an alpha channel: alpha[y * width + x] for each pixel. */
silk_status silk_png_write_alpha(const silk_target *t, const uint8_t *alpha, const char *path, silk_error *err);
/* PNG or PPM by the extension of path; any other extension is an error. */
silk_status silk_image_write(const silk_target *t, const char *path, silk_error *err);
/* The same in the format given (for "-", which has no extension). */
silk_status silk_image_write_as(const silk_target *t, const char *path, silk_image_format fmt, silk_error *err);

/* ---- reading images ---------------------------------------------------------- */

/* Largest image silk_png_read and silk_image_read accept, in pixels (a
 * 16384 x 16384 frame). */
#define SILK_PNG_READ_MAX_PIXELS ((uint64_t)1 << 28)

/* Read path into a malloc'd buffer of width*height R, G, B bytes, rows top
 * to bottom (free it with free()).  Grey, palette and 16-bit images are
 * converted; an alpha channel is composited onto black.  Errors name the
 * file: "a.png: not a PNG file", "a.png: cannot read: libpng: ...". */
silk_status silk_png_read(const char *path, uint8_t **rgb, int *width, int *height, silk_error *err);

/* PNG or binary PPM (P6, maxval up to 255, scaled to 255), told apart by
 * their first bytes; "-" reads standard input.  Alpha is composited onto
 * bg_rgb (0xRRGGBB), so a transparent background reads as that colour.
 * Errors name the file: "a.png: not a PNG or binary PPM image". */
silk_status silk_image_read(const char *path, uint32_t bg_rgb, uint8_t **rgb, int *width, int *height,
                            silk_error *err);
/* The same on a file's bytes in memory (name for messages). */
silk_status silk_image_decode(const uint8_t *data, size_t len, const char *name, uint32_t bg_rgb, uint8_t **rgb,
                              int *width, int *height, silk_error *err);

/* The PPM part on bytes in memory (name for messages; platform/ppm_read.c,
 * which needs no libpng). */
silk_status silk_ppm_parse(const uint8_t *data, size_t len, const char *name, uint8_t **rgb, int *width,
                           int *height, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
