/*
 * test_fb.c - the Linux framebuffer sink (platform/fb_sink.c) against
 * file-backed framebuffers: the same code as a device, without the ioctls.
 *
 * A 500-triangle bunny is rendered in bands of 16 rows straight into 16-,
 * 24- and 32-bit framebuffer files; read back, every pixel must be the
 * full-frame render's, converted here independently of the sink (a 16-bit
 * RGB565 screen gets the rendered bytes unchanged).  A screen with padded
 * rows, a visible area inside a larger virtual one, a BGR layout and a frame
 * hanging off two of its edges checks clipping and addressing: pixels
 * outside the frame keep the fill colour, pixels outside the visible area
 * stay untouched.  Bad geometry and paths fail with one clear message.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "silk/silk.h"
#include "platform/fb.h"

#define ARENA_BYTES (8u << 20)

static uint8_t *arena_buf;
static char dir[64];

static char *read_all(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    char *b = NULL;
    if (fseek(fp, 0, SEEK_END) == 0) {
        long n = ftell(fp);
        if (n >= 0 && fseek(fp, 0, SEEK_SET) == 0 && (b = malloc((size_t)n + 1))) {
            if (fread(b, 1, (size_t)n, fp) != (size_t)n) {
                free(b);
                b = NULL;
            } else {
                *len = (size_t)n;
            }
        }
    }
    fclose(fp);
    return b;
}

/* A scene: the shared bunny, a camera from the front-right, Phong. */
typedef struct scene {
    silk_arena arena;
    silk_mesh mesh;
    silk_view view;
    silk_phong phong;
    silk_hal hal;
    silk_render_opts ro;
} scene;

static int scene_init(scene *s, int w, int h)
{
    char path[512];
    snprintf(path, sizeof path, "%s/bunny-500.obj", check_meshes_dir());
    size_t len = 0;
    char *text = read_all(path, &len);
    if (!text) {
        fprintf(stderr, "cannot read %s\n", path);
        return 0;
    }
    silk_arena_init(&s->arena, arena_buf, ARENA_BYTES);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    silk_error err;
    silk_status st = silk_load_mesh(text, len, "bunny-500.obj", &lo, &s->arena, &s->mesh, &err);
    free(text);
    if (st != SILK_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(SILK_FX_C(13, 10), SILK_FX_C(9, 10), SILK_FX_C(27, 10));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(38, 1);
    cam.znear = SILK_FX_C(1, 2);
    cam.zfar = SILK_FX_C(10, 1);
    cam.width = w;
    cam.height = h;
    if (silk_view_init(&s->view, &cam, &err) != SILK_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    silk_phong_default(&s->phong, &s->view);
    silk_hal_phong(&s->hal, &s->phong);
    silk_render_opts_default(&s->ro);
    s->ro.bg_rgb = 0x3060A0;
    return 1;
}

/* The whole frame at once: the reference. */
static int render_full(scene *s, silk_pixfmt fmt, silk_target *t)
{
    int w = s->view.cam.width, h = s->view.cam.height;
    uint8_t *c = silk_arena_array(&s->arena, (size_t)w * h, silk_pixfmt_bytes(fmt), SILK_MEM_RASTER);
    uint32_t *d = silk_arena_array(&s->arena, (size_t)w * h, sizeof *d, SILK_MEM_RASTER);
    if (!c || !d) return 0;
    silk_target_init(t, w, h, 0, h, fmt, c, d);
    silk_error err;
    if (silk_render(&s->arena, &s->mesh, &s->view, &s->hal, &s->ro, t, NULL, &err) != SILK_OK) {
        fprintf(stderr, "render: %s\n", err.msg);
        return 0;
    }
    return 1;
}

/* The same frame in bands of 16 rows through the framebuffer sink. */
static int render_to_fb(scene *s, silk_pixfmt fmt, silk_fb *fb)
{
    enum { ROWS = 16 };
    int w = s->view.cam.width, h = s->view.cam.height;
    silk_arena_mark mk = silk_arena_top_mark(&s->arena);
    uint8_t *c = silk_arena_array_top(&s->arena, (size_t)w * ROWS, silk_pixfmt_bytes(fmt), SILK_MEM_RASTER);
    uint32_t *d = silk_arena_array_top(&s->arena, (size_t)w * ROWS, sizeof *d, SILK_MEM_RASTER);
    if (!c || !d) return 0;
    silk_target band;
    silk_target_init(&band, w, h, 0, ROWS, fmt, c, d);
    silk_sink sink = { .band = silk_fb_band, .user = fb };
    silk_error err;
    silk_status st = silk_render_bands(&s->arena, &s->mesh, &s->view, &s->hal, &s->ro, &band, &sink, NULL, &err);
    silk_arena_top_release(&s->arena, &mk);
    if (st != SILK_OK) fprintf(stderr, "render_bands: %s\n", err.msg);
    return st == SILK_OK;
}

/* The reference pixel as 8-bit channels, widened here by bit replication. */
static void ref_rgb(const silk_target *t, int x, int y, unsigned rgb[3])
{
    const uint8_t *p = t->color + (size_t)y * t->stride + (size_t)x * silk_pixfmt_bytes(t->fmt);
    if (t->fmt == SILK_PIX_RGB888) {
        rgb[0] = p[0]; rgb[1] = p[1]; rgb[2] = p[2];
        return;
    }
    unsigned v = p[0] | p[1] << 8, r = v >> 11, g = (v >> 5) & 63, b = v & 31;
    rgb[0] = r << 3 | r >> 2;
    rgb[1] = g << 2 | g >> 4;
    rgb[2] = b << 3 | b >> 2;
}

/* Expected bytes of one pixel in the default layouts. */
static void expected_bytes(int bpp, const unsigned c[3], uint8_t out[4])
{
    if (bpp == 16) {
        unsigned v = (c[0] >> 3) << 11 | (c[1] >> 2) << 5 | c[2] >> 3;
        out[0] = (uint8_t)v; out[1] = (uint8_t)(v >> 8);
    } else {
        out[0] = (uint8_t)c[2]; out[1] = (uint8_t)c[1]; out[2] = (uint8_t)c[0]; out[3] = 0;
    }
}

static void check_default_layout(int bpp, silk_pixfmt fmt)
{
    enum { W = 320, H = 240 };
    scene s;
    silk_target ref;
    if (!scene_init(&s, W, H) || !render_full(&s, fmt, &ref)) {
        CHECKF(0, "cannot render the reference");
        return;
    }
    char path[128];
    snprintf(path, sizeof path, "%s/fb%d.raw", dir, bpp);
    silk_fb_info info;
    silk_error err;
    silk_fb fb;
    CHECK(silk_fb_info_default(&info, W, H, bpp, &err) == SILK_OK);
    if (silk_fb_open_file(&fb, path, &info, &err) != SILK_OK) {
        CHECKF(0, "open %s: %s", path, err.msg);
        return;
    }
    int ok = render_to_fb(&s, fmt, &fb);
    CHECK(ok);
    CHECKF(fb.bands == (H + 15) / 16, "%lu bands", (unsigned long)fb.bands);
    CHECK(silk_fb_close(&fb, &err) == SILK_OK);

    size_t len = 0;
    uint8_t *raw = (uint8_t *)read_all(path, &len);
    size_t bytes = (size_t)bpp / 8;
    CHECKF(raw && len == (size_t)W * H * bytes, "%s: %zu bytes", path, len);
    if (!raw || len != (size_t)W * H * bytes) {
        free(raw);
        return;
    }
    long bad = 0, drawn = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned c[3];
            uint8_t e[4];
            ref_rgb(&ref, x, y, c);
            expected_bytes(bpp, c, e);
            drawn += (c[0] << 16 | c[1] << 8 | c[2]) != 0x3060A0;
            if (memcmp(raw + ((size_t)y * W + x) * bytes, e, bytes) != 0 && !bad++)
                fprintf(stderr, "first difference at %d,%d\n", x, y);
        }
    CHECKF(bad == 0, "%d bpp: %ld pixels differ", bpp, bad);
    CHECKF(drawn > 5000, "only %ld pixels of the model", drawn);
    /* RGB565 into a 16-bit screen: the rendered bytes themselves. */
    if (bpp == 16 && fmt == SILK_PIX_RGB565) CHECK(memcmp(raw, ref.color, len) == 0);
    free(raw);
}

TEST(fb16_rgb565) { check_default_layout(16, SILK_PIX_RGB565); }
TEST(fb32_rgb888) { check_default_layout(32, SILK_PIX_RGB888); }
TEST(fb32_rgb565) { check_default_layout(32, SILK_PIX_RGB565); }
TEST(fb24_rgb888) { check_default_layout(24, SILK_PIX_RGB888); }
TEST(fb16_rgb888) { check_default_layout(16, SILK_PIX_RGB888); }

/* Padded rows, an offset visible area, BGR, a frame off two edges. */
TEST(fb_clipping_and_layout)
{
    enum { FW = 120, FH = 60 };
    const int ox = -5, oy = 30;
    scene s;
    silk_target ref;
    if (!scene_init(&s, FW, FH) || !render_full(&s, SILK_PIX_RGB888, &ref)) {
        CHECKF(0, "cannot render the reference");
        return;
    }
    silk_fb_info info;
    memset(&info, 0, sizeof info);
    info.xres = 100; info.yres = 80;
    info.xres_virtual = 128; info.yres_virtual = 100;
    info.xoffset = 10; info.yoffset = 7;
    info.bits_per_pixel = 32;
    info.line_length = 128 * 4 + 16;
    info.red = (silk_fb_field){ 0, 8 };
    info.green = (silk_fb_field){ 8, 8 };
    info.blue = (silk_fb_field){ 16, 8 };
    char path[128];
    snprintf(path, sizeof path, "%s/fbclip.raw", dir);
    silk_fb fb;
    silk_error err;
    if (silk_fb_open_file(&fb, path, &info, &err) != SILK_OK) {
        CHECKF(0, "%s", err.msg);
        return;
    }
    const uint32_t fill = 0x11AA55;
    silk_fb_fill(&fb, fill);
    fb.origin_x = ox;
    fb.origin_y = oy;
    CHECK(render_to_fb(&s, SILK_PIX_RGB888, &fb));
    CHECK(silk_fb_close(&fb, &err) == SILK_OK);
    /* closing twice is harmless */
    CHECK(silk_fb_close(&fb, &err) == SILK_OK);

    size_t len = 0;
    uint8_t *raw = (uint8_t *)read_all(path, &len);
    CHECKF(raw && len == (size_t)info.line_length * info.yres_virtual, "%zu bytes", len);
    if (!raw || len != (size_t)info.line_length * info.yres_virtual) {
        free(raw);
        return;
    }
    long bad_frame = 0, bad_fill = 0, bad_outside = 0, frame_px = 0;
    for (uint32_t vy = 0; vy < info.yres_virtual; vy++)
        for (uint32_t vx = 0; vx < info.xres_virtual; vx++) {
            const uint8_t *p = raw + (size_t)vy * info.line_length + (size_t)vx * 4;
            int sx = (int)vx - (int)info.xoffset, sy = (int)vy - (int)info.yoffset;
            int visible = sx >= 0 && sy >= 0 && sx < (int)info.xres && sy < (int)info.yres;
            if (!visible) {
                bad_outside += p[0] || p[1] || p[2] || p[3];
                continue;
            }
            int fx = sx - ox, fy = sy - oy;
            unsigned c[3];
            if (fx >= 0 && fy >= 0 && fx < FW && fy < FH) {
                ref_rgb(&ref, fx, fy, c);
                frame_px++;
            } else {
                c[0] = fill >> 16; c[1] = (fill >> 8) & 255; c[2] = fill & 255;
            }
            /* BGR: red in the low byte */
            int ok = p[0] == c[0] && p[1] == c[1] && p[2] == c[2] && p[3] == 0;
            if (!ok) {
                if (fx >= 0 && fy >= 0 && fx < FW && fy < FH) bad_frame++;
                else bad_fill++;
            }
        }
    /* rows 30..79 of the screen, columns 0..99 */
    CHECKF(frame_px == 100 * 50, "%ld frame pixels on screen", frame_px);
    CHECKF(bad_frame == 0 && bad_fill == 0 && bad_outside == 0, "frame %ld, fill %ld, outside %ld pixels wrong",
           bad_frame, bad_fill, bad_outside);
    free(raw);
}

/* Narrow channels: each keeps the top bits of the 8-bit value. */
TEST(fb_pixel_fields)
{
    silk_fb_info i;
    silk_error err;
    CHECK(silk_fb_info_default(&i, 4, 4, 16, &err) == SILK_OK);
    CHECK(silk_fb_pixel(&i, 0xFFFFFF) == 0xFFFF);
    CHECK(silk_fb_pixel(&i, 0xFF0000) == 0xF800);
    CHECK(silk_fb_pixel(&i, 0x00FF00) == 0x07E0);
    CHECK(silk_fb_pixel(&i, 0x0000FF) == 0x001F);
    CHECK(silk_fb_pixel(&i, 0x847C18) == ((0x84u >> 3) << 11 | (0x7Cu >> 2) << 5 | (0x18u >> 3)));
    CHECK(silk_fb_info_default(&i, 4, 4, 32, &err) == SILK_OK);
    CHECK(silk_fb_pixel(&i, 0x123456) == 0x123456);
}

static void expect_fail(silk_status got, silk_status want, const silk_error *err, const char *needle)
{
    CHECKF(got == want, "status %d, wanted %d (%s)", (int)got, (int)want, err->msg);
    CHECKF(strstr(err->msg, needle) != NULL, "message \"%s\" lacks \"%s\"", err->msg, needle);
    CHECKF(strchr(err->msg, '\n') == NULL, "message \"%s\" is not one line", err->msg);
}

TEST(fb_bad_input)
{
    silk_fb_info info;
    silk_fb fb;
    silk_error err;
    char path[128];
    snprintf(path, sizeof path, "%s/bad.raw", dir);

    expect_fail(silk_fb_info_default(&info, 64, 48, 8, &err), SILK_ERR_ARG, &err, "8 bits per pixel");
    expect_fail(silk_fb_info_default(&info, 0, 48, 16, &err), SILK_ERR_ARG, &err, "0x48");

    CHECK(silk_fb_info_default(&info, 64, 48, 32, &err) == SILK_OK);
    info.green.length = 9;
    expect_fail(silk_fb_open_file(&fb, path, &info, &err), SILK_ERR_ARG, &err, "pixel layout");
    CHECK(silk_fb_info_default(&info, 64, 48, 32, &err) == SILK_OK);
    info.line_length = 100;
    expect_fail(silk_fb_open_file(&fb, path, &info, &err), SILK_ERR_ARG, &err, "line length");
    CHECK(silk_fb_info_default(&info, 64, 48, 32, &err) == SILK_OK);
    info.xoffset = 1;
    expect_fail(silk_fb_open_file(&fb, path, &info, &err), SILK_ERR_ARG, &err, "visible area");
    CHECK(silk_fb_info_default(&info, 64, 48, 16, &err) == SILK_OK);
    expect_fail(silk_fb_open_file(&fb, "/nonexistent-dir/fb.raw", &info, &err), SILK_ERR_IO, &err,
                "/nonexistent-dir/fb.raw: cannot create");
    /* nothing half-open is left behind */
    CHECK(fb.mem == NULL && fb.fd == -1);

    /* devices: a missing one, and a file that is not a framebuffer */
    expect_fail(silk_fb_open(&fb, "/nonexistent-dir/fb0", &err), SILK_ERR_IO, &err, "/nonexistent-dir/fb0");
    FILE *fp = fopen(path, "wb");
    if (fp) {
        fputs("not a framebuffer", fp);
        fclose(fp);
    }
    silk_status st = silk_fb_open(&fb, path, &err);
    CHECKF(st == SILK_ERR_IO && strstr(err.msg, path) && fb.fd == -1, "status %d: %s", (int)st, err.msg);
    /* a band into a closed framebuffer is ignored, not a crash */
    silk_target t;
    uint8_t px[6] = { 0 };
    uint32_t depth[1] = { 0 };
    silk_target_init(&t, 1, 1, 0, 1, SILK_PIX_RGB888, px, depth);
    CHECK(silk_fb_band(&fb, &t) == 0);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    snprintf(dir, sizeof dir, "/tmp/silk-fb.XXXXXX");
    if (!arena_buf || !mkdtemp(dir)) {
        fprintf(stderr, "setup failed\n");
        return 1;
    }
    RUN(fb16_rgb565);
    RUN(fb32_rgb888);
    RUN(fb32_rgb565);
    RUN(fb24_rgb888);
    RUN(fb16_rgb888);
    RUN(fb_clipping_and_layout);
    RUN(fb_pixel_fields);
    RUN(fb_bad_input);
    const char *names[] = { "fb16.raw", "fb24.raw", "fb32.raw", "fbclip.raw", "bad.raw" };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char p[160];
        snprintf(p, sizeof p, "%s/%s", dir, names[i]);
        unlink(p);
    }
    rmdir(dir);
    free(arena_buf);
    return check_done();
}
