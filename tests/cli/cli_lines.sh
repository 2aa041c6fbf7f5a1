#!/bin/sh
# cli_lines.sh - `silk render --lines over|only` and `--lines-polygonal`
# (tests/core/test_lines.c checks the pixels): each renders; lines alone are an
# outline, not the filled object; over the shading they add no more than
# a thin rim of pixels outside it; the smooth and the polygonal outlines
# differ but are the same shape; a bad value is a usage error.
. "$(dirname "$0")/../shlib.sh"

cyl=$tmp/cyl.obj
"$SILK" gen cylinder -o "$cyl" || { fail "gen cylinder" "exit $?"; done_testing; exit 1; }
opts="--size 160x160 --eye 2.5,3.5,4"

run_silk render "$cyl" $opts -o "$tmp/plain.png"
check "plain render" test "$rc" -eq 0
run_silk render "$cyl" $opts --lines over -o "$tmp/over.png"
check "--lines over: exit 0, stderr empty" test "$rc" -eq 0 -a ! -s "$err"
run_silk render "$cyl" $opts --lines only -o "$tmp/only.png"
check "--lines only: exit 0" test "$rc" -eq 0
run_silk render "$cyl" $opts --lines-polygonal --lines only --mode flat -o "$tmp/poly.png"
check "--lines-polygonal: exit 0" test "$rc" -eq 0

# `silk diff --bg ffffff` takes every non-white pixel as object: the lines
# alone make a thin outline, so their "object" is far smaller than the
# shaded cylinder's, and adding lines over the shading changes the mask by
# at most the pixels just outside the outline.
run_silk diff "$tmp/plain.png" "$tmp/only.png" --bg ffffff
check "lines only: an outline, not a filled shape" grep -qE "differing=[0-9]{4,}" "$out"
run_silk diff "$tmp/plain.png" "$tmp/over.png" --bg ffffff
over=$(sed -E 's/.* differing=([0-9]+) .*/\1/' "$out")
check "lines over: at most the outline's width added ($over px)" test "$over" -lt 600
run_silk diff "$tmp/only.png" "$tmp/poly.png" --bg ffffff
check "smooth and polygonal outlines differ" grep -qvE "differing=0 " "$out"
check "... and are about the same shape" grep -qE "hausdorff_px=[0-2]\." "$out"

want='--lines must be over or only'
expect_usage "--lines bad value" render "$cyl" -o "$tmp/x.png" --lines sideways
check "no image after a usage error" test ! -e "$tmp/x.png"
done_testing
