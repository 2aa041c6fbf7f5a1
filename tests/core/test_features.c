/*
 * test_features.c - feature polylines and their Hermite tangents (paper
 * III-A, eqs. 1 and 4) against a double reference that takes each tangent
 * from the circumscribed circle directly (not from eq. 1), and the point of
 * eq. 4: feature segments over points of a circle stay on the circle.
 * Polylines stop at turns of more than 45 degrees (features.c): a corner
 * between two arcs keeps each side's own circle, an octagon stays one
 * smooth loop, and no segment of fandisk-128 strays from its chord by more
 * than the bound that rule gives; the turns measured on the shared models
 * (docs/formats.md).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "src/curve.h"
#include "silk/silk.h"
#include "src/frame.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (48u << 20)
#define PI 3.14159265358979323846
#define ULP (1.0 / 65536)

/* ---- vectors in double ------------------------------------------------------------------- */

static dvec vpos(const silk_mesh *m, uint32_t v) { return dv(m->pos[v]); }

static double angle_between(dvec a, dvec b)
{
    double c = ddot(a, b) / (dlen(a) * dlen(b));
    return acos(c > 1 ? 1 : (c < -1 ? -1 : c));
}

/* Eq. 5 */
static dvec hermite(dvec p0, dvec p1, dvec t0, dvec t1, double u)
{
    double u2 = u * u, u3 = u2 * u;
    return dadd(dadd(dscale(p0, 2 * u3 - 3 * u2 + 1), dscale(t0, u3 - 2 * u2 + u)),
               dadd(dscale(p1, -2 * u3 + 3 * u2), dscale(t1, u3 - u2)));
}

/* The tangent at x (one of p, q, r, travelled in that order) of the circle
 * through p, q, r: the travel normal crossed with the radius, from the
 * circumcentre.  Straight points give the chord. */
static dvec circle_tangent(dvec p, dvec q, dvec r, dvec x)
{
    dvec a = dsub(p, r), b = dsub(q, r), axb = dcross(a, b);
    double l2 = ddot(axb, axb);
    if (l2 <= 1e-24 * ddot(a, a) * ddot(b, b)) return dsub(r, p);
    dvec o = dadd(r, dscale(dcross(dsub(dscale(b, ddot(a, a)), dscale(a, ddot(b, b))), axb), 1 / (2 * l2)));
    dvec n = dcross(dsub(q, p), dsub(r, q));
    return dcross(n, dsub(x, o));
}

/* Eq. 4 with curve.h's clamp (SILK_ARC_MAX_RATIO = 4 chord lengths) and
 * its bulge bound (L sin theta <= |chord| / SILK_BULGE_DIV). */
static dvec arc_length_scaled(dvec dir, dvec chord)
{
    double lc = dlen(chord), c = ddot(dir, chord) / (dlen(dir) * lc), s = dlen(dcross(dir, chord)) / (dlen(dir) * lc);
    double l = 2 * lc / (1 + c);
    if (!(l < 4 * lc)) l = 4 * lc;
    if (s > 0) l = fmin(l, lc / (SILK_BULGE_DIV * s));
    return dscale(dir, l / dlen(dir));
}

/* ---- the reference feature tangents --------------------------------------------------------- */

static int is_feature(const silk_mesh *m, uint32_t e)
{
    return (m->edge[e].flags & SILK_EDGE_FEATURE) && m->edge[e].v[0] != m->edge[e].v[1];
}

static uint32_t feature_degree(const silk_mesh *m, uint32_t v)
{
    uint32_t n = 0;
    for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) n += is_feature(m, m->vert_edge[i]);
    return n;
}

/* The other end of v's second feature edge (v has exactly two), e the first. */
static uint32_t beyond(const silk_mesh *m, uint32_t v, uint32_t e)
{
    for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) {
        uint32_t f = m->vert_edge[i];
        if (f != e && is_feature(m, f)) return m->edge[f].v[0] == v ? m->edge[f].v[1] : m->edge[f].v[0];
    }
    return v;
}

/* features.c's SILK_FEATURE_TURN_DEG.  Turns within TURN_MARGIN of it may
 * go either way: the core compares unit vectors rounded to Q16.16 (about
 * 0.002 degrees there). */
#define TURN_DEG 45.0
#define TURN_MARGIN 0.01

/* How far (degrees) a polyline through v turns there: the angle between
 * v - a and b - v, a and b the ends of v's two feature edges; -1 when v
 * does not have exactly two, 180 when a neighbour sits on v. */
static double turn_at(const silk_mesh *m, uint32_t v)
{
    if (feature_degree(m, v) != 2) return -1;
    uint32_t nb[2], n = 0;
    for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1] && n < 2; i++) {
        uint32_t e = m->vert_edge[i];
        if (is_feature(m, e)) nb[n++] = m->edge[e].v[0] == v ? m->edge[e].v[1] : m->edge[e].v[0];
    }
    dvec in = dsub(vpos(m, v), vpos(m, nb[0])), out = dsub(vpos(m, nb[1]), vpos(m, v));
    if (dlen(in) == 0 || dlen(out) == 0) return 180;
    return angle_between(in, out) * 180 / PI;
}

/* The stop rule: 1 when a polyline passes through v (two feature edges and,
 * with turn_rule, a turn of at most TURN_DEG), 0 when it ends there, -1
 * when the turn is too close to TURN_DEG to tell.  turn_rule 0 is the rule
 * before the turn limit: only the number of feature edges counts. */
static int passes(const silk_mesh *m, uint32_t v, int turn_rule)
{
    double t = turn_at(m, v);
    if (t < 0) return 0;
    if (!turn_rule) return 1;
    if (fabs(t - TURN_DEG) <= TURN_MARGIN) return -1;
    return t < TURN_DEG;
}

/* features.c's SILK_FEATURE_G1, and how close to its decisions the
 * reference leaves them to rounding. */
#define G1 2.0
#define G1_MARGIN 0.01

/* The sine of the turn at v, 0 where the polyline does not pass through. */
static double turn_sin(const silk_mesh *m, uint32_t v, int turn_rule)
{
    return passes(m, v, turn_rule) > 0 ? sin(turn_at(m, v) * PI / 180) : 0;
}

/* The direction of the tangent at v, passed through from u to w: the long
 * edge's where the spacing changes by more than G1 and the long edge's far
 * end turns less than a quarter as much as v (a line meeting the arc it is
 * tangent to), else the circle's.  *unsure when a rounding could decide
 * otherwise. */
static dvec pass_dir(const silk_mesh *m, uint32_t u, uint32_t v, uint32_t w, int turn_rule, int *unsure)
{
    dvec pu = vpos(m, u), pv = vpos(m, v), pw = vpos(m, w);
    double l0 = dlen(dsub(pv, pu)), l1 = dlen(dsub(pw, pv)), tv = turn_sin(m, v, turn_rule) / 4;
    double tw = turn_sin(m, w, turn_rule), tu = turn_sin(m, u, turn_rule);
    if (fabs(l1 / l0 - G1) < G1_MARGIN || fabs(l0 / l1 - G1) < G1_MARGIN) *unsure = 1;
    if (l1 > G1 * l0 && fabs(tw - tv) < G1_MARGIN * tv) *unsure = 1;
    if (l0 > G1 * l1 && fabs(tu - tv) < G1_MARGIN * tv) *unsure = 1;
    if (l1 > G1 * l0 && tw < tv) return dsub(pw, pv);
    if (l0 > G1 * l1 && tu < tv) return dsub(pv, pu);
    return circle_tangent(pu, pv, pw, pv);
}

/* d mirrored in the bisector plane of the chord and reversed: the end
 * tangent of the circle through the end, its neighbour and the next
 * vertex, from the tangent d at the neighbour (features.c end_dir). */
static dvec mirrored(dvec chord, dvec d)
{
    dvec u = dscale(chord, 1 / dlen(chord));
    d = dscale(d, 1 / dlen(d));
    return dsub(dscale(u, 2 * ddot(d, u)), d);
}

/* Straight stays straight (curve.c): a direction within 2^-10 of the
 * chord's is the chord's. */
static dvec snapped(dvec d, dvec chord, int *unsure)
{
    double s = dlen(dcross(d, chord)) / (dlen(d) * dlen(chord)), lim = 1.0 / 1024;
    if (s > lim / 2 && s < 2 * lim) *unsure = 1;
    return s < lim ? chord : d;
}

/* The reference Hermite tangents of feature edge e (eq. 4 lengths): at an
 * end the polyline passes through, pass_dir; at an end where it stops, the
 * other end's direction mirrored (for plain circles, the tangent of the
 * circle through the end and the next two vertices), or the chord for a
 * polyline of one edge.  Returns 0 when an end is too close to a rule's
 * limit to tell. */
static int ref_tangents(const silk_mesh *m, uint32_t e, int turn_rule, dvec *ta, dvec *tb)
{
    uint32_t a = m->edge[e].v[0], b = m->edge[e].v[1];
    int pa = passes(m, a, turn_rule), pb = passes(m, b, turn_rule), unsure = 0;
    if (pa < 0 || pb < 0) return 0;
    dvec chord = dsub(vpos(m, b), vpos(m, a));
    uint32_t prev = pa ? beyond(m, a, e) : a, next = pb ? beyond(m, b, e) : b;
    if (pa && (prev == a || prev == b)) return 0;   /* a loop of two edges */
    if (pb && (next == b || next == a)) return 0;
    dvec da = pa ? pass_dir(m, prev, a, b, turn_rule, &unsure) : chord;
    dvec db = pb ? pass_dir(m, a, b, next, turn_rule, &unsure) : chord;
    if (!pa && pb) da = mirrored(chord, db);
    if (pa && !pb) db = mirrored(chord, da);
    if (!pa && !pb) {
        *ta = *tb = chord;
        return 1;
    }
    *ta = arc_length_scaled(snapped(da, chord, &unsure), chord);
    *tb = arc_length_scaled(snapped(db, chord, &unsure), chord);
    return !unsure;
}

typedef struct feat_report {
    double dir_ulp, len_ulp;   /* worst tangent error in ulp: direction (angle times the
                                  tangent's length) and length */
    uint32_t checked, skipped;
} feat_report;

/* One stored segment against reference tangents ta, tb. */
static void check_segment(const silk_mesh *m, uint32_t e, dvec ta, dvec tb, double ulp_bound, feat_report *r)
{
    const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
    dvec g0 = dv(s->t0), g1 = dv(s->t1);
    double ea = angle_between(g0, ta) * dlen(ta) / ULP, eb = angle_between(g1, tb) * dlen(tb) / ULP;
    double la = fabs(dlen(g0) - dlen(ta)) / ULP, lb = fabs(dlen(g1) - dlen(tb)) / ULP;
    CHECKF(ea <= ulp_bound && eb <= ulp_bound, "edge %u (%u-%u) tangent directions off by %.2f %.2f ulp", e,
           m->edge[e].v[0], m->edge[e].v[1], ea, eb);
    CHECKF(la <= ulp_bound && lb <= ulp_bound, "edge %u tangent lengths off by %.2f %.2f ulp", e, la, lb);
    r->checked++;
    r->dir_ulp = fmax(r->dir_ulp, fmax(ea, eb));
    r->len_ulp = fmax(r->len_ulp, fmax(la, lb));
}

/* Compare every feature segment of m with the reference; a stored tangent
 * may be off by ulp_bound ulp in direction and in length.  Edges with an end
 * whose turn is within TURN_MARGIN of the limit are skipped and counted. */
static void check_features(const silk_mesh *m, double ulp_bound, feat_report *r)
{
    memset(r, 0, sizeof *r);
    uint32_t nfe = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(m, e)) {
            CHECKF(m->edge_feature[e] == SILK_NO_INDEX, "edge %u is no feature but has a segment", e);
            continue;
        }
        CHECKF(m->edge_feature[e] == nfe, "edge %u segment %u", e, m->edge_feature[e]);
        nfe++;
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        dvec chord = dsub(vpos(m, m->edge[e].v[1]), vpos(m, m->edge[e].v[0]));
        /* eq. 4's clamp holds everywhere */
        double lmax = 4 * dlen(chord) + 2 * ULP;
        CHECKF(dlen(dv(s->t0)) <= lmax && dlen(dv(s->t1)) <= lmax, "edge %u tangents longer than 4 chords", e);
        dvec ta, tb;
        if (!ref_tangents(m, e, 1, &ta, &tb)) {
            r->skipped++;
            continue;
        }
        check_segment(m, e, ta, tb, ulp_bound, r);
    }
    CHECKF(m->nfeature_edges == nfe, "%u feature edges, %u segments", nfe, m->nfeature_edges);
}

/* The angle (radians) at which the two feature segments at v (two feature
 * edges) leave it, both taken as leaving v: pi where the curve goes
 * straight through; and the part of that the rounding of the stored tangents
 * explains (each is rounded to Q16.16 as a whole vector, so its direction
 * carries up to about 0.87 ulp / its length). */
static double meet_angle(const silk_mesh *m, uint32_t v, double *slack)
{
    dvec t[2];
    int n = 0;
    for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1] && n < 2; i++) {
        uint32_t e = m->vert_edge[i];
        if (!is_feature(m, e)) continue;
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        t[n++] = m->edge[e].v[0] == v ? dv(s->t0) : dscale(dv(s->t1), -1);
    }
    *slack = ULP / dlen(t[0]) + ULP / dlen(t[1]);
    return angle_between(t[0], t[1]);
}

/* G1: where a polyline passes through a vertex, its two segments leave with
 * the same tangent direction.  Returns the worst angle beyond the rounding
 * of the stored tangents. */
static double check_g1(const silk_mesh *m, double tol)
{
    double worst = 0;
    for (uint32_t v = 0; v < m->nverts; v++) {
        if (passes(m, v, 1) != 1) continue;
        double slack, a = PI - meet_angle(m, v, &slack);
        CHECKF(a <= tol + slack, "vertex %u: segments meet at %.3g rad (slack %.3g)", v, a, slack);
        if (a - slack > worst) worst = a - slack;
    }
    return worst;
}

/* Largest distance of the feature segments of edges with both ends within
 * eps of the circle (centre c, unit normal n, radius rad) from that circle. */
static double circle_deviation(const silk_mesh *m, dvec c, dvec n, double rad, uint32_t *nseg)
{
    double worst = 0;
    *nseg = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(m, e)) continue;
        dvec p0 = vpos(m, m->edge[e].v[0]), p1 = vpos(m, m->edge[e].v[1]);
        int on = 1;
        for (int k = 0; k < 2; k++) {
            dvec d = dsub(k ? p1 : p0, c);
            double h = ddot(d, n), r = dlen(dsub(d, dscale(n, h)));
            on &= fabs(h) < 1e-3 && fabs(r - rad) < 1e-3 * rad;
        }
        if (!on) continue;
        (*nseg)++;
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        for (int i = 0; i <= 64; i++) {
            dvec d = dsub(hermite(p0, p1, dv(s->t0), dv(s->t1), i / 64.0), c);
            double h = ddot(d, n), r = dlen(dsub(d, dscale(n, h)));
            double dist = sqrt(h * h + (r - rad) * (r - rad));
            if (dist > worst) worst = dist;
        }
    }
    return worst;
}

/* ---- circles ------------------------------------------------------------------------------- */

/* Points of a circle, in the plane through c spanned by unit u and w. */
static dvec on_circle(dvec c, dvec u, dvec w, double rad, double ang)
{
    return dadd(c, dadd(dscale(u, rad * cos(ang)), dscale(w, rad * sin(ang))));
}

/* How far the exact eq. 4 Hermite curve over an arc of phi radians strays
 * from a circle of radius rad: the part of the deviation that is the
 * method's, not the fixed point's. */
static double ideal_arc_error(double rad, double phi)
{
    dvec p0 = dmk(rad, 0, 0), p1 = dmk(rad * cos(phi), rad * sin(phi), 0), chord = dsub(p1, p0);
    dvec t0 = arc_length_scaled(dmk(0, 1, 0), chord), t1 = arc_length_scaled(dmk(-sin(phi), cos(phi), 0), chord);
    double worst = 0;
    for (int i = 0; i <= 256; i++) worst = fmax(worst, fabs(dlen(hermite(p0, p1, t0, t1, i / 256.0)) - rad));
    return worst;
}

static void put(double *pos, uint32_t v, dvec p)
{
    pos[3 * v] = p.x;
    pos[3 * v + 1] = p.y;
    pos[3 * v + 2] = p.z;
}

/* Irregular angles in [0, span): steps between lo and hi degrees. */
static uint32_t irregular_angles(double *ang, uint32_t max, double span, double lo, double hi)
{
    uint32_t n = 0;
    double a = 0;
    while (n < max && a < span - lo * PI / 180) {
        ang[n++] = a;
        a += check_uniform(lo, hi) * PI / 180;
    }
    return n;
}

TEST(closed_loop_on_a_circle)
{
    /* a flat fan in a tilted plane; its boundary is one closed feature loop
     * through points at irregular angles on a circle */
    dvec c = dmk(0.3, -0.2, 0.5), u = dmk(0.6, 0.8, 0), w = dmk(0, 0, 1);
    u = dscale(u, 1 / dlen(u));
    w = dcross(u, dmk(-0.48, 0.36, 0.8));
    w = dscale(w, 1 / dlen(w));
    dvec n = dcross(u, w);
    double rad = 2.5, ang[64];
    for (int round = 0; round < 3; round++) {
        double lo = round == 0 ? 8 : 4, hi = round == 0 ? 12 : (round == 1 ? 20 : 30);
        uint32_t k = irregular_angles(ang, 64, 2 * PI, lo, hi);
        double *pos = malloc(sizeof(double) * 3 * (k + 1));
        uint32_t *tri = malloc(sizeof(uint32_t) * 3 * k);
        put(pos, 0, c);
        for (uint32_t i = 0; i < k; i++) {
            put(pos, i + 1, on_circle(c, u, w, rad, ang[i]));
            tri[3 * i] = 0, tri[3 * i + 1] = i + 1, tri[3 * i + 2] = i + 1 < k ? i + 2 : 1;
        }
        tm_fixture f;
        tm_fixture_init(&f, ARENA_BYTES);
        CHECK(tm_fixture_input(&f, pos, k + 1, tri, k) && tm_fixture_build(&f) == SILK_OK);
        CHECK(f.m.nfeature_edges == k && f.m.nboundary_edges == k);
        feat_report r;
        check_features(&f.m, 4, &r);
        uint32_t nseg;
        double dev = circle_deviation(&f.m, c, n, rad, &nseg);
        double g1 = check_g1(&f.m, 1e-4);
        /* the method's own error over the widest step, plus rounding */
        double ideal = 0;
        for (uint32_t i = 0; i < k; i++) ideal = fmax(ideal, ideal_arc_error(rad, (i + 1 < k ? ang[i + 1] : 2 * PI) - ang[i]));
        double bound = ideal + 2 * ULP;
        CHECKF(nseg == k && dev <= bound, "%u segments, deviation %.3g > %.3g", nseg, dev, bound);
        printf("  closed loop, %2u points, steps %2.0f..%2.0f deg: off the circle by %.2g (%.2f ulp; exact eq. 4: %.2g), "
               "tangents %.2f / %.2f ulp, G1 %.2g rad\n", k, lo, hi, dev, dev / ULP, ideal, r.dir_ulp, r.len_ulp, g1);
        free(pos);
        free(tri);
        free(f.buf);
    }
}

TEST(open_arc_with_junction_ends)
{
    /* a flat sector and a wall hanging from its arc: the arc is a 90-degree
     * crease, an open polyline whose ends meet two boundary edges each */
    dvec c = dmk(-1, 2, 0.25), u = dmk(1, 0, 0), w = dmk(0, 1, 0), down = dmk(0, 0, -0.7);
    double rad = 1.75, ang[64];
    uint32_t k = irregular_angles(ang, 40, 2.2, 6, 22);
    uint32_t nv = 1 + 2 * k, nt = (k - 1) * 3;
    double *pos = malloc(sizeof(double) * 3 * nv);
    uint32_t *tri = malloc(sizeof(uint32_t) * 3 * nt), t = 0;
    put(pos, 0, c);
    for (uint32_t i = 0; i < k; i++) {
        dvec p = on_circle(c, u, w, rad, ang[i]);
        put(pos, 1 + i, p);
        put(pos, 1 + k + i, dadd(p, down));
    }
    for (uint32_t i = 1; i < k; i++) {
        uint32_t p0 = i, p1 = i + 1, q0 = k + i, q1 = k + i + 1;
        tri[3 * t] = 0, tri[3 * t + 1] = p0, tri[3 * t + 2] = p1, t++;
        tri[3 * t] = p1, tri[3 * t + 1] = p0, tri[3 * t + 2] = q0, t++;
        tri[3 * t] = p1, tri[3 * t + 1] = q0, tri[3 * t + 2] = q1, t++;
    }
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    CHECK(tm_fixture_input(&f, pos, nv, tri, nt) && tm_fixture_build(&f) == SILK_OK);
    uint32_t creases = 0;
    for (uint32_t e = 0; e < f.m.nedges; e++) creases += (f.m.edge[e].flags & SILK_EDGE_CREASE) != 0;
    CHECK(creases == k - 1);
    CHECK(feature_degree(&f.m, 1) == 3 && feature_degree(&f.m, k) == 3);
    feat_report r;
    check_features(&f.m, 4, &r);
    uint32_t nseg;
    double dev = circle_deviation(&f.m, c, dmk(0, 0, 1), rad, &nseg);
    double ideal = 0;
    for (uint32_t i = 0; i + 1 < k; i++) ideal = fmax(ideal, ideal_arc_error(rad, ang[i + 1] - ang[i]));
    double bound = ideal + 2 * ULP;
    CHECKF(nseg == k - 1 && dev <= bound, "%u segments, deviation %.3g > %.3g", nseg, dev, bound);
    printf("  open arc, %u points: off the circle by %.2g (%.2f ulp; exact eq. 4: %.2g), tangents %.2f / %.2f ulp\n",
           k, dev, dev / ULP, ideal, r.dir_ulp, r.len_ulp);
    free(pos);
    free(tri);
    free(f.buf);
}

TEST(single_edge_stays_straight)
{
    /* a square folded 90 degrees along its diagonal 0-2: the fold is a
     * polyline of one edge (its ends also have two boundary edges), and the
     * boundary turns 90 degrees at 1 and 3, so it is four more */
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.5, 0.70710678 };
    static const uint32_t tri[] = { 0, 1, 2, 0, 2, 3 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nfeature_edges == 5);
    uint32_t e = f.m.tri_edge[2];
    CHECK(f.m.edge[e].flags & SILK_EDGE_CREASE);
    for (e = 0; e < f.m.nedges; e++) {
        const silk_feature_seg *s = &f.m.feature[f.m.edge_feature[e]];
        silk_vec3 chord = silk_v3_sub(f.m.pos[f.m.edge[e].v[1]], f.m.pos[f.m.edge[e].v[0]]);
        CHECKF(!memcmp(&s->t0, &chord, sizeof chord) && !memcmp(&s->t1, &chord, sizeof chord),
               "edge %u is not straight", e);
    }
    feat_report r;
    check_features(&f.m, 4, &r);
    free(f.buf);
}

/* A random rotation (uniform enough for a test): three random unit axes,
 * made orthonormal. */
static void random_frame(dvec *u, dvec *w, dvec *n)
{
    dvec a = dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1));
    dvec b = dmk(check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1));
    *u = dscale(a, 1 / dlen(a));
    *n = dcross(*u, b);
    *n = dscale(*n, 1 / dlen(*n));
    *w = dcross(*n, *u);
}

/* Octagons turn by exactly SILK_FEATURE_TURN_DEG at every vertex, the one
 * turn the rule lets through by definition ("more than 45 degrees" stops):
 * its boundary must stay one closed loop with G1 everywhere.  Regular ones
 * (points on a circle, where a break would hardly show) and irregular ones
 * (edge lengths from 1.5 to 2.5, where the circles through each three
 * vertices differ and a break leaves a visible kink), in random orientations
 * and positions.  Rounding the positions to Q16.16 moves a turn's cosine by
 * at most 2.5 ulp / the shorter edge, 1.7 ulp here: with the rounding of the
 * unit vectors (1.8) and of the cosine (0.5), inside features.c's 4 ulp. */
TEST(octagon_stays_one_smooth_loop)
{
    double worst_g1 = 0, worst_dir = 0, worst_len = 0;
    uint32_t kinked = 0;
    for (int round = 0; round < 48; round++) {
        double L[8];
        int regular = round < 16;
        for (;;) {
            for (int k = 0; k < 6; k++) L[k] = regular ? 2 : check_uniform(1.5, 2.5);
            /* closes when sum L_k (cos, sin)(k 45 deg) = 0 */
            L[7] = L[3] + L[5] - L[1] - sqrt(2) * (L[0] - L[4]);
            L[6] = L[2] + (L[1] + L[3] - L[5] - L[7]) / sqrt(2);
            if (L[6] >= 1.5 && L[7] >= 1.5 && L[6] <= 2.5 && L[7] <= 2.5) break;
        }
        dvec u, w, n, o = dmk(check_uniform(-3, 3), check_uniform(-3, 3), check_uniform(-3, 3));
        random_frame(&u, &w, &n);
        double pos[3 * 9], x = 0, y = 0;
        uint32_t tri[3 * 8];
        dvec centre = dmk(0, 0, 0);
        for (int k = 0; k < 8; k++) {
            dvec p = dadd(o, dadd(dscale(u, x), dscale(w, y)));
            put(pos, (uint32_t)k + 1, p);
            centre = dadd(centre, dscale(p, 1.0 / 8));
            x += L[k] * cos(k * PI / 4);
            y += L[k] * sin(k * PI / 4);
            tri[3 * k] = 0, tri[3 * k + 1] = (uint32_t)k + 1, tri[3 * k + 2] = k < 7 ? (uint32_t)k + 2 : 1;
        }
        put(pos, 0, centre);
        tm_fixture f;
        tm_fixture_init(&f, 1 << 16);
        CHECK(tm_fixture_input(&f, pos, 9, tri, 8) && tm_fixture_build(&f) == SILK_OK);
        CHECK(f.m.nfeature_edges == 8);
        /* the tangents of one closed loop: the circle through each vertex
         * and its two neighbours, at every vertex */
        feat_report r = { 0 };
        for (uint32_t e = 0; e < f.m.nedges; e++) {
            if (!is_feature(&f.m, e)) continue;
            uint32_t a = f.m.edge[e].v[0], b = f.m.edge[e].v[1];
            dvec pa = vpos(&f.m, a), pb = vpos(&f.m, b), chord = dsub(pb, pa);
            dvec ta = circle_tangent(vpos(&f.m, beyond(&f.m, a, e)), pa, pb, pa);
            dvec tb = circle_tangent(pa, pb, vpos(&f.m, beyond(&f.m, b, e)), pb);
            check_segment(&f.m, e, arc_length_scaled(ta, chord), arc_length_scaled(tb, chord), 4, &r);
        }
        uint32_t bad = 0;
        for (uint32_t v = 1; v <= 8; v++) {
            double slack, a = PI - meet_angle(&f.m, v, &slack);
            bad += a > 1e-4 + slack;
            if (a - slack > worst_g1) worst_g1 = a - slack;
        }
        CHECKF(bad == 0, "%s octagon %d: %u of 8 vertices are corners", regular ? "regular" : "irregular", round, bad);
        kinked += bad;
        worst_dir = fmax(worst_dir, r.dir_ulp);
        worst_len = fmax(worst_len, r.len_ulp);
        free(f.buf);
    }
    printf("  48 octagons (16 regular): %u corners, G1 %.2g rad beyond rounding, tangents %.2f / %.2f ulp\n", kinked,
           worst_g1, worst_dir, worst_len);
}

/* A lens: two circular arcs meeting at two corners (turning by 74 degrees
 * and more), the boundary of a flat fan in a random orientation.  The loop
 * breaks at the corners: there each segment's tangent is its own arc's
 * (the circle through the corner and the next two vertices of that arc),
 * the two leave the corner at the arcs' own angle, and every segment stays
 * on its arc's circle.  With the old rule the corner was an inner vertex
 * and both tangents came from the circle through its two neighbours. */
TEST(sharp_corner_breaks_the_polyline)
{
    const double R = 2, d = 1.2, h = sqrt(R * R - d * d), half = atan2(h, d);
    for (int round = 0; round < 4; round++) {
        dvec u, w, n, o = dmk(check_uniform(-2, 2), check_uniform(-2, 2), check_uniform(-2, 2));
        random_frame(&u, &w, &n);
        dvec ca = dsub(o, dscale(u, d)), cb = dadd(o, dscale(u, d));
        /* arc A (centre ca) from P = o - h w to Q = o + h w, then arc B back */
        double angA[32], angB[32];
        uint32_t na = irregular_angles(angA, 32, 2 * half, 8, 25), nb = irregular_angles(angB, 32, 2 * half, 8, 25);
        uint32_t nv = 1 + na + nb;
        double *pos = malloc(sizeof(double) * 3 * nv);
        uint32_t *tri = malloc(sizeof(uint32_t) * 3 * (na + nb));
        put(pos, 0, o);
        for (uint32_t i = 0; i < na; i++) put(pos, 1 + i, on_circle(ca, u, w, R, angA[i] - half));
        for (uint32_t i = 0; i < nb; i++) put(pos, 1 + na + i, on_circle(cb, u, w, R, PI - half + angB[i]));
        for (uint32_t i = 0; i < na + nb; i++)
            tri[3 * i] = 0, tri[3 * i + 1] = 1 + i, tri[3 * i + 2] = i + 1 < na + nb ? i + 2 : 1;
        tm_fixture f;
        tm_fixture_init(&f, 1 << 20);
        CHECK(tm_fixture_input(&f, pos, nv, tri, na + nb) && tm_fixture_build(&f) == SILK_OK);
        const silk_mesh *m = &f.m;
        CHECK(m->nfeature_edges == na + nb);
        feat_report r;
        check_features(m, 4, &r);
        CHECK(r.skipped == 0 && r.checked == na + nb);
        uint32_t corner[2] = { 1, 1 + na };   /* P and Q */
        double worst_own = 0, worst_old = 0, worst_meet = 0;
        for (int c = 0; c < 2; c++) {
            uint32_t v = corner[c];
            CHECKF(passes(m, v, 1) == 0 && turn_at(m, v) > 70, "corner %u turns by %.1f deg", v, turn_at(m, v));
            dvec pv = vpos(m, v), leave[2];
            int k = 0;
            for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) {
                uint32_t e = m->vert_edge[i];
                if (!is_feature(m, e) || k == 2) continue;
                const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
                uint32_t other = m->edge[e].v[0] == v ? m->edge[e].v[1] : m->edge[e].v[0];
                dvec t = m->edge[e].v[0] == v ? dv(s->t0) : dscale(dv(s->t1), -1);
                /* the edge's own arc: the neighbour's circle; its tangent at
                 * the corner, pointing along the edge */
                dvec cc = other <= na ? ca : cb, radius = dsub(pv, cc), own = dcross(n, radius);
                if (ddot(own, dsub(vpos(m, other), pv)) < 0) own = dscale(own, -1);
                double err = angle_between(t, own) * dlen(t) / ULP;
                CHECKF(err <= 4, "corner %u, edge %u: tangent %.2f ulp off its own arc", v, e, err);
                worst_own = fmax(worst_own, err);
                /* the old rule's tangent: circle through the corner's two
                 * neighbours, travelled from the other one to this edge's */
                uint32_t across = beyond(m, v, e);
                dvec old = circle_tangent(vpos(m, across), pv, vpos(m, other), pv);
                worst_old = fmax(worst_old, angle_between(old, own) * 180 / PI);
                leave[k++] = t;
            }
            /* the arcs' own angle at the corner */
            dvec ta = dcross(n, dsub(pv, ca)), tb = dcross(n, dsub(pv, cb));
            double want = PI - angle_between(ta, tb), got = angle_between(leave[0], leave[1]);
            CHECKF(fabs(got - want) < 1e-3, "corner %u: segments leave at %.4f rad, the arcs at %.4f", v, got, want);
            worst_meet = fmax(worst_meet, fabs(got - want));
        }
        uint32_t sa, sb;
        double da = circle_deviation(m, ca, n, R, &sa), db = circle_deviation(m, cb, n, R, &sb), ideal = 0;
        for (uint32_t i = 0; i < na; i++) ideal = fmax(ideal, ideal_arc_error(R, (i + 1 < na ? angA[i + 1] : 2 * half) - angA[i]));
        for (uint32_t i = 0; i < nb; i++) ideal = fmax(ideal, ideal_arc_error(R, (i + 1 < nb ? angB[i + 1] : 2 * half) - angB[i]));
        CHECKF(sa == na && sb == nb && fmax(da, db) <= ideal + 2 * ULP, "arcs: %u+%u segments, off their circles by %.3g",
               sa, sb, fmax(da, db));
        printf("  lens %d, %u+%u edges: tangents at the corners %.2f ulp off their own arc (the old rule's: %.1f deg), "
               "corner angle %.2g rad off, arcs off their circles by %.2f ulp\n", round, na, nb, worst_own, worst_old,
               worst_meet, fmax(da, db) / ULP);
        free(pos);
        free(tri);
        free(f.buf);
    }
}

TEST(shared_meshes_vs_reference)
{
    static const char *const names[] = {
        "cone-70", "fandisk-128", "fandisk-1000", "fandisk-fine", "pawn-304", "wingnut-500", "rockerarm-500",
        "bunny-500", "dragon-500", "feline-500", "cow-500", "springer-500", "dragon-5k", "knot-480", "cat-500",
        "spot-500", "armadillo-500", "fish-500", "venus-500",
    };   /* not maxplanck-500: 400 units across, its tangents carry 100 times the rounding */
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    double worst_dir = 0, worst_len = 0, worst_g1 = 0;
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, names[i]), "cannot read %s", names[i]);
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", names[i], f.err.msg); continue; }
        feat_report r;
        check_features(&f.m, 4, &r);
        double g1 = check_g1(&f.m, 1e-3);
        printf("  %-14s %4u feature edges (%u near the turn limit skipped): tangents off by %.2f / %.2f ulp, G1 %.2g rad"
               " beyond rounding\n",
               names[i], f.m.nfeature_edges, r.skipped, r.dir_ulp, r.len_ulp, g1);
        worst_dir = fmax(worst_dir, r.dir_ulp);
        worst_len = fmax(worst_len, r.len_ulp);
        worst_g1 = fmax(worst_g1, g1);
        if (!strcmp(names[i], "cone-70")) {
            uint32_t nseg;
            double dev = circle_deviation(&f.m, dmk(0, 0, 0), dmk(0, 1, 0), 1, &nseg);
            double ideal = ideal_arc_error(1, 2 * PI / 35);
            CHECKF(nseg == 35 && dev <= ideal + 2 * ULP, "cone rim: %u segments, off the circle by %.3g", nseg, dev);
            printf("  cone-70 rim: 35 segments, off the unit circle by %.2g (%.2f ulp)\n", dev, dev / ULP);
        }
    }
    printf("  worst: tangent direction %.2f ulp, length %.2f ulp, G1 %.2g rad beyond rounding\n", worst_dir,
           worst_len, worst_g1);
    free(f.buf);
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* The measurement behind SILK_FEATURE_TURN_DEG (docs/formats.md): the turn
 * at every vertex with two feature edges of the coarse models, largest
 * first, and how many of them the curve now has a kink at (its two segments
 * do not leave in one line).  Where the polyline stops on a regular polygon
 * both ends take the same circle and no kink shows, so the kinks are only
 * checked where there must be none (turns of 40 degrees or less); whether
 * the core stops exactly where the rule says is shared_meshes_vs_reference's
 * check. */
TEST(turn_angles_on_shared_meshes)
{
    static const char *const names[] = {
        "fandisk-128", "knot-480", "cone-70", "pawn-304", "wingnut-500", "rockerarm-500", "bunny-500", "cat-500",
        "cow-500", "spot-500", "armadillo-500", "dragon-500", "fish-500", "venus-500", "feline-500",
        "maxplanck-500", "springer-500", "sphere-200", "torus-576",
    };
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    printf("  %-14s %5s %5s %5s %6s  turns (deg), largest first\n", "mesh", "two", ">45", "44-46", "kinked");
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, names[i]), "cannot read %s", names[i]);
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", names[i], f.err.msg); continue; }
        const silk_mesh *m = &f.m;
        double *turn = malloc(sizeof *turn * (m->nverts + 1));
        uint32_t n = 0, over = 0, near = 0, kinked = 0;
        for (uint32_t v = 0; v < m->nverts; v++) {
            double t = turn_at(m, v);
            if (t < 0) continue;
            turn[n++] = t;
            over += t > TURN_DEG;
            near += fabs(t - TURN_DEG) < 1;
            double slack, kink = PI - meet_angle(m, v, &slack);
            kinked += kink > 1e-4 + slack;
            if (t <= 40) CHECKF(kink <= 1e-4 + slack, "%s vertex %u turns %.1f deg, kink %.3g rad", names[i], v, t, kink);
        }
        qsort(turn, n, sizeof *turn, cmp_desc);
        char list[96] = "";
        int len_ = 0;
        for (uint32_t k = 0; k < n && k < 8 && len_ < 80; k++)
            len_ += snprintf(list + len_, sizeof list - (size_t)len_, "%s%.1f", k ? " " : "", turn[k]);
        printf("  %-14s %5u %5u %5u %6u  %s%s\n", names[i], n, over, near, kinked, list, n > 8 ? " ..." : "");
        if (!strcmp(names[i], "cone-70")) {
            /* the rim: 35 turns of 360/35 degrees (up to the file's 7 digits), one closed loop */
            CHECKF(n == 35 && kinked == 0 && fabs(turn[0] - 360.0 / 35) < 0.02 && fabs(turn[34] - 360.0 / 35) < 0.02,
                   "cone rim: %u vertices, turns %.4f..%.4f, %u kinks", n, turn[n ? n - 1 : 0], turn[0], kinked);
        }
        free(turn);
    }
    free(f.buf);
}

/* ---- how far feature segments stray from their chords ---------------------------------- */

/* Largest distance of the Hermite curve p0 t0 t1 p1 from the segment p0 p1,
 * over the chord's length. */
static double seg_dist(dvec p, dvec a, dvec b)
{
    dvec ab = dsub(b, a);
    double t = ddot(dsub(p, a), ab) / ddot(ab, ab);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return dlen(dsub(p, dadd(a, dscale(ab, t))));
}
static double bulge(dvec p0, dvec p1, dvec t0, dvec t1)
{
    double worst = 0;
    for (int i = 1; i < 64; i++) worst = fmax(worst, seg_dist(hermite(p0, p1, t0, t1, i / 64.0), p0, p1));
    return worst / dlen(dsub(p1, p0));
}

/* A camera looking at the model's bounding-box centre from direction dir,
 * 3 bounding radii away. */
static int view_from(const silk_mesh *m, dvec dir, silk_view *v)
{
    dvec lo = dv(m->bbox_min), hi = dv(m->bbox_max), c = dscale(dadd(lo, hi), 0.5);
    double r = dlen(dsub(hi, lo)) / 2;
    dvec eye = dadd(c, dscale(dir, 3 * r / dlen(dir)));
    silk_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(d2fx(eye.x), d2fx(eye.y), d2fx(eye.z));
    cam.target = silk_v3(d2fx(c.x), d2fx(c.y), d2fx(c.z));
    cam.up = fabs(dir.y / dlen(dir)) > 0.9 ? silk_v3(SILK_FX_ONE, 0, 0) : silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(45, 1);
    cam.znear = d2fx(r * 0.01);
    cam.zfar = d2fx(r * 8);
    cam.width = 256;
    cam.height = 256;
    silk_error err;
    return silk_view_init(v, &cam, &err) == SILK_OK;
}

/* The feature edge whose ends are at p0 and p1 (either way round), or
 * SILK_NO_INDEX. */
static uint32_t feature_edge_at(const silk_mesh *m, silk_vec3 p0, silk_vec3 p1)
{
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(m, e)) continue;
        silk_vec3 a = m->pos[m->edge[e].v[0]], b = m->pos[m->edge[e].v[1]];
        if ((!memcmp(&a, &p0, sizeof a) && !memcmp(&b, &p1, sizeof b)) ||
            (!memcmp(&a, &p1, sizeof a) && !memcmp(&b, &p0, sizeof b)))
            return e;
    }
    return SILK_NO_INDEX;
}

/* Every tangent of a polyline lies within the turn limit of its chord: at an
 * inner vertex the circle's tangent lies between the two chords, at an end
 * it is the mirror image of the next one, a single edge is straight.  A
 * Hermite segment with eq. 4 tangents within theta of its chord strays from
 * the chord by at most u(1-u) |t x chord| / |chord| <= tan(theta / 2) / 2
 * chords, 0.207 for 45 degrees.  fandisk-128 under the old rule (its 166
 * degree corner as an inner vertex) loops far beyond that.  Checked on the
 * stored segments, on the curves the smooth frames draw over feature edges
 * from eight views, and on the points they sample. */
TEST(fandisk_feature_segments_near_their_chords)
{
    const double limit = tan(TURN_DEG / 2 * PI / 180) / 2;
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    CHECK(tm_fixture_read_shared(&f, "fandisk-128"));
    if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "fandisk-128: %s", f.err.msg); free(f.buf); return; }
    const silk_mesh *m = &f.m;
    double stored = 0, ref_new = 0, ref_old = 0, chord_min = 1e30;
    uint32_t over_old = 0, worst_e = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(m, e)) continue;
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        dvec p0 = vpos(m, m->edge[e].v[0]), p1 = vpos(m, m->edge[e].v[1]), ta, tb;
        chord_min = fmin(chord_min, dlen(dsub(p1, p0)));
        double b = bulge(p0, p1, dv(s->t0), dv(s->t1));
        if (b > stored) stored = b, worst_e = e;
        if (ref_tangents(m, e, 1, &ta, &tb)) ref_new = fmax(ref_new, bulge(p0, p1, ta, tb));
        ref_tangents(m, e, 0, &ta, &tb);
        double bo = bulge(p0, p1, ta, tb);
        ref_old = fmax(ref_old, bo);
        over_old += bo > limit;
    }
    /* rounding: the stored tangents and the evaluated points carry a few ulp */
    double slack = 4 * ULP / chord_min;
    CHECKF(stored <= limit + slack, "edge %u strays %.3f chords from its chord (limit %.3f)", worst_e, stored, limit);

    static const double dirs[8][3] = { { 1, 0.3, 0.2 }, { -1, 0.2, 0.4 }, { 0.2, 1, 0.1 }, { 0.1, -1, 0.3 },
                                       { 0.3, 0.2, 1 }, { 0.2, 0.1, -1 }, { 1, 1, 1 }, { -1, -0.7, 0.5 } };
    double drawn = 0, sampled = 0;
    uint32_t ncurves = 0, npoints = 0;
    for (int i = 0; i < 8; i++) {
        silk_view v;
        if (!view_from(m, dmk(dirs[i][0], dirs[i][1], dirs[i][2]), &v)) { CHECK(0); break; }
        silk_arena_mark mk = silk_arena_top_mark(&f.a);
        silk_frame_geom g;
        silk_frame_stats st;
        silk_error err;
        memset(&st, 0, sizeof st);
        if (silk_frame_smooth(&f.a, m, &v, SILK_FX_HALF, SILK_VIS_BRUTE, &g, &st, &err) != SILK_OK) {
            CHECKF(0, "view %d: %s", i, err.msg);
            break;
        }
        CHECK(!st.fell_back);
        uint8_t *on_feature = calloc(g.ncurve + 1, 1);
        for (uint32_t c = 0; c < g.ncurve; c++) {
            const silk_curve *cv = &g.curve[c];
            if (feature_edge_at(m, cv->p0, cv->p1) == SILK_NO_INDEX) continue;
            on_feature[c] = 1;
            ncurves++;
            dvec p0 = dv(cv->p0), p1 = dv(cv->p1);
            double worst = 0;
            for (int k = 1; k < 64; k++)   /* as the renderer evaluates it */
                worst = fmax(worst, seg_dist(dv(silk_hermite_point(cv, SILK_FX_ONE * k / 64)), p0, p1));
            drawn = fmax(drawn, worst / dlen(dsub(p1, p0)));
        }
        silk_geom gg = { .mesh = m, .curves = g.curve, .offsets = g.offset };
        for (uint32_t r = 0; r < g.nvrec; r++) {
            const silk_vrec *rec = &g.vrec[r];
            if (rec->kind != SILK_VREC_CURVE || rec->a >= g.ncurve || !on_feature[rec->a]) continue;
            silk_vertex_attr at;
            silk_vrec_eval(&gg, rec, &at);
            const silk_curve *cv = &g.curve[rec->a];
            dvec p0 = dv(cv->p0), p1 = dv(cv->p1);
            sampled = fmax(sampled, seg_dist(dv(at.pos), p0, p1) / dlen(dsub(p1, p0)));
            npoints++;
        }
        free(on_feature);
        silk_arena_top_release(&f.a, &mk);
    }
    CHECKF(ncurves > 0 && npoints > 0, "no feature curves drawn (%u, %u points)", ncurves, npoints);
    CHECKF(drawn <= limit + slack && sampled <= limit + slack, "drawn feature curves stray %.3f, their points %.3f",
           drawn, sampled);
    printf("  fandisk-128, %u feature segments: worst %.3f chords from the chord (limit %.3f; reference %.3f; "
           "the old stop rule: %.3f, %u segments over the limit)\n", m->nfeature_edges, stored, limit, ref_new,
           ref_old, over_old);
    printf("  8 views: %u feature curves drawn, worst %.3f chords; %u points sampled on them, worst %.3f\n", ncurves,
           drawn, npoints, sampled);
    free(f.buf);
}

/* Straight stays straight: a crease along a straight line of unevenly
 * spaced vertices in a random direction (coordinates rounded to Q16.16, so
 * not exactly collinear), and the strip's straight boundaries: every
 * feature segment is exactly its chord, t0 = t1 = the end points'
 * difference, bit for bit, so eq. 5 draws the straight edge itself. */
TEST(straight_polylines_are_exactly_straight)
{
    for (int round = 0; round < 20; round++) {
        dvec u, w, n;
        random_frame(&u, &w, &n);
        dvec o = dmk(check_uniform(-2, 2), check_uniform(-2, 2), check_uniform(-2, 2));
        enum { K = 7 };
        double pos[3 * 3 * K], at = 0;
        uint32_t tri[3 * 4 * (K - 1)], nt = 0;
        for (uint32_t i = 0; i < K; i++) {
            dvec c = dadd(o, dscale(u, at));
            put(pos, 3 * i, c);                                                 /* the crease */
            put(pos, 3 * i + 1, dadd(c, dscale(w, 0.4)));                       /* one face */
            put(pos, 3 * i + 2, dadd(c, dadd(dscale(w, -0.2), dscale(n, 0.35))));   /* the other, 60 degrees on */
            at += check_uniform(0.1, 0.9);
        }
        for (uint32_t i = 0; i + 1 < K; i++) {
            uint32_t c0 = 3 * i, c1 = 3 * i + 3;
            uint32_t t[12] = { c0, c1, c0 + 1, c0 + 1, c1, c1 + 1, c1, c0, c0 + 2, c1, c0 + 2, c1 + 2 };
            memcpy(&tri[3 * nt], t, sizeof t);
            nt += 4;
        }
        tm_fixture f;
        tm_fixture_init(&f, 1 << 18);
        CHECK(tm_fixture_input(&f, pos, 3 * K, tri, nt) && tm_fixture_build(&f) == SILK_OK);
        uint32_t crooked = 0, checked = 0;
        for (uint32_t e = 0; e < f.m.nedges; e++) {
            if (!(f.m.edge[e].flags & SILK_EDGE_FEATURE)) continue;
            const silk_feature_seg *sg = &f.m.feature[f.m.edge_feature[e]];
            silk_vec3 chord = silk_v3_sub(f.m.pos[f.m.edge[e].v[1]], f.m.pos[f.m.edge[e].v[0]]);
            checked++;
            crooked += memcmp(&sg->t0, &chord, sizeof chord) != 0 || memcmp(&sg->t1, &chord, sizeof chord) != 0;
        }
        CHECKF(crooked == 0 && checked >= 3 * (K - 1), "round %d: %u of %u feature segments are not their chord", round,
               crooked, checked);
        free(f.buf);
    }
}

int main(void)
{
    RUN(closed_loop_on_a_circle);
    RUN(open_arc_with_junction_ends);
    RUN(single_edge_stays_straight);
    RUN(straight_polylines_are_exactly_straight);
    RUN(sharp_corner_breaks_the_polyline);
    RUN(octagon_stays_one_smooth_loop);
    RUN(shared_meshes_vs_reference);
    RUN(turn_angles_on_shared_meshes);
    RUN(fandisk_feature_segments_near_their_chords);
    return check_done();
}
