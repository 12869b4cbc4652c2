#!/usr/bin/env bash
# Configures and builds slamsweep into build/ (Release, warnings as errors).
# Usage: scripts/build.sh [extra cmake configure args...]
# SLAMSWEEP_BUILD_TARGETS (space-separated) builds only those targets, e.g. "slamsweep" for the programs
# alone (the main job); unset, everything: tests, benchmarks and the drivers of the installed roster.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${SLAMSWEEP_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSLAMSWEEP_WERROR=ON "$@" >/dev/null
targets=()
[[ -n "${SLAMSWEEP_BUILD_TARGETS:-}" ]] && read -r -a targets <<< "$SLAMSWEEP_BUILD_TARGETS"
if ((${#targets[@]} > 0)); then
  cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"
else
  cmake --build "$build_dir" -j "$(nproc)"
fi
