#!/bin/sh
# cli_layout.sh - the tree's layout keeps its rules: every test sits in a
# group folder and tests/README.md names it, the stage table there names
# every core file and the command table every command; no file in tools/
# includes a core header from src/ (what the tools share with the core is
# public, include/silk/), and tools/prep/ and tools/image/ need nothing of
# the command line (tools/cli/).
. "$(dirname "$0")/../shlib.sh"

root=$here/..
index=$here/README.md
check "tests/README.md exists" test -s "$index"

missing=
for t in "$here"/*/test_*.c "$here"/*/test_*.cpp "$here"/*/cli_*.sh; do
    [ -e "$t" ] || continue
    group=$(basename "$(dirname "$t")")
    name=$(basename "$t")
    case "$name" in *.c) name=${name%.c} ;; esac
    grep -qF "$group/$name" "$index" || missing="$missing $group/$name"
done
check "tests/README.md names every test (missing:${missing:- none})" test -z "$missing"

loose=$(ls "$here"/test_*.c "$here"/test_*.cpp "$here"/cli_*.sh 2>/dev/null | tr '\n' ' ')
check "every test is in a group folder (loose: ${loose:-none})" test -z "$loose"

missing=
for f in "$root"/src/*.c; do
    grep -qF "\`$(basename "$f")\`" "$index" || missing="$missing $(basename "$f")"
done
check "the stage table names every core file (missing:${missing:- none})" test -z "$missing"

missing=
for c in $("$SILK" --help | sed -n 's/^  silk \([a-z][a-z]*\) .*/\1/p' | sort -u); do
    grep -qF "\`silk $c\`" "$index" || missing="$missing $c"
done
check "the command table names every command (missing:${missing:- none})" test -z "$missing"

into_src=$(grep -rlE '#include +"(\.\./)*src/' "$root/tools" 2>/dev/null | sed "s|$root/||" | tr '\n' ' ')
check "no file in tools/ includes one from src/ (${into_src:-none})" test -z "$into_src"
into_cli=$(grep -rlE '#include +"(\.\./)*cli/' "$root/tools/prep" "$root/tools/image" 2>/dev/null | sed "s|$root/||" | tr '\n' ' ')
check "tools/prep/ and tools/image/ include nothing of tools/cli/ (${into_cli:-none})" test -z "$into_cli"

done_testing
