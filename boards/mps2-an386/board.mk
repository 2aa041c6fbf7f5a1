# boards/mps2-an386/board.mk - an ARM Cortex-M4 microcontroller of the
# STM32F4 class, run under QEMU's model of the MPS2-AN386 board (`make
# BOARD=mps2-an386`, then `make BOARD=mps2-an386 run`).
#
# The part: an STM32F407-class Cortex-M4F at 168 MHz with 1 MiB of flash
# and 128 KiB of SRAM, the contiguous main SRAM that DMA reaches (the
# STM32F407's other 64 KiB, core-coupled memory at another address, is
# left out: the arena is one block).  QEMU's AN386 has the AN385's memory
# map (4 MB at 0 used as flash, 4 MB at 0x20000000 as RAM, the CMSDK
# timer at 0x40000000; hw/arm/mps2.c), so the Cortex-M3 board's linker
# script, startup, semihosting and timer serve it unchanged.  No frame
# buffer: 320x240 RGB565 in bands, each streamed to the host.  The models
# are the shared 2 000- and 5 000-triangle meshes, packed into flash.
include boards/mps2-an385/board.mk

# Bands of 24 rows (46 080 bytes of band buffers) leave the arena room for
# the smooth plan of a 5 000-triangle model (dragon-5k needs about 31 KB at
# its worst view); taller bands are faster (docs/small-devices.md).
BOARD_BAND_ROWS := 24
BOARD_FLASH_BYTES := 1048576
BOARD_RAM_BYTES   := 131072
BOARD_STACK_BYTES := 6144
BOARD_ARENA_BYTES := 124416
BOARD_ARCH  := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
# The core's options are in boards/mps2-an386/config.h: flat and smooth, as
# on the Cortex-M3 board (a part of this class draws a fine model's smooth
# silhouette instead of anti-aliasing a coarse one's).
# Room in flash for the budget's own check of every frame (fw_main.c).
BOARD_FW_DEFS := -DFW_REPORT_BUDGET
BOARD_CODE_BYTES := 49152
BOARD_MACHINE := mps2-an386
BOARD_RUN   := qemu-system-arm -M mps2-an386 -icount shift=0 -nographic -monitor none -serial none \
               -semihosting-config enable=on,target=native -kernel
# 168 MHz, the STM32F407's top clock; cycles per instruction assumed
# (docs/small-devices.md, "Speed on the device"): as the Cortex-M3's, with
# its single-cycle 32x32->64 multiplies on one side and five flash wait
# states behind the ART accelerator's cache on the other.
BOARD_CLOCK_HZ := 168000000
BOARD_CPI      := 1.25 1.5

BOARD_MESHES := $(MESHES_DIR)/bunny-2k.obj $(MESHES_DIR)/dragon-5k.obj
BUILD := build-mps2-an386
