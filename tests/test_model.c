/*
 * test_model.c - prepared models (src/model.c, tools/prep/model_file.c,
 * `silk prepare`'s pipeline): a model written and read back gives the
 * mesh it was made of, through silk_load_mesh's format detection too; the
 * container takes sections it does not know unless they are required, and
 * refuses every damaged byte it relies on; and the shared detailed models
 * prepared at 500 triangles give closed manifold meshes within 2% of the
 * target whose every vertex lies on the detailed surface (a vertex of it,
 * bit for bit, so within any tolerance of it) with the file's normals.
 * Malformed files are the .silk files of tests/bad/ (tests/cli_bad.sh) and fuzzed
 * by fuzz/fuzz_model.c.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "silk/validate.h"
#include "support/scene.h"
#include "support/testmesh.h"
#include "../tools/prep/model_file.h"   /* linked with every test (tests/support/stexgen.c) */
#include "../tools/prep/simplify.c"
#include "../tools/prep/surface.c"
#include "../tools/prep/closest.c"
#include "../tools/prep/fit.c"

static uint8_t arena_buf[1 << 22];

/* A unit cube's corners and twelve triangles, one normal per corner. */
static const silk_vec3 cube_pos[8] = {
    { 0, 0, 0 }, { 65536, 0, 0 }, { 65536, 65536, 0 }, { 0, 65536, 0 },
    { 0, 0, 65536 }, { 65536, 0, 65536 }, { 65536, 65536, 65536 }, { 0, 65536, 65536 },
};
static const uint32_t cube_tri[36] = { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                       1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7 };

/* The cube with one file normal per vertex (the corner's direction from
 * the centre, so the file's normals, not computed ones, show). */
static uint8_t *cube_model(size_t *len, uint32_t extra_type, uint32_t extra_flags)
{
    silk_vec3 n[8];
    for (int i = 0; i < 8; i++) {
        int32_t s = 37837;   /* 1/sqrt 3 */
        n[i] = silk_v3(cube_pos[i].x ? s : -s, cube_pos[i].y ? s : -s, cube_pos[i].z ? s : -s);
    }
    model_out m = { 0 };
    if (extra_type) CHECK(model_add(&m, extra_type, extra_flags, "hello", 5) == 0);
    CHECK(model_add_mesh(&m, 8, cube_pos, 8, n, 12, cube_tri, cube_tri) == 0);
    uint8_t *b = model_bytes(&m, len);
    model_free(&m);
    return b;
}

static silk_status load(const uint8_t *b, size_t len, const silk_load_opts *o, silk_mesh *m, silk_error *err)
{
    silk_arena a;
    silk_arena_init(&a, arena_buf, sizeof arena_buf);
    return silk_load_mesh(b, len, "m.silk", o, &a, m, err);
}

TEST(round_trip)
{
    size_t len;
    uint8_t *b = cube_model(&len, 0, 0);
    CHECK(silk_is_model(b, len) && len % 4 == 0);
    silk_mesh m;
    silk_error err;
    CHECKF(load(b, len, NULL, &m, &err) == SILK_OK, "%s", err.msg);
    CHECK(m.nverts == 8 && m.ntris == 12 && m.nnormals == 8 && m.normals_used == SILK_NORMALS_FILE);
    for (int i = 0; i < 8; i++) CHECK(m.pos[i].x == cube_pos[i].x && m.pos[i].y == cube_pos[i].y && m.pos[i].z == cube_pos[i].z);
    for (int i = 0; i < 36; i++) CHECK(m.tri[i] == cube_tri[i]);
    /* one normal per vertex: no split, so no feature edge, although every
     * cube edge is sharp - the model's normals say where creases are */
    CHECK(m.nfeature_edges == 0 && m.nboundary_edges == 0);
    CHECK(silk_mesh_validate(&m, "m", &err) == SILK_OK);
    /* computed normals on request: split at the cube's edges */
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.normals = SILK_NORMALS_COMPUTE;
    CHECK(load(b, len, &o, &m, &err) == SILK_OK && m.normals_used == SILK_NORMALS_COMPUTE && m.nnormals == 24);
    /* a scale is refused: the model was scaled when prepared */
    silk_load_opts_default(&o);
    o.scale.mant = 2;
    CHECK(load(b, len, &o, &m, &err) == SILK_ERR_ARG && strstr(err.msg, "silk prepare"));
    free(b);
}

TEST(container)
{
    size_t len;
    silk_mesh m;
    silk_error err;
    /* an unknown optional section in front is skipped */
    uint8_t *b = cube_model(&len, SILK_SECTION_TYPE('N', 'E', 'X', 'T'), 0);
    CHECKF(load(b, len, NULL, &m, &err) == SILK_OK && m.ntris == 12, "%s", err.msg);
    silk_model md;
    silk_model_section s;
    CHECK(silk_model_open(b, len, "m", &md, &err) == SILK_OK && md.nsections == 2);
    CHECK(silk_model_find(&md, SILK_SECTION_MESH, &s) && s.size == 16 + 12 * 8 + 12 * 8 + 24 * 12);
    CHECK(!silk_model_find(&md, SILK_SECTION_TYPE('H', 'U', 'L', 'L'), &s));
    /* a higher minor version is read */
    b[10] = 7;
    CHECK(load(b, len, NULL, &m, &err) == SILK_OK);
    free(b);
    /* an unknown required one is refused */
    b = cube_model(&len, SILK_SECTION_TYPE('N', 'E', 'X', 'T'), SILK_SECTION_REQUIRED);
    CHECK(load(b, len, NULL, &m, &err) == SILK_ERR_PARSE && strstr(err.msg, "section 0 (NEXT) is required"));
    free(b);
    /* every single-byte change past the magic is refused (the checksums
     * see the data), except of the minor version, which a reader may not
     * know; the arena is restored after failures */
    b = cube_model(&len, 0, 0);
    int refused = 0;
    for (size_t i = 8; i < len; i++) {
        uint8_t keep = b[i];
        b[i] ^= 0x10;
        silk_arena a;
        silk_arena_init(&a, arena_buf, sizeof arena_buf);
        silk_status st = silk_load_mesh(b, len, "m.silk", NULL, &a, &m, &err);
        if (st == SILK_OK) CHECK(silk_mesh_validate(&m, "m", &err) == SILK_OK);
        else {
            refused++;
            CHECK(a.bottom == 0 && a.top == 0 && strncmp(err.msg, "m.silk: ", 8) == 0);
        }
        b[i] = keep;
    }
    CHECKF(refused == (int)len - 8 - 2, "%d of %zu changed bytes refused", refused, len - 8);
    free(b);
    /* the CRC is the usual one (zlib, PNG) */
    CHECK(silk_crc32(0, "123456789", 9) == 0xCBF43926u);
}

/* `silk prepare`'s pipeline on a shared model, as cmd_prepare.c runs it:
 * the model's bytes (malloc'd) and its fine and coarse meshes; NULL when
 * the shared meshes are not there. */
static uint8_t *prepare_shared(const char *name, uint32_t target, size_t *len, simp_mesh *fine, simp_mesh *coarse)
{
    size_t big = (size_t)64 << 20;
    uint8_t *fine_buf = malloc(big);
    silk_arena fa;
    silk_arena_init(&fa, fine_buf, big);
    silk_mesh fm;
    if (!tm_load_shared(&fa, name, &fm)) {
        printf("skip: %s not found\n", name);
        free(fine_buf);
        return NULL;
    }
    CHECK(fm.nboundary_edges == 0 && fm.nnonmanifold_edges == 0);
    simp_mesh f = { fm.nverts, fm.ntris, malloc(3 * sizeof(double) * fm.nverts), malloc(3 * sizeof(uint32_t) * fm.ntris),
                    NULL };
    for (uint32_t i = 0; i < fm.nverts; i++)
        f.pos[3 * i] = fm.pos[i].x / 65536.0, f.pos[3 * i + 1] = fm.pos[i].y / 65536.0,
        f.pos[3 * i + 2] = fm.pos[i].z / 65536.0;
    for (uint32_t i = 0; i < 3 * fm.ntris; i++) f.tri[i] = fm.tri[i];
    free(fine_buf);
    *fine = f;
    CHECK(simp_copy(fine, coarse) == 0);
    simp_opts so;
    simp_opts_default(&so, target);
    so.subset = 1;
    simp_stats st;
    surf_normals sn;
    CHECK(simp_run(coarse, &so, &st) == 0 && surf_normals_compute(fine, coarse, so.crease_deg, &sn) == 0);
    silk_vec3 *pos = malloc(coarse->nverts * sizeof *pos), *nrm = malloc(sn.nnormals * sizeof *nrm);
    for (uint32_t i = 0; i < coarse->nverts; i++)
        pos[i] = silk_v3((silk_fx)llround(coarse->pos[3 * i] * 65536), (silk_fx)llround(coarse->pos[3 * i + 1] * 65536),
                         (silk_fx)llround(coarse->pos[3 * i + 2] * 65536));
    for (uint32_t i = 0; i < sn.nnormals; i++)
        nrm[i] = silk_v3((silk_fx)llround(sn.normal[3 * i] * 65536), (silk_fx)llround(sn.normal[3 * i + 1] * 65536),
                         (silk_fx)llround(sn.normal[3 * i + 2] * 65536));
    model_out mo = { 0 };
    CHECK(model_add_mesh(&mo, coarse->nverts, pos, sn.nnormals, nrm, coarse->ntris, coarse->tri, sn.tri_normal) == 0);
    uint8_t *b = model_bytes(&mo, len);
    free(pos), free(nrm);
    model_free(&mo);
    surf_normals_free(&sn);
    return b;
}

static void prepared(const char *name, uint32_t target)
{
    simp_mesh fine, coarse;
    size_t len;
    uint8_t *b = prepare_shared(name, target, &len, &fine, &coarse);
    if (!b) return;
    silk_mesh m;
    silk_error err;
    CHECKF(load(b, len, NULL, &m, &err) == SILK_OK, "%s", err.msg);
    CHECKF(fabs((double)m.ntris - target) <= 0.02 * target, "%s: %u triangles for %u", name, m.ntris, target);
    CHECKF(m.nboundary_edges == 0 && m.nnonmanifold_edges == 0, "%s: %u boundary, %u non-manifold edges", name,
           m.nboundary_edges, m.nnonmanifold_edges);
    CHECK(m.normals_used == SILK_NORMALS_FILE);
    /* every vertex is the fine vertex it came from, exactly */
    uint32_t off = 0;
    for (uint32_t v = 0; v < m.nverts; v++) {
        const double *p = &fine.pos[3 * coarse.origin[v]];
        off += m.pos[v].x != (silk_fx)llround(p[0] * 65536) || m.pos[v].y != (silk_fx)llround(p[1] * 65536) ||
               m.pos[v].z != (silk_fx)llround(p[2] * 65536);
    }
    CHECKF(off == 0, "%s: %u vertices off the detailed surface", name, off);
    printf("  %s -> %u triangles, %u vertices, %u normals, %u feature edges, %zu bytes\n", name, m.ntris, m.nverts,
           m.nnormals, m.nfeature_edges, len);
    free(b);
    simp_free(&fine);
    simp_free(&coarse);
}

/* --fit on bunny: the objective falls, every normal stays a unit vector
 * within FIT_MAX_DEG of the detailed surface's, split normals stay. */
TEST(fitted_normals)
{
    simp_mesh fine, coarse;
    size_t len;
    uint8_t *b = prepare_shared("bunny-fine.obj", 500, &len, &fine, &coarse);
    if (!b) return;
    free(b);
    surf_normals sn, orig;
    CHECK(surf_normals_compute(&fine, &coarse, 60, &sn) == 0 && surf_normals_compute(&fine, &coarse, 60, &orig) == 0);
    fit_stats st;
    CHECK(fit_normals(&fine, &coarse, &sn, &st) == 0);
    CHECKF(st.after < 0.8 * st.before && st.moved > coarse.nverts / 2, "objective %.3g -> %.3g, %u moved", st.before,
           st.after, st.moved);
    double worst = 0;
    int bad = 0;
    for (uint32_t g = 0; g < sn.nnormals; g++) {
        bad += fabs(len3(&sn.normal[3 * g]) - 1) > 1e-12;
        double a = acos(fmin(1, dot3(&sn.normal[3 * g], &orig.normal[3 * g]))) * 180 / 3.14159265358979323846;
        if (a > worst) worst = a;
    }
    CHECK(bad == 0 && worst <= FIT_MAX_DEG + 1e-9);
    printf("  bunny: objective %.3g -> %.3g, %u normals moved, at most %.1f degrees\n", st.before, st.after, st.moved,
           worst);
    surf_normals_free(&sn);
    surf_normals_free(&orig);
    simp_free(&fine);
    simp_free(&coarse);
}

TEST(prepared_shared_models)
{
    prepared("bunny-fine.obj", 500);
    prepared("armadillo-fine.obj", 500);
    prepared("spot-fine.obj", 500);
    prepared("feline-fine.obj", 500);
}

/* The bulge bound (src/curve.h) on very coarse meshes: the shared models
 * prepared at 100 and 200 triangles, drawn flat, as PN triangles at level 3
 * and smooth from 8 views around them.  Every pixel smooth mode covers
 * outside the union of the flat and PN outlines is within half of the
 * mesh's longest edge (projected at the model's centre) of that union.
 * The curves alone keep within a quarter: a point of a smooth curve lies
 * within 1/8 of its chord from the chord, and a silhouette segment's chord
 * ends on two such curves (without the vertex perturbation of III-E the
 * worst case below is 7 px); the perturbation, which moves vertices next
 * to concave segments by up to twice a segment's rise, takes thin sheets
 * (feline at 100 triangles: 36 px, a quarter being 27) further. */
static void no_bulges(const char *name, uint32_t target)
{
    simp_mesh fine, coarse;
    size_t len;
    uint8_t *b = prepare_shared(name, target, &len, &fine, &coarse);
    if (!b) return;
    size_t size = (size_t)32 << 20;
    uint8_t *buf = malloc(size);
    silk_arena a;
    silk_arena_init(&a, buf, size);
    silk_mesh m;
    silk_error err;
    CHECKF(silk_load_mesh(b, len, name, NULL, &a, &m, &err) == SILK_OK, "%s", err.msg);
    double lo[3], hi[3], c[3], r = 0, lmax = 0;
    for (int k = 0; k < 3; k++) {
        lo[k] = ts_fx2d((&m.bbox_min.x)[k]);
        hi[k] = ts_fx2d((&m.bbox_max.x)[k]);
        c[k] = (lo[k] + hi[k]) / 2;
    }
    for (uint32_t v = 0; v < m.nverts; v++) {
        double d = hypot(hypot(ts_fx2d(m.pos[v].x) - c[0], ts_fx2d(m.pos[v].y) - c[1]), ts_fx2d(m.pos[v].z) - c[2]);
        if (d > r) r = d;
    }
    for (uint32_t e = 0; e < m.nedges; e++) {
        silk_vec3 p = m.pos[m.edge[e].v[0]], q = m.pos[m.edge[e].v[1]];
        double d = hypot(hypot(ts_fx2d(p.x - q.x), ts_fx2d(p.y - q.y)), ts_fx2d(p.z - q.z));
        if (d > lmax) lmax = d;
    }
    enum { W = 320, H = 240 };
    const double fov = 35, dist = 3 * r, pi = 3.14159265358979323846;
    double px_per_unit = H / 2.0 / tan(fov / 2 * pi / 180) / dist;
    double bound = lmax / 2 * px_per_unit + 1;
    ts_image img[3] = { { 0 }, { 0 }, { 0 } };
    double worst = 0;
    long outside = 0;
    for (int view = 0; view < 8; view++) {
        double az = 2 * pi * view / 8 + 0.3, el = 0.35;
        double eye[3] = { c[0] + dist * cos(el) * sin(az), c[1] + dist * sin(el), c[2] + dist * cos(el) * cos(az) };
        silk_camera cam = ts_camera(eye, c, fov, dist - 1.5 * r, dist + 1.5 * r, W, H);
        static const silk_mode modes[3] = { SILK_MODE_FLAT, SILK_MODE_PN, SILK_MODE_SMOOTH };
        for (int k = 0; k < 3; k++) {
            silk_render_opts o;
            silk_render_opts_default(&o);
            o.mode = modes[k];
            o.level = 3;
            CHECKF(ts_render(&a, &m, &cam, &o, &img[k], NULL, &err) == SILK_OK, "%s", err.msg);
        }
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                if (!ts_covered(&img[2], x, y) || ts_covered(&img[0], x, y) || ts_covered(&img[1], x, y)) continue;
                outside++;
                double best = 1e9;
                for (int dy = -60; dy <= 60; dy++)
                    for (int dx = -60; dx <= 60; dx++) {
                        int u = x + dx, v = y + dy;
                        if (u < 0 || v < 0 || u >= W || v >= H) continue;
                        if ((ts_covered(&img[0], u, v) || ts_covered(&img[1], u, v)) && hypot(dx, dy) < best)
                            best = hypot(dx, dy);
                    }
                if (best > worst) worst = best;
            }
    }
    printf("  %s at %u triangles: %ld smooth pixels outside flat and PN3, at most %.2f px from them "
           "(bound %.2f px: half the longest edge)\n", name, m.ntris, outside, worst, bound);
    CHECKF(worst <= bound, "%s at %u: a bulge %.2f px outside flat and PN3 (bound %.2f)", name, target, worst, bound);
    for (int k = 0; k < 3; k++) ts_image_free(&img[k]);
    free(buf);
    free(b);
    simp_free(&fine);
    simp_free(&coarse);
}

TEST(no_bulges_on_very_coarse_meshes)
{
    static const char *names[] = { "bunny-fine.obj", "armadillo-fine.obj", "spot-fine.obj", "feline-fine.obj",
                                   "cow-fine.obj", "fandisk-fine.obj" };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        no_bulges(names[i], 100);
        no_bulges(names[i], 200);
    }
}

int main(void)
{
    RUN(round_trip);
    RUN(container);
    RUN(prepared_shared_models);
    RUN(fitted_normals);
    RUN(no_bulges_on_very_coarse_meshes);
    return check_done();
}
