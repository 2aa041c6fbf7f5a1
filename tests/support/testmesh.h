/*
 * testmesh.h - test support: meshes into the library for the tests.  Whole
 * files read into memory, the shared reference meshes (check_meshes_dir())
 * loaded with silk_load_obj, and a "fixture": an arena with a
 * silk_mesh_input filled from double coordinates (or from the `v` and `f`
 * lines of an OBJ text) for silk_mesh_build.  The calls that find the
 * shared meshes need check.h included first (the tests).
 */
#ifndef SILK_TESTMESH_H
#define SILK_TESTMESH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "silk/silk.h"

/* The rest of the stream, NUL-terminated, in a heap block of exactly
 * *len + 1 bytes (so that ASan sees a read past the data); NULL on error. */
char *tm_read_stream(FILE *fp, size_t *len);
/* tm_read_stream of a whole file; NULL when it cannot be opened or read. */
char *tm_read_file(const char *path, size_t *len);

/* silk_load_obj of DIR/NAME (default load options) into the arena.
 * Returns 1, or 0 after printing why to stderr. */
int tm_load_obj_in(silk_arena *a, const char *dir, const char *name, silk_mesh *m);
#ifdef SILK_CHECK_H
static inline int tm_load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    return tm_load_obj_in(a, check_meshes_dir(), name, m);
}
#endif

/* ---- fixture: silk_mesh_build from doubles ----------------------------------- */

typedef struct tm_fixture {
    void *buf;            /* the arena's memory, on the heap */
    size_t bytes;
    silk_arena a;
    silk_mesh_input in;
    silk_load_opts opts;  /* defaults; tests change them before building */
    silk_mesh m;
    silk_error err;
} tm_fixture;

void tm_fixture_init(tm_fixture *f, size_t bytes);
/* An empty arena, input and mesh again (the options stay). */
void tm_fixture_reset(tm_fixture *f);
void tm_fixture_free(tm_fixture *f);
/* Positions (x y z per vertex) and 0-based corners into the arena, as a
 * loader would put them.  Returns 0 when the arena is too small. */
int tm_fixture_input(tm_fixture *f, const double *pos, uint32_t nv, const uint32_t *tri, uint32_t nt);
silk_status tm_fixture_build(tm_fixture *f);
/* The `v x y z` and `f i j k` lines of an OBJ text (all the shared meshes
 * have, SOURCES.md) as the input.  Returns 0 without vertices or
 * triangles. */
int tm_fixture_parse_obj(char *text, tm_fixture *f);
int tm_fixture_read_obj(tm_fixture *f, const char *path);
#ifdef SILK_CHECK_H
/* NAME.obj of the shared meshes. */
static inline int tm_fixture_read_shared(tm_fixture *f, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.obj", check_meshes_dir(), name);
    return tm_fixture_read_obj(f, path);
}
#endif

/* The mesh at path as silk_load_mesh reads it (any format, default load
 * options), positions widened to double: malloc'd arrays of 3 * *nv
 * coordinates and 3 * *nt corners.  1; 0 when there is no such file (after
 * printing a "skip:" line: the shared meshes may be absent); -1 when it
 * does not load (after printing why). */
int tm_load_doubles(const char *path, double **pos, uint32_t *nv, uint32_t **tri, uint32_t *nt);

#endif
