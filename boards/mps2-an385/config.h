/*
 * boards/mps2-an385/config.h - the core's build options for a Cortex-M3
 * with 512 KiB of flash and 32 KiB of RAM (include/silk/config.h says what
 * each does and costs): flat and smooth frames in a core of at most 40 KiB
 * of code.  The firmware and its host build (fw-host) are both built with
 * it, so their arenas and pixels match byte for byte, and so are the
 * core's unit tests run for this board on the host.
 */
#define SILK_REFERENCE_MODES 0   /* PN and BLEND stay in the host library, where they are measured against */
#define SILK_LINES 0             /* pen-and-ink lines and --wire: the firmware draws neither */
#define SILK_CLIP_MODE 0         /* 11 KiB of code, and its per-frame outline does not fit the RAM yet */
#define SILK_SILTEX_MODE 0       /* its textures are far larger than the flash */
#define SILK_AA 0                /* 3 KiB of code and about 12 KiB of scratch a band: boards/mps2-an385-full has it */
#define SILK_TEXTURES 0          /* boards/mps2-an385-full has them */
#define SILK_PLAN_INDEX16 1      /* the plan in half the RAM: a frame of a model this part holds fits */
#define SILK_INLINE_ACCESS 0     /* the accessors as calls: less code and shallower frames (the model is a compact one) */
#define SILK_SHORTCUTS 0         /* the code budget; the firmware gives the arena-taking ones no room anyway */
#define SILK_CPU32 1             /* a 32-bit part: its unit tests on the host take its routes */
#ifndef SILK_SCENES             /* the scene firmware (cli_scene_fw.sh) builds its core with -DSILK_SCENES=1 */
#define SILK_SCENES 0            /* several objects a frame: 4 KiB beyond the code budget */
#endif
