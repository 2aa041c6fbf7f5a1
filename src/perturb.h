/*
 * perturb.h - internal: vertex perturbation next to concave silhouette
 * segments (perturb.c, paper III-E), the last part of the plan.  Not
 * installed.
 */
#ifndef SILK_PERTURB_H
#define SILK_PERTURB_H

#include "plan.h"

int  silk_perturb_alloc(silk_sil_frame *f);          /* 0 when it does not fit */
void silk_perturb(silk_sil_frame *f);                /* fills offset, vert_offset */

#endif
