/*
 * cmd_info.c - `silk info MESH`: what the mesh holds (counts, features,
 * defects), the arena bytes each part takes, and what one frame from the
 * given (or default) camera costs, from silk_frame_stats.
 *
 * Every value is one "name: value" line, so scripts can grep for them;
 * docs/memory.md explains each memory line.  --json prints the same values
 * as one JSON object (docs/formats.md, "Machine-readable output").
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* info renders a frame for its statistics but writes no image: the look
 * options would change nothing. */
#define INFO_OPTIONS (CLI_OPT_LOAD | CLI_OPT_CAMERA | CLI_OPT_FRAME | CLI_OPT_MODE)

typedef struct info_args {
    int json;
} info_args;

static const cli_opt info_rows[] = {
    { .name = "--json", .group = "", .kind = CLI_FLAG, CLI_FIELD(info_args, json),
      .help = "the same as one JSON object (docs/formats.md)" },
    { .name = NULL },
};

const cli_command cmd_info_spec = {
    .name = "info",
    .usage = "usage: silk info MESH [--json] [options]\n",
    .about =
        "Print MESH's counts (vertices, triangles, normals, edges, feature, boundary\n"
        "and non-manifold edges, degenerate and reoriented triangles), the sections\n"
        "of a prepared model, the arena memory each part takes, and the per-frame\n"
        "counts of one frame rendered (not written) with the camera and frame\n"
        "options below.  MESH - reads standard input.\n",
    .examples =
        "  silk info bunny.obj\n"
        "  silk info bunny.obj --eye 0,0,3 --size 512x512 --tolerance 1\n"
        "  silk info bunny.silk --mode clip\n"
        "  silk info bunny.obj --json | python3 -m json.tool\n",
    .sets = { { info_rows, 0, sizeof(info_args), NULL, NULL }, CLI_SCENE_SET(INFO_OPTIONS) },
    .nsets = 2,
};

/* "name:" padded to a column, then the value. */
static void line(const char *name, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void line(const char *name, const char *fmt, ...)
{
    va_list ap;
    int n = printf("%s:", name);
    printf("%*s", n < 24 ? 24 - n : 1, "");
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
}

static void print_vec(const char *name, silk_vec3 v)
{
    line(name, "%.5g %.5g %.5g", cli_fx_to_double(v.x), cli_fx_to_double(v.y), cli_fx_to_double(v.z));
}

/* The section types of a prepared model ("MESH" ...) with their sizes and
 * whether they are required; 0 sections for a mesh file. */
typedef struct model_info {
    int is_model;
    uint32_t major, minor, n;
    char type[SILK_MODEL_MAX_SECTIONS][5];
    uint32_t bytes[SILK_MODEL_MAX_SECTIONS];
    int required[SILK_MODEL_MAX_SECTIONS];
} model_info;

static void model_sections(const cli_scene *s, model_info *mi)
{
    memset(mi, 0, sizeof *mi);
    silk_model m;
    silk_error err;
    if (!silk_is_model(s->file, s->file_len) || silk_model_open(s->file, s->file_len, "", &m, &err) != SILK_OK) return;
    mi->is_model = 1;
    mi->major = m.version_major;
    mi->minor = m.version_minor;
    for (uint32_t i = 0; i < m.nsections && i < SILK_MODEL_MAX_SECTIONS; i++) {
        silk_model_section sec;
        silk_model_section_at(&m, i, &sec);
        for (int k = 0; k < 4; k++) {
            char c = (char)(sec.type >> (8 * k));
            mi->type[i][k] = c >= 0x20 && c < 0x7f ? c : '?';
        }
        mi->bytes[i] = sec.size;
        mi->required[i] = (sec.flags & SILK_SECTION_REQUIRED) != 0;
        mi->n++;
    }
}

/* Which section of a prepared model the counts describe: the mesh the mode
 * draws, the hull in clip and siltex mode and when the model has no MESH. */
static const char *part_name(const cli_scene *s, const cli_scene_opts *o, const model_info *mi)
{
    if (cli_scene_mesh(s, o->render.mode) == &s->hull) return "HULL";
    for (uint32_t i = 0; i < mi->n; i++)
        if (strcmp(mi->type[i], "MESH") == 0) return "MESH";
    return "HULL";
}

static void print_mesh(const cli_scene *s, const cli_scene_opts *o)
{
    const silk_mesh *m = cli_scene_mesh(s, o->render.mode);
    line("file", "%s (%zu bytes)", cli_input_name(o->mesh_path), s->file_len);
    model_info mi;
    model_sections(s, &mi);
    if (mi.is_model) {
        char list[SILK_MODEL_MAX_SECTIONS * 32] = "";
        for (uint32_t i = 0; i < mi.n; i++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s %u bytes%s", i ? ", " : "", mi.type[i],
                     mi.bytes[i], mi.required[i] ? " (required)" : "");
        line("model", "prepared, version %u.%u", mi.major, mi.minor);
        line("sections", "%s", list);
        line("counts of", "%s", part_name(s, o, &mi));
    }
    line("vertices", "%u", m->nverts);
    line("triangles", "%u", m->ntris);
    line("normals", "%u", m->nnormals);
    line("normals from", "%s", m->normals_used == SILK_NORMALS_FILE ? "the file" : "computed (angle-weighted)");
    line("uvs", "%u", m->nuvs);
    line("edges", "%u", m->nedges);
    line("feature edges", "%u", m->nfeature_edges);
    line("boundary edges", "%u", m->nboundary_edges);
    line("non-manifold edges", "%u", m->nnonmanifold_edges);
    line("degenerate triangles", "%u", m->ndegenerate_tris);
    line("reoriented triangles", "%u", m->nreoriented_tris);
    if (m->nnonorientable_tris) line("non-orientable triangles", "%u (left as in the file)", m->nnonorientable_tris);
    print_vec("bbox min", m->bbox_min);
    print_vec("bbox max", m->bbox_max);
}

/* The smallest arena that draws this frame as it was drawn: what stays
 * (the mesh, the frame's colour and depth) and the frame's own need; the
 * peak also holds what the frame kept for speed where there was room. */
static size_t arena_needed(const cli_scene *s, const silk_frame_stats *st)
{
    return s->arena.bottom + st->frame_bytes;
}

/* The most a FLAT or SMOOTH frame of this mesh, size and options takes
 * from any camera (silk/budget.h), or 0 for the other modes. */
static size_t frame_bound(const cli_scene *s, const cli_scene_opts *o)
{
    silk_budget b;
    return silk_budget_frame(&s->mesh, &o->render, o->width, o->height, o->height, o->fmt, 0, &b, NULL) == SILK_OK
               ? b.frame
               : 0;
}

static void print_memory(const cli_scene *s, const cli_scene_opts *o, const silk_frame_stats *st)
{
    silk_mesh_bytes b;
    const silk_mesh *m = cli_scene_mesh(s, o->render.mode);
    silk_mesh_bytes_used(m, &b);
    printf("\nmesh memory (bytes)\n");
    if (m->packed.base) {
        /* read in place: nothing of the mesh is in the arena */
        const uint8_t *h = m->packed.base;
        unsigned long n = (unsigned long)h[48] | (unsigned long)h[49] << 8 | (unsigned long)h[50] << 16 |
                          (unsigned long)h[51] << 24;
        line("  compact model", "%lu (%.2f a triangle), read in place", n, (double)n / m->ntris);
        line("  in the arena", "%d", 0);
    } else {
    line("  positions", "%zu", b.positions);
    line("  normals", "%zu", b.normals);
    line("  uvs", "%zu", b.uvs);
    line("  triangles", "%zu", b.triangles);
    line("  edges", "%zu", b.edges);
    line("  vertex edges", "%zu", b.vertex_edges);
    line("  features", "%zu", b.features);
    line("  mesh total", "%zu", b.total);
    line("  visibility hierarchy", "%zu", silk_vis_bytes(m->vis));
    }

    const silk_arena *a = &s->arena;
    printf("\narena (bytes)\n");
    line("  size", "%zu", a->size);
    line("  after loading", "%zu", s->load_bytes);
    line("  persistent (bottom)", "%zu", a->bottom);
    line("  peak", "%zu", a->peak);
    line("  needed", "%zu", arena_needed(s, st));
    line("  free", "%zu", silk_arena_free_bytes(a));
    printf("  %-22s %12s %12s\n", "purpose", "now", "peak");
    for (int p = 0; p < SILK_MEM_COUNT; p++)
        printf("  %-22s %12zu %12zu\n", silk_purpose_name((silk_purpose)p), a->used[p], a->peak_used[p]);
}

static void print_frame(const cli_scene *s, const cli_scene_opts *o, const silk_frame_stats *st)
{
    const silk_camera *c = &s->cam;
    printf("\nframe\n");
    line("  size", "%dx%d %s", o->width, o->height, o->fmt == SILK_PIX_RGB565 ? "rgb565" : "rgb888");
    line("  mode", "%s", silk_mode_name(o->render.mode));
    print_vec("  eye", c->eye);
    print_vec("  target", c->target);
    print_vec("  up", c->up);
    if (c->ortho) line("  projection", "orthographic, half height %.5g", cli_fx_to_double(c->ortho_half_height));
    else line("  projection", "perspective, fov %.5g", cli_fx_to_double(c->fov_deg));
    line("  silhouette triangles", "%u", st->silhouette_tris);
    line("  bridges", "%u", st->bridges);
    line("  samples", "%u", st->samples);
    line("  moved vertices", "%u", st->moved_vertices);
    line("  flat segments", "%u", st->flat_segments);
    line("  triangles drawn", "%u", st->tris_drawn);
    line("  frame bytes", "%zu", st->frame_bytes);
    size_t bound = frame_bound(s, o);
    if (bound) line("  frame bytes bound", "%zu", bound);
    line("  fell back", "%s", st->fell_back ? "yes (the arena ran out; part of the frame not smoothed)" : "no");
    if (o->render.mode == SILK_MODE_CLIP) {
        const silk_silmap *m = &s->silmap;
        line("  map views", "%u (%u polytope triangles, %u outline points, %u bytes)", m->nviews, m->ntris, m->npts,
             silk_silmap_bytes(m));
        line("  map triangle", "%u", st->clip_tri);
        line("  polygon vertices", "%u", st->clip_points);
        line("  stencil spans", "%u", st->clip_spans);
    }
    if (o->render.mode == SILK_MODE_SILTEX) {
        const silk_siltex *t = &s->siltex;
        line("  atlas", "%ux%u texels, %u azimuths (K), %u eigenfunctions (E)%s", t->w, t->h, t->k, t->e,
             t->color ? ", colour map" : "");
        line("  texture bytes", "%u", silk_siltex_bytes(t));
        line("  eq. 3 error", "%.4f (mean over the hull's texels; not single-lobed: %.2f%%)", t->error_ppm / 1e6,
             t->multi_lobe_ppm / 1e4);
    }
}

/* ---- JSON ------------------------------------------------------------------------------ */

static void json_vec(const char *name, silk_vec3 v, const char *end)
{
    printf("\"%s\": [%.17g, %.17g, %.17g]%s", name, cli_fx_to_double(v.x), cli_fx_to_double(v.y),
           cli_fx_to_double(v.z), end);
}

static void print_json(const cli_scene *s, const cli_scene_opts *o, const silk_frame_stats *st)
{
    const silk_mesh *m = cli_scene_mesh(s, o->render.mode);
    printf("{\n  \"schema\": \"silk-info/1\",\n  \"file\": ");
    cli_json_string(stdout, cli_input_name(o->mesh_path));
    printf(",\n  \"file_bytes\": %zu,\n", s->file_len);
    model_info mi;
    model_sections(s, &mi);
    if (mi.is_model) {
        printf("  \"model\": {\"version\": \"%u.%u\", \"counts_of\": \"%s\", \"sections\": [", mi.major, mi.minor,
               part_name(s, o, &mi));
        for (uint32_t i = 0; i < mi.n; i++)
            printf("%s{\"type\": \"%s\", \"bytes\": %u, \"required\": %s}", i ? ", " : "", mi.type[i], mi.bytes[i],
                   mi.required[i] ? "true" : "false");
        printf("]},\n");
    } else {
        printf("  \"model\": null,\n");
    }
    printf("  \"mesh\": {\"vertices\": %u, \"triangles\": %u, \"normals\": %u, \"normals_from\": \"%s\", "
           "\"uvs\": %u, \"edges\": %u,\n"
           "    \"feature_edges\": %u, \"boundary_edges\": %u, \"nonmanifold_edges\": %u,\n"
           "    \"degenerate_triangles\": %u, \"reoriented_triangles\": %u, \"nonorientable_triangles\": %u,\n    ",
           m->nverts, m->ntris, m->nnormals, m->normals_used == SILK_NORMALS_FILE ? "file" : "computed", m->nuvs,
           m->nedges, m->nfeature_edges, m->nboundary_edges, m->nnonmanifold_edges, m->ndegenerate_tris,
           m->nreoriented_tris, m->nnonorientable_tris);
    json_vec("bbox_min", m->bbox_min, ", ");
    json_vec("bbox_max", m->bbox_max, "},\n");

    silk_mesh_bytes b;
    silk_mesh_bytes_used(m, &b);
    printf("  \"mesh_bytes\": {\"positions\": %zu, \"normals\": %zu, \"uvs\": %zu, \"triangles\": %zu, "
           "\"edges\": %zu,\n    \"vertex_edges\": %zu, \"features\": %zu, \"total\": %zu, "
           "\"visibility_hierarchy\": %zu},\n",
           b.positions, b.normals, b.uvs, b.triangles, b.edges, b.vertex_edges, b.features, b.total,
           silk_vis_bytes(m->vis));

    const silk_arena *a = &s->arena;
    printf("  \"arena\": {\"size\": %zu, \"after_loading\": %zu, \"persistent\": %zu, \"peak\": %zu, "
           "\"needed\": %zu, \"free\": %zu,\n    \"purposes\": {",
           a->size, s->load_bytes, a->bottom, a->peak, arena_needed(s, st), silk_arena_free_bytes(a));
    for (int p = 0; p < SILK_MEM_COUNT; p++)
        printf("%s\"%s\": {\"now\": %zu, \"peak\": %zu}", p ? ", " : "", silk_purpose_name((silk_purpose)p),
               a->used[p], a->peak_used[p]);
    printf("}},\n");

    const silk_camera *c = &s->cam;
    printf("  \"frame\": {\"width\": %d, \"height\": %d, \"format\": \"%s\", \"mode\": \"%s\", \"level\": %u,\n    ",
           o->width, o->height, o->fmt == SILK_PIX_RGB565 ? "rgb565" : "rgb888", silk_mode_name(o->render.mode),
           (unsigned)o->render.level);
    json_vec("eye", c->eye, ", ");
    json_vec("target", c->target, ", ");
    json_vec("up", c->up, ",\n    ");
    printf("\"projection\": \"%s\", \"fov\": %.17g, \"ortho_half_height\": %.17g,\n",
           c->ortho ? "orthographic" : "perspective", cli_fx_to_double(c->fov_deg),
           cli_fx_to_double(c->ortho_half_height));
    printf("    \"silhouette_triangles\": %u, \"bridges\": %u, \"samples\": %u, \"moved_vertices\": %u,\n"
           "    \"flat_segments\": %u, \"triangles_drawn\": %u, \"frame_bytes\": %zu, \"fell_back\": %s",
           st->silhouette_tris, st->bridges, st->samples, st->moved_vertices, st->flat_segments, st->tris_drawn,
           st->frame_bytes, st->fell_back ? "true" : "false");
    size_t bound = frame_bound(s, o);
    if (bound) printf(", \"frame_bytes_bound\": %zu", bound);
    if (o->render.mode == SILK_MODE_CLIP)
        printf(",\n    \"map_views\": %u, \"map_bytes\": %u, \"map_triangle\": %u, \"polygon_vertices\": %u, "
               "\"stencil_spans\": %u", s->silmap.nviews, silk_silmap_bytes(&s->silmap), st->clip_tri, st->clip_points,
               st->clip_spans);
    if (o->render.mode == SILK_MODE_SILTEX)
        printf(",\n    \"atlas_width\": %u, \"atlas_height\": %u, \"azimuths\": %u, \"eigenfunctions\": %u, "
               "\"colour_map\": %s, \"texture_bytes\": %u, \"error_ppm\": %u, \"multi_lobe_ppm\": %u",
               s->siltex.w, s->siltex.h, s->siltex.k, s->siltex.e, s->siltex.color ? "true" : "false",
               silk_siltex_bytes(&s->siltex), s->siltex.error_ppm, s->siltex.multi_lobe_ppm);
    printf("}\n}\n");
}

int cmd_info(int argc, char **argv)
{
    cli_scene_opts o;
    cli_scene_opts_default(&o);
    o.orient_note = 0;        /* the report has the line */
    info_args ia = { 0 };
    cli_args args;
    void *bases[] = { &ia, &o };
    int rc = cli_parse(&cmd_info_spec, bases, argc, argv, &args);
    if (!rc) rc = cli_one_mesh("info", args.npos, args.pos, "silk info MESH", &o.mesh_path);
    cli_args_free(&args);
    if (rc == CLI_HELP) return 0;
    if (!rc) rc = cli_mode_check("info", o.render.mode, &o.render);
    if (rc) return rc;
    int json = ia.json;

    /* As `silk render` does: without --arena, an arena whose frame fell back
     * for lack of scratch is doubled, so the report shows a full frame. */
    for (int attempt = 0;; attempt++) {
        cli_scene s;
        o.arena_doublings = attempt;
        rc = cli_scene_load(&s, &o);
        if (rc) {
            cli_scene_free(&s);
            return rc;
        }
        silk_frame_stats st;
        silk_error err;
        silk_render_opts ro = o.render;
        cli_scene_render_opts(&s, &ro);
        silk_status r = silk_render(&s.arena, cli_scene_mesh(&s, ro.mode), &s.view, &s.hal, &ro, &s.target, &st, &err);
        if (r != SILK_OK) {
            cli_scene_free(&s);
            return cli_fail(CLI_EXIT_INPUT, "%s: %s", cli_input_name(o.mesh_path), err.msg);
        }
        if (st.fell_back && !o.arena_bytes && attempt < 4) {
            cli_scene_free(&s);
            continue;
        }
        if (json) {
            print_json(&s, &o, &st);
        } else {
            print_mesh(&s, &o);
            print_memory(&s, &o, &st);
            print_frame(&s, &o, &st);
        }
        cli_scene_free(&s);
        return ferror(stdout) ? CLI_EXIT_INPUT : 0;
    }
}
