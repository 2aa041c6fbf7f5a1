/*
 * model_file.c - laying out and writing a prepared model (model_file.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model_file.h"
#include "platform/platform.h"

static void wr32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}

int model_add(model_out *m, uint32_t type, uint32_t flags, const void *data, size_t size)
{
    if (m->n >= SILK_MODEL_MAX_SECTIONS || size > UINT32_MAX / 2) return -1;
    uint8_t *copy = malloc(size ? size : 1);
    if (!copy) return -1;
    if (size) memcpy(copy, data, size);
    m->sec[m->n].type = type;
    m->sec[m->n].flags = flags;
    m->sec[m->n].size = (uint32_t)size;
    m->sec[m->n].data = copy;
    m->n++;
    return 0;
}

int model_add_mesh(model_out *m, uint32_t nverts, const silk_vec3 *pos, uint32_t nnormals, const silk_vec3 *normal,
                   uint32_t ntris, const uint32_t *tri, const uint32_t *tri_normal)
{
    return model_add_mesh_as(m, SILK_SECTION_MESH, SILK_SECTION_REQUIRED, nverts, pos, nnormals, normal, ntris, tri,
                             tri_normal);
}

int model_add_mesh_as(model_out *m, uint32_t type, uint32_t flags, uint32_t nverts, const silk_vec3 *pos,
                      uint32_t nnormals, const silk_vec3 *normal, uint32_t ntris, const uint32_t *tri,
                      const uint32_t *tri_normal)
{
    size_t size = 16 + 12 * (size_t)nverts + 12 * (size_t)nnormals + 24 * (size_t)ntris;
    uint8_t *b = malloc(size), *p = b;
    if (!b) return -1;
    wr32(p, nverts), wr32(p + 4, ntris), wr32(p + 8, nnormals), wr32(p + 12, 0);
    p += 16;
    for (uint32_t i = 0; i < nverts; i++, p += 12)
        wr32(p, (uint32_t)pos[i].x), wr32(p + 4, (uint32_t)pos[i].y), wr32(p + 8, (uint32_t)pos[i].z);
    for (uint32_t i = 0; i < nnormals; i++, p += 12)
        wr32(p, (uint32_t)normal[i].x), wr32(p + 4, (uint32_t)normal[i].y), wr32(p + 8, (uint32_t)normal[i].z);
    for (size_t i = 0; i < 3 * (size_t)ntris; i++, p += 4) wr32(p, tri[i]);
    for (size_t i = 0; i < 3 * (size_t)ntris; i++, p += 4) wr32(p, tri_normal[i]);
    int rc = model_add(m, type, flags, b, size);
    free(b);
    return rc;
}

static silk_fx to_fx(double x) { return (silk_fx)llround(x * 65536.0); }

int model_add_mesh_doubles(model_out *m, uint32_t type, uint32_t flags, uint32_t nverts, const double *pos,
                           uint32_t nnormals, const double *normal, uint32_t ntris, const uint32_t *tri,
                           const uint32_t *tri_normal)
{
    silk_vec3 *p = malloc((nverts ? nverts : 1) * sizeof *p);
    silk_vec3 *n = malloc((nnormals ? nnormals : 1) * sizeof *n);
    int rc = -1;
    if (p && n) {
        /* Input vertices and hull vertices lie on the Q16.16 grid: exact. */
        for (uint32_t i = 0; i < nverts; i++) p[i] = silk_v3(to_fx(pos[3 * i]), to_fx(pos[3 * i + 1]), to_fx(pos[3 * i + 2]));
        for (uint32_t i = 0; i < nnormals; i++)
            n[i] = silk_v3(to_fx(normal[3 * i]), to_fx(normal[3 * i + 1]), to_fx(normal[3 * i + 2]));
        rc = model_add_mesh_as(m, type, flags, nverts, p, nnormals, n, ntris, tri, tri_normal ? tri_normal : tri);
    }
    free(p);
    free(n);
    return rc;
}

int model_add_silmap(model_out *m, const silk_silmap *map)
{
    const uint32_t nv = map->nviews, nt = map->ntris, nl = map->nloops, np = map->npts;
    size_t size = 36 + 72 * (size_t)nv + 24 * (size_t)nt + 4 * ((size_t)nl + 1) + 8 * (size_t)np;
    uint8_t *b = malloc(size), *p = b;
    if (!b) return -1;
    wr32(p, SILK_SMAP_VERSION), wr32(p + 4, nv), wr32(p + 8, nt), wr32(p + 12, nl), wr32(p + 16, np);
    wr32(p + 20, (uint32_t)map->centre.x), wr32(p + 24, (uint32_t)map->centre.y), wr32(p + 28, (uint32_t)map->centre.z);
    wr32(p + 32, 0);
    p += 36;
    for (uint32_t i = 0; i < nv; i++) {
        const silk_silmap_view *v = &map->views[i];
        const silk_vec3 *vec[4] = { &v->cam.eye, &v->cam.right, &v->cam.up, &v->cam.fwd };
        for (int k = 0; k < 4; k++, p += 12)
            wr32(p, (uint32_t)vec[k]->x), wr32(p + 4, (uint32_t)vec[k]->y), wr32(p + 8, (uint32_t)vec[k]->z);
        wr32(p, (uint32_t)v->cam.focal), wr32(p + 4, (uint32_t)v->cam.cx), wr32(p + 8, (uint32_t)v->cam.cy);
        wr32(p + 12, (uint32_t)v->cam.ortho), wr32(p + 16, v->first_loop), wr32(p + 20, v->nloops);
        p += 24;
    }
    for (size_t i = 0; i < 3 * (size_t)nt; i++, p += 4) wr32(p, map->tri[i]);
    for (size_t i = 0; i < 3 * (size_t)nt; i++, p += 4) wr32(p, map->adj[i]);
    for (size_t i = 0; i <= nl; i++, p += 4) wr32(p, map->loop_start[i]);
    for (size_t i = 0; i < np; i++, p += 8) wr32(p, (uint32_t)map->pts[i].x), wr32(p + 4, (uint32_t)map->pts[i].y);
    int rc = model_add(m, SILK_SECTION_SMAP, 0, b, size);
    free(b);
    return rc;
}

uint8_t *model_bytes(const model_out *m, size_t *len)
{
    size_t off = SILK_MODEL_HEADER_BYTES + (size_t)m->n * SILK_MODEL_ENTRY_BYTES;
    size_t total = off;
    for (uint32_t i = 0; i < m->n; i++) total += (m->sec[i].size + 3u) & ~(size_t)3;
    if (total > UINT32_MAX) return NULL;
    uint8_t *b = calloc(total, 1);
    if (!b) return NULL;
    memcpy(b, SILK_MODEL_MAGIC, 8);
    b[8] = SILK_MODEL_VERSION_MAJOR, b[10] = SILK_MODEL_VERSION_MINOR;
    wr32(b + 12, SILK_MODEL_HEADER_BYTES);
    wr32(b + 16, (uint32_t)total);
    wr32(b + 20, m->n);
    for (uint32_t i = 0; i < m->n; i++) {
        uint8_t *e = b + SILK_MODEL_HEADER_BYTES + (size_t)i * SILK_MODEL_ENTRY_BYTES;
        memcpy(b + off, m->sec[i].data, m->sec[i].size);
        wr32(e, m->sec[i].type), wr32(e + 4, m->sec[i].flags), wr32(e + 8, (uint32_t)off);
        wr32(e + 12, m->sec[i].size), wr32(e + 16, silk_crc32(0, b + off, m->sec[i].size));
        off += (m->sec[i].size + 3u) & ~(size_t)3;
    }
    wr32(b + 24, silk_crc32(0, b + SILK_MODEL_HEADER_BYTES, (size_t)m->n * SILK_MODEL_ENTRY_BYTES));
    *len = total;
    return b;
}

silk_status model_write(const model_out *m, const char *path, silk_error *err)
{
    size_t len;
    uint8_t *b = model_bytes(m, &len);
    if (!b) return silk_fail(err, SILK_ERR_NOMEM, path, 0, "out of memory");
    silk_outfile o;
    silk_status st = silk_outfile_open(&o, path, err);
    if (st == SILK_OK) {
        if (fwrite(b, 1, len, o.fp) != len) {
            silk_outfile_abort(&o);
            st = silk_fail(err, SILK_ERR_IO, path, 0, "write failed");
        } else {
            st = silk_outfile_commit(&o, err);
        }
    }
    free(b);
    return st;
}

void model_free(model_out *m)
{
    for (uint32_t i = 0; i < m->n; i++) free(m->sec[i].data);
    memset(m, 0, sizeof *m);
}
