# boards/linux-fb/board.mk - a Linux machine with a framebuffer and no GPU
# worth using: a Raspberry Pi with an SPI display, an industrial panel PC,
# a VM console.  `make BOARD=linux-fb` builds the silk command into
# build-linux-fb/ with this board's defaults; `silk view MESH` then shows
# the model turning on /dev/fb0 until Ctrl-C, rendered in bands straight
# into the screen memory (platform/fb_sink.c): the size and pixel format
# come from the device (16, 24 or 32 bits per pixel).
#
# Cross-compiling for an ARM Linux board: make BOARD=linux-fb CC=aarch64-linux-gnu-gcc
# (libpng for the target must be installed for `silk render`).

# `silk render` defaults: a small RGB565 panel
BOARD_WIDTH  := 320
BOARD_HEIGHT := 240
BOARD_FORMAT := SILK_PIX_RGB565
# `silk view` draws BOARD_BAND_ROWS rows at a time into BOARD_FB
BOARD_BAND_ROWS := 32
BOARD_SINK   := fb
BOARD_FB     := /dev/fb0
BOARD_VIEWS  := 3

BOARD_CFLAGS := -DSILK_BOARD_WIDTH=$(BOARD_WIDTH) -DSILK_BOARD_HEIGHT=$(BOARD_HEIGHT) \
                -DSILK_BOARD_FORMAT=$(BOARD_FORMAT) -DSILK_BOARD_BAND_ROWS=$(BOARD_BAND_ROWS) \
                -DSILK_BOARD_FB='"$(BOARD_FB)"'

BUILD := build-linux-fb
