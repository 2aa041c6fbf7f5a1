#!/bin/sh
# cli_pair_bounds.sh - smooth mode's outline against the detailed model
# (`silk bench --pair`, docs/measurements.md) on the CAD meshes, whose
# outlines are straight creases and thin rims: in every projection,
# smooth's largest distance from the detailed model's outline is at most
# flat's + 1 px.  Smooth once bowed wingnut-500's wing, seen edge-on, 10 px
# outward: the vertex normal at the wing's rounded-off crease leaned along a
# rim edge that is straight (curve.h, the tilt bound).
. "$(dirname "$0")/../shlib.sh"

meshes=${SILK_MESHES:-../shared/meshes}
if [ ! -f "$meshes/wingnut-500.obj" ]; then
    echo "skip: no shared meshes in $meshes"
    done_testing
    exit 0
fi

# error_max_px of MODE in PROJECTION, from the bench lines in $out
max_error() {
    awk -v m="$1" -v p="$2" '$3 == m && $4 == p {
        for (i = 5; i <= NF; i++) if (index($i, "error_max_px=") == 1) print substr($i, 14) }' "$out"
}

for m in wingnut-500 fandisk-1000; do
    run_silk bench --pair "$meshes/$m.obj:$meshes/${m%-*}-fine.obj" --modes flat,smooth --views 12 \
        --size 640x480 --reps 1 --quiet
    check "$m: bench runs (exit $rc)" test "$rc" -eq 0
    for proj in ortho perspective; do
        flat=$(max_error flat "$proj")
        smooth=$(max_error smooth "$proj")
        check "$m $proj: smooth's max error ${smooth:-?} px <= flat's ${flat:-?} + 1" \
            awk -v f="$flat" -v s="$smooth" 'BEGIN { exit !(f != "" && s != "" && s + 0 <= f + 1) }'
    done
done

done_testing
