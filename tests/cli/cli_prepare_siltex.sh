#!/bin/sh
# cli_prepare_siltex.sh - `silk prepare --siltex`: a generated sphere prepared with
# its silhouette texture holds an STEX section of the size its layout
# (docs/formats.md) gives, whole, compressed or with a colour map from the
# detailed mesh's vertex colours; the model still draws; bad
# option values are one-line usage errors and leave no output behind.
# tests/prep/test_stex.c checks the texture itself.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere --segments 24 --bands 16 -o "$tmp/sphere.obj" >/dev/null || { fail "gen" "exit $?"; done_testing; exit 1; }

# section_entry FILE NAME FIELD: the section table's FIELD (8 offset, 12 size)
# for the section NAME (four letters); empty without one
section_entry() {
    n=$(od -A n -t u4 -j 20 -N 4 "$1" | tr -d ' ')
    i=0
    while [ "$i" -lt "$n" ]; do
        e=$((32 + 20 * i))
        if [ "$(od -A n -c -j "$e" -N 4 "$1" | tr -d ' ')" = "$2" ]; then
            od -A n -t u4 -j $((e + $3)) -N 4 "$1" | tr -d ' '
            return
        fi
        i=$((i + 1))
    done
}
section_size() { section_entry "$1" "$2" 12; }
# stex_flags FILE: the STEX section's flags word
stex_flags() { od -A n -t u4 -j $(($(section_entry "$1" STEX 8) + 4)) -N 4 "$1" | tr -d ' '; }
# field NAME: the value of NAME= in the summary line
field() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p" "$out"; }
pad4() { echo $((($1 + 3) / 4 * 4)); }

run_silk prepare "$tmp/sphere.obj" -o "$tmp/s.silk" --triangles 80 --siltex --atlas 32 --angles 8
check "--siltex: the summary line" grep -qE "^prepare .* siltex_bytes=[0-9]+ siltex_error=[0-9.]+ siltex_multi=[0-9.]+ bytes=" "$out"
check "--siltex: nothing on stderr" [ ! -s "$err" ]
ht=$(field hull_triangles)
hv=$((ht / 2 + 2))
size=$(section_size "$tmp/s.silk" STEX)
check "STEX: present" [ -n "$size" ]
check "STEX: header, frames, corners, 8 angles and a normal per texel" \
    [ "$size" = "$(pad4 $((32 + 12 * hv + 12 * ht + 32 * 32 * (8 + 2))))" ]
check "STEX: the size printed" [ "$size" = "$(field siltex_bytes)" ]
check "STEX: eq. 3 error under 2%" awk -v e="$(field siltex_error)" 'BEGIN { exit !(e < 0.02) }'
check "HULL and SMAP still there" [ -n "$(section_size "$tmp/s.silk" HULL)" -a -n "$(section_size "$tmp/s.silk" SMAP)" ]
run_silk render "$tmp/s.silk" -o "$tmp/clip.png" --size 96x64 --mode clip
check "the model draws in clip mode" test "$rc" -eq 0 -a -s "$tmp/clip.png"

# One model in every mode: side by side, from one camera.
run_silk render "$tmp/s.silk" --modes flat,smooth,clip,siltex --sheet -o "$tmp/modes.png" --size 96x64
check "--modes flat,smooth,clip,siltex --sheet draws the model (exit $rc: $(head -c 200 "$err"))" \
    test "$rc" -eq 0 -a ! -s "$err" -a -s "$tmp/modes.png"
eye=$("$SILK" info "$tmp/s.silk" --size 96x64 | grep '^  eye:')
for m in clip siltex; do
    e=$("$SILK" info "$tmp/s.silk" --size 96x64 --mode $m | grep '^  eye:')
    check "render --mode $m: the default camera of flat and smooth ($e; $eye)" test -n "$eye" -a "$e" = "$eye"
    "$SILK" view "$tmp/s.silk" --size 96x64 --events "h shot:$tmp/v-$m-start.ppm" --mode $m >/dev/null 2>&1
    key=5; [ $m = siltex ] && key=6
    "$SILK" view "$tmp/s.silk" --size 96x64 --events "h $key shot:$tmp/v-$m-key.ppm" >/dev/null 2>&1
    check "view, key $key: the view of view --mode $m" cmp -s "$tmp/v-$m-start.ppm" "$tmp/v-$m-key.ppm"
done
# --compare: flat beside the mode asked for
for m in clip siltex pn; do
    "$SILK" render "$tmp/s.silk" --compare --mode $m --size 96x64 -o "$tmp/cmp.ppm" 2>"$err"
    "$SILK" render "$tmp/s.silk" --mode $m --size 96x64 -o "$tmp/one.ppm"
    "$SILK" render "$tmp/s.silk" --mode flat --size 96x64 -o "$tmp/flat.ppm"
    ppm_columns "$tmp/cmp.ppm" 96 96 >"$tmp/right"
    ppm_columns "$tmp/cmp.ppm" 0 96 >"$tmp/left"
    ppm_columns "$tmp/one.ppm" 0 96 >"$tmp/want"
    check "--compare --mode $m: the right half is $m" cmp -s "$tmp/right" "$tmp/want"
    ppm_columns "$tmp/flat.ppm" 0 96 >"$tmp/want"
    check "--compare --mode $m: the left half is flat" cmp -s "$tmp/left" "$tmp/want"
done
want="--compare puts flat beside" expect_usage "--compare --mode flat" render "$tmp/s.silk" --compare --mode flat -o "$tmp/x.png"
# silk info names the sections, and says which mesh it counts
"$SILK" info "$tmp/s.silk" >"$tmp/info.txt"
check "info: the model's sections ($(info_value "$tmp/info.txt" sections))" \
    grep -qE '^sections: +MESH [0-9]+ bytes \(required\), HULL [0-9]+ bytes, SMAP [0-9]+ bytes, STEX [0-9]+ bytes$' "$tmp/info.txt"
check "info: the counts are the coarse mesh's" test "$(info_value "$tmp/info.txt" 'counts of')" = MESH
check "info --mode clip: the counts are the hull's" \
    test "$("$SILK" info "$tmp/s.silk" --mode clip | sed -n 's/^counts of: *//p')" = HULL

run_silk prepare "$tmp/sphere.obj" -o "$tmp/svd.silk" --triangles 80 --siltex --atlas 32 --angles 8 --siltex-svd 4
size=$(section_size "$tmp/svd.silk" STEX)
svd=$((2 * 8 + 4 * 4 + 2 * 4 * 8 + 32 * 32 * 4))
check "--siltex-svd 4: mean, scales, eigenfunctions, weights" \
    [ "$size" = "$(pad4 $((32 + 12 * hv + 12 * ht + (svd + 1) / 2 * 2 + 32 * 32 * 2)))" ]
check "--siltex-svd 4: flags bit 0" [ "$(stex_flags "$tmp/svd.silk")" = 1 ]
check "whole: flags 0" [ "$(stex_flags "$tmp/s.silk")" = 0 ]

# vertex colours: a colour map after the normal map
awk '/^v /{ print $0, ($2 > 0 ? "1 0.5 0" : "0 0.5 1"); next } { print }' "$tmp/sphere.obj" >"$tmp/colour.obj"
run_silk prepare "$tmp/colour.obj" -o "$tmp/colour.silk" --triangles 80 --siltex --atlas 32 --angles 8
check "colours: flags bit 1" [ "$(stex_flags "$tmp/colour.silk")" = 2 ]
check "colours: 3 bytes more per texel" \
    [ "$(section_size "$tmp/colour.silk" STEX)" = "$(pad4 $((32 + 12 * hv + 12 * ht + 32 * 32 * (8 + 2 + 3))))" ]

run_silk prepare "$tmp/sphere.obj" -o "$tmp/cmp.silk" --triangles 80 --siltex --atlas 32 --angles 16 --siltex-compare
check "--siltex-compare: E = 4, 8, 16 and whole" [ "$(grep -cE '^siltex svd=(4|8|16|0) siltex_bytes=[0-9]+ siltex_error=' "$out")" = 4 ]

# errors
expect_usage "--atlas 7" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --atlas 7
expect_usage "--atlas x" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --atlas x
expect_usage "--angles 65" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --angles 65
expect_usage "--angles needs a value" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --angles
want="more eigenfunctions" expect_usage "--siltex-svd above K" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 \
    --siltex --angles 8 --siltex-svd 9
want="goes with --siltex" expect_usage "--atlas without --siltex" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --atlas 64
want="--no-clip" expect_usage "--siltex --no-clip" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --no-clip
want="do not fit" expect_input "atlas too small" prepare "$tmp/sphere.obj" -o "$tmp/x.silk" --triangles 80 --siltex --atlas 8
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n' >"$tmp/open.obj"
want="closed manifold" expect_input "open mesh" prepare "$tmp/open.obj" -o "$tmp/x.silk" --triangles 4 --siltex
check "no output after the errors" [ ! -e "$tmp/x.silk" ]

done_testing
