/*
 * test_remesh.c - local re-meshing (paper Figs. 11, 12): the output of
 * silk_frame_smooth is a closed, consistently oriented mesh wherever the
 * input is (no T-junctions, no cracks), from many views, in both
 * projections; untouched triangles stay as they are; degenerate views and
 * meshes neither crash nor crack; a small arena falls back gracefully; the
 * 200-triangle sphere's triangle count compared with the paper's Table I.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "support/testframe.h"
#include "silk/silk.h"
#include "src/frame.h"

#define ARENA_BYTES (48u << 20)
static unsigned char *arena_buf;

static double fx2d(silk_fx v) { return v / 65536.0; }

static char *read_file(const char *name, size_t *len)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", check_meshes_dir(), name);
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, fp) != (size_t)n) { free(b); b = NULL; }
    fclose(fp);
    if (b) b[n] = 0;
    *len = (size_t)n;
    return b;
}

/* Load an OBJ into a fresh arena (the whole buffer). */
static int load_text(silk_arena *a, size_t bytes, const char *text, size_t len, const char *name, silk_mesh *m)
{
    silk_arena_init(a, arena_buf, bytes);
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    silk_status st = silk_load_obj(text, len, name, &o, a, m, &err);
    if (st != SILK_OK) { fprintf(stderr, "load %s: %s\n", name, err.msg); return 0; }
    return 1;
}

static int load_shared(silk_arena *a, const char *name, silk_mesh *m)
{
    size_t len;
    char *t = read_file(name, &len);
    if (!t) { fprintf(stderr, "cannot read %s/%s\n", check_meshes_dir(), name); return 0; }
    int ok = load_text(a, ARENA_BYTES, t, len, name, m);
    free(t);
    return ok;
}

/* A camera looking at the model's bounding-box centre from direction dir,
 * at dist bounding radii. */
static int make_view(const silk_mesh *m, const double dir[3], double dist, int ortho, int w, int h,
                     silk_view *v)
{
    return tf_view_around_size(m, dir, dist, ortho, w, h, v);
}

static void random_dir(double d[3])
{
    double l;
    do {
        for (int i = 0; i < 3; i++) d[i] = check_uniform(-1, 1);
        l = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (l < 0.01 || l > 1);
}

/* ---- topology of the output ------------------------------------------------- */

typedef struct topo {
    uint32_t tris, degenerate;       /* degenerate: two corners at the same point */
    uint32_t open_edges;             /* directed edges without their opposite */
    uint32_t multi_edges;            /* directed edges used more than once */
    uint32_t bad_records;            /* records pointing outside the frame's arrays */
    double volume, area;
} topo;

typedef struct wkey { silk_fx x, y, z; uint32_t rec; } wkey;
static int cmp_wkey(const void *a, const void *b)
{
    const wkey *p = a, *q = b;
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    if (p->y != q->y) return p->y < q->y ? -1 : 1;
    if (p->z != q->z) return p->z < q->z ? -1 : 1;
    return 0;
}
static int cmp_u64(const void *a, const void *b)
{
    uint64_t p = *(const uint64_t *)a, q = *(const uint64_t *)b;
    return p < q ? -1 : p > q;
}

/* Evaluate every record, weld records at bit-identical positions, and count
 * directed edges without exactly one opposite partner.  A crack or a
 * T-junction shows up as an open edge. */
static void check_topology(const silk_mesh *m, const silk_frame_geom *g, topo *out)
{
    memset(out, 0, sizeof *out);
    silk_geom gg = { .mesh = m, .curves = g->curve, .offsets = g->offset };
    silk_vertex_attr *at = malloc((g->nvrec + 1) * sizeof *at);
    wkey *k = malloc((g->nvrec + 1) * sizeof *k);
    uint32_t *id = malloc((g->nvrec + 1) * sizeof *id);
    for (uint32_t i = 0; i < g->nvrec; i++) {
        const silk_vrec *r = &g->vrec[i];
        if ((r->kind == SILK_VREC_CURVE && r->a >= g->ncurve) ||
            (r->kind == SILK_VREC_MOVED && r->b >= g->noffset) ||
            (r->kind != SILK_VREC_CURVE && r->a >= 3 * m->ntris) || r->kind > SILK_VREC_MOVED)
            out->bad_records++;
        silk_vrec_eval(&gg, r, &at[i]);
        k[i].x = at[i].pos.x; k[i].y = at[i].pos.y; k[i].z = at[i].pos.z; k[i].rec = i;
    }
    qsort(k, g->nvrec, sizeof *k, cmp_wkey);
    uint32_t nid = 0;
    for (uint32_t i = 0; i < g->nvrec; i++) {
        if (i > 0 && cmp_wkey(&k[i - 1], &k[i]) != 0) nid++;
        id[k[i].rec] = nid;
    }
    uint64_t *e = malloc((3 * (size_t)g->ntri + 1) * sizeof *e);
    size_t ne = 0;
    out->tris = g->ntri;
    for (uint32_t t = 0; t < g->ntri; t++) {
        const uint32_t *c = &g->tri[3 * t];
        if (c[0] >= g->nvrec || c[1] >= g->nvrec || c[2] >= g->nvrec) { out->bad_records++; continue; }
        uint32_t a = id[c[0]], b = id[c[1]], d = id[c[2]];
        if (a == b || b == d || d == a) { out->degenerate++; continue; }
        double p[3][3];
        for (int j = 0; j < 3; j++) {
            p[j][0] = fx2d(at[c[j]].pos.x); p[j][1] = fx2d(at[c[j]].pos.y); p[j][2] = fx2d(at[c[j]].pos.z);
        }
        double u[3], w[3], n[3];
        for (int j = 0; j < 3; j++) { u[j] = p[1][j] - p[0][j]; w[j] = p[2][j] - p[0][j]; }
        n[0] = u[1] * w[2] - u[2] * w[1]; n[1] = u[2] * w[0] - u[0] * w[2]; n[2] = u[0] * w[1] - u[1] * w[0];
        out->area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        out->volume += (p[0][0] * n[0] + p[0][1] * n[1] + p[0][2] * n[2]) / 6;
        e[ne++] = (uint64_t)a << 32 | b;
        e[ne++] = (uint64_t)b << 32 | d;
        e[ne++] = (uint64_t)d << 32 | a;
    }
    qsort(e, ne, sizeof *e, cmp_u64);
    for (size_t i = 0; i < ne; i++) {
        if (i + 1 < ne && e[i + 1] == e[i]) {
            out->multi_edges++;
            if (getenv("SILK_DEBUG_TOPO")) {
                uint32_t ia = (uint32_t)(e[i] >> 32), ib = (uint32_t)e[i];
                for (uint32_t r = 0; r < g->nvrec; r++)
                    if (id[r] == ia || id[r] == ib)
                        fprintf(stderr, "  rec %u id %u kind %u a %u t %d pos %d %d %d\n", r, id[r], g->vrec[r].kind,
                                g->vrec[r].a, g->vrec[r].t, at[r].pos.x, at[r].pos.y, at[r].pos.z);
                for (uint32_t t = 0; t < g->ntri; t++) {
                    const uint32_t *c = &g->tri[3 * t];
                    int hit = 0;
                    for (int j = 0; j < 3; j++) hit += id[c[j]] == ia || id[c[j]] == ib;
                    if (hit >= 2) fprintf(stderr, "  tri %u: %u %u %u added %d\n", t, c[0], c[1], c[2], g->tri_added[t]);
                }
            }
            continue;
        }
        uint64_t rev = (e[i] << 32) | (e[i] >> 32);
        size_t lo = 0, hi = ne;
        while (lo < hi) { size_t mid = (lo + hi) / 2; if (e[mid] < rev) lo = mid + 1; else hi = mid; }
        if (lo >= ne || e[lo] != rev) out->open_edges++;
    }
    free(e); free(id); free(k); free(at);
}

static double mesh_volume(const silk_mesh *m)
{
    double v = 0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        double p[3][3];
        for (int j = 0; j < 3; j++) {
            silk_vec3 q = m->pos[m->tri[3 * t + j]];
            p[j][0] = fx2d(q.x); p[j][1] = fx2d(q.y); p[j][2] = fx2d(q.z);
        }
        v += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
              p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6;
    }
    return v;
}

/* One smooth frame; returns 0 (and reports) if it failed. */
static int smooth_frame(silk_arena *a, const silk_mesh *m, const silk_view *v, silk_fx tol,
                        silk_frame_geom *g, silk_frame_stats *st)
{
    silk_error err;
    memset(st, 0, sizeof *st);
    silk_status s = silk_frame_smooth(a, m, v, tol, SILK_VIS_BRUTE, g, st, &err);
    if (s != SILK_OK) { fprintf(stderr, "smooth: %s\n", err.msg); return 0; }
    return 1;
}

/* ---- tests ----------------------------------------------------------------- */

TEST(flat_is_one_corner_record_per_corner)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    silk_arena_mark mk = silk_arena_top_mark(&a);
    silk_frame_geom g;
    silk_error err;
    CHECK(silk_frame_flat(&a, &m, &g, &err) == SILK_OK);
    CHECK(g.nvrec == 3 * m.ntris && g.ntri == m.ntris && g.ncurve == 0 && g.noffset == 0);
    int bad = 0;
    for (uint32_t i = 0; i < g.nvrec; i++)
        bad += g.vrec[i].kind != SILK_VREC_CORNER || g.vrec[i].a != i || g.tri[i] != i;
    for (uint32_t t = 0; t < g.ntri; t++) bad += g.tri_added[t] != 0;
    CHECKF(bad == 0, "%d bad records", bad);
    topo tp;
    check_topology(&m, &g, &tp);
    CHECKF(tp.open_edges == 0 && tp.multi_edges == 0, "open %u multi %u", tp.open_edges, tp.multi_edges);
    silk_arena_top_release(&a, &mk);
}

/* The heart of it: closed in, closed out, from many views. */
static void closed_from_views(const char *name, int nviews, int *any_remeshed)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, name, &m)) { CHECK(0); return; }
    double vol0 = mesh_volume(&m);
    uint32_t worst_open = 0, worst_multi = 0, bad = 0, fell = 0, sil = 0, vol_bad = 0;
    double worst_vol = 0;
    for (int i = 0; i < nviews; i++) {
        double d[3];
        random_dir(d);
        int ortho = i & 1;
        double dist = 1.5 + check_uniform(0, 4);
        silk_view v;
        if (!make_view(&m, d, dist, ortho, 512, 512, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_frame_geom g;
        silk_frame_stats st;
        if (!smooth_frame(&a, &m, &v, SILK_FX_C(1, 2), &g, &st)) { CHECK(0); return; }
        topo tp;
        check_topology(&m, &g, &tp);
        if (tp.open_edges > worst_open) worst_open = tp.open_edges;
        if (tp.multi_edges > worst_multi) worst_multi = tp.multi_edges;
        bad += tp.bad_records;
        fell += st.fell_back;
        sil += st.silhouette_tris;
        /* the smoothed surface bulges out a little, never inside out */
        double rel = tp.volume / vol0 - 1;
        if (fabs(rel) > fabs(worst_vol)) worst_vol = rel;
        if (tp.volume <= 0 || fabs(rel) > 0.25) vol_bad++;
        if (g.ntri > m.ntris) *any_remeshed = 1;
        silk_arena_top_release(&a, &mk);
    }
    printf("  %s: %d views, open edges worst %u, repeated edges worst %u, volume change worst %+.2f%%, "
           "silhouette triangles %.1f per view\n",
           name, nviews, worst_open, worst_multi, 100 * worst_vol, (double)sil / nviews);
    CHECKF(worst_open == 0, "%s: %u open edges", name, worst_open);
    CHECKF(worst_multi == 0, "%s: %u repeated edges", name, worst_multi);
    CHECKF(bad == 0, "%s: %u bad records", name, bad);
    CHECKF(fell == 0, "%s: fell back %u times", name, fell);
    CHECKF(vol_bad == 0, "%s: volume off in %u views", name, vol_bad);
    CHECKF(sil > 0, "%s: no silhouette triangles at all", name);
}

TEST(closed_mesh_stays_closed_sphere) { int r = 0; closed_from_views("sphere-200.obj", 60, &r); CHECK(r); }
TEST(closed_mesh_stays_closed_torus) { int r = 0; closed_from_views("torus-576.obj", 60, &r); CHECK(r); }
TEST(closed_mesh_stays_closed_features)
{
    /* feature edges: the cone's rims, fandisk's creases (Fig. 12) */
    int r = 0;
    closed_from_views("cone-70.obj", 40, &r);
    CHECK(r);
    r = 0;
    closed_from_views("fandisk-128.obj", 40, &r);
    CHECK(r);
}
TEST(closed_mesh_stays_closed_organic)
{
    int r = 0;
    closed_from_views("bunny-500.obj", 20, &r);
    closed_from_views("knot-480.obj", 20, &r);
    CHECK(r);
}

/* Table I: the 200-triangle sphere becomes 332 triangles in the paper. */
TEST(sphere_triangle_count_vs_paper)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    static const silk_fx tols[] = { SILK_FX_C(1, 4), SILK_FX_C(1, 2), SILK_FX_ONE, SILK_FX_C(2, 1) };
    for (int ti = 0; ti < 4; ti++) {
        double sum = 0, sum_samples = 0, sum_sil = 0;
        uint32_t lo = UINT32_MAX, hi = 0;
        int nv = 0;
        for (int i = 0; i < 36; i++) {
            double ang = i * 10 * 3.14159265358979323846 / 180;
            double d[3] = { cos(ang), 0.35, sin(ang) };
            for (int ortho = 0; ortho < 2; ortho++) {
                silk_view v;
                if (!make_view(&m, d, 3.0, ortho, 512, 512, &v)) { CHECK(0); return; }
                silk_arena_mark mk = silk_arena_top_mark(&a);
                silk_frame_geom g;
                silk_frame_stats st;
                if (!smooth_frame(&a, &m, &v, tols[ti], &g, &st)) { CHECK(0); return; }
                sum += g.ntri;
                sum_samples += st.samples;
                sum_sil += st.silhouette_tris;
                if (g.ntri < lo) lo = g.ntri;
                if (g.ntri > hi) hi = g.ntri;
                nv++;
                silk_arena_top_release(&a, &mk);
            }
        }
        printf("  sphere-200 at 512x512, tolerance %.2f px: %.1f triangles per frame (%u..%u), "
               "%.1f silhouette triangles, %.1f samples (paper: 332)\n",
               tols[ti] / 65536.0, sum / nv, lo, hi, sum_sil / nv, sum_samples / nv);
        if (tols[ti] == SILK_FX_C(1, 2) || tols[ti] == SILK_FX_ONE)
            CHECKF(sum / nv >= 332 / 2.0 && sum / nv <= 332 * 2.0, "%.1f triangles", sum / nv);
    }
}

/* Triangles the smoothing leaves alone are exactly the original corners. */
TEST(untouched_triangles_are_original)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "torus-576.obj", &m)) { CHECK(0); return; }
    uint8_t *seen = calloc(m.ntris, 1);
    uint32_t bad = 0, untouched = 0, added = 0;
    for (int i = 0; i < 20; i++) {
        double d[3];
        random_dir(d);
        silk_view v;
        if (!make_view(&m, d, 2 + i % 3, i & 1, 512, 512, &v)) { CHECK(0); break; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_frame_geom g;
        silk_frame_stats st;
        if (!smooth_frame(&a, &m, &v, SILK_FX_HALF, &g, &st)) { CHECK(0); break; }
        memset(seen, 0, m.ntris);
        for (uint32_t t = 0; t < g.ntri; t++) {
            const uint32_t *c = &g.tri[3 * t];
            if (g.tri_added[t]) { added++; continue; }
            untouched++;
            const silk_vrec *r = &g.vrec[c[0]];
            uint32_t o = r->a / 3;
            int ok = r->kind != SILK_VREC_CURVE && r->a % 3 == 0 && o < m.ntris && !seen[o];
            for (int k = 0; k < 3 && ok; k++)
                ok = g.vrec[c[k]].kind != SILK_VREC_CURVE && g.vrec[c[k]].a == 3 * o + (uint32_t)k;
            if (!ok) bad++; else seen[o] = 1;
        }
        CHECK(st.tris_drawn == g.ntri);
        silk_arena_top_release(&a, &mk);
    }
    free(seen);
    printf("  torus: %u untouched, %u added triangles in 20 views\n", untouched, added);
    CHECKF(bad == 0, "%u untouched triangles are not an original triangle (or repeat one)", bad);
    CHECK(untouched > 0 && added > 0);
}

/* Arena exhaustion: from plenty down to nothing, a frame is either the full
 * smoothing, the coarse mesh (fell_back set: the one fall-back of every
 * frame, with or without lines), or, when not even that fits,
 * SILK_ERR_NOMEM - and what is emitted is always closed. */
TEST(small_arena_falls_back)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "torus-576.obj", &m)) { CHECK(0); return; }
    double d[3] = { 0.2, 0.8, 1 };
    silk_view v;
    if (!make_view(&m, d, 2.5, 0, 512, 512, &v)) { CHECK(0); return; }
    silk_arena_mark mk = silk_arena_top_mark(&a);
    silk_frame_geom g;
    silk_frame_stats st;
    if (!smooth_frame(&a, &m, &v, SILK_FX_HALF, &g, &st)) { CHECK(0); return; }
    size_t need = a.top - mk.top;
    uint32_t full_tris = g.ntri;
    silk_arena_top_release(&a, &mk);
    CHECK(!st.fell_back);
    size_t flat_need = 3 * m.ntris * sizeof(silk_vrec) + 3 * m.ntris * sizeof(uint32_t) + m.ntris + 64;

    uint32_t partial = 0, coarse = 0, nomem = 0, full = 0, open = 0, wrong = 0;
    size_t base_free = silk_arena_free_bytes(&a);
    for (size_t avail = need + 64; avail >= 64; avail = avail * 15 / 16) {
        if (avail > base_free) continue;
        silk_arena b = a;                    /* same mesh, less room above it */
        void *pad = silk_arena_alloc(&b, silk_arena_free_bytes(&b) - avail, SILK_MEM_LOAD);
        if (!pad) { CHECK(0); break; }
        silk_error err;
        memset(&st, 0, sizeof st);
        memset(&err, 0, sizeof err);
        silk_status s = silk_frame_smooth(&b, &m, &v, SILK_FX_HALF, SILK_VIS_BRUTE, &g, &st, &err);
        if (s == SILK_ERR_NOMEM) {
            nomem++;
            if (avail > flat_need + 4096) wrong++;
            if (!err.msg[0]) wrong++;
            continue;
        }
        if (s != SILK_OK) { wrong++; continue; }
        topo tp;
        check_topology(&m, &g, &tp);
        if (tp.open_edges || tp.multi_edges || tp.bad_records) open++;
        if (g.ntri == m.ntris && st.fell_back) coarse++;
        else if (g.ntri < full_tris && st.fell_back) partial++;
        else if (g.ntri == full_tris && !st.fell_back) full++;
        else wrong++;
        if (avail >= need && st.fell_back) wrong++;
    }
    printf("  torus frame needs %zu bytes: full %u, partial %u, coarse %u, out of memory %u\n", need, full, partial,
           coarse, nomem);
    CHECKF(open == 0, "%u fallback frames not closed", open);
    CHECKF(wrong == 0, "%u frames in an unexpected state", wrong);
    CHECK(full > 0 && partial == 0 && coarse > 0 && nomem > 0);
}

/* ---- degenerate views and meshes ------------------------------------------ */

static void check_closed_frame(const silk_mesh *m, silk_arena *a, const silk_view *v, const char *what,
                               int closed)
{
    silk_arena_mark mk = silk_arena_top_mark(a);
    silk_frame_geom g;
    silk_frame_stats st;
    if (!smooth_frame(a, m, v, SILK_FX_HALF, &g, &st)) { CHECKF(0, "%s: frame failed", what); return; }
    topo tp;
    check_topology(m, &g, &tp);
    CHECKF(tp.bad_records == 0, "%s: %u bad records", what, tp.bad_records);
    if (closed) CHECKF(tp.open_edges == 0 && tp.multi_edges == 0, "%s: open %u repeated %u", what, tp.open_edges,
                       tp.multi_edges);
    CHECKF(!st.fell_back, "%s: fell back", what);
    silk_arena_top_release(a, &mk);
}

/* N.(E - V) exactly 0: the eye on the tangent plane of a vertex normal. */
TEST(silhouette_through_a_vertex)
{
    silk_arena a;
    silk_mesh m;
    if (!load_shared(&a, "sphere-200.obj", &m)) { CHECK(0); return; }
    int tried = 0;
    for (uint32_t i = 0; i < m.nnormals && tried < 40; i += 5) {
        silk_vec3 n = m.normal[i], p = m.pos[m.normal_vertex[i]];
        /* E - V = k (n.y, -n.x, 0) + j (0, n.z, -n.y): both exactly perpendicular to n */
        silk_camera cam;
        memset(&cam, 0, sizeof cam);
        int64_t k = 3 + (int64_t)(i % 4), j = (int64_t)(i % 3) - 1;
        cam.eye = silk_v3(silk_fx_sat(p.x + k * n.y), silk_fx_sat(p.y - k * n.x + j * n.z),
                          silk_fx_sat(p.z - j * n.y));
        cam.target = silk_v3(0, 0, 0);
        cam.up = silk_v3(0, SILK_FX_ONE, 0);
        cam.fov_deg = SILK_FX_C(60, 1);
        cam.znear = SILK_FX_C(1, 100);
        cam.zfar = SILK_FX_C(100, 1);
        cam.width = cam.height = 256;
        silk_view v;
        silk_error err;
        if (silk_view_init(&v, &cam, &err) != SILK_OK) continue;
        silk_vec3 d = silk_view_to_eye(&v, p);
        CHECK(silk_v3_dot64(n, d) == 0);
        CHECK(silk_normal_visible(&m, &v, i));
        check_closed_frame(&m, &a, &v, "tangent eye", 1);
        tried++;
    }
    CHECK(tried > 10);
}

TEST(eye_inside_and_grazing_views)
{
    silk_arena a;
    silk_mesh m;
    const char *names[] = { "sphere-200.obj", "torus-576.obj", "fandisk-128.obj" };
    for (int mi = 0; mi < 3; mi++) {
        if (!load_shared(&a, names[mi], &m)) { CHECK(0); return; }
        for (int i = 0; i < 12; i++) {
            double d[3];
            random_dir(d);
            silk_view v;
            /* inside (0.05 radii from the centre), very close, very far */
            static const double dist[] = { 0.05, 0.3, 1.01, 60 };
            if (!make_view(&m, d, dist[i % 4], (i / 4) & 1, 320, 240, &v)) { CHECK(0); return; }
            check_closed_frame(&m, &a, &v, names[mi], 1);
        }
    }
}

/* Normals exactly parallel and exactly perpendicular to the view: a cube
 * (every edge a crease) seen straight along its axes. */
TEST(normals_parallel_to_the_view)
{
    static const char cube[] =
        "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    silk_arena a;
    silk_mesh m;
    if (!load_text(&a, ARENA_BYTES, cube, sizeof cube - 1, "cube.obj", &m)) { CHECK(0); return; }
    static const double dirs[][3] = { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0.0001 }, { 1, 1, 0 }, { 1, 1, 1 } };
    for (int i = 0; i < 5; i++)
        for (int ortho = 0; ortho < 2; ortho++) {
            silk_view v;
            if (!make_view(&m, dirs[i], 3, ortho, 256, 256, &v)) { CHECK(0); return; }
            check_closed_frame(&m, &a, &v, "cube", 1);
        }
}

/* A zero-length edge (two vertices at one point, two zero-area triangles)
 * and sliver triangles inside an otherwise closed octahedron. */
TEST(zero_length_edges_and_slivers)
{
    static const char obj[] =
        "v 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv 0 0 1\nv 0 0 1\nv 0 0 -1\nv 0.5 0.5 -0.000001\n"
        /* top: +z split into 5 and 6 */
        "f 1 2 5\nf 2 3 5\nf 3 4 6\nf 4 1 6\nf 5 3 6\nf 6 1 5\n"
        /* bottom, with a sliver vertex 8 almost on edge 1-2 */
        "f 2 8 7\nf 8 1 7\nf 2 1 8\nf 3 2 7\nf 4 3 7\nf 1 4 7\n";
    silk_arena a;
    silk_mesh m;
    if (!load_text(&a, ARENA_BYTES, obj, sizeof obj - 1, "degenerate.obj", &m)) { CHECK(0); return; }
    for (int i = 0; i < 24; i++) {
        double d[3];
        random_dir(d);
        silk_view v;
        if (!make_view(&m, d, 1.5 + i % 3, i & 1, 256, 256, &v)) { CHECK(0); return; }
        silk_arena_mark mk = silk_arena_top_mark(&a);
        silk_frame_geom g;
        silk_frame_stats st;
        if (!smooth_frame(&a, &m, &v, SILK_FX_HALF, &g, &st)) { CHECK(0); return; }
        topo tp;
        check_topology(&m, &g, &tp);
        /* the input is closed (the sliver "f 2 1 8" fills the gap between
         * edge 1-2 and vertex 8), so the output must be too */
        CHECKF(tp.bad_records == 0 && tp.open_edges == 0, "view %d: bad %u open %u", i, tp.bad_records,
               tp.open_edges);
        silk_arena_top_release(&a, &mk);
    }
}

/* Open and non-manifold input: boundary edges are feature curves; nothing
 * may crash and every record must be valid. */
TEST(boundary_and_nonmanifold_edges)
{
    /* an open tube: 12 around, two circular boundary loops */
    char open_obj[2048];
    size_t n = 0;
    for (int i = 0; i < 12; i++) {
        double ang = i * 3.14159265358979 / 6;
        n += (size_t)snprintf(open_obj + n, sizeof open_obj - n, "v %.6f 0 %.6f\nv %.6f 1 %.6f\n", cos(ang),
                              sin(ang), cos(ang), sin(ang));
    }
    for (int i = 0; i < 12; i++) {
        int a0 = 2 * i + 1, a1 = 2 * i + 2, b0 = 2 * ((i + 1) % 12) + 1, b1 = b0 + 1;
        n += (size_t)snprintf(open_obj + n, sizeof open_obj - n, "f %d %d %d\nf %d %d %d\n", a0, a1, b1, a0, b1, b0);
    }
    /* a book: three half-disc pages on one spine (the non-manifold edge
     * 1-2), each a fan of five triangles from vertex 1 whose free edge is a
     * half circle turning 30 degrees at each vertex, so a curved boundary
     * polyline from spine end to spine end; plus a closed tetrahedron.
     * (Pages of one triangle have straight sides since polylines stop at
     * sharp turns: nothing of theirs would be re-meshed.) */
    char book_obj[2048];
    size_t nb = (size_t)snprintf(book_obj, sizeof book_obj, "v 0 -1 0\nv 0 1 0\n");
    static const double page_dir[3][3] = { { 1, 0, 0.2 }, { -1, 0, 0.3 }, { 0.1, 0, -1 } };
    for (int p = 0; p < 3; p++) {
        double l = sqrt(page_dir[p][0] * page_dir[p][0] + page_dir[p][2] * page_dir[p][2]);
        for (int i = 1; i <= 5; i++) {
            double th = i * 3.14159265358979 / 6;
            nb += (size_t)snprintf(book_obj + nb, sizeof book_obj - nb, "v %.6f %.6f %.6f\n",
                                   sin(th) * page_dir[p][0] / l, -cos(th), sin(th) * page_dir[p][2] / l);
        }
    }
    for (int p = 0; p < 3; p++) {
        int v0 = 3 + 5 * p;   /* the page's first rim vertex */
        for (int i = 0; i < 5; i++)
            nb += (size_t)snprintf(book_obj + nb, sizeof book_obj - nb, "f 1 %d %d\n", v0 + i, i < 4 ? v0 + i + 1 : 2);
    }
    nb += (size_t)snprintf(book_obj + nb, sizeof book_obj - nb,
                           "v 3 0 0\nv 4 0 0\nv 3 1 0\nv 3 0 1\nf 18 20 19\nf 18 19 21\nf 19 20 21\nf 18 21 20\n");
    const char *texts[] = { open_obj, book_obj };
    size_t lens[] = { n, nb };
    for (int k = 0; k < 2; k++) {
        silk_arena a;
        silk_mesh m;
        if (!load_text(&a, ARENA_BYTES, texts[k], lens[k], k ? "book.obj" : "open.obj", &m)) { CHECK(0); return; }
        CHECK(k ? m.nnonmanifold_edges > 0 : m.nboundary_edges > 0);
        uint32_t remeshed = 0;
        for (int i = 0; i < 24; i++) {
            double d[3];
            random_dir(d);
            silk_view v;
            if (!make_view(&m, d, 1.5 + i % 3, i & 1, 256, 256, &v)) { CHECK(0); return; }
            silk_arena_mark mk = silk_arena_top_mark(&a);
            silk_frame_geom g;
            silk_frame_stats st;
            if (!smooth_frame(&a, &m, &v, SILK_FX_HALF, &g, &st)) { CHECK(0); return; }
            topo tp;
            check_topology(&m, &g, &tp);
            CHECK(tp.bad_records == 0);
            if (k == 0) CHECKF(tp.multi_edges == 0, "open tube: %u repeated edges", tp.multi_edges);
            remeshed += g.ntri > m.ntris;
            silk_arena_top_release(&a, &mk);
        }
        CHECKF(remeshed > 0, "%s: never re-meshed", k ? "book" : "open");
        printf("  %s: %u triangles, %u boundary and %u non-manifold edges, re-meshed in %u of 24 views\n",
               k ? "book" : "open tube", m.ntris, m.nboundary_edges, m.nnonmanifold_edges, remeshed);
    }
}

int main(void)
{
    arena_buf = malloc(ARENA_BYTES);
    RUN(flat_is_one_corner_record_per_corner);
    RUN(closed_mesh_stays_closed_sphere);
    RUN(closed_mesh_stays_closed_torus);
    RUN(closed_mesh_stays_closed_features);
    RUN(closed_mesh_stays_closed_organic);
    RUN(sphere_triangle_count_vs_paper);
    RUN(untouched_triangles_are_original);
    RUN(small_arena_falls_back);
    RUN(silhouette_through_a_vertex);
    RUN(eye_inside_and_grazing_views);
    RUN(normals_parallel_to_the_view);
    RUN(zero_length_edges_and_slivers);
    RUN(boundary_and_nonmanifold_edges);
    free(arena_buf);
    return check_done();
}
