/*
 * expand.h - test support: a compact model (silk/compact.h) written out
 * into the arrays of a silk_mesh through the accessors of silk/mesh.h, in
 * the same order: the edges in edge order, each vertex's edges in the order
 * its ring gives them.  A frame of the two must then be the same bytes,
 * which checks that every stage reads a mesh only through the accessors.
 */
#ifndef SILK_TEST_EXPAND_H
#define SILK_TEST_EXPAND_H

#include "silk/silk.h"

/* 1, with *out's arrays in the arena; 0 when the arena is short or the
 * model's walks disagree with its random access (an edge listed twice, a
 * ring that misses an edge). */
int ex_expand(const silk_mesh *packed, silk_arena *a, silk_mesh *out);

#endif
