#!/usr/bin/env bash
# The nightly job's fuzzing stage (docs/hostile-input.md): the fuzz targets of tests/fuzz built with clang and
# libFuzzer (-DSLAMSWEEP_FUZZ=ON: AddressSanitizer and UndefinedBehaviorSanitizer too, in a build folder of
# its own), each fuzzed for FUZZ_SECONDS from a corpus kept in the build folder between nights (seeded by the
# target's own seeds and its kept findings, tests/fuzz/corpus/<target>/). Findings (libFuzzer's crash-, leak-,
# timeout- and oom- files) go to OUTPUT_DIR/<target>/ with each target's log, and a table to OUTPUT_DIR/summary.md.
# A finding is kept by copying it into tests/fuzz/corpus/<target>/ with its fix, so ctest replays it for ever.
# The rawlog and rosbag targets run MRPT and librosbag in process, where their allocations and slowness are
# seen; slamsweep runs them in a child process under memory and time limits (evaluator/sequence_io/
# contained_read.h), so out-of-memory and timeout files of those two are counted as contained, not as findings.
# Each target runs alone (one libFuzzer process at a time, at nice FUZZ_NICE), -timeout=10 (an input taking
# longer is a finding), -rss_limit_mb=2048, -malloc_limit_mb=256 (one allocation beyond it is a finding).
# Usage: jobs/fuzz-check.sh [--seconds N] [OUTPUT_DIR]   (default out/fuzz)
# --seconds: wall-clock seconds per target (default FUZZ_SECONDS, or 600). The table gives the CPU seconds
# each target got.
# Environment: FUZZ_SECONDS, FUZZ_TARGETS (names, default every target), FUZZ_NICE (default 5),
# SLAMSWEEP_FUZZ_BUILD_DIR (default <repo>/build-fuzz), SKIP_DEPS=1 (do not install clang), SKIP_BUILD=1 (fuzz
# the programs the build folder holds, as they are).
# Exit code: 0 no finding; 3 a finding (see summary.md); 4 a target wrote no log; otherwise the failing step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

usage="usage: jobs/fuzz-check.sh [--seconds N] [OUTPUT_DIR]"
seconds=${FUZZ_SECONDS:-600}
if [[ "${1:-}" == --seconds ]]; then
  (($# >= 2)) || jobs_die "$JOBS_EXIT_USAGE" "$usage"
  seconds=$2
  shift 2
fi
(($# <= 1)) || jobs_die "$JOBS_EXIT_USAGE" "$usage"
output=$(realpath -m -- "${1:-out/fuzz}")
build_dir=${SLAMSWEEP_FUZZ_BUILD_DIR:-$SLAMSWEEP_ROOT/build-fuzz}
nice_level=${FUZZ_NICE:-5}
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || jobs_die "$JOBS_EXIT_USAGE" "FUZZ_SECONDS must be a positive integer, got '$seconds'"
contained=" rawlog rosbag "

[[ "${SKIP_DEPS:-0}" == 1 ]] || jobs_run "$SLAMSWEEP_ROOT/scripts/install-fuzz-deps.sh"
if [[ "${SKIP_BUILD:-0}" != 1 ]]; then
  CXX=clang++-14 SLAMSWEEP_BUILD_DIR=$build_dir SLAMSWEEP_BUILD_TARGETS=fuzz_targets \
    jobs_run "$SLAMSWEEP_ROOT/scripts/build.sh" -DSLAMSWEEP_FUZZ=ON -DSLAMSWEEP_BUILD_BENCHMARKS=OFF
fi
targets=()
if [[ -n "${FUZZ_TARGETS:-}" ]]; then
  read -r -a targets <<<"$FUZZ_TARGETS"
else
  for program in "$build_dir"/tests/fuzz/fuzz_*; do targets+=("$(basename "$program")"); done
  targets=("${targets[@]#fuzz_}")
fi
rm -rf -- "$output"
mkdir -p "$output"
findings=0
{
  echo "| target | seconds | executions | CPU s | edges | corpus | crash | leak | timeout | oom | verdict |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
} >"$output/summary.md"
for name in "${targets[@]}"; do
  program=$build_dir/tests/fuzz/fuzz_$name
  [[ -x "$program" ]] || jobs_die "$JOBS_EXIT_USAGE" "no fuzz target $name ($program)"
  corpus=$build_dir/fuzz-corpus/$name
  mkdir -p "$corpus" "$output/$name"
  jobs_run "$program" --write-seeds="$corpus" >/dev/null
  cp -- "$SLAMSWEEP_ROOT/tests/fuzz/corpus/$name"/* "$corpus"/ 2>/dev/null || true
  jobs_log "fuzzing $name for $seconds s"
  # Fork mode goes on after a finding, so one night finds more than the first; every finding is a file.
  /usr/bin/time -f '%U %S' -o "$output/$name.cpu" nice -n "$nice_level" "$program" -fork=1 -ignore_crashes=1 \
    -ignore_ooms=1 -ignore_timeouts=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=256 -artifact_prefix="$output/$name/" -print_final_stats=1 "$corpus" \
    >"$output/$name.log" 2>&1 || true
  jobs_require_files "$output/$name.log"
  last=$(grep -E '^#[0-9]+' "$output/$name.log" | grep -E 'cov: [0-9]+' | tail -n 1 || true)
  executions=$(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")
  edges=$(sed -nE 's/.*cov: ([0-9]+).*/\1/p' <<<"$last")
  cpu_s=$(awk 'END {printf "%.0f", $1 + $2}' "$output/$name.cpu")  # the last line: time may first say the exit status
  count() { find "$output/$name" -maxdepth 1 -name "$1-*" | wc -l; }
  crash=$(count crash) leak=$(count leak) timeout=$(count timeout) oom=$(count oom)
  verdict=ok
  if ((crash + leak > 0)) || { [[ "$contained" != *" $name "* ]] && ((timeout + oom > 0)); }; then
    verdict=FINDING
    findings=1
  elif ((timeout + oom > 0)); then
    verdict="ok (oom/timeout contained)"
  fi
  echo "| $name | $seconds | ${executions:-?} | $cpu_s | ${edges:-?} | $(find "$corpus" -type f | wc -l) | $crash | $leak | $timeout | $oom | $verdict |" \
    >>"$output/summary.md"
done
echo "built from $(git -C "$SLAMSWEEP_ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown); $(date -u +%F)" >>"$output/summary.md"
cat "$output/summary.md"
if ((findings)); then
  jobs_log "findings: see $output/summary.md and the files in $output/<target>/"
  exit "$JOBS_EXIT_REGRESSION"
fi
jobs_log "no finding"
