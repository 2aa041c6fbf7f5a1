/*
 * visibility.c - which shading normals face the viewer (paper III-B).
 *
 * A normal N at vertex V is visible when N.(E - V) >= 0 (perspective) or
 * N.D >= 0 with D = -forward (parallel).  This file holds the brute pass, one
 * exact 64-bit dot product per normal, which is the reference every faster
 * method must reproduce bit for bit, and the choice between it and the
 * Gaussian-sphere hierarchy of gauss.c (SILK_VIS_AUTO: by mesh size, with
 * the break-even measured by `silk bench --visibility`).
 */
#include <string.h>
#include "silk/visibility.h"

/* E - V is formed in 64 bits, not with the saturating silk_v3_sub, so an eye
 * far outside the model cannot clamp the difference and flip a sign.  With
 * |N| <= 1 (|components| <= 2^16) and |E - V| < 2^32 per component the sum
 * stays below 2^50: exact. */
static int64_t persp_dot64(silk_vec3 n, silk_vec3 p, silk_vec3 e)
{
    return (int64_t)n.x * ((int64_t)e.x - p.x)
         + (int64_t)n.y * ((int64_t)e.y - p.y)
         + (int64_t)n.z * ((int64_t)e.z - p.z);
}

int silk_normal_visible(const silk_mesh *m, const silk_view *v, uint32_t i)
{
    silk_vec3 n = silk_mesh_normal(m, i);
    if (v->cam.ortho)
        return silk_v3_dot64(n, v->forward) <= 0;   /* N.(-F) >= 0, negation exact */
    return persp_dot64(n, silk_mesh_pos(m, silk_mesh_normal_vertex(m, i)), v->cam.eye) >= 0;
}

void silk_visibility_brute(const silk_mesh *m, const silk_view *v, uint8_t *visible)
{
    uint32_t n = m->nnormals;
    if (m->packed.base) {
        /* a compact model decodes each normal and its vertex's position */
        for (uint32_t i = 0; i < n; i++) {
            silk_vec3 nv = silk_mesh_normal(m, i);
            visible[i] = (uint8_t)(v->cam.ortho ? silk_v3_dot64(nv, v->forward) <= 0
                                                : persp_dot64(nv, silk_mesh_pos(m, silk_mesh_normal_vertex(m, i)), v->cam.eye) >= 0);
        }
        return;
    }
    const silk_vec3 *nrm = m->normal;
    if (v->cam.ortho) {
        silk_vec3 f = v->forward;
        for (uint32_t i = 0; i < n; i++)
            visible[i] = (uint8_t)(silk_v3_dot64(nrm[i], f) <= 0);
    } else {
        silk_vec3 e = v->cam.eye;
        const silk_vec3 *pos = m->pos;
        const silk_index *nv = m->normal_vertex;
        for (uint32_t i = 0; i < n; i++)
            visible[i] = (uint8_t)(persp_dot64(nrm[i], pos[nv[i]], e) >= 0);
    }
}

silk_status silk_visibility(const silk_mesh *m, const silk_view *v, silk_vis_method method,
                            uint8_t *visible, silk_arena *a, silk_vis_stats *stats)
{
    (void)a;   /* neither pass needs scratch */
    if (m == NULL || v == NULL || (visible == NULL && m->nnormals > 0)) return SILK_ERR_ARG;
    int have = m->vis != NULL && m->vis->nnormals == m->nnormals;
    if (method == SILK_VIS_AUTO) {
        /* below the measured break-even the tree walk costs more than it saves */
        uint32_t threshold = v->cam.ortho ? SILK_VIS_AUTO_PARALLEL : SILK_VIS_AUTO_PERSPECTIVE;
        method = have && m->nnormals >= threshold ? SILK_VIS_GAUSS : SILK_VIS_BRUTE;
    }
    if (method == SILK_VIS_GAUSS) {
        if (!have) return SILK_ERR_ARG;
        return silk_visibility_gauss(m, v, visible, stats);
    }
    if (method != SILK_VIS_BRUTE) return SILK_ERR_ARG;
    silk_visibility_brute(m, v, visible);
    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->normals = m->nnormals;
        stats->one_by_one = m->nnormals;
    }
    return SILK_OK;
}
