#!/usr/bin/env bash
# The nightly job's merge stage: combines the shards' result directories into one, with the report
# and junit.xml of the whole night, and says whether any run failed.
# Usage: jobs/merge-shards.sh OUTPUT_DIR SHARD_DIR...
# An earlier result directory at OUTPUT_DIR is removed first unless KEEP_OUTPUT=1.
# Exit code: 0 every run ok; 1 some run failed (merged results and report are still written);
# 2 bad arguments or inputs; 4 the merge left an expected output missing.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# >= 2)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/merge-shards.sh OUTPUT_DIR SHARD_DIR..."
output=$1
shift
for shard in "$@"; do
  [[ -s "$shard/results.sqlite" ]] || jobs_die "$JOBS_EXIT_USAGE" "$shard: not a result directory (no results.sqlite)"
done
jobs_find_binary
jobs_fresh_output "$output"

status=0
jobs_run "$SLAMSWEEP_BIN" merge "$@" -o "$output" || status=$?
((status == 0)) || jobs_die "$status" "slamsweep merge exited with $status"
jobs_require_files "$output/summary.json" "$output/junit.xml" "$output/report/index.html"

total=$(jobs_summary_count "$output" total)
failed=$(jobs_summary_count "$output" failed)
jobs_log "merged $# shards: $total runs, $failed failed; report: $output/report/index.html"
if ((failed > 0)); then
  jobs_log "$failed runs failed: see $output/summary.json (status, failure_kind, reason)"
  exit "$JOBS_EXIT_FAILED_RUNS"
fi
exit "$JOBS_EXIT_OK"
