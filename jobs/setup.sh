#!/usr/bin/env bash
# Jenkins "Setup" stage: installs the missing Debian packages (scripts/install-deps.sh, the same list
# CI and docker/ use), the SLAM roster (scripts/install-slam.sh) and builds slamsweep with warnings as
# errors (scripts/build.sh).
# Usage: jobs/setup.sh
# Environment: SLAMSWEEP_BUILD_DIR (default <repo>/build); SKIP_DEPS=1 skips the package step (agents
# without sudo whose packages an administrator installs); SKIP_BUILD=1 installs only the packages, the
# roster's included, and builds nothing (the nightly's shards run the programs of jobs/build-programs.sh).
# Exit code: 0 built; otherwise the failing step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

if [[ "${SKIP_DEPS:-0}" == 1 ]]; then
  jobs_log "SKIP_DEPS=1: not installing packages"
else
  jobs_run "$SLAMSWEEP_ROOT/scripts/install-deps.sh"
fi
# The paper's roster (pinned upstream builds, cached outside the workspace); SLAMSWEEP_ROSTER as in scripts/test.sh.
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector}"
if [[ "${SKIP_BUILD:-0}" == 1 ]]; then
  [[ "${SKIP_DEPS:-0}" == 1 ]] || jobs_run "$SLAMSWEEP_ROOT/scripts/install-slam.sh" --packages-only "${roster[@]}"
  jobs_log "SKIP_BUILD=1: packages only, nothing built"
  exit 0
fi
jobs_run "$SLAMSWEEP_ROOT/scripts/install-slam.sh" "${roster[@]}"
jobs_run "$SLAMSWEEP_ROOT/scripts/build.sh"
jobs_find_binary
jobs_log "built $SLAMSWEEP_BIN"
