#!/usr/bin/env bash
# The main job: installs what is missing, builds, runs the quick-start sweep
# (configs/quickstart.yaml: MRPT icp-slam, MRPT rbpf-slam and the odometry baseline on MRPT's
# Telecom sample and a simulated floor plan, 3 iterations each) and prints where the report is.
# Extra arguments go to `slamsweep run` (e.g. --jobs 1, --output DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

"$root/scripts/install-deps.sh"
# The paper's roster from the pinned sources (../shared/peers when present, else upstream at the
# pinned commits), cached outside the clone: seconds when already built. The main job installs the
# whole roster (Cartographer's first build takes about 5 minutes on 2 cores), so configs/paper.yaml runs.
read -r -a roster <<< "${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector cartographer}"
"$root/scripts/install-slam.sh" "${roster[@]}"
"$root/scripts/build.sh"
slamsweep="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"

start=$(date +%s)
status=0
"$slamsweep" run "$root/configs/quickstart.yaml" "$@" || status=$?
echo "quickstart: sweep took $(( $(date +%s) - start )) s (exit code $status: 0 all runs ok, 1 some failed, 130 interrupted)"
exit $status
