#!/bin/sh
# cli_stdio.sh - "-" is standard input or output wherever a command reads a
# mesh or an image or writes one; simplify writes PLY for a .ply name; PPM
# is read wherever PNG is (silk diff of the PPM files render writes).
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
"$SILK" gen cone -o "$tmp/cone.obj"
size="--size 160x120"

# ---- meshes from standard input ------------------------------------------------------
"$SILK" render "$sphere" -o "$tmp/file.png" $size
"$SILK" render - -o "$tmp/stdin.png" $size <"$sphere"
check "render - reads the mesh from standard input" cmp -s "$tmp/file.png" "$tmp/stdin.png"
"$SILK" gen sphere -o - | "$SILK" render - -o "$tmp/pipe.png" $size
check "gen -o - | render - gives the same image" cmp -s "$tmp/file.png" "$tmp/pipe.png"
"$SILK" simplify "$tmp/cone.obj" "$tmp/cone.ply" --triangles 40 >/dev/null
"$SILK" render "$tmp/cone.ply" -o "$tmp/ply-file.png" $size
"$SILK" render - -o "$tmp/ply-stdin.png" $size <"$tmp/cone.ply"
check "a PLY from standard input (told by its content)" cmp -s "$tmp/ply-file.png" "$tmp/ply-stdin.png"
"$SILK" info "$sphere" >"$tmp/info-file"
"$SILK" info - <"$sphere" >"$tmp/info-stdin"
check "info - reads standard input" test "$(grep -c '' "$tmp/info-stdin")" -gt 10 -a \
    "$(info_value "$tmp/info-stdin" triangles)" = "$(info_value "$tmp/info-file" triangles)"
check "info names standard input <stdin>" grep -q '^file: *<stdin>' "$tmp/info-stdin"
printf 'v 0 0 0\nf 1 2 3\n' >"$tmp/bad.obj"
want='^silk: <stdin>:2' expect_input "a bad mesh on standard input names <stdin> and the line" render - -o "$tmp/x.png" <"$tmp/bad.obj"
[ -e "$tmp/x.png" ] && fail "no output after a bad mesh" "x.png exists"

# ---- images to standard output ---------------------------------------------------------
"$SILK" render "$sphere" -o - $size >"$tmp/stdout.png"
check "render -o - writes the PNG to standard output" cmp -s "$tmp/file.png" "$tmp/stdout.png"
"$SILK" render "$sphere" -o "$tmp/file.ppm" $size
"$SILK" render "$sphere" -o - --image-format ppm $size >"$tmp/stdout.ppm"
check "render -o - --image-format ppm writes PPM" cmp -s "$tmp/file.ppm" "$tmp/stdout.ppm"
"$SILK" render "$sphere" -o - --bg none $size >"$tmp/alpha.png"
check "render -o - --bg none: an RGBA PNG" test "$(od -An -tu1 -j25 -N1 "$tmp/alpha.png" | tr -d ' ')" = 6
want='image-format' expect_usage "--image-format gif" render "$sphere" -o - --image-format gif
want='image-format' expect_usage "--image-format against the name" render "$sphere" -o "$tmp/a.png" --image-format ppm
check "no file named - appears" test ! -e ./- -a ! -e "$tmp/-"

# An existing output that is not a regular file (a pipe, /dev/null) is
# written as it is, never replaced by a renamed temporary file.
mkfifo "$tmp/fifo.png"
timeout 20 cat "$tmp/fifo.png" >"$tmp/from-fifo.png" &
"$SILK" render "$sphere" -o "$tmp/fifo.png" $size
wait
check "render -o FIFO writes into the pipe" cmp -s "$tmp/file.png" "$tmp/from-fifo.png"
check "the pipe is still a pipe" test -p "$tmp/fifo.png"

# ---- pack to standard output --------------------------------------------------------------
"$SILK" pack "$sphere" -o - >"$tmp/stdout.h"
check "pack -o - writes the header to standard output" grep -q 'static inline silk_status sphere_mesh' "$tmp/stdout.h"
check "pack -o -: symbols from the mesh name, not __mesh" test "$(grep -c '__mesh\|^static const silk_vec3 _' "$tmp/stdout.h")" -eq 0
"$SILK" pack - -o - <"$sphere" >"$tmp/stdin.h"
check "pack - -o -: symbols model_*" grep -q 'static inline silk_status model_mesh' "$tmp/stdin.h"
"$SILK" pack - -o - --name ball <"$sphere" >"$tmp/named.h"
check "pack --name with -o -" grep -q 'static inline silk_status ball_mesh' "$tmp/named.h"
if ${CC:-cc} -std=c11 -Wall -Wextra -Werror -I"$here/../include" -x c -c -o "$tmp/h.o" - 2>"$err" <<EOC
#include "$tmp/stdout.h"
int use(void);
int use(void) { silk_mesh m; sphere_mesh(&m); return (int)m.ntris + sphere_camera(0)->width; }
EOC
then pass "the header from -o - compiles"; else fail "the header from -o - compiles" "$(head -c 300 "$err")"; fi

# ---- simplify -------------------------------------------------------------------------------
"$SILK" simplify "$sphere" "$tmp/s.ply" --triangles 100 >/dev/null
check "simplify OUT.ply writes PLY" test "$(head -n 1 "$tmp/s.ply")" = ply
check "the PLY is ascii with 100 faces" grep -q '^element face 100$' "$tmp/s.ply"
"$SILK" simplify "$sphere" "$tmp/s.obj" --triangles 100 >/dev/null
"$SILK" info "$tmp/s.ply" >"$tmp/i1"
"$SILK" info "$tmp/s.obj" >"$tmp/i2"
check "the PLY loads to the same mesh as the OBJ" test "$(info_value "$tmp/i1" 'bbox max')" = "$(info_value "$tmp/i2" 'bbox max')" -a \
    "$(info_value "$tmp/i1" edges)" = "$(info_value "$tmp/i2" edges)"
"$SILK" simplify - - --triangles 100 <"$sphere" >"$tmp/s-stdout.obj"
same_body() { [ "$(tail -n +2 "$1")" = "$(tail -n +2 "$2")" ]; }
check "simplify - - reads and writes standard streams" same_body "$tmp/s.obj" "$tmp/s-stdout.obj"

# ---- diff reads PPM ---------------------------------------------------------------------------
"$SILK" render "$tmp/cone.obj" -o "$tmp/cone.ppm" $size
"$SILK" render "$tmp/cone.obj" -o "$tmp/cone.png" $size
run_silk diff "$tmp/cone.ppm" "$tmp/cone.png"
check "diff of a PPM and the same PNG: no difference" grep -q 'differing=0 ' "$out"
"$SILK" render "$tmp/cone.obj" -o "$tmp/smooth.ppm" $size --mode smooth
"$SILK" render "$tmp/cone.obj" -o "$tmp/flat.ppm" $size --mode flat
run_silk diff "$tmp/flat.ppm" "$tmp/smooth.ppm"
check "diff of two PPMs ($(cat "$out"))" test "$rc" -eq 0
run_silk diff - "$tmp/cone.png" <"$tmp/cone.ppm"
check "diff - reads one image from standard input" grep -q 'differing=0 ' "$out"
"$SILK" render "$tmp/cone.obj" -o "$tmp/alpha.png" $size --bg none
run_silk diff "$tmp/cone.png" "$tmp/alpha.png"
check "diff: a transparent background is background" grep -q 'differing=0 ' "$out"
printf 'P6\n4 4\n255\nabc' >"$tmp/short.ppm"
want='cut short' expect_input "diff: a truncated PPM" diff "$tmp/short.ppm" "$tmp/cone.png"
printf 'P6\n4 4\n65535\n' >"$tmp/deep.ppm"
want='maxval' expect_input "diff: a 16-bit PPM" diff "$tmp/deep.ppm" "$tmp/cone.png"
printf 'P6\n0 4\n255\n' >"$tmp/empty.ppm"
want='width and height' expect_input "diff: a PPM of width 0" diff "$tmp/empty.ppm" "$tmp/cone.png"
printf 'P6 x' >"$tmp/junk.ppm"
want='header' expect_input "diff: a PPM with a bad header" diff "$tmp/junk.ppm" "$tmp/cone.png"
want='standard input' expect_usage "diff - -" diff - -
want='standard output' expect_usage "diff -o -" diff "$tmp/cone.png" "$tmp/cone.png" -o -

done_testing
