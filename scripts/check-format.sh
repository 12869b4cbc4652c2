#!/usr/bin/env bash
# Checks (or with --fix, applies) the C++ layout of .clang-format on every source file of the repository.
# Exit status 1 names each file whose layout differs. Used by the ctest `source_format`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(find evaluator orchestrator report cli slam tests bench -type f \( -name '*.h' -o -name '*.cc' \) | sort)
if [[ "${1:-}" == "--fix" ]]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
clang-format --dry-run --Werror --style=file "${files[@]}" 2>&1 | grep -o '^[^:]*:[0-9]*:' | sort -u -t: -k1,1 || true
clang-format --dry-run --Werror --style=file "${files[@]}" >/dev/null 2>&1
