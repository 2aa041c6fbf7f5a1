#!/bin/sh
# tools/scripts/zoom.sh [SILK] [OUTDIR] - zoomed silhouettes (docs/methods.md,
# "Zoomed silhouettes"): each coarse mesh rendered 8x magnified on a point
# of its outline in smooth, PN level 3 and 8, and flat mode, and compared
# with a fine reference rendered flat with the same camera by `silk diff`.
#
#   sphere    `silk gen sphere` (200 triangles, every vertex on the unit
#             sphere) against `silk gen sphere --segments 720 --bands 360`
#             (516 960 triangles: 0.06 px from the sphere at this zoom)
#   shared    MESH-500 (or -200) against MESH-fine from ../shared/meshes
#
# The camera: the default view of the reference at 400x400 (silk info),
# aimed at the reference's vertex farthest right on screen (a point of its
# outline) with the field of view 8 times narrower.  Prints one line per
# render and writes OUTDIR/zoom.png: per mesh a row of the reference, then
# the difference pictures of smooth, PN 3 and flat (grey both, red only the
# reference, blue only the method), at half size.
# Needs python3 (for the camera and the picture; the standard library only).
set -e
silk=${1:-build/silk}
out=${2:-out/zoom}
meshes=${SILK_MESHES:-../shared/meshes}
size=400
zoom=8
mkdir -p "$out"

"$silk" gen sphere -o "$out/sphere-200.obj"
"$silk" gen sphere --segments 720 --bands 360 -o "$out/sphere-exact.obj"

# camera FINE: "--eye .. --target .. --fov .." for the reference FINE
camera() {
    info=$("$silk" info "$1" --size ${size}x$size)
    eye=$(echo "$info" | sed -n 's/^ *eye: *//p')
    target=$(echo "$info" | sed -n 's/^ *target: *//p')
    fov=$(echo "$info" | sed -n 's/^ *projection: *perspective, fov *//p')
    python3 - "$1" "$eye" "$target" "$fov" "$zoom" <<'EOF'
import math, sys
path, eye, target, fov, zoom = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
E = [float(x) for x in eye.split()]
T = [float(x) for x in target.split()]
def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def unit(a): l = math.sqrt(dot(a, a)); return [x / l for x in a]
f = unit(sub(T, E))
r = unit([f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0])  # f x up
best, aim = -1e30, None
for line in open(path):
    if line.startswith('v '):
        p = [float(x) for x in line.split()[1:4]]
        d = sub(p, E)
        x = dot(d, r) / dot(d, f)
        if x > best: best, aim = x, p
nfov = 2 * math.degrees(math.atan(math.tan(math.radians(fov / 2)) / zoom))
print("--eye %s --target %s --fov %.4f" % (",".join(eye.split()), ",".join("%.6f" % c for c in aim), nfov))
EOF
}

# compare NAME COARSE FINE
compare() {
    cam=$(camera "$3")
    echo "$1: $cam"
    # shellcheck disable=SC2086
    "$silk" render "$3" --mode flat --size ${size}x$size $cam -o "$out/$1-ref.png"
    for m in smooth pn3 pn8 flat; do
        case $m in
            pn*) mode="--mode pn --level ${m#pn}" ;;
            *) mode="--mode $m" ;;
        esac
        # shellcheck disable=SC2086
        "$silk" render "$2" $mode --size ${size}x$size $cam -o "$out/$1-$m.png"
        line=$("$silk" diff "$out/$1-ref.png" "$out/$1-$m.png" --bg ffffff -o "$out/$1-$m-diff.png")
        echo "  $1 $m: ${line#* * * }"
    done
}

compare sphere "$out/sphere-200.obj" "$out/sphere-exact.obj"
for m in bunny spot venus; do
    [ -f "$meshes/$m-500.obj" ] && compare "$m" "$meshes/$m-500.obj" "$meshes/$m-fine.obj"
done
[ -f "$meshes/sphere-200.obj" ] && compare shared-sphere "$meshes/sphere-200.obj" "$meshes/sphere-fine.obj"

# The picture: rows sphere and bunny; columns reference, smooth, PN 3, flat.
python3 - "$out" "$size" <<'EOF'
import struct, sys, zlib
out, size = sys.argv[1], int(sys.argv[2])
def read(path):
    d = open(path, 'rb').read()
    i, idat = 8, b''
    while i < len(d):
        n, = struct.unpack('>I', d[i:i + 4]); t = d[i + 4:i + 8]; c = d[i + 8:i + 8 + n]; i += 12 + n
        if t == b'IHDR': w, h, depth, ctype = struct.unpack('>IIBB', c[:10])
        elif t == b'IDAT': idat += c
    assert depth == 8 and ctype in (2, 6)
    bpp = 3 if ctype == 2 else 4
    raw, st, rows, prev, p = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for y in range(h):
        ft, line = raw[p], bytearray(raw[p + 1:p + 1 + st]); p += 1 + st
        for x in range(st):
            a = line[x - bpp] if x >= bpp else 0; b = prev[x]; c = prev[x - bpp] if x >= bpp else 0
            if ft == 1: line[x] = (line[x] + a) & 255
            elif ft == 2: line[x] = (line[x] + b) & 255
            elif ft == 3: line[x] = (line[x] + ((a + b) >> 1)) & 255
            elif ft == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[i] for i in range(st) if i % bpp < 3)); prev = line
    return rows
half, gap = size // 2, 4
names = [['sphere-ref', 'sphere-smooth-diff', 'sphere-pn3-diff', 'sphere-flat-diff'],
         ['bunny-ref', 'bunny-smooth-diff', 'bunny-pn3-diff', 'bunny-flat-diff']]
W = 4 * half + 3 * gap
lines = []
for r, row in enumerate(names):
    imgs = [read('%s/%s.png' % (out, n)) for n in row]
    if r: lines += [b'\xff' * 3 * W] * gap
    for y in range(0, size, 2):
        line = b''
        for k, im in enumerate(imgs):
            if k: line += b'\xff' * 3 * gap
            line += b''.join(im[y][3 * x:3 * x + 3] for x in range(0, size, 2))
        lines.append(line)
def chunk(t, c): return struct.pack('>I', len(c)) + t + c + struct.pack('>I', zlib.crc32(t + c) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, len(lines), 8, 2, 0, 0, 0)) + \
      chunk(b'IDAT', zlib.compress(b''.join(b'\0' + l for l in lines), 9)) + chunk(b'IEND', b'')
open('%s/zoom.png' % out, 'wb').write(png)
print('wrote %s/zoom.png (%d bytes)' % (out, len(png)))
EOF
