#!/bin/sh
# bench/bytes.sh SILK OUTDIR - which representation is truest per byte.
# For each shared detailed model (../shared/meshes or $SILK_MESHES; skipped
# when absent), `silk prepare` makes coarse meshes at several triangle
# counts (250 to 16 000, drawn flat and smooth), outer hulls with silhouette maps of
# several view counts (clip) and, where the tool has them, silhouette
# textures of several atlas sizes (siltex); `silk bench` measures each
# against the detailed model from the same cameras and plots the mean
# silhouette error against the model's bytes in flash: OUTDIR/bytes-M.png
# and bytes-M.csv.  OUTDIR/bench-bytes.md then says, for flash budgets
# from 8 KiB to 1 MiB, which of them has the smallest error within it.
# BENCH_VIEWS, BENCH_SIZE override the defaults (12 views, 640x480).
set -eu
silk=${1:-build/silk}
out=${2:-out}
meshes=${SILK_MESHES:-../shared/meshes}
views=${BENCH_VIEWS:-12}
size=${BENCH_SIZE:-640x480}
work=$(dirname "$silk")/bench-bytes
mkdir -p "$work" "$out"

modes=flat,smooth,clip
siltex=0
if "$silk" prepare --help 2>&1 | grep -q -- --siltex; then modes=$modes,siltex siltex=1; fi

md=$out/bench-bytes.md.tmp
{
  echo "<!-- make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(uname -m) -->"
  echo "## Truest per byte"
  echo
  echo "Mean silhouette error (px, $size, $views views x 2 projections, against the detailed"
  echo "model drawn flat) of the representation with the smallest error that fits each flash"
  echo "budget (the mesh drawn plus its silhouette data; \`silk bench\` column \`bytes\`)."
  echo
} > "$md"
header=0
for m in bunny armadillo spot; do
  f=$meshes/$m-fine.obj
  if [ ! -f "$f" ]; then echo "bench/bytes.sh: skipping $m (no $f)"; continue; fi
  pairs=""
  for t in 250 500 1000 2000 4000 8000 16000; do
    "$silk" prepare "$f" -o "$work/$m-$t.silk" --triangles "$t" --no-clip >/dev/null
    pairs="$pairs --pair $work/$m-$t.silk:$f=flat,smooth"
  done
  for v in 42 162 642; do
    "$silk" prepare "$f" -o "$work/$m-500-map$v.silk" --triangles 500 --map-views "$v" >/dev/null
    pairs="$pairs --pair $work/$m-500-map$v.silk:$f=clip"
  done
  if [ "$siltex" = 1 ]; then
    for a in 64 96 128; do
      "$silk" prepare "$f" -o "$work/$m-500-atlas$a.silk" --triangles 500 --siltex --atlas "$a" >/dev/null
      pairs="$pairs --pair $work/$m-500-atlas$a.silk:$f=siltex"
    done
  fi
  # shellcheck disable=SC2086
  "$silk" bench $pairs --modes "$modes" --views "$views" --size "$size" --reps 1 --quiet \
    --csv "$out/bytes-$m.csv" --plot-bytes "$out/bytes-$m.png" >/dev/null
  echo "bench/bytes.sh: wrote $out/bytes-$m.png, $out/bytes-$m.csv"
  # The best row within each budget: error averaged over the projections.
  awk -F, -v model="$m" -v header="$header" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    $(col["mode"]) == "fine" { next }
    { k = $(col["mesh"]) " " $(col["mode"]); err[k] += $(col["error_mean_px"]); n[k]++; bytes[k] = $(col["bytes"]) }
    END {
      if (!header) {
        printf "| model |"; for (b = 8; b <= 1024; b *= 2) printf " %d KiB |", b; printf "\n|---|"
        for (b = 8; b <= 1024; b *= 2) printf "---|"; printf "\n"
      }
      printf "| %s |", model
      for (b = 8; b <= 1024; b *= 2) {
        best = ""; be = 1e9
        for (k in err) if (bytes[k] <= b * 1024 && err[k] / n[k] < be) { be = err[k] / n[k]; best = k }
        if (best == "") printf " - |"
        else { split(best, p, " "); sub("^" model "-", "", p[1]); printf " %s %s: %.2f |", p[2], p[1], be }
      }
      printf "\n"
    }' "$out/bytes-$m.csv" >> "$md"
  header=1
done
{
  echo
  echo "Entries are mode, then the prepared model: triangles (flat, smooth), hull triangles and"
  echo "silhouette-map views (clip), hull triangles and atlas size (siltex); then the error."
} >> "$md"
mv "$md" "$out/bench-bytes.md"
echo "bench/bytes.sh: wrote $out/bench-bytes.md"
