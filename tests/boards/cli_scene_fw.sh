#!/bin/sh
# cli_scene_fw.sh - several objects in one frame on the Cortex-M3 board
# with 64 KiB of RAM (boards/mps2-an385-full): the firmware built with
# -DFW_SCENE (make BOARD=mps2-an385-full scene-firmware) draws, after its
# model's usual frames, one scene of the model and a turned, shrunk copy
# pushed into it (their depths interleave), smooth and anti-aliased, over
# a background its under callback paints, in bands of 8 rows.  Checks: the
# host build and QEMU both end "fw result=ok" with no frame fallen back;
# every frame, the scene's too, is the same bytes on both; the scene's
# report (triangles, checksum) is the same.  It also says what the scene
# costs in code over the board's own firmware (the core's budget does not
# hold it: docs/small-devices.md).
. "$(dirname "$0")/../shlib.sh"

firmware_tests
fw=${SILK_FW_DIR:-build-mps2-an385-full/fw}
dir=$fw/scene
if [ ! -x "$dir/fw-host" ] || [ ! -s "$dir/fw.elf" ]; then
    meshes=${SILK_MESHES:-../shared/meshes}
    if [ ! -d "$meshes" ]; then
        echo "skip: $meshes is missing, and the scene's model is a shared mesh"
        done_testing
        exit 0
    fi
    fail "the scene firmware is built" "no $dir/fw.elf (make BOARD=mps2-an385-full scene-firmware)"
    done_testing
    exit 1
fi
mkdir -p "$tmp/h" "$tmp/q"
"$dir/fw-host" "$tmp/h/f" >"$tmp/host.txt" 2>&1
timeout 300 qemu-system-arm -M "$(cat "$fw/machine" 2>/dev/null || echo mps2-an385)" -icount shift=0 -nographic \
    -monitor none -serial none -semihosting-config enable=on,target=native -kernel "$dir/fw.elf" \
    -append "$tmp/q/f" >"$tmp/qemu.txt" 2>&1
for run in host qemu; do
    check "$run: fw result=ok" grep -qx 'fw result=ok' "$tmp/$run.txt"
    check "$run: the scene frame drawn, nothing fallen back" grep -q '^fw scene objects=2 .* fell_back=0 ' "$tmp/$run.txt"
done
check "the scene frame written" test -s "$tmp/h/f-c0-scene.ppm"
n=0
for f in "$tmp"/h/*.ppm; do
    n=$((n + 1))
    check "$(basename "$f") is the host's bytes under QEMU" cmp -s "$f" "$tmp/q/$(basename "$f")"
done
check "7 frames compared ($n)" test "$n" -eq 7
# the report's triangles and checksum (frame_bytes differs: the host's pointers are 8 bytes)
scene_of() { sed -n 's/^fw scene objects=2 tris=\([0-9]*\) silhouette_tris=\([0-9]*\) .* crc=\([0-9a-f]*\) .*/\1 \2 \3/p' "$1"; }
check "the scene's report is the host's ($(scene_of "$tmp/qemu.txt"))" test "$(scene_of "$tmp/host.txt")" = "$(scene_of "$tmp/qemu.txt")"
grep '^fw scene ' "$tmp/qemu.txt"
grep '^fw ram ' "$tmp/qemu.txt"
# what the scene adds to the firmware's code (the board's own firmware: its first model's)
text() { arm-none-eabi-size -A "$1" 2>/dev/null | awk '$1 == ".text" { print $2 }'; }
first=$(ls -d "$fw"/*/fw.elf | grep -v '/scene/' | head -n 1)
if [ -n "$first" ]; then echo "scene code: .text $(text "$dir/fw.elf") bytes, $(( $(text "$dir/fw.elf") - $(text "$first") )) more than $first"; fi

done_testing
