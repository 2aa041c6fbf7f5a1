// test_cxx.cpp - the public headers from C++: silk/silk.h, silk/validate.h
// and silk/platform.h compile as C++ and their functions link against
// libsilk.a and libsilk_platform.a (the headers declare them extern "C").
// It loads an octahedron, checks it, renders one smooth frame and counts the
// object's pixels; with an argument PREFIX it also writes PREFIX.png and
// PREFIX.ppm and reads the PNG back (tests/cli/cli_install.sh builds it against
// the installed library with pkg-config).  Ends with "N passed, N failed"
// like tests/check.h, which is C.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "silk/silk.h"
#include "silk/platform.h"
#include "silk/validate.h"

static int passed, failed;

static void check(bool ok, const char *what)
{
    if (ok) {
        passed++;
        std::printf("ok %s\n", what);
    } else {
        failed++;
        std::printf("FAIL %s\n", what);
    }
}

int main(int argc, char **argv)
{
    static const char obj[] =
        "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
        "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    enum { W = 64, H = 48 };
    std::vector<uint8_t> memory(1 << 20), pixels(W * H * 3);

    silk_arena arena;
    silk_arena_init(&arena, memory.data(), memory.size());
    silk_error err;
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    silk_mesh mesh;
    silk_status s = silk_load_mesh(obj, std::strlen(obj), "octahedron.obj", &lo, &arena, &mesh, &err);
    check(s == SILK_OK, "silk_load_mesh");
    check(s == SILK_OK && silk_mesh_validate(&mesh, "octahedron", &err) == SILK_OK, "silk_mesh_validate");

    silk_camera cam;
    std::memset(&cam, 0, sizeof cam);
    cam.eye = silk_v3(SILK_FX_C(3, 1), SILK_FX_C(2, 1), SILK_FX_C(4, 1));
    cam.target = silk_v3(0, 0, 0);
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(35, 1);
    cam.znear = SILK_FX_C(1, 10);
    cam.zfar = SILK_FX_C(100, 1);
    cam.width = W;
    cam.height = H;
    silk_view view;
    check(silk_view_init(&view, &cam, &err) == SILK_OK, "silk_view_init");

    silk_phong phong;
    silk_phong_default(&phong, &view);
    silk_hal hal;
    silk_hal_phong(&hal, &phong);
    silk_target target;
    uint32_t *depth = static_cast<uint32_t *>(silk_arena_array(&arena, W * H, sizeof *depth, SILK_MEM_RASTER));
    silk_target_init(&target, W, H, 0, H, SILK_PIX_RGB888, pixels.data(), depth);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    silk_frame_stats st;
    check(silk_render(&arena, &mesh, &view, &hal, &ro, &target, &st, &err) == SILK_OK, "silk_render");
    int object = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) object += silk_target_get(&target, x, y) != ro.bg_rgb;
    check(st.tris_drawn >= 8 && object > 100, "the frame shows the octahedron");
    check(silk_image_format_for_path("frame.png") == SILK_IMAGE_PNG, "silk/platform.h links too");
    if (argc > 1) {
        std::string png = std::string(argv[1]) + ".png", ppm = std::string(argv[1]) + ".ppm";
        check(silk_png_write(&target, png.c_str(), &err) == SILK_OK, "silk_png_write");
        check(silk_ppm_write(&target, ppm.c_str(), &err) == SILK_OK, "silk_ppm_write");
        uint8_t *rgb = NULL;
        int w = 0, h = 0;
        bool read = silk_png_read(png.c_str(), &rgb, &w, &h, &err) == SILK_OK;
        check(read && w == W && h == H && std::memcmp(rgb, pixels.data(), pixels.size()) == 0,
              "silk_png_read gives the frame back");
        std::free(rgb);
    }

    std::printf("%d passed, %d failed\n", passed, failed);
    return failed != 0;
}
