/*
 * plan.h - internal: the plan of a SMOOTH frame, the per-frame data the
 * silhouette stages pass to each other (paper section III-B..E), and
 * silhouette.c, which makes its first part.  Not installed.
 *
 *   silhouette.c  visibility, silhouette triangles, the edges that carry
 *                 points this frame (silhouette bridges, feature segments),
 *                 silhouette points and the sorted point chain of each edge
 *   remesh.c      silhouette segments, adaptive sampling, the re-meshing of
 *                 Figs. 11 and 12, and the emission of vertex records
 *   perturb.c     vertex perturbation next to concave silhouette segments
 *   smooth.c      runs the stages and degrades gracefully when memory runs out
 *
 * Crack-freeness rests on one rule: every point placed on a mesh edge lives
 * in that edge's chain, which is computed once per frame from per-edge data
 * only, and every triangle using the edge walks the whole chain.  Triangles
 * on the two sides of an edge may evaluate the chain on different curves
 * (their own normals and uvs) but with the same end points, tangents and
 * parameters, so the positions agree bit for bit.
 *
 * The plan is all a frame keeps between its stages: the carrying edges,
 * their points, the perturbation.  One emitter, silk_remesh_emit_tri,
 * builds one input triangle's share of the frame from it (its own copies
 * of the records and curves it uses).  The renderer draws share by share,
 * rebuilding each whenever a band needs it (silk_frame_smooth_plan); a
 * stored frame (silk_frame_smooth, which lines need) is every share
 * appended into one buffer.  The records evaluate to the same bits and the
 * triangles come in the same order either way, so the pictures are
 * identical.
 */
#ifndef SILK_PLAN_H
#define SILK_PLAN_H

#include "frame.h"
#include "curve.h"        /* SILK_MAX_SAMPLES */

#define SILK_SIL_NONE UINT32_MAX

/* A mesh index (vertex, normal, uv, edge) or a count the plan keeps: 16
 * bits where the build keeps the plan small (SILK_PLAN_INDEX16, a board's:
 * a plan of a mesh with more than it holds fails, and the frame falls
 * back), else silk_index.  SILK_PLAN_NONE is its SILK_NO_INDEX. */
#if SILK_PLAN_INDEX16
typedef uint16_t silk_plan_index;
#else
typedef silk_index silk_plan_index;
#endif
#define SILK_PLAN_NONE ((silk_plan_index)~(silk_plan_index)0)

/* tri_state bits */
enum {
    SILK_TS_LONE = 3,       /* mask: the corner whose visibility differs (silhouette triangles) */
    SILK_TS_BROKEN = 3,     /* the LONE field's spare value without SIL: silk_sil_tri_ok failed */
    SILK_TS_SIL = 4,        /* silhouette triangle: its corner normals disagree */
    SILK_TS_FRONT = 8,      /* front-facing (computed only for triangles with a feature side) */
    SILK_TS_CONCAVE = 16,   /* its silhouette segment is concave (III-E; set by remesh.c) */
    SILK_TS_CARRY0 = 32,    /* << k: side k lies on a carrying edge (whole triangles only) */
    SILK_TS_CARRY = 7 * SILK_TS_CARRY0   /* mask: any side; without it and SIL a triangle is drawn as it is */
};

/* A silhouette point (eqs. 6-7): one normal pair on one edge.  Its place
 * in the edge's chain is found by u (silk_sil_chain_index) rather than
 * stored: 8 bytes a point with 16-bit indices. */
typedef struct silk_sil_pair {
    silk_plan_index n0, n1;  /* normals at edge.v[0] and edge.v[1] */
    silk_fx u;               /* parameter from edge.v[0] */
} silk_sil_pair;

/* One triangle side lying on a carrying edge, as that triangle sees the
 * edge.  Sides with the same normals and uvs evaluate the edge's points to
 * the same records. */
typedef struct silk_sil_side {
    uint32_t tri;
    uint32_t k;              /* side k joins corners k and (k+1)%3 */
    silk_plan_index n0, n1;  /* normals at edge.v[0], edge.v[1] */
    silk_plan_index uv0, uv1; /* uvs there, or SILK_PLAN_NONE */
} silk_sil_side;

/* An edge that carries points this frame.  Its curve runs from edge.v[0] to
 * edge.v[1], exactly through the two vertices, with the tangents of its
 * feature segment or of the bridge over its first silhouette point: both
 * follow from the mesh and the edge's points, so silk_sil_edge_curve makes
 * the curve when it is asked for instead of keeping 24 bytes of tangents
 * per edge.  The per-edge counts are 16 bits (an edge with more sides than
 * SILK_SIL_SIDES_MAX makes the plan fail, and the frame falls back), the
 * frame's points and parameters are counted in silk_plan_index (more of
 * them than it holds fails the same way) and nfeat is at most
 * SILK_MAX_SAMPLES: 14 bytes an edge with 16-bit indices, 20 with 32-bit. */
typedef struct silk_sil_edge {
    silk_plan_index pair0;   /* its silhouette points: pairs[pair0 .. pair0 + npairs) */
    silk_plan_index chain0;  /* its interior parameters, ascending, distinct: chain[chain0 .. chain0 + nchain) */
    silk_plan_index edge;    /* mesh edge index */
    uint16_t npairs, nchain;
    uint16_t nsides;         /* triangle sides on this edge */
    uint8_t nfeat;           /* feature sampling intervals (0: not sampled) */
    _Bool is_feature : 1;
    _Bool sampled : 1;       /* a visible feature edge: sampled by eq. 8 */
} silk_sil_edge;

/* The most sides one carrying edge may have: its chain (nfeat - 1 samples
 * and a point per side at most) then fits nchain. */
#define SILK_SIL_SIDES_MAX (UINT16_MAX - SILK_MAX_SAMPLES)

/* The silhouette segment of one silhouette triangle (III-D) and its samples. */
typedef struct silk_sil_seg {
    silk_curve c;            /* A -> B with normals and uvs at the silhouette points */
    uint32_t tri;
    uint32_t n;              /* sampling intervals (eq. 8) */
    uint32_t split;          /* sample joined to both base vertices (Fig. 11) */
    int concave;             /* III-E: N_A.F > 0 and N_B.F < 0 */
    silk_vec3 m, nm;         /* S(1/2) and its normal: the plane P_i of III-E (concave only, else zero) */
    silk_fx rise;            /* how far the segment's ends rise above P_i (the same) */
} silk_sil_seg;

/* Edge tangents kept by silk_sil_edge_curve: the three sides of the
 * triangle being emitted. */
#define SILK_SIL_TAN_MEMO 3

/* What the stages that read a plan remember between their questions, so
 * that asking again is cheap: the memos.  The plan itself is read-only once
 * made; its maker hands it a cursor (silk_sil_frame.cur), which the
 * emitter and the outline then own and write, the plan's const
 * notwithstanding.  None of it changes an answer, only what it costs. */
typedef struct silk_sil_cursor {
    /* silk_sil_side_edge: the last triangle asked for + 1 (0: none) and its three sides' edges */
    uint32_t side_tri1;
    struct silk_sil_edge *side_edge[3];
    /* silk_sil_edge_curve: the tangents of the last few edges asked for */
    const struct silk_sil_edge *tan_edge[SILK_SIL_TAN_MEMO];
    silk_vec3 tan[SILK_SIL_TAN_MEMO][2];
    uint32_t tan_next;
    /* silk_remesh_kept_index: the kept segment found last */
    uint32_t kept_last;
    /* silk_sil_pair_point, with the kept segments (silk_remesh_keep): each
     * silhouette point's position and normal, 2 per pair, once
     * pair_ready[i]; NULL when not kept */
    silk_vec3 *pair_pn;
    uint8_t *pair_ready;
} silk_sil_cursor;

/* What the plan keeps for speed where the arena has room, none of it part
 * of the frame's need (silk_sil_kept): the carrying edges' rank
 * (SILK_CARRY_RANK, silk_sil_frame.carry_rank) and the segments
 * (SILK_KEEP_SEGMENTS, silk_remesh_keep), seg_kept[i] that of silhouette
 * triangle seg_tri[i], ascending, as silk_remesh_plan made it.  kept_bytes
 * is the arena they take, kept_need what the frame needed before them (0:
 * nothing kept); room the most they may take, set by the caller of the
 * plan, the one field it sets.  The frame that draws share by share owns
 * it (render.c): a build without those shortcuts has none, and a small
 * part's stack does not hold it. */
typedef struct silk_sil_keep {
    size_t room;
    silk_sil_seg *seg_kept;
    uint32_t *seg_tri;
    uint32_t nseg_kept;
    struct sil_layout *lay_kept;   /* with them: where their points lie on their triangle's boundary (remesh.c) */
    size_t kept_bytes, kept_need;
    uint64_t kept_recs, kept_tris, kept_curves;   /* what the kept segments' shares hold in all */
} silk_sil_keep;

typedef struct silk_sil_frame {
    silk_arena *a;
    const silk_mesh *m;
    const silk_view *v;
    silk_fx tol;
    silk_vis_method vis;

    uint8_t *visible;        /* nnormals, while silhouette.c finds the triangles (NULL after) */
    uint8_t *tri_state;      /* ntris, SILK_TS_*; read only after silhouette.c */
    uint8_t *carrying;       /* nedges bits: the edges that carry points (find them with silk_sil_slot) */
    uint32_t nsil;

    silk_sil_edge *edges;  uint32_t nedges;   /* in mesh edge order */
    silk_sil_pair *pairs;  uint32_t npairs;
    uint32_t nsides;         /* triangle sides on carrying edges */
    silk_fx *chain;        uint32_t nchain;
    uint32_t nsegs;          /* silhouette segments (rebuilt where needed: silk_remesh_seg) */
    uint64_t store_recs, store_curves;   /* what a stored frame holds (its triangles: out_tris) */
    uint32_t max_poly;       /* longest boundary of one re-meshed triangle */
    uint32_t *poly;          /* 2 * max_poly: scratch for one triangle's boundary */
    /* the most one input triangle's share holds, and the frame's totals */
    uint32_t max_recs, max_tris, max_curves;
    uint32_t out_tris, seg_samples;

    /* perturbation (perturb.c) */
    uint32_t near_bound;     /* vertices next to a concave segment: one slot each */
    silk_plan_index *vert_slot;   /* nverts: perturbation slot, or SILK_PLAN_NONE */
    silk_vec3 *acc;          /* per slot: sum of plane normals, then the unit R */
    silk_fx *lift;           /* per slot: how far to move down along R (silk_perturb only, then NULL) */
    silk_plan_index *slot_vert;   /* per slot: its vertex (the same) */
    uint32_t *slot_stamp, nslots;   /* (the same) */
    silk_plan_index *vert_offset; /* nverts view of vert_slot after perturbation: offset index, or SILK_PLAN_NONE */
    silk_vec3 *offset;     uint32_t noffset;   /* the offsets, in acc's memory */

    silk_stage_clock *clock; /* per-stage timing (include/silk/render.h), or NULL */

    /* Edge tangents (silk_sil_edge_curve), last: the fields above are read
     * far more often, and a small part's short loads reach only the first
     * few dozen words. */
    silk_vec3 *tan_kept;     /* 2 per carrying edge of the first ntan_kept (silk_sil_keep_tangents) */
    uint32_t ntan_kept;
    /* the memos of those who read the plan, its maker's (silk_sil_cursor):
     * never NULL from silk_sil_find on */
    silk_sil_cursor *cur;
    /* what it keeps for speed, or NULL: nothing (a stored frame, a build
     * without the shortcuts); the carrying edges' rank, per byte of
     * carrying the carrying edges before it, or NULL (silk_sil_slot) */
    silk_sil_keep *keep;
    uint32_t *carry_rank;
    /* concave segments the perturbation left to the coarse outline
     * (silk_frame_stats.flat_segments), and whether the one being visited
     * is such (perturb.c) */
    uint32_t flat_segs;
    uint8_t refused;
} silk_sil_frame;

/* Whether the plan keeps anything for speed: a build with SILK_KEEP_SEGMENTS
 * or SILK_CARRY_RANK whose caller gave it the room (f->keep). */
#define SILK_SIL_KEEPS (SILK_KEEP_SEGMENTS || SILK_CARRY_RANK)

/* Counts what the plan took from the arena since it had free0 bytes free
 * and the high-water peak as kept for speed (f->keep: kept_bytes, kept_need). */
void silk_sil_kept(silk_sil_frame *f, size_t free0, size_t peak);

/* Whether the plan may keep want more bytes for speed with free0 free: a
 * sixteenth at most, and a mebibyte left, so that what the frame still
 * takes after the plan (a band's rows, the outline's scratch) finds the
 * room it finds without them.  A plan that then does not fit is made
 * again without (render.c). */
static inline int silk_sil_keep_fits(size_t want, size_t free0)
{
    return want <= free0 / 16 && free0 - want >= ((size_t)1 << 20);
}

/* silhouette.c: fills visible .. chain, f->cur set by the caller (and
 * emptied here).  SILK_ERR_NOMEM when scratch runs out. */
silk_status silk_sil_find(silk_sil_frame *f);
/* Whether triangle t is whole (its corners, normals and edges index the
 * mesh): only those are smoothed, and only their sides are counted. */
int silk_sil_tri_ok(const silk_mesh *m, uint32_t t);
/* tri, k, normals and uvs of triangle t's side k on mesh edge e, from the
 * mesh. */
void silk_sil_side_attrs(const silk_mesh *m, uint32_t t, uint32_t k, silk_index v0, silk_sil_side *s);
/* The curve of edge e: its vertices, its tangents; normals and uvs zero.
 * The tangents are read from tan_kept where kept, else computed (a bridge, or the
 * feature segment's) and the last few kept in the frame's memo; the plan
 * changes nothing they depend on once silk_sil_find has filled the points. */
void silk_sil_edge_curve(const silk_sil_frame *f, const silk_sil_edge *e, silk_curve *c);
/* The tangents of the carrying edges into the arena, as many as room (the
 * most it may take) holds, so that silk_sil_edge_curve reads them instead
 * of making them: the same bits, faster.  Returns the bytes taken (0:
 * none). */
size_t silk_sil_keep_tangents(silk_sil_frame *f, size_t room);
/* Position, normal and uv of point u on edge e as side s sees it (what the
 * HAL computes for the record). */
void silk_sil_edge_point(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s,
                         silk_fx u, silk_vec3 *p, silk_vec3 *n, silk_vec2 *uv, uint32_t *rgb);
/* silk_sil_edge_point at the silhouette point of pair pr (side s's, on
 * edge e): its position and normal, the same for both sides that share
 * the point, made once a frame where kept (pair_pn), its uv and colour
 * the side's. */
void silk_sil_pair_point(const silk_sil_frame *f, const silk_sil_edge *e, const silk_sil_side *s,
                         const silk_sil_pair *pr, silk_vec3 *p, silk_vec3 *n, silk_vec2 *uv, uint32_t *rgb);
/* Vertex colour at parameter u along mesh edge e (white without colours). */
uint32_t silk_sil_edge_rgb(const silk_mesh *m, const silk_edge *e, silk_fx u);

/* Whether triangle t faces the eye, by its face normal (what decides which
 * feature edges are sampled, and the coarse outline of lines.c); a
 * zero-area or broken triangle faces nowhere. */
int silk_sil_tri_front(const silk_mesh *m, const silk_view *v, uint32_t t);

/* silk_sil_tri_front of every triangle into facing, two bits each (2 | front,
 * four triangles a byte, silk_aa.facing's layout): one loop that keeps the
 * per-call work out of it (SILK_AA_CANDIDATES). */
void silk_sil_tri_fronts(const silk_mesh *m, const silk_view *v, uint8_t *facing);

/* Eq. 8 for curve c: the number of intervals to sample it with, from its
 * projected chord in pixels and cos alpha (see silhouette.c for why the
 * chord). */
uint32_t silk_sil_intervals(const silk_view *v, const silk_curve *c, silk_fx cos_alpha, silk_fx tol);

/* The slot of mesh edge `edge` in edges[], or SILK_SIL_NONE: a bit, then a
 * binary search of the carrying edges (a bit per mesh edge instead of a
 * slot index: the plan's RAM), or the count of carrying edges before it
 * where their rank is kept (carry_rank, SILK_CARRY_RANK). */
static inline uint32_t silk_sil_slot(const silk_sil_frame *f, uint32_t edge)
{
    if (!(f->carrying[edge >> 3] & (1u << (edge & 7)))) return SILK_SIL_NONE;
    if (SILK_CARRY_RANK && f->carry_rank) {
        unsigned below = f->carrying[edge >> 3] & ((1u << (edge & 7)) - 1);
        /* the bits of a byte by nibbles (__builtin_popcount is a library call without a popcount instruction) */
        static const uint8_t bits[16] = { 0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4 };
        return f->carry_rank[edge >> 3] + bits[below & 15] + bits[below >> 4];
    }
    uint32_t lo = 0, hi = f->nedges;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (f->edges[mid].edge < edge) lo = mid + 1; else hi = mid;
    }
    return lo < f->nedges && f->edges[lo].edge == edge ? lo : SILK_SIL_NONE;
}

/* The carrying edge side k of triangle t lies on, or NULL: most sides are
 * on none, and their tri_state bit says so without looking the edge up.
 * The emitter asks for the same triangle's sides again and again, so the
 * last triangle's three are kept (in the cursor). */
static inline silk_sil_edge *silk_sil_side_edge(const silk_sil_frame *f, uint32_t t, uint32_t k)
{
    if (!(f->tri_state[t] & (SILK_TS_CARRY0 << k))) return NULL;
    silk_sil_cursor *memo = f->cur;
    if (memo->side_tri1 != t + 1) {
        memo->side_tri1 = t + 1;
        for (uint32_t j = 0; j < 3; j++) {
            uint32_t w = f->tri_state[t] & (SILK_TS_CARRY0 << j) ? silk_sil_slot(f, silk_mesh_tri_edge(f->m, t, j))
                                                                 : SILK_SIL_NONE;
            memo->side_edge[j] = w == SILK_SIL_NONE ? NULL : &f->edges[w];
        }
    }
    return memo->side_edge[k];
}

/* The index of parameter u in the ascending chain c[0 .. n): where a
 * silhouette point lies in its edge's chain (a chain holds a few points). */
static inline uint32_t silk_sil_chain_index(const silk_fx *c, uint32_t n, silk_fx u)
{
    uint32_t i = 0;
    while (i < n && c[i] < u) i++;
    return i;
}

/* Whether mesh edge `edge` carries points this frame. */
static inline int silk_sil_chained(const silk_sil_frame *f, uint32_t edge)
{
    uint32_t w = silk_sil_slot(f, edge);
    return w != SILK_SIL_NONE && f->edges[w].nchain > 0;
}

#endif
