#!/bin/sh
# cli_gen.sh - `silk gen`: every shape, default and other parameters, is
# closed, edge-manifold and consistently oriented (each directed edge once,
# its reverse once), has the Euler characteristic of its topology, positive
# signed volume, every vertex within 1e-7 of the analytic surface (checked
# here in awk, independently of gen.c), and loads in silk with no boundary,
# non-manifold or degenerate elements.  Bad parameters are usage errors.
. "$(dirname "$0")/../shlib.sh"

cat >"$tmp/check.awk" <<'AWK'
# Checks an OBJ written by `silk gen` against the analytic shape named in its
# first line ("# silk gen SHAPE --opt value ...").  Prints one line:
#   verts=N tris=N euler=N bad_edges=N volume=V maxdist=D
function abs(x) { return x < 0 ? -x : x }
function seg2(px, py, ax, ay, bx, by,   dx, dy, t, ex, ey) {
    dx = bx - ax; dy = by - ay
    t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)
    if (t < 0) t = 0; if (t > 1) t = 1
    ex = px - (ax + t * dx); ey = py - (ay + t * dy)
    return sqrt(ex * ex + ey * ey)
}
function knot_d2(t, x, y, z,   rho, cx, cy, cz) {
    rho = P["--R"] + P["--r"] * cos(P["--q"] * t)
    cx = rho * cos(P["--p"] * t); cy = -P["--r"] * sin(P["--q"] * t); cz = -rho * sin(P["--p"] * t)
    return (x - cx) ^ 2 + (y - cy) ^ 2 + (z - cz) ^ 2
}
function surface_distance(x, y, z,   rho, d, d2, R, H, i, best, bt, a, b, m1, m2, k) {
    rho = sqrt(x * x + z * z)
    if (shape == "sphere") return abs(sqrt(x * x + y * y + z * z) - P["--radius"])
    if (shape == "torus") return abs(sqrt((rho - P["--R"]) ^ 2 + y * y) - P["--r"])
    R = P["--radius"]; H = P["--height"]
    if (shape == "cone") {
        d = seg2(rho, y, 0, 0, R, 0); d2 = seg2(rho, y, R, 0, 0, H)
        return d < d2 ? d : d2
    }
    if (shape == "cylinder") {
        d = seg2(rho, y, 0, 0, R, 0); d2 = seg2(rho, y, R, 0, R, H); if (d2 < d) d = d2
        d2 = seg2(rho, y, R, H, 0, H); return d2 < d ? d2 : d
    }
    # knot: nearest point of the centre curve, coarse then golden section
    best = 1e300
    for (i = 0; i < NS; i++) { d = (x - KX[i]) ^ 2 + (y - KY[i]) ^ 2 + (z - KZ[i]) ^ 2; if (d < best) { best = d; bt = i } }
    a = (bt - 1) * STEP; b = (bt + 1) * STEP
    for (k = 0; k < 80; k++) {
        m1 = b - (b - a) * 0.6180339887498949; m2 = a + (b - a) * 0.6180339887498949
        if (knot_d2(m1, x, y, z) < knot_d2(m2, x, y, z)) b = m2; else a = m1
    }
    return abs(sqrt(knot_d2((a + b) / 2, x, y, z)) - P["--tube"])
}
NR == 1 {
    shape = $4
    for (i = 5; i < NF; i += 2) P[$i] = $(i + 1)
    if (shape == "knot") {
        NS = 4000; STEP = 6.283185307179586 / NS
        for (i = 0; i < NS; i++) {
            t = i * STEP; rho = P["--R"] + P["--r"] * cos(P["--q"] * t)
            KX[i] = rho * cos(P["--p"] * t); KY[i] = -P["--r"] * sin(P["--q"] * t); KZ[i] = -rho * sin(P["--p"] * t)
        }
    }
}
$1 == "v" { nv++; X[nv] = $2; Y[nv] = $3; Z[nv] = $4 }
$1 == "f" {
    nt++
    a = $2; b = $3; c = $4
    E[a "," b]++; E[b "," c]++; E[c "," a]++
    # signed volume of the tetrahedron (origin, a, b, c)
    vol += (X[a] * (Y[b] * Z[c] - Z[b] * Y[c]) - Y[a] * (X[b] * Z[c] - Z[b] * X[c]) + Z[a] * (X[b] * Y[c] - Y[b] * X[c])) / 6
}
END {
    bad = 0; ne = 0
    for (e in E) {
        split(e, ab, ",")
        if (E[e] != 1 || E[ab[2] "," ab[1]] != 1) bad++
        ne++
    }
    ne = ne / 2
    maxd = 0
    for (i = 1; i <= nv; i++) { d = surface_distance(X[i], Y[i], Z[i]); if (d > maxd) maxd = d }
    printf "verts=%d tris=%d euler=%d bad_edges=%d volume=%.6f maxdist=%.3g\n", nv, nt, nv - ne + nt, bad, vol, maxd
}
AWK

# gen_ok NAME EULER SHAPE ARGS...: generate, check geometry and loading.
gen_ok() {
    name=$1; euler=$2; shift 2
    f=$tmp/$name.obj
    run_silk gen "$@" -o "$f"
    if [ "$rc" -ne 0 ] || [ -s "$err" ]; then fail "$name" "gen exit $rc: $(cat "$err")"; return; fi
    res=$(awk -f "$tmp/check.awk" "$f")
    # the counts the header promises
    hv=$(sed -n '2s/^# \([0-9]*\) vertices, \([0-9]*\) triangles.*/\1/p' "$f")
    ht=$(sed -n '2s/^# \([0-9]*\) vertices, \([0-9]*\) triangles.*/\2/p' "$f")
    echo "$name: $res"
    echo "$res" | awk -v e="$euler" -v hv="$hv" -v ht="$ht" '{
        for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
        ok = v["euler"] == e && v["bad_edges"] == 0 && v["volume"] > 0 && v["maxdist"] < 1e-7 &&
             v["verts"] == hv && v["tris"] == ht && ht > 0
        exit ok ? 0 : 1 }' && pass "$name geometry" || fail "$name geometry" "$res (header $hv/$ht, euler $euler)"
    run_silk info "$f" --size 32x32
    if [ "$rc" -eq 0 ] && [ "$(info_value "$out" "triangles")" = "$ht" ] &&
       [ "$(info_value "$out" "boundary edges")" = 0 ] && [ "$(info_value "$out" "non-manifold edges")" = 0 ] &&
       [ "$(info_value "$out" "degenerate triangles")" = 0 ]; then
        pass "$name loads"
    else
        fail "$name loads" "info exit $rc: $(head -c 300 "$err")"
    fi
}

gen_ok sphere 2 sphere
gen_ok torus 0 torus
gen_ok cone 2 cone
gen_ok cylinder 2 cylinder
gen_ok knot 0 knot
gen_ok sphere-small 2 sphere --segments 3 --bands 2 --radius 0.5
gen_ok sphere-fine 2 sphere --segments 64 --bands 48 --radius 2.5
gen_ok torus-thin 0 torus --segments 3 --bands 3 --R 2 --r 0.1
gen_ok torus-fat 0 torus --segments 40 --bands 30 --R 1 --r 0.9
gen_ok cone-rows 2 cone --segments 12 --bands 4 --radius 0.5 --height 3
gen_ok cylinder-rows 2 cylinder --segments 7 --bands 5 --radius 2 --height 0.5
gen_ok knot-35 0 knot --p 3 --q 5 --tube 0.12 --segments 150 --bands 6
gen_ok knot-unknot 0 knot --p 1 --q 4 --R 1.5 --r 0.5 --tube 0.1 --segments 40 --bands 5

# The default knot and the documented one are smooth tubes: no edge is a
# crease (a tube twisting between its rings, or passing through itself,
# makes them).
smooth_tube() {
    name=$1; shift
    "$SILK" gen knot "$@" -o "$tmp/tube.obj" >/dev/null 2>"$err" && run_silk info "$tmp/tube.obj"
    n=$(info_value "$out" "feature edges")
    check "$name: no feature edges (${n:-none})" test "$rc" -eq 0 -a "$n" = 0
}
smooth_tube "default knot"
smooth_tube "documented knot" --p 3 --q 5 --tube 0.15 --segments 160
check "silk help gen shows the documented knot" sh -c "'$SILK' help gen | grep -q -- '--p 3 --q 5 --tube 0.15 --segments 160'"
want='--tube 0.3 is too thick: the tube would pass through itself \(at most 0\.[0-9]+' \
    expect_usage "knot tube through itself" gen knot --p 3 --q 5 --tube 0.3 -o "$tmp/k.obj"
want='--segments 10 is too few: the tube.s straight pieces would pass through each other \(at least 12 ' \
    expect_usage "knot too coarse: its polyline passes through itself" gen knot --segments 10 -o "$tmp/k.obj"
want='--tube 1.1 is too thick for the curve.s tightest bend \(at most' \
    expect_usage "knot tube folds at a bend" gen knot --p 1 --q 8 --R 3 --r 1 --tube 1.1 -o "$tmp/k.obj"

# the defaults the paper's experiments use
run_silk gen sphere -o "$tmp/s.obj"
check "sphere default is 200 triangles" grep -q '^# 102 vertices, 200 triangles' "$tmp/s.obj"
run_silk gen torus -o "$tmp/t.obj"
check "torus default is 576 triangles" grep -q '^# 288 vertices, 576 triangles' "$tmp/t.obj"

# stdout and the file are the same bytes
"$SILK" gen knot -o - >"$tmp/k1.obj" 2>"$err"
run_silk gen knot -o "$tmp/k2.obj"
check "-o - writes the same mesh to stdout" cmp -s "$tmp/k1.obj" "$tmp/k2.obj"
check "atomic output leaves no temporary file" no_tmp_files "$tmp"

# bad parameters: usage errors, nothing written (an earlier file stays)
o=$tmp/bad.obj
echo earlier >"$tmp/earlier.obj"
want='--tube' expect_usage "a failed run" gen knot --tube 0.5 -o "$tmp/earlier.obj"
check "a failed run keeps an earlier output" test "$(cat "$tmp/earlier.obj")" = earlier
want='--segments' expect_usage "segments too few" gen sphere --segments 2 -o "$o"
want='--bands' expect_usage "bands too few" gen sphere --bands 1 -o "$o"
want='--r must be smaller' expect_usage "torus r >= R" gen torus --R 1 --r 1 -o "$o"
want='common factor' expect_usage "knot p, q not coprime" gen knot --p 2 --q 4 -o "$o"
want='--tube' expect_usage "knot tube too thick" gen knot --tube 0.5 -o "$o"
want='does not apply' expect_usage "option of another shape" gen cone --R 2 -o "$o"
want='unknown shape' expect_usage "unknown shape" gen cube -o "$o"
want='not a number' expect_usage "radius not a number" gen sphere --radius abc -o "$o"
want='between' expect_usage "radius negative" gen sphere --radius -1 -o "$o"
want='positive' expect_usage "radius zero" gen sphere --radius 0 -o "$o"
want='not an integer' expect_usage "segments not an integer" gen sphere --segments 10.5 -o "$o"
want='too many triangles' expect_usage "too many triangles" gen sphere --segments 100000 --bands 100000 -o "$o"
want='needs a value' expect_usage "missing value" gen sphere --radius
want='no output' expect_usage "missing -o" gen sphere
want='\.obj' expect_usage "output not .obj" gen sphere -o "$tmp/s.png"
want='unknown option' expect_usage "unknown option" gen sphere --wobble 3 -o "$o"
check "no output after failures" test ! -e "$o"
check "no .png written for a bad extension" test ! -e "$tmp/s.png"
want="the directory $tmp/no/such/dir does not exist" expect_input "missing directory" gen sphere -o "$tmp/no/such/dir/s.obj"
check "no temporary files after failures" no_tmp_files "$tmp"

help_lists() {
    run_silk gen --help
    [ "$rc" -eq 0 ] || return 1
    for o in sphere torus cone cylinder knot --segments --bands --radius --height --R --r --tube --p --q -o; do
        grep -q -- "$o" "$out" || return 1
    done
}
check "gen --help lists every shape and parameter" help_lists

done_testing
