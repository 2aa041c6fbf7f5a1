/*
 * fuzz_siltex.c - libFuzzer harness for silhouette textures: the STEX
 * reader (src/model.c, silk_model_siltex) and the lookup behind it
 * (src/siltex.c), then a small siltex frame drawn whole and in bands.
 *
 * The input is a .silk file.  It is read as it is, then once more with the
 * file size and every checksum made right (fuzz_model_fix), so the fuzzer
 * reaches the checks of the section's contents.  A texture that passes is
 * looked up at every triangle corner's atlas point and a little outside
 * the atlas, along directions taken from the input, and every texel's
 * angles are reconstructed; then the hull is drawn through it in a 32 x 24
 * frame (with or without its lines): the bands must give the whole
 * frame's bytes.
 */
#include "fuzz.h"
#include "silk/siltex.h"

static void siltex_lookups(const silk_siltex *st, const uint8_t *data, size_t size)
{
    fuzz_bytes in = { data, size, 0 };
    for (uint32_t t = 0; t < st->w * st->h && t < 65536; t++)
        for (uint32_t i = 0; i < st->k; i++) fuzz_expect(silk_siltex_q(st, t, i) <= 255, "q above 255");
    for (uint32_t c = 0; c < 3 * st->ntris && c < 3000; c++) {
        const uint8_t *p = st->uv + 4 * (size_t)c;
        silk_fx u = (silk_fx)((uint32_t)(p[0] | p[1] << 8) << 12) + fuzz_i16(&in) * 64;
        silk_fx v = (silk_fx)((uint32_t)(p[2] | p[3] << 8) << 12) + fuzz_i16(&in) * 64;
        silk_fx cv[3], tv[3];
        int64_t d[3];
        for (int k = 0; k < 3; k++) {
            cv[k] = fuzz_i16(&in) * 4;
            tv[k] = fuzz_i16(&in) * 4;
        }
        if (!silk_unit64(fuzz_i16(&in), fuzz_i16(&in), fuzz_i16(&in) | 1, d)) continue;
        (void)silk_siltex_visible(st, u, v, cv, tv, d);
        int64_t n[3];
        silk_siltex_normal(st, u, v, n);
        for (int k = 0; k < 3; k++) fuzz_expect(n[k] >= -SILK_FX_ONE - 4 && n[k] <= SILK_FX_ONE + 4, "normal out of range");
    }
}

static int siltex_band(void *user, const silk_target *t)
{
    uint8_t *frame = user;
    memcpy(frame + (size_t)t->y0 * 32 * 3, t->color, (size_t)t->rows * 32 * 3);
    return 0;
}

static void siltex_draw(const silk_siltex *st, const uint8_t *b, size_t size)
{
    static uint8_t mem[(size_t)4 << 20];
    silk_arena a;
    silk_arena_init(&a, mem, sizeof mem);
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.part = SILK_PART_HULL;
    silk_mesh m;
    silk_error err;
    if (silk_load_model(b, size, "fuzz.silk", &o, &a, &m, &err) != SILK_OK) return;
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.target = silk_v3((m.bbox_min.x + m.bbox_max.x) / 2, (m.bbox_min.y + m.bbox_max.y) / 2,
                         (m.bbox_min.z + m.bbox_max.z) / 2);
    cam.eye = silk_v3_add(cam.target, silk_v3(SILK_FX_C(3, 1), SILK_FX_C(2, 1), SILK_FX_C(30, 1)));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(35, 1);
    cam.ortho = (int)(size & 1);
    cam.ortho_half_height = SILK_FX_C(4, 1);
    cam.znear = SILK_FX_C(1, 10);
    cam.zfar = SILK_FX_C(4000, 1);
    cam.width = 32;
    cam.height = 24;
    silk_view v;
    if (silk_view_init(&v, &cam, &err) != SILK_OK) return;
    silk_phong ph;
    silk_hal h;
    silk_phong_default(&ph, &v);
    silk_hal_phong(&h, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = SILK_MODE_SILTEX;
    ro.siltex = st;
    ro.lines = (silk_lines)(size % 3);   /* eq. 5's lines too */
    static uint8_t whole[32 * 24 * 3], bands[32 * 24 * 3];
    static uint32_t depth[32 * 24];
    silk_target t;
    silk_target_init(&t, 32, 24, 0, 24, SILK_PIX_RGB888, whole, depth);
    silk_status s = silk_render(&a, &m, &v, &h, &ro, &t, NULL, &err);
    if (s) {
        fuzz_check_error(s, &err, NULL);
        return;
    }
    silk_target_init(&t, 32, 24, 0, 8, SILK_PIX_RGB888, bands + 0, depth);
    static uint8_t band[32 * 8 * 3];
    t.color = band;
    silk_sink sink = { .band = siltex_band, .user = bands };
    s = silk_render_bands(&a, &m, &v, &h, &ro, &t, &sink, NULL, &err);
    fuzz_expect(s == SILK_OK, "the bands failed where the frame did not");
    fuzz_expect(memcmp(whole, bands, sizeof whole) == 0, "bands differ from the whole frame");
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    silk_siltex st;
    silk_error err;
    silk_status s = silk_model_siltex(data, size, "fuzz.silk", &st, &err);
    if (s) fuzz_check_error(s, &err, "fuzz.silk");
    if (size < SILK_MODEL_HEADER_BYTES || size > ((size_t)1 << 20)) return 0;
    uint8_t *b = malloc(size);
    if (!b) return 0;
    memcpy(b, data, size);
    fuzz_model_fix(b, size);
    s = silk_model_siltex(b, size, "fuzz.silk", &st, &err);
    if (s) {
        fuzz_check_error(s, &err, "fuzz.silk");
    } else {
        siltex_lookups(&st, data, size);
        siltex_draw(&st, b, size);
    }
    free(b);
    return 0;
}
