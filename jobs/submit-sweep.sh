#!/usr/bin/env bash
# Jenkins "Sweep" stage of the service job (Jenkinsfile.service): submits one sweep to `slamsweep serve`,
# follows it to the end and downloads its junit.xml and HTML report.
# Usage: jobs/submit-sweep.sh [CONFIG [OUTPUT_DIR]]
#   CONFIG      sweep YAML (default: $CONFIG, else configs/quickstart.yaml)
#   OUTPUT_DIR  where junit.xml and report/ go (default: $OUTPUT_DIR, else ./out)
# Environment: SLAMSWEEP_SERVER (the service's URL, default http://127.0.0.1:8420), PRIORITY (-100..100,
# default 0), SLAMSWEEP_TOKEN_FILE (the bearer token file, mode 0600; Jenkins' file credential).
# Exit code: 0 every run ok; 1 some run failed (junit.xml and the report are still downloaded); 2 the
# server refused the sweep or cannot be reached; 4 an expected download is missing; 130 interrupted (an
# aborted build cancels its sweep on the server).
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

config=${1:-${CONFIG:-$SLAMSWEEP_ROOT/configs/quickstart.yaml}}
output=${2:-${OUTPUT_DIR:-out}}
jobs_find_binary
# An earlier build's downloads must not pass for this build's.
rm -rf -- "$output/junit.xml" "$output/report"
mkdir -p -- "$output"

args=(submit "$config" --server "${SLAMSWEEP_SERVER:-http://127.0.0.1:8420}" --wait
  --junit "$output/junit.xml" --report "$output/report" --priority "${PRIORITY:-0}")
[[ -n "${SLAMSWEEP_TOKEN_FILE:-}" ]] && args+=(--token-file "$SLAMSWEEP_TOKEN_FILE")

status=0
jobs_run "$SLAMSWEEP_BIN" "${args[@]}" || status=$?
case $status in
  0 | 1) ;;
  *) jobs_die "$status" "slamsweep submit exited with $status (2 refused or unreachable, 130 interrupted)" ;;
esac
jobs_require_files "$output/junit.xml" "$output/report/index.html"
jobs_log "report: $output/report/index.html"
exit "$status"
