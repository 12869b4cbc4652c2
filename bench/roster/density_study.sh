#!/usr/bin/env bash
# Cartographer (the roster's upstream options) on the dense intel at three densities: the dense log
# written back as a raw CARMEN log, then with every 2nd and every 3rd scan dropped (every odometry
# reading kept), each scored against Kuemmerle's relations. Measures how much of Cartographer's gap to
# its published intel figure the data's density explains.
# usage: bench/roster/density_study.sh [OUTPUT_DIR] [slamsweep run options]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$(mktemp -d "${TMPDIR:-/tmp}/density-study-XXXXXX")}
[[ $# -gt 0 ]] && shift
slamsweep="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"
shared="${SLAMSWEEP_SHARED:-$root/../shared}"
mkdir -p "$out"
cd "$root"  # the catalog name intel-dense resolves from configs/datasets.yaml
"$slamsweep" data convert intel-dense --to carmen -o "$out/intel-dense-every1.log"
for keep in 2 3; do
  # Drops laser records; every ODOM line stays, so the odometry the program reads is unchanged.
  awk -v keep="$keep" '/^ROBOTLASER1/ { if (n++ % keep) next } { print }' \
    "$out/intel-dense-every1.log" > "$out/intel-dense-every$keep.log"
done
{
  echo "sequences:"
  for keep in 1 2 3; do
    cat <<ENTRY
  - name: dense-every$keep
    format: carmen
    path: $out/intel-dense-every$keep.log
    ground_truth: relations_only
    relations: $shared/datasets/intel/intel.relations
    relations_offset_s: -976052857.337
ENTRY
  done
} > "$out/catalog.yaml"
cat > "$out/sweep.yaml" <<SWEEP
name: density-study
output: $out/results
catalog: $out/catalog.yaml
iterations: 1
seed: 2017
evaluation: {align: se2, rpe_delta_m: 1.0, t_max_diff_s: 0.01, stages: 0, map_resolution_m: 0.1}
algorithms:
  - {name: cartographer, adapter: cartographer, timeout_s: 3600, memory_limit_mb: 8192}
  - {name: odometry, adapter: odometry, timeout_s: 300}
sequences: [dense-every1, dense-every2, dense-every3]
noise:
  - name: none
SWEEP
status=0
"$slamsweep" run "$out/sweep.yaml" --no-report "$@" || status=$?
echo "results: $out/results (summary.csv; sweep exit code $status)"
