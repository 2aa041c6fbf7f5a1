/*
 * progress.c - the progress line of progress.h.  "\r" returns to the start
 * of the line and "\033[K" clears what a longer earlier line left; both are
 * written only to a terminal.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "progress.h"

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

void progress_start(progress *p, int quiet, const char *label)
{
    memset(p, 0, sizeof *p);
    p->on = !quiet && isatty(STDERR_FILENO);
    p->t0 = now_s();
    p->last = -1;
    snprintf(p->label, sizeof p->label, "%s", label);
}

/* Draw at most every 0.1 s; the first time at once. */
static int due(progress *p, double t)
{
    if (!p->on || (p->last >= 0 && t - p->last < 0.1)) return 0;
    p->last = t;
    return 1;
}

void progress_update(progress *p, double done, double total)
{
    double t = now_s();
    if (!(total > 0) || !due(p, t)) return;
    double f = done / total, el = t - p->t0;
    if (f < 0) f = 0;
    if (f > 1) f = 1;
    fprintf(stderr, "\rsilk: %s %3.0f%%", p->label, 100 * f);
    if (el >= 1 && f > 0 && f < 1) {
        double left = el * (1 - f) / f;
        if (left < 90) fprintf(stderr, "  %.0f s left", left);
        else fprintf(stderr, "  %.0f min left", left / 60);
    }
    fputs("\033[K", stderr);
    fflush(stderr);
    p->shown = 1;
}

void progress_note(progress *p, const char *what)
{
    double t = now_s();
    if (!due(p, t)) return;
    fprintf(stderr, "\rsilk: %s: %s  %.0f s\033[K", p->label, what, t - p->t0);
    fflush(stderr);
    p->shown = 1;
}

void progress_end(progress *p)
{
    if (p->on && p->shown) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
    p->shown = 0;
    p->on = 0;
}
