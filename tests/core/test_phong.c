/*
 * test_phong.c - vertex records and the default HAL stages: the Hermite
 * point of eq. 5 against a double reference, silk_vrec_eval for corner,
 * curve and moved records, the Phong vertex stage, and the Phong fragment
 * stage against a double re-implementation of the same lighting model.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include <stdlib.h>
#include "silk/silk.h"
#include "support/scene.h"
#include "src/phong_parts.h"   /* silk_hal_phong_plain */

static silk_fx fxd(double v) { return (silk_fx)llround(v * 65536.0); }
static double dfx(silk_fx v) { return v / 65536.0; }

static silk_vec3 rv3(double lo, double hi)
{
    return silk_v3(fxd(check_uniform(lo, hi)), fxd(check_uniform(lo, hi)), fxd(check_uniform(lo, hi)));
}

static silk_vec3 unit(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return silk_v3(fxd(x / l), fxd(y / l), fxd(z / l));
}

static silk_vec3 runit(void)
{
    double x, y, z, l;
    do {
        x = check_uniform(-1, 1); y = check_uniform(-1, 1); z = check_uniform(-1, 1);
        l = x * x + y * y + z * z;
    } while (l < 0.01 || l > 1);
    return unit(x, y, z);
}

/* ---- eq. 5 --------------------------------------------------------------------- */

static double dhermite(double p0, double p1, double t0, double t1, double u)
{
    return (2 * p0 - 2 * p1 + t0 + t1) * u * u * u - (3 * p0 - 3 * p1 + 2 * t0 + t1) * u * u + t0 * u + p0;
}

TEST(hermite_vs_double)
{
    double worst = 0;
    for (int trial = 0; trial < 200000; trial++) {
        silk_curve c;
        memset(&c, 0, sizeof c);
        double range = trial % 3 == 0 ? 1000 : trial % 3 == 1 ? 10 : 0.01;
        c.p0 = rv3(-range, range);
        c.p1 = silk_v3_add(c.p0, rv3(-range / 4, range / 4));
        c.t0 = rv3(-range, range);
        c.t1 = rv3(-range, range);
        silk_fx u = (silk_fx)(check_rand64() % 65537);
        silk_vec3 s = silk_hermite_point(&c, u);
        silk_fx got[3] = { s.x, s.y, s.z };
        silk_fx P0[3] = { c.p0.x, c.p0.y, c.p0.z }, P1[3] = { c.p1.x, c.p1.y, c.p1.z };
        silk_fx T0[3] = { c.t0.x, c.t0.y, c.t0.z }, T1[3] = { c.t1.x, c.t1.y, c.t1.z };
        for (int k = 0; k < 3; k++) {
            double ref = dhermite(dfx(P0[k]), dfx(P1[k]), dfx(T0[k]), dfx(T1[k]), dfx(u));
            if (fabs(ref) > 32767) continue;
            worst = fmax(worst, fabs(dfx(got[k]) - ref) * 65536);
        }
        if (u == 0) CHECK(s.x == c.p0.x && s.y == c.p0.y && s.z == c.p0.z);
    }
    /* the ends are the end points exactly */
    for (int trial = 0; trial < 1000; trial++) {
        silk_curve c;
        memset(&c, 0, sizeof c);
        c.p0 = rv3(-1000, 1000);
        c.p1 = rv3(-1000, 1000);
        c.t0 = rv3(-3000, 3000);
        c.t1 = rv3(-3000, 3000);
        silk_vec3 a = silk_hermite_point(&c, 0), b = silk_hermite_point(&c, SILK_FX_ONE);
        CHECK(a.x == c.p0.x && a.y == c.p0.y && a.z == c.p0.z);
        CHECK(b.x == c.p1.x && b.y == c.p1.y && b.z == c.p1.z);
    }
    printf("  hermite point: worst error %.3f ulp\n", worst);
    CHECKF(worst <= 0.52, "hermite error %.3f ulp", worst);
    /* huge values saturate instead of wrapping; t outside [0,1] is clamped */
    silk_curve c;
    memset(&c, 0, sizeof c);
    c.p0 = silk_v3(SILK_FX_MAX, SILK_FX_MIN, fxd(30000));
    c.p1 = silk_v3(SILK_FX_MIN, SILK_FX_MAX, fxd(30000));
    c.t0 = silk_v3(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MAX);
    c.t1 = silk_v3(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MIN);
    silk_vec3 s = silk_hermite_point(&c, SILK_FX_HALF);
    CHECK(s.z == SILK_FX_MAX);                 /* S(1/2) = P + (T0 - T1)/8 = 38192: saturated */
    CHECK(abs(s.x) <= 1);                      /* (P0 + P1)/2 + (T0 - T1)/8 = 0 */
    s = silk_hermite_point(&c, 2 * SILK_FX_ONE);
    CHECK(s.x == c.p1.x && s.y == c.p1.y);
}

/* ---- vertex records -------------------------------------------------------------- */

typedef struct small_mesh {
    silk_mesh m;
    silk_vec3 pos[4], nrm[5];
    silk_vec2 uv[4];
    silk_index tri[6], tn[6], tuv[6];
} small_mesh;

static void small(small_mesh *s)
{
    memset(s, 0, sizeof *s);
    s->pos[0] = silk_v3(0, 0, 0);
    s->pos[1] = silk_v3(SILK_FX_ONE, 0, 0);
    s->pos[2] = silk_v3(0, SILK_FX_ONE, 0);
    s->pos[3] = silk_v3(SILK_FX_ONE, SILK_FX_ONE, fxd(0.5));
    for (int i = 0; i < 5; i++) s->nrm[i] = runit();
    for (int i = 0; i < 4; i++) { s->uv[i].x = fxd(0.25 * i); s->uv[i].y = fxd(1 - 0.25 * i); }
    silk_index t[6] = { 0, 1, 2, 1, 3, 2 }, n[6] = { 0, 1, 2, 3, 4, 2 }, u[6] = { 3, 2, 1, 0, 1, 2 };
    memcpy(s->tri, t, sizeof t);
    memcpy(s->tn, n, sizeof n);
    memcpy(s->tuv, u, sizeof u);
    s->m.nverts = 4; s->m.ntris = 2; s->m.nnormals = 5; s->m.nuvs = 4;
    s->m.pos = s->pos; s->m.normal = s->nrm; s->m.uv = s->uv;
    s->m.tri = s->tri; s->m.tri_normal = s->tn; s->m.tri_uv = s->tuv;
}

static int same_attr(const silk_vertex_attr *a, const silk_vertex_attr *b)
{
    return memcmp(&a->pos, &b->pos, sizeof a->pos) == 0 && memcmp(&a->normal, &b->normal, sizeof a->normal) == 0 &&
           a->uv.x == b->uv.x && a->uv.y == b->uv.y;
}

TEST(vrec_corner_and_moved)
{
    small_mesh s;
    small(&s);
    silk_vec3 off[2] = { silk_v3(fxd(0.1), fxd(-0.2), fxd(0.3)), silk_v3(fxd(-5), 0, fxd(2)) };
    silk_geom g = { .mesh = &s.m, .offsets = off };
    for (uint32_t a = 0; a < 6; a++) {
        silk_vrec r = { SILK_VREC_CORNER, a, 0, 0 };
        silk_vertex_attr o;
        silk_vrec_eval(&g, &r, &o);
        silk_vec3 p = s.pos[s.tri[a]], n = s.nrm[s.tn[a]];
        silk_vec2 u = s.uv[s.tuv[a]];
        CHECKF(o.pos.x == p.x && o.pos.y == p.y && o.pos.z == p.z, "corner %u position", a);
        CHECKF(o.normal.x == n.x && o.normal.y == n.y && o.normal.z == n.z, "corner %u normal", a);
        CHECKF(o.uv.x == u.x && o.uv.y == u.y, "corner %u uv", a);
        silk_vrec mv = { SILK_VREC_MOVED, a, a & 1, 0 };
        silk_vertex_attr q;
        silk_vrec_eval(&g, &mv, &q);
        CHECKF(q.pos.x == p.x + off[a & 1].x && q.pos.y == p.y + off[a & 1].y && q.pos.z == p.z + off[a & 1].z,
               "moved %u", a);
        CHECK(q.normal.x == n.x && q.uv.y == u.y);
    }
    /* no uvs: zero */
    s.m.uv = NULL;
    silk_vrec r = { SILK_VREC_CORNER, 4, 0, 0 };
    silk_vertex_attr o;
    silk_vrec_eval(&g, &r, &o);
    CHECK(o.uv.x == 0 && o.uv.y == 0 && o.pos.x == s.pos[3].x);
    /* records out of range give zeros, not a crash */
    silk_vrec badr[3] = { { SILK_VREC_CORNER, 6, 0, 0 }, { SILK_VREC_CORNER, 0xFFFFFFFFu, 0, 0 }, { 7, 0, 0, 0 } };
    for (int i = 0; i < 3; i++) {
        silk_vrec_eval(&g, &badr[i], &o);
        CHECK(o.pos.x == 0 && o.pos.y == 0 && o.pos.z == 0 && o.normal.x == 0);
    }
}

TEST(vrec_curve)
{
    double worst_n = 0;
    for (int trial = 0; trial < 20000; trial++) {
        silk_curve c;
        c.p0 = rv3(-50, 50);
        c.p1 = rv3(-50, 50);
        c.t0 = rv3(-20, 20);
        c.t1 = rv3(-20, 20);
        c.n0 = runit();
        c.n1 = runit();
        c.uv0.x = fxd(check_uniform(0, 1)); c.uv0.y = fxd(check_uniform(0, 1));
        c.uv1.x = fxd(check_uniform(0, 1)); c.uv1.y = fxd(check_uniform(0, 1));
        silk_curve cs[2] = { c, c };
        silk_geom g = { .curves = cs };
        silk_fx t = (silk_fx)(check_rand64() % 65537);
        silk_vrec r = { SILK_VREC_CURVE, 1, 0, t };
        silk_vertex_attr o, o2;
        silk_vrec_eval(&g, &r, &o);
        silk_vrec_eval(&g, &r, &o2);
        CHECK(same_attr(&o, &o2));
        silk_vec3 hp = silk_hermite_point(&c, t);
        CHECK(o.pos.x == hp.x && o.pos.y == hp.y && o.pos.z == hp.z);
        double u = dfx(t), n[3], l = 0;
        silk_fx a0[3] = { c.n0.x, c.n0.y, c.n0.z }, a1[3] = { c.n1.x, c.n1.y, c.n1.z };
        for (int k = 0; k < 3; k++) { n[k] = (1 - u) * dfx(a0[k]) + u * dfx(a1[k]); l += n[k] * n[k]; }
        l = sqrt(l);
        if (l < 0.05) continue;
        silk_fx got[3] = { o.normal.x, o.normal.y, o.normal.z };
        for (int k = 0; k < 3; k++) worst_n = fmax(worst_n, fabs(dfx(got[k]) - n[k] / l));
        double ux = (1 - u) * dfx(c.uv0.x) + u * dfx(c.uv1.x);
        CHECKF(fabs(dfx(o.uv.x) - ux) <= 1.0 / 65536, "uv lerp %g vs %g", dfx(o.uv.x), ux);
    }
    printf("  curve normal: worst error %.2f ulp\n", worst_n * 65536);
    CHECKF(worst_n <= 1.0 / 65536, "curve normal error %g", worst_n);
    /* opposite normals cancel at t = 1/2: the record keeps n0 */
    silk_curve c;
    memset(&c, 0, sizeof c);
    c.n0 = silk_v3(0, SILK_FX_ONE, 0);
    c.n1 = silk_v3(0, -SILK_FX_ONE, 0);
    silk_geom g = { .curves = &c };
    silk_vrec r = { SILK_VREC_CURVE, 0, 0, SILK_FX_HALF };
    silk_vertex_attr o;
    silk_vrec_eval(&g, &r, &o);
    CHECK(o.normal.y == SILK_FX_ONE);
}

/* ---- the Phong stages ----------------------------------------------------------- */

static silk_camera cam(int ortho)
{
    silk_camera c;
    memset(&c, 0, sizeof c);
    c.eye = silk_v3(fxd(2), fxd(1.5), fxd(4));
    c.target = silk_v3(0, 0, 0);
    c.up = silk_v3(0, SILK_FX_ONE, 0);
    c.ortho = ortho;
    c.fov_deg = SILK_FX_C(40, 1);
    c.ortho_half_height = SILK_FX_C(3, 2);
    c.znear = SILK_FX_C(1, 10);
    c.zfar = SILK_FX_C(50, 1);
    c.width = 64;
    c.height = 48;
    return c;
}

TEST(vertex_stage)
{
    small_mesh s;
    small(&s);
    silk_camera c = cam(0);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_phong p;
    silk_phong_default(&p, &v);
    silk_hal h;
    silk_hal_phong(&h, &p);
    CHECK(h.nvaryings == 6 && h.vertex && h.fragment && h.uniforms == &p);
    silk_geom g = { .mesh = &s.m };
    for (uint32_t a = 0; a < 6; a++) {
        silk_vrec r = { SILK_VREC_CORNER, a, 0, 0 };
        silk_vertex_out o;
        silk_vertex_attr at;
        h.vertex(&h, &g, &r, &o);
        silk_vrec_eval(&g, &r, &at);
        silk_vec4 cl = silk_view_clip(&v, at.pos);
        CHECK(memcmp(&o.clip, &cl, sizeof cl) == 0);
        silk_fx want[6] = { at.pos.x, at.pos.y, at.pos.z, at.normal.x, at.normal.y, at.normal.z };
        CHECK(memcmp(o.var, want, sizeof want) == 0);
    }
}

/* The same lighting model in doubles. */
static uint32_t dphong(const silk_phong *p, const silk_fx *var)
{
    double P[3] = { dfx(var[0]), dfx(var[1]), dfx(var[2]) }, N[3] = { dfx(var[3]), dfx(var[4]), dfx(var[5]) }, V[3];
    const silk_view *v = p->view;
    if (!v->cam.ortho) {
        V[0] = dfx(v->cam.eye.x) - P[0]; V[1] = dfx(v->cam.eye.y) - P[1]; V[2] = dfx(v->cam.eye.z) - P[2];
    } else {
        V[0] = -dfx(v->forward.x); V[1] = -dfx(v->forward.y); V[2] = -dfx(v->forward.z);
    }
    double lv = sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]), ln = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    for (int k = 0; k < 3; k++) { V[k] /= lv; N[k] /= ln; }
    double ndv = N[0] * V[0] + N[1] * V[1] + N[2] * V[2];
    if (p->two_sided && ndv < 0)
        for (int k = 0; k < 3; k++) N[k] -= 2 * ndv * V[k];
    double dif[3] = { 0, 0, 0 }, spe[3] = { 0, 0, 0 };
    for (int i = 0; i < p->nlights; i++) {
        const silk_light *li = &p->lights[i];
        double L[3] = { dfx(li->vec.x), dfx(li->vec.y), dfx(li->vec.z) };
        if (li->kind == SILK_LIGHT_POINT) {
            for (int k = 0; k < 3; k++) L[k] -= P[k];
            double l = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
            for (int k = 0; k < 3; k++) L[k] /= l;
        }
        double ndl = N[0] * L[0] + N[1] * L[1] + N[2] * L[2];
        if (ndl <= 0) continue;
        double R[3], rdv = 0;
        for (int k = 0; k < 3; k++) { R[k] = 2 * ndl * N[k] - L[k]; rdv += R[k] * V[k]; }
        double s = rdv > 0 ? pow(fmin(rdv, 1), p->mat.shininess) : 0;
        double lc[3] = { dfx(li->color.x), dfx(li->color.y), dfx(li->color.z) };
        for (int k = 0; k < 3; k++) { dif[k] += ndl * lc[k]; spe[k] += s * lc[k]; }
    }
    double base[3] = { dfx(p->mat.color.x), dfx(p->mat.color.y), dfx(p->mat.color.z) };
    double sc[3] = { dfx(p->mat.specular_color.x), dfx(p->mat.specular_color.y), dfx(p->mat.specular_color.z) };
    uint32_t rgb = 0;
    for (int k = 0; k < 3; k++) {
        double c = base[k] * (dfx(p->mat.ambient) + dfx(p->mat.diffuse) * dif[k]) + dfx(p->mat.specular) * sc[k] * spe[k];
        c = fmin(fmax(c, 0), 1);
        rgb = rgb << 8 | (uint32_t)lround(c * 255);
    }
    return rgb;
}

static int chan_diff(uint32_t a, uint32_t b)
{
    int d = 0;
    for (int s = 0; s < 24; s += 8) {
        int x = abs((int)((a >> s) & 255) - (int)((b >> s) & 255));
        if (x > d) d = x;
    }
    return d;
}

/* nlights random lights (one in point_in a point light, colours up to
 * cmax) and a random material (diffuse up to dmax), one- or two-sided. */
static void random_lighting(silk_phong *p, int nlights, unsigned point_in, double cmax, double dmax)
{
    p->nlights = nlights;
    for (int i = 0; i < p->nlights; i++) {
        p->lights[i].kind = check_rand64() % point_in == point_in - 1 ? SILK_LIGHT_POINT : SILK_LIGHT_DIRECTIONAL;
        p->lights[i].vec = p->lights[i].kind == SILK_LIGHT_POINT ? rv3(-10, 10) : runit();
        p->lights[i].color = rv3(0, cmax);
    }
    p->mat.color = rv3(0, 1);
    p->mat.ambient = fxd(check_uniform(0, 0.3));
    p->mat.diffuse = fxd(check_uniform(0, dmax));
    p->mat.specular = fxd(check_uniform(0, 1));
    p->mat.shininess = 1 + (int)(check_rand64() % 256);
    p->mat.specular_color = rv3(0, 1);
    p->two_sided = (int)(check_rand64() & 1);
}

TEST(fragment_vs_double)
{
    int worst = 0, hist[4] = { 0, 0, 0, 0 };
    for (int trial = 0; trial < 60000; trial++) {
        silk_camera c = cam(trial & 1);
        c.eye = rv3(-6, 6);
        silk_view v;
        if (silk_view_init(&v, &c, NULL) != SILK_OK) continue;
        silk_phong p;
        silk_phong_default(&p, &v);
        if (trial % 3) {
            /* random lights and material */
            random_lighting(&p, 1 + (int)(check_rand64() % SILK_MAX_LIGHTS), 2, 1, 1);
        }
        silk_hal h;
        silk_hal_phong(&h, &p);
        silk_fx var[8];
        silk_vec3 pos = rv3(-2, 2), n = runit();
        /* interpolated normals are not unit: scale them */
        silk_fx sc = fxd(check_uniform(0.6, 1.0));
        n = silk_v3_scale(n, sc);
        silk_fx vv[8] = { pos.x, pos.y, pos.z, n.x, n.y, n.z, 0, 0 };
        memcpy(var, vv, sizeof vv);
        uint32_t got = h.fragment(&h, var), want = dphong(&p, var);
        int d = chan_diff(got, want);
        if (d > worst) worst = d;
        hist[d > 3 ? 3 : d]++;
    }
    printf("  phong fragment vs double: worst %d/255; exact %d, off by 1: %d, by 2: %d, more: %d\n", worst, hist[0],
           hist[1], hist[2], hist[3]);
    /* high exponents near the highlight amplify a 1e-5 error of R.V */
    CHECKF(worst <= 3 && hist[2] + hist[3] < 60, "fragment differs by up to %d", worst);
}

/* Every shaded pixel of whole frames: the default fragment stage wrapped so
 * that each fragment is also shaded by dphong from the same varyings. */
typedef struct probe { const silk_hal *inner; const silk_phong *phong; int worst; long n; } probe;

static uint32_t probe_fragment(const silk_hal *h, const silk_fx *var)
{
    probe *pr = (probe *)(uintptr_t)h->uniforms;
    uint32_t got = pr->inner->fragment(pr->inner, var);
    int d = chan_diff(got, dphong(pr->phong, var));
    if (d > pr->worst) pr->worst = d;
    pr->n++;
    return got;
}

static void probe_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out)
{
    const probe *pr = (const probe *)h->uniforms;
    pr->inner->vertex(pr->inner, g, r, out);
}

TEST(fragment_on_meshes)
{
    size_t size = (size_t)64 << 20;
    unsigned char *mem = malloc(size);
    silk_arena a;
    silk_arena_init(&a, mem, size);
    /* a closed sphere, and an open wavy sheet seen from both sides */
    ts_mesh sph = { 0 }, sheet = { 0 };
    ts_sphere(&sph, 14, 9, 1.0, 0, 0, 0);
    for (int j = 0; j <= 8; j++)
        for (int i = 0; i <= 8; i++)
            ts_vertex(&sheet, i / 4.0 - 1, 0.25 * sin(i * 0.9) * cos(j * 0.7), j / 4.0 - 1);
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++) {
            uint32_t c = (uint32_t)(j * 9 + i);
            ts_tri(&sheet, c, c + 9, c + 1);
            ts_tri(&sheet, c + 1, c + 9, c + 10);
        }
    const ts_mesh *meshes[2] = { &sph, &sheet };
    const double eyes[4][3] = { { 0.5, 0.8, 3.2 }, { -2.5, 1.5, -1.5 }, { 1.0, -2.8, 0.6 }, { 0.2, 3.0, 0.1 } };
    int worst = 0;
    long n = 0;
    for (int mi = 0; mi < 2; mi++)
        for (int e = 0; e < 4; e++)
            for (int mode = 0; mode < 2; mode++) {
                silk_arena_init(&a, mem, size);
                silk_mesh m;
                silk_error err;
                if (ts_build(meshes[mi], &a, &m, &err) != SILK_OK) { CHECKF(0, "%s", err.msg); continue; }
                double target[3] = { 0, 0, 0 };
                silk_camera cam = ts_camera(eyes[e], target, e == 3 ? -1.3 : 45, 0.1, 20, 96, 72);
                silk_view v;
                if (silk_view_init(&v, &cam, &err) != SILK_OK) { CHECKF(0, "%s", err.msg); continue; }
                silk_phong p;
                silk_phong_default(&p, &v);
                silk_hal inner, h;
                silk_hal_phong(&inner, &p);
                probe pr = { &inner, &p, 0, 0 };
                h = inner;
                h.vertex = probe_vertex;
                h.fragment = probe_fragment;
                h.uniforms = &pr;
                silk_render_opts o;
                silk_render_opts_default(&o);
                o.mode = mode ? SILK_MODE_SMOOTH : SILK_MODE_FLAT;
                static uint8_t rgb[96 * 72 * 3];
                static uint32_t depth[96 * 72];
                silk_target t;
                silk_target_init(&t, 96, 72, 0, 72, SILK_PIX_RGB888, rgb, depth);
                silk_target_clear(&t, 0xFFFFFF);
                CHECK(silk_render(&a, &m, &v, &h, &o, &t, NULL, &err) == SILK_OK);
                CHECKF(pr.n > 200, "mesh %d view %d: only %ld fragments", mi, e, pr.n);
                if (pr.worst > worst) worst = pr.worst;
                n += pr.n;
            }
    printf("  %ld fragments of whole frames against double Phong: worst %d/255\n", n, worst);
    CHECKF(worst <= 2, "a pixel differs by %d levels", worst);
    ts_mesh_free(&sph);
    ts_mesh_free(&sheet);
    free(mem);
}

/* Any silk_fx in the varyings, lights and material: defined behaviour (the
 * sanitizer build checks), and black to white only. */
TEST(fragment_extremes)
{
    silk_camera c = cam(0);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    int bad = 0;
    for (int trial = 0; trial < 20000; trial++) {
        silk_phong p;
        silk_phong_default(&p, &v);
        silk_fx *f[] = { &p.mat.ambient, &p.mat.diffuse, &p.mat.specular, &p.mat.color.x, &p.mat.color.z,
                         &p.mat.specular_color.y, &p.lights[0].vec.x, &p.lights[0].color.y, &p.lights[1].vec.z,
                         &p.lights[1].color.x };
        for (int i = 0; i < 10; i++)
            if (check_rand64() % 3 == 0) *f[i] = (silk_fx)(uint32_t)check_rand64();
        p.lights[1].kind = check_rand64() & 1 ? SILK_LIGHT_POINT : SILK_LIGHT_DIRECTIONAL;
        p.two_sided = (int)(check_rand64() & 1);
        silk_hal h;
        silk_hal_phong(&h, &p);
        silk_fx var[8];
        for (int k = 0; k < 8; k++) var[k] = check_rand64() & 1 ? (silk_fx)(uint32_t)check_rand64() : 0;
        bad += h.fragment(&h, var) > 0xFFFFFF;
    }
    CHECK(bad == 0);
}

/* The rasterizer's shortcut for the default stage's usual case gives
 * h->fragment's bits: random scenes in and out of that case, varyings near
 * the surface and anywhere (eye distances past silk_fx's range included). */
TEST(plain_case_same_bits)
{
    int plain = 0, other = 0, bad_case = 0, bad_bits = 0;
    if (!check_built(SILK_PHONG_PLAIN, "SILK_PHONG_PLAIN")) return;
    for (int trial = 0; trial < 20000; trial++) {
        silk_camera c = cam(trial % 5 == 0);
        c.eye = trial % 7 == 0 ? rv3(-30000, 30000) : rv3(-6, 6);
        silk_view v;
        if (silk_view_init(&v, &c, NULL) != SILK_OK) continue;
        silk_phong p;
        silk_phong_default(&p, &v);
        if (trial % 2) {
            random_lighting(&p, trial % 11 == 0 ? 1 + (int)(check_rand64() % SILK_MAX_LIGHTS) : 2, 8,
                            trial % 13 == 0 ? 20 : 1, trial % 17 == 0 ? 20 : 1);
        }
        silk_hal h;
        silk_hal_phong(&h, &p);
        int want = !c.ortho && p.nlights == 2 && p.lights[0].kind == SILK_LIGHT_DIRECTIONAL &&
                   p.lights[1].kind == SILK_LIGHT_DIRECTIONAL && p.mat.diffuse < 16 * SILK_FX_ONE;
        const silk_phong *q = silk_hal_phong_plain(&h);
        bad_case += (q != NULL) != want || (q && q != &p);
        if (!q) {
            other++;
            continue;
        }
        plain++;
        for (int i = 0; i < 8; i++) {
            silk_fx var[8];
            if (i < 6) {
                silk_vec3 pos = rv3(-2, 2), n = silk_v3_scale(runit(), fxd(check_uniform(0.6, 1.0)));
                silk_fx vv[8] = { pos.x, pos.y, pos.z, n.x, n.y, n.z, 0, 0 };
                memcpy(var, vv, sizeof vv);
            } else {
                for (int k = 0; k < 8; k++) var[k] = check_rand64() & 1 ? (silk_fx)(uint32_t)check_rand64() : 0;
            }
            bad_bits += silk_phong_plain_fragment(q, var) != h.fragment(&h, var);
        }
    }
    printf("  plain case: %d scenes in it, %d not\n", plain, other);
    CHECK(plain > 1000 && other > 1000);
    CHECK(bad_case == 0);
    CHECK(bad_bits == 0);
}

TEST(two_sided_and_saturation)
{
    silk_camera c = cam(1);
    c.eye = silk_v3(0, 0, fxd(5));
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_phong p;
    memset(&p, 0, sizeof p);
    p.view = &v;
    p.nlights = 1;
    p.lights[0].kind = SILK_LIGHT_DIRECTIONAL;
    p.lights[0].vec = silk_v3(0, 0, SILK_FX_ONE);        /* from the viewer */
    p.lights[0].color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
    p.mat.color = silk_v3(SILK_FX_ONE, SILK_FX_HALF, 0);
    p.mat.diffuse = SILK_FX_ONE;
    p.mat.shininess = 8;
    silk_hal h;
    silk_hal_phong(&h, &p);
    silk_fx front[8] = { 0, 0, 0, 0, 0, SILK_FX_ONE, 0, 0 }, back[8] = { 0, 0, 0, 0, 0, -SILK_FX_ONE, 0, 0 };
    CHECKF(h.fragment(&h, front) == 0xFF8000, "got %06x", h.fragment(&h, front));
    CHECK(h.fragment(&h, back) == 0x000000);                /* one-sided: the back is unlit */
    p.two_sided = 1;
    CHECK(h.fragment(&h, back) == 0xFF8000);                /* seen squarely from behind: lit as the front */
    /* at a grazing angle the mirrored normal stays close to the original */
    silk_fx graze[8] = { 0, 0, 0, SILK_FX_ONE, 0, -SILK_FX_C(1, 100), 0, 0 };
    uint32_t g1 = h.fragment(&h, graze);
    graze[5] = SILK_FX_C(1, 100);
    CHECK(chan_diff(g1, h.fragment(&h, graze)) <= 1);
    /* far too much light saturates at 255 instead of wrapping */
    p.lights[0].color = silk_v3(SILK_FX_C(1000, 1), SILK_FX_C(1000, 1), SILK_FX_C(1000, 1));
    p.mat.specular = SILK_FX_C(1000, 1);
    p.mat.specular_color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
    p.nlights = 4;
    for (int i = 1; i < 4; i++) p.lights[i] = p.lights[0];
    CHECK(h.fragment(&h, front) == 0xFFFFFF);
    /* zero normal: faces the viewer, no crash */
    silk_fx zero[8] = { 0 };
    CHECK(h.fragment(&h, zero) == 0xFFFFFF);
    /* nlights out of range is clamped */
    p.nlights = 99;
    CHECK(h.fragment(&h, front) == 0xFFFFFF);
    p.nlights = -1;
    CHECK(h.fragment(&h, front) == 0x000000);
}

/* The default lights: a key from the upper left in front, a weaker fill
 * from the lower right, both relative to the camera; a lit sphere is
 * brighter at its upper left than at its lower right. */
TEST(default_lighting)
{
    silk_camera c = cam(0);
    silk_view v;
    CHECK(silk_view_init(&v, &c, NULL) == SILK_OK);
    silk_phong p;
    silk_phong_default(&p, &v);
    CHECK(p.nlights == 2 && p.two_sided == 1);
    silk_vec3 key = p.lights[0].vec, fill = p.lights[1].vec;
    CHECK(silk_v3_dot64(key, v.right) < 0 && silk_v3_dot64(key, v.upv) > 0 && silk_v3_dot64(key, v.forward) < 0);
    CHECK(silk_v3_dot64(fill, v.right) > 0 && silk_v3_dot64(fill, v.upv) < 0);
    CHECK(p.lights[1].color.x < p.lights[0].color.x / 2);
    silk_hal h;
    silk_hal_phong(&h, &p);
    /* sphere normals towards the upper-left and lower-right of the view */
    double lum[2] = { 0, 0 };
    for (int q = 0; q < 2; q++) {
        double sgn = q ? 1 : -1;
        silk_vec3 n;
        silk_v3_normalize(silk_v3_add(silk_v3_add(silk_v3_scale(v.right, fxd(0.5 * sgn)), silk_v3_scale(v.upv, fxd(-0.5 * sgn))),
                                      silk_v3_neg(v.forward)), &n);
        silk_fx var[8] = { n.x, n.y, n.z, n.x, n.y, n.z, 0, 0 };
        uint32_t rgb = h.fragment(&h, var);
        lum[q] = 0.3 * (rgb >> 16) + 0.59 * (rgb >> 8 & 255) + 0.11 * (rgb & 255);
    }
    CHECKF(lum[0] > lum[1] + 40, "upper left %g, lower right %g", lum[0], lum[1]);
    /* without a view: world-fixed directions, still valid units */
    silk_phong_default(&p, NULL);
    CHECK(llabs(silk_v3_dot64(p.lights[0].vec, p.lights[0].vec) - ((int64_t)1 << 32)) < ((int64_t)1 << 20));
}

int main(void)
{
    RUN(hermite_vs_double);
    RUN(vrec_corner_and_moved);
    RUN(vrec_curve);
    RUN(vertex_stage);
    RUN(fragment_vs_double);
    RUN(fragment_on_meshes);
    RUN(fragment_extremes);
    RUN(plain_case_same_bits);
    RUN(two_sided_and_saturation);
    RUN(default_lighting);
    return check_done();
}
