# boards/microbit/board.mk - an ARM Cortex-M0 microcontroller with 16 KiB of
# RAM, run under QEMU's model of the BBC micro:bit (`make BOARD=microbit`,
# then `make BOARD=microbit run`).
#
# The micro:bit's nRF51822 is the part itself: Cortex-M0 at 16 MHz, 256 KiB
# flash at 0, 16 KiB RAM at 0x20000000, no hardware divide and no 32x32->64
# multiply (libgcc does both).  The frame is that of a common SPI display,
# 160x128 RGB565, rendered in bands of BOARD_BAND_ROWS rows and streamed to
# the host through semihosting; the model is compiled into flash by
# `silk pack`.  Startup, semihosting, linker script and scene are the
# Cortex-M3 board's (platform/mps2/); only the timer differs (an nRF51 TIMER,
# platform/mps2/timer_nrf51.c).

BOARD_WIDTH  := 160
BOARD_HEIGHT := 128
BOARD_FORMAT := SILK_PIX_RGB565
# A band costs 160 * rows * (2 + 4) bytes.  Every band sets up again the
# triangles that reach into it, so taller bands are faster, but 2 rows
# (1 920 bytes) leave a smooth frame room to keep its edge tangents: in
# bands of 3 (2 880 bytes) bunny-500's frame from the second packed view
# has none and takes 681 M instructions instead of 133 M (the others are
# 109 and 135 M in bands of 3, 124 and 156 M in bands of 2;
# docs/small-devices.md).
BOARD_BAND_ROWS := 2
BOARD_SINK   := semihosting

# The part.  The arena takes what the stack, libc's few hundred bytes and
# the scene's statics leave.
BOARD_FLASH_BYTES := 262144
BOARD_RAM_BYTES   := 16384
# The stack's painted high-water is 5 620 bytes (`make profile BOARD=microbit`);
# the stage pass after it needs 5 668 and runs in the same room.
BOARD_STACK_BYTES := 5760
BOARD_ARENA_BYTES := 10496

BOARD_CROSS := arm-none-eabi-
BOARD_ARCH  := -mcpu=cortex-m0 -mthumb
# Flat and smooth only, as on the Cortex-M3 board (boards/microbit/config.h):
# PN, blend, clip mode, pen-and-ink lines, --wire, anti-aliased outlines and
# textures stay in the host library.  Thumb-1 code is larger than the
# Cortex-M3's Thumb-2: the core's budget is 52 KiB of the part's 256 KiB of
# flash
BOARD_OPT   := -Os
# (the reader of the compact model, about 6.5 KB, is in it: it takes bunny-500 from
# 44 260 bytes of arrays to 6 142, so flash as a whole holds far more)
BOARD_CODE_BYTES := 53248
# No visibility hierarchy in flash, as on the Cortex-M3 board
# (boards/mps2-an385/board.mk says why).
BOARD_PACK_ARGS := --visibility brute
# The tick counter: TIMER0 of the nRF51 at 16 MHz.  -icount shift=0: one
# instruction is 1 ns of virtual time, so a tick is 62.5 instructions.
BOARD_TIMER := platform/mps2/timer_nrf51.c
BOARD_INSTR_PER_TICK := 62.5
BOARD_MACHINE := microbit
BOARD_RUN   := qemu-system-arm -M $(BOARD_MACHINE) -icount shift=0 -nographic -monitor none -serial none \
               -semihosting-config enable=on,target=native -kernel
# fps estimate: the nRF51's 16 MHz clock; cycles per instruction assumed
# (docs/small-devices.md, "Speed on the device").
BOARD_CLOCK_HZ := 16000000
BOARD_CPI      := 1.25 1.5

# The same Cortex-M0 code linked for 256 KiB of RAM runs on QEMU's
# mps2-an385 (a Cortex-M3 executes the M0's Thumb-1 code unchanged), with
# that board's timer: models whose smooth frames 16 KiB cannot hold
# (knot-480 needs 8.8 KB of frame scratch), measured and compared with the
# host (`make BOARD=microbit firmware-256k`).
BOARD_BIG_TIMER := platform/mps2/timer_cmsdk.c
BOARD_BIG_MACHINE := mps2-an385
BOARD_BIG_INSTR_PER_TICK := 40

# What the firmware renders: bunny-500 when the shared meshes are there,
# and always a torus made by `silk gen`.
BOARD_MESHES ?= $(wildcard $(MESHES_DIR)/bunny-500.obj) $(BUILD)/gen/torus.obj
BOARD_VIEWS  := 3

BOARD_CFLAGS := -DSILK_BOARD_WIDTH=$(BOARD_WIDTH) -DSILK_BOARD_HEIGHT=$(BOARD_HEIGHT) \
                -DSILK_BOARD_FORMAT=$(BOARD_FORMAT)

BUILD := build-microbit
BOARD_RULES := platform/mps2/firmware.mk
.DEFAULT_GOAL := firmware
