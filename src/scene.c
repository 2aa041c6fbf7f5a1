/*
 * scene.c - several objects in one frame (silk/scene.h).
 *
 * Each object is drawn in its own frame: world = pos + s R p, so a world
 * point q is the object's p = R^T (q - pos) / s, and the camera's eye and
 * target go there as points, its up and the directional lights as
 * directions (R^T d), point lights as points, and the near and far planes
 * (and an orthographic half height) as lengths, divided by s.  Rotation
 * and uniform scale keep angles, so the projection of p through that
 * camera is the projection of q through the caller's (x / w and y / w do
 * not change with the scale), Phong's dot products are the same, and so
 * is the depth the rasterizer keeps, 2 znear / w (docs/raster.md), with
 * both znear and w divided by s: up to rounding, the objects share one
 * depth test as if drawn in the world.  Then every object's frame is
 * silk_render's own (frame_steps.h), its plan made once a frame:
 *
 *   prepare every object; what each keeps for speed (from what is left,
 *     leaving room for the outlines of all at once);
 *   per band: clear (or the caller's under callback), every object drawn
 *     into the band, every object's outline walked over the band so drawn
 *     (aa.c: one pixel list for all, so each blends with what lies behind
 *     it, whichever object that is, and none reads another's blended
 *     pixels), its pixels written; then the sink.
 *
 * The rows just above and below a band, which the outline reads, are
 * painted and drawn the same way, so a band gives the whole frame's
 * bytes.  An object drawn after another makes no depth-only pass
 * (frame_draw): at a depth equal to an earlier object's its shading pass
 * would take the pixel, where drawing in one pass leaves it to the first.
 */
#include <string.h>
#include "frame_steps.h"
#include "silk/scene.h"

void silk_place_identity(silk_place *p)
{
    memset(p, 0, sizeof *p);
    for (int i = 0; i < 3; i++) p->rot[i][i] = SILK_FX_ONE;
    p->scale = SILK_FX_ONE;
}

/* a b, 3x3 Q16.16 */
static void mat3_mul(silk_fx out[3][3], silk_fx a[3][3], silk_fx b[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int64_t s = 0;
            for (int k = 0; k < 3; k++) s += (int64_t)a[i][k] * b[k][j];
            out[i][j] = silk_fx_sat(silk_shr_round64(s, 16));
        }
}

void silk_place_euler(silk_place *p, silk_fx yaw_deg, silk_fx pitch_deg, silk_fx roll_deg)
{
    silk_fx sy, cy, sx, cx, sz, cz;
    silk_fx_sincos_deg(yaw_deg, &sy, &cy);
    silk_fx_sincos_deg(pitch_deg, &sx, &cx);
    silk_fx_sincos_deg(roll_deg, &sz, &cz);
    silk_fx ry[3][3] = { { cy, 0, sy }, { 0, SILK_FX_ONE, 0 }, { -sy, 0, cy } };
    silk_fx rx[3][3] = { { SILK_FX_ONE, 0, 0 }, { 0, cx, -sx }, { 0, sx, cx } };
    silk_fx rz[3][3] = { { cz, -sz, 0 }, { sz, cz, 0 }, { 0, 0, SILK_FX_ONE } };
    silk_fx yx[3][3];
    mat3_mul(yx, ry, rx);
    mat3_mul(p->rot, yx, rz);
}

void silk_object_init(silk_object *o, const silk_mesh *m, const silk_phong *p)
{
    memset(o, 0, sizeof *o);
    o->mesh = m;
    o->phong = p;
    silk_place_identity(&o->place);
    silk_render_opts_default(&o->opts);
}

void silk_scene_init(silk_scene *s, const silk_object *objects, uint32_t n)
{
    memset(s, 0, sizeof *s);
    s->objects = objects;
    s->nobjects = n;
    s->bg_rgb = 0xFFFFFF;
}

static int place_is_identity(const silk_place *p)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (p->rot[i][j] != (i == j ? SILK_FX_ONE : 0)) return 0;
    return p->pos.x == 0 && p->pos.y == 0 && p->pos.z == 0 && p->scale == SILK_FX_ONE;
}

/* Whether rot's rows are orthonormal to within 1/256 and it turns no
 * mirror (the triple product of its rows is positive). */
static int place_is_rotation(const silk_place *p)
{
    const int64_t one = (int64_t)1 << 32, tol = one >> 8;
    silk_vec3 r[3];
    for (int i = 0; i < 3; i++) r[i] = silk_v3(p->rot[i][0], p->rot[i][1], p->rot[i][2]);
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            int64_t d = silk_v3_dot64(r[i], r[j]) - (i == j ? one : 0);
            if (d > tol || d < -tol) return 0;
        }
    silk_vec3 c = silk_v3(silk_fx_sat(silk_shr_round64((int64_t)r[0].y * r[1].z - (int64_t)r[0].z * r[1].y, 16)),
                          silk_fx_sat(silk_shr_round64((int64_t)r[0].z * r[1].x - (int64_t)r[0].x * r[1].z, 16)),
                          silk_fx_sat(silk_shr_round64((int64_t)r[0].x * r[1].y - (int64_t)r[0].y * r[1].x, 16)));
    return silk_v3_dot64(c, r[2]) > 0;
}

/* R^T d, a direction into the object's frame. */
static silk_vec3 dir_in(const silk_place *p, silk_vec3 d)
{
    silk_fx o[3];
    for (int i = 0; i < 3; i++)
        o[i] = silk_fx_sat(silk_shr_round64((int64_t)p->rot[0][i] * d.x + (int64_t)p->rot[1][i] * d.y +
                                            (int64_t)p->rot[2][i] * d.z, 16));
    return silk_v3(o[0], o[1], o[2]);
}

/* v / s rounded to nearest (s > 0; v in Q32.32, or Q16.16 shifted up 16),
 * a Q16.16 value, or 0 with *ok cleared when it does not fit. */
static silk_fx div_scale(int64_t v, silk_fx s, int *ok)
{
    int64_t q = v >= 0 ? (v + s / 2) / s : -((-v + s / 2) / s);
    if (q > INT32_MAX || q < -INT32_MAX) {
        *ok = 0;
        return 0;
    }
    return (silk_fx)q;
}

/* R^T (q - pos) / s, a point into the object's frame (the difference and
 * the turn in 64 bits, rounded once). */
static silk_vec3 point_in(const silk_place *p, silk_vec3 q, int *ok)
{
    int64_t d[3] = { (int64_t)q.x - p->pos.x, (int64_t)q.y - p->pos.y, (int64_t)q.z - p->pos.z };
    silk_fx o[3];
    for (int i = 0; i < 3; i++)
        o[i] = div_scale(p->rot[0][i] * d[0] + p->rot[1][i] * d[1] + p->rot[2][i] * d[2], p->scale, ok);
    return silk_v3(o[0], o[1], o[2]);
}

silk_status silk_place_view(const silk_view *v, const silk_place *p, silk_view *out, silk_error *err)
{
    if (place_is_identity(p)) {
        *out = *v;   /* the caller's own: silk_render's bits */
        return SILK_OK;
    }
    if (p->scale <= 0 || !place_is_rotation(p))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_place_view: the placement is not a rotation "
                         "(orthonormal rows, no mirror) with a positive scale");
    silk_camera c = v->cam;
    int ok = 1;
    c.eye = point_in(p, v->cam.eye, &ok);
    c.target = point_in(p, v->cam.target, &ok);
    c.up = dir_in(p, v->cam.up);
    c.znear = div_scale((int64_t)v->cam.znear << 16, p->scale, &ok);
    c.zfar = div_scale((int64_t)v->cam.zfar << 16, p->scale, &ok);
    c.ortho_half_height = div_scale((int64_t)v->cam.ortho_half_height << 16, p->scale, &ok);
    if (!ok)
        return silk_fail(err, SILK_ERR_RANGE, NULL, 0, "silk_place_view: the camera in the object's frame is "
                         "out of range (too far from it, or too small a scale)");
    return silk_view_init(out, &c, err);
}

/* What the scene keeps for one object through the frame. */
typedef struct scene_obj {
    silk_view view;            /* the camera in the object's frame */
    silk_phong phong;          /* its lights there */
    silk_hal hal;
    const silk_hal *h;         /* hal, or the caller's stages */
    silk_render_opts opts;     /* the object's, with the scene's bg_rgb */
    silk_frame_stats stats;
    silk_frame_step *step;
    int outline;               /* silk_frame_step_outline_kind of the first band */
} scene_obj;

/* Object i's view, lights and options. */
static silk_status object_setup(scene_obj *so, const silk_scene *s, uint32_t i, const silk_view *v,
                                silk_error *err)
{
    const silk_object *ob = &s->objects[i];
    const silk_place *p = &ob->place;
    if (!ob->mesh || (!ob->phong && (!ob->hal || !ob->hal->vertex || !ob->hal->fragment)))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: object %lu has no mesh or no stages",
                         (unsigned long)i);
    int identity = place_is_identity(p);
    if (!identity && !ob->phong)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: object %lu: stages of the caller's own "
                         "draw the mesh where it is (its placement must be the identity)", (unsigned long)i);
    so->opts = ob->opts;
    so->opts.bg_rgb = s->bg_rgb;
    silk_status st = silk_place_view(v, p, &so->view, err);
    if (st != SILK_OK) return st;
    if (!ob->phong) {
        so->h = ob->hal;
        return SILK_OK;
    }
    so->phong = *ob->phong;
    so->phong.view = &so->view;
    for (int k = 0; !identity && k < so->phong.nlights && k < SILK_MAX_LIGHTS; k++) {
        silk_light *l = &so->phong.lights[k];
        int ok = 1;
        l->vec = l->kind == SILK_LIGHT_POINT ? point_in(p, l->vec, &ok) : dir_in(p, l->vec);
        if (!ok)
            return silk_fail(err, SILK_ERR_RANGE, NULL, 0, "silk_render_scene: object %lu: light %d is out of "
                             "range in its frame", (unsigned long)i, k);
    }
    silk_hal_phong(&so->hal, &so->phong);
    so->h = &so->hal;
    return SILK_OK;
}

/* A band (or an apron row) before any object: depth the farthest, colour
 * bg_rgb or the caller's under. */
static int paint(const silk_scene *s, silk_target *t)
{
    if (!s->under) {
        silk_target_clear(t, s->bg_rgb);
        return 0;
    }
    uint8_t *color = t->color;
    t->color = NULL;   /* the depth (and the test's write counts) alone */
    silk_target_clear(t, 0);
    t->color = color;
    return s->under(s->under_user, t);
}

static int draw_all(const silk_scene *s, scene_obj *so, silk_target *t)
{
    if (paint(s, t)) return 1;
    for (uint32_t i = 0; i < s->nobjects; i++) silk_frame_step_draw(so[i].step, &so[i].opts, t);
    return 0;
}

/* The anti-aliased outlines of every object over band t, just drawn. */
static int outlines(silk_arena *a, const silk_scene *s, scene_obj *so, silk_target *t, uint32_t max_recs,
                    uint32_t naa, silk_frame_stats *stats)
{
    silk_arena_mark mark = silk_arena_top_mark(a);
    silk_aa aa;
    int stop = 0;
    if (!SILK_AA || !naa || !silk_aa_begin_n(&aa, a, t, max_recs, naa)) {   /* (without SILK_AA: compiled away) */
        if (naa) stats->aa_aliased++;
        silk_aa_alpha(t);
    } else {
        for (int k = 0; !stop && k < 2; k++)
            if (aa.apron[k].rows) stop = draw_all(s, so, &aa.apron[k]);
        for (uint32_t i = 0; !stop && i < s->nobjects; i++)
            if (so[i].outline == 1) silk_frame_step_outline(so[i].step, a, &so[i].view, &so[i].opts, &aa, stats);
        silk_aa_finish(&aa);
        stats->aa_aliased += aa.dropped;
    }
    for (uint32_t i = 0; i < s->nobjects; i++)   /* CLIP's own, over the clear colour */
        if (so[i].outline == 2) silk_frame_step_clip_aa(so[i].step, &so[i].opts, t);
    silk_arena_top_release(a, &mark);
    return stop;
}

static void add_stats(silk_frame_stats *to, const silk_frame_stats *s)
{
    to->silhouette_tris += s->silhouette_tris;
    to->bridges += s->bridges;
    to->samples += s->samples;
    to->tris_drawn += s->tris_drawn;
    to->moved_vertices += s->moved_vertices;
    to->flat_segments += s->flat_segments;
    to->fell_back |= s->fell_back;
    to->clip_spans += s->clip_spans;
    to->aa_aliased += s->aa_aliased;
    if (s->clip_points) {
        to->clip_tri = s->clip_tri;
        to->clip_points = s->clip_points;
    }
}

/* The scene into band, band by band (one band: the whole frame). */
static silk_status scene_frame(silk_arena *a, const silk_scene *s, const silk_view *v, silk_target *band,
                               const silk_sink *sink, silk_frame_stats *stats, silk_error *err)
{
    silk_frame_stats local;
    if (!stats) stats = &local;
    memset(stats, 0, sizeof *stats);
    if (!SILK_SCENES)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: scenes are not built in (SILK_SCENES 0)");
    if (!a || !s || !v || !band || (sink && (!sink->band || (sink->color2 == NULL) != (sink->wait == NULL))))
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: missing argument (a second band buffer "
                         "needs the sink's wait)");
    if (!s->objects || s->nobjects < 1 || s->nobjects > SILK_SCENE_MAX_OBJECTS)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: %lu objects (1 .. %u)",
                         (unsigned long)s->nobjects, SILK_SCENE_MAX_OBJECTS);
    if (band->width < 1 || band->height < 1 || band->width > SILK_MAX_DIM || band->height > SILK_MAX_DIM)
        return silk_fail(err, SILK_ERR_RANGE, "target", 0, "image size %dx%d is outside 1x1 .. %dx%d", band->width,
                         band->height, SILK_MAX_DIM, SILK_MAX_DIM);
    if (band->rows < 1) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: a band of no rows");

    silk_arena_mark mark = silk_arena_top_mark(a);
    a->top_peak = a->top;
    const uint32_t n = s->nobjects;
    scene_obj *so = silk_arena_array_top(a, n, sizeof *so, SILK_MEM_FRAME);
    silk_status st = so ? SILK_OK : silk_fail(err, SILK_ERR_NOMEM, NULL, 0, "silk_render_scene: the arena is full");
    /* every object's plan, then what each keeps for speed from what is
     * left, leaving the outlines of all of them their room */
    for (uint32_t i = 0; st == SILK_OK && i < n; i++) {
        st = object_setup(&so[i], s, i, v, err);
        if (st == SILK_OK)
            st = silk_frame_step_prepare(&so[i].step, a, s->objects[i].mesh, &so[i].view, so[i].h, &so[i].opts,
                                         band, i > 0, &so[i].stats, err);
    }
    uint32_t max_recs = 0, naa = 0;
    size_t reserve = 0, peak_before = a->top_peak, extras = 0;
    for (uint32_t i = 0; st == SILK_OK && i < n; i++) {
        uint32_t m = silk_frame_step_max_recs(so[i].step);
        if (m > max_recs) max_recs = m;
        so[i].outline = silk_frame_step_outline_kind(so[i].step, &so[i].opts, band);
        naa += so[i].outline == 1;
    }
    /* (each object's extras leave its own outline's room too: a SILTEX
     * one's scratch) */
    if (SILK_AA && naa) reserve = silk_aa_bytes_n(band, max_recs, naa);
    for (uint32_t i = 0; st == SILK_OK && i < n; i++) {
        size_t before, bytes;
        silk_frame_step_extras(so[i].step, a, s->objects[i].mesh, so[i].h, &so[i].opts, band, reserve);
        silk_frame_step_need(so[i].step, &before, &bytes);
        extras += bytes;
    }
    /* the bands, as silk_render_bands draws them (render.h: with two
     * colour buffers they alternate) */
    const int rows = band->rows;
    uint8_t *const color0 = band->color;
    for (int y0 = 0, k = 0; st == SILK_OK && y0 < band->height; y0 += rows, k ^= 1) {
        band->color = k && sink && sink->color2 ? sink->color2 : color0;
        if (!sink || !sink->wait || !sink->wait(sink->user, band->color)) {
            band->y0 = y0;
            band->rows = band->height - y0 < rows ? band->height - y0 : rows;
            if (!draw_all(s, so, band) && !outlines(a, s, so, band, max_recs, naa, stats) &&
                (!sink || !sink->band(sink->user, band)))
                continue;
        }
        st = silk_fail(err, SILK_ERR_IO, NULL, 0, "%s stopped at row %d", sink ? "output sink or under callback"
                       : "under callback", y0);
    }
    band->color = color0;
    band->y0 = 0;
    band->rows = rows;
    for (uint32_t i = 0; so && i < n; i++) {
        if (so[i].step && st == SILK_OK) so[i].stats.clip_spans = silk_frame_step_clip_spans(so[i].step);
        add_stats(stats, &so[i].stats);
    }
    /* the need: every plan at once, the outlines' band, not what the
     * objects kept for speed (taken only from what was left) */
    size_t after = a->top_peak - extras;
    stats->frame_bytes = (after > peak_before ? after : peak_before) - mark.top;
    silk_arena_top_release(a, &mark);
    return st;
}

silk_status silk_render_scene(silk_arena *a, const silk_scene *s, const silk_view *v, silk_target *t,
                              silk_frame_stats *stats, silk_error *err)
{
    if (t && t->rows != t->height)
        return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene: the target is a band "
                         "(silk_render_scene_bands draws bands)");
    return scene_frame(a, s, v, t, NULL, stats, err);
}

silk_status silk_render_scene_bands(silk_arena *a, const silk_scene *s, const silk_view *v, silk_target *band,
                                    const silk_sink *sink, silk_frame_stats *stats, silk_error *err)
{
    if (!sink) return silk_fail(err, SILK_ERR_ARG, NULL, 0, "silk_render_scene_bands: missing sink");
    return scene_frame(a, s, v, band, sink, stats, err);
}
