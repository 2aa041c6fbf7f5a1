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
    uint32_t wrong_concave, wrong_moved, not_below, wrong_records, pinned;
    double worst_off;        /* |offset - reference| in ulps beyond 1e-3 relative, worst */
    double worst_above;      /* how far above a plane a moved, uncapped vertex stays */
} pstats;

/* One view: recompute concavity and perturbation in double from the
 * segments' end data and compare. */
static void check_view(const silk_mesh *m, const silk_sil_frame *f, const silk_frame_geom *g, pstats *ps)
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
        int capped = 0;
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
                double den = dot3(R, n), num = dot3(vm, n);
                if (den < 0.25 || num <= 0) continue;
                double l = num / den;
                double cap = fmin(sqrt(dot3(vm, vm)), 2 * fx2d(s->rise));
                if (l > cap) { l = cap; capped = 1; }
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
        uint32_t sl = f->vert_offset ? f->vert_offset[v] : SILK_NO_INDEX;
        int moved = sl != SILK_NO_INDEX;
        int ref = lift > 2.0 / 65536;          /* below that, rounding decides */
        ref_moved += ref;
        if (moved != ref && lift > 4.0 / 65536) ps->wrong_moved++;
        if (!moved) continue;
        ps->moved++;
        double off[3];
        vec3d(g->offset[sl], off);
        double err = 0;
        for (int k = 0; k < 3; k++) err += (off[k] + lift * R[k]) * (off[k] + lift * R[k]);
        /* in ulps, beyond the relative error the Q16.16 inputs allow */
        err = (sqrt(err) - 1e-3 * lift) * 65536;
        if (err > ps->worst_off) ps->worst_off = err;
        if (capped) continue;
        /* uncapped: below every plane it neighbours */
        for (uint32_t i = 0; i < f->nsegs; i++) {
            const silk_sil_seg *s = &segs[i];
            if (!s->concave || !is_near(m, s->tri, v)) continue;
            double n[3], M[3], d = 0;
            vec3d(s->nm, n);
            vec3d(s->m, M);
            if (dot3(R, n) < 0.25) continue;
            for (int k = 0; k < 3; k++) d += (V[k] + off[k] - M[k]) * n[k];
            if (d > ps->worst_above) ps->worst_above = d;
            if (d > 4.0 / 65536) ps->not_below++;
        }
    }
    ps->ref_moved += ref_moved;
    /* every corner at a moved vertex is a MOVED record with that vertex's offset */
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        uint32_t sl = f->vert_offset ? f->vert_offset[m->tri[c]] : SILK_NO_INDEX;
        const silk_vrec *r = &g->vrec[silk_remesh_corner_rec(f, c / 3, c % 3, g->part_rec[c / 3])];
        if (sl == SILK_NO_INDEX ? r->kind != SILK_VREC_CORNER : (r->kind != SILK_VREC_MOVED || r->b != sl))
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
        check_view(&m, &f, &g, ps);
        CHECK(st.moved_vertices == g.noffset);
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %u views, %u concave segments, %u moved vertices (reference %u), worst offset error %.2f ulp "
           "(+1e-3 relative), worst height above a plane after moving %.2e\n",
           name, ps->views, ps->concave, ps->moved, ps->ref_moved, ps->worst_off, ps->worst_above);
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
        check_view(&m, &f, &g, &ps);
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
