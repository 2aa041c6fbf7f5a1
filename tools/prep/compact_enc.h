/*
 * compact_enc.h - the host-side encoder of the compact packed model
 * (include/silk/compact.h, the format's contract): a loaded silk_mesh as
 * the bytes that silk_compact_mesh() reads in place from flash.
 * `silk pack` writes them; the encoder refuses, with a one-line reason,
 * a mesh the format cannot hold.  Host code: double precision, malloc.
 */
#ifndef SILK_TOOLS_COMPACT_ENC_H
#define SILK_TOOLS_COMPACT_ENC_H

#include <stddef.h>
#include <stdint.h>

#include "silk/mesh.h"

typedef struct compact_opts {
    int pos_bits;    /* bits of each quantized coordinate (1..16) */
    int nrm_bits;    /* bits of each octahedral coordinate of a shading normal (2..16) */
    int dir_bits;    /* bits of each octahedral coordinate of a feature tangent (2..16) */
    int adjacency;   /* 1: the corner table, edges and feature segments (smooth-capable); 0: flat only */
} compact_opts;

/* pos_bits 12, nrm_bits 10, dir_bits 8, adjacency 1. */
compact_opts compact_opts_default(void);

/* The arrays of a compact model, in file order (compact.h's layout). */
enum compact_array {
    COMPACT_POS, COMPACT_NRM, COMPACT_EXTRA, COMPACT_XPRE, COMPACT_CORNER, COMPACT_SEL,
    COMPACT_OPP, COMPACT_LIST, COMPACT_VFIRST, COMPACT_NARRAYS
};

/* A compact model's header and where its arrays are. */
typedef struct compact_layout {
    uint32_t nverts, ntris, nnormals, nedges, nlisted, flags;
    int32_t org[3];
    uint8_t pos_bits, pos_shift, nrm_bits, sel_bits, vtx_bits, tri_bits, edge_bits, dir_bits;
    uint32_t list_bits;                  /* bits of one LIST record */
    size_t off[COMPACT_NARRAYS];         /* byte offset of each array in the model */
    size_t bytes[COMPACT_NARRAYS];       /* its bytes (0: absent or empty) */
    size_t size;                         /* the whole model, header and 4 trailing zero bytes included */
} compact_layout;

/* The layout of a model from its header (the counts and field widths
 * filled in; off, bytes, list_bits and size computed from them). */
void compact_layout_place(compact_layout *l);

/* The header of the bytes at b read back into *l (for summaries of an
 * encoded model): 0, or -1 when they do not start like a compact model
 * of len bytes. */
int compact_layout_read(const uint8_t *b, size_t len, compact_layout *l);

/* Encode m (as silk_load_mesh leaves it: arrays, tri_edge, edge_feature)
 * into a malloc'd block *out of *len bytes.  0, or -1 with a one-line
 * reason in why ("texture coordinates", "edge 12 has 3 triangles", ...):
 * what keeps the mesh from being compact, or bad options. */
int compact_encode(const silk_mesh *m, const compact_opts *o, uint8_t **out, size_t *len, char *why, size_t whylen);

/* The octahedral code (u, v) of bits each (2..16) whose decoded vector
 * (silk_compact_octa, the core's own integers) is nearest in angle to the
 * direction d (any length; +z for the zero vector): the encoder's choice
 * for normals and tangent directions. */
void compact_octa_encode(const double d[3], unsigned bits, uint32_t *u, uint32_t *v);

#endif
