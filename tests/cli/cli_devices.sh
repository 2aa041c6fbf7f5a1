#!/bin/sh
# cli_devices.sh - the small-device commands end to end, on the host:
#   silk pack   the header compiles (also with 16-bit indices, and refuses
#               8-bit ones), and the firmware's scene (platform/mps2/fw_main.c)
#               compiled for the host with it renders exactly what
#               `silk render` does, for every packed view, flat and smooth;
#   silk view   into file-backed framebuffers of 16 and 32 bits per pixel
#               the pixels of `silk render` (siltex mode too); runs until
#               SIGINT; bad options.
. "$(dirname "$0")/../shlib.sh"

meshes=${SILK_MESHES:-../shared/meshes}
mesh=$meshes/bunny-500.obj
ntris=500
if [ ! -e "$mesh" ]; then
    echo "note: $mesh is missing; the generated torus stands in for it"
    mesh=$tmp/torus.obj
    ntris=576
    "$SILK" gen torus -o "$mesh" >/dev/null
fi
CC=${CC:-cc}
# The library under test may be built with sanitizers; the scene must link it.
SANFLAGS=
[ -n "${SILK_SAN:-}" ] && SANFLAGS="-fsanitize=address,undefined"

# ---- pack --------------------------------------------------------------------

hdr=$tmp/fwmodel.h
run_silk pack "$mesh" -o "$hdr" --name fwmodel --size 160x120 --format rgb565 --views 3
ok=0; [ "$rc" -eq 0 ] && [ ! -s "$err" ] && [ "$(wc -l <"$out")" -eq 1 ] && ok=1
check "pack: exit 0, one summary line" [ "$ok" -eq 1 ]
check "pack: summary names the model data" grep -q "model data (bytes): compact model [0-9]*, [0-9.]* a triangle" "$out"
# The same model's bytes alone: what `silk render` draws the device's frames from.
"$SILK" pack "$mesh" -o "$tmp/fwmodel.slkc" >/dev/null
check "pack: three cameras recorded" [ "$(grep -c 'camera [0-9]*: --eye ' "$hdr")" -eq 3 ]

# What a first program does with the header alone: the mesh, checked once
# (silk_mesh_validate, which the header's includes declare), and a camera.
printf '#include "fwmodel.h"\nint main(void) { silk_mesh m; silk_error e; fwmodel_mesh(&m);\n'\
'    return silk_mesh_validate(&m, "fwmodel", &e) != SILK_OK || fwmodel_camera(2) == 0; }\n' >"$tmp/use.c"
check "pack: the header compiles warning-free" \
    "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -Iinclude -I"$tmp" -c "$tmp/use.c" -o "$tmp/use.o"
check "pack: ... and with a board's options" \
    "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror "-DSILK_CONFIG_FILE=\"$PWD/boards/microbit/config.h\"" \
    -Iinclude -I"$tmp" -c "$tmp/use.c" -o "$tmp/use16.o"
# An Arduino sketch includes it from C++ (gnu++11, its warnings on).
check "pack: ... and from C++" "${CXX:-c++}" -std=gnu++11 -Wall -Wextra -Werror -Iinclude -I"$tmp" -x c++ \
    -c "$tmp/use.c" -o "$tmp/usexx.o"

# The firmware's scene on the host, with the packed model.
if "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 $SANFLAGS -Iinclude -Iplatform/mps2 -I"$tmp" \
    -DFW_ARENA_BYTES=4194304 -DFW_REPORT_BUDGET -o "$tmp/fw-host" platform/mps2/fw_main.c platform/mps2/fw_io_host.c \
    "$build/libsilk.a" 2>"$tmp/cc.err"; then
    pass "pack: the firmware scene builds for the host"
    "$tmp/fw-host" "$tmp/fw" >"$tmp/fw.report" 2>&1
    check "pack: the scene runs" grep -q '^fw result=ok' "$tmp/fw.report"
    n=0
    grep -o 'camera [0-9]*: --eye [^ ]*' "$hdr" >"$tmp/eyes"
    while read -r _ k _ eye; do
        k=${k%:}
        for mode in flat smooth; do
            "$SILK" render "$tmp/fwmodel.slkc" --size 160x120 --format rgb565 --eye "$eye" --mode "$mode" -o "$tmp/ref.ppm"
            if cmp -s "$tmp/ref.ppm" "$tmp/fw-c$k-$mode.ppm"; then n=$((n + 1)); else
                fail "pack: camera $k $mode equals silk render" "$(cmp "$tmp/ref.ppm" "$tmp/fw-c$k-$mode.ppm" 2>&1)"
            fi
        done
    done <"$tmp/eyes"
    check "pack: 6 frames equal silk render byte for byte ($n)" [ "$n" -eq 6 ]
else
    fail "pack: the firmware scene builds for the host" "$(head -c 300 "$tmp/cc.err")"
fi

# The same scene with an arena that holds the band buffers (160 x 8 x 6
# bytes) and a flat frame but not a smooth frame's plan: every smooth frame
# falls back to flat, and the scene says so instead of "ok", with the count
# and a non-zero exit status.
if "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 $SANFLAGS -Iinclude -Iplatform/mps2 -I"$tmp" \
    -DFW_ARENA_BYTES=10752 -DFW_REPORT_BUDGET -o "$tmp/fw-small" platform/mps2/fw_main.c platform/mps2/fw_io_host.c \
    "$build/libsilk.a" 2>"$tmp/cc.err"; then
    "$tmp/fw-small" >"$tmp/small.report" 2>&1
    status=$?
    check "pack: a scene whose smooth frames fall back says so (exit $status)" \
        grep -qx 'fw result=fell_back frames=6 fell_back=3 smooth_fell_back=3' "$tmp/small.report"
    check "pack: ... and exits 2" [ "$status" -eq 2 ]
    check "pack: ... its frame lines say which" [ "$(grep -c '^fw frame=.* mode=smooth .*fell_back=1 ' "$tmp/small.report")" -eq 3 ]
else
    fail "pack: the firmware scene builds for the host with a small arena" "$(head -c 300 "$tmp/cc.err")"
fi

# Usage and input errors: one line, the right status, no header left behind.
echo stale >"$tmp/stale.h"
expect_usage "pack: no output" pack "$mesh"
want='--eye or --views' expect_usage "pack: --eye with --views" pack "$mesh" -o "$tmp/stale.h" --eye 0,0,3 --views 2
check "pack: a failed run keeps an earlier header" test "$(cat "$tmp/stale.h")" = stale
want='C identifier' expect_usage "pack: bad --name" pack "$mesh" -o "$tmp/x.h" --name 9lives
want='--views' expect_usage "pack: --views 0" pack "$mesh" -o "$tmp/x.h" --views 0
expect_input "pack: missing mesh" pack "$tmp/none.obj" -o "$tmp/x.h"
check "pack: no header after failures" [ ! -e "$tmp/x.h" ]

# ---- view --------------------------------------------------------------------

# PPM pixels (after the header) as one "r g b" line per pixel.
ppm_pixels() {
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -j"$hdr" "$1" | awk '{ for (i = 1; i <= NF; i++) { c[k++ % 3] = $i; if (k % 3 == 0) print c[0], c[1], c[2] } }'
}
# Framebuffer pixels as "r g b" lines: 32 bits B,G,R,X; 16 bits RGB565 widened
# by bit replication, as silk's image writers widen.
fb_pixels() {
    od -An -v -tu1 "$1" | awk -v bpp="$2" '
        { for (i = 1; i <= NF; i++) b[n++] = $i }
        END {
            if (bpp == 32) for (i = 0; i < n; i += 4) print b[i + 2], b[i + 1], b[i]
            else for (i = 0; i < n; i += 2) {
                v = b[i] + 256 * b[i + 1]; r = int(v / 2048); g = int(v / 32) % 64; bl = v % 32
                print r * 8 + int(r / 4), g * 4 + int(g / 16), bl * 8 + int(bl / 4)
            }
        }'
}

eye=1.25,0.75,2.5
for bpp in 16 32; do
    fmt=rgb888; [ "$bpp" = 16 ] && fmt=rgb565
    run_silk view "$mesh" --fb-file "$tmp/fb$bpp.raw" --fb-geometry 160x120x$bpp --frames 1 --eye "$eye"
    ok=0; [ "$rc" -eq 0 ] && grep -q '^silk view: 1 frames of 160x120' "$out" && ok=1
    check "view: $bpp bpp file: exit 0, a summary line" [ "$ok" -eq 1 ]
    check "view: $bpp bpp file has the screen's size" [ "$(wc -c <"$tmp/fb$bpp.raw")" -eq $((160 * 120 * bpp / 8)) ]
    "$SILK" render "$mesh" --size 160x120 --format $fmt --eye "$eye" -o "$tmp/view-ref.ppm"
    ppm_pixels "$tmp/view-ref.ppm" >"$tmp/ref.txt"
    fb_pixels "$tmp/fb$bpp.raw" $bpp >"$tmp/fb.txt"
    check "view: $bpp bpp pixels equal silk render --format $fmt" cmp -s "$tmp/ref.txt" "$tmp/fb.txt"
done

# Siltex mode on the framebuffer (the linux-fb board draws in bands of its
# own): the analytic spheres' model of tests/core/test_siltex.c, byte for byte
# what silk render draws.
if [ -x "$build/tests/test_siltex" ] && "$build/tests/test_siltex" --write "$tmp/spheres.silk" two; then
    for bpp in 16 32; do
        fmt=rgb888; [ "$bpp" = 16 ] && fmt=rgb565
        run_silk view "$tmp/spheres.silk" --mode siltex --fb-file "$tmp/st$bpp.raw" --fb-geometry 160x120x$bpp \
            --frames 1 --eye 0.8,0.4,5
        check "view: siltex into $bpp bpp file, exit 0" [ "$rc" -eq 0 ]
        "$SILK" render "$tmp/spheres.silk" --mode siltex --size 160x120 --format $fmt --eye 0.8,0.4,5 \
            -o "$tmp/st-ref.ppm"
        ppm_pixels "$tmp/st-ref.ppm" >"$tmp/ref.txt"
        fb_pixels "$tmp/st$bpp.raw" $bpp >"$tmp/fb.txt"
        check "view: siltex $bpp bpp pixels equal silk render --mode siltex --format $fmt" cmp -s "$tmp/ref.txt" "$tmp/fb.txt"
    done
else
    fail "view: siltex" "$build/tests/test_siltex cannot write the model (make $build/tests/test_siltex)"
fi

# A smaller frame is centred; the rest of the screen is the background.
run_silk view "$mesh" --fb-file "$tmp/fbc.raw" --fb-geometry 40x30x32 --size 20x10 --frames 2 --bg 102030
# corners of the screen (pixels 1 and 1200) are outside the 20x10 frame
ok=0; [ "$rc" -eq 0 ] && [ "$(fb_pixels "$tmp/fbc.raw" 32 | sed -n '1p;1200p' | sort -u)" = "16 32 48" ] && ok=1
check "view: centred frame, background elsewhere" [ "$ok" -eq 1 ]

# Until SIGINT: it stops cleanly and reports the frames it drew.
"$SILK" view "$mesh" --fb-file "$tmp/fbi.raw" --fb-geometry 64x48x16 >"$tmp/int.out" 2>&1 &
pid=$!
sleep 1
kill -INT "$pid"
wait "$pid"
status=$?
check "view: SIGINT ends it with status 0 ($status)" [ "$status" -eq 0 ]
check "view: ... after some frames" grep -qE '^silk view: [1-9][0-9]* frames' "$tmp/int.out"

want='fb-geometry' expect_usage "view: --fb-file without geometry" view "$mesh" --fb-file "$tmp/g.raw"
want='16, 24 or 32' expect_usage "view: 8 bpp" view "$mesh" --fb-file "$tmp/g.raw" --fb-geometry 10x10x8
want='WIDTHxHEIGHTxBPP' expect_usage "view: bad geometry" view "$mesh" --fb-file "$tmp/g.raw" --fb-geometry 10x10
want='not both' expect_usage "view: --fb and --fb-file" view "$mesh" --fb /dev/null --fb-file "$tmp/g.raw" \
    --fb-geometry 10x10x16
want='/nonexistent/fb0' expect_input "view: missing device" view "$mesh" --fb /nonexistent/fb0
want='not a framebuffer' expect_input "view: not a framebuffer" view "$mesh" --fb "$mesh"

done_testing
