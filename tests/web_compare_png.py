#!/usr/bin/env python3
"""Compares two screenshots (PNG) pixel by pixel, for tests/web_checks.sh: the web page's in Chromium
against the native sandbox's of the same scene and size. Python's standard library only (zlib):
8-bit RGB or RGBA, non-interlaced PNGs, as Chromium and polyroll-sandbox write them.

Usage: web_compare_png.py A.png B.png MAX_SHARE
A may be larger than B: its top-left corner of B's size is compared (a browser's screenshot is of
its whole window, the page's canvas at the top left).
A pixel differs when any colour channel differs by more than CHANNEL_TOLERANCE (antialiasing and
the two GL rasterisers, SwiftShader and llvmpipe, differ by a few levels on edges). Exits 0 when the
share of differing pixels is at most MAX_SHARE, 1 otherwise, 2 for unreadable input; prints the share.
"""
import struct
import sys
import zlib

CHANNEL_TOLERANCE = 48  # of 255


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, width, height, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            channels = {2: 3, 6: 4}.get(colour, 0)
            if depth != 8 or channels == 0 or interlace != 0:
                raise ValueError(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs are read")
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    try:
        wa, ha, ca, ra = read_png(sys.argv[1])
        wb, hb, cb, rb = read_png(sys.argv[2])
        max_share = float(sys.argv[3])
    except (OSError, ValueError, zlib.error) as e:
        print(f"web_compare_png: {e}")
        return 2
    if wa < wb or ha < hb:
        print(f"web_compare_png: {sys.argv[1]} ({wa}x{ha}) is smaller than {sys.argv[2]} ({wb}x{hb})")
        return 1
    ra = ra[:hb]
    differing = 0
    for la, lb in zip(ra, rb):
        for x in range(wb):
            pa, pb = la[x * ca:x * ca + 3], lb[x * cb:x * cb + 3]
            if max(abs(pa[0] - pb[0]), abs(pa[1] - pb[1]), abs(pa[2] - pb[2])) > CHANNEL_TOLERANCE:
                differing += 1
    share = differing / (wb * hb)
    verdict = "within" if share <= max_share else "ABOVE"
    print(f"web_compare_png: {differing} of {wb * hb} pixels differ ({100 * share:.2f} %), {verdict} the "
          f"tolerance of {100 * max_share:.2f} %")
    return 0 if share <= max_share else 1


if __name__ == "__main__":
    sys.exit(main())


def write_png(path, width, height, channels, rows):
    """Writes rows (as read_png returns them) as an 8-bit RGB or RGBA PNG, filter 0."""
    raw = b"".join(b"\x00" + bytes(r[:width * channels]) for r in rows[:height])

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    colour = {3: 2, 4: 6}[channels]
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
