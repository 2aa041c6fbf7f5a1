/*
 * stl.c - STL (ascii and binary) from a memory buffer into a silk_mesh.
 *
 * STL stores each triangle with its own three corners, so the coarse mesh M
 * of paper section III has to be recovered: corners whose coordinates are
 * bit-identical once rounded to Q16.16 become one vertex (the weld below),
 * which gives the shared edges that smoothing, feature detection and
 * orientation need.  Facet normals are not read: silk computes its own.
 *
 * Binary STL is an 80-byte header, a little-endian uint32 triangle count n
 * and n records of 50 bytes (normal, three corners as IEEE-754 binary32,
 * two attribute bytes), so a binary file has exactly 84 + 50 n bytes; that
 * size, not the header text (which may well start with "solid"), tells it
 * from ascii.  Floats are decoded from their bits with integer arithmetic.
 * Ascii STL is read in two passes like OBJ: the first checks the structure
 * (solid / facet / outer loop / 3 vertex / endloop / endfacet / endsolid)
 * and counts facets, the second parses the numbers.
 */
#include <string.h>
#include "load.h"

#define STL_HEADER 84u
#define STL_RECORD 50u
/* As many as silk_mesh_build accepts; keeps 3n corners far from overflow. */
#define STL_MAX_TRIS (1u << 28)

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

int silk_ld_stl_binary_size(const void *data, size_t len)
{
    if (len < STL_HEADER) return 0;
    uint64_t n = le32((const unsigned char *)data + 80);
    return STL_HEADER + STL_RECORD * n == (uint64_t)len;
}

int silk_ld_text_byte(unsigned char ch)
{
    return !((ch < 0x20 && ch != '\t' && ch != '\n' && ch != '\r' && ch != '\f' && ch != '\v') || ch == 0x7f);
}

/* ---- the weld ------------------------------------------------------------------ */

/* Corners in order of position, then of corner number: a total order, so
 * the result does not depend on the sort. */
static int corner_less(const silk_vec3 *p, uint32_t a, uint32_t b)
{
    if (p[a].x != p[b].x) return p[a].x < p[b].x;
    if (p[a].y != p[b].y) return p[a].y < p[b].y;
    if (p[a].z != p[b].z) return p[a].z < p[b].z;
    return a < b;
}

static void sift_down(uint32_t *h, size_t root, size_t n, const silk_vec3 *p)
{
    for (;;) {
        size_t child = 2 * root + 1;
        if (child >= n) return;
        if (child + 1 < n && corner_less(p, h[child], h[child + 1])) child++;
        if (!corner_less(p, h[root], h[child])) return;
        uint32_t t = h[root]; h[root] = h[child]; h[child] = t;
        root = child;
    }
}

/* Heapsort: O(n log n), in place, no recursion. */
static void sort_corners(uint32_t *h, size_t n, const silk_vec3 *p)
{
    for (size_t i = n / 2; i-- > 0;) sift_down(h, i, n, p);
    for (size_t end = n; end-- > 1;) {
        uint32_t t = h[0]; h[0] = h[end]; h[end] = t;
        sift_down(h, 0, end, p);
    }
}

/* Corner positions cpos[0 .. nc-1] (corner 3t+k is corner k of triangle t)
 * into vertices: in->tri gets the vertex of each corner, in->pos (from the
 * arena bottom) one position per distinct point, numbered in the order the
 * corners first use them. */
static silk_status weld(const silk_vec3 *cpos, uint32_t nc, const char *name, silk_arena *a,
                        silk_mesh_input *in, silk_error *err)
{
    silk_arena_mark mark = silk_arena_top_mark(a);
    uint32_t *order = silk_arena_array_top(a, nc, sizeof *order, SILK_MEM_LOAD);
    if (!order) {
        size_t need = 0;
        silk_ld_need(&need, nc, sizeof *order);
        return silk_ld_nomem(err, name, need, a);
    }
    for (uint32_t c = 0; c < nc; c++) order[c] = c;
    sort_corners(order, nc, cpos);

    /* Each corner first points at the lowest corner of its group (the
     * group's first in sorted order), then, walking the corners in file
     * order, at the vertex that lowest corner received. */
    uint32_t nv = 0;
    silk_index *tri = in->tri;
    for (uint32_t i = 0; i < nc; i++) {
        int same = i > 0 && cpos[order[i]].x == cpos[order[i - 1]].x && cpos[order[i]].y == cpos[order[i - 1]].y &&
                   cpos[order[i]].z == cpos[order[i - 1]].z;
        if (!same) nv++;
        tri[order[i]] = same ? tri[order[i - 1]] : order[i];
    }
    silk_arena_top_release(a, &mark);
    in->pos = silk_arena_array(a, nv, sizeof *in->pos, SILK_MEM_MESH);
    if (!in->pos) {
        size_t need = 0;
        silk_ld_need(&need, nv, sizeof *in->pos);
        return silk_ld_nomem(err, name, need, a);
    }
    uint32_t next = 0;
    for (uint32_t c = 0; c < nc; c++) {
        if (tri[c] == c) {
            in->pos[next] = cpos[c];
            tri[c] = next++;
        } else {
            tri[c] = tri[tri[c]];
        }
    }
    in->nverts = nv;
    return SILK_OK;
}

/* ---- ascii --------------------------------------------------------------------- */

typedef silk_ld_text stl_reader;

#define FAIL(r, code, ...) silk_fail((r)->err, (code), (r)->name, (r)->line, __VA_ARGS__)

/* Next non-blank line's first token as [*t, *t + *n), the rest of the line
 * as [*rest, *e).  Returns 0 at the end of the input, -1 after an error. */
static int next_statement(stl_reader *r, const char **t, size_t *n, const char **rest, const char **e,
                          silk_status *st)
{
    while (r->p < r->end) {
        const char *b = r->p, *p = b;
        while (p < r->end && *p != '\n' && *p != '\r') {
            if (!silk_ld_text_byte((unsigned char)*p)) {
                r->line++;
                *st = FAIL(r, SILK_ERR_PARSE, "unexpected byte 0x%02x (not a text file?)", (unsigned)(unsigned char)*p);
                return -1;
            }
            p++;
        }
        r->line++;
        if (p - b > SILK_LD_MAX_LINE) {
            *st = FAIL(r, SILK_ERR_PARSE, "line too long (more than %d bytes)", SILK_LD_MAX_LINE);
            return -1;
        }
        r->p = p < r->end ? p + ((*p == '\r' && p + 1 < r->end && p[1] == '\n') ? 2 : 1) : p;
        /* STL has no comments: '#' is text (a solid may be called "part#2"). */
        while (b < p && (*b == ' ' || *b == '\t' || *b == '\f' || *b == '\v')) b++;
        if (b == p) continue;
        *t = b;
        while (b < p && *b != ' ' && *b != '\t' && *b != '\f' && *b != '\v') b++;
        *n = (size_t)(b - *t);
        *rest = b;
        *e = p;
        return 1;
    }
    return 0;
}

/* Keywords are matched without regard to case: some exporters shout. */
static int keyword_is(const char *t, size_t n, const char *word)
{
    if (strlen(word) != n) return 0;
    for (size_t i = 0; i < n; i++)
        if ((t[i] | 0x20) != word[i]) return 0;
    return 1;
}

enum stl_state { S_OUTSIDE, S_SOLID, S_FACET, S_LOOP, S_LOOP_DONE, S_FACET_DONE };

static const char *expected_in(int state, int corners)
{
    switch (state) {
    case S_OUTSIDE: return "'solid'";
    case S_SOLID: return "'facet' or 'endsolid'";
    case S_FACET: return "'outer loop'";
    case S_LOOP: return corners < 3 ? "'vertex'" : "'endloop'";
    default: return "'endfacet'";
    }
}

/* Both passes: checks the structure and counts facets (cpos == NULL), or
 * also parses each vertex into cpos (sized by the first pass). */
static silk_status ascii_walk(stl_reader *r, uint64_t *facets, silk_vec3 *cpos, silk_ld_coords *coords)
{
    const char *t, *rest, *e, *x;
    size_t n, xn;
    char q[48];
    int state = S_OUTSIDE, corners = 0, got;
    silk_status st = SILK_OK;
    uint64_t nf = 0;
    while ((got = next_statement(r, &t, &n, &rest, &e, &st)) > 0) {
        if (state == S_OUTSIDE && keyword_is(t, n, "solid")) {
            state = S_SOLID;                       /* the name is free text */
        } else if (state == S_SOLID && keyword_is(t, n, "endsolid")) {
            state = S_OUTSIDE;
        } else if (state == S_SOLID && keyword_is(t, n, "facet")) {
            state = S_FACET;                       /* "normal nx ny nz" is not read */
        } else if (state == S_FACET && keyword_is(t, n, "outer")) {
            if (!silk_ld_token(&rest, e, &x, &xn) || !keyword_is(x, xn, "loop"))
                return FAIL(r, SILK_ERR_PARSE, "expected 'outer loop'");
            state = S_LOOP;
            corners = 0;
        } else if (state == S_LOOP && corners < 3 && keyword_is(t, n, "vertex")) {
            silk_decimal d[3];
            int k = 0;
            while (silk_ld_token(&rest, e, &x, &xn)) {
                if (k == 3) return FAIL(r, SILK_ERR_PARSE, "too many values for vertex");
                if (cpos && (st = silk_ld_parse_decimal(x, xn, &d[k], r->name, r->line, r->err))) return st;
                k++;
            }
            if (k < 3) return FAIL(r, SILK_ERR_PARSE, "vertex needs 3 numbers, found %d", k);
            if (cpos) {
                uint32_t c = (uint32_t)(3 * nf + (uint64_t)corners);
                silk_fx *out = &cpos[c].x;
                for (int i = 0; i < 3; i++) silk_ld_coord(coords, d[i], NULL, i, r->line, c, &out[i]);
            }
            corners++;
        } else if (state == S_LOOP && keyword_is(t, n, "endloop")) {
            if (corners < 3) return FAIL(r, SILK_ERR_PARSE, "facet has %d vertices (3 needed)", corners);
            state = S_LOOP_DONE;
        } else if (state == S_LOOP_DONE && keyword_is(t, n, "endfacet")) {
            state = S_SOLID;
            nf++;
            if (nf > STL_MAX_TRIS)
                return FAIL(r, SILK_ERR_RANGE, "more than the %lu triangles supported", (unsigned long)STL_MAX_TRIS);
        } else if (state == S_LOOP && corners == 3 && keyword_is(t, n, "vertex")) {
            return FAIL(r, SILK_ERR_PARSE, "facet has more than 3 vertices (STL facets are triangles)");
        } else {
            return FAIL(r, SILK_ERR_PARSE, "unexpected '%s' (expected %s)", silk_ld_quote(t, n, q, sizeof q),
                        expected_in(state, corners));
        }
    }
    if (got < 0) return st;
    /* A missing final "endsolid" is forgiven; a cut facet is not. */
    if (state != S_OUTSIDE && state != S_SOLID) {
        r->line = 0;
        return FAIL(r, SILK_ERR_PARSE, "file ends inside facet %llu", (unsigned long long)nf + 1);
    }
    *facets = nf;
    return SILK_OK;
}

/* ---- binary -------------------------------------------------------------------- */

static silk_status binary_check(const unsigned char *b, size_t len, const char *name, silk_error *err)
{
    if (len < STL_HEADER)
        return silk_fail(err, SILK_ERR_PARSE, name, 0,
                         "binary STL is too short (%zu bytes; the header alone is %u)", len, STL_HEADER);
    uint64_t n = le32(b + 80), want = STL_HEADER + STL_RECORD * n;
    if (want == (uint64_t)len) return SILK_OK;
    if (want > (uint64_t)len)
        return silk_fail(err, SILK_ERR_PARSE, name, 0,
                         "binary STL is truncated: the header declares %llu triangles (%llu bytes), "
                         "the file has %zu bytes", (unsigned long long)n, (unsigned long long)want, len);
    return silk_fail(err, SILK_ERR_PARSE, name, 0,
                     "binary STL is longer than its header says: %llu triangles take %llu bytes, the file has %zu",
                     (unsigned long long)n, (unsigned long long)want, len);
}

static silk_status binary_fill(const unsigned char *b, uint32_t ntri, silk_vec3 *cpos, silk_ld_coords *coords,
                               const char *name, silk_error *err)
{
    for (uint32_t t = 0; t < ntri; t++) {
        const unsigned char *rec = b + STL_HEADER + (size_t)STL_RECORD * t + 12;   /* past the normal */
        for (uint32_t k = 0; k < 3; k++) {
            silk_fx *out = &cpos[3 * t + k].x;
            for (int i = 0; i < 3; i++) {
                silk_decimal d;
                silk_fx fx;
                int fits;
                if (silk_ld_from_f32(le32(rec + 12 * k + 4 * i), &d, &fx, &fits) != 0)
                    return silk_fail(err, SILK_ERR_PARSE, name, 0,
                                     "triangle %lu: coordinate is not a finite number (NaN or infinity)",
                                     (unsigned long)t + 1);
                silk_ld_coord(coords, d, fits ? &fx : NULL, i, 0, 3 * t + k, &out[i]);
            }
        }
    }
    return SILK_OK;
}

/* ---- entry point --------------------------------------------------------------- */

int silk_ld_stl_solid(const void *data, size_t len)
{
    const unsigned char *p = data;
    size_t i = 0;
    while (i < len && (p[i] == ' ' || p[i] == '\t' || p[i] == '\r' || p[i] == '\n')) i++;
    if (len - i < 5) return 0;
    for (int k = 0; k < 5; k++)
        if ((p[i + k] | 0x20) != "solid"[k]) return 0;
    i += 5;
    return i == len || p[i] == ' ' || p[i] == '\t' || p[i] == '\r' || p[i] == '\n';
}

/* Ascii when it says "solid" and is text; otherwise binary (whose header
 * may say "solid" too).  Only the first 512 bytes are looked at: a binary
 * file's count and first records hold bytes no text has. */
static int looks_ascii(const unsigned char *p, size_t len)
{
    if (!silk_ld_stl_solid(p, len)) return 0;
    for (size_t j = 0; j < len && j < 512; j++)
        if (!silk_ld_text_byte(p[j])) return 0;
    return 1;
}

silk_status silk_load_stl(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err)
{
    silk_load_opts defaults;
    silk_status st0 = silk_ld_start("silk_load_stl", data, len, &name, &opts, &defaults, a, out, err);
    if (st0) return st0;

    const unsigned char *b = data;
    int binary = silk_ld_stl_binary_size(data, len) || !looks_ascii(b, len);
    stl_reader r = { data, (const char *)data + len, 0, name, err };
    uint64_t ntri = 0;
    silk_status st;
    if (binary) {
        if ((st = binary_check(b, len, name, err))) return st;
        ntri = le32(b + 80);
    } else if ((st = ascii_walk(&r, &ntri, NULL, NULL))) {
        return st;
    }
    if (ntri == 0) return silk_fail(err, SILK_ERR_EMPTY, name, 0, "no triangles");
    if (ntri > STL_MAX_TRIS)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "%llu triangles is more than the %lu supported",
                         (unsigned long long)ntri, (unsigned long)STL_MAX_TRIS);

    uint32_t nc = (uint32_t)(3 * ntri);
    size_t need = 0;
    /* the triangles, the corner positions and the weld's sort order */
    if (!silk_ld_need(&need, nc, sizeof(silk_index)) || !silk_ld_need(&need, nc, sizeof(silk_vec3)) ||
        !silk_ld_need(&need, nc, sizeof(uint32_t)) || need > silk_arena_free_bytes(a))
        return silk_ld_nomem(err, name, need, a);

    silk_arena saved = *a;
    silk_arena_mark mark = silk_arena_top_mark(a);
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.ntris = (uint32_t)ntri;
    in.tri = silk_arena_array(a, nc, sizeof(silk_index), SILK_MEM_MESH);
    silk_vec3 *cpos = silk_arena_array_top(a, nc, sizeof *cpos, SILK_MEM_LOAD);
    silk_ld_coords coords;
    silk_ld_coords_init(&coords, opts);
    if (binary) {
        st = binary_fill(b, in.ntris, cpos, &coords, name, err);
    } else {
        r.p = data;
        r.line = 0;
        st = ascii_walk(&r, &ntri, cpos, &coords);
    }
    if (!st) st = silk_ld_coords_finish(&coords, name, err);
    if (!st) st = weld(cpos, nc, name, a, &in, err);
    silk_arena_top_release(a, &mark);
    if (!st) st = silk_mesh_build(&in, name, opts, a, out, err);
    if (st != SILK_OK) {
        silk_ld_arena_restore(a, &saved);
        memset(out, 0, sizeof *out);
    }
    return st;
}
