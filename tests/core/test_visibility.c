/*
 * test_visibility.c - the brute visibility pass against an exact double
 * reference, and the Gaussian-sphere hierarchy (src/gauss.c) against the
 * brute pass: normal for normal, both projections, on the shared meshes, a
 * generated 50k-triangle mesh and random, far, inside and exactly tangent
 * views; the bulge of a lat/long cell; memory; bad input.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "silk/silk.h"
#include "check.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define PI 3.14159265358979323846
#define ARENA_BYTES ((size_t)96 << 20)
static unsigned char *arena_buf;
static int san_scale = 1;              /* views are divided by this under sanitizers */

/* Exact: every product is below 2^49 and the sums below 2^51, so double
 * holds them without rounding. */
static int ref_visible(const silk_mesh *m, const silk_view *v, uint32_t i)
{
    silk_vec3 n = m->normal[i];
    if (v->cam.ortho) {
        silk_vec3 f = v->forward;
        return (double)n.x * f.x + (double)n.y * f.y + (double)n.z * f.z <= 0;
    }
    silk_vec3 p = m->pos[m->normal_vertex[i]], e = v->cam.eye;
    return (double)n.x * ((double)e.x - p.x) + (double)n.y * ((double)e.y - p.y)
         + (double)n.z * ((double)e.z - p.z) >= 0;
}

static void persp_view(silk_view *v, silk_vec3 eye)
{
    memset(v, 0, sizeof *v);
    v->cam.eye = eye;
    v->forward = silk_v3(0, 0, -65536);
}

static void parallel_view(silk_view *v, silk_vec3 forward)
{
    memset(v, 0, sizeof *v);
    v->cam.ortho = 1;
    v->forward = forward;
}

static void random_unit(double d[3])
{
    double l;
    do {
        for (int k = 0; k < 3; k++) d[k] = check_uniform(-1, 1);
        l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (l < 0.1 || l > 1);
    for (int k = 0; k < 3; k++) d[k] /= l;
}

/* ---- comparing the passes ------------------------------------------------- */

typedef struct tally {
    long views, normals, brute_bad, gauss_bad, auto_bad, decided, one_by_one;
} tally;

static void compare_view(const silk_mesh *m, const silk_view *v, silk_arena *a, tally *t,
                         uint8_t *vb, uint8_t *vg, uint8_t *va, const char *what)
{
    silk_vis_stats st;
    CHECK(silk_visibility(m, v, SILK_VIS_BRUTE, vb, a, NULL) == SILK_OK);
    CHECK(silk_visibility(m, v, SILK_VIS_GAUSS, vg, a, &st) == SILK_OK);
    CHECK(silk_visibility(m, v, SILK_VIS_AUTO, va, a, NULL) == SILK_OK);
    CHECKF(st.cell_decided + st.one_by_one == m->nnormals, "%s: %u + %u != %u", what,
           st.cell_decided, st.one_by_one, m->nnormals);
    t->views++;
    t->normals += m->nnormals;
    t->decided += st.cell_decided;
    t->one_by_one += st.one_by_one;
    for (uint32_t i = 0; i < m->nnormals; i++) {
        int r = ref_visible(m, v, i);
        if (vb[i] != r) t->brute_bad++;
        if (vg[i] != vb[i]) {
            if (t->gauss_bad++ == 0)
                fprintf(stderr, "  %s: normal %u gauss %d brute %d (%s)\n", what, i, vg[i], vb[i],
                        v->cam.ortho ? "parallel" : "perspective");
        }
        if (va[i] != vb[i]) t->auto_bad++;
        if (i % 97 == 0) CHECK(silk_normal_visible(m, v, i) == r);
    }
}

/* Random, inside, far, axis-aligned and exactly tangent views of m. */
static void check_mesh_views(const silk_mesh *m, silk_arena *a, int nviews, const char *name)
{
    uint8_t *vb = malloc(m->nnormals + 1), *vg = malloc(m->nnormals + 1), *va = malloc(m->nnormals + 1);
    tally tp = { 0 }, tq = { 0 };
    double lo[3] = { fx2d(m->bbox_min.x), fx2d(m->bbox_min.y), fx2d(m->bbox_min.z) };
    double hi[3] = { fx2d(m->bbox_max.x), fx2d(m->bbox_max.y), fx2d(m->bbox_max.z) };
    double mid[3], size = 0;
    for (int k = 0; k < 3; k++) {
        mid[k] = (lo[k] + hi[k]) / 2;
        size += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    size = sqrt(size) / 2;
    silk_view v;
    for (int it = 0; it < nviews; it++) {
        double d[3];
        random_unit(d);
        int kind = it % 8;
        silk_vec3 eye;
        if (kind <= 2) {            /* around the model, 1.2 .. 8 radii */
            double dist = size * check_uniform(1.2, 8);
            eye = silk_v3(d2fx(mid[0] + d[0] * dist), d2fx(mid[1] + d[1] * dist), d2fx(mid[2] + d[2] * dist));
        } else if (kind == 3) {     /* inside the bounding box */
            eye = silk_v3(d2fx(check_uniform(lo[0], hi[0])), d2fx(check_uniform(lo[1], hi[1])),
                          d2fx(check_uniform(lo[2], hi[2])));
        } else if (kind == 4) {     /* far away, up to the edge of the range */
            double dist = check_uniform(100, 30000);
            eye = silk_v3(d2fx(fmax(-32767, fmin(32767, d[0] * dist))), d2fx(fmax(-32767, fmin(32767, d[1] * dist))),
                          d2fx(fmax(-32767, fmin(32767, d[2] * dist))));
        } else {                    /* on the tangent plane of a random normal: N.(E-V) == 0 */
            uint32_t i = (uint32_t)(check_rand64() % m->nnormals);
            silk_vec3 n = m->normal[i], p = m->pos[m->normal_vertex[i]];
            int64_t x[3];
            for (int k = 0; k < 3; k++) x[k] = (int64_t)(check_rand64() % 9) - 4;
            /* T = N x X in integers: N.T == 0 exactly */
            int64_t t[3] = { n.y * x[2] - n.z * x[1], n.z * x[0] - n.x * x[2], n.x * x[1] - n.y * x[0] };
            if (kind == 7) for (int k = 0; k < 3; k++) t[k] = 0;   /* the eye on the vertex itself */
            eye = silk_v3((silk_fx)(p.x + t[0]), (silk_fx)(p.y + t[1]), (silk_fx)(p.z + t[2]));
        }
        persp_view(&v, eye);
        compare_view(m, &v, a, &tp, vb, vg, va, name);

        /* parallel: random directions, axis directions, directions exactly
         * perpendicular to a normal */
        silk_vec3 f;
        if (kind <= 3) {
            f = silk_v3(d2fx(d[0]), d2fx(d[1]), d2fx(d[2]));
        } else if (kind == 4) {
            int ax = (int)(check_rand64() % 3);
            silk_fx s = (check_rand64() & 1) ? 65536 : -65536;
            f = silk_v3(ax == 0 ? s : 0, ax == 1 ? s : 0, ax == 2 ? s : 0);
        } else {
            uint32_t i = (uint32_t)(check_rand64() % m->nnormals);
            silk_vec3 n = m->normal[i];
            int64_t x[3];
            do {
                for (int k = 0; k < 3; k++) x[k] = (int64_t)(check_rand64() % 3) - 1;
            } while (x[0] == 0 && x[1] == 0 && x[2] == 0);
            f = silk_v3((silk_fx)(n.y * x[2] - n.z * x[1]), (silk_fx)(n.z * x[0] - n.x * x[2]),
                        (silk_fx)(n.x * x[1] - n.y * x[0]));
        }
        parallel_view(&v, f);
        compare_view(m, &v, a, &tq, vb, vg, va, name);
    }
    CHECKF(tp.brute_bad == 0 && tq.brute_bad == 0, "%s: brute differs from the exact reference %ld+%ld times",
           name, tp.brute_bad, tq.brute_bad);
    CHECKF(tp.gauss_bad == 0, "%s: hierarchy differs from brute on %ld normals (perspective)", name, tp.gauss_bad);
    CHECKF(tq.gauss_bad == 0, "%s: hierarchy differs from brute on %ld normals (parallel)", name, tq.gauss_bad);
    CHECKF(tp.auto_bad == 0 && tq.auto_bad == 0, "%s: auto differs from brute", name);
    /* The hierarchy must actually decide cells, or the equality above is
     * empty: a twentieth of the normals on small meshes (few, large cells, and
     * a third of these views are inside or on the surface), half on large. */
    long need = m->nnormals >= 5000 ? 2 : 20;
    CHECKF(tp.decided > tp.normals / need && tq.decided > tq.normals / need,
           "%s: too few normals decided by cells (%ld of %ld, %ld of %ld)", name, tp.decided, tp.normals,
           tq.decided, tq.normals);
    printf("  %-16s normals %6u nodes %6u depth %u  %2d views x2: cell-decided %.1f%% persp, %.1f%% parallel\n", name,
           m->nnormals, m->vis->nnodes, m->vis->depth, nviews, 100.0 * tp.decided / tp.normals,
           100.0 * tq.decided / tq.normals);
    free(vb); free(vg); free(va);
}

/* Corners' normals and vertices before the build, to check that the
 * renumbering kept what every triangle corner sees. */
typedef struct corner_copy { silk_vec3 *n; silk_index *v; } corner_copy;

static corner_copy save_corners(const silk_mesh *m)
{
    corner_copy c;
    c.n = malloc(sizeof *c.n * 3 * (size_t)m->ntris + 1);
    c.v = malloc(sizeof *c.v * 3 * (size_t)m->ntris + 1);
    for (uint32_t k = 0; k < 3 * m->ntris; k++) {
        c.n[k] = m->normal[m->tri_normal[k]];
        c.v[k] = m->normal_vertex[m->tri_normal[k]];
    }
    return c;
}

static void check_build(silk_mesh *m, silk_arena *a, const char *name)
{
    corner_copy before = save_corners(m);
    silk_error err;
    memset(&err, 0, sizeof err);
    size_t bottom = a->bottom, top = a->top;
    silk_status st = silk_vis_build(m, NULL, a, &err);
    CHECKF(st == SILK_OK, "%s: %s", name, err.msg);
    if (st != SILK_OK) return;
    CHECK(a->top == top);                                  /* scratch released */
    CHECK(m->vis != NULL && m->vis->nnormals == m->nnormals);
    size_t nodes = (size_t)m->vis->nnodes * sizeof(silk_vis_node);
    CHECKF(nodes <= 8 * (size_t)m->nnormals, "%s: %zu node bytes for %u normals", name, nodes, m->nnormals);
    CHECK(a->bottom - bottom >= silk_vis_bytes(m->vis));
    CHECKF(m->vis->widened == 0, "%s: %u cells needed a wider radius than their region", name, m->vis->widened);
    uint32_t bad = 0;
    for (uint32_t k = 0; k < 3 * m->ntris; k++) {
        silk_vec3 n = m->normal[m->tri_normal[k]];
        if (n.x != before.n[k].x || n.y != before.n[k].y || n.z != before.n[k].z ||
            m->normal_vertex[m->tri_normal[k]] != before.v[k])
            bad++;
    }
    CHECKF(bad == 0, "%s: %u corners changed by the renumbering", name, bad);
    /* every node's range lies inside its parent's, preorder */
    const silk_vis_node *nd = m->vis->node;
    for (uint32_t i = 0; i < m->vis->nnodes; i++) {
        CHECK(nd[i].skip > i && nd[i].skip <= m->vis->nnodes);
        uint32_t end = nd[i].skip < m->vis->nnodes ? nd[nd[i].skip].first : m->nnormals;
        CHECK(nd[i].first < end);
    }
    free(before.n);
    free(before.v);
}

static int load_shared(const char *file, silk_arena *a, silk_mesh *m)
{
    char path[512], *data;
    size_t len;
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), file);
    if (!(data = tm_read_file(path, &len))) {
        CHECKF(0, "cannot read %s", path);
        return 0;
    }
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_load_mesh(data, len, file, &o, a, m, &err);
    free(data);
    CHECKF(st == SILK_OK, "%s", err.msg);
    return st == SILK_OK;
}

TEST(shared_meshes_hierarchy_equals_brute)
{
    static const char *files[] = { "fandisk-1000.obj", "sphere-200.obj", "torus-576.obj", "bunny-2k.obj",
                                   "cone-70.obj", "pawn-304.obj", "knot-480.obj", "wingnut-500.obj",
                                   "cow-500.obj", "dragon-5k.obj", "fandisk-fine.obj", "bunny-fine.obj" };
    for (size_t f = 0; f < sizeof files / sizeof files[0]; f++) {
        silk_arena a;
        silk_arena_init(&a, arena_buf, ARENA_BYTES);
        silk_mesh m;
        if (!load_shared(files[f], &a, &m)) continue;
        if (strncmp(files[f], "fandisk", 7) == 0 || strncmp(files[f], "cone", 4) == 0)
            CHECKF(m.nnormals > m.nverts, "%s: expected split normals (%u normals, %u vertices)", files[f],
                   m.nnormals, m.nverts);
        check_build(&m, &a, files[f]);
        if (!m.vis) continue;
        int views = m.nnormals > 10000 ? 1500 : 4000;
        check_mesh_views(&m, &a, views / san_scale, files[f]);
    }
}

/* A bumpy torus, 50000 triangles, through the real mesh build: normals of
 * every direction at many offsets from the centre. */
static int gen_bumpy_torus(silk_arena *a, silk_mesh *m, uint32_t nu, uint32_t nv)
{
    silk_mesh_input in;
    memset(&in, 0, sizeof in);
    in.nverts = nu * nv;
    in.ntris = 2 * nu * nv;
    in.pos = silk_arena_array(a, in.nverts, sizeof *in.pos, SILK_MEM_MESH);
    in.tri = silk_arena_array(a, 3 * (size_t)in.ntris, sizeof *in.tri, SILK_MEM_MESH);
    if (!in.pos || !in.tri) return 0;
    for (uint32_t i = 0; i < nu; i++)
        for (uint32_t j = 0; j < nv; j++) {
            double u = 2 * PI * i / nu, w = 2 * PI * j / nv;
            double r = 0.4 * (1 + 0.25 * sin(5 * u) * sin(3 * w));
            double x = (1.5 + r * cos(w)) * cos(u), y = (1.5 + r * cos(w)) * sin(u), z = r * sin(w);
            in.pos[i * nv + j] = silk_v3(d2fx(x + 0.3), d2fx(y - 0.2), d2fx(z + 0.1));
        }
    uint32_t t = 0;
    for (uint32_t i = 0; i < nu; i++)
        for (uint32_t j = 0; j < nv; j++) {
            uint32_t a0 = i * nv + j, a1 = ((i + 1) % nu) * nv + j;
            uint32_t b0 = i * nv + (j + 1) % nv, b1 = ((i + 1) % nu) * nv + (j + 1) % nv;
            uint32_t q[6] = { a0, a1, b1, a0, b1, b0 };
            memcpy(&in.tri[3 * t], q, sizeof q);
            t += 2;
        }
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_mesh_build(&in, "bumpy-torus", &o, a, m, &err);
    CHECKF(st == SILK_OK, "%s", err.msg);
    return st == SILK_OK;
}

TEST(generated_50k_hierarchy_equals_brute)
{
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_mesh m;
    if (!gen_bumpy_torus(&a, &m, 200, 125)) return;
    CHECK(m.ntris == 50000);
    check_build(&m, &a, "bumpy-torus-50k");
    if (m.vis) check_mesh_views(&m, &a, 1500 / san_scale, "bumpy-torus-50k");
}

/* Normals of random length <= 1 at random vertices, eyes anywhere in the
 * fixed-point range: the brute pass must be exact where a saturating E - V
 * would not be. */
TEST(brute_exact_at_the_range_limits)
{
    enum { NV = 64, NN = 256 };
    silk_vec3 pos[NV], nrm[NN];
    silk_index nvx[NN];
    for (int i = 0; i < NV; i++)
        pos[i] = silk_v3(d2fx(check_uniform(-1024, 1024)), d2fx(check_uniform(-1024, 1024)), d2fx(check_uniform(-1024, 1024)));
    for (int i = 0; i < NN; i++) {
        double d[3];
        random_unit(d);
        double l = i % 4 == 0 ? 0 : check_uniform(0, 1);
        nrm[i] = silk_v3(d2fx(d[0] * l), d2fx(d[1] * l), d2fx(d[2] * l));
        nvx[i] = (silk_index)(check_rand64() % NV);
    }
    silk_mesh m;
    memset(&m, 0, sizeof m);
    m.nverts = NV; m.pos = pos; m.nnormals = NN; m.normal = nrm; m.normal_vertex = nvx;
    uint8_t vis[NN];
    long bad = 0;
    silk_view v;
    for (int it = 0; it < 4000; it++) {
        silk_vec3 e = silk_v3((silk_fx)check_rand64(), (silk_fx)check_rand64(), (silk_fx)check_rand64());
        if (it % 3 == 0) e = silk_v3(it & 1 ? SILK_FX_MAX : SILK_FX_MIN, SILK_FX_MIN, it & 2 ? SILK_FX_MAX : 0);
        persp_view(&v, e);
        silk_visibility_brute(&m, &v, vis);
        for (int i = 0; i < NN; i++) bad += vis[i] != ref_visible(&m, &v, (uint32_t)i);
        parallel_view(&v, e);
        silk_visibility_brute(&m, &v, vis);
        for (int i = 0; i < NN; i++) bad += vis[i] != ref_visible(&m, &v, (uint32_t)i);
    }
    CHECKF(bad == 0, "%ld wrong", bad);
}

/* ---- the bulge of a latitude arc ----------------------------------------- */

static void sph(double lat_deg, double lon_deg, double p[3])
{
    double la = lat_deg * PI / 180, lo = lon_deg * PI / 180;
    p[0] = cos(la) * cos(lo); p[1] = cos(la) * sin(lo); p[2] = sin(la);
}

/* Cell of level 3, latitude 22.5..45, longitude 0..45.  The plane through
 * the great circle of its two lower corners, tilted a little towards the
 * pole, has all four corners on its positive side, while the middle of the
 * lower latitude arc (which bulges towards the equator) is on the negative
 * side.  The corner rule would declare the whole cell visible. */
TEST(bulging_cell_is_not_decided_by_its_corners)
{
    const uint32_t level = 3, ilat = 5, ilon = 4;
    double la0 = -90 + ilat * 22.5, la1 = la0 + 22.5, lo0 = -180 + ilon * 45, lo1 = lo0 + 45;
    CHECK(la0 == 22.5 && lo0 == 0);
    double c00[3], c01[3], c10[3], c11[3], mid[3], d[3];
    sph(la0, lo0, c00); sph(la0, lo1, c01); sph(la1, lo0, c10); sph(la1, lo1, c11);
    sph(la0, (lo0 + lo1) / 2, mid);
    /* D = c00 x c01, oriented towards the upper corners, tilted north */
    d[0] = c00[1] * c01[2] - c00[2] * c01[1];
    d[1] = c00[2] * c01[0] - c00[0] * c01[2];
    d[2] = c00[0] * c01[1] - c00[1] * c01[0];
    if (dot3(d, c10) < 0) for (int k = 0; k < 3; k++) d[k] = -d[k];
    d[2] += 0.004;
    double l = sqrt(dot3(d, d));
    for (int k = 0; k < 3; k++) d[k] /= l;
    int naive = dot3(d, c00) > 0 && dot3(d, c01) > 0 && dot3(d, c10) > 0 && dot3(d, c11) > 0;
    CHECKF(naive, "corners %g %g %g %g", dot3(d, c00), dot3(d, c01), dot3(d, c10), dot3(d, c11));
    CHECKF(dot3(d, mid) < 0, "arc middle %g", dot3(d, mid));   /* ... but the cell holds an invisible point */

    /* The library's ball holds the whole cell, arcs included ... */
    silk_vec3 c;
    silk_fx r;
    CHECK(silk_vis_cell_ball(level, ilat, ilon, &c, &r));
    double cd[3] = { fx2d(c.x), fx2d(c.y), fx2d(c.z) }, rd = fx2d(r), worst = 0;
    for (int i = 0; i <= 60; i++)
        for (int j = 0; j <= 60; j++) {
            double p[3];
            sph(la0 + (la1 - la0) * i / 60, lo0 + (lo1 - lo0) * j / 60, p);
            double e = sqrt((p[0] - cd[0]) * (p[0] - cd[0]) + (p[1] - cd[1]) * (p[1] - cd[1]) +
                            (p[2] - cd[2]) * (p[2] - cd[2]));
            if (e > worst) worst = e;
        }
    CHECKF(worst <= rd, "cell point at %g from the centre, radius %g", worst, rd);
    /* ... so it refuses to decide the cell for this view. */
    CHECKF(dot3(cd, d) - rd <= 0, "ball says visible: c.D %g r %g", dot3(cd, d), rd);
    /* every cell of a few levels holds its sampled points */
    double worst_ratio = 0;
    for (uint32_t lv = 1; lv <= 5; lv++)
        for (uint32_t i = 0; i < (1u << lv); i++)
            for (uint32_t j = 0; j < (1u << lv); j++) {
                CHECK(silk_vis_cell_ball(lv, i, j, &c, &r));
                double a0 = -90 + 180.0 * i / (1u << lv), a1 = a0 + 180.0 / (1u << lv);
                double o0 = -180 + 360.0 * j / (1u << lv), o1 = o0 + 360.0 / (1u << lv);
                for (int s = 0; s <= 12; s++)
                    for (int t = 0; t <= 12; t++) {
                        double p[3];
                        sph(a0 + (a1 - a0) * s / 12, o0 + (o1 - o0) * t / 12, p);
                        double e = sqrt((p[0] - fx2d(c.x)) * (p[0] - fx2d(c.x)) + (p[1] - fx2d(c.y)) * (p[1] - fx2d(c.y)) +
                                        (p[2] - fx2d(c.z)) * (p[2] - fx2d(c.z)));
                        if (e / fx2d(r) > worst_ratio) worst_ratio = e / fx2d(r);
                    }
            }
    CHECKF(worst_ratio <= 1, "a cell point outside its ball: ratio %g", worst_ratio);

    /* End to end: normals spread over that cell (one on the arc's middle),
     * a hierarchy whose leaves are level-3 cells, and the view above. */
    enum { NN = 400 };
    silk_vec3 pos[1] = { { 0, 0, 0 } }, nrm[NN];
    silk_index nvx[NN];
    for (int i = 0; i < NN; i++) {
        double p[3];
        if (i == 0) memcpy(p, mid, sizeof p);
        else sph(check_uniform(la0 + 0.01, la1 - 0.01), check_uniform(lo0 + 0.01, lo1 - 0.01), p);
        nrm[i] = silk_v3(d2fx(p[0]), d2fx(p[1]), d2fx(p[2]));
        nvx[i] = 0;
    }
    silk_mesh m;
    memset(&m, 0, sizeof m);
    m.nverts = 1; m.pos = pos; m.nnormals = NN; m.normal = nrm; m.normal_vertex = nvx;
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_vis_opts o = { 3, 4 };
    silk_error err;
    CHECK(silk_vis_build(&m, &o, &a, &err) == SILK_OK);
    CHECK(m.vis && m.vis->depth == 3 && m.vis->widened == 0);
    silk_view v;
    parallel_view(&v, silk_v3(d2fx(-d[0]), d2fx(-d[1]), d2fx(-d[2])));
    uint8_t vb[NN], vg[NN];
    silk_vis_stats st;
    silk_visibility_brute(&m, &v, vb);
    CHECK(silk_visibility_gauss(&m, &v, vg, &st) == SILK_OK);
    int invisible = 0, diff = 0;
    for (int i = 0; i < NN; i++) {
        invisible += !vb[i];
        diff += vb[i] != vg[i];
    }
    CHECKF(invisible > 0, "no invisible normal in the cell");
    CHECKF(diff == 0, "%d normals differ", diff);
    CHECKF(st.one_by_one == NN, "the leaf straddles, all %d normals one by one, got %u", NN, st.one_by_one);
}

/* ---- memory, arguments, failures ------------------------------------------ */

TEST(bad_input_and_small_arenas)
{
    silk_vec3 pos[2] = { { 0, 0, 0 }, { 65536, 0, 0 } };
    silk_vec3 nrm[3] = { { 65536, 0, 0 }, { 0, 65536, 0 }, { 0, 0, 65536 } };
    silk_index nvx[3] = { 0, 1, 5 };
    silk_index trin[3] = { 0, 1, 2 };
    silk_mesh m;
    memset(&m, 0, sizeof m);
    m.nverts = 2; m.pos = pos; m.nnormals = 3; m.normal = nrm; m.normal_vertex = nvx;
    m.ntris = 1; m.tri_normal = trin;
    silk_arena a;
    silk_arena_init(&a, arena_buf, 1 << 20);
    silk_error err;
    memset(&err, 0, sizeof err);
    CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_ERR_ARG);
    CHECKF(strcmp(err.msg, "visibility: normal 2 belongs to vertex 5, beyond the 2 vertices") == 0, "%s", err.msg);
    CHECK(m.vis == NULL && a.bottom == 0 && a.top == 0);
    nvx[2] = 1;
    trin[2] = 7;
    CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_ERR_ARG);
    CHECKF(strcmp(err.msg, "visibility: triangle 0 uses normal 7, beyond the 3 normals") == 0, "%s", err.msg);
    trin[2] = 2;
    nrm[1].y = 3 * 65536;
    CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_ERR_ARG);
    CHECKF(strcmp(err.msg, "visibility: normal 1 is not a unit vector") == 0, "%s", err.msg);
    nrm[1].y = 65536;

    /* an arena too small at every point of the build: clean failure, mesh untouched */
    for (size_t size = 0; size < 1024; size += 8) {
        silk_arena_init(&a, arena_buf, size);
        memset(&err, 0, sizeof err);
        silk_status st = silk_vis_build(&m, NULL, &a, &err);
        if (st == SILK_OK) {
            CHECK(m.vis != NULL);
            break;
        }
        CHECK(st == SILK_ERR_NOMEM && strncmp(err.msg, "visibility: arena too small", 27) == 0);
        CHECK(m.vis == NULL && a.top == 0 && a.bottom == 0);
        CHECK(trin[0] == 0 && trin[1] == 1 && trin[2] == 2);
    }
    CHECK(m.vis != NULL);

    /* gauss without (or with a stale) hierarchy refuses; auto falls back */
    silk_view v;
    persp_view(&v, silk_v3(0, 0, 5 * 65536));
    uint8_t vis[3];
    m.nnormals = 2;
    CHECK(silk_visibility(&m, &v, SILK_VIS_GAUSS, vis, &a, NULL) == SILK_ERR_ARG);
    CHECK(silk_visibility(&m, &v, SILK_VIS_AUTO, vis, &a, NULL) == SILK_OK);
    m.nnormals = 3;
    CHECK(silk_visibility(&m, &v, (silk_vis_method)9, vis, &a, NULL) == SILK_ERR_ARG);
    CHECK(silk_visibility(NULL, &v, SILK_VIS_BRUTE, vis, &a, NULL) == SILK_ERR_ARG);
    /* a zero view direction: every N.0 is 0, so everything is visible */
    parallel_view(&v, silk_v3(0, 0, 0));
    CHECK(silk_visibility(&m, &v, SILK_VIS_GAUSS, vis, &a, NULL) == SILK_OK);
    CHECK(vis[0] && vis[1] && vis[2]);
    /* an empty mesh */
    silk_mesh e;
    memset(&e, 0, sizeof e);
    silk_arena_init(&a, arena_buf, 4096);
    CHECK(silk_vis_build(&e, NULL, &a, &err) == SILK_OK);
    CHECK(silk_visibility(&e, &v, SILK_VIS_GAUSS, NULL, &a, NULL) == SILK_OK);
    CHECK(silk_vis_bytes(NULL) == 0 && silk_vis_bytes(e.vis) >= sizeof(silk_vis));
}

/* Zero normals and normals at the poles and on the date line, views along
 * the axes: the hierarchy still agrees. */
TEST(degenerate_normals)
{
    enum { NN = 600 };
    silk_vec3 pos[4], nrm[NN];
    silk_index nvx[NN];
    for (int i = 0; i < 4; i++) pos[i] = silk_v3(d2fx(i * 0.5 - 1), d2fx(i * 0.25), d2fx(-i * 0.125));
    static const int axes[][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { -1, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 0 } };
    for (int i = 0; i < NN; i++) {
        const int *ax = axes[i % 7];
        if (i % 3 == 0) nrm[i] = silk_v3(ax[0] * 65536, ax[1] * 65536, ax[2] * 65536);
        else {
            double d[3];
            random_unit(d);
            nrm[i] = silk_v3(d2fx(d[0]), d2fx(d[1]), d2fx(d[2]));
        }
        nvx[i] = (silk_index)(i % 4);
    }
    silk_mesh m;
    memset(&m, 0, sizeof m);
    m.nverts = 4; m.pos = pos; m.nnormals = NN; m.normal = nrm; m.normal_vertex = nvx;
    m.bbox_min = silk_v3(d2fx(-1), 0, d2fx(-0.375));
    m.bbox_max = silk_v3(d2fx(0.5), d2fx(0.75), 0);
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_vis_opts o = { 0, 2 };
    silk_error err;
    CHECK(silk_vis_build(&m, &o, &a, &err) == SILK_OK);
    if (!m.vis) return;
    /* A zero normal lies on no cell of the sphere: its cells' radii grow to
     * hold it (and it is visible from everywhere, N.anything == 0). */
    CHECKF(m.vis->widened > 0, "%u", m.vis->widened);
    uint8_t vb[NN], vg[NN];
    long diff = 0;
    silk_view v;
    for (int it = 0; it < 3000 / san_scale; it++) {
        const int *ax = axes[it % 7];
        silk_vec3 f = silk_v3(ax[0] * 65536, ax[1] * 65536, ax[2] * 65536);
        if (it % 2) {
            parallel_view(&v, f);
        } else {
            persp_view(&v, silk_v3(pos[it % 4].x + f.x * (it % 5), pos[it % 4].y + f.y * (it % 3), pos[it % 4].z));
        }
        silk_visibility_brute(&m, &v, vb);
        silk_visibility_gauss(&m, &v, vg, NULL);
        for (int i = 0; i < NN; i++) {
            diff += vb[i] != vg[i];
            if (nrm[i].x == 0 && nrm[i].y == 0 && nrm[i].z == 0) diff += !vg[i];
        }
    }
    CHECKF(diff == 0, "%ld differ", diff);
}

int main(void)
{
    if (getenv("SILK_SAN")) san_scale = 4;
    arena_buf = malloc(ARENA_BYTES);
    if (!arena_buf) return 1;
    RUN(brute_exact_at_the_range_limits);
    RUN(bulging_cell_is_not_decided_by_its_corners);
    RUN(bad_input_and_small_arenas);
    RUN(degenerate_normals);
    RUN(shared_meshes_hierarchy_equals_brute);
    RUN(generated_50k_hierarchy_equals_brute);
    free(arena_buf);
    return check_done();
}
