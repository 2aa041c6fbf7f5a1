/*
 * fuzz_pack.c - libFuzzer harness for packed models: the arrays a
 * `silk pack` header holds, corrupted, through silk_mesh_validate and,
 * when it accepts them, through silk_render.
 *
 * silk has no runtime reader of packed models: `silk pack` writes the
 * loaded mesh as C arrays that a device compiles into flash, and
 * NAME_mesh() only points a silk_mesh at them.  What "loads" packed data on
 * the device is therefore the renderer itself, trusting every index.  So
 * this harness builds exactly those arrays - each in its own heap block of
 * its own size, as the header's separate const arrays are, so that ASan
 * sees a read past any one of them - from a mesh silk loaded, overwrites
 * words of them as a damaged or hand-edited header would, and requires:
 *   silk_mesh_validate rejects it with one clean line, or
 *   silk_render draws it (every mode) without touching memory outside.
 * Counts can only be lowered: an array shorter than its count is beyond
 * any check (the validator cannot know an array's real length).
 *
 * Input: 1 byte E, then E edits of 6 bytes (array: 1, word index: 2,
 * value: 3, see apply_edit), 1 byte of view (mode: bits 0-1, orthographic:
 * bit 2, eye octant: bits 3-5, pen-and-ink lines: bits 6-7, polygonal
 * ones in PN and BLEND), then a mesh (OBJ or PLY).
 */
#include "fuzz.h"
#include "silk/validate.h"

#define PACK_NAME "packed"

enum {
    A_POS, A_NORMAL, A_NORMAL_VERTEX, A_UV, A_TRI, A_TRI_NORMAL, A_TRI_UV, A_EDGE,
    A_VERT_EDGE_START, A_VERT_EDGE, A_FEATURE, A_VIS_NODE, A_NARRAYS
};

/* The packed model: every array on its own, and the silk_vis they point at. */
typedef struct packed {
    void *arr[A_NARRAYS];
    size_t bytes[A_NARRAYS];
    silk_vis vis;
    silk_mesh m;
} packed;

static void *pack_copy(packed *p, int k, const void *src, size_t n)
{
    p->bytes[k] = n;
    if (!src || !n) return NULL;
    p->arr[k] = malloc(n);
    if (p->arr[k]) memcpy(p->arr[k], src, n);
    return p->arr[k];
}

static void pack(packed *p, const silk_mesh *src)
{
    memset(p, 0, sizeof *p);
    silk_mesh *m = &p->m;
    *m = *src;
    size_t nc = 3 * (size_t)src->ntris, is = sizeof(silk_index);
    m->pos = pack_copy(p, A_POS, src->pos, src->nverts * sizeof *src->pos);
    m->normal = pack_copy(p, A_NORMAL, src->normal, src->nnormals * sizeof *src->normal);
    m->normal_vertex = pack_copy(p, A_NORMAL_VERTEX, src->normal_vertex, src->nnormals * is);
    m->uv = pack_copy(p, A_UV, src->uv, src->nuvs * sizeof *src->uv);
    m->tri = pack_copy(p, A_TRI, src->tri, nc * is);
    m->tri_normal = pack_copy(p, A_TRI_NORMAL, src->tri_normal, nc * is);
    m->tri_uv = pack_copy(p, A_TRI_UV, src->tri_uv, src->tri_uv ? nc * is : 0);
    m->tri_edge = NULL;   /* not packed: found from the vertex-edge lists */
    m->edge = pack_copy(p, A_EDGE, src->edge, src->nedges * sizeof *src->edge);
    m->vert_edge_start = pack_copy(p, A_VERT_EDGE_START, src->vert_edge_start,
                                   ((size_t)src->nverts + 1) * sizeof *src->vert_edge_start);
    m->vert_edge = pack_copy(p, A_VERT_EDGE, src->vert_edge, src->vert_edge_start[src->nverts] * is);
    m->edge_feature = NULL;   /* not packed: counted along the edges */
    m->feature = pack_copy(p, A_FEATURE, src->feature, src->nfeature_edges * sizeof *src->feature);
    m->vis = NULL;
    if (src->vis) {
        p->vis = *src->vis;
        p->vis.node = pack_copy(p, A_VIS_NODE, src->vis->node, src->vis->nnodes * sizeof *src->vis->node);
        m->vis = &p->vis;
    }
}

static void unpack(packed *p)
{
    for (int k = 0; k < A_NARRAYS; k++) free(p->arr[k]);
}

static uint32_t lower(uint32_t count, uint32_t v) { return v < count ? v : count; }

/* One edit: a 32-bit word written into an array at a word index, or a
 * count (selectors past the arrays) lowered. */
static void apply_edit(packed *p, uint32_t sel, uint32_t idx, uint32_t val)
{
    silk_mesh *m = &p->m;
    int k = (int)(sel % (A_NARRAYS + 8));
    if (k < A_NARRAYS) {
        if (!p->arr[k] || p->bytes[k] < 4) return;
        size_t words = p->bytes[k] / 4;
        uint32_t *w = p->arr[k];
        w[idx % words] = val;
        return;
    }
    switch (k - A_NARRAYS) {
    case 0: m->nverts = lower(m->nverts, val); break;
    case 1: m->ntris = lower(m->ntris, val); break;
    case 2: m->nnormals = lower(m->nnormals, val); break;
    case 3: m->nedges = lower(m->nedges, val); break;
    case 4: m->nuvs = lower(m->nuvs, val); break;
    case 5: m->nfeature_edges = lower(m->nfeature_edges, val); break;
    case 6: p->vis.nnodes = lower(p->vis.nnodes, val); p->vis.nnormals = lower(p->vis.nnormals, val); break;
    default: p->vis.scale_log2 = (int32_t)val; p->vis.centre.x = (silk_fx)(val * 2654435761u); break;
    }
}

static void draw(const silk_mesh *m, uint32_t view_bits)
{
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    silk_fx d = fuzz_aim(m, &cam);
    int oct = (int)(view_bits >> 3) & 7;
    cam.eye = silk_v3(silk_fx_add(cam.target.x, (oct & 1) ? d : -d / 2),
                      silk_fx_add(cam.target.y, (oct & 2) ? d / 3 : -d / 3),
                      silk_fx_add(cam.target.z, (oct & 4) ? d : -d));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.ortho = (view_bits >> 2) & 1;
    cam.fov_deg = SILK_FX_C(40, 1);
    cam.ortho_half_height = silk_fx_max(d / 2, SILK_FX_ONE);
    cam.znear = SILK_FX_C(1, 100);
    cam.zfar = silk_fx_mul(d, 4 * SILK_FX_ONE);
    cam.width = 24;
    cam.height = 20;
    silk_view view;
    silk_error err;
    if (silk_view_init(&view, &cam, &err) != SILK_OK) return;   /* the bbox of a corrupted mesh */

    size_t arena_size = 64 * (size_t)m->ntris * 100 + 65536;
    uint8_t *mem = malloc(arena_size);
    uint8_t *color = malloc(24 * 20 * 3);
    uint32_t *depth = malloc(24 * 20 * sizeof *depth);
    if (mem && color && depth) {
        silk_arena a;
        silk_arena_init(&a, mem, arena_size);
        silk_phong phong;
        silk_hal hal;
        silk_phong_default(&phong, &view);
        silk_hal_phong(&hal, &phong);
        silk_target t;
        silk_target_init(&t, 24, 20, 0, 20, SILK_PIX_RGB888, color, depth);
        silk_render_opts ro;
        silk_render_opts_default(&ro);
        ro.mode = (silk_mode)(view_bits & 3);
        ro.wire = 1;
        ro.lines = (silk_lines)((view_bits >> 6) % 3);
        ro.lines_polygonal = ro.mode == SILK_MODE_PN || ro.mode == SILK_MODE_BLEND;
        silk_status st = silk_render(&a, m, &view, &hal, &ro, &t, NULL, &err);
        if (st != SILK_OK) fuzz_check_error(st, &err, NULL);
        fuzz_expect(a.top == 0 && a.bottom == 0, "the frame kept memory");
    }
    free(mem);
    free(color);
    free(depth);
}

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_bytes in = { data, size, 0 };
    uint32_t nedits = fuzz_u8(&in) % 16;
    size_t head = 1 + 6 * (size_t)nedits + 1;
    if (size < head) return 0;
    static uint8_t mem[(size_t)4 << 20];     /* kept between runs */
    silk_arena a;
    silk_mesh src;
    silk_error err;
    silk_arena_init(&a, mem, sizeof mem);
    if (silk_load_mesh(data + head, size - head, PACK_NAME, NULL, &a, &src, &err) != SILK_OK ||
        silk_vis_build(&src, NULL, &a, &err) != SILK_OK)
        return 0;
    fuzz_expect(silk_mesh_validate(&src, PACK_NAME, &err) == SILK_OK, "silk's own mesh rejected: %s", err.msg);

    packed p;
    pack(&p, &src);                  /* from here on only the packed arrays are used */
    for (uint32_t i = 0; i < nedits; i++) {
        uint32_t sel = fuzz_u8(&in);
        uint32_t idx = fuzz_u8(&in);
        idx |= fuzz_u8(&in) << 8;
        uint32_t val = fuzz_u8(&in);
        val |= fuzz_u8(&in) << 8;
        val |= fuzz_u8(&in) << 16;
        /* small values are the interesting ones for indices; the top byte
         * repeats the third so that all-ones (SILK_NO_INDEX) is reachable */
        val |= (val & 0x800000u) ? 0xFF000000u : 0;
        apply_edit(&p, sel, idx, val);
    }
    uint32_t view_bits = fuzz_u8(&in);

    silk_status st = silk_mesh_validate(&p.m, PACK_NAME, &err);
    if (st != SILK_OK) fuzz_check_error(st, &err, PACK_NAME);
    else draw(&p.m, view_bits);
    unpack(&p);
    return 0;
}
