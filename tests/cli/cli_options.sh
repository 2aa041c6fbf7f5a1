#!/bin/sh
# cli_options.sh - every command's help and its parser come from one table:
# `silk help --options` lists each command's rows (tools/cli/opt.h), and
# for every command
#   - its help lists exactly the table's options, in the table's order, none
#     twice;
#   - the parser takes every option as --opt=value and as --opt value alike
#     (a flag bare, and refuses a value for it);
#   - a number below or above the table's range is refused, exit 2, in one
#     line naming the option; the ends of the range are taken;
#   - an option not in the table is refused, exit 2, one line naming it;
# and across commands an option name means one thing: a flag everywhere or
# a value everywhere, with the same choices where it has choices.
. "$(dirname "$0")/../shlib.sh"

"$SILK" help --options >"$tmp/table" 2>"$err"
check "help --options: exit 0, nothing on stderr" test $? -eq 0 -a ! -s "$err"
commands=$(cut -f1 "$tmp/table" | awk '!seen[$0]++')
check "help --options: every command" test "$(echo "$commands" | wc -l)" -ge 12

# the arguments that bring a command's parser: gen needs its shape first
args_of() {
    case "$1" in
    gen) echo "gen sphere" ;;
    *) echo "$1" ;;
    esac
}
# option lines of a help: "  -o, --output META" or "  --size META"
option_lines() {
    grep -E '^  -' | sed -E 's/^  -[a-z], (--[a-zA-Z][a-zA-Z0-9-]*).*/\1/; t; s/^  (--[a-zA-Z][a-zA-Z0-9-]*).*/\1/'
}
# a value the option's kind takes
sample() {   # KIND META NAME LO CHOICES
    case "$1" in
    int | real) echo "$4" ;;
    choice) echo "$5" | cut -d'|' -f1 ;;
    size) echo 64x48 ;;
    rgb) echo 808080 ;;
    vec3) echo 1,2,3 ;;
    bytes) echo 1M ;;
    decimal) echo 1.5 ;;
    output) echo "$tmp/o.png" ;;
    dir) echo "$tmp/d" ;;
    text) case "$2" in PATTERN) echo "$tmp/s%d.png" ;; *) echo x ;; esac ;;
    custom) case "$3" in
        --ortho) echo auto ;; --mode) echo "$2" | cut -d'|' -f1 ;; --modes) echo flat ;; --light) echo 1,1,1 ;;
        --pair) echo a.obj:b.obj ;; --eye) echo 1,2,3 ;; --fb-geometry) echo 8x8x16 ;; --pitches) echo 0,30 ;;
        --place) echo 1:1,2,3 ;; --tint) echo 1:808080 ;; --mode-of) echo 1:flat ;;
        --board) "$SILK" help profile | sed -n 's/.*--board \([a-z0-9-]*\)\].*/\1/p' | head -n 1 ;;
        *) echo x ;;
        esac ;;
    esac
}
# run ARGS...: silk's exit status and its stderr with the option's two
# spellings made one ("=" as " ")
run() { "$SILK" "$@" </dev/null >/dev/null 2>"$tmp/e"; echo "$? $(sed 's/=/ /g' "$tmp/e")"; }
# the error is this option's own (its value or its spelling)
own_error() {   # NAME ALT MESSAGE
    echo "$3" | grep -qE -- "silk: ($1|$2)( |:|=)|unknown option|needs a value|takes no value"
}

echo "$commands" | while read -r cmd; do
    set -- $(args_of "$cmd")
    awk -F'\t' -v c="$cmd" '$1 == c' "$tmp/table" | cut -f2- >"$tmp/rows"
    "$SILK" "$@" --help >"$tmp/help" 2>&1
    option_lines <"$tmp/help" >"$tmp/listed"
    cut -f1 "$tmp/rows" >"$tmp/names"
    if cmp -s "$tmp/listed" "$tmp/names"; then pass "$cmd: the help lists the table's options, in order"
    else fail "$cmd: help and table differ" "$(diff "$tmp/names" "$tmp/listed" | tr '\n' ' ' | head -c 300)"; fi
    twice=$(sort "$tmp/names" | uniq -d | tr '\n' ' ')
    if [ -z "$twice" ]; then pass "$cmd: no option twice"; else fail "$cmd: listed twice" "$twice"; fi

    bad=
    while IFS="$(printf '\t')" read -r name alt kind meta lo hi choices group; do
        [ "$alt" = - ] && alt=$name
        if [ "$kind" = flag ] || { [ "$kind" = custom ] && [ "$meta" = - ]; }; then
            r=$(run "$@" "$name")
            own_error "$name" "$alt" "$r" && bad="$bad $name(bare: $r)"
            r=$(run "$@" "$name=1")
            case "$r" in "2 silk: $name takes no value"*) ;; *) bad="$bad $name(=1: $r)" ;; esac
            continue
        fi
        v=$(sample "$kind" "$meta" "$name" "$lo" "$choices")
        a=$(run "$@" "$name=$v")
        b=$(run "$@" "$name" "$v")
        [ "$a" = "$b" ] || bad="$bad $name(--opt=value: $a / --opt value: $b)"
        own_error "$name" "$alt" "$a" && bad="$bad $name($v refused: $a)"
        [ "$alt" != "$name" ] && { c=$(run "$@" "$alt" "$v"); [ "$c" = "$b" ] || bad="$bad $alt($c)"; }
        r=$(run "$@" "$name")
        case "$r" in "2 silk: $name needs a value") ;; *) bad="$bad $name(no value: $r)" ;; esac
        if [ "$kind" = int ] || [ "$kind" = real ]; then
            for end in "$lo" "$hi"; do
                r=$(run "$@" "$name=$end")
                own_error "$name" "$alt" "$r" && bad="$bad $name($end refused: $r)"
            done
            for out in $(awk -v lo="$lo" -v hi="$hi" 'BEGIN { print lo - 1, hi + 1 }'); do
                r=$(run "$@" "$name=$out")
                case "$r" in "2 silk: $name must be between "*) ;; *) bad="$bad $name($out taken: $r)" ;; esac
            done
        fi
        if [ "$kind" = choice ]; then
            r=$(run "$@" "$name=no-such-word")
            case "$r" in "2 silk: $name must be "*) ;; *) bad="$bad $name(a wrong word: $r)" ;; esac
        fi
    done <"$tmp/rows"
    if [ -z "$bad" ]; then pass "$cmd: every option parses as its row says, --opt=value and --opt value alike"
    else fail "$cmd: options" "$(echo "$bad" | head -c 1500)"; fi

    r=$(run "$@" --no-such-option=3)
    case "$r" in "2 silk: ${cmd%% *}: unknown option --no-such-option (try silk $cmd --help)")
        check "$cmd: an unknown option, one line" test "$(wc -l <"$tmp/e")" -eq 1 ;;
    *) fail "$cmd: an unknown option" "$r" ;; esac
done >"$tmp/results"
cat "$tmp/results"
passed=$((passed + $(grep -c '^ok ' "$tmp/results")))
failed=$((failed + $(grep -c '^FAIL ' "$tmp/results")))

# One meaning per name: a flag everywhere or a value everywhere, the same
# choices.  --json is a flag where the command prints (info, diff) and a
# file where it writes next to its lines (bench, docs/formats.md).
awk -F'\t' '{ k = ($4 == "flag" || ($4 == "custom" && $5 == "-")) ? "flag" : "value";
              if ($4 == "choice") k = k " " $8
              if ($2 in kind && kind[$2] != k && $2 != "--json") print $2 ": " where[$2] " " kind[$2] ", " $1 " " k
              kind[$2] = k; where[$2] = $1 }' "$tmp/table" >"$tmp/meanings"
check "one meaning per option name ($(head -c 300 "$tmp/meanings"))" test ! -s "$tmp/meanings"

# Renamed options say their new name.
run_silk prepare x.obj --views 42
check "prepare --views: exit 2, it is --map-views now" \
    test "$rc" -eq 2 -a "$(cat "$err")" = "silk: prepare: unknown option --views (it is --map-views now; try silk prepare --help)"

done_testing
