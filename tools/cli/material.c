/*
 * material.c - the OBJ material (mtllib / usemtl), a --texture image and the
 * mesh's vertex colours, turned into silk_phong fields.  The core does no
 * I/O, so this is where the .mtl file and the texture image are read; the
 * core samples the texture (src/texture.c).
 *
 * One material per model: the first `usemtl` names it (the first material of
 * the .mtl without one).  Kd is the base colour, Ks the highlight colour and
 * strength, Ns the exponent, map_Kd the texture.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "material.h"
#include "cli.h"
#include "prep/gen.h"
#include "silk/platform.h"

int cli_texture_from_rgb(const uint8_t *rgb, int width, int height, const cli_texture_opts *to,
                         const uint32_t *palette, silk_texture *t, uint8_t **pixels, char *msg, size_t msglen)
{
    memset(t, 0, sizeof *t);
    *pixels = NULL;
    if (width < 1 || height < 1 || width > SILK_TEX_MAX_DIM || height > SILK_TEX_MAX_DIM) {
        snprintf(msg, msglen, "a texture must be 1 to %d pixels on a side (the image is %dx%d)", SILK_TEX_MAX_DIM,
                 width, height);
        return -1;
    }
    int levels = silk_texture_max_levels(width, height);
    size_t bytes = silk_texture_bytes(to->format, width, height, levels);
    uint8_t *p = malloc(bytes);
    if (!p) {
        snprintf(msg, msglen, "out of memory for a %dx%d texture", width, height);
        return -1;
    }
    t->pixels = p;
    t->palette = to->format == SILK_TEX_PAL8 ? palette : NULL;
    t->width = (uint16_t)width;
    t->height = (uint16_t)height;
    t->format = (uint8_t)to->format;
    t->levels = (uint8_t)levels;
    t->filter = (uint8_t)to->filter;
    t->wrap = (uint8_t)to->wrap;
    silk_texture_encode(t, p, rgb);
    silk_texture_build_mipmaps(t, p);
    *pixels = p;
    return 0;
}

/* The image's own colours when it has at most 256, else a fixed palette:
 * 6 levels of red and blue, 7 of green (the eye tells green apart best). */
static void make_palette(const uint8_t *rgb, size_t n, uint32_t pal[256])
{
    size_t k = 0;
    for (size_t i = 0; i < n && k <= 256; i++) {
        uint32_t c = (uint32_t)rgb[3 * i] << 16 | (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];
        size_t j = 0;
        while (j < k && j < 256 && pal[j] != c) j++;
        if (j == k) {
            if (k < 256) pal[k] = c;
            k++;
        }
    }
    if (k <= 256) {
        for (size_t j = k; j < 256; j++) pal[j] = pal[0];
        return;
    }
    for (int i = 0; i < 256; i++) {
        int r = i / 42 % 6, g = i / 6 % 7, b = i % 6;
        pal[i] = (uint32_t)(r * 51) << 16 | (uint32_t)(g * 255 / 6) << 8 | (uint32_t)(b * 51);
    }
}

/* Read an image (or draw the built-in checker) into mt's texture; 0, or -1
 * with msg filled. */
static int read_texture(cli_material *mt, const char *path, const cli_texture_opts *to, char *msg, size_t msglen)
{
    uint8_t *rgb = NULL;
    int w = 0, h = 0;
    silk_error err;
    size_t ck = strlen(CLI_CHECKER);
    if (strncmp(path, CLI_CHECKER, ck) == 0 && (path[ck] == '\0' || path[ck] == ':')) {
        long n = CLI_CHECKER_SIZE;
        char *end = NULL;
        if (path[ck] == ':') n = strtol(path + ck + 1, &end, 10);
        if (path[ck] == ':' && (end == path + ck + 1 || *end || n < 8 || n > SILK_TEX_MAX_DIM)) {
            snprintf(msg, msglen, "--texture %s: the checker's size must be 8 to %d", path, SILK_TEX_MAX_DIM);
            return -1;
        }
        w = h = (int)n;
        rgb = malloc((size_t)w * (size_t)h * 3);
        if (!rgb) {
            snprintf(msg, msglen, "out of memory for the checker texture");
            return -1;
        }
        gen_checker(rgb, w, 8);
    } else if (silk_image_read(path, 0, &rgb, &w, &h, &err) != SILK_OK) {
        snprintf(msg, msglen, "%s", err.msg);
        return -1;
    }
    if (to->format == SILK_TEX_PAL8) make_palette(rgb, (size_t)w * (size_t)h, mt->palette);
    int rc = cli_texture_from_rgb(rgb, w, h, to, mt->palette, &mt->texture, &mt->pixels, msg, msglen);
    free(rgb);
    if (rc == 0) mt->have_texture = 1;
    return rc;
}

/* The next line of [*p, end) as [b, e); 0 at the end. */
static int next_line(const char **p, const char *end, const char **b, const char **e)
{
    if (*p >= end) return 0;
    *b = *p;
    while (*p < end && **p != '\n' && **p != '\r') (*p)++;
    *e = *p;
    while (*p < end && (**p == '\n' || **p == '\r')) (*p)++;
    return 1;
}

/* Line [b, e) starts with keyword kw: *rest is what follows it, trimmed. */
static int keyword(const char *b, const char *e, const char *kw, char *rest, size_t n)
{
    while (b < e && isspace((unsigned char)*b)) b++;
    size_t k = strlen(kw);
    if ((size_t)(e - b) <= k || strncmp(b, kw, k) != 0 || !isspace((unsigned char)b[k])) return 0;
    b += k;
    while (b < e && isspace((unsigned char)*b)) b++;
    while (e > b && isspace((unsigned char)e[-1])) e--;
    size_t len = (size_t)(e - b) < n - 1 ? (size_t)(e - b) : n - 1;
    memcpy(rest, b, len);
    rest[len] = '\0';
    return 1;
}

/* dir of `base` (up to its last '/') joined with name; an absolute name as it is. */
static void beside(const char *base, const char *name, char *out, size_t n)
{
    const char *slash = base ? strrchr(base, '/') : NULL;
    if (name[0] == '/' || !slash) snprintf(out, n, "%s", name);
    else snprintf(out, n, "%.*s/%s", (int)(slash - base + 1), base, name);
}

static int read_file(const char *path, char **data, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    size_t cap = 1 << 16, n = 0;
    char *d = malloc(cap);
    while (d) {
        size_t r = fread(d + n, 1, cap - n, f);
        n += r;
        if (n < cap) break;
        char *g = realloc(d, cap * 2);
        if (!g) { free(d); d = NULL; break; }
        d = g;
        cap *= 2;
    }
    int bad = ferror(f) || !d;
    fclose(f);
    if (bad) { free(d); return -1; }
    *data = d;
    *len = n;
    return 0;
}

static void warn(int quiet, const char *fmt, const char *a, const char *b)
{
    if (quiet) return;
    fprintf(stderr, "silk: warning: ");
    fprintf(stderr, fmt, a, b);
    fprintf(stderr, "; rendering without it\n");
}

static int three(const char *s, double v[3])
{
    return sscanf(s, "%lf %lf %lf", &v[0], &v[1], &v[2]) == 3 ? 0 : -1;
}

/* The .mtl's material `want` (the first when want is empty). */
static void parse_mtl(cli_material *mt, const char *mtl_path, const char *data, size_t len, const char *want,
                      char *map, size_t mapn, int quiet)
{
    const char *p = data, *end = data + len, *b, *e;
    char rest[1024];
    int in = 0, found = 0;
    while (next_line(&p, end, &b, &e)) {
        if (keyword(b, e, "newmtl", rest, sizeof rest)) {
            if (found) break;
            in = want[0] == '\0' || strcmp(rest, want) == 0;
            found = in;
        } else if (!in) {
            continue;
        } else if (keyword(b, e, "Kd", rest, sizeof rest)) {
            mt->have_kd = three(rest, mt->kd) == 0;
        } else if (keyword(b, e, "Ks", rest, sizeof rest)) {
            mt->have_ks = three(rest, mt->ks) == 0;
        } else if (keyword(b, e, "Ns", rest, sizeof rest)) {
            mt->have_ns = sscanf(rest, "%lf", &mt->ns) == 1;
        } else if (keyword(b, e, "map_Kd", rest, sizeof rest)) {
            /* options (-o, -s, ...) come first; the file name is the last word */
            char *last = strrchr(rest, ' ');
            snprintf(map, mapn, "%s", last ? last + 1 : rest);
        }
    }
    if (!found) warn(quiet, "%s: no material '%s'", mtl_path, want);
}

int cli_material_load(cli_material *mt, const char *path, const uint8_t *file, size_t len, const silk_mesh *m,
                      const char *texture_path, const cli_texture_opts *to, int quiet)
{
    memset(mt, 0, sizeof *mt);
    char msg[600];
    const char *mesh_name = path && strcmp(path, "-") != 0 ? path : NULL;
    if (texture_path) {
        if (!m->uv)
            return cli_fail(CLI_EXIT_USAGE, "--texture: %s has no texture coordinates",
                            mesh_name ? mesh_name : SILK_STDIN_NAME);
        if (read_texture(mt, texture_path, to, msg, sizeof msg) != 0) return cli_fail(CLI_EXIT_INPUT, "%s", msg);
    }
    /* an OBJ file's material: mtllib and the first usemtl */
    char lib[1024] = "", use[1024] = "", rest[1024];
    if (file && !(len >= 3 && memcmp(file, "ply", 3) == 0)) {
        const char *p = (const char *)file, *end = p + len, *b, *e;
        while (next_line(&p, end, &b, &e) && (!lib[0] || !use[0])) {
            if (!lib[0] && keyword(b, e, "mtllib", rest, sizeof rest)) snprintf(lib, sizeof lib, "%s", rest);
            else if (!use[0] && keyword(b, e, "usemtl", rest, sizeof rest)) snprintf(use, sizeof use, "%s", rest);
        }
    }
    if (!lib[0]) return 0;
    char mtl_path[2100], map[1024] = "";
    beside(mesh_name, lib, mtl_path, sizeof mtl_path);
    char *data;
    size_t dlen;
    if (read_file(mtl_path, &data, &dlen) != 0) {
        warn(quiet, "%s: cannot read the material file%s", mtl_path, "");
        return 0;
    }
    parse_mtl(mt, mtl_path, data, dlen, use, map, sizeof map, quiet);
    free(data);
    if (map[0] && !mt->have_texture) {
        char tex_path[2100];
        beside(mtl_path, map, tex_path, sizeof tex_path);
        if (!m->uv) warn(quiet, "%s: the mesh has no texture coordinates for %s", mesh_name ? mesh_name : SILK_STDIN_NAME, map);
        else if (read_texture(mt, tex_path, to, msg, sizeof msg) != 0) warn(quiet, "%s%s", msg, "");
    }
    return 0;
}

static silk_fx unit(double v) { return cli_fx_from_double(v < 0 ? 0 : (v > 1 ? 1 : v)); }

void cli_material_apply(const cli_material *mt, const silk_mesh *m, int have_color, int have_specular,
                        int have_shininess, silk_phong *p)
{
    /* a texture or vertex colours show their own colours unless told otherwise */
    if (!have_color && (mt->have_texture || m->color)) p->mat.color = silk_v3(SILK_FX_ONE, SILK_FX_ONE, SILK_FX_ONE);
    if (!have_color && mt->have_kd) p->mat.color = silk_v3(unit(mt->kd[0]), unit(mt->kd[1]), unit(mt->kd[2]));
    if (!have_specular && mt->have_ks) {
        double s = mt->ks[0] > mt->ks[1] ? mt->ks[0] : mt->ks[1];
        s = s > mt->ks[2] ? s : mt->ks[2];
        p->mat.specular = unit(s);
        if (s > 0) p->mat.specular_color = silk_v3(unit(mt->ks[0] / s), unit(mt->ks[1] / s), unit(mt->ks[2] / s));
    }
    if (!have_shininess && mt->have_ns) p->mat.shininess = mt->ns < 1 ? 1 : (mt->ns > 256 ? 256 : (int)(mt->ns + 0.5));
    p->texture = mt->have_texture ? &mt->texture : NULL;
    p->vertex_colors = m->color != NULL;
}

void cli_material_free(cli_material *mt)
{
    free(mt->pixels);
    memset(mt, 0, sizeof *mt);
}
