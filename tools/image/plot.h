/*
 * plot.h - grouped bar charts as PNG, drawn by the silk tool itself (no
 * plotting library): `silk bench --plot` shows frame time and silhouette
 * error per mode and mesh; x-y charts: `silk bench --plot-bytes` shows the
 * error against the model's bytes.  Host-side.
 */
#ifndef SILK_TOOLS_PLOT_H
#define SILK_TOOLS_PLOT_H

#include <stdint.h>
#include "silk/error.h"
#include "silk/raster.h"

/* One panel: a bar per group and series, value[g * nseries + s]; a NaN
 * value is drawn as "n/a" without a bar. */
typedef struct plot_panel {
    const char *title;        /* above the panel */
    const char *unit;         /* along the y axis */
    const double *value;
} plot_panel;

typedef struct plot_chart {
    const char *title;        /* top of the picture */
    const char *note;         /* a smaller line under it, or NULL */
    int ngroups, nseries, npanels;
    const char *const *group;     /* ngroups names, under the bars */
    const char *const *series;    /* nseries names, in the legend */
    const uint32_t *series_rgb;   /* nseries colours 0xRRGGBB */
    const plot_panel *panel;      /* npanels, stacked top to bottom */
} plot_chart;

/* An x-y chart: series of points joined by lines in the order given, on a
 * logarithmic x axis (x > 0) and a linear y axis from 0. */
typedef struct plot_series {
    const char *name;             /* in the legend */
    uint32_t rgb;
    int n;
    const double *x, *y;          /* n points; a NaN y is left out */
    const char *const *label;     /* n small labels beside the points, or NULL */
} plot_series;

typedef struct plot_xy {
    const char *title, *note;     /* as plot_chart's */
    const char *x_unit, *y_unit;  /* along the axes */
    double x_scale;               /* tick labels show x / x_scale (1024: bytes as KiB) */
    int nseries;
    const plot_series *series;
} plot_xy;

/* The chart as an RGB888 target whose colour buffer is malloc'd (free
 * t->color); 0, or -1 when out of memory or the chart is empty. */
int plot_render(const plot_chart *c, silk_target *t);

/* plot_render, then written atomically as a PNG. */
silk_status plot_write_png(const plot_chart *c, const char *path, silk_error *err);

/* The same for an x-y chart; -1 also when no series has a point. */
int plot_xy_render(const plot_xy *c, silk_target *t);
silk_status plot_xy_write_png(const plot_xy *c, const char *path, silk_error *err);

#endif
