#!/bin/sh
# cli_simplify.sh - `silk simplify`: generated and shared meshes simplified
# to a target load back in silk as closed, manifold meshes of that many
# triangles (tests/prep/test_simplify.c checks the geometry); "-" writes to
# stdout; bad input is an input error, bad options usage errors, and a
# failed run leaves no output behind.
. "$(dirname "$0")/../shlib.sh"
meshes=${SILK_MESHES:-../shared/meshes}

"$SILK" gen sphere --segments 40 --bands 40 -o "$tmp/sphere.obj" || { fail "gen" "exit $?"; done_testing; exit 1; }
"$SILK" gen torus --segments 48 --bands 24 -o "$tmp/torus.obj"

# simplify_ok NAME IN TARGET EULER: exit 0, the summary line, and silk info
# reads the result as closed and manifold with TARGET triangles.
simplify_ok() {
    name=$1; in=$2; target=$3
    o=$tmp/$name.obj
    run_silk simplify "$in" "$o" --triangles "$target"
    mesh_made "$name" "^simplify .* triangles=$target vertices=[0-9]+ target=$target " "$o" "$target"
}

simplify_ok sphere-200 "$tmp/sphere.obj" 200
simplify_ok torus-100 "$tmp/torus.obj" 100
if [ -f "$meshes/sphere-fine.obj" ]; then
    simplify_ok shared-sphere-200 "$meshes/sphere-fine.obj" 200
    simplify_ok fandisk-128 "$meshes/fandisk-fine.obj" 128
else
    echo "skip: no shared meshes in $meshes"
fi

# --for smooth: every corner carries a normal, and silk uses them by default
run_silk simplify "$tmp/sphere.obj" "$tmp/smooth.obj" --triangles 200 --for smooth
check "--for smooth: 200 triangles" grep -q "triangles=200 " "$out"
check "--for smooth: every face has normals" [ "$(grep -c '^f [0-9]*//[0-9]* [0-9]*//[0-9]* [0-9]*//[0-9]*$' "$tmp/smooth.obj")" = 200 ]
"$SILK" info "$tmp/smooth.obj" --size 64x64 >"$tmp/info" 2>&1
check "--for smooth: silk info uses the file's normals" [ "$(info_value "$tmp/info" "normals from")" = "the file" ]
want="--for smooth writes OBJ" expect_usage "--for smooth to PLY" simplify "$tmp/sphere.obj" "$tmp/smooth.ply" --triangles 200 --for smooth
check "... writes nothing" [ ! -e "$tmp/smooth.ply" ]
"$SILK" info "$tmp/smooth.obj" --size 64x64 --normals compute >"$tmp/info" 2>&1
check "--normals compute: computed" grep -q "^normals from: *computed" "$tmp/info"
expect_usage "bad --for" simplify "$tmp/sphere.obj" "$tmp/x.obj" --triangles 10 --for pn

# a target above the input's count copies it
run_silk simplify "$tmp/sphere.obj" "$tmp/same.obj" --triangles 100000
check "target above the input: unchanged" grep -q "triangles=3120 .* collapses=0 " "$out"
# stdout
"$SILK" simplify "$tmp/sphere.obj" - --triangles 50 >"$tmp/stdout.obj" 2>"$err"
check "to stdout: 50 faces" [ "$(grep -c '^f ' "$tmp/stdout.obj")" = 50 ]
check "to stdout: nothing else on stderr" [ ! -s "$err" ]

# errors
want="no-such.obj: cannot open" expect_input "missing input" simplify "$tmp/no-such.obj" "$tmp/x.obj" --triangles 10
expect_input "malformed input" simplify tests/bad/face-index-zero.obj "$tmp/x.obj" --triangles 10
want="--triangles N is needed" expect_usage "no target" simplify "$tmp/sphere.obj" "$tmp/x.obj"
expect_usage "target too small" simplify "$tmp/sphere.obj" "$tmp/x.obj" --triangles 3
expect_usage "target not a number" simplify "$tmp/sphere.obj" "$tmp/x.obj" --triangles many
expect_usage "no output" simplify "$tmp/sphere.obj" --triangles 10
expect_usage "unknown option" simplify "$tmp/sphere.obj" "$tmp/x.obj" --triangles 10 --fast
expect_usage "bad crease" simplify "$tmp/sphere.obj" "$tmp/x.obj" --triangles 10 --crease 200
cp "$tmp/sphere.obj" "$tmp/stale.obj"
expect_input "failed run" simplify tests/bad/face-index-zero.obj "$tmp/stale.obj" --triangles 10
check "failed run keeps an earlier output" cmp -s "$tmp/sphere.obj" "$tmp/stale.obj"
cp tests/bad/face-index-zero.obj "$tmp/inplace.obj"
expect_input "failed run in place" simplify "$tmp/inplace.obj" "$tmp/inplace.obj" --triangles 10
check "... keeps the input" cmp -s tests/bad/face-index-zero.obj "$tmp/inplace.obj"
check "no temporary files left" no_tmp_files "$tmp"

done_testing
