#!/bin/sh
# cli_alpha.sh - `silk render --bg none` in every mode, with and without
# anti-aliasing, laid over red and over black, looks like the same view
# rendered with --bg ff0000 and --bg 000000: at most 1 level of 255 apart
# in 99.9% of the pixels (tests/support/imgstat.py --composes).  The alpha
# is the object's coverage and the colour does not carry the background.
# Generated meshes (flat, smooth, pn, blend), a generated knot prepared
# with its outer hull, silhouette map and silhouette texture (flat,
# smooth, clip, siltex), and bunny-500 where the shared meshes are.
. "$(dirname "$0")/shlib.sh"

stat_py="$here/support/imgstat.py"
if ! command -v python3 >/dev/null; then
    # CI installs python3 (.ci/run); elsewhere the test skips without it.
    [ -n "${CI:-}" ] && { fail "python3" "CI must have python3"; done_testing; exit 1; }
    echo "skip: python3 missing"; pass "skipped"; done_testing; exit 0
fi
meshes=${SILK_MESHES:-../shared/meshes}
size="--size 160x120"

"$SILK" gen torus -o "$tmp/torus.obj" >/dev/null && "$SILK" gen cone -o "$tmp/cone.obj" >/dev/null &&
    "$SILK" gen knot -o "$tmp/knot.obj" >/dev/null || { fail "gen" "exit $?"; done_testing; exit 1; }
run_silk prepare "$tmp/knot.obj" -o "$tmp/knot.silk" --triangles 240 --views 12 --map-resolution 96 --siltex \
    --atlas 48 --angles 8
check "prepare the knot (hull, map, texture)" [ "$rc" -eq 0 ]

# composes LABEL MESH MODE [render options]: for --aa on and off, over
# red and black
composes() {
    label=$1 mesh=$2 mode=$3
    shift 3
    for aa in on off; do
        if ! "$SILK" render "$mesh" --mode "$mode" $size --aa $aa "$@" --bg none -o "$tmp/none.png" 2>"$err"; then
            fail "$label --aa $aa" "render --bg none: $(head -c 200 "$err")"
            continue
        fi
        for bg in ff0000 000000; do
            "$SILK" render "$mesh" --mode "$mode" $size --aa $aa "$@" --bg $bg -o "$tmp/bg.png" 2>"$err"
            line=$(python3 "$stat_py" --composes "$tmp/none.png" "$tmp/bg.png" $bg)
            n=$(echo "$line" | sed 's/.*pixels=\([0-9]*\).*/\1/')
            off=$(echo "$line" | sed 's/.*off1=\([0-9]*\).*/\1/')
            check "$label --aa $aa over $bg: $line" [ $((off * 1000)) -le "$n" ]
        done
    done
}

composes "torus flat" "$tmp/torus.obj" flat
composes "torus smooth" "$tmp/torus.obj" smooth --yaw 40 --pitch 50
composes "cone smooth" "$tmp/cone.obj" smooth
composes "cone pn" "$tmp/cone.obj" pn
composes "torus blend" "$tmp/torus.obj" blend
composes "knot model flat" "$tmp/knot.silk" flat
composes "knot model smooth" "$tmp/knot.silk" smooth
composes "knot model clip" "$tmp/knot.silk" clip
composes "knot model clip, from above" "$tmp/knot.silk" clip --yaw 100 --pitch 40
composes "knot model siltex" "$tmp/knot.silk" siltex
composes "knot model siltex, orthographic" "$tmp/knot.silk" siltex --ortho auto --yaw 100 --pitch 40
if [ -f "$meshes/bunny-500.obj" ]; then
    for mode in flat smooth pn blend; do composes "bunny-500 $mode" "$meshes/bunny-500.obj" $mode; done
else
    echo "skip: bunny-500 ($meshes not found)"
fi

done_testing
