/*
 * silk_panel.h - ILI9341 and ST7789 SPI panels as a silk_sink: the panel's
 * init sequence, and for every band silk_render_bands() finishes the column
 * and row address window (CASET, RASET), a memory write (RAMWR) and the
 * band's RGB565 pixels, high byte first as both controllers take them in
 * their 16-bit mode (COLMOD 0x55).
 *
 * The board supplies the bus (silk_panel_io): a write function that sends
 * bytes with the data/command line low (a command) or high (its
 * parameters, pixels), and optionally a DMA pair, start and wait.  With
 * DMA and a second band buffer the sink is double-buffered: band() sends
 * the window, starts the pixels' transfer and returns, the renderer draws
 * the next band into the other buffer meanwhile, and the sink's wait says
 * when a buffer is free again (silk_sink.color2 and wait, silk/render.h).
 * One bus carries both, so a band's window waits for the previous band's
 * pixels to be sent; silk_panel_flush() waits for the last one.
 *
 * No heap, no globals, libc's memset and memcpy only: the same code runs on a host
 * (tests/platform/test_panel.c decodes its byte stream with a model of the panels)
 * and on any Cortex-M; docs/porting.md wires it to a board.
 */
#ifndef SILK_PANEL_H
#define SILK_PANEL_H

#include <stddef.h>
#include <stdint.h>
#include "silk/error.h"
#include "silk/render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_panel_kind {
    SILK_PANEL_ILI9341 = 0,   /* Ilitek ILI9341: 240 x 320, the common 2.2-3.2" modules */
    SILK_PANEL_ST7789 = 1     /* Sitronix ST7789(V): 240 x 320 memory, 240x240 and 320x240 IPS modules */
} silk_panel_kind;

/* The bus, from the board.  Every function returns 0 on success; a
 * failure stops the frame (SILK_ERR_IO). */
typedef struct silk_panel_io {
    /* Send n bytes, chip select asserted, with the D/C line low (dc 0: one
     * command byte) or high (dc 1: parameters or pixels); blocking. */
    int (*write)(void *user, int dc, const uint8_t *data, size_t n);
    /* Optional DMA, both or neither: start sending n pixel bytes (D/C high)
     * and return at once; wait until the transfer started last is done.
     * data stays untouched until then. */
    int (*start)(void *user, const uint8_t *data, size_t n);
    int (*wait)(void *user);
    /* Sleep ms milliseconds (after reset and sleep-out, as the datasheets
     * ask); NULL: the board waits on its own. */
    void (*delay_ms)(void *user, uint32_t ms);
    void *user;
} silk_panel_io;

/* Rotations as the panel is usually mounted: 0 and 2 portrait, 1 and 3
 * landscape (320x240 on a 240x320 panel). */
typedef struct silk_panel_config {
    silk_panel_kind kind;
    int width, height;          /* the frame in this rotation, at most the panel's */
    int rotation;               /* 0..3 */
    int x0, y0;                 /* the frame's top-left in the panel's window (240x240 ST7789s: an offset) */
    int bgr;                    /* the module's colour filter is B,G,R (MADCTL bit 3) */
    int invert;                 /* the module shows inverted colours unless INVON is sent (most ST7789 IPS) */
    int swap;                   /* 1: swap each pixel's bytes in place before sending (an 8-bit SPI);
                                   0: the board's DMA start sends 16-bit words, high byte first, from
                                   memory as it is (a 16-bit SPI frame: no swap at all) */
} silk_panel_config;

typedef struct silk_panel {
    silk_panel_config cfg;
    silk_panel_io io;
    uint8_t madctl;             /* the memory access control byte sent */
    const uint8_t *sending;     /* the buffer whose DMA transfer is in flight, or NULL */
    int double_buffered;        /* the sink has two buffers: band() returns while its pixels are sent */
    uint32_t bands;             /* bands sent since init */
} silk_panel;

/* The kind's usual module: landscape 320x240 (rotation 1), ILI9341 with a
 * BGR filter and not inverted, ST7789 RGB and inverted; bytes swapped. */
void silk_panel_config_default(silk_panel_config *c, silk_panel_kind kind);

/* Reset the panel (SWRESET) and send its init sequence: power and gamma
 * settings (ILI9341), memory access control for the rotation, 16-bit
 * pixels, INVON where asked, sleep out, display on, with the datasheets'
 * delays.  The frame must fit the panel.  Errors: SILK_ERR_ARG (a bad
 * configuration or io), SILK_ERR_IO (the bus failed). */
silk_status silk_panel_init(silk_panel *p, const silk_panel_config *c, const silk_panel_io *io, silk_error *err);

/* A silk_sink that sends every band to the panel.  With color2 (a second
 * colour buffer as large as the band's) and the io's DMA pair it is
 * double-buffered; with either missing, band() returns once the band is
 * sent.  Bands must be RGB565 and within the frame; their pixels are
 * byte-swapped in place when cfg.swap is set (the renderer redraws the
 * buffer for the next band anyway). */
void silk_panel_sink(silk_panel *p, uint8_t *color2, silk_sink *sink);

/* Wait for the transfer in flight, if any: after a frame, before the
 * buffers or the bus are used for anything else.  0, or -1 when the bus
 * failed. */
int silk_panel_flush(silk_panel *p);

/* The MADCTL byte of a kind, rotation and filter order (the init sequence
 * sends it; tests and drivers that share the bus read it here). */
uint8_t silk_panel_madctl(silk_panel_kind kind, int rotation, int bgr);

#ifdef __cplusplus
}
#endif

#endif
