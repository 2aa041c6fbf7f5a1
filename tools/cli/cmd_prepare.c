/*
 * cmd_prepare.c - `silk prepare FINE -o MODEL.silk --triangles N`: a
 * detailed mesh made into a prepared model (silk/model.h): the coarse mesh
 * smooth mode wants - simplified by subset placement so every vertex lies
 * on the detailed surface (tools/prep/simplify.c), with the detailed surface's
 * normals there, split along feature edges (tools/prep/surface.c) - and what
 * clip mode draws: the outer hull (tools/prep/hull.c, paper section 7) and the
 * silhouette map (tools/prep/silmap.c, sections 4 and 6), in fixed point, in
 * one checked binary file (tools/prep/model_file.c).  With --siltex, what
 * siltex mode draws too: the hull's silhouette texture (tools/prep/stex_build.c,
 * Wu et al., "Silhouette Texture", section 3).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "prep/fit.h"
#include "prep/hull.h"
#include "prep/silmap.h"
#include "prep/silmap_simplify.h"
#include "commands.h"
#include "prep/model_file.h"
#include "prep/simplify.h"
#include "prep/stex_build.h"
#include "prep/surface.h"
#include "platform/platform.h"

static void help(FILE *f)
{
    fprintf(f,
            "usage: silk prepare FINE -o MODEL.silk --triangles N [options]\n"
            "\n"
            "Make the detailed mesh FINE (OBJ, PLY or STL; - for standard input) into a\n"
            "prepared model: a coarse mesh of N triangles whose vertices are vertices of\n"
            "FINE (so they lie on its surface) and whose normals are FINE's normals there,\n"
            "split along feature edges - the mesh smooth mode draws best.  flat, smooth, pn\n"
            "and blend draw it; every silk command that takes a mesh takes MODEL.silk.\n"
            "With it, for clip mode: FINE's outer hull of N triangles, shaded with FINE's\n"
            "normals, and FINE's silhouette map (its outlines from many views).\n"
            "Written atomically.  Prints:\n"
            "  prepare FINE MODEL triangles=N vertices=N normals=N hull_triangles=N\n"
            "          map_views=N map_bytes=N bytes=N\n"
            "and with --siltex: siltex_bytes=N siltex_error=E siltex_multi=S (the share\n"
            "of view directions the texture gets wrong, averaged over the hull; the\n"
            "share of texels whose visibility is not one lobe).\n"
            "\n"
            "options:\n"
            "  -o, --output FILE   the prepared model (.silk)\n"
            "  --triangles N       triangles of the coarse mesh (at least 4)\n"
            "  --crease DEG        dihedral angle above which an edge is a feature [60]\n"
            "  --feature-weight W  weight of the feature constraint planes, 0..1e6 [100]\n"
            "  --views N           silhouette map views: 12, 42, 162 (default), 642, ...\n"
            "  --map-resolution R  each map view's image, R x R pixels [256]\n"
            "  --map-error PX      simplify the map while a dropped view's outline is\n"
            "                      predicted within PX pixels [0: keep every view]\n"
            "  --siltex            the hull's silhouette texture too (siltex mode)\n"
            "  --atlas N           its atlas, N x N texels, 8..4096 [128]\n"
            "  --angles K          its azimuths per texel, 4..64 [12]\n"
            "  --siltex-svd E      store the angles compressed to E eigenfunctions,\n"
            "                      1..K [0: whole]\n"
            "  --siltex-compare    also print the error and size for E = 4, 8 and 16\n"
            "                      (those up to K) and whole\n"
            "  --no-clip           no outer hull and silhouette map (clip mode)\n"
            "  --no-mesh           only the hull and map (flat mode then draws the hull)\n"
            "  --fit               move each normal (up to 30 degrees) so that the curves\n"
            "                      smooth mode builds over its edges follow FINE closer\n"
            "  --scale S           multiply coordinates by S while reading (as silk render)\n"
            "  --quiet             no progress line on a terminal\n"
            "\n"
            "example:\n"
            "  silk prepare bunny-fine.obj -o bunny.silk --triangles 500\n");
}

/* What clip mode needs (docs/clipping.md): the outer hull and the
 * silhouette map of the detailed mesh. */
typedef struct clip_opts {
    int on;                  /* --no-clip: 0 */
    int mesh;                /* --no-mesh: 0, the hull and map only (flat then draws the hull) */
    int level;               /* icosahedron subdivisions: 10 * 4^level + 2 views */
    int res;                 /* --map-resolution */
    double map_error;        /* --map-error: 0 keeps every view */
    int siltex;              /* --siltex: the silhouette texture too */
    int siltex_compare;      /* --siltex-compare */
    stex_opts so;
} clip_opts;

typedef struct clip_stats {
    uint32_t hull_tris, hull_verts, views, views_before, map_bytes, map_bytes_before;
    int siltex;              /* written */
    size_t stex_bytes;
    double stex_error, stex_multi;
} clip_stats;

/* The STEX section for hull h of fine (stex_build.h).  0, or an exit
 * status after a one-line error. */
static int add_siltex(model_out *mo, const char *in, const simp_mesh *fine, const uint32_t *fine_color,
                      const simp_mesh *h, const clip_opts *co, clip_stats *cs)
{
    stex st;
    stex_svd svd;
    int rc = stex_build(fine, fine_color, h, &co->so, &st);
    if (rc == -2)
        return cli_fail(CLI_EXIT_INPUT, "%s: the hull's %u triangles do not fit a %d x %d atlas (raise --atlas)", in,
                        h->ntris, co->so.atlas, co->so.atlas);
    if (rc) return cli_fail(CLI_EXIT_INPUT, "%s: out of memory while making the silhouette texture", in);
    size_t nt = (size_t)st.atlas.w * st.atlas.h;
    uint8_t *used = malloc(nt), *back = malloc(nt * st.k + 1), *sec = NULL;
    rc = 0;
    if (!used || !back) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    for (size_t t = 0; !rc && t < nt; t++) used[t] = st.atlas.tri[t] >= 0;
    if (!rc && co->siltex_compare) {
        static const int es[] = { 4, 8, 16 };
        for (int i = 0; i < 3 && !rc; i++) {
            if (es[i] > st.k) continue;
            if (stex_svd_compress(st.angles, used, (uint32_t)nt, st.k, es[i], &svd)) {
                rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
                break;
            }
            stex_svd_expand(&svd, back);
            printf("siltex svd=%d siltex_bytes=%zu siltex_error=%.5f psnr=%.2f\n", es[i], stex_section_bytes(&st, es[i]),
                   stex_error(&st, back), stex_psnr(&st, back));
            stex_svd_free(&svd);
        }
        if (!rc)
            printf("siltex svd=0 siltex_bytes=%zu siltex_error=%.5f\n", stex_section_bytes(&st, 0), st.error);
    }
    int compress = co->so.svd > 0;
    double error = st.error;
    if (!rc && compress) {
        if (stex_svd_compress(st.angles, used, (uint32_t)nt, st.k, co->so.svd, &svd)) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
            compress = 0;
        } else {
            stex_svd_expand(&svd, back);
            error = stex_error(&st, back);
        }
    }
    if (!rc && (!(sec = stex_section(&st, compress ? &svd : NULL, error, &cs->stex_bytes)) ||
                model_add(mo, SILK_SECTION_STEX, 0, sec, cs->stex_bytes)))
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    cs->siltex = rc == 0;
    cs->stex_error = error;
    cs->stex_multi = st.multi_share;
    if (compress) stex_svd_free(&svd);
    free(sec), free(used), free(back);
    stex_free(&st);
    return rc;
}

/* A mesh of doubles as a section (model_add_mesh_doubles). */
static int add_mesh(model_out *mo, uint32_t type, uint32_t flags, const simp_mesh *m, const double *normal,
                    uint32_t nnormals, const uint32_t *tri_normal)
{
    return model_add_mesh_doubles(mo, type, flags, m->nverts, m->pos, nnormals, normal, m->ntris, m->tri, tri_normal);
}

/* The map's eyes sit where silk's default perspective camera sits for a
 * 640x480 frame (the camera of silk render and silk bench's path): the
 * framing sphere (tools/cli/cli.c cli_mesh_radius) of the model's coarse mesh
 * just fits the field of view.  The interpolated outline is mapped to the current view through
 * a plane (section 5), exact only for eyes at the map's own distance. */
static double map_distance(const simp_mesh *hull, double fine_radius)
{
    double lo[3], hi[3], c[3], r2 = 0;
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = hull->pos[k];
    for (uint32_t i = 0; i < hull->nverts; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], hull->pos[3 * i + k]), hi[k] = fmax(hi[k], hull->pos[3 * i + k]);
    for (int k = 0; k < 3; k++) c[k] = (lo[k] + hi[k]) / 2;
    for (uint32_t i = 0; i < hull->nverts; i++) {
        double d[3] = { hull->pos[3 * i] - c[0], hull->pos[3 * i + 1] - c[1], hull->pos[3 * i + 2] - c[2] };
        r2 = fmax(r2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    double half_v = CLI_DEFAULT_FOV * CLI_DEG / 2, half_h = atan(tan(half_v) * 640.0 / 480.0);
    double dist = 1.05 * sqrt(r2) / sin(fmin(half_v, half_h));
    return fmax(1.5, dist / fine_radius);
}

/* HULL and SMAP sections for fine.  0, or an exit status after a one-line
 * error; CLIP_NONE (with a note) when fine is not a closed manifold. */
#define CLIP_NONE (-1)
static int add_clip(model_out *mo, const char *in, const simp_mesh *fine, const uint32_t *fine_color,
                    const simp_mesh *coarse, uint32_t target, const clip_opts *co, clip_stats *cs)
{
    simp_topology topo;
    simp_mesh h = { 0, 0, NULL, NULL, NULL };
    hull_opts ho;
    hull_stats hs;
    hull_fine hf = { NULL, NULL };
    silmap map, small;
    silmap_fixed fx = { { { 0, 0, 0 }, 0, 0, 0, 0, NULL, NULL, NULL, NULL, NULL }, NULL };
    silmap_params mp;
    int rc = 0, have_map = 0, have_small = 0;
    memset(&map, 0, sizeof map);
    memset(&small, 0, sizeof small);
    if (simp_topology_check(fine, &topo) != 0) return cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
    if (topo.boundary_edges || topo.nonmanifold_edges || topo.nonmanifold_verts || topo.misoriented_edges ||
        topo.degenerate_tris || !(hull_volume(fine) > 0)) {
        if (!co->siltex)   /* else the caller's error says it */
            fprintf(stderr, "silk: note: %s: not a closed, outward-facing manifold: no outer hull or silhouette map "
                            "(clip mode) in the model\n", in);
        return CLIP_NONE;
    }
    hull_opts_default(&ho, target);
    if (simp_copy(fine, &h) || hull_run(&h, &ho, &hs, &hf)) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while making the hull", in);
        goto done;
    }
    silmap_params_default(&mp);
    mp.level = co->level;
    mp.res = co->res;
    if (silmap_build(fine->pos, fine->nverts, fine->tri, fine->ntris, &mp, &map) != 0) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while making the silhouette map", in);
        goto done;
    }
    have_map = 1;
    /* the eyes at the rendering distance: rebuild with it (cheap next to the hull) */
    double dist = map_distance(coarse, map.radius);
    silmap_free(&map);
    have_map = 0;
    mp.distance = dist;
    if (silmap_build(fine->pos, fine->nverts, fine->tri, fine->ntris, &mp, &map) != 0) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while making the silhouette map", in);
        goto done;
    }
    have_map = 1;
    const silmap *use = &map;
    cs->views_before = map.poly.nviews;
    if (co->map_error > 0) {
        silmap_simplify_stats ss;
        if (silmap_simplify_map(&map, co->map_error, 12, &small, &ss) != 0) {
            rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while simplifying the silhouette map", in);
            goto done;
        }
        have_small = 1;
        use = &small;
    }
    if (silmap_export(use, &fx) != 0) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: the silhouette map does not fit silk's fixed point (a model this large "
                      "needs --scale)", in);
        goto done;
    }
    if (add_mesh(mo, SILK_SECTION_HULL, 0, &h, hf.normal, h.nverts, NULL) || model_add_silmap(mo, &fx.map)) {
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", in);
        goto done;
    }
    if (co->siltex && (rc = add_siltex(mo, in, fine, fine_color, &h, co, cs)) != 0) goto done;
    cs->hull_tris = h.ntris;
    cs->hull_verts = h.nverts;
    cs->views = fx.map.nviews;
    cs->map_bytes = silk_silmap_bytes(&fx.map);
    if (have_small) {
        silmap_fixed big;
        if (silmap_export(&map, &big) == 0) {
            cs->map_bytes_before = silk_silmap_bytes(&big.map);
            silmap_fixed_free(&big);
        }
    } else {
        cs->map_bytes_before = cs->map_bytes;
    }
done:
    if (fx.block) silmap_fixed_free(&fx);
    if (have_small) silmap_free(&small);
    if (have_map) silmap_free(&map);
    simp_free(&h);
    hull_fine_free(&hf);
    return rc;
}

static int prepare(const char *in, const char *out, const simp_opts *so, silk_decimal scale, int quiet, int fit,
                   const clip_opts *co)
{
    simp_result r;
    fit_stats fs = { 0, 0, 0 };
    clip_stats cs;
    model_out mo = { 0 };
    size_t bytes = 0;
    int clip = 0;
    memset(&cs, 0, sizeof cs);
    int rc = simplify_pipeline(in, so, scale, quiet, "prepare", &r);
    if (rc == 0 && fit && fit_normals(&r.fine, &r.mesh, &r.normals, &fs) != 0)
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory while fitting normals", in);
    if (rc == 0 && co->mesh &&
        add_mesh(&mo, SILK_SECTION_MESH, SILK_SECTION_REQUIRED, &r.mesh, r.normals.normal, r.normals.nnormals,
                 r.normals.tri_normal))
        rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", out);
    if (rc == 0 && co->on) {
        rc = add_clip(&mo, in, &r.fine, r.fine_color, &r.mesh, so->target_tris, co, &cs);
        clip = rc == 0;
        if (rc == CLIP_NONE && co->siltex)
            rc = cli_fail(CLI_EXIT_INPUT, "%s: --siltex needs the outer hull, so a closed manifold", in);
        if (rc == CLIP_NONE) rc = co->mesh ? 0 : cli_fail(CLI_EXIT_INPUT, "%s: --no-mesh leaves nothing to write", in);
    }
    uint8_t *probe = NULL;
    if (rc == 0 && !(probe = model_bytes(&mo, &bytes))) rc = cli_fail(CLI_EXIT_INPUT, "%s: out of memory", out);
    free(probe);
    silk_error err;
    if (rc == 0 && model_write(&mo, out, &err) != SILK_OK) rc = cli_fail(CLI_EXIT_INPUT, "%s", err.msg);
    if (rc == 0) {
        printf("prepare %s %s triangles=%u vertices=%u normals=%u", in, out, r.mesh.ntris, r.mesh.nverts,
               r.normals.nnormals);
        if (clip)
            printf(" hull_triangles=%u map_views=%u map_bytes=%u", cs.hull_tris, cs.views, cs.map_bytes);
        if (clip && co->map_error > 0)
            printf(" map_views_before=%u map_bytes_before=%u", cs.views_before, cs.map_bytes_before);
        if (cs.siltex)
            printf(" siltex_bytes=%zu siltex_error=%.5f siltex_multi=%.5f", cs.stex_bytes, cs.stex_error, cs.stex_multi);
        printf(" bytes=%zu", bytes);
        if (fit) printf(" fitted=%u fit_rms_before=%.3g fit_rms_after=%.3g", fs.moved, sqrt(fs.before), sqrt(fs.after));
        printf("\n");
        simplify_warn_short(in, &r.mesh, so->target_tris);
    }
    model_free(&mo);
    simp_result_free(&r);
    return rc;
}

int cmd_prepare(int argc, char **argv)
{
    const char *in = NULL;
    simp_args args = { NULL, -1, { 1, 0 }, 0 };
    simp_opts so;
    simp_opts_default(&so, 0);
    so.subset = 1;
    int rc = 0, fit = 0, k;
    clip_opts co = { 1, 1, 2, 256, 0, 0, 0, { 0, 0, 0, 0, 0, 0 } };
    stex_opts_default(&co.so);
    long lv;
    const char *siltex_opt = NULL;   /* a --siltex option given */
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help(stdout);
            return 0;
        } else if ((k = simp_common_option(argc, argv, &i, &args)) != 0 || (k = simplify_option(argc, argv, &i, &so)) != 0) {
            if (k < 0) rc = CLI_EXIT_USAGE;
        } else if (strcmp(a, "--fit") == 0) {
            fit = 1;
        } else if (strcmp(a, "--no-clip") == 0) {
            co.on = 0;
        } else if (strcmp(a, "--no-mesh") == 0) {
            co.mesh = 0;
        } else if (strcmp(a, "--siltex") == 0) {
            co.siltex = 1;
        } else if (strcmp(a, "--siltex-compare") == 0) {
            co.siltex_compare = 1;
            siltex_opt = a;
        } else if (cli_is(a, "--atlas") || cli_is(a, "--angles") || cli_is(a, "--siltex-svd")) {
            const char *v = cli_value(argc, argv, &i);
            int atlas = cli_is(a, "--atlas"), angles = cli_is(a, "--angles");
            const char *name = atlas ? "--atlas" : angles ? "--angles" : "--siltex-svd";
            siltex_opt = name;
            if (!v || cli_parse_long(name, v, atlas ? 8 : angles ? 4 : 0, atlas ? 4096 : 64, &lv) != 0)
                rc = CLI_EXIT_USAGE;
            else
                *(atlas ? &co.so.atlas : angles ? &co.so.angles : &co.so.svd) = (int)lv;
        } else if (strcmp(a, "--views") == 0 || strcmp(a, "--map-resolution") == 0 || strcmp(a, "--map-error") == 0) {
            double v;
            if (i + 1 >= argc) rc = cli_fail(CLI_EXIT_USAGE, "prepare: %s needs a value", a);
            else if (strcmp(a, "--views") == 0) {
                if (cli_parse_double(a, argv[++i], 12, 40962, &v) == 0) {
                    co.level = 0;
                    while (10.0 * (1 << (2 * co.level)) + 2 < v) co.level++;
                    if (10.0 * (1 << (2 * co.level)) + 2 != v)
                        rc = cli_fail(CLI_EXIT_USAGE, "prepare: --views must be 12, 42, 162, 642, 2562, 10242 or 40962 "
                                      "(a subdivided icosahedron's vertices), got %s", argv[i]);
                } else {
                    rc = CLI_EXIT_USAGE;
                }
            } else if (strcmp(a, "--map-resolution") == 0) {
                if (cli_parse_double(a, argv[++i], 16, 4096, &v) != 0) rc = CLI_EXIT_USAGE;
                else if (v != floor(v)) rc = cli_fail(CLI_EXIT_USAGE, "--map-resolution must be a whole number of pixels");
                else co.res = (int)v;
            } else if (cli_parse_double(a, argv[++i], 0, 100, &co.map_error) != 0) {
                rc = CLI_EXIT_USAGE;
            }
        } else if (a[0] == '-' && a[1]) {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: unknown option %s (try silk prepare --help)", a);
        } else if (!in) {
            in = a;
        } else {
            rc = cli_fail(CLI_EXIT_USAGE, "prepare: one input (got a second, %s; the output goes after -o)", a);
        }
    }
    if (!rc && !in) rc = cli_fail(CLI_EXIT_USAGE, "prepare: give FINE (silk prepare FINE -o MODEL.silk --triangles N)");
    if (!rc && !args.out) rc = cli_fail(CLI_EXIT_USAGE, "prepare: -o MODEL.silk is needed");
    if (!rc && args.target < 0) rc = cli_fail(CLI_EXIT_USAGE, "prepare: --triangles N is needed");
    if (!rc && !co.on && !co.mesh) rc = cli_fail(CLI_EXIT_USAGE, "prepare: --no-clip and --no-mesh leave nothing to write");
    if (!rc && co.siltex && !co.on)
        rc = cli_fail(CLI_EXIT_USAGE, "prepare: --siltex draws over the outer hull, which --no-clip leaves out");
    if (!rc && co.so.svd > co.so.angles)
        rc = cli_fail(CLI_EXIT_USAGE, "prepare: --siltex-svd %d is more eigenfunctions than --angles %d", co.so.svd,
                      co.so.angles);
    if (!rc && !co.siltex && siltex_opt) rc = cli_fail(CLI_EXIT_USAGE, "prepare: %s goes with --siltex", siltex_opt);
    if (rc) return rc;
    so.target_tris = (uint32_t)args.target;
    if (silk_file_same(in, args.out))
        return cli_fail(CLI_EXIT_USAGE, "prepare: the output would overwrite the input %s", in);
    /* A failed run leaves OUT as it was (written atomically), as every command. */
    co.so.quiet = args.quiet;
    return prepare(in, args.out, &so, args.scale, args.quiet, fit, &co);
}
