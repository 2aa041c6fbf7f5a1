/*
 * progress.h - one updating line on stderr for long work (simplify, bench,
 * --turntable, loading large files): "silk: LABEL  42%  3 s left", drawn
 * only when stderr is a terminal and the user did not ask for --quiet, at
 * most ten times a second, and erased when the work ends.  Nothing is
 * printed when stderr is a file or a pipe, so logs and scripts see none.
 */
#ifndef SILK_PROGRESS_H
#define SILK_PROGRESS_H

typedef struct progress {
    int on;                    /* drawing at all */
    int shown;                 /* a line is on the screen */
    double t0, last;           /* seconds: start, last drawing */
    char label[96];
} progress;

/* Start; on only if !quiet and stderr is a terminal. */
void progress_start(progress *p, int quiet, const char *label);
/* done of total (total > 0): percentage and, after the first second, the
 * time left at the rate so far. */
void progress_update(progress *p, double done, double total);
/* Work without a measure: the label, what it is doing and the time so far. */
void progress_note(progress *p, const char *what);
/* Erase the line. */
void progress_end(progress *p);

#endif
