/*
 * test_bands.c - band rendering: silk_render_bands() must
 * give exactly the pixels of silk_render() for any band height.
 *
 * Two shared meshes (bunny-500, torus-576) are drawn at 320x240 from
 * several views (perspective and orthographic, above and below), FLAT and
 * SMOOTH, RGB565 and RGB888, in bands of 1, 7, 16 and 240 rows.  A sink
 * copies each band into a full frame; the copy must equal the full-frame
 * render byte for byte.  The sink also checks what a display driver relies
 * on: bands arrive top to bottom, each row exactly once, never taller than
 * asked (7 does not divide 240, so the last band is short).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "tools/prep/gen.h"
#include "silk/silk.h"

#define W 320
#define H 240
#define ARENA_BYTES (8u << 20)
#define BG 0xFF00FFu

static uint8_t *arena_buf;

static char *read_mesh_file(const char *name, size_t *len)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    char *b = NULL;
    if (fseek(fp, 0, SEEK_END) == 0) {
        long n = ftell(fp);
        if (n > 0 && fseek(fp, 0, SEEK_SET) == 0 && (b = malloc((size_t)n + 1))) {
            if (fread(b, 1, (size_t)n, fp) != (size_t)n) {
                free(b);
                b = NULL;
            } else {
                *len = (size_t)n;
            }
        }
    }
    fclose(fp);
    return b;
}

/* Load a shared mesh with its visibility hierarchy, as `silk render` does. */
static int load(silk_arena *a, const char *name, silk_mesh *m)
{
    size_t len = 0;
    char *text = read_mesh_file(name, &len);
    if (!text) {
        fprintf(stderr, "cannot read %s/%s\n", check_meshes_dir(), name);
        return 0;
    }
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    silk_status st = silk_load_mesh(text, len, name, &o, a, m, &err);
    if (st == SILK_OK) st = silk_vis_build(m, NULL, a, &err);
    free(text);
    if (st != SILK_OK) fprintf(stderr, "%s: %s\n", name, err.msg);
    return st == SILK_OK;
}

static silk_fx d2fx(double v) { return (silk_fx)llround(v * 65536.0); }

/* The model's bounding-box centre seen from azimuth/elevation (degrees). */
static int make_view(const silk_mesh *m, double az, double el, int ortho, silk_view *v)
{
    const double deg = 3.14159265358979323846 / 180;
    double c[3], r = tf_bounds(m, c);
    double d[3] = { cos(el * deg) * sin(az * deg), sin(el * deg), cos(el * deg) * cos(az * deg) };
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(d2fx(c[0] + 3 * r * d[0]), d2fx(c[1] + 3 * r * d[1]), d2fx(c[2] + 3 * r * d[2]));
    cam.target = silk_v3(d2fx(c[0]), d2fx(c[1]), d2fx(c[2]));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.ortho = ortho;
    cam.fov_deg = SILK_FX_C(40, 1);
    cam.ortho_half_height = d2fx(r * 1.1);
    cam.znear = d2fx(r * 0.5);
    cam.zfar = d2fx(r * 5);
    cam.width = W;
    cam.height = H;
    silk_error err;
    if (silk_view_init(v, &cam, &err) != SILK_OK) {
        fprintf(stderr, "view: %s\n", err.msg);
        return 0;
    }
    return 1;
}

static long count_not_bg(const silk_target *t)
{
    long n = 0;
    for (int y = 0; y < t->height; y++)
        for (int x = 0; x < t->width; x++) n += silk_target_get(t, x, y) != BG;   /* magenta survives RGB565 exactly */
    return n;
}

typedef struct scene_case {
    const char *mesh;
    double az, el;
    int ortho;
} scene_case;

static const scene_case cases[] = {
    { "bunny-500.obj", 30, 20, 0 },
    { "bunny-500.obj", 200, -35, 0 },
    { "bunny-500.obj", 110, 60, 1 },
    { "torus-576.obj", 0, 25, 0 },
    { "torus-576.obj", 75, -80, 1 },
};
static const int band_heights[] = { 1, 7, 16, 240 };

/* One scene of mesh m in arena a: full frame once, then every band
 * height; all must agree.  aa 0 as on the boards: the bands then skip the
 * back faces culled once for every band (render.c part_hidden). */
static void check_mesh(silk_arena *arena, const silk_mesh *mesh, const scene_case *sc, silk_mode mode, silk_pixfmt fmt,
                       int wire, int aa)
{
    silk_arena a = *arena;
    silk_mesh m = *mesh;
    silk_view v;
    if (!make_view(&m, sc->az, sc->el, sc->ortho, &v)) {
        CHECKF(0, "cannot set up %s", sc->mesh);
        return;
    }
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;
    ro.bg_rgb = BG;
    ro.wire = wire;
    ro.aa = aa;

    size_t bpp = silk_pixfmt_bytes(fmt), frame_bytes = (size_t)W * H * bpp;
    uint8_t *color = silk_arena_alloc(&a, frame_bytes, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&a, (size_t)W * H, sizeof *depth, SILK_MEM_RASTER);
    uint8_t *copy = malloc(frame_bytes);
    if (!color || !depth || !copy) {
        CHECKF(0, "out of memory");
        free(copy);
        return;
    }
    silk_target full;
    silk_target_init(&full, W, H, 0, H, fmt, color, depth);
    silk_frame_stats fs, bs;
    silk_error err;
    silk_status st = silk_render(&a, &m, &v, &hal, &ro, &full, &fs, &err);
    CHECKF(st == SILK_OK, "%s: %s", sc->mesh, err.msg);
    long drawn = count_not_bg(&full);
    /* A blank frame would make every comparison below pass. */
    CHECKF(drawn > 2000, "%s az %g: only %ld pixels drawn", sc->mesh, sc->az, drawn);
    if (mode == SILK_MODE_SMOOTH) CHECKF(fs.silhouette_tris > 0, "%s: no silhouette", sc->mesh);

    for (size_t k = 0; k < sizeof band_heights / sizeof band_heights[0]; k++) {
        int rows = band_heights[k];
        memset(copy, 0xA5, frame_bytes);
        tf_collect c = { copy, 0, 0, 0, 0, 0 };
        st = tf_render_bands(&a, &m, &v, &hal, &ro, fmt, rows, &c, &bs, &err);
        CHECKF(st == SILK_OK, "rows %d: %s", rows, err.msg);
        CHECKF(c.bad == 0 && c.next_row == H, "rows %d: %d bands out of order or the band target not restored, "
               "ended at row %d", rows, c.bad, c.next_row);
        CHECKF(c.bands == (H + rows - 1) / rows, "rows %d: %d bands", rows, c.bands);
        CHECKF(bs.tris_drawn == fs.tris_drawn && bs.fell_back == fs.fell_back,
               "rows %d: %u triangles, full frame %u", rows, bs.tris_drawn, fs.tris_drawn);
        size_t diff = 0, first = 0;
        for (size_t i = 0; i < frame_bytes; i++)
            if (copy[i] != color[i] && !diff++) first = i;
        CHECKF(diff == 0, "%s az %g el %g %s %s: band height %d differs in %zu bytes, first at row %zu",
               sc->mesh, sc->az, sc->el, mode == SILK_MODE_SMOOTH ? "smooth" : "flat",
               fmt == SILK_PIX_RGB565 ? "rgb565" : "rgb888", rows, diff, first / (W * bpp));
    }
    free(copy);
}

static void check_case(const scene_case *sc, silk_mode mode, silk_pixfmt fmt, int wire, int aa)
{
    silk_arena a;
    silk_mesh m;
    if (!load(&a, sc->mesh, &m)) {
        CHECKF(0, "cannot set up %s", sc->mesh);
        return;
    }
    check_mesh(&a, &m, sc, mode, fmt, wire, aa);
}

TEST(bands_equal_full_frame_flat)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) check_case(&cases[i], SILK_MODE_FLAT, SILK_PIX_RGB565, 0, 1);
}

TEST(bands_equal_full_frame_smooth)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) check_case(&cases[i], SILK_MODE_SMOOTH, SILK_PIX_RGB565, 0, 1);
}

TEST(bands_equal_full_frame_rgb888_wire)
{
    if (!check_built(SILK_LINES, "SILK_LINES")) return;
    check_case(&cases[0], SILK_MODE_SMOOTH, SILK_PIX_RGB888, 1, 1);
    check_case(&cases[3], SILK_MODE_FLAT, SILK_PIX_RGB888, 1, 1);
}

TEST(bands_equal_full_frame_without_aa)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        check_case(&cases[i], SILK_MODE_FLAT, SILK_PIX_RGB565, 0, 0);
        check_case(&cases[i], SILK_MODE_SMOOTH, SILK_PIX_RGB565, 0, 0);
    }
}

/* Creases blended by the anti-aliasing read the rows next to a band too:
 * `silk gen`'s cylinder, its rims in view, FLAT and SMOOTH. */
TEST(bands_equal_full_frame_creases)
{
    const scene_case sc[] = { { "cylinder", 20, 30, 0 }, { "cylinder", 250, -40, 1 } };
    tm_fixture f;
    gen_params p;
    gen_mesh gm;
    silk_error err;
    tm_fixture_init(&f, ARENA_BYTES);
    gen_defaults(GEN_CYLINDER, &p);
    int ok = gen_build(&p, &gm) == 0;
    if (ok) {
        ok = tm_fixture_input(&f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(&f) == SILK_OK &&
             silk_vis_build(&f.m, NULL, &f.a, &err) == SILK_OK;
        gen_free(&gm);
    }
    CHECKF(ok, "cannot build the cylinder");
    for (size_t i = 0; ok && i < sizeof sc / sizeof sc[0]; i++) {
        check_mesh(&f.a, &f.m, &sc[i], SILK_MODE_SMOOTH, SILK_PIX_RGB565, 0, 1);
        check_mesh(&f.a, &f.m, &sc[i], SILK_MODE_FLAT, SILK_PIX_RGB888, 0, 1);
    }
    tm_fixture_free(&f);
}

/* A sink that stops the frame: the error names the row, nothing more is
 * sent, and the arena's top is back where it was. */
TEST(sink_stop_is_an_error)
{
    silk_arena a;
    silk_mesh m;
    silk_view v;
    if (!load(&a, "bunny-500.obj", &m) || !make_view(&m, 30, 20, 0, &v)) {
        CHECKF(0, "cannot set up bunny-500");
        return;
    }
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    enum { ROWS = 16 };
    uint8_t *bc = silk_arena_alloc(&a, (size_t)ROWS * W * 2, SILK_MEM_RASTER);
    uint32_t *bd = silk_arena_array(&a, (size_t)ROWS * W, sizeof *bd, SILK_MEM_RASTER);
    uint8_t *copy = malloc((size_t)W * H * 2);
    CHECK(bc && bd && copy);
    if (!bc || !bd || !copy) {
        free(copy);
        return;
    }
    silk_target band;
    silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB565, bc, bd);
    tf_collect c = { copy, 0, ROWS, 0, 0, 3 };
    silk_sink sink = { .band = tf_collect_band, .user = &c };
    size_t top = a.top;
    silk_error err;
    silk_status st = silk_render_bands(&a, &m, &v, &hal, &ro, &band, &sink, NULL, &err);
    CHECKF(st == SILK_ERR_IO, "status %d", (int)st);
    CHECKF(c.bands == 3, "%d bands after the sink stopped at 3", c.bands);
    CHECKF(strstr(err.msg, "row 32") != NULL, "message \"%s\"", err.msg);
    CHECK(a.top == top);
    CHECK(band.rows == ROWS && band.y0 == 0);

    /* Missing pieces are argument errors, not crashes. */
    silk_sink none = { .band = NULL, .user = NULL };
    CHECK(silk_render_bands(&a, &m, &v, &hal, &ro, &band, &none, NULL, &err) == SILK_ERR_ARG);
    CHECK(silk_render_bands(&a, &m, &v, &hal, &ro, NULL, &sink, NULL, &err) == SILK_ERR_ARG);
    free(copy);
}

/* A sink that sends by "DMA" and completes late: band() only notes the
 * buffer, and its rows are copied into the frame when wait() asks for that
 * buffer back (or at the end, as a flush), so a renderer that drew into a
 * buffer still being sent would show in the frame.  lies: wait() says a
 * buffer is free without completing it (a broken sink the check must see). */
typedef struct late_sink {
    uint8_t *frame;
    const uint8_t *buf[2];          /* the two colour buffers */
    const uint8_t *pending[2];      /* per buffer: being sent (the band's rows below) */
    int y0[2], rows[2];
    int bands, waits, overlaps, wrong_buffer, reused, lies;
} late_sink;

static void late_complete(late_sink *s, int i)
{
    size_t row = (size_t)W * 2;
    if (!s->pending[i]) return;
    memcpy(s->frame + (size_t)s->y0[i] * row, s->pending[i], (size_t)s->rows[i] * row);
    s->pending[i] = NULL;
}

static int late_band(void *user, const silk_target *t)
{
    late_sink *s = user;
    int i = t->color == s->buf[1];
    if (t->color != s->buf[s->bands & 1]) s->wrong_buffer++;   /* the first band of a frame in band->color */
    if (s->pending[i]) s->reused++;                             /* handed back before it was free */
    s->pending[i] = t->color;
    s->y0[i] = t->y0;
    s->rows[i] = t->rows;
    s->bands++;
    return 0;
}

static int late_wait(void *user, const uint8_t *color)
{
    late_sink *s = user;
    int i = color == s->buf[1];
    s->waits++;
    if (s->pending[!i]) s->overlaps++;     /* the other band still being sent while this one is drawn */
    if (!s->lies) late_complete(s, i);
    else if (s->pending[i]) s->pending[i] = NULL;
    return 0;
}

static int late_wait_fails(void *user, const uint8_t *color)
{
    late_sink *s = user;
    (void)color;
    return ++s->waits == 3;
}

/* Double-buffered bands (silk_sink.color2 and wait): the same bytes as the
 * full frame with a sink whose transfers complete only when the renderer
 * needs their buffer again, the bands alternating between the two buffers
 * and drawn while the other one is in transfer; smooth, anti-aliased (the
 * outline's pixels are written after the band is drawn) and flat; a wait
 * that fails stops the frame, and a second buffer without a wait is refused. */
TEST(double_buffered_bands_with_a_late_sink)
{
    silk_arena a;
    silk_mesh m;
    silk_view v;
    if (!load(&a, "bunny-500.obj", &m) || !make_view(&m, 30, 20, 0, &v)) {
        CHECKF(0, "cannot set up bunny-500");
        return;
    }
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    enum { ROWS = 7 };
    size_t frame_bytes = (size_t)W * H * 2;
    uint8_t *color = silk_arena_alloc(&a, frame_bytes, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&a, (size_t)W * H, sizeof *depth, SILK_MEM_RASTER);
    uint8_t *b0 = silk_arena_alloc(&a, (size_t)ROWS * W * 2, SILK_MEM_RASTER);
    uint8_t *b1 = silk_arena_alloc(&a, (size_t)ROWS * W * 2, SILK_MEM_RASTER);
    uint32_t *bd = silk_arena_array(&a, (size_t)ROWS * W, sizeof *bd, SILK_MEM_RASTER);
    uint8_t *copy = malloc(frame_bytes);
    CHECK(color && depth && b0 && b1 && bd && copy);
    if (!color || !depth || !b0 || !b1 || !bd || !copy) {
        free(copy);
        return;
    }
    const int nbands = (H + ROWS - 1) / ROWS;
    for (int mode = 0; mode < 2; mode++) {
        silk_render_opts ro;
        silk_render_opts_default(&ro);
        ro.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
        ro.bg_rgb = BG;
        silk_target full, band;
        silk_target_init(&full, W, H, 0, H, SILK_PIX_RGB565, color, depth);
        silk_error err;
        CHECKF(silk_render(&a, &m, &v, &hal, &ro, &full, NULL, &err) == SILK_OK, "%s", err.msg);
        for (int lies = 0; lies < 2; lies++) {
            memset(copy, 0xA5, frame_bytes);
            late_sink s = { copy, { b0, b1 }, { NULL, NULL }, { 0, 0 }, { 0, 0 }, 0, 0, 0, 0, 0, lies };
            silk_sink sink = { late_band, &s, b1, late_wait };
            silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB565, b0, bd);
            silk_frame_stats st;
            silk_status r = silk_render_bands(&a, &m, &v, &hal, &ro, &band, &sink, &st, &err);
            CHECKF(r == SILK_OK, "%s", err.msg);
            late_complete(&s, 0);   /* the sink's flush */
            late_complete(&s, 1);
            size_t diff = 0;
            for (size_t i = 0; i < frame_bytes; i++) diff += copy[i] != color[i];
            if (!lies) {
                CHECKF(diff == 0, "%s: double-buffered bands differ from the full frame in %zu bytes",
                       mode ? "smooth" : "flat", diff);
                CHECKF(s.bands == nbands && s.waits == nbands, "%d bands, %d waits", s.bands, s.waits);
                CHECKF(s.overlaps == nbands - 1, "%d of %d bands drawn while the last one was sent", s.overlaps,
                       nbands - 1);
                CHECKF(s.wrong_buffer == 0 && s.reused == 0, "%d bands in the wrong buffer, %d buffers reused",
                       s.wrong_buffer, s.reused);
                CHECK(band.color == b0 && band.y0 == 0 && band.rows == ROWS);
                if (mode) CHECK(st.silhouette_tris > 0 && !st.fell_back);
            } else {
                CHECKF(diff > 0, "a sink that says its buffers are free too early goes unseen");
            }
        }
    }
    /* a wait that fails stops the frame where it was asked */
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    silk_target band;
    silk_target_init(&band, W, H, 0, ROWS, SILK_PIX_RGB565, b0, bd);
    late_sink s = { copy, { b0, b1 }, { NULL, NULL }, { 0, 0 }, { 0, 0 }, 0, 0, 0, 0, 0, 0 };
    silk_sink failing = { late_band, &s, b1, late_wait_fails };
    silk_error err;
    CHECK(silk_render_bands(&a, &m, &v, &hal, &ro, &band, &failing, NULL, &err) == SILK_ERR_IO);
    CHECKF(s.bands == 2 && strstr(err.msg, "row 14") != NULL, "%d bands, \"%s\"", s.bands, err.msg);
    CHECK(band.color == b0 && band.y0 == 0 && band.rows == ROWS);
    silk_sink half = { late_band, &s, b1, NULL };
    CHECK(silk_render_bands(&a, &m, &v, &hal, &ro, &band, &half, NULL, &err) == SILK_ERR_ARG);
    free(copy);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    if (!arena_buf) return 1;
    RUN(bands_equal_full_frame_flat);
    RUN(bands_equal_full_frame_smooth);
    RUN(bands_equal_full_frame_rgb888_wire);
    RUN(bands_equal_full_frame_without_aa);
    RUN(bands_equal_full_frame_creases);
    RUN(sink_stop_is_an_error);
    RUN(double_buffered_bands_with_a_late_sink);
    free(arena_buf);
    return check_done();
}
