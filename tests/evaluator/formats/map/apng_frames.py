#!/usr/bin/python3
"""Independent reader for compact_png_test: decodes an (animated) PNG with Pillow and composes its frames as a
browser does (APNG: dispose and blend operations of each fcTL), printing {"frames": N, "loop": L,
"durations_ms": [...], "pixels": [[row-major grey values], ...]} as JSON. Usage: apng_frames.py FILE.png

Pillow decodes every frame's pixels, each frame's data wrapped as a PNG of its own with the file's palette and
transparency; the composition is done here because Debian 12's Pillow (9.4) drops a palette frame's
transparency when it blends it over the frame before."""
import io
import json
import struct
import sys
import zlib

from PIL import Image

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunks(data):
    position = len(SIGNATURE)
    while position < len(data):
        (length,) = struct.unpack(">I", data[position:position + 4])
        yield data[position + 4:position + 8], data[position + 8:position + 8 + length]
        position += 12 + length


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def frame_image(header, shared, width, height, data):
    """One frame's pixels as RGBA, decoded by Pillow from a PNG of the frame alone."""
    ihdr = struct.pack(">II", width, height) + header[8:]
    png = SIGNATURE + chunk(b"IHDR", ihdr) + b"".join(chunk(k, b) for k, b in shared) + chunk(b"IDAT", data) + \
        chunk(b"IEND", b"")
    return Image.open(io.BytesIO(png)).convert("RGBA")


def compose(data):
    """The frames as a browser shows them (grey images), or the one image of a PNG without acTL."""
    parts = list(chunks(data))
    header = next(body for kind, body in parts if kind == b"IHDR")
    if not any(kind == b"acTL" for kind, _ in parts):
        return [Image.open(io.BytesIO(data)).convert("L")]
    width, height = struct.unpack(">II", header[:8])
    shared = [(kind, body) for kind, body in parts if kind in (b"PLTE", b"tRNS")]
    canvas = Image.new("RGBA", (width, height), (0, 0, 0, 0))
    frames, control, pieces = [], None, []

    def finish():
        nonlocal canvas
        _, w, h, x, y, _, _, dispose, blend = control
        before = canvas.copy()
        piece = frame_image(header, shared, w, h, b"".join(pieces))
        if blend == 0:
            canvas.paste(piece, (x, y))
        else:
            canvas.alpha_composite(piece, (x, y))
        frames.append(canvas.convert("L"))
        if dispose == 1:
            canvas.paste((0, 0, 0, 0), (x, y, x + w, y + h))
        elif dispose == 2:
            canvas = before

    for kind, body in parts:
        if kind == b"fcTL":
            if control is not None and pieces:
                finish()
            control, pieces = struct.unpack(">IIIIIHHBB", body), []
        elif kind == b"IDAT" and control is not None:
            pieces.append(body)
        elif kind == b"fdAT":
            pieces.append(body[4:])
    if control is not None and pieces:
        finish()
    return frames


def main():
    with open(sys.argv[1], "rb") as handle:
        data = handle.read()
    image = Image.open(io.BytesIO(data))
    durations = []
    for index in range(getattr(image, "n_frames", 1)):
        image.seek(index)
        durations.append(image.info.get("duration"))
    frames = compose(data)
    json.dump({"frames": len(frames), "loop": image.info.get("loop"), "durations_ms": durations,
               "width": image.width, "height": image.height, "pixels": [list(f.getdata()) for f in frames]},
              sys.stdout)


if __name__ == "__main__":
    main()
