# boards/mps2-an500/board.mk - an ARM Cortex-M7 microcontroller of the
# Teensy 4 / STM32F7 class, run under QEMU's model of the MPS2-AN500 board
# (`make BOARD=mps2-an500`, then `make BOARD=mps2-an500 run`).
#
# The part: a Cortex-M7 at 600 MHz (the Teensy 4.0's i.MX RT1062) with
# 2 MiB of flash and 512 KiB of SRAM in one block (the RT1062's 512 KiB
# of on-chip RAM that DMA reaches; its other 512 KiB, tightly coupled, is
# split between code and data and left out).  QEMU's AN500 maps 4 MB at 0
# (flash here) and 4 MB at 0x20000000 (RAM), with the CMSDK timer at
# 0x40000000 as on the AN385 (hw/arm/mps2.c), so the Cortex-M3 board's
# linker script, startup, semihosting and timer serve it unchanged.  The
# part has the RAM for what the small boards leave out: anti-aliased
# outlines (creases left hard, as on mps2-an385-full) and the vertex cache,
# which evaluates each corner's vertex once per frame instead of once per
# band it reaches.
include boards/mps2-an385/board.mk

# Bands of 60 rows (115 200 bytes of band buffers): four bands a frame.
BOARD_BAND_ROWS := 60
BOARD_FLASH_BYTES := 2097152
BOARD_RAM_BYTES   := 524288
BOARD_STACK_BYTES := 8192
BOARD_ARENA_BYTES := 514048
BOARD_ARCH  := -mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16
# The core's options are in boards/mps2-an500/config.h: anti-aliased
# outlines (not creases), textures and the shortcuts.
# The vertex cache may take this much of the arena (silk_render_opts).
BOARD_FW_DEFS := -DFW_REPORT_BUDGET -DFW_VERTEX_CACHE_BYTES=196608
# The core's code budget: 72 KiB
# (the reader of the compact model, about 6.5 KB, is in it: it takes bunny-500 from
# 44 260 bytes of arrays to 6 142, so flash as a whole holds far more)
BOARD_CODE_BYTES := 73728
BOARD_MACHINE := mps2-an500
BOARD_RUN   := qemu-system-arm -M mps2-an500 -icount shift=0 -nographic -monitor none -serial none \
               -semihosting-config enable=on,target=native -kernel
# 600 MHz, the Teensy 4's clock; cycles per instruction assumed
# (docs/small-devices.md, "Speed on the device"): the Cortex-M7 issues two
# instructions a cycle where it can and runs from tightly coupled memory
# without wait states, about 1.5 times the Cortex-M4's instructions a
# cycle on the same code (ARM's CoreMark per MHz: 5.01 against 3.40).
BOARD_CLOCK_HZ := 600000000
BOARD_CPI      := 0.75 1.0

BOARD_MESHES := $(MESHES_DIR)/feline-2k.obj $(MESHES_DIR)/dragon-5k.obj
BUILD := build-mps2-an500
