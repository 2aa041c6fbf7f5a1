/*
 * panel_model.c - an ILI9341 / ST7789 panel at the bus (panel_model.h).
 *
 * Commands and their parameter counts are those of the ILI9341 datasheet
 * (V1.11, sections 8.2 and 8.3) and the ST7789V datasheet (V1.6, section
 * 9.1), for the commands a driver sends when it sets a panel up and
 * writes to it; the ILI9341's extended commands (power, timing, gamma) are
 * not the ST7789's, so sending them to one is an error.  MADCTL maps the
 * window's address (column x, row y) onto the memory: MV exchanges them,
 * then MX reverses the memory column and MY the memory row.
 */
#include <stdio.h>
#include <string.h>
#include "panel_model.h"
#include "../../platform/panel/silk_panel.h"

typedef struct command_info {
    uint8_t code;
    uint8_t min, max;          /* parameters */
    uint8_t kinds;             /* bit 0 ILI9341, bit 1 ST7789 */
} command_info;

#define BOTH 3
#define ILI 1
#define ST 2
#define PIXELS 0xFF            /* RAMWR: the data are pixels */

static const command_info commands[] = {
    { 0x00, 0, 0, BOTH },      /* NOP */
    { 0x01, 0, 0, BOTH },      /* SWRESET */
    { 0x11, 0, 0, BOTH },      /* SLPOUT */
    { 0x13, 0, 0, BOTH },      /* NORON */
    { 0x20, 0, 0, BOTH },      /* INVOFF */
    { 0x21, 0, 0, BOTH },      /* INVON */
    { 0x26, 1, 1, BOTH },      /* GAMSET */
    { 0x28, 0, 0, BOTH },      /* DISPOFF */
    { 0x29, 0, 0, BOTH },      /* DISPON */
    { 0x2A, 4, 4, BOTH },      /* CASET */
    { 0x2B, 4, 4, BOTH },      /* RASET (PASET) */
    { 0x2C, PIXELS, PIXELS, BOTH }, /* RAMWR */
    { 0x36, 1, 1, BOTH },      /* MADCTL */
    { 0x3A, 1, 1, BOTH },      /* COLMOD */
    { 0xB1, 2, 2, ILI },       /* frame rate control */
    { 0xB6, 3, 4, ILI },       /* display function control */
    { 0xC0, 1, 1, ILI },       /* power control 1 */
    { 0xC1, 1, 1, ILI },       /* power control 2 */
    { 0xC5, 2, 2, ILI },       /* VCOM control 1 */
    { 0xC7, 1, 1, ILI },       /* VCOM control 2 */
    { 0xCB, 5, 5, ILI },       /* power control A */
    { 0xCF, 3, 3, ILI },       /* power control B */
    { 0xE0, 15, 15, ILI },     /* positive gamma */
    { 0xE1, 15, 15, ILI },     /* negative gamma */
    { 0xE8, 3, 3, ILI },       /* driver timing control A */
    { 0xEA, 2, 2, ILI },       /* driver timing control B */
    { 0xED, 4, 4, ILI },       /* power-on sequence control */
    { 0xEF, 3, 3, ILI },       /* (timing, in every vendor's sample code) */
    { 0xF2, 1, 1, ILI },       /* enable 3 gamma */
    { 0xF7, 1, 1, ILI },       /* pump ratio control */
    { 0xB2, 5, 5, ST },        /* porch setting */
    { 0xB7, 1, 1, ST },        /* gate control */
    { 0xBB, 1, 1, ST },        /* VCOM setting */
    { 0xC0, 1, 1, ST },        /* LCM control */
    { 0xC2, 1, 2, ST },        /* VDV and VRH enable */
    { 0xC3, 1, 1, ST },        /* VRH set */
    { 0xC4, 1, 1, ST },        /* VDV set */
    { 0xC6, 1, 1, ST },        /* frame rate in normal mode */
    { 0xD0, 2, 2, ST },        /* power control 1 */
    { 0xE0, 14, 14, ST },      /* positive gamma */
    { 0xE1, 14, 14, ST },      /* negative gamma */
};

static const command_info *find(const panel_model *m, int code)
{
    int bit = m->kind == SILK_PANEL_ILI9341 ? ILI : ST;
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (commands[i].code == code && (commands[i].kinds & bit)) return &commands[i];
    return NULL;
}

static void problem(panel_model *m, const char *what, int value)
{
    if (!m->error[0]) snprintf(m->error, sizeof m->error, "%s (0x%02x) after %ld commands", what, value, m->commands);
}

static int logical_cols(const panel_model *m)
{
    return m->madctl & 0x20 ? PANEL_MODEL_ROWS : PANEL_MODEL_COLS;
}

static int logical_rows(const panel_model *m)
{
    return m->madctl & 0x20 ? PANEL_MODEL_COLS : PANEL_MODEL_ROWS;
}

/* The memory cell of window address (x, y). */
static uint16_t *cell(panel_model *m, int x, int y)
{
    int c = x, r = y;
    if (m->madctl & 0x20) {
        c = y;
        r = x;
    }
    if (m->madctl & 0x40) c = PANEL_MODEL_COLS - 1 - c;
    if (m->madctl & 0x80) r = PANEL_MODEL_ROWS - 1 - r;
    return &m->gram[r][c];
}

static void reset(panel_model *m)
{
    m->cmd = -1;
    m->nparam = m->writing = m->half = 0;
    m->madctl = 0;
    m->colmod = 0x66;          /* 18 bits a pixel after reset */
    m->sleeping = 1;
    m->display_on = m->invon = 0;
    m->xs = m->ys = 0;
    m->xe = PANEL_MODEL_COLS - 1;
    m->ye = PANEL_MODEL_ROWS - 1;
}

void panel_model_init(panel_model *m, int kind)
{
    memset(m, 0, sizeof *m);
    m->kind = kind;
    m->filter_bgr = kind == SILK_PANEL_ILI9341;
    m->inverted = kind == SILK_PANEL_ST7789;
    for (int r = 0; r < PANEL_MODEL_ROWS; r++)
        for (int c = 0; c < PANEL_MODEL_COLS; c++) m->gram[r][c] = (uint16_t)(r * 31 + c * 7);   /* power-on noise */
    reset(m);
}

/* The command whose parameters have all arrived. */
static void finish(panel_model *m)
{
    if (m->cmd < 0) return;
    const command_info *ci = find(m, m->cmd);
    int c = m->cmd;
    m->cmd = -1;
    if (ci->min == PIXELS) {
        m->writing = 0;
        if (m->half) problem(m, "RAMWR ended in the middle of a pixel", c);
        return;
    }
    if (m->nparam < ci->min || m->nparam > ci->max) {
        problem(m, "wrong number of parameters", c);
        return;
    }
    const uint8_t *p = m->param;
    switch (c) {
    case 0x01: reset(m); m->settling = 1; m->ms_since = 0; m->resets++; break;
    case 0x11: m->sleeping = 0; m->settling = 1; m->ms_since = 0; break;
    case 0x20: m->invon = 0; break;
    case 0x21: m->invon = 1; break;
    case 0x28: m->display_on = 0; break;
    case 0x29: m->display_on = 1; break;
    case 0x36: m->madctl = p[0]; break;
    case 0x3A: m->colmod = p[0]; break;
    case 0x2A:
    case 0x2B: {
        int s = p[0] << 8 | p[1], e = p[2] << 8 | p[3], lim = c == 0x2A ? logical_cols(m) : logical_rows(m);
        if (s > e || e >= lim) {
            problem(m, "window outside the memory", c);
            break;
        }
        if (c == 0x2A) {
            m->xs = s;
            m->xe = e;
        } else {
            m->ys = s;
            m->ye = e;
        }
        break;
    }
    default: break;
    }
}

static void pixel(panel_model *m, uint16_t v)
{
    if (m->row > m->ye) {
        problem(m, "more pixels than the window holds", 0x2C);
        return;
    }
    *cell(m, m->col, m->row) = v;
    m->pixels++;
    if (++m->col > m->xe) {
        m->col = m->xs;
        m->row++;
    }
}

void panel_model_bytes(panel_model *m, int dc, const uint8_t *data, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        uint8_t b = data[i];
        if (!dc) {
            finish(m);
            m->commands++;
            if (m->settling && m->ms_since < 5) problem(m, "a command less than 5 ms after SWRESET or SLPOUT", b);
            m->settling = 0;
            const command_info *ci = find(m, b);
            if (!ci) {
                problem(m, "not a command of this controller", b);
                continue;
            }
            m->cmd = b;
            m->nparam = 0;
            if (ci->max == 0) finish(m);   /* no parameters: it takes effect now */
            else if (ci->min == PIXELS) {
                if (m->colmod != 0x55) problem(m, "pixels before 16-bit mode (COLMOD 0x55)", m->colmod);
                m->writing = 1;
                m->col = m->xs;
                m->row = m->ys;
                m->half = 0;
                m->ramwr++;
            }
        } else if (m->cmd < 0) {
            problem(m, "data without a command", b);
        } else if (m->writing) {
            if (!m->half) {
                m->high = b;
                m->half = 1;
            } else {
                pixel(m, (uint16_t)(m->high << 8 | b));   /* high byte first */
                m->half = 0;
            }
        } else if (m->nparam < (int)sizeof m->param) {
            m->param[m->nparam++] = b;
        } else {
            problem(m, "too many parameters", m->cmd);
        }
    }
}

void panel_model_delay(panel_model *m, uint32_t ms)
{
    m->ms_since += ms;
}

uint16_t panel_model_seen(const panel_model *m, int x, int y)
{
    uint16_t v = *cell((panel_model *)m, x, y);
    if (((m->madctl & 0x08) != 0) != (m->filter_bgr != 0))   /* red and blue reach each other's subpixels */
        v = (uint16_t)((v & 0x07E0) | (v >> 11) | (v << 11));
    if (m->invon != m->inverted) v = (uint16_t)~v;
    return v;
}

const char *panel_model_problem(panel_model *m)
{
    finish(m);
    if (m->error[0]) return m->error;
    if (m->sleeping) return "the panel is asleep (no SLPOUT)";
    if (!m->display_on) return "the display is off (no DISPON)";
    return NULL;
}
