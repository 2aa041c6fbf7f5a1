/*
 * stages.h - the optional per-stage timing of a frame (silk_stage_clock,
 * include/silk/render.h): a piece of stage S is timed as
 *     uint32_t t0 = silk_stage_start(clock);  ...  silk_stage_stop(clock, S, t0);
 * Both do nothing but test the pointer when clock is NULL.
 */
#ifndef SILK_STAGES_H
#define SILK_STAGES_H

#include "silk/render.h"

static inline uint32_t silk_stage_start(silk_stage_clock *c)
{
    return c ? c->now(c->user) : 0;
}

static inline void silk_stage_stop(silk_stage_clock *c, silk_stage s, uint32_t t0)
{
    if (!c) return;
    c->ticks[s] += c->now(c->user) - t0;
    c->pieces[s]++;
}

#endif
