/*
 * test_exhaustion.c - running out of arena memory, at every size.
 *
 * Loading: a model is loaded into arenas of every size from 0 upward (in
 * steps of 16 bytes) until it fits.  Each failure must be SILK_ERR_NOMEM
 * with one line that names a byte count, and leave the arena as it was;
 * once a size works, every larger one works too, and the first that works
 * is the peak of a load into a roomy arena (bottom and top together).
 *
 * Frames: with the model loaded, the memory left for the frame is stepped
 * from 0 upward (64 bytes at a time, or in 512 steps for a frame above
 * 32 KB) past what the frame needs.  At every
 * step silk_render either draws the frame or - only when not even the
 * coarse mesh's records fit - fails with one clean line.  A frame drawn in
 * full memory is the reference; a drawn frame is
 *   - byte for byte the reference when it did not fall back (a missing
 *     vertex cache costs time, not pixels),
 *   - byte for byte the FLAT frame when it fell back all the way
 *     (stats show no silhouette triangles),
 *   - otherwise (lines, whose own arrays may be what did not fit; PN and
 *     BLEND) a mix: every pixel is the reference's or the FLAT frame's,
 * and fell_back is set exactly when the frame had less memory than the
 * full frame's peak and did not draw the reference.  Scratch is always
 * released.  PN and BLEND fall back the same way.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "support/scene.h"

#define BIG ((size_t)8 << 20)
static unsigned char big_mem[BIG];

/* OBJ text of a ts_mesh, in a malloc'd buffer. */
static char *obj_text(const ts_mesh *m, size_t *len)
{
    size_t cap = 64 + (size_t)m->nv * 80 + (size_t)m->nf * 40, n = 0;
    char *s = malloc(cap);
    for (uint32_t i = 0; i < m->nv; i++)
        n += (size_t)snprintf(s + n, cap - n, "v %.6f %.6f %.6f\n", m->v[3 * i], m->v[3 * i + 1], m->v[3 * i + 2]);
    for (uint32_t i = 0; i < m->nf; i++)
        n += (size_t)snprintf(s + n, cap - n, "f %u %u %u\n", m->f[3 * i] + 1, m->f[3 * i + 1] + 1, m->f[3 * i + 2] + 1);
    *len = n;
    return s;
}

/* A torus around y: concave silhouettes, so the frame perturbs vertices too. */
static void torus(ts_mesh *m, int segs, int bands, double R, double r)
{
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < segs; i++)
        for (int j = 0; j < bands; j++) {
            double u = 2 * pi * i / segs, v = 2 * pi * j / bands;
            ts_vertex(m, (R + r * cos(v)) * cos(u), r * sin(v), -(R + r * cos(v)) * sin(u));
        }
#define V(i, j) ((uint32_t)(((i) % segs) * bands + ((j) % bands)))
    for (int i = 0; i < segs; i++)
        for (int j = 0; j < bands; j++) {
            ts_tri(m, V(i, j), V(i + 1, j), V(i + 1, j + 1));
            ts_tri(m, V(i, j), V(i + 1, j + 1), V(i, j + 1));
        }
#undef V
}

static int has_number(const char *s)
{
    for (; *s; s++)
        if (*s >= '0' && *s <= '9') return 1;
    return 0;
}

static void load_at_every_size(const char *text, size_t len, const char *name)
{
    /* the peak of a roomy load is the exact minimum arena (what the CLI
     * reports as "loading needs N bytes") */
    silk_arena roomy;
    silk_mesh rm;
    silk_error rerr;
    silk_arena_init(&roomy, big_mem, BIG);
    CHECKF(silk_load_mesh(text, len, name, NULL, &roomy, &rm, &rerr) == SILK_OK, "%s: %s", name, rerr.msg);
    size_t peak = roomy.peak;
    for (int d = 0; d < 2; d++) {
        silk_arena a;
        silk_arena_init(&a, big_mem, peak - (size_t)d * SILK_ARENA_ALIGN);
        CHECKF((silk_load_mesh(text, len, name, NULL, &a, &rm, &rerr) == SILK_OK) == !d,
               "%s: an arena of the peak %zu bytes %s, minus %d does %s", name, peak, d ? "loads" : "fails",
               SILK_ARENA_ALIGN, d ? "too" : "not");
    }

    size_t fits = 0;
    int failures = 0;
    for (size_t size = 0; size < BIG; size += 16) {
        silk_arena a;
        silk_arena_init(&a, big_mem, size);
        silk_mesh m;
        silk_error err;
        memset(&err, 0, sizeof err);
        silk_status st = silk_load_mesh(text, len, name, NULL, &a, &m, &err);
        if (st == SILK_OK) {
            if (!fits) fits = size;
            if (size > fits + 4096) break;         /* well past the minimum: done */
            continue;
        }
        failures++;
        CHECKF(!fits, "%s: loads at %zu bytes but not at %zu", name, fits, size);
        CHECKF(st == SILK_ERR_NOMEM, "%s at %zu bytes: status %d: %s", name, size, (int)st, err.msg);
        CHECKF(strncmp(err.msg, name, strlen(name)) == 0 && strchr(err.msg, '\n') == NULL && has_number(err.msg) &&
               strstr(err.msg, "bytes") != NULL,
               "%s at %zu bytes: \"%s\"", name, size, err.msg);
        CHECKF(a.bottom == 0 && a.top == 0, "%s at %zu bytes: arena not restored", name, size);
        if (size == 4096) printf("  %s in 4096 bytes: %s\n", name, err.msg);
    }
    CHECKF(fits > 0 && fits >= peak && fits < peak + 16, "%s: first loaded at %zu, peak %zu", name, fits, peak);
    printf("  %s: %zu bytes of text need an arena of %zu bytes (%d sizes failed cleanly)\n", name, len, fits,
           failures);
}

TEST(load_sizes)
{
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 10, 8, 1, 0, 0, 0);
    size_t len;
    char *text = obj_text(&tm, &len);
    load_at_every_size(text, len, "sphere.obj");
    free(text);
    ts_mesh_free(&tm);

    /* a PLY with normals and uvs, smoothing-group free, binary */
    static const char head[] = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                               "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                               "property float nz\nproperty float s\nproperty float t\nelement face 4\n"
                               "property list uchar int vertex_indices\nend_header\n";
    static const float vtx[4][8] = { { 0, 0, 0, 0, 0, -1, 0, 0 }, { 1, 0, 0, 1, 0, 0, 1, 0 },
                                     { 0, 1, 0, 0, 1, 0, 0, 1 }, { 0, 0, 1, 0, 0, 1, 1, 1 } };
    static const int32_t face[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    unsigned char ply[1024];
    size_t n = sizeof head - 1;
    memcpy(ply, head, n);
    memcpy(ply + n, vtx, sizeof vtx);
    n += sizeof vtx;
    for (int f = 0; f < 4; f++) {
        ply[n++] = 3;
        memcpy(ply + n, face[f], sizeof face[f]);
        n += sizeof face[f];
    }
    load_at_every_size((const char *)ply, n, "tetra.ply");
}

typedef struct frame_case {
    const char *name;
    silk_mode mode;
    ts_mesh *mesh;
    double eye[3];
    silk_lines lines;        /* with lines a SMOOTH frame is stored, not streamed */
} frame_case;

/* Renders with only `budget` bytes free for the frame. */
static silk_status render_budget(silk_arena *a, const silk_mesh *m, const silk_camera *cam, silk_mode mode,
                                 silk_lines lines, size_t budget, ts_image *img, silk_frame_stats *fs,
                                 silk_error *err)
{
    silk_arena_mark mark = silk_arena_top_mark(a);
    size_t bottom = a->bottom, used = a->used[SILK_MEM_RASTER], free_now = silk_arena_free_bytes(a);
    if (free_now > budget) silk_arena_alloc(a, free_now - budget - (SILK_ARENA_ALIGN - 1), SILK_MEM_RASTER);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;   /* the fall-back is compared pixel by pixel; outlines are anti-aliased by test_aa */
    o.mode = mode;
    o.lines = lines;
    silk_status st = ts_render(a, m, cam, &o, img, fs, err);
    CHECKF(a->top == mark.top, "scratch not released: top %zu", a->top);
    a->bottom = bottom;                     /* drop the filler */
    a->used[SILK_MEM_RASTER] = used;
    return st;
}

static void frames_at_every_size(const frame_case *fc)
{
    /* (a build without lines, PN or BLEND draws no such frame) */
    if ((fc->lines && !SILK_LINES) || (fc->mode != SILK_MODE_SMOOTH && !SILK_REFERENCE_MODES)) return;
    silk_arena a;
    silk_arena_init(&a, big_mem, BIG);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(fc->mesh, &a, &m, &err) == SILK_OK);
    CHECK(silk_vis_build(&m, NULL, &a, &err) == SILK_OK);
    const double target[3] = { 0, 0, 0 };
    silk_camera cam = ts_camera(fc->eye, target, 40, 0.1, 20, 48, 40);
    ts_image ref = { 0 }, flat = { 0 }, img = { 0 };
    silk_frame_stats rs, fs;
    CHECK(render_budget(&a, &m, &cam, fc->mode, fc->lines, BIG, &ref, &rs, &err) == SILK_OK);
    CHECK(render_budget(&a, &m, &cam, SILK_MODE_FLAT, fc->lines, BIG, &flat, &fs, &err) == SILK_OK);
    CHECKF(!rs.fell_back && memcmp(ref.rgb, flat.rgb, 48 * 40 * 3) != 0,
           "%s: the full frame should differ from FLAT", fc->name);
    size_t need = rs.frame_bytes, first_ok = 0;
    int fell = 0, partial = 0, errors = 0;
    /* 64-byte steps, or 512 steps over a frame larger than 32 KB */
    size_t step = need / 512 > 64 ? (need / 512 + 63) & ~(size_t)63 : 64;
    for (size_t budget = 0; budget <= need + 1024; budget += step) {
        memset(&fs, 0, sizeof fs);
        silk_status st = render_budget(&a, &m, &cam, fc->mode, fc->lines, budget, &img, &fs, &err);
        if (st != SILK_OK) {
            errors++;
            CHECKF(!first_ok, "%s: drawn with %zu bytes, not with %zu", fc->name, first_ok, budget);
            CHECKF(st == SILK_ERR_NOMEM && strncmp(err.msg, "frame", 5) == 0 && strchr(err.msg, '\n') == NULL,
                   "%s at %zu: status %d \"%s\"", fc->name, budget, (int)st, err.msg);
            continue;
        }
        if (!first_ok) first_ok = budget ? budget : 1;
        int same_ref = memcmp(img.rgb, ref.rgb, 48 * 40 * 3) == 0;
        int same_flat = memcmp(img.rgb, flat.rgb, 48 * 40 * 3) == 0;
        if (budget >= need) CHECKF(!fs.fell_back && same_ref, "%s at %zu >= %zu: not the full frame", fc->name, budget, need);
        if (!fs.fell_back) {
            CHECKF(same_ref, "%s at %zu: did not fall back, yet differs from the full frame", fc->name, budget);
            continue;
        }
        fell++;
        if (fs.silhouette_tris == 0 && fc->mode == SILK_MODE_SMOOTH && !fc->lines) {
            CHECKF(same_flat, "%s at %zu: fell back all the way, yet differs from FLAT", fc->name, budget);
            continue;
        }
        partial++;
        if (fc->lines) continue;      /* lines follow whatever was drawn: no pixel-wise bound */
        long mixed = 0;
        for (int i = 0; i < 48 * 40; i++)
            if (memcmp(img.rgb + 3 * i, ref.rgb + 3 * i, 3) && memcmp(img.rgb + 3 * i, flat.rgb + 3 * i, 3)) mixed++;
        /* pixels along a boundary between a smoothed and a dropped part may
         * be neither picture's */
        CHECKF(mixed <= 48, "%s at %zu: %ld pixels are neither the full nor the FLAT frame", fc->name, budget,
               mixed);
    }
    CHECKF(first_ok > 0, "%s: never drawn", fc->name);
    CHECKF(fell > 0, "%s: never fell back (need %zu bytes)", fc->name, need);
    printf("  %-10s %-6s%s frame needs %6zu bytes; drawn from %6zu; fell back at %3d sizes (%d partly); %d refused\n",
           fc->name, fc->mode == SILK_MODE_SMOOTH ? "smooth" : fc->mode == SILK_MODE_PN ? "pn" : "blend",
           fc->lines ? " + lines" : "", need,
           first_ok, fell, partial, errors);
    ts_image_free(&ref);
    ts_image_free(&flat);
    ts_image_free(&img);
}

TEST(frame_sizes)
{
    ts_mesh sphere = { 0 }, ring = { 0 }, cup = { 0 };
    ts_sphere(&sphere, 12, 9, 1, 0, 0, 0);
    torus(&ring, 16, 8, 1, 0.4);
    /* an open cup: half a sphere, so its rim is a feature curve */
    ts_sphere(&cup, 12, 8, 1, 0, 0, 0);
    uint32_t kept = 0;
    for (uint32_t t = 0; t < cup.nf; t++) {
        double y = (cup.v[3 * cup.f[3 * t] + 1] + cup.v[3 * cup.f[3 * t + 1] + 1] + cup.v[3 * cup.f[3 * t + 2] + 1]) / 3;
        if (y < 0) memmove(&cup.f[3 * kept++], &cup.f[3 * t], 3 * sizeof *cup.f);
    }
    cup.nf = kept;
    const frame_case cases[] = {
        { "sphere", SILK_MODE_SMOOTH, &sphere, { 0.5, 1, 3.2 }, SILK_LINES_NONE },
        { "torus", SILK_MODE_SMOOTH, &ring, { 0, 2.2, 2.2 }, SILK_LINES_NONE },
        { "cup", SILK_MODE_SMOOTH, &cup, { 0.5, 2, 2.5 }, SILK_LINES_NONE },
        { "torus", SILK_MODE_SMOOTH, &ring, { 0, 2.2, 2.2 }, SILK_LINES_OVER },
        { "sphere", SILK_MODE_PN, &sphere, { 0.5, 1, 3.2 }, SILK_LINES_NONE },
        { "torus", SILK_MODE_BLEND, &ring, { 0, 2.2, 2.2 }, SILK_LINES_NONE },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) frames_at_every_size(&cases[i]);
    ts_mesh_free(&sphere);
    ts_mesh_free(&ring);
    ts_mesh_free(&cup);
}

/* The sink of the band test: each band copied into place in a 48-wide frame. */
static int take_band(void *user, const silk_target *b)
{
    memcpy((uint8_t *)user + (size_t)b->y0 * 48 * 3, b->color, (size_t)b->rows * 48 * 3);
    return 0;
}

/* Band rendering runs out the same way and keeps its promise: the bands
 * together are the frame silk_render draws with the same memory. */
TEST(bands_with_little_memory)
{
    ts_mesh tm = { 0 };
    torus(&tm, 16, 8, 1, 0.4);
    silk_arena a;
    silk_arena_init(&a, big_mem, BIG);
    silk_mesh m;
    silk_error err;
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK);
    ts_mesh_free(&tm);
    const double eye[3] = { 0, 2.2, 2.2 }, target[3] = { 0, 0, 0 };
    silk_camera cam = ts_camera(eye, target, 40, 0.1, 20, 48, 40);
    silk_view v;
    CHECK(silk_view_init(&v, &cam, &err) == SILK_OK);
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &v);
    silk_hal_phong(&hal, &phong);
    silk_render_opts o;
    silk_render_opts_default(&o);
    o.aa = 0;   /* as render_budget: anti-aliasing that does not fit is left out, band by band */
    ts_image whole = { 0 };
    uint8_t bands_rgb[48 * 40 * 3], band_rgb[48 * 7 * 3];
    uint32_t band_depth[48 * 7];
    int checked = 0;
    for (size_t budget = 0; budget < 40000; budget += 1000) {
        silk_frame_stats fs, bs;
        silk_status st = render_budget(&a, &m, &cam, SILK_MODE_SMOOTH, SILK_LINES_NONE, budget, &whole, &fs, &err);
        size_t bottom = a.bottom, used = a.used[SILK_MEM_RASTER], free_now = silk_arena_free_bytes(&a);
        if (free_now > budget) silk_arena_alloc(&a, free_now - budget - (SILK_ARENA_ALIGN - 1), SILK_MEM_RASTER);
        silk_target band;
        silk_target_init(&band, 48, 40, 0, 7, SILK_PIX_RGB888, band_rgb, band_depth);
        silk_sink sink = { .band = take_band, .user = bands_rgb };
        o.bg_rgb = TS_BG;
        silk_status bst = silk_render_bands(&a, &m, &v, &hal, &o, &band, &sink, &bs, &err);
        a.bottom = bottom;
        a.used[SILK_MEM_RASTER] = used;
        CHECKF(a.top == 0, "bands kept scratch");
        CHECKF(bst == st, "budget %zu: bands %d, frame %d", budget, (int)bst, (int)st);
        if (st != SILK_OK || bst != SILK_OK) continue;
        CHECKF(bs.fell_back == fs.fell_back, "budget %zu: fell back %d vs %d", budget, bs.fell_back, fs.fell_back);
        CHECKF(memcmp(bands_rgb, whole.rgb, sizeof bands_rgb) == 0, "budget %zu: bands differ", budget);
        checked++;
    }
    CHECK(checked > 20);
    ts_image_free(&whole);
}

int main(void)
{
    RUN(load_sizes);
    RUN(frame_sizes);
    RUN(bands_with_little_memory);
    return check_done();
}
