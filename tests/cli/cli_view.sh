#!/bin/sh
# cli_view.sh - `silk view`, the desktop viewer (docs/viewer.md).
#
# Without a window: --help lists the keys, bad usage is one error line,
# --benchmark prints its line, --events applies keys and saves screenshots.
#
# In a window: starts `silk view` on a generated torus under Xvfb and drives
# it for a few seconds with synthetic key and mouse events through the X
# server (xdotool: XTEST key presses, pointer drags, wheel clicks, a window
# resize), saving a screenshot (key s) after each step, and checks:
#   - the model is where it should be: in the first view (20 degrees above
#     the torus) the centre pixel is the far side of the tube and a corner is
#     background; after dragging the mouse 100 px down (40 degrees higher)
#     the centre is the hole;
#   - key 1 (flat) changed the silhouette against smooth mode, not the
#     framing; the wheel zoomed in (more object pixels); key w shows the
#     re-meshed triangles in red, key l the silhouette lines in blue, then
#     the lines alone; key h brings the status line (a dark band with text);
#     the screenshot after the resize has the new size; key q quits with
#     status 0.
# Without Xvfb, xdotool or an SDL2 build this part is skipped with a
# message, except in CI (CI set), where .ci/run installs them.
. "$(dirname "$0")/../shlib.sh"

"$SILK" gen torus -o "$tmp/torus.obj" >/dev/null || { fail "gen torus" "exit $?"; done_testing; exit 1; }
torus=$tmp/torus.obj

# ---- without a window -------------------------------------------------------------

run_silk view --help
check "view --help lists the keys" grep -q "1 2 3 4 .*flat, smooth, blend, pn" "$out"
expect_usage "view without a mesh" view
want='unknown option --bogus' expect_usage "view with an unknown option" view "$torus" --bogus
want='--mode must be' expect_usage "view with a bad mode" view "$torus" --mode nope --benchmark 1
want='at most one %d' expect_usage "view with a bad screenshot pattern" view "$torus" -o 'a%d%d.png' --benchmark 1
expect_input "view of a missing mesh" view "$tmp/missing.obj" --benchmark 1
want='unknown event' expect_usage "view with a bad event" view "$torus" --events "1 jump"

run_silk view "$torus" --benchmark 4 --size 64x48
check "view --benchmark prints its line" grep -qE \
    '^view-benchmark .* mode=smooth .*size=64x48 frames=4 render_ms=[0-9.]+ frame_ms=[0-9.]+ fps=[0-9.]+ tris_drawn=[0-9]+' "$out"

# ppm_pixel FILE X Y: "R G B" of one pixel of a P6 file.
ppm_pixel() {
    w=$(ppm_size "$1" | cut -dx -f1)
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -tu1 -j$((hdr + ($3 * w + $2) * 3)) -N3 "$1" | awk '{ print $1, $2, $3 }'
}
# ppm_count FILE AWK-CONDITION: pixels (r, g, b) for which it holds.
ppm_count() {
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -w3 -j"$hdr" "$1" | awk "{ r = \$1; g = \$2; b = \$3 } $2 { n++ } END { print n + 0 }"
}
# ppm_count_rows FILE Y0 Y1 AWK-CONDITION: the same within rows [Y0, Y1).
ppm_count_rows() {
    w=$(ppm_size "$1" | cut -dx -f1)
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -w3 -j$((hdr + $2 * w * 3)) -N$((($3 - $2) * w * 3)) "$1" |
        awk "{ r = \$1; g = \$2; b = \$3 } $4 { n++ } END { print n + 0 }"
}
# ppm_differ A B: pixels that differ between two P6 files of one size.
ppm_differ() {
    ha=$(head -n 3 "$1" | wc -c)
    hb=$(head -n 3 "$2" | wc -c)
    od -An -v -tu1 -w3 -j"$ha" "$1" >"$tmp/da"
    od -An -v -tu1 -w3 -j"$hb" "$2" >"$tmp/db"
    paste -d' ' "$tmp/da" "$tmp/db" | awk '$1 != $4 || $2 != $5 || $3 != $6 { n++ } END { print n + 0 }'
}
object='!(r == 255 && g == 255 && b == 255)'
red='r > 180 && g < 100 && b < 100'
blue='b > 200 && r < 80 && g < 140'

# No display: one line and exit 1 at once, never a wait for input that
# cannot come; --frames N ends after N frames with or without --spin (on
# SDL's invisible driver, asked for by name).  Each under a timeout.
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0   # SDL keeps some allocations until exit
export ASAN_OPTIONS
if "$SILK" view --help | grep -q 'not in this build'; then
    echo "skip: silk is built without SDL2, so view has no window to fail to open"
else
    nodisp() { timeout 2 env -u DISPLAY -u WAYLAND_DISPLAY "$@" >"$out" 2>"$err"; rc=$?; }
    nodisp -u SDL_VIDEODRIVER "$SILK" view "$torus"
    check "no display: exit 1 within 2 s (got $rc)" test "$rc" -eq 1
    want='no display' check "no display: one line saying so ($(head -c 200 "$err"))" one_error_line
    nodisp SDL_VIDEODRIVER=nowhere "$SILK" view "$torus"
    check "SDL_VIDEODRIVER=nowhere: exit 1 within 2 s (got $rc)" test "$rc" -eq 1
    want='cannot open a window' check "SDL_VIDEODRIVER=nowhere: one line ($(head -c 200 "$err"))" one_error_line
    want=
    for spin in "" --spin; do
        rm -f "$tmp"/frames-*.ppm
        timeout 20 env SDL_VIDEODRIVER=offscreen "$SILK" view "$torus" --size 80x60 --frames 3 $spin \
            -o "$tmp/frames-%d.ppm" >"$out" 2>"$err"
        rc=$?
        check "--frames 3 ${spin:-without --spin} ends with status 0 (got $rc: $(head -c 200 "$err"))" test "$rc" -eq 0
        check "--frames 3 ${spin:-without --spin} saves the last frame" test -s "$tmp/frames-1.ppm"
    done
fi
timeout 20 "$SILK" view "$torus" --fb-file "$tmp/fb.raw" --fb-geometry 80x60x16 --frames 3 >"$out" 2>"$err"
check "--fb-file --frames 3 ends after 3 frames (exit $?)" grep -q '^silk view: 3 frames of 80x60' "$out"

# --events: the same viewer, no window.
run_silk view "$torus" --size 160x120 --events "h shot:$tmp/e1.ppm 1 shot:$tmp/e2.ppm"
check "view --events saves screenshots" test -s "$tmp/e1.ppm" -a -s "$tmp/e2.ppm"
check "view --events reports each screenshot" test "$(grep -c '^silk view: saved ' "$out")" -eq 2
n=$(ppm_differ "$tmp/e1.ppm" "$tmp/e2.ppm")
check "view --events: flat differs from smooth ($n px)" test "$n" -gt 20

# The status line never covers the model: it is a band of rows under it,
# at most a third of the frame (one line at 160x120 and 64x48), and the rows
# above it hold exactly the frame the viewer draws at that height without it.
# band_rows FILE: the bottom rows that are mostly the band's dark grey.
band_rows() {
    bw=$(ppm_size "$1" | cut -dx -f1)
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -w3 -j"$hdr" "$1" | awk -v w="$bw" '
        { row = int((NR - 1) / w) } $1 == 32 && $2 == 32 && $3 == 32 { dark[row]++ }
        END { for (r = row; r >= 0 && dark[r] > w / 2; r--) n++; print n + 0 }'
}
# ppm_top FILE N: the pixels of the first N rows, one a line.
ppm_top() {
    tw=$(ppm_size "$1" | cut -dx -f1)
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -w3 -j"$hdr" "$1" | head -n $(($2 * tw))
}
for size in 160x120 64x48 640x480; do
    w=${size%x*}; h=${size#*x}
    "$SILK" view "$torus" --size $size --events "shot:$tmp/hud.ppm" >"$out" 2>"$err"
    band=$(band_rows "$tmp/hud.ppm")
    check "$size: the status band is under the model, one line, at most a third of the frame ($band rows)" \
        test "$band" -ge 9 -a "$band" -le 14 -a "$band" -le $((h / 3))
    "$SILK" view "$torus" --size $size --events "h size:${w}x$((h - band)) shot:$tmp/nohud.ppm" >"$out" 2>"$err"
    ppm_top "$tmp/hud.ppm" $((h - band)) >"$tmp/a"
    ppm_top "$tmp/nohud.ppm" $((h - band)) >"$tmp/b"
    check "$size: the model above the band is the whole frame at ${w}x$((h - band))" cmp -s "$tmp/a" "$tmp/b"
done

# ---- in a window ---------------------------------------------------------------------

missing=
command -v Xvfb >/dev/null 2>&1 || missing="Xvfb"
command -v xdotool >/dev/null 2>&1 || missing="$missing xdotool"
"$SILK" view --help | grep -q 'not in this build' && missing="$missing SDL2 (silk built without it)"
if [ -n "$missing" ]; then
    if [ -n "${CI:-}" ]; then
        fail "window test" "CI must have$missing (.ci/run installs xvfb, xdotool, libsdl2-dev)"
    else
        echo "skip: the window test needs$missing"
    fi
    done_testing
    exit
fi

xvfb_pid=
view_pid=
cleanup() {
    [ -n "$view_pid" ] && kill "$view_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT

# A display of our own: Xvfb picks a free number and writes it to fd 9.
Xvfb -displayfd 9 -screen 0 800x600x24 -nolisten tcp 9>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb_pid=$!
for i in $(seq 50); do [ -s "$tmp/display" ] && break; sleep 0.1; done
if [ ! -s "$tmp/display" ]; then
    fail "Xvfb starts" "$(head -c 300 "$tmp/xvfb.log")"
    done_testing
    exit 1
fi
DISPLAY=:$(cat "$tmp/display")
export DISPLAY

# X and SDL keep some allocations until exit; the sanitizer build would
# report them as leaks of silk.
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
export ASAN_OPTIONS

"$SILK" view "$torus" --size 320x240 -o "$tmp/shot-%d.ppm" >"$tmp/view.out" 2>"$tmp/view.err" &
view_pid=$!
wid=$(timeout 20 xdotool search --sync --name 'silk view' 2>/dev/null | head -n 1)
if [ -z "$wid" ]; then
    fail "the window opens" "$(head -c 300 "$tmp/view.err")"
    done_testing
    exit 1
fi
pass "the window opens"
xdotool windowfocus --sync "$wid"
sleep 0.3

# shot N: press s and wait for shot-N.ppm (written atomically).
shots=0
shot() {
    shots=$((shots + 1))
    xdotool key s
    for i in $(seq 100); do [ -e "$tmp/shot-$shots.ppm" ] && return 0; sleep 0.1; done
    fail "screenshot $shots" "not written: $(head -c 300 "$tmp/view.err")"
    return 1
}

xdotool key h; shot                                       # 1: smooth, no status line
xdotool key 1; shot                                       # 2: flat
# One step at a time with pauses: on a loaded machine (tests run two at a
# time) a press that arrives with the first move may not start the drag.
drag() {
    xdotool mousemove --window "$wid" --sync 160 100; sleep 0.2
    xdotool mousedown 1; sleep 0.2
    xdotool mousemove --window "$wid" --sync 160 200; sleep 0.2
    xdotool mouseup 1; sleep 0.2
}
drag; shot                                                # 3: dragged 100 px down
xdotool click --repeat 3 --delay 50 4; shot               # 4: three wheel notches in
xdotool key 2 w; shot                                     # 5: smooth, wireframe
xdotool key w l; shot                                     # 6: lines over the surface
xdotool key l; shot                                       # 7: lines alone
xdotool key l h; shot                                     # 8: status line
xdotool windowsize --sync "$wid" 400 300; sleep 0.5; shot # 9: resized
xdotool key q
for i in $(seq 50); do kill -0 "$view_pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$view_pid" 2>/dev/null; then
    fail "key q quits" "still running"
else
    wait "$view_pid"
    rc=$?
    check "key q quits with status 0 (got $rc; $(head -c 200 "$tmp/view.err"))" test "$rc" -eq 0
    view_pid=
fi
check "every screenshot is reported" test "$(grep -c '^silk view: saved ' "$tmp/view.out")" -eq 9
cat "$tmp/view.out"

s=$tmp/shot
[ -e "$s-9.ppm" ] || { done_testing; exit 1; }
check "screenshot 1 is 320x240" test "$(ppm_size "$s-1.ppm")" = 320x240
c=$(ppm_pixel "$s-1.ppm" 160 120)
check "first view: the centre is the torus ($c)" test "$c" != "255 255 255"
c=$(ppm_pixel "$s-1.ppm" 3 3)
check "first view: the corner is background ($c)" test "$c" = "255 255 255"
o1=$(ppm_count "$s-1.ppm" "$object")
o2=$(ppm_count "$s-2.ppm" "$object")
n=$(ppm_differ "$s-1.ppm" "$s-2.ppm")
check "key 1: flat differs from smooth ($n px)" test "$n" -gt 50
check "key 1: same framing ($o1 and $o2 object px)" awk -v a="$o1" -v b="$o2" 'BEGIN { exit !(a > 10000 && b > 0.9 * a && b < 1.1 * a) }'
c=$(ppm_pixel "$s-3.ppm" 160 120)
check "mouse drag: from 40 degrees higher the centre is the hole ($c)" test "$c" = "255 255 255"
o3=$(ppm_count "$s-3.ppm" "$object")
o4=$(ppm_count "$s-4.ppm" "$object")
check "wheel: zoomed in ($o3 -> $o4 object px)" awk -v a="$o3" -v b="$o4" 'BEGIN { exit !(b > 1.2 * a) }'
n=$(ppm_count "$s-5.ppm" "$red")
check "key w: re-meshed triangles in red ($n px)" test "$n" -gt 30
n=$(ppm_count "$s-6.ppm" "$red")
check "key w again: no red ($n px)" test "$n" -eq 0
n=$(ppm_count "$s-6.ppm" "$blue")
check "key l: silhouette lines in blue ($n px)" test "$n" -gt 200
o7=$(ppm_count "$s-7.ppm" "$object")
n=$(ppm_count "$s-7.ppm" "$blue")
check "key l again: the lines alone ($n blue of $o7 object px)" test "$n" -gt 200 -a "$o7" -lt $((n * 3 / 2))
# The status band: the bottom rows that are mostly its dark grey; the text
# is the light pixels in them.
band=$(od -An -v -tu1 -w3 -j$(( $(head -n 3 "$s-8.ppm" | wc -c) + 200 * 320 * 3 )) "$s-8.ppm" | awk '
    { row = int((NR - 1) / 320) } $1 == 32 && $2 == 32 && $3 == 32 { dark[row]++ }
    $1 > 200 && $2 > 200 && $3 > 200 { light[row]++ }
    END { for (r = 39; r >= 0 && dark[r] > 160; r--) { rows++; text += light[r] } print rows + 0, text + 0 }')
rows=${band% *}; light=${band#* }
check "key h: a status line ($rows dark rows with $light text px)" test "$rows" -ge 10 -a "$light" -gt 150
n=$(ppm_count_rows "$s-6.ppm" 230 240 'r == 32 && g == 32 && b == 32')
check "no status line before ($n dark px)" test "$n" -lt 100
check "resize: screenshot 9 is 400x300 ($(ppm_size "$s-9.ppm"))" test "$(ppm_size "$s-9.ppm")" = 400x300

done_testing
