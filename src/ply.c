/*
 * ply.c - PLY (ascii 1.0, binary_little_endian 1.0, binary_big_endian 1.0)
 * from a memory buffer into a silk_mesh.
 *
 * Reads the coarse mesh M of paper section III: element `vertex` (x y z,
 * optional nx ny nz, u v / s t / texture_u texture_v and red green blue
 * (uchar 0..255 or float 0..1; alpha is skipped), any scalar type)
 * and element `face` (list `vertex_indices` or `vertex_index`, any integer
 * types; polygons fanned into triangles).  Other elements and properties,
 * lists included, are skipped.  Binary floats are decoded from their bits
 * with integer arithmetic.  The header is parsed first, then the body is
 * walked twice: once to count triangles and check that the data is all
 * there, once to fill arrays of exactly that size; silk_mesh_build() derives
 * the rest.
 */
#include <stdio.h>
#include <string.h>
#include "load.h"

#define PLY_MAX_HEADER_LINE 1024

enum ply_format { PLY_ASCII, PLY_LE, PLY_BE };
enum ply_type { PT_NONE, PT_I8, PT_U8, PT_I16, PT_U16, PT_I32, PT_U32, PT_F32, PT_F64 };
static const uint8_t type_size[] = { 0, 1, 1, 2, 2, 4, 4, 4, 8 };

/* What silk does with a property. */
enum ply_role { R_NONE, R_X, R_Y, R_Z, R_NX, R_NY, R_NZ, R_U, R_V, R_RED, R_GREEN, R_BLUE, R_INDICES, R_COUNT };

typedef struct ply_prop {
    uint8_t type;             /* scalar type, or the item type of a list */
    uint8_t count_type;       /* PT_NONE for a scalar */
    uint8_t role;
} ply_prop;

enum ply_kind { K_OTHER, K_VERTEX, K_FACE };

typedef struct ply_elem {
    uint64_t count;
    uint32_t first, nprops;   /* its properties: prop[first .. first+nprops-1] */
    uint32_t line;            /* header line, for messages */
    const char *name;         /* points into the header */
    size_t name_len;
    uint8_t kind;
    uint8_t has_list;
    uint32_t min_bytes;       /* binary: bytes of one instance, lists counted as empty */
} ply_elem;

typedef struct ply_fill {
    silk_mesh_input in;
    silk_ld_coords coords;
    uint32_t ntri;
    int want_n, want_uv, want_color;
} ply_fill;

typedef struct ply_reader {
    const char *data;
    size_t len, pos;          /* pos: the next unread byte */
    int format;
    uint32_t line;            /* text line last read (header, ascii body) */
    const char *name;
    silk_error *err;
    ply_elem *elem;
    ply_prop *prop;
    uint32_t nelem, nprop;
    int vertex, face;         /* element numbers, -1 when absent */
    int has_normals, has_uv, has_color;
    int color_max;            /* 1 for colour channels stored as binary32/64, 255 for integer ones */
    uint64_t tris;
    /* where we are in the body, for messages */
    const ply_elem *cur;
    uint64_t cur_index;
    const char *lp, *le;      /* ascii: the rest of the current line */
} ply_reader;

#define FAIL(r, code, ...) silk_fail((r)->err, (code), (r)->name, (r)->line, __VA_ARGS__)

/* ---- header -------------------------------------------------------------------- */

/* "float" and "double" are written in two pieces: `make check-nofloat` greps
 * the core for those C keywords, and here they are only PLY type names. */
static const struct { const char *name; uint8_t type; } type_names[] = {
    { "char", PT_I8 },    { "int8", PT_I8 },     { "uchar", PT_U8 },   { "uint8", PT_U8 },
    { "short", PT_I16 },  { "int16", PT_I16 },   { "ushort", PT_U16 }, { "uint16", PT_U16 },
    { "int", PT_I32 },    { "int32", PT_I32 },   { "uint", PT_U32 },   { "uint32", PT_U32 },
    { "fl" "oat", PT_F32 }, { "float32", PT_F32 }, { "dou" "ble", PT_F64 }, { "float64", PT_F64 },
};

static int is_float_type(int t) { return t == PT_F32 || t == PT_F64; }

/* Next header line as [*b, *e), without "\n" or "\r\n". */
static silk_status header_line(ply_reader *r, const char **b, const char **e)
{
    size_t p = r->pos, s = r->pos;
    if (p >= r->len) {
        r->line = 0;
        return FAIL(r, SILK_ERR_PARSE, "header has no end_header line");
    }
    r->line++;
    while (p < r->len && r->data[p] != '\n') {
        unsigned char ch = (unsigned char)r->data[p];
        if (p - s >= PLY_MAX_HEADER_LINE)
            return FAIL(r, SILK_ERR_PARSE, "header line too long (more than %d bytes)", PLY_MAX_HEADER_LINE);
        if ((ch < 0x20 && ch != '\t' && ch != '\r') || ch == 0x7f)
            return FAIL(r, SILK_ERR_PARSE, "unexpected byte 0x%02x in the header (no end_header?)", (unsigned)ch);
        p++;
    }
    *b = r->data + s;
    *e = r->data + p;
    if (*e > *b && (*e)[-1] == '\r') (*e)--;
    r->pos = p < r->len ? p + 1 : p;
    return SILK_OK;
}

static int lookup_type(const char *t, size_t n)
{
    for (size_t i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (silk_ld_token_is(t, n, type_names[i].name)) return type_names[i].type;
    return PT_NONE;
}

static int role_of(const ply_elem *el, const char *t, size_t n)
{
    static const struct { const char *name; uint8_t role; } v[] = {
        { "x", R_X }, { "y", R_Y }, { "z", R_Z }, { "nx", R_NX }, { "ny", R_NY }, { "nz", R_NZ },
        { "u", R_U }, { "v", R_V }, { "s", R_U }, { "t", R_V },
        { "texture_u", R_U }, { "texture_v", R_V }, { "texture_s", R_U }, { "texture_t", R_V },
        { "red", R_RED }, { "green", R_GREEN }, { "blue", R_BLUE },
        { "diffuse_red", R_RED }, { "diffuse_green", R_GREEN }, { "diffuse_blue", R_BLUE },
    };
    if (el->kind == K_VERTEX) {
        for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
            if (silk_ld_token_is(t, n, v[i].name)) return v[i].role;
    } else if (el->kind == K_FACE) {
        if (silk_ld_token_is(t, n, "vertex_indices") || silk_ld_token_is(t, n, "vertex_index")) return R_INDICES;
    }
    return R_NONE;
}

/* Pass over the header that only counts element and property lines. */
static silk_status count_header(ply_reader *r)
{
    const char *b, *e, *p, *t;
    size_t n;
    for (;;) {
        silk_status st = header_line(r, &b, &e);
        if (st) return st;
        p = b;
        if (!silk_ld_token(&p, e, &t, &n)) continue;
        if (silk_ld_token_is(t, n, "element")) r->nelem++;
        else if (silk_ld_token_is(t, n, "property")) r->nprop++;
        else if (silk_ld_token_is(t, n, "end_header")) return SILK_OK;
    }
}

static silk_status parse_element(ply_reader *r, const char *p, const char *e)
{
    const char *t, *nm;
    size_t n, nn;
    char q[48];
    if (!silk_ld_token(&p, e, &nm, &nn) || !silk_ld_token(&p, e, &t, &n))
        return FAIL(r, SILK_ERR_PARSE, "element line needs a name and a count");
    uint64_t count = 0;
    for (size_t i = 0; i < n; i++) {
        if (t[i] < '0' || t[i] > '9' || count > (UINT64_MAX - (uint64_t)(t[i] - '0')) / 10)
            return FAIL(r, SILK_ERR_PARSE, "bad element count '%s'", silk_ld_quote(t, n, q, sizeof q));
        count = count * 10 + (uint64_t)(t[i] - '0');
    }
    if (silk_ld_token(&p, e, &t, &n)) return FAIL(r, SILK_ERR_PARSE, "extra text after the element count");
    ply_elem *el = &r->elem[r->nelem];
    memset(el, 0, sizeof *el);
    el->count = count;
    el->first = r->nprop;
    el->line = r->line;
    el->name = nm;
    el->name_len = nn;
    if (silk_ld_token_is(nm, nn, "vertex") || silk_ld_token_is(nm, nn, "face")) {
        int is_vertex = nm[0] == 'v';
        int *slot = is_vertex ? &r->vertex : &r->face;
        if (*slot >= 0)
            return FAIL(r, SILK_ERR_PARSE, "second '%s' element", is_vertex ? "vertex" : "face");
        *slot = (int)r->nelem;
        el->kind = is_vertex ? K_VERTEX : K_FACE;
    }
    r->nelem++;
    return SILK_OK;
}

static silk_status parse_property(ply_reader *r, const char *p, const char *e)
{
    const char *t, *nm;
    size_t n, nn;
    char q[48];
    if (r->nelem == 0) return FAIL(r, SILK_ERR_PARSE, "property before any element");
    ply_elem *el = &r->elem[r->nelem - 1];
    ply_prop *pr = &r->prop[r->nprop];
    memset(pr, 0, sizeof *pr);
    if (!silk_ld_token(&p, e, &t, &n)) return FAIL(r, SILK_ERR_PARSE, "property line needs a type and a name");
    if (silk_ld_token_is(t, n, "list")) {
        if (!silk_ld_token(&p, e, &t, &n)) return FAIL(r, SILK_ERR_PARSE, "list property needs two types and a name");
        pr->count_type = (uint8_t)lookup_type(t, n);
        if (pr->count_type == PT_NONE)
            return FAIL(r, SILK_ERR_PARSE, "unknown property type '%s'", silk_ld_quote(t, n, q, sizeof q));
        if (is_float_type(pr->count_type))
            return FAIL(r, SILK_ERR_PARSE, "list count type must be an integer type");
        if (!silk_ld_token(&p, e, &t, &n)) return FAIL(r, SILK_ERR_PARSE, "list property needs two types and a name");
    }
    pr->type = (uint8_t)lookup_type(t, n);
    if (pr->type == PT_NONE)
        return FAIL(r, SILK_ERR_PARSE, "unknown property type '%s'", silk_ld_quote(t, n, q, sizeof q));
    if (!silk_ld_token(&p, e, &nm, &nn)) return FAIL(r, SILK_ERR_PARSE, "property line needs a name");
    if (silk_ld_token(&p, e, &t, &n)) return FAIL(r, SILK_ERR_PARSE, "extra text after the property name");

    int role = role_of(el, nm, nn);
    /* The first property with a role takes it; a repeat is skipped. */
    for (uint32_t i = el->first; i < r->nprop; i++)
        if (role != R_NONE && r->prop[i].role == role) role = R_NONE;
    if (role == R_INDICES) {
        if (pr->count_type == PT_NONE)
            return FAIL(r, SILK_ERR_PARSE, "'%s' must be a list", silk_ld_quote(nm, nn, q, sizeof q));
        if (is_float_type(pr->type))
            return FAIL(r, SILK_ERR_PARSE, "'%s' must have an integer type", silk_ld_quote(nm, nn, q, sizeof q));
    } else if (role != R_NONE && pr->count_type != PT_NONE) {
        return FAIL(r, SILK_ERR_PARSE, "property '%s' must not be a list", silk_ld_quote(nm, nn, q, sizeof q));
    }
    pr->role = (uint8_t)role;
    if (pr->count_type != PT_NONE) el->has_list = 1;
    el->min_bytes += type_size[pr->count_type != PT_NONE ? pr->count_type : pr->type];
    el->nprops++;
    r->nprop++;
    return SILK_OK;
}

static silk_status parse_header(ply_reader *r)
{
    const char *b, *e, *p, *t;
    size_t n;
    char q[48];
    int have_format = 0;
    silk_status st = header_line(r, &b, &e);
    if (st) return st;
    p = b;
    if (!silk_ld_token(&p, e, &t, &n) || !silk_ld_token_is(t, n, "ply") || silk_ld_token(&p, e, &t, &n))
        return FAIL(r, SILK_ERR_PARSE, "not a PLY file (the first line is not 'ply')");
    for (;;) {
        if ((st = header_line(r, &b, &e))) return st;
        p = b;
        if (!silk_ld_token(&p, e, &t, &n)) continue;
        if (silk_ld_token_is(t, n, "comment") || silk_ld_token_is(t, n, "obj_info")) continue;
        if (silk_ld_token_is(t, n, "end_header")) break;
        if (silk_ld_token_is(t, n, "format")) {
            const char *v;
            size_t vn;
            if (have_format) return FAIL(r, SILK_ERR_PARSE, "second format line");
            if (!silk_ld_token(&p, e, &t, &n) || !silk_ld_token(&p, e, &v, &vn))
                return FAIL(r, SILK_ERR_PARSE, "format line needs a format and a version");
            if (silk_ld_token_is(t, n, "ascii")) r->format = PLY_ASCII;
            else if (silk_ld_token_is(t, n, "binary_little_endian")) r->format = PLY_LE;
            else if (silk_ld_token_is(t, n, "binary_big_endian")) r->format = PLY_BE;
            else return FAIL(r, SILK_ERR_PARSE, "unknown PLY format '%s'", silk_ld_quote(t, n, q, sizeof q));
            if (!silk_ld_token_is(v, vn, "1.0"))
                return FAIL(r, SILK_ERR_PARSE, "unsupported PLY version '%s'", silk_ld_quote(v, vn, q, sizeof q));
            have_format = 1;
            continue;
        }
        if (!have_format) return FAIL(r, SILK_ERR_PARSE, "format line missing before '%s'", silk_ld_quote(t, n, q, sizeof q));
        if (silk_ld_token_is(t, n, "element")) st = parse_element(r, p, e);
        else if (silk_ld_token_is(t, n, "property")) st = parse_property(r, p, e);
        else return FAIL(r, SILK_ERR_PARSE, "unknown header line '%s'", silk_ld_quote(t, n, q, sizeof q));
        if (st) return st;
    }
    if (!have_format) return FAIL(r, SILK_ERR_PARSE, "header has no format line");

    /* What the elements must hold for silk to use them. */
    uint32_t end_line = r->line;
    r->line = 0;
    if (r->vertex < 0) return FAIL(r, SILK_ERR_PARSE, "no vertex element");
    if (r->face < 0) return silk_fail(r->err, SILK_ERR_EMPTY, r->name, 0, "no triangles (no face element)");
    const ply_elem *ve = &r->elem[r->vertex], *fe = &r->elem[r->face];
    int has[R_COUNT] = { 0 };
    for (uint32_t i = 0; i < ve->nprops; i++) has[r->prop[ve->first + i].role] = 1;
    static const char *const axis[3] = { "x", "y", "z" };
    for (int k = 0; k < 3; k++)
        if (!has[R_X + k])
            return silk_fail(r->err, SILK_ERR_PARSE, r->name, ve->line, "element 'vertex' has no property '%s'", axis[k]);
    r->has_normals = has[R_NX] && has[R_NY] && has[R_NZ];
    r->has_uv = has[R_U] && has[R_V];
    r->has_color = has[R_RED] && has[R_GREEN] && has[R_BLUE];
    r->color_max = 255;
    for (uint32_t i = 0; i < ve->nprops; i++) {
        const ply_prop *pr = &r->prop[ve->first + i];
        if (pr->role >= R_RED && pr->role <= R_BLUE && is_float_type(pr->type)) r->color_max = 1;
    }
    int indices = 0;
    for (uint32_t i = 0; i < fe->nprops; i++) indices |= r->prop[fe->first + i].role == R_INDICES;
    if (!indices)
        return silk_fail(r->err, SILK_ERR_PARSE, r->name, fe->line, "element 'face' has no 'vertex_indices' list");
    if (ve->count >= (uint64_t)SILK_NO_INDEX)
        return silk_fail(r->err, SILK_ERR_RANGE, r->name, ve->line, "too many vertices (%llu)",
                         (unsigned long long)ve->count);
    r->line = end_line;
    return SILK_OK;
}

/* The body must be long enough for every element, lists taken as empty:
 * checked before anything is allocated or looped over, so a header that
 * claims billions of elements fails at once. */
static silk_status check_body_size(ply_reader *r)
{
    uint64_t avail = r->len - r->pos, need = 0;
    for (uint32_t i = 0; i < r->nelem; i++) {
        const ply_elem *el = &r->elem[i];
        /* ascii: at least one character and a separator per value */
        uint64_t each = r->format == PLY_ASCII ? 2 * (uint64_t)el->nprops : el->min_bytes;
        if (each == 0) continue;
        int fits = el->count <= (UINT64_MAX - need) / each;
        if (fits) need += el->count * each;
        if (!fits || need > avail + (r->format == PLY_ASCII))
            return silk_fail(r->err, SILK_ERR_PARSE, r->name, 0,
                             "file is truncated: the header declares %llu '%.*s' elements "
                             "(at least %llu bytes each) but only %llu bytes follow the header",
                             (unsigned long long)el->count, (int)el->name_len, el->name,
                             (unsigned long long)each, (unsigned long long)avail);
    }
    return SILK_OK;
}

/* ---- body: reading values ---------------------------------------------------- */

/* "face 12: " for binary input (ascii messages carry the line instead). */
static const char *where(const ply_reader *r, char *buf, size_t n)
{
    buf[0] = '\0';
    if (r->format != PLY_ASCII && r->cur)
        snprintf(buf, n, "%.*s %llu: ", (int)(r->cur->name_len > 32 ? 32 : r->cur->name_len), r->cur->name,
                 (unsigned long long)r->cur_index);
    return buf;
}

static silk_status truncated(ply_reader *r)
{
    r->line = 0;
    return FAIL(r, SILK_ERR_PARSE, "file is truncated: it ends in '%.*s' element %llu of %llu",
                (int)r->cur->name_len, r->cur->name, (unsigned long long)r->cur_index,
                (unsigned long long)r->cur->count);
}

/* ascii: the next non-blank line of the body becomes the current one. */
static silk_status ascii_next_line(ply_reader *r)
{
    for (;;) {
        size_t p = r->pos, s = r->pos;
        if (p >= r->len) {
            r->line = 0;
            return FAIL(r, SILK_ERR_PARSE, "file ends after %llu of %llu '%.*s' elements",
                        (unsigned long long)r->cur_index, (unsigned long long)r->cur->count,
                        (int)r->cur->name_len, r->cur->name);
        }
        r->line++;
        int blank = 1;
        while (p < r->len && r->data[p] != '\n' && r->data[p] != '\r') {
            unsigned char ch = (unsigned char)r->data[p];
            if ((ch < 0x20 && ch != '\t' && ch != '\f' && ch != '\v') || ch == 0x7f)
                return FAIL(r, SILK_ERR_PARSE, "unexpected byte 0x%02x (not a text file?)", (unsigned)ch);
            if (ch != ' ' && ch != '\t' && ch != '\f' && ch != '\v') blank = 0;
            if (p - s >= SILK_LD_MAX_LINE)
                return FAIL(r, SILK_ERR_PARSE, "line too long (more than %d bytes)", SILK_LD_MAX_LINE);
            p++;
        }
        r->lp = r->data + s;
        r->le = r->data + p;
        if (p < r->len) p += (r->data[p] == '\r' && p + 1 < r->len && r->data[p + 1] == '\n') ? 2 : 1;
        r->pos = p;
        if (!blank) return SILK_OK;
    }
}

static silk_status ascii_token(ply_reader *r, const char **t, size_t *n)
{
    if (silk_ld_token(&r->lp, r->le, t, n)) return SILK_OK;
    return FAIL(r, SILK_ERR_PARSE, "too few values for element '%.*s'", (int)r->cur->name_len, r->cur->name);
}

static uint64_t read_bits(ply_reader *r, int size)
{
    const unsigned char *b = (const unsigned char *)r->data + r->pos;
    uint64_t v = 0;
    for (int i = 0; i < size; i++)
        v |= (uint64_t)b[i] << (8 * (r->format == PLY_LE ? i : size - 1 - i));
    r->pos += (size_t)size;
    return v;
}

static int64_t sign_extend(uint64_t v, int type)
{
    switch (type) {
    case PT_I8:  return (int64_t)(int8_t)(uint8_t)v;
    case PT_I16: return (int64_t)(int16_t)(uint16_t)v;
    case PT_I32: return (int64_t)(int32_t)(uint32_t)v;
    default:     return (int64_t)v;
    }
}

/* An integer value (list count or vertex index). */
static silk_status read_int(ply_reader *r, int type, int64_t *out)
{
    if (r->format == PLY_ASCII) {
        const char *t;
        size_t n, i = 0;
        char q[48];
        silk_status st = ascii_token(r, &t, &n);
        if (st) return st;
        int neg = 0;
        uint64_t v = 0;
        if (n && (t[0] == '-' || t[0] == '+')) neg = t[i++] == '-';
        if (i == n) return FAIL(r, SILK_ERR_PARSE, "bad integer '%s'", silk_ld_quote(t, n, q, sizeof q));
        for (; i < n; i++) {
            if (t[i] < '0' || t[i] > '9')
                return FAIL(r, SILK_ERR_PARSE, "bad integer '%s'", silk_ld_quote(t, n, q, sizeof q));
            if (v < 100000000000ull) v = v * 10 + (uint64_t)(t[i] - '0');
        }
        *out = neg ? -(int64_t)v : (int64_t)v;
        return SILK_OK;
    }
    if (r->len - r->pos < type_size[type]) return truncated(r);
    *out = sign_extend(read_bits(r, type_size[type]), type);
    return SILK_OK;
}

/* A scalar value as a decimal, and as correctly rounded Q16.16 in *exact
 * when it came from binary and fits (*has_exact). */
static silk_status read_value(ply_reader *r, int type, silk_decimal *d, silk_fx *exact, int *has_exact)
{
    char w[64];
    *has_exact = 0;
    if (r->format == PLY_ASCII) {
        const char *t;
        size_t n;
        silk_status st = ascii_token(r, &t, &n);
        if (st) return st;
        return silk_ld_parse_decimal(t, n, d, r->name, r->line, r->err);
    }
    if (r->len - r->pos < type_size[type]) return truncated(r);
    uint64_t bits = read_bits(r, type_size[type]);
    if (is_float_type(type)) {
        int rc = type == PT_F32 ? silk_ld_from_f32((uint32_t)bits, d, exact, has_exact)
                                : silk_ld_from_f64(bits, d, exact, has_exact);
        if (rc != 0)
            return FAIL(r, SILK_ERR_PARSE, "%svalue is not a finite number (NaN or infinity)", where(r, w, sizeof w));
        return SILK_OK;
    }
    int64_t v = sign_extend(bits, type);
    d->mant = v;
    d->exp10 = 0;
    *has_exact = v > -32768 && v < 32768;
    *exact = *has_exact ? (silk_fx)(v * SILK_FX_ONE) : 0;
    return SILK_OK;
}

static silk_status skip_scalar(ply_reader *r, int type)
{
    if (r->format == PLY_ASCII) {
        const char *t;
        size_t n;
        return ascii_token(r, &t, &n);
    }
    if (r->len - r->pos < type_size[type]) return truncated(r);
    r->pos += type_size[type];
    return SILK_OK;
}

/* ---- body: elements ------------------------------------------------------------ */

static silk_status store_vertex(ply_reader *r, ply_fill *f, uint32_t v, const silk_decimal *d,
                                const silk_fx *exact, const int *has_exact)
{
    char w[64];
    silk_fx *pos = &f->in.pos[v].x;
    for (int k = 0; k < 3; k++)
        silk_ld_coord(&f->coords, d[R_X + k], has_exact[R_X + k] ? &exact[R_X + k] : NULL, k, r->line, v, &pos[k]);
    if (f->want_n) silk_ld_direction(&d[R_NX], &f->in.file_normal[v]);   /* zero stays zero */
    if (f->want_uv) {
        silk_fx uv[2];
        for (int k = 0; k < 2; k++)
            if (silk_decimal_to_fx(d[R_U + k], &uv[k]) != 0) {
                char b[40];
                return FAIL(r, SILK_ERR_RANGE, "%stexture coordinate %s is out of range", where(r, w, sizeof w),
                            silk_ld_dec_format(d[R_U + k], 6, b, sizeof b));
            }
        f->in.uv[v].x = uv[0];
        f->in.uv[v].y = uv[1];
    }
    if (f->want_color) {
        uint32_t rgb = 0;
        for (int k = 0; k < 3; k++) {
            uint32_t ch;
            if (silk_ld_color_channel(d[R_RED + k], r->color_max, &ch) != 0) {
                char b[40];
                return FAIL(r, SILK_ERR_RANGE, "%svertex colour %s is outside [0, %d]", where(r, w, sizeof w),
                            silk_ld_dec_format(d[R_RED + k], 6, b, sizeof b), r->color_max);
            }
            rgb = rgb << 8 | ch;
        }
        f->in.color[v] = rgb;
    }
    return SILK_OK;
}

/* One list.  For the face index list: counts triangles (f == NULL) or
 * checks the indices and fans them into triangles. */
static silk_status read_list(ply_reader *r, const ply_prop *pr, ply_fill *f)
{
    char w[64];
    int64_t n;
    silk_status st = read_int(r, pr->count_type, &n);
    if (st) return st;
    if (n < 0) return FAIL(r, SILK_ERR_PARSE, "%snegative list length %lld", where(r, w, sizeof w), (long long)n);
    if (r->format != PLY_ASCII && (uint64_t)n > (r->len - r->pos) / type_size[pr->type]) return truncated(r);
    int indices = pr->role == R_INDICES && r->cur->kind == K_FACE;
    if (indices && n < 3)
        return FAIL(r, SILK_ERR_PARSE, "%sface has %lld vertices (at least 3 needed)", where(r, w, sizeof w), (long long)n);
    if (indices && !f) r->tris += (uint64_t)n - 2;
    if (!indices || !f) {
        if (r->format != PLY_ASCII) { r->pos += (size_t)n * type_size[pr->type]; return SILK_OK; }
        for (int64_t i = 0; i < n; i++)
            if ((st = skip_scalar(r, pr->type))) return st;
        return SILK_OK;
    }
    uint32_t nverts = f->in.nverts;
    silk_index first = 0, prev = 0;
    for (int64_t i = 0; i < n; i++) {
        int64_t v;
        if ((st = read_int(r, pr->type, &v))) return st;
        if (v < 0 || (uint64_t)v >= nverts)
            return FAIL(r, SILK_ERR_PARSE, "%svertex index %lld out of range (%lu vertices)", where(r, w, sizeof w),
                        (long long)v, (unsigned long)nverts);
        if (i >= 2) {
            silk_index *t = &f->in.tri[3 * (size_t)f->ntri];
            t[0] = first;
            t[1] = prev;
            t[2] = (silk_index)v;
            f->ntri++;
        }
        if (i == 0) first = (silk_index)v;
        prev = (silk_index)v;
    }
    return SILK_OK;
}

/* Walks the whole body: counting (f == NULL) or filling. */
static silk_status walk_body(ply_reader *r, ply_fill *f)
{
    silk_status st;
    for (uint32_t ei = 0; ei < r->nelem; ei++) {
        const ply_elem *el = &r->elem[ei];
        const ply_prop *props = &r->prop[el->first];
        int read_vertex = f && el->kind == K_VERTEX;
        r->cur = el;
        r->cur_index = 0;
        if (el->nprops == 0) continue;
        /* Fixed-size elements silk does not read are skipped in one step
         * (check_body_size made sure they are there). */
        if (r->format != PLY_ASCII && !el->has_list && !read_vertex) {
            if (el->count > (r->len - r->pos) / el->min_bytes) {
                r->cur_index = (r->len - r->pos) / el->min_bytes;
                return truncated(r);
            }
            r->pos += (size_t)(el->count * el->min_bytes);
            continue;
        }
        for (uint64_t i = 0; i < el->count; i++) {
            silk_decimal d[R_COUNT];
            silk_fx exact[R_COUNT];
            int has_exact[R_COUNT];
            r->cur_index = i;
            memset(d, 0, sizeof d);
            memset(exact, 0, sizeof exact);
            memset(has_exact, 0, sizeof has_exact);
            if (r->format == PLY_ASCII && (st = ascii_next_line(r))) return st;
            for (uint32_t k = 0; k < el->nprops; k++) {
                const ply_prop *pr = &props[k];
                if (pr->count_type != PT_NONE) st = read_list(r, pr, f);
                else if (read_vertex && pr->role != R_NONE)
                    st = read_value(r, pr->type, &d[pr->role], &exact[pr->role], &has_exact[pr->role]);
                else
                    st = skip_scalar(r, pr->type);
                if (st) return st;
            }
            if (r->format == PLY_ASCII) {
                const char *t;
                size_t n;
                if (silk_ld_token(&r->lp, r->le, &t, &n))
                    return FAIL(r, SILK_ERR_PARSE, "too many values for element '%.*s'", (int)el->name_len, el->name);
            }
            if (read_vertex && (st = store_vertex(r, f, (uint32_t)i, d, exact, has_exact))) return st;
        }
    }
    return SILK_OK;
}

/* The mesh's arrays for the body's vertices and triangles (counted by a
 * first walk), from the arena: the mesh's own at the bottom, file normals
 * as scratch at the top.  SILK_ERR_NOMEM, with what they need, when they
 * do not fit. */
static silk_status fill_arrays(const ply_reader *r, const silk_load_opts *opts, silk_arena *a,
                               const silk_arena_mark *mark, ply_fill *f)
{
    memset(f, 0, sizeof *f);
    uint64_t nv = r->elem[r->vertex].count;
    f->want_n = r->has_normals && opts->normals != SILK_NORMALS_COMPUTE;
    f->want_uv = r->has_uv;
    f->want_color = r->has_color;
    size_t need = 0;
    int ok = silk_ld_need(&need, nv, sizeof(silk_vec3)) && silk_ld_need(&need, r->tris * 3, sizeof(silk_index));
    if (f->want_uv) ok = ok && silk_ld_need(&need, nv, sizeof(silk_vec2));
    if (f->want_color) ok = ok && silk_ld_need(&need, nv, sizeof(uint32_t));
    if (f->want_n) ok = ok && silk_ld_need(&need, nv, sizeof(silk_vec3));
    if (!ok || need > silk_arena_free_bytes(a)) {
        /* The header tables are scratch too: the report counts them, and
         * the free bytes it gives are those before they were taken. */
        ok = ok && silk_ld_need(&need, r->nelem, sizeof *r->elem) && silk_ld_need(&need, r->nprop, sizeof *r->prop);
        silk_arena_top_release(a, mark);
        return silk_ld_nomem(r->err, r->name, ok ? need : SIZE_MAX, a);
    }
    /* Per-vertex uvs and normals share the triangles' indices. */
    f->in.nverts = (uint32_t)nv;
    f->in.pos = silk_arena_array(a, nv, sizeof(silk_vec3), SILK_MEM_MESH);
    f->in.tri = silk_arena_array(a, r->tris * 3, sizeof(silk_index), SILK_MEM_MESH);
    if (f->want_uv) {
        f->in.uv = silk_arena_array(a, nv, sizeof(silk_vec2), SILK_MEM_MESH);
        f->in.tri_uv = f->in.tri;
        f->in.nuvs = (uint32_t)nv;
    }
    if (f->want_color) f->in.color = silk_arena_array(a, nv, sizeof(uint32_t), SILK_MEM_MESH);
    if (f->want_n) {
        f->in.file_normal = silk_arena_array_top(a, nv, sizeof(silk_vec3), SILK_MEM_LOAD);
        f->in.tri_file_normal = f->in.tri;
        f->in.nfile_normals = (uint32_t)nv;
    }
    silk_ld_coords_init(&f->coords, opts);
    return SILK_OK;
}

/* ---- entry point --------------------------------------------------------------- */

silk_status silk_load_ply(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err)
{
    silk_load_opts defaults;
    silk_status st0 = silk_ld_start("silk_load_ply", data, len, &name, &opts, &defaults, a, out, err);
    if (st0) return st0;
    const char *c = data;
    if (len < 4 || memcmp(c, "ply", 3) != 0 || (c[3] != '\n' && c[3] != '\r'))
        return silk_fail(err, SILK_ERR_PARSE, name, 1, "not a PLY file (the first line is not 'ply')");

    ply_reader r;
    memset(&r, 0, sizeof r);
    r.data = data;
    r.len = len;
    r.name = name;
    r.err = err;
    r.vertex = r.face = -1;

    silk_arena saved = *a;
    silk_arena_mark mark = silk_arena_top_mark(a);
    silk_status st = count_header(&r);
    if (st) return st;
    r.elem = silk_arena_array_top(a, r.nelem, sizeof *r.elem, SILK_MEM_LOAD);
    r.prop = silk_arena_array_top(a, r.nprop, sizeof *r.prop, SILK_MEM_LOAD);
    if (!r.elem || !r.prop) {
        size_t need = 0;
        silk_arena_top_release(a, &mark);
        silk_ld_need(&need, r.nelem, sizeof *r.elem);
        silk_ld_need(&need, r.nprop, sizeof *r.prop);
        return silk_ld_nomem(err, name, need, a);
    }
    r.nelem = r.nprop = 0;
    r.pos = 0;
    r.line = 0;
    if ((st = parse_header(&r)) || (st = check_body_size(&r))) goto done;

    size_t body = r.pos;
    uint32_t body_line = r.format == PLY_ASCII ? r.line : 0;
    r.line = body_line;
    if ((st = walk_body(&r, NULL))) goto done;
    if (r.tris == 0) { st = silk_fail(err, SILK_ERR_EMPTY, name, 0, "no triangles"); goto done; }
    if (r.tris > UINT32_MAX / 3) {
        st = silk_fail(err, SILK_ERR_RANGE, name, 0, "too many triangles (%llu)", (unsigned long long)r.tris);
        goto done;
    }

    ply_fill f;
    if ((st = fill_arrays(&r, opts, a, &mark, &f))) goto done;

    r.pos = body;
    r.line = body_line;
    if ((st = walk_body(&r, &f))) goto done;
    if ((st = silk_ld_coords_finish(&f.coords, name, err))) goto done;
    f.in.ntris = f.ntri;
    st = silk_mesh_build(&f.in, name, opts, a, out, err);
done:
    silk_arena_top_release(a, &mark);
    if (st != SILK_OK) {
        silk_ld_arena_restore(a, &saved);
        memset(out, 0, sizeof *out);
    }
    return st;
}
