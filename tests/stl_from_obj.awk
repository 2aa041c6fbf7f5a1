# stl_from_obj.awk - an OBJ's triangles (v and f lines) as STL, for the
# tests: `-v fmt=ascii` copies each coordinate's text, `-v fmt=binary`
# prints the binary file (80-byte header starting with "solid", count,
# 50-byte records of IEEE-754 binary32) as printf(1) octal escapes:
#   printf "$(awk -v fmt=binary -f tests/stl_from_obj.awk m.obj)" >m.stl
# Only what `silk gen` writes: "f a b c" with plain indices.

# x as the bits of the nearest binary32 (round half to even; no subnormals).
function f32(x,    s, e, r, m) {
    if (x == 0) return 0
    s = 0
    if (x < 0) { s = 1; x = -x }
    e = 0
    while (x >= 2) { x /= 2; e++ }
    while (x < 1) { x *= 2; e-- }
    r = x * 8388608; m = int(r)
    if (r - m > 0.5 || (r - m == 0.5 && m % 2 == 1)) m++
    if (m == 16777216) { m = 8388608; e++ }
    return s * 2147483648 + (e + 127) * 8388608 + (m - 8388608)
}
function bytes(v, n,    i) {
    for (i = 0; i < n; i++) { printf "\\%03o", v % 256; v = int(v / 256) }
}
/^v / { nv++; X[nv] = $2; Y[nv] = $3; Z[nv] = $4 }
/^f / { nf++; A[nf] = $2; B[nf] = $3; C[nf] = $4 }
END {
    if (fmt == "ascii") {
        print "solid from_obj"
        for (t = 1; t <= nf; t++) {
            print " facet normal 0 0 0"; print "  outer loop"
            print "   vertex " X[A[t]] " " Y[A[t]] " " Z[A[t]]
            print "   vertex " X[B[t]] " " Y[B[t]] " " Z[B[t]]
            print "   vertex " X[C[t]] " " Y[C[t]] " " Z[C[t]]
            print "  endloop"; print " endfacet"
        }
        print "endsolid from_obj"
        exit
    }
    h = "solid from_obj (binary)"
    for (i = 1; i <= 80; i++) printf "%s", (i <= length(h) ? substr(h, i, 1) : " ")
    bytes(nf, 4)
    for (t = 1; t <= nf; t++) {
        bytes(0, 12)
        bytes(f32(X[A[t]]), 4); bytes(f32(Y[A[t]]), 4); bytes(f32(Z[A[t]]), 4)
        bytes(f32(X[B[t]]), 4); bytes(f32(Y[B[t]]), 4); bytes(f32(Z[B[t]]), 4)
        bytes(f32(X[C[t]]), 4); bytes(f32(Y[C[t]]), 4); bytes(f32(Z[C[t]]), 4)
        bytes(0, 2)
    }
}
