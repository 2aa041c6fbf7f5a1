#!/bin/sh
# demo.sh SILK OUTDIR - the demo behind `make demo`.
#
# Generates the analytic meshes with `silk gen` (next to the silk binary, in
# BUILD/meshes/), takes bunny-500 and fandisk-128 from the shared reference
# meshes when they are there (../shared/meshes or $SILK_MESHES), and writes
# for each model NAME into OUTDIR:
#   NAME-modes.png    contact sheet: flat, smooth, blend and pn side by side,
#                     each labelled with the triangles it drew
#   NAME-wire.png     the same with the edges drawn; smooth mode shows the
#                     triangles re-meshing added in red
#   NAME-closeup.png  the same, zoomed 6x onto a point of the silhouette
#   NAME-compare.png  flat | smooth at full size (silk render --compare)
#   NAME-aa.png       flat | smooth | smooth with anti-aliased outlines, each
#                     drawn 4 times smaller and magnified 4x pixel by pixel
# and turntable.png, the bunny (or the knot) from 8 sides in smooth mode.
# The globe (a sphere with texture coordinates, `silk gen --uv`) wears
# silk's own checker texture (--texture checker), the painted sphere vertex
# colours.
# Ends by listing what it wrote.  DEMO_SIZE sets the cell size (320x240).
set -eu

silk=${1:-build/silk}
outdir=${2:-out}
size=${DEMO_SIZE:-320x240}
meshdir=$(dirname "$silk")/meshes
shared=${SILK_MESHES:-../shared/meshes}
modes=flat,smooth,blend,pn

[ -x "$silk" ] || { echo "demo.sh: $silk not found; run make first" >&2; exit 1; }
mkdir -p "$outdir" "$meshdir"

"$silk" gen sphere -o "$meshdir/sphere-200.obj"
"$silk" gen torus -o "$meshdir/torus-576.obj"
"$silk" gen cone -o "$meshdir/cone-70.obj"
"$silk" gen cylinder --segments 16 -o "$meshdir/cylinder-64.obj"
"$silk" gen knot -o "$meshdir/knot-1024.obj"
"$silk" gen sphere --uv --segments 16 --bands 12 -o "$meshdir/globe-352.obj"
"$silk" gen torus --uv -o "$meshdir/torus-uv-576.obj"
# vertex colours from the position: x, y, z in [-1, 1] to red, green, blue
awk '/^v /{ printf "v %s %s %s %.4f %.4f %.4f\n", $2, $3, $4, ($2 + 1) / 2, ($3 + 1) / 2, ($4 + 1) / 2; next } { print }' \
    "$meshdir/sphere-200.obj" >"$meshdir/painted-200.obj"

# show NAME MESH [options...]
show() {
    name=$1; mesh=$2; shift 2
    echo "demo.sh: $name"
    "$silk" render "$mesh" -o "$outdir/$name-modes.png" --size "$size" --modes $modes --sheet "$@"
    "$silk" render "$mesh" -o "$outdir/$name-wire.png" --size "$size" --modes $modes --sheet --wire "$@"
    "$silk" render "$mesh" -o "$outdir/$name-closeup.png" --size "$size" --modes $modes --sheet --zoom 6 "$@"
    "$silk" render "$mesh" -o "$outdir/$name-aa.png" --size "$size" --modes flat-noaa,smooth-noaa,smooth --sheet \
        --pixels 4 "$@"
    "$silk" render "$mesh" -o "$outdir/$name-compare.png" --size 480x360 --compare "$@"
}

show sphere "$meshdir/sphere-200.obj"
show torus "$meshdir/torus-576.obj"
# the torus from the side: its inner silhouette is concave (paper III-E)
show torus-side "$meshdir/torus-576.obj" --eye 0,0.9,4 --target 0,0,0
show cone "$meshdir/cone-70.obj"
show cylinder "$meshdir/cylinder-64.obj"
show knot "$meshdir/knot-1024.obj"
show sphere-ortho "$meshdir/sphere-200.obj" --ortho auto
show globe "$meshdir/globe-352.obj" --texture checker
show torus-textured "$meshdir/torus-uv-576.obj" --texture checker
show painted "$meshdir/painted-200.obj"

turntable=$meshdir/knot-1024.obj
if [ -d "$shared" ]; then
    if [ -f "$shared/bunny-500.obj" ]; then
        show bunny-500 "$shared/bunny-500.obj"
        turntable=$shared/bunny-500.obj
    fi
    # fandisk's default view is edge-on to its flat sides; this one shows
    # the curved faces and the sharp feature curves between them
    [ -f "$shared/fandisk-128.obj" ] && show fandisk-128 "$shared/fandisk-128.obj" --eye 10,20,-8
else
    echo "demo.sh: $shared not found; showing only the generated meshes"
fi
echo "demo.sh: turntable"
"$silk" render "$turntable" -o "$outdir/turntable.png" --size 240x180 --turntable 8 --sheet --mode smooth

echo "demo.sh: wrote $(ls "$outdir"/*-modes.png "$outdir"/*-wire.png "$outdir"/*-closeup.png \
    "$outdir"/*-compare.png "$outdir"/*-aa.png "$outdir"/turntable.png | wc -l) images to $outdir/:"
ls "$outdir"/*-modes.png "$outdir"/*-closeup.png "$outdir"/*-aa.png "$outdir"/turntable.png | sed 's/^/  /'
