#!/usr/bin/env bash
# A shard's "Programs" step: puts the programs of jobs/pack-programs.sh back at the absolute paths they
# were built at and checks every file against PROGRAMS.sha256, so that every shard runs the same binaries
# as the others. Several shards on one agent unpack the same archive: it goes to a fresh folder that is
# renamed into place, and a ROOT already there is only checked.
# Usage: jobs/unpack-programs.sh ARCHIVE
# Prints the unpacked slamsweep program's path as its last line ("programs: PATH").
# Exit code: 0 in place and checked; 2 bad arguments or a damaged archive; 5 ROOT holds other files.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# == 1)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/unpack-programs.sh ARCHIVE"
archive=$1
[[ -s "$archive" ]] || jobs_die "$JOBS_EXIT_USAGE" "$archive: missing or empty"
manifest=$(tar -tzf "$archive" | grep -m1 '/PROGRAMS.sha256$') ||
  jobs_die "$JOBS_EXIT_USAGE" "$archive: no PROGRAMS.sha256 (not made by jobs/pack-programs.sh)"
root=$(dirname "$manifest")
[[ "$root" == /* ]] || jobs_die "$JOBS_EXIT_USAGE" "$archive: members are not absolute paths"

if [[ ! -e "$root" ]]; then
  staging=$(mktemp -d "$(dirname "$root")/.unpack.XXXXXX" 2>/dev/null) || {
    mkdir -p "$(dirname "$root")"
    staging=$(mktemp -d "$(dirname "$root")/.unpack.XXXXXX")
  }
  tar -xzf "$archive" --absolute-names --transform="s|^$root|$staging|"
  # Another shard may have won the race: then its copy is checked like any other.
  mv -T "$staging" "$root" 2>/dev/null || rm -rf -- "$staging"
fi
if (cd "$root" && sha256sum --quiet --check PROGRAMS.sha256 >/dev/null 2>&1); then
  jobs_log "$root: every program file matches PROGRAMS.sha256"
else
  jobs_die 5 "$root: files differ from PROGRAMS.sha256 (another build left there?); remove it and unpack again"
fi
# The archive's own manifest must be the one on disk: a ROOT left by another build with its own
# consistent manifest is not this build.
if ! tar -xzOf "$archive" --absolute-names "$manifest" | cmp -s - "$root/PROGRAMS.sha256"; then
  jobs_die 5 "$root: holds the programs of another build; remove it and unpack again"
fi
echo "programs: $root/build/slamsweep"
