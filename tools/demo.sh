#!/bin/sh
# demo.sh SILK OUTDIR - the demo behind `make demo`.
#
# Generates the analytic meshes with `silk gen` (next to the silk binary, in
# BUILD/meshes/), then renders each one into OUTDIR as
#   NAME-flat.png     the coarse mesh as it is (Phong shaded)
#   NAME-smooth.png   with smoothed silhouettes (paper section III)
#   NAME-compare.png  the two side by side, flat on the left
#   NAME-wire.png     smooth with edges; triangles added by re-meshing in red
# and, when the shared reference meshes are there (../shared/meshes or
# $SILK_MESHES), a few of those too.  Ends by listing what it wrote.
set -eu

silk=${1:-build/silk}
outdir=${2:-out}
size=${DEMO_SIZE:-480x360}
meshdir=$(dirname "$silk")/meshes
shared=${SILK_MESHES:-../shared/meshes}

[ -x "$silk" ] || { echo "demo.sh: $silk not found; run make first" >&2; exit 1; }
mkdir -p "$outdir" "$meshdir"

"$silk" gen sphere -o "$meshdir/sphere-200.obj"
"$silk" gen torus -o "$meshdir/torus-576.obj"
"$silk" gen cone -o "$meshdir/cone-70.obj"
"$silk" gen cylinder --segments 16 -o "$meshdir/cylinder-64.obj"
"$silk" gen knot -o "$meshdir/knot-1024.obj"

# render NAME MESH [options...]
render() {
    name=$1; mesh=$2; shift 2
    "$silk" render "$mesh" -o "$outdir/$name-flat.png" --size "$size" --mode flat "$@"
    "$silk" render "$mesh" -o "$outdir/$name-smooth.png" --size "$size" --mode smooth "$@"
    "$silk" render "$mesh" -o "$outdir/$name-compare.png" --size "$size" --compare "$@"
    "$silk" render "$mesh" -o "$outdir/$name-wire.png" --size "$size" --mode smooth --wire "$@"
}

render sphere "$meshdir/sphere-200.obj"
render torus "$meshdir/torus-576.obj"
# the torus from the side: its inner silhouette is concave (paper III-E)
render torus-side "$meshdir/torus-576.obj" --eye 0,0.9,4 --target 0,0,0
render cone "$meshdir/cone-70.obj"
render cylinder "$meshdir/cylinder-64.obj"
render knot "$meshdir/knot-1024.obj"
render sphere-ortho "$meshdir/sphere-200.obj" --ortho auto

if [ -d "$shared" ]; then
    for m in bunny-500 knot-480; do
        [ -f "$shared/$m.obj" ] && render "$m" "$shared/$m.obj"
    done
    # models whose front is not +z: views chosen by eye
    [ -f "$shared/spot-500.obj" ] && render spot-500 "$shared/spot-500.obj" --eye 3,1.2,1.5
    # fandisk's default view is edge-on to its flat sides; this one shows
    # the curved faces and the sharp feature curves between them
    [ -f "$shared/fandisk-128.obj" ] && render fandisk-128 "$shared/fandisk-128.obj" --eye 10,20,-8
else
    echo "demo.sh: $shared not found; rendering only the generated meshes"
fi

echo "demo.sh: wrote $(ls "$outdir"/*.png | wc -l) images to $outdir/:"
ls "$outdir"/*-compare.png | sed 's/^/  /'
