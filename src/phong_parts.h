/*
 * phong_parts.h - internal: the default stages (phong.c) in parts, for the
 * renderer's shortcuts (frame_fast.c, frame_cull.c) and the rasterizer's
 * usual case (raster.c).  Not installed.
 */
#ifndef SILK_PHONG_PARTS_H
#define SILK_PHONG_PARTS_H

#include "silk/silk.h"

/* phong.c: whether h's vertex stage is the default one, which reads a
 * record only through silk_vrec_eval: then two CORNER records of the same
 * vertex, normal and uv give the same bits, and the renderer may evaluate
 * them once (frame_fast.c's vertex cache).  A stage of the caller's own may
 * read anything in the record, so it is never assumed to. */
int silk_hal_vertex_by_attrs(const silk_hal *h);
/* phong.c, with silk_hal_vertex_by_attrs (frame_fast.c's SILK_DRAW_DIRECT):
 * the default vertex stage in two parts, the same bits - the clip
 * coordinates it gives a vertex at position pos (a CORNER record's), and
 * its output for record r but the clip coordinates (left as they are). */
silk_vec4 silk_hal_vertex_clip(const silk_hal *h, silk_vec3 pos);
void silk_hal_vertex_varyings(const silk_geom *g, const silk_vrec *r, silk_vertex_out *out);
/* phong.c (the rasterizer's SILK_PHONG_PLAIN): p when h is the default
 * stages (silk_hal_phong) of p in their usual case - a perspective camera,
 * two directional lights, no texture or vertex colours, SILK_PHONG_PLAIN_NVAR
 * varyings and every material term below 16 - else NULL; then
 * silk_phong_plain_fragment(p, var) is h->fragment(h, var), the same bits,
 * with the tests that case settles made once (the rasterizer asks per
 * triangle) rather than per pixel.  It never discards. */
#define SILK_PHONG_PLAIN_NVAR 6
const silk_phong *silk_hal_phong_plain(const silk_hal *h);
uint32_t silk_phong_plain_fragment(const silk_phong *p, const silk_fx *var);
/* phong.c: the view the default vertex stage projects with, or NULL (a
 * stage of the caller's own, or none). */
const silk_view *silk_hal_vertex_view(const silk_hal *h);

#endif
