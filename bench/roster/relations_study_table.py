"""Prints a study's relations table (Markdown) from a sweep's run folders: per sequence and algorithm, the
relations error (mean of each run's mean absolute translational error, with the sample std over runs), the
relations each run was scored on (used, not covered, outside the log), run time and peak memory, and per
sequence the reference floor (the corrected log itself on the same relations) where there is one.

usage: relations_study_table.py OUTPUT_DIR [SEQUENCE ...]
"""
import json
import math
import os
import sys
from collections import defaultdict


def mean_std(values):
    if not values:
        return float("nan"), float("nan")
    mean = sum(values) / len(values)
    if len(values) < 2:
        return mean, float("nan")
    return mean, math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))


def flat(metrics, name, statistic):
    for metric in metrics:
        if metric["metric"] == name and metric["statistic"] == statistic:
            return metric["value"]
    return None


def fmt(mean, std, digits=4):
    if math.isnan(mean):
        return "-"
    if math.isnan(std):
        return f"{mean:.{digits}f}"
    return f"{mean:.{digits}f} ± {std:.{digits}f}"


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    runs_dir = os.path.join(sys.argv[1], "runs")
    wanted = set(sys.argv[2:])
    groups = defaultdict(list)
    floors = {}
    for name in sorted(os.listdir(runs_dir)):
        try:
            with open(os.path.join(runs_dir, name, "run.json")) as f:
                spec = json.load(f)
            with open(os.path.join(runs_dir, name, "result.json")) as f:
                result = json.load(f)
        except (OSError, ValueError):
            continue
        sequence = spec["sequence"]["name"]
        if wanted and sequence not in wanted:
            continue
        groups[(sequence, spec["algorithm"]["name"])].append(result)
        floor = result.get("reference_floor")
        if floor and sequence not in floors:
            floors[sequence] = flat(floor["metrics"], "relations_trans", "mean")
    print("| sequence | algorithm | runs ok | relations error m (mean ± std over runs) | used / not covered / "
          "outside the log | wall s | peak MB |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for (sequence, algorithm), results in sorted(groups.items()):
        ok = [r for r in results if r["status"] == "ok"]
        errors = [flat(r["metrics"], "relations_trans", "mean") for r in ok]
        errors = [e for e in errors if e is not None]
        counts = sorted({(flat(r["metrics"], "relations_trans", "n"), flat(r["metrics"], "relations_trans",
                                                                           "not_covered"),
                          flat(r["metrics"], "relations_trans", "outside_log")) for r in ok})
        count_text = "; ".join(" / ".join("-" if v is None else f"{v:.0f}" for v in c) for c in counts)
        wall = mean_std([r["wall_s"] for r in ok])[0]
        rss = [r["peak_rss_kb"] / 1024 for r in ok if r.get("peak_rss_kb")]
        peak = f"{max(rss):.0f}" if rss else "-"
        failed = [r.get("failure_kind") for r in results if r["status"] != "ok"]
        runs = f"{len(ok)}/{len(results)}" + (f" ({', '.join(sorted(set(failed)))})" if failed else "")
        print(f"| {sequence} | {algorithm} | {runs} | {fmt(*mean_std(errors))} | {count_text} | "
              f"{'-' if math.isnan(wall) else f'{wall:.1f}'} | {peak} |")
    for sequence, floor in sorted(floors.items()):
        print(f"| {sequence} | reference floor (the corrected log itself) | - | {floor:.4f} | | | |")


if __name__ == "__main__":
    main()
