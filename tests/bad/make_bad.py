#!/usr/bin/env python3
"""make_bad.py - writes the malformed-input corpus in tests/bad/.

Each case is a file NAME and NAME.expected: the exact line `silk info` and
`silk render` must print on stderr for it ("silk: tests/bad/NAME: ...").
The expected lines are written here by hand, not taken from silk, so the
corpus checks the messages.  Run from anywhere: python3 tests/bad/make_bad.py
(the produced files are committed too; re-run after changing a case).
"""
import os
import re
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = []


def case(name, data, message):
    if isinstance(data, str):
        data = data.encode("latin-1")
    CASES.append((name, data, message))


TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

# ---- OBJ ---------------------------------------------------------------------
case("empty.obj", "", "no triangles")
case("comments-only.obj", "# nothing here\n\n# at all\n", "no triangles")
case("vertices-only.obj", TRI, "no triangles")
case("face-index-zero.obj", TRI + "f 1 2 0\n", "4: face index 0 is invalid (OBJ indices start at 1)")
case("face-index-beyond.obj", TRI + "f 1 2 3\nf 1 3 4\n", "5: face index 4 out of range (3 vertices)")
case("face-index-too-negative.obj", TRI + "f -1 -2 -4\n", "4: face index -4 out of range (3 vertices so far)")
case("face-index-huge.obj", TRI + "f 1 2 184467440737095516160\n",
     "4: face index 184467440737095516160 out of range (3 vertices)")
case("face-two-vertices.obj", TRI + "f 1 2\n", "4: face has 2 vertices (at least 3 needed)")
case("face-bad-token.obj", TRI + "f 1 2 x\n", "4: bad face vertex 'x'")
case("face-too-many-slashes.obj", TRI + "f 1/1/1/1 2 3\n", "4: bad face vertex '1/1/1/1'")
case("face-texture-beyond.obj", TRI + "vt 0 0\nf 1/1 2/2 3/1\n", "5: texture index 2 out of range (1 texture coordinates)")
case("face-normal-beyond.obj", TRI + "vn 0 0 1\nf 1//1 2//1 3//3\n", "5: normal index 3 out of range (1 normals)")
case("vertex-non-numeric.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", "2: bad number 'zero'")
case("vertex-comma.obj", "v 0 0 0\nv 1,5 0 0\nv 0 1 0\nf 1 2 3\n", "2: bad number '1,5'")
case("vertex-two-coordinates.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "2: vertex needs 3 numbers, found 2")
case("vertex-too-many-values.obj", "v 0 0 0 1 1 1 1 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "1: too many values for vertex")
case("vertex-nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "2: 'nan' is not a finite number")
case("vertex-inf.obj", "v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n", "2: '-inf' is not a finite number")
case("vertex-huge-exponent.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", "2: number '1e999' is out of range")
case("vertex-number-too-long.obj", "v 0 0 0\nv 1." + "0" * 200 + " 0 0\nv 0 1 0\nf 1 2 3\n",
     "2: number '1.000000000000000000000000000000...' is too long")
case("texture-out-of-range.obj", TRI + "vt 0.5 40000\nf 1/1 2/1 3/1\n", "4: texture coordinate 40000.0 is out of range")
case("bad-smoothing-group.obj", "s one\n" + TRI + "f 1 2 3\n", "1: bad smoothing group 'one'")
case("big.obj", "# a model in millimetres\nv 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\n"
                "v 5000.0 0 0\nv 0 1200 0\nf 1 6 7\n",
     "7: coordinate 5000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.1")
case("huge.obj", "v 0 0 0\nv 25000000 0 0\nv 0 1 0\nf 1 2 3\n",
     "2: coordinate 25000000.0 is outside the fixed-point range (+-1024); scale the model with --scale 1e-5")
# just past the limit: six digits would print it as the limit itself ("1024.0")
case("coordinate-just-beyond.obj", "v 0 0 0\nv 1024.00002 0 0\nv 0 1 0\nf 1 2 3\n",
     "2: coordinate 1024.00002 is outside the fixed-point range (+-1024); scale the model with --scale 0.1")
case("tiny.obj", "v 0 0 0\nv 0.001 0 0\nv 0 0.0005 0\nf 1 2 3\n",
     "model is too small for fixed-point precision (size 0.00112); scale it up with --scale 100")
case("single-point.obj", "v 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\n", "model has no size (all vertices are at one point)")
case("tiny-far-away.obj", "v 900 0 0\nv 900.00002 0 0\nv 900 0.00002 0\nf 1 2 3\n",
     "model is too small for fixed-point precision (size 2.83e-5) this far from the origin "
     "(coordinates up to 900.00002); move it to the origin")
case("crlf-bad-index.obj", "v 0 0 0\r\nv 1 0 0\r\n\r\nv 0 1 0\r\nf 1 2 7\r\n", "5: face index 7 out of range (3 vertices)")
case("long-line.obj", TRI + "# " + "x" * 70000 + "\nf 1 2 3\n", "4: line too long (more than 65535 bytes)")
case("binary-garbage.obj", bytes((i * 151 + 7) % 256 for i in range(600)),
     "not a mesh file (binary data); silk reads OBJ, PLY and STL")
case("nul-in-text.obj", TRI + "f 1 2 3\0\n", "4: unexpected byte 0x00 (not a text file?)")

# ---- PLY -------------------------------------------------------------------
HEAD_XYZ = "element vertex {nv}\nproperty {t} x\nproperty {t} y\nproperty {t} z\n"
HEAD_FACE = "element face {nf}\nproperty list {ct} {it} vertex_indices\n"
PACK = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
        "float": "f", "double": "d"}
TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_binary(order, verts=TETRA_V, faces=TETRA_F, t="float", ct="uchar", it="int", nv=None, nf=None,
               extra_header=""):
    e = "<" if order == "le" else ">"
    fmt = "binary_little_endian" if order == "le" else "binary_big_endian"
    h = "ply\nformat %s 1.0\n" % fmt + extra_header
    h += HEAD_XYZ.format(nv=len(verts) if nv is None else nv, t=t)
    h += HEAD_FACE.format(nf=len(faces) if nf is None else nf, ct=ct, it=it) + "end_header\n"
    body = b"".join(struct.pack(e + PACK[t] * 3, *v) for v in verts)
    for f in faces:
        body += struct.pack(e + PACK[ct], len(f)) + struct.pack(e + PACK[it] * len(f), *f)
    return h.encode() + body


def ply_ascii(verts=TETRA_V, faces=TETRA_F, header_edit=None, nv=None, nf=None):
    h = "ply\nformat ascii 1.0\n" + HEAD_XYZ.format(nv=len(verts) if nv is None else nv, t="float")
    h += HEAD_FACE.format(nf=len(faces) if nf is None else nf, ct="uchar", it="int") + "end_header\n"
    if header_edit:
        h = h.replace(*header_edit)
    body = "".join(" ".join(str(c) for c in v) + "\n" for v in verts)
    body += "".join(str(len(f)) + " " + " ".join(str(i) for i in f) + "\n" for f in faces)
    return h + body


case("ply-header-only.ply", "ply\n", "header has no end_header line")
case("ply-no-end-header.ply", ply_ascii().replace("end_header\n", ""), "header has no end_header line")
case("ply-header-cut.ply", "ply\nformat binary_little_endian 1.0\nelement vert", "header has no end_header line")
case("ply-binary-header-no-end.ply", ply_binary("le").replace(b"end_header\n", b""),
     "9: unexpected byte 0x00 in the header (no end_header?)")
case("ply-unknown-format.ply", ply_ascii(header_edit=("ascii", "utf8")), "2: unknown PLY format 'utf8'")
case("ply-bad-version.ply", ply_ascii(header_edit=("1.0", "1.1")), "2: unsupported PLY version '1.1'")
case("ply-unknown-type.ply", ply_ascii(header_edit=("float y", "int64 y")), "5: unknown property type 'int64'")
case("ply-unknown-header-line.ply", ply_ascii(header_edit=("element face", "elements face")),
     "7: unknown header line 'elements'")
case("ply-property-before-element.ply", ply_ascii(header_edit=("element vertex 4\n", "property float w\nelement vertex 4\n")),
     "3: property before any element")
case("ply-missing-z.ply", ply_ascii(header_edit=("property float z\n", "property float w\n")),
     "3: element 'vertex' has no property 'z'")
case("ply-list-coordinate.ply", ply_ascii(header_edit=("property float x", "property list uchar float x")),
     "4: property 'x' must not be a list")
case("ply-float-indices.ply", ply_ascii(header_edit=("uchar int vertex_indices", "uchar float vertex_indices")),
     "8: 'vertex_indices' must have an integer type")
case("ply-no-face-element.ply", ply_ascii(header_edit=("element face 4\nproperty list uchar int vertex_indices\n", "")),
     "no triangles (no face element)")
case("ply-no-faces.ply", ply_ascii(faces=[]), "no triangles")
case("ply-no-vertex-element.ply",
     "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n",
     "no vertex element")
case("ply-garbage-header.ply", b"ply\nformat ascii 1.0\n\x89PNG\r\n\x1a\n", "4: unexpected byte 0x1a in the header (no end_header?)")
case("ply-bad-element-count.ply", ply_ascii(header_edit=("vertex 4", "vertex 4x")), "3: bad element count '4x'")
case("ply-ascii-bad-number.ply", ply_ascii().replace("\n1 0 0\n", "\n1 O 0\n"), "11: bad number 'O'")
case("ply-ascii-nan.ply", ply_ascii().replace("\n1 0 0\n", "\n1 NaN 0\n"), "11: 'NaN' is not a finite number")
case("ply-ascii-too-few.ply", ply_ascii().replace("\n1 0 0\n", "\n1 0\n"), "11: too few values for element 'vertex'")
case("ply-ascii-too-many.ply", ply_ascii().replace("\n3 0 1 3\n", "\n3 0 1 3 3\n"), "15: too many values for element 'face'")
case("ply-ascii-ends-early.ply", ply_ascii(nf=5), "file ends after 4 of 5 'face' elements")
case("ply-ascii-negative-index.ply", ply_ascii(faces=[(0, 2, 1), (0, -1, 3)]), "15: vertex index -1 out of range (4 vertices)")
case("ply-ascii-bad-count.ply", ply_ascii().replace("\n3 0 1 3\n", "\nthree 0 1 3\n"), "15: bad integer 'three'")
case("ply-ascii-short-face.ply", ply_ascii(faces=[(0, 2, 1), (0, 1)]), "15: face has 2 vertices (at least 3 needed)")
case("ply-truncated-vertices-le.ply", ply_binary("le")[:-(4 * 13) - 20],
     "file is truncated: the header declares 4 'vertex' elements (at least 12 bytes each) but only 28 bytes follow the header")
case("ply-truncated-faces-be.ply", ply_binary("be", ct="ushort", it="uint")[:-7],
     "file is truncated: it ends in 'face' element 3 of 4")
case("ply-billions.ply", ply_binary("le", nv=4000000000),
     "file is truncated: the header declares 4000000000 'vertex' elements (at least 12 bytes each) "
     "but only 100 bytes follow the header")
case("ply-too-many-vertices.ply", ply_ascii(nv=4294967295), "3: too many vertices (4294967295)")
case("ply-index-beyond-le.ply", ply_binary("le", faces=[(0, 2, 1), (0, 1, 4)]),
     "face 1: vertex index 4 out of range (4 vertices)")
case("ply-negative-index-be.ply", ply_binary("be", faces=[(0, 2, 1), (0, 1, -7)], it="short"),
     "face 1: vertex index -7 out of range (4 vertices)")
case("ply-short-face-be.ply", ply_binary("be", faces=[(0, 2, 1), (0, 1)], ct="int"),
     "face 1: face has 2 vertices (at least 3 needed)")
case("ply-negative-count.ply", ply_binary("le", ct="char")[:-13] + struct.pack("<b3i", -3, 1, 2, 3),
     "face 3: negative list length -3")
case("ply-huge-list.ply", ply_binary("le", ct="uint")[:-16] + struct.pack("<I3i", 2000000000, 1, 2, 3),
     "file is truncated: it ends in 'face' element 3 of 4")
case("ply-nan-le.ply", ply_binary("le", verts=[(0, 0, 0), (1, float("nan"), 0), (0, 1, 0), (0, 0, 1)]),
     "vertex 1: value is not a finite number (NaN or infinity)")
case("ply-inf-be.ply", ply_binary("be", t="double", verts=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, float("-inf"))]),
     "vertex 3: value is not a finite number (NaN or infinity)")
case("ply-big-be.ply", ply_binary("be", t="double", verts=[(0, 0, 0), (1500.25, 0, 0), (0, 1, 0), (0, 0, 1)]),
     "vertex 1: coordinate 1500.25 is outside the fixed-point range (+-1024); scale the model with --scale 0.1")
case("ply-big-int.ply", ply_binary("le", t="int", verts=[(0, 0, 0), (100000, 0, 0), (0, 100000, 0), (0, 0, 2000000)]),
     "vertex 1: coordinate 100000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.0001")
case("ply-just-beyond-le.ply", ply_binary("le", verts=[(0, 0, 0), (0, -1024.0001, 0), (0, 1, 0), (0, 0, 1)]),
     "vertex 1: coordinate -1024.0001220703125 is outside the fixed-point range (+-1024); "
     "scale the model with --scale 0.1")
case("ply-tiny.ply", ply_binary("le", verts=[(0, 0, 0), (1e-4, 0, 0), (0, 1e-4, 0), (0, 0, 1e-4)]),
     "model is too small for fixed-point precision (size 0.000173); scale it up with --scale 1000")

# ---- STL ---------------------------------------------------------------------
def facet(*corners):
    return (" facet normal 0 0 1\n  outer loop\n" + "".join("   vertex %s\n" % c for c in corners) +
            "  endloop\n endfacet\n")


F1 = facet("0 0 0", "1 0 0", "0 1 0")
case("stl-ascii-empty.stl", "solid empty\nendsolid empty\n", "no triangles")
case("stl-ascii-two-vertices.stl", "solid s\n" + facet("0 0 0", "1 0 0") + "endsolid s\n",
     "6: facet has 2 vertices (3 needed)")
case("stl-ascii-four-vertices.stl", "solid s\n" + facet("0 0 0", "1 0 0", "0 1 0", "1 1 0") + "endsolid s\n",
     "7: facet has more than 3 vertices (STL facets are triangles)")
case("stl-ascii-bad-number.stl", "solid s\n" + F1 + facet("0 0 0", "1 zero 0", "0 1 0"), "12: bad number 'zero'")
case("stl-ascii-nan.stl", "solid s\n" + facet("nan 0 0", "1 0 0", "0 1 0"), "4: 'nan' is not a finite number")
case("stl-ascii-two-coordinates.stl", "solid s\n" + facet("0 0", "1 0 0", "0 1 0"), "4: vertex needs 3 numbers, found 2")
case("stl-ascii-cut.stl", "solid s\n" + F1 + " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n", "file ends inside facet 2")
case("stl-ascii-no-loop.stl", "solid s\n facet normal 0 0 1\n   vertex 0 0 0\n", "3: unexpected 'vertex' (expected 'outer loop')")
case("stl-ascii-no-endfacet.stl", "solid s\n" + F1.replace(" endfacet\n", "") + F1,
     "8: unexpected 'facet' (expected 'endfacet')")
case("stl-ascii-junk-after.stl", "solid s\n" + F1 + "endsolid s\nv 0 0 0\n", "10: unexpected 'v' (expected 'solid')")
case("stl-ascii-out-of-range.stl", "solid s\n" + facet("0 0 0", "5000 0 0", "0 1 0"),
     "5: coordinate 5000.0 is outside the fixed-point range (+-1024); scale the model with --scale 0.1")
case("stl-ascii-one-point.stl", "solid s\n" + facet("1 1 1", "1 1 1", "1 1 1"),
     "model has no size (all vertices are at one point)")
case("stl-ascii-binary-byte.stl", "solid s\n" + F1 * 6 + facet("0 0 0", "1 0\x01 0", "0 1 0"),
     "47: unexpected byte 0x01 (not a text file?)")


def binary_stl(header, count, records, extra=b""):
    data = header.ljust(80, b" ") + struct.pack("<I", count)
    for r in records:
        data += struct.pack("<12f", 0, 0, 1, *r) + b"\0\0"
    return data + extra


TRI_F = (0, 0, 0, 1, 0, 0, 0, 1, 0)
case("stl-binary-zero.stl", binary_stl(b"made by hand", 0, []), "no triangles")
case("stl-binary-truncated.stl", binary_stl(b"made by hand", 2, [TRI_F]),
     "binary STL is truncated: the header declares 2 triangles (184 bytes), the file has 134 bytes")
case("stl-binary-solid-truncated.stl", binary_stl(b"solid part", 3, [TRI_F, TRI_F]),
     "binary STL is truncated: the header declares 3 triangles (234 bytes), the file has 184 bytes")
case("stl-binary-longer.stl", binary_stl(b"solid part", 1, [TRI_F], b"0123456789"),
     "binary STL is longer than its header says: 1 triangles take 134 bytes, the file has 144")
case("stl-binary-too-short.stl", b"\x00\x01\x02" * 13, "binary STL is too short (39 bytes; the header alone is 84)")
case("stl-binary-nan.stl", binary_stl(b"", 2, [TRI_F, (0, 0, 0, float("nan"), 0, 0, 0, 1, 0)]),
     "triangle 2: coordinate is not a finite number (NaN or infinity)")
case("stl-binary-inf.stl", binary_stl(b"solid", 1, [(0, 0, 0, 1, float("-inf"), 0, 0, 1, 0)]),
     "triangle 1: coordinate is not a finite number (NaN or infinity)")
case("stl-binary-out-of-range.stl", binary_stl(b"solid big", 1, [(0, 0, 0, 2000.5, 0, 0, 0, 1, 0)]),
     "vertex 1: coordinate 2000.5 is outside the fixed-point range (+-1024); scale the model with --scale 0.1")

# ---- formats silk does not read, by their first bytes ------------------------
CONVERT = " is not supported: convert it to OBJ, PLY or STL"
case("model.gltf", '{\n  "asset": { "version": "2.0" },\n  "meshes": []\n}\n', "glTF" + CONVERT)
case("model.glb", b"glTF" + struct.pack("<II", 2, 12), "binary glTF (GLB)" + CONVERT)
case("model.json", '{ "vertices": [0, 0, 0] }\n', "JSON" + CONVERT)
case("model-binary.fbx", b"Kaydara FBX Binary  \x00\x1a\x00" + struct.pack("<I", 7400), "FBX" + CONVERT)
case("model-ascii.fbx", "; FBX 7.4.0 project file\n; ----\n", "FBX" + CONVERT)
case("model.3ds", b"MM" + struct.pack("<I", 16) + b"\x02\x00" + struct.pack("<II", 10, 3), "3DS" + CONVERT)
case("model.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "OFF" + CONVERT)
case("model-color.off", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n", "OFF" + CONVERT)
case("mesh.obj.gz", b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", "the file is gzip-compressed: decompress it first")
case("mesh.zip", b"PK\x03\x04\x14\x00\x00\x00\x08\x00", "the file is a zip archive: extract the mesh from it first")
case("mesh.obj.xz", b"\xfd7zXZ\x00\x00\x04\xe6\xd6\xb4\x46", "the file is xz-compressed: decompress it first")
case("mesh.obj.zst", b"\x28\xb5\x2f\xfd\x04\x58\x00\x00", "the file is zstd-compressed: decompress it first")
case("mesh.obj.bz2", b"BZh91AY&SY", "the file is bzip2-compressed: decompress it first")
case("mesh.7z", b"7z\xbc\xaf\x27\x1c\x00\x04", "the file is a 7z archive: extract the mesh from it first")
case("junk.bin", bytes((i * 37 + 11) % 256 for i in range(300)),
     "not a mesh file (binary data); silk reads OBJ, PLY and STL")


def main():
    for f in os.listdir(HERE):
        if not f.endswith(".py"):
            os.remove(os.path.join(HERE, f))
    for name, data, message in CASES:
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(data)
        sep = "" if re.match(r"[0-9]+:", message) else " "
        line = "silk: tests/bad/%s:%s%s\n" % (name, sep, message)
        with open(os.path.join(HERE, name + ".expected"), "w") as f:
            f.write(line)
    print("%d cases written to %s" % (len(CASES), HERE), file=sys.stderr)


if __name__ == "__main__":
    main()
