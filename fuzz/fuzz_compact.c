/*
 * fuzz_compact.c - libFuzzer harness for the compact model reader
 * (src/compact.c, silk/compact.h): bytes -> silk_compact_mesh -> a small
 * frame drawn from the bytes in place.
 *
 * The input is a compact model (.slkc, `silk pack -o FILE.slkc`).  It is
 * read as it is (so the fuzzer meets the header, size and CRC checks),
 * then once more from a copy whose size field, trailing zero bytes and CRC
 * are made right, so that the checks of the arrays behind the CRC are
 * reached.  Each copy sits in a heap block of exactly its size, so ASan
 * sees any read past the model.  Checks besides "no crash":
 *   failure: one clean line naming the model (fuzz_check_error);
 *   success: silk_mesh_validate accepts the mesh; every accessor answers
 *            in range (corners, corner normals of the corner's vertex,
 *            every side's edge joining the side's vertices, every
 *            vertex's ring ending within its triangles' sides and naming
 *            only its edges, feature segments only on feature edges); and
 *            one 24 x 20 frame in the mode the input's length picks (the
 *            next mode for the second copy) draws
 *            or fails cleanly, keeps no frame memory, and in bands of 4
 *            rows gives the whole frame's bytes.
 */
#include "fuzz.h"
#include "silk/compact.h"

#define FC_NAME "fuzz.slkc"
#define FC_W 24
#define FC_H 20
#define FC_ROWS 4

typedef struct fc_band_copy {
    uint8_t *dst;
    size_t stride;
} fc_band_copy;

static int fc_take_band(void *user, const silk_target *band)
{
    fc_band_copy *c = user;
    for (int r = 0; r < band->rows; r++)
        memcpy(c->dst + (size_t)(band->y0 + r) * c->stride, band->color + (size_t)r * band->stride, c->stride);
    return 0;
}

/* The accessors of a checked model answer in range: what silk_compact_mesh
 * promises by checking every value a frame reads. */
static void fc_check_accessors(const silk_mesh *m)
{
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        silk_index v = silk_mesh_corner(m, c), n = silk_mesh_corner_normal(m, c);
        fuzz_expect(v < m->nverts, "corner %u: vertex %u of %u", c, v, m->nverts);
        fuzz_expect(n < m->nnormals, "corner %u: normal %u of %u", c, n, m->nnormals);
        fuzz_expect(silk_mesh_normal_vertex(m, n) == v, "corner %u: normal %u is not of vertex %u", c, n, v);
    }
    if (m->nedges == 0) return;
    for (uint32_t t = 0; t < m->ntris; t++)
        for (uint32_t k = 0; k < 3; k++) {
            silk_index e = silk_mesh_tri_edge(m, t, k);
            fuzz_expect(e < silk_mesh_edge_bound(m), "triangle %u side %u: edge %u of %u", t, k, e, silk_mesh_edge_bound(m));
            silk_edge ed = silk_mesh_edge(m, e);
            silk_index a = silk_mesh_corner(m, 3 * t + k), b = silk_mesh_corner(m, 3 * t + (k + 1) % 3);
            fuzz_expect(ed.v[0] == (a < b ? a : b) && ed.v[1] == (a < b ? b : a) && (ed.t[0] == t || ed.t[1] == t),
                        "triangle %u side %u: edge %u joins %u-%u of triangles %u, %u", t, k, e, ed.v[0], ed.v[1],
                        ed.t[0], ed.t[1]);
            silk_feature_seg s;
            fuzz_expect(silk_mesh_feature_seg(m, e, &s) == silk_edge_has_feature(&ed),
                        "edge %u: a feature segment without a feature flag, or none with one", e);
        }
    /* a ring names each side at the vertex at most once: 2 per corner */
    for (silk_index v = 0; v < m->nverts; v++) {
        silk_mesh_ring r;
        uint32_t n = 0;
        for (silk_index e = silk_mesh_ring_first(m, v, &r); e != SILK_NO_INDEX; e = silk_mesh_ring_next(m, &r)) {
            fuzz_expect(e < silk_mesh_edge_bound(m), "vertex %u: ring edge %u of %u", v, e, silk_mesh_edge_bound(m));
            silk_edge ed = silk_mesh_edge(m, e);
            fuzz_expect(ed.v[0] == v || ed.v[1] == v, "vertex %u: ring edge %u joins %u-%u", v, e, ed.v[0], ed.v[1]);
            fuzz_expect(++n <= 2 * 3 * m->ntris, "vertex %u: the ring does not end", v);
        }
    }
}

/* One frame from outside the model's box, and the same in bands. */
static void fc_draw(const silk_mesh *m, uint32_t mode)
{
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    silk_fx d = fuzz_aim(m, &cam);
    cam.eye = silk_v3(silk_fx_add(cam.target.x, d / 2), silk_fx_add(cam.target.y, d / 3), silk_fx_add(cam.target.z, d));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(40, 1);
    cam.znear = SILK_FX_C(1, 100);
    cam.zfar = silk_fx_mul(d, 4 * SILK_FX_ONE);
    cam.width = FC_W;
    cam.height = FC_H;
    silk_view view;
    silk_error err;
    if (silk_view_init(&view, &cam, &err) != SILK_OK) return;

    static uint8_t mem[(size_t)8 << 20];     /* kept between runs */
    silk_arena a;
    silk_arena_init(&a, mem, sizeof mem);
    uint8_t *color = malloc(FC_W * FC_H * 3), *whole = malloc(FC_W * FC_H * 3), *bcolor = malloc(FC_W * FC_ROWS * 3);
    uint32_t *depth = malloc(FC_W * FC_H * sizeof *depth), *bdepth = malloc(FC_W * FC_ROWS * sizeof *bdepth);
    if (color && whole && bcolor && depth && bdepth) {
        silk_phong phong;
        silk_hal hal;
        silk_phong_default(&phong, &view);
        silk_hal_phong(&hal, &phong);
        silk_render_opts ro;
        silk_render_opts_default(&ro);
        ro.mode = (silk_mode)(mode & 3);
        ro.wire = (mode >> 2) & 1;
        silk_target t;
        silk_target_init(&t, FC_W, FC_H, 0, FC_H, SILK_PIX_RGB888, color, depth);
        silk_frame_stats stats;
        silk_status st = silk_render(&a, m, &view, &hal, &ro, &t, &stats, &err);
        fuzz_expect(a.top == 0 && a.bottom == 0, "the frame kept memory: top %zu", a.top);
        if (st != SILK_OK) {
            fuzz_check_error(st, &err, NULL);
        } else {
            silk_target band;
            silk_target_init(&band, FC_W, FC_H, 0, FC_ROWS, SILK_PIX_RGB888, bcolor, bdepth);
            fc_band_copy bc = { whole, FC_W * 3 };
            silk_sink sink = { .band = fc_take_band, .user = &bc };
            silk_frame_stats bstats;
            silk_status bst = silk_render_bands(&a, m, &view, &hal, &ro, &band, &sink, &bstats, &err);
            fuzz_expect(a.top == 0 && a.bottom == 0, "the banded frame kept memory: top %zu", a.top);
            fuzz_expect(bst == SILK_OK, "bands failed where the frame did not: %s", err.msg);
            fuzz_expect(stats.aa_aliased || bstats.aa_aliased || memcmp(whole, color, FC_W * FC_H * 3) == 0,
                        "band pixels differ from the whole frame's");
        }
    }
    free(color), free(whole), free(bcolor), free(depth), free(bdepth);
}

static void fc_read(const uint8_t *b, size_t size, uint32_t mode)
{
    silk_mesh m;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_compact_mesh(b, size, FC_NAME, &m, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, FC_NAME);
        return;
    }
    fuzz_expect(m.packed.base == b, "the mesh does not read the model in place");
    silk_status v = silk_mesh_validate(&m, FC_NAME, &err);
    fuzz_expect(v == SILK_OK, "a model silk_compact_mesh took fails silk_mesh_validate: %s", err.msg);
    fc_check_accessors(&m);
    fc_draw(&m, mode);
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    if (size > ((size_t)1 << 20)) return 0;
    uint8_t *b = malloc(size ? size : 1);   /* exactly size bytes, as libFuzzer hands them over */
    if (!b) return 0;
    memcpy(b, data, size);
    fc_read(b, size, (uint32_t)size);
    /* the size, the 4 zero bytes at the end and the CRC made right */
    if (size >= SILK_COMPACT_HEADER_BYTES + 4) {
        fuzz_wr32(b + 48, (uint32_t)size);
        fuzz_wr32(b + size - 4, 0);
        fuzz_wr32(b + 52, silk_crc32(0, b + SILK_COMPACT_HEADER_BYTES, size - SILK_COMPACT_HEADER_BYTES));
        fc_read(b, size, (uint32_t)size + 1);   /* a valid model is drawn in two modes */
    }
    free(b);
    return 0;
}
