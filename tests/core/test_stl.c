/*
 * test_stl.c - the STL reader (src/stl.c) and the choice of reader
 * (silk_load_mesh): ascii and binary files of the same triangles load to
 * the same mesh; binary floats round to Q16.16 as double arithmetic here
 * says; corners weld exactly when their Q16.16 coordinates are identical
 * and never otherwise (against a qsort reference); a binary file whose
 * header says "solid" is binary; the forgiving parts of ascii (case,
 * CRLF, several solids, no final endsolid); --scale; a failed load leaves
 * the arena as it was, at every arena size short of the peak.
 * (The malformed files are in tests/bad/, rendering in tests/cli/cli_stl.sh.)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"

#define ARENA_BYTES (16u << 20)

static unsigned char *arena_mem;

/* A binary STL of nt triangles with corners xyz[9 t + 3 k + i]. */
static unsigned char *binary_stl(const char *header, const float *xyz, uint32_t nt, size_t *len)
{
    *len = 84 + 50 * (size_t)nt;
    unsigned char *b = calloc(1, *len);
    memset(b, ' ', 80);
    memcpy(b, header, strlen(header));
    for (int i = 0; i < 4; i++) b[80 + i] = (unsigned char)(nt >> (8 * i));
    for (uint32_t t = 0; t < nt; t++)
        for (int c = 0; c < 9; c++) {
            uint32_t bits;
            memcpy(&bits, &xyz[9 * t + c], 4);
            for (int i = 0; i < 4; i++) b[84 + 50 * t + 12 + 4 * c + i] = (unsigned char)(bits >> (8 * i));
        }
    return b;
}

/* The same triangles as ascii STL, each float with %.9g (exact round trip). */
static char *ascii_stl(const float *xyz, uint32_t nt, size_t *len)
{
    size_t cap = 64 + (size_t)nt * 300;
    char *s = malloc(cap);
    size_t o = (size_t)snprintf(s, cap, "solid test\n");
    for (uint32_t t = 0; t < nt; t++) {
        o += (size_t)snprintf(s + o, cap - o, "facet normal 0 0 0\nouter loop\n");
        for (int k = 0; k < 3; k++)
            o += (size_t)snprintf(s + o, cap - o, "vertex %.9g %.9g %.9g\n", (double)xyz[9 * t + 3 * k],
                                  (double)xyz[9 * t + 3 * k + 1], (double)xyz[9 * t + 3 * k + 2]);
        o += (size_t)snprintf(s + o, cap - o, "endloop\nendfacet\n");
    }
    o += (size_t)snprintf(s + o, cap - o, "endsolid test\n");
    *len = o;
    return s;
}

static silk_status load(const void *data, size_t len, const char *name, silk_arena *a, silk_mesh *m,
                        silk_error *err)
{
    silk_arena_init(a, arena_mem, ARENA_BYTES);
    return silk_load_mesh(data, len, name, NULL, a, m, err);
}

static const float tetra[] = {
    0, 0, 0, 0, 1, 0, 1, 0, 0,       0, 0, 0, 1, 0, 0, 0, 0, 1,
    0, 0, 0, 0, 0, 1, 0, 1, 0,       1, 0, 0, 0, 1, 0, 0, 0, 1,
};

static int fx_eq(silk_vec3 p, const float *x)
{
    return p.x == (silk_fx)lround(x[0] * 65536.0) && p.y == (silk_fx)lround(x[1] * 65536.0) &&
           p.z == (silk_fx)lround(x[2] * 65536.0);
}

TEST(tetrahedron_both_encodings)
{
    silk_arena a, b;
    silk_mesh ma, mb;
    silk_error err;
    size_t la, lb;
    char *txt = ascii_stl(tetra, 4, &la);
    unsigned char *bin = binary_stl("solid tetra - a binary file", tetra, 4, &lb);
    unsigned char *second = malloc(1u << 20);
    CHECKF(load(txt, la, "t.stl", &a, &ma, &err) == SILK_OK, "%s", err.msg);
    silk_arena_init(&b, second, 1u << 20);
    CHECKF(silk_load_mesh(bin, lb, "t.stl", NULL, &b, &mb, &err) == SILK_OK, "%s", err.msg);
    CHECK(ma.nverts == 4 && ma.ntris == 4 && ma.nedges == 6 && ma.nboundary_edges == 0);
    CHECK(mb.nverts == 4 && mb.ntris == 4 && mb.nedges == 6 && mb.nboundary_edges == 0);
    CHECK(ma.nreoriented_tris == 0 && mb.nreoriented_tris == 0);
    for (uint32_t c = 0; c < 12; c++) {
        CHECK(fx_eq(mb.pos[mb.tri[c]], &tetra[3 * c]));
        CHECK(ma.tri[c] == mb.tri[c]);
    }
    /* vertices numbered in the order the corners first use them */
    CHECK(mb.tri[0] == 0 && mb.tri[1] == 1 && mb.tri[2] == 2 && mb.tri[5] == 3);
    free(second);
    free(txt);
    free(bin);
}

/* Binary coordinates round to nearest Q16.16 (ties away from zero), the
 * same as the double arithmetic here; distinct ones never weld. */
TEST(binary_rounding_and_weld)
{
    enum { NT = 3000 };
    static float xyz[9 * NT];
    for (int i = 0; i < 9 * NT; i++) {
        /* few distinct values, so that many corners coincide */
        int k = (int)(check_rand64() % 40);
        xyz[i] = (float)(k < 20 ? (k - 10) * 0.37 : check_uniform(-900, 900));
        if (k == 0) xyz[i] = -0.0f;
    }
    size_t len;
    unsigned char *bin = binary_stl("", xyz, NT, &len);
    silk_arena a;
    silk_mesh m;
    silk_error err;
    CHECKF(load(bin, len, "r.stl", &a, &m, &err) == SILK_OK, "%s", err.msg);
    CHECK(m.ntris == NT);
    int bad = 0;
    for (uint32_t c = 0; c < 3 * NT && !bad; c++) bad = !fx_eq(m.pos[m.tri[c]], &xyz[3 * c]);
    CHECK(!bad);
    /* reference: the number of distinct rounded positions */
    uint32_t distinct = 0;
    for (uint32_t v = 0; v < m.nverts; v++) {
        int dup = 0;
        for (uint32_t w = 0; w < v && !dup; w++)
            dup = m.pos[v].x == m.pos[w].x && m.pos[v].y == m.pos[w].y && m.pos[v].z == m.pos[w].z;
        distinct += !dup;
    }
    CHECKF(distinct == m.nverts, "%u vertices, %u distinct", m.nverts, distinct);
    free(bin);
}

/* Two corners one Q16.16 step apart stay two vertices: the weld is exact. */
TEST(weld_is_exact)
{
    const char *txt = "solid s\n"
                      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                      "facet normal 0 0 1\nouter loop\nvertex 1.0000153 0 0\nvertex 1 1 0\nvertex 0 1.0\nendloop\nendfacet\n"
                      "endsolid\n";
    silk_arena a;
    silk_mesh m;
    silk_error err;
    /* "0 1.0" is one number short */
    CHECK(load(txt, strlen(txt), "w.stl", &a, &m, &err) == SILK_ERR_PARSE);
    CHECK(strcmp(err.msg, "w.stl:13: vertex needs 3 numbers, found 2") == 0);
    const char *ok = "solid s\n"
                     "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                     "facet normal 0 0 1\nouter loop\nvertex 1.0000153 0 0\nvertex 1 1 0\nvertex 0 1.0 -0\nendloop\nendfacet\n"
                     "endsolid\n";
    CHECKF(load(ok, strlen(ok), "w.stl", &a, &m, &err) == SILK_OK, "%s", err.msg);
    CHECKF(m.nverts == 5, "%u vertices", m.nverts);   /* 1 and 1.0000153 differ by one step; 1.0 == 1, -0 == 0 */
    CHECK(m.tri[5] == 2);
}

TEST(forgiving_ascii)
{
    const char *txt = "  SOLID Part#1 (exported)\r\n"
                      "FACET NORMAL nan nan nan\r\n  OUTER LOOP\r\n\r\n    VERTEX 0 0 0\r\n    VERTEX 1 0 0\r\n"
                      "    VERTEX 0 1 0\r\n  ENDLOOP\r\nENDFACET\r\nENDSOLID Part#1\r\n"
                      "solid second\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
                      "endloop\nendfacet\n";   /* no final endsolid */
    silk_arena a;
    silk_mesh m;
    silk_error err;
    CHECKF(load(txt, strlen(txt), "f.stl", &a, &m, &err) == SILK_OK, "%s", err.msg);
    CHECK(m.ntris == 2 && m.nverts == 4 && m.nedges == 5);
    /* --scale */
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.scale.mant = 25;
    o.scale.exp10 = -1;
    silk_arena_init(&a, arena_mem, ARENA_BYTES);
    CHECK(silk_load_stl(txt, strlen(txt), "f.stl", &o, &a, &m, &err) == SILK_OK);
    CHECK(m.bbox_max.x == SILK_FX_C(5, 2) && m.bbox_max.y == SILK_FX_C(5, 2));
}

/* The reader is chosen by content; a name ending in .stl only makes
 * binary data a damaged binary STL. */
TEST(choosing_the_reader)
{
    size_t len;
    unsigned char *bin = binary_stl("solid looks like ascii", tetra, 4, &len);
    silk_arena a;
    silk_mesh m;
    silk_error err;
    CHECK(load(bin, len, "no-extension", &a, &m, &err) == SILK_OK && m.ntris == 4);
    CHECK(load(bin, len - 10, "no-extension", &a, &m, &err) == SILK_ERR_PARSE);
    CHECKF(strstr(err.msg, "binary STL is truncated") != NULL, "%s", err.msg);
    bin[0] = 'x';   /* no "solid": binary data, an STL only by name */
    CHECK(load(bin, len - 10, "part.STL", &a, &m, &err) == SILK_ERR_PARSE);
    CHECKF(strstr(err.msg, "binary STL is truncated") != NULL, "%s", err.msg);
    CHECK(load(bin, len - 10, "part.bin", &a, &m, &err) == SILK_ERR_PARSE);
    CHECKF(strcmp(err.msg, "part.bin: not a mesh file (binary data); silk reads OBJ, PLY and STL") == 0, "%s",
           err.msg);
    /* an OBJ stays an OBJ, whatever it is called */
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK(load(obj, strlen(obj), "odd.stl", &a, &m, &err) == SILK_OK);
    CHECK(load(obj, strlen(obj), "fine.obj", &a, &m, &err) == SILK_OK);
    free(bin);
}

/* Every arena short of the peak fails with NOMEM and leaves it as it was. */
TEST(small_arenas)
{
    size_t la, lb;
    char *txt = ascii_stl(tetra, 4, &la);
    unsigned char *bin = binary_stl("", tetra, 4, &lb);
    for (int enc = 0; enc < 2; enc++) {
        const void *data = enc ? (const void *)bin : txt;
        size_t len = enc ? lb : la;
        silk_arena a;
        silk_mesh m;
        silk_error err;
        silk_arena_init(&a, arena_mem, ARENA_BYTES);
        CHECK(silk_load_stl(data, len, "s.stl", NULL, &a, &m, &err) == SILK_OK);
        size_t peak = a.peak;
        int bad = 0;
        for (size_t size = 0; size < peak; size += 8) {
            silk_arena_init(&a, arena_mem, size);
            silk_status st = silk_load_stl(data, len, "s.stl", NULL, &a, &m, &err);
            if (st != SILK_ERR_NOMEM || a.bottom != 0 || a.top != 0) bad++;
        }
        CHECKF(bad == 0, "%s: %d arena sizes below the peak %zu did not fail cleanly", enc ? "binary" : "ascii", bad,
               peak);
        silk_arena_init(&a, arena_mem, peak);
        CHECK(silk_load_stl(data, len, "s.stl", NULL, &a, &m, &err) == SILK_OK);
    }
    free(txt);
    free(bin);
}

int main(void)
{
    arena_mem = malloc(ARENA_BYTES);
    RUN(tetrahedron_both_encodings);
    RUN(binary_rounding_and_weld);
    RUN(weld_is_exact);
    RUN(forgiving_ascii);
    RUN(choosing_the_reader);
    RUN(small_arenas);
    free(arena_mem);
    return check_done();
}
