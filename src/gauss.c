/*
 * gauss.c - visibility of all normals at once by hierarchical clustering on
 * the Gaussian sphere (paper III-B, after Benichou & Elber).
 *
 * Each normal N at vertex V is the point V' = (N, w), w = -N.(V-C)/s, and is
 * visible iff E'.V' >= 0 with E' = (E - C, s) in perspective (paper III-B, F(E;V),
 * shifted to the model centre C and scaled by s so that |w| <= 1) or
 * E' = (D, 0) in parallel projection.  The sign of E'.V' does not change when
 * V' is scaled, so V' never has to be put on S^3: cells live on S^2 x [-1,1]
 * with coordinates latitude, longitude and w (eight corners), a level halves
 * latitude and longitude and, where the normals spread enough in w, w too
 * (eight children), and a cell's lat/long part is the four-corner cell of
 * the paper's Fig. 9, so one tree serves both projections.
 *
 * A cell decides all its normals when its whole region lies on one side of
 * E'.X = 0.  Four corners on one side do not prove that: a latitude arc is
 * not a great circle and bulges past a plane through its end points.  The
 * region is bounded instead by a ball |N - c| <= r whose radius is the
 * farthest corner (the farthest point of a lat/long cell from its centre is
 * a corner; docs/visibility.md has the argument), and by the cell's w
 * interval; then for every member
 *     E'.V' >= c.E - r|E| + w0 E_w   and   E'.V' <= c.E + r|E| + w1 E_w.
 * All of it is integer arithmetic with a stated margin for the one rounded
 * quantity (the unit view vector), and the build checks every member against
 * its cell's bound, so a decided cell agrees with the brute pass bit for bit.
 */
#include <string.h>
#include "silk/visibility.h"

#define MAX_DEPTH     10      /* levels per coordinate: 3 x 10 bits fit a uint32_t */
#define LEAF_MAX      24      /* default: cells this small are tested one by one */
#define BYTES_PER_NORMAL 8    /* the hierarchy's memory budget */
/* Slack on each cell radius (Q16.16 ulps) for the rounding of the corners'
 * sines and cosines and of the members' latitudes and longitudes. */
#define RADIUS_SLACK  16
/* Normals are unit vectors; anything longer than this is rejected. */
#define NORMAL_MAX_SQ (((int64_t)65536 + 256) * ((int64_t)65536 + 256))

/* ---- small integer helpers ------------------------------------------------ */

static uint32_t ceil_sqrt64(uint64_t v)
{
    uint32_t s = silk_isqrt64(v);
    return (uint64_t)s * s < v ? s + 1 : s;
}


/* N.(E - V), exact: the brute pass's test (see visibility.c). */
static int64_t persp_dot64(silk_vec3 n, silk_vec3 p, silk_vec3 e)
{
    return (int64_t)n.x * ((int64_t)e.x - p.x)
         + (int64_t)n.y * ((int64_t)e.y - p.y)
         + (int64_t)n.z * ((int64_t)e.z - p.z);
}

/* What silk_arena_alloc takes for n bytes (at least one aligned unit). */
static size_t arena_block(size_t n)
{
    return ((n ? n : 1) + SILK_ARENA_ALIGN - 1) & ~(size_t)(SILK_ARENA_ALIGN - 1);
}

/* Radians (Q16.16) of grid line k of 2^level lines over an interval of
 * length span*pi starting at -span*pi/2: latitude uses span 1, longitude 2. */
static silk_fx grid_angle(uint32_t level, uint32_t k, int span)
{
    int64_t num = (int64_t)span * ((int64_t)2 * k - ((int64_t)1 << level)) * SILK_FX_PI;
    return (silk_fx)silk_shr_round64(num, (int)level + 1);
}

static silk_vec3 sphere_point(silk_fx lat, silk_fx lon)
{
    silk_fx slat, clat, slon, clon;
    silk_fx_sincos(lat, &slat, &clat);
    silk_fx_sincos(lon, &slon, &clon);
    return silk_v3(silk_fx_mul(clat, clon), silk_fx_mul(clat, slon), slat);
}

static uint64_t dist_sq(silk_vec3 a, silk_vec3 b)
{
    int64_t dx = (int64_t)a.x - b.x, dy = (int64_t)a.y - b.y, dz = (int64_t)a.z - b.z;
    return (uint64_t)(dx * dx + dy * dy + dz * dz);
}

/* Ball around the centre of lat/long cell (lat, lon) of the given level, in
 * Q16.16, centre rounded to the Q2.14 that nodes store.  Along a latitude
 * the distance to the centre grows with the longitude difference, and along
 * a boundary meridian c.X is a sinusoid without an interior minimum, so with
 * a longitude span of at most pi the farthest point of the cell is a corner
 * (docs/visibility.md). */
static void cell_ball(uint32_t level, uint32_t lat, uint32_t lon, silk_vec3 *c, uint32_t *r)
{
    if (level == 0) {                       /* the whole sphere */
        *c = silk_v3(0, 0, 0);
        *r = 65536 + 256 + RADIUS_SLACK;   /* normals may be 1.004 long */
        return;
    }
    silk_fx mid_lat = grid_angle(level + 1, 2 * lat + 1, 1);
    silk_fx mid_lon = grid_angle(level + 1, 2 * lon + 1, 2);
    silk_vec3 m = sphere_point(mid_lat, mid_lon);
    /* Q2.14 and back: the radius is measured from the centre as stored */
    *c = silk_v3((silk_fx)silk_shr_round64(m.x, 2) * 4, (silk_fx)silk_shr_round64(m.y, 2) * 4,
                 (silk_fx)silk_shr_round64(m.z, 2) * 4);
    uint64_t far = 0;
    for (uint32_t i = 0; i < 2; i++)
        for (uint32_t j = 0; j < 2; j++) {
            silk_vec3 p = sphere_point(grid_angle(level, lat + i, 1), grid_angle(level, lon + j, 2));
            uint64_t d = dist_sq(p, *c);
            if (d > far) far = d;
        }
    *r = ceil_sqrt64(far) + RADIUS_SLACK;
}

int silk_vis_cell_ball(uint32_t level, uint32_t lat, uint32_t lon, silk_vec3 *c, silk_fx *r)
{
    if (level > 30 || lat >= (1u << level) || lon >= (1u << level)) return 0;
    uint32_t rr;
    cell_ball(level, lat, lon, c, &rr);
    *r = (silk_fx)rr;
    return 1;
}

/* ---- building --------------------------------------------------------------- */

/* Every normal's cell at the finest level: latitude, longitude and w index
 * (MAX_DEPTH bits each), packed as lat << 20 | lon << 10 | w. */
#define FINE_LAT(f) ((f) >> 20)
#define FINE_LON(f) (((f) >> 10) & 1023u)
#define FINE_W(f)   ((f) & 1023u)

typedef struct build_ctx {
    silk_mesh *m;
    const uint32_t *fine;     /* per normal (old index) */
    uint32_t *order;          /* position -> old normal index, sorted cell by cell */
    uint32_t *tmp;            /* scratch for the sorts */
    uint32_t depth, leaf_max;
    silk_vis_node *node;      /* NULL while counting */
    uint32_t nnodes, widened, max_level;
} build_ctx;

/* A cell: lat/long indices at level `level`, w index at level `wlevel`. */
typedef struct cell {
    uint32_t level, lat, lon, wlevel, w;
} cell;

static void fill_node(build_ctx *b, silk_vis_node *nd, const cell *cl, silk_vec3 c, uint32_t r,
                      uint32_t lo, uint32_t hi)
{
    /* The members' own check: the bound must hold for the stored vectors,
     * not only for the ideal cell. */
    uint64_t r_sq = (uint64_t)r * r, worst = 0;
    for (uint32_t k = lo; k < hi; k++) {
        uint64_t d = dist_sq(b->m->normal[b->order[k]], c);
        if (d > worst) worst = d;
    }
    if (worst > r_sq) {
        r = ceil_sqrt64(worst) + 1;
        b->widened++;
    }
    nd->c[0] = (int16_t)(c.x / 4);
    nd->c[1] = (int16_t)(c.y / 4);
    nd->c[2] = (int16_t)(c.z / 4);
    nd->r = (uint16_t)((r + 3) / 4);      /* Q2.14, rounded up; r < 2.01 */
    /* [-1 + w 2^(1-wlevel), -1 + (w+1) 2^(1-wlevel)] in Q2.14, exact */
    nd->w0 = (int16_t)(-16384 + (int32_t)(cl->w << (15 - cl->wlevel)));
    nd->w1 = (int16_t)(-16384 + (int32_t)((cl->w + 1) << (15 - cl->wlevel)));
    nd->first = lo;
}

/* Split w as well as latitude and longitude only where the members' spread
 * in w costs more than the cell's angular size: the view's w component is
 * small against its direction part unless the eye is close, so w needs
 * fewer levels than lat/long, and every level of w it gets doubles the
 * cells a parallel view has to visit. */
#define W_SPLIT_NUM 3
#define W_SPLIT_DEN 8

/* First level from `from` on at which a and b (finest-level indices) fall
 * into different cells, at most `to`. */
static uint32_t common_bits(uint32_t a, uint32_t b, uint32_t from, uint32_t to)
{
    while (from < to && (a >> (MAX_DEPTH - from - 1)) == (b >> (MAX_DEPTH - from - 1))) from++;
    return from;
}

/* Emit (or count, when b->node is NULL) the subtree of cell `in` holding the
 * normals order[lo..hi), in depth-first order; the range is sorted by
 * child as it goes, so that every cell is one contiguous range. */
static void build_cell(build_ctx *b, const cell *in, uint32_t lo, uint32_t hi)
{
    /* Narrow the cell to the smallest one of the grid that still holds all
     * its members: tighter bounds, and no chains of one-child cells. */
    uint32_t lat0 = 1023, lat1 = 0, lon0 = 1023, lon1 = 0, w0 = 1023, w1 = 0;
    for (uint32_t k = lo; k < hi; k++) {
        uint32_t f = b->fine[b->order[k]];
        if (FINE_LAT(f) < lat0) lat0 = FINE_LAT(f);
        if (FINE_LAT(f) > lat1) lat1 = FINE_LAT(f);
        if (FINE_LON(f) < lon0) lon0 = FINE_LON(f);
        if (FINE_LON(f) > lon1) lon1 = FINE_LON(f);
        if (FINE_W(f) < w0) w0 = FINE_W(f);
        if (FINE_W(f) > w1) w1 = FINE_W(f);
    }
    cell tight = *in, *cl = &tight;
    uint32_t la = common_bits(lat0, lat1, in->level, b->depth), lv = common_bits(lon0, lon1, in->level, b->depth);
    tight.level = la < lv ? la : lv;
    tight.lat = lat0 >> (MAX_DEPTH - tight.level);
    tight.lon = lon0 >> (MAX_DEPTH - tight.level);
    tight.wlevel = common_bits(w0, w1, in->wlevel, b->depth);
    tight.w = w0 >> (MAX_DEPTH - tight.wlevel);

    uint32_t self = b->nnodes++;
    uint32_t lvl = cl->level > cl->wlevel ? cl->level : cl->wlevel;
    if (lvl > b->max_level) b->max_level = lvl;
    silk_vec3 c;
    uint32_t r;
    cell_ball(cl->level, cl->lat, cl->lon, &c, &r);
    if (b->node) fill_node(b, &b->node[self], cl, c, r, lo, hi);

    int split_ll = cl->level < b->depth, split_w = 0;
    if (hi - lo > b->leaf_max && cl->wlevel < b->depth) {
        /* spread in Q16.16: each finest w cell is 2/1024 wide */
        uint64_t spread = (uint64_t)(w1 - w0 + 1) << 7;
        split_w = !split_ll || spread * W_SPLIT_NUM > (uint64_t)r * W_SPLIT_DEN;
    }
    if (hi - lo > b->leaf_max && (split_ll || split_w)) {
        /* stable counting sort of the range by child, key = (lat, lon, w)
         * bits, carried in tmp's top bits next to the normal's index */
        uint32_t count[9] = { 0 };
        int sl = (int)(MAX_DEPTH - cl->level - 1), sw = (int)(MAX_DEPTH - cl->wlevel - 1);
        for (uint32_t k = lo; k < hi; k++) {
            uint32_t f = b->fine[b->order[k]], key = 0;
            if (split_ll) key = ((FINE_LAT(f) >> sl) & 1u) << 2 | ((FINE_LON(f) >> sl) & 1u) << 1;
            if (split_w) key |= (FINE_W(f) >> sw) & 1u;
            b->tmp[k] = key << 28 | b->order[k];
            count[key + 1]++;
        }
        for (int d = 0; d < 8; d++) count[d + 1] += count[d];
        uint32_t start[9];
        memcpy(start, count, sizeof start);
        for (uint32_t k = lo; k < hi; k++)
            b->order[lo + count[b->tmp[k] >> 28]++] = b->tmp[k] & 0x0FFFFFFFu;
        for (uint32_t key = 0; key < 8; key++) {
            if (start[key] == start[key + 1]) continue;
            cell ch = *cl;
            if (split_ll) {
                ch.level++;
                ch.lat = cl->lat << 1 | (key >> 2);
                ch.lon = cl->lon << 1 | ((key >> 1) & 1u);
            }
            if (split_w) {
                ch.wlevel++;
                ch.w = cl->w << 1 | (key & 1u);
            }
            build_cell(b, &ch, lo + start[key], lo + start[key + 1]);
        }
    }
    if (b->node) b->node[self].skip = b->nnodes;
}

/* Index of an angle (Q16.16 radians) in a grid of 2^depth cells over
 * [-span*pi/2, span*pi/2). */
static uint32_t angle_index(silk_fx angle, int span, uint32_t depth)
{
    int64_t num = ((int64_t)2 * angle + (int64_t)span * SILK_FX_PI) * ((int64_t)1 << depth);
    int64_t den = (int64_t)2 * span * SILK_FX_PI;
    int64_t i = num < 0 ? 0 : num / den;
    int64_t top = ((int64_t)1 << depth) - 1;
    return (uint32_t)(i > top ? top : i);
}

static uint32_t auto_depth(uint32_t n, uint32_t leaf_max)
{
    uint32_t d = 1;
    /* enough levels for ~leaf_max normals per cell if they were uniform,
     * and a few more for the clusters real meshes have */
    while (d < MAX_DEPTH && ((uint64_t)leaf_max << (2 * d)) < n) d++;
    d += 3;
    return d > MAX_DEPTH ? MAX_DEPTH : d;
}

static silk_status check_mesh(const silk_mesh *m, silk_error *err)
{
    if (m->nnormals && (!m->normal || !m->normal_vertex || !m->pos))
        return silk_fail(err, SILK_ERR_ARG, "visibility", 0, "mesh has normals but no arrays");
    if (m->ntris && !m->tri_normal)
        return silk_fail(err, SILK_ERR_ARG, "visibility", 0, "mesh has triangles but no tri_normal");
    if (m->nnormals > 0x0FFFFFFFu)
        return silk_fail(err, SILK_ERR_ARG, "visibility", 0, "too many normals (%lu)", (unsigned long)m->nnormals);
    for (uint32_t i = 0; i < m->nnormals; i++) {
        if (m->normal_vertex[i] >= m->nverts)
            return silk_fail(err, SILK_ERR_ARG, "visibility", 0,
                             "normal %lu belongs to vertex %lu, beyond the %lu vertices",
                             (unsigned long)i, (unsigned long)m->normal_vertex[i],
                             (unsigned long)m->nverts);
        silk_vec3 n = m->normal[i];
        if (silk_v3_dot64(n, n) > NORMAL_MAX_SQ)
            return silk_fail(err, SILK_ERR_ARG, "visibility", 0, "normal %lu is not a unit vector",
                             (unsigned long)i);
    }
    for (uint64_t k = 0; k < (uint64_t)m->ntris * 3; k++)
        if (m->tri_normal[k] >= m->nnormals)
            return silk_fail(err, SILK_ERR_ARG, "visibility", 0,
                             "triangle %lu uses normal %lu, beyond the %lu normals",
                             (unsigned long)(k / 3), (unsigned long)m->tri_normal[k],
                             (unsigned long)m->nnormals);
    return SILK_OK;
}

static silk_status nomem(silk_error *err, silk_arena *a, const silk_arena_mark *mark, const char *what)
{
    size_t need = a->failed_request;
    silk_arena_top_release(a, mark);
    return silk_fail(err, SILK_ERR_NOMEM, "visibility", 0, "arena too small for %s (a request of %lu bytes failed)",
                     what, (unsigned long)need);
}

/* Each normal's key in the hierarchy (fine[i]: latitude, longitude and w
 * at the finest level) with order[i] = i, and the model centre C *centre
 * (middle of the normals' vertices' box); returns k, the scale s = 2^k
 * (Q16.16 units) >= every |N.(V-C)|, so that w = -N.(V-C)/s is in [-1,1]. */
static int fine_keys(const silk_mesh *m, uint32_t *fine, uint32_t *order, silk_vec3 *centre)
{
    uint32_t n = m->nnormals;
    /* C, and s = 2^k >= every |N.(V-C)| (Q32.32) */
    silk_vec3 lo3 = silk_v3(SILK_FX_MAX, SILK_FX_MAX, SILK_FX_MAX), hi3 = silk_v3(SILK_FX_MIN, SILK_FX_MIN, SILK_FX_MIN);
    for (uint32_t i = 0; i < n; i++) {
        silk_vec3 p = m->pos[m->normal_vertex[i]];
        lo3 = silk_v3(silk_fx_min(lo3.x, p.x), silk_fx_min(lo3.y, p.y), silk_fx_min(lo3.z, p.z));
        hi3 = silk_v3(silk_fx_max(hi3.x, p.x), silk_fx_max(hi3.y, p.y), silk_fx_max(hi3.z, p.z));
    }
    silk_vec3 c = n ? silk_v3((silk_fx)(((int64_t)lo3.x + hi3.x) / 2), (silk_fx)(((int64_t)lo3.y + hi3.y) / 2),
                              (silk_fx)(((int64_t)lo3.z + hi3.z) / 2))
                    : silk_v3(0, 0, 0);
    int64_t wmax = 0;
    for (uint32_t i = 0; i < n; i++) {
        int64_t d = (int64_t)silk_abs64(persp_dot64(m->normal[i], c, m->pos[m->normal_vertex[i]]));
        if (d > wmax) wmax = d;
    }
    int scale_log2 = 0;                     /* s = 2^scale_log2 Q16.16 units = 2^(scale_log2+16) in Q32.32 */
    while (((int64_t)1 << (scale_log2 + 16)) < wmax) scale_log2++;

    int64_t s = (int64_t)1 << (scale_log2 + 16);
    for (uint32_t i = 0; i < n; i++) {
        silk_vec3 nn = m->normal[i];
        silk_fx hyp = (silk_fx)silk_isqrt64((uint64_t)((int64_t)nn.x * nn.x + (int64_t)nn.y * nn.y));
        uint32_t la = angle_index(silk_fx_atan2(nn.z, hyp), 1, MAX_DEPTH);
        uint32_t lo = angle_index(silk_fx_atan2(nn.y, nn.x), 2, MAX_DEPTH);
        /* (w + 1)/2 * 2^10 = (s - N.(V-C)) * 2^9 / s, exactly */
        int64_t dot = persp_dot64(nn, c, m->pos[m->normal_vertex[i]]);
        int64_t wi = ((s - dot) << MAX_DEPTH) >> (scale_log2 + 17);
        if (wi > 1023) wi = 1023;
        fine[i] = la << 20 | lo << 10 | (uint32_t)wi;
        order[i] = i;
    }
    *centre = c;
    return scale_log2;
}

/* The mesh's normals renumbered into cell order (order[new] = old; tmp,
 * fine and ncopy scratch of n entries). */
static void renumber(silk_mesh *m, const uint32_t *order, uint32_t *tmp, uint32_t *fine, silk_vec3 *ncopy)
{
    uint32_t n = m->nnormals;
    /* tmp: old -> new */
    for (uint32_t k = 0; k < n; k++) tmp[order[k]] = k;
    for (uint64_t k = 0; k < (uint64_t)m->ntris * 3; k++) m->tri_normal[k] = tmp[m->tri_normal[k]];
    if (n) {
        for (uint32_t k = 0; k < n; k++) fine[k] = m->normal_vertex[order[k]];
        memcpy(m->normal_vertex, fine, (size_t)n * sizeof *fine);
        for (uint32_t k = 0; k < n; k++) ncopy[k] = m->normal[order[k]];
        memcpy(m->normal, ncopy, (size_t)n * sizeof *ncopy);
    }
}

silk_status silk_vis_build(silk_mesh *m, const silk_vis_opts *opts, silk_arena *a, silk_error *err)
{
    if (!m || !a) return silk_fail(err, SILK_ERR_ARG, "visibility", 0, "missing mesh or arena");
    /* the hierarchy renumbers the normals, which a compact model keeps in
     * place: it has none, and its normals are tested one by one */
    if (m->packed.base) return SILK_OK;
    silk_status st = check_mesh(m, err);
    if (st != SILK_OK) return st;
    uint32_t n = m->nnormals;
    uint32_t leaf_max = opts && opts->leaf_max ? opts->leaf_max : LEAF_MAX;
    uint32_t depth = opts && opts->max_depth ? opts->max_depth : auto_depth(n, leaf_max);
    if (depth > MAX_DEPTH) depth = MAX_DEPTH;

    silk_arena_mark mark = silk_arena_top_mark(a);
    uint32_t *fine = silk_arena_array_top(a, n, sizeof *fine, SILK_MEM_LOAD);
    uint32_t *order = silk_arena_array_top(a, n, sizeof *order, SILK_MEM_LOAD);
    uint32_t *tmp = silk_arena_array_top(a, n, sizeof *tmp, SILK_MEM_LOAD);
    silk_vec3 *ncopy = silk_arena_array_top(a, n, sizeof *ncopy, SILK_MEM_LOAD);
    if (!fine || !order || !tmp || !ncopy) return nomem(err, a, &mark, "the hierarchy's scratch");

    silk_vec3 centre;
    int scale_log2 = fine_keys(m, fine, order, &centre);

    /* Count, and coarsen the leaves until the nodes fit the memory budget. */
    build_ctx b;
    memset(&b, 0, sizeof b);
    b.m = m; b.fine = fine; b.order = order; b.tmp = tmp; b.depth = depth;
    uint64_t budget = (uint64_t)n * BYTES_PER_NORMAL;
    if (budget < sizeof(silk_vis_node)) budget = sizeof(silk_vis_node);
    const cell root = { 0, 0, 0, 0, 0 };
    for (b.leaf_max = leaf_max;; b.leaf_max *= 2) {
        b.nnodes = 0;
        if (n) build_cell(&b, &root, 0, n);
        if ((uint64_t)b.nnodes * sizeof(silk_vis_node) <= budget || b.leaf_max >= n) break;
    }

    /* Both persistent blocks only when both fit, so that a failure leaves
     * no bytes behind at the bottom. */
    size_t keep = arena_block(sizeof(silk_vis)) + arena_block((size_t)b.nnodes * sizeof(silk_vis_node));
    if (keep > silk_arena_free_bytes(a)) {
        a->failed_request = keep;
        return nomem(err, a, &mark, "the hierarchy");
    }
    silk_vis *vis = silk_arena_alloc(a, sizeof *vis, SILK_MEM_VISIBILITY);
    silk_vis_node *node = silk_arena_array(a, b.nnodes, sizeof *node, SILK_MEM_VISIBILITY);
    b.node = node;
    b.nnodes = 0;
    b.max_level = 0;
    b.widened = 0;
    if (n) build_cell(&b, &root, 0, n);

    /* Nothing above touched the mesh, so a failure leaves it as it was. */
    renumber(m, order, tmp, fine, ncopy);

    vis->nnodes = b.nnodes;
    vis->nnormals = n;
    vis->depth = b.max_level;
    vis->leaf_max = b.leaf_max;
    vis->centre = centre;
    vis->scale_log2 = scale_log2;
    vis->widened = b.widened;
    vis->node = node;
    m->vis = vis;
    silk_arena_top_release(a, &mark);
    return SILK_OK;
}

size_t silk_vis_bytes(const silk_vis *v)
{
    return v ? sizeof *v + (size_t)v->nnodes * sizeof(silk_vis_node) : 0;
}

/* ---- per frame ---------------------------------------------------------------- */

/* Unit vector of q in Q2.30, within 2^-26 of the exact direction (the
 * margin below relies on it); returns 0 for the zero vector.  Components are
 * brought to [2^29, 2^30] first, so the squares cannot overflow and the
 * rounding of that shift moves the direction by at most 2^-28. */
static int unit4(const int64_t q_in[4], int32_t g[4])
{
    int64_t q[4], big = 0;
    for (int k = 0; k < 4; k++) if ((int64_t)silk_abs64(q_in[k]) > big) big = (int64_t)silk_abs64(q_in[k]);
    if (big == 0) { memset(g, 0, 4 * sizeof *g); return 0; }
    int sh = 0;
    while ((big >> sh) >= ((int64_t)1 << 30)) sh++;
    int up = 0;
    while ((big << up) < ((int64_t)1 << 29)) up++;
    for (int k = 0; k < 4; k++) q[k] = sh ? silk_shr_round64(q_in[k], sh) : q_in[k] * ((int64_t)1 << up);
    uint64_t len_sq = 0;
    for (int k = 0; k < 4; k++) len_sq += (uint64_t)(q[k] * q[k]);
    int64_t len = silk_isqrt64(len_sq);
    for (int k = 0; k < 4; k++) {
        int64_t num = q[k] * ((int64_t)1 << 30);
        g[k] = (int32_t)(num >= 0 ? (num + len / 2) / len : -((-num + len / 2) / len));
    }
    return 1;
}

/* Q46 bound on |(N,w).(g - u)| for |N| <= 1.004, |w| <= 1 and the 2^-26
 * error of unit4: 2.004 * 2^-26 < 2^-24.9, taken as 2^-23. */
#define DOT_MARGIN ((int64_t)1 << 23)

silk_status silk_visibility_gauss(const silk_mesh *m, const silk_view *v, uint8_t *visible,
                                  silk_vis_stats *stats)
{
    const silk_vis *vis = m->vis;
    if (!vis || vis->nnormals != m->nnormals) return SILK_ERR_ARG;
    uint32_t n = m->nnormals, nn = vis->nnodes;
    const silk_vis_node *node = vis->node;
    int ortho = v->cam.ortho;
    int64_t q[4];
    if (ortho) {
        q[0] = -(int64_t)v->forward.x; q[1] = -(int64_t)v->forward.y; q[2] = -(int64_t)v->forward.z;
        q[3] = 0;
    } else {
        q[0] = (int64_t)v->cam.eye.x - vis->centre.x;
        q[1] = (int64_t)v->cam.eye.y - vis->centre.y;
        q[2] = (int64_t)v->cam.eye.z - vis->centre.z;
        q[3] = (int64_t)1 << vis->scale_log2;
    }
    int32_t g[4];
    unit4(q, g);
    int64_t e3 = ceil_sqrt64((uint64_t)((int64_t)g[0] * g[0] + (int64_t)g[1] * g[1] + (int64_t)g[2] * g[2]));
    int64_t gw = (int64_t)g[3] * 4;

    silk_vec3 f = v->forward, e = v->cam.eye;
    const silk_vec3 *nrm = m->normal, *pos = m->pos;
    const silk_index *nv = m->normal_vertex;
    uint32_t decided = 0, one = 0, visited = 0;
    uint32_t i = 0;
    while (i < nn) {
        const silk_vis_node *c = &node[i];
        uint32_t next = c->skip, lo = c->first, hi = next < nn ? node[next].first : n;
        visited++;
        int64_t cd = ((int64_t)c->c[0] * g[0] + (int64_t)c->c[1] * g[1] + (int64_t)c->c[2] * g[2]) * 4;
        int64_t rr = (int64_t)c->r * e3 * 4 + DOT_MARGIN;
        if (cd - rr + c->w0 * gw > 0) {
            memset(visible + lo, 1, hi - lo);
            decided += hi - lo;
            i = next;
        } else if (cd + rr + c->w1 * gw < 0) {
            memset(visible + lo, 0, hi - lo);
            decided += hi - lo;
            i = next;
        } else if (next == i + 1) {
            /* a straddling leaf: one by one, exactly as the brute pass */
            if (ortho)
                for (uint32_t k = lo; k < hi; k++) visible[k] = (uint8_t)(silk_v3_dot64(nrm[k], f) <= 0);
            else
                for (uint32_t k = lo; k < hi; k++)
                    visible[k] = (uint8_t)(persp_dot64(nrm[k], pos[nv[k]], e) >= 0);
            one += hi - lo;
            i = next;
        } else {
            i++;
        }
    }
    if (stats) {
        stats->normals = n;
        stats->cell_decided = decided;
        stats->one_by_one = one;
        stats->cells_visited = visited;
    }
    return SILK_OK;
}
