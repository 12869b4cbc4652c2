#!/usr/bin/env bash
# The roster benchmark: runs bench/roster/roster_bench.yaml (or the sweep given with --config) and
# prints, per algorithm and sequence, the upstream's build time (from its install manifest), mean
# wall and CPU time per run, mean peak memory, and ATE RMSE mean +- std over the iterations.
# usage: bench/roster/roster_bench.sh [--config FILE] [slamsweep run options, e.g. --iterations 2]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
config="$root/bench/roster/roster_bench.yaml"
if [[ "${1:-}" == "--config" ]]; then config=$2; shift 2; fi
slamsweep="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"
out=$(mktemp -d "${TMPDIR:-/tmp}/roster-bench-XXXXXX")
status=0
"$slamsweep" run "$config" --output "$out" --no-report "$@" || status=$?
/usr/bin/python3 "$root/bench/roster/roster_table.py" "$out/runs.csv" "${SLAMSWEEP_SLAM_PREFIX:-$root/slam-prefix}"
echo "results: $out (sweep exit code $status)"
