#!/bin/sh
# cli_progress.sh - long work shows one updating progress line on stderr
# when it is a terminal (simplify, bench, render --turntable, loading a large
# file), nothing when stderr is a file or a pipe, and nothing with --quiet.
# (`make bench` runs `silk bench`, so it shows the same line.)
# The terminal is a pseudo-terminal from script(1); without it only the
# quiet half is checked.
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
# over 4 MiB: loading it shows a line
"$SILK" gen sphere --segments 240 --bands 240 -o "$tmp/big.obj"

# ---- not a terminal: stderr stays empty ----------------------------------------------------
quiet_run() {
    name=$1; shift
    "$SILK" "$@" >/dev/null 2>"$err"
    if [ ! -s "$err" ]; then pass "$name: nothing on a non-terminal stderr"
    else fail "$name: nothing on a non-terminal stderr" "$(head -c 200 "$err")"; fi
}
quiet_run simplify simplify "$tmp/big.obj" "$tmp/s.obj" --triangles 2000
quiet_run bench bench "$sphere" --views 2 --reps 1 --size 64x48 --modes flat
quiet_run "bench --visibility-pass" bench --visibility-pass "$sphere" --batches 1
quiet_run turntable render "$sphere" --turntable 4 -o "$tmp/t_%d.png" --size 64x48
quiet_run "loading a large file" info "$tmp/big.obj"

# ---- a terminal ---------------------------------------------------------------------------------
if ! script -qec true /dev/null >/dev/null 2>&1; then
    echo "script(1) cannot make a terminal here: skipping the terminal half"
    done_testing
    exit $?
fi
# tty NAME WANT ARGS...: the transcript of silk ARGS on a terminal shows WANT
tty() {
    name=$1; want=$2; shift 2
    script -qec "\"$SILK\" $*" /dev/null >"$tmp/tty" 2>&1 </dev/null
    if grep -q "$want" "$tmp/tty" && grep -q "$(printf '\r')silk: " "$tmp/tty"; then pass "$name: progress on a terminal"
    else fail "$name: progress on a terminal" "$(od -c "$tmp/tty" | head -n 5)"; fi
}
tty simplify 'simplify *[0-9]*%' simplify "$tmp/big.obj" "$tmp/s.obj" --triangles 2000
tty bench 'bench sphere *[0-9]*%' bench "$sphere" --views 4 --reps 1 --size 64x48 --modes flat
tty "bench --visibility-pass" 'bench --visibility-pass .*sphere.obj *[0-9]*%' bench --visibility-pass "$sphere" --batches 1
tty turntable 'render *[0-9]*%' render "$sphere" --turntable 4 -o "$tmp/t_%d.png" --size 64x48
tty "loading a large file" 'loading .*big.obj' info "$tmp/big.obj"
script -qec "\"$SILK\" simplify \"$tmp/big.obj\" \"$tmp/s.obj\" --triangles 2000 --quiet" /dev/null >"$tmp/tty" 2>&1 </dev/null
check "simplify --quiet: no progress on a terminal" test "$(grep -c '%' "$tmp/tty")" -eq 0
script -qec "\"$SILK\" info \"$tmp/big.obj\" --quiet" /dev/null >"$tmp/tty" 2>&1 </dev/null
check "info --quiet: no loading line on a terminal" test "$(grep -c 'silk: loading' "$tmp/tty")" -eq 0

done_testing
