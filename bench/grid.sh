#!/bin/sh
# bench/grid.sh SILK OUTDIR - the robustness grid (`silk bench --grid`,
# docs/measurements.md, "The robustness grid"): every shipped mesh of
# ../shared/meshes (or $SILK_MESHES) against its detailed model where there
# is one, and every detailed model made into prepared models of 500
# triangles by `silk prepare` (default options, which fit the normals, and
# --no-fit) against itself,
# 120 views each (24 yaws x 5 pitches, 320x240, outlines not anti-aliased).
# Writes OUTDIR/grid.md (the summary, the worst views and the commands that
# show them), OUTDIR/grid.csv (every view) and OUTDIR/grid.txt.
#
# The prepared models are kept in BUILD/grid/ (BUILD the directory of SILK;
# GRID_CACHE=DIR elsewhere)
# and made again only when the sources of `silk prepare` change
# (bench/grid-models.sh).  They are made with --no-clip, which writes the
# same coarse mesh without the clip mode's hull and map.
# GRID_ARGS adds options (e.g. --threads 1); GRID_ONLY=NAME,... restricts
# the grid to those meshes (names as in the table, e.g. bunny-500,cow-prep).
set -eu
silk=${1:-build/silk}
out=${2:-out}
meshes=${SILK_MESHES:-../shared/meshes}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
if [ ! -d "$meshes" ]; then
  echo "bench/grid.sh: skipped: no reference meshes in $meshes"
  exit 0
fi
cache=${GRID_CACHE:-$(dirname "$silk")/grid}
sh "$here/grid-models.sh" "$silk" "$cache"

list=""
only=${GRID_ONLY:-}
want() {
  [ -z "$only" ] && return 0
  case ",$only," in *",$1,"*) return 0 ;; esac
  return 1
}
# Shipped meshes, each against NAME-fine.obj where it is its source.  The
# torus-576's detailed model comes from another source (SOURCES.md): it is
# measured against its flat drawing alone, like the pawn and the cone.
for c in "$meshes"/*.obj; do
  n=$(basename "$c" .obj)
  case "$n" in *-fine) continue ;; esac
  want "$n" || continue
  f=$meshes/${n%-*}-fine.obj
  if [ "$n" != torus-576 ] && [ -f "$f" ]; then list="$list $c:$f"; else list="$list $c"; fi
done
# Prepared models of every detailed mesh.
for f in "$meshes"/*-fine.obj; do
  m=$(basename "$f" -fine.obj)
  want "$m-prep" && list="$list $cache/$m-prep.silk:$f"
  want "$m-nofit" && list="$list $cache/$m-nofit.silk:$f"
done

# shellcheck disable=SC2086
"$silk" bench --grid $list --worst 3 --md "$out/grid.md.tmp" --csv "$out/grid.csv" ${GRID_ARGS:-} | tee "$out/grid.txt"
{
  echo "<!-- make bench (bench/grid.sh), $(date -u +%Y-%m-%dT%H:%M:%SZ) -->"
  echo "Prepared models: \`$cache/M-prep.silk\` is \`silk prepare $meshes/M-fine.obj -o M-prep.silk --triangles 500\`,"
  echo "\`$cache/M-nofit.silk\` the same with \`--no-fit\` (made with \`--no-clip\`: the same mesh)."
  echo
  cat "$out/grid.md.tmp"
} > "$out/grid.md"
rm -f "$out/grid.md.tmp"
echo "bench/grid.sh: wrote $out/grid.md, $out/grid.csv, $out/grid.txt"
