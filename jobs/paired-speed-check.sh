#!/usr/bin/env bash
# The nightly job's paired speed stage: the core metrics (eval ape / rpe / relations at 100k poses, eval map at
# 2000 x 2000) of this build against the previous build, run in turn on this agent (bench/paired/paired_bench.py),
# so that a slowdown beyond the noise of the measurement itself fails the night. No fixed time target: the
# verdict is a one-sided Mann-Whitney U test over the repeated runs plus a size tolerance taken from the
# spread of the paired ratios (bench/paired/paired_verdict.py).
# Usage: jobs/paired-speed-check.sh [OUTPUT_DIR]   (default out/paired: table.md, samples.json, verdict.json)
# Environment:
#   SPEED_BASELINE      the commit of the previous build (default: the checked-out commit's first parent); it is
#                       built once into $BASELINE_CACHE/<commit> (programs only, through scripts/build.sh's ccache)
#   SPEED_BASELINE_BIN  a slamsweep program of the previous build to use instead of building one
#   BASELINE_CACHE      default /var/tmp/slamsweep-baseline
#   BENCH_RUNS          counted pairs per case (default 21), BENCH_ONLY a regex of case names (default all)
# Exit code: 0 no case slower; 3 a case slower (its row says SLOWER); 2 bad arguments or no program; 4 the
# benchmark wrote no table or a command failed; otherwise the failing build step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/paired-speed-check.sh [OUTPUT_DIR]"
output=${1:-out/paired}
runs=${BENCH_RUNS:-21}
[[ "$runs" =~ ^[1-9][0-9]*$ ]] && ((runs >= 3)) ||
  jobs_die "$JOBS_EXIT_USAGE" "BENCH_RUNS must be an integer of at least 3, got '$runs'"
jobs_find_binary

baseline=${SPEED_BASELINE_BIN:-}
if [[ -z "$baseline" ]]; then
  commit=$(git -C "$SLAMSWEEP_ROOT" rev-parse --verify --quiet "${SPEED_BASELINE:-HEAD^}^{commit}") ||
    jobs_die "$JOBS_EXIT_USAGE" "SPEED_BASELINE '${SPEED_BASELINE:-HEAD^}' names no commit of this checkout"
  cache=${BASELINE_CACHE:-/var/tmp/slamsweep-baseline}/$commit
  baseline=$cache/build/slamsweep
  if [[ ! -x "$baseline" ]]; then
    jobs_log "building the previous build ($commit) in $cache"
    rm -rf -- "$cache"
    mkdir -p "$cache"
    jobs_run git clone --quiet --shared --no-checkout "$SLAMSWEEP_ROOT" "$cache/src"
    jobs_run git -C "$cache/src" checkout --quiet --detach "$commit"
    SLAMSWEEP_BUILD_DIR="$cache/build" SLAMSWEEP_BUILD_TARGETS=slamsweep jobs_run "$cache/src/scripts/build.sh" \
      -DSLAMSWEEP_BUILD_TESTS=OFF -DSLAMSWEEP_BUILD_BENCHMARKS=OFF
  fi
fi
[[ -x "$baseline" ]] || jobs_die "$JOBS_EXIT_USAGE" "no slamsweep program of the previous build at $baseline"

mkdir -p "$output"
rm -f -- "$output/table.md"
only=()
[[ -n "${BENCH_ONLY:-}" ]] && only=(--only "$BENCH_ONLY")
status=0
jobs_run /usr/bin/python3 "$SLAMSWEEP_ROOT/bench/paired/paired_bench.py" --before "$baseline" \
  --after "$SLAMSWEEP_BIN" --runs "$runs" --out "$output" "${only[@]}" || status=$?
case $status in
  0) jobs_log "no case slower than the previous build: $output/table.md" ;;
  3) jobs_log "slower than the previous build beyond the noise: see the SLOWER rows of $output/table.md" ;;
  *) jobs_die "$status" "bench/paired/paired_bench.py exited with $status" ;;
esac
jobs_require_files "$output/table.md" "$output/samples.json" "$output/verdict.json"
exit "$status"
