#!/bin/sh
# bench/visibility.sh SILK OUTDIR - time the per-frame visibility pass (brute
# against the Gaussian-sphere hierarchy) on torus knots of 500, 5000, 50000
# and 200000 triangles made by `silk gen`, and on the scanned bunny-fine, and
# write the result to OUTDIR/bench_visibility.txt.  With CALLGRIND=1 it also
# counts instructions per frame of both passes under valgrind's callgrind
# (slow: the loading is counted too, only the two functions are reported).
set -eu
silk=${1:-build/silk}
out=${2:-out}
meshes=${SILK_MESHES:-../shared/meshes}
work=$(dirname "$silk")/bench
mkdir -p "$work" "$out"

# segments x bands x 2 = triangles
for spec in "25 10 500" "125 20 5000" "500 50 50000" "1000 100 200000"; do
  set -- $spec
  f="$work/knot-$3.obj"
  [ -s "$f" ] || "$silk" gen knot --segments "$1" --bands "$2" -o "$f"
done
list="$work/knot-500.obj $work/knot-5000.obj $work/knot-50000.obj $work/knot-200000.obj"
[ -f "$meshes/bunny-fine.obj" ] && list="$list $meshes/bunny-fine.obj"

{
  echo "# silk bench --visibility-pass, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(uname -m)"
  echo "# ns per frame, median over 36 views of the best of 5 batches; speedup = brute_ns / gauss_ns"
  "$silk" bench --visibility-pass $list
} > "$out/bench_visibility.txt.tmp"
awk '$1 == "visibility" { split($5, b, "="); split($6, g, "="); split($8, a, "=");
       best = b[2] < g[2] ? b[2] : g[2];
       printf "# speedup %s %s %.2fx  auto/faster %.3f\n", $2, $3, b[2] / g[2], a[2] / best }' \
  "$out/bench_visibility.txt.tmp" >> "$out/bench_visibility.txt.tmp"

if [ "${CALLGRIND:-0}" = 1 ] && command -v valgrind >/dev/null; then
  for f in $work/knot-50000.obj $work/knot-200000.obj $meshes/bunny-fine.obj; do
    [ -f "$f" ] || continue
    for p in parallel perspective; do
      line="# callgrind $f $p"
      for m in brute gauss; do
        cg="$work/callgrind.$m.out"
        valgrind --tool=callgrind --callgrind-out-file="$cg" \
          "$silk" bench --visibility-pass --only $m --projection $p --batches 1 "$f" >/dev/null 2>&1
        # instructions of silk_visibility() and all it calls, over the 36 frames
        ir=$(callgrind_annotate --inclusive=yes --threshold=100 "$cg" 2>/dev/null |
             awk 'index($0, ":silk_visibility ") { gsub(",", "", $1); print $1; exit }')
        line="$line ${m}_instructions=$(( ${ir:-0} / 36 ))"
      done
      echo "$line" >> "$out/bench_visibility.txt.tmp"
    done
  done
  rm -f "$work"/callgrind.*.out
fi
mv "$out/bench_visibility.txt.tmp" "$out/bench_visibility.txt"
cat "$out/bench_visibility.txt"
