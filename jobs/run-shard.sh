#!/usr/bin/env bash
# One parallel stage of the nightly job: share I of N of the sweep's matrix, without a report (the
# merge stage writes one for the whole night).
# Usage: jobs/run-shard.sh I N [CONFIG [OUTPUT_DIR]]
#   I, N        this shard (1-based) and the number of shards
#   CONFIG      sweep YAML (default: $CONFIG, else configs/radish.yaml)
#   OUTPUT_DIR  result directory (default: $SHARD_DIR, else out/shard-I)
# Environment: JOBS (runs at once on this agent; default the config's workers). An earlier result
# directory at OUTPUT_DIR is removed first unless KEEP_OUTPUT=1.
# Exit code: 0 every run ok; 1 some run failed (its results are still there to merge); 2 bad
# config or arguments; 4 no summary.json written; 130 interrupted.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# >= 2)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/run-shard.sh I N [CONFIG [OUTPUT_DIR]]"
index=$1
count=$2
[[ "$index" =~ ^[1-9][0-9]*$ && "$count" =~ ^[1-9][0-9]*$ ]] && ((index <= count)) ||
  jobs_die "$JOBS_EXIT_USAGE" "shard I/N: expected positive integers with I <= N, got '$index/$count'"
config=${3:-${CONFIG:-$SLAMSWEEP_ROOT/configs/radish.yaml}}
output=${4:-${SHARD_DIR:-out/shard-$index}}
jobs_find_binary
jobs_fresh_output "$output"

args=(run "$config" --shard "$index/$count" --output "$output" --keep-going --no-report)
[[ -n "${JOBS:-}" ]] && args+=(--jobs "$JOBS")
jobs_run_sweep "${args[@]}"
jobs_require_files "$output/summary.json"
jobs_log "shard $index/$count: $(jobs_summary_count "$output" ok) ok," \
  "$(jobs_summary_count "$output" failed) failed -> $output"
exit "$status"
