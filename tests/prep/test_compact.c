/*
 * test_compact.c - the compact model's encoder (tools/prep/compact_enc.c)
 * against the core's decoder (src/compact.c): meshes loaded as `silk pack`
 * loads them, encoded, read back with silk_compact_mesh and compared
 * through the accessors of silk/mesh.h with the loaded mesh, mapped through
 * the renumbering (vertices in order of first use) worked out here again:
 *   - positions within half a quantization step, corners equal;
 *   - every corner's normal within the angle an octahedral code of
 *     nrm_bits can miss by (measured and printed), and of its own vertex;
 *   - every loaded edge one compact edge (a bijection), with the same two
 *     vertices, triangles and flags; every vertex's ring exactly its edges;
 *   - feature tangents: straight ones the decoded chord, the others within
 *     dir_bits' angle of the loaded direction;
 *   - flat models (no adjacency) the same but for the edges;
 *   - what the encoder must refuse, with its reason; the octahedral search
 *     against an exhaustive one.
 * The shared meshes (bunny-500, spot-500, armadillo-500, fandisk-1000,
 * torus-576) are read when present; generated shapes always.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "silk/silk.h"
#include "silk/compact.h"
#include "silk/model.h"
#include "support/testmesh.h"
#include "tools/prep/compact_enc.h"
#include "tools/prep/gen.h"

#define ARENA_BYTES ((size_t)32 << 20)
#define PI 3.14159265358979323846
#define DEG (180 / PI)

/* ---- loading --------------------------------------------------------------------- */

typedef struct loaded {
    void *mem;
    silk_arena a;
    silk_mesh m;
} loaded;

static int load_text(const char *text, size_t len, const char *name, loaded *l)
{
    l->mem = malloc(ARENA_BYTES);
    if (!l->mem) return 0;
    silk_arena_init(&l->a, l->mem, ARENA_BYTES);
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    silk_status st = silk_load_obj(text, len, name, &o, &l->a, &l->m, &err);
    CHECKF(st == SILK_OK, "%s does not load: %s", name, err.msg);
    return st == SILK_OK;
}

static int load_gen(gen_shape s, int uv, loaded *l)
{
    gen_params p;
    gen_defaults(s, &p);
    p.uv = uv;
    size_t len;
    char *text = gen_obj_text(&p, &len);
    if (!text) return 0;
    int ok = load_text(text, len, gen_shape_name(s), l);
    free(text);
    return ok;
}

static int load_shared(const char *name, loaded *l)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.obj", check_meshes_dir(), name);
    if (check_cur_skipped) return 0;
    size_t len;
    char *text = tm_read_file(path, &len);
    CHECKF(text != NULL, "cannot read %s", path);
    if (!text) return 0;
    int ok = load_text(text, len, name, l);
    free(text);
    return ok;
}

/* An open, wavy n x n grid: boundary edges whose feature polylines curve. */
static char *grid_obj(int n, size_t *len)
{
    size_t cap = (size_t)n * n * 120 + 64;
    char *t = malloc(cap), *p = t;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = (double)i / (n - 1), y = (double)j / (n - 1);
            p += sprintf(p, "v %.6f %.6f %.6f\n", x, y, 0.15 * sin(3 * x) * cos(2 * y));
        }
    for (int j = 0; j + 1 < n; j++)
        for (int i = 0; i + 1 < n; i++) {
            int a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
            p += sprintf(p, "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c);
        }
    *len = (size_t)(p - t);
    return t;
}

static void unload(loaded *l)
{
    free(l->mem);
    l->mem = NULL;
}

/* ---- vectors ---------------------------------------------------------------------- */

static void dvec(silk_vec3 v, double d[3])
{
    d[0] = v.x / 65536.0, d[1] = v.y / 65536.0, d[2] = v.z / 65536.0;
}

/* The angle between a and b in degrees (0 when either is zero). */
static double angle_deg(silk_vec3 a, silk_vec3 b)
{
    double x[3], y[3];
    dvec(a, x), dvec(b, y);
    double lx = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), ly = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    if (lx == 0 || ly == 0) return 0;
    double c = (x[0] * y[0] + x[1] * y[1] + x[2] * y[2]) / (lx * ly);
    return acos(c > 1 ? 1 : c < -1 ? -1 : c) * DEG;
}

static int v3_eq(silk_vec3 a, silk_vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* The largest angle an octahedral code of bits can be off by: half a cell's
 * diagonal, sqrt(2)/M of the unit square's [-1, 1] (cells are 2/M wide),
 * lifted onto the octahedron (a step along x moves z too: sqrt(2) longer)
 * and seen from its face centre, 1/sqrt(3) from the origin: 2 sqrt(3)/M;
 * plus the Q16.16 rounding of both unit vectors (2 x 1.3e-5). */
static double octa_bound_deg(unsigned bits)
{
    double m = (double)((1u << bits) - 1);
    return (2 * sqrt(3.0) / m + 3e-5) * DEG;
}

/* The cosine of the angle between the decoded c and the unit d. */
static double cosine(silk_vec3 c, const double d[3])
{
    double x[3];
    dvec(c, x);
    return (x[0] * d[0] + x[1] * d[1] + x[2] * d[2]) / sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

/* ---- the renumbering, worked out again -------------------------------------------- */

static uint32_t *first_use(const silk_mesh *m, uint32_t *nused)
{
    uint32_t *vnew = malloc((size_t)m->nverts * sizeof *vnew), n = 0;
    for (uint32_t v = 0; v < m->nverts; v++) vnew[v] = SILK_NO_INDEX;
    for (uint32_t c = 0; c < 3 * m->ntris; c++)
        if (vnew[m->tri[c]] == SILK_NO_INDEX) vnew[m->tri[c]] = n++;
    *nused = n;
    return vnew;
}

/* ---- the checks ----------------------------------------------------------------- */

typedef struct stats {
    double pos_err, pos_half;     /* model units */
    double nrm_deg, dir_deg;      /* largest angle errors */
    uint32_t straight, curved;    /* feature ends */
} stats;

static void check_positions(const char *what, const silk_mesh *m, const silk_mesh *cm, const uint32_t *vnew, stats *s)
{
    double half = ldexp(1.0, cm->packed.pos_shift) / 2 / 65536;
    uint32_t bad = 0;
    s->pos_half = half;
    for (uint32_t v = 0; v < m->nverts; v++) {
        if (vnew[v] == SILK_NO_INDEX) continue;
        double a[3], b[3];
        dvec(m->pos[v], a), dvec(silk_mesh_pos(cm, vnew[v]), b);
        for (int k = 0; k < 3; k++) {
            double e = fabs(a[k] - b[k]);
            if (e > s->pos_err) s->pos_err = e;
            bad += e > half;
        }
    }
    CHECKF(bad == 0, "%s: %u coordinates off by more than half a step (%g), worst %g", what, bad, half, s->pos_err);
}

/* Corners equal; each corner's normal near the loaded one and of its own
 * vertex; a loaded normal one compact normal (corners that shared one
 * still do, others do not). */
static void check_corners(const char *what, const silk_mesh *m, const silk_mesh *cm, const uint32_t *vnew, stats *s)
{
    uint32_t bad_corner = 0, bad_vertex = 0, bad_angle = 0, bad_share = 0, nc = 3 * m->ntris;
    double bound = octa_bound_deg(cm->packed.nrm_bits);
    uint32_t *of = malloc((size_t)m->nnormals * sizeof *of), *back = malloc((size_t)cm->nnormals * sizeof *back);
    for (uint32_t n = 0; n < m->nnormals; n++) of[n] = SILK_NO_INDEX;
    for (uint32_t n = 0; n < cm->nnormals; n++) back[n] = SILK_NO_INDEX;
    for (uint32_t c = 0; c < nc; c++) {
        silk_index v = silk_mesh_corner(cm, c), cn = silk_mesh_corner_normal(cm, c), on = m->tri_normal[c];
        bad_corner += v != vnew[m->tri[c]];
        if (cn >= cm->nnormals) {
            bad_vertex++;
            continue;
        }
        bad_vertex += silk_mesh_normal_vertex(cm, cn) != v;
        double a = angle_deg(m->normal[on], silk_mesh_normal(cm, cn));
        if (a > s->nrm_deg) s->nrm_deg = a;
        bad_angle += a > bound;
        if (of[on] == SILK_NO_INDEX) of[on] = cn;
        if (back[cn] == SILK_NO_INDEX) back[cn] = on;
        bad_share += of[on] != cn || back[cn] != on;
    }
    CHECKF(bad_corner == 0, "%s: %u corners differ", what, bad_corner);
    CHECKF(bad_vertex == 0, "%s: %u corner normals not of the corner's vertex", what, bad_vertex);
    CHECKF(bad_angle == 0, "%s: %u normals beyond %.4f degrees (worst %.4f)", what, bad_angle, bound, s->nrm_deg);
    CHECKF(bad_share == 0, "%s: %u corners whose normal is not shared as loaded", what, bad_share);
    free(of);
    free(back);
}

/* The compact edge of every loaded edge, through the sides (triangle order
 * and corners are kept): the same for every side of an edge, a bijection. */
static uint32_t *edge_map(const char *what, const silk_mesh *m, const silk_mesh *cm)
{
    uint32_t bound = silk_mesh_edge_bound(cm);   /* compact edge indices are sides, with gaps */
    uint32_t *map = malloc((size_t)m->nedges * sizeof *map), *hit = calloc((size_t)bound + 1, sizeof *hit);
    uint32_t bad_side = 0, bad_range = 0, bad_bij = 0;
    for (uint32_t e = 0; e < m->nedges; e++) map[e] = SILK_NO_INDEX;
    for (uint32_t h = 0; h < 3 * m->ntris; h++) {
        uint32_t e = m->tri_edge[h], ce = silk_mesh_tri_edge(cm, h / 3, h % 3);
        if (ce >= bound) {
            bad_range++;
            continue;
        }
        if (map[e] == SILK_NO_INDEX) {
            map[e] = ce;
            hit[ce]++;
        }
        bad_side += map[e] != ce;
    }
    uint32_t nhit = 0;
    for (uint32_t e = 0; e < bound; e++) {
        bad_bij += hit[e] > 1;
        nhit += hit[e] == 1;
    }
    bad_bij += nhit != cm->nedges;
    CHECKF(cm->nedges == m->nedges, "%s: %u compact edges, %u loaded", what, cm->nedges, m->nedges);
    CHECKF(bad_range == 0 && bad_side == 0, "%s: %u sides out of range, %u whose edge is not their edge's", what,
           bad_range, bad_side);
    CHECKF(bad_bij == 0, "%s: %u compact edges not exactly one loaded edge", what, bad_bij);
    free(hit);
    return map;
}

static void check_edges(const char *what, const silk_mesh *m, const silk_mesh *cm, const uint32_t *vnew,
                        const uint32_t *map)
{
    uint32_t bad_v = 0, bad_t = 0, bad_flags = 0;
    for (uint32_t e = 0; e < m->nedges; e++) {
        if (map[e] == SILK_NO_INDEX) continue;
        silk_edge o = m->edge[e], c = silk_mesh_edge(cm, map[e]);
        uint32_t a = vnew[o.v[0]], b = vnew[o.v[1]];
        bad_v += c.v[0] != (a < b ? a : b) || c.v[1] != (a < b ? b : a);
        bad_t += c.t[0] != o.t[0] || c.t[1] != o.t[1];
        bad_flags += c.flags != o.flags || silk_mesh_edge_flags(cm, map[e]) != o.flags;
    }
    CHECKF(bad_v == 0 && bad_t == 0 && bad_flags == 0, "%s: edges with other vertices %u, triangles %u, flags %u",
           what, bad_v, bad_t, bad_flags);
}

/* Every vertex's ring lists exactly its loaded edges, each once. */
static void check_rings(const char *what, const silk_mesh *m, const silk_mesh *cm, const uint32_t *vnew,
                        const uint32_t *map)
{
    uint32_t bad = 0;
    uint32_t bound = silk_mesh_edge_bound(cm);
    uint8_t *mark = calloc((size_t)bound + 1, 1);
    for (uint32_t v = 0; v < m->nverts; v++) {
        if (vnew[v] == SILK_NO_INDEX) continue;
        uint32_t deg = m->vert_edge_start[v + 1] - m->vert_edge_start[v], n = 0, wrong = 0;
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) mark[map[m->vert_edge[i]]] = 1;
        silk_mesh_ring r;
        for (silk_index e = silk_mesh_ring_first(cm, vnew[v], &r); e != SILK_NO_INDEX && n <= deg;
             e = silk_mesh_ring_next(cm, &r), n++) {
            if (e >= bound || mark[e] != 1) wrong++;
            else mark[e] = 2;   /* a second visit is wrong too */
        }
        for (uint32_t i = m->vert_edge_start[v]; i < m->vert_edge_start[v + 1]; i++) mark[map[m->vert_edge[i]]] = 0;
        if (n != deg || wrong) {
            if (!bad) fprintf(stderr, "%s: vertex %u (loaded %u): ring of %u edges, %u wrong; it has %u\n", what,
                              vnew[v], v, n, wrong, deg);
            bad++;
        }
    }
    CHECKF(bad == 0, "%s: %u vertices whose ring is not their edges", what, bad);
    free(mark);
}

/* Straight ends give the decoded chord; the others keep their direction
 * within dir_bits' bound. */
static void check_features(const char *what, const silk_mesh *m, const silk_mesh *cm, const uint32_t *vnew,
                           const uint32_t *map, stats *s)
{
    uint32_t bad_has = 0, bad_straight = 0, bad_dir = 0;
    double bound = octa_bound_deg(cm->packed.dir_bits);
    for (uint32_t e = 0; e < m->nedges; e++) {
        const silk_edge *o = &m->edge[e];
        silk_feature_seg got;
        int has = silk_mesh_feature_seg(cm, map[e], &got);
        bad_has += has != silk_edge_has_feature(o);
        if (!has || !silk_edge_has_feature(o)) continue;
        silk_feature_seg want = m->feature[m->edge_feature[e]];
        silk_index o0 = o->v[0], o1 = o->v[1];
        if (vnew[o0] > vnew[o1]) {   /* the compact edge runs the other way */
            silk_feature_seg r = { silk_v3_neg(want.t1), silk_v3_neg(want.t0) };
            want = r;
            o0 = o->v[1], o1 = o->v[0];
        }
        silk_vec3 chord = silk_v3_sub(m->pos[o1], m->pos[o0]);
        silk_vec3 cchord = silk_v3_sub(silk_mesh_pos(cm, vnew[o1]), silk_mesh_pos(cm, vnew[o0]));
        silk_vec3 w[2] = { want.t0, want.t1 }, g[2] = { got.t0, got.t1 };
        for (int k = 0; k < 2; k++) {
            if (v3_eq(w[k], chord)) {
                s->straight++;
                bad_straight += !v3_eq(g[k], cchord);
                continue;
            }
            s->curved++;
            double a = angle_deg(w[k], g[k]);
            if (a > s->dir_deg) s->dir_deg = a;
            bad_dir += a > bound;
        }
    }
    CHECKF(bad_has == 0, "%s: %u edges whose feature segment comes and goes", what, bad_has);
    CHECKF(bad_straight == 0, "%s: %u straight ends not the decoded chord", what, bad_straight);
    CHECKF(bad_dir == 0, "%s: %u tangent directions beyond %.3f degrees (worst %.3f)", what, bad_dir, bound,
           s->dir_deg);
}

/* Encode, decode, compare; flat when adjacency is 0.  Returns the bytes. */
static size_t round_trip(const char *name, const silk_mesh *m, int adjacency)
{
    char what[96], why[320];
    snprintf(what, sizeof what, "%s%s", name, adjacency ? "" : " (flat)");
    compact_opts o = compact_opts_default();
    o.adjacency = adjacency;
    uint8_t *b = NULL, *b2 = NULL;
    size_t len = 0, len2 = 0;
    int rc = compact_encode(m, &o, &b, &len, why, sizeof why);
    CHECKF(rc == 0, "%s: not encoded: %s", what, why);
    if (rc) return 0;
    /* the same bytes every time; the layout's own account of them */
    CHECK(compact_encode(m, &o, &b2, &len2, why, sizeof why) == 0 && len2 == len && memcmp(b, b2, len) == 0);
    free(b2);
    compact_layout l;
    CHECKF(compact_layout_read(b, len, &l) == 0 && l.size == len, "%s: layout", what);
    CHECK(silk_crc32(0, b + SILK_COMPACT_HEADER_BYTES, len - SILK_COMPACT_HEADER_BYTES) ==
          ((uint32_t)b[52] | (uint32_t)b[53] << 8 | (uint32_t)b[54] << 16 | (uint32_t)b[55] << 24));

    silk_mesh cm;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_compact_mesh(b, len, name, &cm, &err);
    CHECKF(st == SILK_OK, "%s: the decoder refuses it: %s", what, err.msg);
    if (st != SILK_OK) {
        free(b);
        return 0;
    }
    uint32_t nused;
    uint32_t *vnew = first_use(m, &nused);
    CHECKF(cm.nverts == nused && cm.ntris == m->ntris, "%s: %u vertices, %u triangles; want %u, %u", what, cm.nverts,
           cm.ntris, nused, m->ntris);
    CHECK(cm.closed_outward == m->closed_outward);
    stats s;
    memset(&s, 0, sizeof s);
    check_positions(what, m, &cm, vnew, &s);
    check_corners(what, m, &cm, vnew, &s);
    if (adjacency) {
        uint32_t *map = edge_map(what, m, &cm);
        check_edges(what, m, &cm, vnew, map);
        check_rings(what, m, &cm, vnew, map);
        check_features(what, m, &cm, vnew, map, &s);
        CHECKF(cm.nfeature_edges == m->nfeature_edges && cm.nboundary_edges == m->nboundary_edges,
               "%s: %u feature, %u boundary edges; loaded %u, %u", what, cm.nfeature_edges, cm.nboundary_edges,
               m->nfeature_edges, m->nboundary_edges);
        free(map);
    } else {
        CHECKF(cm.nedges == 0 && !(l.flags & SILK_COMPACT_ADJACENCY), "%s: a flat model with %u edges", what,
               cm.nedges);
    }
    printf("  %-22s %6zu bytes, %5.2f a triangle; positions within %.2g (half step %.2g), normals within %.4f deg "
           "(bound %.4f)",
           what, len, (double)len / m->ntris, s.pos_err, s.pos_half, s.nrm_deg, octa_bound_deg(l.nrm_bits));
    if (adjacency)
        printf(", %u curved tangents within %.3f deg (bound %.3f), %u straight", s.curved, s.dir_deg,
               octa_bound_deg(l.dir_bits), s.straight);
    printf("\n");
    free(vnew);
    free(b);
    return len;
}

static void both(const char *name, const silk_mesh *m)
{
    round_trip(name, m, 1);
    round_trip(name, m, 0);
}

/* ---- tests ---------------------------------------------------------------------- */

TEST(shared_meshes)
{
    static const char *const names[] = { "bunny-500", "spot-500", "armadillo-500", "fandisk-1000", "torus-576" };
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        loaded l = { 0 };
        if (load_shared(names[i], &l)) both(names[i], &l.m);
        unload(&l);
        if (check_cur_skipped) return;
    }
}

TEST(generated_shapes)
{
    /* the cylinder's rims are crease polylines, the torus has none */
    const gen_shape shapes[] = { GEN_TORUS, GEN_SPHERE, GEN_CYLINDER, GEN_KNOT };
    for (size_t i = 0; i < sizeof shapes / sizeof *shapes; i++) {
        loaded l = { 0 };
        if (load_gen(shapes[i], 0, &l)) both(gen_shape_name(shapes[i]), &l.m);
        unload(&l);
    }
    /* an open surface: boundary edges, curved boundary polylines */
    size_t len;
    char *text = grid_obj(9, &len);
    loaded l = { 0 };
    if (load_text(text, len, "grid", &l)) both("grid", &l.m);
    unload(&l);
    free(text);
}

/* Options change the widths and stay exact where they should. */
TEST(options)
{
    loaded l = { 0 };
    if (!load_gen(GEN_CYLINDER, 0, &l)) return;
    const int pos_bits[] = { 3, 8, 16 }, nrm_bits[] = { 2, 6, 16 };
    for (int i = 0; i < 3; i++) {
        compact_opts o = compact_opts_default();
        o.pos_bits = pos_bits[i], o.nrm_bits = nrm_bits[i], o.dir_bits = nrm_bits[i];
        uint8_t *b;
        size_t len;
        char why[200];
        int rc = compact_encode(&l.m, &o, &b, &len, why, sizeof why);
        CHECKF(rc == 0, "pos_bits %d: %s", pos_bits[i], why);
        if (rc) continue;
        silk_mesh cm;
        silk_error err;
        silk_status st = silk_compact_mesh(b, len, "cyl", &cm, &err);
        CHECKF(st == SILK_OK, "pos_bits %d: %s", pos_bits[i], err.msg);
        if (st == SILK_OK) {
            double worst = 0;
            for (uint32_t n = 0; n < cm.nnormals; n++) {
                double d[3];
                dvec(silk_mesh_normal(&cm, n), d);
                worst = fmax(worst, fabs(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 1));
            }
            CHECKF(worst < 1e-4, "nrm_bits %d: a decoded normal of length 1 %+g", nrm_bits[i], worst);
        }
        free(b);
    }
    compact_opts o = compact_opts_default();
    char why[200];
    uint8_t *b;
    size_t len;
    o.pos_bits = 17;
    CHECK(compact_encode(&l.m, &o, &b, &len, why, sizeof why) == -1 && strstr(why, "pos_bits"));
    /* the cylinder is 2 units across: 2 bits of at most 2^15 ulps cannot span it */
    o.pos_bits = 2;
    CHECKF(compact_encode(&l.m, &o, &b, &len, why, sizeof why) == -1 && strstr(why, "box"), "%s", why);
    o = compact_opts_default();
    o.dir_bits = 1;
    CHECK(compact_encode(&l.m, &o, &b, &len, why, sizeof why) == -1 && strstr(why, "dir_bits"));
    unload(&l);
}

/* What the format cannot hold is refused with its reason; flat models
 * take what only the corner table cannot. */
static void expect_refusal(const char *obj, int adjacency, const char *word)
{
    loaded l = { 0 };
    if (!load_text(obj, strlen(obj), "case", &l)) return;
    compact_opts o = compact_opts_default();
    o.adjacency = adjacency;
    uint8_t *b = NULL;
    size_t len;
    char why[320] = "";
    int rc = compact_encode(&l.m, &o, &b, &len, why, sizeof why);
    if (word) {
        CHECKF(rc == -1 && strstr(why, word), "want a refusal naming \"%s\", got %d \"%s\"", word, rc, why);
        CHECKF(!strchr(why, '\n') && strlen(why) > 10, "reason \"%s\"", why);
    } else {
        CHECKF(rc == 0, "refused: %s", why);
        silk_mesh cm;
        silk_error err;
        if (rc == 0) CHECKF(silk_compact_mesh(b, len, "case", &cm, &err) == SILK_OK, "%s", err.msg);
    }
    free(b);
    unload(&l);
}

TEST(refusals)
{
    /* a fin: three triangles on one edge */
    const char *fin = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    expect_refusal(fin, 1, "non-manifold");
    expect_refusal(fin, 0, NULL);
    /* two tetrahedra touching at one vertex */
    const char *bowtie = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
                         "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 6 5\nf 1 5 7\nf 1 7 6\nf 5 6 7\n";
    expect_refusal(bowtie, 1, "fan");
    expect_refusal(bowtie, 0, NULL);
    /* a repeated corner */
    expect_refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 3\n", 0, "repeats");
    /* vertex colours, texture coordinates */
    expect_refusal("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n", 1, "colour");
    expect_refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", 1, "texture");
    /* a cone's apex has a normal for each face: 35 fit (at most 64), 80 do not */
    loaded l = { 0 };
    if (load_gen(GEN_CONE, 0, &l)) {
        uint8_t *b = NULL;
        size_t len;
        char why[320];
        CHECKF(compact_encode(&l.m, NULL, &b, &len, why, sizeof why) == 0, "cone: %s", why);
        free(b);
    }
    unload(&l);
    gen_params cp;
    gen_defaults(GEN_CONE, &cp);
    cp.segments = 80;
    size_t clen;
    char *ctext = gen_obj_text(&cp, &clen);
    if (ctext && load_text(ctext, clen, "cone-80", &l)) {
        uint8_t *b = NULL;
        size_t len;
        char why[320];
        CHECK(compact_encode(&l.m, NULL, &b, &len, why, sizeof why) == -1 && strstr(why, "at most 64"));
        free(b);
    }
    free(ctext);
    unload(&l);
    /* a single triangle, an unused vertex and a zero-area triangle are fine */
    expect_refusal("v 0 0 0\nv 1 0 0\nv 5 5 5\nv 0 1 0\nf 1 2 4\n", 1, NULL);
    expect_refusal("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 2 3 4\nf 1 3 2\n", 1, NULL);
}

/* decode(encode(d)) is the nearest code (by angle): against every code for
 * few bits, against a wide window for many. */
TEST(octa_nearest)
{
    uint32_t worse = 0, runs = 0;
    double worst_deg[17] = { 0 };
    for (unsigned bits = 2; bits <= 16; bits++) {
        uint32_t m = (1u << bits) - 1;
        for (int i = 0; i < (bits <= 6 ? 400 : 2000); i++) {
            double d[3] = { check_uniform(-1, 1), check_uniform(-1, 1), check_uniform(-1, 1) };
            if (i < 6) d[0] = d[1] = d[2] = 0, d[i % 3] = i < 3 ? 1 : -1;   /* the axes */
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (len < 1e-3) continue;
            for (int k = 0; k < 3; k++) d[k] /= len;
            uint32_t u = 0, v = 0;
            compact_octa_encode(d, bits, &u, &v);
            double got = cosine(silk_compact_octa(u, v, bits), d), best = got;
            /* every code, or a window 7 wide around the chosen one and its mirror cells */
            uint32_t lo_u = bits <= 6 ? 0 : (u > 3 ? u - 3 : 0), hi_u = bits <= 6 ? m : (u + 3 < m ? u + 3 : m);
            uint32_t lo_v = bits <= 6 ? 0 : (v > 3 ? v - 3 : 0), hi_v = bits <= 6 ? m : (v + 3 < m ? v + 3 : m);
            for (uint32_t a = lo_u; a <= hi_u; a++)
                for (uint32_t b = lo_v; b <= hi_v; b++) {
                    double c = cosine(silk_compact_octa(a, b, bits), d);
                    if (c > best) best = c;
                }
            worse += best > got + 1e-12;
            runs++;
            double a = acos(got > 1 ? 1 : got) * DEG;
            if (a > worst_deg[bits]) worst_deg[bits] = a;
        }
        CHECKF(worst_deg[bits] <= octa_bound_deg(bits), "%u bits: %.5f degrees, beyond the bound %.5f", bits,
               worst_deg[bits], octa_bound_deg(bits));
    }
    CHECKF(worse == 0, "%u of %u directions have a nearer code than the chosen one", worse, runs);
    printf("  octahedral codes, largest angle seen (bound): 8 bits %.4f (%.4f), 10 bits %.4f (%.4f), 12 bits %.5f "
           "(%.5f) degrees\n",
           worst_deg[8], octa_bound_deg(8), worst_deg[10], octa_bound_deg(10), worst_deg[12], octa_bound_deg(12));
}

int main(void)
{
    RUN(octa_nearest);
    RUN(generated_shapes);
    RUN(options);
    RUN(refusals);
    RUN(shared_meshes);
    return check_done();
}
