#!/usr/bin/env bash
# Packs what the shards run from ROOT (jobs/build-programs.sh) into one archive for Jenkins' stash: the
# source tree without .git (configs, scripts, data the programs read), the programs of ROOT/build
# (slamsweep, its helpers and format modules, the roster's drivers with their configuration files) and
# the roster's install prefix. ROOT/PROGRAMS.sha256 lists every packed file's digest, so that an unpacked
# copy can be checked.
# Usage: jobs/pack-programs.sh ROOT ARCHIVE
# Exit code: 0 packed; 2 bad arguments; 4 ROOT holds no built slamsweep.
set -euo pipefail
# shellcheck source=jobs/lib.sh
source "$(dirname "$0")/lib.sh"

(($# == 2)) || jobs_die "$JOBS_EXIT_USAGE" "usage: jobs/pack-programs.sh ROOT ARCHIVE"
root=$1
archive=$2
[[ "$root" == /* ]] || jobs_die "$JOBS_EXIT_USAGE" "ROOT must be an absolute path, got '$root'"
jobs_require_files "$root/build/slamsweep"
cd "$root"
list=$(mktemp)
trap 'rm -f -- "$list"' EXIT
{
  find src -path src/.git -prune -o -path src/build -prune -o -type f -print
  find build -maxdepth 1 -type f \( -name 'slamsweep*' -o -name '*.so' \) -print
  [[ -d build/slam/bin ]] && find build/slam/bin -type f -print
} | LC_ALL=C sort >"$list"
xargs -d '\n' sha256sum <"$list" >PROGRAMS.sha256
echo PROGRAMS.sha256 >>"$list"
mkdir -p "$(dirname "$archive")"
archive=$(cd "$(dirname "$archive")" && pwd)/$(basename "$archive")
# Absolute member names: the programs go back to the very paths they were built at.
sed "s|^|$root/|" "$list" | tar -C / -czf "$archive" --absolute-names -T -
jobs_log "packed $(wc -l <"$list") files of $root into $archive"
