#!/bin/sh
# cli_bench_modes.sh - `silk bench` over the render modes: one line per
# mesh, mode and projection; the CSV starts with the documented columns and
# has a row per line; the Markdown and the chart are written; the error of
# a view is exactly what `silk diff` says about the same two renders (the
# --dump images), and view 0 is `silk render`'s default camera; flat draws
# the mesh's triangles and PN level 3 nine per triangle; bad options are
# usage errors, missing meshes input errors.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere -o "$tmp/coarse.obj" || { fail "gen" "exit $?"; done_testing; exit 1; }
"$SILK" gen sphere --segments 48 --bands 48 -o "$tmp/fine.obj"
# --dump makes its directory; one in a directory that is missing is refused
# before any frame, naming it

run_silk bench --pair "$tmp/coarse.obj:$tmp/fine.obj" --views 2 --size 160x120 --modes flat,smooth,pn3 --reps 1 \
    --csv "$tmp/b.csv" --md "$tmp/b.md" --plot "$tmp/b.png" --dump "$tmp/dump"
check "exit 0, stderr empty" test "$rc" -eq 0 -a ! -s "$err"
line_re='^bench coarse (flat|smooth|pn3|fine) (ortho|perspective) triangles=[0-9]+ drawn=[0-9]+ ms=[0-9.]+ fps=[0-9.]+ error_mean_px=[0-9.]+ error_max_px=[0-9.]+ arena_bytes=[0-9]+ bytes=[0-9]+$'
check "8 lines: 3 modes and the reference, 2 projections" [ "$(grep -cE "$line_re" "$out")" = 8 ]
check "CSV columns" [ "$(head -n 1 "$tmp/b.csv" | cut -d, -f1-10)" = \
    "mesh,mode,level,projection,triangles_in,triangles_drawn,ms_per_frame,error_mean_px,error_max_px,arena_peak_bytes" ]
check "CSV: a row per line" [ "$(tail -n +2 "$tmp/b.csv" | wc -l)" = 8 ]
check "CSV: pn3 has level 3, 9 triangles per triangle" grep -q "^coarse,pn3,3,ortho,200,1800\.0," "$tmp/b.csv"
check "CSV: flat draws the mesh" grep -q '^coarse,flat,,perspective,200,200\.0,' "$tmp/b.csv"
check "Markdown table" grep -q '^| coarse | 200 | smooth |' "$tmp/b.md"
check "Markdown: smooth mode's goals checked" grep -qE '^\| coarse \| [0-9.]+ \((met|NOT met)\) \| .* \| (yes|no) \|$' "$tmp/b.md"
check "chart is a PNG" is_png "$tmp/b.png"
check "16 dumped views: 2 projections x 2 views x (3 modes + fine)" [ "$(ls "$tmp/dump" | wc -l)" = 16 ]
want="--dump $tmp/no/dump: the directory $tmp/no does not exist" expect_input "--dump into a missing directory" \
    bench "$tmp/coarse.obj" --views 1 --reps 1 --modes flat --dump "$tmp/no/dump"
want="the directory $tmp/no does not exist" expect_input "--csv into a missing directory" \
    bench "$tmp/coarse.obj" --views 1 --reps 1 --modes flat --csv "$tmp/no/b.csv"
# on an analytic sphere the smoothed outline is far closer than the polygon
fe=$(awk -F, '$2 == "flat" && $4 == "perspective" { print $8 }' "$tmp/b.csv")
se=$(awk -F, '$2 == "smooth" && $4 == "perspective" { print $8 }' "$tmp/b.csv")
check "sphere: smooth error $se < flat error $fe / 2" awk -v s="$se" -v f="$fe" 'BEGIN { exit !(s < f / 2) }'

# Bytes: the coarse mesh's flash bytes grow with its triangles, and a pair
# may name its own modes; --plot-bytes draws error against bytes.
"$SILK" gen sphere --segments 32 --bands 16 -o "$tmp/coarse2.obj"
run_silk bench --pair "$tmp/coarse.obj:$tmp/fine.obj" --pair "$tmp/coarse2.obj:$tmp/fine.obj=smooth" --views 1 \
    --size 80x60 --modes flat,smooth --reps 1 --projection ortho --csv "$tmp/y.csv" --plot-bytes "$tmp/y.png"
check "per-pair modes: coarse2 drawn smooth only" [ "$(grep -c '^bench coarse2 ' "$out")" = 2 ]
check "per-pair modes: coarse drawn flat and smooth" [ "$(grep -c '^bench coarse ' "$out")" = 3 ]
b1=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } $1 == "coarse" && $2 == "smooth" { print $c["bytes"] }' "$tmp/y.csv")
b2=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } $1 == "coarse2" && $2 == "smooth" { print $c["bytes"] }' "$tmp/y.csv")
check "bytes grow with the triangles: $b1 < $b2" [ "$b1" -gt 0 -a "$b1" -lt "$b2" ]
check "bytes chart is a PNG" is_png "$tmp/y.png"
want="not one of --modes" expect_usage "pair mode not in --modes" bench --pair "$tmp/coarse.obj:$tmp/fine.obj=pn3" --modes flat
want="COARSE:FINE=MODES" expect_usage "pair with empty modes" bench --pair "$tmp/coarse.obj:$tmp/fine.obj="

# One view: the bench's error is silk diff's on the same two images.
rm -f "$tmp/dump"/*
run_silk bench --pair "$tmp/coarse.obj:$tmp/fine.obj" --views 1 --size 160x120 --modes smooth --reps 1 \
    --projection perspective --dump "$tmp/dump"
mean=$(grep ' smooth ' "$out" | sed -E 's/.*error_mean_px=([^ ]+).*/\1/')
max=$(grep ' smooth ' "$out" | sed -E 's/.*error_max_px=([^ ]+).*/\1/')
run_silk diff "$tmp/dump/coarse-perspective-00-fine.png" "$tmp/dump/coarse-perspective-00-smooth.png"
check "diff agrees: mean $mean" grep -q "mean_px=$mean " "$out"
check "diff agrees: max $max" grep -q "hausdorff_px=$max\$" "$out"
"$SILK" render "$tmp/coarse.obj" --size 160x120 --mode smooth -o "$tmp/render.png"
run_silk diff "$tmp/render.png" "$tmp/dump/coarse-perspective-00-smooth.png"
check "view 0 is silk render's default camera" grep -q "differing=0 " "$out"

# a mesh without a reference: no error columns
run_silk bench "$tmp/coarse.obj" --views 1 --size 32x24 --modes flat --reps 1 --csv "$tmp/c.csv"
check "no reference: no error" grep -qE '^bench coarse flat ortho triangles=200 drawn=200 ms=[0-9.]+ fps=[0-9.]+ arena_bytes=[0-9]+ bytes=[0-9]+$' "$out"
check "no reference: empty CSV cells" grep -q '^coarse,flat,,ortho,200,200\.0,[0-9.]*,,,' "$tmp/c.csv"

# the visibility benchmark is still there
run_silk bench --visibility-pass --batches 1 --projection parallel "$tmp/coarse.obj"
check "--visibility-pass runs the visibility benchmark" grep -q '^visibility ' "$out"

want="not a mode" expect_usage "unknown mode" bench "$tmp/coarse.obj" --modes flat,shiny
expect_usage "PN level too high" bench "$tmp/coarse.obj" --modes pn99
# one parser for every --modes: a mode listed twice is refused alike
want="listed twice" expect_usage "bench --modes pn3,pn3" bench "$tmp/coarse.obj" --modes pn3,pn3
want="listed twice" expect_usage "bench --modes pn,pn3 (pn is pn3 here)" bench "$tmp/coarse.obj" --modes pn,pn3
want="listed twice" expect_usage "render --modes pn3,pn3" render "$tmp/coarse.obj" --modes pn3,pn3 --sheet -o "$tmp/m.png"
expect_usage "mode twice" bench "$tmp/coarse.obj" --modes flat,flat
want="COARSE:FINE" expect_usage "pair without colon" bench --pair "$tmp/coarse.obj"
expect_usage "no mesh" bench --views 2
expect_usage "zero views" bench "$tmp/coarse.obj" --views 0
expect_usage "chart must be PNG" bench "$tmp/coarse.obj" --plot "$tmp/x.ppm"
expect_usage "unknown option" bench "$tmp/coarse.obj" --fast
want="no-such.obj: cannot open" expect_input "missing mesh" bench "$tmp/no-such.obj" --views 1 --size 16x16
want="no-such.obj: cannot open" expect_input "missing reference" bench --pair "$tmp/coarse.obj:$tmp/no-such.obj" --views 1 --size 16x16
check "no temporary files left" no_tmp_files "$tmp"

done_testing
