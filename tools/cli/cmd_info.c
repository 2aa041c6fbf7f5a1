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
#include <string.h>

#include "cli.h"
#include "commands.h"

/* info renders a frame for its statistics but writes no image: the look
 * options would change nothing. */
#define INFO_OPTIONS (CLI_OPT_LOAD | CLI_OPT_CAMERA | CLI_OPT_FRAME | CLI_OPT_MODE)

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk info MESH [--json] [options]\n"
            "\n"
            "Print MESH's counts (vertices, triangles, normals, edges, feature, boundary\n"
            "and non-manifold edges, degenerate triangles), the arena memory each part\n"
            "takes, and the per-frame counts of one frame rendered (not written) with\n"
            "the camera and frame options below.  MESH - reads standard input.\n"
            "\n"
            "  --json               the same as one JSON object (docs/formats.md)\n");
    cli_print_scene_help(f, INFO_OPTIONS);
    fprintf(f,
            "\n"
            "examples:\n"
            "  silk info bunny.obj\n"
            "  silk info bunny.obj --eye 0,0,3 --size 512x512 --tolerance 1\n"
            "  silk info bunny.obj --json | python3 -m json.tool\n");
}

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

static void print_mesh(const cli_scene *s, const cli_scene_opts *o)
{
    const silk_mesh *m = &s->mesh;
    line("file", "%s (%zu bytes)", cli_input_name(o->mesh_path), s->file_len);
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

static void print_memory(const cli_scene *s, const silk_frame_stats *st)
{
    silk_mesh_bytes b;
    silk_mesh_bytes_used(&s->mesh, &b);
    printf("\nmesh memory (bytes)\n");
    line("  positions", "%zu", b.positions);
    line("  normals", "%zu", b.normals);
    line("  uvs", "%zu", b.uvs);
    line("  triangles", "%zu", b.triangles);
    line("  edges", "%zu", b.edges);
    line("  vertex edges", "%zu", b.vertex_edges);
    line("  features", "%zu", b.features);
    line("  mesh total", "%zu", b.total);
    line("  visibility hierarchy", "%zu", silk_vis_bytes(s->mesh.vis));

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
    const silk_mesh *m = &s->mesh;
    printf("{\n  \"schema\": \"silk-info/1\",\n  \"file\": ");
    cli_json_string(stdout, cli_input_name(o->mesh_path));
    printf(",\n  \"file_bytes\": %zu,\n", s->file_len);
    printf("  \"mesh\": {\"vertices\": %u, \"triangles\": %u, \"normals\": %u, \"uvs\": %u, \"edges\": %u,\n"
           "    \"feature_edges\": %u, \"boundary_edges\": %u, \"nonmanifold_edges\": %u,\n"
           "    \"degenerate_triangles\": %u, ",
           m->nverts, m->ntris, m->nnormals, m->nuvs, m->nedges, m->nfeature_edges, m->nboundary_edges,
           m->nnonmanifold_edges, m->ndegenerate_tris);
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
           "    \"triangles_drawn\": %u, \"frame_bytes\": %zu, \"fell_back\": %s",
           st->silhouette_tris, st->bridges, st->samples, st->moved_vertices, st->tris_drawn, st->frame_bytes,
           st->fell_back ? "true" : "false");
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
    o.groups = INFO_OPTIONS;
    o.orient_note = 0;        /* the report has the line */
    int rc = 0, json = 0;
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        if (cli_help(a, help)) return 0;
        if (strcmp(a, "--json") == 0) {
            json = 1;
            continue;
        }
        if (cli_scene_arg(&o, argc, argv, &i, &rc)) continue;
        rc = cli_mesh_arg("info", a, &o.mesh_path);
    }
    if (!rc && !o.mesh_path) rc = cli_fail(CLI_EXIT_USAGE, "info: no mesh given (silk info MESH)");
    if (rc) return rc;

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
        silk_status r = silk_render(&s.arena, &s.mesh, &s.view, &s.hal, &o.render, &s.target, &st, &err);
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
            print_memory(&s, &st);
            print_frame(&s, &o, &st);
        }
        cli_scene_free(&s);
        return ferror(stdout) ? CLI_EXIT_INPUT : 0;
    }
}
