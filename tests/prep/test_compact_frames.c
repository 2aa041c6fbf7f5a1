/*
 * test_compact_frames.c - a compact model draws exactly as the same model
 * held in arrays.
 *
 * Each mesh is encoded (tools/prep/compact_enc.c), read in place
 * (silk_compact_mesh), and written out again into silk_mesh arrays in the
 * same order (support/expand.c).  The two then hold the same numbers, so
 * every frame of them - flat, smooth, smooth with anti-aliased outlines,
 * whole and in bands - must be the same bytes: a stage that read the
 * mesh's arrays directly, instead of through the accessors of silk/mesh.h,
 * reads nothing of a compact model and shows here.  Meshes: bunny-500,
 * knot-480, fandisk-1000 and cone-70 from the shared meshes (skipped when
 * absent), a generated torus, and a height field with a boundary.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/expand.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "tools/prep/compact_enc.h"
#include "tools/prep/gen.h"
#include "silk/silk.h"
#include "silk/validate.h"

#define W 160
#define H 120
#define ARENA_BYTES (16u << 20)
#define BG 0x204060u

static uint8_t *arena_buf;

/* The OBJ text of a bumpy 9 x 9 height field: an open surface, so its
 * rim is a boundary. */
static char *height_field(size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    for (int j = 0; j < 9; j++)
        for (int i = 0; i < 9; i++)
            n += (size_t)snprintf(s + n, cap - n, "v %g %g %g\n", i / 4.0 - 1, 0.3 * sin(i * 0.9) * cos(j * 0.7),
                                  j / 4.0 - 1);
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++) {
            int a = 1 + j * 9 + i, b = a + 1, c = a + 9, d = c + 1;
            n += (size_t)snprintf(s + n, cap - n, "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d);
        }
    *len = n;
    return s;
}

/* The OBJ text of mesh `name`: a shared mesh, "torus" or "field". */
static char *mesh_text(const char *name, size_t *len)
{
    if (strcmp(name, "field") == 0) return height_field(len);
    if (strcmp(name, "torus") == 0) {
        gen_params p;
        gen_defaults(GEN_TORUS, &p);
        return gen_obj_text(&p, len);
    }
    char path[512];
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
    return tm_read_file(path, len);
}

/* The box's centre seen from azimuth/elevation (degrees), 3 radii away. */
static int make_view(const silk_mesh *m, double az, double el, int ortho, silk_view *v)
{
    const double deg = 3.14159265358979323846 / 180;
    double d[3] = { cos(el * deg) * sin(az * deg), sin(el * deg), cos(el * deg) * cos(az * deg) };
    return tf_view_around_size(m, d, 3, ortho, W, H, v);
}

/* One frame of m into frame (W x H RGB888), whole or in bands of `rows`. */
static int draw(silk_arena *arena, const silk_mesh *m, const silk_view *v, silk_mode mode, int aa, int rows,
                uint8_t *frame, silk_frame_stats *fs)
{
    silk_arena a = *arena;
    silk_phong ph;
    silk_hal hal;
    silk_phong_default(&ph, v);
    silk_hal_phong(&hal, &ph);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.mode = mode;
    ro.bg_rgb = BG;
    ro.aa = aa;
    silk_error err;
    silk_status st;
    if (rows) {
        tf_collect c = { frame, 0, 0, 0, 0, 0 };
        st = tf_render_bands(&a, m, v, &hal, &ro, SILK_PIX_RGB888, rows, &c, fs, &err);
    } else {
        uint8_t *color = silk_arena_alloc(&a, (size_t)W * H * 3, SILK_MEM_RASTER);
        uint32_t *depth = silk_arena_array(&a, (size_t)W * H, sizeof *depth, SILK_MEM_RASTER);
        if (!color || !depth) return 0;
        silk_target t;
        silk_target_init(&t, W, H, 0, H, SILK_PIX_RGB888, color, depth);
        st = silk_render(&a, m, v, &hal, &ro, &t, fs, &err);
        memcpy(frame, color, (size_t)W * H * 3);
    }
    if (st != SILK_OK) fprintf(stderr, "render: %s\n", err.msg);
    return st == SILK_OK;
}

static const struct { double az, el; int ortho; } views[] = {
    { 30, 20, 0 }, { 200, -35, 0 }, { 110, 60, 1 }, { 300, -70, 0 }, { 0, 0, 1 }, { 150, 10, 0 },
};

/* name: encode, read in place, expand, and compare every frame. */
static void check_model(const char *name, int adjacency)
{
    size_t len = 0;
    char *text = mesh_text(name, &len);
    if (!text) {
        CHECKF(check_cur_skipped, "cannot read %s", name);
        return;
    }
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    silk_mesh full, packed, expanded;
    silk_error err;
    silk_status st = silk_load_mesh(text, len, name, &lo, &a, &full, &err);
    free(text);
    CHECKF(st == SILK_OK, "%s: %s", name, err.msg);
    if (st != SILK_OK) return;
    compact_opts o = compact_opts_default();
    o.adjacency = adjacency;
    uint8_t *bytes = NULL;
    size_t nbytes = 0;
    char why[200];
    int enc = compact_encode(&full, &o, &bytes, &nbytes, why, sizeof why);
    CHECKF(enc == 0, "%s: %s", name, why);
    if (enc != 0) return;
    st = silk_compact_mesh(bytes, nbytes, name, &packed, &err);
    CHECKF(st == SILK_OK, "%s: %s", name, err.msg);
    CHECKF(silk_mesh_validate(&packed, name, &err) == SILK_OK, "%s: validate: %s", name, err.msg);
    int ok = st == SILK_OK && ex_expand(&packed, &a, &expanded);
    CHECKF(ok, "%s: the model's walks disagree with its random access", name);
    uint8_t *f0 = malloc((size_t)W * H * 3), *f1 = malloc((size_t)W * H * 3);
    for (size_t i = 0; ok && f0 && f1 && i < sizeof views / sizeof views[0]; i++) {
        silk_view v;
        if (!make_view(&full, views[i].az, views[i].el, views[i].ortho, &v)) continue;
        for (int mode = 0; mode < 3; mode++) {
            silk_mode md = mode == 0 ? SILK_MODE_FLAT : SILK_MODE_SMOOTH;
            int aa = mode == 2 && SILK_AA, rows = i % 2 ? 8 : 0;
            if (mode == 2 && !SILK_AA) continue;
            silk_frame_stats s0, s1;
            /* without adjacency a smooth frame is the flat one (its triangles have no edges to smooth) */
            const silk_mesh *other = adjacency || md == SILK_MODE_FLAT ? &expanded : &packed;
            silk_mode md1 = adjacency ? md : SILK_MODE_FLAT;
            int d0 = draw(&a, &packed, &v, md, aa, rows, f0, &s0), d1 = draw(&a, other, &v, md1, aa, rows, f1, &s1);
            CHECKF(d0 && d1, "%s view %zu mode %d: a frame failed", name, i, mode);
            size_t diff = 0;
            for (size_t b = 0; d0 && d1 && b < (size_t)W * H * 3; b++) diff += f0[b] != f1[b];
            CHECKF(diff == 0, "%s%s view %zu (az %g el %g) %s%s: %zu bytes differ", name, adjacency ? "" : " (flat only)",
                   i, views[i].az, views[i].el, md == SILK_MODE_FLAT ? "flat" : "smooth", aa ? " aa" : "", diff);
            if (md == SILK_MODE_SMOOTH && adjacency)
                CHECKF(s0.silhouette_tris > 0 || strcmp(name, "field") == 0 || strcmp(name, "cone-70.obj") == 0,
                       "%s: no silhouette", name);
        }
    }
    free(f0);
    free(f1);
    free(bytes);
}

TEST(compact_frames_bunny) { check_model("bunny-500.obj", 1); }
TEST(compact_frames_knot) { check_model("knot-480.obj", 1); }
TEST(compact_frames_fandisk) { check_model("fandisk-1000.obj", 1); }
TEST(compact_frames_cone) { check_model("cone-70.obj", 1); }
TEST(compact_frames_torus) { check_model("torus", 1); }
TEST(compact_frames_boundary) { check_model("field", 1); }
TEST(compact_frames_flat_only) { check_model("bunny-500.obj", 0); }

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    if (!arena_buf) return 1;
    RUN(compact_frames_bunny);
    RUN(compact_frames_knot);
    RUN(compact_frames_fandisk);
    RUN(compact_frames_cone);
    RUN(compact_frames_torus);
    RUN(compact_frames_boundary);
    RUN(compact_frames_flat_only);
    free(arena_buf);
    return check_done();
}
