#!/bin/sh
# cli_man.sh - the manual page is the help: `silk help --man` holds, block
# for block, exactly what `silk --help` and `silk help COMMAND` print; the
# page the build made (BUILD/silk.1, which make install installs) is that
# output; man(1) reads it without warnings; the licence is there.
. "$(dirname "$0")/../shlib.sh"

run_silk help --man
check "help --man: exit 0, nothing on stderr" test "$rc" -eq 0 -a ! -s "$err"
cp "$out" "$tmp/silk.1"
check "help --man is a man(7) page" grep -q '^\.TH SILK 1 ' "$tmp/silk.1"

# block TITLE: the lines of the .nf block after the heading TITLE, with roff's
# escapes undone.
block() {
    awk -v want="$1" '
        /^\.S[HS] / { h = $0; sub(/^\.S[HS] /, "", h); gsub(/\\-/, "-", h) }
        h == want && $0 == ".nf" { on = 1; next }
        on && $0 == ".fi" { exit }
        on { gsub(/\\-/, "-"); gsub(/\\e/, "\\"); sub(/^\\&/, ""); print }
    ' "$tmp/silk.1"
}
"$SILK" --help >"$tmp/want"
block DESCRIPTION >"$tmp/got"
check "the page's description is silk --help" cmp -s "$tmp/want" "$tmp/got"
# the commands silk --help lists
cmds=$("$SILK" --help | sed -n 's/^  silk \([a-z][a-z]*\) .*/\1/p' | grep -v '^help$')
ncmds=$(echo $cmds | wc -w)
for c in $cmds; do
    "$SILK" help "$c" >"$tmp/want"
    block "silk $c" >"$tmp/got"
    check "the page's silk $c is silk help $c" test -s "$tmp/want" -a -s "$tmp/got" && cmp -s "$tmp/want" "$tmp/got"
done
n=$(grep -c '^\.SS silk ' "$tmp/silk.1")
check "one section per command ($n of $ncmds)" test "$n" -eq "$ncmds"

if [ -e "$build/silk.1" ]; then
    check "$build/silk.1 is silk help --man" cmp -s "$build/silk.1" "$tmp/silk.1"
else
    fail "$build/silk.1 is made by make" "missing"
fi
if command -v man >/dev/null 2>&1; then
    LC_ALL=C MANWIDTH=80 man --warnings -l "$tmp/silk.1" >"$tmp/man.txt" 2>"$tmp/man.err"
    check "man reads the page without warnings ($(head -c 200 "$tmp/man.err"))" test ! -s "$tmp/man.err" -a -s "$tmp/man.txt"
    check "the rendered page shows an option as typed" grep -q -- '--tolerance PX' "$tmp/man.txt"
else
    echo "skip: man is not installed; the page is not rendered"
fi

check "LICENSE is MIT, the silk authors" grep -q 'Copyright (c) .* the silk authors' "$here/../LICENSE"
check "LICENSE is MIT" grep -q '^MIT License' "$here/../LICENSE"

done_testing
