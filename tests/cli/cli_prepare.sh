#!/bin/sh
# cli_prepare.sh - `silk prepare`: a generated sphere and torus prepared into
# .silk files that every command taking a mesh reads (info says the normals
# are the file's, render draws it in every mode, pack packs it, bench and
# simplify take it); bad usage and bad input fail cleanly and leave no
# output behind.  tests/core/test_model.c checks the models themselves.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere --segments 24 --bands 16 -o "$tmp/sphere.obj" >/dev/null || { fail "gen" "exit $?"; done_testing; exit 1; }
"$SILK" gen torus -o "$tmp/torus.obj" >/dev/null

run_silk prepare "$tmp/sphere.obj" -o "$tmp/sphere.silk" --triangles 120
check "prepare: the summary line" grep -qE "^prepare .* triangles=120 vertices=62 normals=62 hull_triangles=1[12][0-9] map_views=162 map_bytes=[0-9]+ bytes=[0-9]+ fitted=[0-9]+ fit_rms_before=[0-9.e-]+ fit_rms_after=[0-9.e-]+$" "$out"
check "prepare: nothing on stderr" [ ! -s "$err" ]
run_silk info "$tmp/sphere.silk" --size 64x64
check "info reads it: 120 triangles" [ "$(info_value "$out" triangles)" = 120 ]
check "info: the file's normals" [ "$(info_value "$out" "normals from")" = "the file" ]
run_silk info "$tmp/sphere.silk" --size 64x64 --normals compute
check "--normals compute: computed" grep -q "^normals from: *computed" "$out"
for mode in flat smooth pn blend clip; do
    run_silk render "$tmp/sphere.silk" -o "$tmp/$mode.png" --size 96x64 --mode "$mode"
    check "render --mode $mode" test "$rc" -eq 0 -a -s "$tmp/$mode.png"
done
run_silk pack "$tmp/sphere.silk" -o "$tmp/sphere.h"
check "pack" grep -q "sphere_mesh" "$tmp/sphere.h"
run_silk prepare "$tmp/sphere.obj" -o "$tmp/fit.silk" --triangles 120
check "prepare fits the normals by default" grep -qE "^prepare .* triangles=120 .* fitted=[0-9]+ fit_rms_before=.* fit_rms_after=" "$out"
run_silk prepare "$tmp/sphere.obj" -o "$tmp/nofit.silk" --triangles 120 --no-fit
check "prepare --no-fit" [ "$rc" -eq 0 ] && ! grep -q "fitted=" "$out"
run_silk prepare "$tmp/torus.obj" -o "$tmp/torus.silk" --triangles 200
check "torus: 200 triangles" grep -q "triangles=200 " "$out"
run_silk bench "$tmp/torus.silk" --views 1 --reps 1 --modes flat,smooth --size 64x48
check "bench takes it" [ "$rc" -eq 0 ]
run_silk simplify "$tmp/torus.silk" "$tmp/torus-100.obj" --triangles 100
check "simplify takes it" grep -q "triangles=100 " "$out"

# clip mode: the hull and the map; a model without them says so
run_silk prepare "$tmp/sphere.obj" -o "$tmp/small-map.silk" --triangles 60 --map-views 42 --map-resolution 64
check "--map-views 42 --map-resolution 64" grep -qE "map_views=42 map_bytes=[0-9]+ " "$out"
run_silk bench "$tmp/small-map.silk" --views 2 --reps 1 --modes flat,clip --size 64x48
check "bench: a clip row" grep -q "^bench small-map clip perspective" "$out"
run_silk prepare "$tmp/sphere.obj" -o "$tmp/no-clip.silk" --triangles 60 --no-clip
check "--no-clip: no map" sh -c "! grep -q map_views $out"
run_silk prepare "$tmp/sphere.obj" -o "$tmp/hull-only.silk" --triangles 60 --no-mesh --map-views 12 --map-resolution 32
run_silk render "$tmp/hull-only.silk" -o "$tmp/hull-flat.png" --size 96x64 --mode flat
check "--no-mesh: flat draws the hull" [ "$rc" -eq 0 ]
want="leave nothing to write" expect_usage "--no-clip --no-mesh" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 10 --no-clip --no-mesh
want="no HULL section" expect_input "clip without a hull" render "$tmp/no-clip.silk" -o "$tmp/x.png" --mode clip
want="clip mode draws a prepared model" expect_input "clip of a mesh file" render "$tmp/sphere.obj" -o "$tmp/x.png" --mode clip
want="--map-views must be 12, 42, 162" expect_usage "--map-views 50" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 10 --map-views 50

# errors
want="--triangles N is needed" expect_usage "no target" prepare "$tmp/sphere.obj" -o "$tmp/x.silk"
want="-o MODEL.silk is needed" expect_usage "no output" prepare "$tmp/sphere.obj" --triangles 10
expect_usage "unknown option" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 10 --fast
expect_usage "two inputs" prepare "$tmp/sphere.obj" "$tmp/torus.obj" -o "$tmp/x.silk" --triangles 10
expect_usage "output over the input" prepare "$tmp/sphere.obj" -o "$tmp/sphere.obj" --triangles 10
want="no-such.obj: cannot open" expect_input "missing input" prepare "$tmp/no-such.obj" -o "$tmp/x.silk" --triangles 10
cp "$tmp/sphere.silk" "$tmp/stale.silk"
expect_input "malformed input" prepare tests/bad/face-index-zero.obj -o "$tmp/stale.silk" --triangles 10
check "failed run keeps an earlier output" cmp -s "$tmp/sphere.silk" "$tmp/stale.silk"
want="scale it was prepared with" expect_input "--scale on a model" info "$tmp/sphere.silk" --scale 2
check "no temporary files left" no_tmp_files "$tmp"

done_testing
