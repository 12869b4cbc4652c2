#!/usr/bin/env bash
# The nightly job's scale stage: bench/scale/scale_bench.py with the built program at 1,000, 3,000 and
# 10,000 runs (4 shards, merge, report), checking the byte and count budgets and, at 10,000 runs, the time
# and memory goals (orchestration overhead per run, report time and memory, merge time). CI checks the
# budgets only, at 1,000 runs (tests/bench, bench_scale_budgets).
# Usage: jobs/scale-check.sh [OUTPUT_DIR]   (default out/scale: table.md, results.json)
# Environment: SCALE_SIZES (default 1000,3000,10000), SCALE_JOBS (workers, default 2).
# Run it on a quiet machine (agents labelled slamsweep-bench): other load reads as a slower program.
# Exit code: 0 every budget and goal met; 3 one missed (the script names it); 2 bad arguments, no program
# or no data.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/scale-check.sh [OUTPUT_DIR]"
output=${1:-out/scale}
sizes=${SCALE_SIZES:-1000,3000,10000}
[[ "$sizes" =~ ^[1-9][0-9]*(,[1-9][0-9]*)*$ ]] ||
  jobs_die "$JOBS_EXIT_USAGE" "SCALE_SIZES must be a comma-separated list of run counts, got '$sizes'"
jobs_find_binary
mkdir -p "$output"
status=0
jobs_run nice -n 10 /usr/bin/python3 "$SLAMSWEEP_ROOT/bench/scale/scale_bench.py" --sizes "$sizes" \
  --jobs "${SCALE_JOBS:-2}" --check-times --out "$output" --slamsweep "$SLAMSWEEP_BIN" || status=$?
case $status in
  0) jobs_log "every scale budget and goal met: $output/table.md" ;;
  3) jobs_log "a scale budget or goal was missed: see $output/table.md" ;;
  *) jobs_die "$status" "bench/scale/scale_bench.py exited with $status" ;;
esac
jobs_require_files "$output/table.md" "$output/results.json"
exit "$status"
