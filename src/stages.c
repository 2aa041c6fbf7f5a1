/*
 * stages.c - the stage clock's two calls (stages.h).
 */
#include "stages.h"

uint32_t silk_stage_start(silk_stage_clock *c)
{
    return c ? c->now(c->user) : 0;
}

void silk_stage_stop(silk_stage_clock *c, silk_stage s, uint32_t t0)
{
    if (!c) return;
    c->ticks[s] += c->now(c->user) - t0;
    c->pieces[s]++;
}
