#!/bin/sh
# bench/grid-models.sh SILK CACHE [NAME...] - the prepared models of the
# robustness grid: for every detailed mesh M-fine.obj of ../shared/meshes
# (or $SILK_MESHES; only the NAMEs given, if any), CACHE/M-prep.silk
# (`silk prepare M-fine.obj --triangles 500`, the normals fitted as by
# default) and CACHE/M-nofit.silk (the same with --no-fit: the detailed
# mesh's own normals), both with --no-clip (the same coarse mesh, without
# clip mode's hull and map).  Made again only when the sources that make
# them change (their checksum is kept in CACHE/stamp).  Used by
# bench/grid.sh and tests/cli/cli_grid.sh.
set -eu
silk=$1
cache=$2
shift 2
meshes=${SILK_MESHES:-../shared/meshes}
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$cache"
# what a prepared model depends on: the tool's simplification, surface
# normals and fit, and the core's loader (fixed-point positions)
sum=$(cat "$src"/tools/cli/cmd_prepare.c "$src"/tools/prep/simplify.c "$src"/tools/prep/surface.c \
  "$src"/tools/prep/fit.c "$src"/tools/prep/closest.c "$src"/tools/prep/model_file.c "$src"/src/obj.c \
  "$src"/src/load.c "$src"/src/fixed.c |
  cksum | cut -d' ' -f1)
if [ "$(cat "$cache/stamp" 2>/dev/null)" != "$sum" ]; then
  rm -f "$cache"/*.silk
  echo "$sum" > "$cache/stamp"
fi
names=$*
if [ -z "$names" ]; then
  for f in "$meshes"/*-fine.obj; do names="$names $(basename "$f" -fine.obj)"; done
fi
for m in $names; do
  f=$meshes/$m-fine.obj
  [ -f "$f" ] || continue
  if [ ! -f "$cache/$m-prep.silk" ]; then
    "$silk" prepare "$f" -o "$cache/$m-prep.silk" --triangles 500 --no-clip --quiet >/dev/null
  fi
  if [ ! -f "$cache/$m-nofit.silk" ]; then
    "$silk" prepare "$f" -o "$cache/$m-nofit.silk" --triangles 500 --no-clip --no-fit --quiet >/dev/null
  fi
done
