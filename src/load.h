/*
 * load.h - internal: what the OBJ and PLY readers share (implemented in
 * load.c).  Not installed.
 *
 * Every coordinate a reader finds goes through silk_ld_coord(): it is scaled
 * by the user's --scale as a decimal, rounded once to Q16.16, and recorded in
 * an exact decimal bounding box, so that a model outside the fixed-point
 * range (or too small for it) is reported with a --scale that fixes it.
 */
#ifndef SILK_LOAD_H
#define SILK_LOAD_H

#include <stddef.h>
#include <stdint.h>
#include "silk/silk.h"

/* Longest text line either reader accepts; longer means "not a text file". */
#define SILK_LD_MAX_LINE 65535
/* Longest single number; longer text is refused rather than truncated. */
#define SILK_LD_MAX_TOKEN 128

typedef struct silk_ld_coords {
    silk_decimal scale;
    int unit_scale;              /* scale is exactly 1: binary floats may round directly */
    uint32_t count;              /* coordinates seen */
    unsigned have;               /* bit i: axis i has been seen */
    silk_decimal lo[3], hi[3];   /* bounding box of the raw (unscaled) coordinates */
    /* the first coordinate outside +-SILK_COORD_MAX, reported by silk_ld_coords_finish */
    int bad;
    uint32_t bad_line, bad_vertex;
    silk_decimal bad_value;      /* scaled */
} silk_ld_coords;

void silk_ld_coords_init(silk_ld_coords *c, const silk_load_opts *o);

/* Scale, round and record one coordinate (axis 0..2) of vertex `vertex` on
 * text line `line` (0 for binary input).  exact, if not NULL, is the value
 * already correctly rounded to Q16.16 from its binary form (used only when
 * the scale is 1).  An out-of-range value gives *out = 0 and is remembered;
 * the caller goes on, and silk_ld_coords_finish() reports it. */
void silk_ld_coord(silk_ld_coords *c, silk_decimal raw, const silk_fx *exact, int axis,
                   uint32_t line, uint32_t vertex, silk_fx *out);

/* After all vertices: the first out-of-range coordinate, or a model too
 * small for Q16.16, as one message with the --scale that fixes it. */
silk_status silk_ld_coords_finish(const silk_ld_coords *c, const char *name, silk_error *err);

/* A direction (file normal) as Q16.16: its three components are scaled by a
 * common power of ten until they fit, so only the direction survives.
 * Returns 0, or -1 for the zero vector (which the caller may accept). */
int silk_ld_direction(const silk_decimal d[3], silk_vec3 *out);

/* A vertex colour channel as 0..255: a value in [0, 1] (max 1) or an
 * integer in [0, 255] (max 255), rounded.  Returns -1 outside the range. */
int silk_ld_color_channel(silk_decimal d, int max, uint32_t *out);

/* An IEEE-754 binary32 / binary64 bit pattern as a decimal (at most 18
 * digits), and, when it fits, correctly rounded to Q16.16 (*fits = 0 when
 * |v| >= 32768).  Integer arithmetic only.  Returns -1 for NaN or infinity. */
int silk_ld_from_f32(uint32_t bits, silk_decimal *d, silk_fx *fx, int *fits);
int silk_ld_from_f64(uint64_t bits, silk_decimal *d, silk_fx *fx, int *fits);

/* Decimal helpers. */
int silk_ld_dec_cmp(silk_decimal a, silk_decimal b);          /* -1, 0, 1 */
/* Up to `sig` significant digits, "5000.0", "0.001", "1.5e+30". */
char *silk_ld_dec_format(silk_decimal d, int sig, char *buf, size_t n);

/* Where a text reader is: the rest of the buffer, the line last read (for
 * messages), the file's name and the error to fill. */
typedef struct silk_ld_text {
    const char *p, *end;
    uint32_t line;
    const char *name;
    silk_error *err;
} silk_ld_text;

/* Next whitespace-separated token of the text [*p, e) as [*tb, *tb + *tn);
 * a token starting with '#' comments out the rest.  Returns 0 at the end. */
int silk_ld_token(const char **p, const char *e, const char **tb, size_t *tn);
int silk_ld_token_is(const char *t, size_t n, const char *word);
/* A decimal number token (not NUL-terminated).  Returns SILK_OK, or an
 * error naming the token: "bad number 'abc'", "'nan' is not a finite number". */
silk_status silk_ld_parse_decimal(const char *t, size_t n, silk_decimal *d,
                                  const char *name, uint32_t line, silk_error *err);

/* Quote at most 32 bytes of a token for an error message. */
const char *silk_ld_quote(const char *s, size_t n, char *buf, size_t bufsize);

/* STL (stl.c): whether the buffer has exactly the size of the binary STL
 * its header describes (84 + 50 n bytes), and whether a byte may appear in
 * a text file (the mesh readers' test for binary data). */
int silk_ld_stl_binary_size(const void *data, size_t len);
/* Whether the buffer starts (after blanks) with the keyword "solid". */
int silk_ld_stl_solid(const void *data, size_t len);
int silk_ld_text_byte(unsigned char ch);

/* What every reader checks first: a name ("mesh" for NULL), options (the
 * defaults, in *defaults, for NULL), a buffer, an arena and an output
 * (fn names the reader in that error), a positive scale.  Clears *out. */
silk_status silk_ld_start(const char *fn, const void *data, size_t len, const char **name,
                          const silk_load_opts **opts, silk_load_opts *defaults, silk_arena *a, silk_mesh *out,
                          silk_error *err);

/* Arena bytes an array of count*size takes (aligned), added to *total with
 * overflow check.  Returns 0 on overflow. */
int silk_ld_need(size_t *total, uint64_t count, size_t size);
/* Undo every allocation made since `saved` was copied from *a: a failed load
 * leaves the arena as it found it. */
void silk_ld_arena_restore(silk_arena *a, const silk_arena *saved);
silk_status silk_ld_nomem(silk_error *err, const char *name, size_t need, const silk_arena *a);

#endif
