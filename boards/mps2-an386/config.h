/*
 * boards/mps2-an386/config.h - the core's build options for a Cortex-M4F
 * of the STM32F4 class with 1 MiB of flash and 128 KiB of RAM
 * (include/silk/config.h says what each does and costs): flat and smooth
 * frames, as on boards/mps2-an385; the RAM goes to larger models instead
 * of anti-aliasing a coarse one's outline.
 */
#define SILK_REFERENCE_MODES 0   /* as on boards/mps2-an385 */
#define SILK_LINES 0
#define SILK_CLIP_MODE 0
#define SILK_SILTEX_MODE 0
#define SILK_AA 0
#define SILK_TEXTURES 0
#define SILK_PLAN_INDEX16 1      /* a 5 000-triangle model's plan in half the RAM */
#define SILK_INLINE_ACCESS 0     /* the accessors as calls: less code and shallower frames (the model is a compact one) */
#define SILK_SHORTCUTS 0
#define SILK_CPU32 1
