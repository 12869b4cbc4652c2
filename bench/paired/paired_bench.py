#!/usr/bin/python3
"""Paired whole-process benchmark of the core metrics: two slamsweep programs (before, after) run the same
commands on the same inputs in turn (before, after, then after, before in the next round, ...), so the
machine's drift falls on both alike, and paired_verdict.py decides from the repeated samples whether
`after` is slower beyond the noise of this very measurement.

Cases (inputs from bench/cli/make_inputs.py):
  eval-ape-se3-100k    eval ape tum-100000-ref.tum tum-100000-est.tum --align se3
  eval-rpe-1m-100k     eval rpe tum-100000-ref.tum tum-100000-est.tum --delta 1 --delta-unit m
  eval-relations-100k  eval relations tum-100000-est.tum relations-100000.txt
  eval-map-2000        eval map map-2000.yaml (on one core, taskset -c 0, as bench/cli times it)

usage: paired_bench.py --before BINARY --after BINARY [--runs N] [--warmup N] [--only REGEX] [--out DIR]
                       [--metric cpu|wall] [--alpha A] [--min-effect E]
Writes OUT/samples.json (every run's wall, user + system CPU and peak RSS), OUT/verdict.json and
OUT/table.md; the table also says whether both programs printed the same JSON (a change of results is
for the tests to judge, so it is shown, not failed here). Exit status: 0 no case slower, 3 a case slower
(a regression), 2 bad arguments, 4 a command failed.
Each run is timed from outside, as a whole process: wall by the monotonic clock around fork and wait,
CPU and peak RSS from wait4's resource usage (which includes the helper program the core starts).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paired_verdict  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

CASES = [
    ("eval-ape-se3-100k", [], ["eval", "ape", "tum-100000-ref.tum", "tum-100000-est.tum", "--align", "se3"]),
    ("eval-rpe-1m-100k", [], ["eval", "rpe", "tum-100000-ref.tum", "tum-100000-est.tum", "--delta", "1",
                              "--delta-unit", "m"]),
    ("eval-relations-100k", [], ["eval", "relations", "tum-100000-est.tum", "relations-100000.txt"]),
    ("eval-map-2000", ["taskset", "-c", "0"], ["eval", "map", "map-2000.yaml"]),
]


def run_once(argv, cwd):
    """One whole-process run: (wall seconds, user + system CPU seconds, peak RSS in KB, exit status)."""
    with open(os.devnull, "wb") as sink:
        start = time.perf_counter()
        process = subprocess.Popen(argv, cwd=cwd, stdout=sink, stderr=sink)
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss, process.returncode


def json_output(argv, cwd):
    result = subprocess.run(argv + ["--json"], cwd=cwd, capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True, help="the slamsweep program of the earlier build")
    parser.add_argument("--after", required=True, help="the slamsweep program under test")
    parser.add_argument("--runs", type=int, default=21, help="counted pairs per case (default 21)")
    parser.add_argument("--warmup", type=int, default=2, help="uncounted pairs first (default 2)")
    parser.add_argument("--only", default="", help="only the cases whose name matches this regex")
    parser.add_argument("--out", default=os.path.join(os.environ.get("SLAMSWEEP_BUILD_DIR", ROOT + "/build"),
                                                      "bench-paired"))
    parser.add_argument("--metric", choices=("cpu", "wall"), default="cpu",
                        help="what the verdict compares (default cpu: user + system time)")
    parser.add_argument("--alpha", type=float, default=0.01)
    parser.add_argument("--min-effect", type=float, default=0.02)
    args = parser.parse_args()
    if args.runs < 3 or args.warmup < 0:
        parser.error("--runs must be at least 3 and --warmup at least 0")
    programs = {}
    for label in ("before", "after"):
        path = os.path.abspath(getattr(args, label))
        if not os.access(path, os.X_OK):
            parser.error(f"--{label} {path}: not an executable")
        programs[label] = path

    out = os.path.abspath(args.out)
    inputs = os.path.join(out, "inputs")
    os.makedirs(out, exist_ok=True)
    cases = [case for case in CASES if re.search(args.only, case[0])]
    if not cases:
        parser.error(f"--only {args.only!r} matches no case")
    # Only the inputs these cases read (the generator's 1,000,000-pose pair takes minutes).
    files = sorted({word for _, _, arguments in cases for word in arguments if "." in word})
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "bench/cli/make_inputs.py"), inputs, "--files", *files],
                   check=True)
    samples = {"programs": programs, "runs": args.runs, "load_before": os.getloadavg(), "cases": []}
    for name, prefix, arguments in cases:
        outputs = {label: json_output(prefix + [path] + arguments, inputs) for label, path in programs.items()}
        for label, (status, _, stderr) in outputs.items():
            if status != 0:
                print(f"paired_bench.py: {name}: the {label} program exited {status}: {stderr.strip()}",
                      file=sys.stderr)
                return 4
        record = {"case": name, "command": " ".join(prefix + ["slamsweep"] + arguments),
                  "same_output": outputs["before"][1] == outputs["after"][1]}
        for label in programs:
            record[label] = {"wall_s": [], "cpu_s": [], "peak_rss_kb": []}
        for round_index in range(args.warmup + args.runs):
            order = ["before", "after"] if round_index % 2 == 0 else ["after", "before"]
            for label in order:
                wall, cpu, rss, status = run_once(prefix + [programs[label]] + arguments, inputs)
                if status != 0:
                    print(f"paired_bench.py: {name}: the {label} program exited {status}", file=sys.stderr)
                    return 4
                if round_index >= args.warmup:
                    record[label]["wall_s"].append(wall)
                    record[label]["cpu_s"].append(cpu)
                    record[label]["peak_rss_kb"].append(rss)
        samples["cases"].append(record)
    samples["load_after"] = os.getloadavg()
    with open(os.path.join(out, "samples.json"), "w") as stream:
        json.dump(samples, stream, indent=1)

    results = paired_verdict.decide_all(samples, args.metric, args.alpha, args.min_effect)
    with open(os.path.join(out, "verdict.json"), "w") as stream:
        json.dump({"metric": args.metric, "cases": results}, stream, indent=1)
    lines = [f"Paired whole-process runs ({args.runs} pairs after {args.warmup} warm-up, verdict on {args.metric} "
             f"time; load average {samples['load_before'][0]:.2f} before, {samples['load_after'][0]:.2f} after)",
             "", "| case | before ms | after ms | paired ratio | tolerance | p (slower) | verdict | same output |",
             "|---|---|---|---|---|---|---|---|"]
    for record, result in zip(samples["cases"], results):
        lines.append(f"| `{result['case']}` | {result['median_before'] * 1e3:.1f} | {result['median_after'] * 1e3:.1f} "
                     f"| {result['median_ratio']:.3f} | {result['tolerance']:.3f} | {result['p_slower']:.2g} "
                     f"| {result['verdict']} | {'yes' if record['same_output'] else 'NO'} |")
    table = "\n".join(lines) + "\n"
    with open(os.path.join(out, "table.md"), "w") as stream:
        stream.write(table)
    print(table, end="")
    for result in results:
        print(paired_verdict.describe(result))
    if not all(record["same_output"] for record in samples["cases"]):
        print("paired_bench.py: the programs printed different results (same output: NO)", file=sys.stderr)
    return 3 if any(result["verdict"] == "SLOWER" for result in results) else 0


if __name__ == "__main__":
    sys.exit(main())
