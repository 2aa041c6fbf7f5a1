/*
 * test_stex.c - the host side of silhouette textures (tools/stex_*.c,
 * tools/prep/bvh.c) against double-precision references written here: ray hits
 * through the hierarchy against every triangle tried; the atlas (corners
 * inside it, texel centres on their charts, gutters around every chart);
 * the single-lobe encoding of a sphere inside a hull sphere, whose
 * visibility functions are cones of half-angle asin(r / |p|) towards the
 * centre (Wu et al., "Silhouette Texture", eq. 2) - every stored angle
 * within one angle unit of the cone's boundary plus one unit along its azimuth, eq. 3
 * near 0; two such spheres side by side, where a direction that passes one
 * sphere's hull to meet the other sphere is false (interior silhouettes); an
 * ellipsoid off centre, where the renderer's eq. 4 on the section's bytes
 * (silk/siltex.h) agrees with the builder's encoding and the true
 * visibility; the SVD compression's round trip; the section's layout.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/siltex.h"
#include "../tools/prep/bvh.h"
#include "../tools/prep/gen.h"
#include "../tools/prep/stex_build.h"
#include "../tools/prep/vec3.h"

static const double PI = 3.14159265358979323846;

static double frand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffffff) / 16777216.0;
}

static void free_mesh(simp_mesh *m)
{
    free(m->pos);
    free(m->tri);
}

static int sphere(int segments, int bands, double radius, simp_mesh *m)
{
    gen_params p;
    gen_defaults(GEN_SPHERE, &p);
    p.segments = segments, p.bands = bands, p.radius = radius;
    gen_mesh g;
    if (gen_build(&p, &g)) return -1;
    m->nverts = g.nverts, m->ntris = g.ntris, m->pos = g.pos, m->tri = g.tri, m->origin = NULL;
    return 0;
}

TEST(bvh_matches_brute_force)
{
    simp_mesh m;
    gen_params p;
    gen_defaults(GEN_KNOT, &p);
    gen_mesh g;
    CHECK(gen_build(&p, &g) == 0);
    m.nverts = g.nverts, m.ntris = g.ntris, m.pos = g.pos, m.tri = g.tri, m.origin = NULL;
    cp_tree t;
    CHECK(cp_build(&t, m.pos, m.tri, m.ntris) == 0);
    unsigned seed = 7;
    int hits = 0, bad = 0;
    for (int i = 0; i < 3000; i++) {
        double o[3], d[3];
        for (int k = 0; k < 3; k++) o[k] = 6 * frand(&seed) - 3, d[k] = 2 * frand(&seed) - 1 - o[k] / 3;
        uint32_t skip = i % 3 == 0 ? (uint32_t)(frand(&seed) * m.ntris) : BVH_NO_TRI;
        double tmax = i % 5 == 0 ? 2 : INFINITY, tmin = i % 7 == 0 ? 0.5 : 0;
        double best = INFINITY;
        uint32_t bt = BVH_NO_TRI, ht = BVH_NO_TRI;
        for (uint32_t f = 0; f < m.ntris; f++) {
            if (f == skip) continue;
            const uint32_t *v = &m.tri[3 * f];
            double h = ray_tri(o, d, &m.pos[3 * v[0]], &m.pos[3 * v[1]], &m.pos[3 * v[2]]);
            if (h > tmin && h < tmax && h < best) best = h, bt = f;
        }
        double h = bvh_ray(&t, o, d, tmin, tmax, skip, &ht);
        hits += best < INFINITY;
        if (!(h == best && (best == INFINITY || ht == bt))) bad++;
    }
    CHECKF(bad == 0, "%d of 3000 rays differ", bad);
    CHECKF(hits > 500, "only %d rays hit", hits);
    cp_free(&t);
    free_mesh(&m);
}

/* The texel's point on the hull. */
static void point_of(const stex *s, const simp_mesh *h, size_t t, double p[3])
{
    const uint32_t *v = &h->tri[3 * (size_t)s->atlas.tri[t]];
    const double *b = &s->atlas.bary[3 * t];
    for (int k = 0; k < 3; k++) p[k] = b[0] * h->pos[3 * v[0] + k] + b[1] * h->pos[3 * v[1] + k] + b[2] * h->pos[3 * v[2] + k];
}

TEST(atlas_charts_and_gutters)
{
    simp_mesh h;
    CHECK(sphere(16, 10, 1, &h) == 0);
    stex_atlas a;
    CHECK(stex_atlas_build(&h, 64, 64, &a) == 0);
    int outside = 0, off_chart = 0, bare = 0, inside = 0;
    for (uint32_t f = 0; f < h.ntris; f++)
        for (int k = 0; k < 3; k++)
            outside += a.uv[6 * f + 2 * k] >= 64 * 16 || a.uv[6 * f + 2 * k + 1] >= 64 * 16;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            size_t t = (size_t)y * 64 + x;
            if (a.tri[t] < 0 || !a.inside[t]) continue;
            inside++;
            /* the barycentric coordinates give back the texel's centre */
            double u = 0, v = 0;
            for (int k = 0; k < 3; k++) {
                u += a.bary[3 * t + k] * a.uv[6 * a.tri[t] + 2 * k] / 16.0;
                v += a.bary[3 * t + k] * a.uv[6 * a.tri[t] + 2 * k + 1] / 16.0;
            }
            off_chart += fabs(u - (x + 0.5)) > 1e-9 || fabs(v - (y + 0.5)) > 1e-9;
            /* a bilinear lookup from here never reaches an unfilled texel */
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < 64 && yy < 64) bare += a.tri[(size_t)yy * 64 + xx] < 0;
                }
        }
    /* charts keep their triangles' shapes: every side at the atlas's density */
    double worst = 0;
    for (uint32_t f = 0; f < h.ntris; f++)
        for (int k = 0; k < 3; k++) {
            int k1 = (k + 1) % 3;
            double du = (a.uv[6 * f + 2 * k1] - a.uv[6 * f + 2 * k]) / 16.0;
            double dv = (a.uv[6 * f + 2 * k1 + 1] - a.uv[6 * f + 2 * k + 1]) / 16.0, d[3];
            sub3(&h.pos[3 * h.tri[3 * f + k1]], &h.pos[3 * h.tri[3 * f + k]], d);
            worst = fmax(worst, fabs(hypot(du, dv) - a.density * len3(d)));
        }
    CHECKF(worst < 0.1, "a side is %.3f texels off", worst);
    CHECK(outside == 0);
    CHECKF(off_chart == 0, "%d texels off their chart", off_chart);
    CHECKF(bare == 0, "%d unfilled texels next to charts", bare);
    CHECKF(inside > 64 * 64 / 4, "only %d texels inside charts", inside);
    CHECK(a.ncharts > 0 && a.ncharts <= h.ntris / 2);   /* charts of several triangles */
    stex_atlas_free(&a);
    CHECK(stex_atlas_build(&h, 8, 8, &a) == -2);
    free_mesh(&h);

    /* a tetrahedron with a sliver face, flat once its corners are rounded to
     * 1/16 texel: every texel still gets a point on the hull */
    double pos[12] = { 0, 0, 0, 1, 0, 0, 0.5, 1e-6, 0, 0.5, 0.5, 1 };
    uint32_t tri[12] = { 0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3 };
    simp_mesh tet = { 4, 4, pos, tri, NULL };
    CHECK(stex_atlas_build(&tet, 16, 16, &a) == 0);
    int finite = 1;
    for (size_t t = 0; t < 256; t++)
        if (a.tri[t] >= 0) {
            double sum = a.bary[3 * t] + a.bary[3 * t + 1] + a.bary[3 * t + 2];
            finite &= fabs(sum - 1) < 1e-9 && a.bary[3 * t] >= 0 && a.bary[3 * t + 1] >= 0 && a.bary[3 * t + 2] >= 0;
        }
    CHECK(finite);
    stex_atlas_free(&a);
}

/* The angle from C along the great circle towards u (unit, u . C = 0) at
 * which it leaves the cone around A of half-angle beta (C inside it). */
static double cone_exit(const double *C, const double *u, const double *A, double beta)
{
    double a = dot3(C, A), b = dot3(u, A), r = hypot(a, b);
    return atan2(b, a) + acos(cos(beta) / r);
}

TEST(sphere_in_a_hull_sphere)
{
    const double R = 1, r = 0.6;
    simp_mesh fine, hull;
    CHECK(sphere(64, 48, r, &fine) == 0);
    CHECK(sphere(12, 8, R, &hull) == 0);
    stex_opts o;
    stex_opts_default(&o);
    o.atlas = 48, o.angles = 16, o.samples = 1024, o.quiet = 1;
    stex s;
    CHECK(stex_build(&fine, NULL, &hull, &o, &s) == 0);
    const double step = PI / 255;
    double worst = 0, worst_c = 1;
    size_t nt = (size_t)s.atlas.w * s.atlas.h, checked = 0;
    for (uint32_t v = 0; v < hull.nverts; v++) {
        double C[3], in[3];
        for (int k = 0; k < 3; k++) C[k] = s.frame[6 * v + k] / 16384.0, in[k] = -hull.pos[3 * v + k];
        worst_c = fmin(worst_c, dot3(C, in) / len3(C) / len3(in));
    }
    for (size_t t = 0; t < nt; t++) {
        if (s.atlas.tri[t] < 0) continue;
        double p[3], A[3];
        point_of(&s, &hull, t, p);
        double dist = len3(p), beta = asin(r / dist);
        for (int k = 0; k < 3; k++) A[k] = -p[k] / dist;
        const double *C = &s.basis[9 * t], *T = C + 3, *B = C + 6;
        for (int k = 0; k < s.k; k++) {
            double th = 2 * PI * k / s.k, u[3];
            for (int i = 0; i < 3; i++) u[i] = cos(th) * T[i] + sin(th) * B[i];
            /* stored: the boundary plus one unit, rounded */
            double e = fabs(s.angles[t * s.k + k] * step - cone_exit(C, u, A, beta) - step);
            if (e > worst) worst = e;
        }
        checked++;
    }
    CHECKF(worst_c > 0.99, "a vertex's C is %.4f off inward", worst_c);   /* the texels' mean, near the axis */
    CHECKF(worst <= step, "an angle is off by %.3f units", worst / step);
    CHECKF(s.error < 0.005, "eq. 3 error %.5f", s.error);
    CHECK(s.multi_share == 0);
    CHECK(checked > nt / 4);
    printf("  sphere in a sphere: worst angle %.2f units, eq. 3 error %.5f over %u texels\n", worst / step, s.error,
           s.texels_in);

    /* the section: the layout of docs/formats.md */
    size_t size;
    uint8_t *b = stex_section(&s, NULL, s.error, &size);
    CHECK(b != NULL);
    CHECK(size == stex_section_bytes(&s, 0) && size % 4 == 0);
    CHECK(size == ((32 + 12 * (size_t)hull.nverts + 12 * (size_t)hull.ntris + nt * (16 + 2) + 3) & ~(size_t)3));
    CHECK(b[0] == 1 && b[4] == 0 && b[8] == 48 && b[10] == 48 && b[12] == 16 && b[14] == 0);
    CHECK((b[16] | b[17] << 8) == (int)hull.nverts && (b[20] | b[21] << 8) == (int)hull.ntris);
    uint32_t ppm = b[24] | b[25] << 8 | b[26] << 16 | (uint32_t)b[27] << 24;
    CHECK(ppm == (uint32_t)lround(s.error * 1e6));
    size_t angles_at = 32 + 12 * (size_t)hull.nverts + 12 * (size_t)hull.ntris;
    CHECK(memcmp(b + angles_at, s.angles, nt * s.k) == 0);
    int16_t c0 = (int16_t)(b[32] | b[33] << 8);
    CHECK(c0 == s.frame[0]);
    free(b);

    /* compressed: the angles the section's bytes give back by the formula are the expansion's */
    uint8_t *used = malloc(nt), *back = malloc(nt * s.k), *again = malloc(nt * s.k);
    stex_svd c;
    for (size_t t = 0; t < nt; t++) used[t] = s.atlas.tri[t] >= 0;
    CHECK(stex_svd_compress(s.angles, used, (uint32_t)nt, s.k, 4, &c) == 0);
    stex_svd_expand(&c, back);
    b = stex_section(&s, &c, 0, &size);
    CHECK(size == stex_section_bytes(&s, 4) && b[4] == 1 && b[14] == 4);
    const uint8_t *at = b + angles_at;
    int16_t mean[16], v[4 * 16];
    int32_t sc[4];
    for (int k = 0; k < 16; k++, at += 2) mean[k] = (int16_t)(at[0] | at[1] << 8);
    for (int e = 0; e < 4; e++, at += 4) sc[e] = (int32_t)(at[0] | at[1] << 8 | at[2] << 16 | (uint32_t)at[3] << 24);
    for (int i = 0; i < 4 * 16; i++, at += 2) v[i] = (int16_t)(at[0] | at[1] << 8);
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 16; k++)
            again[t * 16 + k] = stex_svd_angle(mean, sc, v, (const int8_t *)at + 4 * t, 16, 4, k);
    CHECK(memcmp(back, again, nt * s.k) == 0);
    CHECK(stex_psnr(&s, back) > 25);
    printf("  4 eigenfunctions: eq. 3 error %.5f, PSNR %.1f dB\n", stex_error(&s, back), stex_psnr(&s, back));
    stex_svd_free(&c);
    free(b), free(used), free(back), free(again);
    stex_free(&s);
    free_mesh(&fine);
    free_mesh(&hull);
}

/* Two copies of m side by side, the second moved by dx along x. */
static int twice(simp_mesh *m, double dx)
{
    double *pos = malloc(6 * (size_t)m->nverts * sizeof *pos);
    uint32_t *tri = malloc(6 * (size_t)m->ntris * sizeof *tri);
    if (!pos || !tri) return -1;
    for (uint32_t i = 0; i < 3 * m->nverts; i++) pos[i] = m->pos[i], pos[3 * m->nverts + i] = m->pos[i] + (i % 3 == 0 ? dx : 0);
    for (uint32_t i = 0; i < 3 * m->ntris; i++) tri[i] = m->tri[i], tri[3 * m->ntris + i] = m->tri[i] + m->nverts;
    free(m->pos), free(m->tri);
    m->pos = pos, m->tri = tri, m->nverts *= 2, m->ntris *= 2;
    return 0;
}

/* Whether the ray o + t d (t > 0) meets the sphere (c, r). */
static int ray_sphere(const double *o, const double *d, const double *c, double r)
{
    double oc[3];
    sub3(o, c, oc);
    double b = dot3(oc, d), disc = b * b - (dot3(oc, oc) - r * r);
    return disc >= 0 && -b + sqrt(disc) > 0;
}

TEST(interior_silhouettes)
{
    /* Two spheres in their hull spheres, side by side.  From a point on the
     * first hull, a direction that misses the first sphere leaves its hull
     * before it can reach the second sphere: false (eq. 2), though the
     * detailed mesh lies along it. */
    const double r = 0.6, gap = 2.5, ca[3] = { 0, 0, 0 }, cb[3] = { gap, 0, 0 };
    simp_mesh fine, hull;
    CHECK(sphere(48, 32, r, &fine) == 0 && twice(&fine, gap) == 0);
    CHECK(sphere(12, 8, 1, &hull) == 0 && twice(&hull, gap) == 0);
    stex_opts o;
    stex_opts_default(&o);
    o.atlas = 64, o.samples = 256, o.quiet = 1;
    stex s;
    CHECK(stex_build(&fine, NULL, &hull, &o, &s) == 0);
    size_t nt = (size_t)s.atlas.w * s.atlas.h, row = (size_t)(s.nsamples + 7) / 8;
    long wrong = 0, total = 0, behind = 0;
    for (size_t t = 0; t < nt; t++) {
        if (s.atlas.tri[t] < 0 || !s.atlas.inside[t]) continue;
        double p[3];
        point_of(&s, &hull, t, p);
        const double *c = p[0] < gap / 2 ? ca : cb, *other = p[0] < gap / 2 ? cb : ca;
        for (int i = 0; i < s.nsamples; i++) {
            const double *d = &s.samples[3 * i];
            int want = ray_sphere(p, d, c, r), got = (s.vf[t * row + i / 8] >> (i % 8)) & 1;
            behind += !want && ray_sphere(p, d, other, r);
            wrong += want != got;
            total++;
        }
    }
    CHECKF(wrong < total / 500, "%ld of %ld directions wrong", wrong, total);
    CHECKF(behind > 1000, "only %ld directions reach the other sphere", behind);
    printf("  two spheres: %ld of %ld directions differ from the analytic cones, %ld pass the other sphere\n", wrong,
           total, behind);
    stex_free(&s);
    free_mesh(&fine);
    free_mesh(&hull);
}

/* Whether the ray o + t d (t > 0) meets the ellipsoid of semi-axes ax
 * along the orthonormal rows of R, centred at c. */
static int ray_ellipsoid(const double *o, const double *d, const double *c, const double R[9], const double ax[3])
{
    double oc[3], lo[3], ld[3];
    sub3(o, c, oc);
    for (int i = 0; i < 3; i++) lo[i] = dot3(&R[3 * i], oc) / ax[i], ld[i] = dot3(&R[3 * i], d) / ax[i];
    double a = dot3(ld, ld), b = dot3(lo, ld), disc = b * b - a * (dot3(lo, lo) - 1);
    return disc >= 0 && -b + sqrt(disc) > 0;
}

/* d turned by angle a towards the unit direction e of its own plane. */
static void tilt(const double *d, double a, int i, double out[3])
{
    double axis[3] = { i == 0, i == 1, i == 2 }, e[3];
    cross3(d, axis, e);
    if (len3(e) < 1e-6) axis[0] = 1, axis[1] = axis[2] = 0, cross3(d, axis, e);
    double l = len3(e);
    for (int k = 0; k < 3; k++) e[k] /= l;
    for (int k = 0; k < 3; k++) out[k] = cos(a) * d[k] + sin(a) * e[k];
}

TEST(runtime_lookup_agrees_with_the_encoding)
{
    /* An ellipsoid, turned and off centre, in a hull sphere: its visibility
     * functions are lobes neither round nor centred on C, so any difference
     * between the builder's conventions and the renderer's (azimuth
     * direction, T/B handedness, atlas units, texel centres, the sign of
     * d) shows.  At the centre of every texel inside a chart, the
     * renderer's eq. 4 (silk_siltex_visible on the section's bytes, C and
     * T interpolated as the vertex stage does) must agree with the
     * builder's decision away from the stored boundary, and with the true
     * visibility away from the true boundary. */
    const double c[3] = { 0.12, -0.06, 0.09 }, ax[3] = { 0.72, 0.42, 0.3 };
    const double ca = cos(0.6), sa = sin(0.6), cb = cos(0.4), sb = sin(0.4);
    const double R[9] = { ca, sa, 0, -sa * cb, ca * cb, sb, sa * sb, -ca * sb, cb };
    simp_mesh fine, hull;
    CHECK(sphere(48, 32, 1, &fine) == 0);
    for (uint32_t i = 0; i < fine.nverts; i++) {
        double *q = &fine.pos[3 * i], l[3] = { q[0] * ax[0], q[1] * ax[1], q[2] * ax[2] };
        for (int k = 0; k < 3; k++) q[k] = c[k] + R[k] * l[0] + R[3 + k] * l[1] + R[6 + k] * l[2];
    }
    CHECK(sphere(12, 8, 1, &hull) == 0);
    stex_opts o;
    stex_opts_default(&o);
    o.atlas = 48, o.samples = 256, o.quiet = 1;
    stex s;
    CHECK(stex_build(&fine, NULL, &hull, &o, &s) == 0);
    size_t size, nt = (size_t)s.atlas.w * s.atlas.h;
    uint8_t *b = stex_section(&s, NULL, s.error, &size);
    CHECK(b != NULL);
    silk_siltex st;
    memset(&st, 0, sizeof st);
    st.w = (uint32_t)s.atlas.w, st.h = (uint32_t)s.atlas.h, st.k = (uint32_t)s.k;
    st.nverts = hull.nverts, st.ntris = hull.ntris, st.bytes = (uint32_t)size;
    st.frame = b + 32;
    st.uv = st.frame + 12 * (size_t)hull.nverts;
    st.angles = st.uv + 12 * (size_t)hull.ntris;
    st.normal = st.angles + nt * s.k;
    const double step = PI / 255, near = 1.5 * PI / 180;
    long runtime_vs_host = 0, runtime_vs_true = 0, compared_host = 0, compared_true = 0, seen = 0;
    unsigned seed = 11;
    for (size_t t = 0; t < nt; t++) {
        if (s.atlas.tri[t] < 0 || !s.atlas.inside[t]) continue;
        double p[3];
        point_of(&s, &hull, t, p);
        const uint32_t *v = &hull.tri[3 * (size_t)s.atlas.tri[t]];
        const double *w = &s.atlas.bary[3 * t];
        silk_fx cf[3], tf[3];
        for (int k = 0; k < 3; k++) {
            double cs = 0, ts = 0;
            for (int i = 0; i < 3; i++) cs += w[i] * s.frame[6 * v[i] + k] * 4, ts += w[i] * s.frame[6 * v[i] + 3 + k] * 4;
            cf[k] = (silk_fx)lround(cs), tf[k] = (silk_fx)lround(ts);
        }
        silk_fx u = (silk_fx)((2 * (t % st.w) + 1) << 15), vv = (silk_fx)((2 * (t / st.w) + 1) << 15);
        for (int i = 0; i < 64; i++) {
            /* directions about C, most within the lobe's reach */
            const double *C = &s.basis[9 * t];
            double d[3], r[3] = { frand(&seed) - 0.5, frand(&seed) - 0.5, frand(&seed) - 0.5 };
            double spread = 0.9 * frand(&seed);
            for (int k = 0; k < 3; k++) d[k] = C[k] + spread * r[k] / (len3(r) + 1e-9);
            double l = len3(d);
            for (int k = 0; k < 3; k++) d[k] /= l;
            int64_t d64[3] = { lround(d[0] * 65536), lround(d[1] * 65536), lround(d[2] * 65536) };
            int got = silk_siltex_visible(&st, u, vv, cf, tf, d64);
            seen += got;
            double z = dot3(d, C), a = acos(z > 1 ? 1 : z), phi = stex_phi(&s, s.angles, t, d);
            if (fabs(a - phi) > step) {
                compared_host++;
                runtime_vs_host += got != (a <= phi);
            }
            int want = ray_ellipsoid(p, d, c, R, ax), edge = 0;
            for (int j = 0; j < 6 && !edge; j++) {
                double e[3];
                tilt(d, j < 3 ? near : -near, j % 3, e);
                edge = ray_ellipsoid(p, e, c, R, ax) != want;
            }
            if (!edge) {
                compared_true++;
                runtime_vs_true += got != want;
            }
        }
    }
    printf("  ellipsoid: renderer vs builder %ld of %ld directions differ, vs the true visibility %ld of %ld (%ld seen)\n",
           runtime_vs_host, compared_host, runtime_vs_true, compared_true, seen);
    CHECK(seen > compared_true / 8);
    CHECKF(runtime_vs_host <= compared_host / 2000, "renderer and builder differ at %ld of %ld directions",
           runtime_vs_host, compared_host);
    CHECKF(runtime_vs_true <= compared_true / 200, "renderer and the true visibility differ at %ld of %ld directions",
           runtime_vs_true, compared_true);
    free(b);
    stex_free(&s);
    free_mesh(&fine);
    free_mesh(&hull);
}

TEST(jacobi_eigenvectors)
{
    /* A = Q diag(5, 2, 1) Q^T for a rotation Q */
    double q[9], lam[3] = { 5, 2, 1 }, a[9] = { 0 }, vals[3], vecs[9];
    double c = cos(0.7), s = sin(0.7);
    double rot[9] = { c, -s, 0, s * 0.8, c * 0.8, -0.6, s * 0.6, c * 0.6, 0.8 };
    memcpy(q, rot, sizeof q);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) a[i * 3 + j] += q[i * 3 + k] * lam[k] * q[j * 3 + k];
    jacobi_eigen(a, 3, vals, vecs);
    for (int k = 0; k < 3; k++) {
        CHECKF(fabs(vals[k] - lam[k]) < 1e-12, "eigenvalue %d: %g", k, vals[k]);
        double d = fabs(vecs[3 * k] * q[k] + vecs[3 * k + 1] * q[3 + k] + vecs[3 * k + 2] * q[6 + k]);
        CHECKF(fabs(d - 1) < 1e-12, "eigenvector %d: %g", k, d);
    }
}

TEST(svd_round_trip)
{
    /* rows of a mean plus three patterns: four eigenfunctions rebuild them
     * within the weights' rounding, all sixteen within one unit of anything */
    enum { K = 16, N = 3000 };
    uint8_t *a = malloc(N * K), *back = malloc(N * K), *used = malloc(N);
    unsigned seed = 3;
    for (int t = 0; t < N; t++) {
        double w1 = frand(&seed) * 2 - 1, w2 = frand(&seed) * 2 - 1, w3 = frand(&seed) * 2 - 1;
        for (int k = 0; k < K; k++) {
            double th = 2 * PI * k / K;
            double v = 110 + 40 * w1 * cos(th) + 30 * w2 * sin(th) + 20 * w3 * cos(2 * th);
            a[t * K + k] = (uint8_t)lround(v);
        }
        used[t] = t % 10 != 0;
    }
    stex_svd c;
    int worst = 0, worst_all = 0, unused_mean = 1;
    CHECK(stex_svd_compress(a, used, N, K, 4, &c) == 0);
    stex_svd_expand(&c, back);
    for (int t = 0; t < N; t++)
        for (int k = 0; k < K; k++) {
            int d = abs(back[t * K + k] - a[t * K + k]);
            if (used[t] && d > worst) worst = d;
            if (!used[t]) unused_mean &= back[t * K + k] == stex_svd_angle(c.mean, c.s, c.v, (const int8_t[4]){ 0 }, K, 4, k);
        }
    CHECKF(worst <= 2, "4 eigenfunctions: off by %d", worst);
    CHECK(unused_mean);
    stex_svd_free(&c);
    for (int t = 0; t < N; t++)
        for (int k = 0; k < K; k++) a[t * K + k] = (uint8_t)(frand(&seed) * 60 + 100);
    CHECK(stex_svd_compress(a, used, N, K, K, &c) == 0);
    stex_svd_expand(&c, back);
    for (int t = 0; t < N; t++)
        for (int k = 0; k < K && used[t]; k++)
            if (abs(back[t * K + k] - a[t * K + k]) > worst_all) worst_all = abs(back[t * K + k] - a[t * K + k]);
    CHECKF(worst_all <= 1, "16 of 16 eigenfunctions: off by %d", worst_all);
    stex_svd_free(&c);
    /* the integer formula: clamped, rounded to nearest */
    int16_t mean[2] = { 16 * 100, 16 * 250 }, v[2] = { 16384, -16384 };
    int32_t sc[1] = { 65536 * 10 };
    int8_t w[1] = { 3 };
    CHECK(stex_svd_angle(mean, sc, v, w, 2, 1, 0) == 130);
    CHECK(stex_svd_angle(mean, sc, v, w, 2, 1, 1) == 220);
    w[0] = 127;
    CHECK(stex_svd_angle(mean, sc, v, w, 2, 1, 0) == 255 && stex_svd_angle(mean, sc, v, w, 2, 1, 1) == 0);
    free(a), free(back), free(used);
}

int main(void)
{
    RUN(bvh_matches_brute_force);
    RUN(atlas_charts_and_gutters);
    RUN(sphere_in_a_hull_sphere);
    RUN(interior_silhouettes);
    RUN(runtime_lookup_agrees_with_the_encoding);
    RUN(jacobi_eigenvectors);
    RUN(svd_round_trip);
    return check_done();
}
