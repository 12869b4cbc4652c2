#!/usr/bin/env bash
# bench/cli/cli_bench.sh still runs end to end against the current program: inputs generated, hyperfine and
# GNU time run, table.md and summary.json written with a row per selected case and exit status 0 for
# each command. No timing is asserted (speed is judged by the benchmark's own table, never by a test).
# Usage: cli_bench_smoke_test.sh SLAMSWEEP_BINARY
set -euo pipefail
binary=${1:?usage: cli_bench_smoke_test.sh SLAMSWEEP_BINARY}
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v hyperfine >/dev/null || { echo "hyperfine missing: scripts/install-deps.sh installs it" >&2; exit 1; }
out=$(mktemp -d "${TMPDIR:-/tmp}/slamsweep-cli-bench.XXXXXX")
trap 'rm -rf -- "$out"' EXIT

"$root/bench/cli/cli_bench.sh" --runs 1 --out "$out" --only '^(version|plan|eval-ape-1k|eval-map-200)$' \
  after="$binary" >"$out/stdout" 2>"$out/stderr" || { cat "$out/stdout" "$out/stderr"; echo "cli_bench.sh failed"; exit 1; }

/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
summary = json.load(open(f"{out}/summary.json"))
cases = {case["case"]: case for case in summary["cases"]}
expected = {"version", "plan", "eval-ape-1k", "eval-map-200"}
assert set(cases) == expected, f"cases in summary.json: {sorted(cases)}, expected {sorted(expected)}"
for name, case in cases.items():
    program = case["programs"]["after"]
    assert program["exit_status"] == 0, f"{name}: the command exited {program['exit_status']}"
    assert program["median_ms"] > 0 and program["peak_rss_mb"] > 0, f"{name}: no timing or RSS recorded: {program}"
table = open(f"{out}/table.md").read()
for name in expected:
    assert f"| `{name}` |" in table, f"table.md has no row for {name}:\n{table}"
print("ok: cli_bench.sh wrote a row per case, every command exited 0")
PY
