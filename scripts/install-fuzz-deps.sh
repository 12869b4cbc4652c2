#!/usr/bin/env bash
# Installs what the fuzzing build needs and nothing else uses (docs/hostile-input.md): Debian's clang 14 with
# its runtime libraries (libclang-rt-14-dev holds libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
# for clang) and llvm-14 (llvm-symbolizer names the source lines of a finding). The normal and the sanitizer
# builds use GCC and need none of it. Idempotent (scripts/install-deps.sh installs only what is missing).
set -euo pipefail
exec "$(dirname "$0")/install-deps.sh" clang-14 libclang-rt-14-dev llvm-14
