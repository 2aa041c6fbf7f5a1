#!/bin/sh
# cli_texture.sh - textures, materials and vertex colours through the
# command: `silk gen --uv`, `--texture FILE.png` and `--texture checker`,
# an OBJ's mtllib / usemtl (Kd, map_Kd), and what goes wrong: a texture
# that cannot be read or a mesh without texture coordinates is an error; a
# missing .mtl, material or map_Kd image is one warning line and the model
# renders untextured; `silk pack --texture` packs the texels.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere --uv --segments 12 --bands 8 -o "$tmp/globe.obj" >/dev/null
"$SILK" gen sphere --segments 12 --bands 8 -o "$tmp/plain.obj" >/dev/null
check "gen --uv writes vt lines and v/vt faces" grep -q '^f [0-9]*/[0-9]* ' "$tmp/globe.obj"
want='--uv does not apply to a cone' expect_usage "gen --uv on a cone" gen cone --uv -o "$tmp/c.obj"

run_silk render "$tmp/globe.obj" --size 64x48 -o "$tmp/untextured.png"
check "the globe renders without a texture" [ "$rc" -eq 0 ]
run_silk render "$tmp/globe.obj" --size 64x48 --texture checker -o "$tmp/checker.png"
check "--texture checker renders, quietly" [ "$rc" -eq 0 ] && [ ! -s "$err" ]
check "the texture changes the picture" sh -c "! cmp -s '$tmp/untextured.png' '$tmp/checker.png'"
"$SILK" render "$tmp/globe.obj" --size 32x32 --texture checker:16 --ortho auto --mode flat -o "$tmp/small.png" \
    2>/dev/null
check "--texture checker:16" [ -s "$tmp/small.png" ]

want='no-such.png' expect_input "an unreadable texture" render "$tmp/globe.obj" --texture "$tmp/no-such.png" \
    -o "$tmp/x.png"
check "no image after an unreadable texture" [ ! -e "$tmp/x.png" ]
want='has no texture coordinates' expect_usage "--texture on a mesh without uvs" render "$tmp/plain.obj" \
    --texture checker -o "$tmp/x.png"
want='checker.s size must be 8 to' expect_input "a checker too small" render "$tmp/globe.obj" --texture checker:3 \
    -o "$tmp/x.png"

# how the texels are stored and sampled
for opt in "--texture-format rgb565" "--texture-format pal8" "--texture-filter nearest" "--texture-wrap clamp"; do
    # shellcheck disable=SC2086
    run_silk render "$tmp/globe.obj" --size 64x48 --texture checker $opt -o "$tmp/opt.png"
    check "$opt renders" [ "$rc" -eq 0 ] && [ -s "$tmp/opt.png" ]
    check "$opt changes the picture" sh -c "! cmp -s '$tmp/checker.png' '$tmp/opt.png'"
done
want='must be rgb888, rgb565 or pal8' expect_usage "a bad --texture-format" render "$tmp/globe.obj" \
    --texture checker --texture-format rgb999 -o "$tmp/x.png"
want='must be repeat or clamp' expect_usage "a bad --texture-wrap" render "$tmp/globe.obj" --texture checker \
    --texture-wrap mirror -o "$tmp/x.png"

# a material: Kd and map_Kd (the checker written as an image first)
"$SILK" render "$tmp/globe.obj" --size 64x64 --texture checker -o "$tmp/any.png" 2>/dev/null
{ echo "mtllib globe.mtl"; echo "usemtl painted"; cat "$tmp/globe.obj"; } >"$tmp/mat.obj"
printf 'newmtl other\nKd 0 0 1\nnewmtl painted\nKd 1 0.5 0.25\nNs 80\n' >"$tmp/globe.mtl"
run_silk render "$tmp/mat.obj" --size 64x48 -o "$tmp/kd.png"
check "a material renders, quietly" [ "$rc" -eq 0 ] && [ ! -s "$err" ]
check "Kd changes the colour" sh -c "! cmp -s '$tmp/untextured.png' '$tmp/kd.png'"
run_silk render "$tmp/mat.obj" --size 64x48 --color 30c060 --shininess 24 -o "$tmp/over.png"
"$SILK" render "$tmp/globe.obj" --size 64x48 --color 30c060 -o "$tmp/green.png" 2>/dev/null
check "--color and --shininess override the material" cmp -s "$tmp/green.png" "$tmp/over.png"
printf 'newmtl painted\nmap_Kd missing.png\n' >"$tmp/globe.mtl"
run_silk render "$tmp/mat.obj" --size 64x48 -o "$tmp/nomap.png"
check "a missing map_Kd: exit 0" [ "$rc" -eq 0 ]
check "a missing map_Kd: one warning line" sh -c "[ \$(wc -l <'$err') -eq 1 ] && grep -q '^silk: warning: .*missing.png' '$err'"
rm "$tmp/globe.mtl"
run_silk render "$tmp/mat.obj" --size 64x48 -o "$tmp/nomtl.png"
check "a missing .mtl: exit 0" [ "$rc" -eq 0 ]
check "a missing .mtl: one warning line" sh -c "[ \$(wc -l <'$err') -eq 1 ] && grep -q '^silk: warning: .*globe.mtl' '$err'"
check "a missing .mtl renders as without it" cmp -s "$tmp/untextured.png" "$tmp/nomtl.png"
run_silk render "$tmp/mat.obj" --size 64x48 --quiet -o "$tmp/quiet.png"
check "--quiet: no warning" [ ! -s "$err" ]
printf 'newmtl painted\nmap_Kd -s 1 1 1 tex.png\n' >"$tmp/globe.mtl"
cp "$tmp/any.png" "$tmp/tex.png"
run_silk render "$tmp/mat.obj" --size 64x48 -o "$tmp/map.png"
check "map_Kd (after options) is read" [ "$rc" -eq 0 ] && [ ! -s "$err" ]
check "map_Kd changes the picture" sh -c "! cmp -s '$tmp/untextured.png' '$tmp/map.png'"

# Files the model names that are not regular files, or too large, are not
# read (a device that never ends, a pipe without a writer, a sparse 2 GiB
# file): one warning each, at once, and the model renders without them.
# Each run gets 10 s and 200 MB of memory (not under the sanitizers, whose
# shadow memory needs more): reading /dev/zero to its cap, or waiting on the
# pipe, does not finish so.
named() {   # NAME MTLLIB [MTL TEXT]
    { echo "mtllib $2"; echo "usemtl painted"; cat "$tmp/globe.obj"; } >"$tmp/named.obj"
    [ -n "${3:-}" ] && printf "$3" >"$tmp/named.mtl"
    ([ -n "${SILK_SAN:-}" ] || ulimit -v 200000; timeout 10 "$SILK" render "$tmp/named.obj" --size 64x48 -o "$tmp/named.png") >"$out" 2>"$err"
    rc=$?
    check "$1: exit 0 at once (got $rc)" [ "$rc" -eq 0 ]
    check "$1: one warning line ($(head -c 200 "$err"))" \
        sh -c "[ \$(wc -l <'$err') -eq 1 ] && grep -qE '^silk: warning: .*$4' '$err'"
}
named "mtllib /dev/zero" /dev/zero "" "/dev/zero: not a regular file"
mkfifo "$tmp/fifo.mtl" 2>/dev/null && named "mtllib of a FIFO" fifo.mtl "" "fifo.mtl: not a regular file"
named "map_Kd /dev/zero" named.mtl 'newmtl painted\nmap_Kd /dev/zero\n' "/dev/zero: not a regular file"
truncate -s 2G "$tmp/big.png" 2>/dev/null &&
    named "map_Kd of 2 GiB" named.mtl 'newmtl painted\nmap_Kd big.png\n' "big.png: 2147483648 bytes, more than"
truncate -s 100M "$tmp/big.mtl" 2>/dev/null && named "an .mtl of 100 MiB" big.mtl "" "big.mtl: [0-9]+ bytes, more than"

# vertex colours: used without being asked
awk '/^v /{ print $0, 1, 0, 0; next } { print }' "$tmp/plain.obj" >"$tmp/red.obj"
"$SILK" render "$tmp/plain.obj" --size 64x48 -o "$tmp/plain.png" 2>/dev/null
run_silk render "$tmp/red.obj" --size 64x48 -o "$tmp/red.png"
check "vertex colours render" [ "$rc" -eq 0 ] && [ ! -s "$err" ]
check "vertex colours change the picture" sh -c "! cmp -s '$tmp/plain.png' '$tmp/red.png'"

# pack: the texels and the look go into the header
run_silk pack "$tmp/globe.obj" --texture checker:16 -o "$tmp/globe.h"
check "pack --texture" [ "$rc" -eq 0 ] && grep -q 'globe_texels\[' "$tmp/globe.h" && grep -q 'p->texture = &globe_texture;' "$tmp/globe.h"
check "pack reports the texture bytes" grep -q 'texture [0-9]' "$out"
run_silk pack "$tmp/globe.obj" --texture checker:16 --texture-format pal8 -o "$tmp/pal.h"
check "pack --texture-format pal8: the palette and the options" grep -q 'pal_palette\[256\]' "$tmp/pal.h" &&
    grep -q 'texture: `--texture checker:16 --texture-format pal8`' "$tmp/pal.h"
run_silk pack "$tmp/red.obj" -o "$tmp/red.h"
check "pack: vertex colours" grep -q 'm->color = (uint32_t \*)red_color;' "$tmp/red.h"
done_testing
