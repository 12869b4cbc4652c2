#!/usr/bin/env bash
# The nightly job's browser stage: the report's browser tests (headless Chromium against a local server that
# sends Jenkins' Content-Security-Policy) built and run on this agent, and their screenshots copied to
# OUTPUT_DIR for the job to archive, so a person can look at the pages as a browser drew them.
# Usage: jobs/browser-check.sh [OUTPUT_DIR]   (default out/screenshots)
# Exit code: 0 every browser test passed; 3 one failed (the screenshots are copied all the same); 2 bad
# arguments; 4 no screenshot was written; otherwise the failing step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/browser-check.sh [OUTPUT_DIR]"
output=${1:-out/screenshots}
build_dir=${SLAMSWEEP_BUILD_DIR:-$SLAMSWEEP_ROOT/build}
shots="$build_dir/artefacts/report-screenshots"

SLAMSWEEP_BUILD_TARGETS=report_browser_test jobs_run "$SLAMSWEEP_ROOT/scripts/build.sh"
rm -rf -- "$shots" "$output"
mkdir -p "$output"
status=0
# CI=true: a missing Chromium fails the tests instead of skipping them.
CI=true jobs_run ctest --test-dir "$build_dir" --output-on-failure -R 'BrowserTest\.' || status=$?
if [[ -d "$shots" ]]; then
  cp -r -- "$shots"/. "$output"/
fi
compgen -G "$output/*.png" >/dev/null ||
  jobs_die "$JOBS_EXIT_MISSING_OUTPUT" "the browser tests wrote no screenshot into $shots"
if ((status != 0)); then
  jobs_log "a browser test failed; screenshots in $output"
  exit "$JOBS_EXIT_REGRESSION"
fi
jobs_log "every browser test passed; screenshots in $output"
