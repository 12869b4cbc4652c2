#!/usr/bin/python3
"""Do two result directories of the same sweep carry the same results? Compares summary.json, summary.csv,
runs.csv, validity.csv and junit.xml with what varies from one execution to the next left out: times of
day, wall/CPU time and peak memory (and statistics of them), and the sweep's own paths. Used to check that a
change to how results are stored or reported keeps every number (bench/scale/README.md).

Usage: same_results.py [--across-builds] DIR_A DIR_B     exit 0 when the same, 1 with the differences listed
  --across-builds  the two directories come from two builds of slamsweep (before and after a change): the
                   groups' build identity (build, build_description) is left out too
"""
import csv
import io
import json
import re
import sys

# inputs_sha256 (summary.json's "validity"): the digest of the study's inputs, resources and build included.
VOLATILE_KEYS = {"generated_at", "started_at", "finished_at", "wall_s", "cpu_s", "peak_rss_kb", "run_dir",
                 "reference_map", "inputs_sha256"}
# The names of the files a run folder holds (map.pgm or map.png, stages/ or stages.png) are layout, not results.
LAYOUT_KEYS = {"outputs"}
RESOURCES = ("wall_s", "cpu_s", "peak_rss_kb")
BUILD_KEYS = {"build", "build_description"}


def scrub(value, left_out=frozenset()):
    """A JSON value with the volatile members (and the run folder's file names, and `left_out`) left out, at
    every depth."""
    if isinstance(value, dict):
        return {key: scrub(item, left_out) for key, item in value.items()
                if key not in VOLATILE_KEYS and key not in LAYOUT_KEYS and key not in left_out and
                not any(key.startswith(r) for r in RESOURCES)}
    if isinstance(value, list):
        kept = [scrub(item, left_out) for item in value]
        # Validity rows that correlate a metric with a resource vary with the machine's load.
        return [item for item in kept if not (isinstance(item, dict) and any(
            str(item.get(field, "")) in RESOURCES for field in ("metric", "x", "y", "quantity", "other")))]
    return value


def read(path):
    try:
        with open(path, newline="") as handle:
            return handle.read()
    except FileNotFoundError:
        return None


def csv_rows(text):
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return rows
    header = rows[0]
    keep = [i for i, name in enumerate(header)
            if name not in VOLATILE_KEYS and not any(name.startswith(r) or name.endswith(r) or r in name
                                                      for r in RESOURCES)]
    kept = [[row[i] for i in keep if i < len(row)] for row in rows]
    return [row for row in kept if not any(cell in RESOURCES for cell in row)]


def junit_text(text):
    text = re.sub(r'\s(time|timestamp|hostname)="[^"]*"', "", text)
    # wall/CPU/memory lines in system-out
    text = re.sub(r"(wall|cpu|peak)[^\n<]*\n", "", text)
    return text


def main():
    arguments = sys.argv[1:]
    left_out = frozenset(BUILD_KEYS) if "--across-builds" in arguments else frozenset()
    arguments = [argument for argument in arguments if argument != "--across-builds"]
    if len(arguments) != 2:
        sys.exit(__doc__)
    a, b = arguments
    scrub_all = lambda value: scrub(value, left_out)
    differences = []
    for name in ("summary.json",):
        left, right = read(f"{a}/{name}"), read(f"{b}/{name}")
        if (left is None) != (right is None):
            differences.append(f"{name}: in only one of the directories")
        elif left is not None and scrub_all(json.loads(left)) != scrub_all(json.loads(right)):
            differences.append(f"{name}: differs")
            left_runs = {r["run_id"]: scrub_all(r) for r in json.loads(left).get("runs", [])}
            right_runs = {r["run_id"]: scrub_all(r) for r in json.loads(right).get("runs", [])}
            for run_id in sorted(set(left_runs) | set(right_runs)):
                left_run, right_run = left_runs.get(run_id) or {}, right_runs.get(run_id) or {}
                if left_run != right_run:
                    keys = sorted(k for k in set(left_run) | set(right_run) if left_run.get(k) != right_run.get(k))
                    for key in keys:
                        differences.append(f"  run {run_id}: {key}: {left_run.get(key)} != {right_run.get(key)}"[:600])
                    break
            left_summary, right_summary = scrub_all(json.loads(left)), scrub_all(json.loads(right))
            for key in sorted(set(left_summary) | set(right_summary)):
                if key != "runs" and left_summary.get(key) != right_summary.get(key):
                    differences.append(f"  {key}: differs")
    for name in ("summary.csv", "runs.csv", "validity.csv"):
        left, right = read(f"{a}/{name}"), read(f"{b}/{name}")
        if (left is None) != (right is None):
            differences.append(f"{name}: in only one of the directories")
        elif left is not None and csv_rows(left) != csv_rows(right):
            differences.append(f"{name}: differs")
    left, right = read(f"{a}/junit.xml"), read(f"{b}/junit.xml")
    if left is not None and right is not None and junit_text(left) != junit_text(right):
        differences.append("junit.xml: differs")
    for line in differences:
        print(line)
    print("same results" if not differences else f"{len(differences)} differences")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
