/*
 * test_panel.c - the ILI9341 and ST7789 band sinks (platform/panel/): the
 * byte stream they send, decoded by a model of each panel
 * (support/panel_model.c), must show exactly the pixels of a full-frame
 * silk_render(), byte for byte, and be a stream the panel takes.
 *
 * The bus is a test double: it hands every byte to the model with its D/C
 * level; with DMA it only notes a transfer when it starts and reads the
 * buffer when the transfer completes, at the sink's wait, so a band drawn
 * into a buffer still being sent would show.  Cases: both panels, blocking
 * writes, DMA with one band buffer, DMA double-buffered (each band drawn
 * while the last one is in transfer), a bus of 16-bit words, portrait,
 * landscape and the 240x240 ST7789 modules' window offset, flat and smooth
 * frames of a generated torus and, when the shared meshes are there, of
 * bunny-500; then the init sequence command by command, and the errors.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/panel_model.h"
#include "support/testmesh.h"
#include "support/testframe.h"
#include "tools/prep/gen.h"
#include "platform/panel/silk_panel.h"
#include "silk/silk.h"

#define ARENA_BYTES (8u << 20)

static uint8_t *arena_buf;
static panel_model model;

/* ---- the bus -------------------------------------------------------------- */

typedef struct bus {
    panel_model *m;
    int word16;                 /* start() sends 16-bit words from memory (no byte swap needed) */
    const uint8_t *pending;     /* a DMA transfer started and not yet done */
    size_t pending_n;
    uint32_t pending_band;      /* the sink's band count when it started */
    uint32_t *bands;            /* the wrapper's count of bands handed over */
    int transfers, overlaps, misuse;
    long calls, fail_at;        /* fail the fail_at-th call (0: never) */
    uint32_t ms;
} bus;

static int bus_fails(bus *b)
{
    return b->fail_at && ++b->calls == b->fail_at;
}

static int bus_write(void *user, int dc, const uint8_t *data, size_t n)
{
    bus *b = user;
    if (bus_fails(b)) return -1;
    if (b->pending) b->misuse++;   /* the bus is busy with pixels */
    panel_model_bytes(b->m, dc, data, n);
    return 0;
}

static int bus_start(void *user, const uint8_t *data, size_t n)
{
    bus *b = user;
    if (bus_fails(b)) return -1;
    if (b->pending) b->misuse++;
    b->pending = data;
    b->pending_n = n;
    b->pending_band = b->bands ? *b->bands : 0;
    b->transfers++;
    return 0;
}

static int bus_wait(void *user)
{
    bus *b = user;
    if (bus_fails(b)) return -1;
    if (!b->pending) return 0;
    if (b->bands && *b->bands > b->pending_band) b->overlaps++;   /* another band was drawn meanwhile */
    if (b->word16) {   /* 16-bit frames: each word's high byte first on the wire */
        for (size_t i = 0; i + 1 < b->pending_n; i += 2) {
            uint8_t w[2] = { b->pending[i + 1], b->pending[i] };
            panel_model_bytes(b->m, 1, w, 2);
        }
    } else {
        panel_model_bytes(b->m, 1, b->pending, b->pending_n);
    }
    b->pending = NULL;
    return 0;
}

static void bus_delay(void *user, uint32_t ms)
{
    bus *b = user;
    b->ms += ms;
    panel_model_delay(b->m, ms);
}

/* The panel's sink wrapped to count the bands handed over (the bus reads
 * the count to see a transfer outlive its band). */
typedef struct counted {
    silk_sink inner;
    uint32_t bands;
} counted;

static int counted_band(void *user, const silk_target *t)
{
    counted *c = user;
    c->bands++;
    return c->inner.band(c->inner.user, t);
}

static int counted_wait(void *user, const uint8_t *color)
{
    counted *c = user;
    return c->inner.wait(c->inner.user, color);
}

/* ---- one case -------------------------------------------------------------- */

typedef struct panel_case {
    silk_panel_kind kind;
    int width, height, rotation, x0, y0;
    int dma, two_buffers, word16, rows;
} panel_case;

static const char *kind_name(silk_panel_kind k)
{
    return k == SILK_PANEL_ILI9341 ? "ILI9341" : "ST7789";
}

/* A camera in front of the mesh, a little above, at w x h. */
static int view_for(const silk_mesh *m, int w, int h, silk_view *v)
{
    const double dir[3] = { 0.55, 0.35, 1.0 };
    return tf_view_around_size(m, dir, 2.6, 0, w, h, v);
}

static void run_case(const silk_mesh *mesh, const char *name, const panel_case *pc, silk_mode mode)
{
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    a.bottom = 0;
    silk_view v;
    if (!view_for(mesh, pc->width, pc->height, &v)) {
        CHECKF(0, "%s: no view", name);
        return;
    }
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;

    /* the reference: the whole frame at once */
    size_t frame_bytes = (size_t)pc->width * pc->height * 2;
    uint8_t *color = silk_arena_alloc(&a, frame_bytes, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&a, (size_t)pc->width * pc->height, sizeof *depth, SILK_MEM_RASTER);
    uint8_t *b0 = silk_arena_alloc(&a, (size_t)pc->width * pc->rows * 2, SILK_MEM_RASTER);
    uint8_t *b1 = silk_arena_alloc(&a, (size_t)pc->width * pc->rows * 2, SILK_MEM_RASTER);
    uint32_t *bd = silk_arena_array(&a, (size_t)pc->width * pc->rows, sizeof *bd, SILK_MEM_RASTER);
    if (!color || !depth || !b0 || !b1 || !bd) {
        CHECKF(0, "out of arena");
        return;
    }
    silk_target full;
    silk_target_init(&full, pc->width, pc->height, 0, pc->height, SILK_PIX_RGB565, color, depth);
    silk_error err;
    silk_frame_stats fs;
    CHECKF(silk_render(&a, mesh, &v, &hal, &ro, &full, &fs, &err) == SILK_OK, "%s", err.msg);
    if (mode == SILK_MODE_SMOOTH) CHECKF(fs.silhouette_tris > 0 && !fs.fell_back, "%s: not smoothed", name);

    panel_model_init(&model, pc->kind);
    bus b = { &model, pc->word16, NULL, 0, 0, NULL, 0, 0, 0, 0, 0, 0 };
    silk_panel_io io = { bus_write, pc->dma ? bus_start : NULL, pc->dma ? bus_wait : NULL, bus_delay, &b };
    silk_panel_config cfg;
    silk_panel_config_default(&cfg, pc->kind);
    cfg.width = pc->width;
    cfg.height = pc->height;
    cfg.rotation = pc->rotation;
    cfg.x0 = pc->x0;
    cfg.y0 = pc->y0;
    cfg.swap = !pc->word16;
    silk_panel p;
    CHECKF(silk_panel_init(&p, &cfg, &io, &err) == SILK_OK, "%s", err.msg);
    long init_commands = model.commands;

    counted c;
    silk_panel_sink(&p, pc->two_buffers ? b1 : NULL, &c.inner);
    c.bands = 0;
    b.bands = &c.bands;
    silk_sink sink = { counted_band, &c, c.inner.color2, c.inner.wait ? counted_wait : NULL };
    silk_target band;
    silk_target_init(&band, pc->width, pc->height, 0, pc->rows, SILK_PIX_RGB565, b0, bd);
    silk_frame_stats bs;
    silk_status st = silk_render_bands(&a, mesh, &v, &hal, &ro, &band, &sink, &bs, &err);
    CHECKF(st == SILK_OK, "%s", err.msg);
    CHECK(silk_panel_flush(&p) == 0);

    char what[160];
    snprintf(what, sizeof what, "%s %s %dx%d rotation %d at %d,%d, %s%s%s, bands of %d", name, kind_name(pc->kind),
             pc->width, pc->height, pc->rotation, pc->x0, pc->y0,
             mode == SILK_MODE_SMOOTH ? "smooth" : "flat",
             pc->dma ? (pc->two_buffers ? ", DMA double-buffered" : ", DMA one buffer") : ", blocking",
             pc->word16 ? ", 16-bit bus" : "", pc->rows);
    const char *why = panel_model_problem(&model);
    CHECKF(why == NULL, "%s: the panel refuses the stream: %s", what, why ? why : "");
    long diff = 0, first = -1;
    for (int y = 0; y < pc->height; y++)
        for (int x = 0; x < pc->width; x++) {
            size_t i = ((size_t)y * pc->width + x) * 2;
            uint16_t want = (uint16_t)(color[i] | color[i + 1] << 8);
            if (panel_model_seen(&model, pc->x0 + x, pc->y0 + y) != want && !diff++) first = y;
        }
    CHECKF(diff == 0, "%s: %ld pixels on the panel differ from silk_render's, the first in row %ld", what, diff, first);
    int nbands = (pc->height + pc->rows - 1) / pc->rows;
    CHECKF(model.ramwr == nbands && model.pixels == (long)pc->width * pc->height,
           "%s: %ld memory writes of %ld pixels for %d bands", what, model.ramwr, model.pixels, nbands);
    CHECKF(model.commands - init_commands == 3L * nbands, "%s: %ld commands for %d bands (CASET, RASET, RAMWR each)",
           what, model.commands - init_commands, nbands);
    CHECKF(b.misuse == 0, "%s: %d bytes sent while a transfer was in flight", what, b.misuse);
    if (pc->dma) {
        CHECK(b.transfers == nbands);
        /* double-buffered: every band but the last was still being sent
         * while the next one was drawn; one buffer: never */
        int want = pc->two_buffers ? nbands - 1 : 0;
        CHECKF(b.overlaps == want, "%s: %d transfers outlived their band, want %d", what, b.overlaps, want);
    }
    CHECK(band.color == b0);
}

/* ---- the cases ---------------------------------------------------------------- */

static const panel_case cases[] = {
    { SILK_PANEL_ILI9341, 320, 240, 1, 0, 0, 0, 0, 0, 8 },   /* blocking writes */
    { SILK_PANEL_ILI9341, 320, 240, 1, 0, 0, 1, 0, 0, 7 },   /* DMA, one buffer */
    { SILK_PANEL_ILI9341, 320, 240, 1, 0, 0, 1, 1, 0, 8 },   /* DMA, double-buffered */
    { SILK_PANEL_ILI9341, 240, 320, 0, 0, 0, 1, 1, 0, 16 },  /* portrait */
    { SILK_PANEL_ILI9341, 320, 240, 3, 0, 0, 1, 1, 1, 5 },   /* landscape the other way, 16-bit words */
    { SILK_PANEL_ST7789, 320, 240, 1, 0, 0, 0, 0, 0, 8 },
    { SILK_PANEL_ST7789, 320, 240, 1, 0, 0, 1, 1, 1, 16 },
    { SILK_PANEL_ST7789, 240, 240, 2, 0, 80, 1, 1, 0, 10 },  /* a 240x240 module upside down */
};
#define NCASES (sizeof cases / sizeof cases[0])

static void run_all(const silk_mesh *m, const char *name)
{
    for (size_t i = 0; i < NCASES; i++) {
        run_case(m, name, &cases[i], SILK_MODE_SMOOTH);
        run_case(m, name, &cases[i], SILK_MODE_FLAT);
    }
}

TEST(streams_decode_to_the_rendered_frame_torus)
{
    gen_params gp;
    gen_mesh gm;
    gen_defaults(GEN_TORUS, &gp);
    tm_fixture f;
    tm_fixture_init(&f, 4u << 20);
    int ok = gen_build(&gp, &gm) == 0;
    ok = ok && tm_fixture_input(&f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(&f) == SILK_OK;
    if (gm.pos) gen_free(&gm);
    CHECKF(ok, "cannot build the torus");
    if (ok) run_all(&f.m, "torus");
    tm_fixture_free(&f);
}

TEST(streams_decode_to_the_rendered_frame_bunny)
{
    static uint8_t mesh_mem[4u << 20];
    silk_arena a;
    silk_arena_init(&a, mesh_mem, sizeof mesh_mem);
    silk_mesh m;
    if (!tm_load_shared(&a, "bunny-500.obj", &m)) {
        CHECKF(0, "cannot load bunny-500");
        return;
    }
    run_all(&m, "bunny-500");
}

/* The init sequence as a panel sees it: a reset first, the datasheets'
 * delays, the MADCTL of each rotation, 16-bit pixels, INVON where the
 * module needs it, awake and on at the end; the ILI9341's extended
 * settings, which an ST7789 would refuse (the model knows each
 * controller's commands). */
TEST(init_sequences)
{
    static const uint8_t ili[4] = { 0x48, 0x28, 0x88, 0xE8 }, st[4] = { 0x00, 0x60, 0xC0, 0xA0 };
    for (int kind = 0; kind < 2; kind++)
        for (int r = 0; r < 4; r++) {
            panel_model_init(&model, kind);
            bus b = { &model, 0, NULL, 0, 0, NULL, 0, 0, 0, 0, 0, 0 };
            silk_panel_io io = { bus_write, NULL, NULL, bus_delay, &b };
            silk_panel_config cfg;
            silk_panel_config_default(&cfg, (silk_panel_kind)kind);
            cfg.rotation = r;
            cfg.width = r & 1 ? 320 : 240;
            cfg.height = r & 1 ? 240 : 320;
            silk_panel p;
            silk_error err;
            CHECKF(silk_panel_init(&p, &cfg, &io, &err) == SILK_OK, "%s", err.msg);
            const char *why = panel_model_problem(&model);
            CHECKF(!why, "%s rotation %d: %s", kind_name((silk_panel_kind)kind), r, why ? why : "");
            CHECK(model.resets == 1 && model.colmod == 0x55 && b.ms >= 270);
            CHECKF(model.madctl == (kind ? st : ili)[r], "%s rotation %d: MADCTL %02x", kind_name((silk_panel_kind)kind),
                   r, model.madctl);
            CHECK(model.invon == (kind == SILK_PANEL_ST7789));
            CHECK(model.commands == (kind == SILK_PANEL_ILI9341 ? 22 : 6));
        }
    /* the same ILI9341 stream to an ST7789 is refused command by command */
    panel_model_init(&model, SILK_PANEL_ST7789);
    bus b = { &model, 0, NULL, 0, 0, NULL, 0, 0, 0, 0, 0, 0 };
    silk_panel_io io = { bus_write, NULL, NULL, bus_delay, &b };
    silk_panel_config cfg;
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
    silk_panel p;
    silk_error err;
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_OK);
    const char *why = panel_model_problem(&model);
    CHECK(why && strstr(why, "not a command of this controller"));
    /* without the delays the panel is not ready for them */
    panel_model_init(&model, SILK_PANEL_ILI9341);
    io.delay_ms = NULL;
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_OK);
    why = panel_model_problem(&model);
    CHECK(why && strstr(why, "5 ms"));
}

static int wait_none(void *user)
{
    (void)user;
    return 0;
}

/* Bad configurations, a failing bus in the init sequence and during a
 * frame, and bands the panel cannot take stop with one message or status. */
TEST(errors)
{
    panel_model_init(&model, SILK_PANEL_ILI9341);
    bus b = { &model, 0, NULL, 0, 0, NULL, 0, 0, 0, 0, 0, 0 };
    silk_panel_io io = { bus_write, NULL, NULL, bus_delay, &b };
    silk_panel_config cfg;
    silk_panel p;
    silk_error err;
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
    cfg.width = 321;
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_ERR_ARG && strstr(err.msg, "does not fit"));
    silk_panel_config_default(&cfg, SILK_PANEL_ST7789);
    cfg.rotation = 0;
    cfg.width = 240;
    cfg.height = 240;
    cfg.y0 = 81;
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_ERR_ARG);
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
    silk_panel_io half = { bus_write, bus_start, NULL, NULL, &b };
    CHECK(silk_panel_init(&p, &cfg, &half, &err) == SILK_ERR_ARG);
    silk_panel_io words = { bus_write, NULL, NULL, NULL, &b };
    cfg.swap = 0;
    CHECK(silk_panel_init(&p, &cfg, &words, &err) == SILK_ERR_ARG && strstr(err.msg, "16-bit"));
    cfg.swap = 1;
    cfg.kind = (silk_panel_kind)7;
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_ERR_ARG);
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
    b.fail_at = 5;
    CHECK(silk_panel_init(&p, &cfg, &io, &err) == SILK_ERR_IO && strstr(err.msg, "init"));

    /* a frame whose bus fails part-way, and an RGB888 band */
    tm_fixture f;
    tm_fixture_init(&f, 4u << 20);
    gen_params gp;
    gen_mesh gm;
    gen_defaults(GEN_SPHERE, &gp);
    int ok = gen_build(&gp, &gm) == 0;
    ok = ok && tm_fixture_input(&f, gm.pos, gm.nverts, gm.tri, gm.ntris) && tm_fixture_build(&f) == SILK_OK;
    if (gm.pos) gen_free(&gm);
    silk_view v;
    CHECK(ok && view_for(&f.m, 320, 240, &v));
    if (ok) {
        silk_phong ph;
        silk_hal hal;
        silk_phong_default(&ph, &v);
        silk_hal_phong(&hal, &ph);
        silk_render_opts ro;
        silk_render_opts_default(&ro);
        static uint8_t c0[320 * 8 * 3], c1[320 * 8 * 2];
        static uint32_t d[320 * 8];
        for (int fmt = 0; fmt < 2; fmt++) {
            panel_model_init(&model, SILK_PANEL_ILI9341);
            bus fb = { &model, 0, NULL, 0, 0, NULL, 0, 0, 0, 0, 0, 0 };
            silk_panel_io dio = { bus_write, bus_start, wait_none, bus_delay, &fb };
            silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);
            CHECK(silk_panel_init(&p, &cfg, &dio, &err) == SILK_OK);
            fb.fail_at = fb.calls + 20;   /* in the seventh band's window */
            silk_sink sink;
            silk_panel_sink(&p, c1, &sink);
            silk_target band;
            silk_target_init(&band, 320, 240, 0, 8, fmt ? SILK_PIX_RGB888 : SILK_PIX_RGB565, c0, d);
            if (fmt) sink.color2 = NULL, sink.wait = NULL;
            silk_status st = silk_render_bands(&f.a, &f.m, &v, &hal, &ro, &band, &sink, NULL, &err);
            CHECKF(st == SILK_ERR_IO, "%s: status %d", fmt ? "RGB888" : "failing bus", (int)st);
            CHECK(strstr(err.msg, fmt ? "row 0" : "row ") != NULL);
        }
    }
    tm_fixture_free(&f);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    if (!arena_buf) return 1;
    RUN(streams_decode_to_the_rendered_frame_torus);
    RUN(streams_decode_to_the_rendered_frame_bunny);
    RUN(init_sequences);
    RUN(errors);
    free(arena_buf);
    return check_done();
}
