#!/usr/bin/python3
"""The paper profile's map metrics (../shared/spec/metrics.md) written plainly in Python + OpenCV:
the reference that `slamsweep eval map` is timed against (bench/paired/, docs/performance.md).

It follows the spec step by step with whole-image OpenCV calls and no shortcuts, as a user would
write it; tests/bench/map_metrics_reference_test.py checks it against the independent values of
../shared/reference/maps/expected_paper_metrics*.json.

usage: map_metrics_reference.py [--no-crop] [--unknown-value V] MAP.pgm|MAP.png|MAP.yaml
Prints one JSON object. A map_server YAML is read for its image only (trinary, unknown = 205).
"""
import argparse
import json
import os
import sys

import cv2
import numpy as np


def read_grey(path):
    if path.endswith(".yaml"):
        with open(path) as stream:
            for line in stream:
                key, _, value = line.partition(":")
                if key.strip() == "image":
                    path = os.path.join(os.path.dirname(path), value.strip())
                    break
    image = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    if image is None:
        sys.exit(f"map_metrics_reference.py: cannot read {path}")
    return image


def crop_to_known(grey, unknown_value, margin):
    known_rows = np.flatnonzero((grey != unknown_value).any(axis=1))
    known_cols = np.flatnonzero((grey != unknown_value).any(axis=0))
    if known_rows.size == 0:
        return grey
    r0, r1 = max(known_rows[0] - margin, 0), min(known_rows[-1] + margin + 1, grey.shape[0])
    c0, c1 = max(known_cols[0] - margin, 0), min(known_cols[-1] + margin + 1, grey.shape[1])
    return grey[r0:r1, c0:c1]


def occupied_proportion(p, unknown):
    occupancy = np.where(unknown, 0.0, p)
    threshold = occupancy.mean()
    occupied = int((occupancy > threshold).sum())
    total = occupancy.size
    known = total - int(unknown.sum())
    return {
        "threshold": float(threshold),
        "occupied": occupied,
        "occupied_to_free_unknown": occupied / (total - occupied),
        "occupied_to_known": occupied / known if known else 0.0,
        "occupied_to_all": occupied / total,
        "unknown_to_all": int(unknown.sum()) / total,
    }


def corner_count(p, unknown):
    remapped = np.where(unknown, 0.0, 1.0 - p).astype(np.float32)
    blurred = cv2.GaussianBlur(remapped, (5, 5), 1.0)
    log = cv2.Laplacian(blurred, cv2.CV_32F, ksize=3)
    magnitude = np.abs(log)
    if magnitude.max() == 0:
        return 0
    mask = (magnitude > 0.1 * magnitude.max()).astype(np.uint8)
    count, labels, stats, _ = cv2.connectedComponentsWithStats(mask, connectivity=8)
    keep = stats[:, cv2.CC_STAT_AREA] >= 5
    keep[0] = False
    cleaned = np.where(keep[labels], log, 0).astype(np.float32)
    corners = cv2.goodFeaturesToTrack(cleaned, maxCorners=0, qualityLevel=0.01, minDistance=10,
                                      blockSize=2, useHarrisDetector=True, k=0.04)
    return 0 if corners is None else len(corners)


def enclosed_areas(p, unknown):
    image = np.round(255.0 * (1.0 - p)).astype(np.uint8)
    best, best_u = 0, 0
    for u in range(0, 255, 5):
        image[unknown] = u
        threshold, free = cv2.threshold(image, 0, 255, cv2.THRESH_BINARY + cv2.THRESH_OTSU)
        count, labels, stats, _ = cv2.connectedComponentsWithStats(free, connectivity=8)
        x, y = stats[:, cv2.CC_STAT_LEFT], stats[:, cv2.CC_STAT_TOP]
        w, h = stats[:, cv2.CC_STAT_WIDTH], stats[:, cv2.CC_STAT_HEIGHT]
        inside = (x > 0) & (y > 0) & (x + w < image.shape[1]) & (y + h < image.shape[0])
        enclosed = int((inside & (stats[:, cv2.CC_STAT_AREA] >= 4))[1:].sum())
        if enclosed > best:
            best, best_u = enclosed, u
    return best, best_u


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("map")
    parser.add_argument("--no-crop", action="store_true")
    parser.add_argument("--unknown-value", type=int, default=205)
    args = parser.parse_args()
    grey = read_grey(args.map)
    height, width = grey.shape
    if not args.no_crop:
        grey = crop_to_known(grey, args.unknown_value, 2)
    unknown = grey == args.unknown_value
    p = (255.0 - grey.astype(np.float64)) / 255.0
    result = {"width": width, "height": height, "cropped_width": grey.shape[1], "cropped_height": grey.shape[0]}
    result.update(occupied_proportion(p, unknown))
    result["corners"] = corner_count(p, unknown)
    result["enclosed_areas"], result["at_unknown_value"] = enclosed_areas(p, unknown)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
