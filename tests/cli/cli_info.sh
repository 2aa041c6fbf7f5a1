#!/bin/sh
# cli_info.sh - `silk info`: the counts of generated meshes follow from their
# construction (V, F, E = 3F/2 for a closed mesh, the cone's rim is 35
# feature edges), the shared meshes give the counts SOURCES.md lists, the
# memory report adds up, and the per-frame counts respond to the options.
. "$(dirname "$0")/../shlib.sh"

meshes=${SILK_MESHES:-../shared/meshes}

# expect_counts NAME FILE V F [FEATURE]: vertices, triangles, edges = 3F/2, no defects.
expect_counts() {
    name=$1; f=$2; v=$3; t=$4; feat=${5:-}
    run_silk info "$f" --size 64x64 --crease 40
    got="v=$(info_value "$out" vertices) t=$(info_value "$out" triangles) e=$(info_value "$out" edges)"
    got="$got b=$(info_value "$out" "boundary edges") nm=$(info_value "$out" "non-manifold edges")"
    got="$got d=$(info_value "$out" "degenerate triangles")"
    wanted="v=$v t=$t e=$((3 * t / 2)) b=0 nm=0 d=0"
    if [ "$rc" -eq 0 ] && [ "$got" = "$wanted" ] &&
       { [ -z "$feat" ] || [ "$(info_value "$out" "feature edges")" = "$feat" ]; }; then
        pass "$name counts"
    else
        fail "$name counts" "exit $rc: got $got feature $(info_value "$out" "feature edges"), want $wanted feature $feat $(head -c 200 "$err")"
    fi
}

"$SILK" gen sphere -o "$tmp/sphere.obj"
"$SILK" gen torus -o "$tmp/torus.obj"
"$SILK" gen cone -o "$tmp/cone.obj"
"$SILK" gen cylinder --segments 16 -o "$tmp/cyl.obj"
expect_counts sphere "$tmp/sphere.obj" 102 200 0
expect_counts torus "$tmp/torus.obj" 288 576 0
expect_counts cone "$tmp/cone.obj" 37 70 35
expect_counts cylinder "$tmp/cyl.obj" 34 64 32

if [ -d "$meshes" ]; then
    expect_counts sphere-200 "$meshes/sphere-200.obj" 102 200
    expect_counts bunny-500 "$meshes/bunny-500.obj" 252 500
    expect_counts fandisk-128 "$meshes/fandisk-128.obj" 66 128
    expect_counts torus-576 "$meshes/torus-576.obj" 288 576
else
    echo "note: $meshes not found; shared meshes skipped"
fi

# The memory report: every line present, the parts add up to the total,
# and the arena after loading holds at least the mesh.
run_silk info "$tmp/torus.obj" --size 64x64
memory_adds_up() {
    [ "$rc" -eq 0 ] || return 1
    sum=0
    for k in positions normals uvs triangles edges "vertex edges" features; do
        v=$(info_value "$out" "  $k")
        [ -n "$v" ] || return 1
        case $v in *[!0-9]*) return 1 ;; esac
        sum=$((sum + v))
    done
    total=$(info_value "$out" "  mesh total")
    after=$(info_value "$out" "  after loading")
    [ "${total:-0}" -gt 0 ] && [ "$sum" -eq "$total" ] && [ "${after:-0}" -ge "$total" ] &&
        grep -qE '^ +mesh +[0-9]+ +[0-9]+$' "$out" && grep -qE '^ +raster +[0-9]+ +[0-9]+$' "$out" &&
        grep -qE '^ +frame +[0-9]+ +[0-9]+$' "$out"
}
check "memory report adds up" memory_adds_up
# The frame's raster comes from the arena: 64x64 RGB888 colour + depth.
raster=$(grep -E '^ +raster ' "$out" | awk '{ print $2 }'); raster=${raster:-0}
check "raster bytes $raster = 64*64*(3+4)" test "$raster" -ge $((64 * 64 * 7)) -a "$raster" -lt $((64 * 64 * 7 + 64))
run_silk info "$tmp/torus.obj" --size 64x64 --format rgb565
raster=$(grep -E '^ +raster ' "$out" | awk '{ print $2 }'); raster=${raster:-0}
check "rgb565 raster bytes $raster = 64*64*(2+4)" test "$raster" -ge $((64 * 64 * 6)) -a "$raster" -lt $((64 * 64 * 6 + 64))

# Per-frame counts: flat draws the mesh as it is; smooth finds silhouette
# triangles on a sphere from any side and draws more triangles.
run_silk info "$tmp/sphere.obj" --mode flat
check "flat frame draws the 200 triangles" test "$(info_value "$out" "  triangles drawn")" = 200
check "flat frame has no silhouette work" test "$(info_value "$out" "  silhouette triangles")" = 0
for eye in 0,0,4 3,3,3 0,-5,0.5 -2,1,-3; do
    run_silk info "$tmp/sphere.obj" --eye $eye
    st=$(info_value "$out" "  silhouette triangles"); td=$(info_value "$out" "  triangles drawn")
    check "smooth frame from $eye: $st silhouette triangles, $td drawn" test "$rc" -eq 0 -a "${st:-0}" -gt 0 -a "${td:-0}" -gt 200
done
# A convex sphere has no concave segment to leave to the coarse outline;
# a torus from the side has (its inner rim), and JSON says the same.
check "sphere: no flat segments" test "$(info_value "$out" "  flat segments")" = 0
run_silk info "$tmp/torus.obj" --eye 0,0.9,4 --target 0,0,0
flat=$(info_value "$out" "  flat segments")
check "torus from the side: $flat flat segments, a count" test "${flat:-x}" -ge 0 2>/dev/null
run_silk info "$tmp/torus.obj" --eye 0,0.9,4 --target 0,0,0 --json
check "JSON: flat_segments" grep -qE "\"flat_segments\": ${flat:-x}," "$out"
run_silk info "$tmp/sphere.obj" --ortho auto
check "info reports orthographic" grep -q 'orthographic' "$out"
run_silk info "$tmp/sphere.obj"
check "info reports the default camera" grep -qE '^ +projection: +perspective, fov 35$' "$out"
check "info fell back: no" test "$(info_value "$out" "  fell back")" = no

# What the frame needs, not the whole arena: `needed` (what stays plus the
# frame's own bytes) is an arena that draws the same picture, and the
# bound for any view is at least the frame's bytes.
run_silk info "$tmp/torus.obj" --size 160x120 --format rgb565
needed=$(info_value "$out" "  needed"); fb=$(info_value "$out" "  frame bytes"); bound=$(info_value "$out" "  frame bytes bound")
peak=$(info_value "$out" "  peak")
check "info: needed $needed below the peak $peak" test "${needed:-0}" -gt 0 -a "${needed:-0}" -lt "${peak:-0}"
check "info: the bound $bound at least the frame's $fb bytes" test "${bound:-0}" -ge "${fb:-1}"
"$SILK" render "$tmp/torus.obj" --size 160x120 --format rgb565 -o "$tmp/roomy.ppm"
"$SILK" render "$tmp/torus.obj" --size 160x120 --format rgb565 --arena "$needed" -o "$tmp/needed.ppm"
check "info: an arena of the needed bytes draws the same frame" cmp -s "$tmp/roomy.ppm" "$tmp/needed.ppm"
if command -v python3 >/dev/null; then
    run_silk info "$tmp/torus.obj" --size 160x120 --format rgb565 --json
    check "info --json: needed and the bound" python3 -c "
import json, sys
d = json.load(open(sys.argv[1]))
assert d['arena']['needed'] == $needed and d['frame']['frame_bytes_bound'] == $bound
" "$out"
fi
run_silk info "$tmp/torus.obj" --mode pn
check "info: no bound for a stored frame" test -z "$(info_value "$out" "  frame bytes bound")"

# An arena too small to load the mesh: one line, exit 1.
run_silk info "$tmp/sphere.obj" --arena 4K
check "info with a 4K arena fails cleanly" test "$rc" -eq 1 -a "$(wc -l <"$err")" -eq 1

done_testing
