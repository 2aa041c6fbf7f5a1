#!/bin/sh
# cli_sheet.sh - frame series of `silk render` (docs/viewer.md):
#   --turntable N -o turn_%03d.ppm writes N numbered frames: frame 0 is the
#   plain render byte for byte, and with --eye 0,0,4 frame 1 of 4 is the
#   plain render from --eye 4,0,0 (a quarter turn about +y);
#   --modes LIST --sheet lays frames out in one labelled image: each cell
#   holds exactly the plain render of its mode, labels and title are drawn;
#   --zoom centres the view on a silhouette point (object on one side,
#   background on the other);
#   bad combinations and values are usage errors, and a failed series leaves
#   no frames behind.
. "$(dirname "$0")/shlib.sh"

"$SILK" gen sphere -o "$tmp/sphere.obj" >/dev/null || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
sphere=$tmp/sphere.obj

# The pixels of rows [Y0, Y0+H) and columns [X0, X0+W) of a P6 file, one
# "R G B" triple per line.
ppm_rect() {
    f=$1; x0=$2; y0=$3; w=$4; h=$5
    fw=$(ppm_size "$f" | cut -dx -f1)
    hdr=$(head -n 3 "$f" | wc -c)
    od -An -v -tu1 -w3 -j"$hdr" "$f" |
        awk -v fw="$fw" -v x0="$x0" -v y0="$y0" -v w="$w" -v h="$h" \
            '{ x = (NR - 1) % fw; y = int((NR - 1) / fw) } x >= x0 && x < x0 + w && y >= y0 && y < y0 + h { print $1, $2, $3 }'
}
same_pixels() { cmp -s "$1" "$2"; }
ppm_pixel() {
    w=$(ppm_size "$1" | cut -dx -f1)
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -tu1 -j$((hdr + ($3 * w + $2) * 3)) -N3 "$1" | awk '{ print $1, $2, $3 }'
}

# ---- turntables ------------------------------------------------------------------

run_silk render "$sphere" --size 64x48 --turntable 5 -o "$tmp/turn_%03d.ppm"
check "turntable 5: exit 0, silent" test "$rc" -eq 0 -a ! -s "$err"
n=0
for k in 000 001 002 003 004; do [ "$(ppm_size "$tmp/turn_$k.ppm")" = 64x48 ] && n=$((n + 1)); done
check "turntable 5: five 64x48 frames turn_000 .. turn_004 ($n)" test "$n" -eq 5
check "turntable 5: no sixth frame" test ! -e "$tmp/turn_005.ppm"
"$SILK" render "$sphere" --size 64x48 -o "$tmp/plain.ppm"
check "turntable frame 0 is the plain render" cmp -s "$tmp/turn_000.ppm" "$tmp/plain.ppm"
check "turntable frames differ" test "$(cmp -l "$tmp/turn_000.ppm" "$tmp/turn_002.ppm" 2>/dev/null | wc -l)" -gt 10

"$SILK" gen cone -o "$tmp/cone.obj" >/dev/null
run_silk render "$tmp/cone.obj" --size 64x48 --eye 0,0,4 --target 0,0,0 --turntable 4 -o "$tmp/q%d.ppm"
"$SILK" render "$tmp/cone.obj" --size 64x48 --eye 4,0,0 --target 0,0,0 -o "$tmp/side.ppm"
check "turntable: a quarter turn about +y is --eye 4,0,0" cmp -s "$tmp/q1.ppm" "$tmp/side.ppm"

run_silk render "$sphere" --size 48x36 --turntable 3 --sheet -o "$tmp/turn-sheet.png"
check "turntable --sheet writes one PNG" is_png "$tmp/turn-sheet.png"
check "turntable --sheet writes no frames" test ! -e "$tmp/turn-sheet0.png"

# ---- contact sheets -----------------------------------------------------------------

run_silk render "$sphere" --size 100x80 --modes flat,smooth,blend,pn2 --sheet -o "$tmp/modes.ppm"
check "modes sheet: exit 0, silent ($(head -c 200 "$err"))" test "$rc" -eq 0 -a ! -s "$err"
# Layout (tools/image/sheet.h): a 6 px gap around and between cells, a title line
# of 9 px + gap, two 9 px label lines + 4 under each cell (font scale 1
# below 240 px cells): 4 cells of 100 px, one row of 80.
check "modes sheet: 4 cells side by side ($(ppm_size "$tmp/modes.ppm"))" test "$(ppm_size "$tmp/modes.ppm")" = 430x129
for m in flat:0 smooth:1 blend:2 pn2:3; do
    mode=${m%%:*}; col=${m#*:}
    # one mode without --sheet is a plain frame of that mode
    "$SILK" render "$sphere" --size 100x80 --modes "$mode" -o "$tmp/one.ppm"
    ppm_rect "$tmp/one.ppm" 0 0 100 80 >"$tmp/want"
    ppm_rect "$tmp/modes.ppm" $((6 + 106 * col)) 21 100 80 >"$tmp/got"
    check "modes sheet: cell $col is the $mode render" same_pixels "$tmp/got" "$tmp/want"
    # its label: dark text in the two lines under the cell
    n=$(ppm_rect "$tmp/modes.ppm" $((6 + 106 * col)) 104 100 20 | grep -c '^32 32 32$')
    check "modes sheet: cell $col has a label ($n text px)" test "$n" -gt 60
done
"$SILK" render "$sphere" --size 100x80 --mode flat -o "$tmp/flat.ppm"
"$SILK" render "$sphere" --size 100x80 --modes flat -o "$tmp/one.ppm"
check "--modes flat is --mode flat" cmp -s "$tmp/flat.ppm" "$tmp/one.ppm"
"$SILK" render "$sphere" --size 100x80 --modes blend -o "$tmp/blend.ppm"
check "--modes blend is not flat" test "$(cmp -l "$tmp/flat.ppm" "$tmp/blend.ppm" 2>/dev/null | wc -l)" -gt 10
n=$(ppm_rect "$tmp/modes.ppm" 0 0 430 20 | grep -c '^0 0 0$')
check "modes sheet: a title ($n px)" test "$n" -gt 100
flat_label=$(ppm_rect "$tmp/modes.ppm" 6 104 100 20 | cksum)
smooth_label=$(ppm_rect "$tmp/modes.ppm" 112 104 100 20 | cksum)
check "modes sheet: labels differ per mode" test "$flat_label" != "$smooth_label"

run_silk render "$sphere" --size 60x40 --modes flat,smooth --turntable 3 --sheet -o "$tmp/grid.ppm"
# 2 columns of 60, 3 rows of 40 + 22 + 6
check "modes x turntable: modes across, views down ($(ppm_size "$tmp/grid.ppm"))" test "$(ppm_size "$tmp/grid.ppm")" = 138x225

# ---- close-up ----------------------------------------------------------------------

run_silk render "$sphere" --size 80x60 --zoom 5 --mode flat -o "$tmp/zoom.ppm"
check "zoom: exit 0" test "$rc" -eq 0
left=$(ppm_pixel "$tmp/zoom.ppm" 30 30)
right=$(ppm_pixel "$tmp/zoom.ppm" 50 30)
check "zoom: centred on the silhouette (left $left, right $right)" test "$left" != "255 255 255" -a "$right" = "255 255 255"
n=$(ppm_count_not "$tmp/zoom.ppm" ffffff)
check "zoom: about half object ($n of 4800 px)" test "$n" -gt 1200 -a "$n" -lt 3600

# ---- errors ------------------------------------------------------------------------

want='frame number' expect_usage "turntable needs a numbered -o" render "$sphere" --turntable 4 -o "$tmp/t.png"
want='needs --sheet' expect_usage "several modes need --sheet" render "$sphere" --modes flat,smooth -o "$tmp/t.png"
want='is not a mode' expect_usage "unknown mode" render "$sphere" --modes flat,wobbly --sheet -o "$tmp/t.png"
want='is not a mode' expect_usage "empty mode" render "$sphere" --modes flat,,smooth --sheet -o "$tmp/t.png"
want='is not a mode' expect_usage "pn level out of range" render "$sphere" --modes pn99 --sheet -o "$tmp/t.png"
want='between 1 and' expect_usage "turntable 0" render "$sphere" --turntable 0 -o "$tmp/t%d.png"
want='between 1 and' expect_usage "turntable 361" render "$sphere" --turntable 361 -o "$tmp/t%d.png"
want='--compare' expect_usage "compare with a sheet" render "$sphere" --compare --sheet -o "$tmp/t.png"
want='between 1 and 64' expect_usage "zoom below 1" render "$sphere" --zoom 0.5 -o "$tmp/t.png"
want='frame number' expect_usage "pattern with %s" render "$sphere" --turntable 2 -o "$tmp/t%s.png"
want='frame number' expect_usage "pattern with two numbers" render "$sphere" --turntable 2 -o "$tmp/t%d%d.png"
rm -f "$tmp"/gone*
expect_input "turntable of a missing mesh" render "$tmp/missing.obj" --turntable 3 -o "$tmp/gone%d.png"
check "a missing mesh writes no frames" test -z "$(ls "$tmp" | grep '^gone')"
# frame 2's name is taken by a directory: frames 0 and 1 were written, then
# the series failed, and they are gone again
mkdir "$tmp/gone2.ppm"
expect_input "turntable that cannot write frame 2" render "$sphere" --size 32x24 --turntable 4 -o "$tmp/gone%d.ppm"
check "a failed turntable removes the frames it wrote" test -z "$(ls "$tmp" | grep '^gone[013]')"
want='unknown image format' expect_usage "turntable to an unknown format" render "$sphere" --turntable 2 -o "$tmp/t%d.gif"

done_testing
