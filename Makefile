# silk - build with plain make.  `make` builds build/libsilk.a and build/silk.
# See README.md for the targets.

CC       ?= cc
AR       ?= ar
PREFIX   ?= /usr/local
BUILD    ?= build
OPT      ?= -O2
WARN     := -Wall -Wextra -Wpedantic
CFLAGS_BASE := -std=c11 $(WARN) $(OPT) -g -Iinclude
SAN      ?=
ifeq ($(SAN),1)
  BUILD  := build-san
  SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
CFLAGS   ?=
ALL_CFLAGS = $(CFLAGS_BASE) $(SANFLAGS) $(CFLAGS)
LDFLAGS  ?=
# The board: the silk tool's defaults for this target (boards/*/board.mk).
BOARD    ?= host
include boards/$(BOARD)/board.mk
PNG_LIBS := $(shell pkg-config --libs libpng 2>/dev/null || echo -lpng)
PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)

CORE_SRC  := $(wildcard src/*.c)
PLAT_SRC  := platform/png_sink.c platform/ppm_sink.c platform/file.c platform/png_read.c platform/fb_sink.c
TOOL_SRC  := $(wildcard tools/*.c)
TEST_SRC  := $(wildcard tests/test_*.c)

CORE_OBJ  := $(CORE_SRC:%.c=$(BUILD)/obj/%.o)
PLAT_OBJ  := $(PLAT_SRC:%.c=$(BUILD)/obj/%.o)
TOOL_OBJ  := $(TOOL_SRC:%.c=$(BUILD)/obj/%.o)
TEST_BIN  := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TEST_SUPPORT := $(wildcard tests/support/*.c)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT:%.c=$(BUILD)/obj/%.o)

.PHONY: all lib test test-fast check-nofloat demo install clean tests bench
all: $(BUILD)/libsilk.a $(BUILD)/silk

lib: $(BUILD)/libsilk.a

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(PNG_CFLAGS) -MMD -MP -c $< -o $@

# The tool takes its defaults (image size, pixel format) from the board.
$(TOOL_OBJ): ALL_CFLAGS += $(BOARD_CFLAGS)
$(TOOL_OBJ): boards/$(BOARD)/board.mk

$(BUILD)/libsilk.a: $(CORE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && $(AR) rcs $@ $^

$(BUILD)/libsilk_platform.a: $(PLAT_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

$(BUILD)/silk: $(TOOL_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(TOOL_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a $(PNG_LIBS) -lm

$(BUILD)/tests/%: tests/%.c $(TEST_SUPPORT_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a tests/check.h
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -Itests -o $@ $< $(TEST_SUPPORT_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a $(PNG_LIBS) -lm

tests: $(TEST_BIN) $(BUILD)/silk

# The core may not use floating point: compiled without FP/SIMD registers,
# any float or double use is a compile error.
check-nofloat:
	@for f in $(CORE_SRC); do \
	  $(CC) -std=c11 -Iinclude -O0 -mgeneral-regs-only -c $$f -o /dev/null || { echo "check-nofloat: $$f uses floating point"; exit 1; }; \
	done; \
	if grep -nwE 'float|double' $(CORE_SRC) include/silk/*.h | grep -vE ':[0-9]+:\s*(/\*|\*|//)'; then \
	  echo "check-nofloat: the words above appear in the core"; exit 1; fi; \
	if grep -nE '\b(malloc|calloc|realloc|free)\s*\(' $(CORE_SRC); then \
	  echo "check-nofloat: the core calls the heap allocator"; exit 1; fi; \
	echo "check-nofloat: $(words $(CORE_SRC)) core files compile without floating point"

# Normal build, then the same suite under AddressSanitizer + UBSan.
test: check-nofloat
	$(MAKE) tests
	SILK=$(BUILD)/silk sh tests/run.sh $(BUILD)
	$(MAKE) SAN=1 tests
	SILK=build-san/silk SILK_SAN=1 sh tests/run.sh build-san

# Just the normal build's suite.
test-fast: check-nofloat tests
	SILK=$(BUILD)/silk sh tests/run.sh $(BUILD)

# Per-frame visibility, brute pass against the hierarchy: out/bench_visibility.txt
# (CALLGRIND=1 adds instruction counts).
bench: $(BUILD)/silk
	sh bench/visibility.sh $(BUILD)/silk out

demo: $(BUILD)/silk
	sh tools/demo.sh $(BUILD)/silk out

install: $(BUILD)/libsilk.a $(BUILD)/silk
	install -d $(DESTDIR)$(PREFIX)/lib $(DESTDIR)$(PREFIX)/include/silk $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 $(BUILD)/libsilk.a $(DESTDIR)$(PREFIX)/lib/
	install -m 644 include/silk/*.h $(DESTDIR)$(PREFIX)/include/silk/
	install -m 755 $(BUILD)/silk $(DESTDIR)$(PREFIX)/bin/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|0.1.0|g' silk.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/silk.pc

clean:
	rm -rf build build-san out

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/*/*/*.d)

# ---- small devices (docs/small-devices.md) ----------------------------------
# A device board's own rules (the firmware of boards/mps2-an385).
ifdef BOARD_RULES
include $(BOARD_RULES)
else
# From the host: the firmware targets run in the device board's build.
FW_BOARD ?= mps2-an385
.PHONY: firmware firmware-host firmware-big-ram run
firmware firmware-host firmware-big-ram run:
	$(MAKE) BOARD=$(FW_BOARD) BUILD=build-$(FW_BOARD) SAN= CFLAGS= $@
endif

# The ARM toolchain and QEMU for the firmware (Debian, Ubuntu).
DEPS_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
.PHONY: deps profile
deps:
	$(if $(filter 0,$(shell id -u)),,sudo) apt-get install -y --no-install-recommends $(DEPS_PACKAGES)

# Where every byte goes on a board: `make profile [PROFILE_BOARD=..] [PROFILE_MESH=..]`.
PROFILE_BOARD ?= $(if $(BOARD_RULES),$(BOARD),mps2-an385)
PROFILE_MESH  ?= $(or $(SILK_MESHES),../shared/meshes)/bunny-500.obj
profile: $(BUILD)/silk
	$(BUILD)/silk profile $(PROFILE_MESH) --board $(PROFILE_BOARD)

# `make test` runs the firmware under QEMU (tests/cli_qemu.sh) when the ARM
# toolchain is installed; in CI it must be.
HAVE_ARM := $(shell command -v arm-none-eabi-gcc >/dev/null 2>&1 && command -v qemu-system-arm >/dev/null 2>&1 && echo 1)
ifeq ($(BOARD)$(HAVE_ARM),host1)
ifneq ($(SAN),1)
tests: firmware-for-tests
.PHONY: firmware-for-tests
firmware-for-tests:
	$(MAKE) BOARD=$(FW_BOARD) BUILD=build-$(FW_BOARD) SAN= CFLAGS= firmware firmware-host firmware-big-ram
endif
endif

