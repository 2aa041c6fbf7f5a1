/*
 * spi_panel.c - silk on an SPI panel: a model that `silk pack` put into
 * flash, drawn from each of its packed views on an ILI9341 (or, with
 * -DPANEL=SILK_PANEL_ST7789, an ST7789) at 320x240 in bands of 16 rows,
 * double-buffered: while DMA sends one band's pixels the renderer draws
 * the next into the other buffer.  One static arena holds
 * the two colour buffers, the depth band and every frame's scratch; the
 * model stays in flash.
 *
 *   silk pack model.obj -o model.h --name model --size 320x240 --format rgb565 --views 4
 *   cc -Iinclude -Iplatform/panel -Iexamples/spi_panel -I. spi_panel.c board.c \
 *      platform/panel/silk_panel.c libsilk.a
 *
 * The board supplies the bus (board.h).  docs/porting.md explains each
 * step; tests/boards/cli_porting.sh builds this file for the host, where the bus
 * is a model of the panel whose picture must equal `silk render`'s byte for
 * byte, and for a Cortex-M4 and a Cortex-M0+.
 */
#include <stdio.h>
#include "silk/silk.h"
#include "silk_panel.h"
#include "model.h"
#include "board.h"

#ifndef PANEL                  /* SILK_PANEL_ST7789 for a 320x240 ST7789 */
#define PANEL SILK_PANEL_ILI9341
#endif
#define WIDTH 320
#define HEIGHT 240
#define BAND_ROWS 16
/* Two colour bands and a depth band, 320 x 16 x (2 + 2 + 4) bytes = 40 KiB,
 * and a frame's scratch: 16 KiB covers a smooth 500-triangle model's worst
 * view at this size (silk info and make profile measure a model's). */
#ifndef ARENA_BYTES
#define ARENA_BYTES (56 * 1024)
#endif

static _Alignas(SILK_ARENA_ALIGN) uint8_t arena_mem[ARENA_BYTES];

/* The panel's bus, as silk_panel.h wants it, from the board's functions. */
static int bus_write(void *user, int dc, const uint8_t *data, size_t n)
{
    (void)user;
    return board_spi_write(dc, data, n);
}

static int bus_start(void *user, const uint8_t *data, size_t n)
{
    (void)user;
    return board_spi_start(data, n);
}

static int bus_wait(void *user)
{
    (void)user;
    return board_spi_wait();
}

static void bus_delay(void *user, uint32_t ms)
{
    (void)user;
    board_delay_ms(ms);
}

static int fail(const char *what, const silk_error *err)
{
    char line[SILK_ERROR_MSG + 40];
    snprintf(line, sizeof line, "%s: %s", what, err->msg);
    board_log(line);
    return 1;
}

/* Every packed view once, smooth; 0 when all were drawn. */
int spi_panel_run(void)
{
    silk_error err;
    silk_panel_io io = { bus_write, bus_start, bus_wait, bus_delay, NULL };
    silk_panel_config cfg;
    silk_panel_config_default(&cfg, PANEL);   /* 320x240 landscape */
    silk_panel panel;
    if (silk_panel_init(&panel, &cfg, &io, &err) != SILK_OK) return fail("panel", &err);

    /* The mesh reads the model in place in flash, checked once as it is made. */
    silk_mesh mesh;
    if (model_mesh(&mesh) != SILK_OK || silk_mesh_validate(&mesh, "model", &err) != SILK_OK) return fail("model", &err);

    /* The band buffers from the arena's bottom, every frame's scratch from
     * its top. */
    silk_arena arena;
    silk_arena_init(&arena, arena_mem, sizeof arena_mem);
    size_t band_px = (size_t)WIDTH * BAND_ROWS;
    uint8_t *color0 = silk_arena_array(&arena, band_px, 2, SILK_MEM_RASTER);
    uint8_t *color1 = silk_arena_array(&arena, band_px, 2, SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&arena, band_px, sizeof *depth, SILK_MEM_RASTER);
    if (!color0 || !color1 || !depth) {
        board_log("the arena cannot hold the band buffers");
        return 1;
    }
    silk_target band;
    silk_target_init(&band, WIDTH, HEIGHT, 0, BAND_ROWS, SILK_PIX_RGB565, color0, depth);
    silk_sink sink;
    silk_panel_sink(&panel, color1, &sink);   /* double-buffered: the bus has DMA */

    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = SILK_MODE_SMOOTH;
    ro.aa = 0;                   /* anti-aliased outlines: 12 KiB more a band at this width */
    ro.vertex_cache_bytes = 0;   /* nothing kept for speed: the RAM a frame needs is its frame_bytes */
    for (int k = 0; k < model_NCAMERAS; k++) {
        silk_view view;
        if (silk_view_init(&view, model_camera(k), &err) != SILK_OK) return fail("camera", &err);
        silk_phong phong;
        silk_hal hal;
        silk_phong_default(&phong, &view);
        model_look(&phong);
        silk_hal_phong(&hal, &phong);
        silk_frame_stats st;
        if (silk_render_bands(&arena, &mesh, &view, &hal, &ro, &band, &sink, &st, &err) != SILK_OK)
            return fail("frame", &err);
        if (st.fell_back) board_log("the frame's plan did not fit the arena: drawn unsmoothed");
        if (silk_panel_flush(&panel)) {   /* the last band's pixels sent */
            board_log("the bus failed");
            return 1;
        }
        board_frame_shown(k);
    }
    return 0;
}
