#!/bin/sh
# cli_readme.sh - the README keeps its promises: the library example in it
# compiles warning-free against the built library and renders a generated
# sphere with smoothed silhouettes; the commands it names exist.
. "$(dirname "$0")/../shlib.sh"

readme=$here/../README.md
awk '/^```c$/ { on = 1; next } /^```$/ { on = 0 } on' "$readme" >"$tmp/example.c"
check "README has a C example" test -s "$tmp/example.c"

flags="-std=c11 -Wall -Wextra -Wpedantic -Werror"
case "$build" in *san*) flags="$flags -fsanitize=address,undefined" ;; esac
if ${CC:-cc} $flags -I"$here/../include" "$tmp/example.c" "$build/libsilk.a" -o "$tmp/example" 2>"$err"; then
    pass "README example compiles without warnings"
else
    fail "README example compiles without warnings" "$(head -c 500 "$err")"
fi

"$SILK" gen sphere -o "$tmp/sphere.obj"
"$tmp/example" "$tmp/sphere.obj" >"$out" 2>"$err"
rc=$?
example_ok() {
    [ "$rc" -eq 0 ] && awk '{ exit !($1 > 200 && $5 > 0 && $0 ~ /triangles drawn, [0-9]+ on the silhouette, arena peak [0-9]+ bytes/) }' "$out"
}
check "README example renders ($(cat "$out"))" example_ok
"$tmp/example" "$tmp/missing.obj" >"$out" 2>"$err"
check "README example reports a missing file" test $? -eq 1 -a -s "$err"
"$tmp/example" "$here/bad/face-index-zero.obj" >"$out" 2>"$err"
check "README example reports a load error" test $? -eq 1 -a -s "$err"
# Over its 1 MiB buffer: it says so rather than parse a cut file.
"$SILK" gen sphere --segments 200 --bands 120 -o "$tmp/big.obj"
"$tmp/example" "$tmp/big.obj" >"$out" 2>"$err"
rc=$?
check "README example says a file is too large ($(head -c 200 "$err"))" \
    test "$rc" -eq 1 -a "$(cat "$err")" = "$tmp/big.obj: too large for the 1048576-byte buffer"
head -c 1048576 "$tmp/big.obj" >"$tmp/exact.obj"
"$tmp/example" "$tmp/exact.obj" >"$out" 2>"$err"
check "README example reads a file of exactly its buffer's size" test $? -eq 1 -a -z "$(grep 'too large' "$err")"

# The examples after "run by tests/cli/cli_readme.sh" run as they are, one
# command line at a time, in an empty directory with this silk on PATH.
if command -v python3 >/dev/null; then
    awk '/run by tests\/cli\/cli_readme.sh/ { want = 1; next }
         want && /^```sh$/ { on = 1; next } on && /^```$/ { on = 0; want = 0 } on' "$readme" >"$tmp/examples.sh"
    check "README has examples for the tests to run" test "$(grep -c '^silk' "$tmp/examples.sh")" -ge 10
    mkdir -p "$tmp/bin" "$tmp/run"
    silk_abs=$(cd "$(dirname "$SILK")" && pwd)/$(basename "$SILK")
    ln -s "$silk_abs" "$tmp/bin/silk"
    while IFS= read -r line; do
        case "$line" in ''|'#'*) continue ;; esac
        if (cd "$tmp/run" && PATH="$tmp/bin:$PATH" sh -c "set -e; $line" >"$out" 2>"$err"); then
            pass "README: $line"
        else
            fail "README: $line" "$(head -c 300 "$err")"
        fi
    done <"$tmp/examples.sh"
else
    echo "python3 missing: the README examples are not run"
fi

for c in "make demo" "make test" "silk render" "silk info" "silk gen" ".ci/run"; do
    check "README mentions $c" grep -q -- "$c" "$readme"
done
for c in "render --help" "info --help" "gen --help"; do
    check "silk $c works" "$SILK" $c >/dev/null
done

done_testing
