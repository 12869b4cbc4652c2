#!/usr/bin/python3
"""Writes the synthetic inputs of bench/cli/cli_bench.sh into OUT_DIR (no ../shared needed).

  trajectories: tum-<n>-ref.tum / tum-<n>-est.tum for n = 1000, 100000, 1000000: a 10 Hz,
                ~1 m/s wandering planar drive and a drifting, noisy, rigidly displaced copy with
                +-3 ms stamp jitter, printed with Python's shortest round-trip repr (as evo writes).
  relations:    relations-<n>.txt for n = 100000: Kuemmerle's format (t1 t2 x y z roll pitch yaw),
                the reference's exact motion from every pose to the one 10 poses later (n - 10 lines).
  maps:         map-<side>.pgm + .yaml (map_saver trinary: 0 occupied, 254 free, 205 unknown) and
                map-<side>.png for side = 200 and 2000: a floor plan of rooms with 2-cell walls,
                doors, furniture and speckle, unknown outside a margin.

Deterministic (fixed seeds); a file that already exists is kept, so a rerun costs nothing.
Usage: make_inputs.py OUT_DIR [--files NAME ...]
  --files  write only the inputs these file names belong to (a TUM pair, a map with its .pgm/.yaml/.png,
           a relations file), e.g. what the selected benchmark cases read: the 1,000,000-pose pair alone
           takes minutes of Python.
"""
import argparse
import math
import os
import random
import struct
import sys
import zlib


def write_tum_pair(directory, count):
    reference_path = os.path.join(directory, f"tum-{count}-ref.tum")
    estimate_path = os.path.join(directory, f"tum-{count}-est.tum")
    if os.path.exists(reference_path) and os.path.exists(estimate_path):
        return
    rng = random.Random(42)
    offset_yaw, offset_x, offset_y = 0.5, 5.0, -3.0
    cos_o, sin_o = math.cos(offset_yaw), math.sin(offset_yaw)
    x = y = yaw = 0.0
    reference_lines = ["# timestamp tx ty tz qx qy qz qw\n"]
    estimate_lines = ["# timestamp tx ty tz qx qy qz qw\n"]
    for i in range(count):
        t = 0.1 * i
        yaw += 0.02 * math.sin(0.01 * t) + 0.01 * math.sin(0.0007 * t)
        x += 0.1 * math.cos(yaw)
        y += 0.1 * math.sin(yaw)
        reference_lines.append(f"{t!r} {x!r} {y!r} 0 0 0 {math.sin(yaw / 2)!r} {math.cos(yaw / 2)!r}\n")
        ex = x * 1.001 + rng.gauss(0.0, 0.02)
        ey = y + rng.gauss(0.0, 0.02)
        eyaw = yaw + rng.gauss(0.0, 0.002) + offset_yaw
        mx = cos_o * ex - sin_o * ey + offset_x
        my = sin_o * ex + cos_o * ey + offset_y
        stamp = t + rng.uniform(-0.003, 0.003)
        estimate_lines.append(
            f"{stamp!r} {mx!r} {my!r} 0 0 0 {math.sin(eyaw / 2)!r} {math.cos(eyaw / 2)!r}\n")
    with open(reference_path, "w") as out:
        out.writelines(reference_lines)
    with open(estimate_path, "w") as out:
        out.writelines(estimate_lines)


def write_relations(directory, count, step=10):
    """Relations on the reference drive of write_tum_pair (same path, same stamps)."""
    path = os.path.join(directory, f"relations-{count}.txt")
    if os.path.exists(path):
        return
    poses = []
    x = y = yaw = 0.0
    for i in range(count):
        t = 0.1 * i
        yaw += 0.02 * math.sin(0.01 * t) + 0.01 * math.sin(0.0007 * t)
        x += 0.1 * math.cos(yaw)
        y += 0.1 * math.sin(yaw)
        poses.append((t, x, y, yaw))
    lines = []
    for i in range(count - step):
        t1, x1, y1, yaw1 = poses[i]
        t2, x2, y2, yaw2 = poses[i + step]
        c, s = math.cos(yaw1), math.sin(yaw1)
        dx, dy = c * (x2 - x1) + s * (y2 - y1), -s * (x2 - x1) + c * (y2 - y1)
        dyaw = math.atan2(math.sin(yaw2 - yaw1), math.cos(yaw2 - yaw1))
        lines.append(f"{t1!r} {t2!r} {dx!r} {dy!r} 0 0 0 {dyaw!r}\n")
    with open(path, "w") as out:
        out.writelines(lines)


def floor_plan(side):
    """Rows of grey values: 205 unknown, 254 free, 0 occupied, 100 furniture-like grey."""
    rng = random.Random(11)
    grid = [bytearray([205]) * side for _ in range(side)]

    def fill(row0, col0, rows, cols, value):
        for r in range(max(row0, 0), min(row0 + rows, side)):
            c0, c1 = max(col0, 0), min(col0 + cols, side)
            if c1 > c0:
                grid[r][c0:c1] = bytes([value]) * (c1 - c0)

    margin = side // 20
    rooms = 12 if side >= 1000 else 3
    room = (side - 2 * margin) // rooms
    first, last = margin, margin + rooms * room
    fill(first, first, last - first, last - first, 254)
    for k in range(first, last + 1, room):
        fill(k, first, 2, last - first + 2, 0)
        fill(first, k, last - first + 2, 2, 0)
    door = max(room // 9, 4)
    for r in range(first, last, room):
        for c in range(first, last, room):
            if rng.randrange(4) != 0:
                fill(r, c + room // 5 + rng.randrange(room // 2), 2, door, 254)
            if rng.randrange(4) != 0:
                fill(r + room // 5 + rng.randrange(room // 2), c, door, 2, 254)
            for _ in range(3):
                fill(r + 10 + rng.randrange(room - 40), c + 10 + rng.randrange(room - 40),
                     4 + rng.randrange(room // 8), 4 + rng.randrange(room // 8), 0)
    for _ in range(side * side // 100):
        grid[first + rng.randrange(last - first)][first + rng.randrange(last - first)] = 0
    return grid


def write_map(directory, side):
    stem = os.path.join(directory, f"map-{side}")
    if all(os.path.exists(stem + ext) for ext in (".pgm", ".yaml", ".png")):
        return
    grid = floor_plan(side)
    with open(stem + ".pgm", "wb") as out:
        out.write(b"P5\n# slamsweep bench floor plan\n%d %d\n255\n" % (side, side))
        for row in grid:
            out.write(row)
    with open(stem + ".yaml", "w") as out:
        out.write(f"image: map-{side}.pgm\nmode: trinary\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"
                  "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    raw = b"".join(b"\x00" + bytes(row) for row in grid)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    with open(stem + ".png", "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        out.write(chunk(b"IEND", b""))


def main():
    parser = argparse.ArgumentParser(usage="make_inputs.py OUT_DIR [--files NAME ...]")
    parser.add_argument("directory")
    parser.add_argument("--files", nargs="*", default=None)
    args = parser.parse_args()
    directory = args.directory

    def wanted(*names):
        return args.files is None or any(name in args.files for name in names)

    os.makedirs(directory, exist_ok=True)
    for count in (1000, 100_000, 1_000_000):
        if wanted(f"tum-{count}-ref.tum", f"tum-{count}-est.tum"):
            write_tum_pair(directory, count)
    if wanted("relations-100000.txt"):
        write_relations(directory, 100_000)
    for side in (200, 2000):
        if wanted(f"map-{side}.yaml", f"map-{side}.pgm", f"map-{side}.png"):
            write_map(directory, side)


if __name__ == "__main__":
    main()
