#!/usr/bin/env python3
"""Writes the PNG files of this folder from source.ppm, byte by byte.

An encoder of our own, independent of libpng (which rt uses to read and write PNG): only the
Python standard library's zlib (deflate and CRC-32) and struct. It follows the PNG specification
(ISO/IEC 15948, W3C PNG 2nd edition) directly: chunks, the five row filters, Adam7 interlacing,
sub-byte grey depths, palettes, 16-bit samples. The test tests/image/foreign_png_test.cpp reads
every file with rt's reader and compares it with source.ppm, as README.md describes.

Run from this folder:  python3 make_pngs.py
"""

import struct
import zlib

# Adam7 passes: (first column, first row, column step, row step).
ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2),
         (0, 1, 1, 2)]


def read_p3(path):
    words = []
    with open(path) as f:
        for line in f:
            words += line.split('#', 1)[0].split()
    assert words[0] == 'P3' and words[3] == '255'
    width, height = int(words[1]), int(words[2])
    values = [int(w) for w in words[4:]]
    assert len(values) == width * height * 3
    pixels = [[tuple(values[(y * width + x) * 3:(y * width + x) * 3 + 3]) for x in range(width)]
              for y in range(height)]
    return width, height, pixels


def chunk(kind, data):
    body = kind + data
    return struct.pack('>I', len(data)) + body + struct.pack('>I', zlib.crc32(body) & 0xffffffff)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def filter_row(kind, row, previous, bpp):
    """One scanline filtered with filter type kind (0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth)."""
    out = bytearray([kind])
    for i, x in enumerate(row):
        a = row[i - bpp] if i >= bpp else 0
        b = previous[i] if previous else 0
        c = previous[i - bpp] if previous and i >= bpp else 0
        predictor = [0, a, b, (a + b) // 2, paeth(a, b, c)][kind]
        out.append((x - predictor) % 256)
    return out


def pack_samples(samples, depth):
    """A row of samples as bytes: 16-bit big-endian, 8-bit, or sub-byte packed from the left."""
    if depth == 16:
        return b''.join(struct.pack('>H', s) for s in samples)
    if depth == 8:
        return bytes(samples)
    out = bytearray()
    per_byte = 8 // depth
    for i in range(0, len(samples), per_byte):
        byte = 0
        for k, s in enumerate(samples[i:i + per_byte]):
            byte |= s << (8 - depth * (k + 1))
        out.append(byte)
    return bytes(out)


def image_data(rows, depth, channels, interlaced):
    """The filtered scanlines; rows are lists of samples. Filter types cycle 0..4 row by row."""
    bpp = max(1, depth * channels // 8)
    height, width = len(rows), len(rows[0]) // channels
    passes = ADAM7 if interlaced else [(0, 0, 1, 1)]
    out = bytearray()
    line = 0
    for x0, y0, dx, dy in passes:
        previous = None
        for y in range(y0, height, dy):
            samples = []
            for x in range(x0, width, dx):
                samples += rows[y][x * channels:(x + 1) * channels]
            if not samples:
                continue
            packed = pack_samples(samples, depth)
            out += filter_row(line % 5, packed, previous, bpp)
            previous = packed
            line += 1
    return bytes(out)


def write_png(path, width, rows, depth, colour_type, channels, interlaced=False, extra=b''):
    header = struct.pack('>IIBBBBB', width, len(rows), depth, colour_type, 0, 0, int(interlaced))
    compressed = zlib.compress(image_data(rows, depth, channels, interlaced), 9)
    # IDAT split in chunks of 64 bytes: a reader must join them.
    idat = b''.join(chunk(b'IDAT', compressed[i:i + 64]) for i in range(0, len(compressed), 64))
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) + extra + idat + chunk(b'IEND', b''))


def transparent(x, y):
    """Where the alpha variants are fully transparent (alpha 0); elsewhere alpha is 255."""
    return (x + 2 * y) % 7 == 0


def main():
    width, height, px = read_p3('source.ppm')
    rgb = [[s for p in row for s in p] for row in px]
    red = [[p[0] for p in row] for row in px]
    write_png('rgb8.png', width, rgb, 8, 2, 3)
    write_png('rgb8_adam7.png', width, rgb, 8, 2, 3, interlaced=True)
    write_png('rgb16.png', width, [[s * 257 for s in row] for row in rgb], 16, 2, 3)
    rgba = [[s for x, p in enumerate(row) for s in p + (0 if transparent(x, y) else 255,)]
            for y, row in enumerate(px)]
    write_png('rgba8.png', width, rgba, 8, 6, 4)
    write_png('grey8.png', width, red, 8, 0, 1)
    grey_alpha = [[s for x, r in enumerate(row) for s in (r, 0 if transparent(x, y) else 255)]
                  for y, row in enumerate(red)]
    write_png('grey_alpha8_adam7.png', width, grey_alpha, 8, 4, 2, interlaced=True)
    write_png('grey4.png', width, [[r >> 4 for r in row] for row in red], 4, 0, 1)
    write_png('grey1.png', width, [[r >> 7 for r in row] for row in red], 1, 0, 1)
    palette = sorted({p for row in px for p in row})
    index = {p: i for i, p in enumerate(palette)}
    plte = chunk(b'PLTE', b''.join(bytes(p) for p in palette))
    write_png('palette8.png', width, [[index[p] for p in row] for row in px], 8, 3, 1,
              extra=plte)


if __name__ == '__main__':
    main()
