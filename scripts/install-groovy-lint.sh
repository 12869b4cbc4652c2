#!/usr/bin/env bash
# npm-groovy-lint, the linter the tests run on the Jenkinsfiles (tests/jobs), pinned, with what it needs:
# Debian's Java runtime (it runs CodeNarc) and Node.js/npm (Debian's when none is installed).
# Installed outside the clone, in ~/.cache/slamsweep/npm-groovy-lint-<version>, so a fresh clone reuses
# it; prints the linter's path. Idempotent: fast when everything is present.
# Usage: scripts/install-groovy-lint.sh [--check]   (--check: print the path if installed, else exit 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# 14.x is the newest line that runs on Debian 12's Node.js 18.
version=14.6.0
prefix=${SLAMSWEEP_CACHE_DIR:-$HOME/.cache/slamsweep}/npm-groovy-lint-$version
linter=$prefix/node_modules/.bin/npm-groovy-lint
if [[ "${1:-}" == --check ]]; then
  [[ -x "$linter" ]] && command -v java >/dev/null && echo "$linter" && exit 0
  exit 1
fi
"$root/scripts/install-deps.sh" openjdk-17-jre-headless >&2
if ! command -v npm >/dev/null; then
  "$root/scripts/install-deps.sh" nodejs npm >&2
fi
if [[ ! -x "$linter" ]]; then
  mkdir -p "$prefix"
  npm install --prefix "$prefix" --no-audit --no-fund --loglevel=error "npm-groovy-lint@$version" >&2
fi
echo "$linter"
