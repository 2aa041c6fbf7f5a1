#!/bin/sh
# cli_json.sh - the machine-readable output: `silk info --json`, `silk diff
# --json` and `silk bench --json` parse as JSON (python3 -m json.tool), hold
# the values of the text output (bench: the CSV's columns), and keep the
# exit codes.  The schemas are in docs/formats.md.
. "$(dirname "$0")/../shlib.sh"

if ! command -v python3 >/dev/null; then
    # CI installs python3 (.ci/run); elsewhere the test skips without it.
    [ -n "${CI:-}" ] && { fail "python3" "CI must have python3"; done_testing; exit 1; }
    echo "skip: python3 missing"; pass "skipped"; done_testing; exit 0
fi
sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }
is_json() { python3 -m json.tool "$1" >/dev/null 2>&1; }
# py FILE EXPR: print EXPR evaluated with j = the parsed file
py() { python3 -c "import json, sys; j = json.load(open(sys.argv[1])); print($2)" "$1"; }

# ---- info ------------------------------------------------------------------------------
run_silk info "$sphere" --json
cp "$out" "$tmp/info.json"
check "info --json parses" is_json "$tmp/info.json"
"$SILK" info "$sphere" >"$tmp/info.txt"
check "info --json: the triangles of the text output" \
    test "$(py "$tmp/info.json" 'j["mesh"]["triangles"]')" = "$(info_value "$tmp/info.txt" triangles)"
check "info --json: triangles drawn" \
    test "$(py "$tmp/info.json" 'j["frame"]["triangles_drawn"]')" = "$(info_value "$tmp/info.txt" '  triangles drawn')"
check "info --json: arena peak" \
    test "$(py "$tmp/info.json" 'j["arena"]["peak"]')" = "$(info_value "$tmp/info.txt" '  peak')"
check "info --json: schema silk-info/1" test "$(py "$tmp/info.json" 'j["schema"]')" = silk-info/1
check "info --json: every section" test "$(py "$tmp/info.json" '" ".join(sorted(j))')" = \
    "arena file file_bytes frame mesh mesh_bytes model schema"
check "info --json: a mesh file is no prepared model" test "$(py "$tmp/info.json" 'j["model"]')" = None
# every count of the text is in the JSON
check "info --json: reoriented triangles as the text" \
    test "$(py "$tmp/info.json" 'j["mesh"]["reoriented_triangles"]')" = "$(info_value "$tmp/info.txt" 'reoriented triangles')"
check "info --json: normals from as the text" \
    test "$(py "$tmp/info.json" 'j["mesh"]["normals_from"]')" = \
    "$(info_value "$tmp/info.txt" 'normals from' | sed 's/the file/file/; s/computed.*/computed/')"
run_silk info "$tmp/missing.obj" --json
check "info --json: a missing file is still exit 1, nothing on stdout" test "$rc" -eq 1 -a ! -s "$out"

# ---- diff --------------------------------------------------------------------------------
"$SILK" render "$sphere" -o "$tmp/a.png" --size 160x120 --mode flat
"$SILK" render "$sphere" -o "$tmp/b.png" --size 160x120
run_silk diff "$tmp/a.png" "$tmp/b.png" --json
cp "$out" "$tmp/diff.json"
check "diff --json parses" is_json "$tmp/diff.json"
"$SILK" diff "$tmp/a.png" "$tmp/b.png" >"$tmp/diff.txt"
check "diff --json: differing as in the text line" \
    grep -q "differing=$(py "$tmp/diff.json" 'j["differing"]') " "$tmp/diff.txt"
check "diff --json: schema and fields" test "$(py "$tmp/diff.json" '" ".join(j)')" = \
    "schema a b width height differing boundary mean_px hausdorff_px"
"$SILK" render "$sphere" -o "$tmp/empty.png" --size 160x120 --eye 0,0,-50 --target 0,0,-60
run_silk diff "$tmp/a.png" "$tmp/empty.png" --json
check "diff --json: inf is null" test "$(py "$out" 'j["hausdorff_px"]')" = None
run_silk diff "$tmp/a.png" "$tmp/nothing.png" --json
check "diff --json: a missing image is still exit 1" test "$rc" -eq 1 -a ! -s "$out"

# ---- bench ---------------------------------------------------------------------------------
bench="bench $sphere --views 2 --reps 1 --size 64x48 --modes flat,smooth"
run_silk $bench --csv "$tmp/b.csv" --json "$tmp/b.json"
check "bench --json FILE parses" is_json "$tmp/b.json"
check "bench --json: one object per CSV row" \
    test "$(py "$tmp/b.json" 'len(j)')" -eq "$(($(grep -c '' "$tmp/b.csv") - 1))"
check "bench --json: the CSV's columns" test "$(py "$tmp/b.json" '",".join(k for k in j[0] if k != "schema")')" = \
    "$(head -n 1 "$tmp/b.csv")"
check "bench --json: triangles drawn as in the CSV" \
    test "$(py "$tmp/b.json" '"%.1f" % j[1]["triangles_drawn"]')" = "$(sed -n 3p "$tmp/b.csv" | cut -d, -f6)"
run_silk $bench --json -
check "bench --json -: standard output holds only the JSON" is_json "$out"

done_testing
