#!/usr/bin/env bash
# Configures and builds slamsweep into build/ (Release, warnings as errors).
# Usage: scripts/build.sh [extra cmake configure args...]   (e.g. -DSLAMSWEEP_BUILD_TESTS=OFF)
# SLAMSWEEP_BUILD_TARGETS (space-separated) builds only those targets, e.g. "slamsweep" for the programs
# alone (the main job); unset, everything: tests, benchmarks and the drivers of the installed roster.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${SLAMSWEEP_BUILD_DIR:-$root/build}
# A compiler cache beside the roster's builds, outside the clone: a fresh clone (CI's) or another
# worktree compiles only what changed. Paths are taken relative to the clone, so its location does not matter.
launcher=()
if [[ -z "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]] && command -v ccache >/dev/null; then
  export CCACHE_DIR=${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/slamsweep/ccache}
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
  # Builds with line tables (-g1: the sanitizer and fuzz builds) would otherwise hash the build folder too, and
  # miss across worktrees; the cost is a debug-info compilation directory that may name another build folder.
  export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# Tests and benchmarks are configured unless the arguments turn them off (the later -D wins): the main job
# turns them off, and a later build in the same folder turns them on again.
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSLAMSWEEP_WERROR=ON \
  -DSLAMSWEEP_BUILD_TESTS=ON -DSLAMSWEEP_BUILD_BENCHMARKS=ON "${launcher[@]}" "$@" >/dev/null
targets=()
[[ -n "${SLAMSWEEP_BUILD_TARGETS:-}" ]] && read -r -a targets <<< "$SLAMSWEEP_BUILD_TARGETS"
if ((${#targets[@]} > 0)); then
  cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"
else
  cmake --build "$build_dir" -j "$(nproc)"
fi
