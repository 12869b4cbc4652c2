#!/usr/bin/env bash
# The nightly job's speed stage: the whole-process targets of bench/cli (start-up, eval ape/rpe/map, the worker)
# measured on this agent by bench/cli/cli_bench.sh --check with the built program, so that a change that
# makes slamsweep slower or fatter than its targets turns the night UNSTABLE.
# Usage: jobs/speed-check.sh [OUTPUT_DIR]   (default out/speed: table.md, summary.json, hyperfine JSON)
# Environment: BENCH_RUNS (runs per case, default 10), BENCH_ONLY (regex of case names, default all).
# Run it on a quiet machine (agents labelled slamsweep-bench): other load reads as a slower program.
# Exit code: 0 every target met; 3 a target missed (the table's `met` column says which); 2 bad arguments
# or no program; 4 the benchmark wrote no table.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/speed-check.sh [OUTPUT_DIR]"
output=${1:-out/speed}
runs=${BENCH_RUNS:-10}
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || jobs_die "$JOBS_EXIT_USAGE" "BENCH_RUNS must be a positive integer, got '$runs'"
jobs_find_binary
command -v hyperfine >/dev/null ||
  jobs_die "$JOBS_EXIT_USAGE" "hyperfine is missing: jobs/setup.sh (scripts/install-deps.sh) installs it"

rm -rf -- "$output/worker-after"  # the worker case must run in a folder this build prepared
mkdir -p "$output"
only=()
[[ -n "${BENCH_ONLY:-}" ]] && only=(--only "$BENCH_ONLY")
status=0
jobs_run "$SLAMSWEEP_ROOT/bench/cli/cli_bench.sh" --check --runs "$runs" --out "$output" "${only[@]}" \
  after="$SLAMSWEEP_BIN" || status=$?
case $status in
  0) jobs_log "every speed target met: $output/table.md" ;;
  3) jobs_log "a speed target was missed (regression): see the NO rows of $output/table.md" ;;
  *) jobs_die "$status" "bench/cli/cli_bench.sh exited with $status" ;;
esac
jobs_require_files "$output/table.md" "$output/summary.json"
exit "$status"
