#!/usr/bin/python3
"""Independent writer for animated_png_reader_test: writes an animated PNG from JSON, in one of two ways.
Usage: apng_writer.py IN.json OUT.png

"mode": "L" or "P": Pillow (python3-pil) writes the frames {"width", "height", "blend": B, "duration_ms": T,
"frames": [[row-major grey values], ...]} as a grey (L) or grey-palette (P) APNG, choosing its own filters and
frame rectangles.
"mode": "chunks": the chunks are written here, byte by byte after the APNG specification, for what Pillow 9.4
cannot write: {"width", "height", "bit_depth", "palette": [grey levels], "transparent": index or null,
"frames": [{"x", "y", "w", "h", "dispose", "blend", "filter", "indices": [row-major palette indices]}]}."""
import json
import struct
import sys
import zlib

from PIL import Image

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def filtered_rows(rows, kind):
    """Each packed row with PNG filter `kind` applied (one byte per pixel step: depths up to 8)."""
    out, previous = b"", bytes(len(rows[0]))
    for row in rows:
        line = bytearray([kind])
        for i, value in enumerate(row):
            a = row[i - 1] if i > 0 else 0
            b = previous[i]
            c = previous[i - 1] if i > 0 else 0
            predictor = [0, a, b, (a + b) // 2, paeth(a, b, c)][kind]
            line.append((value - predictor) % 256)
        out += bytes(line)
        previous = row
    return out


def packed(indices, width, height, depth):
    rows = []
    for y in range(height):
        bits, row = 0, bytearray()
        value = 0
        for x in range(width):
            value = (value << depth) | indices[y * width + x]
            bits += depth
            if bits == 8:
                row.append(value)
                bits, value = 0, 0
        if bits:
            row.append(value << (8 - bits))
        rows.append(bytes(row))
    return rows


def write_chunks(spec, path):
    depth = spec["bit_depth"]
    data = SIGNATURE + chunk(b"IHDR", struct.pack(">IIBBBBB", spec["width"], spec["height"], depth, 3, 0, 0, 0))
    frames = spec["frames"]
    data += chunk(b"acTL", struct.pack(">II", len(frames), 0))
    data += chunk(b"PLTE", b"".join(bytes([level] * 3) for level in spec["palette"]))
    if spec.get("transparent") is not None:
        alpha = [255] * len(spec["palette"])
        alpha[spec["transparent"]] = 0
        data += chunk(b"tRNS", bytes(alpha))
    sequence = 0
    for number, frame in enumerate(frames):
        data += chunk(b"fcTL", struct.pack(">IIIIIHHBB", sequence, frame["w"], frame["h"], frame["x"], frame["y"],
                                           10, 100, frame["dispose"], frame["blend"]))
        sequence += 1
        pixels = zlib.compress(filtered_rows(packed(frame["indices"], frame["w"], frame["h"], depth),
                                             frame["filter"]))
        if number == 0:
            data += chunk(b"IDAT", pixels)
        else:
            data += chunk(b"fdAT", struct.pack(">I", sequence) + pixels)
            sequence += 1
    data += chunk(b"IEND", b"")
    with open(path, "wb") as handle:
        handle.write(data)


def write_with_pillow(spec, path):
    frames = []
    levels = sorted({value for frame in spec["frames"] for value in frame})
    for pixels in spec["frames"]:
        image = Image.new("L", (spec["width"], spec["height"]))
        image.putdata(pixels)
        if spec["mode"] == "P":
            # A grey palette of the levels in use, padded to 256 entries (Pillow 9.4 writes animated palette
            # images at 8 bits only).
            palette = [channel for level in levels for channel in (level, level, level)]
            index = {level: i for i, level in enumerate(levels)}
            image = Image.new("P", (spec["width"], spec["height"]))
            image.putpalette(palette + [0] * (768 - len(palette)))
            image.putdata([index[value] for value in pixels])
        frames.append(image)
    frames[0].save(path, format="PNG", save_all=True, append_images=frames[1:], loop=0,
                   duration=spec["duration_ms"], disposal=0, blend=spec["blend"], default_image=False)


def main():
    with open(sys.argv[1]) as handle:
        spec = json.load(handle)
    if spec["mode"] == "chunks":
        write_chunks(spec, sys.argv[2])
    else:
        write_with_pillow(spec, sys.argv[2])


if __name__ == "__main__":
    main()
