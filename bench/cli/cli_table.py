#!/usr/bin/python3
"""The table of bench/cli/cli_bench.sh: one row per case, per program the median wall time
(hyperfine), the median peak RSS (GNU time), the exit status, and whether the targets are met.

Usage: cli_table.py [--check] OUT_DIR RUNS NOTE LABEL...
Writes OUT_DIR/summary.json and prints the markdown table. With --check the exit status is 3 when the
last program misses a target (the "met" column says NO), so a performance job can fail on a regression.
"""
import json
import os
import sys


def read_text(path, default=""):
    try:
        with open(path) as handle:
            return handle.read().strip()
    except OSError:
        return default


TARGET_MISSED = 3  # jobs/lib.sh's code for a regression


def time_target_of(target_ms, labels, first_median_ms):
    """The time target's text and limit in ms (None: not checked). target_ms is "-", a number, or
    "half[:BEFORE_MS]": at most half the first program's median when two or more programs run
    (e.g. before=... after=...), else half the recorded BEFORE_MS, else not checked."""
    if target_ms == "-":
        return "", None
    if not target_ms.startswith("half"):
        return f"<= {target_ms} ms", float(target_ms)
    if len(labels) > 1:
        return f"<= 1/2 of {labels[0]}", first_median_ms / 2.0
    recorded = target_ms.partition(":")[2]
    if recorded:
        return f"<= 1/2 of the recorded before ({recorded} ms)", float(recorded) / 2.0
    return "<= 1/2 of a before program (not checked: one program)", None


def main():
    argv = sys.argv[1:]
    check = bool(argv) and argv[0] == "--check"
    if check:
        argv = argv[1:]
    if len(argv) < 4:
        sys.exit("usage: cli_table.py [--check] OUT_DIR RUNS NOTE LABEL...")
    out_dir, runs, note, labels = argv[0], argv[1], argv[2], argv[3:]
    missed = []
    header = ["case", "target"]
    for label in labels:
        header += [f"{label} ms", f"{label} CPU ms", f"{label} MB"]
    header.append("met")
    rows = []
    summary = {"runs": int(runs), "note": note, "cases": []}
    with open(os.path.join(out_dir, "cases.txt")) as handle:
        cases = [line.rstrip("\n").split("|", 3) for line in handle if line.strip()]
    for name, target_ms, target_mb, arguments in cases:
        with open(os.path.join(out_dir, f"{name}.json")) as handle:
            results = {result["command"]: result for result in json.load(handle)["results"]}
        time_target, limit_ms = time_target_of(target_ms, labels, results[labels[0]]["median"] * 1000.0)
        target = " ".join(part for part in (time_target, f"<= {target_mb} MB" if target_mb != "-" else "") if part) or "-"
        row = [f"`{name}`", target]
        case_summary = {"case": name, "arguments": arguments, "target_ms": target_ms, "target_mb": target_mb,
                        "programs": {}}
        met = "-"
        for label in labels:
            result = results[label]
            median_ms = result["median"] * 1000.0
            rss_mb = int(read_text(os.path.join(out_dir, f"{name}.{label}.rss_kb"), "0")) / 1024.0
            status = int(read_text(os.path.join(out_dir, f"{name}.{label}.status"), "-1"))
            cell = f"{median_ms:.1f}" + ("" if status == 0 else f" (exit {status})")
            cpu_ms = (result["user"] + result["system"]) * 1000.0
            row += [cell, f"{cpu_ms:.1f}", f"{rss_mb:.1f}"]
            case_summary["programs"][label] = {
                "median_ms": median_ms, "min_ms": result["min"] * 1000.0, "max_ms": result["max"] * 1000.0,
                "user_ms": result["user"] * 1000.0, "system_ms": result["system"] * 1000.0,
                "peak_rss_mb": rss_mb, "exit_status": status}
            if label == labels[-1] and (limit_ms is not None or target_mb != "-"):
                ok = status == 0
                ok = ok and (limit_ms is None or median_ms <= limit_ms)
                ok = ok and (target_mb == "-" or rss_mb <= float(target_mb))
                met = "yes" if ok else "NO"
                if not ok:
                    missed.append(name)
        case_summary["met"] = {"yes": True, "NO": False}.get(met)
        row.append(met)
        rows.append(row)
        summary["cases"].append(case_summary)
    with open(os.path.join(out_dir, "summary.json"), "w") as handle:
        json.dump(summary, handle, indent=2)
    print(f"Whole process, median of {runs} runs after 3 warm-up runs (hyperfine); CPU: mean user + system time (hyperfine); peak RSS: median of {runs} "
          f"runs (GNU time). `met` is for the last program. {note}.\n")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in rows:
        print("| " + " | ".join(row) + " |")
    if missed:
        print(f"\ntargets missed by {labels[-1]}: {', '.join(missed)}", file=sys.stderr)
        if check:
            return TARGET_MISSED
    return 0


if __name__ == "__main__":
    sys.exit(main())
