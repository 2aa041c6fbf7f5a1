# boards/host/board.mk - the host configuration (a Linux or macOS desktop),
# included by the Makefile (BOARD ?= host).
#
# The host has a frame buffer, libc's malloc and a file system, so the
# `silk` tool renders whole frames in one pass, writes PNG or PPM, and sizes
# its arena from the mesh file (docs/memory.md).  A device board would set a
# smaller frame, RGB565 (what most small LCDs take) and a fixed arena.
#
# What the tool uses when no option says otherwise:
BOARD_WIDTH  := 640
BOARD_HEIGHT := 480
BOARD_FORMAT := SILK_PIX_RGB888
# The whole frame in one band, written as PNG (what `silk profile --board
# host` measures; device boards set a smaller band and their own sink).
BOARD_BAND_ROWS := $(BOARD_HEIGHT)
BOARD_SINK   := png

BOARD_CFLAGS := -DSILK_BOARD_WIDTH=$(BOARD_WIDTH) -DSILK_BOARD_HEIGHT=$(BOARD_HEIGHT) \
                -DSILK_BOARD_FORMAT=$(BOARD_FORMAT)
