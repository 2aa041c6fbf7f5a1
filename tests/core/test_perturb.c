/*
 * test_perturb.c - vertex perturbation (paper III-E, Fig. 15) against a
 * double-precision reference: which segments are concave, which vertices
 * move, by how much and in which direction, that moved vertices end up below
 * the planes P_i, and that every corner at a moved vertex moves with it.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "src/perturb.h"
#include "src/remesh.h"
#include "support/testframe.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (32u << 20)
static unsigned char *arena_buf;

static int load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, ARENA_BYTES);
    return tm_load_shared(a, name, m);
}

/* Is v a neighbouring vertex of triangle t (a corner, or one edge from one)? */
static int is_near(const silk_mesh *m, uint32_t t, uint32_t v)
{
    for (int c = 0; c < 3; c++) {
        uint32_t x = m->tri[3 * t + c];
        if (x == v) return 1;
        for (uint32_t i = m->vert_edge_start[x]; i < m->vert_edge_start[x + 1]; i++) {
            const silk_edge *e = &m->edge[m->vert_edge[i]];
            if (e->v[0] == v || e->v[1] == v) return 1;
        }
    }
    return 0;
}

typedef struct pstats {
    uint32_t views, concave, moved, ref_moved;
    uint32_t wrong_concave, wrong_moved, not_below, wrong_records, pinned, flat;
    double worst_off;        /* |offset - reference| in ulps beyond 1e-3 relative, worst */
    double worst_above;      /* how far above a plane that constrains it a moved vertex stays */
} pstats;

/* Where V lies against segment s on screen, as perturb.c decides it: the
 * points projected by silk_view_project and taken to an eighth of a pixel
 * (the rule is the core's, its arithmetic exact in 64 bits here):
 * in_slab, its projection onto the chord A B within it or a quarter of it
 * past either end; stands_out, further from the chord on the side away
 * from the segment's middle M than twice M's distance; unsure, not on the
 * screen within the core's range (then the core says neither). */
static void place(const silk_view *v, const silk_sil_seg *s, silk_vec3 V, int *in_slab, int *stands_out, int *unsure)
{
    const silk_vec3 pts[4] = { s->c.p0, s->c.p1, V, s->m };
    int64_t x[4], y[4];
    *in_slab = *stands_out = *unsure = 0;
    for (int i = 0; i < 4; i++) {
        silk_vec2 q;
        if (!silk_view_project(v, pts[i], &q)) {
            *unsure = 1;
            return;
        }
        x[i] = (int64_t)(q.x >> 13) - (i ? x[0] : 0);
        y[i] = (int64_t)(q.y >> 13) - (i ? y[0] : 0);
        if (i && (llabs(x[i]) >= 8192 || llabs(y[i]) >= 8192)) return;   /* the core: not beside */
    }
    int64_t d = x[1] * x[2] + y[1] * y[2], l = (x[1] * x[1] + y[1] * y[1]) / 4;
    int64_t cq = x[1] * y[2] - y[1] * x[2], cm = x[1] * y[3] - y[1] * x[3];
    int64_t out = cm >= 0 ? -cq : cq, lim = 2 * (cm >= 0 ? cm : -cm);
    *in_slab = d >= -l && d <= 5 * l;
    *stands_out = out > lim;
}

static double beside(const silk_view *v, const silk_sil_seg *s, silk_vec3 V)
{
    int in, out, unsure;
    place(v, s, V, &in, &out, &unsure);
    return in && !out;
}

/* One view: recompute concavity and perturbation in double from the
 * segments' end data and compare. */
static void check_view(const silk_mesh *m, const silk_view *view, const silk_sil_frame *f, const silk_frame_geom *g,
                       uint32_t flat, pstats *ps)
{
    silk_sil_seg *segs = tf_segs(f);
    ps->views++;
    uint32_t ref_moved = 0;
    for (uint32_t i = 0; i < f->nsegs; i++) {
        const silk_sil_seg *s = &segs[i];
        double a[3], b[3], na[3], nb[3], F[3];
        vec3d(s->c.p0, a); vec3d(s->c.p1, b); vec3d(s->c.n0, na); vec3d(s->c.n1, nb);
        for (int k = 0; k < 3; k++) F[k] = b[k] - a[k];
        int concave = dot3(na, F) > 0 && dot3(nb, F) < 0;
        /* the exact 64-bit signs and the double ones agree except for |dot| ~ 0 */
        if (concave != s->concave && fabs(dot3(na, F)) > 1e-9 && fabs(dot3(nb, F)) > 1e-9) ps->wrong_concave++;
        ps->concave += s->concave;
    }
    for (uint32_t v = 0; v < m->nverts; v++) {
        double R[3] = { 0, 0, 0 }, V[3];
        vec3d(m->pos[v], V);
        int any = 0;
        for (uint32_t i = 0; i < f->nsegs; i++) {
            const silk_sil_seg *s = &segs[i];
            if (!s->concave || !is_near(m, s->tri, v)) continue;
            double n[3];
            vec3d(s->nm, n);
            for (int k = 0; k < 3; k++) R[k] += n[k];
            any = 1;
        }
        double lift = 0;
        int unsure = 0;
        if (any) {
            double rl = sqrt(dot3(R, R));
            for (int k = 0; k < 3; k++) R[k] /= rl;
            for (uint32_t i = 0; i < f->nsegs; i++) {
                const silk_sil_seg *s = &segs[i];
                if (!s->concave || !is_near(m, s->tri, v)) continue;
                double n[3], M[3], vm[3];
                vec3d(s->nm, n);
                vec3d(s->m, M);
                for (int k = 0; k < 3; k++) vm[k] = V[k] - M[k];
                double den = dot3(R, n), num = dot3(vm, n), by = beside(view, s, m->pos[v]);
                if (den < 0.25 || num <= 0 || by == 0) continue;
                double l = num / den, rise = fx2d(s->rise);
                /* more than the segment's rise: not lowered for this plane */
                if (fabs(l - rise) < 4.0 / 65536 || by == 0.5) unsure = 1;
                if (l > rise) continue;
                if (l > lift) lift = l;
            }
        }
        /* a vertex with a point of its edges' chains exactly on it stays put */
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) {
            uint32_t e = m->vert_edge[i], w = silk_sil_slot(f, e);
            if (w == SILK_SIL_NONE || !f->edges[w].nchain) continue;
            const silk_sil_edge *we = &f->edges[w];
            silk_fx t = m->edge[e].v[0] == v ? f->chain[we->chain0] : f->chain[we->chain0 + we->nchain - 1];
            silk_curve wc;
            silk_sil_edge_curve(f, we, &wc);
            silk_vec3 q = silk_hermite_point(&wc, t);
            if (q.x == m->pos[v].x && q.y == m->pos[v].y && q.z == m->pos[v].z) {
                lift = 0;
                ps->pinned++;
            }
        }
        uint32_t sl = f->vert_offset ? f->vert_offset[v] : SILK_PLAN_NONE;
        int moved = sl != SILK_PLAN_NONE;
        int ref = lift > 2.0 / 65536;          /* below that, rounding decides */
        ref_moved += ref && !unsure;
        if (moved != ref && lift > 4.0 / 65536 && !unsure) ps->wrong_moved++;
        if (!moved) continue;
        ps->moved++;
        double off[3];
        vec3d(g->offset[sl], off);
        double err = 0;
        for (int k = 0; k < 3; k++) err += (off[k] + lift * R[k]) * (off[k] + lift * R[k]);
        /* in ulps, beyond the relative error the Q16.16 inputs allow */
        err = (sqrt(err) - 1e-3 * lift) * 65536;
        if (err > ps->worst_off && !unsure) ps->worst_off = err;
        /* below every plane that constrains it */
        for (uint32_t i = 0; i < f->nsegs && !unsure; i++) {
            const silk_sil_seg *s = &segs[i];
            if (!s->concave || !is_near(m, s->tri, v) || !beside(view, s, m->pos[v])) continue;
            double n[3], M[3], d = 0, vm[3];
            vec3d(s->nm, n);
            vec3d(s->m, M);
            for (int k = 0; k < 3; k++) vm[k] = V[k] - M[k];
            if (dot3(R, n) < 0.25 || dot3(vm, n) / dot3(R, n) > fx2d(s->rise)) continue;
            for (int k = 0; k < 3; k++) d += (V[k] + off[k] - M[k]) * n[k];
            if (d > ps->worst_above) ps->worst_above = d;
            if (d > 4.0 / 65536) ps->not_below++;
        }
    }
    ps->ref_moved += ref_moved;
    /* the concave segments left to the coarse outline: one a neighbouring
     * vertex above its plane and beside it that could not be lowered, as it
     * stands out beyond twice the segment's sagitta or is further above
     * the plane than the segment's rise */
    uint32_t ref_flat = 0;
    int flat_unsure = 0;
    for (uint32_t i = 0; i < f->nsegs; i++) {
        const silk_sil_seg *s = &segs[i];
        if (!s->concave) continue;
        int refused = 0;
        for (uint32_t v = 0; v < m->nverts && !refused; v++) {
            if (!is_near(m, s->tri, v)) continue;
            double R[3] = { 0, 0, 0 }, V[3], n[3], M[3], vm[3];
            for (uint32_t j = 0; j < f->nsegs; j++) {
                if (!segs[j].concave || !is_near(m, segs[j].tri, v)) continue;
                double nj[3];
                vec3d(segs[j].nm, nj);
                for (int k = 0; k < 3; k++) R[k] += nj[k];
            }
            double rl = sqrt(dot3(R, R));
            for (int k = 0; k < 3; k++) R[k] /= rl;
            vec3d(m->pos[v], V);
            vec3d(s->nm, n);
            vec3d(s->m, M);
            for (int k = 0; k < 3; k++) vm[k] = V[k] - M[k];
            double den = dot3(R, n), num = dot3(vm, n);
            if (den < 0.25 || num <= 0) continue;
            int in, out, unsure;
            place(view, s, m->pos[v], &in, &out, &unsure);
            double rise = fx2d(s->rise), l = num / den;
            if (unsure || fabs(den - 0.25) < 1e-4 || fabs(l - rise) < 4.0 / 65536) flat_unsure = 1;
            if (!in) continue;
            refused = out || l > rise;
        }
        ref_flat += refused;
    }
    if (!flat_unsure) CHECKF(flat == ref_flat, "%u segments left to the coarse outline, reference %u", flat, ref_flat);
    ps->flat += flat;
    /* every corner at a moved vertex is a MOVED record with that vertex's offset */
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        uint32_t sl = f->vert_offset ? f->vert_offset[m->tri[c]] : SILK_PLAN_NONE;
        const silk_vrec *r = &g->vrec[silk_remesh_corner_rec(f, c / 3, c % 3, g->part_rec[c / 3])];
        if (sl == SILK_PLAN_NONE ? r->kind != SILK_VREC_CORNER : (r->kind != SILK_VREC_MOVED || r->b != sl))
            ps->wrong_records++;
        if (r->a != c) ps->wrong_records++;
    }
    free(segs);
}

static void perturb_views(const char *name, int nviews, pstats *ps)
{
    silk_arena a;
    silk_mesh m;
    memset(ps, 0, sizeof *ps);
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    for (int i = 0; i < nviews; i++) {
        /* around the model and a little above: the inner rim of a torus in view */
        double ang = i * 2 * 3.14159265358979 / nviews;
        double d[3] = { cos(ang), 0.15 + 0.5 * (i % 3), sin(ang) };
        silk_view v;
        if (!tf_view_around(&m, d, 2 + (i % 4), i & 1, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        check_view(&m, &v, &f, &g, st.flat_segments, ps);
        CHECK(st.moved_vertices == g.noffset);
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u views, %u concave segments, %u moved vertices (reference %u, where it can say), worst offset error %.2f ulp "
           "(+1e-3 relative), worst height above a plane after moving %.2e; %u segments left to the coarse outline\n",
           name, ps->views, ps->concave, ps->moved, ps->ref_moved, ps->worst_off, ps->worst_above, ps->flat);
    CHECKF(ps->wrong_concave == 0, "%u segments misjudged", ps->wrong_concave);
    CHECKF(ps->wrong_moved == 0, "%u vertices moved / not moved against the reference", ps->wrong_moved);
    CHECKF(ps->not_below == 0, "%u moved vertices still above a plane", ps->not_below);
    CHECKF(ps->wrong_records == 0, "%u corner records wrong", ps->wrong_records);
    CHECKF(ps->worst_off < 4, "offset error %.3g ulp", ps->worst_off);
}

/* The inner rim of a torus is a saddle: concave segments, moved vertices. */
TEST(torus_inner_rim_is_perturbed)
{
    pstats ps;
    perturb_views("torus-576.obj", 24, &ps);
    CHECK(ps.concave > 0 && ps.moved > 0);
}

TEST(knot_is_perturbed)
{
    pstats ps;
    perturb_views("knot-480.obj", 12, &ps);
    CHECK(ps.concave > 0 && ps.moved > 0);
}

/* A sphere is convex: nothing is concave, nothing moves. */
TEST(sphere_never_moves)
{
    pstats ps;
    perturb_views("sphere-200.obj", 24, &ps);
    CHECK(ps.concave == 0 && ps.moved == 0);
}

/* The paper's l = max_i{-(V - M_i).N_i / (R.N_i)} taken literally would move
 * a vertex up: check the direction on a hand-made case.  One concave segment
 * with plane z = 0 (normal +z) and a vertex at height 0.25: it must come down
 * along -R = -z to the plane, not go up. */
TEST(moves_down_to_the_plane)
{
    /* a saddle strip: rows at y = -1, 0, 1; z rises with x^2 and falls with y^2 */
    static const char obj[] =
        "v -1 -1 0\nv 0 -1 -0.5\nv 1 -1 0\n"
        "v -1 0 0.5\nv 0 0 0\nv 1 0 0.5\n"
        "v -1 1 0\nv 0 1 -0.5\nv 1 1 0\n"
        "f 1 2 5\nf 1 5 4\nf 2 3 6\nf 2 6 5\nf 4 5 8\nf 4 8 7\nf 5 6 9\nf 5 9 8\n";
    silk_arena a;
    silk_arena_init(&a, arena_buf, ARENA_BYTES);
    silk_load_opts o;
    silk_load_opts_default(&o);
    o.crease_deg = SILK_FX_C(179, 1);
    silk_mesh m;
    silk_error err;
    if (silk_load_obj(obj, sizeof obj - 1, "saddle.obj", &o, &a, &m, &err) != SILK_OK) {
        fprintf(stderr, "%s\n", err.msg);
        CHECK(0);
        return;
    }
    /* the computed normals taken as a file's: the bridges without the tilt
     * bound (curve.h), whose flatter concave segments would leave this
     * small saddle's vertices where they are */
    m.normals_used = SILK_NORMALS_FILE;
    /* from high above +y, tilted a little: the saddle's rim along x is the silhouette */
    int found = 0, wrong_dir = 0;
    pstats ps;
    memset(&ps, 0, sizeof ps);
    for (int i = 0; i < 16; i++) {
        double ang = (i - 8) * 0.08;
        silk_camera cam;
        memset(&cam, 0, sizeof cam);
        cam.eye = silk_v3(d2fx(10 * sin(ang) * 0.1), d2fx(10), d2fx(0.3 + 0.05 * i));
        cam.target = silk_v3(0, 0, 0);
        cam.up = silk_v3(0, 0, SILK_FX_ONE);
        cam.ortho = i & 1;
        cam.fov_deg = SILK_FX_C(30, 1);
        cam.ortho_half_height = SILK_FX_C(2, 1);
        cam.znear = SILK_FX_C(1, 10);
        cam.zfar = SILK_FX_C(100, 1);
        cam.width = cam.height = 256;
        silk_view v;
        if (silk_view_init(&v, &cam, &err) != SILK_OK) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_sil_frame f;
        silk_frame_geom g;
        silk_frame_stats st;
        if (!tf_run_frame(&a, &m, &v, SILK_FX_HALF, &f, &g, &st)) { CHECK(0); return; }
        check_view(&m, &v, &f, &g, st.flat_segments, &ps);
        silk_sil_seg *segs = tf_segs(&f);
        for (uint32_t vtx = 0; vtx < m.nverts; vtx++) {
            uint32_t sl = f.vert_offset ? f.vert_offset[vtx] : SILK_NO_INDEX;
            if (sl == SILK_NO_INDEX) continue;
            found++;
            /* every concave plane here has a normal with n.z > 0 near the saddle's middle:
             * moving down means the offset has a negative component along the plane normals */
            for (uint32_t s = 0; s < f.nsegs; s++) {
                if (!segs[s].concave || !is_near(&m, segs[s].tri, vtx)) continue;
                if (silk_v3_dot64(g.offset[sl], segs[s].nm) >= 0) wrong_dir++;
            }
        }
        free(segs);
        silk_arena_top_release(&a, &mk);
    }
    printf("  saddle: %u concave segments, %d vertex moves\n", ps.concave, found);
    CHECK(ps.concave > 0);
    CHECK(found > 0);
    CHECKF(wrong_dir == 0, "%d moves go up", wrong_dir);
    CHECKF(ps.not_below == 0 && ps.wrong_moved == 0 && ps.wrong_records == 0, "below %u moved %u records %u",
           ps.not_below, ps.wrong_moved, ps.wrong_records);
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    RUN(torus_inner_rim_is_perturbed);
    RUN(knot_is_perturbed);
    RUN(sphere_never_moves);
    RUN(moves_down_to_the_plane);
    free(arena_buf);
    return check_done();
}
