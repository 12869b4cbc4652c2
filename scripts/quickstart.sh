#!/usr/bin/env bash
# The main job: installs what is missing, builds, scores real SLAM outputs and prints
# where the results are. (The orchestrator issue turns this into the quick-start sweep.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${SLAMSWEEP_SHARED:-$root/../shared}
out=${SLAMSWEEP_OUTPUT:-$root/out/quickstart}

"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
slamsweep="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"

if [[ ! -d "$shared/reference" ]]; then
  echo "quickstart: $shared/reference is missing: it holds the real maps and trajectories this job scores." >&2
  echo "quickstart: put the shared/ folder beside the repository or set SLAMSWEEP_SHARED." >&2
  exit 2
fi
mkdir -p "$out"
maps=$shared/reference/maps
trajectories=$shared/reference/trajectories

echo "== paper map metrics of real MRPT SLAM maps (Telecom Faculty sample) =="
for name in telecom_icp telecom_rbpf; do
  "$slamsweep" eval map "$maps/$name.pgm" --unknown-value 205
  "$slamsweep" eval map "$maps/$name.pgm" --unknown-value 205 --json > "$out/$name.map_metrics.json"
  "$slamsweep" vectorize "$maps/$name.yaml" --threshold 75 -o "$out/$name.geojson" --json > "$out/$name.vector_stats.json"
  "$slamsweep" vectorize "$maps/$name.yaml" --threshold 75 -o "$out/$name.svg" > /dev/null
done

echo "== GMapping on the Intel Research Lab log against the corrected poses =="
"$slamsweep" eval ape "$trajectories/intel_corrected.tum" "$trajectories/intel_gmapping.tum" --align se3
"$slamsweep" eval ape "$trajectories/intel_corrected.tum" "$trajectories/intel_gmapping.tum" --align se3 --json > "$out/intel_gmapping.ape.json"
"$slamsweep" eval rpe "$trajectories/intel_corrected.tum" "$trajectories/intel_gmapping.tum" --delta 1 --delta-unit m --json > "$out/intel_gmapping.rpe_1m.json"

echo "== simulated floor plan: exact ground truth, noisy odometry, maps from both =="
"$slamsweep" data simulate -o "$out/simulated" --seed 1
"$slamsweep" data info "$out/simulated/sequence.rawlog"
"$slamsweep" eval ape "$out/simulated/ground_truth.tum" "$out/simulated/odometry.tum" --align se2
"$slamsweep" eval map "$out/simulated/floor_plan.yaml" --json > "$out/simulated/floor_plan.map_metrics.json"

echo
echo "quickstart: results are in $out"
