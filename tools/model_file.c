/*
 * model_file.c - laying out and writing a prepared model (model_file.h).
 */
#include <stdlib.h>
#include <string.h>

#include "model_file.h"
#include "../platform/platform.h"

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
    int rc = model_add(m, SILK_SECTION_MESH, SILK_SECTION_REQUIRED, b, size);
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
