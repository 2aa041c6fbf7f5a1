#!/bin/sh
# cli_soak.sh - the soak run (platform/mps2/fw_soak.c): the Cortex-M3
# board's scene (mps2-an385, bunny-500 packed into flash) along a random
# camera path, flat and smooth, SILK_SOAK_FRAMES frames (default 1000) on
# the host build of the firmware and SILK_SOAK_QEMU_FRAMES (default 100)
# under QEMU.  Checks: both end "fw result=ok"; no frame fell back; the
# arena holds the same bytes after every frame (the band buffers: nothing
# kept or leaked) and its high-water mark stays within the arena; and every
# frame the board drew equals the host build's, checksum, high-water mark and
# all.  `make soak` runs it alone, with longer runs through the variables.
. "$(dirname "$0")/../shlib.sh"

firmware_tests
dir=${SILK_FW_DIR:-build-mps2-an385/fw}/soak
if [ ! -x "$dir/soak-host" ] || [ ! -s "$dir/soak.elf" ]; then
    meshes=${SILK_MESHES:-../shared/meshes}
    if [ ! -d "$meshes" ]; then
        echo "skip: $meshes is missing, and the soak's model is a shared mesh"
        done_testing
        exit 0
    fi
    fail "the soak firmware is built" "no $dir/soak.elf (make BOARD=mps2-an385 soak-firmware)"
    done_testing
    exit 1
fi
frames=${SILK_SOAK_FRAMES:-1000}
qframes=${SILK_SOAK_QEMU_FRAMES:-100}
# the sizes the firmware was built with: flash, RAM, stack, arena, ...
arena=$(awk '{ print $4 }' "$dir/../defs.args")

# soak_ok NAME REPORT N: the run's own verdict, and what every frame says
soak_ok() {
    check "$1: $3 frames, fw result=ok" grep -qx 'fw result=ok' "$2"
    check "$1: $((2 * $3)) frames reported" test "$(grep -c '^fw soak frame=' "$2")" -eq $((2 * $3))
    check "$1: no frame fell back" test -z "$(grep '^fw soak frame=.* fell_back=1' "$2" | head -n 1)"
    kept=$(sed -n 's/^fw soak frame=.* kept=\([0-9]*\)$/\1/p' "$2" | sort -u | tr '\n' ' ')
    check "$1: the arena holds the same after every frame (${kept% } bytes)" test "$(echo $kept | wc -w)" -eq 1
    peak=$(sed -n 's/^fw soak frame=.* peak=\([0-9]*\) .*/\1/p' "$2" | sort -n | tail -n 1)
    check "$1: the high-water mark within the arena ($peak of $arena bytes)" test -n "$peak" -a "$peak" -le "$arena"
    sed -n 's/^fw soak frames=.*/&/p' "$2"
}

"$dir/soak-host" "$frames" >"$tmp/host.txt" 2>&1
soak_ok "host build" "$tmp/host.txt" "$frames"
timeout 600 qemu-system-arm -M "$(cat "$dir/../machine" 2>/dev/null || echo mps2-an385)" -nographic -monitor none \
    -serial none -semihosting-config enable=on,target=native -kernel "$dir/soak.elf" -append "$qframes" \
    >"$tmp/qemu.txt" 2>&1
soak_ok "mps2-an385 under QEMU" "$tmp/qemu.txt" "$qframes"
grep '^fw soak frame=' "$tmp/qemu.txt" >"$tmp/q"
grep '^fw soak frame=' "$tmp/host.txt" | head -n $((2 * qframes)) >"$tmp/h"
check "every frame under QEMU equals the host build's ($(diff "$tmp/h" "$tmp/q" | head -n 2 | tr '\n' ' '))" \
    cmp -s "$tmp/h" "$tmp/q"

done_testing
