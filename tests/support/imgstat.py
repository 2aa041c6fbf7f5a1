#!/usr/bin/env python3
"""imgstat.py - pixel statistics of a silk render, for the shell tests.

    imgstat.py IMAGE [--bg RRGGBB] [--region all|left|right|top|bottom]

reads an 8-bit PNG (RGB or RGBA, decoded here with zlib alone) or a binary
PPM and prints key=value pairs about the object pixels (those whose colour
is not the background, or whose alpha is not 0 in an RGBA PNG) inside the
region: object, mean_r, mean_g, mean_b, mean_luma, max_luma, bright (pixels
with luma >= 230), and for RGBA alpha0, alpha255, alpha_other.

    imgstat.py --alpha-matches RGBA.png OPAQUE.ppm BG

prints "match" when the alpha channel of RGBA.png is 255 exactly where the
opaque render of the same view differs from BG and 0 elsewhere, else the
number of pixels that disagree.

    imgstat.py --composes RGBA.png OPAQUE BG

lays RGBA.png over the colour BG (each channel a C + (255 - a) BG over 255,
rounded) and compares it with OPAQUE, the same view rendered on BG: prints
pixels=N off1=K off10=J worst=L, the pixels more than 1 level of 255
apart in some channel, those more than 10% (25 levels) apart, and the
largest difference.
"""
import struct
import sys
import zlib


def read_png(data):
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            if depth != 8 or ctype not in (2, 6):
                raise SystemExit("imgstat: only 8-bit RGB or RGBA PNG")
            ch = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride = zlib.decompress(idat), w * ch
    out, prev = bytearray(), bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - ch] if x >= ch else 0
            b, c = prev[x], prev[x - ch] if x >= ch else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        prev = line
    return w, h, ch, out


def read_ppm(data):
    fields, pos = [], 2
    while len(fields) < 3:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(int(data[start:pos]))
    w, h, _ = fields
    return w, h, 3, data[pos + 1:pos + 1 + w * h * 3]


def read(path):
    data = open(path, "rb").read()
    return read_png(data) if data[:4] == b"\x89PNG" else read_ppm(data)


def pixels(path):
    w, h, ch, px = read(path)
    for y in range(h):
        for x in range(w):
            i = (y * w + x) * ch
            yield x, y, w, h, tuple(px[i:i + 3]), (px[i + 3] if ch == 4 else None)


def main(argv):
    if argv[0] == "--alpha-matches":
        bg = tuple(bytes.fromhex(argv[3]))
        bad = sum(1 for (_, _, _, _, _, a), (_, _, _, _, c, _) in zip(pixels(argv[1]), pixels(argv[2]))
                  if a != (255 if c != bg else 0))
        print("match" if bad == 0 else "%d pixels disagree" % bad)
        return
    if argv[0] == "--composes":
        bg = tuple(bytes.fromhex(argv[3]))
        n, off1, off10, worst = 0, 0, 0, 0
        for (_, _, _, _, c, a), (_, _, _, _, o, _) in zip(pixels(argv[1]), pixels(argv[2])):
            a = 255 if a is None else a
            d = max(abs((a * c[k] + (255 - a) * bg[k] + 127) // 255 - o[k]) for k in range(3))
            n, off1, off10, worst = n + 1, off1 + (d > 1), off10 + (d > 25), max(worst, d)
        print("pixels=%d off1=%d off10=%d worst=%d" % (n, off1, off10, worst))
        return
    path, bg, region = argv[0], (255, 255, 255), "all"
    for k in range(1, len(argv), 2):
        if argv[k] == "--bg": bg = tuple(bytes.fromhex(argv[k + 1]))
        elif argv[k] == "--region": region = argv[k + 1]
    n, s, lmax, bright, alpha = 0, [0, 0, 0, 0], 0, 0, [0, 0, 0]
    for x, y, w, h, c, a in pixels(path):
        if a is not None:
            alpha[0 if a == 0 else 1 if a == 255 else 2] += 1
        inside = {"all": True, "left": x < w // 2, "right": x >= w // 2, "top": y < h // 2,
                  "bottom": y >= h // 2}[region]
        if not inside or (a == 0 if a is not None else c == bg):
            continue
        luma = (299 * c[0] + 587 * c[1] + 114 * c[2]) / 1000
        n += 1
        for k in range(3):
            s[k] += c[k]
        s[3] += luma
        lmax, bright = max(lmax, luma), bright + (luma >= 230)
    m = [v / n if n else 0 for v in s]
    print("object=%d mean_r=%.1f mean_g=%.1f mean_b=%.1f mean_luma=%.1f max_luma=%.0f bright=%d"
          % (n, m[0], m[1], m[2], m[3], lmax, bright), end="")
    if alpha != [0, 0, 0]:
        print(" alpha0=%d alpha255=%d alpha_other=%d" % tuple(alpha), end="")
    print()


main(sys.argv[1:])
