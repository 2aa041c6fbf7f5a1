/*
 * silk/compact.h - the compact packed model: a mesh with everything flat
 * and smooth frames need, in about a fifth of the bytes of its arrays,
 * read in place (from flash) by every stage through the accessors of
 * silk/mesh.h.  `silk pack` writes it; docs/formats.md "Compact models"
 * describes it field by field.
 *
 * A corner table (Rossignac's: each triangle side knows the triangle
 * across it) replaces the edge list, the vertex-edge lists and the
 * triangles' edges: an edge is the side of the lower-numbered of its two
 * triangles, numbered in the order of those sides; the sides around a
 * vertex are found by turning about it.  Positions are quantized to a
 * power-of-two step in the model's box, normals and feature tangent
 * directions are octahedral codes, and every array is a run of fixed-width
 * bit fields, so element i of any array is found without decoding others.
 *
 * Layout (little-endian; a bit array holds value i of width w in bits
 * i*w .. i*w+w-1, bit b being bit b%8 of byte b/8 of the array):
 *
 *   offset size
 *    0  4  magic "SLKC"
 *    4  2  version (SILK_COMPACT_VERSION)
 *    6  2  flags (SILK_COMPACT_*)
 *    8  4  nverts (3 .. 2^24-1)
 *   12  4  ntris (1 .. 2^24-2)
 *   16  4  nnormals (nverts .. 2^24-1)
 *   20  4  nedges: edges, sides that own one (0 without SILK_COMPACT_ADJACENCY)
 *   24  4  nlisted: edges in LIST
 *   28 12  org: three int32, Q16.16
 *   40  1  pos_bits  (1..16)   a coordinate is org + (q << pos_shift)
 *   41  1  pos_shift (0..15)
 *   42  1  nrm_bits  (2..16)   bits of each octahedral coordinate of a normal
 *   43  1  sel_bits  (0..6)    bits of a corner's normal selector
 *   44  1  vtx_bits  (1..24)   bits of a vertex index
 *   45  1  tri_bits  (1..24)   bits of a triangle index; all ones: none
 *   46  1  edge_bits (1..24)   bits of an edge index (a side, 3t + k)
 *   47  1  dir_bits  (2..16)   bits of each octahedral coordinate of a tangent direction
 *   48  4  size: bytes of the whole model, the 4 zero bytes at its end included
 *   52  4  CRC-32 of bytes 56 .. size-1
 *   56     the arrays, each starting at a byte, in this order:
 *     POS    3 nverts x pos_bits      x, y, z of each vertex
 *     NRM    2 nnormals x nrm_bits    octahedral u, v of each shading normal:
 *            normal v is vertex v's first, then come the others (EXTRA's)
 *     EXTRA  (nnormals-nverts) x vtx_bits, non-decreasing: the vertex of
 *            each normal after the first nverts; vertex v's second is
 *            nverts + (entries < v), its third the next
 *     XPRE   ceil(nverts/8) x xpre_bits (none without EXTRA; xpre_bits
 *            the bits of nnormals - nverts): the EXTRA entries below vertex 8i
 *     CORNER 3 ntris x vtx_bits       the vertices of each triangle
 *     SEL    3 ntris x sel_bits       each corner's normal: 0 its vertex's first, s the s+1-th
 *   with SILK_COMPACT_ADJACENCY:
 *     OPP    3 ntris x tri_bits       the triangle across side k of each (corners k, k+1), or none
 *     LIST   nlisted records, by edge: edge (edge_bits), flags (3 bits:
 *            crease, groups, degenerate), then for each end (v[0], v[1]):
 *            straight (1 bit), u, v (dir_bits each)
 *     VFIRST ceil(nverts/8) x tri_bits  the first triangle using vertex 8i
 *   4 zero bytes.
 *
 * A side (t, k) owns its edge when it has no triangle across it or the one
 * across has a higher index; the edge's index is the side's, 3t + k, so
 * edge indices run below 3 ntris with gaps (nedges counts the edges).
 * An edge's v[0] < v[1] are its side's corners, t[0] the owner, t[1] the
 * triangle across; flags are BOUNDARY when there is none, and LIST's.
 * LIST holds every edge with a flag (boundary ones included), so the
 * feature segment of an edge is its LIST record: the tangent at each end is
 * the chord (straight) or eq. 4's tangent along the decoded direction.
 * Vertices are numbered in the order triangles first use them (VFIRST is
 * then non-decreasing).
 */
#ifndef SILK_COMPACT_H
#define SILK_COMPACT_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SILK_COMPACT_MAGIC "SLKC"
#define SILK_COMPACT_VERSION 1
#define SILK_COMPACT_HEADER_BYTES 56

enum silk_compact_flag {
    SILK_COMPACT_ADJACENCY   = 1u << 0,  /* OPP, LIST, VFIRST: smooth-capable */
    SILK_COMPACT_FILE_NORMALS = 1u << 1, /* the normals came with the mesh (silk_mesh.normals_used) */
    SILK_COMPACT_CLOSED      = 1u << 2   /* closed and wound outward (silk_mesh.closed_outward) */
};

/* The unit vector of octahedral code (u, v), bits each (2..16): with
 * M = 2^bits - 1, X = 2u - M, Y = 2v - M and Z = M - |X| - |Y|; where
 * Z < 0 the lower half is folded, X, Y = (M - |Y|) sgn X, (M - |X|) sgn Y
 * (sgn 0 = +1); then (X, Y, Z) normalized to Q16.16.  The same integers on
 * every machine, so an encoder picks the code whose decoded vector is
 * nearest. */
silk_vec3 silk_compact_octa(uint32_t u, uint32_t v, unsigned bits);

/* Check a compact model (header, sizes, CRC, and every value a frame
 * reads: coordinates, codes, indices, the corner table's symmetry, edge
 * counts, LIST's order, VFIRST) and point *out at it: no array is copied,
 * the bytes must stay where they are while the mesh is used.  name is for
 * messages ("model" when NULL).  SILK_OK, or SILK_ERR_PARSE with "name:
 * what is wrong". */
silk_status silk_compact_mesh(const void *data, size_t len, const char *name, silk_mesh *out, silk_error *err);

/* Whether the bytes start like a compact model (the magic). */
int silk_is_compact(const void *data, size_t len);

#ifdef __cplusplus
}
#endif

#endif
