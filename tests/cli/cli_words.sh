#!/bin/sh
# cli_words.sh - what users read speaks to users: the README, docs/, every
# command's help and the benchmark's Markdown report never mention the
# project's own work items (issues, acceptance targets).
. "$(dirname "$0")/../shlib.sh"

root=$here/..
words='\bissues?\b|acceptance'

found=$(grep -n -i -E "$words" "$root/README.md" "$root"/docs/*.md 2>/dev/null | head -n 5)
check "README and docs speak to users${found:+ (found: $found)}" test -z "$found"

"$SILK" --help >"$tmp/help.txt" 2>&1
for c in render info gen view bench diff simplify pack profile; do
    "$SILK" help "$c" >>"$tmp/help.txt" 2>&1
done
found=$(grep -i -E "$words" "$tmp/help.txt" | head -n 3)
check "every command's help speaks to users${found:+ (found: $found)}" test -z "$found"

# The benchmark's report, on a generated sphere and a finer one.
"$SILK" gen sphere -o "$tmp/coarse.obj" >/dev/null &&
    "$SILK" gen sphere --segments 40 --bands 30 -o "$tmp/fine.obj" >/dev/null &&
    run_silk bench --pair "$tmp/coarse.obj:$tmp/fine.obj" --views 1 --size 80x60 --modes flat,smooth,pn3 \
        --reps 1 --md "$tmp/b.md"
check "bench --md writes its report" test "$rc" -eq 0 -a -s "$tmp/b.md"
found=$(grep -i -E "$words|target" "$tmp/b.md" | head -n 3)
check "bench --md speaks to users${found:+ (found: $found)}" test -z "$found"

done_testing
