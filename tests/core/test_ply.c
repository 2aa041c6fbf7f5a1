/*
 * test_ply.c - the PLY reader: ascii and binary in both byte orders, every
 * scalar type for coordinates, list counts and indices, skipped elements and
 * properties, normals and uvs, IEEE-754 decoding against a double reference
 * (exact Q16.16), the one-line errors, and robustness: every truncation and
 * random corruption of a valid file fails cleanly.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"

static unsigned char arena_buf[4 << 20];
static silk_arena arena;
static silk_mesh mesh;
static silk_error err;

/* ---- building PLY files in memory ---------------------------------------- */

typedef struct buf {
    unsigned char d[1 << 17];
    size_t n;
    int be;            /* body byte order: 1 big-endian */
} buf;

static buf B;

static void put_str(buf *b, const char *s)
{
    size_t n = strlen(s);
    memcpy(b->d + b->n, s, n);
    b->n += n;
}

static void put_bytes(buf *b, uint64_t v, int size)
{
    for (int i = 0; i < size; i++) {
        int shift = 8 * (b->be ? size - 1 - i : i);
        b->d[b->n++] = (unsigned char)(v >> shift);
    }
}

static void put_f32(buf *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    put_bytes(b, u, 4);
}

static void put_f64(buf *b, double f)
{
    uint64_t u;
    memcpy(&u, &f, 8);
    put_bytes(b, u, 8);
}

/* Writes value v as PLY type t (binary). */
static void put_typed(buf *b, const char *t, double v)
{
    if (!strcmp(t, "float") || !strcmp(t, "float32")) put_f32(b, (float)v);
    else if (!strcmp(t, "double") || !strcmp(t, "float64")) put_f64(b, v);
    else {
        int size = (!strcmp(t, "char") || !strcmp(t, "uchar") || !strcmp(t, "int8") || !strcmp(t, "uint8")) ? 1
                 : (!strcmp(t, "short") || !strcmp(t, "ushort") || !strcmp(t, "int16") || !strcmp(t, "uint16")) ? 2 : 4;
        put_bytes(b, (uint64_t)(int64_t)v, size);
    }
}

static void start(buf *b, const char *format)
{
    b->n = 0;
    b->be = strstr(format, "big") != NULL;
    put_str(b, "ply\nformat ");
    put_str(b, format);
    put_str(b, " 1.0\n");
}

static silk_status load_buf_opts(const buf *b, const silk_load_opts *o)
{
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    memset(&err, 0, sizeof err);
    return silk_load_ply(b->d, b->n, "t.ply", o, &arena, &mesh, &err);
}

/* The file's triangles as written: these tests check the parser, whose
 * small inputs are not all wound consistently. */
static silk_status load_buf(const buf *b)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.orient = SILK_ORIENT_KEEP;
    return load_buf_opts(b, &o);
}

static silk_status load_text(const char *text)
{
    B.n = strlen(text);
    memcpy(B.d, text, B.n);
    return load_buf(&B);
}

static silk_fx ref_fx(double v)
{
    return (silk_fx)llround(v * 65536.0);
}

static int tri_is(uint32_t t, silk_index a, silk_index b, silk_index c)
{
    return mesh.tri[3 * t] == a && mesh.tri[3 * t + 1] == b && mesh.tri[3 * t + 2] == c;
}

#define CHECK_MSG(st, code_, msg_)                                                     \
    do {                                                                               \
        silk_status st_ = (st);                                                        \
        CHECKF(st_ == (code_), "status %d, want %d (%s)", (int)st_, (int)(code_), err.msg); \
        CHECKF(strcmp(err.msg, (msg_)) == 0, "got \"%s\"\n     want \"%s\"", err.msg, (msg_)); \
        CHECKF(arena.bottom == 0 && arena.top == 0, "arena not restored"); \
    } while (0)

static const char *tetra_ascii =
    "ply\n"
    "format ascii 1.0\n"
    "comment made by hand\n"
    "obj_info nothing\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "element face 4\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0\n"
    "1.5 0 0\n"
    "0 -2.25 0\n"
    "0 0 0.001\n"
    "3 0 2 1\n"
    "3 0 1 3\n"
    "3 0 3 2\n"
    "3 1 2 3\n";

TEST(ascii_basic)
{
    CHECK(load_text(tetra_ascii) == SILK_OK);
    CHECK(mesh.nverts == 4 && mesh.ntris == 4 && mesh.nedges == 6 && mesh.nboundary_edges == 0);
    CHECK(mesh.pos[1].x == ref_fx(1.5) && mesh.pos[2].y == ref_fx(-2.25) && mesh.pos[3].z == ref_fx(0.001));
    CHECK(tri_is(0, 0, 2, 1) && tri_is(3, 1, 2, 3));
    CHECK(arena.top == 0);
    /* CRLF, blank body lines, tabs */
    char text[1024];
    size_t o = 0;
    for (const char *p = tetra_ascii; *p; p++) {
        if (*p == '\n') { text[o++] = '\r'; text[o++] = '\n'; }
        else text[o++] = *p == ' ' && p[-1] != 'y' ? '\t' : *p;
        if (*p == '\n' && !strncmp(p + 1, "3 0 1 3", 7)) { memcpy(text + o, " \r\n\r\n", 5); o += 5; }
    }
    text[o] = '\0';
    CHECK(load_text(text) == SILK_OK);
    CHECK(mesh.ntris == 4 && mesh.pos[2].y == ref_fx(-2.25));
}

/* A tetrahedron with coordinates of type ct and lists (count type lt, index type it). */
static void tetra_binary(buf *b, const char *format, const char *ct, const char *lt, const char *it,
                         const double v[12])
{
    char h[512];
    start(b, format);
    snprintf(h, sizeof h,
             "element vertex 4\nproperty %s x\nproperty %s y\nproperty %s z\n"
             "element face 4\nproperty list %s %s vertex_indices\nend_header\n", ct, ct, ct, lt, it);
    put_str(b, h);
    for (int i = 0; i < 12; i++) put_typed(b, ct, v[i]);
    static const int f[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    for (int t = 0; t < 4; t++) {
        put_typed(b, lt, 3);
        for (int k = 0; k < 3; k++) put_typed(b, it, f[t][k]);
    }
}

TEST(binary_all_types)
{
    static const char *const formats[] = { "binary_little_endian", "binary_big_endian" };
    static const char *const coord_types[] = { "char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                               "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64" };
    static const char *const int_types[] = { "char", "uchar", "short", "ushort", "int", "uint",
                                             "int8", "uint8", "int16", "uint16", "int32", "uint32" };
    int combos = 0;
    for (int f = 0; f < 2; f++)
        for (size_t c = 0; c < sizeof coord_types / sizeof *coord_types; c++)
            for (size_t l = 0; l < sizeof int_types / sizeof *int_types; l++) {
                const char *ct = coord_types[c];
                int is_float = strstr(ct, "float") || !strcmp(ct, "double");
                int is_unsigned = ct[0] == 'u';
                double v[12] = { 0, 0, 0, 100, 0, 0, 0, 50, 0, 0, 0, 7 };
                if (is_float) { v[3] = 1.375; v[7] = -0.3; v[11] = 1000.0 / 3; }
                else if (!is_unsigned) { v[7] = -50; }
                const char *it = int_types[(l + c) % 12];
                tetra_binary(&B, formats[f], ct, int_types[l], it, v);
                silk_status st = load_buf(&B);
                CHECKF(st == SILK_OK, "%s %s %s %s: %s", formats[f], ct, int_types[l], it, err.msg);
                if (st != SILK_OK) continue;
                int ok = mesh.ntris == 4 && tri_is(0, 0, 2, 1) && tri_is(3, 1, 2, 3);
                for (int i = 0; i < 12; i++) {
                    /* the reference is the value as stored in the file's type */
                    double stored = strstr(ct, "64") || !strcmp(ct, "double") ? v[i] : is_float ? (double)(float)v[i] : v[i];
                    ok &= (&mesh.pos[0].x)[i] == ref_fx(stored);
                }
                CHECKF(ok, "%s %s %s %s: wrong mesh", formats[f], ct, int_types[l], it);
                combos++;
            }
    printf("  %d type combinations\n", combos);
}

/* Random binary values: Q16.16 must be the correctly rounded value. */
static void random_values(int use_f64, int be, const silk_load_opts *o, double scale, int *bad, int *off_by_one)
{
    enum { N = 2000 };
    static double v[N * 3];
    start(&B, be ? "binary_big_endian" : "binary_little_endian");
    char h[256];
    const char *t = use_f64 ? "double" : "float";
    snprintf(h, sizeof h, "element vertex %d\nproperty %s x\nproperty %s y\nproperty %s z\n"
             "element face 1\nproperty list uchar uint vertex_indices\nend_header\n", N, t, t, t);
    put_str(&B, h);
    for (int i = 0; i < 3 * N; i++) {
        double x;
        switch (i % 5) {
        case 0: x = check_uniform(-1024, 1024); break;
        case 1: x = check_uniform(-1, 1) * 1e-4; break;                   /* below one ulp */
        case 2: x = (double)((int64_t)(check_rand64() % 134217728) - 67108864) / 65536.0 + 1.0 / 131072; break; /* ties */
        case 3: x = ldexp(check_uniform(-1, 1), -(int)(check_rand64() % 40)); break;
        default: x = (double)((int64_t)(check_rand64() % 2049) - 1024); break;
        }
        if (i < 3) x = i == 0 ? 5 : 0;       /* a model of size >= SILK_SIZE_MIN */
        if (!use_f64) x = (float)x;
        v[i] = x;
        if (use_f64) put_f64(&B, x); else put_f32(&B, (float)x);
    }
    put_bytes(&B, 3, 1);
    put_bytes(&B, 0, 4); put_bytes(&B, 1, 4); put_bytes(&B, 2, 4);
    silk_status st = load_buf_opts(&B, o);
    CHECKF(st == SILK_OK, "%s", err.msg);
    if (st != SILK_OK) return;
    for (int i = 0; i < 3 * N; i++) {
        silk_fx want = ref_fx(v[i] * scale), got = (&mesh.pos[0].x)[i];
        if (got != want) (*bad)++;
        if (got - want > 1 || want - got > 1) (*off_by_one)++;
    }
}

TEST(ieee_decoding_is_exact)
{
    int bad = 0, far = 0;
    for (int f64 = 0; f64 < 2; f64++)
        for (int be = 0; be < 2; be++) random_values(f64, be, NULL, 1.0, &bad, &far);
    CHECKF(bad == 0, "%d of 24000 values not correctly rounded", bad);
    /* with a scale the decimal path is used: same rounding but for values
     * within 1e-16 (relative) of a tie */
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 5; o.scale.exp10 = -1;
    bad = far = 0;
    for (int f64 = 0; f64 < 2; f64++) random_values(f64, 0, &o, 0.5, &bad, &far);
    CHECKF(far == 0 && bad <= 10, "scaled: %d not correctly rounded, %d off by more than one ulp", bad, far);
    printf("  scaled by 0.5: %d of 12000 values differ from the double reference by one ulp\n", bad);
}

TEST(special_floats)
{
    double v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    v[1] = -0.0;
    v[2] = 1e-310;          /* subnormal double */
    tetra_binary(&B, "binary_little_endian", "double", "uchar", "int", v);
    CHECK(load_buf(&B) == SILK_OK && mesh.pos[0].y == 0 && mesh.pos[0].z == 0);
    v[2] = 1e-40;           /* subnormal float */
    tetra_binary(&B, "binary_big_endian", "float", "uchar", "int", v);
    CHECK(load_buf(&B) == SILK_OK && mesh.pos[0].z == 0);

    v[5] = NAN;
    tetra_binary(&B, "binary_little_endian", "float", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: vertex 1: value is not a finite number (NaN or infinity)");
    v[5] = -INFINITY;
    tetra_binary(&B, "binary_big_endian", "double", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: vertex 1: value is not a finite number (NaN or infinity)");
    v[5] = 0;
    v[9] = 1e30;
    tetra_binary(&B, "binary_little_endian", "float", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_RANGE,
              "t.ply: vertex 3: coordinate 1e+30 is outside the fixed-point range (+-1024); scale the model with --scale 1e-27");
    v[9] = -1500.5;
    tetra_binary(&B, "binary_little_endian", "double", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_RANGE,
              "t.ply: vertex 3: coordinate -1500.5 is outside the fixed-point range (+-1024); scale the model with --scale 0.1");
    v[9] = 40000;
    tetra_binary(&B, "binary_little_endian", "int", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_RANGE,
              "t.ply: vertex 3: coordinate 40000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.01");
    v[9] = 0;
    v[3] = 1e-4; v[7] = 1e-4; v[11] = 1e-4;
    tetra_binary(&B, "binary_little_endian", "double", "uchar", "int", v);
    CHECK_MSG(load_buf(&B), SILK_ERR_RANGE,
              "t.ply: model is too small for fixed-point precision (size 0.000173); scale it up with --scale 1000");
}

TEST(skipped_elements_and_properties)
{
    start(&B, "binary_big_endian");
    put_str(&B, "comment elements silk does not read, around and between\n"
                "element material 2\nproperty uchar r\nproperty list ushort float weights\nproperty double gloss\n"
                "element vertex 3\n"
                "property uchar red\nproperty float x\nproperty list uchar int neighbours\nproperty float y\n"
                "property double confidence\nproperty float z\nproperty ushort flags\n"
                "element edge 2\nproperty int vertex1\nproperty int vertex2\n"
                "element face 2\n"
                "property uchar flags\nproperty list uint short vertex_index\nproperty list uchar float texcoord\n"
                "element tail 3\nproperty short a\n"
                "end_header\n");
    /* material */
    for (int m = 0; m < 2; m++) {
        put_bytes(&B, 9, 1);
        put_bytes(&B, (uint64_t)m + 1, 2);
        for (int k = 0; k <= m; k++) put_f32(&B, 0.5f);
        put_f64(&B, 2.0);
    }
    static const float pos[3][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 3, 0.25f } };
    for (int v = 0; v < 3; v++) {
        put_bytes(&B, 200, 1);
        put_f32(&B, pos[v][0]);
        put_bytes(&B, (uint64_t)v, 1);
        for (int k = 0; k < v; k++) put_bytes(&B, 77, 4);
        put_f32(&B, pos[v][1]);
        put_f64(&B, 0.9);
        put_f32(&B, pos[v][2]);
        put_bytes(&B, 0xffff, 2);
    }
    for (int e = 0; e < 2; e++) { put_bytes(&B, 0, 4); put_bytes(&B, 1, 4); }
    /* a triangle and a quad (fanned), with texcoord lists */
    put_bytes(&B, 1, 1); put_bytes(&B, 3, 4); put_bytes(&B, 0, 2); put_bytes(&B, 1, 2); put_bytes(&B, 2, 2);
    put_bytes(&B, 2, 1); put_f32(&B, 0); put_f32(&B, 0);
    put_bytes(&B, 1, 1); put_bytes(&B, 4, 4); put_bytes(&B, 2, 2); put_bytes(&B, 1, 2); put_bytes(&B, 0, 2); put_bytes(&B, 1, 2);
    put_bytes(&B, 0, 1);
    for (int i = 0; i < 3; i++) put_bytes(&B, 5, 2);
    CHECKF(load_buf(&B) == SILK_OK, "%s", err.msg);
    CHECK(mesh.nverts == 3 && mesh.ntris == 3);
    CHECK(mesh.pos[1].x == 2 * SILK_FX_ONE && mesh.pos[2].y == 3 * SILK_FX_ONE && mesh.pos[2].z == SILK_FX_ONE / 4);
    CHECK(tri_is(0, 0, 1, 2) && tri_is(1, 2, 1, 0) && tri_is(2, 2, 0, 1));
    CHECK(mesh.uv == NULL);
}

TEST(normals_and_uvs)
{
    static const char *const uv_names[3][2] = { { "u", "v" }, { "s", "t" }, { "texture_u", "texture_v" } };
    for (int n = 0; n < 3; n++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                 "property float nx\nproperty float ny\nproperty float nz\nproperty float %s\nproperty float %s\n"
                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0  0 0 -2  0.25 0.5\n1 0 0  0 0 -1  1 0\n0 1 0  0 0 -1e3  0 1\n3 0 1 2\n",
                 uv_names[n][0], uv_names[n][1]);
        silk_load_opts o;
        silk_load_opts_default(&o);
        o.normals = SILK_NORMALS_FILE;
        B.n = strlen(text);
        memcpy(B.d, text, B.n);
        CHECKF(load_buf_opts(&B, &o) == SILK_OK, "%s", err.msg);
        CHECK(mesh.nuvs == 3 && mesh.uv && mesh.tri_uv);
        CHECK(mesh.uv[0].x == SILK_FX_ONE / 4 && mesh.uv[0].y == SILK_FX_HALF && mesh.uv[2].y == SILK_FX_ONE);
        CHECK(mesh.tri_uv[0] == 0 && mesh.tri_uv[1] == 1 && mesh.tri_uv[2] == 2);
        /* the file says -z although the winding says +z: file mode believes the file */
        for (int c = 0; c < 3; c++) CHECK(mesh.normal[mesh.tri_normal[c]].z == -SILK_FX_ONE);
        o.normals = SILK_NORMALS_COMPUTE;
        CHECK(load_buf_opts(&B, &o) == SILK_OK && mesh.normal[mesh.tri_normal[0]].z == SILK_FX_ONE);
    }
}

TEST(crlf_header_binary_body)
{
    double v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    tetra_binary(&B, "binary_little_endian", "float", "uchar", "int", v);
    /* redo the header with CRLF line ends */
    static buf C;
    const unsigned char *body = (const unsigned char *)strstr((const char *)B.d, "end_header\n") + 11;
    C.n = 0;
    for (const unsigned char *p = B.d; p < body; p++) {
        if (*p == '\n') C.d[C.n++] = '\r';
        C.d[C.n++] = *p;
    }
    memcpy(C.d + C.n, body, (size_t)(B.d + B.n - body));
    C.n += (size_t)(B.d + B.n - body);
    CHECKF(load_buf(&C) == SILK_OK, "%s", err.msg);
    CHECK(mesh.pos[1].x == SILK_FX_ONE && mesh.ntris == 4);
}

/* An ascii header + body with one thing changed. */
static silk_status ascii_with(const char *from, const char *to)
{
    static char text[4096];
    const char *p = strstr(tetra_ascii, from);
    if (!p) { printf("test bug: '%s' not in the file\n", from); return SILK_ERR_ARG; }
    size_t a = (size_t)(p - tetra_ascii);
    memcpy(text, tetra_ascii, a);
    strcpy(text + a, to);
    strcat(text, p + strlen(from));
    return load_text(text);
}

TEST(header_errors)
{
    CHECK_MSG(load_text("plx\n"), SILK_ERR_PARSE, "t.ply:1: not a PLY file (the first line is not 'ply')");
    CHECK_MSG(load_text("ply\n"), SILK_ERR_PARSE, "t.ply: header has no end_header line");
    CHECK_MSG(ascii_with("end_header\n", ""), SILK_ERR_PARSE, "t.ply: header has no end_header line");
    CHECK_MSG(ascii_with("ascii", "binary_middle_endian"), SILK_ERR_PARSE, "t.ply:2: unknown PLY format 'binary_middle_endian'");
    CHECK_MSG(ascii_with("1.0", "2.0"), SILK_ERR_PARSE, "t.ply:2: unsupported PLY version '2.0'");
    CHECK_MSG(ascii_with("format ascii 1.0\n", ""), SILK_ERR_PARSE, "t.ply:4: format line missing before 'element'");
    CHECK_MSG(ascii_with("property float y", "property int64 y"), SILK_ERR_PARSE, "t.ply:7: unknown property type 'int64'");
    CHECK_MSG(ascii_with("property float y", "property float"), SILK_ERR_PARSE, "t.ply:7: property line needs a name");
    CHECK_MSG(ascii_with("property float y", "property float y z"), SILK_ERR_PARSE, "t.ply:7: extra text after the property name");
    CHECK_MSG(ascii_with("element vertex 4", "element vertex four"), SILK_ERR_PARSE, "t.ply:5: bad element count 'four'");
    CHECK_MSG(ascii_with("element vertex 4", "element vertex -4"), SILK_ERR_PARSE, "t.ply:5: bad element count '-4'");
    CHECK_MSG(ascii_with("element vertex 4", "element vertex 99999999999999999999999"), SILK_ERR_PARSE,
              "t.ply:5: bad element count '99999999999999999999999'");
    CHECK_MSG(ascii_with("element vertex 4\n", "property float w\nelement vertex 4\n"), SILK_ERR_PARSE,
              "t.ply:5: property before any element");
    CHECK_MSG(ascii_with("property float y\n", ""), SILK_ERR_PARSE, "t.ply:5: element 'vertex' has no property 'y'");
    CHECK_MSG(ascii_with("property float y", "property list uchar float y"), SILK_ERR_PARSE,
              "t.ply:7: property 'y' must not be a list");
    CHECK_MSG(ascii_with("list uchar int", "list float int"), SILK_ERR_PARSE, "t.ply:10: list count type must be an integer type");
    CHECK_MSG(ascii_with("list uchar int", "list uchar float"), SILK_ERR_PARSE, "t.ply:10: 'vertex_indices' must have an integer type");
    CHECK_MSG(ascii_with("property list uchar int vertex_indices", "property int vertex_indices"), SILK_ERR_PARSE,
              "t.ply:10: 'vertex_indices' must be a list");
    CHECK_MSG(ascii_with("vertex_indices", "corners"), SILK_ERR_PARSE, "t.ply:9: element 'face' has no 'vertex_indices' list");
    CHECK_MSG(ascii_with("element face 4\nproperty list uchar int vertex_indices\n", ""), SILK_ERR_EMPTY,
              "t.ply: no triangles (no face element)");
    CHECK_MSG(ascii_with("element vertex 4\nproperty float x\nproperty float y\nproperty float z\n", ""),
              SILK_ERR_PARSE, "t.ply: no vertex element");
    CHECK_MSG(ascii_with("element face", "element vertex 2\nelement face"), SILK_ERR_PARSE, "t.ply:9: second 'vertex' element");
    CHECK_MSG(ascii_with("comment", "colour"), SILK_ERR_PARSE, "t.ply:3: unknown header line 'colour'");
    CHECK_MSG(ascii_with("comment made", "comment \x01made"), SILK_ERR_PARSE,
              "t.ply:3: unexpected byte 0x01 in the header (no end_header?)");
    static char longline[1200];
    memset(longline, 'c', sizeof longline - 1);
    memcpy(longline, "comment ", 8);
    longline[sizeof longline - 1] = '\0';
    CHECK_MSG(ascii_with("comment made by hand", longline), SILK_ERR_PARSE, "t.ply:3: header line too long (more than 1024 bytes)");
    CHECK_MSG(ascii_with("element vertex 4", "element vertex 4294967295"), SILK_ERR_RANGE, "t.ply:5: too many vertices (4294967295)");
}

TEST(body_errors_ascii)
{
    CHECK_MSG(ascii_with("0 -2.25 0", "0 -2.25"), SILK_ERR_PARSE, "t.ply:14: too few values for element 'vertex'");
    CHECK_MSG(ascii_with("0 -2.25 0", "0 -2.25 0 1"), SILK_ERR_PARSE, "t.ply:14: too many values for element 'vertex'");
    CHECK_MSG(ascii_with("0 -2.25 0", "0 -2.x5 0"), SILK_ERR_PARSE, "t.ply:14: bad number '-2.x5'");
    CHECK_MSG(ascii_with("0 -2.25 0", "0 NaN 0"), SILK_ERR_PARSE, "t.ply:14: 'NaN' is not a finite number");
    CHECK_MSG(ascii_with("3 0 1 3", "3 0 1 4"), SILK_ERR_PARSE, "t.ply:17: vertex index 4 out of range (4 vertices)");
    CHECK_MSG(ascii_with("3 0 1 3", "3 0 1 -1"), SILK_ERR_PARSE, "t.ply:17: vertex index -1 out of range (4 vertices)");
    CHECK_MSG(ascii_with("3 0 1 3", "3 0 1 x"), SILK_ERR_PARSE, "t.ply:17: bad integer 'x'");
    CHECK_MSG(ascii_with("3 0 1 3", "2 0 1"), SILK_ERR_PARSE, "t.ply:17: face has 2 vertices (at least 3 needed)");
    CHECK_MSG(ascii_with("3 0 1 3", "-3 0 1 3"), SILK_ERR_PARSE, "t.ply:17: negative list length -3");
    CHECK_MSG(ascii_with("3 0 1 3", "3 0 1"), SILK_ERR_PARSE, "t.ply:17: too few values for element 'face'");
    CHECK_MSG(ascii_with("3 1 2 3\n", ""), SILK_ERR_PARSE, "t.ply: file ends after 3 of 4 'face' elements");
    CHECK_MSG(ascii_with("3 1 2 3\n", "3 1 2 3\x7f\n"), SILK_ERR_PARSE, "t.ply:19: unexpected byte 0x7f (not a text file?)");
    CHECK_MSG(ascii_with("element face 4", "element face 400000"), SILK_ERR_PARSE,
              "t.ply: file is truncated: the header declares 400000 'face' elements (at least 2 bytes each) "
              "but only 66 bytes follow the header");
}

TEST(body_errors_binary)
{
    double v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    tetra_binary(&B, "binary_little_endian", "float", "uchar", "int", v);
    size_t full = B.n;
    B.n = full - 1;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: file is truncated: it ends in 'face' element 3 of 4");
    B.n = full - 4 * 13 - 5;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE,
              "t.ply: file is truncated: the header declares 4 'vertex' elements (at least 12 bytes each) "
              "but only 43 bytes follow the header");
    /* index out of range, negative, short face, negative count */
    size_t face0 = full - 4 * 13;
    B.n = full;
    B.d[face0 + 1] = 9;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: face 0: vertex index 9 out of range (4 vertices)");
    B.d[face0 + 1] = 0xff; B.d[face0 + 2] = 0xff; B.d[face0 + 3] = 0xff; B.d[face0 + 4] = 0xff;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: face 0: vertex index -1 out of range (4 vertices)");
    tetra_binary(&B, "binary_big_endian", "float", "char", "uint", v);
    B.d[B.n - 13] = 2;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: face 3: face has 2 vertices (at least 3 needed)");
    B.d[B.n - 13] = 0x80;
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: face 3: negative list length -128");
    tetra_binary(&B, "binary_big_endian", "float", "uint", "uint", v);
    B.d[B.n - 16] = 0x7f;                  /* a count of about two billion */
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE, "t.ply: file is truncated: it ends in 'face' element 3 of 4");
    tetra_binary(&B, "binary_big_endian", "uint", "uint", "uint", v);
    B.d[B.n - 4 * 16 - 4 * 3 + 3] = 0;     /* x of vertex 3 becomes 1: fine */
    CHECK(load_buf(&B) == SILK_OK);
    tetra_binary(&B, "binary_big_endian", "uint", "uint", "uint", v);
    B.d[B.n - 4 * 16 - 4 * 2] = 0x80;      /* y of vertex 3 becomes > 2^31 */
    CHECK_MSG(load_buf(&B), SILK_ERR_RANGE,
              "t.ply: vertex 3: coordinate 2.14748e+9 is outside the fixed-point range (+-1024); scale the model with --scale 1e-7");

    /* billions of elements: refused from the header, before any loop or allocation */
    start(&B, "binary_little_endian");
    put_str(&B, "element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; i++) put_f32(&B, 1);
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE,
              "t.ply: file is truncated: the header declares 4000000000 'vertex' elements (at least 12 bytes each) "
              "but only 36 bytes follow the header");
    start(&B, "binary_little_endian");
    put_str(&B, "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 18446744073709551615\nproperty list uchar int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; i++) put_f32(&B, 1);
    CHECK_MSG(load_buf(&B), SILK_ERR_PARSE,
              "t.ply: file is truncated: the header declares 18446744073709551615 'face' elements (at least 1 bytes each) "
              "but only 36 bytes follow the header");
    /* an element without properties costs nothing, whatever its count */
    start(&B, "binary_little_endian");
    put_str(&B, "element nothing 18446744073709551615\n"
                "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; i++) put_f32(&B, i == 3 || i == 7 ? 1.0f : 0.0f);
    put_bytes(&B, 3, 1); put_bytes(&B, 0, 4); put_bytes(&B, 1, 4); put_bytes(&B, 2, 4);
    CHECKF(load_buf(&B) == SILK_OK, "%s", err.msg);
    CHECK(mesh.ntris == 1);
}

TEST(arena_too_small)
{
    static unsigned char small[8192];
    double v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    tetra_binary(&B, "binary_little_endian", "float", "uchar", "int", v);
    /* first the header tables (2 elements, 4 properties; their size is the reader's business) */
    size_t tables = 0;
    char want[128];
    silk_arena_init(&arena, small, 64);
    CHECK(silk_load_ply(B.d, B.n, "t.ply", NULL, &arena, &mesh, &err) == SILK_ERR_NOMEM);
    CHECKF(sscanf(err.msg, "t.ply: arena too small: loading needs %zu bytes, 64 are free", &tables) == 1 &&
           tables > 64 && tables < 1024, "%s", err.msg);
    snprintf(want, sizeof want, "t.ply: arena too small: loading needs %zu bytes, 64 are free", tables);
    CHECKF(strcmp(err.msg, want) == 0, "%s", err.msg);
    CHECK(arena.bottom == 0 && arena.top == 0);
    /* room for the tables, not for positions (48) and triangles (48) */
    silk_arena_init(&arena, small, tables + 64);
    CHECK(silk_load_ply(B.d, B.n, "t.ply", NULL, &arena, &mesh, &err) == SILK_ERR_NOMEM);
    snprintf(want, sizeof want, "t.ply: arena too small: loading needs %zu bytes, %zu are free", tables + 96, tables + 64);
    CHECKF(strcmp(err.msg, want) == 0, "%s", err.msg);
    CHECK(arena.bottom == 0 && arena.top == 0);
    silk_arena_init(&arena, small, sizeof small);
    CHECK(silk_load_ply(B.d, B.n, "t.ply", NULL, &arena, &mesh, &err) == SILK_OK);
}

TEST(scale_option)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 25; o.scale.exp10 = -3;
    double v[12] = { 0, 0, 0, 100, 0, 0, 0, -40, 0, 0, 0, 1000 };
    tetra_binary(&B, "binary_big_endian", "short", "uchar", "int", v);
    CHECK(load_buf_opts(&B, &o) == SILK_OK);
    CHECK(mesh.pos[1].x == ref_fx(2.5) && mesh.pos[2].y == ref_fx(-1) && mesh.pos[3].z == ref_fx(25));
    B.n = strlen(tetra_ascii);
    memcpy(B.d, tetra_ascii, B.n);
    CHECK(load_buf_opts(&B, &o) == SILK_OK);
    CHECK(mesh.pos[1].x == ref_fx(0.0375) && mesh.pos[3].z == ref_fx(0.000025));
}

/* Every prefix of a valid file, and random corruptions of it, must either
 * load or fail with a message naming the file: never crash, never read out
 * of bounds (the sanitizer build checks that). */
static void mangle(const buf *good, const char *what)
{
    static buf m;
    int ok = 0, failed = 0, unnamed = 0;
    /* (an ascii file without its last newline is still whole) */
    for (size_t n = 0; n < good->n - (good->d[good->n - 1] == '\n'); n++) {
        memcpy(m.d, good->d, n);
        m.n = n;
        silk_status st = load_buf(&m);
        if (st == SILK_OK) ok++;
        else { failed++; if (strncmp(err.msg, "t.ply", 5) != 0) unnamed++; }
    }
    CHECKF(ok == 0, "%s: %d truncated files loaded", what, ok);
    for (int i = 0; i < 3000; i++) {
        memcpy(m.d, good->d, good->n);
        m.n = good->n;
        int flips = 1 + (int)(check_rand64() % 4);
        for (int k = 0; k < flips; k++) m.d[check_rand64() % m.n] = (unsigned char)(check_rand64() >> 56);
        silk_status st = load_buf(&m);
        if (st == SILK_OK) {
            ok++;
            CHECK(mesh.ntris > 0 && mesh.nverts > 0);
        } else {
            failed++;
            if (strncmp(err.msg, "t.ply", 5) != 0 || strchr(err.msg, '\n')) unnamed++;
        }
        CHECK(st == SILK_OK || (arena.bottom == 0 && arena.top == 0));
    }
    CHECKF(unnamed == 0, "%s: %d messages do not name the file", what, unnamed);
    printf("  %s: %d loads, %d clean failures\n", what, ok, failed);
}

TEST(truncation_and_corruption)
{
    double v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    static buf good;
    tetra_binary(&good, "binary_little_endian", "double", "ushort", "int", v);
    mangle(&good, "binary");
    tetra_binary(&good, "binary_big_endian", "float", "uchar", "uchar", v);
    mangle(&good, "binary big-endian");
    good.n = strlen(tetra_ascii);
    memcpy(good.d, tetra_ascii, good.n);
    mangle(&good, "ascii");
}

int main(void)
{
    RUN(ascii_basic);
    RUN(binary_all_types);
    RUN(ieee_decoding_is_exact);
    RUN(special_floats);
    RUN(skipped_elements_and_properties);
    RUN(normals_and_uvs);
    RUN(crlf_header_binary_body);
    RUN(header_errors);
    RUN(body_errors_ascii);
    RUN(body_errors_binary);
    RUN(arena_too_small);
    RUN(scale_option);
    RUN(truncation_and_corruption);
    return check_done();
}
