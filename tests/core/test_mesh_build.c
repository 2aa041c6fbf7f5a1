/*
 * test_mesh_build.c - silk_mesh_build(): edges, their triangles and flags,
 * triangle->edge and vertex->edge links, degenerate triangles, bounding box,
 * bad input and small arenas, and the topology of every shared mesh
 * (counts and Euler characteristic against ../shared/meshes/SOURCES.md).
 *
 * The reference adjacency is built independently here: every triangle side
 * as (lo, hi, triangle, side), sorted with qsort.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (48u << 20)

/* ---- the reference adjacency ----------------------------------------------------- */

typedef struct side { uint32_t lo, hi, t, k; } side;

static int side_cmp(const void *pa, const void *pb)
{
    const side *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    if (a->t != b->t) return a->t < b->t ? -1 : 1;
    return a->k < b->k ? -1 : (a->k > b->k);
}

static int tri_degenerate(const silk_mesh *m, uint32_t t)
{
    const silk_index *v = &m->tri[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return 1;
    silk_vec3 p = m->pos[v[0]], q = m->pos[v[1]], r = m->pos[v[2]];
    int64_t ax = (int64_t)q.x - p.x, ay = (int64_t)q.y - p.y, az = (int64_t)q.z - p.z;
    int64_t bx = (int64_t)r.x - p.x, by = (int64_t)r.y - p.y, bz = (int64_t)r.z - p.z;
    return ay * bz - az * by == 0 && az * bx - ax * bz == 0 && ax * by - ay * bx == 0;
}

/* Checks every adjacency field of m against the reference; returns the
 * number of mismatches (each also reported through CHECKF). */
static int check_adjacency(const silk_mesh *m)
{
    int bad0 = check_cur_failed;
    uint32_t ns = 3 * m->ntris;
    side *s = malloc(sizeof *s * ns);
    for (uint32_t t = 0; t < m->ntris; t++)
        for (uint32_t k = 0; k < 3; k++) {
            uint32_t a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
            s[3 * t + k] = (side){ a < b ? a : b, a < b ? b : a, t, k };
        }
    qsort(s, ns, sizeof *s, side_cmp);

    uint32_t ne = 0, nbnd = 0, nnm = 0, ndeg = 0;
    uint8_t *deg = calloc(m->ntris, 1);
    for (uint32_t t = 0; t < m->ntris; t++) ndeg += deg[t] = (uint8_t)tri_degenerate(m, t);
    CHECKF(m->ndegenerate_tris == ndeg, "degenerate triangles %u, expected %u", m->ndegenerate_tris, ndeg);

    for (uint32_t i = 0; i < ns;) {
        uint32_t j = i, ntri = 0, first[2] = { SILK_NO_INDEX, SILK_NO_INDEX }, any_deg = 0;
        for (; j < ns && s[j].lo == s[i].lo && s[j].hi == s[i].hi; j++) {
            if (j == i || s[j].t != s[j - 1].t) {
                if (ntri < 2) first[ntri] = s[j].t;
                ntri++;
            }
            any_deg |= deg[s[j].t];
        }
        if (ne >= m->nedges) { ne++; i = j; continue; }
        const silk_edge *e = &m->edge[ne];
        CHECKF(e->v[0] == s[i].lo && e->v[1] == s[i].hi, "edge %u is %u-%u, expected %u-%u", ne, e->v[0],
               e->v[1], s[i].lo, s[i].hi);
        CHECKF(e->t[0] == first[0] && e->t[1] == first[1], "edge %u triangles %u %u, expected %u %u", ne,
               e->t[0], e->t[1], first[0], first[1]);
        uint32_t want = 0;
        if (s[i].lo == s[i].hi) want = SILK_EDGE_DEGENERATE;
        else {
            if (ntri == 1) want |= SILK_EDGE_BOUNDARY;
            if (ntri > 2) want |= SILK_EDGE_NONMANIFOLD;
            if (any_deg) want |= SILK_EDGE_DEGENERATE;
        }
        uint32_t mask = SILK_EDGE_BOUNDARY | SILK_EDGE_NONMANIFOLD | SILK_EDGE_DEGENERATE;
        CHECKF((e->flags & mask) == want, "edge %u flags %#x, expected %#x", ne, e->flags & mask, want);
        nbnd += (want & SILK_EDGE_BOUNDARY) != 0;
        nnm += (want & SILK_EDGE_NONMANIFOLD) != 0;
        /* Every side of the edge links to it: the edge has exactly its triangles. */
        for (uint32_t q = i; q < j; q++)
            CHECKF(m->tri_edge[3 * s[q].t + s[q].k] == ne, "triangle %u side %u links edge %u, expected %u",
                   s[q].t, s[q].k, m->tri_edge[3 * s[q].t + s[q].k], ne);
        ne++;
        i = j;
    }
    CHECKF(m->nedges == ne, "%u edges, expected %u", m->nedges, ne);
    CHECKF(m->nboundary_edges == nbnd, "%u boundary edges, expected %u", m->nboundary_edges, nbnd);
    CHECKF(m->nnonmanifold_edges == nnm, "%u non-manifold edges, expected %u", m->nnonmanifold_edges, nnm);

    /* vertex -> edges: each vertex lists exactly the edges it ends, in edge order */
    CHECK(m->vert_edge_start[0] == 0);
    uint32_t *fill = calloc(m->nverts, sizeof *fill);
    for (uint32_t e = 0; e < m->nedges && e < ne; e++) {
        for (int end = 0; end < 2; end++) {
            uint32_t v = m->edge[e].v[end];
            if (end == 1 && v == m->edge[e].v[0]) break;
            uint32_t at = m->vert_edge_start[v] + fill[v]++;
            CHECKF(at < m->vert_edge_start[v + 1] && m->vert_edge[at] == e, "vertex %u edge list wrong at %u", v,
                   fill[v] - 1);
        }
    }
    for (uint32_t v = 0; v < m->nverts; v++)
        CHECKF(m->vert_edge_start[v + 1] - m->vert_edge_start[v] == fill[v], "vertex %u has %u edges, expected %u",
               v, m->vert_edge_start[v + 1] - m->vert_edge_start[v], fill[v]);

    /* bounding box */
    silk_vec3 lo = m->pos[0], hi = m->pos[0];
    for (uint32_t v = 0; v < m->nverts; v++) {
        silk_vec3 p = m->pos[v];
        if (p.x < lo.x) lo.x = p.x;
        if (p.y < lo.y) lo.y = p.y;
        if (p.z < lo.z) lo.z = p.z;
        if (p.x > hi.x) hi.x = p.x;
        if (p.y > hi.y) hi.y = p.y;
        if (p.z > hi.z) hi.z = p.z;
    }
    CHECK(memcmp(&lo, &m->bbox_min, sizeof lo) == 0 && memcmp(&hi, &m->bbox_max, sizeof hi) == 0);

    /* every triangle corner has a normal of its own vertex; features match flags */
    for (uint32_t c = 0; c < 3 * m->ntris; c++)
        CHECKF(m->tri_normal[c] < m->nnormals && m->normal_vertex[m->tri_normal[c]] == m->tri[c],
               "corner %u normal %u", c, m->tri_normal[c]);
    uint32_t nfe = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        int feat = (m->edge[e].flags & SILK_EDGE_FEATURE) != 0;
        CHECKF(feat == (m->edge_feature[e] != SILK_NO_INDEX), "edge %u feature link", e);
        if (feat) CHECKF(m->edge_feature[e] == nfe++, "edge %u feature index", e);
    }
    CHECK(m->nfeature_edges == nfe);
    free(fill);
    free(deg);
    free(s);
    return check_cur_failed - bad0;
}

/* ---- hand-made meshes ------------------------------------------------------------ */

static const double tet_pos[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
static const uint32_t tet_tri[] = { 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2 };

static const double cube_pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
static const uint32_t cube_tri[] = {
    0, 3, 2, 0, 2, 1,  4, 5, 6, 4, 6, 7,  0, 1, 5, 0, 5, 4,
    2, 3, 7, 2, 7, 6,  1, 2, 6, 1, 6, 5,  0, 4, 7, 0, 7, 3,
};

TEST(closed_tetrahedron_and_cube)
{
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, tet_pos, 4, tet_tri, 4) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nedges == 6 && f.m.nboundary_edges == 0 && f.m.nnonmanifold_edges == 0);
    CHECK((int)f.m.nverts - (int)f.m.nedges + (int)f.m.ntris == 2);
    check_adjacency(&f.m);
    for (uint32_t v = 0; v < 4; v++) CHECK(f.m.vert_edge_start[v + 1] - f.m.vert_edge_start[v] == 3);
    tm_fixture_free(&f);

    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, cube_pos, 8, cube_tri, 12) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nedges == 18 && f.m.nboundary_edges == 0 && f.m.ndegenerate_tris == 0);
    CHECK((int)f.m.nverts - (int)f.m.nedges + (int)f.m.ntris == 2);
    check_adjacency(&f.m);
    /* with the bounding box of the unit cube */
    CHECK(f.m.bbox_min.x == 0 && f.m.bbox_max.z == SILK_FX_ONE);
    tm_fixture_free(&f);
}

TEST(open_square)
{
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
    static const uint32_t tri[] = { 0, 1, 2, 0, 2, 3 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nedges == 5 && f.m.nboundary_edges == 4);
    check_adjacency(&f.m);
    for (uint32_t e = 0; e < f.m.nedges; e++) {
        const silk_edge *ed = &f.m.edge[e];
        int diag = ed->v[0] == 0 && ed->v[1] == 2;
        CHECKF(diag ? (ed->t[0] == 0 && ed->t[1] == 1) : (ed->t[1] == SILK_NO_INDEX), "edge %u", e);
        CHECK(!diag == ((ed->flags & SILK_EDGE_BOUNDARY) != 0));
    }
    tm_fixture_free(&f);
}

TEST(nonmanifold_fan)
{
    /* three triangles on the edge 0-1 */
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0.2, 0.5, 0, 1 };
    static const uint32_t tri[] = { 0, 1, 2, 1, 0, 3, 0, 1, 4 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 5, tri, 3) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nedges == 7 && f.m.nnonmanifold_edges == 1 && f.m.nboundary_edges == 6);
    check_adjacency(&f.m);
    uint32_t e01 = f.m.tri_edge[0];
    CHECK(f.m.edge[e01].v[0] == 0 && f.m.edge[e01].v[1] == 1);
    CHECK(f.m.edge[e01].t[0] == 0 && f.m.edge[e01].t[1] == 1);
    CHECK(f.m.edge[e01].flags & SILK_EDGE_NONMANIFOLD);
    CHECK(f.m.tri_edge[3 * 1 + 0] == e01 && f.m.tri_edge[3 * 2 + 0] == e01);  /* the third still links */
    /* a non-manifold edge is a feature edge and separates the normals */
    CHECK(f.m.edge_feature[e01] != SILK_NO_INDEX);
    CHECK(f.m.tri_normal[0] != f.m.tri_normal[3 + 1] && f.m.tri_normal[0] != f.m.tri_normal[6]);
    tm_fixture_free(&f);
}

TEST(duplicate_triangles)
{
    uint32_t tri[15];
    memcpy(tri, tet_tri, sizeof tet_tri);
    memcpy(tri + 12, tet_tri, 3 * sizeof *tri);     /* face 0 twice */
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, tet_pos, 4, tri, 5) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nedges == 6 && f.m.nnonmanifold_edges == 3);
    check_adjacency(&f.m);
    tm_fixture_free(&f);
}

TEST(degenerate_triangles)
{
    /* a square, a zero-area triangle on its edge 1-2 (vertex 4 halfway),
     * a triangle repeating vertex 0, and the unused vertex 5 */
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0.5, 0, 7, 7, 7 };
    static const uint32_t tri[] = { 0, 1, 2, 0, 2, 3, 1, 4, 2, 0, 0, 3 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 6, tri, 4) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.ndegenerate_tris == 2);
    check_adjacency(&f.m);
    /* the zero-length side 0-0 is an edge of its own, flagged, never a feature */
    uint32_t e00 = f.m.tri_edge[9];
    CHECK(f.m.edge[e00].v[0] == 0 && f.m.edge[e00].v[1] == 0);
    CHECK(f.m.edge[e00].flags == SILK_EDGE_DEGENERATE && f.m.edge_feature[e00] == SILK_NO_INDEX);
    /* zero-area triangle 2: all three edges flagged, and never creases */
    for (int k = 0; k < 3; k++) {
        uint32_t fl = f.m.edge[f.m.tri_edge[6 + k]].flags;
        CHECK((fl & SILK_EDGE_DEGENERATE) && !(fl & SILK_EDGE_CREASE));
    }
    /* the unused vertex: no edges, no normal, but it is in the bounding box */
    CHECK(f.m.vert_edge_start[6] == f.m.vert_edge_start[5]);
    for (uint32_t n = 0; n < f.m.nnormals; n++) CHECK(f.m.normal_vertex[n] != 5);
    CHECK(f.m.bbox_max.x == d2fx(7));
    /* vertex 4 has only the degenerate triangle: still a unit normal */
    for (uint32_t n = 0; n < f.m.nnormals; n++) {
        silk_vec3 u = f.m.normal[n];
        double l = sqrt((double)u.x * u.x + (double)u.y * u.y + (double)u.z * u.z) / 65536.0;
        CHECKF(fabs(l - 1) < 1e-4, "normal %u length %g", n, l);
    }
    tm_fixture_free(&f);
}

TEST(tiny_face_normal_keeps_direction)
{
    /* a triangle a few ulp across, tilted: the 64-bit cross product keeps
     * its direction exactly where a Q16.16 cross product would be zero */
    static const double pos[] = { 1, 1, 1, 1 + 3 / 65536.0, 1, 1 + 1 / 65536.0, 1, 1 + 2 / 65536.0, 1 };
    static const uint32_t tri[] = { 0, 1, 2 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 3, tri, 1) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.ndegenerate_tris == 0);
    silk_vec3 n = silk_mesh_face_normal(&f.m, 0);
    /* (3,0,1) x (0,2,0) = (-2, 0, 6) */
    double l = sqrt(40.0), ex = -2 / l, ez = 6 / l;
    CHECKF(fabs(n.x / 65536.0 - ex) < 2.0 / 65536 && n.y == 0 && fabs(n.z / 65536.0 - ez) < 2.0 / 65536,
           "normal %d %d %d", n.x, n.y, n.z);
    CHECK(silk_mesh_face_normal(&f.m, 1).x == 0);   /* out of range: zero, no crash */
    tm_fixture_free(&f);
}

TEST(bad_input)
{
    tm_fixture f;
    static const uint32_t bad_tri[] = { 0, 1, 9 };
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, tet_pos, 4, bad_tri, 1));
    CHECK(tm_fixture_build(&f) == SILK_ERR_ARG);
    CHECKF(strcmp(f.err.msg, "test: triangle 1 uses vertex 10 (4 vertices)") == 0, "%s", f.err.msg);
    tm_fixture_free(&f);

    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, tet_pos, 4, tet_tri, 4));
    f.in.pos[2].y = SILK_COORD_MAX + 1;
    CHECK(tm_fixture_build(&f) == SILK_ERR_RANGE);
    CHECKF(strstr(f.err.msg, "vertex 3") != NULL, "%s", f.err.msg);
    f.in.pos[2].y = 0;
    f.in.ntris = 0;
    CHECK(tm_fixture_build(&f) == SILK_ERR_EMPTY);
    CHECKF(strcmp(f.err.msg, "test: no triangles") == 0, "%s", f.err.msg);
    f.in.ntris = 4;
    f.opts.crease_deg = SILK_FX_C(200, 1);
    CHECK(tm_fixture_build(&f) == SILK_ERR_ARG);
    CHECKF(strstr(f.err.msg, "crease angle 200") != NULL, "%s", f.err.msg);
    f.opts.crease_deg = SILK_FX_C(60, 1);
    CHECK(silk_mesh_build(NULL, "test", &f.opts, &f.a, &f.m, &f.err) == SILK_ERR_ARG);
    CHECK(silk_mesh_build(&f.in, "test", NULL, &f.a, &f.m, &f.err) == SILK_ERR_ARG);
    CHECK(silk_mesh_build(&f.in, "test", &f.opts, &f.a, &f.m, NULL) == SILK_OK);
    tm_fixture_free(&f);
}

/* Every arena size below what the build needs fails cleanly with NOMEM
 * (and leaves the top of the arena where it was); the first that suffices
 * gives the same mesh. */
TEST(small_arenas)
{
    tm_fixture big;
    tm_fixture_init(&big, 1 << 16);
    CHECK(tm_fixture_input(&big, cube_pos, 8, cube_tri, 12) && tm_fixture_build(&big) == SILK_OK);
    size_t need = big.a.peak;
    int ok_seen = 0, bad_msgs = 0;
    for (size_t size = 0; size <= need + 64; size += 8) {
        tm_fixture f;
        tm_fixture_init(&f, size);
        if (!tm_fixture_input(&f, cube_pos, 8, cube_tri, 12)) { tm_fixture_free(&f); continue; }
        silk_status st = tm_fixture_build(&f);
        if (st == SILK_OK) {
            ok_seen = 1;
            CHECK(f.m.nedges == 18 && f.m.nnormals == big.m.nnormals);
        } else {
            CHECK(st == SILK_ERR_NOMEM);
            bad_msgs += strstr(f.err.msg, "out of arena memory") == NULL;
        }
        CHECK(f.a.top == 0);
        tm_fixture_free(&f);
    }
    CHECK(ok_seen && bad_msgs == 0);
    printf("  cube needs %lu arena bytes at the peak (bottom %lu)\n", (unsigned long)need,
           (unsigned long)big.a.bottom);
    tm_fixture_free(&big);
}

TEST(bytes_used_adds_up)
{
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, cube_pos, 8, cube_tri, 12) && tm_fixture_build(&f) == SILK_OK);
    silk_mesh_bytes b;
    silk_mesh_bytes_used(&f.m, &b);
    /* positions and triangles come from this test, the rest from the build */
    CHECKF(b.total == f.a.bottom, "bytes_used %lu, arena bottom %lu", (unsigned long)b.total,
           (unsigned long)f.a.bottom);
    CHECK(b.positions == 8 * sizeof(silk_vec3) && b.features > 0);
    tm_fixture_free(&f);
}

/* ---- the shared meshes: counts from SOURCES.md and the Euler characteristic ----- */

TEST(shared_meshes_topology)
{
    char path[512];
    snprintf(path, sizeof path, "%s/SOURCES.md", check_meshes_dir());
    FILE *fp = fopen(path, "r");
    CHECKF(fp != NULL, "cannot open %s", path);
    if (!fp) return;
    char line[1024];
    int nmesh = 0, nclosed = 0;
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    while (fgets(line, sizeof line, fp)) {
        char name[128];
        unsigned tris, verts, bnd, nme, nmv, inc, deg, dup, g, cc;
        if (sscanf(line, "| %127[^ |] | %u | %u | %u | %u | %u | %u | %u | %u | %u | %u |", name, &tris, &verts,
                   &bnd, &nme, &nmv, &inc, &deg, &dup, &g, &cc) != 11)
            continue;
        snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
        silk_arena_init(&f.a, f.buf, ARENA_BYTES);
        memset(&f.in, 0, sizeof f.in);
        CHECKF(tm_fixture_read_obj(&f, path), "cannot read %s", path);
        silk_status st = tm_fixture_build(&f);
        CHECKF(st == SILK_OK, "%s: %s", name, f.err.msg);
        if (st != SILK_OK) continue;
        nmesh++;
        const silk_mesh *m = &f.m;
        CHECKF(m->ntris == tris && m->nverts == verts, "%s: %u tris %u verts", name, m->ntris, m->nverts);
        CHECKF(m->nboundary_edges == bnd && m->nnonmanifold_edges == nme && m->ndegenerate_tris == deg,
               "%s: %u boundary %u non-manifold %u degenerate", name, m->nboundary_edges, m->nnonmanifold_edges,
               m->ndegenerate_tris);
        if (bnd == 0 && nme == 0) {
            long chi = (long)m->nverts - (long)m->nedges + (long)m->ntris;
            CHECKF(chi == 2L * cc - 2L * g, "%s: V-E+F = %ld, genus %u", name, chi, g);
            nclosed++;
        }
        /* only the small ones get the full (quadratic-free but slow) reference */
        if (m->ntris <= 2000) CHECKF(check_adjacency(m) == 0, "%s adjacency", name);
        if (!strcmp(name, "bunny-500.obj") || !strcmp(name, "fandisk-128.obj") || !strcmp(name, "bunny-fine.obj")) {
            silk_mesh_bytes b;
            silk_mesh_bytes_used(m, &b);
            printf("  %-18s %5u verts %5u tris: mesh %7lu bytes (%.1f per triangle; build adds %lu), "
                   "build scratch peak %lu\n", name, m->nverts, m->ntris, (unsigned long)b.total,
                   (double)b.total / m->ntris, (unsigned long)(b.total - b.positions - b.triangles),
                   (unsigned long)f.a.top_peak);
        }
    }
    fclose(fp);
    tm_fixture_free(&f);
    printf("  %d shared meshes, %d closed ones with V-E+F = 2-2g\n", nmesh, nclosed);
    CHECK(nmesh >= 30 && nclosed == nmesh);
}

int main(void)
{
    RUN(closed_tetrahedron_and_cube);
    RUN(open_square);
    RUN(nonmanifold_fan);
    RUN(duplicate_triangles);
    RUN(degenerate_triangles);
    RUN(tiny_face_normal_keeps_direction);
    RUN(bad_input);
    RUN(small_arenas);
    RUN(bytes_used_adds_up);
    RUN(shared_meshes_topology);
    return check_done();
}
