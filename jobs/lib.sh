# shellcheck shell=bash
# Shared bits of the job scripts (sourced, never run): where the repository and the slamsweep binary
# are, logging, and reading a result directory's summary.json. Nothing here needs Jenkins, so CI runs
# exactly the steps the pipelines run.
#
# Environment (all optional):
#   SLAMSWEEP_BUILD_DIR  build directory of scripts/build.sh (default: <repo>/build)
#   SLAMSWEEP_BIN        the slamsweep program (default: $SLAMSWEEP_BUILD_DIR/slamsweep)

# The repository root: the folder above jobs/, whatever the caller's working directory.
SLAMSWEEP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export SLAMSWEEP_ROOT

# Exit codes shared by the job scripts, so that the Jenkinsfiles can map each to a build result.
# 0, 1, 2 and 130 mean what they mean for `slamsweep run`; 3 is `slamsweep history compare`'s.
readonly JOBS_EXIT_OK=0
readonly JOBS_EXIT_FAILED_RUNS=1
readonly JOBS_EXIT_USAGE=2
readonly JOBS_EXIT_REGRESSION=3
readonly JOBS_EXIT_MISSING_OUTPUT=4
export JOBS_EXIT_OK JOBS_EXIT_FAILED_RUNS JOBS_EXIT_USAGE JOBS_EXIT_REGRESSION JOBS_EXIT_MISSING_OUTPUT

jobs_name=$(basename "$0" .sh)

# Prints a progress line prefixed with the script's name (Jenkins console and CI logs read alike).
jobs_log() {
  echo "jobs/${jobs_name}: $*"
}

jobs_die() {
  local code=$1
  shift
  echo "jobs/${jobs_name}: error: $*" >&2
  exit "$code"
}

# Prints the command, then runs it; returns its exit status.
jobs_run() {
  echo "jobs/${jobs_name}: \$ $*"
  "$@"
}

# Runs `slamsweep ARGS...` (a run) and leaves its exit code in $status: failed SLAM runs (exit 1)
# are results for the later steps to report (the script exits with $status at its end), anything
# else (2 config/usage, 130 interrupted) ends the job at once with that code.
jobs_run_sweep() {
  status=0
  jobs_run "$SLAMSWEEP_BIN" "$@" || status=$?
  case $status in
    0 | 1) ;;
    *) jobs_die "$status" "slamsweep run exited with $status (2 config/usage, 130 interrupted)" ;;
  esac
}

# Resolves the slamsweep binary into $SLAMSWEEP_BIN, or exits with a message saying how to build it.
jobs_find_binary() {
  local build_dir=${SLAMSWEEP_BUILD_DIR:-$SLAMSWEEP_ROOT/build}
  SLAMSWEEP_BIN=${SLAMSWEEP_BIN:-$build_dir/slamsweep}
  [[ -x "$SLAMSWEEP_BIN" ]] ||
    jobs_die "$JOBS_EXIT_USAGE" "no slamsweep program at $SLAMSWEEP_BIN; run jobs/setup.sh first or set SLAMSWEEP_BIN"
  export SLAMSWEEP_BIN
}

# Prints one count ("total", "ok" or "failed") of DIR/summary.json. python3 rather than grep, because
# a run's parameters may use any key; python3 is installed with the ROS bag test tools.
jobs_summary_count() {
  local dir=$1 key=$2
  python3 - "$dir/summary.json" "$key" <<'EOF'
import json, sys
with open(sys.argv[1]) as f:
    print(int(json.load(f)["counts"][sys.argv[2]]))
EOF
}

# Exits with JOBS_EXIT_MISSING_OUTPUT naming the first of the given files that is missing or empty.
jobs_require_files() {
  local file
  for file in "$@"; do
    [[ -s "$file" ]] || jobs_die "$JOBS_EXIT_MISSING_OUTPUT" "expected output $file is missing or empty"
  done
}

# Makes DIR an empty output directory. A job must not pick up an earlier build's results from a reused
# workspace (`slamsweep run` would skip those runs as done), so an old result directory is removed;
# anything else in the way is an error rather than a deletion. KEEP_OUTPUT=1 keeps it (to resume).
jobs_fresh_output() {
  local dir=$1
  [[ -e "$dir" ]] || return 0
  if [[ "${KEEP_OUTPUT:-0}" == 1 ]]; then
    jobs_log "KEEP_OUTPUT=1: keeping $dir (finished runs are skipped)"
    return 0
  fi
  [[ -d "$dir" ]] || jobs_die "$JOBS_EXIT_USAGE" "$dir: exists and is not a directory"
  if [[ -e "$dir/results.sqlite" || -e "$dir/summary.json" ]]; then
    jobs_log "removing the earlier results in $dir"
    rm -rf -- "$dir"
  elif [[ -n "$(ls -A -- "$dir")" ]]; then
    jobs_die "$JOBS_EXIT_USAGE" "$dir: not empty and not a result directory; choose another output directory"
  fi
}
