/*
 * obj.c - Wavefront OBJ from a memory buffer into a silk_mesh.
 *
 * Reads what a coarse mesh M (paper section III) needs: `v` (with an
 * optional vertex colour `r g b` in [0, 1] after x y z), `vt`, `vn`,
 * `f` (v, v/t, v//n, v/t/n, negative indices; polygons fanned into
 * triangles) and `s` smoothing groups; everything else is skipped
 * (materials, `mtllib`/`usemtl`, are read by the host tool, which does the
 * file I/O).  Two
 * passes: the first counts and checks the structure of each line, the second
 * parses numbers into arrays of exactly the counted size, then
 * silk_mesh_build() derives the rest.
 */
#include <string.h>
#include "load.h"

typedef struct obj_counts {
    uint64_t v, vt, vn, tris;
    uint64_t vcolor;             /* `v` lines with a colour */
    int all_uv, all_n;           /* every face corner has a t / n index */
    int any_s;                   /* there is an `s` statement */
} obj_counts;

typedef silk_ld_text obj_reader;

/* Next line as [*b, *e) without its end ("\n", "\r\n" or a lone "\r"). */
static int next_line(obj_reader *r, const char **b, const char **e)
{
    const char *p = r->p;
    if (p >= r->end) return 0;
    *b = p;
    while (p < r->end && *p != '\n' && *p != '\r') p++;
    *e = p;
    if (p < r->end) p += (*p == '\r' && p + 1 < r->end && p[1] == '\n') ? 2 : 1;
    r->p = p;
    r->line++;
    return 1;
}

/* "name:line: message" for the line being read. */
#define FAIL(r, code, ...) silk_fail((r)->err, (code), (r)->name, (r)->line, __VA_ARGS__)

/* The numbers of a `v`/`vt`/`vn` line: at least `need`, at most `most`. */
static silk_status parse_numbers(obj_reader *r, const char *p, const char *e, int need, int most,
                                 const char *what, silk_decimal *out, int *found)
{
    const char *t;
    size_t n;
    int k = 0;
    while (silk_ld_token(&p, e, &t, &n)) {
        silk_decimal d;
        if (k == most) return FAIL(r, SILK_ERR_PARSE, "too many values for %s", what);
        silk_status s = silk_ld_parse_decimal(t, n, &d, r->name, r->line, r->err);
        if (s) return s;
        if (k < 6) out[k] = d;
        k++;
    }
    if (k < need) return FAIL(r, SILK_ERR_PARSE, "%s needs %d numbers, found %d", what, need, k);
    if (found) *found = k;
    return SILK_OK;
}

/* ---- pass 1: count ----------------------------------------------------------- */

static silk_status count_face(obj_reader *r, const char *p, const char *e, obj_counts *c)
{
    const char *t;
    size_t n;
    uint64_t corners = 0;
    while (silk_ld_token(&p, e, &t, &n)) {
        const char *s1 = memchr(t, '/', n);
        const char *s2 = s1 ? memchr(s1 + 1, '/', (size_t)(t + n - s1 - 1)) : NULL;
        int has_uv = s1 && (s2 ? s2 : t + n) > s1 + 1;
        int has_n = s2 && t + n > s2 + 1;
        if (!has_uv) c->all_uv = 0;
        if (!has_n) c->all_n = 0;
        corners++;
    }
    if (corners < 3)
        return FAIL(r, SILK_ERR_PARSE, "face has %lu vertices (at least 3 needed)", (unsigned long)corners);
    c->tris += corners - 2;
    return SILK_OK;
}

static silk_status count_pass(obj_reader *r, obj_counts *c)
{
    const char *b, *e;
    memset(c, 0, sizeof *c);
    c->all_uv = c->all_n = 1;
    while (next_line(r, &b, &e)) {
        if (e - b > SILK_LD_MAX_LINE)
            return FAIL(r, SILK_ERR_PARSE, "line too long (more than %d bytes)", SILK_LD_MAX_LINE);
        /* Control bytes mean binary data: say so rather than parse it. */
        for (const char *s = b; s < e; s++) {
            unsigned char ch = (unsigned char)*s;
            if ((ch < 0x20 && ch != '\t' && ch != '\f' && ch != '\v') || ch == 0x7f)
                return FAIL(r, SILK_ERR_PARSE, "unexpected byte 0x%02x (not a text file?)", (unsigned)ch);
        }
        const char *p = b, *t;
        size_t n;
        if (!silk_ld_token(&p, e, &t, &n)) continue;
        if (silk_ld_token_is(t, n, "v")) {
            c->v++;
            int k = 0;
            while (silk_ld_token(&p, e, &t, &n)) k++;
            if (k >= 6) c->vcolor++;
        }
        else if (silk_ld_token_is(t, n, "vt")) c->vt++;
        else if (silk_ld_token_is(t, n, "vn")) c->vn++;
        else if (silk_ld_token_is(t, n, "s")) c->any_s = 1;
        else if (silk_ld_token_is(t, n, "f")) {
            silk_status s = count_face(r, p, e, c);
            if (s) return s;
        }
    }
    return SILK_OK;
}

/* ---- pass 2: fill ------------------------------------------------------------ */

typedef struct obj_fill {
    silk_mesh_input in;
    silk_ld_coords coords;
    uint32_t nv, nvt, nvn;       /* seen so far, for negative indices */
    uint32_t ntri;
    uint32_t group;
    int want_uv, want_n, want_color;
} obj_fill;

/* One index field of a face corner.  kind names it in messages. */
static silk_status resolve(obj_reader *r, const char *t, size_t n, const char *kind, const char *things,
                           uint32_t so_far, uint64_t total, uint32_t *out)
{
    char q[48];
    size_t i = 0;
    int neg = 0;
    uint64_t v = 0;
    if (i < n && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
    if (i == n) return FAIL(r, SILK_ERR_PARSE, "bad face vertex '%s'", silk_ld_quote(t, n, q, sizeof q));
    for (; i < n; i++) {
        if (t[i] < '0' || t[i] > '9')
            return FAIL(r, SILK_ERR_PARSE, "bad face vertex '%s'", silk_ld_quote(t, n, q, sizeof q));
        if (v < 10000000000000ull) v = v * 10 + (uint64_t)(t[i] - '0');
    }
    if (v == 0) return FAIL(r, SILK_ERR_PARSE, "%s 0 is invalid (OBJ indices start at 1)", kind);
    /* v saturates for absurd digit strings; the message quotes the text. */
    if (neg) {
        if (v > so_far)
            return FAIL(r, SILK_ERR_PARSE, "%s %s out of range (%lu %s so far)",
                        kind, silk_ld_quote(t, n, q, sizeof q), (unsigned long)so_far, things);
        *out = so_far - (uint32_t)v;
    } else {
        if (v > total)
            return FAIL(r, SILK_ERR_PARSE, "%s %s out of range (%llu %s)",
                        kind, silk_ld_quote(t, n, q, sizeof q), (unsigned long long)total, things);
        *out = (uint32_t)(v - 1);
    }
    return SILK_OK;
}

/* One face corner "v", "v/t", "v//n" or "v/t/n" into indices (SILK_NO_INDEX when absent). */
static silk_status parse_corner(obj_reader *r, const char *t, size_t n, const obj_fill *f,
                                const obj_counts *c, silk_index idx[3])
{
    const char *field[3];
    size_t len[3];
    int nf = 0;
    const char *s = t, *e = t + n;
    char q[48];
    while (nf < 3) {
        const char *slash = memchr(s, '/', (size_t)(e - s));
        field[nf] = s;
        len[nf] = (size_t)((slash ? slash : e) - s);
        nf++;
        if (!slash) break;
        s = slash + 1;
        if (nf == 3) return FAIL(r, SILK_ERR_PARSE, "bad face vertex '%s'", silk_ld_quote(t, n, q, sizeof q));
    }
    static const char *const kind[3] = { "face index", "texture index", "normal index" };
    static const char *const things[3] = { "vertices", "texture coordinates", "normals" };
    const uint32_t so_far[3] = { f->nv, f->nvt, f->nvn };
    const uint64_t total[3] = { c->v, c->vt, c->vn };
    for (int k = 0; k < 3; k++) {
        uint32_t v = 0;
        idx[k] = SILK_NO_INDEX;
        if (k >= nf || (k > 0 && len[k] == 0)) continue;
        silk_status st = resolve(r, field[k], len[k], kind[k], things[k], so_far[k], total[k], &v);
        if (st) return st;
        idx[k] = (silk_index)v;
    }
    return SILK_OK;
}

static silk_status fill_face(obj_reader *r, const char *p, const char *e, obj_fill *f, const obj_counts *c)
{
    const char *t;
    size_t n;
    silk_index first[3], prev[3], cur[3];
    uint32_t k = 0;
    while (silk_ld_token(&p, e, &t, &n)) {
        silk_status st = parse_corner(r, t, n, f, c, cur);
        if (st) return st;
        if (k >= 2) {
            uint32_t base = f->ntri * 3;
            const silk_index *corner[3] = { first, prev, cur };
            for (uint32_t j = 0; j < 3; j++) {
                f->in.tri[base + j] = corner[j][0];
                if (f->want_uv) f->in.tri_uv[base + j] = corner[j][1];
                if (f->want_n) f->in.tri_file_normal[base + j] = corner[j][2];
            }
            if (f->in.tri_group) f->in.tri_group[f->ntri] = f->group;
            f->ntri++;
        }
        if (k == 0) memcpy(first, cur, sizeof first);
        memcpy(prev, cur, sizeof prev);
        k++;
    }
    return SILK_OK;
}

static silk_status fill_line(obj_reader *r, const char *p, const char *e, obj_fill *f, const obj_counts *c)
{
    const char *t;
    size_t n;
    silk_decimal d[6];
    silk_status st;
    char q[48];
    if (!silk_ld_token(&p, e, &t, &n)) return SILK_OK;
    if (silk_ld_token_is(t, n, "v")) {
        /* x y z, then w (not used) or a colour r g b [a] (alpha not used) */
        int found = 0;
        if ((st = parse_numbers(r, p, e, 3, 7, "vertex", d, &found))) return st;
        if (found == 5) return FAIL(r, SILK_ERR_PARSE, "vertex colour needs 3 numbers (r g b), found 2");
        silk_fx *pos = &f->in.pos[f->nv].x;
        for (int k = 0; k < 3; k++)
            silk_ld_coord(&f->coords, d[k], NULL, k, r->line, f->nv, &pos[k]);
        if (f->want_color) {
            uint32_t rgb = 0xffffff;   /* a vertex without a colour: white, no change */
            if (found >= 6) {
                rgb = 0;
                for (int k = 0; k < 3; k++) {
                    uint32_t ch;
                    if (silk_ld_color_channel(d[3 + k], 1, &ch) != 0) {
                        char b[40];
                        return FAIL(r, SILK_ERR_RANGE, "vertex colour %s is outside [0, 1]",
                                    silk_ld_dec_format(d[3 + k], 6, b, sizeof b));
                    }
                    rgb = rgb << 8 | ch;
                }
            }
            f->in.color[f->nv] = rgb;
        }
        f->nv++;
    } else if (silk_ld_token_is(t, n, "vt")) {
        d[1].mant = 0; d[1].exp10 = 0;
        if ((st = parse_numbers(r, p, e, 1, 3, "texture coordinate", d, NULL))) return st;
        if (f->want_uv) {
            silk_fx uv[2];
            for (int k = 0; k < 2; k++)
                if (silk_decimal_to_fx(d[k], &uv[k]) != 0) {
                    char b[40];
                    return FAIL(r, SILK_ERR_RANGE, "texture coordinate %s is out of range",
                                silk_ld_dec_format(d[k], 6, b, sizeof b));
                }
            f->in.uv[f->nvt].x = uv[0];
            f->in.uv[f->nvt].y = uv[1];
        }
        f->nvt++;
    } else if (silk_ld_token_is(t, n, "vn")) {
        if ((st = parse_numbers(r, p, e, 3, 3, "normal", d, NULL))) return st;
        /* A zero normal stays zero: silk_mesh_build falls back to the face's. */
        if (f->want_n) silk_ld_direction(d, &f->in.file_normal[f->nvn]);
        f->nvn++;
    } else if (silk_ld_token_is(t, n, "f")) {
        return fill_face(r, p, e, f, c);
    } else if (silk_ld_token_is(t, n, "s")) {
        const char *a;
        size_t an;
        if (!silk_ld_token(&p, e, &a, &an)) return FAIL(r, SILK_ERR_PARSE, "smoothing group needs a number or 'off'");
        if (silk_ld_token_is(a, an, "off")) { f->group = 0; return SILK_OK; }
        uint64_t g = 0;
        for (size_t i = 0; i < an; i++) {
            if (a[i] < '0' || a[i] > '9' || g > UINT32_MAX / 10)
                return FAIL(r, SILK_ERR_PARSE, "bad smoothing group '%s'", silk_ld_quote(a, an, q, sizeof q));
            g = g * 10 + (uint64_t)(a[i] - '0');
        }
        if (g > UINT32_MAX)
            return FAIL(r, SILK_ERR_PARSE, "bad smoothing group '%s'", silk_ld_quote(a, an, q, sizeof q));
        f->group = (uint32_t)g;
    }
    return SILK_OK;
}

silk_status silk_load_obj(const void *data, size_t len, const char *name,
                          const silk_load_opts *opts, silk_arena *a, silk_mesh *out, silk_error *err)
{
    silk_load_opts defaults;
    silk_status st0 = silk_ld_start("silk_load_obj", data, len, &name, &opts, &defaults, a, out, err);
    if (st0) return st0;

    obj_reader r = { data, (const char *)data + len, 0, name, err };
    if (len >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0) r.p += 3;   /* UTF-8 byte order mark */
    const char *start = r.p;

    obj_counts c;
    silk_status st = count_pass(&r, &c);
    if (st) return st;
    if (c.v >= (uint64_t)SILK_NO_INDEX || c.vt >= (uint64_t)SILK_NO_INDEX || c.vn >= (uint64_t)SILK_NO_INDEX
        || c.tris > UINT32_MAX / 3)
        return silk_fail(err, SILK_ERR_RANGE, name, 0, "too many elements (%llu vertices, %llu triangles)",
                         (unsigned long long)c.v, (unsigned long long)c.tris);

    obj_fill f;
    memset(&f, 0, sizeof f);
    f.want_uv = c.all_uv && c.vt > 0;
    f.want_n = c.all_n && c.vn > 0 && opts->normals != SILK_NORMALS_COMPUTE;
    f.want_color = c.vcolor > 0;

    size_t need = 0;
    int ok = silk_ld_need(&need, c.v, sizeof(silk_vec3)) && silk_ld_need(&need, c.tris * 3, sizeof(silk_index));
    if (f.want_uv) ok = ok && silk_ld_need(&need, c.vt, sizeof(silk_vec2)) && silk_ld_need(&need, c.tris * 3, sizeof(silk_index));
    if (f.want_n) ok = ok && silk_ld_need(&need, c.vn, sizeof(silk_vec3)) && silk_ld_need(&need, c.tris * 3, sizeof(silk_index));
    if (c.any_s) ok = ok && silk_ld_need(&need, c.tris, sizeof(uint32_t));
    if (f.want_color) ok = ok && silk_ld_need(&need, c.v, sizeof(uint32_t));
    if (!ok || need > silk_arena_free_bytes(a)) return silk_ld_nomem(err, name, ok ? need : SIZE_MAX, a);

    silk_arena saved = *a;
    silk_arena_mark mark = silk_arena_top_mark(a);
    /* The mesh keeps positions, triangles and uvs; file normals and groups
     * are only read by silk_mesh_build, so they live on the top. */
    f.in.pos = silk_arena_array(a, c.v, sizeof(silk_vec3), SILK_MEM_MESH);
    f.in.tri = silk_arena_array(a, c.tris * 3, sizeof(silk_index), SILK_MEM_MESH);
    if (f.want_uv) {
        f.in.uv = silk_arena_array(a, c.vt, sizeof(silk_vec2), SILK_MEM_MESH);
        f.in.tri_uv = silk_arena_array(a, c.tris * 3, sizeof(silk_index), SILK_MEM_MESH);
    }
    if (f.want_color) f.in.color = silk_arena_array(a, c.v, sizeof(uint32_t), SILK_MEM_MESH);
    if (f.want_n) {
        f.in.file_normal = silk_arena_array_top(a, c.vn, sizeof(silk_vec3), SILK_MEM_LOAD);
        f.in.tri_file_normal = silk_arena_array_top(a, c.tris * 3, sizeof(silk_index), SILK_MEM_LOAD);
    }
    if (c.any_s) f.in.tri_group = silk_arena_array_top(a, c.tris, sizeof(uint32_t), SILK_MEM_LOAD);
    silk_ld_coords_init(&f.coords, opts);

    r.p = start;
    r.line = 0;
    const char *b, *e;
    st = SILK_OK;
    while (st == SILK_OK && next_line(&r, &b, &e))
        st = fill_line(&r, b, e, &f, &c);
    /* Checked after the syntax, so that a broken line is reported as such. */
    if (st == SILK_OK && f.ntri == 0) st = silk_fail(err, SILK_ERR_EMPTY, name, 0, "no triangles");
    if (st == SILK_OK) st = silk_ld_coords_finish(&f.coords, name, err);
    if (st == SILK_OK) {
        f.in.nverts = (uint32_t)c.v;
        f.in.ntris = f.ntri;
        f.in.nuvs = f.want_uv ? (uint32_t)c.vt : 0;
        f.in.nfile_normals = f.want_n ? (uint32_t)c.vn : 0;
        st = silk_mesh_build(&f.in, name, opts, a, out, err);
    }
    silk_arena_top_release(a, &mark);
    if (st != SILK_OK) {
        silk_ld_arena_restore(a, &saved);
        memset(out, 0, sizeof *out);
    }
    return st;
}
