#!/usr/bin/env python3
"""Writes graphs/lagoon_ripples.png, the user texture of the lagoon example graph.

A 256x256 RGBA8 PNG that tiles: RGB is a tangent-space normal map (x right, y down the
texture, z out of it; rgb = n * 0.5 + 0.5) of a height field summed from sine waves whose
wave vectors are whole numbers of cycles per tile, so every edge meets the opposite one;
A is a foam mask from a second, finer sum of such waves. Linear data, not colour: the graph
samples it with color_space linear. Only the standard library; the output is the same
bytes on every run (the test suite checks the file in the repository against it).

    scripts/make_lagoon_texture.py [out.png]     (default graphs/lagoon_ripples.png)
"""
import math
import struct
import sys
import zlib

SIZE = 256
# (cycles along x, cycles along y, amplitude, phase): a few long swells and short ripples.
RIPPLES = [(1, 2, 0.50, 0.3), (3, -1, 0.30, 1.7), (-2, 5, 0.18, 4.1), (7, 3, 0.10, 2.2), (-9, 8, 0.06, 0.9),
           (13, -11, 0.035, 5.3)]
FOAM = [(4, 6, 1.0, 0.0), (-7, 5, 0.8, 2.0), (11, -9, 0.6, 4.0), (17, 13, 0.4, 1.0), (-23, 19, 0.3, 3.0)]
SLOPE_SCALE = 0.35  # how steep the normals are: tangent-space xy of n before normalising


def wave_sum(waves, x, y):
    """The height and its gradient (per texel) at texel centre (x, y)."""
    h = dx = dy = 0.0
    for kx, ky, a, phase in waves:
        w = 2.0 * math.pi / SIZE
        arg = w * (kx * x + ky * y) + phase
        h += a * math.sin(arg)
        dx += a * w * kx * math.cos(arg)
        dy += a * w * ky * math.cos(arg)
    return h, dx, dy


def byte(v):
    return max(0, min(255, int(round(v * 255.0))))


def pixels():
    amplitude = sum(a for _, _, a, _ in FOAM)
    rows = []
    for y in range(SIZE):
        row = bytearray([0])  # PNG filter type 0 (none) for each scanline
        for x in range(SIZE):
            _, hx, hy = wave_sum(RIPPLES, x + 0.5, y + 0.5)
            nx, ny, nz = -hx * SIZE * SLOPE_SCALE / 8.0, -hy * SIZE * SLOPE_SCALE / 8.0, 1.0
            length = math.sqrt(nx * nx + ny * ny + nz * nz)
            f, _, _ = wave_sum(FOAM, x + 0.5, y + 0.5)
            foam = min(1.0, max(0.0, (f / amplitude - 0.25) / 0.5))
            row += bytes([byte(nx / length * 0.5 + 0.5), byte(ny / length * 0.5 + 0.5), byte(nz / length * 0.5 + 0.5),
                          byte(foam)])
        rows.append(bytes(row))
    return b"".join(rows)


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "graphs/lagoon_ripples.png"
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0)  # 8-bit RGBA, no interlace
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(pixels(), 9)) + chunk(b"IEND", b"")
    with open(out, "wb") as f:
        f.write(png)
    print("wrote " + out)


if __name__ == "__main__":
    main()
