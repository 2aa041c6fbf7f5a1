#!/bin/sh
# cli_clip.sh - clip mode from the command line on a generated knot that
# silk prepares (outer hull and silhouette map): a turntable of 72 views
# 0.5 degrees apart, across the changes of polytope triangle the eye passes
# through, keeps the outline coherent: between consecutive frames the
# outline moves at most 0.5 px on average (silk diff's mean_px; the knot's
# own outline moves up to 0.15 px per step at 320x240).  The largest move of
# a single outline pixel (silk diff's Hausdorff distance) is printed, not
# checked: small loops of the interpolated outline (the knot's see-through
# gaps, specks) still appear and vanish between frames (docs/clipping.md).
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen knot -o "$tmp/knot.obj" >/dev/null || { fail "gen" "exit $?"; done_testing; exit 1; }
run_silk prepare "$tmp/knot.obj" -o "$tmp/knot.silk" --triangles 300 --map-views 42 --map-resolution 128
check "prepare" [ "$rc" -eq 0 ]

worst=0
worst_mean=0
tris=""
k=0
while [ $k -lt 72 ]; do
    yaw=$(awk "BEGIN { print $k * 0.5 }")
    "$SILK" render "$tmp/knot.silk" --mode clip --size 320x240 --yaw "$yaw" -o "$tmp/f$k.png" 2>"$err" || break
    t=$("$SILK" info "$tmp/knot.silk" --mode clip --size 320x240 --yaw "$yaw" | awk -F: '/map triangle/ { print $2 + 0 }')
    case " $tris " in *" $t "*) ;; *) tris="$tris $t" ;; esac
    if [ $k -gt 0 ]; then
        "$SILK" diff "$tmp/f$((k - 1)).png" "$tmp/f$k.png" >"$out"
        h=$(sed 's/.*hausdorff_px=//' "$out")
        m=$(sed 's/.*mean_px=\([0-9.]*\).*/\1/' "$out")
        worst=$(awk "BEGIN { print ($h > $worst) ? $h : $worst }")
        worst_mean=$(awk "BEGIN { print ($m > $worst_mean) ? $m : $worst_mean }")
    fi
    k=$((k + 1))
done
check "72 frames rendered" [ $k -eq 72 ]
ntris=$(echo $tris | wc -w)
echo "  between frames: mean outline move up to $worst_mean px, largest single move $worst px; polytope triangles met: $ntris"
check "the eye crossed polytope triangles" [ "$ntris" -gt 1 ]
check "the outline moves at most 0.5 px on average per step" awk "BEGIN { exit !($worst_mean <= 0.5) }"

done_testing
