#!/bin/sh
# cli_grid.sh - `silk bench --grid`, the robustness grid (docs/measurements.md,
# "The robustness grid"), on the shared meshes whose outlines smooth mode
# once got visibly wrong - bunny-500's ear notch, fish-500's belly,
# knot-480's concave rim, dragon-500's creases along its base, the cow
# prepared with fitted normals (a torn leg), feline prepared with and
# without them (holes in its tail),
# fandisk-1000's straight creases - over all 120 views: no view may lose 10
# or more pixels lying 3 px inside both the flat and the detailed object,
# nor show an enclosed hole of more than 2 px.  Also the tool's output:
# one summary line per mesh and its worst views with the silk render
# command that shows them (which runs), a CSV row per view, the Markdown
# table, the pictures of --dump, and bad options.  The whole grid (every
# shared mesh and prepared model) is bench/grid.sh, in make bench.
. "$(dirname "$0")/../shlib.sh"

if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: the grid is measured in the normal pass (its frames' memory is checked by the core's tests)"
    done_testing
    exit 0
fi
meshes=${SILK_MESHES:-../shared/meshes}
if [ ! -f "$meshes/bunny-500.obj" ]; then
    echo "skip: no shared meshes in $meshes"
    done_testing
    exit 0
fi

# The prepared models, kept in the build directory (made again only when
# the preparation's sources change).
cache=$build/grid
if ! sh "$here/../bench/grid-models.sh" "$SILK" "$cache" cow feline; then
    fail "prepared models" "bench/grid-models.sh failed"
    done_testing
    exit 1
fi

list="$meshes/bunny-500.obj:$meshes/bunny-fine.obj $meshes/fish-500.obj:$meshes/fish-fine.obj
 $meshes/knot-480.obj:$meshes/knot-fine.obj $meshes/dragon-500.obj:$meshes/dragon-fine.obj
 $meshes/fandisk-1000.obj:$meshes/fandisk-fine.obj $cache/cow-prep.silk:$meshes/cow-fine.obj
 $cache/feline-prep.silk:$meshes/feline-fine.obj $cache/feline-nofit.silk:$meshes/feline-fine.obj"
mkdir -p "$tmp/dump"
# shellcheck disable=SC2086
run_silk bench --grid $list --worst 2 --max-lost 9 --max-hole 2 --csv "$tmp/g.csv" --md "$tmp/g.md" --dump "$tmp/dump"
check "grid: no view loses 10 px or has a hole over 2 px (exit $rc)" test "$rc" -eq 0
if [ "$rc" -ne 0 ]; then sed 's/^/  /' "$err"; fi
line_re='^grid [a-z0-9-]+ views=120 lost10=0 lost_max=[0-9] hole_views=0 hole_max=[0-2] bulge_max=[0-9.]+ excess_max=[0-9.]+ flat_segments=[0-9]+$'
check "a summary line per mesh" [ "$(grep -cE "$line_re" "$out")" = 8 ]
check "two worst views per mesh, each with its command" \
    [ "$(grep -cE '^grid-view .* yaw=[0-9.]+ pitch=-?[0-9]+ lost=[0-9]+ .*: silk render .* --yaw [0-9.]+ --pitch -?[0-9]+ --size 320x240 --aa off --compare$' "$out")" = 16 ]
check "CSV: a row per view" [ "$(tail -n +2 "$tmp/g.csv" | wc -l)" = 960 ]
check "CSV columns" [ "$(head -n 1 "$tmp/g.csv" | cut -d, -f1-8)" = "mesh,yaw,pitch,lost,hole,hole_px,bulge_px,excess_px" ]
check "Markdown: the summary and the worst views" grep -q '^| cow-prep | 120 | 0 |' "$tmp/g.md"
check "dump: a picture per worst view" [ "$(ls "$tmp/dump" | wc -l)" = 16 ]
check "dump: PNG" is_png "$(ls "$tmp/dump"/*.png | head -n 1)"

# The command a worst view names shows that view.
cmd=$(grep '^grid-view cow-prep ' "$out" | head -n 1 | sed 's/.*: silk render //; s/ -o view.png / -o '"$(echo "$tmp" | sed 's/[\/&]/\\&/g')"'\/view.png /')
# shellcheck disable=SC2086
run_silk render $cmd
check "the worst view's command renders it (exit $rc)" test "$rc" -eq 0 -a -s "$tmp/view.png"
check "it is flat | smooth side by side" [ "$(png_size "$tmp/view.png")" = 640x240 ]

# One mesh without a detailed model: measured against its flat drawing.
"$SILK" gen torus -o "$tmp/torus.obj"
run_silk bench --grid "$tmp/torus.obj" --yaws 6 --pitches -30,30 --threads 1 --worst 0
check "no detailed model: 12 views, nothing lost" grep -qE '^grid torus views=12 lost10=0 lost_max=0 ' "$out"

want="--pitches" expect_usage "bad pitches" bench --grid "$tmp/torus.obj" --pitches 10,x
want="--yaws" expect_usage "bad yaws" bench --grid "$tmp/torus.obj" --yaws 0
want="unknown option" expect_usage "unknown option" bench --grid "$tmp/torus.obj" --frobnicate
want="no mesh" expect_usage "no mesh" bench --grid
expect_input "missing mesh" bench --grid "$tmp/none.obj"
check "no partial CSV after a failure" no_tmp_files "$tmp"

done_testing
