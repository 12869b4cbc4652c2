#!/usr/bin/python3
"""Independent reader for sweep_commands_test: decodes a GIF with Pillow (python3-pil) and prints
{"format": "GIF", "frames": N, "width": W, "height": H, "loop": L, "durations_ms": [...],
"last_frame_levels": [grey levels of the last frame as shown]} as JSON. Usage: gif_frames.py FILE.gif"""
import json
import sys

from PIL import Image


def main():
    image = Image.open(sys.argv[1])
    durations = []
    frames = getattr(image, "n_frames", 1)
    for index in range(frames):
        image.seek(index)
        durations.append(image.info.get("duration"))
    last = image.convert("L")
    json.dump({"format": image.format, "frames": frames, "width": image.width, "height": image.height,
               "loop": image.info.get("loop"), "durations_ms": durations,
               "last_frame_levels": sorted(set(last.getdata()))}, sys.stdout)


if __name__ == "__main__":
    main()
