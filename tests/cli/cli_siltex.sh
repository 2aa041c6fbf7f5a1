#!/bin/sh
# cli_siltex.sh - siltex mode from the command line, on the analytic
# spheres' model of tests/core/test_siltex.c (its silhouette texture is made
# exactly, without ray casting): render, info (text and JSON), bench with a
# --pair (the silhouette error against the detailed sphere), profile, the
# viewer's key, the silhouette lines; and the errors: a mesh file, a model
# without a texture.
. "$(dirname "$0")/../shlib.sh"

if ! "$build/tests/test_siltex" --write "$tmp/s.silk" >/dev/null 2>&1; then
    fail "model" "$build/tests/test_siltex cannot write the model (make $build/tests/test_siltex)"
    done_testing
    exit 1
fi

run_silk render "$tmp/s.silk" --mode siltex --size 160x120 -o "$tmp/s.png"
check "render --mode siltex" [ "$rc" -eq 0 ] && [ -s "$tmp/s.png" ]
run_silk render "$tmp/s.silk" --mode siltex --size 160x120 --ortho auto --format rgb565 -o "$tmp/o.ppm"
check "render --mode siltex, orthographic, rgb565" [ "$rc" -eq 0 ] && [ -s "$tmp/o.ppm" ]

run_silk render "$tmp/s.silk" --mode siltex --size 160x120 --lines only -o "$tmp/l.png"
check "render --mode siltex --lines only (eq. 5)" [ "$rc" -eq 0 ] && [ -s "$tmp/l.png" ]

run_silk info "$tmp/s.silk" --mode siltex --size 160x120
check "info: atlas, azimuths, bytes" grep -qE '^  atlas: +108x108 texels, 8 azimuths \(K\), 0 eigenfunctions' "$out"
check "info: texture bytes" grep -qE '^  texture bytes: +[0-9]+' "$out"
run_silk info "$tmp/s.silk" --mode siltex --size 160x120 --json
check "info --json: the texture" grep -q '"atlas_width": 108, "atlas_height": 108, "azimuths": 8' "$out"

# The detailed model: a sphere of radius 1 (the texture's inner sphere).
"$SILK" gen sphere --segments 96 --bands 48 -o "$tmp/fine.obj" >/dev/null
run_silk bench "$tmp/s.silk" --pair "$tmp/s.silk:$tmp/fine.obj" --modes flat,siltex --views 2 --size 160x120
check "bench: siltex rows with an error" grep -qE '^bench s siltex (ortho|perspective) .*error_mean_px=0\.[0-9]+' "$out"
m=$(awk '/^bench s siltex perspective .*error_mean_px/ { sub(/.*error_mean_px=/, ""); print $1 + 0 }' "$out")
check "bench: siltex's mean error under 0.5 px ($m)" awk "BEGIN { exit !($m < 0.5) }"

run_silk profile "$tmp/s.silk" --mode siltex
check "profile --mode siltex: the texture's flash bytes" grep -qE '^  silhouette texture +[0-9]+' "$out"

run_silk view "$tmp/s.silk" --size 80x60 --events "6 shot:$tmp/v.png"
check "view: key 6 is siltex" grep -q 'siltex' "$out"

want='draws a prepared model' expect_input "siltex on a mesh file" render "$tmp/fine.obj" --mode siltex -o "$tmp/x.png"
"$SILK" prepare "$tmp/fine.obj" -o "$tmp/noclip.silk" --triangles 100 --no-clip >/dev/null 2>&1
want='no (HULL|STEX) section' expect_input "siltex on a model without a texture" render "$tmp/noclip.silk" --mode siltex \
    -o "$tmp/x.png"
check "no output left behind" [ ! -e "$tmp/x.png" ]

done_testing
