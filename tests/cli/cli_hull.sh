#!/bin/sh
# cli_hull.sh - `silk hull`: outer and inner hulls of generated meshes load
# back in silk as closed, manifold meshes of the target's triangle count
# (tests/prep/test_hull.c checks that they hold the mesh); a mesh that is open
# or turned inside out is an input error, bad options usage errors, and a
# failed run leaves no output behind.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere --segments 40 --bands 40 -o "$tmp/sphere.obj" || { fail "gen" "exit $?"; done_testing; exit 1; }
"$SILK" gen torus --segments 48 --bands 24 -o "$tmp/torus.obj"

# hull_ok NAME IN TARGET [--inner]: exit 0, the summary line, and silk info
# reads the result as closed and manifold with TARGET triangles.
hull_ok() {
    name=$1; in=$2; target=$3; shift 3
    o=$tmp/$name.obj
    run_silk hull "$in" -o "$o" --triangles "$target" "$@"
    mesh_made "$name" "^hull .* triangles=$target vertices=[0-9]+ target=$target .*volume=" "$o" "$target"
}

hull_ok sphere-200 "$tmp/sphere.obj" 200
hull_ok torus-100 "$tmp/torus.obj" 100
hull_ok sphere-inner-200 "$tmp/sphere.obj" 200 --inner
run_silk hull "$tmp/sphere.obj" -o "$tmp/o.obj" --triangles 200
check "outer: more volume" grep -qE '\(\+[0-9.]+%\)' "$out"
run_silk hull "$tmp/sphere.obj" -o "$tmp/i.obj" --triangles 200 --inner
check "inner: less volume" grep -qE '\(-[0-9.]+%\)' "$out"
"$SILK" hull "$tmp/sphere.obj" -o - --triangles 50 >"$tmp/stdout.obj" 2>"$err"
check "to stdout: 50 faces" [ "$(grep -c '^f ' "$tmp/stdout.obj")" = 50 ]
check "to stdout: nothing else on stderr" [ ! -s "$err" ]

# a cube cannot lose a corner without cutting into itself: all of it, and a warning
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n' >"$tmp/cube.obj"
printf 'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n' >>"$tmp/cube.obj"
run_silk hull "$tmp/cube.obj" -o "$tmp/cube-hull.obj" --triangles 4
cube_kept() {
    [ "$rc" -eq 0 ] && grep -q "triangles=12 .*collapses=0" "$out" && grep -q "^silk: warning: .*stopped at 12 triangles" "$err"
}
check "cube: kept whole, with a warning" cube_kept

# errors
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n' >"$tmp/open.obj"
want="closed, manifold" expect_input "open mesh" hull "$tmp/open.obj" -o "$tmp/x.obj" --triangles 4
awk '/^f /{print "f", $2, $4, $3; next} {print}' "$tmp/sphere.obj" >"$tmp/inside-out.obj"
# Loading turns an inside-out mesh outward, so its hull is the sphere's.
"$SILK" hull "$tmp/sphere.obj" -o "$tmp/right.obj" --triangles 100 2>/dev/null
"$SILK" hull "$tmp/inside-out.obj" -o "$tmp/x.obj" --triangles 100 2>/dev/null
for f in right x; do grep -v '^#' "$tmp/$f.obj" >"$tmp/$f.obj.body"; done
check "inside-out mesh: turned outward at load, same hull" cmp -s "$tmp/right.obj.body" "$tmp/x.obj.body"
want="no-such.obj: cannot open" expect_input "missing input" hull "$tmp/no-such.obj" -o "$tmp/x.obj" --triangles 10
expect_input "malformed input" hull tests/bad/face-index-zero.obj -o "$tmp/x.obj" --triangles 10
want="--triangles N is needed" expect_usage "no target" hull "$tmp/sphere.obj" -o "$tmp/x.obj"
expect_usage "target too small" hull "$tmp/sphere.obj" -o "$tmp/x.obj" --triangles 3
expect_usage "target not a number" hull "$tmp/sphere.obj" -o "$tmp/x.obj" --triangles many
want="-o HULL.obj" expect_usage "no output" hull "$tmp/sphere.obj" --triangles 10
expect_usage "a second mesh" hull "$tmp/sphere.obj" "$tmp/x.obj" --triangles 10
expect_usage "unknown option" hull "$tmp/sphere.obj" -o "$tmp/x.obj" --triangles 10 --fast
cp "$tmp/sphere.obj" "$tmp/stale.obj"
expect_input "failed run" hull "$tmp/open.obj" -o "$tmp/stale.obj" --triangles 10
check "failed run leaves the old output" cmp -s "$tmp/sphere.obj" "$tmp/stale.obj"
cp "$tmp/sphere.obj" "$tmp/stale.obj"
expect_usage "usage error" hull "$tmp/sphere.obj" -o "$tmp/stale.obj" --triangles 10 --fast
check "usage error leaves the old output" cmp -s "$tmp/sphere.obj" "$tmp/stale.obj"
check "no temporary files left" no_tmp_files "$tmp"

done_testing
