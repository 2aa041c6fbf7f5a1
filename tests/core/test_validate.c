/*
 * test_validate.c - silk_mesh_validate (silk/validate.h): every mesh silk
 * loads passes it, and each kind of damage a packed model can carry is
 * caught with its own message, before the renderer would have indexed an
 * array with it.
 */
#include <string.h>
#include "check.h"
#include "silk/silk.h"
#include "silk/validate.h"
#include "support/scene.h"

static unsigned char arena_mem[4 << 20];

static silk_status load(const char *text, silk_arena *a, silk_mesh *m, silk_error *err)
{
    silk_arena_init(a, arena_mem, sizeof arena_mem);
    silk_status st = silk_load_obj(text, strlen(text), "v.obj", NULL, a, m, err);
    if (st == SILK_OK) st = silk_vis_build(m, NULL, a, err);
    return st;
}

/* Every kind of mesh the loaders make is accepted. */
TEST(loaded_meshes_pass)
{
    static const char *const texts[] = {
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 1 5\nf 3 3 3\n",
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\ns 1\nf 1/1/1 3/3/1 2/2/1\n"
         "s 2\nf 1/1/1 2/2/1 4/3/1\nf 1/2 4/3 3/1\nf 2 3 4\nv 9 9 9\n"),
    };
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        silk_arena a;
        silk_mesh m;
        silk_error err;
        CHECKF(load(texts[i], &a, &m, &err) == SILK_OK, "mesh %zu: %s", i, err.msg);
        CHECKF(silk_mesh_validate(&m, "v.obj", &err) == SILK_OK, "mesh %zu: %s", i, err.msg);
        m.vis = NULL;
        CHECKF(silk_mesh_validate(&m, NULL, &err) == SILK_OK, "mesh %zu without hierarchy: %s", i, err.msg);
    }
    ts_mesh tm = { 0 };
    ts_sphere(&tm, 24, 16, 1, 0, 0, 0);
    silk_arena a;
    silk_mesh m;
    silk_error err;
    silk_arena_init(&a, arena_mem, sizeof arena_mem);
    CHECK(ts_build(&tm, &a, &m, &err) == SILK_OK && silk_vis_build(&m, NULL, &a, &err) == SILK_OK);
    CHECK(silk_mesh_validate(&m, "sphere", &err) == SILK_OK);
    ts_mesh_free(&tm);
}

/* One damaged word at a time, each restored afterwards. */
TEST(damage_is_caught)
{
    silk_arena a;
    silk_mesh m;
    silk_error err;
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 1\n"
               "f 1/1 3/2 2/1\nf 1/1 2/1 4/2\nf 1/2 4/1 3/1\nf 2/1 3/1 4/2\n",
               &a, &m, &err) == SILK_OK);
    CHECK(silk_mesh_validate(&m, "p", &err) == SILK_OK);
    silk_vis *vis = (silk_vis *)m.vis;
    silk_vis_node *node = (silk_vis_node *)vis->node;
    CHECK(vis->nnodes >= 1);

#define EXPECT(lvalue, bad, want)                                                                     \
    do {                                                                                              \
        __typeof__(lvalue) saved_ = (lvalue);                                                         \
        (lvalue) = (bad);                                                                             \
        silk_status st_ = silk_mesh_validate(&m, "p", &err);                                          \
        CHECKF(st_ == SILK_ERR_PARSE && strstr(err.msg, want) != NULL && strncmp(err.msg, "p: ", 3) == 0, \
               "%s = %s: status %d \"%s\", want \"%s\"", #lvalue, #bad, (int)st_, err.msg, want);      \
        (lvalue) = saved_;                                                                            \
    } while (0)

    EXPECT(m.tri[4], 7, "triangle 1 uses vertex 7 (4 vertices)");
    EXPECT(m.tri[4], SILK_NO_INDEX, "triangle 1 uses vertex");
    EXPECT(m.tri_normal[0], m.nnormals, "triangle 0 uses normal");
    EXPECT(m.tri_normal[0], m.tri_normal[1], "belongs to vertex");
    EXPECT(m.normal_vertex[0], 9, "normal 0 belongs to vertex 9");
    EXPECT(m.tri_uv[2], 2, "texture coordinate 2 (2 given)");
    EXPECT(m.tri_edge[0], m.nedges, "uses edge");
    EXPECT(m.tri_edge[0], m.tri_edge[1], "is not its edge");
    EXPECT(m.edge[0].v[0], m.edge[0].v[1] + 1, "edge 0");
    EXPECT(m.edge[0].t[0], m.ntris, "its triangle 4 does not use it");
    EXPECT(m.edge[0].t[1], 3, "its triangle 3 does not use it");
    EXPECT(m.vert_edge_start[0], 1, "start at 1, not 0");
    EXPECT(m.vert_edge_start[2], m.vert_edge_start[1] - 1, "vertex-edge list of vertex 1");
    EXPECT(m.vert_edge_start[m.nverts], m.vert_edge_start[m.nverts] - 1, "edge ends");
    EXPECT(m.vert_edge[0], m.nedges, "which does not end there");
    EXPECT(m.vert_edge[0], m.vert_edge[m.vert_edge_start[m.nverts] - 1], "which does not end there");
    EXPECT(m.edge_feature[0], m.nfeature_edges + 1, "feature segment");
    EXPECT(m.pos[2].y, SILK_COORD_MAX + 1, "vertex 2 is outside +-1024");
    EXPECT(m.normal[1], silk_v3(2 * SILK_FX_ONE, 0, 0), "normal 1 is not of unit length");
    EXPECT(m.normal[1], silk_v3(0, 0, 0), "not of unit length");
    EXPECT(node[0].skip, 0, "visibility node 0 skips to 0");
    EXPECT(node[0].skip, vis->nnodes + 1, "skips to");
    EXPECT(node[vis->nnodes - 1].first, m.nnormals + 1, "holds normals");
    EXPECT(vis->scale_log2, 63, "visibility scale 2^63");
    EXPECT(m.pos, NULL, "an array is missing");
    EXPECT(m.vert_edge, NULL, "an array is missing");
    EXPECT(m.uv, NULL, "texture coordinates (2)");
    EXPECT(m.feature, NULL, "feature edges but no feature segments");
    EXPECT(m.ntris, 0, "empty mesh");
    EXPECT(m.nverts, 3, "vertex 3 (3 vertices)");
    EXPECT(m.nnormals, 1, "normals)");
    EXPECT(m.nedges, m.nfeature_edges - 1, "feature edges of");
    EXPECT(m.nuvs, 1, "texture coordinate 1 (1 given)");
    EXPECT(m.nfeature_edges, m.nedges + 1, "feature edges of");
    EXPECT(m.ntris, (1u << 28) + 1, "more than the");
#undef EXPECT
    /* a hierarchy for other normals is not used, so not checked */
    vis->nnormals++;
    node[0].skip = 0;
    CHECK(silk_mesh_validate(&m, "p", &err) == SILK_OK);
    CHECK(silk_mesh_validate(NULL, "p", &err) == SILK_ERR_ARG);
    /* and nothing was left damaged */
    CHECK(silk_mesh_validate(&m, "p", &err) == SILK_OK);
}

/* A packed mesh has neither tri_edge nor edge_feature (silk pack): the
 * renderer finds the edges from the vertex-edge lists and counts the
 * feature segments, which must give the loader's arrays exactly; the
 * validator checks what those lookups rely on. */
TEST(packed_form_without_tri_edge)
{
    silk_arena a;
    silk_mesh m;
    silk_error err;
    /* a tetrahedron: every edge is a crease, so every edge has a segment */
    CHECK(load("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", &a, &m, &err) ==
          SILK_OK);
    CHECK(m.nfeature_edges > 0);
    silk_mesh p = m;
    p.tri_edge = NULL;
    p.edge_feature = NULL;
    int same = 1;
    for (uint32_t t = 0; t < m.ntris; t++)
        for (uint32_t k = 0; k < 3; k++) same &= silk_mesh_tri_edge(&p, t, k) == m.tri_edge[3 * t + k];
    for (uint32_t e = 0; e < m.nedges; e++) same &= silk_mesh_edge_feature(&p, e) == m.edge_feature[e];
    CHECK(same);
    CHECK(silk_mesh_validate(&p, "p", &err) == SILK_OK);
    /* a side whose corners no edge joins, and more feature edges than segments */
    silk_index saved = p.vert_edge[0];
    p.vert_edge[0] = p.vert_edge[1];
    CHECK(silk_mesh_validate(&p, "p", &err) == SILK_ERR_PARSE && strstr(err.msg, "no edge joins its corners"));
    p.vert_edge[0] = saved;
    p.nfeature_edges--;
    CHECK(silk_mesh_validate(&p, "p", &err) == SILK_ERR_PARSE && strstr(err.msg, "feature segments"));
    p.nfeature_edges++;
    CHECK(silk_mesh_validate(&p, "p", &err) == SILK_OK);
}

int main(void)
{
    RUN(loaded_meshes_pass);
    RUN(damage_is_caught);
    RUN(packed_form_without_tri_edge);
    return check_done();
}
