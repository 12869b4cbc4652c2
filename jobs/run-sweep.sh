#!/usr/bin/env bash
# Jenkins "Sweep" stage of the parameterised job: runs one sweep and checks it left junit.xml,
# summary.json and the report behind.
# Usage: jobs/run-sweep.sh [CONFIG [OUTPUT_DIR]]
#   CONFIG      sweep YAML (default: $CONFIG, else configs/quickstart.yaml)
#   OUTPUT_DIR  result directory (default: $OUTPUT_DIR, else ./out)
# Environment (the job's parameters; empty = the config's): ALGORITHMS and SEQUENCES (comma lists of
# names from the config), ITERATIONS (a count), JOBS (runs at once). An earlier result directory at
# OUTPUT_DIR is removed first (a reused workspace must not look finished) unless KEEP_OUTPUT=1.
# Exit code: 0 every run ok; 1 some run failed (results and report are still written); 2 bad config or
# parameter; 4 the sweep left an expected output missing; 130 interrupted.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

config=${1:-${CONFIG:-$SLAMSWEEP_ROOT/configs/quickstart.yaml}}
output=${2:-${OUTPUT_DIR:-out}}
jobs_find_binary
jobs_fresh_output "$output"

args=(run "$config" --output "$output" --keep-going)
[[ -n "${ALGORITHMS:-}" ]] && args+=(--only-algorithms "$ALGORITHMS")
[[ -n "${SEQUENCES:-}" ]] && args+=(--only-sequences "$SEQUENCES")
[[ -n "${ITERATIONS:-}" ]] && args+=(--iterations "$ITERATIONS")
[[ -n "${JOBS:-}" ]] && args+=(--jobs "$JOBS")

jobs_run_sweep "${args[@]}"
jobs_require_files "$output/summary.json" "$output/junit.xml" "$output/report/index.html"
jobs_log "$(jobs_summary_count "$output" ok) ok, $(jobs_summary_count "$output" failed) failed of" \
  "$(jobs_summary_count "$output" total) runs; report: $output/report/index.html"
exit "$status"
