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
 *   test_golden            compare (make test)
 *   test_golden --update   rewrite the images that differ or are missing
 *                          and print "changed: NAME" / "new: NAME" for each
 *                          (make golden)
 *
 * SILK_GOLDEN overrides the directory (default tests/golden).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "../platform/platform.h"
#include "../platform/png_read.h"
#include "../tools/prep/gen.h"
#include "../tools/prep/hull.h"
#include "../tools/prep/model_file.h"
#include "../tools/prep/silmap.h"
#include "support/testmesh.h"
#include "support/testframe.h"
#include "support/stexgen.h"

#define W 128
#define H 96
#define BG 0xFFFFFFu
#define ARENA_BYTES (24u << 20)

static int update;
static int n_changed, n_new, n_same;
static const silk_texture *mesh_texture;   /* the texture of the mesh being drawn, or NULL */
static const silk_siltex *mesh_siltex;     /* the silhouette texture of the hull being drawn, or NULL */

static const char *golden_dir(void)
{
    const char *d = getenv("SILK_GOLDEN");
    return d ? d : "tests/golden";
}

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

/* The frame against NAME.png: 1 when equal (or rewritten with --update). */
static int compare_golden(const silk_target *t, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.png", golden_dir(), name);
    size_t n = (size_t)t->width * (size_t)t->height * 3;
    uint8_t *mine = malloc(n);
    for (int y = 0; y < t->height; y++) silk_target_row_rgb888(t, y, mine + (size_t)y * (size_t)t->width * 3);

    uint8_t *ref = NULL;
    int rw = 0, rh = 0;
    silk_error err;
    FILE *probe = fopen(path, "rb");
    int exists = probe != NULL;
    if (probe) fclose(probe);
    long differ = -1;
    if (exists && silk_png_read(path, &ref, &rw, &rh, &err) == SILK_OK && rw == t->width && rh == t->height) {
        differ = 0;
        for (size_t i = 0; i < n; i += 3) differ += memcmp(mine + i, ref + i, 3) != 0;
    }
    free(ref);
    free(mine);
    if (differ == 0) {
        n_same++;
        return 1;
    }
    if (update) {
        if (silk_png_write(t, path, &err) != SILK_OK) {
            CHECKF(0, "%s", err.msg);
            return 0;
        }
        printf("%s: %s\n", exists ? "changed" : "new", name);
        if (exists) n_changed++;
        else n_new++;
        return 1;
    }
    if (!exists) CHECKF(0, "%s: no golden image (make golden)", path);
    else CHECKF(differ == 0, "%s: %ld pixels differ from the golden image", name, differ);
    return 0;
}

static void golden_case(tm_fixture *f, const char *mesh, const view_case *vc, const mode_case *mc,
                        silk_pixfmt fmt, int one_row_bands, const silk_silmap *map, int antialias)
{
    char name[128];
    snprintf(name, sizeof name, "%s-%s-%s%s%s", mesh, vc->name, mc->name, map && !antialias ? "-centres" : "",
             fmt == SILK_PIX_RGB565 ? "-565" : "");
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
    if (map) ro.aa = antialias;   /* clip frames: with and without; the others as by default */

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
    compare_golden(&full, name);
    free(copy);
    silk_arena_top_release(&f->a, &mk);
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
TEST(golden_knot_clip) { golden_clip(); }
TEST(golden_spheres_siltex) { golden_siltex(); }

int main(int argc, char **argv)
{
    update = argc > 1 && !strcmp(argv[1], "--update");
    RUN(golden_sphere);
    RUN(golden_torus);
    RUN(golden_cone);
    RUN(golden_knot);
    RUN(golden_knot_clip);
    RUN(golden_spheres_siltex);
    RUN(golden_bunny);
    RUN(golden_globe);
    RUN(golden_painted);
    if (update)
        printf("golden: %d changed, %d new, %d unchanged in %s\n", n_changed, n_new, n_same, golden_dir());
    return check_done();
}
