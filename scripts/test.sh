#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds with warnings as errors, runs ctest.
# This is the README's test command and what .ci/run calls.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# The whole roster from the pinned sources (../shared/peers when present, else upstream at the pinned
# commits), cached outside the clone (~/.cache/slamsweep): seconds when already built; from an empty cache
# Cartographer's first build takes about 5 minutes on 2 cores; slam_toolbox's Karto adds about 80 CPU seconds and
# LaMa about 250 (docs/roster-beyond-the-paper.md). Every roster test covers all eight algorithms (the paper's five,
# slam-toolbox, lama, lama-pf). BreezySLAM is only the independent tinySLAM that tests/slam/tinyslam
# cross-checks against. SLAMSWEEP_ROSTER picks another set (a CI run without all of them fails RosterSweepTest).
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector breezyslam cartographer slam-toolbox lama}"
"$root/scripts/install-slam.sh" "${roster[@]}"
# The Jenkinsfiles' linter (npm-groovy-lint with Debian's Java runtime) for tests/jobs.
"$root/scripts/install-groovy-lint.sh" >/dev/null
# The independent MCAP/CDR readers and writers the ROS 2 bag tests check against (pinned npm packages).
"$root/scripts/install-bag-tools.sh" >/dev/null
"$root/scripts/build.sh"
cd "${SLAMSWEEP_BUILD_DIR:-$root/build}"
# Label docker (scripts/docker-check.sh: root, a Docker daemon, about 45 minutes) is the nightly job's.
ctest --output-on-failure -j "$(nproc)" --timeout 900 --label-exclude docker
