/*
 * silk_panel.c - ILI9341 and ST7789 SPI panels as a band sink (silk_panel.h).
 *
 * The command set is the MIPI DCS one both controllers share: SWRESET
 * 0x01, SLPOUT 0x11, INVON 0x21, DISPON 0x29, CASET 0x2A and RASET 0x2B
 * (start and end address, two bytes each, high byte first), RAMWR 0x2C
 * (pixels follow, the address advancing along the window's columns, then
 * rows), MADCTL 0x36 (row/column order and exchange, RGB/BGR), COLMOD 0x3A
 * (0x55: 16 bits a pixel, R5 G6 B5, high byte first).  The ILI9341 also
 * gets the power, VCOM, frame-rate and gamma settings of its datasheet's
 * sample code (ILI9341 datasheet V1.11, section 8; the same values the
 * common open drivers send); the ST7789 runs on its reset defaults
 * (ST7789V datasheet V1.6, section 9), which suit its modules.
 *
 * Delays (both datasheets): 5 ms after SWRESET before the next command
 * (120 ms before SLPOUT when it came in sleep-out mode: 150 ms here), and
 * 5 ms after SLPOUT before the next (120 ms before a later SLPIN: 120 ms
 * here, which also lets the supply settle before DISPON).
 */
#include <string.h>
#include "silk_panel.h"

enum {
    CMD_SWRESET = 0x01,
    CMD_SLPOUT = 0x11,
    CMD_INVON = 0x21,
    CMD_DISPON = 0x29,
    CMD_CASET = 0x2A,
    CMD_RASET = 0x2B,
    CMD_RAMWR = 0x2C,
    CMD_MADCTL = 0x36,
    CMD_COLMOD = 0x3A
};

/* MADCTL bits: row address order, column address order, row/column
 * exchange, BGR filter */
#define MADCTL_MY 0x80u
#define MADCTL_MX 0x40u
#define MADCTL_MV 0x20u
#define MADCTL_BGR 0x08u

/* Both controllers' memory: 240 columns by 320 rows. */
#define PANEL_COLS 240
#define PANEL_ROWS 320

/* The ILI9341's settings after reset, as { count, command, parameters... }
 * with count the parameters' number, ended by 0xFF. */
static const uint8_t ili9341_setup[] = {
    3, 0xEF, 0x03, 0x80, 0x02,
    3, 0xCF, 0x00, 0xC1, 0x30,             /* power control B */
    4, 0xED, 0x64, 0x03, 0x12, 0x81,       /* power-on sequence control */
    3, 0xE8, 0x85, 0x00, 0x78,             /* driver timing control A */
    5, 0xCB, 0x39, 0x2C, 0x00, 0x34, 0x02, /* power control A */
    1, 0xF7, 0x20,                         /* pump ratio control */
    2, 0xEA, 0x00, 0x00,                   /* driver timing control B */
    1, 0xC0, 0x23,                         /* power control 1: GVDD 4.6 V */
    1, 0xC1, 0x10,                         /* power control 2 */
    2, 0xC5, 0x3E, 0x28,                   /* VCOM control 1 */
    1, 0xC7, 0x86,                         /* VCOM control 2 */
    2, 0xB1, 0x00, 0x18,                   /* frame rate: 79 Hz */
    3, 0xB6, 0x08, 0x82, 0x27,             /* display function control */
    1, 0xF2, 0x00,                         /* 3-gamma off */
    1, 0x26, 0x01,                         /* gamma curve 1 */
    15, 0xE0, 0x0F, 0x31, 0x2B, 0x0C, 0x0E, 0x08, 0x4E, 0xF1, 0x37, 0x07, 0x10, 0x03, 0x0E, 0x09, 0x00,
    15, 0xE1, 0x00, 0x0E, 0x14, 0x03, 0x11, 0x07, 0x31, 0xC1, 0x48, 0x08, 0x0F, 0x0C, 0x31, 0x36, 0x0F,
    0xFF
};

void silk_panel_config_default(silk_panel_config *c, silk_panel_kind kind)
{
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->width = 320;
    c->height = 240;
    c->rotation = 1;
    c->bgr = kind == SILK_PANEL_ILI9341;
    c->invert = kind == SILK_PANEL_ST7789;
    c->swap = 1;
}

uint8_t silk_panel_madctl(silk_panel_kind kind, int rotation, int bgr)
{
    /* The orders that turn each controller's usual module to the rotation:
     * the ILI9341's are mounted with the column order reversed. */
    static const uint8_t ili9341[4] = { MADCTL_MX, MADCTL_MV, MADCTL_MY, MADCTL_MX | MADCTL_MY | MADCTL_MV };
    static const uint8_t st7789[4] = { 0, MADCTL_MX | MADCTL_MV, MADCTL_MX | MADCTL_MY, MADCTL_MY | MADCTL_MV };
    uint8_t m = (kind == SILK_PANEL_ILI9341 ? ili9341 : st7789)[rotation & 3];
    return (uint8_t)(m | (bgr ? MADCTL_BGR : 0));
}

static int command(silk_panel *p, uint8_t cmd, const uint8_t *param, size_t n)
{
    if (p->io.write(p->io.user, 0, &cmd, 1)) return -1;
    return n ? p->io.write(p->io.user, 1, param, n) : 0;
}

static void delay(const silk_panel *p, uint32_t ms)
{
    if (p->io.delay_ms) p->io.delay_ms(p->io.user, ms);
}

/* The bus free for commands: the transfer in flight done. */
int silk_panel_flush(silk_panel *p)
{
    if (!p->sending) return 0;
    p->sending = NULL;
    return p->io.wait(p->io.user) ? -1 : 0;
}

silk_status silk_panel_init(silk_panel *p, const silk_panel_config *c, const silk_panel_io *io, silk_error *err)
{
    memset(p, 0, sizeof *p);
    if (!c || !io || !io->write || (io->start == NULL) != (io->wait == NULL))
        return silk_fail(err, SILK_ERR_ARG, "panel", 0, "the bus needs a write function (and DMA start and wait together)");
    if (c->kind != SILK_PANEL_ILI9341 && c->kind != SILK_PANEL_ST7789)
        return silk_fail(err, SILK_ERR_ARG, "panel", 0, "unknown panel kind %d", (int)c->kind);
    if (!c->swap && !io->start)
        return silk_fail(err, SILK_ERR_ARG, "panel", 0, "pixels sent as 16-bit words (swap 0) need the bus's DMA start");
    int cols = c->rotation & 1 ? PANEL_ROWS : PANEL_COLS, rows = c->rotation & 1 ? PANEL_COLS : PANEL_ROWS;
    if (c->rotation < 0 || c->rotation > 3 || c->width < 1 || c->height < 1 || c->x0 < 0 || c->y0 < 0 ||
        c->width > cols - c->x0 || c->height > rows - c->y0)
        return silk_fail(err, SILK_ERR_ARG, "panel", 0, "a %dx%d frame at %d,%d does not fit a %dx%d panel (rotation %d)",
                         c->width, c->height, c->x0, c->y0, cols, rows, c->rotation);
    p->cfg = *c;
    p->io = *io;
    p->madctl = silk_panel_madctl(c->kind, c->rotation, c->bgr);

    int bad = command(p, CMD_SWRESET, NULL, 0);
    delay(p, 150);
    if (c->kind == SILK_PANEL_ILI9341)
        for (const uint8_t *s = ili9341_setup; !bad && s[0] != 0xFF; s += 2 + s[0]) bad = command(p, s[1], s + 2, s[0]);
    const uint8_t colmod = 0x55;
    if (!bad) bad = command(p, CMD_MADCTL, &p->madctl, 1);
    if (!bad) bad = command(p, CMD_COLMOD, &colmod, 1);
    if (!bad && c->invert) bad = command(p, CMD_INVON, NULL, 0);
    if (!bad) bad = command(p, CMD_SLPOUT, NULL, 0);
    delay(p, 120);
    if (!bad) bad = command(p, CMD_DISPON, NULL, 0);
    if (bad) return silk_fail(err, SILK_ERR_IO, "panel", 0, "the bus failed during the init sequence");
    return SILK_OK;
}

/* CASET / RASET: first and last address, high bytes first. */
static int address(silk_panel *p, uint8_t cmd, int first, int last)
{
    const uint8_t a[4] = { (uint8_t)(first >> 8), (uint8_t)first, (uint8_t)(last >> 8), (uint8_t)last };
    return command(p, cmd, a, sizeof a);
}

/* Each pixel's two bytes exchanged, RGB565 in memory (low byte first,
 * silk/raster.h) to the panels' order: a word at a time where the buffer
 * allows (4.5 instructions a pixel on a Cortex-M3 instead of 9). */
static void swap_bytes(uint8_t *b, size_t n)
{
    size_t i = 0;
    if (((uintptr_t)b & 3) == 0) {
#if defined(__GNUC__)
        uint8_t *a = __builtin_assume_aligned(b, 4);
#else
        uint8_t *a = b;
#endif
        for (; i + 4 <= n; i += 4) {
            uint32_t w;
            memcpy(&w, a + i, 4);
#if defined(__GNUC__)
            w = __builtin_bswap32(w);   /* with the rotation, ARM's rev16 */
            w = w >> 16 | w << 16;
#else
            w = (w & 0x00FF00FFu) << 8 | (w >> 8 & 0x00FF00FFu);
#endif
            memcpy(a + i, &w, 4);
        }
    }
    for (; i + 1 < n; i += 2) {
        uint8_t lo = b[i];
        b[i] = b[i + 1];
        b[i + 1] = lo;
    }
}

/* silk_sink.band: the band's window, then its pixels. */
static int panel_band(void *user, const silk_target *t)
{
    silk_panel *p = user;
    size_t n = (size_t)t->width * (size_t)t->rows * 2;
    if (t->fmt != SILK_PIX_RGB565 || t->stride != (size_t)t->width * 2 || t->width > p->cfg.width ||
        t->y0 < 0 || t->y0 + t->rows > p->cfg.height)
        return -1;
    if (silk_panel_flush(p)) return -1;   /* one bus: the last band's pixels go first */
    int x = p->cfg.x0, y = p->cfg.y0 + t->y0;
    if (address(p, CMD_CASET, x, x + t->width - 1) || address(p, CMD_RASET, y, y + t->rows - 1) ||
        command(p, CMD_RAMWR, NULL, 0))
        return -1;
    if (p->cfg.swap) swap_bytes(t->color, n);   /* the panel takes the high byte first */
    p->bands++;
    if (!p->io.start) return p->io.write(p->io.user, 1, t->color, n) ? -1 : 0;
    if (p->io.start(p->io.user, t->color, n)) return -1;
    p->sending = t->color;
    /* one buffer: the renderer draws the next band into it on return */
    return p->double_buffered ? 0 : silk_panel_flush(p);
}

/* silk_sink.wait: a buffer is free once its transfer is done. */
static int panel_wait(void *user, const uint8_t *color)
{
    silk_panel *p = user;
    return color == p->sending ? silk_panel_flush(p) : 0;
}

void silk_panel_sink(silk_panel *p, uint8_t *color2, silk_sink *sink)
{
    memset(sink, 0, sizeof *sink);
    sink->band = panel_band;
    sink->user = p;
    p->double_buffered = color2 && p->io.start;
    if (p->double_buffered) {
        sink->color2 = color2;
        sink->wait = panel_wait;
    }
}
