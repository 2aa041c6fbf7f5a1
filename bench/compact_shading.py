#!/usr/bin/env python3
"""compact_shading.py - shading differences between two renders (bench/compact.sh).

    compact_shading.py A.ppm B.ppm     two lines, "all d0 d1 ... d255" and
                                       "inner d0 ...": the histogram of the
                                       largest channel difference over the
                                       pixels both draw, and over those of
                                       them whose 8 neighbours both draw too
                                       (not on either outline)
    compact_shading.py --sum all|inner FILE
                                       those lines of FILE added up: prints
                                       max,p99,within2 (within2: the share
                                       of pixels at most 2 levels apart)
    compact_shading.py --outline A.ppm B.ppm
                                       the Hausdorff distance (pixels) between
                                       the outlines of the two objects, where
                                       a pinhole (at most 16 pixels of
                                       background, away from the border)
                                       counts as the object's

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
    w, h = wa, ha
    both = [pa[3 * i:3 * i + 3] != b"\xff\xff\xff" and pb[3 * i:3 * i + 3] != b"\xff\xff\xff" for i in range(w * h)]
    hist, inner = [0] * 256, [0] * 256
    for i in range(w * h):
        if not both[i]:
            continue
        x, y = pa[3 * i:3 * i + 3], pb[3 * i:3 * i + 3]
        d = max(abs(x[0] - y[0]), abs(x[1] - y[1]), abs(x[2] - y[2]))
        hist[d] += 1
        cx, cy = i % w, i // w
        if 0 < cx < w - 1 and 0 < cy < h - 1 and all(both[i + dy * w + dx] for dy in (-1, 0, 1) for dx in (-1, 0, 1)):
            inner[d] += 1
    print("all " + " ".join(str(v) for v in hist))
    print("inner " + " ".join(str(v) for v in inner))


def outer_mask(path):
    """Object pixels, with every pinhole filled in: a piece of background
    of at most PINHOLE pixels (4-connected) that does not touch the border."""
    w, h, p = read_ppm(path)
    bg = [p[3 * i:3 * i + 3] == b"\xff\xff\xff" for i in range(w * h)]
    seen = bytearray(w * h)
    obj = [not v for v in bg]
    for s0 in range(w * h):
        if not bg[s0] or seen[s0]:
            continue
        seen[s0] = 1
        comp, stack, border = [s0], [s0], False
        while stack:
            i = stack.pop()
            x, y = i % w, i // w
            if x == 0 or y == 0 or x == w - 1 or y == h - 1:
                border = True
            for j in (i - w if y > 0 else -1, i + w if y < h - 1 else -1, i - 1 if x > 0 else -1, i + 1 if x < w - 1 else -1):
                if j >= 0 and bg[j] and not seen[j]:
                    seen[j] = 1
                    stack.append(j)
                    if len(comp) <= PINHOLE:
                        comp.append(j)
        if not border and len(comp) <= PINHOLE:
            for i in comp:
                obj[i] = True
    return w, h, obj


PINHOLE = 16


def boundary(w, h, m):
    s = set()
    for y in range(h):
        for x in range(w):
            i = y * w + x
            if m[i] and (x == 0 or y == 0 or x == w - 1 or y == h - 1 or not (m[i - 1] and m[i + 1] and m[i - w] and m[i + w])):
                s.add((x, y))
    return s


def outline(a, b):
    w, h, ma = outer_mask(a)
    w2, h2, mb = outer_mask(b)
    if (w, h) != (w2, h2):
        raise SystemExit("%s, %s: sizes differ" % (a, b))
    ba, bb = boundary(w, h, ma), boundary(w, h, mb)
    if not ba or not bb:
        print("inf" if ba or bb else "0")
        return
    worst = 0.0
    for s1, s2 in ((ba, bb), (bb, ba)):
        for (x, y) in s1 - s2:
            best, r = None, 1
            while best is None and r < 64:
                for v in range(y - r, y + r + 1):
                    for u in range(x - r, x + r + 1):
                        if (u, v) in s2:
                            d = ((u - x) ** 2 + (v - y) ** 2) ** 0.5
                            best = d if best is None or d < best else best
                r *= 2
            worst = max(worst, best if best is not None else 64.0)
    print("%.3f" % worst)


def summary(path, which):
    hist = [0] * 256
    with open(path) as f:
        for line in f:
            parts = line.split()
            if parts and parts[0] == which:
                for i, v in enumerate(parts[1:]):
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
    if len(sys.argv) == 4 and sys.argv[1] == "--sum":
        summary(sys.argv[3], sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "--outline":
        outline(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3:
        compare(sys.argv[1], sys.argv[2])
    else:
        raise SystemExit(__doc__)
