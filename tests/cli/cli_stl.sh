#!/bin/sh
# cli_stl.sh - STL through the `silk` command: a generated sphere and torus
# written as ascii STL (the OBJ's numbers copied) and as binary STL (whose
# header starts with "solid", as many exporters write it) by
# tests/stl_from_obj.awk load to the same mesh as the OBJ (vertices welded,
# closed) and render byte-identical to it.  Binary STL holds binary32
# floats, not the OBJ's 9 digits: a coordinate whose float lies on the
# other side of a Q16.16 rounding midpoint moves by 2^-16, so where that
# happens (the torus) the outline must still be the OBJ's, pixel for
# pixel.  A truncated binary STL and a file of another format get one
# clear line.
. "$(dirname "$0")/../shlib.sh"

for shape in sphere torus; do
    obj=$tmp/$shape.obj
    "$SILK" gen $shape -o "$obj" || { fail "gen $shape" "exit $?"; continue; }
    awk -v fmt=ascii -f "$here/stl_from_obj.awk" "$obj" >"$tmp/$shape-ascii.stl"
    printf "$(awk -v fmt=binary -f "$here/stl_from_obj.awk" "$obj")" >"$tmp/$shape-binary.stl"
    nf=$(grep -c '^f ' "$obj")
    check "$shape: binary STL has 84 + 50 n bytes" test "$(wc -c <"$tmp/$shape-binary.stl")" -eq $((84 + 50 * nf))
    check "$shape: binary STL header starts with solid" test "$(head -c 5 "$tmp/$shape-binary.stl")" = solid

    run_silk info "$obj"
    cp "$out" "$tmp/info-obj"
    for enc in ascii binary; do
        run_silk info "$tmp/$shape-$enc.stl"
        check "$shape, $enc STL: info exits 0" test "$rc" -eq 0
        for key in vertices triangles edges "boundary edges" "non-manifold edges" "feature edges"; do
            check "$shape, $enc STL: $key as the OBJ" \
                test "$(info_value "$out" "$key")" = "$(info_value "$tmp/info-obj" "$key")"
        done
    done
    # the outlines as drawn (--aa off): an anti-aliased outline's faintest
    # pixels follow positions finer than a binary STL's floats hold
    for mode in smooth flat; do
        run_silk render "$obj" --mode $mode --size 240x180 --aa off -o "$tmp/obj-$mode.png"
        check "$shape, $mode: OBJ renders" test "$rc" -eq 0
        for enc in ascii binary; do
            run_silk render "$tmp/$shape-$enc.stl" --mode $mode --size 240x180 --aa off -o "$tmp/$enc-$mode.png"
            check "$shape, $mode: $enc STL renders, stderr empty" test "$rc" -eq 0 -a ! -s "$err"
            if [ "$shape-$enc" = torus-binary ]; then
                run_silk diff "$tmp/obj-$mode.png" "$tmp/$enc-$mode.png"
                check "$shape, $mode: $enc STL has the OBJ's outline" grep -q " differing=0 " "$out"
            else
                check "$shape, $mode: $enc STL byte-identical to the OBJ" \
                    cmp -s "$tmp/obj-$mode.png" "$tmp/$enc-$mode.png"
            fi
        done
    done
done

head -c 1000 "$tmp/sphere-binary.stl" >"$tmp/cut.stl"
want='cut.stl: binary STL is truncated: the header declares 200 triangles \(10084 bytes\), the file has 1000 bytes'
expect_input "truncated binary STL" render "$tmp/cut.stl" -o "$tmp/cut.png"
check "no image from a truncated STL" test ! -e "$tmp/cut.png"
printf '{ "asset": { "version": "2.0" } }\n' >"$tmp/model.gltf"
want='model.gltf: glTF is not supported: convert it to OBJ, PLY or STL'
expect_input "glTF named" info "$tmp/model.gltf"
done_testing
