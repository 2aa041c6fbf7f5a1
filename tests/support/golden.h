/*
 * golden.h - the one way the tests compare a frame with its reference image
 * (tests/golden/NAME.png, or NAME.ppm for the rasterizer's first scenes) and
 * the one way to update them (`make golden`).
 *
 *   golden_compare(t, name, msg, n): the frame (any pixel format, widened to
 *   RGB888) against the reference, byte for byte.  Returns 1 when they are
 *   equal.  Otherwise 0 with msg saying how they differ, and the frame is
 *   left as OUT/NAME.png and the difference as OUT/NAME-diff.png: the
 *   reference faded to light grey, the pixels that differ in red (a
 *   missing or differently sized reference: the frame only).
 *
 * SILK_GOLDEN_UPDATE=1 (make golden) writes the frame as the reference
 * instead when it differs or is missing, names it on stdout ("changed:
 * NAME", "new: NAME") and returns 1.  SILK_GOLDEN is the references'
 * directory (default tests/golden), SILK_TEST_OUT where the failures go
 * (default build/tests/out; tests/run.sh sets BUILD/tests/out).
 */
#ifndef SILK_TEST_GOLDEN_H
#define SILK_TEST_GOLDEN_H

#include <stddef.h>
#include "silk/raster.h"

int golden_compare(const silk_target *t, const char *name, char *msg, size_t n);

/* How many references were the same, changed and new so far, as one line
 * (after an update). */
void golden_summary(void);

/* The directories in use. */
const char *golden_dir(void);
const char *golden_out_dir(void);

#endif
