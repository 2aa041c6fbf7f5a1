/*
 * testmesh.c - test support: files, shared meshes and mesh-build fixtures
 * (see testmesh.h).
 */
#include "testmesh.h"
#include "testvec.h"

#include <stdlib.h>
#include <string.h>

char *tm_read_stream(FILE *fp, size_t *len)
{
    size_t n = 0, cap = 1 << 16;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) return NULL;
        n += fread(buf + n, 1, cap - 1 - n, fp);
        if (n < cap - 1) break;
        char *nb = realloc(buf, cap *= 2);
        if (!nb) free(buf);
        buf = nb;
    }
    if (ferror(fp)) { free(buf); return NULL; }
    /* trimmed to the data, so that a loader reading past it is caught */
    char *exact = realloc(buf, n + 1);
    if (!exact) { free(buf); return NULL; }
    exact[n] = '\0';
    *len = n;
    return exact;
}

char *tm_read_file(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    char *buf = tm_read_stream(fp, len);
    fclose(fp);
    return buf;
}

int tm_load_obj_in(silk_arena *a, const char *dir, const char *name, silk_mesh *m)
{
    char path[512];
    size_t len;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    char *text = tm_read_file(path, &len);
    if (!text) { fprintf(stderr, "cannot read %s\n", path); return 0; }
    silk_load_opts o;
    silk_load_opts_default(&o);
    silk_error err;
    silk_status st = silk_load_obj(text, len, name, &o, a, m, &err);
    free(text);
    if (st != SILK_OK) { fprintf(stderr, "%s\n", err.msg); return 0; }
    return 1;
}

/* ---- fixture ------------------------------------------------------------------ */

void tm_fixture_init(tm_fixture *f, size_t bytes)
{
    memset(f, 0, sizeof *f);
    f->buf = malloc(bytes ? bytes : 1);
    f->bytes = bytes;
    silk_arena_init(&f->a, f->buf, bytes);
    silk_load_opts_default(&f->opts);
}

void tm_fixture_reset(tm_fixture *f)
{
    silk_arena_init(&f->a, f->buf, f->bytes);
    memset(&f->in, 0, sizeof f->in);
    memset(&f->m, 0, sizeof f->m);
}

void tm_fixture_free(tm_fixture *f) { free(f->buf); }

int tm_fixture_input(tm_fixture *f, const double *pos, uint32_t nv, const uint32_t *tri, uint32_t nt)
{
    f->in.nverts = nv;
    f->in.ntris = nt;
    f->in.pos = silk_arena_array(&f->a, nv, sizeof(silk_vec3), SILK_MEM_MESH);
    f->in.tri = silk_arena_array(&f->a, 3 * (size_t)nt, sizeof(silk_index), SILK_MEM_MESH);
    if (!f->in.pos || !f->in.tri) return 0;
    for (uint32_t v = 0; v < nv; v++)
        f->in.pos[v] = silk_v3(d2fx(pos[3 * v]), d2fx(pos[3 * v + 1]), d2fx(pos[3 * v + 2]));
    for (uint32_t c = 0; c < 3 * nt; c++) f->in.tri[c] = tri[c];
    return 1;
}

silk_status tm_fixture_build(tm_fixture *f)
{
    return silk_mesh_build(&f->in, "test", &f->opts, &f->a, &f->m, &f->err);
}

#define NEXT_LINE(l) (strchr(l, '\n') ? strchr(l, '\n') + 1 : (l) + strlen(l))

int tm_fixture_parse_obj(char *text, tm_fixture *f)
{
    uint32_t nv = 0, nt = 0;
    for (char *l = text; *l; l = NEXT_LINE(l)) {
        if (l[0] == 'v' && l[1] == ' ') nv++;
        if (l[0] == 'f' && l[1] == ' ') nt++;
    }
    double *pos = malloc(3 * sizeof(double) * (nv ? nv : 1));
    uint32_t *tri = malloc(3 * sizeof(uint32_t) * (nt ? nt : 1));
    uint32_t iv = 0, it = 0;
    for (char *l = text; *l; l = NEXT_LINE(l)) {
        char *p = l + 2;
        if (l[0] == 'v' && l[1] == ' ') {
            for (int k = 0; k < 3; k++) pos[3 * iv + k] = strtod(p, &p);
            iv++;
        } else if (l[0] == 'f' && l[1] == ' ') {
            for (int k = 0; k < 3; k++) tri[3 * it + k] = (uint32_t)strtoul(p, &p, 10) - 1;
            it++;
        }
    }
    int ok = nv > 0 && nt > 0 && tm_fixture_input(f, pos, nv, tri, nt);
    free(pos);
    free(tri);
    return ok;
}

int tm_fixture_read_obj(tm_fixture *f, const char *path)
{
    size_t len;
    char *text = tm_read_file(path, &len);
    if (!text) return 0;
    int ok = tm_fixture_parse_obj(text, f);
    free(text);
    return ok;
}

/* ---- as double arrays ---------------------------------------------------------- */

int tm_load_doubles(const char *path, double **pos, uint32_t *nv, uint32_t **tri, uint32_t *nt)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        printf("skip: no %s\n", path);
        return 0;
    }
    fclose(f);
    size_t len;
    char *text = tm_read_file(path, &len);
    if (!text) {
        fprintf(stderr, "cannot read %s\n", path);
        return -1;
    }
    size_t bytes = len * 16 + ((size_t)4 << 20);
    void *buf = malloc(bytes);
    silk_arena a;
    silk_arena_init(&a, buf, bytes);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    silk_mesh m;
    silk_error err;
    silk_status st = silk_load_mesh((const uint8_t *)text, len, path, &lo, &a, &m, &err);
    free(text);
    if (st != SILK_OK) {
        fprintf(stderr, "%s\n", err.msg);
        free(buf);
        return -1;
    }
    *nv = m.nverts, *nt = m.ntris;
    *pos = malloc(3 * sizeof **pos * (m.nverts ? m.nverts : 1));
    *tri = malloc(3 * sizeof **tri * (m.ntris ? m.ntris : 1));
    for (uint32_t i = 0; i < m.nverts; i++) vec3d(m.pos[i], &(*pos)[3 * i]);
    for (uint32_t i = 0; i < 3 * m.ntris; i++) (*tri)[i] = m.tri[i];
    free(buf);
    return 1;
}
