#!/usr/bin/env bash
# Checks (or with --fix, applies) the C++ layout of .clang-format on every source file of the repository.
# Exit status 1 names each file whose layout differs. Used by the ctest `source_format`. The check compares
# clang-format's output with the file (its --dry-run also reports no-op edits on C++20 inline namespace comments).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(find evaluator orchestrator report cli slam tests bench -type f \( -name '*.h' -o -name '*.cc' \) | sort)
if [[ "${1:-}" == "--fix" ]]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
status=0
for file in "${files[@]}"; do
  if ! clang-format --style=file "$file" | cmp -s - "$file"; then
    echo "$file: not in the .clang-format layout (scripts/check-format.sh --fix)"
    status=1
  fi
done
exit $status
