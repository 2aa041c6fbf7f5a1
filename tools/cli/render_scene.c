/*
 * render_scene.c - `silk render A B ... -o OUT`: several meshes in one
 * picture, one frame of silk_render_scene (silk/scene.h).
 *
 * Each mesh is loaded as `silk render` loads one (its material, texture,
 * prepared model's parts), then placed in the world by its --place (at the
 * origin, unturned, scale 1 without), tinted by its --tint (else --color,
 * else its material) and drawn in its --mode-of (else --mode).  The
 * camera options are the scene's: the default camera frames every placed
 * mesh at once, and --eye, --target, --light are in world units.
 *
 * Why options and not a scene file: a scene for a script or CI stays one
 * command, with every option `silk render` has and no second file to keep
 * in step with it, and the objects are named by where their meshes stand
 * on that command line.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render_scene.h"
#include "silk/scene.h"

/* "N:rest" with N in 1 .. CLI_SCENE_MAX: the object and the rest. */
static cli_object *object_of(const char *opt, const char *value, cli_object *objs, const char **rest)
{
    char *end;
    long n = strtol(value, &end, 10);
    if (end == value || *end != ':' || n < 1 || n > CLI_SCENE_MAX) {
        cli_fail(-1, "%s: \"%s\" should start with the mesh's number and a colon, 1:... to %d:...", opt, value,
                 CLI_SCENE_MAX);
        return NULL;
    }
    *rest = end + 1;
    objs[n - 1].given = 1;
    return &objs[n - 1];
}

int cli_parse_place(const char *opt, const char *value, cli_object *objs)
{
    const char *rest;
    cli_object *ob = object_of(opt, value, objs, &rest);
    if (!ob) return -1;
    char buf[256];
    if (strlen(rest) >= sizeof buf) return cli_fail(-1, "%s is too long", opt);
    strcpy(buf, rest);
    char *turn = strchr(buf, ':'), *scale = NULL;
    if (turn) {
        *turn++ = 0;
        if ((scale = strchr(turn, ':')) != NULL) *scale++ = 0;
    }
    ob->scale = 1;
    ob->turn[0] = ob->turn[1] = ob->turn[2] = 0;
    if (cli_parse_vec3(opt, buf, CLI_MAX_COORD, ob->pos)) return -1;
    if (turn && cli_parse_vec3(opt, turn, 3600, ob->turn)) return -1;
    if (scale && cli_parse_double(opt, scale, 1.0 / 256, 256, &ob->scale)) return -1;
    ob->have_place = 1;
    return 0;
}

int cli_parse_tint(const char *opt, const char *value, cli_object *objs)
{
    const char *rest;
    cli_object *ob = object_of(opt, value, objs, &rest);
    if (!ob || cli_parse_rgb(opt, rest, &ob->tint)) return -1;
    ob->have_tint = 1;
    return 0;
}

int cli_parse_mode_of(const char *opt, const char *value, cli_object *objs)
{
    const char *rest;
    cli_object *ob = object_of(opt, value, objs, &rest);
    int n = 0;
    if (!ob || cli_parse_modes(opt, rest, &ob->mode, 1, &n)) return -1;
    ob->have_mode = 1;
    return 0;
}

static void place_of(const cli_object *ob, silk_place *p)
{
    silk_place_identity(p);
    if (!ob->have_place) return;
    silk_place_euler(p, cli_fx_from_double(ob->turn[0]), cli_fx_from_double(ob->turn[1]),
                     cli_fx_from_double(ob->turn[2]));
    p->pos = silk_v3(cli_fx_from_double(ob->pos[0]), cli_fx_from_double(ob->pos[1]), cli_fx_from_double(ob->pos[2]));
    p->scale = cli_fx_from_double(ob->scale);
}

/* Every placed vertex of the n meshes in world units, as one mesh of
 * points (positions and bounds only) for cli_camera to frame. */
static int world_points(const cli_scene *sc, const silk_place *pl, int n, silk_mesh *all)
{
    uint32_t total = 0;
    for (int i = 0; i < n; i++) total += sc[i].mesh.nverts;
    memset(all, 0, sizeof *all);
    silk_vec3 *pos = malloc((size_t)(total ? total : 1) * sizeof *pos);
    if (!pos) return cli_fail(CLI_EXIT_INPUT, "out of memory for the scene's bounds");
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    uint32_t k = 0;
    for (int i = 0; i < n; i++) {
        const silk_place *p = &pl[i];
        double s = cli_fx_to_double(p->scale);
        for (uint32_t v = 0; v < sc[i].mesh.nverts; v++) {
            const silk_vec3 q = silk_mesh_pos(&sc[i].mesh, v);
            double m[3] = { cli_fx_to_double(q.x), cli_fx_to_double(q.y), cli_fx_to_double(q.z) }, w[3];
            for (int r = 0; r < 3; r++) {
                w[r] = cli_fx_to_double((&p->pos.x)[r]) + s * (cli_fx_to_double(p->rot[r][0]) * m[0] +
                                                                cli_fx_to_double(p->rot[r][1]) * m[1] +
                                                                cli_fx_to_double(p->rot[r][2]) * m[2]);
                if (fabs(w[r]) > CLI_MAX_COORD) {
                    free(pos);
                    return cli_fail(CLI_EXIT_USAGE, "render: --place puts mesh %d beyond +-%g", i + 1, CLI_MAX_COORD);
                }
                lo[r] = fmin(lo[r], w[r]);
                hi[r] = fmax(hi[r], w[r]);
            }
            pos[k++] = silk_v3(cli_fx_from_double(w[0]), cli_fx_from_double(w[1]), cli_fx_from_double(w[2]));
        }
    }
    all->pos = pos;
    all->nverts = total;
    all->bbox_min = silk_v3(cli_fx_from_double(lo[0]), cli_fx_from_double(lo[1]), cli_fx_from_double(lo[2]));
    all->bbox_max = silk_v3(cli_fx_from_double(hi[0]), cli_fx_from_double(hi[1]), cli_fx_from_double(hi[2]));
    return 0;
}

typedef struct scene_run {
    int n;
    cli_scene sc[CLI_SCENE_MAX];
    cli_scene_opts so[CLI_SCENE_MAX];   /* each object's options: --tint, --mode-of */
    silk_object obj[CLI_SCENE_MAX];
    silk_phong phong[CLI_SCENE_MAX];
    int loaded;
} scene_run;

static void run_free(scene_run *r)
{
    for (int i = 0; i < r->loaded; i++) cli_scene_free(&r->sc[i]);
    r->loaded = 0;
}

int cli_render_scene(cli_scene_opts *o, const char *out, silk_image_format out_fmt, int n, const char *const *paths,
                     const cli_object *objs)
{
    for (int i = n; i < CLI_SCENE_MAX; i++)
        if (objs[i].given)
            return cli_fail(CLI_EXIT_USAGE, "render: an option names mesh %d, but %d meshes are given", i + 1, n);
    if (n > CLI_SCENE_MAX) return cli_fail(CLI_EXIT_USAGE, "render: at most %d meshes in one picture", CLI_SCENE_MAX);
    for (int i = 0; i < n; i++) {
        if (objs[i].have_mode) {
            silk_render_opts ro = o->render;
            int rc = cli_mode_check("render", objs[i].mode.mode, &ro);
            if (rc) return rc;
        }
        for (int j = 0; j < i; j++)
            if (!strcmp(paths[i], "-") && !strcmp(paths[j], "-"))
                return cli_fail(CLI_EXIT_USAGE, "render: standard input (-) can be read once");
    }
    scene_run *r = calloc(1, sizeof *r);
    if (!r) return cli_fail(CLI_EXIT_INPUT, "out of memory");
    r->n = n;
    int rc = 0;
    for (int attempt = 0;; attempt++) {
        silk_place pl[CLI_SCENE_MAX];
        for (int i = 0; !rc && i < n; i++) {
            r->so[i] = *o;
            r->so[i].mesh_path = paths[i];
            r->so[i].arena_doublings = attempt;
            if (objs[i].have_tint) {
                r->so[i].look.have_color = 1;
                r->so[i].look.color = objs[i].tint;
            }
            if (objs[i].have_mode) {
                r->so[i].render.mode = objs[i].mode.mode;
                if (objs[i].mode.level) r->so[i].render.level = objs[i].mode.level;
                if (objs[i].mode.aa_off) r->so[i].render.aa = 0;
            }
            place_of(&objs[i], &pl[i]);
            rc = cli_scene_load(&r->sc[i], &r->so[i]);
            r->loaded = i + 1;
        }
        /* the camera frames every placed mesh; the target, alpha and
         * image are the first mesh's */
        silk_mesh all;
        silk_camera cam;
        silk_view view;
        silk_error err;
        if (!rc) rc = world_points(r->sc, pl, n, &all);
        if (!rc) {
            rc = cli_camera(o, &all, NULL, &cam);
            free((void *)all.pos);
        }
        if (!rc && silk_view_init(&view, &cam, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_USAGE, "%s", err.msg);
        size_t bytes = 0;
        for (int i = 0; !rc && i < n; i++) {
            silk_object *ob = &r->obj[i];
            silk_mode mode = r->so[i].render.mode;
            silk_object_init(ob, cli_scene_mesh(&r->sc[i], mode), &r->phong[i]);
            ob->place = pl[i];
            ob->opts = r->so[i].render;
            cli_scene_render_opts(&r->sc[i], &ob->opts);
            cli_scene_phong(&r->sc[i], &r->so[i], mode, &view, &r->phong[i]);
            bytes += silk_arena_free_bytes(&r->sc[i].arena);
        }
        if (rc) break;
        if (o->arena_bytes) bytes = o->arena_bytes;
        void *buf = malloc(bytes);
        if (!buf) {
            rc = cli_fail(CLI_EXIT_INPUT, "out of memory for a %zu-byte arena", bytes);
            break;
        }
        silk_arena a;
        silk_arena_init(&a, buf, bytes);
        silk_scene s;
        silk_scene_init(&s, r->obj, (uint32_t)n);
        s.bg_rgb = o->render.bg_rgb;
        silk_target *t = &r->sc[0].target;
        silk_frame_stats st;
        silk_status ss = silk_render_scene(&a, &s, &view, t, &st, &err);
        free(buf);
        if (ss != SILK_OK) {
            rc = cli_fail(CLI_EXIT_INPUT, "render: %s", err.msg);
            break;
        }
        if (st.fell_back && !o->arena_bytes && attempt < 4) {
            run_free(r);
            continue;
        }
        rc = cli_write_image(t, out, out_fmt, cli_alpha_for(o), o->render.bg_rgb);
        if (!rc && st.fell_back)
            fprintf(stderr, "silk: warning: the arena ran out during the frame; part of it is not smoothed\n");
        else if (!rc && st.aa_aliased)
            fprintf(stderr, "silk: warning: the arena ran short for anti-aliasing; part of the outline is left "
                    "aliased\n");
        break;
    }
    run_free(r);
    free(r);
    return rc;
}
