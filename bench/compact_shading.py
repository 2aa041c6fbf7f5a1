#!/usr/bin/env python3
"""compact_shading.py - shading differences between two renders (bench/compact.sh).

    compact_shading.py A.ppm B.ppm     one line: pixels d0 d1 d2 ... d255, the
                                       histogram of the largest channel
                                       difference over pixels both draw
    compact_shading.py --sum FILE      the lines of FILE added up: prints
                                       max,p99,within2 (within2: the share
                                       of pixels at most 2 levels apart)

Both images are binary PPMs of the same size with silk render's white
background; a pixel is drawn when it is not white.
"""
import sys


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while data[pos:pos + 1] not in (b"\n", b""):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6" or fields[3] != b"255":
        raise SystemExit("%s: not an 8-bit binary PPM" % path)
    w, h = int(fields[1]), int(fields[2])
    return w, h, data[pos + 1:pos + 1 + 3 * w * h]


def compare(a, b):
    wa, ha, pa = read_ppm(a)
    wb, hb, pb = read_ppm(b)
    if (wa, ha) != (wb, hb):
        raise SystemExit("%s, %s: sizes differ" % (a, b))
    hist = [0] * 256
    for i in range(0, len(pa), 3):
        x, y = pa[i:i + 3], pb[i:i + 3]
        if x == b"\xff\xff\xff" or y == b"\xff\xff\xff":
            continue
        hist[max(abs(x[0] - y[0]), abs(x[1] - y[1]), abs(x[2] - y[2]))] += 1
    print(" ".join(str(v) for v in hist))


def summary(path):
    hist = [0] * 256
    with open(path) as f:
        for line in f:
            for i, v in enumerate(line.split()):
                hist[i] += int(v)
    n = sum(hist)
    if n == 0:
        print("0,0,1")
        return
    worst = max(i for i in range(256) if hist[i])
    acc, p99 = 0, 0
    for i in range(256):
        acc += hist[i]
        if acc >= 0.99 * n:
            p99 = i
            break
    print("%d,%d,%.4f" % (worst, p99, sum(hist[:3]) / n))


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--sum":
        summary(sys.argv[2])
    elif len(sys.argv) == 3:
        compare(sys.argv[1], sys.argv[2])
    else:
        raise SystemExit(__doc__)
