/*
 * panel_model.h - test support: a model of an ILI9341 or ST7789 panel at
 * the bus, a command interpreter for what silk's panel sink sends
 * (platform/panel/silk_panel.c).  It takes the bytes of the SPI stream
 * with the level of the D/C line, as a logic analyser would record them,
 * and keeps the controller's state: its 240 x 320 memory, the column and
 * row window (CASET, RASET), the write pointer of RAMWR, MADCTL's address
 * order and colour order, COLMOD, INVON, sleep and display on.  Anything
 * a panel would not take is an error (the first is kept): a command the
 * controller does not have, a wrong number of parameters, a window outside
 * the memory, more pixels than the window, pixels before 16-bit mode, a
 * command sooner than 5 ms after SWRESET or SLPOUT.
 *
 * What a viewer sees is read through the same MADCTL, with the module's
 * filter order and inversion: a sink that forgets BGR or INVON shows
 * other colours than it rendered.
 */
#ifndef SILK_PANEL_MODEL_H
#define SILK_PANEL_MODEL_H

#include <stddef.h>
#include <stdint.h>

#define PANEL_MODEL_COLS 240
#define PANEL_MODEL_ROWS 320

typedef struct panel_model {
    int kind;                  /* SILK_PANEL_ILI9341 or SILK_PANEL_ST7789 */
    int filter_bgr;            /* the module's filter is B,G,R */
    int inverted;              /* the module shows inverted colours without INVON */
    uint16_t gram[PANEL_MODEL_ROWS][PANEL_MODEL_COLS];
    /* the command whose parameters arrive, -1 none */
    int cmd;
    uint8_t param[16];
    int nparam;
    /* RAMWR */
    int writing, col, row, half;
    uint8_t high;
    int xs, xe, ys, ye;        /* the window */
    uint8_t madctl, colmod;
    int sleeping, display_on, invon;
    uint32_t ms_since;         /* since the last SWRESET or SLPOUT */
    int settling;              /* a command must wait 5 ms (SWRESET, SLPOUT) */
    long commands, pixels, ramwr, resets;
    char error[200];
} panel_model;

/* A panel just powered up: asleep, display off, window the whole memory. */
void panel_model_init(panel_model *m, int kind);
/* Bytes on the bus: dc 0 a command byte each, dc 1 parameters or pixels. */
void panel_model_bytes(panel_model *m, int dc, const uint8_t *data, size_t n);
/* Time passing on the bus (the sink's delay). */
void panel_model_delay(panel_model *m, uint32_t ms);
/* The RGB565 colour the viewer sees at (x, y) of the window's address
 * space under the MADCTL in force. */
uint16_t panel_model_seen(const panel_model *m, int x, int y);
/* NULL when the stream was one a panel takes and the picture is shown
 * (awake, display on), else what is wrong. */
const char *panel_model_problem(panel_model *m);

#endif
