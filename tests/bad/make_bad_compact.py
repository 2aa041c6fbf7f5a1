#!/usr/bin/env python3
"""make_bad_compact.py - writes the malformed compact models in tests/bad/
(compact-*.slkc and their .expected lines) from a small valid one with
every array (extra normals, selectors, a corner table, LIST records):

    silk gen cylinder --segments 8 -o c.obj
    silk pack c.obj -o c.slkc
    python3 tests/bad/make_bad_compact.py c.slkc [SILK]

Each case changes one thing and makes the CRC right again (all but the
checksum case), so that each file reaches the check it is about.  The
.expected line of each is what `SILK info FILE` prints on stderr (SILK is
build/silk by default): generated from the reader itself, so read them
after running this to see that each names its problem.  The layout is
include/silk/compact.h's.
"""
import os
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
HEADER = 56


def bits_for(x):
    return x.bit_length()


class Model:
    """The header's fields and the byte offset of every array."""

    def __init__(self, b):
        self.b = bytearray(b)
        (self.nverts, self.ntris, self.nnormals, self.nedges, self.nlisted) = struct.unpack_from("<5I", b, 8)
        self.flags = struct.unpack_from("<H", b, 6)[0]
        self.org = list(struct.unpack_from("<3i", b, 28))
        (self.pos_bits, self.pos_shift, self.nrm_bits, self.sel_bits, self.vtx_bits, self.tri_bits,
         self.edge_bits, self.dir_bits) = b[40:48]
        self.list_bits = self.edge_bits + 3 + 2 * (1 + 2 * self.dir_bits)
        sizes = [
            ("pos", 3 * self.nverts, self.pos_bits),
            ("nrm", 2 * self.nnormals, self.nrm_bits),
            ("extra", self.nnormals - self.nverts, self.vtx_bits),
            ("xpre", (self.nverts + 7) // 8 if self.nnormals > self.nverts else 0,
             (self.nnormals - self.nverts).bit_length()),
            ("corner", 3 * self.ntris, self.vtx_bits),
            ("sel", 3 * self.ntris, self.sel_bits),
        ]
        if self.flags & 1:
            sizes += [
                ("opp", 3 * self.ntris, self.tri_bits),
                ("list", self.nlisted, self.list_bits),
                ("vfirst", (self.nverts + 7) // 8, self.tri_bits),
            ]
        self.off = {}
        at = HEADER
        for name, n, w in sizes:
            self.off[name] = at
            at += (n * w + 7) // 8
        assert at + 4 == len(b), "not a compact model of this layout"

    def get(self, arr, i, w):
        """Value i of width w of array arr."""
        return self.get_bits(arr, i * w, w)

    def get_bits(self, arr, bit, w):
        v = 0
        for j in range(w):
            p = self.off[arr] * 8 + bit + j
            v |= ((self.b[p >> 3] >> (p & 7)) & 1) << j
        return v

    def put(self, arr, i, w, v):
        self.put_bits(arr, i * w, w, v)

    def put_bits(self, arr, bit, w, v):
        for j in range(w):
            p = self.off[arr] * 8 + bit + j
            if (v >> j) & 1:
                self.b[p >> 3] |= 1 << (p & 7)
            else:
                self.b[p >> 3] &= ~(1 << (p & 7)) & 0xFF

    def corner(self, c):
        return self.get("corner", c, self.vtx_bits)

    def opp(self, t, k):
        return self.get("opp", 3 * t + k, self.tri_bits)

    def extra_count(self, v):
        return sum(1 for i in range(self.nnormals - self.nverts) if self.get("extra", i, self.vtx_bits) == v)


def fix(b):
    """The CRC of bytes 56.. made right."""
    b = bytearray(b)
    struct.pack_into("<I", b, 52, zlib.crc32(bytes(b[HEADER:])) & 0xFFFFFFFF)
    return bytes(b)


def cases(base):
    m = Model(base)
    assert m.flags & 1 and m.nnormals > m.nverts and m.nlisted >= 2 and m.nverts > 8, \
        "the base model needs adjacency, extra normals, 2 LIST records and 9 vertices"
    out = []

    out.append(("compact-truncated.slkc", base[:40], False))

    b = bytearray(base)
    b[0:4] = b"SLKX"
    out.append(("compact-magic.slkc", b, True))

    b = bytearray(base)
    struct.pack_into("<H", b, 4, 2)
    out.append(("compact-version.slkc", b, True))

    b = bytearray(base)
    b[m.off["corner"]] ^= 0x10
    out.append(("compact-checksum.slkc", b, False))

    b = bytearray(base)
    struct.pack_into("<I", b, 8, m.nverts + 1)
    out.append(("compact-counts.slkc", b, True))

    # a corner of the last triangle (every vertex is used by then) beyond the vertices
    x = Model(base)
    x.put("corner", 3 * (x.ntris - 1), x.vtx_bits, x.nverts)
    assert x.nverts < (1 << x.vtx_bits)
    out.append(("compact-vertex-index.slkc", x.b, True))

    # side (0, 0) points at a triangle that is not across it
    x = Model(base)
    across = [x.opp(0, k) for k in range(3)]
    other = next(t for t in range(1, x.ntris) if t not in across)
    x.put("opp", 0, x.tri_bits, other)
    out.append(("compact-opp.slkc", x.b, True))

    # a selector one past its vertex's normals (that still fits sel_bits)
    x = Model(base)
    for c in range(3 * x.ntris):
        n = 1 + x.extra_count(x.corner(c))
        if n < (1 << x.sel_bits):
            x.put("sel", c, x.sel_bits, n)
            break
    else:
        raise SystemExit("no corner whose vertex has fewer normals than its selector can name")
    out.append(("compact-selector.slkc", x.b, True))

    # LIST's first two records' edges swapped
    x = Model(base)
    e0 = x.get_bits("list", 0, x.edge_bits)
    e1 = x.get_bits("list", x.list_bits, x.edge_bits)
    x.put_bits("list", 0, x.edge_bits, e1)
    x.put_bits("list", x.list_bits, x.edge_bits, e0)
    out.append(("compact-list-order.slkc", x.b, True))

    # VFIRST of vertex 8 one triangle late
    x = Model(base)
    x.put("vfirst", 1, x.tri_bits, x.get("vfirst", 1, x.tri_bits) + 1)
    out.append(("compact-vfirst.slkc", x.b, True))

    # a LIST record naming a side whose edge the triangle across owns
    x = Model(base)
    none = (1 << x.tri_bits) - 1
    ids = [x.get_bits("list", i * x.list_bits, x.edge_bits) for i in range(x.nlisted)]
    for i in range(x.nlisted):
        lo = ids[i - 1] if i else -1
        hi = ids[i + 1] if i + 1 < x.nlisted else 3 * x.ntris
        h = next((h for h in range(lo + 1, hi) if x.get("opp", h, x.tri_bits) not in (none,)
                  and x.get("opp", h, x.tri_bits) < h // 3), None)
        if h is not None:
            x.put_bits("list", i * x.list_bits, x.edge_bits, h)
            break
    out.append(("compact-list-side.slkc", x.b, True))

    b = bytearray(base)
    b[40] = 0
    out.append(("compact-pos-bits.slkc", b, True))

    # the box moved up to x = 1022: the largest code would decode past 1024
    b = bytearray(base)
    struct.pack_into("<i", b, 28, 1022 << 16)
    out.append(("compact-coordinate-range.slkc", b, True))

    return out


def main():
    base = open(sys.argv[1], "rb").read()
    silk = sys.argv[2] if len(sys.argv) > 2 else "build/silk"
    written = cases(base)
    for name, data, crc in written:
        path = os.path.join(HERE, name)
        with open(path, "wb") as f:
            f.write(fix(data) if crc else bytes(data))
        rel = os.path.join("tests/bad", name)
        r = subprocess.run([silk, "info", rel], capture_output=True, text=True)
        if r.returncode == 0 or r.stdout:
            raise SystemExit("%s: silk info accepted it or printed on stdout" % rel)
        with open(path + ".expected", "w") as f:
            f.write(r.stderr)
        print("%s: %s" % (name, r.stderr.strip()), file=sys.stderr)
    print("%d cases written to %s" % (len(written), HERE), file=sys.stderr)


if __name__ == "__main__":
    main()
