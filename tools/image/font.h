/*
 * font.h - a 5x7 bitmap font for labels in the pictures the silk tool
 * draws (bar charts, contact sheets).  Printable ASCII; each glyph sits in
 * a 6x8 cell (one column and one row of spacing).  Host-side, drawn into a
 * silk_target so it works in any pixel format.
 */
#ifndef SILK_TOOLS_FONT_H
#define SILK_TOOLS_FONT_H

#include <stdint.h>
#include "silk/raster.h"

#define FONT_W 5              /* glyph width in pixels */
#define FONT_H 7              /* glyph height */
#define FONT_ADVANCE 6        /* cell width: glyph plus one column of space */
#define FONT_LINE 9           /* line height */

/* The 7 rows of the glyph for c, top first, bit 4 the leftmost pixel;
 * characters outside printable ASCII give the glyph of '?'. */
const uint8_t *font_glyph(char c);

/* Width in pixels of s drawn at the given scale (no trailing space). */
int font_text_width(const char *s, int scale);

/* Draw s with its top-left corner at (x, y), every font pixel a scale x
 * scale square of colour rgb; pixels outside the target are skipped.
 * Newlines start a new line.  font_draw_up turns the text 90 degrees
 * counter-clockwise (reading upwards, for y-axis labels); (x, y) is then
 * the bottom-left corner of the text. */
void font_draw(silk_target *t, int x, int y, const char *s, uint32_t rgb, int scale);
void font_draw_up(silk_target *t, int x, int y, const char *s, uint32_t rgb, int scale);

#endif
