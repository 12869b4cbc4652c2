#!/usr/bin/env bash
# Configures and builds slamsweep into build/ (Release, warnings as errors).
# Usage: scripts/build.sh [extra cmake configure args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${SLAMSWEEP_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSLAMSWEEP_WERROR=ON "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
