/*
 * mkseed.c - writes the seed inputs of the fuzz harnesses that cannot be
 * written with printf in fuzz/seeds.sh: a mesh as PLY (ASCII, binary
 * little- or big-endian) from a simple OBJ, and a file with a byte header
 * in front (the scene header of fuzz_render, the edit list of fuzz_pack).
 *
 *   mkseed ply-ascii|ply-le|ply-be IN.obj OUT.ply
 *   mkseed prefix HEX IN OUT          (HEX: the header bytes, "0a1b...")
 *
 * A host tool (it may use double); it reads only "v x y z" and "f a b c ..."
 * lines (polygons become fans, "a/b/c" keeps a), which is what silk gen and
 * the shared meshes contain.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char *what, const char *arg)
{
    fprintf(stderr, "mkseed: %s%s%s\n", what, arg ? ": " : "", arg ? arg : "");
    return 1;
}

typedef struct mesh {
    double *v;
    long *f;
    long nv, nf, cv, cf;
} mesh;

static int push_v(mesh *m, double x, double y, double z)
{
    if (m->nv == m->cv) {
        m->cv = m->cv ? 2 * m->cv : 256;
        double *n = realloc(m->v, (size_t)m->cv * 3 * sizeof *n);
        if (!n) return -1;
        m->v = n;
    }
    m->v[3 * m->nv] = x;
    m->v[3 * m->nv + 1] = y;
    m->v[3 * m->nv + 2] = z;
    m->nv++;
    return 0;
}

static int push_f(mesh *m, long a, long b, long c)
{
    if (m->nf == m->cf) {
        m->cf = m->cf ? 2 * m->cf : 256;
        long *n = realloc(m->f, (size_t)m->cf * 3 * sizeof *n);
        if (!n) return -1;
        m->f = n;
    }
    m->f[3 * m->nf] = a;
    m->f[3 * m->nf + 1] = b;
    m->f[3 * m->nf + 2] = c;
    m->nf++;
    return 0;
}

static int read_obj(const char *path, mesh *m)
{
    FILE *fp = fopen(path, "r");
    if (!fp) return fail("cannot open", path);
    char line[4096];
    int rc = 0;
    while (!rc && fgets(line, sizeof line, fp)) {
        if (line[0] == 'v' && line[1] == ' ') {
            double x, y, z;
            if (sscanf(line + 2, "%lf %lf %lf", &x, &y, &z) != 3 || push_v(m, x, y, z)) rc = fail("bad vertex", path);
        } else if (line[0] == 'f' && line[1] == ' ') {
            long idx[64];
            int n = 0;
            char *s = line + 2, *end;
            while (n < 64) {
                long i = strtol(s, &end, 10);
                if (end == s) break;
                idx[n++] = i < 0 ? m->nv + i : i - 1;
                s = end;
                while (*s && *s != ' ' && *s != '\t' && *s != '\n') s++;
            }
            for (int k = 1; k + 1 < n && !rc; k++)
                if (push_f(m, idx[0], idx[k], idx[k + 1])) rc = fail("out of memory", NULL);
        }
    }
    fclose(fp);
    return rc;
}

static void put_u32(FILE *fp, uint32_t v, int be)
{
    for (int i = 0; i < 4; i++) fputc((int)(v >> (be ? 24 - 8 * i : 8 * i)) & 255, fp);
}

static void put_f32(FILE *fp, double d, int be)
{
    float f = (float)d;
    uint32_t u;
    memcpy(&u, &f, 4);
    put_u32(fp, u, be);
}

static int write_ply(const mesh *m, const char *kind, const char *path)
{
    int ascii = strcmp(kind, "ply-ascii") == 0, be = strcmp(kind, "ply-be") == 0;
    FILE *fp = fopen(path, "wb");
    if (!fp) return fail("cannot write", path);
    fprintf(fp, "ply\nformat %s 1.0\ncomment mkseed\nelement vertex %ld\nproperty float x\nproperty float y\n"
                "property float z\nelement face %ld\nproperty list uchar int vertex_indices\nend_header\n",
            ascii ? "ascii" : be ? "binary_big_endian" : "binary_little_endian", m->nv, m->nf);
    for (long i = 0; i < m->nv; i++) {
        if (ascii) {
            fprintf(fp, "%.9g %.9g %.9g\n", m->v[3 * i], m->v[3 * i + 1], m->v[3 * i + 2]);
        } else {
            for (int k = 0; k < 3; k++) put_f32(fp, m->v[3 * i + k], be);
        }
    }
    for (long i = 0; i < m->nf; i++) {
        if (ascii) {
            fprintf(fp, "3 %ld %ld %ld\n", m->f[3 * i], m->f[3 * i + 1], m->f[3 * i + 2]);
        } else {
            fputc(3, fp);
            for (int k = 0; k < 3; k++) put_u32(fp, (uint32_t)m->f[3 * i + k], be);
        }
    }
    return fclose(fp) ? fail("cannot write", path) : 0;
}

static int prefix(const char *hex, const char *in, const char *out)
{
    size_t n = strlen(hex);
    if (n % 2) return fail("odd number of hex digits", hex);
    FILE *fi = fopen(in, "rb"), *fo = fi ? fopen(out, "wb") : NULL;
    if (!fi || !fo) {
        if (fi) fclose(fi);
        return fail("cannot open", fi ? out : in);
    }
    for (size_t i = 0; i < n; i += 2) {
        unsigned b;
        if (sscanf(hex + i, "%2x", &b) != 1) { fclose(fi); fclose(fo); return fail("bad hex", hex); }
        fputc((int)b, fo);
    }
    int c;
    while ((c = fgetc(fi)) != EOF) fputc(c, fo);
    fclose(fi);
    return fclose(fo) ? fail("cannot write", out) : 0;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strncmp(argv[1], "ply-", 4) == 0) {
        mesh m = { 0 };
        int rc = read_obj(argv[2], &m);
        if (!rc) rc = write_ply(&m, argv[1], argv[3]);
        free(m.v);
        free(m.f);
        return rc;
    }
    if (argc == 5 && strcmp(argv[1], "prefix") == 0) return prefix(argv[2], argv[3], argv[4]);
    return fail("usage: mkseed ply-ascii|ply-le|ply-be IN.obj OUT.ply | mkseed prefix HEX IN OUT", NULL);
}
