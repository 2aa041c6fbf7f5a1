# platform/mps2/firmware.mk - building the Cortex-M firmware (boards
# mps2-an385 and microbit), included by the Makefile when
# boards/$(BOARD)/board.mk sets BOARD_RULES to this file.
#
#   make BOARD=mps2-an385              the core for the board's CPU, then one
#                                      firmware per model in BOARD_MESHES:
#                                      $(BUILD)/fw/NAME/fw.elf (+ .map)
#   make BOARD=mps2-an385 run          run each under QEMU; frames and the
#                                      report go to $(BUILD)/fw/NAME/
#   BOARD_MESHES="a.obj b.obj"         other models (`silk gen` meshes too)
#   make BOARD=mps2-an385 firmware-256k
#                                      the same linked for a 256 KiB part
#                                      (STM32F429-class) in
#                                      $(BUILD)/fw/ram256k/NAME: the smooth
#                                      frames the 64 KiB budget cannot hold
#                                      yet, for the bit-exactness test;
#                                      a board whose machine has less RAM
#                                      names another machine for it
#                                      (BOARD_BIG_MACHINE, its timer
#                                      BOARD_BIG_TIMER)
#   make BOARD=microbit profile-256k   `make profile` of that build: the
#                                      smooth frames and the RAM they need
#
# Each output directory records the QEMU machine its firmware runs on
# ($(FW_OUT)/machine) and the instructions a tick of its timer is under
# -icount shift=0 ($(FW_OUT)/instr_per_tick), for the tests.
#
# The model is packed at build time by the host-side tool ($(BUILD)/silk,
# built with the host compiler from the same sources) into
# $(BUILD)/fw/NAME/fwmodel.h; never copied into the source tree.  For the
# bit-exactness test the same scene is also built for the host,
# $(BUILD)/fw/NAME/fw-host, with the same arena.

FW_CC    := $(BOARD_CROSS)gcc
FW_AR    := $(BOARD_CROSS)ar
FW_DIR   := $(BUILD)/fw
# Per-model outputs; a variant (FW_VARIANT=ram256k) gets its own directory.
FW_VARIANT ?=
FW_OUT   := $(FW_DIR)$(if $(FW_VARIANT),/$(FW_VARIANT))
# The board's build options (BOARD_CONFIG, include/silk/config.h), for the
# firmware and for its host build alike.
FW_CONFIG := $(call config_flag,$(BOARD_CONFIG))
FW_CFLAGS := -std=c11 $(WARN) $(BOARD_OPT) $(FW_CONFIG) -g $(BOARD_ARCH) -ffunction-sections -fdata-sections -Iinclude
FW_HOST_CFLAGS = $(CFLAGS_BASE) $(FW_CONFIG) $(SANFLAGS) $(CFLAGS)
FW_DEFS  := -DFW_BOARD='"$(BOARD)"' -DFW_BAND_ROWS=$(BOARD_BAND_ROWS) -DFW_ARENA_BYTES=$(BOARD_ARENA_BYTES) \
            -DFW_FORMAT=$(BOARD_FORMAT) $(BOARD_FW_DEFS)
FW_LDFLAGS := $(BOARD_ARCH) -nostartfiles -specs=nano.specs -specs=nosys.specs -Wl,--gc-sections \
              -T platform/mps2/mps2.ld -Wl,--defsym=__flash_size=$(BOARD_FLASH_BYTES) \
              -Wl,--defsym=__ram_size=$(BOARD_RAM_BYTES) -Wl,--defsym=__stack_size=$(BOARD_STACK_BYTES)
FW_PACK_ARGS := --size $(BOARD_WIDTH)x$(BOARD_HEIGHT) \
                --format $(if $(filter SILK_PIX_RGB565,$(BOARD_FORMAT)),rgb565,rgb888) --views $(BOARD_VIEWS) \
                $(BOARD_PACK_ARGS)

FW_CORE_OBJ := $(CORE_SRC:%.c=$(FW_DIR)/obj/%.o)
# The tick counter (fw_ticks) of the board's machine.
BOARD_TIMER ?= platform/mps2/timer_cmsdk.c
BOARD_INSTR_PER_TICK ?= 40
BOARD_MACHINE ?= mps2-an385
FW_PLAT_OBJ := $(FW_DIR)/obj/platform/mps2/startup.o $(FW_DIR)/obj/platform/mps2/semihost.o \
               $(BOARD_TIMER:%.c=$(FW_DIR)/obj/%.o)
FW_NAMES    := $(basename $(notdir $(BOARD_MESHES)))
FW_ELF      := $(FW_NAMES:%=$(FW_OUT)/%/fw.elf)
FW_HOST     := $(FW_NAMES:%=$(FW_OUT)/%/fw-host)

.PHONY: firmware firmware-host firmware-256k run FORCE
firmware: $(FW_ELF) $(FW_OUT)/machine $(FW_OUT)/instr_per_tick
firmware-host: $(FW_HOST)
FW_256K := FW_VARIANT=ram256k BOARD_RAM_BYTES=262144 BOARD_ARENA_BYTES=255488 \
           $(if $(BOARD_BIG_MACHINE),BOARD_MACHINE=$(BOARD_BIG_MACHINE) BOARD_TIMER=$(BOARD_BIG_TIMER) \
           BOARD_INSTR_PER_TICK=$(BOARD_BIG_INSTR_PER_TICK))
firmware-256k: $(FW_DIR)/libsilk.a $(FW_PLAT_OBJ) $(BUILD)/silk
	$(MAKE) $(FW_256K) firmware

.PHONY: profile-256k
profile-256k: $(FW_DIR)/libsilk.a $(FW_PLAT_OBJ) $(BUILD)/silk
	$(MAKE) $(FW_256K) profile

$(FW_OUT)/machine $(FW_OUT)/instr_per_tick: FORCE
	@mkdir -p $(dir $@)
	@v='$(if $(filter %/machine,$@),$(BOARD_MACHINE),$(BOARD_INSTR_PER_TICK))'; \
	  echo "$$v" | cmp -s - $@ || echo "$$v" > $@

# Meshes made by `silk gen` for BOARD_MESHES: $(BUILD)/gen/SHAPE.obj.
$(BUILD)/gen/%.obj: $(BUILD)/silk
	@mkdir -p $(dir $@)
	$(BUILD)/silk gen $* -o $@

$(FW_DIR)/obj/%.o: %.c boards/$(BOARD)/board.mk
	@mkdir -p $(dir $@)
	$(FW_CC) $(FW_CFLAGS) -MMD -MP -c $< -o $@

$(FW_DIR)/libsilk.a: $(FW_CORE_OBJ)
	rm -f $@ && $(FW_AR) rcs $@ $^

# The core for the host with the board's options: what fw-host links, so
# that its plan records and arena are the firmware's.
FW_HOST_OBJ := $(CORE_SRC:%.c=$(FW_DIR)/host-obj/%.o)
FW_HOST_LIB := $(FW_DIR)/host-obj/libsilk.a
$(FW_DIR)/host-obj/%.o: %.c boards/$(BOARD)/board.mk
	@mkdir -p $(dir $@)
	$(CC) $(FW_HOST_CFLAGS) -MMD -MP -c $< -o $@

$(FW_HOST_LIB): $(FW_HOST_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

# The pack options are remembered, so that changing them repacks; a model
# may add its own (FW_PACK_EXTRA_NAME).
$(FW_OUT)/%/pack.args: FORCE
	@mkdir -p $(dir $@)
	@echo '$(FW_PACK_ARGS) $(FW_PACK_EXTRA_$*)' | cmp -s - $@ || echo '$(FW_PACK_ARGS) $(FW_PACK_EXTRA_$*)' > $@

# A generated model: a globe with texture coordinates (`silk gen --uv`),
# packed with silk's own checker texture in flash.
$(BUILD)/models/globe.obj: $(BUILD)/silk
	@mkdir -p $(dir $@)
	$(BUILD)/silk gen sphere --uv --segments 16 --bands 12 -o $@
FW_PACK_EXTRA_globe := --texture checker:64 --texture-format rgb565

# The sizes are compiled and linked in: remembered like the pack options.
FW_SIZES := $(BOARD_FLASH_BYTES) $(BOARD_RAM_BYTES) $(BOARD_STACK_BYTES) $(BOARD_ARENA_BYTES) \
            $(BOARD_BAND_ROWS) $(BOARD_FORMAT) $(BOARD_TIMER) $(BOARD_FW_DEFS)
$(FW_OUT)/defs.args: FORCE
	@mkdir -p $(dir $@)
	@echo '$(FW_SIZES)' | cmp -s - $@ || echo '$(FW_SIZES)' > $@

# One firmware per model: $(1) the name, $(2) the mesh file.
define fw_model
$(FW_OUT)/$(1)/fwmodel.h: $(2) $(BUILD)/silk $(FW_OUT)/$(1)/pack.args
	$(BUILD)/silk pack $(2) -o $$@ --name fwmodel $(FW_PACK_ARGS) $(FW_PACK_EXTRA_$(1))

$(FW_OUT)/$(1)/fw_main.o: platform/mps2/fw_main.c platform/mps2/fw_io.h platform/mps2/fw_say.h $(FW_OUT)/$(1)/fwmodel.h $(FW_OUT)/defs.args
	$(FW_CC) $(FW_CFLAGS) $(FW_DEFS) -DFW_MODEL_NAME='"$(1)"' -Iplatform/mps2 -I$(FW_OUT)/$(1) -c $$< -o $$@

$(FW_OUT)/$(1)/fw.elf: $(FW_OUT)/$(1)/fw_main.o $(FW_PLAT_OBJ) $(FW_DIR)/libsilk.a platform/mps2/mps2.ld \
                      $(FW_OUT)/defs.args
	$(FW_CC) $(FW_LDFLAGS) -Wl,-Map=$(FW_OUT)/$(1)/fw.map -o $$@ $(FW_OUT)/$(1)/fw_main.o $(FW_PLAT_OBJ) \
	    $(FW_DIR)/libsilk.a

$(FW_OUT)/$(1)/fw-host: platform/mps2/fw_main.c platform/mps2/fw_io_host.c platform/mps2/fw_io.h platform/mps2/fw_say.h \
                        $(FW_OUT)/$(1)/fwmodel.h $(FW_OUT)/defs.args $(FW_HOST_LIB)
	$(CC) $(FW_HOST_CFLAGS) $(FW_DEFS) -DFW_REPORT_BUDGET -DFW_MODEL_NAME='"$(1)"' -Iplatform/mps2 -I$(FW_OUT)/$(1) \
	    -o $$@ platform/mps2/fw_main.c platform/mps2/fw_io_host.c $(FW_HOST_LIB)

run-$(1): $(FW_OUT)/$(1)/fw.elf
	timeout 120 $(BOARD_RUN) $(FW_OUT)/$(1)/fw.elf -append $(FW_OUT)/$(1)/frame 2>&1 | tee $(FW_OUT)/$(1)/report.txt
endef
$(foreach m,$(BOARD_MESHES),$(eval $(call fw_model,$(basename $(notdir $(m))),$(m))))

run: $(FW_NAMES:%=run-%)

# The soak run (platform/mps2/fw_soak.c, tests/boards/cli_soak.sh): the first
# model's scene along a random camera path, for the board and for the host.
FW_SOAK_MODEL := $(firstword $(FW_NAMES))
FW_SOAK := $(FW_OUT)/soak
.PHONY: soak-firmware
soak-firmware: $(if $(FW_SOAK_MODEL),$(FW_SOAK)/soak.elf $(FW_SOAK)/soak-host $(FW_OUT)/machine)
$(FW_SOAK)/fw_soak.o: platform/mps2/fw_soak.c platform/mps2/fw_io.h platform/mps2/fw_say.h $(FW_OUT)/$(FW_SOAK_MODEL)/fwmodel.h \
                      $(FW_OUT)/defs.args
	@mkdir -p $(dir $@)
	$(FW_CC) $(FW_CFLAGS) $(FW_DEFS) -Iplatform/mps2 -I$(FW_OUT)/$(FW_SOAK_MODEL) -c $< -o $@
$(FW_SOAK)/soak.elf: $(FW_SOAK)/fw_soak.o $(FW_PLAT_OBJ) $(FW_DIR)/libsilk.a platform/mps2/mps2.ld $(FW_OUT)/defs.args
	$(FW_CC) $(FW_LDFLAGS) -o $@ $(FW_SOAK)/fw_soak.o $(FW_PLAT_OBJ) $(FW_DIR)/libsilk.a
$(FW_SOAK)/soak-host: platform/mps2/fw_soak.c platform/mps2/fw_io_host.c platform/mps2/fw_io.h platform/mps2/fw_say.h \
                      $(FW_OUT)/$(FW_SOAK_MODEL)/fwmodel.h $(FW_OUT)/defs.args $(FW_HOST_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(FW_HOST_CFLAGS) $(FW_DEFS) -Iplatform/mps2 -I$(FW_OUT)/$(FW_SOAK_MODEL) \
	    -o $@ platform/mps2/fw_soak.c platform/mps2/fw_io_host.c $(FW_HOST_LIB)

# The scene frame (fw_main.c built with -DFW_SCENE, tests/boards/cli_scene_fw.sh):
# the first model and a copy of it in one frame of silk_render_scene_bands,
# for the board and for the host, on a core of the board's options with
# SILK_SCENES 1 (the boards leave it out: beyond their code budget, which
# `make profile` keeps checking on the firmware without it).  Linked for
# the board's RAM, with its own map.
FW_SCENE := $(FW_OUT)/scene
FW_SCENE_OBJ := $(CORE_SRC:%.c=$(FW_SCENE)/obj/%.o)
FW_SCENE_HOST_OBJ := $(CORE_SRC:%.c=$(FW_SCENE)/host-obj/%.o)
.PHONY: scene-firmware
scene-firmware: $(if $(FW_SOAK_MODEL),$(FW_SCENE)/fw.elf $(FW_SCENE)/fw-host $(FW_OUT)/machine)
$(FW_SCENE)/obj/%.o: %.c boards/$(BOARD)/board.mk
	@mkdir -p $(dir $@)
	$(FW_CC) $(FW_CFLAGS) -DSILK_SCENES=1 -MMD -MP -c $< -o $@
$(FW_SCENE)/host-obj/%.o: %.c boards/$(BOARD)/board.mk
	@mkdir -p $(dir $@)
	$(CC) $(FW_HOST_CFLAGS) -DSILK_SCENES=1 -MMD -MP -c $< -o $@
$(FW_SCENE)/libsilk.a: $(FW_SCENE_OBJ)
	rm -f $@ && $(FW_AR) rcs $@ $^
$(FW_SCENE)/host-libsilk.a: $(FW_SCENE_HOST_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(FW_SCENE)/fw_main.o: platform/mps2/fw_main.c platform/mps2/fw_io.h platform/mps2/fw_say.h \
                       $(FW_OUT)/$(FW_SOAK_MODEL)/fwmodel.h $(FW_OUT)/defs.args
	@mkdir -p $(dir $@)
	$(FW_CC) $(FW_CFLAGS) -DSILK_SCENES=1 $(FW_DEFS) -DFW_SCENE -DFW_MODEL_NAME='"$(FW_SOAK_MODEL)"' -Iplatform/mps2 \
	    -I$(FW_OUT)/$(FW_SOAK_MODEL) -c $< -o $@
$(FW_SCENE)/fw.elf: $(FW_SCENE)/fw_main.o $(FW_PLAT_OBJ) $(FW_SCENE)/libsilk.a platform/mps2/mps2.ld $(FW_OUT)/defs.args
	$(FW_CC) $(FW_LDFLAGS) -Wl,-Map=$(FW_SCENE)/fw.map -o $@ $(FW_SCENE)/fw_main.o $(FW_PLAT_OBJ) $(FW_SCENE)/libsilk.a
$(FW_SCENE)/fw-host: platform/mps2/fw_main.c platform/mps2/fw_io_host.c platform/mps2/fw_io.h platform/mps2/fw_say.h \
                     $(FW_OUT)/$(FW_SOAK_MODEL)/fwmodel.h $(FW_OUT)/defs.args $(FW_SCENE)/host-libsilk.a
	@mkdir -p $(dir $@)
	$(CC) $(FW_HOST_CFLAGS) -DSILK_SCENES=1 $(FW_DEFS) -DFW_SCENE -DFW_MODEL_NAME='"$(FW_SOAK_MODEL)"' -Iplatform/mps2 \
	    -I$(FW_OUT)/$(FW_SOAK_MODEL) -o $@ platform/mps2/fw_main.c platform/mps2/fw_io_host.c $(FW_SCENE)/host-libsilk.a

-include $(wildcard $(FW_DIR)/obj/*/*.d $(FW_DIR)/obj/*/*/*.d $(FW_DIR)/host-obj/*/*.d $(FW_DIR)/scene/*obj/*/*.d)
