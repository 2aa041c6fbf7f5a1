/*
 * sheet.h - contact sheets: frames of one size laid out in a labelled grid
 * in a single RGB888 image (`silk render --sheet`, `make demo`), and the
 * numbered file names of frame series (`silk render --turntable N -o
 * turn_%03d.png`, the screenshots of `silk view`).  Host-side; labels use
 * the built-in bitmap font (tools/image/font.h).
 */
#ifndef SILK_TOOLS_SHEET_H
#define SILK_TOOLS_SHEET_H

#include <stddef.h>
#include <stdint.h>
#include "silk/error.h"
#include "silk/raster.h"
#include "silk/render.h"

#define SHEET_GAP 6            /* pixels between cells and around the grid */
#define SHEET_LABEL_LINES 2    /* lines of text under each cell */
#define SHEET_MAX_SIDE 16384   /* largest sheet width or height */

typedef struct sheet {
    int cols, rows;            /* the grid */
    int cell_w, cell_h;        /* every frame's size */
    int scale;                 /* font scale: 1, or 2 for cells 240 pixels wide and more */
    int title_h, label_h;      /* pixels for the title line, and under each cell */
    silk_target img;           /* the sheet, RGB888, colour only (malloc'd) */
} sheet;

/* A sheet of cols x rows cells of cell_w x cell_h pixels with title (may be
 * NULL) on top.  Returns 0, or -1 after printing why (too large, out of
 * memory); sheet_free is safe either way. */
int sheet_init(sheet *s, int cols, int rows, int cell_w, int cell_h, const char *title);

/* Copy frame (a full frame of the cell size, any pixel format) into cell
 * (col, row) and write label under it: up to SHEET_LABEL_LINES lines
 * separated by '\n', each cut to the cell's width. */
void sheet_put(sheet *s, int col, int row, const silk_target *frame, const char *label);

void sheet_free(sheet *s);

/* ---- numbered file names ------------------------------------------------------
 *
 * A pattern holds at most one printf-style integer conversion, %d, %i or %u
 * with optional '0' or '-' flag and width ("turn_%03d.png"), and "%%" for a
 * percent sign.  pattern_check returns the number of conversions (0 or 1),
 * or -1 for anything else (%s, two conversions, a lone '%').
 * pattern_path writes the name of frame k into buf, or returns -1 when it
 * does not fit n bytes (or the pattern is bad). */
int pattern_check(const char *pattern);
int pattern_path(const char *pattern, long k, char *buf, size_t n);

#endif
