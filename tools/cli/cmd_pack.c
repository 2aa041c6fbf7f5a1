/*
 * cmd_pack.c - `silk pack MESH -o model.h`: the loaded mesh as a C header,
 * for a device that renders a model from flash.
 *
 * Everything silk_load_mesh() and silk_vis_build() compute at load time is
 * written out as `const` arrays of exact integers (Q16.16 for coordinates):
 * positions, normals, normal_vertex, triangles, tri_normal, edges, the
 * vertex->edge CSR, feature segments and the visibility hierarchy; not
 * tri_edge, which the renderer finds from the vertex-edge lists (2 index
 * bytes a corner less in flash, silk_mesh_tri_edge), nor edge_feature,
 * which it counts for the few feature edges a frame uses
 * (silk_mesh_edge_feature).  The
 * header's NAME_mesh() points a silk_mesh at them, so the device does no
 * loading at all and keeps none of it in RAM; the pointers cast const away
 * because silk_mesh is shared with the loaders, but the renderer only reads.
 *
 * The cameras of the scene options (one per --eye, --views N around the
 * model, or the default framing) are written too, computed exactly as
 * `silk render` computes them for the same options, and each camera's
 * comment gives the --eye that makes `silk render` use it: a device
 * rendering camera k with the packed mesh must produce the bytes
 * `silk render` writes (tests/boards/cli_qemu.sh checks it).
 *
 * Indices are written as silk_index (32 bits in every build) and
 * SILK_NO_INDEX, so the header compiles with any of the core's options.
 *
 * That is the full form (--model-format full).  The default is the compact
 * model of silk/compact.h (tools/prep/compact_enc.c): the mesh as one byte
 * array of bit fields, about a fifth of the full form's arrays, that
 * NAME_mesh() hands to silk_compact_mesh() to be read in place; --flat
 * leaves out its corner table and edges (flat frames only).  A mesh the
 * compact model cannot hold (texture coordinates, vertex colours, a
 * non-manifold edge ...) is written in the full form, with a line on
 * stderr saying why.  -o FILE.slkc writes the compact bytes themselves.
 * Either form's NAME_mesh() returns a silk_status, so callers check both
 * alike.
 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "platform/platform.h"
#include "prep/compact_enc.h"
#include "silk/compact.h"

#define PACK_MAX_EYES 16
/* pack renders nothing: mode and look options would change nothing; the
 * texture goes into the header. */
#define PACK_OPTIONS (CLI_OPT_LOAD | CLI_OPT_CAMERA | CLI_OPT_FRAME | CLI_OPT_TEXTURE)

enum { PACK_COMPACT, PACK_FULL };

typedef struct pack_args {
    const char *out, *name;
    int views;                 /* 0: --eye or the default view */
    int neyes;
    double eyes[PACK_MAX_EYES][3];
    int model_format;          /* PACK_COMPACT or PACK_FULL */
    int flat;                  /* compact without the corner table: flat frames only */
    int pos_bits, nrm_bits;    /* the compact model's widths; 0: compact_opts_default's */
} pack_args;

/* Each --eye is one camera (the scene option keeps only the last). */
static int parse_eye(const cli_opt *o, const char *v, void *base)
{
    pack_args *p = base;
    if (p->neyes == PACK_MAX_EYES) return cli_fail(-1, "pack: at most %d --eye options", PACK_MAX_EYES);
    return cli_parse_vec3(o->name, v, CLI_MAX_COORD, p->eyes[p->neyes++]);
}

static int parse_name(const cli_opt *o, const char *v, void *base);
static const int model_format_v[] = { PACK_COMPACT, PACK_FULL };

#define XSTR(x) STR(x)
#define STR(x) #x
static const cli_opt pack_rows[] = {
    { .name = "--output", .alt = "-o", .group = "", .kind = CLI_OUTPUT, .meta = "FILE",
      CLI_FIELD(pack_args, out),
      .help = "the header to write (atomically), or a FILE ending in .slkc: the compact model's bytes alone; - "
              "writes the header to standard output" },
    { .name = "--name", .kind = CLI_TEXT, .meta = "NAME", CLI_FIELD(pack_args, name), .parse = parse_name,
      .help = "prefix of every symbol (default: FILE's base name, or MESH's with -o -, or \"model\" when both are "
              "-)" },
    { .name = "--eye", .kind = CLI_CUSTOM, .meta = "x,y,z", .parse = parse_eye,
      .help = "a camera at x,y,z (repeat for up to " XSTR(PACK_MAX_EYES) " views)" },
    { .name = "--views", .kind = CLI_INT, .meta = "N", .lo = 1, .hi = PACK_MAX_EYES, CLI_FIELD(pack_args, views),
      .help = "N cameras around the model (%R): the default view turned by k*360/N degrees about the vertical "
              "through the target, odd k mirrored to look from below" },
    { .name = "--model-format", .kind = CLI_CHOICE, .choices = "compact|full", .values = model_format_v,
      CLI_FIELD(pack_args, model_format),
      .help = "compact: the mesh as one array of bit fields read in place (silk/compact.h; the default, "
              "when the mesh allows it); full: every array of the loaded mesh, the visibility hierarchy too" },
    { .name = "--flat", .kind = CLI_FLAG, CLI_FIELD(pack_args, flat),
      .help = "the compact model without its corner table, edges and feature segments: smaller, for flat "
              "frames only" },
    { .name = "--position-bits", .kind = CLI_INT, .meta = "N", .lo = 8, .hi = 16, CLI_FIELD(pack_args, pos_bits),
      .help = "bits of each quantized coordinate of the compact model (%R; default 12: docs/formats.md)" },
    { .name = "--normal-bits", .kind = CLI_INT, .meta = "N", .lo = 6, .hi = 16, CLI_FIELD(pack_args, nrm_bits),
      .help = "bits of each octahedral coordinate of a normal of the compact model (%R; default 10)" },
    { .name = NULL },
};

const cli_command cmd_pack_spec = {
    .name = "pack",
    .usage = "usage: silk pack MESH -o MODEL.h [--name NAME] [--eye x,y,z]... [options]\n"
             "       silk pack MESH -o MODEL.slkc [--flat] [options]\n",
    .about =
        "Write MESH, loaded and with everything precomputed (normals, edges, feature\n"
        "segments), as a C header that a device renders from flash: NAME_mesh(&mesh)\n"
        "fills a silk_mesh reading it in place and returns SILK_OK (or an error for\n"
        "damaged data).  By default the header holds the compact model (silk/compact.h):\n"
        "one const byte array NAME_model of quantized positions (12 bits a coordinate),\n"
        "octahedral normals, corners and a corner table, about a seventh of the full\n"
        "arrays; --flat leaves out the corner table and edges (flat frames only).\n"
        "A mesh the compact model cannot hold (texture coordinates, vertex colours,\n"
        "non-manifold edges or vertices, a repeated corner) is written in the full\n"
        "form, with one line on stderr saying why; --model-format full always writes\n"
        "it: the loaded mesh's own arrays and its visibility hierarchy.  -o FILE.slkc\n"
        "writes the compact model's bytes alone, for a device that reads them from\n"
        "storage.\n"
        "The header also holds the cameras NAME_camera(k) that `silk render` would\n"
        "use with the same options: one per --eye, N of --views, or the default view;\n"
        "each camera's comment names the --eye that gives `silk render` the same view.\n"
        "--texture packs the texture, as `silk render --texture` takes it, with its\n"
        "mipmaps; NAME_look(&phong) sets it, the OBJ material and the vertex colours\n"
        "as `silk render` does.\n",
    .examples =
        "  silk pack bunny-500.obj -o bunny.h\n"
        "  silk pack bunny-500.obj -o bunny.slkc --flat\n"
        "  silk pack bunny-500.obj -o bunny.h --model-format full\n"
        "  silk pack bunny-500.obj -o bunny.h --size 320x240 --eye 0,0,3 --eye 3,1,0\n"
        "  silk pack knot-480.obj -o knot.h --size 320x240 --format rgb565 --views 3\n"
        "  silk gen sphere -o - | silk pack - -o - --name sphere > sphere.h\n"
        "  silk gen sphere --uv -o globe.obj && silk pack globe.obj --texture checker:64 -o globe.h\n",
    .sets = { { pack_rows, 0, sizeof(pack_args), NULL, NULL }, CLI_SCENE_SET(PACK_OPTIONS) },
    .nsets = 2,
};

/* ---- C text ------------------------------------------------------------------- */

typedef struct writer {
    FILE *fp;
    const char *name;          /* symbol prefix */
    int col;                   /* characters on the current line */
    size_t bytes[16];          /* data bytes per kind, for the summary */
} writer;

enum { K_POS, K_NORMAL, K_UV, K_COLOR, K_TRI, K_EDGE, K_VERT_EDGE, K_FEATURE, K_VIS, K_TEXTURE, K_COUNT };
static const char *const kind_name[K_COUNT] = { "positions", "normals",      "uvs",      "colours",
                                                "triangles", "edges",        "vertex edges", "features",
                                                "visibility", "texture" };

/* Items are filled into lines of at most 100 characters. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void item(writer *w, const char *fmt, ...)
{
    char buf[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    int n = (int)strlen(buf) + 1;
    if (w->col == 0 || w->col + 1 + n > 100) {
        fputs("\n   ", w->fp);
        w->col = 3;
    }
    fprintf(w->fp, " %s,", buf);
    w->col += 1 + n;
}

static void array_open(writer *w, const char *type, const char *field, size_t n, int kind, size_t elem)
{
    fprintf(w->fp, "static const %s %s_%s[%zu] = {", type, w->name, field, n ? n : 1);
    w->col = 0;
    w->bytes[kind] += n * elem;
}

static void array_close(writer *w, size_t n)
{
    /* C has no empty arrays (nor, before C23, empty initializers); the count
     * says 0.  C++ takes the empty one, without a warning. */
    if (n == 0) fputs("\n#ifndef __cplusplus\n    0\n#endif", w->fp);
    fputs("\n};\n\n", w->fp);
}

static void index_text(char *buf, size_t n, silk_index v)
{
    if (v == SILK_NO_INDEX) snprintf(buf, n, "SILK_NO_INDEX");
    else snprintf(buf, n, "%lu", (unsigned long)v);
}

static void put_index_array(writer *w, const char *field, const silk_index *v, size_t n, int kind)
{
    array_open(w, "silk_index", field, n, kind, sizeof(silk_index));
    char b[24];
    for (size_t i = 0; i < n; i++) {
        index_text(b, sizeof b, v[i]);
        item(w, "%s", b);
    }
    array_close(w, n);
}

static void put_u32_array(writer *w, const char *field, const uint32_t *v, size_t n, int kind)
{
    array_open(w, "uint32_t", field, n, kind, sizeof(uint32_t));
    for (size_t i = 0; i < n; i++) item(w, "%lu", (unsigned long)v[i]);
    array_close(w, n);
}

static void put_vec3_array(writer *w, const char *field, const silk_vec3 *v, size_t n, int kind)
{
    array_open(w, "silk_vec3", field, n, kind, sizeof(silk_vec3));
    for (size_t i = 0; i < n; i++) item(w, "{%ld, %ld, %ld}", (long)v[i].x, (long)v[i].y, (long)v[i].z);
    array_close(w, n);
}

static void put_vec2_array(writer *w, const char *field, const silk_vec2 *v, size_t n, int kind)
{
    array_open(w, "silk_vec2", field, n, kind, sizeof(silk_vec2));
    for (size_t i = 0; i < n; i++) item(w, "{%ld, %ld}", (long)v[i].x, (long)v[i].y);
    array_close(w, n);
}

static void put_edges(writer *w, const silk_edge *e, size_t n)
{
    array_open(w, "silk_edge", "edge", n, K_EDGE, sizeof(silk_edge));
    char a[4][24];
    for (size_t i = 0; i < n; i++) {
        index_text(a[0], sizeof a[0], e[i].v[0]);
        index_text(a[1], sizeof a[1], e[i].v[1]);
        index_text(a[2], sizeof a[2], e[i].t[0]);
        index_text(a[3], sizeof a[3], e[i].t[1]);
        item(w, "{{%s, %s}, {%s, %s}, %lu}", a[0], a[1], a[2], a[3], (unsigned long)e[i].flags);
    }
    array_close(w, n);
}

static void put_features(writer *w, const silk_feature_seg *f, size_t n)
{
    array_open(w, "silk_feature_seg", "feature", n, K_FEATURE, sizeof(silk_feature_seg));
    for (size_t i = 0; i < n; i++)
        item(w, "{{%ld, %ld, %ld}, {%ld, %ld, %ld}}", (long)f[i].t0.x, (long)f[i].t0.y, (long)f[i].t0.z,
             (long)f[i].t1.x, (long)f[i].t1.y, (long)f[i].t1.z);
    array_close(w, n);
}

static void put_vis(writer *w, const silk_vis *v)
{
    array_open(w, "silk_vis_node", "vis_node", v->nnodes, K_VIS, sizeof(silk_vis_node));
    for (uint32_t i = 0; i < v->nnodes; i++) {
        const silk_vis_node *n = &v->node[i];
        item(w, "{{%d, %d, %d}, %u, %d, %d, %lu, %lu}", n->c[0], n->c[1], n->c[2], (unsigned)n->r, n->w0, n->w1,
             (unsigned long)n->first, (unsigned long)n->skip);
    }
    array_close(w, v->nnodes);
    w->bytes[K_VIS] += sizeof(silk_vis);
    fprintf(w->fp,
            "static const silk_vis %s_vis = {\n"
            "    .nnodes = %lu, .nnormals = %lu, .depth = %lu, .leaf_max = %lu,\n"
            "    .centre = {%ld, %ld, %ld}, .scale_log2 = %ld, .widened = %lu, .node = %s_vis_node\n"
            "};\n\n",
            w->name, (unsigned long)v->nnodes, (unsigned long)v->nnormals, (unsigned long)v->depth,
            (unsigned long)v->leaf_max, (long)v->centre.x, (long)v->centre.y, (long)v->centre.z,
            (long)v->scale_log2, (unsigned long)v->widened, w->name);
}

static void put_cameras(writer *w, const silk_camera *c, int n)
{
    fprintf(w->fp, "/* The cameras of `silk pack` (what `silk render` uses with the same options). */\n");
    fprintf(w->fp, "static const silk_camera %s_cameras[%d] = {\n", w->name, n);
    for (int i = 0; i < n; i++)
        fprintf(w->fp,
                "    /* camera %d: --eye %.17g,%.17g,%.17g */\n"
                "    { .eye = {%ld, %ld, %ld}, .target = {%ld, %ld, %ld}, .up = {%ld, %ld, %ld},\n"
                "      .ortho = %d, .fov_deg = %ld, .ortho_half_height = %ld, .znear = %ld, .zfar = %ld,\n"
                "      .width = %d, .height = %d },\n",
                i, cli_fx_to_double(c[i].eye.x), cli_fx_to_double(c[i].eye.y), cli_fx_to_double(c[i].eye.z),
                (long)c[i].eye.x, (long)c[i].eye.y, (long)c[i].eye.z, (long)c[i].target.x, (long)c[i].target.y,
                (long)c[i].target.z, (long)c[i].up.x, (long)c[i].up.y, (long)c[i].up.z, c[i].ortho,
                (long)c[i].fov_deg, (long)c[i].ortho_half_height, (long)c[i].znear, (long)c[i].zfar, c[i].width,
                c[i].height);
    fprintf(w->fp, "};\n\n");
}

static void put_texture(writer *w, const silk_texture *t)
{
    size_t n = silk_texture_bytes((silk_texfmt)t->format, t->width, t->height, t->levels);
    array_open(w, "uint8_t", "texels", n, K_TEXTURE, 1);
    for (size_t i = 0; i < n; i++) item(w, "%u", (unsigned)t->pixels[i]);
    array_close(w, n);
    if (t->palette) put_u32_array(w, "palette", t->palette, 256, K_TEXTURE);
    w->bytes[K_TEXTURE] += sizeof(silk_texture);
    fprintf(w->fp,
            "static const silk_texture %s_texture = {\n"
            "    %s_texels, %s%s, %u, %u, %u, %u, %u, %u\n"
            "};\n\n",
            w->name, w->name, t->palette ? w->name : "NULL", t->palette ? "_palette" : "", (unsigned)t->width, (unsigned)t->height, (unsigned)t->format, (unsigned)t->levels,
            (unsigned)t->filter, (unsigned)t->wrap);
}

/* NAME_look: the material, texture and vertex colours `silk render` applies
 * over silk_phong_default (cli_scene_phong), for the same pixels. */
static void put_look(writer *w, const cli_scene *s)
{
    silk_phong p;
    silk_phong_default(&p, NULL);
    cli_material_apply(&s->material, &s->mesh, 0, 0, 0, &p);
    const silk_material *m = &p.mat;
    fprintf(w->fp,
            "/* The look `silk render` gives the model over silk_phong_default: its material,\n"
            " * texture and vertex colours.  Call it after silk_phong_default and before\n"
            " * silk_hal_phong. */\n"
            "static inline void %s_look(silk_phong *p)\n{\n"
            "    p->mat.color = silk_v3(%ld, %ld, %ld);\n"
            "    p->mat.specular = %ld;\n"
            "    p->mat.specular_color = silk_v3(%ld, %ld, %ld);\n"
            "    p->mat.shininess = %d;\n"
            "    p->texture = %s%s%s;\n"
            "    p->vertex_colors = %d;\n}\n\n",
            w->name, (long)m->color.x, (long)m->color.y, (long)m->color.z, (long)m->specular,
            (long)m->specular_color.x, (long)m->specular_color.y, (long)m->specular_color.z, m->shininess,
            p.texture ? "&" : "NULL", p.texture ? w->name : "", p.texture ? "_texture" : "", p.vertex_colors);
}

static void put_camera_fn(writer *w)
{
    const char *n = w->name;
    fprintf(w->fp,
            "/* Camera k of %s_NCAMERAS, or NULL. */\n"
            "static inline const silk_camera *%s_camera(int k)\n{\n"
            "    return k >= 0 && k < %s_NCAMERAS ? &%s_cameras[k] : NULL;\n}\n\n",
            n, n, n, n);
}

static void put_mesh_fn(writer *w, const silk_mesh *m)
{
    const char *n = w->name;
    FILE *f = w->fp;
    /* a silk_status, as the compact form's: callers check either alike */
    fprintf(f,
            "/* Point *m at the arrays above; nothing is copied.  The renderer only reads\n"
            " * a mesh, so the casts that drop const are safe.  Returns SILK_OK (the\n"
            " * compact form's NAME_mesh checks its bytes and may fail). */\n"
            "static inline silk_status %s_mesh(silk_mesh *m)\n{\n"
            "    memset(m, 0, sizeof *m);\n",
            n);
    fprintf(f, "    m->nverts = %lu;\n    m->ntris = %lu;\n    m->nnormals = %lu;\n    m->nuvs = %lu;\n",
            (unsigned long)m->nverts, (unsigned long)m->ntris, (unsigned long)m->nnormals, (unsigned long)m->nuvs);
    fprintf(f, "    m->nedges = %lu;\n    m->nfeature_edges = %lu;\n    m->nboundary_edges = %lu;\n",
            (unsigned long)m->nedges, (unsigned long)m->nfeature_edges, (unsigned long)m->nboundary_edges);
    fprintf(f, "    m->nnonmanifold_edges = %lu;\n    m->ndegenerate_tris = %lu;\n",
            (unsigned long)m->nnonmanifold_edges, (unsigned long)m->ndegenerate_tris);
    /* where the normals came from: the smooth outline trusts a file's (curve.h, the tilt bound) */
    if (m->normals_used == SILK_NORMALS_FILE) fprintf(f, "    m->normals_used = SILK_NORMALS_FILE;\n");
    fprintf(f, "    m->pos = (silk_vec3 *)%s_pos;\n", n);
    fprintf(f, "    m->normal = (silk_vec3 *)%s_normal;\n", n);
    fprintf(f, "    m->normal_vertex = (silk_index *)%s_normal_vertex;\n", n);
    if (m->uv) fprintf(f, "    m->uv = (silk_vec2 *)%s_uv;\n    m->tri_uv = (silk_index *)%s_tri_uv;\n", n, n);
    if (m->color) fprintf(f, "    m->color = (uint32_t *)%s_color;\n", n);
    fprintf(f, "    m->tri = (silk_index *)%s_tri;\n", n);
    fprintf(f, "    m->tri_normal = (silk_index *)%s_tri_normal;\n", n);
    fprintf(f, "    m->tri_edge = NULL;   /* found from the vertex-edge lists (silk_mesh_tri_edge) */\n");
    fprintf(f, "    m->edge = (silk_edge *)%s_edge;\n", n);
    fprintf(f, "    m->vert_edge_start = (silk_index *)%s_vert_edge_start;\n", n);
    fprintf(f, "    m->vert_edge = (silk_index *)%s_vert_edge;\n", n);
    fprintf(f, "    m->edge_feature = NULL;   /* counted along the edges (silk_mesh_edge_feature) */\n");
    fprintf(f, "    m->feature = (silk_feature_seg *)%s_feature;\n", n);
    if (m->vis) fprintf(f, "    m->vis = &%s_vis;\n", n);
    /* closed and wound outward (orient.c): back faces may be culled */
    if (m->closed_outward) fprintf(f, "    m->closed_outward = 1;\n");
    fprintf(f, "    m->bbox_min = silk_v3(%ld, %ld, %ld);\n", (long)m->bbox_min.x, (long)m->bbox_min.y,
            (long)m->bbox_min.z);
    fprintf(f, "    m->bbox_max = silk_v3(%ld, %ld, %ld);\n    return SILK_OK;\n}\n\n", (long)m->bbox_max.x,
            (long)m->bbox_max.y, (long)m->bbox_max.z);
    put_camera_fn(w);
}

static int write_header(writer *w, const char *mesh_path, const char *texture, const cli_scene *s,
                        const silk_camera *cams, int ncams)
{
    const silk_mesh *m = &s->mesh;
    FILE *f = w->fp;
    size_t corners = 3 * (size_t)m->ntris;
    fprintf(f,
            "/*\n"
            " * %s - generated by `silk pack %s` (silk %s); do not edit.\n"
            " *\n"
            " * The mesh with everything silk computes at load time, as const arrays\n"
            " * for flash: %s_mesh(&m) makes a silk_mesh of them, %s_camera(k) gives\n"
            " * the packed views, %s_look(&phong) the material.  Coordinates are Q16.16.\n"
            " * Check the arrays once before the first frame, silk_mesh_validate(&m,\n"
            " * \"%s\", &err) (silk/validate.h, included here), so that a damaged header\n"
            " * is an error, not a wild read.\n"
            "%s%s%s"
            " */\n",
            w->name, mesh_path, SILK_VERSION, w->name, w->name, w->name, w->name, texture ? " * texture: `" : "",
            texture ? texture : "", texture ? "`\n" : "");
    fprintf(f,
            "#ifndef SILK_PACK_%s_H\n#define SILK_PACK_%s_H\n\n#include <string.h>\n#include \"silk/silk.h\"\n"
            "#include \"silk/validate.h\"\n\n",
            w->name, w->name);
    fprintf(f, "#define %s_NCAMERAS %d\n\n", w->name, ncams);

    put_vec3_array(w, "pos", m->pos, m->nverts, K_POS);
    put_vec3_array(w, "normal", m->normal, m->nnormals, K_NORMAL);
    put_index_array(w, "normal_vertex", m->normal_vertex, m->nnormals, K_NORMAL);
    if (m->uv) {
        put_vec2_array(w, "uv", m->uv, m->nuvs, K_UV);
        put_index_array(w, "tri_uv", m->tri_uv, corners, K_UV);
    }
    if (m->color) put_u32_array(w, "color", m->color, m->nverts, K_COLOR);
    if (s->material.have_texture) put_texture(w, &s->material.texture);
    put_index_array(w, "tri", m->tri, corners, K_TRI);
    put_index_array(w, "tri_normal", m->tri_normal, corners, K_NORMAL);
    put_edges(w, m->edge, m->nedges);
    put_index_array(w, "vert_edge_start", m->vert_edge_start, (size_t)m->nverts + 1, K_VERT_EDGE);
    put_index_array(w, "vert_edge", m->vert_edge, m->vert_edge_start[m->nverts], K_VERT_EDGE);
    put_features(w, m->feature, m->nfeature_edges);
    if (m->vis) put_vis(w, m->vis);
    put_cameras(w, cams, ncams);
    put_mesh_fn(w, m);
    put_look(w, s);
    fprintf(f, "#endif\n");
    return ferror(f) ? -1 : 0;
}

/* ---- the compact form --------------------------------------------------------- */

/* The model's bytes, counted apart from the other kinds (the summary
 * breaks them down by array). */
static void put_model_bytes(writer *w, const uint8_t *b, size_t n)
{
    fprintf(w->fp, "static const uint8_t %s_model[%zu] = {", w->name, n);
    w->col = 0;
    for (size_t i = 0; i < n; i++) item(w, "%u", (unsigned)b[i]);
    fputs("\n};\n\n", w->fp);
}

static int write_compact_header(writer *w, const char *mesh_path, const char *texture, const cli_scene *s,
                                const silk_camera *cams, int ncams, const uint8_t *model, size_t len, int flat)
{
    FILE *f = w->fp;
    const char *n = w->name;
    fprintf(f,
            "/*\n"
            " * %s - generated by `silk pack %s` (silk %s); do not edit.\n"
            " *\n"
            " * The mesh as a compact model (silk/compact.h) for flash%s: %s_mesh(&m)\n"
            " * checks the bytes of %s_model and makes a silk_mesh that reads them in\n"
            " * place (SILK_OK, or SILK_ERR_PARSE when they are damaged); %s_camera(k)\n"
            " * gives the packed views, %s_look(&phong) the material.\n"
            "%s%s%s"
            " */\n",
            n, mesh_path, SILK_VERSION, flat ? ", flat frames only" : "", n, n, n, n, texture ? " * texture: `" : "",
            texture ? texture : "", texture ? "`\n" : "");
    /* validate.h as in the full form: callers that check a mesh either way compile */
    fprintf(f,
            "#ifndef SILK_PACK_%s_H\n#define SILK_PACK_%s_H\n\n#include \"silk/silk.h\"\n#include \"silk/compact.h\"\n"
            "#include \"silk/validate.h\"\n\n",
            n, n);
    fprintf(f, "#define %s_NCAMERAS %d\n\n", n, ncams);
    put_model_bytes(w, model, len);
    if (s->material.have_texture) put_texture(w, &s->material.texture);
    put_cameras(w, cams, ncams);
    fprintf(f,
            "/* Check %s_model and point *m at it; nothing is copied. */\n"
            "static inline silk_status %s_mesh(silk_mesh *m)\n{\n"
            "    return silk_compact_mesh(%s_model, sizeof %s_model, \"%s\", m, NULL);\n}\n\n",
            n, n, n, n, n);
    put_camera_fn(w);
    put_look(w, s);
    fprintf(f, "#endif\n");
    return ferror(f) ? -1 : 0;
}

/* "compact model N bytes, B a triangle (positions ..., header and end H)". */
static void compact_summary(FILE *f, const uint8_t *model, size_t len)
{
    compact_layout l;
    if (compact_layout_read(model, len, &l) != 0) return;
    const size_t *b = l.bytes;
    fprintf(f,
            "compact model %zu, %.2f a triangle (positions %zu, normals %zu, corners %zu, selectors %zu, "
            "adjacency %zu, edges list %zu, vertex index %zu, header %zu)",
            len, (double)len / l.ntris, b[COMPACT_POS], b[COMPACT_NRM] + b[COMPACT_EXTRA] + b[COMPACT_XPRE], b[COMPACT_CORNER],
            b[COMPACT_SEL], b[COMPACT_OPP], b[COMPACT_LIST], b[COMPACT_VFIRST],
            (size_t)SILK_COMPACT_HEADER_BYTES + 4);
}

static int has_suffix(const char *s, const char *suf)
{
    size_t n = strlen(s), k = strlen(suf);
    return n >= k && strcmp(s + n - k, suf) == 0;
}

/* The compact bytes of s's mesh into *model, or NULL (and why) when it
 * cannot be compact. */
static void encode_compact(const cli_scene *s, const pack_args *pa, uint8_t **model, size_t *len, char *why,
                           size_t n)
{
    compact_opts co = compact_opts_default();
    co.adjacency = !pa->flat;
    if (pa->pos_bits) co.pos_bits = pa->pos_bits;
    if (pa->nrm_bits) co.nrm_bits = pa->nrm_bits;
    if (compact_encode(&s->mesh, &co, model, len, why, n) != 0) *model = NULL;
}

/* A C identifier from the base name of path, without its extension. */
static void name_from_path(const char *path, char *out, size_t n)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    size_t k = 0;
    if (isdigit((unsigned char)*b) && k + 1 < n) out[k++] = 'm';
    for (; *b && *b != '.' && k + 1 < n; b++) out[k++] = isalnum((unsigned char)*b) ? *b : '_';
    out[k] = 0;
    if (k == 0) snprintf(out, n, "model");
}

static int valid_name(const char *s)
{
    if (!*s || isdigit((unsigned char)*s) || strlen(s) > 40) return 0;
    for (; *s; s++)
        if (!isalnum((unsigned char)*s) && *s != '_') return 0;
    return 1;
}

/* --views: the default eye turned about the vertical through the target.
 * Each eye is rounded to Q16.16 first, so that --eye with its exact decimal
 * gives `silk render` the very same camera (znear and zfar included). */
static int orbit_eyes(const cli_scene_opts *o, const silk_mesh *m, int n, double eyes[][3])
{
    silk_camera c0;
    int rc = cli_camera(o, m, NULL, &c0);
    if (rc) return rc;
    double t[3] = { cli_fx_to_double(c0.target.x), cli_fx_to_double(c0.target.y), cli_fx_to_double(c0.target.z) };
    double d[3] = { cli_fx_to_double(c0.eye.x) - t[0], cli_fx_to_double(c0.eye.y) - t[1],
                    cli_fx_to_double(c0.eye.z) - t[2] };
    for (int k = 0; k < n; k++) {
        double a = 2 * CLI_PI * k / n, ca = cos(a), sa = sin(a);
        double e[3] = { t[0] + d[0] * ca + d[2] * sa, t[1] + (k % 2 ? -d[1] : d[1]), t[2] - d[0] * sa + d[2] * ca };
        for (int i = 0; i < 3; i++) {
            if (fabs(e[i]) > CLI_MAX_COORD)
                return cli_fail(CLI_EXIT_USAGE, "pack: view %d would put the eye beyond +-%g", k, CLI_MAX_COORD);
            eyes[k][i] = cli_fx_to_double(cli_fx_from_double(e[i]));
        }
    }
    return 0;
}

static int parse_name(const cli_opt *o, const char *v, void *base)
{
    (void)o;
    if (!valid_name(v))
        return cli_fail(-1, "pack: --name must be a C identifier of at most 40 characters (got \"%s\")", v);
    ((pack_args *)base)->name = v;
    return 0;
}

int cmd_pack(int argc, char **argv)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    pack_args pa;
    memset(&pa, 0, sizeof pa);
    cli_args args;
    void *bases[] = { &pa, &o };
    int rc = cli_parse(&cmd_pack_spec, bases, argc, argv, &args);
    if (!rc) rc = cli_one_mesh("pack", args.npos, args.pos, "silk pack MESH -o MODEL.h", &o.mesh_path);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    const char *out = pa.out, *name_opt = pa.name;
    double (*eyes)[3] = pa.eyes;
    int neyes = pa.neyes, nviews = pa.views;
    if (!rc && !out) rc = cli_fail(CLI_EXIT_USAGE, "pack: no output given (-o MODEL.h)");
    if (!rc && neyes && nviews) rc = cli_fail(CLI_EXIT_USAGE, "pack: give --eye or --views, not both");
    int full = pa.model_format == PACK_FULL, raw = !rc && has_suffix(out, ".slkc");
    if (!rc && full && pa.flat)
        rc = cli_fail(CLI_EXIT_USAGE, "pack: --flat is for the compact model, not --model-format full");
    if (!rc && full && raw)
        rc = cli_fail(CLI_EXIT_USAGE, "pack: -o %s writes the compact model, not --model-format full", out);
    if (!rc && raw && o.look.texture_path)
        rc = cli_fail(CLI_EXIT_USAGE, "pack: -o %s holds the mesh alone: --texture needs a header (-o MODEL.h)", out);
    /* A failed run leaves OUT as it was (written atomically). */
    if (rc) return rc;

    cli_scene s;
    rc = cli_scene_load(&s, &o);
    if (!rc && s.mesh.packed.base)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: already a compact model; pack the mesh it was made from", o.mesh_path);
    if (rc) {
        cli_scene_free(&s);
        return rc;
    }
    char name[48];
    if (name_opt) snprintf(name, sizeof name, "%s", name_opt);
    else if (!silk_path_is_stdio(out)) name_from_path(out, name, sizeof name);
    else if (!silk_path_is_stdio(o.mesh_path)) name_from_path(o.mesh_path, name, sizeof name);
    else snprintf(name, sizeof name, "model");

    /* compact unless told otherwise or the mesh cannot be (then full, saying why) */
    uint8_t *model = NULL;
    size_t model_len = 0;
    if (!full) {
        char why[320];
        encode_compact(&s, &pa, &model, &model_len, why, sizeof why);
        if (!model && raw) {
            cli_scene_free(&s);
            return cli_fail(CLI_EXIT_INPUT, "pack: %s: the compact model needs %s", cli_input_name(o.mesh_path), why);
        }
        if (!model) fprintf(stderr, "silk pack: %s: full format (compact needs %s)\n", name, why);
    }
    /* The cameras frame what the device draws, as `silk render` frames the
     * compact model itself (-o .slkc): its quantized box, not the mesh's. */
    silk_mesh loaded = s.mesh;
    if (model) {
        silk_error cerr;
        if (silk_compact_mesh(model, model_len, name, &s.mesh, &cerr) != SILK_OK) {
            free(model);
            cli_scene_free(&s);
            return cli_fail(CLI_EXIT_INPUT, "pack: %s", cerr.msg);
        }
    }
    silk_camera cams[PACK_MAX_EYES];
    int ncams = neyes ? neyes : nviews ? nviews : 1;
    if (!rc && nviews) rc = orbit_eyes(&o, &s.mesh, nviews, eyes);
    for (int k = 0; !rc && k < ncams; k++) {
        if (neyes || nviews) {
            memcpy(o.eye, eyes[k], sizeof o.eye);
            o.have_eye = 1;
        }
        rc = cli_scene_camera(&s, &o, &cams[k]);
        silk_view check;
        silk_error err;
        if (!rc && silk_view_init(&check, &cams[k], &err) != SILK_OK) rc = cli_fail(CLI_EXIT_USAGE, "%s", err.msg);
    }
    s.mesh = loaded;
    if (rc) {
        free(model);
        cli_scene_free(&s);
        return rc;
    }

    writer w;
    memset(&w, 0, sizeof w);
    w.name = name;
    silk_outfile of;
    silk_error err;
    silk_status st = silk_outfile_open(&of, out, &err);
    if (st == SILK_OK) {
        w.fp = of.fp;
        char texture[600];
        cli_texture_args_text(&o, texture, sizeof texture);
        const char *tex = o.look.texture_path ? texture : NULL, *in = cli_input_name(o.mesh_path);
        int bad = raw     ? fwrite(model, 1, model_len, w.fp) != model_len
                  : model ? write_compact_header(&w, in, tex, &s, cams, ncams, model, model_len, pa.flat) != 0
                          : write_header(&w, in, tex, &s, cams, ncams) != 0;
        if (bad) {
            silk_outfile_abort(&of);
            st = silk_fail(&err, SILK_ERR_IO, of.path, 0, "write failed");
        } else {
            st = silk_outfile_commit(&of, &err);
        }
    }
    cli_scene_free(&s);
    if (st != SILK_OK || silk_path_is_stdio(out)) {   /* stdout holds the header */
        free(model);
        return st != SILK_OK ? cli_fail(CLI_EXIT_INPUT, "%s", err.msg) : 0;
    }
    FILE *sf = stdout;
    if (raw) {
        fprintf(sf, "%s: %s as a %scompact model; bytes: ", of.path, cli_input_name(o.mesh_path),
                pa.flat ? "flat " : "");
        compact_summary(sf, model, model_len);
        fputc('\n', sf);
        free(model);
        return 0;
    }
    size_t total = model_len;
    fprintf(sf, "%s: %s as %s_mesh()%s, %d camera%s; model data (bytes):", of.path, cli_input_name(o.mesh_path), name,
            model ? pa.flat ? " (compact, flat)" : " (compact)" : "", ncams, ncams == 1 ? "" : "s");
    if (model) {
        fputc(' ', sf);
        compact_summary(sf, model, model_len);
        fputc(',', sf);
    }
    for (int k = 0; k < K_COUNT; k++) {
        if (!w.bytes[k]) continue;
        fprintf(sf, " %s %zu,", kind_name[k], w.bytes[k]);
        total += w.bytes[k];
    }
    fprintf(sf, " total %zu\n", total);
    free(model);
    return 0;
}
