/*
 * surface.c - the detailed surface's normals at the vertices of an
 * on-surface coarse mesh (surface.h): angle-weighted fine face normals
 * around each coarse vertex's point (paper section III-B's weighting),
 * split along the coarse mesh's feature edges.
 */
#include <stdlib.h>
#include <string.h>

#include "surface.h"
#include "vec3.h"

void surf_normals_free(surf_normals *n)
{
    free(n->normal);
    free(n->tri_normal);
    memset(n, 0, sizeof *n);
}

/* Unit normal of triangle t of m; 0 for a degenerate one. */
static int face_unit(const simp_mesh *m, uint32_t t, double n[3])
{
    const uint32_t *v = &m->tri[3 * t];
    tri_normal(&m->pos[3 * v[0]], &m->pos[3 * v[1]], &m->pos[3 * v[2]], n);
    double l = len3(n);
    if (!(l > 0)) return 0;
    n[0] /= l, n[1] /= l, n[2] /= l;
    return 1;
}

/* The angle of triangle t of m at its corner k. */
static double corner_angle(const simp_mesh *m, uint32_t t, int k)
{
    const double *p = &m->pos[3 * m->tri[3 * t + k]], *a = &m->pos[3 * m->tri[3 * t + (k + 1) % 3]],
                 *b = &m->pos[3 * m->tri[3 * t + (k + 2) % 3]];
    double e1[3], e2[3], c[3];
    sub3(a, p, e1);
    sub3(b, p, e2);
    cross3(e1, e2, c);
    return atan2(len3(c), dot3(e1, e2));
}

static uint32_t group_root(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

typedef struct side { uint32_t a, b, corner; } side;   /* a < b; corner: 3 * face + k of the edge's start */

static int side_cmp(const void *x, const void *y)
{
    const side *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return 0;
}

/* The corner of face f at vertex v. */
static uint32_t corner_of(const simp_mesh *m, uint32_t f, uint32_t v)
{
    for (uint32_t k = 0; k < 3; k++)
        if (m->tri[3 * f + k] == v) return 3 * f + k;
    return 3 * f;
}

/* The crease groups of the fine faces around fine vertex f (at most
 * SURF_MAX_FAN of them, the rest left in their own group): faces joined
 * across an edge at f whose dihedral angle stays below the crease angle.
 * grp[i] names the group of face vface[start + i]; dir[3 * g] sums the
 * angle-weighted unit normals of group g.  Returns the number of faces. */
#define SURF_MAX_FAN 64
static uint32_t fine_groups(const simp_mesh *fine, const uint32_t *vstart, const uint32_t *vface, uint32_t f,
                            double cos_crease, uint32_t grp[SURF_MAX_FAN], double dir[3 * SURF_MAX_FAN])
{
    uint32_t n = vstart[f + 1] - vstart[f];
    if (n > SURF_MAX_FAN) n = SURF_MAX_FAN;
    double nrm[3 * SURF_MAX_FAN];
    int ok[SURF_MAX_FAN];
    for (uint32_t i = 0; i < n; i++) {
        grp[i] = i;
        ok[i] = face_unit(fine, vface[vstart[f] + i] / 3, &nrm[3 * i]);
    }
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            if (!ok[i] || !ok[j] || dot3(&nrm[3 * i], &nrm[3 * j]) < cos_crease) continue;
            const uint32_t *p = &fine->tri[vface[vstart[f] + i] / 3 * 3], *q = &fine->tri[vface[vstart[f] + j] / 3 * 3];
            int shared = 0;   /* a second vertex in both: the faces meet along an edge at f */
            for (int x = 0; x < 3; x++)
                for (int y = 0; y < 3; y++) shared |= p[x] != f && p[x] == q[y];
            if (!shared) continue;
            uint32_t ri = group_root(grp, i), rj = group_root(grp, j);
            if (ri != rj) grp[ri > rj ? ri : rj] = ri < rj ? ri : rj;
        }
    for (uint32_t i = 0; i < 3 * n; i++) dir[i] = 0;
    for (uint32_t i = 0; i < n; i++) {
        grp[i] = group_root(grp, i);
        if (!ok[i]) continue;
        uint32_t fc = vface[vstart[f] + i];
        double w = corner_angle(fine, fc / 3, (int)(fc % 3));
        for (int k = 0; k < 3; k++) dir[3 * grp[i] + k] += w * nrm[3 * i + k];
    }
    return n;
}

/* For every coarse corner, the fine crease group at its vertex that its
 * face faces most nearly (the index of that group's root face). */
static void corner_fine_groups(const simp_mesh *fine, const simp_mesh *c, const double *fn, const uint32_t *vstart,
                               const uint32_t *vface, const uint32_t *cstart, const uint32_t *vcorner,
                               double cos_crease, uint32_t *cgrp)
{
    uint32_t grp[SURF_MAX_FAN];
    double dir[3 * SURF_MAX_FAN];
    for (uint32_t v = 0; v < c->nverts; v++) {
        uint32_t n = fine_groups(fine, vstart, vface, c->origin[v], cos_crease, grp, dir);
        for (uint32_t i = cstart[v]; i < cstart[v + 1]; i++) {
            uint32_t corner = vcorner[i], best_g = 0;
            double best = -INFINITY;
            for (uint32_t g = 0; g < n; g++) {
                if (grp[g] != g) continue;
                double l = len3(&dir[3 * g]);
                double d = l > 0 ? dot3(&dir[3 * g], &fn[3 * (corner / 3)]) / l : -2;
                if (d > best) best = d, best_g = g;
            }
            cgrp[corner] = best_g;
        }
    }
}

/* Corners of the coarse mesh joined across every edge with exactly two
 * faces, unless the detailed surface has a crease along it: at both of
 * its ends the two faces fall into different fine crease groups. */
static int group_corners(const simp_mesh *c, const uint32_t *cgrp, uint32_t *parent)
{
    size_t nc = 3 * (size_t)c->ntris;
    side *h = malloc((nc ? nc : 1) * sizeof *h);
    if (!h) return -1;
    for (uint32_t i = 0; i < nc; i++) {
        parent[i] = i;
        uint32_t a = c->tri[i], b = c->tri[i - i % 3 + (i + 1) % 3];
        h[i] = (side){ a < b ? a : b, a < b ? b : a, i };
    }
    qsort(h, nc, sizeof *h, side_cmp);
    for (size_t i = 0; i < nc;) {
        size_t j = i;
        while (j < nc && h[j].a == h[i].a && h[j].b == h[i].b) j++;
        if (j - i == 2) {
            uint32_t f0 = h[i].corner / 3, f1 = h[i + 1].corner / 3;
            uint32_t a0 = corner_of(c, f0, h[i].a), a1 = corner_of(c, f1, h[i].a);
            uint32_t b0 = corner_of(c, f0, h[i].b), b1 = corner_of(c, f1, h[i].b);
            int crease = cgrp[a0] != cgrp[a1] && cgrp[b0] != cgrp[b1];
            if (!crease)
                for (int end = 0; end < 2; end++) {
                    uint32_t r0 = group_root(parent, end ? b0 : a0), r1 = group_root(parent, end ? b1 : a1);
                    if (r0 != r1) parent[r0 < r1 ? r1 : r0] = r0 < r1 ? r0 : r1;
                }
        }
        i = j;
    }
    free(h);
    return 0;
}

int surf_normals_compute(const simp_mesh *fine, const simp_mesh *coarse, double crease_deg, surf_normals *out)
{
    memset(out, 0, sizeof *out);
    size_t nc = 3 * (size_t)coarse->ntris, nfv = fine->nverts;
    double *fn = malloc((coarse->ntris ? coarse->ntris : 1) * 3 * sizeof *fn);
    double *gsum = calloc((nc ? nc : 1) * 3, sizeof *gsum);   /* per root corner: coarse, then fine sums */
    double *fsum = calloc((nc ? nc : 1) * 3, sizeof *fsum);
    uint32_t *parent = malloc((nc ? nc : 1) * sizeof *parent);
    uint32_t *vstart = calloc(nfv + 1, sizeof *vstart), *vface = malloc((3 * (size_t)fine->ntris + 1) * sizeof *vface);
    uint32_t *cstart = calloc((size_t)coarse->nverts + 1, sizeof *cstart);
    uint32_t *vcorner = calloc(nc ? nc : 1, sizeof *vcorner);
    uint32_t *gindex = malloc((nc ? nc : 1) * sizeof *gindex), *cgrp = malloc((nc ? nc : 1) * sizeof *cgrp);
    out->tri_normal = malloc((nc ? nc : 1) * sizeof *out->tri_normal);
    out->normal = malloc((nc ? nc : 1) * 3 * sizeof *out->normal);
    int rc = -1;
    if (!fn || !gsum || !fsum || !parent || !vstart || !vface || !cstart || !vcorner || !gindex || !cgrp || !out->tri_normal ||
        !out->normal)
        goto done;

    for (uint32_t t = 0; t < coarse->ntris; t++)
        if (!face_unit(coarse, t, &fn[3 * t])) fn[3 * t] = fn[3 * t + 1] = fn[3 * t + 2] = 0;
    double cos_crease = crease_deg >= 180 ? -2 : cos(crease_deg * 3.14159265358979323846 / 180);

    /* fine vertex -> faces, and coarse vertex -> corners (CSR) */
    for (size_t i = 0; i < 3 * (size_t)fine->ntris; i++) vstart[fine->tri[i] + 1]++;
    for (size_t v = 0; v < nfv; v++) vstart[v + 1] += vstart[v];
    for (size_t i = 0; i < 3 * (size_t)fine->ntris; i++) vface[vstart[fine->tri[i]]++] = (uint32_t)i;
    for (size_t v = nfv; v > 0; v--) vstart[v] = vstart[v - 1];
    vstart[0] = 0;
    for (size_t i = 0; i < nc; i++) cstart[coarse->tri[i] + 1]++;
    for (uint32_t v = 0; v < coarse->nverts; v++) cstart[v + 1] += cstart[v];
    for (size_t i = 0; i < nc; i++) vcorner[cstart[coarse->tri[i]]++] = (uint32_t)i;
    for (uint32_t v = coarse->nverts; v > 0; v--) cstart[v] = cstart[v - 1];
    cstart[0] = 0;
    corner_fine_groups(fine, coarse, fn, vstart, vface, cstart, vcorner, cos_crease, cgrp);
    if (group_corners(coarse, cgrp, parent)) goto done;

    /* Each group's coarse direction: its faces' normals, angle-weighted. */
    for (size_t i = 0; i < nc; i++) {
        uint32_t r = group_root(parent, (uint32_t)i);
        double w = corner_angle(coarse, (uint32_t)(i / 3), (int)(i % 3));
        for (int k = 0; k < 3; k++) gsum[3 * r + k] += w * fn[3 * (i / 3) + k];
    }

    uint32_t ng = 0;
    for (uint32_t v = 0; v < coarse->nverts; v++) {
        uint32_t f = coarse->origin[v];
        /* Every fine face around the point goes to the group it faces most. */
        for (uint32_t j = vstart[f]; j < vstart[f + 1]; j++) {
            uint32_t fc = vface[j], ft = fc / 3;
            double n[3];
            if (!face_unit(fine, ft, n)) continue;
            double w = corner_angle(fine, ft, (int)(fc % 3)), best = -INFINITY;
            uint32_t to = UINT32_MAX;
            for (uint32_t i = cstart[v]; i < cstart[v + 1]; i++) {
                uint32_t r = group_root(parent, vcorner[i]);
                double d = dot3(n, &gsum[3 * r]) / (len3(&gsum[3 * r]) + 1e-300);
                if (d > best) best = d, to = r;
            }
            if (to != UINT32_MAX)
                for (int k = 0; k < 3; k++) fsum[3 * to + k] += w * n[k];
        }
        /* One normal per group, numbered in corner order. */
        for (uint32_t i = cstart[v]; i < cstart[v + 1]; i++) gindex[group_root(parent, vcorner[i])] = UINT32_MAX;
        for (uint32_t i = cstart[v]; i < cstart[v + 1]; i++) {
            uint32_t c = vcorner[i], r = group_root(parent, c);
            if (gindex[r] == UINT32_MAX) {
                const double *s = len3(&fsum[3 * r]) > 0 ? &fsum[3 * r] : &gsum[3 * r];
                double l = len3(s);
                double *o = &out->normal[3 * ng];
                if (l > 0) o[0] = s[0] / l, o[1] = s[1] / l, o[2] = s[2] / l;
                else o[0] = 0, o[1] = 0, o[2] = 1;
                gindex[r] = ng++;
            }
            out->tri_normal[c] = gindex[r];
        }
    }
    out->nnormals = ng;
    rc = 0;
done:
    free(fn), free(gsum), free(fsum), free(parent), free(vstart), free(vface), free(cstart), free(vcorner), free(gindex), free(cgrp);
    if (rc) surf_normals_free(out);
    return rc;
}
