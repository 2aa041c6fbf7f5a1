# shlib.sh - helpers for the shell tests of the silk command (tests/*/cli_*.sh),
# sourced, not run.  Each test script gets the build directory as $1 and
# ends with done_testing, which prints "N passed, N failed" like check.h.
#
#   check NAME COMMAND...            passes when COMMAND succeeds
#   run_silk ARGS...                 runs $SILK; sets $rc, $out, $err (files)
#   expect_usage NAME ARGS...        exit 2, one "silk: " line on stderr
#   expect_input NAME ARGS...        exit 1, one "silk: " line on stderr

build=${1:-build}
SILK=$build/silk
# the tests folder (every script sits in a group folder below it)
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/silk-cli.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
out=$tmp/stdout
err=$tmp/stderr

pass() { passed=$((passed + 1)); echo "ok $1"; }
# run.sh shows lines starting with FAIL
fail() { failed=$((failed + 1)); echo "FAIL $1: $2"; }

check() {
    name=$1; shift
    if "$@"; then pass "$name"; else fail "$name" "$*"; fi
}

run_silk() {
    "$SILK" "$@" >"$out" 2>"$err"
    rc=$?
}

# One line on stderr, "silk: ..." (and a message matching $want if set).
one_error_line() {
    [ "$(wc -l <"$err")" -eq 1 ] && head -n 1 "$err" | grep -q '^silk: ' &&
        { [ -z "${want:-}" ] || grep -qE -- "$want" "$err"; }
}

expect_status() {
    code=$1; name=$2; shift 2
    run_silk "$@"
    if [ "$rc" -eq "$code" ] && one_error_line; then
        pass "$name"
    else
        fail "$name" "silk $* -> exit $rc, stderr: $(head -c 300 "$err")"
    fi
    want=
}
expect_usage() { expect_status 2 "$@"; }
expect_input() { expect_status 1 "$@"; }

# Files in a directory whose names contain ".tmp" (uncommitted outputs).
no_tmp_files() {
    [ -z "$(find "$1" -name '*.tmp*' 2>/dev/null)" ]
}

# The first bytes of a file as hex pairs separated by spaces.
hex_head() {
    od -An -tx1 -N"$2" "$1" | tr -s ' \n' '  ' | sed 's/^ //; s/ $//'
}

# Width and height from a PNG's IHDR chunk (big-endian at byte 16).
png_size() {
    od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%dx%d\n", (($1*256+$2)*256+$3)*256+$4, (($5*256+$6)*256+$7)*256+$8 }'
}

is_png() {
    [ "$(hex_head "$1" 8)" = "89 50 4e 47 0d 0a 1a 0a" ]
}

# "WxH" from a P6 header (the sink writes "P6\nW H\n255\n").
ppm_size() {
    head -c 20 "$1" | awk 'NR == 1 && $0 != "P6" { exit 1 } NR == 2 { print $1 "x" $2; exit }'
}

# Pixels of a PPM that differ from the colour RRGGBB (hex).
ppm_count_not() {
    bg=$2
    r=$(printf '%d' "0x$(echo "$bg" | cut -c1-2)")
    g=$(printf '%d' "0x$(echo "$bg" | cut -c3-4)")
    b=$(printf '%d' "0x$(echo "$bg" | cut -c5-6)")
    hdr=$(head -n 3 "$1" | wc -c)
    od -An -v -tu1 -j"$hdr" "$1" | awk -v r="$r" -v g="$g" -v b="$b" '
        { for (i = 1; i <= NF; i++) { c[k++ % 3] = $i; if (k % 3 == 0 && (c[0] != r || c[1] != g || c[2] != b)) n++ } }
        END { print n + 0 }'
}

# The pixels of columns [X0, X0 + W) of a PPM, one pixel a line ("r g b").
ppm_columns() {
    hdr=$(head -n 3 "$1" | wc -c)
    iw=$(ppm_size "$1" | cut -dx -f1)
    od -An -v -tu1 -w3 -j"$hdr" "$1" | awk -v x0="$2" -v w="$3" -v iw="$iw" '{ x = (NR - 1) % iw } x >= x0 && x < x0 + w'
}

# The value of a "name: value" line of `silk info`; name includes the
# line's indentation ("  samples" in the frame section).
# header_model HEADER OUT: the bytes of a `silk pack` header's compact model
# (its NAME_model array) into OUT, for `silk render OUT`; 1 when the header
# holds the full form instead.
header_model() {
    python3 - "$1" "$2" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"static const uint8_t \w+_model\[\d+\] = \{([^}]*)\}", text)
if not m:
    sys.exit(1)
open(sys.argv[2], "wb").write(bytes(int(v) for v in m.group(1).replace(",", " ").split()))
PY
}

info_value() {
    grep -E "^$2: " "$1" | head -n 1 | sed -E "s/^$2: +//"
}

done_testing() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

# mesh_made NAME PATTERN FILE TARGET: the command run_silk just ran exited 0
# with nothing on stderr and a line matching PATTERN on stdout, and silk
# info reads FILE as closed and manifold with TARGET triangles.
mesh_made() {
    if [ "$rc" -ne 0 ] || [ -s "$err" ] || ! grep -qE -- "$2" "$out"; then
        fail "$1" "exit $rc: $(head -c 300 "$err") $(head -c 300 "$out")"; return
    fi
    "$SILK" info "$3" >"$tmp/info" 2>&1
    if [ "$(info_value "$tmp/info" triangles)" = "$4" ] && [ "$(info_value "$tmp/info" "boundary edges")" = 0 ] &&
       [ "$(info_value "$tmp/info" "non-manifold edges")" = 0 ] && [ "$(info_value "$tmp/info" "degenerate triangles")" = 0 ]; then
        pass "$1: $4 triangles, closed, manifold"
    else
        fail "$1" "silk info: $(head -c 400 "$tmp/info")"
    fi
}

# firmware_tests: the preamble of a test that runs the firmware under QEMU.
# It skips under the sanitizers (the firmware has no sanitizer build) and
# without qemu-system-arm and arm-none-eabi-gcc, except in CI, where a
# missing tool fails.
firmware_tests() {
    if [ -n "${SILK_SAN:-}" ]; then
        echo "skip: the firmware is checked in the normal pass (it has no sanitizer build)"
        done_testing
        exit 0
    fi
    missing=
    command -v qemu-system-arm >/dev/null 2>&1 || missing="qemu-system-arm"
    command -v arm-none-eabi-gcc >/dev/null 2>&1 || missing="$missing arm-none-eabi-gcc"
    if [ -n "$missing" ]; then
        if [ -n "${CI:-}" ]; then
            fail "toolchain" "CI must have$missing (make deps; .ci/run installs them)"
            done_testing
            exit 1
        fi
        echo "skip: $missing not installed (make deps installs the ARM toolchain and QEMU)"
        done_testing
        exit 0
    fi
}
