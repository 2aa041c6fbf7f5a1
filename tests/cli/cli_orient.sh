#!/bin/sh
# cli_orient.sh - triangle orientation at load (`--orient fix|keep`,
# docs/formats.md): a generated sphere with some triangles wound the other
# way, and one inside out, render byte-identical to the sphere itself in
# every mode; `silk info` reports the triangles turned round and `silk
# render` says so in one line on stderr; `--orient keep` draws the file as
# it is; a Moebius band (non-orientable) and a non-manifold fin render
# without a crash; a bad value is a usage error.
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
# Wind every third face the other way (its last two corners swapped), or all.
awk '/^f / { if (n++ % 3 == 0) { t = $3; $3 = $4; $4 = t } } { print }' "$sphere" >"$tmp/flipped.obj"
awk '/^f / { t = $3; $3 = $4; $4 = t } { print }' "$sphere" >"$tmp/inside-out.obj"
nf=$(grep -c '^f ' "$sphere")

opts="--size 200x150"
for mode in smooth flat pn blend; do
    run_silk render "$sphere" $opts --mode $mode -o "$tmp/ref-$mode.png"
    check "$mode: sphere renders, stderr empty" test "$rc" -eq 0 -a ! -s "$err"
    for v in flipped inside-out; do
        run_silk render "$tmp/$v.obj" $opts --mode $mode -o "$tmp/$v-$mode.png"
        check "$mode: $v sphere renders" test "$rc" -eq 0
        check "$mode: $v sphere is byte-identical to the sphere" cmp -s "$tmp/ref-$mode.png" "$tmp/$v-$mode.png"
    done
done

run_silk render "$tmp/inside-out.obj" $opts -o "$tmp/x.png"
check "render: one note on stderr" test "$(wc -l <"$err")" -eq 1
check "... naming the file and the count" grep -q "^silk: note: $tmp/inside-out.obj: $nf triangles turned round" "$err"
run_silk info "$tmp/inside-out.obj"
check "info: reoriented triangles: $nf" test "$(info_value "$out" "reoriented triangles")" = "$nf"
check "info: no note on stderr" test ! -s "$err"
run_silk info "$tmp/flipped.obj"
check "info: a third reoriented" test "$(info_value "$out" "reoriented triangles")" = "$(( (nf + 2) / 3 ))"
run_silk info "$sphere"
check "info: 0 on the sphere" test "$(info_value "$out" "reoriented triangles")" = 0

run_silk render "$tmp/inside-out.obj" $opts --orient keep -o "$tmp/keep.png"
check "--orient keep: renders, no note" test "$rc" -eq 0 -a ! -s "$err"
check "--orient keep: draws the file's winding" test -n "$(cmp "$tmp/keep.png" "$tmp/ref-smooth.png")"
run_silk info "$tmp/inside-out.obj" --orient keep
check "--orient keep: info reports 0" test "$(info_value "$out" "reoriented triangles")" = 0

# A Moebius band of 16 quads, and three fins on one edge.
awk 'BEGIN { n = 16; pi = 3.14159265358979
    for (i = 0; i < n; i++) { a = 2 * pi * i / n
        for (s = -1; s <= 1; s += 2) { w = 0.3 * s
            printf "v %.6f %.6f %.6f\n", (1 + w * cos(a / 2)) * cos(a), (1 + w * cos(a / 2)) * sin(a), w * sin(a / 2) } }
    for (i = 0; i < n; i++) { a0 = 2 * i + 1; a1 = a0 + 1; b0 = 2 * ((i + 1) % n) + 1; b1 = b0 + 1
        if (i == n - 1) { t = b0; b0 = b1; b1 = t }
        printf "f %d %d %d\nf %d %d %d\n", a0, b0, b1, a0, b1, a1 } }' >"$tmp/moebius.obj"
for mode in smooth flat; do
    run_silk render "$tmp/moebius.obj" $opts --mode $mode -o "$tmp/moebius-$mode.png"
    check "Moebius band, $mode: renders" test "$rc" -eq 0 -a -s "$tmp/moebius-$mode.png"
done
check "Moebius band: the note says non-orientable" grep -q "non-orientable surface; left as in the file" "$err"
run_silk info "$tmp/moebius.obj"
check "Moebius band: info reports the triangles" test "$(info_value "$out" "non-orientable triangles")" = "32 (left as in the file)"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 2 1 5\n' >"$tmp/fin.obj"
run_silk render "$tmp/fin.obj" $opts -o "$tmp/fin.png"
check "non-manifold fin: renders" test "$rc" -eq 0

want='--orient must be fix or keep'
expect_usage "--orient bad value" render "$sphere" -o "$tmp/y.png" --orient outward
check "no image after a usage error" test ! -e "$tmp/y.png"
done_testing
