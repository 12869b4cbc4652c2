#!/usr/bin/env bash
# The nightly job's last stage: records the night's merged results in the history database (one night
# per sweep, kept across builds) and compares them with the night before, or with a named baseline.
# Usage: jobs/nightly-compare.sh RESULT_DIR [HISTORY_DB]
#   HISTORY_DB  default: $SLAMSWEEP_HISTORY, else out/history.sqlite. In Jenkins it must outlive the
#               workspace (see jobs/README.md).
# Environment (optional): NIGHT_LABEL (default: the sweep's start time), BASELINE_LABEL (compare with this
# night instead of the previous one), REGRESSION_ALPHA, REGRESSION_MIN_EFFECT (override the defaults of
# `slamsweep history compare`).
# Writes RESULT_DIR/regressions.xml (JUnit: one failing testcase per regression) when it compares.
# Exit code: 0 no regression (or the first night: nothing to compare with); 3 a regression; 2 bad
# arguments, result directory or history database; 4 no RESULT_DIR/summary.json.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# >= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/nightly-compare.sh RESULT_DIR [HISTORY_DB]"
result_dir=$1
history=${2:-${SLAMSWEEP_HISTORY:-out/history.sqlite}}
jobs_require_files "$result_dir/summary.json"
jobs_find_binary

first_night=0
[[ -s "$history" ]] || first_night=1

record=(history record "$result_dir" --history "$history")
[[ -n "${NIGHT_LABEL:-}" ]] && record+=(--label "$NIGHT_LABEL")
jobs_run "$SLAMSWEEP_BIN" "${record[@]}" || jobs_die "$JOBS_EXIT_USAGE" "could not record $result_dir in $history"

if [[ -z "${BASELINE_LABEL:-}" ]] && ((first_night)); then
  jobs_log "$history was empty: this night is the first, nothing to compare with"
  exit "$JOBS_EXIT_OK"
fi

compare=(history compare "$result_dir" --history "$history" --junit "$result_dir/regressions.xml")
if [[ -n "${BASELINE_LABEL:-}" ]]; then
  compare+=(--baseline-label "$BASELINE_LABEL")
else
  compare+=(--previous)
fi
[[ -n "${REGRESSION_ALPHA:-}" ]] && compare+=(--alpha "$REGRESSION_ALPHA")
[[ -n "${REGRESSION_MIN_EFFECT:-}" ]] && compare+=(--min-effect "$REGRESSION_MIN_EFFECT")

status=0
jobs_run "$SLAMSWEEP_BIN" "${compare[@]}" || status=$?
case $status in
  0) jobs_log "no regression" ;;
  3) jobs_log "regression found: see $result_dir/regressions.xml" ;;
  *) jobs_die "$status" "slamsweep history compare exited with $status" ;;
esac
exit "$status"
