/*
 * model_file.h - writing prepared models (silk/model.h, docs/formats.md):
 * sections are added one by one, then the container - header, section
 * table with each section's CRC-32, the sections 4-byte aligned - is laid
 * out in memory and written atomically.  Host-side.
 */
#ifndef SILK_TOOLS_MODEL_FILE_H
#define SILK_TOOLS_MODEL_FILE_H

#include <stddef.h>
#include <stdint.h>
#include "silk/silk.h"
#include "src/silmap_interp.h"

typedef struct model_out {
    uint32_t n;
    struct { uint32_t type, flags, size; uint8_t *data; } sec[SILK_MODEL_MAX_SECTIONS];
} model_out;

/* A section of the given bytes (copied).  0, or -1 when out of memory or
 * the table is full. */
int model_add(model_out *m, uint32_t type, uint32_t flags, const void *data, size_t size);

/* A MESH section: Q16.16 positions and unit normals, triangles and the
 * normal of each corner.  0 or -1. */
int model_add_mesh(model_out *m, uint32_t nverts, const silk_vec3 *pos, uint32_t nnormals, const silk_vec3 *normal,
                   uint32_t ntris, const uint32_t *tri, const uint32_t *tri_normal);

/* The same layout as another section type (HULL). */
int model_add_mesh_as(model_out *m, uint32_t type, uint32_t flags, uint32_t nverts, const silk_vec3 *pos,
                      uint32_t nnormals, const silk_vec3 *normal, uint32_t ntris, const uint32_t *tri,
                      const uint32_t *tri_normal);

/* The same from doubles (rounded to Q16.16); tri_normal NULL: one normal
 * per vertex. */
int model_add_mesh_doubles(model_out *m, uint32_t type, uint32_t flags, uint32_t nverts, const double *pos,
                           uint32_t nnormals, const double *normal, uint32_t ntris, const uint32_t *tri,
                           const uint32_t *tri_normal);

/* An SMAP section: the silhouette map in the layout silk_model_silmap
 * reads.  0 or -1. */
int model_add_silmap(model_out *m, const silk_silmap *map);

/* The whole file in one malloc'd buffer; NULL when out of memory. */
uint8_t *model_bytes(const model_out *m, size_t *len);

/* Write the file atomically (temporary file, then rename).  SILK_OK or an
 * I/O error in err. */
silk_status model_write(const model_out *m, const char *path, silk_error *err);

void model_free(model_out *m);

#endif
