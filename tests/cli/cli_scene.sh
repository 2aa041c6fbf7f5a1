#!/bin/sh
# cli_scene.sh - `silk render A B ...`: several meshes in one picture.  Two
# meshes drawn together differ from either alone and cover what both do;
# a mesh placed far off leaves the other's pixels as it draws them alone
# in the same frame; --tint and --mode-of change only their mesh; the
# picture is deterministic; the per-mesh options' errors are one line and
# exit 2, and a failure leaves no output.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen torus -o "$tmp/torus.obj" || { fail "gen torus" "exit $?"; done_testing; exit 1; }
"$SILK" gen sphere -o "$tmp/sphere.obj"
t=$tmp/torus.obj
s=$tmp/sphere.obj
cam="--size 96x72 --eye 0.9,1.7,4.3 --target 0.2,0,0 --bg ffffff"
place="--place 1:0,0,0:-20,62,0 --place 2:0.8,0.1,0.1:30,0,10:0.55"

run_silk render "$t" "$s" $cam $place --tint 2:8090c0 -o "$tmp/two.ppm"
if [ "$rc" -eq 0 ] && [ ! -s "$err" ] && [ "$(ppm_size "$tmp/two.ppm")" = 96x72 ]; then pass "two meshes"; else
    fail "two meshes" "exit $rc: $(head -c 300 "$err")"; fi
run_silk render "$t" "$s" $cam $place --tint 2:8090c0 -o "$tmp/two-again.ppm"
check "deterministic" cmp -s "$tmp/two.ppm" "$tmp/two-again.ppm"

# the sphere moved out of the frame: the torus as it is drawn alone
run_silk render "$t" "$s" $cam --place 1:0,0,0:-20,62,0 --place 2:0,400,0 -o "$tmp/torus-only.ppm"
run_silk render "$t" "$t" $cam --place 1:0,0,0:-20,62,0 --place 2:0,400,0 -o "$tmp/torus-twice.ppm"
check "a mesh out of the frame changes nothing" cmp -s "$tmp/torus-only.ppm" "$tmp/torus-twice.ppm"
n_two=$(ppm_count_not "$tmp/two.ppm" ffffff)
n_torus=$(ppm_count_not "$tmp/torus-only.ppm" ffffff)
check "the sphere adds pixels ($n_two > $n_torus)" [ "$n_two" -gt "$n_torus" ]
check "the pictures differ" sh -c "! cmp -s '$tmp/two.ppm' '$tmp/torus-only.ppm'"

run_silk render "$t" "$s" $cam $place --tint 2:c04040 -o "$tmp/red.ppm"
check "--tint changes the picture" sh -c "! cmp -s '$tmp/two.ppm' '$tmp/red.ppm'"
run_silk render "$t" "$s" $cam $place --tint 2:8090c0 --mode-of 1:flat -o "$tmp/flat.ppm"
check "--mode-of changes the picture" sh -c "! cmp -s '$tmp/two.ppm' '$tmp/flat.ppm'"
run_silk render "$t" "$s" $cam $place --format rgb565 -o "$tmp/565.png"
check "rgb565 png" is_png "$tmp/565.png"

want='names mesh 3' expect_usage "a mesh number past the meshes" render "$t" "$s" --place 3:0,0,0 -o "$tmp/x.png"
want='number and a colon' expect_usage "no mesh number" render "$t" "$s" --place 0,0,0 -o "$tmp/x.png"
want='three numbers' expect_usage "a bad position" render "$t" "$s" --place 2:1,2 -o "$tmp/x.png"
want='between' expect_usage "a zero scale" render "$t" "$s" --place 2:0,0,0:0,0,0:0 -o "$tmp/x.png"
want='not a mode' expect_usage "a bad mode" render "$t" "$s" --mode-of 2:bogus -o "$tmp/x.png"
want='RRGGBB|colour|color' expect_usage "a bad tint" render "$t" "$s" --tint 2:xyz -o "$tmp/x.png"
want='several meshes' expect_usage "--place with one mesh" render "$t" --place 1:0,0,0 -o "$tmp/x.png"
want='one frame' expect_usage "--compare with two meshes" render "$t" "$s" --compare -o "$tmp/x.png"
want='once' expect_usage "standard input twice" render - - -o "$tmp/x.png"
want='missing.obj' expect_input "a missing mesh" render "$t" "$tmp/missing.obj" -o "$tmp/x.png"
check "no output after a failure" [ ! -e "$tmp/x.png" ]
check "no temporary files" no_tmp_files "$tmp"

done_testing
