#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds with warnings as errors, runs ctest.
# This is the README's test command and what .ci/run calls.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# The paper's roster from the pinned sources (../shared/peers when present, else upstream at the
# pinned commits), cached outside the clone: seconds when already built. Cartographer's first build
# (about 5 minutes on 2 cores, plus its packages) is left to the nightly job and to the opt-in run
# SLAMSWEEP_ROSTER="gmapping slam-constructor hector breezyslam cartographer" scripts/test.sh, which
# adds it to every roster test.
# BreezySLAM is only the independent tinySLAM that tests/slam/tinyslam cross-checks against.
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector breezyslam}"
"$root/scripts/install-slam.sh" "${roster[@]}"
# The Jenkinsfiles' linter (npm-groovy-lint with Debian's Java runtime) for tests/jobs.
"$root/scripts/install-groovy-lint.sh" >/dev/null
"$root/scripts/build.sh"
cd "${SLAMSWEEP_BUILD_DIR:-$root/build}"
# Label docker (scripts/docker-check.sh: root, a Docker daemon, about 45 minutes) is the nightly job's.
ctest --output-on-failure -j "$(nproc)" --timeout 900 --label-exclude docker
