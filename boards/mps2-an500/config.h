/*
 * boards/mps2-an500/config.h - the core's build options for a Cortex-M7 of
 * the Teensy 4 / STM32F7 class with 2 MiB of flash and 512 KiB of RAM
 * (include/silk/config.h says what each does and costs): flat and smooth
 * frames with anti-aliased outlines (creases left hard, as on
 * boards/mps2-an385-full), textures, and the shortcuts that spend RAM on
 * instructions (the vertex cache among them).
 */
#define SILK_REFERENCE_MODES 0   /* as on boards/mps2-an385 */
#define SILK_LINES 0
#define SILK_CLIP_MODE 0
#define SILK_SILTEX_MODE 0
#define SILK_AA_CREASES 0
#define SILK_PLAN_INDEX16 1
#define SILK_INLINE_ACCESS 0     /* the accessors as calls: less code and shallower frames (the model is a compact one) */
#define SILK_CPU32 1
