# boards/mps2-an385/board.mk - an ARM Cortex-M3 microcontroller, run under
# QEMU's model of the MPS2-AN385 board (`make BOARD=mps2-an385`, then
# `make BOARD=mps2-an385 run`).
#
# The AN385 itself has 8 MB of SSRAM; the firmware is linked for the budget
# of a real small part instead: a Cortex-M3 with 512 KiB of flash and
# 32 KiB of SRAM (the LPC1768's main SRAM bank, say): the linker refuses a
# program that does not fit (platform/mps2/mps2.ld).  No frame buffer: the frame is rendered in
# bands of BOARD_BAND_ROWS rows and each band is streamed to the host through
# ARM semihosting, as a display driver would send it over SPI.  The model is
# compiled into flash by `silk pack` (docs/small-devices.md).

# The frame (also the defaults of the host-side tool build-mps2-an385/silk)
BOARD_WIDTH  := 320
BOARD_HEIGHT := 240
BOARD_FORMAT := SILK_PIX_RGB565
# Bands of 8 rows (15 360 bytes of band buffers) leave the arena 11 520
# bytes for a frame's scratch: a smooth frame of a 500-triangle shared
# model needs 7.5 to 10.1 KB; taller bands are faster, since every band
# sets up again the triangles that reach into it (4 rows take a smooth
# bunny-500 frame from about 36 to 42 M instructions).
BOARD_BAND_ROWS := 8
BOARD_SINK   := semihosting

# The part: flash, RAM, and how the RAM is split.  The arena holds the band
# buffers (RASTER) and the per-frame scratch (FRAME); the rest of .bss and
# .data is a few hundred bytes of libc and startup state.
BOARD_FLASH_BYTES := 524288
BOARD_RAM_BYTES   := 32768
# The stack's painted high-water is about 5.1 KiB (`make profile`, its stage passes included).
BOARD_STACK_BYTES := 5632
BOARD_ARENA_BYTES := 26880

# Toolchain and flags (`make deps` installs them on Debian/Ubuntu)
BOARD_CROSS := arm-none-eabi-
BOARD_ARCH  := -mcpu=cortex-m3 -mthumb
# The core's build options are in boards/mps2-an385/config.h (flat and
# smooth frames only: no PN or blend, lines, --wire, clip or siltex mode,
# anti-aliased outlines or textures, and none of the host's shortcuts).
BOARD_OPT   := -Os
# The core's code budget (`make profile` checks it): 48 KiB
# (the reader of the compact model, about 6.5 KB, is in it: it takes bunny-500 from
# 44 260 bytes of arrays to 6 142, so flash as a whole holds far more)
BOARD_CODE_BYTES := 49152
# -icount shift=0: virtual time advances exactly 1 ns per instruction, so
# the firmware's timer (25 MHz, 40 ns a tick) counts instructions.
BOARD_RUN   := qemu-system-arm -M mps2-an385 -icount shift=0 -nographic -monitor none -serial none \
               -semihosting-config enable=on,target=native -kernel
# For the frames-per-second estimate of `make profile`: the usual clock of a
# Cortex-M3 part (STM32F103: 72 MHz) and the cycles per instruction assumed,
# a range (docs/small-devices.md, "Speed on the device").
BOARD_CLOCK_HZ := 72000000
BOARD_CPI      := 1.25 1.5

# What the firmware renders: each model packed into flash, from BOARD_VIEWS
# cameras around it (`silk pack --views`), each in flat and smooth mode.
BOARD_MESHES ?= $(MESHES_DIR)/bunny-500.obj $(MESHES_DIR)/knot-480.obj
BOARD_VIEWS  := 3
# No visibility hierarchy in flash (860 bytes for bunny-500): a few hundred
# normals are tested one by one about as fast, with the same result.
BOARD_PACK_ARGS := --visibility brute

BOARD_CFLAGS := -DSILK_BOARD_WIDTH=$(BOARD_WIDTH) -DSILK_BOARD_HEIGHT=$(BOARD_HEIGHT) \
                -DSILK_BOARD_FORMAT=$(BOARD_FORMAT)

# Host-side objects (the tool that packs models) go to their own directory;
# the firmware's rules are in platform/mps2/firmware.mk.
BUILD := build-mps2-an385
BOARD_RULES := platform/mps2/firmware.mk
.DEFAULT_GOAL := firmware
