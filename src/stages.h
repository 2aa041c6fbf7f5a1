/*
 * stages.h - the optional per-stage timing of a frame (silk_stage_clock,
 * include/silk/render.h): a piece of stage S is timed as
 *     uint32_t t0 = silk_stage_start(clock);  ...  silk_stage_stop(clock, S, t0);
 * Both do nothing but test the pointer when clock is NULL.  They are
 * functions (stages.c), not inline: a frame times some thirty places, and
 * on a small part a call is 4 bytes of code where each test inline is a
 * dozen or more.
 */
#ifndef SILK_STAGES_H
#define SILK_STAGES_H

#include "silk/render.h"

uint32_t silk_stage_start(silk_stage_clock *c);
void silk_stage_stop(silk_stage_clock *c, silk_stage s, uint32_t t0);

#endif
