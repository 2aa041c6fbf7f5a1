/*
 * fuzz_render.c - libFuzzer harness for one whole frame: bytes -> mesh ->
 * camera -> silk_render (paper section III in SMOOTH mode, the coarse mesh
 * in FLAT, the reference methods in PN and BLEND) -> a small image.
 *
 * Input: a 32-byte scene header, then a mesh (OBJ or PLY, picked by
 * silk_load_mesh).  Header bytes (little-endian, all values wrap):
 *    0     mode (bits 0-1), orthographic (2), wire (3), visibility (4-5:
 *          auto, brute, gauss, auto without a hierarchy), bands (6), rgb565 (7)
 *    1, 2  width, height: 1 + b % 48
 *    3     bit 0: eye and target relative to the model's centre;
 *          bits 1-4: s, coordinates below are i16 * 2^s in Q16.16 ulps
 *    4-9   eye (3 x i16)       10-15 target (3 x i16)
 *    16-18 up (3 x i8, * 2^10)
 *    19-20 field of view: (u16 % 11521) / 64 degrees (0 .. 180, both ends
 *          invalid on purpose)
 *    21    znear: 1 + 16 b^2 ulps      22  zfar: znear + (b + 1)^3 * 2^8 ulps
 *    23    tolerance: (b + 1) / 64 px  24  ortho half height: (b + 1)^2 * 2^8 ulps
 *    25    PN level: 1 + b % 32        26  BLEND beta: b * 2^8 ulps
 *    27    frame memory: the arena keeps 2^(8 + b % 15) bytes free after
 *          the mesh, plus bytes 30-31 (u16) modulo that, or all of its 8 MB
 *          when b >= 240
 *    28    band rows: 1 + b % 16; pen-and-ink lines: (b >> 4) % 3 (none,
 *          over, only), polygonal: bit 6
 *    29    crease angle: b % 181 degrees
 * A mesh with texture coordinates is drawn with a small mipmapped texture
 * (5 x 3, repeating), one with vertex colours with them.
 * Checks besides "no crash": a failure is one clean line; the frame's
 * scratch is all released; with bands, the band-by-band pixels equal the
 * whole frame's (silk/render.h promises identical bytes), from the same
 * geometry (same fall-back, same triangle count).
 */
#include "fuzz.h"
#include "silk/validate.h"

#define HEADER 32
#define ARENA_SIZE ((size_t)8 << 20)

typedef struct band_copy {
    uint8_t *dst;           /* the whole frame, rows of stride bytes */
    size_t stride;
    int bands;
} band_copy;

static int take_band(void *user, const silk_target *band)
{
    band_copy *c = user;
    for (int r = 0; r < band->rows; r++)
        memcpy(c->dst + (size_t)(band->y0 + r) * c->stride, band->color + (size_t)r * band->stride, c->stride);
    c->bands++;
    return 0;
}

static silk_fx coord(int32_t v, int s)
{
    return silk_fx_sat((int64_t)v * ((int64_t)1 << s));
}

static silk_fx centre(silk_fx lo, silk_fx hi) { return (silk_fx)(((int64_t)lo + hi) / 2); }

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    if (size < HEADER) return 0;
    fuzz_bytes h = { data, HEADER, 0 };
    uint32_t flags = fuzz_u8(&h);
    int width = 1 + (int)(fuzz_u8(&h) % 48), height = 1 + (int)(fuzz_u8(&h) % 48);
    uint32_t place = fuzz_u8(&h);
    int s = (int)((place >> 1) & 15);
    int32_t ev[3], tv[3], uv[3];
    for (int k = 0; k < 3; k++) ev[k] = fuzz_i16(&h);
    for (int k = 0; k < 3; k++) tv[k] = fuzz_i16(&h);
    for (int k = 0; k < 3; k++) uv[k] = (int8_t)fuzz_u8(&h);
    uint32_t fov = fuzz_u8(&h);
    fov |= fuzz_u8(&h) << 8;
    uint32_t bn = fuzz_u8(&h), bf = fuzz_u8(&h), btol = fuzz_u8(&h), bortho = fuzz_u8(&h);
    uint32_t blevel = fuzz_u8(&h), bbeta = fuzz_u8(&h), bmem = fuzz_u8(&h), brows = fuzz_u8(&h);
    uint32_t bcrease = fuzz_u8(&h);
    uint32_t bfine = fuzz_u8(&h);
    bfine |= fuzz_u8(&h) << 8;

    /* kept between runs: a fresh 8 MB block per run costs more than a frame */
    static uint8_t mem[ARENA_SIZE];
    silk_arena a;
    silk_mesh m;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_arena_init(&a, mem, ARENA_SIZE);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    lo.crease_deg = SILK_FX_C(bcrease % 181, 1);
    silk_status st = silk_load_mesh(data + HEADER, size - HEADER, "fuzz", &lo, &a, &m, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, "fuzz");
        return 0;
    }
    fuzz_expect(silk_mesh_validate(&m, "fuzz", &err) == SILK_OK, "loaded mesh inconsistent: %s", err.msg);
    uint32_t vis_bits = (flags >> 4) & 3;
    if (vis_bits != 3 && silk_vis_build(&m, NULL, &a, &err) != SILK_OK) fuzz_check_error(err.code, &err, NULL);

    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    silk_vec3 c = silk_v3(0, 0, 0);
    if (place & 1)
        c = silk_v3(centre(m.bbox_min.x, m.bbox_max.x), centre(m.bbox_min.y, m.bbox_max.y),
                    centre(m.bbox_min.z, m.bbox_max.z));
    cam.target = silk_v3(silk_fx_add(c.x, coord(tv[0], s)), silk_fx_add(c.y, coord(tv[1], s)),
                         silk_fx_add(c.z, coord(tv[2], s)));
    cam.eye = silk_v3(silk_fx_add(cam.target.x, coord(ev[0], s)), silk_fx_add(cam.target.y, coord(ev[1], s)),
                      silk_fx_add(cam.target.z, coord(ev[2], s)));
    if (!(place & 1)) cam.eye = silk_v3(coord(ev[0], s), coord(ev[1], s), coord(ev[2], s));
    cam.up = silk_v3(uv[0] * 1024, uv[1] * 1024, uv[2] * 1024);
    cam.ortho = (flags >> 2) & 1;
    cam.fov_deg = (silk_fx)((fov % 11521) * 1024);
    cam.ortho_half_height = (silk_fx)((bortho + 1) * (bortho + 1) * 256);
    cam.znear = (silk_fx)(1 + 16 * bn * bn);
    cam.zfar = silk_fx_sat((int64_t)cam.znear + (int64_t)(bf + 1) * (bf + 1) * (bf + 1) * 256);
    cam.width = width;
    cam.height = height;
    silk_view view;
    st = silk_view_init(&view, &cam, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, "camera");
        return 0;
    }

    /* Leave only the frame budget free: a block at the bottom takes the rest. */
    if (bmem < 240) {
        size_t base = (size_t)256 << (bmem % 15), budget = base + bfine % base;
        size_t free_now = silk_arena_free_bytes(&a);
        if (free_now > budget) silk_arena_alloc(&a, free_now - budget - SILK_ARENA_ALIGN, SILK_MEM_RASTER);
    }

    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = (silk_mode)(flags & 3);
    ro.wire = (flags >> 3) & 1;
    ro.visibility = vis_bits == 1 ? SILK_VIS_BRUTE : vis_bits == 2 ? SILK_VIS_GAUSS : SILK_VIS_AUTO;
    ro.tolerance_px = (silk_fx)((btol + 1) * 1024);
    ro.level = 1 + blevel % 32;
    ro.blend_beta = (silk_fx)(bbeta * 256);
    ro.lines = (silk_lines)((brows >> 4) % 3);
    ro.lines_polygonal = (brows >> 6) & 1;
    silk_pixfmt fmt = (flags >> 7) ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
    size_t bpp = silk_pixfmt_bytes(fmt), px = (size_t)width * (size_t)height;
    /* exact sizes on the heap, so that ASan sees any write outside */
    uint8_t *color = malloc(px * bpp);
    uint32_t *depth = malloc(px * sizeof *depth);
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &view);
    static uint8_t texels[3 * (15 + 2 + 1)];
    for (size_t i = 0; i < 45; i++) texels[i] = (uint8_t)(i * 37);
    silk_texture tex = { texels, NULL, 5, 3, SILK_TEX_RGB888, 3, SILK_TEX_BILINEAR, SILK_TEX_REPEAT };
    silk_texture_build_mipmaps(&tex, texels);
    phong.texture = m.uv ? &tex : NULL;
    phong.vertex_colors = m.color != NULL;
    silk_hal_phong(&hal, &phong);
    silk_target t;
    silk_target_init(&t, width, height, 0, height, fmt, color, depth);

    size_t bottom = a.bottom;
    silk_frame_stats stats;
    st = silk_render(&a, &m, &view, &hal, &ro, &t, &stats, &err);
    fuzz_expect(a.top == 0 && a.bottom == bottom, "the frame kept memory: top %zu", a.top);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, NULL);
    } else if ((flags >> 6) & 1) {
        int rows = 1 + (int)(brows % 16);
        uint8_t *whole = malloc(px * bpp), *bcolor = malloc((size_t)rows * width * bpp);
        uint32_t *bdepth = malloc((size_t)rows * width * sizeof *bdepth);
        silk_target band;
        silk_target_init(&band, width, height, 0, rows, fmt, bcolor, bdepth);
        band_copy bc = { whole, (size_t)width * bpp, 0 };
        silk_sink sink = { .band = take_band, .user = &bc };
        silk_frame_stats bstats;
        silk_status bst = silk_render_bands(&a, &m, &view, &hal, &ro, &band, &sink, &bstats, &err);
        fuzz_expect(a.top == 0 && a.bottom == bottom, "the banded frame kept memory: top %zu", a.top);
        fuzz_expect(bst == SILK_OK, "bands failed where the frame did not: %s", err.msg);
        fuzz_expect(bc.bands == (height + rows - 1) / rows, "%d bands of %d rows for %d rows", bc.bands, rows,
                    height);
        fuzz_expect(bstats.fell_back == stats.fell_back && bstats.tris_drawn == stats.tris_drawn,
                    "bands drew another frame (fell back %d/%d, %u/%u triangles)", bstats.fell_back,
                    stats.fell_back, bstats.tris_drawn, stats.tris_drawn);
        /* the same bytes unless the anti-aliased outline ran out of room in
         * either (too little arena, or more crossings than a band's list holds) */
        fuzz_expect(stats.aa_aliased || bstats.aa_aliased || memcmp(whole, color, px * bpp) == 0,
                    "band pixels differ from the whole frame's (%d rows)", rows);
        free(whole);
        free(bcolor);
        free(bdepth);
    }
    free(color);
    free(depth);
    return 0;
}
