#!/bin/sh
# cli_render.sh - `silk render` end to end: a generated sphere at 16x16 up to
# 2048x2048, perspective and orthographic, PNG and PPM, both pixel formats,
# the eye inside the model, --compare and --wire; the default camera frames
# the model (its area on screen is what the framing rule predicts); renders
# are deterministic; failures leave no partial output and keep an earlier one.
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
"$SILK" gen torus -o "$tmp/torus.obj"

# render_ok NAME OUT WxH ARGS...: exit 0, silent, an image of that size.
render_ok() {
    name=$1; o=$2; size=$3; shift 3
    run_silk render "$@" -o "$o"
    if [ "$rc" -ne 0 ] || [ -s "$err" ] || [ -s "$out" ]; then
        fail "$name" "exit $rc: $(head -c 300 "$err")"; return
    fi
    case "$o" in
    *.png) if is_png "$o" && [ "$(png_size "$o")" = "$size" ]; then pass "$name"; else fail "$name" "not a ${size} PNG: $(hex_head "$o" 24)"; fi ;;
    *.ppm) if [ "$(ppm_size "$o")" = "$size" ]; then pass "$name"; else fail "$name" "not a ${size} PPM: $(hex_head "$o" 16)"; fi ;;
    esac
}

for s in 16x16 64x48 512x512 2048x2048; do
    render_ok "perspective $s png" "$tmp/p$s.png" "$s" "$sphere" --size "$s"
done
render_ok "orthographic 64x48 ppm" "$tmp/o.ppm" 64x48 "$sphere" --size 64x48 --ortho 1.5
render_ok "orthographic 512x512 png" "$tmp/o.png" 512x512 "$sphere" --size 512x512 --ortho auto
render_ok "rgb565 png" "$tmp/c565.png" 64x48 "$sphere" --size 64x48 --format rgb565
render_ok "rgb565 ppm" "$tmp/c565.ppm" 64x48 "$sphere" --size 64x48 --format rgb565
render_ok "flat mode" "$tmp/flat.ppm" 64x48 "$sphere" --size 64x48 --mode flat
render_ok "wireframe" "$tmp/wire.png" 64x48 "$sphere" --size 64x48 --wire
render_ok "compare is twice as wide" "$tmp/cmp.png" 128x48 "$sphere" --size 64x48 --compare
render_ok "1x1" "$tmp/one.ppm" 1x1 "$sphere" --size 1x1
render_ok "tall 8x200" "$tmp/tall.png" 8x200 "$sphere" --size 8x200
render_ok "all options" "$tmp/all.png" 40x30 "$tmp/torus.obj" --size=40x30 --eye 0,3,3 --target 0,0,0 \
    --up 0,1,0 --fov 50 --bg 102030 --crease 30 --scale 2 --mode smooth --tolerance 1 --wire \
    --format rgb888 --arena 8M --normals compute

# The framing rule: orthographic with half height H shows a unit sphere as a
# disc of radius h/(2H) pixels; the coarse mesh covers a little less (the
# pixels drawn: anti-aliased, every pixel the outline touches would count).
bg=00ff00
run_silk render "$sphere" --size 64x64 --ortho 1.5 --bg $bg --aa off -o "$tmp/disc.ppm"
n=$(ppm_count_not "$tmp/disc.ppm" $bg)
exact=$(awk 'BEGIN { r = 64 / 2 / 1.5; printf "%d", 3.14159265 * r * r }')
check "ortho disc area $n px (exact sphere $exact)" awk -v n="$n" -v e="$exact" 'BEGIN { exit !(n > 0.94 * e && n < 1.03 * e) }'

# Default perspective framing: the sphere around the box centre through the
# farthest vertex, enlarged by 5%, just fits the 35 degree view.  For the
# unit sphere that is radius 1.05, so the sphere subtends
# asin(sin(17.5 deg) / 1.05) and covers a disc of radius
# 32 tan(that) / tan(17.5 deg) pixels; --ortho auto shows it with radius
# 32 / 1.05 pixels.
run_silk render "$sphere" --size 64x64 --bg $bg -o "$tmp/frame.ppm"
n=$(ppm_count_not "$tmp/frame.ppm" $bg)
exact=$(awk 'BEGIN { h = 17.5 * 3.14159265 / 180; s = sin(h) / 1.05; a = atan2(s, sqrt(1 - s * s));
                     r = 32 * (sin(a) / cos(a)) / (sin(h) / cos(h)); printf "%d", 3.14159265 * r * r }')
check "default framing covers $n px (exact sphere $exact)" awk -v n="$n" -v e="$exact" 'BEGIN { exit !(n > 0.94 * e && n < 1.03 * e) }'
run_silk render "$sphere" --size 64x64 --bg $bg --ortho auto -o "$tmp/frame-o.ppm"
n=$(ppm_count_not "$tmp/frame-o.ppm" $bg)
exact=$(awk 'BEGIN { r = 32 / 1.05; printf "%d", 3.14159265 * r * r }')
check "--ortho auto covers $n px (exact sphere $exact)" awk -v n="$n" -v e="$exact" 'BEGIN { exit !(n > 0.94 * e && n < 1.03 * e) }'
# Wide and tall images: the smaller field of view decides, so the sphere
# spans the same number of pixels as in the square image (within 6%).
square=$(ppm_count_not "$tmp/frame.ppm" $bg)
for s in 128x64 64x128; do
    run_silk render "$sphere" --size $s --bg $bg -o "$tmp/frame-$s.ppm"
    n=$(ppm_count_not "$tmp/frame-$s.ppm" $bg)
    check "$s frames like 64x64 ($n px, square $square)" awk -v n="$n" -v e="$square" 'BEGIN { exit !(n > 0.94 * e && n < 1.06 * e) }'
done

# The eye inside the sphere, looking out: the inside covers every pixel.
run_silk render "$sphere" --size 32x32 --eye 0,0,0 --target 0,0,-1 --bg $bg -o "$tmp/inside.ppm"
check "eye inside the model: exit 0" test "$rc" -eq 0
n=$(ppm_count_not "$tmp/inside.ppm" $bg)
check "eye inside the model sees the inside everywhere ($n of 1024 px)" test "$n" -eq 1024
run_silk render "$tmp/torus.obj" --size 48x48 --eye 1,0,0 --target 0,0,0 -o "$tmp/inside-torus.png"
check "eye inside the torus tube" test "$rc" -eq 0

# The eye as far as the options allow (28378 units away), the narrowest
# field of view: a sphere of radius 200 subtends 0.404 of the 0.5 degree half
# view, a disc of radius 12.9 px (523 px) in 32x32.
run_silk render "$sphere" --scale 200 --size 32x32 --eye 16384,16384,16384 --fov 1 --bg $bg -o "$tmp/far.ppm"
n=$(ppm_count_not "$tmp/far.ppm" $bg)
check "eye at the far corner: exit $rc, $n px drawn (523 exact)" test "$rc" -eq 0 -a "$n" -gt 480 -a "$n" -lt 560
run_silk render "$sphere" --size 32x32 --eye -16384,0,0 --fov 175 -o "$tmp/far2.png"
check "far eye with the widest field of view" test "$rc" -eq 0

# rgb565 widened: in every channel the low bits repeat the high bits
bit_replicated() {
    od -An -v -tu1 -j"$(head -n 3 "$1" | wc -c)" "$1" | awk '
        { for (i = 1; i <= NF; i++) { k++; v = $i
              if (k % 3 == 2) { if (v % 4 != int(v / 64)) bad++ } else if (v % 8 != int(v / 32)) bad++ } }
        END { exit !(k > 0 && bad == 0) }'
}
run_silk render "$sphere" --size 16x16 --format rgb565 -o "$tmp/565.ppm"
check "rgb565 output is bit-replicated" bit_replicated "$tmp/565.ppm"

# Same input, same bytes.
run_silk render "$tmp/torus.obj" --size 96x64 -o "$tmp/d1.ppm"
run_silk render "$tmp/torus.obj" --size 96x64 -o "$tmp/d2.ppm"
check "deterministic" cmp -s "$tmp/d1.ppm" "$tmp/d2.ppm"

# Flat and smooth differ (the silhouette is smoothed) but cover similar areas.
run_silk render "$sphere" --size 128x128 --mode flat --bg $bg -o "$tmp/f.ppm"
run_silk render "$sphere" --size 128x128 --mode smooth --bg $bg -o "$tmp/s.ppm"
differ() { ! cmp -s "$1" "$2"; }
check "smooth differs from flat" differ "$tmp/f.ppm" "$tmp/s.ppm"
nf=$(ppm_count_not "$tmp/f.ppm" $bg)
ns=$(ppm_count_not "$tmp/s.ppm" $bg)
check "smooth covers more than flat ($ns > $nf px)" test "$ns" -gt "$nf"

# ---- failures leave the output as it was ------------------------------------------
o=$tmp/fail.png
cp "$tmp/o.ppm" "$tmp/good.ppm"
want='cannot open: No such file or directory' expect_input "missing mesh" render "$tmp/nope.obj" -o "$tmp/good.ppm"
check "missing mesh keeps an earlier output" cmp -s "$tmp/o.ppm" "$tmp/good.ppm"
want='--mode must be' expect_usage "a typo in --mode" render "$sphere" --mode smoth -o "$tmp/good.ppm"
check "a typo in --mode keeps an earlier output" cmp -s "$tmp/o.ppm" "$tmp/good.ppm"
want='size' expect_usage "bad size" render "$sphere" --size 0x5 -o "$o"
check "usage error writes nothing" test ! -e "$o"
cp "$tmp/o.ppm" "$tmp/input.ppm"
expect_input "an image as the mesh" render "$tmp/input.ppm" -o "$tmp/input.ppm"
check "a failed render never removes its input" cmp -s "$tmp/o.ppm" "$tmp/input.ppm"
# a missing directory is named, before any work
want="-o $tmp/no/dir/x.png: the directory $tmp/no/dir does not exist" expect_input "missing output directory" render "$sphere" -o "$tmp/no/dir/x.png"
want="the directory $tmp/no does not exist" expect_input "missing --turntable directory" render "$sphere" -o "$tmp/no/t%d.png" --turntable 2
want='unknown image format' expect_usage "unknown extension" render "$sphere" -o "$tmp/x.jpg"
check "nothing written for an unknown extension" test ! -e "$tmp/x.jpg"
mkdir "$tmp/dir.png"
want='Is a directory' expect_input "output is a directory" render "$sphere" -o "$tmp/dir.png"
check "the directory is kept" test -d "$tmp/dir.png"
want='arena' expect_input "arena too small" render "$sphere" --arena 4K -o "$o"
check "no output after a small arena" test ! -e "$o"

# An arena that holds the mesh and the frame buffer but little scratch: the
# frame is drawn unsmoothed with a one-line warning, or (when even that does
# not fit) one error line and no image; never a crash or a partial file.
# (Without anti-aliasing, whose outline pixels take what the frame leaves:
# with too little they stay aliased and the frame is still smoothed.)
run_silk info "$sphere" --size 64x64 --aa off
loaded=$(info_value "$out" "  after loading")
scratch=$(info_value "$out" "  frame bytes")
small=$(( (loaded + 64 * 64 * 7 + scratch / 2) / 1024 + 1 ))K
run_silk render "$sphere" --size 64x64 --aa off --arena "$small" -o "$o"
if { [ "$rc" -eq 0 ] && is_png "$o" && grep -q '^silk: warning: the arena ran out' "$err"; } ||
   { [ "$rc" -eq 1 ] && one_error_line && [ ! -e "$o" ]; }; then
    pass "scarce arena ($small): exit $rc, $(head -c 80 "$err")"
else
    fail "scarce arena ($small)" "exit $rc: $(cat "$err")"
fi
rm -f "$o"
# With anti-aliasing, an arena a little larger than what loading and the
# frame buffer take leaves part of the outline aliased, and says so (the
# outline takes what the frame leaves, so the window is a kilobyte or two).
for k in $(seq 48 64); do
    run_silk render "$sphere" --size 64x64 --arena ${k}K -o "$o"
    grep -q '^silk: warning: the arena ran short for anti-aliasing' "$err" && break
done
check "an arena short for anti-aliasing: one warning line, the image written" \
    test "$rc" -eq 0 -a "$(wc -l <"$err")" -eq 1 -a -s "$o"
grep -q 'anti-aliasing' "$err" || fail "no arena size between 48K and 64K left the outline aliased" "$(cat "$err")"
rm -f "$o"
run_silk render "$sphere" --size 64x64 -o "$o"
check "the automatic arena draws the frame fully (no warning)" test "$rc" -eq 0 -a ! -s "$err"

# A write that fails half way (file size limit, like a full disk): exit 1,
# no file at all, not even a temporary one.
for ext in png ppm; do
    (ulimit -f 8; trap '' XFSZ; exec "$SILK" render "$sphere" --size 256x256 -o "$tmp/big.$ext") >"$out" 2>"$err"
    rc=$?
    if [ "$rc" -eq 1 ] && one_error_line && grep -q 'cannot write' "$err" && [ ! -e "$tmp/big.$ext" ]; then
        pass "write failure leaves no $ext"
    else
        fail "write failure leaves no $ext" "exit $rc: $(cat "$err")"
    fi
done
check "no temporary files left" no_tmp_files "$tmp"

done_testing
