/*
 * silk/mesh.h - the compact indexed mesh every stage reads.
 *
 * Loading is two passes over a byte buffer the caller already holds (the
 * core does no file I/O): the first counts, the second fills arrays of
 * exactly that size from the arena.  silk_mesh_build() then derives the edge
 * adjacency, the shading normals (angle-weighted, split at feature edges) and
 * the feature flags.  All arrays are plain indices, no pointers between
 * elements, so a packed mesh can live in flash unchanged.
 */
#ifndef SILK_MESH_H
#define SILK_MESH_H

#include <stddef.h>
#include <stdint.h>
#include "fixed.h"
#include "arena.h"
#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* An index into one of the mesh's arrays: 32 bits in every build, so that
 * a mesh's layout is the same for every program and core (a small board's
 * plan keeps its own indices in 16 bits: SILK_PLAN_INDEX16, silk/config.h). */
typedef uint32_t silk_index;
#define SILK_NO_INDEX ((silk_index)~(silk_index)0)

/* Model coordinates (after --scale) must satisfy |c| <= SILK_COORD_MAX, and
 * the bounding-box diagonal must be at least SILK_SIZE_MIN, so that every
 * later product fits Q16.16 and the model keeps enough resolution. */
#define SILK_COORD_MAX  SILK_FX_C(1024, 1)
#define SILK_SIZE_MIN   SILK_FX_C(1, 16)

enum silk_edge_flag {
    SILK_EDGE_BOUNDARY    = 1u << 0,  /* one incident triangle */
    SILK_EDGE_NONMANIFOLD = 1u << 1,  /* three or more incident triangles */
    SILK_EDGE_CREASE      = 1u << 2,  /* dihedral angle above the crease threshold */
    SILK_EDGE_GROUPS      = 1u << 3,  /* separates two OBJ smoothing groups */
    SILK_EDGE_DEGENERATE  = 1u << 4,  /* zero length, or next to a zero-area triangle */
    /* any of the first four makes the edge a feature edge */
    SILK_EDGE_FEATURE = SILK_EDGE_BOUNDARY | SILK_EDGE_NONMANIFOLD | SILK_EDGE_CREASE | SILK_EDGE_GROUPS
};

typedef struct silk_edge {
    silk_index v[2];          /* v[0] < v[1] (equal only on a zero-length DEGENERATE edge) */
    silk_index t[2];          /* incident triangles; t[1] == SILK_NO_INDEX on a boundary.
                                 On a non-manifold edge the first two found. */
    uint8_t flags;            /* enum silk_edge_flag (all fit 8 bits) */
} silk_edge;

/* A feature segment (paper III-A): the Hermite tangents of one feature edge,
 * computed once at load.  The curve runs from edge.v[0] to edge.v[1]; its
 * end points are the vertex positions, so only the tangents are stored. */
typedef struct silk_feature_seg {
    silk_vec3 t0, t1;
} silk_feature_seg;

struct silk_vis;   /* Gaussian-sphere hierarchy, silk/visibility.h */

/* Where a compact model's arrays are (silk/compact.h): the bytes in place,
 * the offset of each bit array in them and its field widths.  base is NULL
 * for a mesh held in the arrays of silk_mesh. */
typedef struct silk_mesh_packed {
    const uint8_t *base;
    uint32_t pos, nrm, extra, xpre, corner, sel, opp, list, vfirst;   /* byte offsets in base */
    uint32_t nextra, nlisted;
    silk_vec3 org;
    uint8_t pos_bits, pos_shift, nrm_bits, sel_bits, vtx_bits, tri_bits, edge_bits, dir_bits;
    uint8_t list_bits;        /* bits of one LIST record */
} silk_mesh_packed;

/* Where the shading normals come from (silk_load_opts.normals) and, in
 * silk_mesh.normals_used, where they came from. */
typedef enum silk_normals_source {
    SILK_NORMALS_AUTO = 0,    /* the file's where every corner has one, computed otherwise (default) */
    SILK_NORMALS_COMPUTE,     /* angle-weighted, split at feature edges (paper III-B) */
    SILK_NORMALS_FILE         /* the file's vn / nx ny nz: the same rule as AUTO, its older name */
} silk_normals_source;

typedef struct silk_mesh {
    uint32_t nverts, ntris, nnormals, nuvs, nedges;
    uint32_t nfeature_edges, nboundary_edges, nnonmanifold_edges, ndegenerate_tris;
    /* Orientation at load (silk_load_opts.orient): triangles whose corner
     * order was turned round, and triangles left as in the file because
     * their surface cannot be oriented (a Moebius band). */
    uint32_t nreoriented_tris, nnonorientable_tris;

    silk_vec3  *pos;          /* nverts, model units */
    silk_vec3  *normal;       /* nnormals unit shading normals: one per smooth group of each vertex */
    silk_index *normal_vertex;/* nnormals: the vertex each normal belongs to */
    silk_vec2  *uv;           /* nuvs, or NULL */
    uint32_t   *color;        /* nverts vertex colours 0xRRGGBB, or NULL */

    silk_index *tri;          /* 3*ntris vertex indices, counter-clockwise seen from outside */
    silk_index *tri_normal;   /* 3*ntris: index into normal[] for each corner */
    silk_index *tri_uv;       /* 3*ntris indices into uv[], or NULL */
    silk_index *tri_edge;     /* 3*ntris: edge k joins corners k and (k+1)%3; or NULL (a packed
                                 mesh): found in the vertex-edge lists.  Read it with
                                 silk_mesh_tri_edge(). */
    silk_edge  *edge;         /* nedges */

    /* vertex -> incident edges, CSR: edges of vertex v are
     * vert_edge[vert_edge_start[v] .. vert_edge_start[v+1]-1] */
    silk_index *vert_edge_start;   /* nverts + 1; the edge ends (at most 2 nedges) fit silk_index */
    silk_index *vert_edge;

    /* feature segments, one per feature edge (purpose FEATURES), in edge order */
    silk_index *edge_feature;      /* nedges: index into feature[], or SILK_NO_INDEX; NULL in a packed
                                      mesh (read it with silk_mesh_edge_feature()) */
    silk_feature_seg *feature;     /* nfeature_edges */

    const struct silk_vis *vis;    /* visibility hierarchy, or NULL (built on request) */

    silk_vec3 bbox_min, bbox_max;
    silk_normals_source normals_used;   /* COMPUTE or FILE: what the loader did (0, AUTO, when no loader set it) */
    /* 1: every part of the mesh is closed and wound outward (orient.c at
     * load), so from outside it its back faces cannot show and the
     * renderer may skip them; 0: not known (any mesh may say 0). */
    uint8_t closed_outward;
    /* A compact model read in place (silk_compact_mesh): the arrays above
     * are then NULL and every stage reads through the accessors below. */
    silk_mesh_packed packed;
} silk_mesh;


typedef enum silk_orient_mode {
    SILK_ORIENT_FIX = 0,      /* wind triangles consistently, closed parts outward (docs/formats.md) */
    SILK_ORIENT_KEEP          /* the file's corner order, as it is */
} silk_orient_mode;

/* Which mesh of a prepared model to load (docs/formats.md): what flat,
 * smooth, pn and blend draw, or the outer hull clip mode draws. */
typedef enum silk_model_part {
    SILK_PART_COARSE = 0,     /* the MESH section, or the hull when the model has none */
    SILK_PART_HULL            /* the HULL section */
} silk_model_part;

typedef struct silk_load_opts {
    silk_decimal scale;       /* coordinates are multiplied by this before rounding; {1,0} = none */
    silk_fx crease_deg;       /* dihedral angle (degrees) above which an edge is a feature */
    silk_normals_source normals;
    silk_orient_mode orient;
    silk_model_part part;     /* which mesh of a prepared model (silk/model.h) */
} silk_load_opts;

/* Documented default crease angle; see docs/formats.md for how it was chosen. */
extern const silk_fx SILK_DEFAULT_CREASE_DEG;
void silk_load_opts_default(silk_load_opts *o);

/* Parse OBJ / PLY from memory.  name is used only in error messages.  The
 * result's arrays live in the arena (purposes MESH and ADJACENCY). */
silk_status silk_load_obj(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err);
silk_status silk_load_ply(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err);
/* STL, ascii or binary (told apart by the binary size, 84 + 50 n bytes).
 * Corners with bit-identical Q16.16 coordinates become one vertex. */
silk_status silk_load_stl(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err);
/* Picks the reader from the content: a prepared model's signature
 * (silk/model.h), "ply" magic, the size of a binary STL
 * or an ascii STL's "solid", else OBJ; binary data in a file whose name
 * ends in ".stl" is read as a (damaged) binary STL.  Files of other formats (glTF, FBX, 3DS,
 * OFF, compressed or archived files, binary data) fail with a line naming
 * what they are (docs/formats.md). */
silk_status silk_load_mesh(const void *data, size_t len, const char *name,
                           const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err);

/* The loaders' common back end: given pos/tri (and optional uv/tri_uv,
 * file normals, smoothing group per triangle) already in the arena, derive
 * edges, vertex->edge links, shading normals and feature flags. */
typedef struct silk_mesh_input {
    uint32_t nverts, ntris, nuvs, nfile_normals;
    silk_vec3 *pos;
    silk_index *tri;
    silk_vec2 *uv;            silk_index *tri_uv;          /* may be NULL */
    uint32_t *color;          /* nverts vertex colours 0xRRGGBB, or NULL */
    silk_vec3 *file_normal;   silk_index *tri_file_normal; /* may be NULL */
    uint32_t *tri_group;      /* OBJ smoothing group per triangle (0 = off), or NULL */
} silk_mesh_input;

silk_status silk_mesh_build(const silk_mesh_input *in, const char *name, const silk_load_opts *opts,
                            silk_arena *a, silk_mesh *out, silk_error *err);

/* ---- reading a mesh ------------------------------------------------------------
 * Every stage reads a mesh through these, so that a mesh held in arrays
 * (what the loaders build) and a compact model in flash (silk/compact.h,
 * decoded field by field in compact.c) draw alike.  Indices must be in
 * range: a mesh is checked once (silk_mesh_validate, silk_compact_mesh). */

silk_vec3  silk_packed_pos(const silk_mesh *m, silk_index v);
silk_vec3  silk_packed_normal(const silk_mesh *m, silk_index n);
silk_index silk_packed_corner(const silk_mesh *m, uint32_t c);
silk_index silk_packed_corner_normal(const silk_mesh *m, uint32_t c);
silk_index silk_packed_normal_vertex(const silk_mesh *m, silk_index n);
silk_edge  silk_packed_edge(const silk_mesh *m, silk_index e);
uint8_t    silk_packed_edge_flags(const silk_mesh *m, silk_index e);
void       silk_packed_edge_ends(const silk_mesh *m, silk_index e, silk_index v[2]);
void       silk_packed_edge_tris(const silk_mesh *m, silk_index e, silk_index t[2]);
silk_index silk_packed_tri_edge(const silk_mesh *m, uint32_t t, uint32_t k);

/* Whether the corners have shading normals (a loaded mesh always has). */
static inline int silk_mesh_has_corner_normals(const silk_mesh *m)
{
    return m->packed.base || m->tri_normal;
}

#if SILK_INLINE_ACCESS
/* Position of vertex v, model units. */
static inline silk_vec3 silk_mesh_pos(const silk_mesh *m, silk_index v)
{
    return m->packed.base ? silk_packed_pos(m, v) : m->pos[v];
}
/* Unit shading normal n. */
static inline silk_vec3 silk_mesh_normal(const silk_mesh *m, silk_index n)
{
    return m->packed.base ? silk_packed_normal(m, n) : m->normal[n];
}
/* The vertex of corner c (corner k of triangle t is c = 3t + k). */
static inline silk_index silk_mesh_corner(const silk_mesh *m, uint32_t c)
{
    return m->packed.base ? silk_packed_corner(m, c) : m->tri[c];
}
/* The shading normal of corner c. */
static inline silk_index silk_mesh_corner_normal(const silk_mesh *m, uint32_t c)
{
    return m->packed.base ? silk_packed_corner_normal(m, c) : m->tri_normal[c];
}
/* The vertex shading normal n belongs to. */
static inline silk_index silk_mesh_normal_vertex(const silk_mesh *m, silk_index n)
{
    return m->packed.base ? silk_packed_normal_vertex(m, n) : m->normal_vertex[n];
}
/* Edge e. */
static inline silk_edge silk_mesh_edge(const silk_mesh *m, silk_index e)
{
    return m->packed.base ? silk_packed_edge(m, e) : m->edge[e];
}
/* The vertices of edge e, v[0] < v[1]: what most stages need of an edge
 * (a compact model reads two corners for them, and no flags). */
static inline void silk_mesh_edge_ends(const silk_mesh *m, silk_index e, silk_index v[2])
{
    if (m->packed.base) {
        silk_packed_edge_ends(m, e, v);
    } else {
        v[0] = m->edge[e].v[0];
        v[1] = m->edge[e].v[1];
    }
}
/* The triangles of edge e (edge.t). */
static inline void silk_mesh_edge_tris(const silk_mesh *m, silk_index e, silk_index t[2])
{
    if (m->packed.base) {
        silk_packed_edge_tris(m, e, t);
    } else {
        t[0] = m->edge[e].t[0];
        t[1] = m->edge[e].t[1];
    }
}
/* Flags of edge e (enum silk_edge_flag). */
static inline uint8_t silk_mesh_edge_flags(const silk_mesh *m, silk_index e)
{
    return m->packed.base ? silk_packed_edge_flags(m, e) : m->edge[e].flags;
}

#else
/* Position of vertex v, model units. */
silk_vec3 silk_mesh_pos(const silk_mesh *m, silk_index v);
/* Unit shading normal n. */
silk_vec3 silk_mesh_normal(const silk_mesh *m, silk_index n);
/* The vertex of corner c (corner k of triangle t is c = 3t + k). */
silk_index silk_mesh_corner(const silk_mesh *m, uint32_t c);
/* The shading normal of corner c. */
silk_index silk_mesh_corner_normal(const silk_mesh *m, uint32_t c);
/* The vertex shading normal n belongs to. */
silk_index silk_mesh_normal_vertex(const silk_mesh *m, silk_index n);
/* Edge e. */
silk_edge silk_mesh_edge(const silk_mesh *m, silk_index e);
/* The vertices of edge e, v[0] < v[1]. */
void silk_mesh_edge_ends(const silk_mesh *m, silk_index e, silk_index v[2]);
/* The triangles of edge e (edge.t). */
void silk_mesh_edge_tris(const silk_mesh *m, silk_index e, silk_index t[2]);
/* Flags of edge e (enum silk_edge_flag). */
uint8_t silk_mesh_edge_flags(const silk_mesh *m, silk_index e);
#endif

/* Every edge index is below this: nedges for a mesh in arrays; 3 ntris for
 * a compact model, whose edge indices are the sides that own them (with
 * gaps: walk the edges with silk_mesh_edges_first/next). */
static inline uint32_t silk_mesh_edge_bound(const silk_mesh *m)
{
    return m->packed.base && m->nedges ? 3 * m->ntris : m->nedges;
}

/* The lower vertex of edge e. */
static inline silk_index silk_mesh_edge_v0(const silk_mesh *m, silk_index e)
{
    silk_index v[2];
    silk_mesh_edge_ends(m, e, v);
    return v[0];
}

/* The edge joining vertices a and b (SILK_NO_INDEX when there is none),
 * from the vertex-edge lists. */
silk_index silk_mesh_find_edge(const silk_mesh *m, silk_index a, silk_index b);

/* Edge k of triangle t, joining corners k and (k+1)%3: tri_edge's entry,
 * or, without tri_edge, the edge found from the two corners (a few
 * comparisons: what a packed mesh saves 2 index bytes a corner with), or
 * the compact model's corner table. */
static inline silk_index silk_mesh_tri_edge(const silk_mesh *m, uint32_t t, uint32_t k)
{
    if (m->packed.base) return silk_packed_tri_edge(m, t, k);
    const silk_index *c = &m->tri[3 * (size_t)t];
    return m->tri_edge ? m->tri_edge[3 * (size_t)t + k] : silk_mesh_find_edge(m, c[k], c[k == 2 ? 0 : k + 1]);
}

/* The edges at a vertex, one at a time:
 *     silk_mesh_ring r;
 *     for (silk_index e = silk_mesh_ring_first(m, v, &r); e != SILK_NO_INDEX; e = silk_mesh_ring_next(m, &r))
 * A mesh in arrays lists them from its vertex-edge lists, a compact model
 * turns about the vertex through its corner table (another order). */
typedef struct silk_mesh_ring {
    uint32_t i, end;          /* arrays: the place in vert_edge */
    uint32_t t0, t, side;     /* compact: the first triangle, the current one, the side to leave by */
    silk_index v;
    uint8_t phase;            /* compact: 0 forward, 1 backward, 2 the last boundary edge, 3 done */
} silk_mesh_ring;
silk_index silk_mesh_ring_first(const silk_mesh *m, silk_index v, silk_mesh_ring *r);
silk_index silk_mesh_ring_next(const silk_mesh *m, silk_mesh_ring *r);

/* Every edge in order, each into *ed (what a pass over all edges uses: a
 * compact model's edges one after another cost a few field reads each):
 *     silk_mesh_edges it;
 *     for (silk_index e = silk_mesh_edges_first(m, &it, &ed); e != SILK_NO_INDEX;
 *          e = silk_mesh_edges_next(m, &it, &ed)) */
typedef struct silk_mesh_edges {
    silk_index e;
    uint32_t t, k, list;      /* compact: the side of edge e, the next LIST record */
} silk_mesh_edges;
silk_index silk_mesh_edges_first(const silk_mesh *m, silk_mesh_edges *it, silk_edge *ed);
silk_index silk_mesh_edges_next(const silk_mesh *m, silk_mesh_edges *it, silk_edge *ed);

/* Whether edge e has a feature segment: a feature edge of nonzero length. */
static inline int silk_edge_has_feature(const silk_edge *e)
{
    return (e->flags & SILK_EDGE_FEATURE) && e->v[0] != e->v[1];
}

/* The Hermite tangents of edge e's feature segment into *out: 1, or 0 when
 * e has none. */
int silk_mesh_feature_seg(const silk_mesh *m, silk_index e, silk_feature_seg *out);

/* The feature segment of edge e (its index in feature[]), or SILK_NO_INDEX:
 * edge_feature's entry, or without it the number of feature segments before
 * e (segments are in edge order).  That count walks the edges before e, so
 * it is for the few feature edges a frame looks up, not for every edge. */
silk_index silk_mesh_edge_feature(const silk_mesh *m, uint32_t e);

/* Unit face normal of triangle t (zero vector for a degenerate triangle).
 * Computed in 64 bits, so tiny triangles keep their direction. */
silk_vec3 silk_mesh_face_normal(const silk_mesh *m, uint32_t t);

/* Bytes of the arena each part of the mesh takes (for `silk info`). */
typedef struct silk_mesh_bytes {
    size_t positions, normals, uvs, colors, triangles, edges, vertex_edges;
    size_t features;          /* edge_feature[] and feature[] */
    size_t total;
} silk_mesh_bytes;
void silk_mesh_bytes_used(const silk_mesh *m, silk_mesh_bytes *b);

#ifdef __cplusplus
}
#endif

#endif
