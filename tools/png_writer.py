# SPDX-License-Identifier: MIT
# An 8-bit PNG writer in the Python standard library (zlib), for the tools/ scripts that
# make test and example pictures.
import os
import struct
import zlib


def png(path, width, height, channels, pixel):
    """Writes an 8-bit PNG at `path` whose pixel (x, y) from the top left is pixel(x, y):
    a tuple of channels (1 grey, 3 RGB) in [0, 1]."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            for c in pixel(x, y)[:channels]:
                rows.append(max(0, min(255, round(255 * c))))
    colour = {1: 0, 3: 2}[channels]

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0))
    data += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data)
