"""tiled_tiff.py WIDTH HEIGHT OUT: a small tiled TIFF (RGB, 8 bits, deflate) that declares WIDTH x
HEIGHT pixels in tiles of 1024 x 1024 whose offsets all point at the same single tile of zeros:
a few kilobytes that decode to gigabytes (issue 41: 27 KB declaring 32768 x 32768 took 6.9 GB).
Used by tests/cli/render_texture_limits.sh; made fuzz/corpus/image_header/tiff_tiled_20000x20000."""
import struct
import sys
import zlib

width, height, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
TILE = 1024
tiles = ((width + TILE - 1) // TILE) * ((height + TILE - 1) // TILE)
tile = zlib.compress(bytes(TILE * TILE * 3), 9)
SHORT, LONG = 3, 4
entries = 11
ifd = 8
bits = ifd + 2 + 12 * entries + 4           # BitsPerSample's three values
offsets = bits + 6                           # TileOffsets
counts = offsets + 4 * tiles                 # TileByteCounts
data = counts + 4 * tiles                    # the one tile
tags = [(256, LONG, 1, width), (257, LONG, 1, height), (258, SHORT, 3, bits), (259, SHORT, 1, 8),
        (262, SHORT, 1, 2), (277, SHORT, 1, 3), (284, SHORT, 1, 1), (322, LONG, 1, TILE), (323, LONG, 1, TILE),
        (324, LONG, tiles, offsets if tiles > 1 else data), (325, LONG, tiles, counts if tiles > 1 else len(tile))]
body = b"II" + struct.pack("<HI", 42, ifd) + struct.pack("<H", entries)
for tag, kind, count, value in tags:
    body += struct.pack("<HHII", tag, kind, count, value) if kind == LONG or count > 1 else \
        struct.pack("<HHIHH", tag, kind, count, value, 0)
body += struct.pack("<I", 0) + struct.pack("<3H", 8, 8, 8)
body += struct.pack("<%dI" % tiles, *([data] * tiles)) + struct.pack("<%dI" % tiles, *([len(tile)] * tiles)) + tile
open(out, "wb").write(body)
