#!/bin/sh
# cli_look.sh - material, light and view from the command line change the
# picture as `silk render --help` says: --color, --ambient, --specular,
# --shininess, --light (directional, point, coloured, several), --bg none
# (alpha 255 exactly on the object), --yaw/--pitch (the eye orbits the
# model) and --up-axis z (a Z-up copy of a model looks like the Y-up one).
. "$(dirname "$0")/../shlib.sh"

stat_py="$here/support/imgstat.py"
if ! command -v python3 >/dev/null; then
    # CI installs python3 (.ci/run); elsewhere the test skips without it.
    [ -n "${CI:-}" ] && { fail "python3" "CI must have python3"; done_testing; exit 1; }
    echo "skip: python3 missing"; pass "skipped"; done_testing; exit 0
fi
"$SILK" gen cone -o "$tmp/cone.obj" || { fail "gen cone" "exit $?"; done_testing; exit 1; }
"$SILK" gen sphere -o "$tmp/sphere.obj"
size="--size 160x120"

# value KEY FILE [imgstat options]: one number of imgstat's line
value() {
    key=$1; shift
    python3 "$stat_py" "$@" | tr ' ' '\n' | sed -n "s/^$key=//p"
}
# gt A B: A > B as numbers
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }

r() { out_img=$1; shift; "$SILK" render "$tmp/sphere.obj" -o "$tmp/$out_img" $size "$@" 2>"$err"; }

# ---- material -------------------------------------------------------------------------
r red.ppm --color ff0000 --specular 0
check "--color ff0000: the object is red" gt "$(value mean_r "$tmp/red.ppm")" "$(( $(value mean_g "$tmp/red.ppm" | cut -d. -f1) * 4 + 10 ))"
r dark.ppm --ambient 0 && r bright.ppm --ambient 1
check "--ambient 1 is brighter than 0" gt "$(value mean_luma "$tmp/bright.ppm")" "$(value mean_luma "$tmp/dark.ppm")"
r matte.ppm --specular 0 && r shiny.ppm --specular 1
check "--specular 1 adds a highlight" gt "$(value max_luma "$tmp/shiny.ppm")" "$(value max_luma "$tmp/matte.ppm")"
r broad.ppm --specular 1 --shininess 2 && r tight.ppm --specular 1 --shininess 200
check "--shininess: a low exponent spreads the highlight" \
    gt "$(value bright "$tmp/broad.ppm")" "$(value bright "$tmp/tight.ppm")"

# ---- lights (model axes; the default eye looks from +z, 30 degrees right) ---------------
flat="--ambient 0 --specular 0"
r left.ppm $flat --light -1,0,0
r right.ppm $flat --light 1,0,0
check "--light -1,0,0 lights the left half" \
    gt "$(value mean_luma "$tmp/left.ppm" --region left)" "$(value mean_luma "$tmp/left.ppm" --region right)"
check "--light 1,0,0 lights the right half" \
    gt "$(value mean_luma "$tmp/right.ppm" --region right)" "$(value mean_luma "$tmp/right.ppm" --region left)"
r above.ppm $flat --light point:0,3,0
check "--light point:0,3,0 lights the top half" \
    gt "$(value mean_luma "$tmp/above.ppm" --region top)" "$(value mean_luma "$tmp/above.ppm" --region bottom)"
r blue.ppm $flat --color ffffff --light 0,0,1:0000ff
check "--light x,y,z:0000ff is a blue light" gt "$(value mean_b "$tmp/blue.ppm")" "$(value mean_r "$tmp/blue.ppm")"
r two.ppm $flat --light -1,0,0 --light 1,0,0
check "two --light add up" gt "$(value mean_luma "$tmp/two.ppm")" "$(value mean_luma "$tmp/left.ppm")"
want='at most 4' expect_usage "a fifth --light" render "$tmp/sphere.obj" -o "$tmp/x.png" --light 1,0,0 \
    --light 1,0,0 --light 1,0,0 --light 1,0,0 --light 1,0,0
want='--light' expect_usage "--light 0,0,0" render "$tmp/sphere.obj" -o "$tmp/x.png" --light 0,0,0
want='--light' expect_usage "--light with a bad colour" render "$tmp/sphere.obj" -o "$tmp/x.png" --light 1,0,0:red
want='--shininess' expect_usage "--shininess 0" render "$tmp/sphere.obj" -o "$tmp/x.png" --shininess 0
want='--ambient' expect_usage "--ambient 2" render "$tmp/sphere.obj" -o "$tmp/x.png" --ambient 2

# ---- --bg none ----------------------------------------------------------------------------
"$SILK" render "$tmp/cone.obj" -o "$tmp/alpha.png" $size --bg none --aa off
"$SILK" render "$tmp/cone.obj" -o "$tmp/opaque.ppm" $size --aa off
check "--bg none: an RGBA PNG" test "$(od -An -tu1 -j25 -N1 "$tmp/alpha.png" | tr -d ' ')" = 6
check "--bg none --aa off: alpha 255 on the object, 0 elsewhere" \
    test "$(python3 "$stat_py" --alpha-matches "$tmp/alpha.png" "$tmp/opaque.ppm" ffffff)" = match
"$SILK" render "$tmp/cone.obj" -o "$tmp/aa.png" $size --bg none
check "--bg none: anti-aliased outline pixels have alpha between" \
    test "$(python3 "$stat_py" --alpha-matches "$tmp/aa.png" "$tmp/opaque.ppm" ffffff)" != match
"$SILK" render "$tmp/cone.obj" -o "$tmp/lines.png" $size --bg none --lines only --mode flat
"$SILK" render "$tmp/cone.obj" -o "$tmp/lines.ppm" $size --lines only --mode flat
check "--bg none --lines only: alpha on the lines" \
    test "$(python3 "$stat_py" --alpha-matches "$tmp/lines.png" "$tmp/lines.ppm" ffffff)" = match
# ---- anti-aliasing: --aa, --ssaa, --pixels ----------------------------------------------------
"$SILK" render "$tmp/cone.obj" -o "$tmp/ss.png" $size --ssaa 4 --bg none
check "--ssaa 4: the image has --size" test "$(png_size "$tmp/ss.png")" = "160x120"
check "--ssaa 4 --bg none: alpha between on the outline" \
    test "$(python3 "$stat_py" --alpha-matches "$tmp/ss.png" "$tmp/opaque.ppm" ffffff)" != match
"$SILK" render "$tmp/cone.obj" -o "$tmp/px.png" --size 120x60 --modes flat-noaa,smooth --sheet --pixels 4
check "--pixels 4: a sheet of 120x60 cells" is_png "$tmp/px.png"
want='--aa' expect_usage "--aa maybe" render "$tmp/cone.obj" -o "$tmp/x.png" --aa maybe
want='--ssaa' expect_usage "--ssaa 9" render "$tmp/cone.obj" -o "$tmp/x.png" --ssaa 9
want='--ssaa' expect_usage "--ssaa with --compare" render "$tmp/cone.obj" -o "$tmp/x.png" --ssaa 2 --compare
want='--pixels' expect_usage "--pixels without --sheet" render "$tmp/cone.obj" -o "$tmp/x.png" --pixels 4
want='not a mode' expect_usage "--modes smooth-aa" render "$tmp/cone.obj" -o "$tmp/x.png" --modes smooth-aa --sheet
want='PNG' expect_usage "--bg none to a PPM" render "$tmp/cone.obj" -o "$tmp/x.ppm" --bg none
want='--bg none' expect_usage "view --bg none" view "$tmp/cone.obj" --bg none --benchmark 1

# ---- the eye orbits the model ---------------------------------------------------------------
# eye minus target of `silk info --json`, as "dx dy dz"
eye_dir() {
    "$SILK" info "$tmp/cone.obj" --json "$@" | python3 -c '
import json, sys
f = json.load(sys.stdin)["frame"]
print(" ".join("%.3f" % (e - t) for e, t in zip(f["eye"], f["target"])))'
}
set -- $(eye_dir --yaw -30)
check "--yaw -30: the eye straight in front (+z)" awk -v x="$1" -v z="$3" 'BEGIN { exit !(x * x < 1e-4 && z > 0) }'
set -- $(eye_dir --yaw 60)
check "--yaw 60: the eye to the right (+x)" awk -v x="$1" -v z="$3" 'BEGIN { exit !(x > 0 && z * z < 1e-4) }'
set -- $(eye_dir --pitch 70)
check "--pitch 70: the eye straight above" awk -v x="$1" -v y="$2" -v z="$3" 'BEGIN { exit !(y > 0 && x * x + z * z < 1e-4) }'
set -- $(eye_dir --eye 0,0,5 --yaw 90)
check "--yaw turns a given --eye too" awk -v x="$1" -v z="$3" 'BEGIN { exit !(x > 4.9 && z * z < 1e-4) }'
"$SILK" render "$tmp/cone.obj" -o "$tmp/front.png" $size
"$SILK" render "$tmp/cone.obj" -o "$tmp/top.png" $size --pitch 70
"$SILK" diff "$tmp/front.png" "$tmp/top.png" >"$out"
check "--pitch 70 changes the picture" grep -qv 'differing=0 ' "$out"
want='--pitch' expect_usage "--pitch 100" render "$tmp/cone.obj" -o "$tmp/x.png" --pitch 100

# ---- Z-up models ------------------------------------------------------------------------------
# The cone turned so that its axis is +z: (x, y, z) -> (x, -z, y).
awk '$1 == "v" { print "v", $2, -$4, $3; next } { print }' "$tmp/cone.obj" >"$tmp/cone-z.obj"
"$SILK" render "$tmp/cone-z.obj" -o "$tmp/zup.png" $size --up-axis z
"$SILK" render "$tmp/cone-z.obj" -o "$tmp/zlying.png" $size
"$SILK" diff "$tmp/front.png" "$tmp/zup.png" >"$out"
check "--up-axis z: the Z-up copy has the Y-up silhouette ($(cat "$out"))" grep -q 'differing=0 ' "$out"
"$SILK" diff "$tmp/front.png" "$tmp/zlying.png" >"$out"
check "without --up-axis z it lies on its side" grep -qv 'differing=0 ' "$out"
want='--up-axis' expect_usage "--up-axis x" render "$tmp/cone.obj" -o "$tmp/x.png" --up-axis x
# the viewer orbits about the same up axis (arrow left: 15 degrees about it)
"$SILK" view "$tmp/cone.obj" --events "left shot:$tmp/vy.png" $size >/dev/null 2>&1
"$SILK" view "$tmp/cone-z.obj" --up-axis z --events "left shot:$tmp/vz.png" $size >/dev/null 2>&1
"$SILK" diff "$tmp/vy.png" "$tmp/vz.png" >"$out" 2>&1
check "view --up-axis z orbits the Z-up copy as the Y-up model ($(cat "$out"))" grep -q 'differing=0 ' "$out"

done_testing
