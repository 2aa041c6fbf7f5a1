/*
 * perturb.h - internal: vertex perturbation next to concave silhouette
 * segments (perturb.c, paper III-E), the last part of the plan.  Not
 * installed.
 */
#ifndef SILK_PERTURB_H
#define SILK_PERTURB_H

#include "plan.h"

int silk_perturb_alloc(silk_sil_frame *f);           /* the slots and offsets; 0 when they do not fit */
int silk_perturb(silk_sil_frame *f);                 /* fills offset, vert_offset; 0 when its scratch does not fit */

#endif
