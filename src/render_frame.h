/*
 * render_frame.h - internal: the frame that silk_render and
 * silk_render_bands draw (render.c), shared by the files that draw it.
 * Not installed.
 *
 *   render.c        the entry points, the per-mode table, a frame's
 *                   preparation and the band loop
 *   frame_shares.c  frames drawn share by share: an input triangle's share
 *                   rebuilt and put through the vertex stage when a band
 *                   needs it
 *   frame_fast.c    what a frame keeps for speed where the arena has room:
 *                   the vertex cache and the triangles drawn straight from
 *                   it, the kept shares, which triangles won a depth
 *   frame_cull.c    what need not be drawn: back faces that cannot show,
 *                   the rows each share can reach
 *   frame_draw.c    one band's triangles, --wire's edges and the lines
 *   frame_aa.c      the anti-aliased outlines over a band just drawn
 *
 * Each file's functions carry its prefix (silk_shares_, silk_fast_,
 * silk_cull_, silk_draw_, silk_outline_).
 */
#ifndef SILK_RENDER_FRAME_H
#define SILK_RENDER_FRAME_H

#include <string.h>
#include "smooth.h"
#include "remesh.h"
#include "lines.h"
#include "stages.h"
#include "clip.h"
#include "aa.h"
#include "compiler.h"
#include "silk/siltex.h"
#include "raster_place.h"
#include "phong_parts.h"

/* What a frame keeps for speed where the arena has room, for the
 * shortcuts that take it (silk/config.h: SILK_VERTEX_CACHE,
 * SILK_DRAW_DIRECT, SILK_KEEP_SHARES, SILK_DEPTH_WINS, SILK_BACK_FACES_LAST,
 * SILK_AA_CANDIDATES, and the plan's SILK_KEEP_SEGMENTS and
 * SILK_CARRY_RANK): a field is NULL or 0 where it took none.  A build
 * without any of them has no frame_fast: silk_render's is compiled away,
 * and a small part's stack does not hold it (FRAME_FAST). */
typedef struct frame_fast {
    /* The vertex cache of a frame drawn share by share (silk_fast_vertex_cache),
     * or NULL: slot s holds the vertex stage's output for the corner
     * whose normal, vertex and uv are vc_tag[3s .. 3s+2]. */
    silk_vertex_out *vc;
    uint32_t *vc_tag;
    uint32_t vc_mask;
    uint8_t *cand;            /* closed mesh: silk_aa_candidates' bits, or NULL */
    uint8_t cand_ready;       /* made (by the first band's silk_outline_draw) */
    /* SMOOTH: the shares that silk_fast_draw_direct does not draw as first built
     * (silk_fast_keep_shares): input triangle t's at ks + ks_at[t] - 1, ks_at[t] 0
     * until it is built */
    uint8_t *ks;
    uint32_t *ks_at;
    size_t ks_cap, ks_used;
    /* where g's arrays, the cache and the curves are when a share is built
     * (a kept share is read where it is kept: share_view) */
    silk_frame_geom home;
    silk_vertex_out *home_cache;
    /* the share in g as kept: where its records are placed, once *kxy_ready
     * (frame_draw.c's draw_tris); NULL when it is not kept */
    int32_t (*kxy)[2];
    uint32_t *kxy_ready;
    /* FLAT, and SMOOTH's input triangles drawn as they are (direct_ok):
     * where the rasterizer places the mesh's vertex p (position index),
     * vc_xy[2p .. 2p+1] (silk_raster_place), or VC_OUTSIDE (clipped), and
     * the vertex stage's clip coordinates of it, vc_clip[p], once xy_ready
     * (silk_fast_place_vertices); NULL when the triangles are not drawn straight from
     * the cache (silk_fast_draw_direct) */
    int32_t *vc_xy;
    silk_vec4 *vc_clip;
    uint8_t xy_ready;
    uint8_t all_before;       /* every vertex so placed lies in front of the near plane (before_near) */
    /* SMOOTH with a depth pass: per part, which of its triangles wrote a
     * depth in it (depth_wins), or NULL; and the back faces of its
     * re-meshed parts it draws last (silk_fast_back_last), room for back_cap */
    uint32_t *won;
    struct back_tri *back;
    uint32_t back_cap, nback;
    silk_sil_keep keep;       /* SMOOTH: what the plan keeps (silk_sil_frame.keep) */
} frame_fast;

/* Whether the build has a frame_fast: any of its shortcuts. */
#define FRAME_FAST (SILK_VERTEX_CACHE || SILK_DRAW_DIRECT || SILK_KEEP_SHARES || SILK_DEPTH_WINS || \
                    SILK_BACK_FACES_LAST || SILK_AA_CANDIDATES || SILK_SIL_KEEPS)

/* SILTEX: the hull drawn through the silhouette texture by these stages
 * (siltex.c), which kill the pixels where the detailed model is not seen.
 * silk_render's, compiled away without SILK_SILTEX_MODE. */
typedef struct frame_siltex {
    silk_hal hal;
    silk_siltex_stage stage;
} frame_siltex;

/* How a frame is drawn in parts (frame.nparts): a stored frame is one part,
 * all there (PN, BLEND, and FLAT and SMOOTH with lines); a frame drawn
 * share by share has its input triangles' shares as parts, each rebuilt
 * when a band needs it (frame_shares.c). */
typedef enum frame_parts {
    FRAME_STORED = 0,
    FRAME_SHARES = 1
} frame_parts;

/* A frame ready to rasterize: geometry plus the vertex stage's output. */
typedef struct frame {
    const silk_hal *hal;
    silk_geom geom;
    silk_frame_geom g;
    silk_vertex_out *cache;   /* NULL when the arena could not hold it */
    silk_vertex_out *line_cache;   /* the same for the lines' records */
    uint32_t *line_lift;      /* per line record (lines.c), or NULL */
    /* A frame is drawn in nparts parts, frame_part(f, k) filling g and
     * cache with part k (frame_parts says how) */
    uint32_t nparts;
    frame_parts parts;
    silk_stage_clock *clock;  /* per-stage timing, or NULL */
    uint8_t *rows;            /* per part: first and last row it can reach, in units of row_unit, or NULL */
    int row_unit;             /* rows a unit of rows[] spans (silk_cull_rows) */
    silk_clip *clip;          /* CLIP: the outline and its stencil (clip.c), else NULL */
    frame_siltex *siltex;     /* SILTEX: its stages, else NULL */
    frame_fast *fast;         /* what it keeps for speed, or NULL: a build without the shortcuts */
    uint8_t *facing;          /* silk_aa.facing for silk_outline_draw, or NULL */
    size_t vc_bytes;          /* the arena the vertex cache, the facing memo and the rest of fast take */
    size_t tan_bytes;         /* the arena the kept edge tangents take (silk_fast_keep_tangents) */
    size_t peak_before;       /* the arena's top high-water before those */
    size_t reserve;           /* what a band's outline takes (render.c, outline_reserve): those leave it free */
    uint8_t smooth;           /* SMOOTH's plan made (else the coarse mesh's shares) */
    uint8_t cull;             /* back faces cannot show (silk_cull_back_faces) */
    uint8_t plain;            /* SMOOTH: the part drawn last is its input triangle as it is (bytes: the
                                 frame is on a small board's stack) */
    uint8_t in_scene;         /* one object of a scene (scene.c): the scene clears the band, not silk_draw_frame */
    uint8_t after;            /* drawn after another object into the same depth: no depth pass (silk_draw_frame) */
    silk_sil_frame sil;       /* SMOOTH: the plan (last: the fields above are read more often) */
    silk_sil_cursor cur;      /* SMOOTH: the emitter's memos over it (sil.cur) */
} frame;

/* Whether f is a CLIP frame, a SILTEX one: never in a build without the mode. */
#define CLIP_FRAME(f) (SILK_CLIP_MODE && (f)->clip != NULL)
#define SILTEX_FRAME(f) (SILK_SILTEX_MODE && (f)->siltex != NULL)
/* Whether frame f has a vertex cache (silk_fast_vertex_cache). */
#define VERTEX_CACHED(f) (SILK_VERTEX_CACHE && (f)->fast->vc != NULL)
#define VC_OUTSIDE INT32_MIN         /* vc_xy: outside a clip plane */

/* The vertex stage for CORNER record r, through the vertex cache: the
 * default stage's output is a function of the corner's normal, vertex and
 * uv (silk_hal_vertex_by_attrs), so the corners of the six or so triangles
 * around a vertex are evaluated once, not once each.  The cache is
 * direct-mapped on the normal index: neighbouring triangles come close
 * together in a mesh, and a miss only costs the evaluation.  corner_slot
 * returns the slot holding the output for corner a (record r, or when r is
 * NULL the corner's own CORNER record, as silk_frame_flat_emit_tri makes
 * it), UINT32_MAX for a corner without a usable normal (not cached).
 * With clip not NULL, a miss takes the corner's clip coordinates from
 * there (silk_fast_draw_direct's, placed) and runs only the rest of the stage. */
SILK_ALWAYS_INLINE   /* every corner of a streamed frame: inline in silk_shares_part, as a call it costs a tenth more */
static inline uint32_t corner_slot(const frame *f, uint32_t a, const silk_vrec *r, const silk_vec4 *clip)
{
    const silk_mesh *m = f->geom.mesh;
    frame_fast *x = f->fast;
    uint32_t n;
    if (a / 3 >= m->ntris || (n = silk_mesh_corner_normal(m, a)) >= m->nnormals) return UINT32_MAX;
    uint32_t v = silk_mesh_corner(m, a), uv = m->tri_uv ? m->tri_uv[a] : SILK_NO_INDEX;
    uint32_t s = n & x->vc_mask, *tag = &x->vc_tag[3 * s];
    if (tag[0] != n || tag[1] != v || tag[2] != uv) {
        const silk_vrec own = { SILK_VREC_CORNER, a, 0, 0 };
        if (SILK_DRAW_DIRECT && clip) {
            x->vc[s].clip = *clip;
            silk_hal_vertex_varyings(&f->geom, &own, &x->vc[s]);
        } else {
            f->hal->vertex(f->hal, &f->geom, r ? r : &own, &x->vc[s]);
        }
        tag[0] = n;
        tag[1] = v;
        tag[2] = uv;
    }
    return s;
}

/* Whether input triangle k may be drawn by silk_fast_draw_direct: in FLAT every one;
 * in SMOOTH one away from the silhouette, neither on it nor carrying its
 * points, with no vertex moved, whose share is its three CORNER records
 * (silk_remesh_emit_tri), drawn with back faces culled (silk_draw_frame) as
 * silk_fast_draw_direct does. */
static inline int direct_ok(const frame *f, uint32_t k)
{
    if (!f->smooth) return 1;
    const silk_sil_frame *s = &f->sil;
    if (s->tri_state[k] & (SILK_TS_SIL | SILK_TS_CARRY)) return 0;
    const silk_mesh *m = f->geom.mesh;
    const silk_plan_index *vo = s->vert_offset;
    return !vo || (vo[silk_mesh_corner(m, 3 * k)] == SILK_PLAN_NONE && vo[silk_mesh_corner(m, 3 * k + 1)] == SILK_PLAN_NONE &&
                   vo[silk_mesh_corner(m, 3 * k + 2)] == SILK_PLAN_NONE);
}

/* Whether part k can reach no row of y0 .. y1 (silk_cull_rows). */
static inline int part_misses(const frame *f, uint32_t k, int y0, int y1)
{
    if (!f->rows) return 0;
    int u = f->row_unit;
    return f->rows[2 * k] * u > y1 || f->rows[2 * k + 1] * u + u - 1 < y0;
}

/* ---- frame_shares.c ---- */
/* Whether options o draw their frame share by share (FLAT, SMOOTH and CLIP
 * without lines). */
static inline int silk_shares_wanted(const silk_render_opts *o)
{
    return o->lines == SILK_LINES_NONE &&
           (o->mode == SILK_MODE_FLAT || o->mode == SILK_MODE_SMOOTH || o->mode == SILK_MODE_CLIP);
}
/* Input triangle t's share into f->g, through the vertex stage into f->cache. */
void silk_shares_part(frame *f, uint32_t t);

/* Part k of f into f->g and f->cache: a stored frame's one part is there already. */
static inline void frame_part(frame *f, uint32_t k)
{
    if (f->parts == FRAME_SHARES) silk_shares_part(f, k);
}

/* ---- frame_fast.c ---- */
/* The arena free beyond the outline's reserve. */
static inline size_t silk_fast_spare(const frame *f, const silk_arena *a)
{
    size_t free_bytes = silk_arena_free_bytes(a);
    return free_bytes > f->reserve ? free_bytes - f->reserve : 0;
}
void silk_fast_vertex_cache(frame *f, silk_arena *a, const silk_render_opts *o);
void silk_fast_keep_shares(frame *f, silk_arena *a, const silk_render_opts *o);
/* Input triangle t's share as kept, into f->g and f->cache: 1, or 0 when it
 * is not kept (then g and cache point where a share is built). */
int silk_fast_kept_view(frame *f, uint32_t t);
/* The share of t just built kept, where it is to be and there is room. */
void silk_fast_kept_store(frame *f, uint32_t t);
void silk_fast_depth_wins(frame *f, silk_arena *a, const silk_render_opts *o, const silk_target *t);
int silk_fast_back_last(frame *f, const silk_target *t, const int32_t *const p[3], const uint32_t c[3], uint32_t part,
                        uint32_t bit);
void silk_fast_back_draw(frame *f, silk_target *t);
void silk_fast_place_vertices(frame *f, const silk_target *t);
int silk_fast_draw_direct(frame *f, silk_target *t, const silk_hal *shade, uint32_t k);

/* ---- frame_cull.c ---- */
int silk_cull_back_faces(const frame *f, const silk_hal *h, const silk_render_opts *o);
void silk_cull_rows(frame *f, const silk_render_opts *o, const silk_target *band);

/* ---- frame_draw.c ---- */
void silk_draw_frame(frame *f, const silk_render_opts *o, silk_target *t);
/* SILTEX: the hull's front faces into s (frame_aa.c's outline), through
 * stage h, or depth alone (h NULL). */
void silk_draw_hull(frame *f, const silk_render_opts *o, silk_target *s, const silk_hal *h);

/* ---- frame_aa.c ---- */
/* Whether silk_outline_draw anti-aliases the outline of frame f in band t
 * with silk_aa_begin's scratch: not with wire, not a stored frame's, not
 * where there is no depth, not siltex's with lines (its fragment stage
 * draws them, aliased).  (Clip mode's is its own, clip.c.)  Out of line:
 * render.c asks it too, for the room the outline takes. */
int silk_outline_wanted(const frame *f, const silk_render_opts *o, const silk_target *t);
void silk_outline_facing(frame *f, silk_arena *a, const silk_render_opts *o);
void silk_outline_draw(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_target *t,
                       silk_frame_stats *stats);
/* Frame f's outlines walked into aa, begun over the band just drawn
 * (silk_outline_draw; scene.c walks every object's into one): its
 * shares', or SILTEX's found in the band. */
void silk_outline_walk(frame *f, silk_arena *a, const silk_view *v, const silk_render_opts *o, silk_aa *aa,
                       silk_frame_stats *stats);

#endif
