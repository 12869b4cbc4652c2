#!/usr/bin/env bash
# Nightly "Programs" stage: builds slamsweep and the SLAM roster once, in ROOT, for every shard. Each shard
# building its own would give other binaries (absolute source paths are compiled in), so digests and with
# them the runs' build identities would differ between shards and the merged night would split into groups.
# ROOT is an absolute folder outside any workspace, the same on every agent: jobs/unpack-programs.sh puts
# the programs back at exactly these paths, so every path compiled into them holds there too.
# Usage: jobs/build-programs.sh [ROOT]
#   ROOT  default: $PROGRAMS_ROOT, else /var/tmp/slamsweep-programs/$BUILD_TAG (Jenkins sets BUILD_TAG)
# Environment: SLAMSWEEP_ROSTER (as scripts/test.sh; default: the whole roster, Cartographer included).
# Exit code: 0 built; 2 bad arguments; otherwise the failing step's code.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

root=${1:-${PROGRAMS_ROOT:-/var/tmp/slamsweep-programs/${BUILD_TAG:-local}}}
[[ "$root" == /* ]] || jobs_die "$JOBS_EXIT_USAGE" "ROOT must be an absolute path, got '$root'"
commit=$(git -C "$SLAMSWEEP_ROOT" rev-parse HEAD)
jobs_log "building commit $commit in $root"
rm -rf -- "$root/src" "$root/build"
mkdir -p "$root"
# A clone of the checked-out commit: git describe gives the build its revision (the objects are shared
# with the workspace while building; the packed tree leaves .git out).
jobs_run git clone --quiet --shared --no-checkout "$SLAMSWEEP_ROOT" "$root/src"
jobs_run git -C "$root/src" checkout --quiet --detach "$commit"
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector breezyslam cartographer slam-toolbox lama}"
jobs_run "$root/src/scripts/install-slam.sh" "${roster[@]}"
SLAMSWEEP_BUILD_DIR="$root/build" jobs_run "$root/src/scripts/build.sh"
jobs_log "built $root/build/slamsweep"
