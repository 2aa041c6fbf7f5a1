/*
 * sheet.c - contact sheets and numbered frame names (see sheet.h).
 *
 * A sheet is a grey page with the frames in a grid, each with its label
 * underneath in the 5x7 font, and a title line on top.  The frames may be
 * RGB565; they are widened to RGB888 row by row as they are copied in.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sheet.h"
#include "font.h"
#include "cli/cli.h"
#include "platform/platform.h"

#define SHEET_BG    0xDCDCDCu
#define SHEET_TEXT  0x202020u
#define SHEET_TITLE 0x000000u

static int cell_x(const sheet *s, int col) { return SHEET_GAP + col * (s->cell_w + SHEET_GAP); }

static int cell_y(const sheet *s, int row)
{
    return SHEET_GAP + s->title_h + row * (s->cell_h + s->label_h + SHEET_GAP);
}

int sheet_init(sheet *s, int cols, int rows, int cell_w, int cell_h, const char *title)
{
    memset(s, 0, sizeof *s);
    if (cols < 1 || rows < 1 || cell_w < 1 || cell_h < 1) return cli_fail(-1, "sheet: no cells");
    s->cols = cols;
    s->rows = rows;
    s->cell_w = cell_w;
    s->cell_h = cell_h;
    /* Labels must stay readable on small cells too: never below the font's
     * own size, doubled once the cells are wide enough for two columns of
     * numbers at that size. */
    s->scale = cell_w >= 240 ? 2 : 1;
    s->title_h = title && *title ? FONT_LINE * s->scale + SHEET_GAP : 0;
    s->label_h = SHEET_LABEL_LINES * FONT_LINE * s->scale + 4;
    long long w = SHEET_GAP + (long long)cols * (cell_w + SHEET_GAP);
    long long h = SHEET_GAP + s->title_h + (long long)rows * (cell_h + s->label_h + SHEET_GAP);
    if (w > SHEET_MAX_SIDE || h > SHEET_MAX_SIDE)
        return cli_fail(-1, "the contact sheet would be %lldx%lld pixels (at most %d a side): use a smaller --size",
                        w, h, SHEET_MAX_SIDE);
    size_t stride = (size_t)w * 3;
    uint8_t *px = malloc(stride * (size_t)h);
    if (!px) return cli_fail(-1, "out of memory for a %lldx%lld contact sheet", w, h);
    silk_target_init(&s->img, (int)w, (int)h, 0, (int)h, SILK_PIX_RGB888, px, NULL);
    silk_target_clear(&s->img, SHEET_BG);
    if (s->title_h) font_draw(&s->img, SHEET_GAP, SHEET_GAP, title, SHEET_TITLE, s->scale);
    return 0;
}

void sheet_put(sheet *s, int col, int row, const silk_target *frame, const char *label)
{
    if (col < 0 || col >= s->cols || row < 0 || row >= s->rows) return;
    int x = cell_x(s, col), y = cell_y(s, row);
    int w = frame->width < s->cell_w ? frame->width : s->cell_w;
    int h = frame->rows < s->cell_h ? frame->rows : s->cell_h;
    uint8_t *line = malloc((size_t)frame->width * 3);
    if (!line) return;
    for (int j = 0; j < h; j++) {
        silk_target_row_rgb888(frame, j, line);
        memcpy(s->img.color + (size_t)(y + j) * s->img.stride + (size_t)x * 3, line, (size_t)w * 3);
    }
    free(line);
    if (!label) return;

    /* Each line cut to what fits under the cell, so that labels never run
     * into the neighbour's. */
    int fit = (s->cell_w + 1) / (FONT_ADVANCE * s->scale);
    const char *p = label;
    for (int n = 0; n < SHEET_LABEL_LINES && *p; n++) {
        size_t len = strcspn(p, "\n");
        char text[256];
        size_t k = len < (size_t)fit ? len : (size_t)fit;
        if (k >= sizeof text) k = sizeof text - 1;
        memcpy(text, p, k);
        text[k] = 0;
        font_draw(&s->img, x, y + s->cell_h + 3 + n * FONT_LINE * s->scale, text, SHEET_TEXT, s->scale);
        p += len;
        if (*p == '\n') p++;
    }
}

void sheet_free(sheet *s)
{
    free(s->img.color);
    memset(s, 0, sizeof *s);
}

/* ---- numbered file names --------------------------------------------------------- */

/* The conversion at p (just after a '%'): flags, width and type, or 0 when
 * it is not one pattern_check allows.  Sets *zero, *left and *width. */
static size_t conversion(const char *p, int *zero, int *left, int *width)
{
    const char *q = p;
    *zero = *left = *width = 0;
    for (; *q == '0' || *q == '-'; q++) {
        if (*q == '0') *zero = 1;
        else *left = 1;
    }
    for (; *q >= '0' && *q <= '9'; q++) {
        *width = *width * 10 + (*q - '0');
        if (*width > 32) return 0;
    }
    if (*q != 'd' && *q != 'i' && *q != 'u') return 0;
    return (size_t)(q - p) + 1;
}

int pattern_check(const char *pattern)
{
    int n = 0, zero, left, width;
    for (const char *p = pattern; *p; p++) {
        if (*p != '%') continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        size_t k = conversion(p + 1, &zero, &left, &width);
        if (!k || ++n > 1) return -1;
        p += k;
    }
    return n;
}

int pattern_path(const char *pattern, long k, char *buf, size_t n)
{
    if (pattern_check(pattern) < 0 || n == 0) return -1;
    size_t o = 0;
    for (const char *p = pattern; *p; p++) {
        char piece[48];
        size_t len;
        int zero, left, width;
        if (*p != '%') {
            piece[0] = *p;
            len = 1;
        } else if (p[1] == '%') {
            piece[0] = '%';
            len = 1;
            p++;
        } else {
            size_t c = conversion(p + 1, &zero, &left, &width);
            int m = left ? snprintf(piece, sizeof piece, "%-*ld", width, k)
                         : zero ? snprintf(piece, sizeof piece, "%0*ld", width, k)
                                : snprintf(piece, sizeof piece, "%*ld", width, k);
            if (m < 0 || (size_t)m >= sizeof piece) return -1;
            len = (size_t)m;
            p += c;
        }
        if (o + len >= n) return -1;
        memcpy(buf + o, piece, len);
        o += len;
    }
    buf[o] = 0;
    return 0;
}
