#!/usr/bin/env bash
# The nightly job's sanitizer stage: slamsweep built with AddressSanitizer and UndefinedBehaviorSanitizer
# (-DSLAMSWEEP_SANITIZE=address,undefined, in a build folder of its own) and the ctest suite run under it,
# except the tests labelled not_instrumented (each listed with its reason in not-instrumented-tests.txt,
# copied to OUTPUT_DIR, and in docs/hostile-input.md) and those labelled docker (the Docker stage's).
# Usage: jobs/sanitize-check.sh [OUTPUT_DIR]   (default out/sanitize: junit.xml, ctest.log, not-instrumented-tests.txt)
# Environment: SLAMSWEEP_SANITIZE_BUILD_DIR (default <repo>/build-sanitize); SANITIZE_TESTS (a ctest -R regex,
# default every test).
# Exit code: 0 every test passed; 3 a test failed (a sanitizer report or any other failure: see ctest.log);
# 4 ctest wrote no JUnit file; otherwise the failing step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/sanitize-check.sh [OUTPUT_DIR]"
output=$(realpath -m -- "${1:-out/sanitize}")
build_dir=${SLAMSWEEP_SANITIZE_BUILD_DIR:-$SLAMSWEEP_ROOT/build-sanitize}

SLAMSWEEP_BUILD_DIR=$build_dir jobs_run "$SLAMSWEEP_ROOT/scripts/build.sh" -DSLAMSWEEP_SANITIZE=address,undefined
rm -rf -- "$output"
mkdir -p "$output"
cp -- "$build_dir/not-instrumented-tests.txt" "$output/"
jobs_log "tests left out (not instrumented), with their reasons:"
sed 's/^/    /' "$output/not-instrumented-tests.txt"
only=()
[[ -n "${SANITIZE_TESTS:-}" ]] && only=(-R "$SANITIZE_TESTS")
status=0
CI=true jobs_run ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" --timeout 1800 \
  --label-exclude 'docker|not_instrumented' --output-junit "$output/junit.xml" "${only[@]}" \
  >"$output/ctest.log" 2>&1 || status=$?
tail -n 30 "$output/ctest.log"
jobs_require_files "$output/junit.xml"
if ((status != 0)); then
  jobs_log "a test failed under the sanitizers: see $output/ctest.log"
  exit "$JOBS_EXIT_REGRESSION"
fi
jobs_log "every test passed under AddressSanitizer and UndefinedBehaviorSanitizer"
