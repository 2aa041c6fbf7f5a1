/*
 * test_golden.c - golden frames: the exact pixels of every mode.
 *
 * Meshes made by `silk gen`'s generator (tools/prep/gen.c, with explicit
 * parameters so that a change of its defaults does not move them: sphere,
 * torus, cone and a clean (2,3) knot) and the shared bunny-500 (skipped
 * with one line when ../shared/meshes is missing), each from three views
 * (three-quarter perspective, orthographic from above, and a grazing
 * close-up nearly edge-on to the model's equator), are drawn in every mode:
 * flat, smooth, pn, blend, lines over, lines only, polygonal lines (over PN
 * patches) and wireframe, RGB888, and a few in RGB565.  Each frame is drawn
 * whole and in bands of 16 rows (some also of 1 row); the bands must give
 * the whole frame's bytes, and the whole frame must give the bytes of its
 * reference image tests/golden/NAME.png (RGB565 widened by bit replication,
 * which loses nothing).  Any difference fails, naming the image and the
 * number of pixels that differ.
 *
 * Two more meshes carry surface colour: "globe", a sphere with texture
 * coordinates (gen --uv) under a mipmapped checker texture (gen_checker),
 * and "painted", a sphere whose vertex colours follow the position; both in
 * the surface modes from two views.
 *
 * The comparison is tests/support/golden.c's, as for every reference
 * image: a frame that differs is left in build/tests/out/ with a picture of
 * the difference, and `make golden` (SILK_GOLDEN_UPDATE=1) rewrites the
 * references that differ or are missing and names them.  The last test
 * checks that a failing comparison leaves those two images.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "silk/silk.h"
#include "platform/platform.h"
#include "platform/png_read.h"
#include "tools/prep/gen.h"
#include "tools/prep/hull.h"
#include "tools/prep/model_file.h"
#include "tools/prep/silmap.h"
#include "support/scene.h"
#include "support/golden.h"
#include "support/testmesh.h"
#include "support/testframe.h"
#include "support/stexgen.h"

#define W 128
#define H 96
#define BG 0xFFFFFFu
#define ARENA_BYTES (24u << 20)

static int update;   /* SILK_GOLDEN_UPDATE: the aliased frames' CRCs are rewritten too */
static int n_changed, n_new, n_same, n_unbuilt;
static const silk_texture *mesh_texture;   /* the texture of the mesh being drawn, or NULL */
static const silk_siltex *mesh_siltex;     /* the silhouette texture of the hull being drawn, or NULL */

/* ---- the meshes ------------------------------------------------------------- */

static int gen_fixture(tm_fixture *f, const gen_params *p)
{
    gen_mesh gm;
    char msg[256];
    if (gen_check(p, msg, sizeof msg)) {
        fprintf(stderr, "gen: %s\n", msg);
        return 0;
    }
    if (gen_build(p, &gm) != 0) return 0;
    int ok = tm_fixture_input(f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(f) == SILK_OK;
    gen_free(&gm);
    return ok;
}

/* The globe: gen's OBJ text (with vt lines) through silk_load_obj. */
static int globe_fixture(tm_fixture *f)
{
    gen_params p;
    gen_defaults(GEN_SPHERE, &p);
    p.radius = 1; p.segments = 12; p.bands = 9; p.uv = 1;
    size_t len;
    char *text = gen_obj_text(&p, &len);
    int ok = text && silk_load_obj(text, len, "globe", &f->opts, &f->a, &f->m, &f->err) == SILK_OK && f->m.uv;
    free(text);
    return ok;
}

/* The painted sphere: colour channels from the position, 0 at -1, 255 at +1. */
static int painted_fixture(tm_fixture *f)
{
    gen_params p;
    gen_defaults(GEN_SPHERE, &p);
    p.radius = 1; p.segments = 10; p.bands = 11;
    gen_mesh gm;
    if (gen_build(&p, &gm) != 0) return 0;
    int ok = tm_fixture_input(f, gm.pos, gm.nverts, gm.tri, gm.ntris);
    f->in.color = ok ? silk_arena_array(&f->a, gm.nverts, sizeof(uint32_t), SILK_MEM_MESH) : NULL;
    for (uint32_t v = 0; f->in.color && v < gm.nverts; v++) {
        uint32_t rgb = 0;
        for (int k = 0; k < 3; k++) rgb = rgb << 8 | (uint32_t)((gm.pos[3 * v + k] + 1) * 127.5 + 0.5);
        f->in.color[v] = rgb;
    }
    ok = f->in.color && tm_fixture_build(f) == SILK_OK && f->m.color;
    gen_free(&gm);
    return ok;
}

/* Returns 1 when the mesh is in f->m, 0 when it is skipped (bunny without
 * the shared meshes), -1 on failure. */
static int make_mesh(const char *name, tm_fixture *f)
{
    gen_params p;
    if (!strcmp(name, "bunny")) {
        char path[512];
        snprintf(path, sizeof path, "%s/bunny-500.obj", check_meshes_dir());
        FILE *fp = fopen(path, "rb");
        if (!fp) {
            printf("skip: bunny: %s not found (SILK_MESHES)\n", path);
            return 0;
        }
        fclose(fp);
        return tm_fixture_read_obj(f, path) && tm_fixture_build(f) == SILK_OK ? 1 : -1;
    }
    if (!strcmp(name, "globe")) return globe_fixture(f) ? 1 : -1;
    if (!strcmp(name, "painted")) return painted_fixture(f) ? 1 : -1;
    if (!strcmp(name, "sphere")) {
        gen_defaults(GEN_SPHERE, &p);
        p.radius = 1; p.segments = 10; p.bands = 11;                  /* 200 triangles */
    } else if (!strcmp(name, "torus")) {
        gen_defaults(GEN_TORUS, &p);
        p.R = 1; p.r = 0.4; p.segments = 16; p.bands = 8;             /* 256 */
    } else if (!strcmp(name, "cone")) {
        gen_defaults(GEN_CONE, &p);
        p.radius = 1; p.height = 1.5; p.segments = 24; p.bands = 1;   /* 48 */
    } else {
        gen_defaults(GEN_KNOT, &p);
        p.p = 2; p.q = 3; p.R = 1; p.r = 0.4; p.tube = 0.2; p.segments = 48; p.bands = 6;  /* 576 */
    }
    return gen_fixture(f, &p) ? 1 : -1;
}

/* ---- the views and modes ------------------------------------------------------ */

typedef struct view_case {
    const char *name;
    double dir[3], dist;
    int ortho;
} view_case;

static const view_case views[] = {
    { "front", { 0.470, 0.342, 0.814 }, 2.2, 0 },    /* the command's default direction */
    { "top", { -0.55, 0.78, -0.30 }, 3.0, 1 },
    { "graze", { 0.90, 0.03, 0.43 }, 1.7, 0 },       /* eye nearly in the equator plane, close */
};

typedef struct mode_case {
    const char *name;
    silk_mode mode;
    silk_lines lines;
    int polygonal, wire;
} mode_case;

static const mode_case modes[] = {
    { "flat", SILK_MODE_FLAT, SILK_LINES_NONE, 0, 0 },
    { "smooth", SILK_MODE_SMOOTH, SILK_LINES_NONE, 0, 0 },
    { "pn", SILK_MODE_PN, SILK_LINES_NONE, 0, 0 },
    { "blend", SILK_MODE_BLEND, SILK_LINES_NONE, 0, 0 },
    { "lines-over", SILK_MODE_SMOOTH, SILK_LINES_OVER, 0, 0 },
    { "lines-only", SILK_MODE_SMOOTH, SILK_LINES_ONLY, 0, 0 },
    { "lines-poly", SILK_MODE_PN, SILK_LINES_OVER, 1, 0 },
    { "wire", SILK_MODE_SMOOTH, SILK_LINES_NONE, 0, 1 },
};

/* ---- one golden frame --------------------------------------------------------- */

/* The frame's pixels as RGB888 rows (malloc'd). */
static uint8_t *frame_rgb(const silk_target *t)
{
    uint8_t *rgb = malloc((size_t)t->width * (size_t)t->height * 3);
    for (int y = 0; rgb && y < t->height; y++) silk_target_row_rgb888(t, y, rgb + (size_t)y * (size_t)t->width * 3);
    return rgb;
}

/* The pixels of the frame that differ from NAME.png's (-1: no such image
 * of the frame's size). */
static long golden_differ(const silk_target *t, const char *path)
{
    uint8_t *mine = frame_rgb(t), *ref = NULL;
    int rw = 0, rh = 0;
    silk_error err;
    long differ = -1;
    FILE *probe = fopen(path, "rb");
    if (probe) fclose(probe);
    if (mine && probe && silk_png_read(path, &ref, &rw, &rh, &err) == SILK_OK && rw == t->width && rh == t->height) {
        differ = 0;
        for (size_t i = 0, n = (size_t)t->width * (size_t)t->height * 3; i < n; i += 3)
            differ += memcmp(mine + i, ref + i, 3) != 0;
    }
    free(ref);
    free(mine);
    return differ;
}

/* The frame against NAME's reference (support/golden.h). */
static int compare_golden(const silk_target *t, const char *name)
{
    char msg[600];
    int same = golden_compare(t, name, msg, sizeof msg);
    CHECKF(same, "%s", msg);
    return same;
}

/* ---- the frames as a build without anti-aliasing draws them ------------------- */

/* A build with SILK_AA 0 draws every frame as silk_render_opts.aa = 0
 * does, one with SILK_AA_CREASES 0 as aa = 2 does (silk/config.h; the
 * boards' configurations): tests/golden/aliased.txt holds those frames of
 * the golden cases (aa 1) as NAME-aa0 and NAME-aa2 with the CRC-32 of
 * their RGB888 rows, one a line, where they differ from NAME.png (a frame
 * not listed is NAME.png's).  The host draws all three and the boards'
 * configurations theirs, so a board's frames are checked here too. */
#define ALIASED_MAX 1024
static struct aliased_entry {
    char name[128];
    uint32_t crc;
} aliased[ALIASED_MAX];
static int n_aliased, aliased_loaded, aliased_changed;

static const char *aliased_path(void)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/aliased.txt", golden_dir());
    return path;
}

static struct aliased_entry *aliased_find(const char *name)
{
    if (!aliased_loaded) {
        aliased_loaded = 1;
        FILE *fp = fopen(aliased_path(), "r");
        char line[160];
        while (fp && fgets(line, sizeof line, fp) && n_aliased < ALIASED_MAX) {
            struct aliased_entry *e = &aliased[n_aliased];
            unsigned crc;
            if (line[0] != '#' && sscanf(line, "%127s %x", e->name, &crc) == 2) {
                e->crc = crc;
                n_aliased++;
            }
        }
        if (fp) fclose(fp);
    }
    for (int i = 0; i < n_aliased; i++)
        if (!strcmp(aliased[i].name, name)) return &aliased[i];
    return NULL;
}

static void aliased_write(void)
{
    FILE *fp = fopen(aliased_path(), "w");
    CHECKF(fp != NULL, "%s: cannot write", aliased_path());
    if (!fp) return;
    fprintf(fp, "# The golden frames as silk_render_opts.aa 0 (-aa0) and 2 (-aa2) draw them, where they\n"
                "# differ from NAME.png: the CRC-32 of their RGB888 rows (tests/test_golden.c, make golden).\n");
    for (int i = 0; i < n_aliased; i++) fprintf(fp, "%s %08x\n", aliased[i].name, (unsigned)aliased[i].crc);
    fclose(fp);
}

/* The frame, drawn as aa (0 or 2) draws NAME's, against its entry or
 * NAME.png; with --update the entry follows the frame. */
static void compare_aliased(const silk_target *t, const char *name, int aa)
{
    char vname[128], path[512];
    snprintf(vname, sizeof vname, "%s-aa%d", name, aa);
    snprintf(path, sizeof path, "%s/%s.png", golden_dir(), name);
    uint8_t *rgb = frame_rgb(t);
    uint32_t crc = rgb ? silk_crc32(0, rgb, (size_t)t->width * (size_t)t->height * 3) : 0;
    free(rgb);
    struct aliased_entry *e = aliased_find(vname);
    int same = e ? e->crc == crc : golden_differ(t, path) == 0;
    if (same) {
        n_same++;
        return;
    }
    if (update) {
        int existed = e != NULL;
        if (!e && n_aliased < ALIASED_MAX) {
            e = &aliased[n_aliased++];
            snprintf(e->name, sizeof e->name, "%s", vname);
        }
        if (e) e->crc = crc;
        printf("%s: %s (aliased.txt)\n", existed ? "changed" : "new", vname);
        if (existed) n_changed++;
        else n_new++;
        aliased_changed = 1;
        return;
    }
    CHECKF(0, "%s: differs from %s (make golden)", vname, e ? "its CRC in aliased.txt" : "the golden image");
}

/* The anti-aliasing a build draws when asked for aa: 0 without SILK_AA,
 * 2 (outlines only) without SILK_AA_CREASES. */
static int aa_drawn(int aa)
{
    return !SILK_AA ? 0 : aa == 1 && !SILK_AA_CREASES ? 2 : aa;
}

/* Draws one frame whole and in bands, and compares it: with NAME.png
 * (aa 1, or a clip frame), with its aliased form (aa 0, 2), or not at all
 * (compare 0: a build without textures draws a textured model otherwise). */
static void golden_frame(tm_fixture *f, const char *name, const view_case *vc, const mode_case *mc, silk_pixfmt fmt,
                         int one_row_bands, const silk_silmap *map, int aa, int compare)
{
    silk_view v;
    if (!tf_view_around_size(&f->m, vc->dir, vc->dist, vc->ortho, W, H, &v)) {
        CHECKF(0, "%s: no view", name);
        return;
    }
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    if (mesh_texture || f->m.color || (mesh_siltex && mesh_siltex->color)) ph.mat.color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
    ph.texture = mesh_texture;
    ph.vertex_colors = f->m.color != NULL;
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mc->mode;
    ro.lines = mc->lines;
    ro.lines_polygonal = mc->polygonal;
    ro.wire = mc->wire;
    ro.bg_rgb = BG;
    ro.silmap = map;
    ro.siltex = mesh_siltex;
    ro.aa = aa;

    silk_arena_mark mk = silk_arena_top_mark(&f->a);
    size_t bpp = silk_pixfmt_bytes(fmt), bytes = (size_t)W * H * bpp;
    uint8_t *color = silk_arena_alloc_top(&f->a, bytes, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array_top(&f->a, (size_t)W * H, sizeof *depth, SILK_MEM_RASTER);
    uint8_t *copy = malloc(bytes);
    if (!color || !depth || !copy) {
        CHECKF(0, "%s: out of memory", name);
        free(copy);
        silk_arena_top_release(&f->a, &mk);
        return;
    }
    silk_target full;
    silk_target_init(&full, W, H, 0, H, fmt, color, depth);
    silk_target_clear(&full, BG);
    silk_frame_stats fs, bs;
    silk_error err;
    silk_status st = silk_render(&f->a, &f->m, &v, &hal, &ro, &full, &fs, &err);
    CHECKF(st == SILK_OK, "%s: %s", name, err.msg);
    CHECKF(!fs.fell_back, "%s: the frame fell back", name);

    int heights[2] = { 16, 1 };
    for (int k = 0; k < (one_row_bands ? 2 : 1); k++) {
        memset(copy, 0xA5, bytes);
        tf_collect c = { copy, 0, 0, 0, 0, 0 };
        st = tf_render_bands(&f->a, &f->m, &v, &hal, &ro, fmt, heights[k], &c, &bs, &err);
        CHECKF(st == SILK_OK && c.bad == 0 && c.next_row == H, "%s: bands of %d: %s", name, heights[k],
               st == SILK_OK ? "out of order" : err.msg);
        CHECKF(memcmp(copy, color, bytes) == 0, "%s: bands of %d rows differ from the whole frame", name,
               heights[k]);
    }
    if (!compare) n_unbuilt++;
    else if (map || aa == 1) compare_golden(&full, name);
    else compare_aliased(&full, name, aa);
    free(copy);
    silk_arena_top_release(&f->a, &mk);
}

/* One golden case: a clip frame with (antialias) or without its outline
 * anti-aliased (NAME-centres), another as the default draws it (aa 1) and
 * as aa 0 and 2 do, each as far as the core is built to draw it. */
static void golden_case(tm_fixture *f, const char *mesh, const view_case *vc, const mode_case *mc,
                        silk_pixfmt fmt, int one_row_bands, const silk_silmap *map, int antialias)
{
    char name[128];
    snprintf(name, sizeof name, "%s-%s-%s%s%s", mesh, vc->name, mc->name, map && !antialias ? "-centres" : "",
             fmt == SILK_PIX_RGB565 ? "-565" : "");
    int compare = SILK_TEXTURES || !(mesh_texture || (mesh_siltex && mesh_siltex->color));
    if (!ts_mode_built(mc->mode) || (!SILK_LINES && (mc->lines || mc->wire)) || (map && antialias && !SILK_AA)) {
        n_unbuilt++;
        return;
    }
    if (map) {
        golden_frame(f, name, vc, mc, fmt, one_row_bands, map, antialias, compare);
        return;
    }
    static const int aas[3] = { 1, 0, 2 };
    for (int k = 0, first = 1; k < 3; k++)
        if (aa_drawn(aas[k]) == aas[k]) {
            golden_frame(f, name, vc, mc, fmt, one_row_bands && first, NULL, aas[k], compare);
            first = 0;
        }
}

static void golden_mesh(const char *mesh)
{
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    int got = make_mesh(mesh, &f);
    CHECKF(got >= 0, "%s: cannot make the mesh", mesh);
    if (got == 1) {
        for (size_t iv = 0; iv < sizeof views / sizeof views[0]; iv++)
            for (size_t im = 0; im < sizeof modes / sizeof modes[0]; im++)
                golden_case(&f, mesh, &views[iv], &modes[im], SILK_PIX_RGB888, iv == 0, NULL, 0);
        /* RGB565: the default mode with and without lines, and flat, from the first view. */
        golden_case(&f, mesh, &views[0], &modes[0], SILK_PIX_RGB565, 1, NULL, 0);
        golden_case(&f, mesh, &views[0], &modes[1], SILK_PIX_RGB565, 1, NULL, 0);
        golden_case(&f, mesh, &views[2], &modes[4], SILK_PIX_RGB565, 0, NULL, 0);
    }
    tm_fixture_free(&f);
}

/* A prepared model of a (2,3) knot of 2304 triangles in memory, as silk
 * prepare makes one: its outer hull of 400 triangles with the detailed
 * normals at its vertices (HULL), and its silhouette map of 42 views of
 * 128 pixels (SMAP).  NULL when out of memory. */
static uint8_t *knot_model(size_t *len)
{
    gen_params p;
    gen_mesh gm;
    gen_defaults(GEN_KNOT, &p);
    p.p = 2; p.q = 3; p.R = 1; p.r = 0.4; p.tube = 0.2; p.segments = 96; p.bands = 12;
    if (gen_build(&p, &gm) != 0) return NULL;
    simp_mesh fine = { gm.nverts, gm.ntris, gm.pos, gm.tri, NULL }, h;
    hull_opts ho;
    hull_stats hs;
    hull_fine hf = { NULL, NULL };
    silmap_params mp;
    silmap map;
    silmap_fixed fx;
    model_out mo = { 0 };
    uint8_t *bytes = NULL;
    hull_opts_default(&ho, 400);
    silmap_params_default(&mp);
    mp.level = 1;
    mp.res = 128;
    if (simp_copy(&fine, &h) == 0 && hull_run(&h, &ho, &hs, &hf) == 0 &&
        silmap_build(gm.pos, gm.nverts, gm.tri, gm.ntris, &mp, &map) == 0) {
        if (silmap_export(&map, &fx) == 0) {
            if (model_add_mesh_doubles(&mo, SILK_SECTION_HULL, 0, h.nverts, h.pos, h.nverts, hf.normal, h.ntris,
                                       h.tri, NULL) == 0 &&
                model_add_silmap(&mo, &fx.map) == 0)
                bytes = model_bytes(&mo, len);
            silmap_fixed_free(&fx);
        }
        silmap_free(&map);
    }
    model_free(&mo);
    simp_free(&h);
    hull_fine_free(&hf);
    gen_free(&gm);
    return bytes;
}

static void golden_clip(void)
{
    size_t len = 0;
    uint8_t *file = knot_model(&len);
    CHECKF(file != NULL, "knot model: out of memory");
    if (!file) return;
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    silk_silmap map;
    f.opts.part = SILK_PART_HULL;
    CHECKF(silk_load_model(file, len, "knot.silk", &f.opts, &f.a, &f.m, &f.err) == SILK_OK, "%s", f.err.msg);
    CHECKF(silk_model_silmap(file, len, "knot.silk", &map, &f.err) == SILK_OK, "%s", f.err.msg);
    static const mode_case clip = { "clip", SILK_MODE_CLIP, SILK_LINES_NONE, 0, 0 };
    if (f.m.ntris)
        for (size_t iv = 0; iv < sizeof views / sizeof views[0]; iv++)
            for (int aa = 1; aa >= 0; aa--) golden_case(&f, "knot", &views[iv], &clip, SILK_PIX_RGB888, 1, &map, aa);
    tm_fixture_free(&f);
    free(file);
}

/* Siltex frames of two spheres' hulls (tests/support/stexgen.c), one in
 * front of the other from the first view, with a colour map; the angles
 * stored and compressed draw the same (the compressed form is exact here). */
static void golden_siltex(void)
{
    stexgen_opts o;
    stexgen_defaults(&o);
    o.nspheres = 2;
    o.c[1][0] = 1.2;
    o.c[1][1] = 0.3;
    o.c[1][2] = -1.6;
    o.r[1] = 0.8;
    o.R[1] = 0.85;
    o.color = 1;
    size_t len = 0;
    uint8_t *file = stexgen_model(&o, &len);
    CHECKF(file != NULL, "spheres model: out of memory");
    if (!file) return;
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    silk_siltex st;
    f.opts.part = SILK_PART_HULL;
    CHECKF(silk_load_model(file, len, "spheres.silk", &f.opts, &f.a, &f.m, &f.err) == SILK_OK, "%s", f.err.msg);
    CHECKF(silk_model_siltex(file, len, "spheres.silk", &st, &f.err) == SILK_OK, "%s", f.err.msg);
    static const mode_case siltex = { "siltex", SILK_MODE_SILTEX, SILK_LINES_NONE, 0, 0 };
    mesh_siltex = &st;
    /* from the front the far sphere shows through the near one's hull */
    static const view_case sv[] = {
        { "front", { 0.470, 0.342, 0.814 }, 2.2, 0 },
        { "overlap", { 0.12, 0.05, 1 }, 2.0, 0 },
        { "overlap-ortho", { 0.12, 0.05, 1 }, 3.0, 1 },
    };
    if (f.m.ntris) {
        for (size_t iv = 0; iv < sizeof sv / sizeof sv[0]; iv++)
            golden_case(&f, "spheres", &sv[iv], &siltex, SILK_PIX_RGB888, 1, NULL, 0);
        golden_case(&f, "spheres", &sv[1], &siltex, SILK_PIX_RGB565, 0, NULL, 0);
        /* the silhouettes from the texture (eq. 5), the near sphere's over the far one */
        static const mode_case lines = { "siltex-lines-only", SILK_MODE_SILTEX, SILK_LINES_ONLY, 0, 0 };
        static const mode_case over = { "siltex-lines-over", SILK_MODE_SILTEX, SILK_LINES_OVER, 0, 0 };
        golden_case(&f, "spheres", &sv[1], &lines, SILK_PIX_RGB888, 1, NULL, 0);
        golden_case(&f, "spheres", &sv[2], &over, SILK_PIX_RGB888, 0, NULL, 0);
    }
    mesh_siltex = NULL;
    tm_fixture_free(&f);
    free(file);
}

/* The surface modes from the front and grazing views, and smooth in RGB565. */
static void golden_coloured(const char *mesh, const silk_texture *tex)
{
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    mesh_texture = tex;
    int got = make_mesh(mesh, &f);
    CHECKF(got == 1, "%s: cannot make the mesh", mesh);
    if (got == 1) {
        for (size_t iv = 0; iv < sizeof views / sizeof views[0]; iv += 2)
            for (size_t im = 0; im < 4; im++) golden_case(&f, mesh, &views[iv], &modes[im], SILK_PIX_RGB888, iv == 0, NULL, 0);
        golden_case(&f, mesh, &views[0], &modes[1], SILK_PIX_RGB565, 0, NULL, 0);
    }
    mesh_texture = NULL;
    tm_fixture_free(&f);
}

TEST(golden_globe)
{
    enum { SIZE = 128 };
    static uint8_t px[SIZE * SIZE * 3 * 2];
    silk_texture t = { px, NULL, SIZE, SIZE, SILK_TEX_RGB888, 0, SILK_TEX_BILINEAR, SILK_TEX_REPEAT };
    t.levels = (uint8_t)silk_texture_max_levels(SIZE, SIZE);
    CHECK(silk_texture_bytes(SILK_TEX_RGB888, SIZE, SIZE, t.levels) <= sizeof px);
    gen_checker(px, SIZE, 8);
    silk_texture_build_mipmaps(&t, px);
    golden_coloured("globe", &t);
}

TEST(golden_painted) { golden_coloured("painted", NULL); }

TEST(golden_sphere) { golden_mesh("sphere"); }
TEST(golden_torus) { golden_mesh("torus"); }
TEST(golden_cone) { golden_mesh("cone"); }
TEST(golden_knot) { golden_mesh("knot"); }
TEST(golden_bunny) { golden_mesh("bunny"); }
/* A comparison that fails leaves the frame and the difference: a sphere's
 * frame against a reference with three pixels changed, in a directory of
 * its own. */
TEST(failure_leaves_images)
{
    char dir[] = "/tmp/silk-golden.XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char refdir[64], outdir[64], path[128];
    snprintf(refdir, sizeof refdir, "%s/ref", dir);
    snprintf(outdir, sizeof outdir, "%s/out", dir);
    CHECK(mkdir(refdir, 0777) == 0);
    enum { TW = 32, TH = 24 };
    static uint8_t px[TW * TH * 3];
    for (int i = 0; i < TW * TH * 3; i++) px[i] = (uint8_t)(i * 7);
    silk_target t;
    silk_target_init(&t, TW, TH, 0, TH, SILK_PIX_RGB888, px, NULL);
    silk_error err;
    snprintf(path, sizeof path, "%s/frame.png", refdir);
    /* the reference: the frame with three pixels changed */
    static uint8_t ref[TW * TH * 3];
    memcpy(ref, px, sizeof ref);
    const int changed[3] = { 0, 5 * TW + 7, TW * TH - 1 };
    for (int k = 0; k < 3; k++) ref[3 * changed[k]] ^= 0x40;
    silk_target rt;
    silk_target_init(&rt, TW, TH, 0, TH, SILK_PIX_RGB888, ref, NULL);
    CHECK(silk_png_write(&rt, path, &err) == SILK_OK);
    const char *was_golden = getenv("SILK_GOLDEN"), *was_out = getenv("SILK_TEST_OUT"),
               *was_update = getenv("SILK_GOLDEN_UPDATE");
    char keep[3][512];
    snprintf(keep[0], sizeof keep[0], "%s", was_golden ? was_golden : "");
    snprintf(keep[1], sizeof keep[1], "%s", was_out ? was_out : "");
    snprintf(keep[2], sizeof keep[2], "%s", was_update ? was_update : "");
    setenv("SILK_GOLDEN", refdir, 1);
    setenv("SILK_TEST_OUT", outdir, 1);
    unsetenv("SILK_GOLDEN_UPDATE");
    char msg[600];
    CHECKF(golden_compare(&t, "frame", msg, sizeof msg) == 0, "the frame differs, yet it passed");
    CHECKF(strstr(msg, "3 pixels differ") != NULL, "%s", msg);
    uint8_t *got = NULL, *diff = NULL;
    int w = 0, h = 0, dw = 0, dh = 0;
    snprintf(path, sizeof path, "%s/frame.png", outdir);
    CHECKF(silk_png_read(path, &got, &w, &h, &err) == SILK_OK, "%s is not there: %s", path, err.msg);
    CHECK(got && w == TW && h == TH && memcmp(got, px, sizeof px) == 0);
    snprintf(path, sizeof path, "%s/frame-diff.png", outdir);
    CHECKF(silk_png_read(path, &diff, &dw, &dh, &err) == SILK_OK, "%s is not there: %s", path, err.msg);
    int red = 0, red_right = 0;
    for (int i = 0; diff && dw == TW && dh == TH && i < TW * TH; i++) {
        int is_red = diff[3 * i] == 255 && diff[3 * i + 1] == 0 && diff[3 * i + 2] == 0;
        red += is_red;
        for (int k = 0; k < 3; k++) red_right += is_red && i == changed[k];
    }
    CHECKF(red == 3 && red_right == 3, "the difference has %d red pixels, %d of them the changed ones", red, red_right);
    free(got);
    free(diff);
    /* as it was */
    if (was_golden) setenv("SILK_GOLDEN", keep[0], 1);
    else unsetenv("SILK_GOLDEN");
    if (was_out) setenv("SILK_TEST_OUT", keep[1], 1);
    else unsetenv("SILK_TEST_OUT");
    if (was_update) setenv("SILK_GOLDEN_UPDATE", keep[2], 1);
    const char *files[] = { "ref/frame.png", "out/frame.png", "out/frame-diff.png", "ref", "out" };
    for (int k = 0; k < 5; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        remove(path);
    }
    remove(dir);
}
TEST(golden_knot_clip)
{
    if (check_built(SILK_CLIP_MODE, "SILK_CLIP_MODE")) golden_clip();
}

TEST(golden_spheres_siltex)
{
    if (check_built(SILK_SILTEX_MODE, "SILK_SILTEX_MODE")) golden_siltex();
}

int main(void)
{
    update = getenv("SILK_GOLDEN_UPDATE") && *getenv("SILK_GOLDEN_UPDATE") && strcmp(getenv("SILK_GOLDEN_UPDATE"), "0");
    RUN(golden_sphere);
    RUN(golden_torus);
    RUN(golden_cone);
    RUN(golden_knot);
    RUN(golden_knot_clip);
    RUN(golden_spheres_siltex);
    RUN(golden_bunny);
    RUN(golden_globe);
    RUN(golden_painted);
    RUN(failure_leaves_images);
    if (update && aliased_changed) aliased_write();
    if (update && (n_changed || n_new))
        printf("golden: %d aliased frames changed, %d new in %s/aliased.txt\n", n_changed, n_new, golden_dir());
    golden_summary();
    if (n_unbuilt)
        printf("golden: %d frames not drawn or not compared: the core is built without what they need "
               "(silk/config.h)\n", n_unbuilt);
    return check_done();
}
