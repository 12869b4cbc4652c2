#!/usr/bin/env bash
# The nightly job's Docker stage: the image built and run for real (scripts/docker-check.sh) through its
# ctest, label docker, which scripts/test.sh leaves out. Writes ctest's JUnit file and the check's outputs
# (build log, quick-start report and junit.xml from the container, times.txt with the image size, build
# and quick-start times) for Jenkins to publish.
# Usage: jobs/docker-check.sh [OUTPUT_DIR]   (default out/docker)
# Run it on an agent where it may be root or use the Docker daemon (label slamsweep-docker), after
# jobs/setup.sh. Exit code: 0 the check passed; 1 it failed; 2 bad arguments or no build.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/docker-check.sh [OUTPUT_DIR]"
output=${1:-out/docker}
jobs_find_binary
build_dir=${SLAMSWEEP_BUILD_DIR:-$SLAMSWEEP_ROOT/build}
mkdir -p "$output"
output=$(cd "$output" && pwd)
status=0
jobs_run ctest --test-dir "$build_dir" --label-regex '^docker$' --output-on-failure \
  --output-junit "$output/ctest-junit.xml" || status=$?
# The check writes into the build tree (tests/docker); a copy goes with the job's artifacts.
rm -rf "$output/check"
cp -r "$build_dir/tests/docker/docker-check" "$output/check" 2>/dev/null || jobs_log "the check left no outputs"
if ((status == 0)); then
  jobs_log "the Docker image passed: $output/check/times.txt"
else
  jobs_log "the Docker check failed: see $output/ctest-junit.xml and $output/check"
  exit "$JOBS_EXIT_FAILED_RUNS"
fi
