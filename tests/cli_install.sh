#!/bin/sh
# cli_install.sh - what `make install` gives a user: into a temporary
# PREFIX, the libraries (libsilk.a, libsilk_platform.a), the headers
# (silk/platform.h among them), silk.pc and silk-platform.pc, the command,
# its manual page and the licence.  A small program built with
#   cc prog.c $(pkg-config --cflags --libs silk-platform)
# renders a generated sphere and writes it as PNG and PPM with the
# installed writers, and reads the PNG back; the installed `silk` works
# from another directory (gen, render, info, profile, help --man).
. "$(dirname "$0")/shlib.sh"

root=$(cd "$here/.." && pwd)
if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: make install is checked in the normal pass (a sanitizer build is not installed)"
    done_testing
    exit 0
fi
command -v pkg-config >/dev/null 2>&1 || { echo "skip: pkg-config is not installed"; done_testing; exit 0; }

prefix=$tmp/prefix
case "$build" in /*) b=$build ;; *) b=$root/$build ;; esac
make -s -C "$root" BUILD="$b" PREFIX="$prefix" install >"$tmp/install.log" 2>&1
check "make install PREFIX=... succeeds ($(tail -n 3 "$tmp/install.log"))" test $? -eq 0
for f in lib/libsilk.a lib/libsilk_platform.a lib/pkgconfig/silk.pc lib/pkgconfig/silk-platform.pc \
         include/silk/silk.h include/silk/platform.h include/silk/validate.h bin/silk \
         share/man/man1/silk.1 share/doc/silk/LICENSE; do
    check "installed $f" test -s "$prefix/$f"
done
check "the installed page is silk help --man" sh -c "'$prefix/bin/silk' help --man | cmp -s - '$prefix/share/man/man1/silk.1'"

cat >"$tmp/prog.c" <<'PROG'
/* Renders a sphere OBJ with the installed library, writes PNG and PPM. */
#include <stdio.h>
#include <stdlib.h>
#include <silk/silk.h>
#include <silk/platform.h>

enum { W = 96, H = 72 };
static uint8_t memory[4 << 20], pixels[W * H * 3];

int main(int argc, char **argv)
{
    silk_error err;
    uint8_t *text;
    size_t len;
    if (argc < 4 || silk_file_read(argv[1], &text, &len, &err) != SILK_OK) {
        fprintf(stderr, "%s\n", argc < 4 ? "usage: prog MESH OUT.png OUT.ppm" : err.msg);
        return 1;
    }
    silk_arena arena;
    silk_arena_init(&arena, memory, sizeof memory);
    silk_load_opts lo;
    silk_load_opts_default(&lo);
    silk_mesh mesh;
    silk_camera cam = { 0 };
    cam.eye = silk_v3(SILK_FX_C(3, 1), SILK_FX_C(2, 1), SILK_FX_C(4, 1));
    cam.up = silk_v3(0, SILK_FX_ONE, 0);
    cam.fov_deg = SILK_FX_C(35, 1);
    cam.znear = SILK_FX_C(1, 10);
    cam.zfar = SILK_FX_C(100, 1);
    cam.width = W;
    cam.height = H;
    silk_view view;
    silk_phong phong;
    silk_hal hal;
    silk_target target;
    silk_render_opts ro;
    silk_frame_stats st;
    silk_render_opts_default(&ro);
    int ok = silk_load_mesh(text, len, argv[1], &lo, &arena, &mesh, &err) == SILK_OK &&
             silk_view_init(&view, &cam, &err) == SILK_OK;
    free(text);
    if (ok) {
        silk_phong_default(&phong, &view);
        silk_hal_phong(&hal, &phong);
        uint32_t *depth = silk_arena_array(&arena, W * H, sizeof *depth, SILK_MEM_RASTER);
        silk_target_init(&target, W, H, 0, H, SILK_PIX_RGB888, pixels, depth);
        ok = silk_render(&arena, &mesh, &view, &hal, &ro, &target, &st, &err) == SILK_OK &&
             silk_png_write(&target, argv[2], &err) == SILK_OK && silk_ppm_write(&target, argv[3], &err) == SILK_OK;
    }
    uint8_t *rgb = NULL;
    int w = 0, h = 0;
    if (ok) ok = silk_png_read(argv[2], &rgb, &w, &h, &err) == SILK_OK && w == W && h == H;
    free(rgb);
    if (!ok) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    printf("%u triangles drawn\n", st.tris_drawn);
    return 0;
}
PROG
PKG_CONFIG_PATH=$prefix/lib/pkgconfig
export PKG_CONFIG_PATH
flags=$(pkg-config --cflags --libs silk-platform 2>"$err")
check "pkg-config silk-platform ($flags$(head -c 200 "$err"))" test -n "$flags"
${CC:-cc} -std=c11 -Wall -Wextra -Wpedantic -Werror "$tmp/prog.c" -o "$tmp/prog" $flags 2>"$err"
check "a program builds against the installed library ($(head -c 300 "$err"))" test $? -eq 0

# From a directory with no silk sources in sight, with the installed tools only.
mkdir -p "$tmp/elsewhere"
cd "$tmp/elsewhere" || exit 1
PATH=$prefix/bin:$PATH
"$prefix/bin/silk" gen sphere -o sphere.obj >"$out" 2>"$err"
check "silk gen from another directory" test $? -eq 0 -a -s sphere.obj
"$tmp/prog" sphere.obj prog.png prog.ppm >"$out" 2>"$err"
check "the program renders and writes PNG and PPM ($(cat "$out" "$err" | head -c 200))" \
    test $? -eq 0 -a -s prog.png -a -s prog.ppm
check "its PNG is a PNG" is_png prog.png
check "its PPM is 96x72" test "$(ppm_size prog.ppm)" = 96x72
"$prefix/bin/silk" render sphere.obj -o r.png --size 96x72 >"$out" 2>"$err"
check "silk render from another directory" test $? -eq 0 -a -s r.png
"$prefix/bin/silk" info sphere.obj >"$out" 2>"$err"
check "silk info from another directory" test $? -eq 0 -a -s "$out"
"$prefix/bin/silk" profile sphere.obj --board host --csv p.csv >"$out" 2>"$err"
check "silk profile --board host from another directory ($(head -c 200 "$err"))" \
    grep -qE '^footprint host sphere ram_total_bytes=[0-9]+ model_bytes=[0-9]+$' "$out"
check "silk profile writes its CSV" grep -q '^ram,ram total,' p.csv
"$prefix/bin/silk" profile sphere.obj --board mps2-an385 >"$out" 2>"$err"
check "silk profile of a firmware board points at make profile ($(head -c 200 "$err"))" \
    test $? -eq 2 -a "$(wc -l <"$err")" -eq 1 && grep -q 'make profile PROFILE_BOARD=mps2-an385' "$err"
if command -v man >/dev/null 2>&1; then
    MANPATH=$prefix/share/man LC_ALL=C MANWIDTH=80 man silk >"$out" 2>"$err"
    check "man silk reads the installed page" grep -q 'silk render' "$out"
fi
cd "$root" || exit 1

done_testing
