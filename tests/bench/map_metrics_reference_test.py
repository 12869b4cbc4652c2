#!/usr/bin/python3
"""bench/map_metrics_reference.py, the Python + OpenCV paper map metrics that `eval map` is timed against, gives
the values of an independent implementation (../shared/reference/maps/expected_paper_metrics*.json) on the three
reference maps, cropped and on the raw grid: a timing against it is a timing against the same computation.
usage: map_metrics_reference_test.py REPOSITORY_ROOT SHARED_DIR
Exit 77 (skipped) when the shared maps are missing, a failure under CI=true."""
import json
import os
import subprocess
import sys

root, shared = sys.argv[1], os.environ.get("SLAMSWEEP_SHARED", sys.argv[2])
maps = os.path.join(shared, "reference", "maps")
expected_files = {"crop": "expected_paper_metrics_cropped.json", "no-crop": "expected_paper_metrics.json"}
missing = [name for name in expected_files.values() if not os.path.isfile(os.path.join(maps, name))]
if missing:
    print(f"missing under {maps}: {', '.join(missing)} (the read-only shared data, ../shared)", file=sys.stderr)
    sys.exit(1 if os.environ.get("CI") == "true" else 77)

failures = 0
for mode, name in expected_files.items():
    for expected in json.load(open(os.path.join(maps, name)))["maps"]:
        command = ["/usr/bin/python3", os.path.join(root, "bench", "map_metrics_reference.py"),
                   os.path.join(maps, expected["map"])] + (["--no-crop"] if mode == "no-crop" else [])
        actual = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
        for key, value in expected.items():
            if key in ("map", "unknown_value", "crop_margin_cells"):
                continue
            same = actual[key] == value if isinstance(value, int) else abs(actual[key] - value) <= 1e-9
            if not same:
                failures += 1
                print(f"FAILED {expected['map']} ({mode}) {key}: {actual[key]} != expected {value}")
        print(f"{expected['map']} ({mode}): compared {len(expected) - 3} values")
sys.exit(1 if failures else 0)
