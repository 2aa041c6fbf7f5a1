/*
 * test_hard_geometry.c - meshes that are not clean closed 2-manifolds:
 * open surfaces, non-manifold edges, duplicate and zero-area triangles,
 * inconsistent orientation, isolated vertices, a single triangle, and one
 * million triangles.  Each must load (or fail with one clean line), pass
 * silk_mesh_validate, and render in every mode without touching memory it
 * does not own; where the answer is known, the picture is checked too.
 *
 * Boundary edges are feature curves (paper III-A: "feature curves", here
 * the mesh border): an 8-sided disc seen face-on must come out rounder in
 * SMOOTH mode than the octagon FLAT mode draws.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "silk/silk.h"
#include "silk/validate.h"
#include "support/scene.h"

#define PI 3.14159265358979323846
#define ARENA_BYTES ((size_t)32 << 20)
static unsigned char arena_mem[ARENA_BYTES];

/* Builds tm, validates it and renders it in all four modes from two
 * sides; returns the SMOOTH coverage of the first view (or -1). */
static long render_all(const ts_mesh *tm, const char *what, const double eye[3], const double target[3])
{
    silk_arena a;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    silk_mesh m;
    silk_error err;
    silk_status st = ts_build(tm, &a, &m, &err);
    CHECKF(st == SILK_OK, "%s: %s", what, err.msg);
    if (st != SILK_OK) return -1;
    CHECKF(silk_mesh_validate(&m, what, &err) == SILK_OK, "%s: %s", what, err.msg);
    CHECKF(silk_vis_build(&m, NULL, &a, &err) == SILK_OK, "%s: %s", what, err.msg);
    size_t bottom = a.bottom;
    long smooth_cov = -1;
    ts_image img = { 0 };
    for (int side = 0; side < 2; side++) {
        double e[3];
        for (int k = 0; k < 3; k++) e[k] = side ? 2 * target[k] - eye[k] : eye[k];
        for (int mode = 0; mode < 4; mode++)
            for (int ortho = 0; ortho < 2 && ts_mode_built(mode); ortho++) {
                silk_camera cam = ts_camera(e, target, ortho ? -2.5 : 45, 0.05, 50, 64, 48);
                silk_render_opts o;
                silk_render_opts_default(&o);
                o.mode = (silk_mode)mode;
                o.wire = side && TS_WIRE_BUILT;
                silk_frame_stats fs;
                st = ts_render(&a, &m, &cam, &o, &img, &fs, &err);
                CHECKF(st == SILK_OK, "%s mode %d: %s", what, mode, err.msg);
                CHECKF(a.top == 0 && a.bottom == bottom, "%s mode %d: the frame kept memory", what, mode);
                CHECKF(!fs.fell_back, "%s mode %d fell back", what, mode);
                if (side == 0 && mode == SILK_MODE_SMOOTH && !ortho) smooth_cov = ts_count_covered(&img);
            }
    }
    ts_image_free(&img);
    return smooth_cov;
}

static const double EYE[3] = { 1.2, 1.5, 3.5 }, ORIGIN[3] = { 0, 0, 0 };

/* Loads an OBJ text into the arena; returns the status. */
static silk_status load_text(const char *text, silk_arena *a, silk_mesh *m, silk_error *err)
{
    silk_arena_init(a, arena_mem, sizeof arena_mem);
    return silk_load_obj(text, strlen(text), "hard.obj", NULL, a, m, err);
}

TEST(single_triangle)
{
    ts_mesh tm = { 0 };
    ts_tri(&tm, ts_vertex(&tm, -1, -1, 0), ts_vertex(&tm, 1, -1, 0), ts_vertex(&tm, 0, 1, 0));
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECK(m.nedges == 3 && m.nboundary_edges == 3 && m.nfeature_edges == 3 && m.nnormals == 3);
    long cov = render_all(&tm, "one triangle", EYE, ORIGIN);
    CHECKF(cov > 100, "covers %ld pixels", cov);
    ts_mesh_free(&tm);
}

/* The upper half of a sphere: the rim is open. */
TEST(open_mesh)
{
    const int segs = 12, bands = 6;
    ts_mesh tm = { 0 };
    uint32_t top = ts_vertex(&tm, 0, 1, 0);
    for (int b = 1; b <= bands / 2; b++)
        for (int s = 0; s < segs; s++) {
            double th = PI * b / bands, ph = 2 * PI * s / segs;
            ts_vertex(&tm, sin(th) * cos(ph), cos(th), -sin(th) * sin(ph));
        }
#define RING(b, s) (1 + (uint32_t)((b) - 1) * segs + (uint32_t)((s) % segs))
    for (int s = 0; s < segs; s++) {
        ts_tri(&tm, top, RING(1, s), RING(1, s + 1));
        for (int b = 1; b < bands / 2; b++) {
            ts_tri(&tm, RING(b, s), RING(b + 1, s), RING(b + 1, s + 1));
            ts_tri(&tm, RING(b, s), RING(b + 1, s + 1), RING(b, s + 1));
        }
    }
#undef RING
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECKF(m.nboundary_edges == (uint32_t)segs, "%u boundary edges", m.nboundary_edges);
    /* every boundary edge is a feature edge with a feature segment */
    uint32_t with_segment = 0;
    for (uint32_t e = 0; e < m.nedges; e++)
        if (m.edge[e].flags & SILK_EDGE_BOUNDARY) {
            CHECK(m.edge[e].flags & SILK_EDGE_FEATURE);
            with_segment += m.edge_feature[e] != SILK_NO_INDEX;
        }
    CHECK(with_segment == (uint32_t)segs);
    const double below[3] = { 0.5, -2.5, 2 };
    CHECK(render_all(&tm, "hemisphere", EYE, ORIGIN) > 100);
    CHECK(render_all(&tm, "hemisphere from below", below, ORIGIN) > 100);
    ts_mesh_free(&tm);
}

/* An 8-sided disc seen face-on: FLAT draws the octagon (area 2 sqrt 2 r^2);
 * SMOOTH draws its border as feature curves through the corners, so the
 * area comes close to the circle's (pi r^2). */
TEST(boundary_is_feature_curve)
{
    const int n = 8;
    ts_mesh tm = { 0 };
    uint32_t c = ts_vertex(&tm, 0, 0, 0);
    for (int i = 0; i < n; i++) ts_vertex(&tm, cos(2 * PI * i / n), sin(2 * PI * i / n), 0);
    for (int i = 0; i < n; i++) ts_tri(&tm, c, 1 + (uint32_t)i, 1 + (uint32_t)((i + 1) % n));
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECK(m.nfeature_edges == (uint32_t)n && m.nboundary_edges == (uint32_t)n);
    const double eye[3] = { 0, 0, 3 };
    const int size = 200;
    const double half = 1.25, px_area = (2 * half / size) * (2 * half / size);
    double area[2];
    ts_image img = { 0 };
    for (int mode = 0; mode < 2; mode++) {
        silk_camera cam = ts_camera(eye, ORIGIN, -half, 0.5, 10, size, size);
        silk_render_opts o;
        silk_render_opts_default(&o);
        o.mode = (silk_mode)mode;
        o.tolerance_px = SILK_FX_C(1, 4);
        silk_frame_stats fs;
        CHECK(ts_render(&a, &m, &cam, &o, &img, &fs, &err) == SILK_OK);
        area[mode] = ts_count_covered(&img) * px_area;
        if (mode == SILK_MODE_SMOOTH) CHECKF(fs.samples >= (uint32_t)n, "%u samples on the border", fs.samples);
    }
    ts_image_free(&img);
    double octagon = 2 * sqrt(2.0), circle = PI;
    CHECKF(fabs(area[0] - octagon) < 0.02 * octagon, "flat area %.4f, octagon %.4f", area[0], octagon);
    CHECKF(fabs(area[1] - circle) < 0.02 * circle, "smooth area %.4f, circle %.4f (flat %.4f)", area[1], circle,
           area[0]);
    printf("  disc of 8 sides: flat %.4f (octagon %.4f), smooth %.4f (circle %.4f)\n", area[0], octagon, area[1],
           circle);
    ts_mesh_free(&tm);
}

/* Three and four triangles on one edge (a fin, a book), and a bow tie (two
 * triangles sharing only a vertex). */
TEST(non_manifold)
{
    ts_mesh tm = { 0 };
    uint32_t a0 = ts_vertex(&tm, 0, -1, 0), a1 = ts_vertex(&tm, 0, 1, 0);
    for (int i = 0; i < 4; i++) {
        double ang = 2 * PI * i / 4 + 0.3;
        ts_tri(&tm, a0, a1, ts_vertex(&tm, cos(ang), 0, sin(ang)));
    }
    uint32_t b0 = ts_vertex(&tm, 1.5, 0, 0);
    ts_tri(&tm, b0, ts_vertex(&tm, 2, 0.5, 0), ts_vertex(&tm, 2, -0.5, 0.2));
    ts_tri(&tm, b0, ts_vertex(&tm, 1, 0.5, 0.1), ts_vertex(&tm, 1, -0.5, 0));
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECKF(m.nnonmanifold_edges == 1, "%u non-manifold edges", m.nnonmanifold_edges);
    CHECK(render_all(&tm, "book", EYE, ORIGIN) > 50);
    ts_mesh_free(&tm);
}

/* Duplicates (same corners, same corners reversed), zero-area triangles
 * (collinear corners, a repeated index), on a closed sphere. */
TEST(duplicate_and_degenerate)
{
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 10, 8, 1, 0, 0, 0);
    uint32_t nf = tm.nf;
    for (uint32_t t = 0; t < nf; t += 7) ts_tri(&tm, tm.f[3 * t], tm.f[3 * t + 1], tm.f[3 * t + 2]);
    for (uint32_t t = 3; t < nf; t += 11) ts_tri(&tm, tm.f[3 * t], tm.f[3 * t + 2], tm.f[3 * t + 1]);
    uint32_t p = ts_vertex(&tm, 0, 0, 1), q = ts_vertex(&tm, 0.5, 0, 1), r = ts_vertex(&tm, 1, 0, 1);
    ts_tri(&tm, p, q, r);                       /* collinear */
    ts_tri(&tm, p, p, r);                       /* repeated index */
    ts_tri(&tm, q, q, q);                       /* a point */
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECKF(m.ndegenerate_tris == 3, "%u degenerate triangles", m.ndegenerate_tris);
    CHECK(m.nnonmanifold_edges > 0);
    CHECK(render_all(&tm, "duplicates", EYE, ORIGIN) > 500);
    ts_mesh_free(&tm);

    /* nothing but degenerate triangles: loads and draws at most the pixel
     * or two that the rounded projection of a line of zero area covers */
    ts_mesh flat = { 0 };
    uint32_t u = ts_vertex(&flat, 0, 0, 0), v = ts_vertex(&flat, 1, 1, 1), w = ts_vertex(&flat, 2, 2, 2);
    ts_tri(&flat, u, v, w);
    ts_tri(&flat, u, u, v);
    long cov = render_all(&flat, "only degenerate", EYE, ORIGIN);
    CHECKF(cov >= 0 && cov <= 2, "covers %ld pixels", cov);
    ts_mesh_free(&flat);
}

/* A sphere with every third triangle turned over: the flipped edges are
 * creases (dihedral near 180 degrees), the picture stays a disc. */
TEST(inconsistent_orientation)
{
    ts_mesh good = { 0 }, bad = { 0 };
    ts_sphere(&good, 16, 12, 1, 0, 0, 0);
    ts_sphere(&bad, 16, 12, 1, 0, 0, 0);
    for (uint32_t t = 0; t < bad.nf; t += 3) {
        uint32_t x = bad.f[3 * t + 1];
        bad.f[3 * t + 1] = bad.f[3 * t + 2];
        bad.f[3 * t + 2] = x;
    }
    long cg = render_all(&good, "sphere", EYE, ORIGIN), cb = render_all(&bad, "flipped sphere", EYE, ORIGIN);
    CHECKF(cg > 500 && labs(cb - cg) < cg / 20, "coverage %ld, consistent %ld", cb, cg);
    ts_mesh_free(&good);
    ts_mesh_free(&bad);
}

/* Vertices no triangle uses, one of them far away: they widen the box but
 * change nothing else. */
TEST(isolated_vertices)
{
    ts_mesh tm = { 0 };
    ts_vertex(&tm, 1000, -1000, 1000);
    ts_sphere(&tm, 10, 8, 1, 0, 0, 0);
    ts_vertex(&tm, 0, 0, 0);
    ts_vertex(&tm, 0.5, 0.5, 0.5);
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    CHECK(m.nverts == tm.nv && m.bbox_max.x == SILK_FX_C(1000, 1));
    CHECK(render_all(&tm, "isolated vertices", EYE, ORIGIN) > 500);
    ts_mesh_free(&tm);

    /* From text: the same, and a file with vertices but no triangle fails cleanly. */
    silk_mesh lm;
    CHECK(load_text("v 5 5 5\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv -7 2 1\nf 2 3 4\n", &a, &lm, &err) == SILK_OK);
    CHECK(lm.nverts == 5 && lm.ntris == 1);
    CHECK(load_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n", &a, &lm, &err) == SILK_ERR_EMPTY);
    CHECKF(strcmp(err.msg, "hard.obj: no triangles") == 0, "got \"%s\"", err.msg);
}

/* One million triangles: a UV sphere of 1000 x 501, built and drawn flat
 * and smooth at 256 x 256.  About 0.4 GB of arena; skipped under the
 * sanitizers (SILK_SAN=1), where it would take minutes. */
TEST(million_triangles)
{
    if (getenv("SILK_SAN")) {
        printf("  skipped under the sanitizers\n");
        return;
    }
    if (!check_built(!SILK_PLAN_INDEX16, "a plan of more than 65535 edges: SILK_PLAN_INDEX16 0")) return;
    clock_t t0 = clock();
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 1000, 501, 1, 0, 0, 0);
    CHECK(tm.nf == 1000000);
    size_t size = (size_t)448 << 20;
    unsigned char *mem = malloc(size);
    CHECK(mem != NULL);
    if (!mem) return;
    silk_arena a;
    silk_arena_init(&a, mem, size);
    silk_mesh m;
    silk_error err;
    silk_status st = ts_build(&tm, &a, &m, &err);
    ts_mesh_free(&tm);
    CHECKF(st == SILK_OK, "%s", err.msg);
    if (st == SILK_OK) {
        CHECK(silk_mesh_validate(&m, "million", &err) == SILK_OK);
        CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_OK);
        double load_s = (double)(clock() - t0) / CLOCKS_PER_SEC;
        ts_image img = { 0 };
        long cov[2];
        for (int mode = 0; mode < 2; mode++) {
            silk_camera cam = ts_camera(EYE, ORIGIN, 45, 0.5, 10, 256, 256);
            silk_render_opts o;
            silk_render_opts_default(&o);
            o.mode = (silk_mode)mode;
            o.aa = 0;   /* the pixels drawn: an anti-aliased outline's faintest pixels follow each mode's outline */
            silk_frame_stats fs;
            clock_t t1 = clock();
            CHECK(ts_render(&a, &m, &cam, &o, &img, &fs, &err) == SILK_OK);
            cov[mode] = ts_count_covered(&img);
            CHECK(!fs.fell_back && fs.tris_drawn >= 1000000);
            printf("  %s: %u triangles drawn, %zu frame bytes, %.2f s\n", mode ? "smooth" : "flat", fs.tris_drawn,
                   fs.frame_bytes, (double)(clock() - t1) / CLOCKS_PER_SEC);
        }
        /* a sphere of radius 1 seen from |EYE| under 45 degrees */
        double dist = sqrt(EYE[0] * EYE[0] + EYE[1] * EYE[1] + EYE[2] * EYE[2]);
        double rp = 128 * tan(asin(1 / dist)) / tan(22.5 * PI / 180);
        CHECKF(fabs(cov[0] - PI * rp * rp) < 0.01 * PI * rp * rp && labs(cov[1] - cov[0]) < 40,
               "coverage flat %ld smooth %ld, disc %.0f", cov[0], cov[1], PI * rp * rp);
        printf("  built in %.2f s, arena peak %zu bytes\n", load_s, a.peak);
        ts_image_free(&img);
    }
    free(mem);
    double total = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECKF(total < 20, "%.1f s", total);
}

int main(void)
{
    RUN(single_triangle);
    RUN(open_mesh);
    RUN(boundary_is_feature_curve);
    RUN(non_manifold);
    RUN(duplicate_and_degenerate);
    RUN(inconsistent_orientation);
    RUN(isolated_vertices);
    RUN(million_triangles);
    return check_done();
}
