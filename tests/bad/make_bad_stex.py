#!/usr/bin/env python3
"""make_bad_stex.py - writes the malformed silhouette-texture cases in
tests/bad/ (model-stex-*.silk and their .expected lines, as make_bad_smap.py
does for the map) from a small valid prepared model with a texture:

    build/tests/test_siltex --write s.silk tiny
    python3 tests/bad/make_bad_stex.py s.silk

Each case changes the STEX section and makes its checksums right again, so
the reader's checks of the texture's contents are what fails.
"""
import struct
import sys

from make_bad_smap import sections, write_cases


def main():
    base = bytearray(open(sys.argv[1], "rb").read())
    found = [(off, size) for i, t, off, size in sections(base) if t == b"STEX"]
    if not found:
        raise SystemExit("no STEX section in the base model")
    off, size = found[0]
    w, h, k, e, nverts, ntris = struct.unpack_from("<HHHHII", base, off + 8)
    frame = off + 32
    uv = frame + 12 * nverts
    cases = []

    def case(name, edit, message):
        b = bytearray(base)
        edit(b)
        cases.append((name, b, "STEX section: " + message))

    case("model-stex-version.silk", lambda b: struct.pack_into("<I", b, off, 2),
         "texture version 2; this silk reads version 1")
    case("model-stex-flags.silk", lambda b: struct.pack_into("<I", b, off + 4, 8), "unknown flags 0x8")
    case("model-stex-atlas.silk", lambda b: struct.pack_into("<H", b, off + 8, 5000),
         "atlas of 5000x%d texels (8..4096 on a side)" % h)
    case("model-stex-azimuths.silk", lambda b: struct.pack_into("<H", b, off + 12, 3), "3 azimuth samples (4..64)")
    case("model-stex-eigen.silk", lambda b: struct.pack_into("<H", b, off + 14, 2),
         "2 eigenfunctions in uncompressed angles (%d azimuths; 0 expected)" % k)
    case("model-stex-hull.silk", lambda b: struct.pack_into("<I", b, off + 20, ntris + 1),
         "%d vertices and %d triangles, the HULL section has %d and %d" % (nverts, ntris + 1, nverts, ntris))
    want = 32 + 12 * nverts + 12 * ntris + w * h * (k + 1) + 2 * w * h
    case("model-stex-size.silk", lambda b: struct.pack_into("<H", b, off + 12, k + 1),
         "a %dx%d atlas with %d azimuths takes %d bytes, the section has %d" % (w, h, k + 1, (want + 3) & ~3, size))
    case("model-stex-centre.silk", lambda b: struct.pack_into("<hhh", b, frame, 8000, 0, 0),
         "vertex 0's centre direction C is not of unit length")
    case("model-stex-tangent.silk",
         lambda b: struct.pack_into("<hhh", b, frame + 6, *struct.unpack_from("<hhh", b, frame)),
         "vertex 0's tangent T is not across C (|T.C| above 1/16)")
    case("model-stex-uv.silk", lambda b: struct.pack_into("<H", b, uv + 4 * 4, 16 * w + 1),
         "triangle 1 corner 1's atlas point (%d/16, %d/16) lies outside the %dx%d atlas"
         % (16 * w + 1, struct.unpack_from("<H", base, uv + 4 * 4 + 2)[0], w, h))

    write_cases(cases)


if __name__ == "__main__":
    main()
