/*
 * boards/mps2-an385-full/config.h - the core's build options for the
 * Cortex-M3 of boards/mps2-an385 as a part with 64 KiB of RAM
 * (include/silk/config.h says what each does and costs): flat and smooth
 * frames with anti-aliased outlines and textures, in a core of at most
 * 48 KiB of code.
 */
#define SILK_REFERENCE_MODES 0   /* as on boards/mps2-an385 */
#define SILK_LINES 0
#define SILK_CLIP_MODE 0
#define SILK_SILTEX_MODE 0
#define SILK_AA_CREASES 0        /* anti-aliased creases (about 1 KiB) do not fit the code budget: outlines only */
#define SILK_PLAN_INDEX16 1
#define SILK_INLINE_ACCESS 0     /* the accessors as calls: less code and shallower frames (the model is a compact one) */
#define SILK_SHORTCUTS 0
#define SILK_CPU32 1
#ifndef SILK_SCENES             /* the scene firmware (cli_scene_fw.sh) builds its core with -DSILK_SCENES=1 */
#define SILK_SCENES 0            /* several objects a frame: 4 KiB beyond the code budget */
#endif
