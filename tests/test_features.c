/*
 * test_features.c - feature polylines and their Hermite tangents (paper
 * III-A, eqs. 1 and 4) against a double reference that takes each tangent
 * from the circumscribed circle directly (not from eq. 1), and the point of
 * eq. 4: feature segments over points of a circle stay on the circle.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"

#define ARENA_BYTES (48u << 20)
#define PI 3.14159265358979323846
#define ULP (1.0 / 65536)

static silk_fx to_fx(double d) { return (silk_fx)llround(d * 65536.0); }
static double fx_d(silk_fx v) { return v / 65536.0; }

typedef struct fixture {
    void *buf;
    silk_arena a;
    silk_mesh_input in;
    silk_load_opts opts;
    silk_mesh m;
    silk_error err;
} fixture;

static void fx_init(fixture *f, size_t bytes)
{
    memset(f, 0, sizeof *f);
    f->buf = malloc(bytes);
    silk_arena_init(&f->a, f->buf, bytes);
    silk_load_opts_default(&f->opts);
}

static void fx_reset(fixture *f)
{
    silk_arena_init(&f->a, f->buf, ARENA_BYTES);
    memset(&f->in, 0, sizeof f->in);
    memset(&f->m, 0, sizeof f->m);
}

static int fx_input(fixture *f, const double *pos, uint32_t nv, const uint32_t *tri, uint32_t nt)
{
    f->in.nverts = nv;
    f->in.ntris = nt;
    f->in.pos = silk_arena_array(&f->a, nv, sizeof(silk_vec3), SILK_MEM_MESH);
    f->in.tri = silk_arena_array(&f->a, 3 * (size_t)nt, sizeof(silk_index), SILK_MEM_MESH);
    if (!f->in.pos || !f->in.tri) return 0;
    for (uint32_t v = 0; v < nv; v++)
        f->in.pos[v] = silk_v3(to_fx(pos[3 * v]), to_fx(pos[3 * v + 1]), to_fx(pos[3 * v + 2]));
    for (uint32_t c = 0; c < 3 * nt; c++) f->in.tri[c] = tri[c];
    return 1;
}

static silk_status fx_build(fixture *f) { return silk_mesh_build(&f->in, "test", &f->opts, &f->a, &f->m, &f->err); }

/* Minimal reader for the shared meshes (only `v` and `f` lines). */
static int read_obj(const char *name, fixture *f)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.obj", check_meshes_dir(), name);
    FILE *fp = fopen(path, "rb");
    if (!fp) return 0;
    fseek(fp, 0, SEEK_END);
    long len = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *text = malloc((size_t)len + 1);
    size_t got = fread(text, 1, (size_t)len, fp);
    fclose(fp);
    text[got] = 0;
    uint32_t nv = 0, nt = 0;
    for (char *l = text; *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : l + strlen(l)) {
        if (l[0] == 'v' && l[1] == ' ') nv++;
        if (l[0] == 'f' && l[1] == ' ') nt++;
    }
    double *pos = malloc(3 * sizeof(double) * (nv ? nv : 1));
    uint32_t *tri = malloc(3 * sizeof(uint32_t) * (nt ? nt : 1));
    uint32_t iv = 0, it = 0;
    for (char *l = text; *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : l + strlen(l)) {
        char *p = l + 2;
        if (l[0] == 'v' && l[1] == ' ') {
            for (int k = 0; k < 3; k++) pos[3 * iv + k] = strtod(p, &p);
            iv++;
        } else if (l[0] == 'f' && l[1] == ' ') {
            for (int k = 0; k < 3; k++) tri[3 * it + k] = (uint32_t)strtoul(p, &p, 10) - 1;
            it++;
        }
    }
    int ok = fx_input(f, pos, nv, tri, nt);
    free(text);
    free(pos);
    free(tri);
    return ok;
}

/* ---- vectors in double ------------------------------------------------------------------- */

typedef struct d3 { double x, y, z; } d3;

static d3 dv(double x, double y, double z) { d3 r = { x, y, z }; return r; }
static d3 add(d3 a, d3 b) { return dv(a.x + b.x, a.y + b.y, a.z + b.z); }
static d3 sub(d3 a, d3 b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static d3 scale(d3 a, double s) { return dv(a.x * s, a.y * s, a.z * s); }
static double dot(d3 a, d3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static d3 cross(d3 a, d3 b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static double len(d3 a) { return sqrt(dot(a, a)); }
static d3 of_fx(silk_vec3 v) { return dv(fx_d(v.x), fx_d(v.y), fx_d(v.z)); }
static d3 vpos(const silk_mesh *m, uint32_t v) { return of_fx(m->pos[v]); }

static double angle_between(d3 a, d3 b)
{
    double c = dot(a, b) / (len(a) * len(b));
    return acos(c > 1 ? 1 : (c < -1 ? -1 : c));
}

/* Eq. 5 */
static d3 hermite(d3 p0, d3 p1, d3 t0, d3 t1, double u)
{
    double u2 = u * u, u3 = u2 * u;
    return add(add(scale(p0, 2 * u3 - 3 * u2 + 1), scale(t0, u3 - 2 * u2 + u)),
               add(scale(p1, -2 * u3 + 3 * u2), scale(t1, u3 - u2)));
}

/* The tangent at x (one of p, q, r, travelled in that order) of the circle
 * through p, q, r: the travel normal crossed with the radius, from the
 * circumcentre.  Straight points give the chord. */
static d3 circle_tangent(d3 p, d3 q, d3 r, d3 x)
{
    d3 a = sub(p, r), b = sub(q, r), axb = cross(a, b);
    double l2 = dot(axb, axb);
    if (l2 <= 1e-24 * dot(a, a) * dot(b, b)) return sub(r, p);
    d3 o = add(r, scale(cross(sub(scale(b, dot(a, a)), scale(a, dot(b, b))), axb), 1 / (2 * l2)));
    d3 n = cross(sub(q, p), sub(r, q));
    return cross(n, sub(x, o));
}

/* Eq. 4 with curve.h's clamp (SILK_ARC_MAX_RATIO = 4 chord lengths). */
static d3 arc_length_scaled(d3 dir, d3 chord)
{
    double lc = len(chord), c = dot(dir, chord) / (len(dir) * lc);
    double l = 2 * lc / (1 + c);
    if (!(l < 4 * lc)) l = 4 * lc;
    return scale(dir, l / len(dir));
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

typedef struct feat_report {
    double dir_ulp, len_ulp;   /* worst tangent error in ulp: direction (angle times the
                                  tangent's length) and length */
    uint32_t checked, skipped;
} feat_report;

/* Compare every feature segment of m with the reference; a stored tangent
 * may be off by ulp_bound ulp in direction and in length.  Turns sharper
 * than 120 degrees (where eq. 1 and the circle both break down, and
 * features.c falls back to one side) are skipped and counted. */
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
        uint32_t a = m->edge[e].v[0], b = m->edge[e].v[1];
        d3 pa = vpos(m, a), pb = vpos(m, b), chord = sub(pb, pa);
        uint32_t da = feature_degree(m, a), db = feature_degree(m, b);
        d3 ta, tb;
        int sharp = 0;
        if (da == 2) {
            d3 pp = vpos(m, beyond(m, a, e));
            ta = circle_tangent(pp, pa, pb, pa);
            sharp |= angle_between(sub(pa, pp), chord) > 2 * PI / 3;
        }
        if (db == 2) {
            d3 pn = vpos(m, beyond(m, b, e));
            tb = circle_tangent(pa, pb, pn, pb);
            if (da != 2) ta = circle_tangent(pa, pb, pn, pa);
            sharp |= angle_between(chord, sub(pn, pb)) > 2 * PI / 3;
        }
        if (da == 2 && db != 2) tb = circle_tangent(vpos(m, beyond(m, a, e)), pa, pb, pb);
        if (da != 2 && db != 2) ta = tb = chord;   /* a polyline of one edge stays straight */
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        /* eq. 4's clamp holds everywhere, hairpins included */
        double lmax = 4 * len(chord) + 2 * ULP;
        CHECKF(len(of_fx(s->t0)) <= lmax && len(of_fx(s->t1)) <= lmax, "edge %u tangents longer than 4 chords", e);
        if (sharp) { r->skipped++; continue; }
        r->checked++;
        ta = arc_length_scaled(ta, chord);
        tb = arc_length_scaled(tb, chord);
        d3 g0 = of_fx(s->t0), g1 = of_fx(s->t1);
        double ea = angle_between(g0, ta) * len(ta) / ULP, eb = angle_between(g1, tb) * len(tb) / ULP;
        double la = fabs(len(g0) - len(ta)) / ULP, lb = fabs(len(g1) - len(tb)) / ULP;
        CHECKF(ea <= ulp_bound && eb <= ulp_bound, "edge %u (%u-%u) tangent directions off by %.2f %.2f ulp", e,
               a, b, ea, eb);
        CHECKF(la <= ulp_bound && lb <= ulp_bound, "edge %u tangent lengths off by %.2f %.2f ulp", e, la, lb);
        r->dir_ulp = fmax(r->dir_ulp, fmax(ea, eb));
        r->len_ulp = fmax(r->len_ulp, fmax(la, lb));
    }
    CHECKF(m->nfeature_edges == nfe, "%u feature edges, %u segments", nfe, m->nfeature_edges);
}

/* G1: where a polyline passes through a vertex, its two segments leave with
 * the same tangent direction.  Returns the worst angle beyond the rounding
 * of the stored tangents. */
static double check_g1(const silk_mesh *m, double tol)
{
    double worst = 0;
    for (uint32_t v = 0; v < m->nverts; v++) {
        if (feature_degree(m, v) != 2) continue;
        d3 t[2];
        int n = 0;
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1] && n < 2; i++) {
            uint32_t e = m->vert_edge[i];
            if (!is_feature(m, e)) continue;
            const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
            /* both as "leaving v" */
            t[n++] = m->edge[e].v[0] == v ? of_fx(s->t0) : scale(of_fx(s->t1), -1);
        }
        /* each tangent is rounded to Q16.16 as a whole vector: its direction
         * carries up to about 0.87 ulp / its length */
        double a = PI - angle_between(t[0], t[1]), slack = ULP / len(t[0]) + ULP / len(t[1]);
        CHECKF(a <= tol + slack, "vertex %u: segments meet at %.3g rad (slack %.3g)", v, a, slack);
        if (a - slack > worst) worst = a - slack;
    }
    return worst;
}

/* Largest distance of the feature segments of edges with both ends within
 * eps of the circle (centre c, unit normal n, radius rad) from that circle. */
static double circle_deviation(const silk_mesh *m, d3 c, d3 n, double rad, uint32_t *nseg)
{
    double worst = 0;
    *nseg = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (!is_feature(m, e)) continue;
        d3 p0 = vpos(m, m->edge[e].v[0]), p1 = vpos(m, m->edge[e].v[1]);
        int on = 1;
        for (int k = 0; k < 2; k++) {
            d3 d = sub(k ? p1 : p0, c);
            double h = dot(d, n), r = len(sub(d, scale(n, h)));
            on &= fabs(h) < 1e-3 && fabs(r - rad) < 1e-3 * rad;
        }
        if (!on) continue;
        (*nseg)++;
        const silk_feature_seg *s = &m->feature[m->edge_feature[e]];
        for (int i = 0; i <= 64; i++) {
            d3 d = sub(hermite(p0, p1, of_fx(s->t0), of_fx(s->t1), i / 64.0), c);
            double h = dot(d, n), r = len(sub(d, scale(n, h)));
            double dist = sqrt(h * h + (r - rad) * (r - rad));
            if (dist > worst) worst = dist;
        }
    }
    return worst;
}

/* ---- circles ------------------------------------------------------------------------------- */

/* Points of a circle, in the plane through c spanned by unit u and w. */
static d3 on_circle(d3 c, d3 u, d3 w, double rad, double ang)
{
    return add(c, add(scale(u, rad * cos(ang)), scale(w, rad * sin(ang))));
}

/* How far the exact eq. 4 Hermite curve over an arc of phi radians strays
 * from a circle of radius rad: the part of the deviation that is the
 * method's, not the fixed point's. */
static double ideal_arc_error(double rad, double phi)
{
    d3 p0 = dv(rad, 0, 0), p1 = dv(rad * cos(phi), rad * sin(phi), 0), chord = sub(p1, p0);
    d3 t0 = arc_length_scaled(dv(0, 1, 0), chord), t1 = arc_length_scaled(dv(-sin(phi), cos(phi), 0), chord);
    double worst = 0;
    for (int i = 0; i <= 256; i++) worst = fmax(worst, fabs(len(hermite(p0, p1, t0, t1, i / 256.0)) - rad));
    return worst;
}

static void put(double *pos, uint32_t v, d3 p)
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
    d3 c = dv(0.3, -0.2, 0.5), u = dv(0.6, 0.8, 0), w = dv(0, 0, 1);
    u = scale(u, 1 / len(u));
    w = cross(u, dv(-0.48, 0.36, 0.8));
    w = scale(w, 1 / len(w));
    d3 n = cross(u, w);
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
        fixture f;
        fx_init(&f, ARENA_BYTES);
        CHECK(fx_input(&f, pos, k + 1, tri, k) && fx_build(&f) == SILK_OK);
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
    d3 c = dv(-1, 2, 0.25), u = dv(1, 0, 0), w = dv(0, 1, 0), down = dv(0, 0, -0.7);
    double rad = 1.75, ang[64];
    uint32_t k = irregular_angles(ang, 40, 2.2, 6, 22);
    uint32_t nv = 1 + 2 * k, nt = (k - 1) * 3;
    double *pos = malloc(sizeof(double) * 3 * nv);
    uint32_t *tri = malloc(sizeof(uint32_t) * 3 * nt), t = 0;
    put(pos, 0, c);
    for (uint32_t i = 0; i < k; i++) {
        d3 p = on_circle(c, u, w, rad, ang[i]);
        put(pos, 1 + i, p);
        put(pos, 1 + k + i, add(p, down));
    }
    for (uint32_t i = 1; i < k; i++) {
        uint32_t p0 = i, p1 = i + 1, q0 = k + i, q1 = k + i + 1;
        tri[3 * t] = 0, tri[3 * t + 1] = p0, tri[3 * t + 2] = p1, t++;
        tri[3 * t] = p1, tri[3 * t + 1] = p0, tri[3 * t + 2] = q0, t++;
        tri[3 * t] = p1, tri[3 * t + 1] = q0, tri[3 * t + 2] = q1, t++;
    }
    fixture f;
    fx_init(&f, ARENA_BYTES);
    CHECK(fx_input(&f, pos, nv, tri, nt) && fx_build(&f) == SILK_OK);
    uint32_t creases = 0;
    for (uint32_t e = 0; e < f.m.nedges; e++) creases += (f.m.edge[e].flags & SILK_EDGE_CREASE) != 0;
    CHECK(creases == k - 1);
    CHECK(feature_degree(&f.m, 1) == 3 && feature_degree(&f.m, k) == 3);
    feat_report r;
    check_features(&f.m, 4, &r);
    uint32_t nseg;
    double dev = circle_deviation(&f.m, c, dv(0, 0, 1), rad, &nseg);
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
     * polyline of one edge (its ends also have two boundary edges) */
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.5, 0.70710678 };
    static const uint32_t tri[] = { 0, 1, 2, 0, 2, 3 };
    fixture f;
    fx_init(&f, 1 << 16);
    CHECK(fx_input(&f, pos, 4, tri, 2) && fx_build(&f) == SILK_OK);
    uint32_t e = f.m.tri_edge[2];
    CHECK(f.m.edge[e].flags & SILK_EDGE_CREASE);
    const silk_feature_seg *s = &f.m.feature[f.m.edge_feature[e]];
    silk_vec3 chord = silk_v3_sub(f.m.pos[2], f.m.pos[0]);
    CHECK(!memcmp(&s->t0, &chord, sizeof chord) && !memcmp(&s->t1, &chord, sizeof chord));
    feat_report r;
    check_features(&f.m, 4, &r);
    free(f.buf);
}

TEST(shared_meshes_vs_reference)
{
    static const char *const names[] = {
        "cone-70", "fandisk-128", "fandisk-1000", "fandisk-fine", "pawn-304", "wingnut-500", "rockerarm-500",
        "bunny-500", "dragon-500", "feline-500", "cow-500", "springer-500", "dragon-5k",
    };
    fixture f;
    fx_init(&f, ARENA_BYTES);
    double worst_dir = 0, worst_len = 0, worst_g1 = 0;
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        fx_reset(&f);
        CHECKF(read_obj(names[i], &f), "cannot read %s", names[i]);
        if (fx_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", names[i], f.err.msg); continue; }
        feat_report r;
        check_features(&f.m, 4, &r);
        double g1 = check_g1(&f.m, 1e-3);
        printf("  %-14s %4u feature edges (%3u sharp turns skipped): tangents off by %.2f / %.2f ulp, G1 %.2g rad"
               " beyond rounding\n",
               names[i], f.m.nfeature_edges, r.skipped, r.dir_ulp, r.len_ulp, g1);
        worst_dir = fmax(worst_dir, r.dir_ulp);
        worst_len = fmax(worst_len, r.len_ulp);
        worst_g1 = fmax(worst_g1, g1);
        if (!strcmp(names[i], "cone-70")) {
            uint32_t nseg;
            double dev = circle_deviation(&f.m, dv(0, 0, 0), dv(0, 1, 0), 1, &nseg);
            double ideal = ideal_arc_error(1, 2 * PI / 35);
            CHECKF(nseg == 35 && dev <= ideal + 2 * ULP, "cone rim: %u segments, off the circle by %.3g", nseg, dev);
            printf("  cone-70 rim: 35 segments, off the unit circle by %.2g (%.2f ulp)\n", dev, dev / ULP);
        }
    }
    printf("  worst: tangent direction %.2f ulp, length %.2f ulp, G1 %.2g rad beyond rounding\n", worst_dir,
           worst_len, worst_g1);
    free(f.buf);
}

int main(void)
{
    RUN(closed_loop_on_a_circle);
    RUN(open_arc_with_junction_ends);
    RUN(single_edge_stays_straight);
    RUN(shared_meshes_vs_reference);
    return check_done();
}
