/*
 * boards/microbit/config.h - the core's build options for the nRF51822, a
 * Cortex-M0 with 256 KiB of flash and 16 KiB of RAM
 * (include/silk/config.h says what each does and costs): flat and smooth
 * frames only, as on boards/mps2-an385, in a core of at most 48 KiB of
 * Thumb-1 code.
 */
#define SILK_REFERENCE_MODES 0
#define SILK_LINES 0
#define SILK_CLIP_MODE 0
#define SILK_SILTEX_MODE 0
#define SILK_AA 0
#define SILK_TEXTURES 0
#define SILK_PLAN_INDEX16 1
#define SILK_INLINE_ACCESS 0     /* the accessors as calls: less code and shallower frames (the model is a compact one) */
#define SILK_SHORTCUTS 0
#define SILK_CPU32 1
