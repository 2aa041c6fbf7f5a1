#!/bin/sh
# cli_exhaustion.sh BUILD - the command with a fixed --arena that is too
# small: for loading, one error line naming the bytes the model needs
# (and that many bytes are then enough); for the frame's silhouette work,
# the image is still written, unsmoothed where memory ran out, with one
# warning line; for even the unsmoothed frame, one error line naming its
# bytes.  `silk info` says "fell back: yes" in the same case.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen sphere -o "$tmp/sphere.obj" >/dev/null
o=$tmp/out.png

# loading: the exact need is named, and it is enough
want='^silk: .*sphere\.obj: arena too small: loading needs [0-9]+ bytes, --arena gives 4096$' \
    expect_input "load: needs named" render "$tmp/sphere.obj" --arena 4K --size 32x32 -o "$o"
need=$(sed -nE 's/.*loading needs ([0-9]+) bytes.*/\1/p' "$err")
check "load: no image left" test ! -e "$o"
# (a streamed flat frame needs only a few hundred bytes, which loading's
# released temporaries leave)
run_silk info "$tmp/sphere.obj" --arena "$need" --size 1x1 --mode flat
check "load: $need bytes load it" test "$rc" -eq 0 -a ! -s "$err"
run_silk info "$tmp/sphere.obj" --arena $((need - 8)) --size 1x1 --mode flat
check "load: 8 bytes fewer do not" grep -q "loading needs $need bytes" "$err"

# the frame's silhouette work does not fit: drawn, unsmoothed, one warning
# (the arena: the mesh, the 32x32 frame buffer and half the smooth frame's scratch)
run_silk info "$tmp/sphere.obj" --size 32x32
loaded=$(info_value "$out" "  after loading")
scratch=$(info_value "$out" "  frame bytes")
half=$((loaded + 32 * 32 * 7 + scratch / 2))
[ "$half" -ge "$need" ] || half=$need
run_silk render "$tmp/sphere.obj" --arena "$half" --size 32x32 -o "$o"
check "frame: exit 0 when falling back" test "$rc" -eq 0
check "frame: the image is written" is_png "$o"
check "frame: one warning line" test "$(cat "$err")" = \
    "silk: warning: the arena ran out during the frame; part of it is not smoothed"
run_silk info "$tmp/sphere.obj" --arena "$half" --size 32x32
check "info: fell back: yes" grep -qE '^  fell back: +yes' "$out"
run_silk info "$tmp/sphere.obj" --size 32x32
check "info: fell back: no with room" grep -qE '^  fell back: +no' "$out"

# not even the unsmoothed frame fits: one error line with its bytes (the
# arena: the mesh, the 64x64 frame buffer and 64 bytes)
rm -f "$o"
want='^silk: .*sphere\.obj: frame: arena too small for the frame: even the unsmoothed frame needs [0-9]+ bytes, [0-9]+ are free$' \
    expect_input "frame: unsmoothed need named" render "$tmp/sphere.obj" --arena $((loaded + 64 * 64 * 7 + 64)) \
    --size 64x64 -o "$o"
check "frame: no image left" test ! -e "$o"

done_testing
