#!/usr/bin/env bash
# The independent side of the ROS 2 bag tests (tests/evaluator/formats/rosbag2): foxglove's MCAP reader and
# writer (@mcap/core, @mcap/support), ROS 2 message definitions and CDR (@foxglove/rosmsg,
# @foxglove/rosmsg2-serialization), zstd and lz4 (@foxglove/wasm-zstd, @foxglove/wasm-lz4, lz4js), pinned by
# the package-lock.json beside tests/evaluator/formats/rosbag2/bag_tools/bag_tool.cjs (every package's version and
# integrity hash). Installed with `npm ci` outside the clone, in ~/.cache/slamsweep/bag-tools-<lock hash>, so a
# fresh clone reuses it; prints the folder that holds node_modules. Needs Node.js >= 20 and npm (Debian's when
# none is installed). Idempotent: fast when everything is present.
# Usage: scripts/install-bag-tools.sh [--check]   (--check: print the folder if installed, else exit 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tools=$root/tests/evaluator/formats/rosbag2/bag_tools
hash=$(cat "$tools/package.json" "$tools/package-lock.json" | sha256sum | cut -c1-16)
prefix=${SLAMSWEEP_CACHE_DIR:-$HOME/.cache/slamsweep}/bag-tools-$hash
if [[ "${1:-}" == --check ]]; then
  [[ -f "$prefix/node_modules/.installed" ]] && command -v node >/dev/null && echo "$prefix" && exit 0
  exit 1
fi
if ! command -v npm >/dev/null; then
  "$root/scripts/install-deps.sh" nodejs npm >&2
fi
if [[ ! -f "$prefix/node_modules/.installed" ]]; then
  rm -rf "$prefix"
  mkdir -p "$prefix"
  cp "$tools/package.json" "$tools/package-lock.json" "$prefix/"
  (cd "$prefix" && npm ci --no-audit --no-fund --loglevel=error >&2)
  touch "$prefix/node_modules/.installed"
fi
echo "$prefix"
