/*
 * plot.c - grouped bar charts drawn pixel by pixel into a silk_target and
 * written with the PNG sink: a title, a legend, then panels stacked top to
 * bottom, each with a y axis from 0 to a round number, grid lines, a bar per
 * group and series, and the value over every bar.  And x-y charts: points
 * joined by lines over a logarithmic x axis, for a quantity that spans
 * decades (bytes).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "font.h"
#include "plot.h"
#include "platform/platform.h"

enum {
    SCALE = 2,              /* labels: the 5x7 font doubled */
    MARGIN = 16,
    BAR_W = 22,             /* one bar */
    GROUP_GAP = 34,         /* between groups of bars */
    PLOT_H = 220,           /* height of a panel's axis box */
    TICKS = 5
};

#define RGB_TEXT 0x202020u
#define RGB_AXIS 0x404040u
#define RGB_GRID 0xDDDDDDu
#define RGB_BG   0xFFFFFFu

static void fill(silk_target *t, int x0, int y0, int x1, int y1, uint32_t rgb)
{
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > t->width) x1 = t->width;
    if (y1 > t->height) y1 = t->height;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) silk_target_put(t, x, y, rgb);
}

/* 1, 2 or 5 times a power of ten, at least v. */
static double nice_step(double v)
{
    double p = pow(10, floor(log10(v)));
    return v <= p ? p : v <= 2 * p ? 2 * p : v <= 5 * p ? 5 * p : 10 * p;
}

static void format_value(double v, char *buf, size_t n)
{
    if (isnan(v)) snprintf(buf, n, "n/a");
    else if (isinf(v)) snprintf(buf, n, "inf");
    else if (v != 0 && fabs(v) < 0.01) snprintf(buf, n, "%.1e", v);
    else snprintf(buf, n, "%.3g", v);
}

/* The title and the note under it from the top-left margin; the row the
 * legend goes on. */
static int draw_title(silk_target *t, const char *title, const char *note)
{
    int y = MARGIN;
    font_draw(t, MARGIN, y, title ? title : "", RGB_TEXT, SCALE);
    y += FONT_LINE * SCALE;
    if (note) {
        font_draw(t, MARGIN, y + 2, note, RGB_AXIS, 1);
        y += FONT_LINE + 4;
    }
    return y + 8;
}

/* A legend entry (a swatch and the name) at x; where the next one goes. */
static int legend_item(silk_target *t, int x, int y, const char *name, uint32_t rgb)
{
    fill(t, x, y, x + 14, y + 14, rgb);
    font_draw(t, x + 20, y, name, RGB_TEXT, SCALE);
    return x + 14 + 6 + font_text_width(name, SCALE) + 20;
}

typedef struct layout {
    int left, group_w, width, height;
    int header_h, panel_h;
} layout;

static layout measure(const plot_chart *c)
{
    layout L;
    L.left = MARGIN + FONT_LINE * SCALE + 8 + 7 * FONT_ADVANCE * SCALE;   /* unit, tick labels */
    L.group_w = c->nseries * BAR_W;
    for (int g = 0; g < c->ngroups; g++)
        if (font_text_width(c->group[g], SCALE) > L.group_w) L.group_w = font_text_width(c->group[g], SCALE);
    L.group_w += GROUP_GAP;
    int legend_w = 0;
    for (int s = 0; s < c->nseries; s++) legend_w += 14 + 6 + font_text_width(c->series[s], SCALE) + 20;
    int w = L.left + c->ngroups * L.group_w + MARGIN;
    int tw = MARGIN * 2 + font_text_width(c->title ? c->title : "", SCALE);
    if (c->note && MARGIN * 2 + font_text_width(c->note, 1) > tw) tw = MARGIN * 2 + font_text_width(c->note, 1);
    if (tw > w) w = tw;
    if (MARGIN * 2 + legend_w > w) w = MARGIN * 2 + legend_w;
    for (int p = 0; p < c->npanels; p++) {
        int pw = L.left + font_text_width(c->panel[p].title ? c->panel[p].title : "", SCALE) + MARGIN;
        if (pw > w) w = pw;
    }
    L.width = w;
    L.header_h = MARGIN + FONT_LINE * SCALE + (c->note ? FONT_LINE + 4 : 0) + 8 + FONT_LINE * SCALE + 12;
    L.panel_h = FONT_LINE * SCALE + 8 + PLOT_H + 8 + FONT_LINE * SCALE + 16;
    L.height = L.header_h + c->npanels * L.panel_h + MARGIN;
    return L;
}

static void draw_panel(silk_target *t, const plot_chart *c, const plot_panel *p, const layout *L, int top)
{
    font_draw(t, L->left, top, p->title ? p->title : "", RGB_TEXT, SCALE);
    int y0 = top + FONT_LINE * SCALE + 8, y1 = y0 + PLOT_H;   /* axis box rows */
    int x0 = L->left, x1 = L->left + c->ngroups * L->group_w;

    double vmax = 0;
    for (int i = 0; i < c->ngroups * c->nseries; i++)
        if (isfinite(p->value[i]) && p->value[i] > vmax) vmax = p->value[i];
    double step = nice_step(vmax > 0 ? vmax / TICKS : 1.0 / TICKS);
    double top_v = ceil(vmax / step - 1e-9) * step;
    if (top_v <= 0) top_v = step * TICKS;
    /* room over the tallest bar for its value */
    double scale_px = (PLOT_H - 3 * FONT_LINE) / top_v;

    for (double v = 0; v <= top_v * (1 + 1e-9); v += step) {
        int y = y1 - (int)lround(v * scale_px);
        fill(t, x0, y, x1, y + 1, RGB_GRID);
        char buf[32];
        snprintf(buf, sizeof buf, "%g", v);
        font_draw(t, x0 - 6 - font_text_width(buf, SCALE), y - FONT_H * SCALE / 2, buf, RGB_TEXT, SCALE);
    }
    fill(t, x0, y0, x0 + 1, y1 + 1, RGB_AXIS);
    fill(t, x0, y1, x1, y1 + 1, RGB_AXIS);
    if (p->unit) {
        int uw = font_text_width(p->unit, SCALE);
        font_draw_up(t, MARGIN, y0 + PLOT_H / 2 + uw / 2, p->unit, RGB_TEXT, SCALE);
    }

    for (int g = 0; g < c->ngroups; g++) {
        int gx = x0 + g * L->group_w + (L->group_w - c->nseries * BAR_W) / 2;   /* bars centred */
        for (int s = 0; s < c->nseries; s++) {
            double v = p->value[g * c->nseries + s];
            int bx = gx + s * BAR_W, h = isfinite(v) && v > 0 ? (int)lround(v * scale_px) : 0;
            if (h > 0) fill(t, bx + 1, y1 - h, bx + BAR_W - 1, y1, c->series_rgb[s]);
            char buf[32];
            format_value(v, buf, sizeof buf);
            int tw = font_text_width(buf, 1);
            if (tw <= BAR_W) font_draw(t, bx + (BAR_W - tw) / 2, y1 - h - FONT_LINE, buf, RGB_TEXT, 1);
            else font_draw_up(t, bx + (BAR_W - FONT_H) / 2, y1 - h - 3, buf, RGB_TEXT, 1);
        }
        int nw = font_text_width(c->group[g], SCALE);
        font_draw(t, gx + (c->nseries * BAR_W - nw) / 2, y1 + 8, c->group[g], RGB_TEXT, SCALE);
    }
}

int plot_render(const plot_chart *c, silk_target *t)
{
    memset(t, 0, sizeof *t);
    if (c->ngroups < 1 || c->nseries < 1 || c->npanels < 1) return -1;
    layout L = measure(c);
    uint8_t *rgb = malloc((size_t)L.width * L.height * 3);
    if (!rgb) return -1;
    silk_target_init(t, L.width, L.height, 0, L.height, SILK_PIX_RGB888, rgb, NULL);
    fill(t, 0, 0, L.width, L.height, RGB_BG);

    int y = draw_title(t, c->title, c->note), x = MARGIN;
    for (int s = 0; s < c->nseries; s++) x = legend_item(t, x, y, c->series[s], c->series_rgb[s]);
    for (int p = 0; p < c->npanels; p++) draw_panel(t, c, &c->panel[p], &L, L.header_h + p * L.panel_h);
    return 0;
}

/* A chart drawn by render (0 or -1), written as a PNG. */
static silk_status write_png(int rendered, silk_target *t, const char *path, silk_error *err)
{
    if (rendered != 0) return silk_fail(err, SILK_ERR_IO, path, 0, "cannot draw the chart (out of memory or empty)");
    silk_status s = silk_png_write(t, path, err);
    free(t->color);
    return s;
}

silk_status plot_write_png(const plot_chart *c, const char *path, silk_error *err)
{
    silk_target t;
    return write_png(plot_render(c, &t), &t, path, err);
}

/* ---- x-y charts ---- */

enum { XY_W = 720, XY_H = 420, MARK = 3 };

/* A line two pixels wide from (x0, y0) to (x1, y1), by steps along the
 * longer axis. */
static void line(silk_target *t, int x0, int y0, int x1, int y1, uint32_t rgb)
{
    int dx = abs(x1 - x0), dy = abs(y1 - y0), n = dx > dy ? dx : dy;
    for (int i = 0; i <= n; i++) {
        int x = n ? x0 + (x1 - x0) * i / n : x0, y = n ? y0 + (y1 - y0) * i / n : y0;
        fill(t, x, y, x + 2, y + 2, rgb);
    }
}

typedef struct xy_range {
    double lx0, lx1;          /* log10 of the x axis' ends */
    double ytop;              /* the y axis' top */
} xy_range;

static int xy_range_of(const plot_xy *c, xy_range *r, double *ystep)
{
    double xmin = INFINITY, xmax = 0, ymax = 0;
    for (int s = 0; s < c->nseries; s++)
        for (int i = 0; i < c->series[s].n; i++) {
            double x = c->series[s].x[i], y = c->series[s].y[i];
            if (!(x > 0) || !isfinite(x) || !isfinite(y)) continue;
            if (x < xmin) xmin = x;
            if (x > xmax) xmax = x;
            if (y > ymax) ymax = y;
        }
    if (xmax == 0) return -1;
    r->lx0 = floor(log10(xmin / 1.2) * 4) / 4;   /* a quarter decade of room each side */
    r->lx1 = ceil(log10(xmax * 1.2) * 4) / 4;
    *ystep = nice_step(ymax > 0 ? ymax / TICKS : 1.0 / TICKS);
    r->ytop = ceil(ymax / *ystep - 1e-9) * *ystep;
    if (r->ytop <= 0) r->ytop = *ystep * TICKS;
    return 0;
}

int plot_xy_render(const plot_xy *c, silk_target *t)
{
    memset(t, 0, sizeof *t);
    xy_range R;
    double ystep;
    if (c->nseries < 1 || xy_range_of(c, &R, &ystep) != 0) return -1;
    int left = MARGIN + FONT_LINE * SCALE + 8 + 6 * FONT_ADVANCE * SCALE;
    int header = MARGIN + FONT_LINE * SCALE + (c->note ? FONT_LINE + 4 : 0) + 8 + FONT_LINE * SCALE + 12;
    int width = left + XY_W + MARGIN, height = header + XY_H + 8 + 2 * FONT_LINE * SCALE + 16 + MARGIN;
    uint8_t *rgb = malloc((size_t)width * height * 3);
    if (!rgb) return -1;
    silk_target_init(t, width, height, 0, height, SILK_PIX_RGB888, rgb, NULL);
    fill(t, 0, 0, width, height, RGB_BG);

    int y = draw_title(t, c->title, c->note), x = MARGIN;
    for (int s = 0; s < c->nseries; s++) x = legend_item(t, x, y, c->series[s].name, c->series[s].rgb);

    int x0 = left, x1 = left + XY_W, y0 = header, y1 = header + XY_H;
#define XPIX(v) (x0 + (int)lround((log10(v) - R.lx0) / (R.lx1 - R.lx0) * XY_W))
#define YPIX(v) (y1 - (int)lround((v) / R.ytop * XY_H))
    for (double v = 0; v <= R.ytop * (1 + 1e-9); v += ystep) {
        int yy = YPIX(v);
        fill(t, x0, yy, x1, yy + 1, RGB_GRID);
        char buf[32];
        snprintf(buf, sizeof buf, "%g", v);
        font_draw(t, x0 - 6 - font_text_width(buf, SCALE), yy - FONT_H * SCALE / 2, buf, RGB_TEXT, SCALE);
    }
    /* x ticks at 1, 2 and 5 times powers of ten of the scaled unit */
    double scale = c->x_scale > 0 ? c->x_scale : 1;
    for (double d = pow(10, floor(R.lx0 - log10(scale))); d * scale <= pow(10, R.lx1); d *= 10)
        for (int m = 1; m <= 5; m += m == 1 ? 1 : 3) {
            double v = d * m * scale;
            if (log10(v) < R.lx0 || log10(v) > R.lx1) continue;
            int xx = XPIX(v);
            fill(t, xx, y0, xx + 1, y1, RGB_GRID);
            char buf[32];
            snprintf(buf, sizeof buf, "%g", d * m);
            font_draw(t, xx - font_text_width(buf, SCALE) / 2, y1 + 8, buf, RGB_TEXT, SCALE);
        }
    fill(t, x0, y0, x0 + 1, y1 + 1, RGB_AXIS);
    fill(t, x0, y1, x1, y1 + 1, RGB_AXIS);
    if (c->y_unit) {
        int uw = font_text_width(c->y_unit, SCALE);
        font_draw_up(t, MARGIN, y0 + XY_H / 2 + uw / 2, c->y_unit, RGB_TEXT, SCALE);
    }
    if (c->x_unit)
        font_draw(t, x0 + (XY_W - font_text_width(c->x_unit, SCALE)) / 2, y1 + 8 + FONT_LINE * SCALE + 6, c->x_unit,
                  RGB_TEXT, SCALE);

    for (int s = 0; s < c->nseries; s++) {
        const plot_series *S = &c->series[s];
        int px = 0, py = 0, have = 0;
        for (int i = 0; i < S->n; i++) {
            if (!(S->x[i] > 0) || !isfinite(S->x[i]) || !isfinite(S->y[i])) continue;
            int xx = XPIX(S->x[i]), yy = YPIX(S->y[i]);
            if (have) line(t, px, py, xx, yy, S->rgb);
            fill(t, xx - MARK, yy - MARK, xx + MARK + 1, yy + MARK + 1, S->rgb);
            if (S->label && S->label[i]) font_draw(t, xx + MARK + 3, yy - FONT_H - 2, S->label[i], RGB_TEXT, 1);
            px = xx, py = yy, have = 1;
        }
    }
#undef XPIX
#undef YPIX
    return 0;
}

silk_status plot_xy_write_png(const plot_xy *c, const char *path, silk_error *err)
{
    silk_target t;
    return write_png(plot_xy_render(c, &t), &t, path, err);
}
