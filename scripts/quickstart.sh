#!/usr/bin/env bash
# The main job: installs what is missing, builds, runs the quick-start sweep
# (configs/quickstart.yaml: MRPT icp-slam, MRPT rbpf-slam and the odometry baseline on MRPT's
# Telecom sample and a simulated floor plan, 3 iterations each) and prints where the report is.
# Extra arguments go to `slamsweep run` (e.g. --jobs 1, --output DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

# Only the packages the main job needs; the test command (scripts/test.sh) installs the rest.
"$root/scripts/install-deps.sh" --main
# The quick-start sweep uses no roster algorithm (MRPT's programs come with the apt step), so the main job
# builds none: the paper's roster is installed ahead of time by scripts/install-slam.sh NAME... (or here
# with SLAMSWEEP_ROSTER="gmapping slam-constructor hector cartographer"); `slamsweep algorithms` says how
# to get each missing one.
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-}"
((${#roster[@]} == 0)) || "$root/scripts/install-slam.sh" "${roster[@]}"
# Only what the sweep runs: the programs and the drivers of the installed roster. Tests and benchmarks
# are built by the test command (scripts/test.sh).
# Without tests and benchmarks configured, GoogleTest and Google Benchmark need not be installed.
SLAMSWEEP_BUILD_TARGETS="slamsweep slam/all" "$root/scripts/build.sh" -DSLAMSWEEP_BUILD_TESTS=OFF -DSLAMSWEEP_BUILD_BENCHMARKS=OFF
slamsweep="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"

start=$(date +%s)
status=0
"$slamsweep" run "$root/configs/quickstart.yaml" "$@" || status=$?
echo "quickstart: sweep took $(( $(date +%s) - start )) s (exit code $status: 0 all runs ok, 1 some failed, 130 interrupted)"
exit $status
