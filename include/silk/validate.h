/*
 * silk/validate.h - checking a mesh that silk did not load itself.
 *
 * The loaders build a silk_mesh whose arrays agree with each other, and the
 * per-frame stages rely on that: they index one array with the contents of
 * another.  A mesh that arrives from elsewhere - the const arrays of a
 * `silk pack` header in flash, a buffer received over a link, a struct
 * filled by hand - has had no such guarantee, so a device can run this once
 * before its first frame.  It reads every array once (no arena, no
 * scratch) and accepts exactly the meshes the renderer can draw without
 * reading or writing outside an array.
 */
#ifndef SILK_VALIDATE_H
#define SILK_VALIDATE_H

#include "error.h"
#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SILK_OK, or SILK_ERR_PARSE with "name: what is inconsistent" (name may
 * be NULL: "mesh").  What is checked:
 *  - counts are nonzero where the mesh needs them, fit silk_index below
 *    SILK_NO_INDEX, and every array they size is present;
 *  - positions within +-SILK_COORD_MAX; shading normals of unit length
 *    (within 1/64);
 *  - every index in range: triangle corners, corner normals (and the
 *    normal's vertex is the corner's vertex), corner uvs, corner edges;
 *  - every triangle side's edge joins that side's two vertices, and every
 *    edge's triangles use it;
 *  - the vertex->edge lists: start[0] == 0, non-decreasing, each listed
 *    edge has that vertex at an end, and as many entries as edge ends;
 *  - feature links in range;
 *  - the visibility hierarchy, if any: node ranges nested and in order,
 *    each subtree's end after its node, its scale within range.
 * Not checked: whether normals and features are what silk would have
 * computed (a wrong one draws a wrong picture, never outside memory). */
silk_status silk_mesh_validate(const silk_mesh *m, const char *name, silk_error *err);

#ifdef __cplusplus
}
#endif

#endif
