/*
 * compact_enc.c - the encoder of the compact packed model: a mesh loaded by
 * silk_load_mesh as the bytes of include/silk/compact.h (the contract,
 * field by field), which the core reads in place through the accessors of
 * silk/mesh.h.
 *
 * What it computes, in order:
 *   - the vertices renumbered in the order the triangles first use them
 *     (triangles and their corners stay as they are; unused vertices go),
 *     so that a triangle's vertices are near its index and VFIRST, the first
 *     triangle of every eighth vertex, is non-decreasing;
 *   - each vertex's shading normals in the order its corners first use them
 *     (normals no corner uses go), EXTRA (a vertex's count of normals less
 *     one, as repeats of its index) and each corner's selector into them;
 *   - positions quantized to the smallest power-of-two step that fits
 *     pos_bits over the box, rounded to the nearest step;
 *   - normals and feature tangent directions as the octahedral code whose
 *     decoded vector (the core's own integer decode) is nearest;
 *   - with adjacency: the corner table (the triangle across every side),
 *     the edges as the sides owned by the lower of their two triangles
 *     (numbered after them), the flagged edges' records (LIST: flags and
 *     the two end tangents, straight or coded);
 *   - the header, the CRC and the 4 trailing zero bytes.
 * What the format cannot hold (texture coordinates, vertex colours, a
 * repeated corner, and with adjacency a non-manifold edge or vertex, a
 * winding that turns across an edge, two triangles sharing two sides)
 * is refused with a one-line reason, so that `silk pack` can fall back on
 * the full form.  Host code: double precision, malloc.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compact_enc.h"
#include "silk/compact.h"
#include "silk/model.h"

#define NONE UINT32_MAX
#define MAX_COUNT ((1u << 24) - 1)     /* nverts, nnormals; ntris one less (compact.h) */
#define MAX_SEL_NORMALS 64             /* sel_bits 0..6 */

compact_opts compact_opts_default(void)
{
    compact_opts o = { 12, 10, 8, 1 };
    return o;
}

/* Bits to write x (0 for 0). */
static unsigned bits_for(uint64_t x)
{
    unsigned b = 0;
    while (b < 64 && (x >> b) != 0) b++;
    return b;
}

static size_t bit_bytes(uint64_t count, unsigned width)
{
    return (size_t)((count * width + 7) / 8);
}

/* ---- layout ------------------------------------------------------------------ */

void compact_layout_place(compact_layout *l)
{
    int adj = (l->flags & SILK_COMPACT_ADJACENCY) != 0;
    uint64_t nt = l->ntris, nv = l->nverts;
    l->list_bits = l->edge_bits + 3u + 2u * (1u + 2u * l->dir_bits);
    size_t b[COMPACT_NARRAYS] = {
        bit_bytes(3 * nv, l->pos_bits),
        bit_bytes(2 * (uint64_t)l->nnormals, l->nrm_bits),
        bit_bytes(l->nnormals >= l->nverts ? l->nnormals - l->nverts : 0, l->vtx_bits),
        l->nnormals > l->nverts ? bit_bytes((nv + 7) / 8, bits_for(l->nnormals - l->nverts)) : 0,
        bit_bytes(3 * nt, l->vtx_bits),
        bit_bytes(3 * nt, l->sel_bits),
        adj ? bit_bytes(3 * nt, l->tri_bits) : 0,
        adj ? bit_bytes(l->nlisted, l->list_bits) : 0,
        adj ? bit_bytes((nv + 7) / 8, l->tri_bits) : 0,
    };
    size_t at = SILK_COMPACT_HEADER_BYTES;
    for (int k = 0; k < COMPACT_NARRAYS; k++) {
        l->off[k] = at;
        l->bytes[k] = b[k];
        at += b[k];
    }
    l->size = at + 4;
}

static uint32_t rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void wr16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8);
}

static void wr32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}

int compact_layout_read(const uint8_t *b, size_t len, compact_layout *l)
{
    memset(l, 0, sizeof *l);
    if (len < SILK_COMPACT_HEADER_BYTES || memcmp(b, SILK_COMPACT_MAGIC, 4) != 0) return -1;
    l->flags = (uint32_t)b[6] | (uint32_t)b[7] << 8;
    l->nverts = rd32(b + 8);
    l->ntris = rd32(b + 12);
    l->nnormals = rd32(b + 16);
    l->nedges = rd32(b + 20);
    l->nlisted = rd32(b + 24);
    for (int k = 0; k < 3; k++) l->org[k] = (int32_t)rd32(b + 28 + 4 * k);
    l->pos_bits = b[40], l->pos_shift = b[41], l->nrm_bits = b[42], l->sel_bits = b[43];
    l->vtx_bits = b[44], l->tri_bits = b[45], l->edge_bits = b[46], l->dir_bits = b[47];
    compact_layout_place(l);
    return l->size == rd32(b + 48) && l->size <= len ? 0 : -1;
}

/* ---- octahedral codes -------------------------------------------------------- */

/* The code's vector exactly as the core decodes it, so that the search
 * below picks by the integers a device will see. */
static void octa_vec(uint32_t u, uint32_t v, unsigned bits, double out[3])
{
    silk_vec3 d = silk_compact_octa(u, v, bits);
    out[0] = d.x / 65536.0, out[1] = d.y / 65536.0, out[2] = d.z / 65536.0;
}

static double sgn1(double x) { return x < 0 ? -1 : 1; }

void compact_octa_encode(const double d3[3], unsigned bits, uint32_t *u, uint32_t *v)
{
    /* no direction (a normal of zero-area triangles only): any code will do, +z's */
    static const double up[3] = { 0, 0, 1 };
    const double *d = d3[0] != 0 || d3[1] != 0 || d3[2] != 0 ? d3 : up;
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double s = fabs(d[0]) + fabs(d[1]) + fabs(d[2]);
    double n[3] = { d[0] / len, d[1] / len, d[2] / len };
    double x = d[0] / s, y = d[1] / s;
    if (d[2] < 0) {   /* the lower half, folded over the diamond's edges */
        double fx = (1 - fabs(y)) * sgn1(x), fy = (1 - fabs(x)) * sgn1(y);
        x = fx, y = fy;
    }
    const double m = (double)((1u << bits) - 1);
    /* The projection's rounding is not the nearest code on the sphere (the
     * map stretches, and the decode normalizes integers): the 4 x 4 codes
     * around it are tried.  By the cosine of the angle, not the dot alone:
     * a decoded vector is unit only to Q16.16's rounding, 1e-5, which is
     * what the dots of neighbouring codes differ by from 10 bits on, so the
     * largest dot would pick the longest vector, not the nearest one. */
    long u0 = (long)floor((x * m + m) / 2), v0 = (long)floor((y * m + m) / 2);
    double best = -2;
    for (long i = u0 - 1; i <= u0 + 2; i++)
        for (long j = v0 - 1; j <= v0 + 2; j++) {
            if (i < 0 || j < 0 || i > (long)m || j > (long)m) continue;
            double c[3];
            octa_vec((uint32_t)i, (uint32_t)j, bits, c);
            double cl = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            double cosine = (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) / cl;
            if (cosine > best) {
                best = cosine;
                *u = (uint32_t)i, *v = (uint32_t)j;
            }
        }
}

/* ---- the encoder's state ----------------------------------------------------- */

typedef struct enc {
    const silk_mesh *m;
    compact_opts o;
    char *why;
    size_t whylen;
    compact_layout l;
    uint32_t *vnew;     /* m->nverts: the new number of each vertex, NONE when unused */
    uint32_t *vold;     /* nverts: the loaded number of each new vertex */
    uint32_t *vtri;     /* nverts: the first triangle using each new vertex */
    uint32_t *nfirst;   /* nverts + 1: each new vertex's first new normal */
    uint32_t *nold;     /* nnormals: the loaded normal of each new one */
    uint8_t *sel;       /* 3 ntris: each corner's normal among its vertex's */
    uint32_t *cfirst;   /* nverts + 1, corners: the corners of each new vertex ... */
    uint32_t *corner;   /* 3 ntris: ... in corner order */
    uint32_t *opp;      /* 3 ntris: the triangle across each side, NONE on a boundary */
    uint32_t *eid;      /* 3 ntris: the compact edge of each side */
    uint32_t *eside;    /* nedges: the side (3t + k) that owns each compact edge */
    uint32_t *listed;   /* nlisted: the compact edges in LIST, by id */
    uint32_t (*q)[3];   /* nverts: quantized positions */
} enc;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static int refuse(enc *e, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (e->why && e->whylen) vsnprintf(e->why, e->whylen, fmt, ap);
    va_end(ap);
    return -1;
}

static void enc_free(enc *e)
{
    free(e->vnew), free(e->vold), free(e->vtri), free(e->nfirst), free(e->nold), free(e->sel);
    free(e->cfirst), free(e->corner), free(e->opp), free(e->eid), free(e->eside), free(e->listed), free(e->q);
}

static int nomem(enc *e) { return refuse(e, "memory: out of memory for the encoder's tables"); }

static uint32_t next3(uint32_t k) { return k == 2 ? 0 : k + 1; }

/* ---- checks of the input ----------------------------------------------------- */

static int check_opts(enc *e)
{
    const compact_opts *o = &e->o;
    if (o->pos_bits < 1 || o->pos_bits > 16) return refuse(e, "pos_bits of 1..16: got %d", o->pos_bits);
    if (o->nrm_bits < 2 || o->nrm_bits > 16) return refuse(e, "nrm_bits of 2..16: got %d", o->nrm_bits);
    if (o->dir_bits < 2 || o->dir_bits > 16) return refuse(e, "dir_bits of 2..16: got %d", o->dir_bits);
    return 0;
}

/* What the format has no room for, and the corners every model must have. */
static int check_mesh(enc *e)
{
    const silk_mesh *m = e->m;
    if (m->uv || m->nuvs) return refuse(e, "no texture coordinates: the mesh has %lu", (unsigned long)m->nuvs);
    if (m->color) return refuse(e, "no vertex colours: the mesh has them");
    if (!m->tri || !m->pos || m->ntris == 0) return refuse(e, "triangles: the mesh has none");
    if (!m->tri_normal || !m->normal || !m->normal_vertex)
        return refuse(e, "shading normals: the mesh has none");
    if (m->ntris > MAX_COUNT - 1)
        return refuse(e, "at most %lu triangles: the mesh has %lu", (unsigned long)(MAX_COUNT - 1),
                      (unsigned long)m->ntris);
    for (uint32_t t = 0; t < m->ntris; t++) {
        const silk_index *c = &m->tri[3 * (size_t)t];
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
            return refuse(e, "triangles of three different vertices: triangle %lu repeats vertex %lu",
                          (unsigned long)t + 1, (unsigned long)(c[1] == c[2] ? c[1] : c[0]) + 1);
    }
    /* A selector counts among the corner's own vertex's normals. */
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        silk_index n = m->tri_normal[c];
        if (n >= m->nnormals || m->normal_vertex[n] != m->tri[c])
            return refuse(e, "each corner's normal to be its vertex's: corner %lu of triangle %lu is not",
                          (unsigned long)c % 3 + 1, (unsigned long)c / 3 + 1);
    }
    return 0;
}

/* ---- vertices and normals ---------------------------------------------------- */

/* New numbers in the order of first use: a triangle's vertices then sit
 * near each other and VFIRST is non-decreasing (compact.h). */
static int renumber_vertices(enc *e)
{
    const silk_mesh *m = e->m;
    e->vnew = malloc((size_t)m->nverts * sizeof *e->vnew);
    e->vold = malloc((size_t)m->nverts * sizeof *e->vold);
    e->vtri = malloc((size_t)m->nverts * sizeof *e->vtri);
    if (!e->vnew || !e->vold || !e->vtri) return nomem(e);
    for (uint32_t v = 0; v < m->nverts; v++) e->vnew[v] = NONE;
    uint32_t nv = 0;
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        silk_index v = m->tri[c];
        if (e->vnew[v] != NONE) continue;
        e->vnew[v] = nv;
        e->vold[nv] = v;
        e->vtri[nv] = c / 3;
        nv++;
    }
    if (nv > MAX_COUNT)
        return refuse(e, "at most %lu vertices: the mesh uses %lu", (unsigned long)MAX_COUNT, (unsigned long)nv);
    e->l.nverts = nv;
    e->l.vtx_bits = (uint8_t)(nv > 2 ? bits_for(nv - 1) : 1);
    return 0;
}

/* Each vertex's normals in the order its corners first use them, so that
 * a corner's selector is small where it can be (and most are 0, which the
 * reader takes without a look-up); normals no corner uses are dropped. */
static int order_normals(enc *e)
{
    const silk_mesh *m = e->m;
    uint32_t nv = e->l.nverts, nc = 3 * m->ntris;
    uint32_t *local = malloc((size_t)m->nnormals * sizeof *local);   /* a normal's place at its vertex */
    uint32_t *count = calloc((size_t)nv, sizeof *count);
    e->nfirst = malloc(((size_t)nv + 1) * sizeof *e->nfirst);
    e->sel = malloc((size_t)nc);
    if (!local || !count || !e->nfirst || !e->sel) {
        free(local), free(count);
        return nomem(e);
    }
    for (uint32_t n = 0; n < m->nnormals; n++) local[n] = NONE;
    uint32_t most = 0;
    for (uint32_t c = 0; c < nc; c++) {
        uint32_t n = m->tri_normal[c], v = e->vnew[m->tri[c]];
        if (local[n] == NONE) local[n] = count[v]++;
        if (count[v] > most) most = count[v];
        e->sel[c] = (uint8_t)(local[n] < 255 ? local[n] : 255);
    }
    uint64_t nn = 0;
    for (uint32_t v = 0; v < nv; v++) {
        e->nfirst[v] = (uint32_t)(nn < NONE ? nn : NONE);
        nn += count[v];
    }
    int rc = 0;
    if (most > MAX_SEL_NORMALS) {
        uint32_t v = 0;
        while (count[v] != most) v++;
        rc = refuse(e, "at most %d shading normals a vertex: vertex %lu has %lu", MAX_SEL_NORMALS,
                    (unsigned long)e->vold[v] + 1, (unsigned long)most);
    } else if (nn > MAX_COUNT) {
        rc = refuse(e, "at most %lu shading normals: the mesh has %llu", (unsigned long)MAX_COUNT,
                    (unsigned long long)nn);
    }
    if (!rc) {
        e->nfirst[nv] = (uint32_t)nn;
        e->l.nnormals = (uint32_t)nn;
        e->l.sel_bits = (uint8_t)bits_for(most - 1);
        e->nold = malloc((size_t)nn * sizeof *e->nold);
        if (!e->nold) rc = nomem(e);
    }
    /* the model's numbering: normal v is vertex v's first, the others
     * follow all of those in vertex order (EXTRA's order) */
    for (uint32_t c = 0; !rc && c < nc; c++) {
        uint32_t v = e->vnew[m->tri[c]];
        e->nold[e->sel[c] ? nv + (e->nfirst[v] - v) + e->sel[c] - 1 : v] = m->tri_normal[c];
    }
    free(local);
    free(count);
    return rc;
}

/* ---- positions --------------------------------------------------------------- */

/* The smallest step 2^shift over which every coordinate, rounded to the
 * nearest step, fits pos_bits above the box's low corner; and every code
 * pos_bits can hold must decode within the core's coordinate range, since
 * the core checks the fields, not the mesh. */
static int quantize_positions(enc *e)
{
    const silk_mesh *m = e->m;
    uint32_t nv = e->l.nverts;
    int64_t lo[3] = { INT64_MAX, INT64_MAX, INT64_MAX }, hi[3] = { INT64_MIN, INT64_MIN, INT64_MIN };
    for (uint32_t v = 0; v < nv; v++) {
        silk_vec3 p = m->pos[e->vold[v]];
        int64_t c[3] = { p.x, p.y, p.z };
        for (int k = 0; k < 3; k++) {
            if (c[k] < lo[k]) lo[k] = c[k];
            if (c[k] > hi[k]) hi[k] = c[k];
        }
    }
    int64_t span = 0;
    for (int k = 0; k < 3; k++)
        if (hi[k] - lo[k] > span) span = hi[k] - lo[k];
    const int pb = e->o.pos_bits;
    const int64_t top = ((int64_t)1 << pb) - 1;
    int shift = 0;
    while (shift <= 15 && ((span + (shift ? (int64_t)1 << (shift - 1) : 0)) >> shift) > top) shift++;
    if (shift > 15)
        return refuse(e, "a box of at most %lld Q16.16 steps for %d-bit positions: it spans %lld", (long long)top << 15,
                      pb, (long long)span);
    for (int k = 0; k < 3; k++)
        if (lo[k] + (top << shift) > SILK_COORD_MAX)
            return refuse(e, "every %d-bit position code within +-1024: %c codes reach %.6g", pb, "xyz"[k],
                          (double)(lo[k] + (top << shift)) / 65536.0);
    e->q = malloc((size_t)nv * sizeof *e->q);
    if (!e->q) return nomem(e);
    const int64_t half = shift ? (int64_t)1 << (shift - 1) : 0;
    for (uint32_t v = 0; v < nv; v++) {
        silk_vec3 p = m->pos[e->vold[v]];
        int64_t c[3] = { p.x, p.y, p.z };
        for (int k = 0; k < 3; k++) e->q[v][k] = (uint32_t)((c[k] - lo[k] + half) >> shift);
    }
    for (int k = 0; k < 3; k++) e->l.org[k] = (int32_t)lo[k];
    e->l.pos_bits = (uint8_t)pb;
    e->l.pos_shift = (uint8_t)shift;
    return 0;
}

/* ---- the corner table -------------------------------------------------------- */

static uint32_t tri_bits_for(uint32_t ntris)
{
    unsigned b = 1;
    while (((uint64_t)1 << b) - 2 < ntris) b++;   /* all ones stays "none" */
    return b;
}

/* The triangle across every side, from the loaded edge table; an edge of
 * three or more triangles has no single one. */
static int build_opp(enc *e)
{
    const silk_mesh *m = e->m;
    uint32_t nc = 3 * m->ntris;
    if (!m->tri_edge || !m->edge) return refuse(e, "edges: the mesh has no edge table");
    e->opp = malloc((size_t)nc * sizeof *e->opp);
    if (!e->opp) return nomem(e);
    for (uint32_t h = 0; h < nc; h++) {
        uint32_t t = h / 3;
        const silk_edge *ed = &m->edge[m->tri_edge[h]];
        if (ed->flags & SILK_EDGE_NONMANIFOLD)
            return refuse(e, "edges of at most two triangles: edge %lu-%lu has more (non-manifold)",
                          (unsigned long)ed->v[0] + 1, (unsigned long)ed->v[1] + 1);
        e->opp[h] = ed->t[1] == SILK_NO_INDEX ? NONE : ed->t[0] == t ? ed->t[1] : ed->t[0];
    }
    return 0;
}

/* The side of triangle u joining loaded vertices a and b (either way
 * round: the corner table does not need one winding), or NONE. */
static uint32_t side_of(const silk_mesh *m, uint32_t u, silk_index a, silk_index b)
{
    for (uint32_t j = 0; j < 3; j++) {
        silk_index x = m->tri[3 * u + j], y = m->tri[3 * u + next3(j)];
        if ((x == a && y == b) || (x == b && y == a)) return j;
    }
    return NONE;
}

/* Every side must find its way back as the decoder looks for it: the
 * triangle across has exactly one side with the same two vertices, and
 * this triangle across that side.  (With manifold edges and no repeated
 * corner it always has; the check keeps the encoder honest.) */
static int check_opp(enc *e)
{
    const silk_mesh *m = e->m;
    for (uint32_t h = 0; h < 3 * m->ntris; h++) {
        uint32_t t = h / 3, u = e->opp[h];
        if (u == NONE) continue;
        silk_index a = m->tri[h], b = m->tri[3 * t + next3(h % 3)];
        uint32_t n = 0, j = NONE;
        for (uint32_t i = 0; i < 3; i++) {
            silk_index x = m->tri[3 * u + i], y = m->tri[3 * u + next3(i)];
            if ((x == a && y == b) || (x == b && y == a)) n++, j = i;
        }
        if (n != 1 || e->opp[3 * u + j] != t)
            return refuse(e, "one triangle across each side: across side %lu of triangle %lu, triangle %lu does not "
                          "share it back (the side across is ambiguous)", (unsigned long)h % 3 + 1,
                          (unsigned long)t + 1, (unsigned long)u + 1);
    }
    return 0;
}

/* The corners of each new vertex, for the fan check. */
static int vertex_corners(enc *e)
{
    const silk_mesh *m = e->m;
    uint32_t nv = e->l.nverts, nc = 3 * m->ntris;
    e->cfirst = calloc((size_t)nv + 1, sizeof *e->cfirst);
    e->corner = malloc((size_t)nc * sizeof *e->corner);
    if (!e->cfirst || !e->corner) return nomem(e);
    for (uint32_t c = 0; c < nc; c++) e->cfirst[e->vnew[m->tri[c]] + 1]++;
    for (uint32_t v = 0; v < nv; v++) e->cfirst[v + 1] += e->cfirst[v];
    uint32_t *fill = calloc((size_t)nv, sizeof *fill);
    if (!fill) return nomem(e);
    for (uint32_t c = 0; c < nc; c++) {
        uint32_t v = e->vnew[m->tri[c]];
        e->corner[e->cfirst[v] + fill[v]++] = c;
    }
    free(fill);
    return 0;
}

/* The corner (0..2) of triangle t at loaded vertex v; 3 when it has none. */
static uint32_t corner_at(const silk_mesh *m, uint32_t t, silk_index v)
{
    for (uint32_t k = 0; k < 3; k++)
        if (m->tri[3 * t + k] == v) return k;
    return 3;
}

/* Cross side *side of *t (a side at v) and leave the triangle across by
 * its other side at v, found by the vertex, not the winding (as the
 * decoder turns).  0 at a boundary or back at t0. */
static int turn(const enc *e, silk_index v, uint32_t t0, uint32_t *t, uint32_t *side)
{
    const silk_mesh *m = e->m;
    uint32_t u = e->opp[3 * *t + *side];
    if (u == NONE || u == t0) return 0;
    silk_index w = m->tri[3 * *t + *side];
    if (w == v) w = m->tri[3 * *t + next3(*side)];
    uint32_t j = corner_at(m, u, v);
    if (j == 3) return 0;   /* not reached: u shares the side at v */
    *side = m->tri[3 * u + next3(j)] == w ? (j + 2) % 3 : j;
    *t = u;
    return 1;
}

/* How many triangles turning about v from corner c0 reaches: out by one
 * side at v until a boundary or back at the start, then out by the other.
 * What the decoder's ring walks, so a vertex whose triangles are more than
 * one fan would lose edges. */
static uint32_t fan_size(const enc *e, silk_index v, uint32_t c0, uint32_t limit)
{
    uint32_t n = 1, t0 = c0 / 3, t = t0, side = c0 % 3;
    while (n <= limit && turn(e, v, t0, &t, &side)) n++;
    if (e->opp[3 * t + side] == t0 && t != t0) return n;   /* a closed fan */
    t = t0, side = (c0 % 3 + 2) % 3;
    while (n <= limit && turn(e, v, t0, &t, &side)) n++;
    return n;
}

static int check_fans(enc *e)
{
    for (uint32_t v = 0; v < e->l.nverts; v++) {
        uint32_t deg = e->cfirst[v + 1] - e->cfirst[v];
        uint32_t n = fan_size(e, e->vold[v], e->corner[e->cfirst[v]], deg);
        if (n != deg)
            return refuse(e, "vertices whose triangles make one fan: vertex %lu's %lu triangles do not (non-manifold "
                          "vertex)", (unsigned long)e->vold[v] + 1, (unsigned long)deg);
    }
    return 0;
}

/* ---- edges ------------------------------------------------------------------- */

/* An edge is the side of its lower triangle (or its only one); the model
 * numbers it after that side (3t + k), the encoder in side order (id). */
static int number_edges(enc *e)
{
    const silk_mesh *m = e->m;
    uint32_t nc = 3 * m->ntris, ne = 0;
    e->eid = malloc((size_t)nc * sizeof *e->eid);
    e->eside = malloc((size_t)nc * sizeof *e->eside);
    if (!e->eid || !e->eside) return nomem(e);
    for (uint32_t h = 0; h < nc; h++) {
        uint32_t u = e->opp[h];
        e->eid[h] = NONE;
        if (u != NONE && u < h / 3) continue;
        e->eside[ne] = h;
        e->eid[h] = ne++;
    }
    /* the side across takes its owner's edge */
    for (uint32_t h = 0; h < nc; h++) {
        if (e->eid[h] != NONE) continue;
        uint32_t u = e->opp[h];
        e->eid[h] = e->eid[3 * u + side_of(m, u, m->tri[h], m->tri[3 * (h / 3) + next3(h % 3)])];
    }
    unsigned eb = bits_for(nc - 1);   /* the model's edge index is a side's */
    if (eb > 24)
        return refuse(e, "at most %lu edges: the mesh has %lu", (unsigned long)MAX_COUNT, (unsigned long)ne);
    e->l.nedges = ne;
    e->l.edge_bits = (uint8_t)(eb ? eb : 1);
    return 0;
}

/* The LIST flags of a compact edge: bit 0 crease, 1 groups, 2 degenerate. */
static uint32_t list_flags(const silk_edge *ed)
{
    return ((ed->flags & SILK_EDGE_CREASE) ? 1u : 0) | ((ed->flags & SILK_EDGE_GROUPS) ? 2u : 0) |
           ((ed->flags & SILK_EDGE_DEGENERATE) ? 4u : 0);
}

static const silk_edge *loaded_edge(const enc *e, uint32_t id)
{
    return &e->m->edge[e->m->tri_edge[e->eside[id]]];
}

/* LIST: every edge with a flag, boundary ones included, by id. */
static int list_edges(enc *e)
{
    uint32_t n = 0;
    e->listed = malloc(((size_t)e->l.nedges + 1) * sizeof *e->listed);
    if (!e->listed) return nomem(e);
    for (uint32_t id = 0; id < e->l.nedges; id++)
        if (e->opp[e->eside[id]] == NONE || list_flags(loaded_edge(e, id))) e->listed[n++] = id;
    e->l.nlisted = n;
    return 0;
}

/* ---- writing ----------------------------------------------------------------- */

/* Value v in bits at .. at+w-1 of a (bit b of the array is bit b%8 of byte b/8). */
static void put_bits(uint8_t *a, uint64_t at, uint32_t v, unsigned w)
{
    for (unsigned j = 0; j < w; j++, at++)
        if ((v >> j) & 1u) a[at >> 3] |= (uint8_t)(1u << (at & 7));
}

static void vec_of(silk_vec3 p, double d[3])
{
    d[0] = p.x, d[1] = p.y, d[2] = p.z;
}

static void write_geometry(const enc *e, uint8_t *b)
{
    const silk_mesh *m = e->m;
    const compact_layout *l = &e->l;
    for (uint32_t v = 0; v < l->nverts; v++)
        for (int k = 0; k < 3; k++)
            put_bits(b + l->off[COMPACT_POS], (3 * (uint64_t)v + k) * l->pos_bits, e->q[v][k], l->pos_bits);
    for (uint32_t n = 0; n < l->nnormals; n++) {
        double d[3];
        uint32_t cu = 0, cv = 0;
        vec_of(m->normal[e->nold[n]], d);
        compact_octa_encode(d, l->nrm_bits, &cu, &cv);
        put_bits(b + l->off[COMPACT_NRM], 2 * (uint64_t)n * l->nrm_bits, cu, l->nrm_bits);
        put_bits(b + l->off[COMPACT_NRM], (2 * (uint64_t)n + 1) * l->nrm_bits, cv, l->nrm_bits);
    }
    uint64_t x = 0;
    unsigned xb = l->nnormals > l->nverts ? bits_for(l->nnormals - l->nverts) : 0;
    for (uint32_t v = 0; v < l->nverts; v++) {
        if (xb && v % 8 == 0) put_bits(b + l->off[COMPACT_XPRE], (uint64_t)(v / 8) * xb, x, xb);
        for (uint32_t i = e->nfirst[v] + 1; i < e->nfirst[v + 1]; i++)
            put_bits(b + l->off[COMPACT_EXTRA], x++ * l->vtx_bits, v, l->vtx_bits);
    }
    for (uint32_t c = 0; c < 3 * l->ntris; c++) {
        put_bits(b + l->off[COMPACT_CORNER], (uint64_t)c * l->vtx_bits, e->vnew[m->tri[c]], l->vtx_bits);
        put_bits(b + l->off[COMPACT_SEL], (uint64_t)c * l->sel_bits, e->sel[c], l->sel_bits);
    }
}

/* One end of a LIST record: straight when the loaded tangent is the chord
 * bit for bit (the decoder then takes its own chord), else its direction. */
static void put_end(const enc *e, uint8_t *a, uint64_t at, silk_vec3 t, silk_vec3 chord)
{
    unsigned w = e->l.dir_bits;
    if ((t.x == chord.x && t.y == chord.y && t.z == chord.z) || (t.x == 0 && t.y == 0 && t.z == 0)) {
        put_bits(a, at, 1, 1);
        return;
    }
    double d[3];
    uint32_t u = 0, v = 0;
    vec_of(t, d);
    compact_octa_encode(d, w, &u, &v);
    put_bits(a, at + 1, u, w);
    put_bits(a, at + 1 + w, v, w);
}

static void write_list(const enc *e, uint8_t *b)
{
    const silk_mesh *m = e->m;
    const compact_layout *l = &e->l;
    uint8_t *a = b + l->off[COMPACT_LIST];
    unsigned end_bits = 1u + 2u * l->dir_bits;
    for (uint32_t i = 0; i < l->nlisted; i++) {
        uint32_t id = e->listed[i];
        const silk_edge *ed = loaded_edge(e, id);
        uint64_t at = (uint64_t)i * l->list_bits;
        put_bits(a, at, e->eside[id], l->edge_bits);   /* the model's index: the owning side */
        put_bits(a, at + l->edge_bits, list_flags(ed), 3);
        at += l->edge_bits + 3u;
        silk_feature_seg s = { { 0, 0, 0 }, { 0, 0, 0 } };
        int has = silk_edge_has_feature(ed) && m->edge_feature && m->feature &&
                  m->edge_feature[m->tri_edge[e->eside[id]]] != SILK_NO_INDEX;
        if (has) s = m->feature[m->edge_feature[m->tri_edge[e->eside[id]]]];
        /* the compact edge runs from its lower new vertex: the loaded one
         * reversed is the same curve with ends swapped and tangents negated */
        silk_index o0 = ed->v[0], o1 = ed->v[1];
        if (e->vnew[o0] > e->vnew[o1]) {
            silk_index sw = o0;
            o0 = o1, o1 = sw;
            silk_feature_seg r = { silk_v3_neg(s.t1), silk_v3_neg(s.t0) };
            s = r;
        }
        silk_vec3 chord = silk_v3_sub(m->pos[o1], m->pos[o0]);
        if (!has) {   /* no segment (a degenerate edge): straight, codes zero */
            put_bits(a, at, 1, 1);
            put_bits(a, at + end_bits, 1, 1);
            continue;
        }
        put_end(e, a, at, s.t0, chord);
        put_end(e, a, at + end_bits, s.t1, chord);
    }
}

static void write_adjacency(const enc *e, uint8_t *b)
{
    const compact_layout *l = &e->l;
    uint32_t none = (1u << l->tri_bits) - 1, nc = 3 * l->ntris;
    for (uint32_t h = 0; h < nc; h++)
        put_bits(b + l->off[COMPACT_OPP], (uint64_t)h * l->tri_bits, e->opp[h] == NONE ? none : e->opp[h], l->tri_bits);
    write_list(e, b);
    for (uint32_t v = 0; v < l->nverts; v += 8)
        put_bits(b + l->off[COMPACT_VFIRST], (uint64_t)(v / 8) * l->tri_bits, e->vtri[v], l->tri_bits);
}

static void write_header(const enc *e, uint8_t *b)
{
    const compact_layout *l = &e->l;
    memcpy(b, SILK_COMPACT_MAGIC, 4);
    wr16(b + 4, SILK_COMPACT_VERSION);
    wr16(b + 6, l->flags);
    wr32(b + 8, l->nverts);
    wr32(b + 12, l->ntris);
    wr32(b + 16, l->nnormals);
    wr32(b + 20, l->nedges);
    wr32(b + 24, l->nlisted);
    for (int k = 0; k < 3; k++) wr32(b + 28 + 4 * k, (uint32_t)l->org[k]);
    uint8_t f[8] = { l->pos_bits, l->pos_shift, l->nrm_bits, l->sel_bits, l->vtx_bits, l->tri_bits, l->edge_bits,
                     l->dir_bits };
    memcpy(b + 40, f, 8);
    wr32(b + 48, (uint32_t)l->size);
    wr32(b + 52, silk_crc32(0, b + SILK_COMPACT_HEADER_BYTES, l->size - SILK_COMPACT_HEADER_BYTES));
}

/* ---- the whole ----------------------------------------------------------------- */

static int encode_steps(enc *e)
{
    const silk_mesh *m = e->m;
    if (check_opts(e) || check_mesh(e) || renumber_vertices(e) || order_normals(e) || quantize_positions(e)) return -1;
    e->l.ntris = m->ntris;
    e->l.tri_bits = (uint8_t)tri_bits_for(m->ntris);
    e->l.nrm_bits = (uint8_t)e->o.nrm_bits;
    e->l.dir_bits = (uint8_t)e->o.dir_bits;
    e->l.edge_bits = 1;
    e->l.flags = (m->normals_used == SILK_NORMALS_FILE ? SILK_COMPACT_FILE_NORMALS : 0) |
                 (m->closed_outward ? SILK_COMPACT_CLOSED : 0);
    if (e->o.adjacency) {
        e->l.flags |= SILK_COMPACT_ADJACENCY;
        if (build_opp(e) || check_opp(e) || vertex_corners(e) || check_fans(e) || number_edges(e) || list_edges(e))
            return -1;
    }
    compact_layout_place(&e->l);
    if (e->l.size > UINT32_MAX) return refuse(e, "at most 4 GB: the model would take %zu bytes", e->l.size);
    return 0;
}

int compact_encode(const silk_mesh *m, const compact_opts *o, uint8_t **out, size_t *len, char *why, size_t whylen)
{
    enc e;
    memset(&e, 0, sizeof e);
    e.m = m;
    e.o = o ? *o : compact_opts_default();
    e.why = why;
    e.whylen = whylen;
    *out = NULL;
    *len = 0;
    if (why && whylen) why[0] = 0;
    int rc = encode_steps(&e);
    uint8_t *b = rc ? NULL : calloc(e.l.size, 1);
    if (!rc && !b) rc = nomem(&e);
    if (!rc) {
        write_geometry(&e, b);
        if (e.o.adjacency) write_adjacency(&e, b);
        write_header(&e, b);   /* last: the CRC covers the arrays */
        *out = b;
        *len = e.l.size;
    }
    enc_free(&e);
    return rc;
}
