/*
 * test_orient.c - orientation at load (src/orient.c): triangles wound
 * inconsistently or inside out come back exactly as the correctly wound
 * mesh has them, closed parts face outward (signed volume computed here in
 * double), open parts keep the winding most of their triangles have,
 * non-orientable and non-manifold surfaces load without a change or a
 * crash, and --orient keep (SILK_ORIENT_KEEP) leaves the file alone.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "silk/validate.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (8u << 20)
#define PI 3.14159265358979323846

typedef struct shape {
    double pos[3 * 4096];
    uint32_t tri[3 * 8192];
    uint32_t nv, nt;
} shape;

/* UV sphere (poles on y), counter-clockwise seen from outside; bands = 0
 * leaves out the lower half's caps and rows (an open bowl). */
static void add_sphere(shape *s, double cx, double r, int seg, int bands, int open)
{
    uint32_t base = s->nv;
    double *p = &s->pos[3 * s->nv];
    *p++ = cx; *p++ = r; *p++ = 0;
    for (int b = 1; b < bands; b++)
        for (int k = 0; k < seg; k++) {
            double th = PI * b / bands, ph = 2 * PI * k / seg;
            *p++ = cx + r * sin(th) * cos(ph);
            *p++ = r * cos(th);
            *p++ = -r * sin(th) * sin(ph);
        }
    *p++ = cx; *p++ = -r; *p++ = 0;
    s->nv += 2 + (uint32_t)((bands - 1) * seg);
    uint32_t south = base + 1 + (uint32_t)((bands - 1) * seg);
#define RING(b, k) (base + 1 + (uint32_t)(((b) - 1) * seg + ((k) % seg)))
#define TRI(a, b_, c) do { uint32_t *t = &s->tri[3 * s->nt++]; t[0] = (a); t[1] = (b_); t[2] = (c); } while (0)
    for (int k = 0; k < seg; k++) TRI(base, RING(1, k), RING(1, k + 1));
    int rows = open ? bands / 2 : bands - 1;
    for (int b = 1; b < rows; b++)
        for (int k = 0; k < seg; k++) {
            TRI(RING(b, k), RING(b + 1, k), RING(b + 1, k + 1));
            TRI(RING(b, k), RING(b + 1, k + 1), RING(b, k + 1));
        }
    if (!open)
        for (int k = 0; k < seg; k++) TRI(RING(bands - 1, k), south, RING(bands - 1, k + 1));
#undef RING
#undef TRI
}

static void flip(uint32_t *t)
{
    uint32_t x = t[1];
    t[1] = t[2];
    t[2] = x;
}

static tm_fixture F;   /* one arena for every test */

static silk_status build(const shape *s, const uint32_t *tri, silk_orient_mode mode)
{
    tm_fixture_reset(&F);
    F.opts.orient = mode;
    if (!tm_fixture_input(&F, s->pos, s->nv, tri, s->nt)) return SILK_ERR_NOMEM;
    return tm_fixture_build(&F);
}

static int same_tris(const silk_mesh *m, const uint32_t *tri)
{
    for (uint32_t c = 0; c < 3 * m->ntris; c++)
        if (m->tri[c] != tri[c]) return 0;
    return 1;
}

/* Signed volume of the whole mesh, in double (the reference). */
static double volume(const silk_mesh *m)
{
    double v = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        dvec p0 = dv(m->pos[m->tri[3 * t]]), p1 = dv(m->pos[m->tri[3 * t + 1]]), p2 = dv(m->pos[m->tri[3 * t + 2]]);
        v += ddot(p0, dcross(p1, p2)) / 6;
    }
    return v;
}

/* Every edge with two triangles is run in opposite directions by them. */
static int consistent(const silk_mesh *m)
{
    for (uint32_t e = 0; e < m->nedges; e++) {
        const silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || (ed->flags & SILK_EDGE_NONMANIFOLD)) continue;
        int dir[2];
        for (int i = 0; i < 2; i++)
            for (int k = 0; k < 3; k++)
                if (m->tri_edge[3 * ed->t[i] + k] == e) dir[i] = m->tri[3 * ed->t[i] + k] == ed->v[0];
        if (dir[0] == dir[1]) return 0;
    }
    return 1;
}

static shape S;
static uint32_t T[3 * 8192];   /* S's triangles as the test winds them */

/* T = S's triangles, then every step-th of [from, to) flipped (returns how
 * many). */
static void new_shape(void) { memset(&S, 0, sizeof S); }
static void copy_tris(void) { memcpy(T, S.tri, sizeof(uint32_t) * 3 * S.nt); }
static uint32_t flip_range(uint32_t from, uint32_t to, uint32_t step)
{
    uint32_t n = 0;
    for (uint32_t t = from; t < to; t += step) flip(&T[3 * t]), n++;
    return n;
}

TEST(sphere_is_outward_already)
{
    new_shape();
    add_sphere(&S, 0, 1, 10, 11, 0);
    CHECK(build(&S, S.tri, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(F.m.nreoriented_tris == 0 && F.m.nnonorientable_tris == 0);
    CHECK(same_tris(&F.m, S.tri));
    CHECK(volume(&F.m) > 3.5 && consistent(&F.m));
}

TEST(flipped_and_inside_out)
{
    new_shape();
    add_sphere(&S, 0, 1, 10, 11, 0);
    /* every third triangle, then every triangle, then all but the first */
    for (int pattern = 0; pattern < 3; pattern++) {
        copy_tris();
        uint32_t flipped = flip_range(pattern == 2, S.nt, pattern == 0 ? 3 : 1);
        CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
        CHECKF(F.m.nreoriented_tris == flipped, "pattern %d: %u reoriented, %u flipped", pattern,
               F.m.nreoriented_tris, flipped);
        CHECKF(same_tris(&F.m, S.tri), "pattern %d: not the original triangles", pattern);
        CHECK(silk_mesh_validate(&F.m, "test", &F.err) == SILK_OK);
        /* keep: the file as it is */
        CHECK(build(&S, T, SILK_ORIENT_KEEP) == SILK_OK);
        CHECK(F.m.nreoriented_tris == 0 && same_tris(&F.m, T));
    }
}

/* Two spheres, one inside out, one of them with a scrambled winding: each
 * closed part is turned outward on its own. */
TEST(components_each_outward)
{
    new_shape();
    add_sphere(&S, -2, 1, 8, 7, 0);
    uint32_t first = S.nt;
    add_sphere(&S, 2, 0.5, 12, 9, 0);
    copy_tris();
    flip_range(first, S.nt, 1);
    flip_range(0, first, 5);
    CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(same_tris(&F.m, S.tri));
    CHECK(consistent(&F.m) && volume(&F.m) > 0);
}

/* An open bowl has no inside: the winding most of its triangles have wins. */
TEST(open_surface_majority)
{
    new_shape();
    add_sphere(&S, 0, 1, 10, 10, 1);
    CHECK(build(&S, S.tri, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(F.m.nboundary_edges > 0 && F.m.nreoriented_tris == 0);
    copy_tris();
    uint32_t few = flip_range(0, S.nt, 4);
    CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(F.m.nreoriented_tris == few && same_tris(&F.m, S.tri));
    /* all flipped: a consistent open surface is left as it is */
    copy_tris();
    flip_range(0, S.nt, 1);
    CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(F.m.nreoriented_tris == 0 && same_tris(&F.m, T));
}

/* A Moebius band cannot be oriented: it is left exactly as given. */
TEST(moebius_left_alone)
{
    new_shape();
    const int n = 24;
    for (int i = 0; i < n; i++) {
        double a = 2 * PI * i / n, w;
        for (int side = 0; side < 2; side++) {
            w = side ? 0.3 : -0.3;
            double *p = &S.pos[3 * S.nv++];
            p[0] = (1 + w * cos(a / 2)) * cos(a);
            p[1] = (1 + w * cos(a / 2)) * sin(a);
            p[2] = w * sin(a / 2);
        }
    }
    for (int i = 0; i < n; i++) {
        uint32_t a0 = (uint32_t)(2 * i), a1 = a0 + 1, b0 = (uint32_t)(2 * ((i + 1) % n)), b1 = b0 + 1;
        if (i == n - 1) { uint32_t x = b0; b0 = b1; b1 = x; }   /* the half twist */
        uint32_t *t = &S.tri[3 * S.nt];
        t[0] = a0; t[1] = b0; t[2] = b1;
        t[3] = a0; t[4] = b1; t[5] = a1;
        S.nt += 2;
    }
    copy_tris();
    flip_range(0, S.nt, 3);
    CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
    CHECKF(F.m.nnonorientable_tris == S.nt && F.m.nreoriented_tris == 0, "%u non-orientable, %u reoriented",
           F.m.nnonorientable_tris, F.m.nreoriented_tris);
    CHECK(same_tris(&F.m, T));
    CHECK(silk_mesh_validate(&F.m, "test", &F.err) == SILK_OK);
}

/* Three fins on one edge and a triangle that repeats a vertex: no walk
 * across the non-manifold edge, nothing broken. */
TEST(nonmanifold_and_degenerate)
{
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 1, 1, 1 };
    static const uint32_t tri[] = { 0, 1, 2, 1, 0, 3, 0, 1, 4, 2, 1, 5, 5, 5, 2 };
    new_shape();
    memcpy(S.pos, pos, sizeof pos);
    memcpy(S.tri, tri, sizeof tri);
    S.nv = 6;
    S.nt = 5;
    CHECK(build(&S, S.tri, SILK_ORIENT_FIX) == SILK_OK);
    CHECK(F.m.nnonmanifold_edges == 1);
    CHECK(silk_mesh_validate(&F.m, "test", &F.err) == SILK_OK);
}

/* At the edge of the coordinate range each volume term is near 2^82: the
 * sum must still have the right sign (it would wrap in 64 bits). */
TEST(volume_at_the_range_limit)
{
    for (int big = 0; big < 2; big++) {
        double s = big ? 1023.0 : 0.001;
        static const double unit[] = { -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                       -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1 };
        /* the 12 triangles of a cube, outward */
        static const uint32_t cube[] = { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3 };
        new_shape();
        for (int i = 0; i < 24; i++) S.pos[i] = unit[i] * s + (big ? 0 : 0.5);
        S.nv = 8;
        S.nt = 12;
        memcpy(S.tri, cube, sizeof cube);
        copy_tris();
        flip_range(0, 12, 1);
        CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
        CHECKF(same_tris(&F.m, S.tri) && F.m.nreoriented_tris == 12, "scale %g: %u reoriented", s,
               F.m.nreoriented_tris);
        CHECK(volume(&F.m) > 0);
    }
}

/* Random windings of random closed meshes (spheres of several sizes): the
 * result is consistent and outward, and the original winding. */
TEST(random_windings)
{
    for (int round = 0; round < 40; round++) {
        new_shape();
        int seg = 3 + (int)(check_rand64() % 20), bands = 2 + (int)(check_rand64() % 20);
        add_sphere(&S, check_uniform(-5, 5), check_uniform(0.1, 20), seg, bands, 0);
        copy_tris();
        for (uint32_t t = 0; t < S.nt; t++)
            if (check_rand64() & 1) flip(&T[3 * t]);
        CHECK(build(&S, T, SILK_ORIENT_FIX) == SILK_OK);
        CHECKF(same_tris(&F.m, S.tri), "round %d: %dx%d sphere", round, seg, bands);
        CHECK(consistent(&F.m) && volume(&F.m) > 0);
    }
}

int main(void)
{
    tm_fixture_init(&F, ARENA_BYTES);
    RUN(sphere_is_outward_already);
    RUN(flipped_and_inside_out);
    RUN(components_each_outward);
    RUN(open_surface_majority);
    RUN(moebius_left_alone);
    RUN(nonmanifold_and_degenerate);
    RUN(volume_at_the_range_limit);
    RUN(random_windings);
    tm_fixture_free(&F);
    return check_done();
}
