/*
 * silk/model.h - the prepared model file (`.silk`, made by `silk prepare`;
 * docs/formats.md has the byte layout).
 *
 * A versioned container of typed sections: a 32-byte header, a table of
 * sections (type, flags, offset, size, CRC-32 of the bytes), then the
 * sections.  Each section holds one representation of the model or data
 * that goes with one; a reader uses the sections it knows and skips the
 * others unless they are marked required.  The core reads a model from
 * memory (the caller holds the bytes), checks every byte it relies on, and
 * decodes what it needs into the arena: no heap, no floating point.
 */
#ifndef SILK_MODEL_H
#define SILK_MODEL_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "mesh.h"

#define SILK_MODEL_MAGIC "\x89silk\r\n\x1a"   /* 8 bytes */
#define SILK_MODEL_VERSION_MAJOR 1           /* a reader refuses a higher major version */
#define SILK_MODEL_VERSION_MINOR 0           /* added sections or fields a version-1 reader may skip */
#define SILK_MODEL_HEADER_BYTES 32
#define SILK_MODEL_ENTRY_BYTES 20
#define SILK_MODEL_MAX_SECTIONS 64

/* Section types: four ASCII bytes, read as a little-endian uint32. */
#define SILK_SECTION_TYPE(a, b, c, d) \
    ((uint32_t)(a) | (uint32_t)(b) << 8 | (uint32_t)(c) << 16 | (uint32_t)(d) << 24)
/* The coarse mesh for flat, smooth, pn and blend: vertices on the detailed
 * surface, the detailed surface's normals at them. */
#define SILK_SECTION_MESH SILK_SECTION_TYPE('M', 'E', 'S', 'H')
/* The outer hull for clip mode (the MESH layout): a coarse mesh that holds
 * the detailed one, with the detailed surface's normal at each vertex's
 * closest point there. */
#define SILK_SECTION_HULL SILK_SECTION_TYPE('H', 'U', 'L', 'L')
/* The silhouette map of the detailed model that goes with the hull. */
#define SILK_SECTION_SMAP SILK_SECTION_TYPE('S', 'M', 'A', 'P')
#define SILK_SMAP_VERSION 1        /* a reader refuses another map layout */
/* The silhouette texture of the detailed model that goes with the hull
 * (siltex mode, silk/siltex.h). */
#define SILK_SECTION_STEX SILK_SECTION_TYPE('S', 'T', 'E', 'X')

#define SILK_SECTION_REQUIRED 1u   /* flags bit 0: a reader that does not know the type must refuse the file */

typedef struct silk_model_section {
    uint32_t type, flags;
    const uint8_t *data;     /* inside the caller's buffer */
    uint32_t size;
} silk_model_section;

typedef struct silk_model {
    const uint8_t *base;
    size_t len;
    uint32_t version_major, version_minor, nsections;
} silk_model;

/* Whether the bytes start like a prepared model (the magic). */
int silk_is_model(const void *data, size_t len);

/* Check the header, the section table and every section's bounds and
 * CRC-32.  SILK_ERR_PARSE with "name: what is wrong" otherwise. */
silk_status silk_model_open(const void *data, size_t len, const char *name, silk_model *out, silk_error *err);

/* Section i (< nsections) of an opened model. */
void silk_model_section_at(const silk_model *m, uint32_t i, silk_model_section *out);
/* The first section of a type; 0 when there is none. */
int silk_model_find(const silk_model *m, uint32_t type, silk_model_section *out);

/* The model's MESH section as a silk_mesh, like silk_load_obj: positions
 * and triangles in the arena, the file's normals used unless opts->normals
 * is SILK_NORMALS_COMPUTE.  opts->scale must be 1 (the model was scaled
 * when it was prepared).  opts->part picks the representation: the coarse
 * mesh (MESH, or HULL when the file has no MESH) or the hull (HULL). */
silk_status silk_load_model(const void *data, size_t len, const char *name, const silk_load_opts *opts,
                            silk_arena *a, silk_mesh *out, silk_error *err);

/* The model's silhouette map (docs/formats.md "SMAP") as a silk_silmap
 * (silk/silmap.h) whose arrays point into the caller's bytes, so a
 * model in flash keeps its map there.  Every count, index and number the
 * interpolation relies on is checked.  The bytes must be 4-byte aligned
 * (the arrays are read in place) and the host little-endian.  SILK_OK,
 * or SILK_ERR_PARSE with the reason (also when there is no map). */
struct silk_silmap;
silk_status silk_model_silmap(const void *data, size_t len, const char *name, struct silk_silmap *out,
                              silk_error *err);

/* The model's silhouette texture (docs/formats.md "STEX") as a silk_siltex
 * (silk/siltex.h) pointing into the caller's bytes (any alignment), so a
 * model in flash keeps its texture there.  Checked: the version, flags and
 * counts, that the HULL section it goes with has its numbers of vertices
 * and triangles, the section's size to the byte, every C and T of unit
 * length with T across C, every atlas point inside the atlas.  SILK_OK, or
 * SILK_ERR_PARSE with the reason (also when there is no texture). */
struct silk_siltex;
silk_status silk_model_siltex(const void *data, size_t len, const char *name, struct silk_siltex *out,
                              silk_error *err);

/* CRC-32 (IEEE 802.3, as zlib and PNG): crc of the bytes, continuing from
 * crc (0 to start). */
uint32_t silk_crc32(uint32_t crc, const void *data, size_t len);

#endif
