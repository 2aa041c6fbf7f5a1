# boards/mps2-an385-full/board.mk - the Cortex-M3 board of
# boards/mps2-an385 as a part with 64 KiB of SRAM (an STM32F103RE-class
# device: 512 KiB of flash, 64 KiB of SRAM), with anti-aliased outlines and
# textures built in: the same QEMU machine and frame, in bands of 8 rows
# (an anti-aliased band also draws the rows above and below it, which costs
# half again in bands of 4).  Its
# models are bunny-500 and a globe from `silk gen --uv` packed with silk's
# own checker texture in RGB565 (platform/mps2/firmware.mk).
include boards/mps2-an385/board.mk

BOARD_BAND_ROWS   := 8
BOARD_RAM_BYTES   := 65536
# The stack: a textured frame's stage-timing pass (fw_main.c, a wrapped
# HAL) reaches 6 176 bytes, the curve of an anti-aliased outline drawn
# through the vertex stage from inside the outline walk; 512 bytes more
# than the 6 144 it had, taken from the arena, whose peak is 42 688.
BOARD_STACK_BYTES := 6656
BOARD_ARENA_BYTES := 58624
# The core's options are in boards/mps2-an385-full/config.h: those of
# boards/mps2-an385 with anti-aliased outlines (not creases: they do not fit
# the code budget) and textures.  The core's code budget: 56 KiB
# (the reader of the compact model, about 6.5 KB, is in it: it takes bunny-500 from
# 44 260 bytes of arrays to 6 142, so flash as a whole holds far more)
BOARD_CODE_BYTES := 57344
BUILD := build-mps2-an385-full
BOARD_MESHES := $(MESHES_DIR)/bunny-500.obj $(BUILD)/models/globe.obj
