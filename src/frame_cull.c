/*
 * frame_cull.c - what a frame need not draw, known before drawing it: back
 * faces that cannot show (a closed mesh seen from outside), and the rows
 * each input triangle's share can reach, so that a band rebuilds only the
 * shares that reach into it and none a share that draws nothing.
 */
#include "render_frame.h"

/* Whether point p lies in front of the near plane as the rasterizer clips:
 * z >= -w (raster.c), strictly. */
SILK_CPU32_NOINLINE static int before_near(const silk_view *v, silk_vec3 p)   /* (two callers: one copy on a small part) */
{
    silk_vec4 c = silk_view_clip(v, p);
    return c.w > 0 && (int64_t)c.z + c.w > 0;
}

/* Whether the sphere about the bounding box's centre through the farthest
 * vertex lies in front of the near plane (eye depth znear, in perspective
 * and orthographic alike), by a margin far above the rounding of
 * silk_view_clip: then every vertex does, at a fraction of the cost of
 * transforming each. */
static int sphere_before_near(const silk_mesh *m, const silk_view *v)
{
    int64_t c[3] = { ((int64_t)m->bbox_min.x + m->bbox_max.x) / 2, ((int64_t)m->bbox_min.y + m->bbox_max.y) / 2,
                     ((int64_t)m->bbox_min.z + m->bbox_max.z) / 2 };
    uint64_t r2 = 0;   /* coordinates below 2^26: each square below 2^54 */
    for (uint32_t i = 0; i < m->nverts; i++) {
        int64_t dx = silk_mesh_pos(m, i).x - c[0], dy = silk_mesh_pos(m, i).y - c[1], dz = silk_mesh_pos(m, i).z - c[2];
        uint64_t d2 = (uint64_t)(dx * dx) + (uint64_t)(dy * dy) + (uint64_t)(dz * dz);
        if (d2 > r2) r2 = d2;
    }
    int64_t r = (int64_t)silk_isqrt64(r2) + 1;
    const silk_vec3 *e = &v->cam.eye, *fw = &v->forward;
    int64_t depth = ((c[0] - e->x) * fw->x + (c[1] - e->y) * fw->y + (c[2] - e->z) * fw->z) >> 16;
    int64_t margin = (r >> 10) + (int64_t)(silk_abs64(depth) >> 10) + (v->cam.znear >> 10) + 256;
    return depth - r - margin > v->cam.znear;
}

/* Whether the frame's back faces cannot show, so the rasterizer may skip
 * them.  A closed surface wound outward (silk_mesh.closed_outward) seen
 * from outside hides its back faces behind its front faces: along any ray
 * from the eye the first crossing enters the solid, through a front face,
 * and is the nearest.  The rasterizer's snapped triangles still form a
 * closed surface in screen x, y and depth, so this holds pixel for pixel.
 * The eye is outside when the whole mesh lies in front of the near plane
 * (then also no triangle is cut open by it): its bounding box or the
 * sphere about the box's centre through the farthest vertex when that does
 * (a camera fitted to the bounding sphere may cut the box's corners), else
 * every vertex as the vertex stage projects it; the default vertex stage's
 * view tells where the mesh goes (a stage of the caller's own may move or
 * mirror it).  FLAT, and in SMOOTH frames drawn share by share only the
 * input triangles drawn as they are (silk_draw_frame): SMOOTH re-meshes and
 * moves vertices near the silhouette, where the outline is made of both
 * sides, so those triangles are all drawn (skipping a re-meshed part seen
 * wholly from behind changed pixels of self-intersecting meshes, which a
 * board must draw as the host does); PN and BLEND bulge. */
int silk_cull_back_faces(const frame *f, const silk_hal *h, const silk_render_opts *o)
{
    const silk_mesh *m = f->geom.mesh;
    const silk_view *v = silk_hal_vertex_view(h);
    if (!m->closed_outward || !v || (o->mode != SILK_MODE_FLAT && f->parts != FRAME_SHARES)) return 0;
    int corners_before = 1;   /* the bounding box's: then every vertex is */
    for (int i = 0; corners_before && i < 8; i++)
        corners_before = before_near(v, silk_v3(i & 1 ? m->bbox_max.x : m->bbox_min.x,
                                                i & 2 ? m->bbox_max.y : m->bbox_min.y,
                                                i & 4 ? m->bbox_max.z : m->bbox_min.z));
    if (corners_before) return 1;
    /* every vertex placed already (frame_extras): by the same stage, so the
     * answer of the loop below, without another pass over the mesh */
    if (SILK_DRAW_DIRECT && f->fast->xy_ready && f->hal == h) return f->fast->all_before;
    if (sphere_before_near(m, v)) return 1;
    for (uint32_t i = 0; i < m->nverts; i++)
        if (!before_near(v, silk_mesh_pos(m, i))) return 0;
    return 1;
}

/* Whether the part just built draws nothing in any band: silk_draw_frame culls
 * back faces for it (a plain share, or any share of a FLAT frame: one
 * triangle of corners) and silk_raster_culled says its triangle is culled
 * or outside the view.  Only where silk_draw_frame is all that draws the parts
 * (no outline anti-aliasing, wire, lines, stencil or SILTEX), so that a
 * band need not rebuild it. */
static int part_hidden(const frame *f, const silk_render_opts *o, const silk_target *band)
{
    int aa = SILK_AA ? o->aa : 0;   /* (a build without them: o->aa draws nothing) */
    if (!f->cull || (f->smooth && !f->plain) || f->g.ntri != 1 || aa || o->wire || o->lines || SILTEX_FRAME(f) || CLIP_FRAME(f))
        return 0;
    const uint32_t *c = f->g.tri;
    return silk_raster_culled(band, &f->cache[c[0]], &f->cache[c[1]], &f->cache[c[2]]);
}

/* The rows each input triangle can reach.  Everything drawn for it lies in
 * the screen triangles of its share's records, so between their highest and
 * lowest row; one row more on each side covers the rasterizer's rounding to
 * subpixels.  A record behind the eye plane (w <= 0) may reach anywhere.
 * f->rows is 2 bytes per input triangle, or NULL: without room for the rows
 * every band rebuilds every triangle: slower, the same pixels.  A byte
 * counts units of f->row_unit rows, the fewest that number a frame's rows
 * below 255 (one row up to 254 rows high, so on a small display the rows
 * are exact); the first and last unit are rounded outwards, so a band may
 * rebuild a triangle it does not need, never miss one.  The pair 255, 0
 * reaches no row. */
void silk_cull_rows(frame *f, const silk_render_opts *o, const silk_target *band)
{
    uint32_t n = f->geom.mesh->ntris;
    int height = band->height;
    f->row_unit = height / 255 + 1;   /* 255 units more than the height: 255, 0 is past every band */
    for (uint32_t t = 0; f->rows && t < n; t++) {
        silk_shares_part(f, t);
        int64_t lo = height, hi = -1;
        if (part_hidden(f, o, band)) {                   /* no band draws it: none rebuilds it */
            f->rows[2 * t] = UINT8_MAX;
            f->rows[2 * t + 1] = 0;
            continue;
        }
        for (uint32_t i = 0; i < f->g.nvrec; i++) {
            const silk_vec4 *c = &f->cache[i].clip;
            if (c->w <= 0) {
                lo = 0;
                hi = height - 1;
                break;
            }
            int64_t y = silk_raster_row(c, height);
            if (y - 1 < lo) lo = y - 1;
            if (y + 1 > hi) hi = y + 1;
        }
        if (lo < 0) lo = 0;
        if (hi > height - 1) hi = height - 1;
        f->rows[2 * t] = lo <= hi ? (uint8_t)(lo / f->row_unit) : UINT8_MAX;   /* never reached: no band takes it */
        f->rows[2 * t + 1] = lo <= hi ? (uint8_t)(hi / f->row_unit) : 0;
    }
}
