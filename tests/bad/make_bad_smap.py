#!/usr/bin/env python3
"""make_bad_smap.py - writes the malformed silhouette-map cases in tests/bad/
(model-smap-*.silk and their .expected lines, as make_bad.py does for the
other formats) from a small valid prepared model with a map:

    silk gen sphere --segments 6 --bands 5 -o s.obj
    silk prepare s.obj -o s.silk --triangles 24 --map-views 12 --map-resolution 32
    python3 tests/bad/make_bad_smap.py s.silk

Each case changes the SMAP section and makes its checksums right again, so
the reader's checks of the map's contents are what fails.
"""
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def sections(b):
    n = struct.unpack_from("<I", b, 20)[0]
    out = []
    for i in range(n):
        e = 32 + 20 * i
        t, flags, off, size, crc = struct.unpack_from("<4sIIII", b, e)
        out.append((i, t, off, size))
    return out


def fix(b):
    n = struct.unpack_from("<I", b, 20)[0]
    for i, t, off, size in sections(b):
        struct.pack_into("<I", b, 32 + 20 * i + 16, zlib.crc32(bytes(b[off:off + size])) & 0xFFFFFFFF)
    struct.pack_into("<I", b, 24, zlib.crc32(bytes(b[32:32 + 20 * n])) & 0xFFFFFFFF)
    return bytes(b)


def write_cases(cases):
    """Each (name, bytes, message) with its checksums made right, and its .expected line."""
    for name, data, message in cases:
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(fix(data))
        with open(os.path.join(HERE, name + ".expected"), "w") as f:
            f.write("silk: tests/bad/%s: %s\n" % (name, message))
    print("%d cases written to %s" % (len(cases), HERE), file=sys.stderr)


def smap(b):
    for i, t, off, size in sections(b):
        if t == b"SMAP":
            return off, size
    raise SystemExit("no SMAP section in the base model")


def main():
    base = bytearray(open(sys.argv[1], "rb").read())
    off, size = smap(base)
    nviews, ntris, nloops, npts = struct.unpack_from("<IIII", base, off + 4)
    views = off + 36
    tri = views + 72 * nviews
    start = tri + 24 * ntris  # loop starts (after triangles and neighbours)
    cases = []

    b = bytearray(base)
    struct.pack_into("<I", b, off, 2)
    cases.append(("model-smap-version.silk", b, "SMAP section: map version 2; this silk reads version 1"))

    b = bytearray(base)
    struct.pack_into("<I", b, tri, 99)
    cases.append(("model-smap-view-index.silk", b, "SMAP section: triangle 0 uses view 99 of %d" % nviews))

    b = bytearray(base)
    struct.pack_into("<I", b, off + 16, npts + 1)
    want = 36 + 72 * nviews + 24 * ntris + 4 * (nloops + 1) + 8 * (npts + 1)
    cases.append(("model-smap-size.silk", b, "SMAP section: %d views, %d triangles, %d loops and %d points take %d "
                  "bytes, the section has %d" % (nviews, ntris, nloops, npts + 1, want, size)))

    b = bytearray(base)
    struct.pack_into("<i", b, views + 48, 0)
    cases.append(("model-smap-focal.silk", b, "SMAP section: view 0's focal length or image centre is out of range"))

    b = bytearray(base)
    struct.pack_into("<I", b, start + 4, 1)
    cases.append(("model-smap-loop.silk", b, "SMAP section: loop 0 has fewer than 3 points"))

    write_cases(cases)


if __name__ == "__main__":
    main()
