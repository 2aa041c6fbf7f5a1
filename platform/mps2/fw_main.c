/*
 * fw_main.c - the firmware's scene: a model packed into flash by
 * `silk pack --name fwmodel` (no loading, nothing of the mesh in RAM),
 * rendered from every packed camera in FLAT and SMOOTH mode by
 * silk_render_bands() into one band of FW_BAND_ROWS rows.  Each finished
 * band goes to the host as PPM rows, as a display driver would send it over
 * SPI; then the program reports what memory it used.
 *
 * The packed mesh is validated once (silk_mesh_validate) before the first
 * frame.  Everything comes from one static arena (band buffers at the bottom,
 * per-frame scratch from the top), so the RAM a frame takes is the arena's
 * high-water mark plus static data plus the measured stack.
 *
 * fw_scene() is the program: the startup code (startup.c) calls it on the
 * board, fw_io_host.c's main() on the host.
 *
 * Command line: PROGRAM [PREFIX]; with PREFIX, camera C's two frames are
 * written to PREFIX-cC-flat.ppm and PREFIX-cC-smooth.ppm.  Report lines are
 * "fw NAME key=value ..." on the console (docs/small-devices.md).  The last
 * is "fw result=ok" (exit status 0), "fw result=error" (1), or, when frames
 * were drawn unsmoothed because the arena could not hold their plan,
 * "fw result=fell_back frames=N fell_back=N smooth_fell_back=N" (2).
 *
 * Speed: fw_ticks() is read around each silk_render_bands() call and around
 * each band handed to the sink, so "fw time" gives the renderer's own ticks
 * per frame (the frame's minus the sink's: checksum, widening and the
 * writes to the host are the output's cost, not the renderer's).  Under
 * QEMU's -icount these are instructions (tools/scripts/profile_fw.sh converts them;
 * "fw timer" runs a loop of known length to check the rate).  After the
 * memory report, each frame is rendered twice more, unwritten ("fw
 * stages"): once with the renderer's stage clock (render_opts.clock, the
 * ticks of visibility, silhouette plan, emission, vertex stage and
 * rasterizer), once through a HAL whose fragment stage is timed call by
 * call, to take the fragment stage out of the rasterizer's time.  Each
 * timed piece's own overhead (measured on an empty piece) is taken off by
 * profile_fw.sh.
 *
 * Built by the board's firmware rules (platform/mps2/firmware.mk) with
 * -DFW_BOARD, -DFW_BAND_ROWS, -DFW_ARENA_BYTES, -DFW_FORMAT and
 * -I<dir of fwmodel.h>.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "silk/silk.h"
#include "silk/validate.h"
#include "fw_io.h"
#include "fw_say.h"
#include "fwmodel.h"
#include "../../src/stages.h"      /* the core's own timing of a piece, to measure its overhead */

#ifndef FW_MODEL_NAME
#define FW_MODEL_NAME "fwmodel"
#endif
/* Whether the core draws anti-aliased outlines (silk render's --aa) */
#if !SILK_AA
#define FW_AA "off"
#elif !SILK_AA_CREASES
#define FW_AA "outline"
#else
#define FW_AA "on"
#endif
/* The vertex cache may take this much of the arena (silk_render_opts):
 * none by default, so the RAM a frame needs is what `make profile` reports
 * and the budget is the board's; a board with RAM to spare sets it. */
#ifndef FW_VERTEX_CACHE_BYTES
#define FW_VERTEX_CACHE_BYTES 0
#endif

#define CHUNK_PIXELS 32          /* pixels converted per host write */

static uint8_t arena_mem[FW_ARENA_BYTES] __attribute__((aligned(SILK_ARENA_ALIGN)));

/* Where the bands go: a host file (or nowhere) and a checksum. */
typedef struct band_out {
    int handle;                  /* -1: no file */
    int failed;
    uint32_t crc;                /* FNV-1a over the frame's pixels as rendered */
    uint32_t ticks;              /* fw_ticks() spent in send_band */
    uint32_t frame_ticks;        /* ... and in the whole frame (here: no extra stack) */
} band_out;

static void put(band_out *o, const void *p, size_t n)
{
    if (o->handle >= 0 && !o->failed && fw_write(o->handle, p, n) != 0) o->failed = 1;
}

/* RGB565 widened by bit replication, exactly as the host's PPM writer
 * (platform/ppm_sink.c) does, so the files compare byte for byte. */
static void widen(const uint8_t *src, silk_pixfmt fmt, int n, uint8_t *out)
{
    if (fmt == SILK_PIX_RGB888) {
        memcpy(out, src, (size_t)n * 3);
        return;
    }
    for (int x = 0; x < n; x++, src += 2, out += 3) {
        unsigned v = (unsigned)src[0] | (unsigned)src[1] << 8;
        unsigned r = v >> 11, g = (v >> 5) & 63u, b = v & 31u;
        out[0] = (uint8_t)(r << 3 | r >> 2);
        out[1] = (uint8_t)(g << 2 | g >> 4);
        out[2] = (uint8_t)(b << 3 | b >> 2);
    }
}

static int send_band(void *user, const silk_target *t)
{
    band_out *o = user;
    uint32_t t0 = fw_ticks();
    size_t bpp = silk_pixfmt_bytes(t->fmt);
    uint8_t rgb[CHUNK_PIXELS * 3];
    for (int y = 0; y < t->rows; y++) {
        const uint8_t *row = t->color + (size_t)y * t->stride;
        for (size_t i = 0; i < (size_t)t->width * bpp; i++) o->crc = (o->crc ^ row[i]) * 16777619u;
        for (int x = 0; x < t->width; x += CHUNK_PIXELS) {
            int n = t->width - x < CHUNK_PIXELS ? t->width - x : CHUNK_PIXELS;
            widen(row + (size_t)x * bpp, t->fmt, n, rgb);
            put(o, rgb, (size_t)n * 3);
        }
    }
    o->ticks += fw_ticks() - t0;
    return o->failed;
}

/* The HAL with each fragment stage call timed: ticks and calls.  Summed
 * over many calls the tick count is the stage's time (each call's start
 * falls anywhere within a tick), plus a fixed overhead per call.  The
 * vertex stage stays the default one: the renderer culls back faces only
 * behind it (it knows where that stage puts the mesh), so the frame is
 * drawn as the one written, with as many fragments (the stage clock times
 * the vertex stage). */
typedef struct timed_hal {
    silk_hal hal;                /* first: the core calls the stages with &hal */
    const silk_hal *inner;
    uint32_t fticks, fcalls;
} timed_hal;

static uint32_t timed_fragment(const silk_hal *h, const silk_fx *var)
{
    timed_hal *t = (timed_hal *)h;
    uint32_t t0 = fw_ticks();
    uint32_t rgb = t->inner->fragment(t->inner, var);
    t->fticks += fw_ticks() - t0;
    t->fcalls++;
    return rgb;
}

static void timed_hal_init(timed_hal *t, const silk_hal *inner)
{
    memset(t, 0, sizeof *t);
    t->hal = *inner;
    t->hal.fragment = timed_fragment;
    t->inner = inner;
}

static uint32_t empty_fragment(const silk_hal *h, const silk_fx *var)
{
    (void)h;
    (void)var;
    return 0;
}

/* Ticks per 1000 calls that timed_fragment adds around a stage.  The calls
 * are spaced unevenly (fw_spin) so that they start at every point of a tick,
 * as the core's calls do, instead of always at the same one. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static uint32_t timing_overhead(void)
{
    silk_hal empty = { 0 };
    empty.fragment = empty_fragment;
    timed_hal t;
    timed_hal_init(&t, &empty);
    silk_fx var[4] = { 0 };
    for (uint32_t i = 0; i < 100000; i++) {
        fw_spin(1 + i % 20);
        t.hal.fragment(&t.hal, var);
    }
    return t.fticks / 100;
}

static uint32_t clock_now(void *user)
{
    (void)user;
    return fw_ticks();
}

/* Ticks per 1000 pieces that the renderer's stage clock adds around a
 * piece: the core's own start/stop (src/stages.h) around nothing, spaced
 * unevenly as timing_overhead() does. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static uint32_t clock_overhead(void)
{
    silk_stage_clock c = { clock_now, NULL, { 0 }, { 0 } };
    for (uint32_t i = 0; i < 100000; i++) {
        fw_spin(1 + i % 20);
        uint32_t t0 = silk_stage_start(&c);
        silk_stage_stop(&c, SILK_STAGE_EMIT, t0);
    }
    return c.ticks[SILK_STAGE_EMIT] / 100;
}

static int discard_band(void *user, const silk_target *t)
{
    (void)user;
    (void)t;
    return 0;
}

/* A pass over the frames: written to PREFIX (or nowhere), or the stage pass. */
typedef struct fw_pass {
    int files;                   /* write the frames (a PREFIX was given) */
    int stages;                  /* time the HAL's stages, write nothing */
    uint32_t overhead;           /* timing_overhead(), for the report */
    uint32_t clock_overhead;     /* clock_overhead(), for the report */
    int frames, fell_back, smooth_fell_back;   /* the frames written, and how many fell back */
} fw_pass;

/* The stage pass of one frame: unwritten, the HAL's stages timed.  Never
 * inlined, so its timed_hal adds nothing to the stack of the frames written;
 * it uses the caller's options, statistics and error, so it adds little
 * to the stack of its own frames either (the board's stack holds both). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int time_stages(silk_arena *a, const silk_mesh *m, const silk_view *view, const silk_hal *hal,
                       silk_render_opts *ro, silk_target *band, const fw_pass *pass, int frame, int k,
                       silk_frame_stats *st, silk_error *err)
{
    timed_hal th;
    timed_hal_init(&th, hal);
    static const silk_sink none = { .band = discard_band, .user = NULL };   /* not on the stack */
    silk_stage_clock clock = { clock_now, NULL, { 0 }, { 0 } };
    ro->clock = &clock;
    silk_status s = silk_render_bands(a, m, view, hal, ro, band, &none, st, err);
    ro->clock = NULL;
    if (s != SILK_OK || silk_render_bands(a, m, view, &th.hal, ro, band, &none, st, err) != SILK_OK) {
        say("fw error frame=%d %s", frame, err->msg);
        return 1;
    }
    const char *mname = ro->mode == SILK_MODE_FLAT ? "flat" : "smooth";
    say("fw stages frame=%d camera=%d mode=%s fragment_ticks=%lu fragment_calls=%lu "
        "overhead_ticks_per_1000_calls=%lu",
        frame, k, mname, (unsigned long)th.fticks, (unsigned long)th.fcalls, (unsigned long)pass->overhead);
    for (int s = 0; s < SILK_STAGE_COUNT; s++)
        say("fw stage frame=%d camera=%d mode=%s stage=%s ticks=%lu pieces=%lu overhead_ticks_per_1000_pieces=%lu",
            frame, k, mname, silk_stage_name((silk_stage)s), (unsigned long)clock.ticks[s],
            (unsigned long)clock.pieces[s], (unsigned long)pass->clock_overhead);
    return 0;
}

/* PREFIX from "PROGRAM PREFIX", or NULL. */
static const char *out_prefix(char *cmd, size_t size)
{
    fw_cmdline(cmd, size);
    char *p = strchr(cmd, ' ');
    if (!p) return NULL;
    while (*p == ' ') p++;
    char *end = strchr(p, ' ');
    if (end) *end = 0;
    return *p ? p : NULL;
}

/* Whether the command line names a PREFIX.  Not inlined: the command line
 * is read again where a frame's file is opened, so that its buffer is not
 * on the stack under every frame. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int want_files(void)
{
    char cmd[160];
    return out_prefix(cmd, sizeof cmd) != NULL;
}

/* PREFIX-cK-MODE.ppm opened on the host and its header written.  Not
 * inlined: its buffers would otherwise stay on the stack under the frame. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int open_frame(band_out *o, int k, const char *mname, const silk_camera *cam)
{
    char cmd[160], path[128];
    snprintf(path, sizeof path, "%s-c%d-%s.ppm", out_prefix(cmd, sizeof cmd), k, mname);
    if ((o->handle = fw_open_write(path)) < 0) {
        say("fw error cannot open %s on the host", path);
        return 0;
    }
    char hdr[32];
    int n = snprintf(hdr, sizeof hdr, "P6\n%d %d\n255\n", cam->width, cam->height);
    put(o, hdr, (size_t)n);
    return 1;
}

#ifdef FW_REPORT_BUDGET
/* The arena silk_budget_frame() says a frame of each mode can take at
 * most (silk/budget.h), and each frame's own need checked against it: a
 * build with -DFW_REPORT_BUDGET (the host build of the scene, and boards
 * with the code bytes to spare) says "fw budget mode=M bands=N frame=N
 * total=N" and refuses a frame that needed more than its bound. */
static size_t budget_frame[2];

#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int report_budget(const silk_mesh *m, const silk_camera *c0, int rows)
{
    for (int mode = 0; mode < 2; mode++) {
        silk_render_opts ro;
        silk_render_opts_default(&ro);
        ro.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
        silk_budget b;
        silk_error err;
        if (silk_budget_frame(m, &ro, c0->width, c0->height, rows, FW_FORMAT, 0, &b, &err) != SILK_OK) {
            say("fw error %s", err.msg);
            return 0;
        }
        budget_frame[mode] = b.frame;
        say("fw budget mode=%s bands=%lu frame=%lu total=%lu", mode ? "smooth" : "flat", (unsigned long)b.bands,
            (unsigned long)b.frame, (unsigned long)b.total);
    }
    return 1;
}
#endif

/* The frame written: to PREFIX's file (or nowhere), checksummed and
 * reported.  Not inlined, like time_stages: each pass's own locals are not
 * on the stack under the other's frames. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int write_frame(silk_arena *a, const silk_mesh *m, const silk_view *view, const silk_hal *hal,
                       const silk_render_opts *ro, silk_target *band, fw_pass *pass, int frame, int k,
                       silk_frame_stats *st, silk_error *err)
{
    const char *mname = ro->mode == SILK_MODE_FLAT ? "flat" : "smooth";
    band_out o = { -1, 0, 2166136261u, 0, 0 };
    if (pass->files && !open_frame(&o, k, mname, fwmodel_camera(k))) return 1;
    silk_sink sink = { .band = send_band, .user = &o };
    o.frame_ticks = fw_ticks();
    silk_status s = silk_render_bands(a, m, view, hal, ro, band, &sink, st, err);
    o.frame_ticks = fw_ticks() - o.frame_ticks;
    if (o.handle >= 0 && fw_close(o.handle) != 0) o.failed = 1;
    if (s != SILK_OK || o.failed) {
        say("fw error frame=%d %s", frame, s != SILK_OK ? err->msg : "writing to the host failed");
        return 1;
    }
    say("fw frame=%d camera=%d mode=%s tris=%lu silhouette_tris=%lu samples=%lu frame_bytes=%lu fell_back=%d "
        "crc=%08lx",
        frame, k, mname, (unsigned long)st->tris_drawn, (unsigned long)st->silhouette_tris,
        (unsigned long)st->samples, (unsigned long)st->frame_bytes, st->fell_back, (unsigned long)o.crc);
#ifdef FW_REPORT_BUDGET
    if (st->frame_bytes > budget_frame[ro->mode == SILK_MODE_SMOOTH]) {
        say("fw error frame=%d needed %lu bytes, over its bound %lu", frame, (unsigned long)st->frame_bytes,
            (unsigned long)budget_frame[ro->mode == SILK_MODE_SMOOTH]);
        return 1;
    }
#endif
    pass->frames++;
    pass->fell_back += st->fell_back != 0;
    pass->smooth_fell_back += st->fell_back && ro->mode == SILK_MODE_SMOOTH;
    say("fw time frame=%d camera=%d mode=%s ticks=%lu sink_ticks=%lu render_ticks=%lu", frame, k, mname,
        (unsigned long)o.frame_ticks, (unsigned long)o.ticks, (unsigned long)(o.frame_ticks - o.ticks));
    return 0;
}

static int render_one(silk_arena *a, const silk_mesh *m, int k, silk_mode mode, silk_target *band,
                      fw_pass *pass, int frame)
{
    const silk_camera *cam = fwmodel_camera(k);
    silk_view view;
    silk_error err;
    if (silk_view_init(&view, cam, &err) != SILK_OK) {
        say("fw error camera=%d %s", k, err.msg);
        return 1;
    }
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &view);
    fwmodel_look(&phong);
    silk_hal_phong(&hal, &phong);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;
    ro.vertex_cache_bytes = FW_VERTEX_CACHE_BYTES;
    silk_frame_stats st;
    if (pass->stages) return time_stages(a, m, &view, &hal, &ro, band, pass, frame, k, &st, &err);
    return write_frame(a, m, &view, &hal, &ro, band, pass, frame, k, &st, &err);
}

/* What the frames written needed: the arena's high-water marks by purpose,
 * the stack's, static RAM, and their total against the linked budget. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void report_memory(const silk_arena *a, size_t band_bytes)
{
    fw_mem mem;
    fw_memory(&mem);
    say("fw arena size=%lu peak=%lu band_buffers=%lu", (unsigned long)a->size, (unsigned long)a->peak,
        (unsigned long)band_bytes);
    for (int p = 0; p < SILK_MEM_COUNT; p++)
        say("fw arena_purpose name=%s peak=%lu", silk_purpose_name((silk_purpose)p),
            (unsigned long)a->peak_used[p]);
    /* the arena is part of .bss; the host has no such figures */
    size_t other_static = mem.data + mem.bss > sizeof arena_mem ? mem.data + mem.bss - sizeof arena_mem : 0;
    say("fw stack size=%lu used=%lu", (unsigned long)mem.stack_size, (unsigned long)mem.stack_used);
    say("fw static data=%lu bss=%lu arena_reserved=%lu other=%lu", (unsigned long)mem.data, (unsigned long)mem.bss,
        (unsigned long)sizeof arena_mem, (unsigned long)other_static);
    say("fw ram static=%lu arena_peak=%lu stack_used=%lu total=%lu budget=%lu", (unsigned long)other_static,
        (unsigned long)a->peak, (unsigned long)mem.stack_used,
        (unsigned long)(other_static + a->peak + mem.stack_used), (unsigned long)mem.ram_size);
}

/* The arrays in flash were not loaded by silk: check them once, so a
 * damaged or hand-edited header is an error, not a wild read.  Not inlined:
 * its error message would otherwise stay on the stack under every frame. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int model_ok(const silk_mesh *mesh, const silk_camera *c0)
{
    silk_error err;
    if (silk_mesh_validate(mesh, FW_MODEL_NAME, &err) != SILK_OK || !c0) {
        say("fw error %s", c0 ? err.msg : "the model has no camera");
        return 0;
    }
    return 1;
}

int fw_scene(void)
{
    int files = want_files();
    silk_mesh mesh;
    fwmodel_mesh(&mesh);
    const silk_camera *c0 = fwmodel_camera(0);
    if (!model_ok(&mesh, c0)) return 1;
    say("fw board=%s model=%s size=%dx%d format=%s band_rows=%d cameras=%d aa=%s", FW_BOARD, FW_MODEL_NAME, c0->width,
        c0->height, FW_FORMAT == SILK_PIX_RGB565 ? "rgb565" : "rgb888", FW_BAND_ROWS, fwmodel_NCAMERAS, FW_AA);

    /* The timer's rate, from a loop of a known number of instructions. */
    uint32_t spin = 1000000u, t0 = fw_ticks();
    fw_spin(spin);
    say("fw timer loop_instructions=%lu ticks=%lu", (unsigned long)(2 * spin), (unsigned long)(fw_ticks() - t0));

    silk_arena arena;
    silk_arena_init(&arena, arena_mem, sizeof arena_mem);
    int rows = FW_BAND_ROWS < c0->height ? FW_BAND_ROWS : c0->height;
    uint8_t *color = silk_arena_array(&arena, (size_t)rows * (size_t)c0->width, silk_pixfmt_bytes(FW_FORMAT),
                                      SILK_MEM_RASTER);
    uint32_t *depth = silk_arena_array(&arena, (size_t)rows * (size_t)c0->width, sizeof *depth, SILK_MEM_RASTER);
    if (!color || !depth) {
        say("fw error the arena (%lu bytes) cannot hold a band of %d rows", (unsigned long)sizeof arena_mem, rows);
        return 1;
    }
    size_t band_bytes = arena.bottom;
#ifdef FW_REPORT_BUDGET
    if (!report_budget(&mesh, c0, rows)) return 1;
#endif
    silk_target band;
    silk_target_init(&band, c0->width, c0->height, 0, rows, FW_FORMAT, color, depth);

    int rc = 0;
    fw_pass pass = { files, 0, 0, 0, 0, 0, 0 };
    for (int p = 0; p < 2; p++) {
        if (p == 1) {   /* the stage pass last, so that its timing adds nothing to the memory reported */
            report_memory(&arena, band_bytes);
            if (rc) break;
            pass.files = 0;   /* the counts of the frames written stay */
            pass.stages = 1;
            pass.overhead = timing_overhead();
            pass.clock_overhead = clock_overhead();
        }
        for (int k = 0, frame = 0; k < fwmodel_NCAMERAS && !rc; k++)
            for (int mode = 0; mode < 2 && !rc; mode++)
                rc = render_one(&arena, &mesh, k, mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT, &band, &pass, frame++);
    }
    /* A frame drawn unsmoothed for lack of RAM is not a success: say how
     * many, and exit 2 (1 is an error), so that a run that only checks the
     * status sees it too. */
    if (rc) {
        say("fw result=error");
        return 1;
    }
    if (pass.fell_back) {
        say("fw result=fell_back frames=%d fell_back=%d smooth_fell_back=%d", pass.frames, pass.fell_back,
            pass.smooth_fell_back);
        return 2;
    }
    say("fw result=ok");
    return 0;
}
