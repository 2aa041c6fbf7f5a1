/*
 * test_obj.c - the OBJ reader: every syntax feature on small files built in
 * memory (exact Q16.16 values against a double reference), the one-line
 * errors, the --scale range checks, arena handling, and every reference
 * mesh in ../shared/meshes loading with the counts SOURCES.md gives.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "support/testmesh.h"

static unsigned char arena_buf[4 << 20];
static silk_arena arena;
static silk_mesh mesh;
static silk_error err;

static silk_status load_opts(const char *text, const silk_load_opts *o)
{
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    memset(&err, 0, sizeof err);
    return silk_load_obj(text, strlen(text), "t.obj", o, &arena, &mesh, &err);
}

/* The file's triangles as written: these tests check the parser, whose
 * small inputs are not all wound consistently. */
static silk_status load(const char *text)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.orient = SILK_ORIENT_KEEP;
    return load_opts(text, &o);
}

/* Q16.16 of a decimal string, rounded to nearest, halves away from zero. */
static silk_fx ref_fx(double v)
{
    return (silk_fx)llround(v * 65536.0);
}

static int has_pos(uint32_t v, double x, double y, double z)
{
    return mesh.pos[v].x == ref_fx(x) && mesh.pos[v].y == ref_fx(y) && mesh.pos[v].z == ref_fx(z);
}

static int tri_is(uint32_t t, silk_index a, silk_index b, silk_index c)
{
    return mesh.tri[3 * t] == a && mesh.tri[3 * t + 1] == b && mesh.tri[3 * t + 2] == c;
}

#define CHECK_ERR(text, code_, msg_)                                                    \
    do {                                                                               \
        silk_status st_ = load(text);                                                  \
        CHECKF(st_ == (code_), "status %d, want %d (%s)", (int)st_, (int)(code_), err.msg); \
        CHECKF(strcmp(err.msg, (msg_)) == 0, "got \"%s\"\n     want \"%s\"", err.msg, (msg_)); \
        CHECKF(arena.bottom == 0 && arena.top == 0, "arena not restored: %zu/%zu", arena.bottom, arena.top); \
    } while (0)

TEST(basic_triangle)
{
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") == SILK_OK);
    CHECK(mesh.nverts == 3 && mesh.ntris == 1);
    CHECK(has_pos(1, 1, 0, 0) && has_pos(2, 0, 1, 0));
    CHECK(tri_is(0, 0, 1, 2));
    CHECK(mesh.uv == NULL && mesh.tri_uv == NULL);
    CHECK(arena.top == 0);   /* load scratch released */
}

TEST(exact_values)
{
    static const double v[] = { 0.5, -1.25, 3.14159, 1e-3, -1024, 1024, 0.0000076, 123.456789, -0.00001, 7e2 };
    const char *text =
        "v 0.5 -1.25 3.14159\n"
        "v 1e-3 -1024 1024\n"
        "v 0.0000076 123.456789 -0.00001\n"
        "v 7e2 +0 -0.0\n"
        "f 1 2 3\nf 1 3 4\n";
    CHECK(load(text) == SILK_OK);
    const silk_fx *p = &mesh.pos[0].x;
    for (int i = 0; i < 10; i++) CHECKF(p[i] == ref_fx(v[i]), "value %d: %d want %d", i, p[i], ref_fx(v[i]));
    CHECK(p[10] == 0 && p[11] == 0);
}

TEST(random_values_round_exactly)
{
    /* Six-decimal text is never within double error of a Q16.16 tie, so
     * the double reference is exact. */
    enum { N = 3000 };
    static char text[N * 48 + 64];
    static double want[N * 3];
    size_t o = 0;
    for (int i = 0; i < N; i++) {
        o += (size_t)snprintf(text + o, sizeof text - o, "v");
        for (int k = 0; k < 3; k++) {
            long long micro = (long long)(check_rand64() % 2048000001ull) - 1024000000ll;
            want[3 * i + k] = (double)micro / 1e6;
            o += (size_t)snprintf(text + o, sizeof text - o, " %s%lld.%06lld", micro < 0 ? "-" : "",
                                  llabs(micro) / 1000000, llabs(micro) % 1000000);
        }
        o += (size_t)snprintf(text + o, sizeof text - o, "\n");
    }
    snprintf(text + o, sizeof text - o, "f 1 2 3\n");
    CHECK(load(text) == SILK_OK);
    int bad = 0;
    for (int i = 0; i < 3 * N; i++)
        if ((&mesh.pos[0].x)[i + (i / 3) * 0] != ref_fx(want[i])) bad++;
    CHECKF(bad == 0, "%d of %d coordinates not correctly rounded", bad, 3 * N);
}

TEST(vertex_extras)
{
    CHECK(load("v 1 2 3 1.0\nv 4 5 6 0.5 0.25 1\nv 7 8 9 1 0 0 1\nf 1 2 3\n") == SILK_OK);
    CHECK(has_pos(0, 1, 2, 3) && has_pos(1, 4, 5, 6) && has_pos(2, 7, 8, 9));
    CHECK_ERR("v 1 2\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: vertex needs 3 numbers, found 2");
    CHECK_ERR("v 1 2 3 4 5 6 7 8\n", SILK_ERR_PARSE, "t.obj:1: too many values for vertex");
}

TEST(corner_forms)
{
    const char *text =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.25 0\n"
        "vn 0 0 1\nvn 0 0 2\n"
        "f 1/1/1 2/2/1 3/3/2\n"
        "f 1/1/1 3/3/2 4/4/2\n";
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.normals = SILK_NORMALS_FILE;
    CHECK(load_opts(text, &o) == SILK_OK);
    CHECK(mesh.ntris == 2 && mesh.nuvs == 4 && mesh.uv && mesh.tri_uv);
    CHECK(mesh.uv[3].x == SILK_FX_HALF && mesh.uv[3].y == SILK_FX_ONE / 4);
    CHECK(mesh.tri_uv[3] == 0 && mesh.tri_uv[4] == 2 && mesh.tri_uv[5] == 3);
    for (uint32_t c = 0; c < 6; c++) {
        silk_vec3 n = mesh.normal[mesh.tri_normal[c]];
        CHECKF(n.x == 0 && n.y == 0 && n.z == SILK_FX_ONE, "corner %u normal %d %d %d", c, n.x, n.y, n.z);
    }

    /* v//n: normals but no uvs */
    CHECK(load_opts("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -3\nf 1//1 2//1 3//1\n", &o) == SILK_OK);
    CHECK(mesh.uv == NULL);
    CHECK(mesh.normal[mesh.tri_normal[0]].z == -SILK_FX_ONE);
    /* v/t */
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nf 1/1 2/1 3/1\n") == SILK_OK);
    CHECK(mesh.nuvs == 1 && mesh.uv[0].x == SILK_FX_ONE / 4 && mesh.uv[0].y == 3 * SILK_FX_ONE / 4);
    /* uvs on some corners only: none are kept */
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3/1\n") == SILK_OK);
    CHECK(mesh.uv == NULL && mesh.nuvs == 0);
    /* a vt with one number: v defaults to 0 */
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nf 1/1 2/1 3/1\n") == SILK_OK);
    CHECK(mesh.uv[0].x == SILK_FX_HALF && mesh.uv[0].y == 0);
}

/* --normals auto (the default): the file's normals when every corner has
 * one, computed ones otherwise; the mesh says which it used. */
TEST(normals_auto)
{
    const char *all = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 1\nf 1//1 2//1 3//1\n";
    const char *some = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 1\nf 1//1 2 3//1\n";
    silk_load_opts o;
    silk_load_opts_default(&o);
    CHECK(load_opts(all, &o) == SILK_OK && mesh.normals_used == SILK_NORMALS_FILE);
    CHECK(mesh.normal[0].y == mesh.normal[0].z && mesh.normal[0].y > 0 && mesh.normal[0].x == 0);
    CHECK(load_opts(some, &o) == SILK_OK && mesh.normals_used == SILK_NORMALS_COMPUTE);
    CHECK(mesh.normal[0].z == SILK_FX_ONE);
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") == SILK_OK && mesh.normals_used == SILK_NORMALS_COMPUTE);
    o.normals = SILK_NORMALS_COMPUTE;
    CHECK(load_opts(all, &o) == SILK_OK && mesh.normals_used == SILK_NORMALS_COMPUTE && mesh.normal[0].z == SILK_FX_ONE);
    o.normals = SILK_NORMALS_FILE;
    CHECK(load_opts(all, &o) == SILK_OK && mesh.normals_used == SILK_NORMALS_FILE);
}

TEST(file_normals_ignored_when_computing)
{
    /* The file's normal points the wrong way; compute mode must not use it. */
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.normals = SILK_NORMALS_COMPUTE;
    CHECK(load_opts("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1\nf 1//1 2//1 3//1\n", &o) == SILK_OK);
    CHECK(mesh.normal[mesh.tri_normal[0]].z == SILK_FX_ONE);
}

TEST(negative_and_forward_indices)
{
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -3 -2\nf -1 -2 -4\n") == SILK_OK);
    CHECK(tri_is(0, 0, 1, 2) && tri_is(1, 3, 2, 0));
    /* relative to the vertices read so far, not to the file's total */
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nv 6 5 5\nf -1 -2 -3\n") == SILK_OK);
    CHECK(tri_is(0, 0, 1, 2) && tri_is(1, 4, 3, 2));
    /* a face may name vertices defined after it */
    CHECK(load("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n") == SILK_OK);
    CHECK(tri_is(0, 0, 1, 2));
}

TEST(polygons_are_fanned)
{
    CHECK(load("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\nf 1 2 3 4\nf 1 4 5 2 3\n") == SILK_OK);
    CHECK(mesh.ntris == 2 + 3);
    CHECK(tri_is(0, 0, 1, 2) && tri_is(1, 0, 2, 3));
    CHECK(tri_is(2, 0, 3, 4) && tri_is(3, 0, 4, 1) && tri_is(4, 0, 1, 2));
}

/* The edge between vertices a and b. */
static const silk_edge *find_edge(silk_index a, silk_index b)
{
    for (uint32_t e = 0; e < mesh.nedges; e++)
        if ((mesh.edge[e].v[0] == a && mesh.edge[e].v[1] == b) || (mesh.edge[e].v[0] == b && mesh.edge[e].v[1] == a))
            return &mesh.edge[e];
    return NULL;
}

TEST(smoothing_groups)
{
    /* A flat strip of three triangles: only a change of group makes a feature. */
    const char *base = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n";
    char text[256];
    snprintf(text, sizeof text, "%ss 1\nf 1 2 3\nf 2 4 3\ns 2\nf 2 5 4\n", base);
    CHECK(load(text) == SILK_OK);
    const silk_edge *e23 = find_edge(1, 2), *e24 = find_edge(1, 3);
    CHECK(e23 && !(e23->flags & SILK_EDGE_GROUPS));
    CHECK(e24 && (e24->flags & SILK_EDGE_GROUPS));
    snprintf(text, sizeof text, "%ss off\nf 1 2 3\ns 0\nf 2 4 3\ns 7\nf 2 5 4\n", base);
    CHECK(load(text) == SILK_OK);
    e23 = find_edge(1, 2); e24 = find_edge(1, 3);
    CHECK(e23 && !(e23->flags & SILK_EDGE_GROUPS) && e24 && (e24->flags & SILK_EDGE_GROUPS));
    /* no `s` at all: no group edges */
    snprintf(text, sizeof text, "%sf 1 2 3\nf 2 4 3\nf 2 5 4\n", base);
    CHECK(load(text) == SILK_OK);
    for (uint32_t e = 0; e < mesh.nedges; e++) CHECK(!(mesh.edge[e].flags & SILK_EDGE_GROUPS));
    CHECK_ERR("s x1\n", SILK_ERR_PARSE, "t.obj:1: bad smoothing group 'x1'");
    CHECK_ERR("s\n", SILK_ERR_PARSE, "t.obj:1: smoothing group needs a number or 'off'");
}

TEST(text_conventions)
{
    const char *text =
        "\xEF\xBB\xBF# exported by something\r\n"
        "mtllib x.mtl\r\n"
        "o thing\r\n\r\n"
        "g part one\r"
        "usemtl red\n"
        "  v\t0 0 0   # trailing comment\n"
        "v 1 0 0\n"
        "vp 0.5 0.5\n"
        "v 0 1 0\n"
        "l 1 2\n"
        "p 1\n"
        "curv 0 1 1 2\n"
        "frobnicate 1 2 3\n"
        "\t\n"
        "f 1 2 3 # a face\n"
        "v 0 0 1";                 /* no newline at the end */
    CHECK(load(text) == SILK_OK);
    CHECK(mesh.nverts == 4 && mesh.ntris == 1);
    CHECK(has_pos(3, 0, 0, 1));
    /* lone CR line ends count as lines for error messages */
    CHECK_ERR("v 0 0 0\rv 1 0 0\rf 1 2 9\r", SILK_ERR_PARSE, "t.obj:3: face index 9 out of range (2 vertices)");
    CHECK_ERR("v 0 0 0\r\nv 1 0 0\r\n\r\nf 1 2 9\r\n", SILK_ERR_PARSE, "t.obj:4: face index 9 out of range (2 vertices)");
}

TEST(scale_option)
{
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 1; o.scale.exp10 = -3;      /* millimetres to metres */
    CHECK(load_opts("v 1500 0 0\nv 0 2500 0\nv 0 0 -333\nf 1 2 3\n", &o) == SILK_OK);
    CHECK(mesh.pos[0].x == ref_fx(1.5) && mesh.pos[1].y == ref_fx(2.5) && mesh.pos[2].z == ref_fx(-0.333));
    o.scale.exp10 = 3;
    CHECK(load_opts("v 0.0015 0 0\nv 0 0.0001 0\nv 0 0 1\nf 1 2 3\n", &o) == SILK_OK);
    CHECK(mesh.pos[0].x == ref_fx(1.5) && mesh.pos[1].y == ref_fx(0.1));
    o.scale.mant = 0;
    CHECK(load_opts("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &o) == SILK_ERR_ARG);
    CHECK(strcmp(err.msg, "t.obj: scale must be positive") == 0);
}

TEST(range_errors)
{
    CHECK_ERR("v 0 0 0\nv 5000 0 0\nv 0 1 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj:2: coordinate 5000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.1");
    /* the suggestion fits the largest coordinate, not just the first bad one */
    CHECK_ERR("v 0 0 0\nv 2000 0 0\nv 0 -250000 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj:2: coordinate 2000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.001");
    CHECK_ERR("v 1e30 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj:1: coordinate 1e+30 is outside the fixed-point range (+-1024); scale the model with --scale 1e-27");
    CHECK_ERR("v 0 0 0\nv 0.001 0 0\nv 0 0 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj: model is too small for fixed-point precision (size 0.001); scale it up with --scale 100");
    CHECK_ERR("v 0 0 0\nv 0.0003 0.0004 0\nv 0 0 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj: model is too small for fixed-point precision (size 0.0005); scale it up with --scale 1000");
    CHECK_ERR("v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj: model has no size (all vertices are at one point)");
    CHECK_ERR("v 500 0 0\nv 500.00001 0 0\nv 500 0.00001 0\nf 1 2 3\n", SILK_ERR_RANGE,
              "t.obj: model is too small for fixed-point precision (size 1.41e-5) this far from the origin "
              "(coordinates up to 500.00001); move it to the origin");
    /* exactly at the limits is fine */
    CHECK(load("v -1024 0 0\nv 1024 0 0\nv 0 1024 0\nf 1 2 3\n") == SILK_OK);
    CHECK(load("v 0 0 0\nv 0.0625 0 0\nv 0 0 0\nf 1 2 3\n") == SILK_OK);

    /* following the advice works */
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 1; o.scale.exp10 = 2;
    CHECK(load_opts("v 0 0 0\nv 0.001 0 0\nv 0 0 0\nf 1 2 3\n", &o) == SILK_OK);
    o.scale.exp10 = -1;
    CHECK(load_opts("v 0 0 0\nv 5000 0 0\nv 0 1 0\nf 1 2 3\n", &o) == SILK_OK);
    CHECK(mesh.pos[1].x == ref_fx(500));
    /* the scale applies before the range check */
    o.scale.exp10 = 4;
    CHECK(load_opts("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &o) == SILK_ERR_RANGE);
    CHECKF(strcmp(err.msg, "t.obj:2: coordinate 10000.0 is outside the fixed-point range (+-1024); "
                           "scale the model with --scale 1000") == 0, "%s", err.msg);
}

TEST(syntax_errors)
{
    const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char t[512];
#define WITH(extra) (snprintf(t, sizeof t, "%s%s", tri, extra), t)
    CHECK_ERR("", SILK_ERR_EMPTY, "t.obj: no triangles");
    CHECK_ERR("# nothing\n\n", SILK_ERR_EMPTY, "t.obj: no triangles");
    CHECK_ERR(tri, SILK_ERR_EMPTY, "t.obj: no triangles");
    CHECK_ERR(WITH("f 1 2\n"), SILK_ERR_PARSE, "t.obj:4: face has 2 vertices (at least 3 needed)");
    CHECK_ERR(WITH("f\n"), SILK_ERR_PARSE, "t.obj:4: face has 0 vertices (at least 3 needed)");
    CHECK_ERR(WITH("f 1 2 0\n"), SILK_ERR_PARSE, "t.obj:4: face index 0 is invalid (OBJ indices start at 1)");
    CHECK_ERR(WITH("f 1 2 4\n"), SILK_ERR_PARSE, "t.obj:4: face index 4 out of range (3 vertices)");
    CHECK_ERR(WITH("f 1 2 99999999999999999999\n"), SILK_ERR_PARSE,
              "t.obj:4: face index 99999999999999999999 out of range (3 vertices)");
    CHECK_ERR(WITH("f -1 -2 -4\n"), SILK_ERR_PARSE, "t.obj:4: face index -4 out of range (3 vertices so far)");
    CHECK_ERR(WITH("f 1 2 3x\n"), SILK_ERR_PARSE, "t.obj:4: bad face vertex '3x'");
    CHECK_ERR(WITH("f 1 2 /3\n"), SILK_ERR_PARSE, "t.obj:4: bad face vertex ''");
    CHECK_ERR(WITH("f 1 2 3/1/1/1\n"), SILK_ERR_PARSE, "t.obj:4: bad face vertex '3/1/1/1'");
    CHECK_ERR(WITH("f 1 2 -\n"), SILK_ERR_PARSE, "t.obj:4: bad face vertex '-'");
    CHECK_ERR(WITH("f 1/1 2/1 3/1\n"), SILK_ERR_PARSE, "t.obj:4: texture index 1 out of range (0 texture coordinates)");
    CHECK_ERR(WITH("vn 0 0 1\nf 1//1 2//1 3//2\n"), SILK_ERR_PARSE, "t.obj:5: normal index 2 out of range (1 normals)");
    CHECK_ERR(WITH("vt 0 0\nf 1/-2 2/1 3/1\n"), SILK_ERR_PARSE,
              "t.obj:5: texture index -2 out of range (1 texture coordinates so far)");
    CHECK_ERR("v 0 0 abc\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: bad number 'abc'");
    CHECK_ERR("v 0 0 1,5\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: bad number '1,5'");
    CHECK_ERR("v 0 0 1e\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: bad number '1e'");
    CHECK_ERR("v 0 nan 0\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: 'nan' is not a finite number");
    CHECK_ERR("v 0 -Inf 0\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: '-Inf' is not a finite number");
    CHECK_ERR("v 0 1e999 0\nf 1 1 1\n", SILK_ERR_RANGE, "t.obj:1: number '1e999' is out of range");
    CHECK_ERR(WITH("vt 0 99999\nf 1/1 2/1 3/1\n"), SILK_ERR_RANGE, "t.obj:4: texture coordinate 99999.0 is out of range");
    CHECK_ERR(WITH("vn 1 2\nf 1 2 3\n"), SILK_ERR_PARSE, "t.obj:4: normal needs 3 numbers, found 2");
    CHECK_ERR("v 0 0 0\x01\nf 1 1 1\n", SILK_ERR_PARSE, "t.obj:1: unexpected byte 0x01 (not a text file?)");
    CHECK_ERR("v 0 0 0\nv 1 0\0 0\n", SILK_ERR_PARSE, "t.obj:2: vertex needs 3 numbers, found 2");  /* strlen stops at the NUL */
#undef WITH
}

TEST(binary_and_long_lines)
{
    static char text[70000];
    memset(text, 'x', sizeof text - 1);
    memcpy(text, "v 0 0 0\n# ", 10);
    text[sizeof text - 1] = '\0';
    CHECK_ERR(text, SILK_ERR_PARSE, "t.obj:2: line too long (more than 65535 bytes)");

    /* garbage bytes, loaded with an explicit length (they contain NULs) */
    unsigned char junk[512];
    for (size_t i = 0; i < sizeof junk; i++) junk[i] = (unsigned char)(check_rand64() >> 56);
    junk[0] = 0;
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    CHECK(silk_load_obj(junk, sizeof junk, "j.obj", NULL, &arena, &mesh, &err) == SILK_ERR_PARSE);
    CHECKF(strcmp(err.msg, "j.obj:1: unexpected byte 0x00 (not a text file?)") == 0, "%s", err.msg);
}

TEST(arena_too_small)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
    static unsigned char small[4096];
    silk_load_opts o;
    silk_load_opts_default(&o);
    /* positions 4*12 -> 48, triangles 12*4 -> 48 */
    silk_arena_init(&arena, small, 64);
    CHECK(silk_load_obj(text, strlen(text), "t.obj", &o, &arena, &mesh, &err) == SILK_ERR_NOMEM);
    CHECKF(strcmp(err.msg, "t.obj: arena too small: loading needs 96 bytes, 64 are free") == 0, "%s", err.msg);
    CHECK(arena.bottom == 0 && arena.top == 0);
    /* enough for the reader, not for the adjacency: the build's own error, arena restored */
    silk_arena_init(&arena, small, 160);
    CHECK(silk_load_obj(text, strlen(text), "t.obj", &o, &arena, &mesh, &err) == SILK_ERR_NOMEM);
    CHECK(arena.bottom == 0 && arena.top == 0 && arena.used[SILK_MEM_MESH] == 0);
    /* find the smallest arena that works: it must work, and loads are deterministic */
    size_t lo = 160, hi = sizeof small;
    silk_arena_init(&arena, small, hi);
    CHECK(silk_load_obj(text, strlen(text), "t.obj", &o, &arena, &mesh, &err) == SILK_OK);
    while (lo + 8 < hi) {
        size_t mid = (lo + hi) / 2 & ~(size_t)7;
        silk_arena_init(&arena, small, mid);
        if (silk_load_obj(text, strlen(text), "t.obj", &o, &arena, &mesh, &err) == SILK_OK) hi = mid; else lo = mid;
    }
    silk_arena_init(&arena, small, hi);
    CHECK(silk_load_obj(text, strlen(text), "t.obj", &o, &arena, &mesh, &err) == SILK_OK);
    CHECK(mesh.ntris == 4 && mesh.nedges == 6 && mesh.nboundary_edges == 0);
    printf("  smallest arena for a tetrahedron: %zu bytes\n", hi);
}

TEST(bad_arguments)
{
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    CHECK(silk_load_obj(NULL, 5, "t.obj", NULL, &arena, &mesh, &err) == SILK_ERR_ARG);
    CHECK(silk_load_obj("v", 1, "t.obj", NULL, NULL, &mesh, &err) == SILK_ERR_ARG);
    CHECK(silk_load_obj("v", 1, "t.obj", NULL, &arena, NULL, &err) == SILK_ERR_ARG);
    CHECK(silk_load_obj(NULL, 0, "t.obj", NULL, &arena, &mesh, NULL) == SILK_ERR_EMPTY);   /* no err is fine */
    CHECK(silk_load_obj("v 0 0 0\nf 1 1 1\n", 16, NULL, NULL, &arena, &mesh, &err) == SILK_ERR_RANGE);
    CHECKF(strncmp(err.msg, "mesh: ", 6) == 0, "%s", err.msg);
}

TEST(dispatch)
{
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const char *ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n2 0 0\n0 2 0\n3 0 1 2\n";
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    CHECK(silk_load_mesh(obj, strlen(obj), "a", NULL, &arena, &mesh, &err) == SILK_OK && mesh.pos[1].x == SILK_FX_ONE);
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    CHECK(silk_load_mesh(ply, strlen(ply), "b", NULL, &arena, &mesh, &err) == SILK_OK && mesh.pos[1].x == 2 * SILK_FX_ONE);
    silk_load_opts o;
    silk_load_opts_default(&o);
    CHECK(o.crease_deg == SILK_DEFAULT_CREASE_DEG && o.scale.mant == 1 && o.scale.exp10 == 0);
    CHECK(o.normals == SILK_NORMALS_AUTO);
}

TEST(truncation_and_corruption)
{
    /* Every prefix and random corruptions of a valid file either load or
     * fail with one line naming the file; the sanitizer build checks that
     * nothing reads outside the buffer (which is not NUL-terminated here). */
    static const char good[] =
        "# cube corner\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 -1\n"
        "s 1\nf 1/1/1 3/3/1 2/2/1\nf 1/1 2/2 4/3\ns off\nf -4//1 -1//1 -2//1\nf 2 3 4\n";
    static char m[sizeof good];
    int ok = 0, failed = 0, unnamed = 0;
    size_t n0 = sizeof good - 1;
    for (int i = 0; i < 4000; i++) {
        size_t n = n0;
        memcpy(m, good, n0);
        if (i < (int)n0) n = (size_t)i;
        else
            for (int k = 0; k < 1 + (int)(check_rand64() % 4); k++)
                m[check_rand64() % n0] = (char)(check_rand64() >> 56);
        char *heap = malloc(n ? n : 1);      /* exact size, so ASan sees any overread */
        memcpy(heap, m, n);
        silk_arena_init(&arena, arena_buf, sizeof arena_buf);
        silk_status st = silk_load_obj(heap, n, "c.obj", NULL, &arena, &mesh, &err);
        free(heap);
        if (st == SILK_OK) ok++;
        else {
            failed++;
            if (strncmp(err.msg, "c.obj", 5) != 0 || strchr(err.msg, '\n')) unnamed++;
            CHECK(arena.bottom == 0 && arena.top == 0);
        }
    }
    CHECKF(unnamed == 0, "%d messages do not name the file", unnamed);
    printf("  %d loads, %d clean failures\n", ok, failed);
}

/* ---- the reference meshes -------------------------------------------------- */

TEST(shared_meshes)
{
    /* Every row of the table in SOURCES.md: | file | tris | verts | bnd | nm-e | ... */
    char path[512];
    size_t slen;
    snprintf(path, sizeof path, "%s/SOURCES.md", check_meshes_dir());
    char *sources = tm_read_file(path, &slen);
    CHECKF(sources != NULL, "cannot read %s", path);
    if (!sources) return;
    size_t big = 16u << 20;
    unsigned char *mem = malloc(big);
    int files = 0;
    for (char *line = sources; line && *line; ) {
        char *next = strchr(line, '\n');
        if (next) *next++ = '\0';
        char file[128];
        unsigned tris, verts, bnd, nme;
        if (sscanf(line, "| %127[^ |] | %u | %u | %u | %u |", file, &tris, &verts, &bnd, &nme) == 5 &&
            strstr(file, ".obj")) {
            size_t len;
            snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), file);
            char *data = tm_read_file(path, &len);
            CHECKF(data != NULL, "cannot read %s", path);
            if (data) {
                silk_arena_init(&arena, mem, big);
                silk_status st = silk_load_mesh(data, len, file, NULL, &arena, &mesh, &err);
                CHECKF(st == SILK_OK, "%s: %s", file, err.msg);
                if (st == SILK_OK) {
                    CHECKF(mesh.ntris == tris && mesh.nverts == verts, "%s: %u/%u, want %u/%u", file,
                           mesh.ntris, mesh.nverts, tris, verts);
                    CHECKF(mesh.nboundary_edges == bnd && mesh.nnonmanifold_edges == nme, "%s: bnd %u nm %u", file,
                           mesh.nboundary_edges, mesh.nnonmanifold_edges);
                    CHECKF(mesh.nedges == 3 * tris / 2, "%s: %u edges", file, mesh.nedges);
                }
                files++;
                free(data);
            }
        }
        line = next;
    }
    CHECKF(files >= 40, "only %d meshes listed", files);
    printf("  %d reference meshes loaded\n", files);
    free(mem);
    free(sources);
}

TEST(shared_mesh_values)
{
    /* cone-70 was generated with exact values: apex (0,1.5,0), rim radius 1 at y=0. */
    char path[512];
    size_t len;
    snprintf(path, sizeof path, "%s/cone-70.obj", check_meshes_dir());
    char *data = tm_read_file(path, &len);
    CHECK(data != NULL);
    if (!data) return;
    silk_arena_init(&arena, arena_buf, sizeof arena_buf);
    CHECK(silk_load_obj(data, len, "cone-70.obj", NULL, &arena, &mesh, &err) == SILK_OK);
    /* compare every vertex with a double parse of the same text */
    uint32_t v = 0;
    int bad = 0;
    for (char *p = data; p && *p; ) {
        double x, y, z;
        if (sscanf(p, "v %lf %lf %lf", &x, &y, &z) == 3) {
            if (v >= mesh.nverts || !has_pos(v, x, y, z)) bad++;
            v++;
        }
        p = strchr(p, '\n');
        if (p) p++;
    }
    CHECK(v == 37 && bad == 0);
    CHECK(mesh.bbox_max.y == ref_fx(1.5) && mesh.bbox_min.y == 0);
    free(data);
}

int main(void)
{
    RUN(basic_triangle);
    RUN(exact_values);
    RUN(random_values_round_exactly);
    RUN(vertex_extras);
    RUN(corner_forms);
    RUN(normals_auto);
    RUN(file_normals_ignored_when_computing);
    RUN(negative_and_forward_indices);
    RUN(polygons_are_fanned);
    RUN(smoothing_groups);
    RUN(text_conventions);
    RUN(scale_option);
    RUN(range_errors);
    RUN(syntax_errors);
    RUN(binary_and_long_lines);
    RUN(arena_too_small);
    RUN(truncation_and_corruption);
    RUN(bad_arguments);
    RUN(dispatch);
    RUN(shared_meshes);
    RUN(shared_mesh_values);
    return check_done();
}
