/*
 * cmd_view.c - `silk view MESH`: the desktop viewer (viewer.h) without its
 * window: the orbit camera, what the keys do, the frame and its status
 * line, screenshots, and the two modes that need no window at
 * all: `--benchmark N` (time N frames turning about the model) and
 * `--events "..."` (apply a list of key and mouse events, for scripts).
 *
 * The overlays are the core's own: key w is opts.wire (every edge, the
 * triangles re-meshing added in red), key l cycles opts.lines (the sampled
 * silhouette segments and feature curves of paper III-A/D over the surface,
 * then alone), key c switches those to the coarse mesh's polygonal outline.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "commands.h"
#include "view/viewer.h"
#include "image/font.h"
#include "image/sheet.h"
#include "platform/platform.h"

#define DEG CLI_DEG

#define HUD_BG    0x202020u
#define HUD_TEXT  0xF0F0F0u
#define LINE_SIL  0x1060FFu     /* silhouette lines: blue on the grey surface */
#define LINE_FEAT 0x10A040u     /* feature lines: green */
#define MAX_DOUBLINGS 4

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

/* ---- the scene and the camera ------------------------------------------------------ */

/* (Re)load the mesh; the arena is the tool's default size doubled
 * v->doublings times (a frame that fell back asks for more). */
static int load_scene(viewer *v)
{
    cli_scene_free(&v->s);
    cli_scene_opts o = v->o;
    /* The frame lives outside the arena (it changes size with the window):
     * the scene gets a 1x1 target and no raster bytes to speak of. */
    o.width = o.height = 1;
    o.arena_doublings = v->doublings;
    /* a prepared model's hull, map and texture too, for keys 5 and 6: every
     * mode is drawn from one camera, the mesh's */
    o.parts_if_any = 1;
    return cli_scene_load(&v->s, &o);
}

/* Into clip or siltex mode: a model without a hull and map or texture says
 * why (cli_silmap, cli_siltex) and the viewer stays in the mode it was. */
static void check_mode(viewer *v, silk_mode was)
{
    const cli_scene *s = &v->s;
    const char *name = cli_input_name(v->o.mesh_path);
    silk_silmap map;
    silk_siltex tex;
    if (v->ro.mode == SILK_MODE_CLIP && !s->have_silmap) {
        if (!cli_silmap(s->file, s->file_len, name, &map))
            cli_fail(0, "%s: clip mode needs the model's hull", name);
        v->ro.mode = was;
    } else if (v->ro.mode == SILK_MODE_SILTEX && !s->have_siltex) {
        if (!cli_siltex(s->file, s->file_len, name, &tex))
            cli_fail(0, "%s: siltex mode needs the model's hull", name);
        v->ro.mode = was;
    }
}

/* The options as this mode draws them: the lines it has (pn and blend the
 * polygonal ones, clip none), the model's map or texture. */
static silk_render_opts frame_opts(const viewer *v)
{
    silk_render_opts ro = v->ro;
    if (ro.lines && (ro.mode == SILK_MODE_PN || ro.mode == SILK_MODE_BLEND)) ro.lines_polygonal = 1;
    if (ro.mode == SILK_MODE_CLIP) ro.lines = SILK_LINES_NONE;
    cli_scene_render_opts(&v->s, &ro);
    return ro;
}

/* The camera of the orbit state, for a w x h frame. */
static int update_camera(viewer *v)
{
    cli_scene_opts o = v->o;
    o.width = v->w;
    o.height = v->vh;
    double d[3], up[3];
    cli_orbit_dir(&o, v->az, v->el, d);
    cli_up_axis(&o, up);
    /* Orthographic: the view is as high as the perspective view at the
     * target, and the eye steps back out of the model. */
    double half = v->dist * tan(o.fov * DEG / 2), back = v->dist;
    if (v->ortho) {
        double off = 0;
        for (int k = 0; k < 3; k++) off += (v->target[k] - v->centre[k]) * (v->target[k] - v->centre[k]);
        double need = 2.2 * v->radius + sqrt(off);
        if (back < need) back = need;
    }
    o.have_eye = o.have_target = o.have_up = 1;
    o.yaw = o.pitch = 0;   /* the orbit state took them in */
    for (int k = 0; k < 3; k++) {
        o.target[k] = v->target[k];
        o.eye[k] = v->target[k] + d[k] * back;
        o.up[k] = up[k];
    }
    o.ortho = v->ortho;
    o.ortho_auto = 0;
    o.ortho_half = half < 1.0 / 256 ? 1.0 / 256 : half;
    silk_camera cam;
    int rc = cli_scene_camera(&v->s, &o, &cam);
    if (rc) return rc;
    silk_error err;
    if (silk_view_init(&v->view, &cam, &err) != SILK_OK) return cli_fail(CLI_EXIT_USAGE, "view: %s", err.msg);
    cli_scene_phong(&v->s, &v->o, v->ro.mode, &v->view, &v->phong);
    silk_hal_phong(&v->hal, &v->phong);
    return 0;
}

/* Keep the orbit where the camera stays valid: the eye within the tool's
 * coordinate limit, the target near the model, never straight up or down
 * (the up vector would be along the view). */
static void clamp_orbit(viewer *v)
{
    v->el = clampd(v->el, -89, 89);
    v->az = fmod(v->az, 360);
    double far = CLI_MAX_COORD / 4;
    if (far > 200 * v->radius) far = 200 * v->radius;
    v->dist = clampd(v->dist, 0.02 * v->radius, far);
    for (int k = 0; k < 3; k++) v->target[k] = clampd(v->target[k], v->centre[k] - 2 * v->radius, v->centre[k] + 2 * v->radius);
}

/* ---- frame buffers ------------------------------------------------------------------- */

int viewer_resize(viewer *v, int w, int h)
{
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    if (w > CLI_MAX_SIDE) w = CLI_MAX_SIDE;
    if (h > CLI_MAX_SIDE) h = CLI_MAX_SIDE;
    size_t px = (size_t)w * (size_t)h;
    uint8_t *color = malloc(px * silk_pixfmt_bytes(v->o.fmt));
    uint32_t *depth = malloc(px * sizeof *depth);
    if (!color || !depth) {
        free(color);
        free(depth);
        return cli_fail(CLI_EXIT_INPUT, "view: out of memory for a %dx%d frame", w, h);
    }
    free(v->color);
    free(v->depth);
    v->color = color;
    v->depth = depth;
    v->w = w;
    v->h = v->vh = h;
    silk_target_init(&v->t, w, h, 0, h, v->o.fmt, color, depth);
    v->dirty = 1;
    return update_camera(v);
}

int viewer_open(viewer *v, const cli_scene_opts *o, const char *shot_pattern)
{
    memset(v, 0, sizeof *v);
    v->o = *o;
    v->ro = o->render;
    v->ro.line_rgb = LINE_SIL;
    v->ro.line_feature_rgb = LINE_FEAT;
    v->ortho = o->ortho;
    v->hud = 1;
    v->spin_step = VIEWER_SPIN_DEG;
    v->shot_pattern = shot_pattern;
    int rc = load_scene(v);
    if (rc) return rc;

    /* Start where `silk render` looks from: its camera for this size. */
    silk_camera cam;
    if ((rc = cli_scene_camera(&v->s, o, &cam)) != 0) return rc;
    const silk_mesh *m = &v->s.mesh;
    double lo[3] = { cli_fx_to_double(m->bbox_min.x), cli_fx_to_double(m->bbox_min.y), cli_fx_to_double(m->bbox_min.z) };
    double hi[3] = { cli_fx_to_double(m->bbox_max.x), cli_fx_to_double(m->bbox_max.y), cli_fx_to_double(m->bbox_max.z) };
    double r2 = 0;
    for (int k = 0; k < 3; k++) v->centre[k] = (lo[k] + hi[k]) / 2;
    for (uint32_t i = 0; i < m->nverts; i++) {
        double dx = cli_fx_to_double(silk_mesh_pos(m, i).x) - v->centre[0], dy = cli_fx_to_double(silk_mesh_pos(m, i).y) - v->centre[1],
               dz = cli_fx_to_double(silk_mesh_pos(m, i).z) - v->centre[2];
        if (dx * dx + dy * dy + dz * dz > r2) r2 = dx * dx + dy * dy + dz * dz;
    }
    v->radius = r2 > 0 ? sqrt(r2) : 1;
    double e[3] = { cli_fx_to_double(cam.eye.x), cli_fx_to_double(cam.eye.y), cli_fx_to_double(cam.eye.z) };
    double t[3] = { cli_fx_to_double(cam.target.x), cli_fx_to_double(cam.target.y), cli_fx_to_double(cam.target.z) };
    double d[3] = { e[0] - t[0], e[1] - t[1], e[2] - t[2] };
    memcpy(v->target, t, sizeof t);
    v->dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(v->dist > 0)) v->dist = 3 * v->radius;
    cli_orbit_angles(o, d, &v->az, &v->el);
    if (o->ortho) v->dist = cli_fx_to_double(cam.ortho_half_height) / tan(o->fov * DEG / 2);
    clamp_orbit(v);
    memcpy(v->home, v->target, sizeof v->target);
    v->home[3] = v->az;
    v->home[4] = v->el;
    v->home[5] = v->dist;
    return viewer_resize(v, o->width, o->height);
}

void viewer_close(viewer *v)
{
    cli_scene_free(&v->s);
    free(v->color);
    free(v->depth);
    memset(v, 0, sizeof *v);
}

/* ---- input ------------------------------------------------------------------------- */

void viewer_orbit(viewer *v, double dx_px, double dy_px)
{
    v->az -= dx_px * VIEWER_ORBIT_DEG_PER_PX;
    v->el += dy_px * VIEWER_ORBIT_DEG_PER_PX;
    clamp_orbit(v);
    v->dirty = 1;
}

/* Move the target in the view plane so that the model follows the mouse. */
void viewer_pan(viewer *v, double dx_px, double dy_px)
{
    double per_px = 2 * v->dist * tan(v->o.fov * DEG / 2) / v->vh;
    double r[3] = { cli_fx_to_double(v->view.right.x), cli_fx_to_double(v->view.right.y), cli_fx_to_double(v->view.right.z) };
    double u[3] = { cli_fx_to_double(v->view.upv.x), cli_fx_to_double(v->view.upv.y), cli_fx_to_double(v->view.upv.z) };
    for (int k = 0; k < 3; k++) v->target[k] += (-dx_px * r[k] + dy_px * u[k]) * per_px;
    clamp_orbit(v);
    v->dirty = 1;
}

void viewer_zoom(viewer *v, double notches)
{
    v->dist /= pow(VIEWER_ZOOM_STEP, notches);
    clamp_orbit(v);
    v->dirty = 1;
}

int viewer_key(viewer *v, int key)
{
    static const silk_mode cycle[] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH, SILK_MODE_BLEND, SILK_MODE_PN,
                                       SILK_MODE_CLIP, SILK_MODE_SILTEX };
    int was_dirty = v->dirty;
    silk_mode was = v->ro.mode;
    v->dirty = 1;
    switch (key) {
    case '1': case '2': case '3': case '4': case '5': case '6':
        v->ro.mode = cycle[key - '1'];
        check_mode(v, was);
        break;
    case 'm':
        for (int i = 0; i < 6; i++)
            if (cycle[i] == was) {
                /* past the modes the model has not */
                for (int k = 1; k <= 6 && v->ro.mode == was; k++) {
                    silk_mode next = cycle[(i + k) % 6];
                    if ((next == SILK_MODE_CLIP && !v->s.have_silmap) || (next == SILK_MODE_SILTEX && !v->s.have_siltex))
                        continue;
                    v->ro.mode = next;
                }
                break;
            }
        break;
    case 'w': v->ro.wire = !v->ro.wire; break;
    case 'l': v->ro.lines = (silk_lines)((v->ro.lines + 1) % (SILK_LINES_ONLY + 1)); break;
    case 'c': v->ro.lines_polygonal = !v->ro.lines_polygonal; break;
    case 'h': v->hud = !v->hud; break;
    case ' ': v->spin = !v->spin; break;
    case 'o': v->ortho = !v->ortho; break;
    /* Tolerance in steps of two over the range silk_render supports. */
    case '+': case '=':
        if (v->ro.tolerance_px < SILK_FX_C(4, 1)) v->ro.tolerance_px = silk_fx_min(2 * v->ro.tolerance_px, SILK_FX_C(4, 1));
        break;
    case '-':
        if (v->ro.tolerance_px > SILK_FX_C(1, 4)) v->ro.tolerance_px = silk_fx_max(v->ro.tolerance_px / 2, SILK_FX_C(1, 4));
        break;
    case ']': if (v->ro.level < SILK_PN_MAX_LEVEL) v->ro.level++; break;
    case '[': if (v->ro.level > 1) v->ro.level--; break;
    case 'r':
        memcpy(v->target, v->home, sizeof v->target);
        v->az = v->home[3];
        v->el = v->home[4];
        v->dist = v->home[5];
        break;
    case VIEWER_KEY_LEFT: viewer_orbit(v, 15 / VIEWER_ORBIT_DEG_PER_PX, 0); break;
    case VIEWER_KEY_RIGHT: viewer_orbit(v, -15 / VIEWER_ORBIT_DEG_PER_PX, 0); break;
    case VIEWER_KEY_UP: viewer_orbit(v, 0, 15 / VIEWER_ORBIT_DEG_PER_PX); break;
    case VIEWER_KEY_DOWN: viewer_orbit(v, 0, -15 / VIEWER_ORBIT_DEG_PER_PX); break;
    /* The screenshot is the frame on screen, not a new one. */
    case 's': v->dirty = was_dirty; return viewer_screenshot(v, NULL);
    case 'q': v->quit = 1; break;
    default: v->dirty = was_dirty; break;
    }
    return 0;
}

/* ---- the status line ---------------------------------------------------------------- */

static void mode_text(const silk_render_opts *ro, char *buf, size_t n)
{
    if (ro->mode == SILK_MODE_PN) snprintf(buf, n, "pn level %u", (unsigned)ro->level);
    else if (ro->mode == SILK_MODE_FLAT || ro->mode == SILK_MODE_CLIP || ro->mode == SILK_MODE_SILTEX) snprintf(buf, n, "%s", silk_mode_name(ro->mode));
    else snprintf(buf, n, "%s tol %g", silk_mode_name(ro->mode), cli_fx_to_double(ro->tolerance_px));
}

void viewer_status(const viewer *v, char *buf, size_t n)
{
    static const char *const lines[] = { "", " | lines", " | lines only" };
    char mode[40];
    mode_text(&v->ro, mode, sizeof mode);
    /* This frame's render, and the last copy to the window: the status
     * line is drawn before the frame is finished.  What matters most
     * first: a small window shows only the first parts. */
    double ms = v->render_ms + v->present_ms;
    size_t used = v->s.load_bytes + v->stats.frame_bytes;
    snprintf(buf, n, "%s%s | %.1f ms %.0f fps | %u tris, %u silhouette | arena %zuK of %zuK | %s%s%s%s", mode,
             v->stats.fell_back ? " | FELL BACK" : "", ms, ms > 0 ? 1000 / ms : 0.0, (unsigned)v->stats.tris_drawn,
             (unsigned)v->stats.silhouette_tris, (used + 1023) / 1024, (v->s.arena.size + 1023) / 1024,
             v->ortho ? "ortho" : "persp", v->ro.wire ? " | wire" : "", lines[v->ro.lines % 3],
             v->ro.lines && v->ro.lines_polygonal ? " coarse" : "");
}

/* The status line's font scale, and how many lines of it the frame takes:
 * a sixth of its height, and one line at least as long as that is at most
 * a third of it (none in a smaller frame). */
static int hud_scale(const viewer *v) { return v->w >= 1280 && v->h >= 480 ? 2 : 1; }
static int hud_max_lines(const viewer *v)
{
    int scale = hud_scale(v), line = FONT_LINE * scale;
    int n = (v->h / 6 - 4 * scale) / line;
    if (n < 1) n = (line + 4 * scale) * 3 <= v->h;
    return n;
}

/* The status line wrapped at its " | " separators into at most max lines
 * of the frame's width, the parts that do not fit left out; returns the
 * lines used. */
static int hud_text(const viewer *v, int max, char *out, size_t n)
{
    int scale = hud_scale(v), fit = (v->w - 8 * scale) / (FONT_ADVANCE * scale);
    char text[256];
    viewer_status(v, text, sizeof text);
    size_t k = 0, col = 0;
    int nlines = 1;
    out[0] = 0;
    for (char *seg = text; *seg;) {
        char *bar = strstr(seg, " | ");
        size_t len = bar ? (size_t)(bar - seg) : strlen(seg);
        if (col > 0 && col + 3 + len > (size_t)(fit > 0 ? fit : 1)) {
            if (nlines == max) break;
            out[k++] = '\n';
            col = 0;
            nlines++;
        } else if (col > 0) {
            memcpy(out + k, " | ", 3);
            k += 3;
            col += 3;
        }
        if (k + len + 1 >= n) break;
        memcpy(out + k, seg, len);
        k += len;
        col += len;
        seg += len + (bar ? 3 : 0);
    }
    out[k] = 0;
    return nlines;
}

/* Rows of the status band for this frame: 0 without it. */
static int hud_band(const viewer *v)
{
    int max = hud_max_lines(v);
    if (!v->hud || max < 1) return 0;
    char lines[256];
    return (hud_text(v, max, lines, sizeof lines) * FONT_LINE + 4) * hud_scale(v);
}

/* The status line in a dark band of rows under the model's view. */
static void draw_hud(viewer *v, int band)
{
    int scale = hud_scale(v);
    char lines[256];
    hud_text(v, (band / scale - 4) / FONT_LINE, lines, sizeof lines);
    for (int y = v->h - band; y < v->h; y++)
        for (int x = 0; x < v->w; x++) silk_target_put(&v->t, x, y, HUD_BG);
    font_draw(&v->t, 4 * scale, v->h - band + 3 * scale, lines, HUD_TEXT, scale);
}

/* ---- frames ------------------------------------------------------------------------------ */

int viewer_frame(viewer *v)
{
    if (!v->dirty && !v->spin) return 0;
    if (v->spin) {
        v->az += v->spin_step;
        clamp_orbit(v);
    }
    for (;;) {
        /* the model in the rows above the status band, never under it (the
         * band's lines from the last frame's status) */
        int band = hud_band(v);
        v->vh = v->h - band;
        silk_target view;
        silk_target_init(&view, v->w, v->vh, 0, v->vh, v->o.fmt, v->color, v->depth);
        int rc = update_camera(v);
        if (rc) return rc;
        silk_error err;
        silk_render_opts ro = frame_opts(v);
        double t0 = now_ms();
        if (silk_render(&v->s.arena, cli_scene_mesh(&v->s, ro.mode), &v->view, &v->hal, &ro, &view, &v->stats, &err) !=
            SILK_OK)
            return cli_fail(CLI_EXIT_INPUT, "%s: %s", v->o.mesh_path, err.msg);
        /* the next frame's search for the eye starts where this one's ended */
        v->ro.silmap_hint = v->stats.clip_tri;
        double t1 = now_ms();
        /* As `silk render` does: a frame that ran out of scratch gets a
         * larger arena (unless --arena fixed it) and is drawn again. */
        if (v->stats.fell_back && !v->o.arena_bytes && v->doublings < MAX_DOUBLINGS) {
            v->doublings++;
            if ((rc = load_scene(v)) != 0) return rc;
            continue;
        }
        v->render_ms = t1 - t0;
        if (band) draw_hud(v, band);
        v->frame_ms = now_ms() - t0;
        break;
    }
    v->frames++;
    v->dirty = 0;
    return 0;
}

int viewer_screenshot(viewer *v, const char *path)
{
    int rc = viewer_frame(v);
    if (rc) return rc;
    char name[4096];
    int numbered = !path;
    if (numbered) {
        if (pattern_path(v->shot_pattern, v->shots + 1, name, sizeof name) != 0)
            return cli_fail(CLI_EXIT_USAGE, "view: screenshot name too long: %s", v->shot_pattern);
        path = name;
    }
    silk_error err;
    if (silk_image_write(&v->t, path, &err) != SILK_OK) return cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    v->shots += numbered;
    char mode[40];
    mode_text(&v->ro, mode, sizeof mode);
    printf("silk view: saved %s (%dx%d, %s, %s, %u triangles drawn, %u silhouette)\n", path, v->w, v->h, mode,
           v->ortho ? "orthographic" : "perspective", (unsigned)v->stats.tris_drawn,
           (unsigned)v->stats.silhouette_tris);
    fflush(stdout);
    return 0;
}

/* ---- headless: --benchmark and --events ---------------------------------------------------- */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* N frames, each turned 360/N degrees further: the time silk_render takes
 * and the time of the whole frame with overlays, as medians. */
static int run_benchmark(viewer *v, long n)
{
    double *render = malloc((size_t)n * sizeof *render), *frame = malloc((size_t)n * sizeof *frame);
    if (!render || !frame) {
        free(render);
        free(frame);
        return cli_fail(CLI_EXIT_INPUT, "view: out of memory");
    }
    double tris = 0, sil = 0;
    size_t peak = 0;
    int rc = 0;
    for (long i = 0; i < n && !rc; i++) {
        v->az += 360.0 / n;
        clamp_orbit(v);
        v->dirty = 1;
        rc = viewer_frame(v);
        render[i] = v->render_ms;
        frame[i] = v->frame_ms;
        tris += v->stats.tris_drawn;
        sil += v->stats.silhouette_tris;
        if (v->stats.frame_bytes > peak) peak = v->stats.frame_bytes;
    }
    if (!rc) {
        qsort(render, (size_t)n, sizeof *render, cmp_double);
        qsort(frame, (size_t)n, sizeof *frame, cmp_double);
        double rm = render[n / 2], fm = frame[n / 2];
        printf("view-benchmark %s mode=%s level=%u tolerance=%g size=%dx%d frames=%ld render_ms=%.3f frame_ms=%.3f "
               "fps=%.1f tris_drawn=%.0f silhouette_tris=%.0f arena_bytes=%zu frame_bytes=%zu\n",
               v->o.mesh_path, silk_mode_name(v->ro.mode), (unsigned)v->ro.level, cli_fx_to_double(v->ro.tolerance_px),
               v->w, v->h, n, rm, fm, fm > 0 ? 1000 / fm : 0.0, tris / n, sil / n, v->s.arena.size, peak);
    }
    free(render);
    free(frame);
    return rc;
}

/* --events: words separated by blanks, applied in order:
 *   a key as itself (1..5 w l + - [ ] o s h r m), "space", "left" "right" "up"
 *   "down", "drag:DX,DY" (orbit), "pan:DX,DY", "wheel:N", "size:WxH",
 *   "shot:PATH" (a screenshot to PATH). */
static int run_events(viewer *v, const char *script)
{
    static const struct { const char *name; int key; } named[] = {
        { "space", ' ' }, { "left", VIEWER_KEY_LEFT }, { "right", VIEWER_KEY_RIGHT },
        { "up", VIEWER_KEY_UP }, { "down", VIEWER_KEY_DOWN }, { "plus", '+' }, { "minus", '-' },
    };
    const char *p = script;
    int rc = 0;
    while (!rc && !v->quit) {
        p += strspn(p, " \t\n");
        if (!*p) break;
        size_t len = strcspn(p, " \t\n");
        char word[512];
        if (len >= sizeof word) return cli_fail(CLI_EXIT_USAGE, "--events: word too long at \"%.20s...\"", p);
        memcpy(word, p, len);
        word[len] = 0;
        p += len;
        double a, b;
        int w, h, key = -1;
        char extra;
        for (size_t i = 0; i < sizeof named / sizeof named[0]; i++)
            if (strcmp(word, named[i].name) == 0) key = named[i].key;
        if (key < 0 && len == 1 && strchr("123456mwlchor+-=[]sq", word[0])) key = word[0];
        if (key >= 0) rc = viewer_key(v, key);
        else if (sscanf(word, "drag:%lf,%lf%c", &a, &b, &extra) == 2) viewer_orbit(v, a, b);
        else if (sscanf(word, "pan:%lf,%lf%c", &a, &b, &extra) == 2) viewer_pan(v, a, b);
        else if (sscanf(word, "wheel:%lf%c", &a, &extra) == 1) viewer_zoom(v, a);
        else if (sscanf(word, "size:%dx%d%c", &w, &h, &extra) == 2 && w > 0 && h > 0 && w <= CLI_MAX_SIDE &&
                 h <= CLI_MAX_SIDE)
            rc = viewer_resize(v, w, h);
        else if (strncmp(word, "shot:", 5) == 0 && word[5]) rc = viewer_screenshot(v, word + 5);
        else
            return cli_fail(CLI_EXIT_USAGE, "--events: unknown event \"%s\" (see silk view --help)", word);
        if (!rc) rc = viewer_frame(v);
    }
    return rc;
}

/* ---- the command ------------------------------------------------------------------------ */

typedef struct view_args {
    const char *pattern, *events;
    int spin;
    double spin_step;          /* 0: the display's default */
    long frames, benchmark;
    view_fb_opts fb;
    int have_geo;
} view_args;

static void view_defaults(void *base)
{
    view_args *a = base;
    memset(a, 0, sizeof *a);
    a->pattern = "silk-view-%03d.png";
}

static int parse_pattern(const cli_opt *o, const char *v, void *base)
{
    if (pattern_check(v) < 0) return cli_fail(-1, "view: -o %s: at most one %%d (and %%%% for a percent sign)", v);
    if (silk_image_format_for_path(v) == SILK_IMAGE_NONE)
        return cli_fail(-1, "view: -o %s: unknown image format (use .png or .ppm)", v);
    if (cli_check_output_dir(o->name, v)) return CLI_EXIT_INPUT;
    ((view_args *)base)->pattern = v;
    return 0;
}

/* --fb-geometry WxHxBPP */
static int parse_geometry(const cli_opt *o, const char *s, void *base)
{
    (void)o;
    view_fb_opts *f = &((view_args *)base)->fb;
    char *end;
    long v[3];
    const char *p = s;
    for (int k = 0; k < 3; k++) {
        if (*p < '0' || *p > '9') goto bad;
        v[k] = strtol(p, &end, 10);
        if (k < 2 && *end != 'x') goto bad;
        p = end + (k < 2);
    }
    if (*end) goto bad;
    if (v[0] < 1 || v[1] < 1 || v[0] > CLI_MAX_SIDE || v[1] > CLI_MAX_SIDE)
        return cli_fail(-1, "--fb-geometry: width and height must be 1 to %d (got %s)", CLI_MAX_SIDE, s);
    if (v[2] != 16 && v[2] != 24 && v[2] != 32)
        return cli_fail(-1, "--fb-geometry: bits per pixel must be 16, 24 or 32 (got %s)", s);
    f->geo_w = (int)v[0];
    f->geo_h = (int)v[1];
    f->geo_bpp = (int)v[2];
    return 0;
bad:
    return cli_fail(-1, "--fb-geometry must be WIDTHxHEIGHTxBPP, e.g. 320x240x16 (got \"%s\")", s);
}

#define F(member) CLI_FIELD(view_args, member)
#define XSTR(x) STR(x)
#define STR(x) #x
static const cli_opt view_rows[] = {
    { .name = "--output", .alt = "-o", .group = "", .kind = CLI_TEXT, .meta = "PATTERN", F(pattern),
      .parse = parse_pattern, .help = "screenshot names; a %%d in it counts them (default %D)" },
    { .name = "--spin", .kind = CLI_FLAG, F(spin),
      .help = "start spinning (on a framebuffer the model always spins)" },
    { .name = "--spin-step", .kind = CLI_REAL, .meta = "DEG", .lo = -360, .hi = 360, F(spin_step),
      .help = "degrees the model turns a frame while spinning (%R; default 2 in the window, 3 on a framebuffer)" },
    { .name = "--frames", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 100000000, F(frames),
      .help = "quit after N frames (in the window saving the last as a screenshot)" },
    { .name = "--benchmark", .group = "Without a window", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = 100000,
      F(benchmark), .help = "render N frames, each turned 360/N degrees, and print the median time per frame:\n"
      "view-benchmark MESH mode=M size=WxH frames=N render_ms=X frame_ms=X fps=X ..." },
    { .name = "--events", .kind = CLI_TEXT, .meta = "\"...\"", F(events),
      .help = "apply these events in order, then quit: keys as above (space left right up down plus minus by "
              "name), drag:DX,DY  pan:DX,DY  wheel:N  size:WxH  shot:PATH" },
    { .name = "--fb", .group = "On a Linux framebuffer (docs/small-devices.md)", .kind = CLI_TEXT, .meta = "DEVICE",
      F(fb.fb_dev),
      .help = "show the model turning on a framebuffer device, e.g. /dev/fb0, until Ctrl-C, rendered in bands of "
              "--rows lines straight into the screen (no frame buffer of silk's own): size and pixel format from "
              "the device (16, 24 or 32 bits per pixel)"
#ifdef SILK_BOARD_FB
              "; default on this board: " SILK_BOARD_FB
#endif
    },
    { .name = "--fb-file", .kind = CLI_TEXT, .meta = "PATH", F(fb.fb_file),
      .help = "a file-backed framebuffer instead (created or truncated)" },
    { .name = "--fb-geometry", .kind = CLI_CUSTOM, .meta = "WxHxBPP", CLI_SEEN(view_args, have_geo),
      .parse = parse_geometry, .help = "its size and bits per pixel (16, 24 or 32)" },
    { .name = "--rows", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = CLI_MAX_SIDE, F(fb.rows),
      .help = "band height in rows (%R, default " XSTR(VIEW_FB_ROWS) "); the frame fills the screen unless --size "
              "is given (then it is centred), in RGB565 on a 16-bit screen, RGB888 otherwise, unless --format says "
              "otherwise" },
    { .name = NULL },
};
#undef F

static void view_more(FILE *f)
{
    fprintf(f,
            "\n"
            "mouse:\n"
            "  left drag            orbit around the target\n"
            "  right or middle drag pan\n"
            "  wheel                zoom\n"
            "keys:\n"
            "  1 2 3 4 5 6          mode: flat, smooth, blend, pn, clip, siltex  m  next mode\n"
            "                       (clip and siltex: a prepared model's hull, from the same view)\n"
            "  w                    wireframe; triangles added by re-meshing in red\n"
            "  l                    lines: silhouette (blue) and feature curves (green) over\n"
            "                       the surface, then alone, then off\n"
            "  c                    lines of the coarse mesh's polygonal outline instead\n"
            "  + -                  silhouette tolerance up / down (0.25 .. 4 px)\n"
            "  [ ]                  PN level down / up\n"
            "  o                    perspective / orthographic\n"
            "  s  F12               screenshot (PNG) to the -o pattern\n"
            "  h                    status line on / off (a band under the model)\n"
            "  space                spin the model\n"
            "  arrows               orbit by 15 degrees\n"
            "  r                    back to the first view\n"
            "  q  Esc               quit\n");
}

const cli_command cmd_view_spec = {
    .name = "view",
    .usage =
        "usage: silk view MESH [options]            a window (SDL2)"
        #ifndef SILK_HAVE_SDL2
        " - not in this build (no SDL2)"
        #endif
        "\n"
        "       silk view MESH --benchmark N        no window: time N frames\n"
        "       silk view MESH --events \"KEYS...\"   no window: apply events, save screenshots\n"
        "       silk view MESH --fb DEVICE          a Linux framebuffer,\n"
        "       silk view MESH --fb-file PATH --fb-geometry WxHxBPP   or a file standing in for one\n",
    .about =
        "Show MESH in a window and turn it with the mouse.  The status line under\n"
        "the model shows the mode, the frame time, the triangles drawn and on the\n"
        "silhouette, and the arena in use (mesh + this frame's scratch).\n",
    .examples =
        "  silk view bunny.obj\n"
        "  silk view bunny.obj --size 1024x768 --mode pn -o shots/bunny-%02d.png\n"
        "  silk view bunny.obj --benchmark 100 --size 640x480\n"
        "  silk view sphere.obj --events \"1 shot:flat.png 2 w shot:smooth.png\"\n"
        "  silk view bunny.obj --fb /dev/fb0\n"
        "  silk view bunny.obj --fb-file /tmp/fb.raw --fb-geometry 320x240x16 --frames 10\n"
        "docs/viewer.md has more.\n",
    .more = view_more,
    .sets = { { view_rows, 0, sizeof(view_args), view_defaults, NULL }, CLI_SCENE_SET(CLI_OPT_ALL) },
    .nsets = 2,
};

/* The options of one display only, refused on the other. */
static int check_display(const view_args *a, const cli_args *args, int fb)
{
    static const char *const window_only[] = { "--benchmark", "--events", "--output" };
    static const char *const fb_only[] = { "--fb-geometry", "--rows" };
    for (int k = 0; fb && k < 3; k++)
        if (cli_given(args, window_only[k]))
            return cli_fail(CLI_EXIT_USAGE, "view: %s is not for a framebuffer (--fb, --fb-file)", window_only[k]);
    for (int k = 0; !fb && k < 2; k++)
        if (cli_given(args, fb_only[k]))
            return cli_fail(CLI_EXIT_USAGE, "view: %s is for --fb and --fb-file", fb_only[k]);
    if (a->fb.fb_dev && a->fb.fb_file) return cli_fail(CLI_EXIT_USAGE, "view: give --fb or --fb-file, not both");
    if (a->fb.fb_file && !a->have_geo)
        return cli_fail(CLI_EXIT_USAGE, "view: --fb-file needs --fb-geometry WxHxBPP, e.g. 320x240x16");
    if (a->have_geo && !a->fb.fb_file)
        return cli_fail(CLI_EXIT_USAGE, "view: --fb-geometry is for --fb-file (a device has its own)");
    if (a->benchmark && a->events) return cli_fail(CLI_EXIT_USAGE, "view: --benchmark or --events, not both");
    return 0;
}

int cmd_view(int argc, char **argv)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    view_args a;
    view_defaults(&a);
    cli_args args;
    void *bases[] = { &a, &o };
    int rc = cli_parse(&cmd_view_spec, bases, argc, argv, &args);
    if (!rc) rc = cli_one_mesh("view", args.npos, args.pos, "silk view MESH", &o.mesh_path);
    if (rc == CLI_HELP) rc = 0, o.mesh_path = NULL;
    int fb = !rc && o.mesh_path && (a.fb.fb_dev || a.fb.fb_file);
#ifdef SILK_BOARD_FB
    /* A framebuffer board shows `silk view` on its screen. */
    if (!rc && o.mesh_path && !a.benchmark && !a.events && !fb) {
        a.fb.fb_dev = SILK_BOARD_FB;
        fb = 1;
    }
#endif
    if (!rc && o.mesh_path) rc = check_display(&a, &args, fb);
    a.fb.have_size = cli_given(&args, "--size");
    a.fb.have_format = cli_given(&args, "--format");
    cli_args_free(&args);
    if (rc || !o.mesh_path) return rc;
    if (o.bg_none) return cli_fail(CLI_EXIT_USAGE, "view: --bg none is for images (silk render); give a colour");
    if ((rc = cli_mode_check("view", o.render.mode, &o.render)) != 0) return rc;
    if (fb) {
        a.fb.frames = a.frames;
        a.fb.spin = a.spin_step;
        return view_fb(&o, &a.fb);
    }
#ifndef SILK_HAVE_SDL2
    if (!a.benchmark && !a.events)
        return cli_fail(CLI_EXIT_USAGE, "view: this silk was built without SDL2, so it has no window; use --fb DEVICE, "
                        "--benchmark N or --events (install libsdl2-dev and rebuild for the window)");
#endif

    viewer *v = malloc(sizeof *v);
    if (!v) return cli_fail(CLI_EXIT_INPUT, "view: out of memory");
    rc = viewer_open(v, &o, a.pattern);
    v->spin = a.spin;
    if (a.spin_step) v->spin_step = a.spin_step;
    if (!rc) {
        if (a.benchmark) rc = run_benchmark(v, a.benchmark);
        else if (a.events) rc = run_events(v, a.events);
        else rc = viewer_run_sdl(v, a.frames);
    }
    viewer_close(v);
    free(v);
    return rc;
}
