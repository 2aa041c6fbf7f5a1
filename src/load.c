/*
 * load.c - choosing the mesh reader, the load options, and what the OBJ and
 * PLY readers share: model coordinates scaled as decimals and rounded once
 * to Q16.16, the fixed-point range check with a --scale suggestion, IEEE-754
 * bits decoded without floating point, and the arena-size report.
 *
 * No paper equation lives here; this is the input side of section III: the
 * coarse mesh M the rest of silk smooths.
 */
#include <string.h>
#include "load.h"
#include "silk/model.h"
#include "silk/compact.h"

/* The dihedral angle above which an edge is a crease (docs/formats.md). */
const silk_fx SILK_DEFAULT_CREASE_DEG = SILK_FX_C(60, 1);

void silk_load_opts_default(silk_load_opts *o)
{
    o->scale.mant = 1;
    o->scale.exp10 = 0;
    o->crease_deg = SILK_DEFAULT_CREASE_DEG;
    o->normals = SILK_NORMALS_AUTO;
    o->orient = SILK_ORIENT_FIX;
    o->part = SILK_PART_COARSE;
}

/* ---- choosing the reader --------------------------------------------------- */

static int starts_with(const unsigned char *p, size_t len, const char *magic, size_t n)
{
    return len >= n && memcmp(p, magic, n) == 0;
}

/* Whether the text [p, p+len) contains word (a short ASCII string). */
static int contains(const unsigned char *p, size_t len, const char *word)
{
    size_t n = strlen(word);
    for (size_t i = 0; i + n <= len; i++)
        if (p[i] == (unsigned char)word[0] && memcmp(p + i, word, n) == 0) return 1;
    return 0;
}

/* OFF's first keyword: [ST][C][N][4][n]OFF, e.g. OFF, COFF, NOFF, STCOFF. */
static int is_off(const unsigned char *p, size_t len)
{
    static const char prefix[] = "STCN4n";
    size_t i = 0, k = 0;
    while (i < len && k < sizeof prefix - 1) {
        if (p[i] == (unsigned char)prefix[k]) i++;
        k++;
    }
    if (!starts_with(p + i, len - i, "OFF", 3)) return 0;
    i += 3;
    return i == len || p[i] == ' ' || p[i] == '\t' || p[i] == '\r' || p[i] == '\n';
}

/* Written after the name of a mesh format silk does not read. */
#define CONVERT " is not supported: convert it to OBJ, PLY or STL"

static const char binary_data[] = "not a mesh file (binary data); silk reads OBJ, PLY and STL";

/* The line for a file in a format silk does not read, told by its first
 * bytes, or NULL. */
static const char *unsupported(const unsigned char *p, size_t len)
{
    static const struct { const char *magic; size_t n; const char *what; } magic[] = {
        { "glTF", 4, "binary glTF (GLB)" CONVERT },
        { "Kaydara FBX Binary", 18, "FBX" CONVERT },
        { "; FBX", 5, "FBX" CONVERT },
        { "\x1f\x8b", 2, "the file is gzip-compressed: decompress it first" },
        { "PK\x03\x04", 4, "the file is a zip archive: extract the mesh from it first" },
        { "PK\x05\x06", 4, "the file is an empty zip archive" },
        { "\xfd" "7zXZ\x00", 6, "the file is xz-compressed: decompress it first" },
        { "\x28\xb5\x2f\xfd", 4, "the file is zstd-compressed: decompress it first" },
        { "7z\xbc\xaf\x27\x1c", 6, "the file is a 7z archive: extract the mesh from it first" },
    };
    for (size_t i = 0; i < sizeof magic / sizeof magic[0]; i++)
        if (starts_with(p, len, magic[i].magic, magic[i].n)) return magic[i].what;
    if (len >= 4 && p[0] == 'B' && p[1] == 'Z' && p[2] == 'h' && p[3] >= '1' && p[3] <= '9')
        return "the file is bzip2-compressed: decompress it first";
    /* A 3DS file is one main chunk, id 0x4D4D, whose length covers the file. */
    if (len >= 6 && p[0] == 0x4D && p[1] == 0x4D) {
        uint32_t n = (uint32_t)p[2] | (uint32_t)p[3] << 8 | (uint32_t)p[4] << 16 | (uint32_t)p[5] << 24;
        if (n >= 6 && n <= len) return "3DS" CONVERT;
    }
    size_t i = 0;
    if (starts_with(p, len, "\xEF\xBB\xBF", 3)) i = 3;
    while (i < len && (p[i] == ' ' || p[i] == '\t' || p[i] == '\r' || p[i] == '\n')) i++;
    if (i < len && p[i] == '{')
        return contains(p + i, len - i, "\"asset\"") ? "glTF" CONVERT : "JSON" CONVERT;
    if (is_off(p + i, len - i)) return "OFF" CONVERT;
    /* Binary data on the first line: no text mesh starts so. */
    for (size_t j = 0; j < len && j < 512 && p[j] != '\n'; j++)
        if (!silk_ld_text_byte(p[j])) return binary_data;
    return NULL;
}

static int name_ends_stl(const char *name)
{
    size_t n = name ? strlen(name) : 0;
    return n >= 4 && name[n - 4] == '.' && (name[n - 3] | 0x20) == 's' && (name[n - 2] | 0x20) == 't' &&
           (name[n - 1] | 0x20) == 'l';
}

silk_status silk_load_mesh(const void *data, size_t len, const char *name,
                           const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err)
{
    const unsigned char *p = data;
    if (!data) return silk_load_obj(data, len, name, opts, a, out, err);   /* reports it */
    if (silk_is_model(data, len)) return silk_load_model(data, len, name, opts, a, out, err);
    if (silk_is_compact(data, len)) return silk_compact_mesh(data, len, name, out, err);   /* read in place */
    if (len >= 4 && memcmp(p, "ply", 3) == 0 && (p[3] == '\n' || p[3] == '\r'))
        return silk_load_ply(data, len, name, opts, a, out, err);
    /* A binary STL has exactly the size its header gives; an OBJ of that
     * size would need its bytes 80..83, read as that count, to match. */
    if (silk_ld_stl_binary_size(data, len) || silk_ld_stl_solid(data, len))
        return silk_load_stl(data, len, name, opts, a, out, err);
    /* Binary data named .stl is taken for a damaged binary STL. */
    const char *what = unsupported(p, len);
    if (what == binary_data && name_ends_stl(name)) return silk_load_stl(data, len, name, opts, a, out, err);
    if (what) {
        if (out) memset(out, 0, sizeof *out);
        return silk_fail(err, SILK_ERR_PARSE, name ? name : "mesh", 0, "%s", what);
    }
    return silk_load_obj(data, len, name, opts, a, out, err);
}

/* ---- decimals ---------------------------------------------------------------- */

static const uint64_t pow10_u64[20] = {
    1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull, 1000000ull, 10000000ull,
    100000000ull, 1000000000ull, 10000000000ull, 100000000000ull, 1000000000000ull,
    10000000000000ull, 100000000000000ull, 1000000000000000ull, 10000000000000000ull,
    100000000000000000ull, 1000000000000000000ull, 10000000000000000000ull
};
#define DEC_LIMIT 1000000000000000000ull   /* mantissas stay below 10^18 */

static int ndigits(uint64_t u)
{
    int n = 1;
    while (n < 20 && u >= pow10_u64[n]) n++;
    return n;
}

static uint64_t mag_u64(int64_t m)
{
    return m < 0 ? (uint64_t)0 - (uint64_t)m : (uint64_t)m;
}

/* Order of magnitude: |d| is in [10^(k-1), 10^k).  d must be nonzero. */
static int64_t dec_order(silk_decimal d)
{
    return ndigits(mag_u64(d.mant)) + (int64_t)d.exp10;
}

static int dec_cmp_mag(silk_decimal a, silk_decimal b)
{
    uint64_t ua = mag_u64(a.mant), ub = mag_u64(b.mant);
    if (ua == 0 || ub == 0) return (ua != 0) - (ub != 0);
    int64_t oa = dec_order(a), ob = dec_order(b);
    if (oa != ob) return oa < ob ? -1 : 1;
    /* Same order: line both mantissas up to 19 digits, exactly. */
    ua *= pow10_u64[19 - ndigits(ua)];
    ub *= pow10_u64[19 - ndigits(ub)];
    return (ua > ub) - (ua < ub);
}

int silk_ld_dec_cmp(silk_decimal a, silk_decimal b)
{
    int sa = (a.mant > 0) - (a.mant < 0), sb = (b.mant > 0) - (b.mant < 0);
    if (sa != sb) return sa < sb ? -1 : 1;
    if (sa == 0) return 0;
    int r = dec_cmp_mag(a, b);
    return sa > 0 ? r : -r;
}

/* a - b to about 17 digits: enough for a bounding-box extent. */
static silk_decimal dec_sub(silk_decimal a, silk_decimal b)
{
    b.mant = -b.mant;
    if (a.mant == 0) return b;
    if (b.mant == 0) return a;
    if (a.exp10 < b.exp10) { silk_decimal t = a; a = b; b = t; }
    while (a.exp10 > b.exp10 && mag_u64(a.mant) < DEC_LIMIT / 10) { a.mant *= 10; a.exp10--; }
    while (a.exp10 > b.exp10 && b.mant != 0) { b.mant /= 10; b.exp10++; }
    silk_decimal r = { a.mant + b.mant, a.exp10 };
    return r;
}

/* |d| rounded to an integer count of 10^t (half up). */
static uint64_t dec_units(silk_decimal d, int64_t t)
{
    uint64_t u = mag_u64(d.mant);
    int64_t s = (int64_t)d.exp10 - t;
    if (s >= 0) return s > 19 ? UINT64_MAX : u * pow10_u64[s];
    if (-s > 19) return 0;
    uint64_t q = pow10_u64[-s];
    return u / q + (u % q >= q / 2 + q % 2 ? 1 : 0);
}

char *silk_ld_dec_format(silk_decimal d, int sig, char *buf, size_t n)
{
    char digits[24];
    size_t o = 0;
    uint64_t u = mag_u64(d.mant);
    int64_t e = d.exp10;
    if (n == 0) return buf;
    buf[0] = '\0';
    if (sig < 1) sig = 1;
    if (sig > 18) sig = 18;
    if (u == 0) { strncpy(buf, "0.0", n - 1); buf[n - 1] = '\0'; return buf; }
    int nd = ndigits(u), rounded = 0;
    if (nd > sig) {
        uint64_t q = pow10_u64[nd - sig];
        rounded = u % q != 0;
        u = (u + q / 2) / q;
        e += nd - sig;
        if (u >= pow10_u64[sig]) { u /= 10; e++; }
    }
    while (u % 10 == 0) { u /= 10; e++; }
    nd = ndigits(u);
    for (int i = nd - 1; i >= 0; i--) { digits[i] = (char)('0' + u % 10); u /= 10; }
    digits[nd] = '\0';
    int64_t order = nd + e;                 /* digits before the decimal point */
    char tmp[64];
    if (d.mant < 0) tmp[o++] = '-';
    /* Fixed notation only when every integer digit shown is a real one. */
    if (order > 15 || (rounded && order > sig) || order < -3) {
        tmp[o++] = digits[0];
        if (nd > 1) { tmp[o++] = '.'; memcpy(tmp + o, digits + 1, (size_t)nd - 1); o += (size_t)nd - 1; }
        int64_t x = order - 1;
        tmp[o++] = 'e';
        tmp[o++] = x < 0 ? '-' : '+';
        if (x < 0) x = -x;
        char xb[24]; int xn = 0;
        do { xb[xn++] = (char)('0' + x % 10); x /= 10; } while (x && xn < 20);
        while (xn) tmp[o++] = xb[--xn];
    } else if (e >= 0) {
        memcpy(tmp + o, digits, (size_t)nd); o += (size_t)nd;
        for (int64_t i = 0; i < e; i++) tmp[o++] = '0';
        tmp[o++] = '.'; tmp[o++] = '0';
    } else if (order > 0) {
        memcpy(tmp + o, digits, (size_t)order); o += (size_t)order;
        tmp[o++] = '.';
        memcpy(tmp + o, digits + order, (size_t)(nd - order)); o += (size_t)(nd - order);
    } else {
        tmp[o++] = '0'; tmp[o++] = '.';
        for (int64_t i = 0; i < -order; i++) tmp[o++] = '0';
        memcpy(tmp + o, digits, (size_t)nd); o += (size_t)nd;
    }
    tmp[o] = '\0';
    strncpy(buf, tmp, n - 1);
    buf[n - 1] = '\0';
    return buf;
}

/* 10^k as a --scale argument: "100", "0.01", "1e-27". */
static char *format_pow10(int64_t k, char *buf, size_t n)
{
    silk_decimal f = { 1, (int32_t)k };
    if (k < 0 || k > 15) return silk_ld_dec_format(f, 1, buf, n);
    char tmp[24];
    tmp[0] = '1';
    for (int64_t i = 0; i < k; i++) tmp[1 + i] = '0';
    tmp[1 + k] = '\0';
    strncpy(buf, tmp, n - 1);
    buf[n - 1] = '\0';
    return buf;
}

/* ---- coordinates ------------------------------------------------------------- */

void silk_ld_coords_init(silk_ld_coords *c, const silk_load_opts *o)
{
    static const silk_decimal one = { 1, 0 };
    memset(c, 0, sizeof *c);
    c->scale = o->scale;
    c->unit_scale = silk_ld_dec_cmp(o->scale, one) == 0;
}

void silk_ld_coord(silk_ld_coords *c, silk_decimal raw, const silk_fx *exact, int axis,
                   uint32_t line, uint32_t vertex, silk_fx *out)
{
    int first = !(c->have & (1u << axis));
    if (first || silk_ld_dec_cmp(raw, c->lo[axis]) < 0) c->lo[axis] = raw;
    if (first || silk_ld_dec_cmp(raw, c->hi[axis]) > 0) c->hi[axis] = raw;
    c->have |= 1u << axis;
    c->count++;

    silk_decimal scaled = c->unit_scale ? raw : silk_decimal_mul(raw, c->scale);
    silk_fx v = 0;
    int r = 0;
    if (c->unit_scale && exact) v = *exact;
    else r = silk_decimal_to_fx(scaled, &v);
    if (r != 0 || v > SILK_COORD_MAX || v < -SILK_COORD_MAX) {
        if (!c->bad) {
            c->bad = 1;
            c->bad_line = line;
            c->bad_vertex = vertex;
            c->bad_value = scaled;
        }
        v = 0;
    }
    *out = v;
}

/* Bounding-box diagonal of the raw coordinates, to about 9 digits. */
static silk_decimal raw_diagonal(const silk_ld_coords *c)
{
    silk_decimal ext[3];
    int64_t top = INT64_MIN;
    for (int i = 0; i < 3; i++) {
        ext[i] = dec_sub(c->hi[i], c->lo[i]);
        if (ext[i].mant != 0 && dec_order(ext[i]) > top) top = dec_order(ext[i]);
    }
    silk_decimal d = { 0, 0 };
    if (top == INT64_MIN) return d;
    int64_t t = top - 9;          /* each extent becomes at most 10^9 units */
    uint64_t sum = 0;
    for (int i = 0; i < 3; i++) {
        uint64_t u = ext[i].mant ? dec_units(ext[i], t) : 0;
        sum += u * u;
    }
    d.mant = silk_isqrt64(sum);
    d.exp10 = (int32_t)t;
    return d;
}

/* The largest |coordinate| of the raw bounding box. */
static silk_decimal raw_max_abs(const silk_ld_coords *c)
{
    silk_decimal m = { 0, 0 };
    for (int i = 0; i < 3; i++) {
        if (dec_cmp_mag(c->lo[i], m) > 0) m = c->lo[i];
        if (dec_cmp_mag(c->hi[i], m) > 0) m = c->hi[i];
    }
    m.mant = (int64_t)mag_u64(m.mant);
    return m;
}

silk_status silk_ld_coords_finish(const silk_ld_coords *c, const char *name, silk_error *err)
{
    static const silk_decimal size_min = { 625, -4 };      /* SILK_SIZE_MIN, 1/16 */
    const silk_decimal coord_max = { SILK_COORD_MAX >> SILK_FX_SHIFT, 0 };
    char vbuf[40], sbuf[40];
    if (c->count == 0) return SILK_OK;

    silk_decimal maxabs = raw_max_abs(c);
    if (c->bad) {
        /* The largest power of ten that brings every coordinate in range. */
        int64_t k = 4 - dec_order(maxabs);
        silk_decimal t = { maxabs.mant, (int32_t)(maxabs.exp10 + k) };
        if (silk_ld_dec_cmp(t, coord_max) > 0) k--;
        /* Six digits would round a value just past the limit onto it
         * ("1024.0" for 1024.00002): such a value is shown in full. */
        const silk_decimal near_limit = { (SILK_COORD_MAX >> SILK_FX_SHIFT) * 10 + 5, -1 };
        silk_ld_dec_format(c->bad_value, dec_cmp_mag(c->bad_value, near_limit) < 0 ? 18 : 6, vbuf, sizeof vbuf);
        format_pow10(k, sbuf, sizeof sbuf);
        if (c->bad_line)
            return silk_fail(err, SILK_ERR_RANGE, name, c->bad_line,
                             "coordinate %s is outside the fixed-point range (+-%d); "
                             "scale the model with --scale %s", vbuf, (int)coord_max.mant, sbuf);
        return silk_fail(err, SILK_ERR_RANGE, name, 0,
                         "vertex %lu: coordinate %s is outside the fixed-point range (+-%d); "
                         "scale the model with --scale %s", (unsigned long)c->bad_vertex, vbuf,
                         (int)coord_max.mant, sbuf);
    }

    silk_decimal diag = raw_diagonal(c);
    silk_decimal size = c->unit_scale ? diag : silk_decimal_mul(diag, c->scale);
    if (silk_ld_dec_cmp(size, size_min) >= 0) return SILK_OK;
    if (diag.mant == 0)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "model has no size (all vertices are at one point)");
    /* The smallest power of ten that makes the model at least SILK_SIZE_MIN. */
    int64_t k = -dec_order(diag);
    silk_decimal t = { diag.mant, (int32_t)(diag.exp10 + k - 1) };
    if (silk_ld_dec_cmp(t, size_min) >= 0) k--;
    silk_decimal far = { maxabs.mant, (int32_t)(maxabs.exp10 + k) };
    silk_ld_dec_format(size, 3, vbuf, sizeof vbuf);
    if (silk_ld_dec_cmp(far, coord_max) > 0) {
        silk_ld_dec_format(silk_decimal_mul(maxabs, c->scale), 9, sbuf, sizeof sbuf);
        return silk_fail(err, SILK_ERR_RANGE, name, 0,
                         "model is too small for fixed-point precision (size %s) this far from "
                         "the origin (coordinates up to %s); move it to the origin", vbuf, sbuf);
    }
    format_pow10(k, sbuf, sizeof sbuf);
    return silk_fail(err, SILK_ERR_RANGE, name, 0,
                     "model is too small for fixed-point precision (size %s); "
                     "scale it up with --scale %s", vbuf, sbuf);
}

int silk_ld_color_channel(silk_decimal d, int max, uint32_t *out)
{
    silk_fx v;
    if (silk_decimal_to_fx(d, &v) != 0 || v < 0 || v > silk_fx_from_int(max)) return -1;
    int64_t c = max == 1 ? ((int64_t)v * 255 + SILK_FX_HALF) >> 16 : ((int64_t)v + SILK_FX_HALF) >> 16;
    *out = (uint32_t)c;
    return 0;
}

int silk_ld_direction(const silk_decimal d[3], silk_vec3 *out)
{
    int64_t top = INT64_MIN;
    for (int i = 0; i < 3; i++)
        if (d[i].mant != 0 && dec_order(d[i]) > top) top = dec_order(d[i]);
    *out = silk_v3(0, 0, 0);
    if (top == INT64_MIN) return -1;
    /* Bring the largest component into [0.1, 1): all three then fit. */
    silk_fx c[3];
    for (int i = 0; i < 3; i++) {
        silk_decimal s = { d[i].mant, 0 };
        int64_t e = (int64_t)d[i].exp10 - top;
        if (d[i].mant == 0 || e < -400) { c[i] = 0; continue; }
        s.exp10 = (int32_t)e;
        if (silk_decimal_to_fx(s, &c[i]) != 0) c[i] = 0;
    }
    if (!silk_v3_normalize(silk_v3(c[0], c[1], c[2]), out)) return -1;
    return 0;
}

/* ---- IEEE-754 without floating point ----------------------------------------- */

static int bit_length(uint64_t m)
{
    int n = 0;
    while (m) { n++; m >>= 1; }
    return n;
}

/* v = (-1)^neg * m * 2^e2, m < 2^53. */
static void binary_to_decimal(int neg, uint64_t m, int e2, silk_decimal *d)
{
    int64_t e10 = 0;
    while (m && !(m & 1)) { m >>= 1; e2++; }
    /* Each step trades a power of two for a power of ten, dropping one
     * decimal digit (rounded) whenever the mantissa would pass 18 digits. */
    while (e2 > 0) {
        if (m < DEC_LIMIT / 2) { m <<= 1; e2--; }
        else { m = (m + 5) / 10; e10++; }
    }
    while (e2 < 0) {
        if (m < DEC_LIMIT / 5) { m *= 5; e10--; e2++; }   /* m * 2^-1 = m * 5 / 10 */
        else { m = (m + 5) / 10; e10++; }
    }
    while (m >= DEC_LIMIT) { m = (m + 5) / 10; e10++; }
    d->mant = neg ? -(int64_t)m : (int64_t)m;
    d->exp10 = (int32_t)e10;
}

static int from_binary(uint64_t bits, int mbits, int ebits, silk_decimal *d, silk_fx *fx, int *fits)
{
    int neg = (int)((bits >> (mbits + ebits)) & 1);
    int bexp = (int)((bits >> mbits) & ((1u << ebits) - 1));
    uint64_t m = bits & (((uint64_t)1 << mbits) - 1);
    int bias = (1 << (ebits - 1)) - 1;
    int e2;
    if (bexp == (1 << ebits) - 1) return -1;          /* infinity or NaN */
    if (bexp == 0) e2 = 1 - bias - mbits;             /* subnormal */
    else { m |= (uint64_t)1 << mbits; e2 = bexp - bias - mbits; }

    d->mant = 0; d->exp10 = 0;
    *fx = 0; *fits = 1;
    if (m == 0) return 0;

    /* Q16.16 straight from the bits: m * 2^(e2+16), rounded half away from zero. */
    int s = e2 + SILK_FX_SHIFT;
    uint64_t q;
    if (s >= 0) {
        if (bit_length(m) + s > 31) { *fits = 0; q = 0; }
        else q = m << s;
    } else if (-s >= 64) {
        q = 0;
    } else {
        q = (m >> -s) + ((m >> (-s - 1)) & 1);
    }
    if (q > (uint64_t)SILK_FX_MAX) { *fits = 0; q = 0; }
    *fx = neg ? -(silk_fx)q : (silk_fx)q;
    binary_to_decimal(neg, m, e2, d);
    return 0;
}

int silk_ld_from_f32(uint32_t bits, silk_decimal *d, silk_fx *fx, int *fits)
{
    return from_binary(bits, 23, 8, d, fx, fits);
}

int silk_ld_from_f64(uint64_t bits, silk_decimal *d, silk_fx *fx, int *fits)
{
    return from_binary(bits, 52, 11, d, fx, fits);
}

/* ---- text ---------------------------------------------------------------------- */

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

int silk_ld_token(const char **p, const char *e, const char **tb, size_t *tn)
{
    const char *s = *p;
    while (s < e && is_space(*s)) s++;
    if (s >= e || *s == '#') { *p = e; return 0; }
    *tb = s;
    while (s < e && !is_space(*s)) s++;
    *tn = (size_t)(s - *tb);
    *p = s;
    return 1;
}

int silk_ld_token_is(const char *t, size_t n, const char *word)
{
    return strlen(word) == n && memcmp(t, word, n) == 0;
}

silk_status silk_ld_parse_decimal(const char *t, size_t n, silk_decimal *d,
                                  const char *name, uint32_t line, silk_error *err)
{
    char buf[SILK_LD_MAX_TOKEN + 1], q[48];
    const char *end;
    silk_ld_quote(t, n, q, sizeof q);
    if (n > SILK_LD_MAX_TOKEN)
        return silk_fail(err, SILK_ERR_PARSE, name, line, "number '%s' is too long", q);
    /* The parser wants a terminated string; the buffer is not one. */
    memcpy(buf, t, n);
    buf[n] = '\0';
    int rc = silk_decimal_parse(buf, &end, d);
    if (rc == -2)
        return silk_fail(err, SILK_ERR_RANGE, name, line, "number '%s' is out of range", q);
    if (rc != 0 || end != buf + n) {
        const char *s = buf + (buf[0] == '-' || buf[0] == '+');
        if ((s[0] | 0x20) == 'n' || (s[0] | 0x20) == 'i')
            return silk_fail(err, SILK_ERR_PARSE, name, line, "'%s' is not a finite number", q);
        return silk_fail(err, SILK_ERR_PARSE, name, line, "bad number '%s'", q);
    }
    return SILK_OK;
}

/* ---- messages and memory ------------------------------------------------------- */

silk_status silk_ld_start(const char *fn, const void *data, size_t len, const char **name,
                          const silk_load_opts **opts, silk_load_opts *defaults, silk_arena *a, silk_mesh *out,
                          silk_error *err)
{
    if (!*name) *name = "mesh";
    if (!*opts) { silk_load_opts_default(defaults); *opts = defaults; }
    if (!a || !out || (!data && len))
        return silk_fail(err, SILK_ERR_ARG, *name, 0, "%s: missing buffer, arena or output", fn);
    if ((*opts)->scale.mant <= 0)
        return silk_fail(err, SILK_ERR_ARG, *name, 0, "scale must be positive");
    memset(out, 0, sizeof *out);
    return SILK_OK;
}

const char *silk_ld_quote(const char *s, size_t n, char *buf, size_t bufsize)
{
    size_t keep = n > 32 ? 32 : n, o = 0;
    if (bufsize < 40) { if (bufsize) buf[0] = '\0'; return buf; }
    for (size_t i = 0; i < keep; i++) {
        unsigned char ch = (unsigned char)s[i];
        buf[o++] = (ch < 0x20 || ch == 0x7f) ? '?' : (char)ch;
    }
    if (keep < n) { memcpy(buf + o, "...", 3); o += 3; }
    buf[o] = '\0';
    return buf;
}

int silk_ld_need(size_t *total, uint64_t count, size_t size)
{
    if (size && count > (uint64_t)(SIZE_MAX / size)) return 0;
    size_t n = (size_t)count * size;
    if (n == 0) n = 1;
    if (n > SIZE_MAX - (SILK_ARENA_ALIGN - 1)) return 0;
    n = (n + (SILK_ARENA_ALIGN - 1)) & ~(size_t)(SILK_ARENA_ALIGN - 1);
    if (*total > SIZE_MAX - n) return 0;
    *total += n;
    return 1;
}

silk_status silk_ld_nomem(silk_error *err, const char *name, size_t need, const silk_arena *a)
{
    return silk_fail(err, SILK_ERR_NOMEM, name, 0,
                     "arena too small: loading needs %zu bytes, %zu are free",
                     need, silk_arena_free_bytes(a));
}

void silk_ld_arena_restore(silk_arena *a, const silk_arena *saved)
{
    a->bottom = saved->bottom;
    a->top = saved->top;
    memcpy(a->used, saved->used, sizeof a->used);
    memcpy(a->top_used, saved->top_used, sizeof a->top_used);
}
