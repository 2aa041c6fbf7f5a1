#!/bin/sh
# bench/compact.sh SILK OUTDIR - what the compact packed model costs and
# what it changes (docs/measurements.md, "Compact models").
#
# For every shared 500-triangle model (../shared/meshes or $SILK_MESHES;
# skipped when absent), `silk pack` writes the compact model (-o .slkc:
# smooth-capable, and --flat: flat frames only), and both it and the mesh it
# was packed from are drawn from the same 12 cameras (yaw 0..330 in steps of
# 30, pitch +25 and -35 by turns), flat and smooth, 320x240:
#   - outline: the Hausdorff distance between the outer outlines of the two
#     renders (bench/compact_shading.py --outline: a pinhole inside the object,
#     which the rasterizer leaves in some large frames, is not outline) made
#     at 8 times the size (1280x960), divided by 4: the outlines' distance in
#     pixels of the 320x240 frame, to 1/4 pixel;
#   - shading: at 320x240, over the pixels both draw, the largest difference
#     of a channel (levels of 255), the 99th percentile of it and the share
#     within 2 levels; and the same over the inner pixels (both draw the 8
#     around them too: not on an outline, where a moved edge changes which
#     triangle a pixel shows) (bench/compact_shading.py).
# Writes OUTDIR/compact.md (a table row per model) and OUTDIR/compact.csv.
# COMPACT_ONLY=NAME,... restricts the models (e.g. bunny-500,spot-500);
# COMPACT_PACK_ARGS adds options to `silk pack` (e.g. --position-bits 14).
set -eu
silk=${1:-build/silk}
out=${2:-out}
meshes=${SILK_MESHES:-../shared/meshes}
here=$(cd "$(dirname "$0")" && pwd)
work=$(dirname "$silk")/bench-compact
mkdir -p "$work" "$out"
if [ ! -d "$meshes" ]; then
  echo "bench/compact.sh: skipped: no reference meshes in $meshes"
  exit 0
fi
csv=$out/compact.csv
echo "model,triangles,bytes_full,bytes_smooth,per_tri_smooth,bytes_flat,per_tri_flat,outline_flat_px,outline_smooth_px,shade_max,shade_p99,shade_within2,inner_max,inner_p99,inner_within2" > "$csv"
for f in "$meshes"/*-500.obj "$meshes"/knot-480.obj "$meshes"/fandisk-1000.obj; do
  [ -f "$f" ] || continue
  m=$(basename "$f" .obj)
  if [ -n "${COMPACT_ONLY:-}" ]; then
    case ",$COMPACT_ONLY," in *",$m,"*) ;; *) continue ;; esac
  fi
  # shellcheck disable=SC2086
  if ! "$silk" pack "$f" -o "$work/$m.slkc" ${COMPACT_PACK_ARGS:-} >/dev/null 2>"$work/$m.err"; then
    echo "bench/compact.sh: $m: $(head -1 "$work/$m.err")"
    continue
  fi
  # shellcheck disable=SC2086
  "$silk" pack "$f" --flat -o "$work/$m-flat.slkc" ${COMPACT_PACK_ARGS:-} >/dev/null
  full=$("$silk" pack "$f" --model-format full -o "$work/$m-full.h" 2>&1 | sed -n 's/.*total \([0-9]*\).*/\1/p')
  tris=$("$silk" info "$f" | awk '/^triangles:/ {print $2}')
  smooth_b=$(wc -c < "$work/$m.slkc" | tr -d ' ')
  flat_b=$(wc -c < "$work/$m-flat.slkc" | tr -d ' ')
  # the cameras: around the centre of the box, 3.2 half-diagonals away
  set -- $("$silk" info "$f" | awk '/^bbox min:/ {x0=$3; y0=$4; z0=$5} /^bbox max:/ {x1=$3; y1=$4; z1=$5}
        END {printf "%.6f %.6f %.6f %.6f", (x0+x1)/2, (y0+y1)/2, (z0+z1)/2,
             sqrt((x1-x0)^2+(y1-y0)^2+(z1-z0)^2)/2}')
  cx=$1 cy=$2 cz=$3 r=$4
  of=0 os=0
  : > "$work/$m.shade"
  : > "$work/$m.views"
  k=0
  while [ $k -lt 12 ]; do
    eye=$(awk -v k=$k -v cx=$cx -v cy=$cy -v cz=$cz -v r=$r 'BEGIN {
        pi = 3.14159265358979; yaw = k * 30 * pi / 180; pitch = (k % 2 ? -35 : 25) * pi / 180; d = 3.2 * r
        printf "%.6f,%.6f,%.6f", cx + d * cos(pitch) * sin(yaw), cy + d * sin(pitch), cz + d * cos(pitch) * cos(yaw) }')
    cam="--eye $eye --target $cx,$cy,$cz"
    for mode in flat smooth; do
      for s in 1280x960 320x240; do
        "$silk" render "$f" -o "$work/a.ppm" $cam --size $s --mode $mode
        "$silk" render "$work/$m.slkc" -o "$work/b.ppm" $cam --size $s --mode $mode
        if [ $s = 1280x960 ]; then
          h=$(python3 "$here/compact_shading.py" --outline "$work/a.ppm" "$work/b.ppm")
          echo "$m $mode view $k: $cam: hausdorff $h px at 4x" >> "$work/$m.views"
          if [ "$mode" = flat ]; then of=$(awk -v a=$of -v b="$h" 'BEGIN { b = b == "inf" ? 1e9 : b / 4; print (b > a ? b : a) }')
          else os=$(awk -v a=$os -v b="$h" 'BEGIN { b = b == "inf" ? 1e9 : b / 4; print (b > a ? b : a) }'); fi
        else
          python3 "$here/compact_shading.py" "$work/a.ppm" "$work/b.ppm" >> "$work/$m.shade"
        fi
      done
    done
    k=$((k + 1))
  done
  shade=$(python3 "$here/compact_shading.py" --sum all "$work/$m.shade"),$(python3 "$here/compact_shading.py" --sum inner "$work/$m.shade")
  echo "$m,$tris,$full,$smooth_b,$(awk -v b=$smooth_b -v t=$tris 'BEGIN{printf "%.2f", b/t}'),$flat_b,$(awk -v b=$flat_b -v t=$tris 'BEGIN{printf "%.2f", b/t}'),$of,$os,$shade" >> "$csv"
  echo "bench/compact.sh: $m done"
done
{
  echo "<!-- make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ) -->"
  echo "## Compact models"
  echo
  echo "\`silk pack\`'s compact model against the arrays it was packed from: bytes in flash, and the"
  echo "largest change over 12 views (320x240) of the outline (Hausdorff distance, measured at 4x"
  echo "the size) and of the shading (levels of 255, pixels both draw)."
  echo
  echo "| model | arrays, bytes | compact, bytes | a triangle | flat only | a triangle | outline flat, px | outline smooth, px | shading max / p99 / within 2 | inner pixels |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---|---|"
  tail -n +2 "$csv" | awk -F, '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s / %s / %.2f%% | %s / %s / %.2f%% |\n", $1, $3, $4, $5, $6, $7, $8, $9, $10, $11, 100 * $12, $13, $14, 100 * $15 }'
} > "$out/compact.md"
echo "bench/compact.sh: wrote $out/compact.md, $csv"
