#!/bin/sh
# seeds.sh SILK MKSEED OUT - the seed corpora of the fuzz harnesses, written
# into OUT/fuzz_obj, OUT/fuzz_ply, OUT/fuzz_stl, OUT/fuzz_render,
# OUT/fuzz_pack, OUT/fuzz_math, OUT/fuzz_ppm, OUT/fuzz_model, OUT/fuzz_siltex and
# OUT/fuzz_compact from:
#   - the malformed-input corpus tests/bad/ (each file one error path),
#   - the regression inputs tests/regress/HARNESS/ (every finding so far),
#   - small meshes from `silk gen` (every shape, few triangles) and a few
#     of the smallest shared meshes, as OBJ, as PLY in all three
#     encodings (mkseed) and as ascii and binary STL
#     (tests/stl_from_obj.awk), and a handful of hand-written hard cases,
#   - for fuzz_render and fuzz_pack, those meshes behind a scene header or
#     edit list (the formats are described at the top of each harness),
#   - for fuzz_math, each of its six cases with fixed operand bytes,
#   - for fuzz_compact, the shapes as compact models (`silk pack -o X.slkc`,
#     with and without --flat) and the malformed ones of tests/bad/.
# Run from the repository root (make fuzz does).
set -eu
silk=$1
mkseed=$2
out=$3
meshes=${SILK_MESHES:-../shared/meshes}

rm -rf "$out"
mkdir -p "$out/fuzz_obj" "$out/fuzz_ply" "$out/fuzz_stl" "$out/fuzz_render" "$out/fuzz_pack" "$out/fuzz_math" \
    "$out/fuzz_ppm" "$out/fuzz_model" "$out/fuzz_siltex" "$out/fuzz_compact" "$out/shapes"

# small generated shapes
"$silk" gen sphere --segments 6 --bands 5 -o "$out/shapes/sphere.obj" >/dev/null
"$silk" gen torus --segments 8 --bands 6 -o "$out/shapes/torus.obj" >/dev/null
"$silk" gen cone --segments 8 -o "$out/shapes/cone.obj" >/dev/null
"$silk" gen cylinder --segments 8 -o "$out/shapes/cylinder.obj" >/dev/null
"$silk" gen knot --segments 24 --bands 4 -o "$out/shapes/knot.obj" >/dev/null
for m in cone-70 fandisk-128 sphere-200; do
    [ -f "$meshes/$m.obj" ] && cp "$meshes/$m.obj" "$out/shapes/$m.obj"
done
# hard cases: one triangle, an open strip, a non-manifold fin, smoothing
# groups with uvs and normals, a zero-area triangle, a duplicate, a quad
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$out/shapes/one.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.2\nv 2 0 0\nf 1 2 3\nf 2 4 3\nf 2 5 4\n' >"$out/shapes/strip.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n' >"$out/shapes/fin.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 1 1 1\ns 1\nf 1/1/1 3/3/1 2/2/1\ns 2\nf 1/1/2 2/2/2 4/3/2\ns off\nf 1//1 4//1 3//1\nf -3/-1/-1 -2/-2/-2 -1/-3/-1\n' >"$out/shapes/groups.obj"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\nf 1 2 4\nf 1 1 4\n' >"$out/shapes/degenerate.obj"
# surface colour: a textured globe (vt), vertex colours, a material line
"$silk" gen sphere --uv --segments 6 --bands 5 -o "$out/shapes/globe.obj" >/dev/null
printf 'mtllib a.mtl\nusemtl m\nv 0 0 0 1 0 0.5\nv 1 0 0 0 1 0\nv 0 1 0 0.2 0.4 0.6 1\nv 0 0 1\nf 1 2 3\nf 1 3 4\n' >"$out/shapes/colours.obj"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float texture_u\nproperty float texture_v\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 0 0 255 0 128 255\n1 0 0 1 0 0 255 0 9\n0 1 0 0 1 1 2 3 0\n3 0 1 2\n' >"$out/fuzz_ply/colours-uv.ply"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n' >"$out/shapes/pyramid.obj"

cp tests/bad/*.obj "$out/fuzz_obj/"
cp tests/bad/*.ply "$out/fuzz_ply/"
cp "$out/shapes/"*.obj "$out/fuzz_obj/"
cp tests/bad/*.stl "$out/fuzz_stl/"
for f in "$out/shapes/"*.obj; do
    b=$(basename "$f" .obj)
    awk -v fmt=ascii -f tests/stl_from_obj.awk "$f" >"$out/fuzz_stl/$b-ascii.stl"
    printf "$(awk -v fmt=binary -f tests/stl_from_obj.awk "$f")" >"$out/fuzz_stl/$b-binary.stl"
done
for f in "$out/shapes/"*.obj; do
    b=$(basename "$f" .obj)
    for enc in ascii le be; do
        "$mkseed" "ply-$enc" "$f" "$out/fuzz_ply/$b-$enc.ply"
    done
done
# fuzz_ppm: a small render as PPM, besides its regression inputs
"$silk" render "$out/shapes/sphere.obj" -o "$out/fuzz_ppm/sphere.ppm" --size 8x6 >/dev/null
for h in obj ply stl render pack math ppm model siltex compact; do
    if [ -d "tests/regress/$h" ]; then
        for f in tests/regress/"$h"/*; do
            [ -f "$f" ] && [ "${f%.expected}" = "$f" ] && cp "$f" "$out/fuzz_$h/"
        done
    fi
done

# fuzz_render: 32-byte scene headers (see fuzz/fuzz_render.c) in front of meshes
# place (relative to the model, s = 4), eye 0,0.5,1 units away, target the
# centre, up +y, fov 40, znear 0.1, zfar 19, tolerance 0.5 px, ortho half
# height 2, level 3, beta 0.25, all the memory, bands of 4 rows, crease 60
camera=09""000000200040""000000000000""004000""000a""14101f160240ff033c0000
i=0
for flags in 411f17 0c1f17 221f17 831f17 152010 010101; do
    for f in "$out/shapes/"*.obj "$out/fuzz_ply/sphere-le.ply"; do
        i=$((i + 1))
        # every header gets two shapes; the mode cycles over all of them
        [ $((i % 3)) -eq 0 ] || continue
        "$mkseed" prefix "$flags$camera" "$f" "$out/fuzz_render/scene-$i"
    done
done
# the same scene with 4 KB of frame memory, and seen from inside the model
"$mkseed" prefix "411f17${camera%??????????}04033c0000" "$out/shapes/torus.obj" "$out/fuzz_render/small-arena"
"$mkseed" prefix 411f17010000000000e0000000000020004000000a14101f160240ff033c0000 \
    "$out/shapes/sphere.obj" "$out/fuzz_render/eye-inside"

# fuzz_pack: no edits or one edit, then the view byte, then a mesh
for f in "$out/shapes/"*.obj; do
    b=$(basename "$f" .obj)
    "$mkseed" prefix 0001 "$f" "$out/fuzz_pack/$b"
    "$mkseed" prefix 01040500070000"09" "$f" "$out/fuzz_pack/$b-edit"
done
# fuzz_math: a selector byte, then operand bytes (any bytes will do)
for sel in 0 1 2 3 4 5; do
    { printf "\\00$sel"; head -c 400 tests/bad/binary-garbage.obj; } >"$out/fuzz_math/case-$sel"
    { printf "\\00$sel"; tail -c 400 "$out/fuzz_ply/knot-le.ply"; } >"$out/fuzz_math/case-$sel-mesh"
done
printf '\001-1024.00002e0 3E+2 .5e-3 18446744073709551616' >"$out/fuzz_math/text"
# fuzz_model: the closed shapes prepared (silk prepare), and tests/bad/*.silk
for b in sphere torus cylinder knot; do
    "$silk" prepare "$out/shapes/$b.obj" -o "$out/fuzz_model/$b.silk" --triangles 64 >/dev/null
done
cp tests/bad/*.silk "$out/fuzz_model/"
# fuzz_siltex: its regression inputs (an analytic sphere's texture) and the malformed textures
cp tests/bad/model-stex-*.silk "$out/fuzz_siltex/"
# fuzz_compact: every shape the compact model holds, with its corner table and
# flat (the cone's apex has too many normals: pack says so and is skipped),
# and the malformed models
for f in "$out/shapes/"*.obj; do
    b=$(basename "$f" .obj)
    "$silk" pack "$f" -o "$out/fuzz_compact/$b.slkc" >/dev/null 2>&1 || rm -f "$out/fuzz_compact/$b.slkc"
    "$silk" pack "$f" -o "$out/fuzz_compact/$b-flat.slkc" --flat >/dev/null 2>&1 || rm -f "$out/fuzz_compact/$b-flat.slkc"
done
cp tests/bad/*.slkc "$out/fuzz_compact/"
rm -rf "$out/shapes"
