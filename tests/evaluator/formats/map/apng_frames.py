#!/usr/bin/python3
"""Independent reader for compact_png_test: decodes an (animated) PNG with Pillow, composing APNG frames as a
browser does, and prints {"frames": N, "loop": L, "durations_ms": [...], "pixels": [[row-major grey values],
...]} as JSON. Usage: apng_frames.py FILE.png"""
import json
import sys

from PIL import Image


def main():
    image = Image.open(sys.argv[1])
    frames, durations = [], []
    for index in range(getattr(image, "n_frames", 1)):
        image.seek(index)
        grey = image.convert("L")
        frames.append(list(grey.getdata()))
        durations.append(image.info.get("duration"))
    json.dump({"frames": len(frames), "loop": image.info.get("loop"), "durations_ms": durations,
               "width": image.width, "height": image.height, "pixels": frames}, sys.stdout)


if __name__ == "__main__":
    main()
