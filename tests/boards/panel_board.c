/*
 * panel_board.c - examples/spi_panel/board.h for the host: the SPI bus is
 * a model of the ILI9341, or with -DPANEL=SILK_PANEL_ST7789 the ST7789
 * (support/panel_model.c), its DMA completes only
 * when it is waited for (so a band drawn into a buffer still being sent
 * would show), and each frame the panel shows is written as a PPM file,
 * widened from RGB565 by bit replication as silk's PPM writer does, so
 * that it compares byte for byte with `silk render --format rgb565`.
 *
 *   panel_board PREFIX     frames to PREFIX-cK.ppm; exit 1 when the panel
 *                          refused the stream or the example failed
 *
 * Built and run by tests/cli_porting.sh with the example.
 */
#include <stdio.h>
#include <stdlib.h>
#include "board.h"
#include "support/panel_model.h"
#include "silk_panel.h"

#ifndef PANEL                  /* the example's (spi_panel.c) */
#define PANEL SILK_PANEL_ILI9341
#endif

int spi_panel_run(void);

static panel_model model;
static const char *prefix;
static const uint8_t *pending;
static size_t pending_n;
static int misuse, shown;

int board_spi_write(int dc, const uint8_t *data, size_t n)
{
    if (pending) misuse++;
    panel_model_bytes(&model, dc, data, n);
    return 0;
}

int board_spi_start(const uint8_t *data, size_t n)
{
    if (pending) misuse++;
    pending = data;
    pending_n = n;
    return 0;
}

int board_spi_wait(void)
{
    if (pending) panel_model_bytes(&model, 1, pending, pending_n);
    pending = NULL;
    return 0;
}

void board_delay_ms(uint32_t ms)
{
    panel_model_delay(&model, ms);
}

void board_log(const char *msg)
{
    fprintf(stderr, "panel_board: %s\n", msg);
}

void board_frame_shown(int k)
{
    char path[512];
    snprintf(path, sizeof path, "%s-c%d.ppm", prefix, k);
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        exit(1);
    }
    fprintf(f, "P6\n320 240\n255\n");
    for (int y = 0; y < 240; y++)
        for (int x = 0; x < 320; x++) {
            unsigned v = panel_model_seen(&model, x, y), r = v >> 11, g = (v >> 5) & 63u, b = v & 31u;
            unsigned char px[3] = { (unsigned char)(r << 3 | r >> 2), (unsigned char)(g << 2 | g >> 4),
                                    (unsigned char)(b << 3 | b >> 2) };
            fwrite(px, 1, 3, f);
        }
    if (fclose(f) != 0) {
        perror(path);
        exit(1);
    }
    shown++;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: panel_board PREFIX\n");
        return 2;
    }
    prefix = argv[1];
    panel_model_init(&model, PANEL);
    int rc = spi_panel_run();
    const char *why = panel_model_problem(&model);
    if (why) fprintf(stderr, "panel_board: the panel refuses the stream: %s\n", why);
    if (misuse) fprintf(stderr, "panel_board: %d bytes sent while pixels were in flight\n", misuse);
    printf("panel_board: %d frames shown, %ld memory writes of %ld pixels, %ld commands\n", shown, model.ramwr,
           model.pixels, model.commands);
    return rc || why || misuse ? 1 : 0;
}
