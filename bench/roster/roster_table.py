"""Prints the roster benchmark table from a sweep's runs.csv and the roster's install manifests.

usage: roster_table.py RUNS_CSV SLAM_PREFIX
"""
import csv
import json
import math
import os
import sys
from collections import defaultdict

UPSTREAM = {"gmapping": "gmapping", "tinyslam": "slam-constructor", "vinyslam": "slam-constructor",
            "hector": "hector", "cartographer": "cartographer"}


def mean_std(values):
    if not values:
        return float("nan"), float("nan")
    mean = sum(values) / len(values)
    if len(values) < 2:
        return mean, 0.0
    return mean, math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))


def build_seconds(prefix, algorithm):
    upstream = UPSTREAM.get(algorithm)
    if upstream is None:
        return "-"
    try:
        with open(os.path.join(prefix, "share", "slamsweep", "slam", upstream + ".json")) as manifest:
            return str(json.load(manifest)["build_seconds"])
    except (OSError, KeyError, ValueError):
        return "?"


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def main():
    runs_csv, prefix = sys.argv[1], sys.argv[2]
    groups = defaultdict(list)
    with open(runs_csv) as table:
        for row in csv.DictReader(table):
            groups[(row["algorithm"], row["sequence"])].append(row)
    print("| algorithm | sequence | build s | ok/runs | wall s | CPU s | peak MB | relations trans m (mean +- std, coverage) "
          "| ATE RMSE m (mean +- std) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (algorithm, sequence), rows in sorted(groups.items()):
        ok = [r for r in rows if r["status"] == "ok"]
        wall = mean_std([v for v in (number(r["wall_s"]) for r in ok) if v is not None])[0]
        cpu = mean_std([v for v in (number(r["cpu_s"]) for r in ok) if v is not None])[0]
        rss = [v for v in (number(r["peak_rss_kb"]) for r in ok) if v is not None]
        peak = "-" if not rss else "%.0f" % (sum(rss) / len(rss) / 1024)
        ate_mean, ate_std = mean_std([v for v in (number(r.get("ape_trans.rmse")) for r in ok) if v is not None])
        # The relations error: mean over the relations of each run (its own std is the spread over
        # relations), averaged over runs; coverage = used / (used + not_covered).
        rel = [v for v in (number(r.get("relations_trans.mean")) for r in ok) if v is not None]
        rel_std = [v for v in (number(r.get("relations_trans.std")) for r in ok) if v is not None]
        used = [v for v in (number(r.get("relations_trans.n")) for r in ok) if v is not None]
        skipped = [v for v in (number(r.get("relations_trans.not_covered")) for r in ok) if v is not None]
        if rel:
            coverage = sum(used) / max(1.0, sum(used) + sum(skipped))
            relations = "%.4f +- %.4f (%.1f %%)" % (mean_std(rel)[0], mean_std(rel_std)[0], 100.0 * coverage)
        else:
            relations = "-"
        print("| %s | %s | %s | %d/%d | %.1f | %.1f | %s | %s | %.3f +- %.3f |" %
              (algorithm, sequence, build_seconds(prefix, algorithm), len(ok), len(rows), wall, cpu, peak,
               relations, ate_mean, ate_std))


if __name__ == "__main__":
    main()
