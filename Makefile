# silk - build with plain make.  `make` builds build/libsilk.a and build/silk.
# See README.md for the targets.

CC       ?= cc
AR       ?= ar
PREFIX   ?= /usr/local
BUILD    ?= build
OPT      ?= -O2
WARN     := -Wall -Wextra -Wpedantic -Wundef
CFLAGS_BASE := -std=c11 $(WARN) $(OPT) -g -Iinclude
SAN      ?=
ifeq ($(SAN),1)
  BUILD  := build-san
  SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
CFLAGS   ?=
ALL_CFLAGS = $(CFLAGS_BASE) $(HOST_CONFIG) $(SANFLAGS) $(CFLAGS)
LDFLAGS  ?=
# The board: the silk tool's defaults for this target (boards/*/board.mk).
BOARD    ?= host
# The shared reference meshes (tests, demo, firmware models); the build and
# the tests go on without them.
MESHES_DIR := $(or $(SILK_MESHES),../shared/meshes)
include boards/$(BOARD)/board.mk
# The core's build options (include/silk/config.h) are the board's header,
# boards/NAME/config.h, named by -DSILK_CONFIG_FILE.  A firmware board's
# build directory also holds the host-side tool that packs its models,
# built with the host's options; its firmware and the firmware's host build
# take the board's (platform/mps2/firmware.mk).  CORE_CONFIG=FILE builds
# everything here with that header instead (`make test` runs the core's
# unit tests so in each firmware board's configuration).
BOARD_CONFIG ?= boards/$(BOARD)/config.h
config_flag = -DSILK_CONFIG_FILE='"$(abspath $(1))"'
CORE_CONFIG ?= $(if $(BOARD_RULES),boards/host/config.h,$(BOARD_CONFIG))
HOST_CONFIG := $(call config_flag,$(CORE_CONFIG))
PNG_LIBS := $(shell pkg-config --libs libpng 2>/dev/null || echo -lpng)
PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)

CORE_SRC  := $(wildcard src/*.c)
PLAT_SRC  := platform/png_sink.c platform/ppm_sink.c platform/file.c platform/png_read.c platform/ppm_read.c platform/fb_sink.c \
             platform/panel/silk_panel.c
# The silk command's parts, a folder each (tools/README.md): the command line,
# host-side preparation, the viewer and image helpers.
TOOL_SRC  := $(wildcard tools/cli/*.c tools/prep/*.c tools/view/*.c tools/image/*.c)
# The window of `silk view` needs SDL2 (docs/viewer.md); without it the rest
# builds, and `silk view` offers only --fb, --benchmark and --events.
# (SDL2_OK= on the command line builds without it.)  The objects that differ
# with it depend on BUILD/sdl2.stamp, which changes when the answer does, so
# a build follows its configuration without `make clean`.
SDL2_OK   ?= $(shell pkg-config --exists sdl2 2>/dev/null && echo 1)
ifeq ($(SDL2_OK),1)
  SDL2_CFLAGS := $(shell pkg-config --cflags sdl2)
  SDL2_LIBS   := $(shell pkg-config --libs sdl2)
  TOOL_SRC  := $(filter-out tools/view/viewer_nosdl.c,$(TOOL_SRC))
else
  TOOL_SRC  := $(filter-out tools/view/viewer_sdl.c,$(TOOL_SRC))
  $(info silk: SDL2 not found (pkg-config sdl2): building without the viewer window)
endif
# The tests, a folder per part they test (tests/README.md): core/, platform/,
# prep/ (host-side preparation and image helpers); cli/ and boards/ hold the
# shell tests.  Every test program is BUILD/tests/test_NAME, whatever its folder.
TEST_DIRS := core platform prep
TEST_SRC  := $(foreach d,$(TEST_DIRS),$(wildcard tests/$(d)/test_*.c))

CORE_OBJ  := $(CORE_SRC:%.c=$(BUILD)/obj/%.o)
PLAT_OBJ  := $(PLAT_SRC:%.c=$(BUILD)/obj/%.o)
TOOL_OBJ  := $(TOOL_SRC:%.c=$(BUILD)/obj/%.o)
TEST_BIN  := $(addprefix $(BUILD)/tests/,$(basename $(notdir $(TEST_SRC)))) $(BUILD)/tests/test_cxx
TEST_SUPPORT := $(wildcard tests/support/*.c)
# (stexgen.c writes prepared models with the tool's writer)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/tools/prep/model_file.o

.PHONY: all lib test test-fast check-nofloat demo install clean tests bench bench-peers fuzz fuzz-build
all: $(BUILD)/libsilk.a $(BUILD)/silk $(BUILD)/silk.1

lib: $(BUILD)/libsilk.a

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(PNG_CFLAGS) -MMD -MP -c $< -o $@

# The tool takes its defaults (image size, pixel format) from the board, and
# `silk profile` the board's bands and views.
BOARD_TOOL_CFLAGS := $(BOARD_CFLAGS) -DSILK_BOARD_NAME='"$(BOARD)"' -DSILK_BOARD_VIEWS=$(or $(BOARD_VIEWS),3)
$(BUILD)/obj/tools/cli/cmd_profile.o: BOARD_TOOL_CFLAGS += -DSILK_BOARD_BAND_ROWS=$(BOARD_BAND_ROWS)
# Tools include each other by folder ("prep/hull.h") and the host I/O as
# "platform/...".
TOOL_INC := -Itools -I.
$(TOOL_OBJ) $(TEST_SUPPORT_OBJ): ALL_CFLAGS += $(TOOL_INC)
$(TOOL_OBJ): ALL_CFLAGS += $(BOARD_TOOL_CFLAGS)
$(TOOL_OBJ): boards/$(BOARD)/board.mk
ifeq ($(SDL2_OK),1)
$(BUILD)/obj/tools/cli/cmd_view.o: ALL_CFLAGS += -DSILK_HAVE_SDL2
$(BUILD)/obj/tools/view/viewer_sdl.o: ALL_CFLAGS += $(SDL2_CFLAGS) -DSILK_HAVE_SDL2
endif
$(BUILD)/obj/tools/cli/cmd_view.o $(BUILD)/silk: $(BUILD)/sdl2.stamp
.PHONY: FORCE
$(BUILD)/sdl2.stamp: FORCE
	@mkdir -p $(dir $@)
	@echo 'SDL2_OK=$(SDL2_OK)' | cmp -s - $@ 2>/dev/null || echo 'SDL2_OK=$(SDL2_OK)' >$@

$(BUILD)/libsilk.a: $(CORE_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && $(AR) rcs $@ $^

$(BUILD)/libsilk_platform.a: $(PLAT_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

$(BUILD)/silk: $(TOOL_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(TOOL_OBJ) $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a $(PNG_LIBS) $(SDL2_LIBS) -lm -pthread

# The manual page is the help text (tools/cli/man.c).
$(BUILD)/silk.1: $(BUILD)/silk
	$(BUILD)/silk help --man >$@.tmp && mv $@.tmp $@

define TEST_RULE
$$(BUILD)/tests/%: tests/$(1)/%.c $$(TEST_SUPPORT_OBJ) $$(BUILD)/libsilk_platform.a $$(BUILD)/libsilk.a tests/check.h
	@mkdir -p $$(dir $$@)
	$$(CC) $$(ALL_CFLAGS) $$(LDFLAGS) -Itests $$(TOOL_INC) -o $$@ $$< $$(TEST_TOOL_OBJ) $$(TEST_SUPPORT_OBJ) $$(BUILD)/libsilk_platform.a $$(BUILD)/libsilk.a $$(PNG_LIBS) -lm
endef
$(foreach d,$(TEST_DIRS),$(eval $(call TEST_RULE,$(d))))

# Tests of host tools link the tools' objects they test; tests that draw
# meshes made by `silk gen`'s generator link it.
$(BUILD)/tests/test_hull: TEST_TOOL_OBJ = $(addprefix $(BUILD)/obj/tools/prep/,hull.o lp.o simplify.o gen.o closest.o)
$(BUILD)/tests/test_hull: $(addprefix $(BUILD)/obj/tools/prep/,hull.o lp.o simplify.o gen.o closest.o)
$(BUILD)/tests/test_compact_frames: TEST_TOOL_OBJ = $(addprefix $(BUILD)/obj/tools/prep/,compact_enc.o gen.o)
$(BUILD)/tests/test_compact_frames: $(addprefix $(BUILD)/obj/tools/prep/,compact_enc.o gen.o)
$(BUILD)/tests/test_silmap: TEST_TOOL_OBJ = $(addprefix $(BUILD)/obj/tools/prep/,silmap.o gen.o)
$(BUILD)/tests/test_silmap: $(addprefix $(BUILD)/obj/tools/prep/,silmap.o gen.o)
$(BUILD)/tests/test_compact: TEST_TOOL_OBJ = $(addprefix $(BUILD)/obj/tools/prep/,compact_enc.o gen.o)
$(BUILD)/tests/test_compact: $(addprefix $(BUILD)/obj/tools/prep/,compact_enc.o gen.o)
GEN_TESTS := $(BUILD)/tests/test_golden $(BUILD)/tests/test_lines $(BUILD)/tests/test_aa $(BUILD)/tests/test_texture \
             $(BUILD)/tests/test_bands $(BUILD)/tests/test_panel $(BUILD)/tests/test_budget \
             $(BUILD)/tests/test_scene
$(GEN_TESTS): $(BUILD)/obj/tools/prep/gen.o
$(GEN_TESTS): TEST_TOOL_OBJ = $(BUILD)/obj/tools/prep/gen.o
# clip mode's golden frames draw a model prepared as silk prepare makes one
CLIP_TOOL_OBJ := $(addprefix $(BUILD)/obj/tools/prep/,gen.o hull.o lp.o simplify.o closest.o silmap.o)
$(BUILD)/tests/test_golden: $(CLIP_TOOL_OBJ)
$(BUILD)/tests/test_golden: TEST_TOOL_OBJ = $(CLIP_TOOL_OBJ)
STEX_TOOL_OBJ := $(addprefix $(BUILD)/obj/tools/prep/,stex_build.o stex_atlas.o stex_svd.o bvh.o closest.o gen.o)
$(BUILD)/tests/test_stex: $(STEX_TOOL_OBJ)
$(BUILD)/tests/test_stex: TEST_TOOL_OBJ = $(STEX_TOOL_OBJ) -pthread
$(BUILD)/tests/test_silmap_interp: TEST_TOOL_OBJ = $(addprefix $(BUILD)/obj/tools/prep/,silmap.o silmap_simplify.o gen.o)
$(BUILD)/tests/test_silmap_interp: $(addprefix $(BUILD)/obj/tools/prep/,silmap.o silmap_simplify.o gen.o)

# The public headers from C++ (extern "C"): compiles and links against the core.
$(BUILD)/tests/test_cxx: tests/core/test_cxx.cpp $(BUILD)/libsilk_platform.a $(BUILD)/libsilk.a $(wildcard include/silk/*.h)
	@mkdir -p $(dir $@)
	$(CXX) -std=c++11 $(WARN) $(OPT) -g -Iinclude $(SANFLAGS) $(CXXFLAGS) $(LDFLAGS) -o $@ $< $(BUILD)/libsilk_platform.a \
	    $(BUILD)/libsilk.a $(PNG_LIBS)

tests: $(TEST_BIN) $(BUILD)/silk $(BUILD)/silk.1

# Rewrite the reference images (tests/golden/) that differ or are missing
# and name them: the one way to update them (tests/support/golden.c).
.PHONY: golden
golden: $(BUILD)/tests/test_golden $(BUILD)/tests/test_raster $(BUILD)/tests/test_scene
	SILK_GOLDEN_UPDATE=1 $(BUILD)/tests/test_golden
	SILK_GOLDEN_UPDATE=1 $(BUILD)/tests/test_raster
	SILK_GOLDEN_UPDATE=1 $(BUILD)/tests/test_scene

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

# Normal build, then the core's tests in every board's configuration, then
# the whole suite under AddressSanitizer + UBSan.
# The builds `make test` makes run two jobs at a time (one per core, at
# most two) unless make was given -j itself.
NPROC2 := $(shell n=$$(nproc 2>/dev/null || echo 1); [ "$$n" -gt 2 ] && n=2; echo $$n)
BUILD_JOBS = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(NPROC2))
test: check-nofloat
	$(MAKE) $(BUILD_JOBS) tests
	SILK=$(BUILD)/silk sh tests/run.sh $(BUILD)
	$(MAKE) $(BUILD_JOBS) test-configs
	$(MAKE) $(BUILD_JOBS) SAN=1 tests
	SILK=build-san/silk SILK_SAN=1 sh tests/run.sh build-san

# The core's unit tests built with each board's boards/NAME/config.h (in
# build-config/NAME) and run on the host, so every branch a board's options
# choose runs here, QEMU or not.  A board whose options come to the same
# (silk/config.h's macros once derived) as the host's or as a board's tested
# before is not built again; the tests of the host tools and the host I/O
# (tests/prep, tests/platform) run in the host's configuration only, and a test of what
# a configuration leaves out says it is skipped (tests/check.h).
CONFIG_TESTS := $(basename $(notdir $(wildcard tests/core/test_*.c))) test_cxx
CONFIG_BOARDS := $(filter-out host,$(notdir $(wildcard boards/*)))
config_macros = printf '\043include "silk/config.h"\n' | $(CC) -Iinclude "-DSILK_CONFIG_FILE=\"$(CURDIR)/$(1)\"" -dM -E -x c - | \
                grep ' SILK_' | grep -v ' SILK_CONFIG_FILE ' | sort | cksum | cut -d' ' -f1
.PHONY: test-configs
test-configs: $(BUILD)/silk
	@seen=$$($(call config_macros,boards/host/config.h)); \
	for b in $(CONFIG_BOARDS); do \
	  sum=$$($(call config_macros,boards/$$b/config.h)) || exit 1; \
	  case " $$seen " in *" $$sum "*) echo "test-configs: $$b: the core's options as a configuration already tested"; continue;; esac; \
	  seen="$$seen $$sum"; \
	  echo "test-configs: $$b (boards/$$b/config.h)"; \
	  $(MAKE) --no-print-directory BUILD=build-config/$$b CORE_CONFIG=boards/$$b/config.h SAN= \
	      $(addprefix build-config/$$b/tests/,$(CONFIG_TESTS)) || exit 1; \
	  SILK=$(BUILD)/silk sh tests/run.sh build-config/$$b $(addprefix build-config/$$b/tests/,$(CONFIG_TESTS)) || exit 1; \
	done

# Just the normal build's suite.
test-fast: check-nofloat tests
	SILK=$(BUILD)/silk sh tests/run.sh $(BUILD)

# Per-frame visibility, brute pass against the hierarchy: out/bench_visibility.txt
# (CALLGRIND=1 adds instruction counts).  Then the render modes side by side
# (bench/modes.sh, docs/measurements.md): out/bench.md, bench.csv, bench.png.
# Then error against bytes per representation (bench/bytes.sh):
# out/bytes-MODEL.png, out/bench-bytes.md.  Then what the compact packed
# model costs and changes (bench/compact.sh): out/compact.md, compact.csv.
# Then the robustness grid of smooth outlines over every shared mesh and
# prepared model (bench/grid.sh): out/grid.md, grid.csv.
bench: $(BUILD)/silk
	sh bench/visibility.sh $(BUILD)/silk out
	sh bench/modes.sh $(BUILD)/silk out
	sh bench/bytes.sh $(BUILD)/silk out
	sh bench/compact.sh $(BUILD)/silk out
	sh bench/grid.sh $(BUILD)/silk out
	if [ -d ../shared/peers ]; then $(MAKE) bench-peers; fi

# silk against small3dlib and PortableGL, frames interleaved in one process
# (bench/peers.sh, ../shared/peers): out/bench-peers.md.
bench-peers: $(BUILD)/libsilk.a
	sh bench/peers.sh out

demo: $(BUILD)/silk
	sh tools/scripts/demo.sh $(BUILD)/silk out

# The core (silk.pc) and the host I/O around it (silk-platform.pc: the PNG
# and PPM writers and readers of silk/platform.h), the command, its manual
# page, and the README and docs/ with the licence in share/doc/silk.
# `make uninstall` removes exactly these (and the directories left empty).
VERSION  := 0.1.0
INSTALL_DIRS := lib lib/pkgconfig include/silk bin share/man/man1 share/doc/silk share/doc/silk/docs \
                share/doc/silk/docs/img
INSTALL_FILES := lib/libsilk.a lib/libsilk_platform.a lib/pkgconfig/silk.pc lib/pkgconfig/silk-platform.pc \
                 $(wildcard include/silk/*.h) bin/silk share/man/man1/silk.1 \
                 share/doc/silk/LICENSE share/doc/silk/README.md $(addprefix share/doc/silk/,$(wildcard docs/*.md) \
                 $(wildcard docs/img/*.png))
install: $(BUILD)/libsilk.a $(BUILD)/libsilk_platform.a $(BUILD)/silk $(BUILD)/silk.1
	install -d $(INSTALL_DIRS:%=$(DESTDIR)$(PREFIX)/%)
	install -m 644 $(BUILD)/libsilk.a $(BUILD)/libsilk_platform.a $(DESTDIR)$(PREFIX)/lib/
	install -m 644 include/silk/*.h $(DESTDIR)$(PREFIX)/include/silk/
	install -m 755 $(BUILD)/silk $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(BUILD)/silk.1 $(DESTDIR)$(PREFIX)/share/man/man1/
	install -m 644 LICENSE README.md $(DESTDIR)$(PREFIX)/share/doc/silk/
	install -m 644 docs/*.md $(DESTDIR)$(PREFIX)/share/doc/silk/docs/
	install -m 644 docs/img/*.png $(DESTDIR)$(PREFIX)/share/doc/silk/docs/img/
	for pc in silk silk-platform; do \
	  sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@PNG_LIBS@|$(PNG_LIBS)|g' \
	    $$pc.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/$$pc.pc || exit 1; \
	done

.PHONY: uninstall
uninstall:
	rm -f $(INSTALL_FILES:%=$(DESTDIR)$(PREFIX)/%)
	for d in share/doc/silk/docs/img share/doc/silk/docs share/doc/silk include/silk; do \
	  rmdir $(DESTDIR)$(PREFIX)/$$d 2>/dev/null || true; \
	done

# The library managers' packages (docs/porting.md): PlatformIO builds the
# tree as it is (library.json); an Arduino library needs its own layout,
# made here in ARDUINO_OUT/silk: library.properties, the core, its headers
# and the panel sink under src/ (the one folder Arduino puts on the include
# path), and the example sketch with its model.
ARDUINO_OUT ?= $(BUILD)/arduino
# The project's home page, which the library managers list.
SILK_URL ?= https://silk.invalid
.PHONY: arduino example-model
arduino:
	rm -rf $(ARDUINO_OUT)/silk
	mkdir -p $(ARDUINO_OUT)/silk/src/silk $(ARDUINO_OUT)/silk/src/core $(ARDUINO_OUT)/silk/examples/silk_panel
	sed -e 's|@VERSION@|$(VERSION)|' -e 's|@URL@|$(SILK_URL)|' platform/arduino/library.properties \
	    >$(ARDUINO_OUT)/silk/library.properties
	cp LICENSE $(ARDUINO_OUT)/silk/
	cp include/silk/*.h $(ARDUINO_OUT)/silk/src/silk/
	cp src/*.c src/*.h $(ARDUINO_OUT)/silk/src/core/
	cp include/silk.h platform/panel/silk_panel.c platform/panel/silk_panel.h $(ARDUINO_OUT)/silk/src/
	cp examples/silk_panel/silk_panel.ino examples/silk_panel/model.h $(ARDUINO_OUT)/silk/examples/silk_panel/
	@echo "silk: the Arduino library is in $(ARDUINO_OUT)/silk (copy it into your sketchbook's libraries folder)"

# The example sketch's model: a torus made and packed by this silk (the
# test checks that the committed header is what this writes).
example-model: $(BUILD)/silk
	mkdir -p $(BUILD)/example-model
	cd $(BUILD)/example-model && ../silk gen torus --segments 16 --bands 8 -o torus.obj && \
	  ../silk pack torus.obj -o model.h --name model --size 320x240 --format rgb565 --views 12 --visibility brute
	cp $(BUILD)/example-model/model.h examples/silk_panel/model.h

clean:
	rm -rf build build-san build-fuzz build-config out

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/*/*/*.d $(BUILD)/obj/*/*/*/*.d)

# ---- fuzzing (docs/overflow.md, fuzz/run.sh) --------------------------------
# `make fuzz FUZZ_SECONDS=N` builds every fuzz/fuzz_*.c harness with clang's
# libFuzzer, ASan and UBSan (the core instrumented for coverage) and runs
# each for N seconds from the seeds of fuzz/seeds.sh; a finding fails it.
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_BUILD   := build-fuzz
FUZZ_CFLAGS  := -std=c11 $(WARN) -O1 -g -Iinclude -fsanitize=address,undefined \
                -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_SRC     := $(wildcard fuzz/fuzz_*.c)
FUZZ_BIN     := $(FUZZ_SRC:fuzz/%.c=$(FUZZ_BUILD)/%)
FUZZ_CORE_OBJ := $(CORE_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
.SECONDARY: $(FUZZ_CORE_OBJ)

$(FUZZ_BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

$(FUZZ_BUILD)/fuzz_%: fuzz/fuzz_%.c fuzz/fuzz.h $(FUZZ_CORE_OBJ)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_CORE_OBJ)

$(FUZZ_BUILD)/mkseed: fuzz/mkseed.c
	@mkdir -p $(dir $@)
	$(CC) -std=c11 $(WARN) -O2 -o $@ $<

fuzz-build: $(FUZZ_BIN) $(FUZZ_BUILD)/mkseed

fuzz: fuzz-build $(BUILD)/silk
	sh fuzz/seeds.sh $(BUILD)/silk $(FUZZ_BUILD)/mkseed $(FUZZ_BUILD)/seeds
	sh fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The regression test runs the harnesses' code on tests/regress/.
$(BUILD)/tests/test_regress: $(FUZZ_SRC) fuzz/fuzz.h

-include $(wildcard $(FUZZ_BUILD)/obj/*/*.d)

# ---- small devices (docs/small-devices.md) ----------------------------------
# A device board's own rules (the firmware of boards/mps2-an385 and
# boards/microbit).
ifdef BOARD_RULES
include $(BOARD_RULES)
else
# From the host: the firmware targets run in the device board's build.
FW_BOARD ?= mps2-an385
.PHONY: firmware firmware-host firmware-256k run
firmware firmware-host firmware-256k run:
	$(MAKE) BOARD=$(FW_BOARD) BUILD=build-$(FW_BOARD) SAN= CFLAGS= $@

# The soak run alone (tests/boards/cli_soak.sh; make test runs it too):
# SOAK_FRAMES frames on the host build of the Cortex-M3 firmware and
# SOAK_QEMU_FRAMES under QEMU, along a random camera path.
SOAK_FRAMES ?= 1000
SOAK_QEMU_FRAMES ?= 100
.PHONY: soak
soak: $(BUILD)/silk
	$(MAKE) BOARD=$(FW_BOARD) BUILD=build-$(FW_BOARD) SAN= CFLAGS= soak-firmware
	SILK_SOAK_FRAMES=$(SOAK_FRAMES) SILK_SOAK_QEMU_FRAMES=$(SOAK_QEMU_FRAMES) sh tests/boards/cli_soak.sh $(BUILD)
endif

# `make clean` leaves the boards' build directories; this removes them.
.PHONY: clean-boards
clean-boards:
	rm -rf build-mps2-an385 build-mps2-an385-full build-mps2-an386 build-mps2-an500 build-microbit build-linux-fb

# The ARM toolchain and QEMU for the firmware (Debian, Ubuntu).
DEPS_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
.PHONY: deps profile
SUDO := $(if $(filter 0,$(shell id -u)),,sudo)
deps:
	$(SUDO) apt-get update
	$(SUDO) apt-get install -y --no-install-recommends $(DEPS_PACKAGES)

# Where every byte goes on a board: `make profile [PROFILE_BOARD=..]
# [PROFILE_MESH=..] [PROFILE_ARGS=--check]`, the table also as
# BUILD/profile-MESH.csv.  Another board's profile runs in that board's
# build; a firmware board's firmware is built for the mesh and run by
# tools/scripts/profile_fw.sh with this board.mk's settings; any other board is
# measured in-process by its own `silk profile`.
PROFILE_BOARD ?= $(if $(BOARD_RULES),$(BOARD),mps2-an385)
PROFILE_MESH  ?= $(MESHES_DIR)/bunny-500.obj
PROFILE_CSV   ?= $(BUILD)/profile-$(basename $(notdir $(PROFILE_MESH))).csv
PROFILE_ARGS  ?=
ifneq ($(PROFILE_BOARD),$(BOARD))
profile:
	$(MAKE) BOARD=$(PROFILE_BOARD) BUILD=build-$(PROFILE_BOARD) SAN= CFLAGS= PROFILE_MESH='$(PROFILE_MESH)' profile
else ifdef BOARD_RULES
profile:
	$(MAKE) -s BOARD_MESHES='$(PROFILE_MESH)' firmware
	BOARD='$(BOARD)' FW_DIR='$(FW_OUT)' BOARD_RUN='$(BOARD_RUN)' BOARD_CROSS='$(BOARD_CROSS)' \
	  BOARD_FLASH_BYTES='$(BOARD_FLASH_BYTES)' BOARD_WIDTH='$(BOARD_WIDTH)' BOARD_HEIGHT='$(BOARD_HEIGHT)' \
	  BOARD_BAND_ROWS='$(BOARD_BAND_ROWS)' BOARD_CLOCK_HZ='$(BOARD_CLOCK_HZ)' BOARD_CPI='$(BOARD_CPI)' \
	  BOARD_INSTR_PER_TICK='$(BOARD_INSTR_PER_TICK)' BOARD_CODE_BYTES='$(BOARD_CODE_BYTES)' \
	  PROFILE_CSV='$(PROFILE_CSV)' sh tools/scripts/profile_fw.sh '$(PROFILE_MESH)' $(PROFILE_ARGS)
else
profile: $(BUILD)/silk
	$(BUILD)/silk profile '$(PROFILE_MESH)' --csv '$(PROFILE_CSV)' $(PROFILE_ARGS)
endif

# `make test` runs the firmware under QEMU (tests/boards/cli_qemu.sh) when the ARM
# toolchain is installed; in CI it must be.
HAVE_ARM := $(shell command -v arm-none-eabi-gcc >/dev/null 2>&1 && command -v qemu-system-arm >/dev/null 2>&1 && echo 1)
ifeq ($(BOARD)$(HAVE_ARM),host1)
ifneq ($(SAN),1)
tests: firmware-for-tests
.PHONY: firmware-for-tests
# The Cortex-M3, M4 and M7 boards' models are shared meshes: without them
# tests/boards/cli_qemu.sh skips those boards.  The Cortex-M0 board always
# has its `silk gen` model.
firmware-for-tests:
	@if [ -d '$(MESHES_DIR)' ]; then \
	  $(MAKE) BOARD=$(FW_BOARD) BUILD=build-$(FW_BOARD) SAN= CFLAGS= firmware firmware-host firmware-256k soak-firmware && \
	  $(MAKE) BOARD=$(FW_BOARD)-full BUILD=build-$(FW_BOARD)-full SAN= CFLAGS= firmware firmware-host scene-firmware && \
	  $(MAKE) BOARD=mps2-an386 BUILD=build-mps2-an386 SAN= CFLAGS= firmware firmware-host && \
	  $(MAKE) BOARD=mps2-an500 BUILD=build-mps2-an500 SAN= CFLAGS= firmware firmware-host; \
	else echo "silk: $(MESHES_DIR) is missing: no $(FW_BOARD), mps2-an386 or mps2-an500 firmware for the tests" \
	  "(their models are shared meshes)"; fi
	$(MAKE) BOARD=microbit BUILD=build-microbit SAN= CFLAGS= firmware firmware-host firmware-256k
endif
endif

