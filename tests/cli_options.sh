#!/bin/sh
# cli_options.sh - every command's --help and its parser agree: each option
# the help lists is accepted, each option the command accepts is listed,
# and no option is listed twice.
#
# "Listed": an option line of the help (two spaces, then -x or --xx), or an
# option named in the usage lines.  "Accepted": `silk CMD OPT` says anything
# but "unknown option".  The options tried are every one any help lists and
# every "--..." string in the tool's sources, so an option one command
# takes and another ignores is caught.
. "$(dirname "$0")/shlib.sh"

src=$here/../tools
# the variants: a name, the arguments that reach the parser, and the help
variants="render|render
info|info
gen|gen sphere
bench|bench
bench-visibility|bench --visibility
simplify|simplify
prepare|prepare
hull|hull
diff|diff
pack|pack
view|view
view-fb|view --fb-file $tmp/fb.raw --fb-geometry 8x8x16
profile|profile"

# option lines of a help: "  -o, --output" or "  --size"; then usage lines
option_lines() {
    grep -E '^  -' | sed -E 's/^  (-o), (--[a-z]+).*/\1\n\2/; t; s/^  (-{1,2}[a-zA-Z][a-zA-Z0-9-]*).*/\1/'
}
usage_opts() {
    awk '/^usage:/ { u = 1 } /^$/ { u = 0 } u' | grep -oE '(^| |\[)-{1,2}[a-zA-Z][a-zA-Z0-9-]*' | tr -d ' ['
}

universe=$tmp/universe
: >"$universe"
echo "$variants" | while IFS='|' read -r name args; do
    # shellcheck disable=SC2086
    "$SILK" $args --help >"$tmp/help-$name" 2>&1
    option_lines <"$tmp/help-$name" >>"$universe"
    usage_opts <"$tmp/help-$name" >>"$universe"
done
grep -ohE '"--[a-z][a-z0-9-]*' "$src"/*/*.c | tr -d '"' >>"$universe"
sort -u "$universe" | grep -vxE -- '--help|-h|--version' >"$universe.sorted"
check "options found ($(wc -l <"$universe.sorted"))" test "$(wc -l <"$universe.sorted")" -gt 60

echo "$variants" | while IFS='|' read -r name args; do
    h=$tmp/help-$name
    option_lines <"$h" | sort >"$tmp/listed-$name"
    { cat "$tmp/listed-$name"; usage_opts <"$h"; } | sort -u >"$tmp/named-$name"
    # gen's shapes share parameters, so its help lists them per shape: every
    # "--x" in it counts, once or not
    if [ "$name" = gen ]; then
        { grep -oE -- '--[a-zA-Z][a-zA-Z0-9-]*' "$h"; option_lines <"$h"; } | sort -u >"$tmp/named-$name"
        cp "$tmp/named-$name" "$tmp/listed-$name"
    fi
    twice=$(uniq -d "$tmp/listed-$name" | tr '\n' ' ')
    if [ -z "$twice" ]; then pass "$name: no option listed twice"; else fail "$name: listed twice" "$twice"; fi

    not_accepted= not_listed=
    # probe every option, four at a time: "OPT 1" if accepted, "OPT 0" if not
    # shellcheck disable=SC2016
    xargs -P 4 -n 1 sh -c 'if timeout 10 "$0" '"$args"' "$1" </dev/null 2>&1 >/dev/null | grep -q "unknown option";
        then echo "$1 0"; else echo "$1 1"; fi' "$SILK" <"$universe.sorted" >"$tmp/probe-$name"
    while read -r opt; do
        accepted=$(grep -m 1 -- "^$opt " "$tmp/probe-$name" | cut -d' ' -f2)
        if grep -qx -- "$opt" "$tmp/named-$name"; then
            [ "$accepted" = 1 ] || not_accepted="$not_accepted $opt"
        else
            [ "$accepted" = 0 ] || not_listed="$not_listed $opt"
        fi
    done <"$universe.sorted"
    if [ -z "$not_accepted" ]; then pass "$name: every listed option is accepted"
    else fail "$name: listed but refused" "$not_accepted"; fi
    if [ -z "$not_listed" ]; then pass "$name: every accepted option is listed"
    else fail "$name: accepted but not listed" "$not_listed"; fi
done >"$tmp/results"
cat "$tmp/results"
passed=$((passed + $(grep -c '^ok ' "$tmp/results")))
failed=$((failed + $(grep -c '^FAIL ' "$tmp/results")))

done_testing
