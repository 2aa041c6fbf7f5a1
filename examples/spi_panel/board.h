/*
 * board.h - what examples/spi_panel/spi_panel.c needs from a board: the
 * SPI bus to the panel with its data/command line, a DMA transfer of
 * pixels, a millisecond delay and a place for messages.  A port writes
 * these few functions for its MCU (docs/porting.md has an STM32 sketch of
 * each); tests/support/panel_board.c writes them for the host, where the
 * bus is a model of the panel.
 */
#ifndef SPI_PANEL_BOARD_H
#define SPI_PANEL_BOARD_H

#include <stddef.h>
#include <stdint.h>

/* Send n bytes with chip select asserted and the D/C line low (dc 0, one
 * command byte) or high (dc 1, parameters or pixels); return when they are
 * on the wire.  0 on success. */
int board_spi_write(int dc, const uint8_t *data, size_t n);
/* Start a DMA transfer of n pixel bytes (D/C high) and return at once. */
int board_spi_start(const uint8_t *data, size_t n);
/* Wait until the transfer started last is done (its buffer free again). */
int board_spi_wait(void);
void board_delay_ms(uint32_t ms);
/* A message for the developer (a UART, semihosting, nothing). */
void board_log(const char *msg);
/* Frame k is on the panel (the last band sent): pace the frames here. */
void board_frame_shown(int k);

#endif
