/*
 * texture.c - texture sampling: nearest and bilinear filtering, repeat and
 * clamp addressing, and mipmap levels chosen per pixel from how far the
 * texture coordinates move between neighbouring pixels (the standard
 * level-of-detail rule, OpenGL 4.6 section 8.14: lambda = log2 rho, rho the
 * larger texel footprint), blended linearly between the two nearest levels.
 *
 * Not a paper equation: the paper only carries uvs through the re-meshing
 * (section V); how a texel is read is the usual GPU way, in integers.
 * Texel centres sit at half-integer texel coordinates: x = u W - 1/2.
 * Bilinear weights keep 16 fractional bits (within one level of an 8-bit
 * channel of the exact blend, tests/core/test_texture.c), the level 4 (lambda
 * from the exponent of rho and four bits of log2 of its mantissa by
 * repeated squaring); everything is an integer function of its inputs, so a device
 * samples the same bits as the host.
 */
#include "silk/texture.h"

size_t silk_texture_texel_bytes(silk_texfmt f)
{
    return f == SILK_TEX_RGB888 ? 3 : f == SILK_TEX_RGB565 ? 2 : f == SILK_TEX_PAL8 ? 1 : 0;
}

static int level_dim(int d, int k) { return (d >> k) > 0 ? d >> k : 1; }

int silk_texture_max_levels(int width, int height)
{
    int n = 1;
    while (width > 1 || height > 1) {
        width = level_dim(width, 1);
        height = level_dim(height, 1);
        n++;
    }
    return n;
}

size_t silk_texture_bytes(silk_texfmt f, int width, int height, int levels)
{
    size_t b = silk_texture_texel_bytes(f), total = 0;
    if (!b || width < 1 || height < 1 || width > SILK_TEX_MAX_DIM || height > SILK_TEX_MAX_DIM || levels < 1 ||
        levels > silk_texture_max_levels(width, height))
        return 0;
    for (int k = 0; k < levels; k++) total += (size_t)level_dim(width, k) * (size_t)level_dim(height, k) * b;
    return total;
}

/* Byte offset of level k. */
static size_t level_offset(const silk_texture *t, int k)
{
    return k == 0 ? 0 : silk_texture_bytes((silk_texfmt)t->format, t->width, t->height, k);
}

static uint32_t fetch(const silk_texture *t, const uint8_t *lv, int w, int x, int y)
{
    size_t i = (size_t)y * (size_t)w + (size_t)x;
    switch (t->format) {
    case SILK_TEX_RGB565: {
        uint32_t p = (uint32_t)lv[2 * i] | (uint32_t)lv[2 * i + 1] << 8;
        uint32_t r = p >> 11, g = (p >> 5) & 63, b = p & 31;
        return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 | (b << 3 | b >> 2);
    }
    case SILK_TEX_PAL8:
        return t->palette ? t->palette[lv[i]] & 0xffffff : 0;
    default:
        return (uint32_t)lv[3 * i] << 16 | (uint32_t)lv[3 * i + 1] << 8 | lv[3 * i + 2];
    }
}

static void store(const silk_texture *t, uint8_t *lv, size_t i, uint32_t rgb)
{
    uint32_t r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
    switch (t->format) {
    case SILK_TEX_RGB565: {
        uint32_t p = ((r * 31 + 127) / 255) << 11 | ((g * 63 + 127) / 255) << 5 | ((b * 31 + 127) / 255);
        lv[2 * i] = (uint8_t)p;
        lv[2 * i + 1] = (uint8_t)(p >> 8);
        break;
    }
    case SILK_TEX_PAL8: {
        uint32_t best = 0, bestd = UINT32_MAX;
        for (uint32_t k = 0; t->palette && k < 256; k++) {
            int32_t dr = (int32_t)(t->palette[k] >> 16 & 0xff) - (int32_t)r;
            int32_t dg = (int32_t)(t->palette[k] >> 8 & 0xff) - (int32_t)g;
            int32_t db = (int32_t)(t->palette[k] & 0xff) - (int32_t)b;
            uint32_t d = (uint32_t)(dr * dr + dg * dg + db * db);
            if (d < bestd) bestd = d, best = k;
        }
        lv[i] = (uint8_t)best;
        break;
    }
    default:
        lv[3 * i] = (uint8_t)r;
        lv[3 * i + 1] = (uint8_t)g;
        lv[3 * i + 2] = (uint8_t)b;
        break;
    }
}

void silk_texture_encode(const silk_texture *t, uint8_t *pixels, const uint8_t *rgb)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++)
        store(t, pixels, i, (uint32_t)rgb[3 * i] << 16 | (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2]);
}

void silk_texture_build_mipmaps(silk_texture *t, uint8_t *pixels)
{
    for (int k = 1; k < t->levels; k++) {
        int sw = level_dim(t->width, k - 1), sh = level_dim(t->height, k - 1);
        int w = level_dim(t->width, k), h = level_dim(t->height, k);
        const uint8_t *src = pixels + level_offset(t, k - 1);
        uint8_t *dst = pixels + level_offset(t, k);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                /* the 2x2 block above; a side of length 1 repeats its texel */
                int x0 = 2 * x < sw ? 2 * x : sw - 1, x1 = 2 * x + 1 < sw ? 2 * x + 1 : x0;
                int y0 = 2 * y < sh ? 2 * y : sh - 1, y1 = 2 * y + 1 < sh ? 2 * y + 1 : y0;
                uint32_t c[4] = { fetch(t, src, sw, x0, y0), fetch(t, src, sw, x1, y0), fetch(t, src, sw, x0, y1),
                                  fetch(t, src, sw, x1, y1) };
                uint32_t out = 0;
                for (int s = 0; s <= 16; s += 8)
                    out |= (((c[0] >> s & 0xff) + (c[1] >> s & 0xff) + (c[2] >> s & 0xff) + (c[3] >> s & 0xff) + 2) / 4)
                           << s;
                store(t, dst, (size_t)y * (size_t)w + (size_t)x, out);
            }
    }
}

/* Texel index i on a side of n texels under the wrap mode. */
static int wrap(int64_t i, int n, int mode)
{
    if (mode == SILK_TEX_CLAMP) return i < 0 ? 0 : (i >= n ? n - 1 : (int)i);
    int64_t r = i % n;
    return (int)(r < 0 ? r + n : r);
}

/* c0 + (c1 - c0) f / 2^bits per channel, rounded. */
static uint32_t mix(uint32_t c0, uint32_t c1, int32_t f, int bits)
{
    uint32_t out = 0;
    for (int s = 0; s <= 16; s += 8) {
        int32_t a = (int32_t)(c0 >> s & 0xff), b = (int32_t)(c1 >> s & 0xff);
        out |= (uint32_t)(a + (((b - a) * f + (1 << (bits - 1))) >> bits)) << s;
    }
    return out;
}

static uint32_t sample_level(const silk_texture *t, int k, silk_fx u, silk_fx v)
{
    int w = level_dim(t->width, k), h = level_dim(t->height, k);
    const uint8_t *lv = t->pixels + level_offset(t, k);
    /* texel coordinates in Q16.16; v runs upwards, rows downwards */
    int64_t x = (int64_t)u * w, y = ((int64_t)SILK_FX_ONE - v) * h;
    if (t->filter == SILK_TEX_NEAREST)
        return fetch(t, lv, w, wrap(x >> 16, w, t->wrap), wrap(y >> 16, h, t->wrap));
    x -= SILK_FX_HALF;
    y -= SILK_FX_HALF;
    int64_t xi = x >> 16, yi = y >> 16;
    int32_t fx = (int32_t)(x & 0xffff), fy = (int32_t)(y & 0xffff);
    int x0 = wrap(xi, w, t->wrap), x1 = wrap(xi + 1, w, t->wrap);
    int y0 = wrap(yi, h, t->wrap), y1 = wrap(yi + 1, h, t->wrap);
    /* the rows blended with 8 extra bits kept, then the columns */
    int64_t c[3];
    uint32_t t00 = fetch(t, lv, w, x0, y0), t10 = fetch(t, lv, w, x1, y0);
    uint32_t t01 = fetch(t, lv, w, x0, y1), t11 = fetch(t, lv, w, x1, y1);
    uint32_t out = 0;
    for (int k = 0; k < 3; k++) {
        int s = 16 - 8 * k;
        int64_t top = ((int64_t)(t00 >> s & 0xff) << 16) + ((int64_t)(t10 >> s & 0xff) - (t00 >> s & 0xff)) * fx;
        int64_t bot = ((int64_t)(t01 >> s & 0xff) << 16) + ((int64_t)(t11 >> s & 0xff) - (t01 >> s & 0xff)) * fx;
        c[k] = ((top << 16) + (bot - top) * fy + ((int64_t)1 << 31)) >> 32;
        out |= (uint32_t)c[k] << s;
    }
    return out;
}

uint32_t silk_texture_sample(const silk_texture *t, silk_fx u, silk_fx v, silk_fx du, silk_fx dv)
{
    if (!t || !t->pixels || t->width < 1 || t->height < 1) return 0xffffff;
    /* rho: texels per pixel along the faster-moving coordinate, Q16.16 */
    int64_t ru = (int64_t)(du < 0 ? -(int64_t)du : du) * t->width;
    int64_t rv = (int64_t)(dv < 0 ? -(int64_t)dv : dv) * t->height;
    int64_t rho = ru > rv ? ru : rv;
    int levels = t->levels < 1 ? 1 : t->levels;
    if (levels == 1 || rho <= SILK_FX_ONE) return sample_level(t, 0, u, v);
    /* lambda = log2 rho in Q4: the exponent, then four bits of the
     * fraction by squaring the mantissa m in [1, 2): each squaring that
     * reaches 2 is a 1 bit (then halve) */
    int b = 0;
    while ((rho >> (b + 1)) != 0) b++;
    int64_t m = rho >> (b - 16);   /* Q16 in [1, 2) */
    int lod = b - 16;
    for (int i = 0; i < 4; i++) {
        m = (m * m) >> 16;
        lod = 2 * lod + (m >= 2 * SILK_FX_ONE);
        if (m >= 2 * SILK_FX_ONE) m >>= 1;
    }
    int k = lod >> 4, f = lod & 15;
    if (k >= levels - 1) return sample_level(t, levels - 1, u, v);
    if (t->filter == SILK_TEX_NEAREST) return sample_level(t, f >= 8 ? k + 1 : k, u, v);
    uint32_t c0 = sample_level(t, k, u, v);
    return f ? mix(c0, sample_level(t, k + 1, u, v), f, 4) : c0;
}
