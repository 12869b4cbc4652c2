#!/usr/bin/env bash
# The nightly's check of the known hostile inputs' cost: bench/hostile/rawlog_mutants.sh --check with the built
# program, the five mutated rawlogs of ../shared/fuzz each rejected in under 1 s and 100 MB.
# Usage: jobs/hostile-bench.sh [OUTPUT_DIR]   (default out/fuzz-bench: table.md)
# Environment: BENCH_RUNS (runs per mutant, default 5); SLAMSWEEP_SHARED (the data folder holding fuzz/).
# Exit code: 0 every target met; 3 a target missed; 2 bad arguments, no program or no shared data.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/hostile-bench.sh [OUTPUT_DIR]"
output=${1:-out/fuzz-bench}
jobs_find_binary
mkdir -p "$output"
status=0
jobs_run "$SLAMSWEEP_ROOT/bench/hostile/rawlog_mutants.sh" --check --runs "${BENCH_RUNS:-5}" "$SLAMSWEEP_BIN" \
  >"$output/table.md" || status=$?
cat "$output/table.md"
case $status in
  0) jobs_log "every mutated rawlog rejected within its targets" ;;
  3) jobs_log "a mutated rawlog missed its time or memory target: see $output/table.md" ;;
  *) jobs_die "$status" "bench/hostile/rawlog_mutants.sh exited with $status" ;;
esac
exit "$status"
