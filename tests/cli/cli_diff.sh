#!/bin/sh
# cli_diff.sh - `silk diff`: identical renders differ nowhere; a sphere drawn
# larger differs by the ring between the two outlines, so the mean error is
# the gap between the radii and the Hausdorff distance about the same; the
# picture of the differences has the renders' size and only the documented
# colours; unreadable or mismatched images are input errors, bad options
# usage errors, and a failed run leaves no picture behind.
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere --segments 48 --bands 48 -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }

# Orthographic, half height 1.5 and 1.4 on 300x300: disc radii 100 and
# 107.14 px (a little less for the polygon), 7.1 px apart.
"$SILK" render "$sphere" --size 300x300 --ortho 1.5 --mode flat -o "$tmp/a.png"
"$SILK" render "$sphere" --size 300x300 --ortho 1.5 --mode flat -o "$tmp/a2.png"
"$SILK" render "$sphere" --size 300x300 --ortho 1.4 --mode flat -o "$tmp/b.png"

line_re='^diff [^ ]+ [^ ]+ differing=[0-9]+ boundary=[0-9]+ mean_px=([0-9]+\.[0-9]{3}|inf) hausdorff_px=([0-9]+\.[0-9]{3}|inf)$'
field() { sed -E "s/.* $1=([^ ]+).*/\1/" "$out"; }

run_silk diff "$tmp/a.png" "$tmp/a2.png"
check "identical renders: one line" grep -qE "$line_re" "$out"
check "identical renders: nothing differs" grep -q "differing=0 .* mean_px=0.000 hausdorff_px=0.000" "$out"

run_silk diff "$tmp/a.png" "$tmp/b.png" --bg ffffff -o "$tmp/d.png"
check "exit 0, stderr empty" test "$rc" -eq 0 -a ! -s "$err"
check "one parseable line" grep -qE "$line_re" "$out"
mean=$(field mean_px); haus=$(field hausdorff_px); len=$(field boundary)
check "outline length $len ~ 2 pi 100" awk -v l="$len" 'BEGIN { exit !(l > 0.97 * 628.3 && l < 1.03 * 628.3) }'
check "mean error $mean ~ radius gap 7.14" awk -v m="$mean" 'BEGIN { exit !(m > 6.6 && m < 7.6) }'
check "hausdorff $haus ~ radius gap" awk -v h="$haus" 'BEGIN { exit !(h >= 6 && h <= 8.5) }'
check "difference picture is a 300x300 PNG" [ "$(png_size "$tmp/d.png")" = 300x300 ]
# The picture: B contains A, so its non-white pixels are B's object, and
# its blue ones (A's mask is everything against a blue background) are as
# many as the pixels that differ.
differing=$(field differing)
run_silk diff "$tmp/b.png" "$tmp/d.png"
check "picture: grey and blue are B's object" grep -q "differing=0 " "$out"
run_silk diff "$tmp/a.png" "$tmp/d.png" --bg 1e46e0
check "picture: blue pixels ($(field differing)) are the differing ones ($differing)" [ "$(field differing)" = "$differing" ]
run_silk diff "$tmp/b.png" "$tmp/a.png" -o "$tmp/rev.png"
check "reversed: same Hausdorff" grep -q "hausdorff_px=$haus" "$out"

# an image of background only: infinite errors, said as inf
"$SILK" render "$sphere" --size 300x300 --eye 0,0,5 --target 0,0,10 -o "$tmp/empty.png"
run_silk diff "$tmp/a.png" "$tmp/empty.png"
check "empty B: hausdorff inf" grep -qE "differing=[0-9]+ boundary=[0-9]+ mean_px=[0-9.]+ hausdorff_px=inf$" "$out"

# errors
printf 'not a png' >"$tmp/text.png"
"$SILK" render "$sphere" --size 200x100 -o "$tmp/small.png"
head -c 200 "$tmp/a.png" >"$tmp/cut.png"
want="no-such.png: cannot open" expect_input "missing file" diff "$tmp/no-such.png" "$tmp/a.png"
want="not a PNG or binary PPM image" expect_input "not a PNG" diff "$tmp/a.png" "$tmp/text.png"
want="cannot read" expect_input "truncated PNG" diff "$tmp/cut.png" "$tmp/a.png"
want="300x300 but .* 200x100" expect_input "size mismatch" diff "$tmp/a.png" "$tmp/small.png"
expect_usage "one image" diff "$tmp/a.png"
expect_usage "three images" diff "$tmp/a.png" "$tmp/a.png" "$tmp/a.png"
expect_usage "bad --bg" diff "$tmp/a.png" "$tmp/b.png" --bg white
expect_usage "unknown option" diff "$tmp/a.png" "$tmp/b.png" --frobnicate
expect_usage "picture must be PNG" diff "$tmp/a.png" "$tmp/b.png" -o "$tmp/d.ppm"
cp "$tmp/d.png" "$tmp/stale.png"
expect_input "failed run" diff "$tmp/a.png" "$tmp/small.png" -o "$tmp/stale.png"
check "failed run keeps an earlier picture" cmp -s "$tmp/d.png" "$tmp/stale.png"
check "no temporary files left" no_tmp_files "$tmp"
run_silk diff --help
check "help" grep -q "usage: silk diff" "$out"

done_testing
