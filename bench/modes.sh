#!/bin/sh
# bench/modes.sh SILK OUTDIR - the render modes side by side (`silk bench`,
# docs/measurements.md): a sphere and a torus made by `silk gen` against
# finely tessellated ones of the same shapes, and shared scanned and CAD
# meshes against their fine originals (../shared/meshes or $SILK_MESHES,
# skipped when absent), and bunny-fine simplified to 500 triangles by
# `silk simplify`.  Writes OUTDIR/bench.md, bench.csv and bench.png.
# Then the shipped coarse scans against the same detailed models made into
# prepared models by `silk prepare` (500 triangles, default options - the
# normals fitted - and with --no-fit), flat, smooth and pn3:
# OUTDIR/bench-prepared.md and bench-prepared.csv.
# BENCH_VIEWS, BENCH_SIZE and BENCH_REPS override the defaults.
set -eu
silk=${1:-build/silk}
out=${2:-out}
meshes=${SILK_MESHES:-../shared/meshes}
views=${BENCH_VIEWS:-12}
size=${BENCH_SIZE:-640x480}
reps=${BENCH_REPS:-3}
work=$(dirname "$silk")/bench
mkdir -p "$work" "$out"

# Generated pairs: every vertex of both on the exact surface.
"$silk" gen sphere -o "$work/gen-sphere-200.obj"
"$silk" gen sphere --segments 80 --bands 80 -o "$work/gen-sphere-fine.obj"
"$silk" gen torus -o "$work/gen-torus-576.obj"
"$silk" gen torus --segments 96 --bands 48 -o "$work/gen-torus-fine.obj"
pairs="--pair $work/gen-sphere-200.obj:$work/gen-sphere-fine.obj --pair $work/gen-torus-576.obj:$work/gen-torus-fine.obj"

# Shared pairs: the coarse ones are MeshLab's quadric simplifications of the
# fine ones (SOURCES.md).
for p in bunny-500:bunny-fine fandisk-128:fandisk-fine fandisk-1000:fandisk-fine wingnut-500:wingnut-fine armadillo-500:armadillo-fine \
    knot-480:knot-fine; do
  c=$meshes/${p%%:*}.obj f=$meshes/${p#*:}.obj
  if [ -f "$c" ] && [ -f "$f" ]; then pairs="$pairs --pair $c:$f"; else echo "bench/modes.sh: skipping $p (not in $meshes)"; fi
done

# The same bunny simplified by `silk simplify`, against the same reference.
if [ -f "$meshes/bunny-fine.obj" ]; then
  "$silk" simplify "$meshes/bunny-fine.obj" "$work/bunny-silk-500.obj" --triangles 500 >/dev/null
  pairs="$pairs --pair $work/bunny-silk-500.obj:$meshes/bunny-fine.obj"
fi

# shellcheck disable=SC2086
"$silk" bench $pairs --views "$views" --size "$size" --reps "$reps" --modes flat,smooth,blend,pn2,pn3 \
  --csv "$out/bench.csv" --md "$out/bench.md.tmp" --plot "$out/bench.png"
{
  echo "<!-- make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(uname -m), $(nproc 2>/dev/null || echo ?) cores -->"
  cat "$out/bench.md.tmp"
} > "$out/bench.md"
rm -f "$out/bench.md.tmp"
echo "bench/modes.sh: wrote $out/bench.md, $out/bench.csv, $out/bench.png"

# Shipped coarse scans against prepared models of the same detailed ones.
pairs=""
for m in bunny cow armadillo spot feline springer fish cat; do
  c=$meshes/$m-500.obj f=$meshes/$m-fine.obj
  if [ -f "$c" ] && [ -f "$f" ]; then
    "$silk" prepare "$f" -o "$work/$m-prepared-500.silk" --triangles 500 --no-clip >/dev/null
    "$silk" prepare "$f" -o "$work/$m-prepared-nofit-500.silk" --triangles 500 --no-clip --no-fit >/dev/null
    pairs="$pairs --pair $c:$f --pair $work/$m-prepared-500.silk:$f --pair $work/$m-prepared-nofit-500.silk:$f"
  else
    echo "bench/modes.sh: skipping $m (not in $meshes)"
  fi
done
if [ -n "$pairs" ]; then
  # shellcheck disable=SC2086
  "$silk" bench $pairs --views "$views" --size "$size" --reps "$reps" --modes flat,smooth,pn3 \
    --csv "$out/bench-prepared.csv" --md "$out/bench-prepared.md.tmp"
  {
    echo "<!-- make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(uname -m), $(nproc 2>/dev/null || echo ?) cores -->"
    cat "$out/bench-prepared.md.tmp"
  } > "$out/bench-prepared.md"
  rm -f "$out/bench-prepared.md.tmp"
  echo "bench/modes.sh: wrote $out/bench-prepared.md, $out/bench-prepared.csv"
fi
