#!/usr/bin/env bash
# bench/paired/paired_bench.py still runs end to end: the same program on both sides, every case, three pairs.
# No timing is asserted (the verdict logic is tested on synthetic samples by paired_verdict_test.py).
# Usage: paired_bench_smoke_test.sh SLAMSWEEP_BINARY
set -euo pipefail
binary=${1:?usage: paired_bench_smoke_test.sh SLAMSWEEP_BINARY}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d "${TMPDIR:-/tmp}/slamsweep-paired-bench.XXXXXX")
trap 'rm -rf -- "$out"' EXIT

status=0
/usr/bin/python3 "$root/bench/paired/paired_bench.py" --before "$binary" --after "$binary" --runs 3 --warmup 0 \
  --out "$out" >"$out/stdout" 2>"$out/stderr" || status=$?
# 0 or, by a rare draw of the machine's noise, 3; anything else is a broken script or command.
[[ $status == 0 || $status == 3 ]] || { cat "$out/stdout" "$out/stderr"; echo "paired_bench.py exited $status"; exit 1; }

/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
samples = json.load(open(f"{out}/samples.json"))
verdict = json.load(open(f"{out}/verdict.json"))
expected = {"eval-ape-se3-100k", "eval-rpe-1m-100k", "eval-relations-100k", "eval-map-2000"}
assert {case["case"] for case in samples["cases"]} == expected, samples["cases"]
for case in samples["cases"]:
    assert case["same_output"], f"{case['case']}: one program printed two different results"
    for label in ("before", "after"):
        assert len(case[label]["cpu_s"]) == 3 and min(case[label]["wall_s"]) > 0, case
assert {case["case"] for case in verdict["cases"]} == expected, verdict
table = open(f"{out}/table.md").read()
for name in expected:
    assert f"| `{name}` |" in table, f"table.md has no row for {name}:\n{table}"
print("ok: paired_bench.py wrote samples, verdicts and a row per case")
PY
