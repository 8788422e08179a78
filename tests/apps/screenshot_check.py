"""Checks a screenshot of the campaign page: a PNG decoded with the standard library only.

Usage: screenshot_check.py FILE.png
Passes (exit 0) when the page is not blank: at least 5% of its pixels are not background white, the
table header colour (#e8eef6) covers a region of at least 2000 pixels (the results table rendered
with its style), and the saturated colours of the inlined figures (plot lines, heat maps) cover at
least 2000 pixels (the images were decoded, not broken-image icons).
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, width, height, colour_type = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour_type = struct.unpack(">IIBB", chunk[:10])
            if depth != 8 or colour_type not in (2, 6):
                raise SystemExit(f"{path}: expected 8-bit RGB or RGBA, got depth {depth} type {colour_type}")
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    channels = 4 if colour_type == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


def main():
    width, height, channels, rows = read_png(sys.argv[1])
    total = width * height
    not_white = header = saturated = 0
    for line in rows:
        for x in range(0, len(line), channels):
            r, g, b = line[x], line[x + 1], line[x + 2]
            if r < 245 or g < 245 or b < 245:
                not_white += 1
            if abs(r - 0xE8) <= 3 and abs(g - 0xEE) <= 3 and abs(b - 0xF6) <= 3:
                header += 1
            if max(r, g, b) - min(r, g, b) > 100:
                saturated += 1
    print(f"{width}x{height}: {not_white / total:.1%} not white, {header} header pixels, {saturated} saturated")
    failures = []
    if not_white < 0.05 * total:
        failures.append("the page is (nearly) blank")
    if header < 2000:
        failures.append("no styled table header")
    if saturated < 2000:
        failures.append("no coloured figure pixels")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
