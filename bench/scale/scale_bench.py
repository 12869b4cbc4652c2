#!/usr/bin/python3
"""Cost growth of a big sweep: a synthetic sweep of the odometry baseline on 50-scan sequences (many
iterations and noise levels) run as 4 shards, merged and reported, at each size asked for.

Usage: bench/scale/scale_bench.py [--sizes 1000,3000,10000] [--out DIR] [--slamsweep BINARY] [--jobs N]
                                  [--check] [--check-times] [--keep] [--label TEXT]

Per size it measures (bench/scale/README.md says how each is defined):
  plan      `slamsweep plan` of the whole sweep: wall time, peak RSS
  run       the 4 shards one after another (`slamsweep run --shard I/4 --no-report --jobs N`): wall and
            CPU time, per-run orchestration overhead beyond the program's own time
  merge     `slamsweep merge` of the 4 shards (--no-report): wall time, peak RSS
  report    `slamsweep report` of the merged directory: wall time, peak RSS
  disk      the merged directory: allocated bytes (hard links counted once) per run, by part (runs/,
            report/, results.sqlite, the tables), files per run folder, results.sqlite bytes per run
With $SLAMSWEEP_PHASE_TIMES support in the program, where the orchestrator's and workers' time goes.

--check        exit 3 when a byte or count budget is missed (CI: these do not depend on the machine's load)
--check-times  exit 3 when a time or memory goal is missed too (the nightly on a quiet agent; the goals are
               stated at 10,000 runs and are only checked at sizes of at least 10,000)
Results: OUT/results.json (every figure), OUT/table.md; the sweep folders are deleted unless --keep.
The sequences need ../shared/datasets (SLAMSWEEP_SHARED): a missing file is named and exit status is 2.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHARDS = 4
BUDGET_MISSED = 3  # jobs/lib.sh's code for a missed target

# Byte and count budgets (checked in CI at any size) and time/memory goals (checked at >= 10,000 runs).
BUDGETS = {
    "disk_kb_per_run": 100.0,
    "db_kb_per_run": 10.0,
    "files_per_run_folder": 10,
}
GOALS_AT_10K = {
    "overhead_ms_per_run": 15.0,
    "report_s": 30.0,
    "report_peak_mb": 1024.0,
    "merge_s": 20.0,
}

# 50-scan cuts of real logs (the Radish corrected logs in ../shared/datasets) and one simulated floor,
# so maps have the sizes of real robots' first minute.
SEQUENCES = [
    ("intel", "intel-50", "intel/intel-corrected.log.gz"),
    ("fr079", "fr079-50", "fr079/freiburg-079-corrected.log.gz"),
    ("mit-csail", "csail-50", "mit-csail/csail-corrected.log.gz"),
]
NOISE_LEVELS = 25


def sweep_yaml(name, runs):
    """The sweep file for `runs` runs: 4 sequences x 25 noise levels x runs/100 iterations."""
    groups = (len(SEQUENCES) + 1) * NOISE_LEVELS
    if runs % groups != 0:
        sys.exit(f"scale_bench.py: a size must be a multiple of {groups} (sequences x noise levels), got {runs}")
    lines = [
        f"# Written by bench/scale/scale_bench.py: {runs} runs of the odometry baseline.",
        f"name: {name}",
        f"iterations: {runs // groups}",
        "seed: 11",
        "evaluation: {align: se2, rpe_delta_m: 1.0, t_max_diff_s: 0.01, stages: 24, map_resolution_m: 0.05}",
        "algorithms:",
        "  - {name: odometry, adapter: odometry, timeout_s: 60}",
        "sequences:",
    ]
    for catalog, cut, _ in SEQUENCES:
        lines.append(f"  - {{catalog: {catalog}, name: {cut}, max_scans: 50}}")
    lines += [
        "  - name: floor-50",
        "    format: simulated",
        "    ground_truth: exact",
        "    max_scans: 50",
        "    simulation: {floor_plan: {seed: 3, rooms_per_side: 2}, path: {rate_hz: 4.0}, noise_seed: 3}",
        "    citation: slamsweep's floor-plan simulator.",
        "    licence: Generated data; no restrictions.",
        "noise:",
    ]
    for level in range(NOISE_LEVELS):
        a = 0.001 * (level + 1)
        lines.append(f"  - {{name: n{level:02d}, odometry: {{alpha1: {a:.3f}, alpha2: 0.0001, alpha3: {a:.3f}, "
                     f"alpha4: 0.0001}}}}")
    return "\n".join(lines) + "\n"


def run_measured(argv, env, log_path):
    """Runs argv; returns wall s, user+sys CPU s of it and its waited-for descendants, peak RSS MB of the
    largest process, and the exit status. Output goes to log_path."""
    start = time.monotonic()
    with open(log_path, "w") as log:
        process = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env)
        _, status, usage = os.wait4(process.pid, 0)
    wall = time.monotonic() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    return {"wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime, "peak_mb": usage.ru_maxrss / 1024.0,
            "exit": process.returncode}


def require_ok(step, measured, log_path, allowed=(0,)):
    if measured["exit"] not in allowed:
        with open(log_path) as log:
            tail = log.read()[-4000:]
        sys.exit(f"scale_bench.py: {step} exited with {measured['exit']}; its output ({log_path}):\n{tail}")


def file_kind(relative):
    """What a file is, for the breakdown: runs/*/map.png, report/runs/*.html, results.sqlite, ..."""
    parts = relative.split(os.sep)
    if parts[0] == "runs" and len(parts) > 2:
        return "runs/*/" + "/".join(parts[2:3] + (["..."] if len(parts) > 3 else []))
    if parts[0] == "report" and len(parts) > 2 and parts[1] == "runs":
        return "report/runs/*.html" if len(parts) == 3 else "report/runs/*/" + parts[3]
    if parts[0] == "report" and len(parts) > 2:
        return "report/" + parts[1] + "/"
    if parts[0].startswith("results.sqlite"):
        return "results.sqlite"
    return "/".join(parts[:2]) if len(parts) > 1 else parts[0]


def disk_usage(root, runs):
    """Allocated bytes under root by part and by kind of file, every inode counted once: runs/ first, so a
    report file hard-linked to a run file costs the report nothing."""
    seen = set()
    parts, kinds = {}, {}
    files_per_run_folder = []
    tops = sorted(os.listdir(root), key=lambda name: (name != "runs", name))
    for top in tops:
        for directory, _, files in os.walk(os.path.join(root, top)) if os.path.isdir(os.path.join(root, top)) \
                else [(root, [], [top])]:
            relative_dir = os.path.relpath(directory, root)
            if relative_dir.startswith("runs" + os.sep) and relative_dir.count(os.sep) == 1:
                files_per_run_folder.append(sum(len(f) for _, _, f in os.walk(directory)))
            for name in files:
                relative = os.path.normpath(os.path.join(relative_dir, name))
                info = os.lstat(os.path.join(root, relative))
                part = "results.sqlite" if top.startswith("results.sqlite") else (top if top in ("runs", "report", "reference_maps") else "tables")
                kind = file_kind(relative)
                for table, key in ((parts, part), (kinds, kind)):
                    entry = table.setdefault(key, {"bytes": 0, "allocated": 0, "files": 0})
                    entry["files"] += 1
                if (info.st_dev, info.st_ino) in seen:
                    continue
                seen.add((info.st_dev, info.st_ino))
                for table, key in ((parts, part), (kinds, kind)):
                    table[key]["bytes"] += info.st_size
                    table[key]["allocated"] += info.st_blocks * 512
    total = sum(entry["allocated"] for entry in parts.values())
    apparent = sum(entry["bytes"] for entry in parts.values())
    files_per_run_folder.sort()
    return {
        "parts": parts,
        "kinds": kinds,
        "allocated_bytes": total,
        "apparent_bytes": apparent,
        "disk_kb_per_run": total / 1024.0 / runs,
        "apparent_kb_per_run": apparent / 1024.0 / runs,
        "files_per_run_folder_max": files_per_run_folder[-1] if files_per_run_folder else 0,
        "files_per_run_folder_median": files_per_run_folder[len(files_per_run_folder) // 2]
        if files_per_run_folder else 0,
        "run_folders": len(files_per_run_folder),
    }


def program_seconds(summary_path):
    """Σ of the runs' own program time (result.json wall_s: for the baseline, rendering its map) and run counts."""
    with open(summary_path) as handle:
        summary = json.load(handle)
    total = sum(run.get("wall_s") or 0.0 for run in summary["runs"])
    return total, summary["counts"]


def phase_times(path):
    """Sums of $SLAMSWEEP_PHASE_TIMES lines ({"process": kind, "phases": {name: wall s}, "cpu": {name: CPU s}})
    per process kind (sweep, worker, merge, report)."""
    sums = {}
    if not os.path.exists(path):
        return sums
    with open(path) as handle:
        for line in handle:
            record = json.loads(line)
            kind = sums.setdefault(record["process"], {"count": 0, "phases": {}, "cpu": {}})
            kind["count"] += 1
            for key in ("phases", "cpu"):
                for phase, seconds in record.get(key, {}).items():
                    kind[key][phase] = kind[key].get(phase, 0.0) + seconds
    return sums


def measure_size(runs, args, env, shared):
    work = os.path.join(args.out, f"n{runs}")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    config = os.path.join(work, "scale.yaml")
    with open(config, "w") as handle:
        handle.write(sweep_yaml(f"scale-{runs}", runs))
    phases_file = os.path.join(work, "phase_times.jsonl")
    env = dict(env, SLAMSWEEP_PHASE_TIMES=phases_file)
    result = {"runs": runs, "jobs": args.jobs}
    print(f"scale_bench: {runs} runs in {work}", flush=True)

    log = os.path.join(work, "plan.log")
    measured = run_measured([args.slamsweep, "plan", config], env, log)
    require_ok("plan", measured, log)
    result["plan"] = measured

    shard_dirs = []
    run_total = {"wall_s": 0.0, "cpu_s": 0.0, "peak_mb": 0.0}
    program_s = 0.0
    for shard in range(SHARDS):
        shard_dir = os.path.join(work, f"shard-{shard}")
        log = os.path.join(work, f"run-{shard}.log")
        measured = run_measured([args.slamsweep, "run", config, "--shard", f"{shard + 1}/{SHARDS}", "--output",
                                 shard_dir, "--no-report", "--jobs", str(args.jobs)], env, log)
        require_ok(f"run of shard {shard + 1}/{SHARDS}", measured, log)
        for key in ("wall_s", "cpu_s"):
            run_total[key] += measured[key]
        run_total["peak_mb"] = max(run_total["peak_mb"], measured["peak_mb"])
        seconds, counts = program_seconds(os.path.join(shard_dir, "summary.json"))
        if counts["failed"] != 0:
            sys.exit(f"scale_bench.py: shard {shard + 1}: {counts['failed']} runs failed (see {shard_dir}/summary.json)")
        program_s += seconds
        shard_dirs.append(shard_dir)
        print(f"scale_bench:   shard {shard + 1}/{SHARDS}: {measured['wall_s']:.1f} s", flush=True)
    run_total["program_s"] = program_s
    # A worker slot is busy jobs x wall; what the program did not use of it is the orchestration's.
    run_total["overhead_ms_per_run"] = (args.jobs * run_total["wall_s"] - program_s) / runs * 1000.0
    run_total["cpu_ms_per_run"] = run_total["cpu_s"] / runs * 1000.0
    run_total["cpu_overhead_ms_per_run"] = (run_total["cpu_s"] - program_s) / runs * 1000.0
    result["run"] = run_total

    merged = os.path.join(work, "merged")
    log = os.path.join(work, "merge.log")
    measured = run_measured([args.slamsweep, "merge", *shard_dirs, "-o", merged, "--no-report"], env, log)
    require_ok("merge", measured, log)
    result["merge"] = measured
    # The shards' folders are hard-linked into the merged one; gone, they leave its bytes alone.
    for shard_dir in shard_dirs:
        shutil.rmtree(shard_dir)

    log = os.path.join(work, "report.log")
    measured = run_measured([args.slamsweep, "report", merged], env, log)
    require_ok("report", measured, log)
    result["report"] = measured

    _, counts = program_seconds(os.path.join(merged, "summary.json"))
    if counts["total"] != runs or counts["ok"] != runs:
        sys.exit(f"scale_bench.py: the merged sweep has {counts}, expected {runs} ok runs")
    disk = disk_usage(merged, runs)
    database = disk["parts"].get("results.sqlite", {"bytes": 0})["bytes"]
    disk["db_kb_per_run"] = database / 1024.0 / runs
    result["disk"] = disk
    result["phases"] = phase_times(phases_file)
    # The same overhead from CPU time alone, which other load on the machine hardly changes: everything the
    # shards' processes used (supervisors, workers, programs) but the programs' own CPU (for the odometry
    # baseline, rendering its map: the workers' "collect" phase). On an otherwise idle machine whose cores the
    # workers keep busy, jobs x wall is this CPU time, so it is what the wall-clock overhead comes to there.
    program_cpu_s = result["phases"].get("worker", {}).get("cpu", {}).get("collect")
    if program_cpu_s is not None:
        result["run"]["program_cpu_s"] = program_cpu_s
        result["run"]["cpu_overhead_ms_per_run"] = (result["run"]["cpu_s"] - program_cpu_s) / runs * 1000.0
    if not args.keep:
        shutil.rmtree(work)
    return result


def check(results, times, budgets):
    """The missed budgets (and goals with `times`), as sentences."""
    missed = []
    for result in results:
        runs = result["runs"]
        disk = result["disk"]
        for key, value in (("disk_kb_per_run", disk["disk_kb_per_run"]), ("db_kb_per_run", disk["db_kb_per_run"]),
                           ("files_per_run_folder", disk["files_per_run_folder_max"])):
            if value > budgets[key]:
                missed.append(f"{runs} runs: {key} {value:.1f} > {budgets[key]}")
        if times and runs >= 10000:
            figures = {"overhead_ms_per_run": result["run"]["overhead_ms_per_run"],
                       "report_s": result["report"]["wall_s"], "report_peak_mb": result["report"]["peak_mb"],
                       "merge_s": result["merge"]["wall_s"]}
            for key, value in figures.items():
                if value > GOALS_AT_10K[key]:
                    missed.append(f"{runs} runs: {key} {value:.1f} > {GOALS_AT_10K[key]}")
    return missed


def table(results, note):
    rows = [
        ("plan s", lambda r: f"{r['plan']['wall_s']:.2f}"),
        ("plan peak MB", lambda r: f"{r['plan']['peak_mb']:.0f}"),
        ("run s (4 shards)", lambda r: f"{r['run']['wall_s']:.1f}"),
        ("overhead ms/run (goal <= 15)", lambda r: f"{r['run']['overhead_ms_per_run']:.1f}"),
        ("CPU ms/run", lambda r: f"{r['run']['cpu_ms_per_run']:.1f}"),
        ("CPU overhead ms/run (CPU - program CPU; the quiet-machine overhead)",
         lambda r: f"{r['run']['cpu_overhead_ms_per_run']:.1f}"),
        ("program ms/run", lambda r: f"{r['run']['program_s'] / r['runs'] * 1000:.1f}"),
        ("merge s (goal <= 20 at 10k)", lambda r: f"{r['merge']['wall_s']:.1f}"),
        ("report s (goal <= 30 at 10k)", lambda r: f"{r['report']['wall_s']:.1f}"),
        ("report peak MB (goal <= 1024)", lambda r: f"{r['report']['peak_mb']:.0f}"),
        ("disk KB/run (budget <= 100)", lambda r: f"{r['disk']['disk_kb_per_run']:.1f}"),
        ("  apparent size KB/run", lambda r: f"{r['disk'].get('apparent_kb_per_run', 0):.1f}"),
        ("results.sqlite KB/run (budget <= 10)", lambda r: f"{r['disk']['db_kb_per_run']:.1f}"),
        ("files per run folder (budget <= 10)", lambda r: f"{r['disk']['files_per_run_folder_max']}"),
    ]
    parts = sorted({part for r in results for part in r["disk"]["parts"]})
    for part in parts:
        rows.append((f"  {part} KB/run", lambda r, p=part: f"{r['disk']['parts'].get(p, {'allocated': 0})['allocated'] / 1024 / r['runs']:.1f}"))
    kinds = (("sweep", "per run, CPU ms", "cpu", 1000.0, True), ("worker", "per run, CPU ms", "cpu", 1000.0, True),
             ("merge", "wall s", "phases", 1.0, False), ("report", "wall s", "phases", 1.0, False))
    for kind, unit, key, scale, per_run in kinds:
        names = sorted({name for r in results for name in r.get("phases", {}).get(kind, {}).get(key, {})})
        for name in names:
            def cell(r, kind=kind, key=key, name=name, scale=scale, per_run=per_run):
                value = r.get("phases", {}).get(kind, {}).get(key, {}).get(name)
                if value is None:
                    return "-"
                return f"{value * scale / (r['runs'] if per_run else 1):.2f}"
            rows.append((f"  {kind} {name} ({unit})", cell))
    header = "| | " + " | ".join(f"{r['runs']} runs" for r in results) + " |"
    lines = [header, "|---|" + "---:|" * len(results)]
    for label, cell in rows:
        lines.append(f"| {label} | " + " | ".join(cell(r) for r in results) + " |")
    lines.append("")
    lines.append(note)
    # Disk by kind of file at the largest size (allocated KB per run; apparent KB per run).
    largest = results[-1]
    lines += ["", f"Disk by kind of file at {largest['runs']} runs (KB per run: allocated, apparent; files):", "",
              "| file | allocated | apparent | files |", "|---|---:|---:|---:|"]
    kinds = sorted(largest["disk"].get("kinds", {}).items(), key=lambda item: -item[1]["allocated"])
    for kind, entry in kinds[:25]:
        lines.append(f"| {kind} | {entry['allocated'] / 1024 / largest['runs']:.2f} | "
                     f"{entry['bytes'] / 1024 / largest['runs']:.2f} | {entry['files']} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", default="1000,3000,10000")
    parser.add_argument("--out", default=os.path.join(os.environ.get("SLAMSWEEP_BUILD_DIR", os.path.join(ROOT, "build")),
                                                      "bench-scale"))
    parser.add_argument("--slamsweep", default=os.path.join(os.environ.get("SLAMSWEEP_BUILD_DIR",
                                                                           os.path.join(ROOT, "build")), "slamsweep"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--check-times", action="store_true")
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--label", default="")
    parser.add_argument("--disk-kb-per-run", type=float, default=BUDGETS["disk_kb_per_run"],
                        help="the disk budget --check applies (default: the goal); CI holds today's figure so that "
                             "a regression fails while the goal is not met yet")
    args = parser.parse_args()
    args.out = os.path.abspath(args.out)
    args.slamsweep = os.path.abspath(args.slamsweep)
    if not os.access(args.slamsweep, os.X_OK):
        print(f"scale_bench.py: {args.slamsweep}: not an executable", file=sys.stderr)
        return 2
    shared = os.environ.get("SLAMSWEEP_SHARED", os.path.join(ROOT, "..", "shared"))
    for _, _, path in SEQUENCES:
        if not os.path.isfile(os.path.join(shared, "datasets", path)):
            print(f"scale_bench.py: {os.path.join(shared, 'datasets', path)} missing (set SLAMSWEEP_SHARED)",
                  file=sys.stderr)
            return 2
    env = dict(os.environ, SLAMSWEEP_SHARED=os.path.abspath(shared))
    os.makedirs(args.out, exist_ok=True)
    load_before = open("/proc/loadavg").read().split()[:3]
    results = [measure_size(int(size), args, env, shared) for size in args.sizes.split(",")]
    load_after = open("/proc/loadavg").read().split()[:3]
    note = (f"{args.label + ': ' if args.label else ''}{os.cpu_count()} cores, --jobs {args.jobs}; load average "
            f"before {' '.join(load_before)}, after {' '.join(load_after)}; {args.slamsweep}")
    with open(os.path.join(args.out, "results.json"), "w") as handle:
        json.dump({"note": note, "budgets": BUDGETS, "goals_at_10k": GOALS_AT_10K, "sizes": results}, handle, indent=2)
    text = table(results, note)
    with open(os.path.join(args.out, "table.md"), "w") as handle:
        handle.write(text)
    print(text)
    budgets = dict(BUDGETS, disk_kb_per_run=args.disk_kb_per_run)
    missed = check(results, args.check_times, budgets) if (args.check or args.check_times) else []
    for sentence in missed:
        print(f"scale_bench: missed: {sentence}")
    return BUDGET_MISSED if missed else 0


if __name__ == "__main__":
    sys.exit(main())
