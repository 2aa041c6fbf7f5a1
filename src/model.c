/*
 * model.c - reading a prepared model (silk/model.h, docs/formats.md
 * "Prepared models"): the container (header, section table, CRC-32 of
 * each section) and its MESH section, the coarse mesh whose vertices lie
 * on the detailed surface with that surface's normals (the input side of
 * paper section III: the mesh M and the shading normals of III-B).
 *
 * Every field is read byte by byte as little-endian, so the buffer needs
 * no alignment and the result is the same on every host; every count is
 * checked against the bytes present before anything is decoded, and every
 * index against its array, before silk_mesh_build sees it.
 */
#include <string.h>
#include "load.h"
#include "silk/model.h"
#include "silmap_interp.h"
#include "silk/siltex.h"

#define BAD(...) silk_fail(err, SILK_ERR_PARSE, name, 0, __VA_ARGS__)
#define UL(x) ((unsigned long)(x))

/* The fixed part of a MESH section before its arrays. */
#define MESH_HEAD_BYTES 16
/* |n|^2 of a stored normal within 1 +- 1/64, in Q32.32 (as validate.c). */
#define UNIT_SLACK ((int64_t)1 << 26)

static uint32_t rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static uint16_t rd16(const uint8_t *p) { return (uint16_t)(p[0] | p[1] << 8); }
static int32_t rd32s(const uint8_t *p)
{
    uint32_t u = rd32(p);
    return u <= 0x7fffffffu ? (int32_t)u : -(int32_t)(~u) - 1;
}

uint32_t silk_crc32(uint32_t crc, const void *data, size_t len)
{
    const uint8_t *p = data;
    crc = ~crc;
    for (size_t i = 0; i < len; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

int silk_is_model(const void *data, size_t len)
{
    return data && len >= 8 && memcmp(data, SILK_MODEL_MAGIC, 8) == 0;
}

/* "MESH", or "0x..." for a type that is not four printable characters. */
static const char *type_name(uint32_t type, char buf[12])
{
    for (int i = 0; i < 4; i++) {
        unsigned char c = (unsigned char)(type >> (8 * i));
        if (c < 0x21 || c > 0x7e) {
            static const char hex[] = "0123456789abcdef";
            buf[0] = '0', buf[1] = 'x';
            for (int k = 0; k < 8; k++) buf[2 + k] = hex[(type >> (28 - 4 * k)) & 15];
            buf[10] = '\0';
            return buf;
        }
        buf[i] = (char)c;
    }
    buf[4] = '\0';
    return buf;
}

void silk_model_section_at(const silk_model *m, uint32_t i, silk_model_section *out)
{
    const uint8_t *e = m->base + SILK_MODEL_HEADER_BYTES + (size_t)i * SILK_MODEL_ENTRY_BYTES;
    out->type = rd32(e);
    out->flags = rd32(e + 4);
    out->data = m->base + rd32(e + 8);
    out->size = rd32(e + 12);
}

int silk_model_find(const silk_model *m, uint32_t type, silk_model_section *out)
{
    for (uint32_t i = 0; i < m->nsections; i++) {
        silk_model_section_at(m, i, out);
        if (out->type == type) return 1;
    }
    return 0;
}

static int known_type(uint32_t type)
{
    return type == SILK_SECTION_MESH || type == SILK_SECTION_HULL || type == SILK_SECTION_SMAP ||
           type == SILK_SECTION_STEX;
}

silk_status silk_model_open(const void *data, size_t len, const char *name, silk_model *out, silk_error *err)
{
    const uint8_t *p = data;
    if (!name) name = "model";
    memset(out, 0, sizeof *out);
    if (!silk_is_model(data, len)) return BAD("not a prepared model (no silk model signature)");
    if (len < SILK_MODEL_HEADER_BYTES) return BAD("truncated: %lu bytes, the header alone is %u", UL(len), SILK_MODEL_HEADER_BYTES);
    uint32_t major = rd16(p + 8), minor = rd16(p + 10), hsize = rd32(p + 12), fsize = rd32(p + 16);
    uint32_t n = rd32(p + 20), table_crc = rd32(p + 24);
    if (major != SILK_MODEL_VERSION_MAJOR)
        return BAD("format version %lu.%lu; this silk reads version %u", UL(major), UL(minor), SILK_MODEL_VERSION_MAJOR);
    if (hsize != SILK_MODEL_HEADER_BYTES) return BAD("header size %lu, expected %u", UL(hsize), SILK_MODEL_HEADER_BYTES);
    if (fsize != len)
        return BAD("the header says %lu bytes, the file has %lu (truncated or padded)", UL(fsize), UL(len));
    if (rd32(p + 28) != 0) return BAD("reserved header field is not zero");
    if (n == 0 || n > SILK_MODEL_MAX_SECTIONS)
        return BAD("%lu sections (1..%u allowed)", UL(n), SILK_MODEL_MAX_SECTIONS);
    size_t table_end = SILK_MODEL_HEADER_BYTES + (size_t)n * SILK_MODEL_ENTRY_BYTES;
    if (table_end > len) return BAD("truncated: the table of %lu sections ends past the file's end", UL(n));
    if (silk_crc32(0, p + SILK_MODEL_HEADER_BYTES, table_end - SILK_MODEL_HEADER_BYTES) != table_crc)
        return BAD("section table checksum mismatch (the file is damaged)");
    out->base = p;
    out->len = len;
    out->version_major = major;
    out->version_minor = minor;
    out->nsections = n;
    for (uint32_t i = 0; i < n; i++) {
        const uint8_t *e = p + SILK_MODEL_HEADER_BYTES + (size_t)i * SILK_MODEL_ENTRY_BYTES;
        uint32_t type = rd32(e), flags = rd32(e + 4), off = rd32(e + 8), size = rd32(e + 12), crc = rd32(e + 16);
        char tb[12];
        if (off < table_end || off % 4 != 0 || off > len || size > len - off)
            return BAD("section %lu (%s): bytes %lu..%lu lie outside the data (%lu..%lu, 4-byte aligned)", UL(i),
                       type_name(type, tb), UL(off), UL((uint64_t)off + size), UL(table_end), UL(len));
        for (uint32_t j = 0; j < i; j++) {
            const uint8_t *f = p + SILK_MODEL_HEADER_BYTES + (size_t)j * SILK_MODEL_ENTRY_BYTES;
            uint64_t o2 = rd32(f + 8), s2 = rd32(f + 12);
            if ((uint64_t)off < o2 + s2 && o2 < (uint64_t)off + size)
                return BAD("sections %lu and %lu overlap", UL(j), UL(i));
        }
        if (silk_crc32(0, p + off, size) != crc)
            return BAD("section %lu (%s): checksum mismatch (the file is damaged)", UL(i), type_name(type, tb));
        if ((flags & SILK_SECTION_REQUIRED) && !known_type(type))
            return BAD("section %lu (%s) is required but unknown to this silk (a newer one wrote it)", UL(i),
                       type_name(type, tb));
    }
    return SILK_OK;
}

/* The counts of a MESH section and the offsets of its arrays. */
typedef struct mesh_layout {
    uint32_t nverts, ntris, nnormals;
    size_t pos, normal, tri, tri_normal;
} mesh_layout;

static silk_status mesh_layout_of(const silk_model_section *s, const char *sec, const char *name, mesh_layout *l,
                                  silk_error *err)
{
    if (s->size < MESH_HEAD_BYTES) return BAD("%s section of %lu bytes is shorter than its counts", sec, UL(s->size));
    l->nverts = rd32(s->data);
    l->ntris = rd32(s->data + 4);
    l->nnormals = rd32(s->data + 8);
    if (rd32(s->data + 12) != 0) return BAD("%s section: reserved field is not zero", sec);
    if (l->nverts < 3 || l->ntris == 0 || l->nnormals == 0)
        return BAD("%s section: %lu vertices, %lu triangles, %lu normals (an empty mesh)", sec, UL(l->nverts),
                   UL(l->ntris), UL(l->nnormals));
    if ((uint64_t)l->nverts >= (uint64_t)SILK_NO_INDEX || (uint64_t)l->nnormals >= (uint64_t)SILK_NO_INDEX ||
        l->ntris > UINT32_MAX / 3)
        return BAD("%s section: too many elements (%lu vertices, %lu triangles, %lu normals)", sec, UL(l->nverts),
                   UL(l->ntris), UL(l->nnormals));
    uint64_t want = MESH_HEAD_BYTES + 12 * (uint64_t)l->nverts + 12 * (uint64_t)l->nnormals + 24 * (uint64_t)l->ntris;
    if (want != s->size)
        return BAD("%s section: %lu vertices, %lu normals and %lu triangles take %llu bytes, the section has %lu", sec,
                   UL(l->nverts), UL(l->nnormals), UL(l->ntris), (unsigned long long)want, UL(s->size));
    l->pos = MESH_HEAD_BYTES;
    l->normal = l->pos + 12 * (size_t)l->nverts;
    l->tri = l->normal + 12 * (size_t)l->nnormals;
    l->tri_normal = l->tri + 12 * (size_t)l->ntris;
    return SILK_OK;
}

/* Every value of the section is one the mesh builder may take. */
static silk_status mesh_check(const silk_model_section *s, const char *sec, const mesh_layout *l, const char *name,
                              silk_error *err)
{
    const uint8_t *d = s->data;
    silk_fx lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    for (uint32_t v = 0; v < l->nverts; v++)
        for (int k = 0; k < 3; k++) {
            silk_fx c = rd32s(d + l->pos + 12 * (size_t)v + 4 * (size_t)k);
            if (c > SILK_COORD_MAX || c < -SILK_COORD_MAX)
                return BAD("%s section: vertex %lu lies outside +-%d model units", sec, UL(v), (int)(SILK_COORD_MAX >> 16));
            if (v == 0 || c < lo[k]) lo[k] = c;
            if (v == 0 || c > hi[k]) hi[k] = c;
        }
    int64_t diag2 = 0;
    for (int k = 0; k < 3; k++) diag2 += (int64_t)(hi[k] - lo[k]) * (hi[k] - lo[k]);
    if (diag2 < (int64_t)SILK_SIZE_MIN * SILK_SIZE_MIN)
        return BAD("%s section: the model is smaller than 1/16 unit across", sec);
    for (uint32_t i = 0; i < l->nnormals; i++) {
        silk_vec3 n = silk_v3(rd32s(d + l->normal + 12 * (size_t)i), rd32s(d + l->normal + 12 * (size_t)i + 4),
                              rd32s(d + l->normal + 12 * (size_t)i + 8));
        /* components checked first, so the square cannot overflow */
        const silk_fx lim = 2 * SILK_FX_ONE;
        int big = n.x > lim || n.x < -lim || n.y > lim || n.y < -lim || n.z > lim || n.z < -lim;
        int64_t n2 = big ? 0 : silk_v3_dot64(n, n);
        if (n2 < ((int64_t)1 << 32) - UNIT_SLACK || n2 > ((int64_t)1 << 32) + UNIT_SLACK)
            return BAD("%s section: normal %lu is not of unit length", sec, UL(i));
    }
    for (uint32_t c = 0; c < 3 * l->ntris; c++) {
        uint32_t v = rd32(d + l->tri + 4 * (size_t)c), n = rd32(d + l->tri_normal + 4 * (size_t)c);
        if (v >= l->nverts)
            return BAD("%s section: triangle %lu uses vertex %lu of %lu", sec, UL(c / 3), UL(v), UL(l->nverts));
        if (n >= l->nnormals)
            return BAD("%s section: triangle %lu uses normal %lu of %lu", sec, UL(c / 3), UL(n), UL(l->nnormals));
    }
    return SILK_OK;
}

static silk_status smap_check(const silk_model_section *sp, const char *name, silk_silmap *out, silk_error *err);
static silk_status stex_of(const silk_model *m, const silk_model_section *s, const char *name, silk_siltex *out,
                           silk_error *err);

/* The section of opened model m that opts->part draws, laid out and
 * checked into *s and *l, and the model's map and texture checked: a
 * damaged one fails the model however it is drawn, as a damaged mesh does. */
static silk_status mesh_section(const silk_model *m, const silk_load_opts *opts, const char *name,
                                silk_model_section *s, mesh_layout *l, silk_error *err)
{
    /* clip mode draws the hull; the other modes the coarse mesh, or the hull when that is all there is */
    const char *sec = "HULL";
    if (opts->part == SILK_PART_HULL) {
        if (!silk_model_find(m, SILK_SECTION_HULL, s))
            return BAD("no HULL section (prepared without the outer hull clip mode draws)");
    } else if (silk_model_find(m, SILK_SECTION_MESH, s)) {
        sec = "MESH";
    } else if (!silk_model_find(m, SILK_SECTION_HULL, s)) {
        return BAD("no MESH or HULL section (no mesh to draw)");
    }
    silk_status st;
    if ((st = mesh_layout_of(s, sec, name, l, err)) || (st = mesh_check(s, sec, l, name, err))) return st;
    silk_model_section ms;
    silk_silmap map;
    if (silk_model_find(m, SILK_SECTION_SMAP, &ms) && (st = smap_check(&ms, name, &map, err))) return st;
    silk_siltex tex;
    if (SILK_SILTEX_MODE && silk_model_find(m, SILK_SECTION_STEX, &ms) && (st = stex_of(m, &ms, name, &tex, err)))
        return st;
    return SILK_OK;
}

silk_status silk_load_model(const void *data, size_t len, const char *name, const silk_load_opts *opts,
                            silk_arena *a, silk_mesh *out, silk_error *err)
{
    silk_load_opts defaults;
    if (!name) name = "model";
    if (!opts) {
        silk_load_opts_default(&defaults);
        opts = &defaults;
    }
    if (!a || !out || (!data && len))
        return silk_fail(err, SILK_ERR_ARG, name, 0, "silk_load_model: missing buffer, arena or output");
    const silk_decimal one = { 1, 0 };
    if (silk_ld_dec_cmp(opts->scale, one) != 0)
        return silk_fail(err, SILK_ERR_ARG, name, 0, "a prepared model keeps the scale it was prepared with "
                                                      "(give --scale to silk prepare instead)");
    memset(out, 0, sizeof *out);
    silk_model m;
    silk_model_section s;
    mesh_layout l = { 0, 0, 0, 0, 0, 0, 0 };
    silk_status st = silk_model_open(data, len, name, &m, err);
    if (st || (st = mesh_section(&m, opts, name, &s, &l, err))) return st;

    int want_n = opts->normals != SILK_NORMALS_COMPUTE;
    size_t need = 0;
    int ok = silk_ld_need(&need, l.nverts, sizeof(silk_vec3)) && silk_ld_need(&need, 3 * (uint64_t)l.ntris, sizeof(silk_index));
    if (want_n)
        ok = ok && silk_ld_need(&need, l.nnormals, sizeof(silk_vec3)) &&
             silk_ld_need(&need, 3 * (uint64_t)l.ntris, sizeof(silk_index));
    if (!ok || need > silk_arena_free_bytes(a)) return silk_ld_nomem(err, name, ok ? need : SIZE_MAX, a);

    silk_arena saved = *a;
    silk_arena_mark mark = silk_arena_top_mark(a);
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = l.nverts;
    in.ntris = l.ntris;
    in.pos = silk_arena_array(a, l.nverts, sizeof(silk_vec3), SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 3 * (size_t)l.ntris, sizeof(silk_index), SILK_MEM_MESH);
    if (want_n) {
        in.nfile_normals = l.nnormals;
        in.file_normal = silk_arena_array_top(a, l.nnormals, sizeof(silk_vec3), SILK_MEM_LOAD);
        in.tri_file_normal = silk_arena_array_top(a, 3 * (size_t)l.ntris, sizeof(silk_index), SILK_MEM_LOAD);
    }
    const uint8_t *d = s.data;
    for (uint32_t v = 0; v < l.nverts; v++) {
        const uint8_t *q = d + l.pos + 12 * (size_t)v;
        in.pos[v] = silk_v3(rd32s(q), rd32s(q + 4), rd32s(q + 8));
    }
    for (uint32_t c = 0; c < 3 * l.ntris; c++) in.tri[c] = (silk_index)rd32(d + l.tri + 4 * (size_t)c);
    if (want_n) {
        for (uint32_t i = 0; i < l.nnormals; i++) {
            const uint8_t *q = d + l.normal + 12 * (size_t)i;
            in.file_normal[i] = silk_v3(rd32s(q), rd32s(q + 4), rd32s(q + 8));
        }
        for (uint32_t c = 0; c < 3 * l.ntris; c++) in.tri_file_normal[c] = (silk_index)rd32(d + l.tri_normal + 4 * (size_t)c);
    }
    /* The model's normals say where the detailed surface has creases (an
     * edge across which they differ is a feature); the coarse dihedral
     * angle, large wherever the coarse mesh is coarse, is not consulted. */
    silk_load_opts own = *opts;
    if (want_n) own.crease_deg = SILK_FX_C(180, 1);
    st = silk_mesh_build(&in, name, &own, a, out, err);
    silk_arena_top_release(a, &mark);
    if (st != SILK_OK) {
        silk_ld_arena_restore(a, &saved);
        memset(out, 0, sizeof *out);
    }
    return st;
}

/* ---- SMAP: the silhouette map ------------------------------------------------- */

/* The fixed part of an SMAP section before its arrays (docs/formats.md). */
#define SMAP_HEAD_BYTES 36
#define SMAP_VIEW_WORDS 18
/* Image points within +-2^14 pixels, focal lengths below 2^14 pixels:
 * what the interpolation's 64-bit products are sized for. */
#define SMAP_PX_MAX ((silk_fx)16384 << 16)
#define SMAP_FOCAL_MAX ((silk_fx)16383 << 16)

/* The arrays are read in place, so their layout must be this host's. */
_Static_assert(sizeof(silk_silmap_view) == 4 * SMAP_VIEW_WORDS, "silk_silmap_view is 18 words");
_Static_assert(sizeof(silk_vec2) == 8 && sizeof(silk_vec3) == 12, "vectors are packed words");

static int unit_vec(const uint8_t *p)
{
    silk_vec3 n = silk_v3(rd32s(p), rd32s(p + 4), rd32s(p + 8));
    const silk_fx lim = 2 * SILK_FX_ONE;
    if (n.x > lim || n.x < -lim || n.y > lim || n.y < -lim || n.z > lim || n.z < -lim) return 0;
    int64_t n2 = silk_v3_dot64(n, n);
    return n2 >= ((int64_t)1 << 32) - UNIT_SLACK && n2 <= ((int64_t)1 << 32) + UNIT_SLACK;
}

static int in_coords(const uint8_t *p)
{
    for (int k = 0; k < 3; k++)
        if (rd32s(p + 4 * k) > SILK_COORD_MAX || rd32s(p + 4 * k) < -SILK_COORD_MAX) return 0;
    return 1;
}

/* Every count, index and number of an SMAP section, byte by byte (any
 * alignment); the arrays' places on success. */
static silk_status smap_check(const silk_model_section *sp, const char *name, silk_silmap *out, silk_error *err)
{
    const silk_model_section s = *sp;
    const uint8_t *d = s.data;
    if (s.size < SMAP_HEAD_BYTES) return BAD("SMAP section of %lu bytes is shorter than its counts", UL(s.size));
    if (rd32(d) != SILK_SMAP_VERSION)
        return BAD("SMAP section: map version %lu; this silk reads version %u", UL(rd32(d)), SILK_SMAP_VERSION);
    uint32_t nviews = rd32(d + 4), ntris = rd32(d + 8), nloops = rd32(d + 12), npts = rd32(d + 16);
    if (rd32(d + 32) != 0) return BAD("SMAP section: reserved field is not zero");
    if (nviews < 4 || ntris < 4 || nviews > (1u << 20) || ntris > (1u << 21) || nloops > (1u << 24) ||
        npts > (1u << 26))
        return BAD("SMAP section: %lu views, %lu triangles, %lu loops, %lu points (4.. views and triangles, "
                   "at most 2^20 views, 2^21 triangles, 2^24 loops, 2^26 points)",
                   UL(nviews), UL(ntris), UL(nloops), UL(npts));
    uint64_t want = SMAP_HEAD_BYTES + 4 * SMAP_VIEW_WORDS * (uint64_t)nviews + 24 * (uint64_t)ntris +
                    4 * ((uint64_t)nloops + 1) + 8 * (uint64_t)npts;
    if (want != s.size)
        return BAD("SMAP section: %lu views, %lu triangles, %lu loops and %lu points take %llu bytes, the section "
                   "has %lu", UL(nviews), UL(ntris), UL(nloops), UL(npts), (unsigned long long)want, UL(s.size));
    if (!in_coords(d + 20)) return BAD("SMAP section: the centre lies outside +-%d model units", (int)(SILK_COORD_MAX >> 16));
    const uint8_t *views = d + SMAP_HEAD_BYTES, *tri = views + 4 * SMAP_VIEW_WORDS * (size_t)nviews;
    const uint8_t *adj = tri + 12 * (size_t)ntris, *start = adj + 12 * (size_t)ntris;
    const uint8_t *pts = start + 4 * ((size_t)nloops + 1);
    for (uint32_t v = 0; v < nviews; v++) {
        const uint8_t *c = views + 4 * SMAP_VIEW_WORDS * (size_t)v;
        silk_fx focal = rd32s(c + 48), cx = rd32s(c + 52), cy = rd32s(c + 56);
        uint32_t first = rd32(c + 64), n = rd32(c + 68);
        if (!in_coords(c)) return BAD("SMAP section: view %lu's eye lies outside +-%d model units", UL(v),
                                      (int)(SILK_COORD_MAX >> 16));
        if (!unit_vec(c + 12) || !unit_vec(c + 24) || !unit_vec(c + 36))
            return BAD("SMAP section: view %lu's camera axes are not of unit length", UL(v));
        if (focal <= 0 || focal > SMAP_FOCAL_MAX || cx < -SMAP_PX_MAX || cx > SMAP_PX_MAX || cy < -SMAP_PX_MAX ||
            cy > SMAP_PX_MAX)
            return BAD("SMAP section: view %lu's focal length or image centre is out of range", UL(v));
        if (rd32(c + 60) != 0) return BAD("SMAP section: view %lu is not a perspective view", UL(v));
        if (first > nloops || n > nloops - first)
            return BAD("SMAP section: view %lu uses loops %lu..%lu of %lu", UL(v), UL(first), UL((uint64_t)first + n),
                       UL(nloops));
    }
    for (uint32_t c = 0; c < 3 * ntris; c++) {
        uint32_t v = rd32(tri + 4 * (size_t)c), t = rd32(adj + 4 * (size_t)c);
        if (v >= nviews) return BAD("SMAP section: triangle %lu uses view %lu of %lu", UL(c / 3), UL(v), UL(nviews));
        if (t >= ntris && t != UINT32_MAX)
            return BAD("SMAP section: triangle %lu's neighbour %lu is not one of %lu", UL(c / 3), UL(t), UL(ntris));
    }
    for (uint32_t t = 0; t < ntris; t++) {
        uint32_t a = rd32(tri + 12 * (size_t)t), b = rd32(tri + 12 * (size_t)t + 4), c = rd32(tri + 12 * (size_t)t + 8);
        if (a == b || b == c || a == c) return BAD("SMAP section: triangle %lu repeats a view", UL(t));
    }
    if (rd32(start) != 0 || rd32(start + 4 * (size_t)nloops) != npts)
        return BAD("SMAP section: the loops do not start at point 0 and end at point %lu", UL(npts));
    for (uint32_t i = 0; i < nloops; i++)
        if (rd32(start + 4 * (size_t)i + 4) < rd32(start + 4 * (size_t)i) ||
            rd32(start + 4 * (size_t)i + 4) - rd32(start + 4 * (size_t)i) < 3)
            return BAD("SMAP section: loop %lu has fewer than 3 points", UL(i));
    for (uint32_t i = 0; i < 2 * npts; i++) {
        silk_fx c = rd32s(pts + 4 * (size_t)i);
        if (c < -SMAP_PX_MAX || c > SMAP_PX_MAX)
            return BAD("SMAP section: point %lu lies outside +-%d pixels", UL(i / 2), (int)(SMAP_PX_MAX >> 16));
    }
    memset(out, 0, sizeof *out);
    out->centre = silk_v3(rd32s(d + 20), rd32s(d + 24), rd32s(d + 28));
    out->nviews = nviews;
    out->ntris = ntris;
    out->nloops = nloops;
    out->npts = npts;
    out->views = (const silk_silmap_view *)(const void *)views;
    out->tri = (const uint32_t *)(const void *)tri;
    out->adj = (const uint32_t *)(const void *)adj;
    out->loop_start = (const uint32_t *)(const void *)start;
    out->pts = (const silk_vec2 *)(const void *)pts;
    return SILK_OK;
}

silk_status silk_model_silmap(const void *data, size_t len, const char *name, silk_silmap *out, silk_error *err)
{
    if (!name) name = "model";
    memset(out, 0, sizeof *out);
    const uint32_t one = 1;
    if (*(const uint8_t *)&one != 1) return BAD("silhouette maps are read in place on little-endian hosts only");
    silk_model m;
    silk_model_section s;
    silk_silmap map;
    silk_status st = silk_model_open(data, len, name, &m, err);
    if (st) return st;
    if (!silk_model_find(&m, SILK_SECTION_SMAP, &s))
        return BAD("no SMAP section (prepared without the silhouette map clip mode needs)");
    if ((st = smap_check(&s, name, &map, err))) return st;
    if ((uintptr_t)s.data % 4 != 0) return BAD("SMAP section: the model's bytes are not 4-byte aligned in memory");
    *out = map;
    return SILK_OK;
}

/* ---- STEX: the silhouette texture ------------------------------------------------ */

/* |v|^2 of a Q1.14 vector within (1 +- 1/64)^2, in Q2.28. */
static int unit14(const uint8_t *p)
{
    int64_t x = (int16_t)rd16(p), y = (int16_t)rd16(p + 2), z = (int16_t)rd16(p + 4);
    int64_t n2 = x * x + y * y + z * z, one = (int64_t)1 << 28;
    return n2 >= one - one / 32 + one / 4096 && n2 <= one + one / 32 + one / 4096;
}

static silk_status stex_check(const silk_model_section *sp, const mesh_layout *hull, const uint8_t *hull_tri,
                              const char *name, silk_siltex *out, silk_error *err)
{
    const silk_model_section s = *sp;
    const uint8_t *d = s.data;
    if (s.size < SILK_STEX_HEAD_BYTES) return BAD("STEX section of %lu bytes is shorter than its counts", UL(s.size));
    if (rd32(d) != SILK_STEX_VERSION)
        return BAD("STEX section: texture version %lu; this silk reads version %u", UL(rd32(d)), SILK_STEX_VERSION);
    uint32_t flags = rd32(d + 4), w = rd16(d + 8), h = rd16(d + 10), k = rd16(d + 12), e = rd16(d + 14);
    uint32_t nverts = rd32(d + 16), ntris = rd32(d + 20);
    if (flags & ~(SILK_STEX_COMPRESSED | SILK_STEX_COLOR)) return BAD("STEX section: unknown flags 0x%lx", UL(flags));
    if (w < SILK_STEX_MIN_DIM || h < SILK_STEX_MIN_DIM || w > SILK_STEX_MAX_DIM || h > SILK_STEX_MAX_DIM)
        return BAD("STEX section: atlas of %lux%lu texels (%d..%d on a side)", UL(w), UL(h), SILK_STEX_MIN_DIM,
                   SILK_STEX_MAX_DIM);
    if (k < SILK_STEX_MIN_K || k > SILK_STEX_MAX_K)
        return BAD("STEX section: %lu azimuth samples (%d..%d)", UL(k), SILK_STEX_MIN_K, SILK_STEX_MAX_K);
    int packed = (flags & SILK_STEX_COMPRESSED) != 0;
    if (packed ? (e < 1 || e > k) : e != 0)
        return BAD(packed ? "STEX section: %lu eigenfunctions for %lu azimuths (1..%lu)"
                          : "STEX section: %lu eigenfunctions in uncompressed angles (%lu azimuths; 0 expected)",
                   UL(e), UL(k), UL(k));
    if (nverts != hull->nverts || ntris != hull->ntris)
        return BAD("STEX section: %lu vertices and %lu triangles, the HULL section has %lu and %lu", UL(nverts),
                   UL(ntris), UL(hull->nverts), UL(hull->ntris));
    uint64_t texels = (uint64_t)w * h, off = SILK_STEX_HEAD_BYTES;
    uint64_t frame = off, uv = frame + 12 * (uint64_t)nverts, angles = uv + 12 * (uint64_t)ntris;
    uint64_t mean = angles, scale = mean + 2 * (uint64_t)k, basis = scale + 4 * (uint64_t)e;
    uint64_t weights = basis + 2 * (uint64_t)e * k, normal;
    if (packed) {
        normal = weights + texels * e;
        normal += normal & 1;   /* to 2 bytes */
    } else {
        normal = angles + texels * k;
    }
    uint64_t color = normal + 2 * texels, end = color + ((flags & SILK_STEX_COLOR) ? 3 * texels : 0);
    end = (end + 3) & ~(uint64_t)3;
    if (end != s.size)
        return BAD("STEX section: a %lux%lu atlas with %lu azimuths%s takes %llu bytes, the section has %lu", UL(w),
                   UL(h), UL(k), packed ? " (compressed)" : "", (unsigned long long)end, UL(s.size));
    for (uint32_t v = 0; v < nverts; v++) {
        const uint8_t *c = d + frame + 12 * (size_t)v, *t = c + 6;
        if (!unit14(c)) return BAD("STEX section: vertex %lu's centre direction C is not of unit length", UL(v));
        if (!unit14(t)) return BAD("STEX section: vertex %lu's tangent T is not of unit length", UL(v));
        int64_t tc = 0;
        for (int i = 0; i < 3; i++) tc += (int64_t)(int16_t)rd16(c + 2 * i) * (int16_t)rd16(t + 2 * i);
        if (silk_abs64(tc) > ((int64_t)1 << 28) / 16)
            return BAD("STEX section: vertex %lu's tangent T is not across C (|T.C| above 1/16)", UL(v));
    }
    for (uint32_t c = 0; c < 3 * ntris; c++) {
        uint32_t u = rd16(d + uv + 4 * (size_t)c), v = rd16(d + uv + 4 * (size_t)c + 2);
        if (u > 16 * w || v > 16 * h)
            return BAD("STEX section: triangle %lu corner %lu's atlas point (%lu/16, %lu/16) lies outside the "
                       "%lux%lu atlas", UL(c / 3), UL(c % 3), UL(u), UL(v), UL(w), UL(h));
    }
    memset(out, 0, sizeof *out);
    out->flags = flags;
    out->w = w;
    out->h = h;
    out->k = k;
    out->e = e;
    out->nverts = nverts;
    out->ntris = ntris;
    out->error_ppm = rd32(d + 24);
    out->multi_lobe_ppm = rd32(d + 28);
    out->bytes = s.size;
    out->frame = d + frame;
    out->uv = d + uv;
    if (packed) {
        out->mean = d + mean;
        out->scale = d + scale;
        out->basis = d + basis;
        out->weights = d + weights;
    } else {
        out->angles = d + angles;
    }
    out->normal = d + normal;
    out->color = (flags & SILK_STEX_COLOR) ? d + color : NULL;
    out->hull_tri = hull_tri;
    return SILK_OK;
}

/* The opened model's STEX section s, with the HULL it goes with. */
static silk_status stex_of(const silk_model *m, const silk_model_section *s, const char *name, silk_siltex *out,
                           silk_error *err)
{
    silk_model_section hs;
    mesh_layout hull;
    silk_status st;
    if (!silk_model_find(m, SILK_SECTION_HULL, &hs)) return BAD("STEX section without the HULL section it goes with");
    if ((st = mesh_layout_of(&hs, "HULL", name, &hull, err))) return st;
    if ((st = mesh_check(&hs, "HULL", &hull, name, err))) return st;
    return stex_check(s, &hull, hs.data + hull.tri, name, out, err);
}

silk_status silk_model_siltex(const void *data, size_t len, const char *name, silk_siltex *out, silk_error *err)
{
    if (!name) name = "model";
    memset(out, 0, sizeof *out);
    if (!SILK_SILTEX_MODE) return BAD("silhouette textures are not built in (SILK_SILTEX_MODE 0)");
    silk_model m;
    silk_model_section s;
    silk_status st = silk_model_open(data, len, name, &m, err);
    if (st) return st;
    if (!silk_model_find(&m, SILK_SECTION_STEX, &s))
        return BAD("no STEX section (prepared without the silhouette texture siltex mode needs)");
    if ((st = stex_of(&m, &s, name, out, err))) memset(out, 0, sizeof *out);
    return st;
}
