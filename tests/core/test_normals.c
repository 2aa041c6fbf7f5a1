/*
 * test_normals.c - crease and smoothing-group flags, and the split,
 * angle-weighted shading normals (paper III-B, Fig. 8), against a double
 * reference; file normals; cone apexes split into face normals (cone-70,
 * armadillo-500's spike, `silk gen cone`, pyramids either side of 50
 * degrees); and the measurements behind the default crease angle and the
 * apex threshold (docs/formats.md).
 */
#define _POSIX_C_SOURCE 200809L   /* popen, for `silk gen` */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "support/testmesh.h"
#include "support/testvec.h"

#define ARENA_BYTES (48u << 20)
#define PI 3.14159265358979323846

/* The silk program next to this test (BUILD/tests/test_normals ->
 * BUILD/silk), for `silk gen`. */
static char silk_path[512] = "build/silk";

/* Runs `silk gen ARGS -o -` and parses what it writes. */
static int gen_obj(const char *args, tm_fixture *f)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s gen %s -o -", silk_path, args);
    FILE *fp = popen(cmd, "r");
    if (!fp) return 0;
    size_t len;
    char *text = tm_read_stream(fp, &len);
    int rc = pclose(fp);
    int ok = rc == 0 && text && tm_fixture_parse_obj(text, f);
    free(text);
    return ok;
}

/* ---- the double reference ------------------------------------------------------------ */

static void posd(const silk_mesh *m, uint32_t v, double p[3])
{
    p[0] = fx2d(m->pos[v].x);
    p[1] = fx2d(m->pos[v].y);
    p[2] = fx2d(m->pos[v].z);
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static double len3(const double a[3]) { return sqrt(dot3(a, a)); }

/* Unit face normal (zero for zero area) and the angle at each corner. */
static void ref_face(const silk_mesh *m, uint32_t t, double n[3], double ang[3])
{
    double p[3][3];
    for (int k = 0; k < 3; k++) posd(m, m->tri[3 * t + k], p[k]);
    double e1[3], e2[3];
    for (int i = 0; i < 3; i++) e1[i] = p[1][i] - p[0][i], e2[i] = p[2][i] - p[0][i];
    cross3(e1, e2, n);
    double l = len3(n);
    for (int i = 0; i < 3; i++) n[i] = l > 0 ? n[i] / l : 0;
    for (int k = 0; k < 3; k++) {
        double a[3], b[3], c[3];
        for (int i = 0; i < 3; i++) a[i] = p[(k + 1) % 3][i] - p[k][i], b[i] = p[(k + 2) % 3][i] - p[k][i];
        cross3(a, b, c);
        ang[k] = l > 0 ? atan2(len3(c), dot3(a, b)) : 0;
    }
}

/* Dihedral angle (between face normals) of a two-triangle edge in degrees,
 * or -1 when it has none. */
static double ref_dihedral(const silk_mesh *m, uint32_t e)
{
    const silk_edge *ed = &m->edge[e];
    if (ed->t[1] == SILK_NO_INDEX || (ed->flags & (SILK_EDGE_NONMANIFOLD | SILK_EDGE_DEGENERATE))) return -1;
    double n0[3], n1[3], a[3];
    ref_face(m, ed->t[0], n0, a);
    ref_face(m, ed->t[1], n1, a);
    double d = dot3(n0, n1);
    return acos(d > 1 ? 1 : (d < -1 ? -1 : d)) * 180 / PI;
}

static uint32_t find(uint32_t *p, uint32_t c)
{
    while (p[c] != c) c = p[c] = p[p[c]];
    return c;
}
static void unite(uint32_t *p, uint32_t a, uint32_t b)
{
    a = find(p, a);
    b = find(p, b);
    if (a != b) p[a > b ? a : b] = a < b ? a : b;
}

/* normals.c's SILK_APEX_DEG.  Groups within APEX_MARGIN of it may go either
 * way: the core compares rounded unit vectors (about 0.002 degrees there). */
#define APEX_DEG 50.0
#define APEX_MARGIN 0.01

/* Corners of one vertex connected through non-feature edges (and the
 * corners of a triangle that repeats a vertex) share a root in p. */
static void ref_groups(const silk_mesh *m, uint32_t *p)
{
    uint32_t nc = 3 * m->ntris;
    for (uint32_t c = 0; c < nc; c++) p[c] = c;
    for (uint32_t t = 0; t < m->ntris; t++)
        for (int k = 0; k < 3; k++)
            for (int j = k + 1; j < 3; j++)
                if (m->tri[3 * t + k] == m->tri[3 * t + j]) unite(p, 3 * t + k, 3 * t + j);
    for (uint32_t e = 0; e < m->nedges; e++) {
        const silk_edge *ed = &m->edge[e];
        if (ed->t[1] == SILK_NO_INDEX || (ed->flags & SILK_EDGE_FEATURE)) continue;
        for (int end = 0; end < 2; end++)
            for (int k = 0; k < 3; k++)
                for (int j = 0; j < 3; j++)
                    if (m->tri[3 * ed->t[0] + k] == ed->v[end] && m->tri[3 * ed->t[1] + j] == ed->v[end])
                        unite(p, 3 * ed->t[0] + k, 3 * ed->t[1] + j);
    }
}

/* Per group (at its root corner): the angle in degrees between its
 * angle-weighted normal and the nearest of its (non-degenerate) faces, the
 * measure of the apex rule; -1 for a group of one corner or one whose
 * weighted normal vanishes. */
static void apex_angles(const silk_mesh *m, uint32_t *p, double *apex)
{
    uint32_t nc = 3 * m->ntris;
    double *sum = calloc(nc, 3 * sizeof(double));
    uint32_t *members = calloc(nc, sizeof *members);
    for (uint32_t t = 0; t < m->ntris; t++) {
        double n[3], ang[3];
        ref_face(m, t, n, ang);
        for (int k = 0; k < 3; k++) {
            uint32_t r = find(p, 3 * t + k);
            for (int i = 0; i < 3; i++) sum[3 * r + i] += ang[k] * n[i];
            members[r]++;
        }
    }
    for (uint32_t c = 0; c < nc; c++) apex[c] = -1;
    for (uint32_t c = 0; c < nc; c++) {
        uint32_t r = find(p, c);
        double n[3], ang[3], l = len3(&sum[3 * r]);
        ref_face(m, c / 3, n, ang);
        if (members[r] < 2 || l < 1e-12 || len3(n) == 0) continue;
        double d = dot3(n, &sum[3 * r]) / l;
        double a = acos(d > 1 ? 1 : (d < -1 ? -1 : d)) * 180 / PI;
        if (apex[r] < 0 || a < apex[r]) apex[r] = a;
    }
    free(sum);
    free(members);
}

/* The apex rule: a group whose weighted normal is more than APEX_DEG from
 * every one of its faces falls apart into single corners.  Within
 * APEX_MARGIN of the limit, m's own choice is taken (its corners have one
 * normal or several).  Returns the number of groups split. */
static uint32_t ref_split_apexes(const silk_mesh *m, uint32_t *p)
{
    uint32_t nc = 3 * m->ntris, split = 0;
    double *apex = malloc(sizeof *apex * (nc + 1));
    uint8_t *cut = calloc(nc + 1, 1);
    apex_angles(m, p, apex);
    for (uint32_t c = 0; c < nc; c++) {
        uint32_t r = find(p, c);
        if (r != c || apex[r] < 0) continue;
        if (fabs(apex[r] - APEX_DEG) <= APEX_MARGIN) {
            for (uint32_t d = 0; d < nc; d++)
                if (find(p, d) == r && m->tri_normal[d] != m->tri_normal[r]) cut[r] = 1;
        } else {
            cut[r] = apex[r] > APEX_DEG;
        }
        split += cut[r];
    }
    uint32_t *root = malloc(sizeof *root * (nc + 1));
    for (uint32_t c = 0; c < nc; c++) root[c] = find(p, c);
    for (uint32_t c = 0; c < nc; c++) p[c] = cut[root[c]] ? c : root[c];
    free(root);
    free(cut);
    free(apex);
    return split;
}

typedef struct normal_report {
    double max_err_ulp;      /* worst component error of a shading normal */
    double max_err_kappa;    /* its conditioning (sum of weights / length of the weighted sum) */
    uint32_t groups, checked, apexes;
} normal_report;

/* Checks the crease flags against the double dihedral angle (edges within
 * margin_deg of the threshold may go either way), then the grouping and the
 * normals against a double angle-weighted average over groups formed from
 * m's feature flags and split at apexes. */
static void check_normals(const silk_mesh *m, double crease_deg, double margin_deg, normal_report *r)
{
    memset(r, 0, sizeof *r);
    for (uint32_t e = 0; e < m->nedges; e++) {
        double d = ref_dihedral(m, e);
        int crease = (m->edge[e].flags & SILK_EDGE_CREASE) != 0;
        if (d < 0) CHECKF(!crease, "edge %u has no dihedral angle but is a crease", e);
        else if (fabs(d - crease_deg) > margin_deg)
            CHECKF(crease == (d > crease_deg), "edge %u dihedral %.4f crease %d", e, d, crease);
    }
    uint32_t nc = 3 * m->ntris;
    uint32_t *p = malloc(sizeof *p * (nc + 1));
    ref_groups(m, p);
    r->apexes = ref_split_apexes(m, p);
    double *sum = calloc(nc, 3 * sizeof(double)), *wsum = calloc(nc, sizeof(double));
    uint32_t *silk_of = malloc(sizeof *silk_of * nc), *ref_of = malloc(sizeof *ref_of * (m->nnormals + 1));
    for (uint32_t c = 0; c < nc; c++) silk_of[c] = SILK_NO_INDEX;
    for (uint32_t g = 0; g <= m->nnormals; g++) ref_of[g] = SILK_NO_INDEX;
    for (uint32_t t = 0; t < m->ntris; t++) {
        double n[3], ang[3];
        ref_face(m, t, n, ang);
        for (int k = 0; k < 3; k++) {
            uint32_t c = 3 * t + k, r0 = find(p, c), g = m->tri_normal[c];
            for (int i = 0; i < 3; i++) sum[3 * r0 + i] += ang[k] * n[i];
            wsum[r0] += ang[k];
            /* the same partition: ref group <-> silk normal, one to one */
            if (silk_of[r0] == SILK_NO_INDEX) silk_of[r0] = g;
            CHECKF(silk_of[r0] == g, "corner %u: normal %u, its group has %u", c, g, silk_of[r0]);
            if (g < m->nnormals) {
                if (ref_of[g] == SILK_NO_INDEX) ref_of[g] = r0;
                CHECKF(ref_of[g] == r0, "normal %u spans two groups", g);
            }
        }
    }
    for (uint32_t c = 0; c < nc; c++) {
        if (find(p, c) != c) continue;
        r->groups++;
        double l = len3(&sum[3 * c]);
        if (l < 1e-9) continue;
        r->checked++;
        silk_vec3 n = m->normal[m->tri_normal[c]];
        double got[3] = { fx2d(n.x), fx2d(n.y), fx2d(n.z) };
        /* Rounded face normals and angles, summed exactly, normalised once:
         * about 1 ulp, growing with the cancellation in the sum (kappa). */
        double kappa = wsum[c] / l;
        for (int i = 0; i < 3; i++) {
            double err = fabs(got[i] - sum[3 * c + i] / l) * 65536;
            CHECKF(err <= 1.0 + 0.5 * kappa, "normal %u component %d off by %.2f ulp (kappa %.2f)",
                   m->tri_normal[c], i, err, kappa);
            if (err > r->max_err_ulp) {
                r->max_err_ulp = err;
                r->max_err_kappa = kappa;
            }
        }
    }
    CHECKF(r->groups == m->nnormals, "%u reference groups, %u normals", r->groups, m->nnormals);
    free(p);
    free(sum);
    free(wsum);
    free(silk_of);
    free(ref_of);
}

/* ---- small meshes ------------------------------------------------------------------------- */

static const double cube_pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
static const uint32_t cube_tri[] = {
    0, 3, 2, 0, 2, 1,  4, 5, 6, 4, 6, 7,  0, 1, 5, 0, 5, 4,
    2, 3, 7, 2, 7, 6,  1, 2, 6, 1, 6, 5,  0, 4, 7, 0, 7, 3,
};

TEST(cube_split_normals)
{
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, cube_pos, 8, cube_tri, 12) && tm_fixture_build(&f) == SILK_OK);
    const silk_mesh *m = &f.m;
    CHECK(m->nnormals == 24);
    uint32_t per_vertex[8] = { 0 };
    for (uint32_t g = 0; g < m->nnormals; g++) {
        silk_vec3 n = m->normal[g];
        per_vertex[m->normal_vertex[g]]++;
        /* exactly a unit axis: the two triangles of a face are coplanar */
        int axes = (n.x != 0) + (n.y != 0) + (n.z != 0);
        int unit = silk_fx_abs(n.x) + silk_fx_abs(n.y) + silk_fx_abs(n.z) == SILK_FX_ONE;
        CHECKF(axes == 1 && unit, "normal %u = %d %d %d", g, n.x, n.y, n.z);
        if (g > 0) CHECK(m->normal_vertex[g] >= m->normal_vertex[g - 1]);   /* vertex order */
    }
    for (int v = 0; v < 8; v++) CHECKF(per_vertex[v] == 3, "vertex %d has %u normals", v, per_vertex[v]);
    /* both triangles of a face share the normal at a shared corner */
    CHECK(m->tri_normal[0] == m->tri_normal[3]);
    CHECK(m->nfeature_edges == 12);   /* the cube's edges, not its diagonals */
    normal_report r;
    check_normals(m, fx2d(f.opts.crease_deg), 1e-3, &r);
    CHECK(r.max_err_ulp == 0);
    free(f.buf);
}

TEST(crease_threshold)
{
    /* two triangles hinged on the x axis, 50 degrees between their normals */
    double s = sin(50 * PI / 180), c = cos(50 * PI / 180);
    double pos[] = { 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -c, -s };
    static const uint32_t tri[] = { 0, 1, 2, 1, 0, 3 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    f.opts.crease_deg = SILK_FX_C(40, 1);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2) && tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.edge[f.m.tri_edge[0]].flags & SILK_EDGE_CREASE);
    CHECK(f.m.nnormals == 6);
    tm_fixture_reset(&f);
    f.opts.crease_deg = SILK_FX_C(60, 1);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2) && tm_fixture_build(&f) == SILK_OK);
    CHECK(!(f.m.edge[f.m.tri_edge[0]].flags & SILK_EDGE_CREASE));
    CHECK(f.m.nnormals == 4);   /* the hinge vertices have one normal: the bisector */
    CHECK(f.m.normal[f.m.tri_normal[0]].x == 0);   /* the bisector of the two faces */
    normal_report r;
    check_normals(&f.m, 60, 1e-3, &r);
    CHECKF(r.max_err_ulp <= 3, "hinge normal error %.2f ulp", r.max_err_ulp);
    free(f.buf);
}

TEST(smoothing_groups)
{
    /* a flat square whose two triangles are in different smoothing groups */
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
    static const uint32_t tri[] = { 0, 1, 2, 0, 2, 3 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2));
    uint32_t groups[2] = { 1, 2 };
    f.in.tri_group = groups;
    CHECK(tm_fixture_build(&f) == SILK_OK);
    uint32_t diag = f.m.tri_edge[2];   /* side 2-0 of triangle 0 */
    CHECK(f.m.edge[diag].flags & SILK_EDGE_GROUPS);
    CHECK(!(f.m.edge[diag].flags & SILK_EDGE_CREASE));
    CHECK(f.m.nnormals == 6 && f.m.nfeature_edges == 5);
    tm_fixture_reset(&f);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 2));
    groups[1] = 1;
    f.in.tri_group = groups;
    CHECK(tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nnormals == 4 && f.m.nfeature_edges == 4);
    free(f.buf);
}

TEST(file_normals)
{
    static const double pos[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    static const uint32_t tri[] = { 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2 };
    tm_fixture f;
    tm_fixture_init(&f, 1 << 16);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 4));
    /* one file normal per vertex, not unit length, and one zero normal */
    silk_vec3 fn[4] = { { 0, 0, 0 }, { d2fx(3), 0, 0 }, { 0, d2fx(0.5), 0 }, { d2fx(1), d2fx(1), d2fx(1) } };
    silk_index tfn[12];
    for (int c = 0; c < 12; c++) tfn[c] = tri[c];
    f.in.file_normal = fn;
    f.in.tri_file_normal = tfn;
    f.in.nfile_normals = 4;
    f.opts.normals = SILK_NORMALS_FILE;
    CHECK(tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nnormals == 4);
    CHECK(f.m.normal[f.m.tri_normal[1]].y == SILK_FX_ONE);   /* vertex 2: (0,0.5,0) normalised */
    CHECK(f.m.normal[f.m.tri_normal[2]].x == SILK_FX_ONE);
    silk_vec3 n3 = f.m.normal[f.m.tri_normal[5]];
    CHECK(abs(n3.x - 37837) <= 1 && n3.x == n3.y && n3.y == n3.z);   /* 1/sqrt 3 */
    silk_vec3 n0 = f.m.normal[f.m.tri_normal[0]];                     /* zero: a face normal */
    CHECK(abs(silk_fx_abs(n0.x) + silk_fx_abs(n0.y) + silk_fx_abs(n0.z) - SILK_FX_ONE) <= 2);
    CHECK(f.m.nfeature_edges == 6);   /* features are still found: every edge is sharp */

    /* per-corner file normals: three normals at each vertex */
    tm_fixture_reset(&f);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 4));
    silk_vec3 fn12[12];
    for (int c = 0; c < 12; c++) {
        fn12[c] = silk_v3(0, 0, d2fx(c + 1));
        tfn[c] = (silk_index)c;
    }
    f.in.file_normal = fn12;
    f.in.tri_file_normal = tfn;
    f.in.nfile_normals = 12;
    CHECK(tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nnormals == 12 && f.m.normal[5].z == SILK_FX_ONE);

    /* a corner without a file normal: computed normals instead */
    tm_fixture_reset(&f);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 4));
    tfn[7] = SILK_NO_INDEX;
    f.in.file_normal = fn12;
    f.in.tri_file_normal = tfn;
    f.in.nfile_normals = 12;
    CHECK(tm_fixture_build(&f) == SILK_OK);
    CHECK(f.m.nnormals == 12 && f.m.normal[5].z != SILK_FX_ONE);
    normal_report r;
    check_normals(&f.m, fx2d(f.opts.crease_deg), 1e-3, &r);

    /* a file normal index out of range is an error, not a crash */
    tm_fixture_reset(&f);
    CHECK(tm_fixture_input(&f, pos, 4, tri, 4));
    tfn[7] = 12;
    f.in.file_normal = fn12;
    f.in.tri_file_normal = tfn;
    f.in.nfile_normals = 12;
    CHECK(tm_fixture_build(&f) == SILK_ERR_ARG);
    free(f.buf);
}

/* ---- the shared meshes ----------------------------------------------------------------------- */

static const char *const all_meshes[] = {
    "sphere-200", "sphere-fine", "knot-480", "knot-fine", "bunny-500", "bunny-2k", "bunny-fine", "fish-500",
    "fish-fine", "cat-500", "cat-fine", "cow-500", "cow-fine", "spot-500", "spot-fine", "maxplanck-500",
    "maxplanck-fine", "venus-500", "venus-fine", "feline-500", "feline-2k", "feline-fine", "armadillo-500",
    "armadillo-fine", "dragon-500", "dragon-5k", "dragon-fine", "fandisk-128", "fandisk-1000", "fandisk-fine",
    "torus-576", "torus-fine", "pawn-304", "cone-70", "springer-500", "springer-fine", "wingnut-500",
    "wingnut-fine", "rockerarm-500", "rockerarm-fine",
};

TEST(shared_meshes_normals_vs_reference)
{
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    double worst = 0, worst_kappa = 0;
    const char *worst_name = "";
    for (size_t i = 0; i < sizeof all_meshes / sizeof *all_meshes; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, all_meshes[i]), "cannot read %s", all_meshes[i]);
        silk_status st = tm_fixture_build(&f);
        CHECKF(st == SILK_OK, "%s: %s", all_meshes[i], f.err.msg);
        if (st != SILK_OK) continue;
        normal_report r;
        check_normals(&f.m, fx2d(f.opts.crease_deg), 1e-3, &r);
        printf("  %-15s %6u normals  worst %.2f ulp (kappa %.2f)\n", all_meshes[i], f.m.nnormals, r.max_err_ulp,
               r.max_err_kappa);
        if (r.max_err_ulp > worst) worst = r.max_err_ulp, worst_kappa = r.max_err_kappa, worst_name = all_meshes[i];
    }
    printf("  worst normal component error %.2f ulp (%s, kappa %.2f)\n", worst, worst_name, worst_kappa);
    free(f.buf);
}

/* Segments of the fine fandisk's sharp edges: where the real creases are. */
typedef struct seg { double a[3], b[3]; } seg;

static double point_seg_dist(const double p[3], const seg *s)
{
    double ab[3], ap[3];
    for (int i = 0; i < 3; i++) ab[i] = s->b[i] - s->a[i], ap[i] = p[i] - s->a[i];
    double l2 = dot3(ab, ab), t = l2 > 0 ? dot3(ab, ap) / l2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    double d[3];
    for (int i = 0; i < 3; i++) d[i] = p[i] - (s->a[i] + t * ab[i]);
    return len3(d);
}

/* The dihedral-angle distribution of the coarse models, and what the
 * default crease angle makes of it (docs/formats.md has the table). */
TEST(crease_default_on_shared_meshes)
{
    static const char *const names[] = {
        "bunny-500", "cat-500", "cow-500", "spot-500", "armadillo-500", "dragon-500", "fish-500", "venus-500",
        "feline-500", "maxplanck-500", "springer-500", "knot-480", "sphere-200", "torus-576", "rockerarm-500",
        "wingnut-500", "pawn-304", "fandisk-128", "cone-70",
    };
    static const double th[] = { 30, 45, 60, 70, 80, 90 };
    double deflt = fx2d(SILK_DEFAULT_CREASE_DEG);
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    printf("  default crease angle %.1f degrees\n", deflt);
    printf("  %-14s %5s  %-28s  crease edges at (deg)          default\n", "mesh", "edges",
           "dihedral histogram 0..180/20");
    printf("  %-14s %5s  %-28s  %5.0f %5.0f %5.0f %5.0f %5.0f %5.0f\n", "", "", "", th[0], th[1], th[2], th[3],
           th[4], th[5]);
    uint32_t organic = 0, organic_edges = 0;
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, names[i]), "cannot read %s", names[i]);
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", names[i], f.err.msg); continue; }
        const silk_mesh *m = &f.m;
        uint32_t hist[9] = { 0 }, above[6] = { 0 }, creases = 0;
        for (uint32_t e = 0; e < m->nedges; e++) {
            double d = ref_dihedral(m, e);
            creases += (m->edge[e].flags & SILK_EDGE_CREASE) != 0;
            if (d < 0) continue;
            hist[d >= 180 ? 8 : (int)(d / 20)]++;
            for (int k = 0; k < 6; k++) above[k] += d > th[k];
        }
        char h[64];
        int n = 0;
        for (int k = 0; k < 9; k++) n += snprintf(h + n, sizeof h - (size_t)n, "%u%s", hist[k], k < 8 ? "," : "");
        printf("  %-14s %5u  %-28s  %5u %5u %5u %5u %5u %5u  %5u\n", names[i], m->nedges, h, above[0], above[1],
               above[2], above[3], above[4], above[5], creases);
        normal_report r;
        check_normals(m, deflt, 1e-3, &r);
        if (i < 15) organic += creases, organic_edges += m->nedges;

        if (!strcmp(names[i], "sphere-200") || !strcmp(names[i], "torus-576"))
            CHECKF(creases == 0, "%s has %u creases", names[i], creases);
        if (!strcmp(names[i], "cone-70")) {
            /* exactly the rim: 35 edges with both ends at y = 0, off the axis */
            uint32_t rim = 0;
            for (uint32_t e = 0; e < m->nedges; e++) {
                silk_vec3 a = m->pos[m->edge[e].v[0]], b = m->pos[m->edge[e].v[1]];
                int on_rim = a.y == 0 && b.y == 0 && (a.x || a.z) && (b.x || b.z);
                rim += on_rim;
                CHECKF(on_rim == ((m->edge[e].flags & SILK_EDGE_CREASE) != 0), "cone edge %u", e);
            }
            CHECK(rim == 35 && creases == 35);
            /* two normals at each rim vertex, one at the base centre, and
             * one per triangle at the apex (split, test apex_split) */
            uint32_t *count = calloc(m->nverts, sizeof *count);
            for (uint32_t g = 0; g < m->nnormals; g++) count[m->normal_vertex[g]]++;
            for (uint32_t v = 0; v < m->nverts; v++) {
                int on_rim = m->pos[v].y == 0 && (m->pos[v].x || m->pos[v].z), apex = m->pos[v].y > 0;
                CHECKF(count[v] == (apex ? 35u : on_rim ? 2u : 1u), "cone vertex %u has %u normals", v, count[v]);
            }
            CHECK(m->nnormals == 35 * 2 + 1 + 35);
            free(count);
        }
        if (!strcmp(names[i], "fandisk-128")) {
            /* the real creases: coarse edges lying (ends and middle within 1%
             * of the model size) along sharp edges (> 45 deg) of fandisk-fine */
            silk_mesh coarse = *m;
            tm_fixture g;
            tm_fixture_init(&g, ARENA_BYTES);
            CHECK(tm_fixture_read_shared(&g, "fandisk-fine") && tm_fixture_build(&g) == SILK_OK);
            seg *sharp = malloc(sizeof *sharp * g.m.nedges);
            uint32_t nsharp = 0;
            for (uint32_t e = 0; e < g.m.nedges; e++)
                if (ref_dihedral(&g.m, e) > 45) {
                    posd(&g.m, g.m.edge[e].v[0], sharp[nsharp].a);
                    posd(&g.m, g.m.edge[e].v[1], sharp[nsharp].b);
                    nsharp++;
                }
            double lo[3], hi[3], dg[3];
            posd(&g.m, 0, lo);
            posd(&g.m, 0, hi);
            for (uint32_t v = 0; v < g.m.nverts; v++) {
                double p[3];
                posd(&g.m, v, p);
                for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], p[k]), hi[k] = fmax(hi[k], p[k]);
            }
            for (int k = 0; k < 3; k++) dg[k] = hi[k] - lo[k];
            double tol = 0.01 * len3(dg);
            uint32_t real = 0, real_kept = 0, real_sharp = 0, spurious = 0;
            for (uint32_t e = 0; e < coarse.nedges; e++) {
                double p[3][3];
                posd(&coarse, coarse.edge[e].v[0], p[0]);
                posd(&coarse, coarse.edge[e].v[1], p[1]);
                for (int k = 0; k < 3; k++) p[2][k] = (p[0][k] + p[1][k]) / 2;
                int on = 1;
                for (int q = 0; q < 3 && on; q++) {
                    double best = 1e30;
                    for (uint32_t s = 0; s < nsharp; s++) best = fmin(best, point_seg_dist(p[q], &sharp[s]));
                    on = best < tol;
                }
                int crease = (coarse.edge[e].flags & SILK_EDGE_CREASE) != 0;
                double d = ref_dihedral(&coarse, e);
                real += on;
                real_kept += on && crease;
                spurious += !on && crease;
                if (on && d >= 45) {
                    real_sharp++;
                    CHECKF(crease, "fandisk-128 edge %u (%.1f deg) lies on a real crease but is not one", e, d);
                }
            }
            printf("  fandisk-128: %u edges on real creases (%u of them sharper than 45 deg), %u kept, "
                   "%u other creases\n", real, real_sharp, real_kept, spurious);
            free(sharp);
            free(g.buf);
        }
    }
    printf("  the 15 organic / smooth models: %u crease edges of %u (%.1f%%)\n", organic, organic_edges,
           100.0 * organic / organic_edges);
    free(f.buf);
}

/* ---- cone apexes (normals.c split_apex_groups) ------------------------------------------- */

/* Checks that every corner at v has a normal of its own, equal to its
 * triangle's face normal (the core's, to 1 ulp per component, and the double
 * one, to 1.5 ulp).  Returns the number of corners. */
static uint32_t check_split_vertex(const silk_mesh *m, uint32_t v, double *worst_ulp)
{
    uint32_t n = 0;
    for (uint32_t c = 0; c < 3 * m->ntris; c++) {
        if (m->tri[c] != v) continue;
        n++;
        uint32_t t = c / 3, g = m->tri_normal[c];
        for (uint32_t d = 0; d < c; d++)
            if (m->tri[d] == v) CHECKF(m->tri_normal[d] != g, "vertex %u: corners %u and %u share normal %u", v, d, c, g);
        silk_vec3 got = m->normal[g], fn = silk_mesh_face_normal(m, t);
        double dn[3], ang[3], err = 0, ferr = 0;
        ref_face(m, t, dn, ang);
        for (int i = 0; i < 3; i++) {
            ferr = fmax(ferr, fabs(fx2d((&got.x)[i]) - fx2d((&fn.x)[i])) * 65536);
            err = fmax(err, fabs(fx2d((&got.x)[i]) - dn[i]) * 65536);
        }
        CHECKF(ferr <= 1 && err <= 1.5, "vertex %u corner %u: normal %.2f ulp from the core's face normal, %.2f from "
               "the exact one", v, c, ferr, err);
        *worst_ulp = fmax(*worst_ulp, err);
    }
    return n;
}

/* The vertices the core split at apexes: some group of corners connected
 * through non-feature edges holds more than one normal.  Fills at most max
 * of them into vs (in vertex order); returns how many there are. */
static uint32_t split_vertices(const silk_mesh *m, uint32_t *vs, uint32_t max)
{
    uint32_t nc = 3 * m->ntris, n = 0;
    uint32_t *p = malloc(sizeof *p * (nc + 1));
    uint8_t *hit = calloc(m->nverts + 1, 1);
    ref_groups(m, p);
    for (uint32_t c = 0; c < nc; c++) {
        uint32_t r = find(p, c);
        if (m->tri_normal[c] != m->tri_normal[r]) hit[m->tri[c]] = 1;
    }
    for (uint32_t v = 0; v < m->nverts; v++)
        if (hit[v]) {
            if (n < max) vs[n] = v;
            n++;
        }
    free(hit);
    free(p);
    return n;
}

/* The apex angle of vertex v's groups (the largest, as apex_angles measures
 * it), -1 when none has one. */
static double vertex_apex_angle(const silk_mesh *m, uint32_t v)
{
    uint32_t nc = 3 * m->ntris;
    uint32_t *p = malloc(sizeof *p * (nc + 1));
    double *apex = malloc(sizeof *apex * (nc + 1)), worst = -1;
    ref_groups(m, p);
    apex_angles(m, p, apex);
    for (uint32_t c = 0; c < nc; c++)
        if (m->tri[c] == v) worst = fmax(worst, apex[find(p, c)]);
    free(p);
    free(apex);
    return worst;
}

/* cone-70's apex: its averaged normal points up the axis, 56 degrees from
 * every face, so its 35 corners are split and each keeps its face normal;
 * armadillo-500's one spike the same; nothing else on either. */
TEST(apex_split_cone_and_spike)
{
    static const char *const names[] = { "cone-70", "armadillo-500" };
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    for (int i = 0; i < 2; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, names[i]), "cannot read %s", names[i]);
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", names[i], f.err.msg); continue; }
        const silk_mesh *m = &f.m;
        uint32_t vs[4], n = split_vertices(m, vs, 4);
        CHECKF(n == 1, "%s: %u vertices split", names[i], n);
        if (n != 1) continue;
        if (i == 0) CHECKF(m->pos[vs[0]].y == SILK_FX_C(3, 2) && m->pos[vs[0]].x == 0 && m->pos[vs[0]].z == 0,
                           "cone-70: split vertex %u is not the apex", vs[0]);
        double worst = 0, apex = vertex_apex_angle(m, vs[0]);
        uint32_t corners = check_split_vertex(m, vs[0], &worst);
        CHECKF(corners >= 3 && apex > APEX_DEG, "%s: vertex %u, %u corners, %.2f deg", names[i], vs[0], corners, apex);
        printf("  %-14s vertex %u at (%.3f %.3f %.3f): %u corners, group normal %.2f deg from the nearest face; "
               "split, normals within %.2f ulp of the faces'\n", names[i], vs[0], fx2d(m->pos[vs[0]].x),
               fx2d(m->pos[vs[0]].y), fx2d(m->pos[vs[0]].z), corners, apex, worst);
    }
    free(f.buf);
}

/* `silk gen cone`: the apex is split when the faces are more than 50
 * degrees from the axis (atan(height / (radius cos(pi/segments)))), not
 * below: the default cone (56.4), one of 64 segments 1.25 high (51.4) and a
 * banded one of 8 segments 2 high (65.2) are split; 1.15 high (49.0) and 1
 * high (45.1) are not. */
TEST(apex_split_gen_cone)
{
    static const struct { const char *args; int split; } cases[] = {
        { "cone", 1 },
        { "cone --segments 64 --height 1.25", 1 },
        { "cone --segments 8 --height 2 --bands 3", 1 },
        { "cone --segments 64 --height 1.15", 0 },
        { "cone --height 1", 0 },
    };
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        tm_fixture_reset(&f);
        if (!gen_obj(cases[i].args, &f)) { CHECKF(0, "`%s gen %s` failed (make tests builds it)", silk_path, cases[i].args); continue; }
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", cases[i].args, f.err.msg); continue; }
        const silk_mesh *m = &f.m;
        uint32_t apex = 0;
        for (uint32_t v = 1; v < m->nverts; v++)
            if (m->pos[v].y > m->pos[apex].y) apex = v;
        double angle = vertex_apex_angle(m, apex), worst = 0;
        uint32_t vs[2], n = split_vertices(m, vs, 2), fan = 0;
        for (uint32_t c = 0; c < 3 * m->ntris; c++) fan += m->tri[c] == apex;
        CHECKF((angle > APEX_DEG) == cases[i].split, "%s: apex angle %.2f deg", cases[i].args, angle);
        CHECKF(n == (uint32_t)cases[i].split && (n == 0 || vs[0] == apex), "%s: %u vertices split", cases[i].args, n);
        if (cases[i].split) {
            check_split_vertex(m, apex, &worst);
        } else {
            uint32_t g = SILK_NO_INDEX;
            for (uint32_t c = 0; c < 3 * m->ntris; c++)
                if (m->tri[c] == apex) {
                    if (g == SILK_NO_INDEX) g = m->tri_normal[c];
                    CHECKF(m->tri_normal[c] == g, "%s: apex corner %u has its own normal", cases[i].args, c);
                }
            CHECKF(g != SILK_NO_INDEX && m->normal[g].y == SILK_FX_ONE, "%s: the apex normal is not +y", cases[i].args);
        }
        printf("  silk gen %-40s apex: %2u triangles, %.2f deg from the nearest face: %s\n", cases[i].args, fan, angle,
               n ? "split" : "one normal");
    }
    free(f.buf);
}

/* Pyramids with n sides in random orientations, their faces 49 or 51
 * degrees from the axis: split exactly above 50 (the rule does not depend
 * on the axis), and when split each corner keeps its face normal. */
TEST(apex_split_threshold_any_axis)
{
    uint32_t split_count = 0, whole = 0;
    double worst = 0;
    for (int round = 0; round < 24; round++) {
        int sides = 5 + round % 7;
        double want = round & 1 ? 51 : 49, r = 1.3;
        double h = r * cos(PI / sides) * tan(want * PI / 180);
        double a[3] = { check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1) }, b[3] = { 0.3, -0.8, 0.5 };
        double u[3], w[3], ax[3];
        double la = len3(a);
        for (int i = 0; i < 3; i++) ax[i] = a[i] / la;
        cross3(ax, b, u);
        double lu = len3(u);
        for (int i = 0; i < 3; i++) u[i] /= lu;
        cross3(ax, u, w);
        /* apex 0, base centre 1, rim 2.. */
        double pos[3 * 16], o[3] = { check_uniform(-2, 2), check_uniform(-2, 2), check_uniform(-2, 2) };
        uint32_t tri[3 * 2 * 14], nt = 0;
        for (int i = 0; i < 3; i++) pos[i] = o[i] + h * ax[i], pos[3 + i] = o[i];
        for (int k = 0; k < sides; k++) {
            double t = 2 * PI * k / sides + 0.3;
            for (int i = 0; i < 3; i++) pos[3 * (2 + k) + i] = o[i] + r * (cos(t) * u[i] + sin(t) * w[i]);
            uint32_t p0 = 2 + (uint32_t)k, p1 = 2 + (uint32_t)((k + 1) % sides);
            tri[3 * nt] = 0, tri[3 * nt + 1] = p0, tri[3 * nt + 2] = p1, nt++;
            tri[3 * nt] = 1, tri[3 * nt + 1] = p1, tri[3 * nt + 2] = p0, nt++;
        }
        tm_fixture f;
        tm_fixture_init(&f, 1 << 18);
        CHECK(tm_fixture_input(&f, pos, 2 + (uint32_t)sides, tri, nt) && tm_fixture_build(&f) == SILK_OK);
        double angle = vertex_apex_angle(&f.m, 0);
        CHECKF(fabs(angle - want) < 0.01, "pyramid %d: apex angle %.3f, built for %.0f", round, angle, want);
        uint32_t vs[2], n = split_vertices(&f.m, vs, 2);
        if (want > APEX_DEG) {
            CHECKF(n == 1 && vs[0] == 0, "pyramid %d (%d sides, %.1f deg): %u vertices split", round, sides, angle, n);
            CHECK(check_split_vertex(&f.m, 0, &worst) == (uint32_t)sides);
            split_count++;
        } else {
            CHECKF(n == 0, "pyramid %d (%d sides, %.1f deg): %u vertices split", round, sides, angle, n);
            whole++;
        }
        normal_report rep;
        check_normals(&f.m, fx2d(f.opts.crease_deg), 1e-3, &rep);
        free(f.buf);
    }
    printf("  24 pyramids, 5..11 sides, random axes: %u split at 51 deg, %u whole at 49; split normals within %.2f ulp "
           "of their faces\n", split_count, whole, worst);
}

/* The measurement behind SILK_APEX_DEG (docs/formats.md): per mesh, how
 * many groups of corners have their angle-weighted normal more than 40, 45,
 * 50, 55 degrees from every face of the group, the largest such angle, and
 * how many vertices the core split (those above 50). */
TEST(apex_angles_on_shared_meshes)
{
    static const double th[] = { 40, 45, 50, 55 };
    tm_fixture f;
    tm_fixture_init(&f, ARENA_BYTES);
    printf("  %-15s %5s %5s %5s %5s  %7s  %5s\n", "mesh", ">40", ">45", ">50", ">55", "largest", "split");
    uint32_t coarse_split = 0;
    for (size_t i = 0; i < sizeof all_meshes / sizeof *all_meshes; i++) {
        tm_fixture_reset(&f);
        CHECKF(tm_fixture_read_shared(&f, all_meshes[i]), "cannot read %s", all_meshes[i]);
        if (tm_fixture_build(&f) != SILK_OK) { CHECKF(0, "%s: %s", all_meshes[i], f.err.msg); continue; }
        const silk_mesh *m = &f.m;
        uint32_t nc = 3 * m->ntris, above[4] = { 0 };
        uint32_t *p = malloc(sizeof *p * (nc + 1));
        double *apex = malloc(sizeof *apex * (nc + 1)), largest = 0;
        ref_groups(m, p);
        apex_angles(m, p, apex);
        for (uint32_t c = 0; c < nc; c++) {
            if (find(p, c) != c || apex[c] < 0) continue;
            for (int k = 0; k < 4; k++) above[k] += apex[c] > th[k];
            largest = fmax(largest, apex[c]);
        }
        uint32_t vs[1], split = split_vertices(m, vs, 1);
        CHECKF(split == above[2], "%s: %u vertices split, %u groups above %.0f deg", all_meshes[i], split, above[2],
               th[2]);
        if (!strstr(all_meshes[i], "-fine") && !strstr(all_meshes[i], "-2k") && !strstr(all_meshes[i], "-5k") &&
            !strstr(all_meshes[i], "-1000"))
            coarse_split += split;
        printf("  %-15s %5u %5u %5u %5u  %7.1f  %5u\n", all_meshes[i], above[0], above[1], above[2], above[3],
               largest, split);
        free(p);
        free(apex);
    }
    printf("  coarse meshes: %u vertices split\n", coarse_split);
    free(f.buf);
}

int main(int argc, char **argv)
{
    /* BUILD/tests/test_normals -> BUILD/silk */
    const char *slash = argc > 0 ? strrchr(argv[0], '/') : NULL;
    if (slash && slash - argv[0] >= 6 && !strncmp(slash - 6, "/tests", 6))
        snprintf(silk_path, sizeof silk_path, "%.*s/silk", (int)(slash - 6 - argv[0]), argv[0]);
    /* The CLI is a host tool: a board configuration's tests use the host's. */
    if (getenv("SILK") && *getenv("SILK")) snprintf(silk_path, sizeof silk_path, "%s", getenv("SILK"));
    RUN(cube_split_normals);
    RUN(crease_threshold);
    RUN(smoothing_groups);
    RUN(file_normals);
    RUN(shared_meshes_normals_vs_reference);
    RUN(crease_default_on_shared_meshes);
    RUN(apex_split_cone_and_spike);
    RUN(apex_split_gen_cone);
    RUN(apex_split_threshold_any_axis);
    RUN(apex_angles_on_shared_meshes);
    return check_done();
}
