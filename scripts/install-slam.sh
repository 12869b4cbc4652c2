#!/usr/bin/env bash
# The slam_* variables come from the sourced recipe (scripts/slam/NAME.sh).
# shellcheck disable=SC2154
# Builds the SLAM roster from pinned upstream sources into a prefix the drivers
# (slam/<algorithm>/) build against and the adapters read their manifests from.
#
# usage: scripts/install-slam.sh [--prefix DIR] [--from DIR] [--packages-only] [NAME...]
#   NAME     gmapping slam-constructor breezyslam hector cartographer slam-toolbox lama (default: all of them)
#   --from   a folder holding the pinned tarballs (../shared/peers); each is checked against the
#            SHA-256 pinned in its recipe. Without it, and when ../shared/peers is absent, the
#            sources come from the upstream repository at the pinned commit (git verifies the commit).
#   --prefix default: <repo>/slam-prefix (ignored by git); SLAMSWEEP_SLAM_PREFIX overrides it.
#   --packages-only  only the Debian packages the recipes need (a machine that runs drivers built
#            elsewhere: the nightly's shards, jobs/unpack-programs.sh).
#
# Each upstream has a recipe, scripts/slam/<NAME>.sh: where it comes from, its licence, the Debian
# packages its build needs (installed through scripts/install-deps.sh) and slam_build, which builds
# the unpacked sources into a folder; files of ours a build uses (slam-toolbox's stand-in headers) sit in the
# recipe's folder scripts/slam/<NAME>/, which slam_build finds as $slam_files. Builds are cached outside the
# clone, in ${SLAMSWEEP_PEERS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/slamsweep/peers}/<NAME>-<tarball sha256:16>-<recipe sha256:8>,
# so CI on a fresh clone rebuilds nothing that a previous run built from the same tarball and recipe;
# a changed recipe (a patch, a flag, a file of its folder) is a new key, never a stale build. Installing
# copies the cached build to <prefix>/<NAME> and writes <prefix>/share/slamsweep/slam/<NAME>.json, the manifest the
# driver build and `slamsweep algorithms` read. Idempotent: an installed manifest with the same key
# is left alone.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
all_names=(gmapping slam-constructor breezyslam hector cartographer slam-toolbox lama)

prefix=${SLAMSWEEP_SLAM_PREFIX:-$root/slam-prefix}
from=""
packages_only=0
names=()
while (($# > 0)); do
  case "$1" in
    --prefix) prefix=${2:?--prefix needs a folder}; shift 2 ;;
    --from) from=${2:?--from needs a folder}; shift 2 ;;
    --packages-only) packages_only=1; shift ;;
    -h|--help) sed -n '4,25p' "$0"; exit 0 ;;
    -*) echo "install-slam: unknown option '$1' (expected --prefix DIR, --from DIR, NAME...)" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
((${#names[@]} > 0)) || names=("${all_names[@]}")
if [[ -z "$from" && -d "$root/../shared/peers" ]]; then
  from=$(cd "$root/../shared/peers" && pwd)
fi
cache=${SLAMSWEEP_PEERS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/slamsweep/peers}
mkdir -p "$prefix/share/slamsweep/slam" "$cache"
prefix=$(cd "$prefix" && pwd)

# Fetches the sources of the sourced recipe into $1 (an empty folder) and prints the tarball's SHA-256.
fetch_sources() {
  local dest=$1
  if [[ -n "$from" ]]; then
    local tarball="$from/$slam_tarball"
    [[ -f "$tarball" ]] || { echo "install-slam: $slam_name: $tarball missing (expected the pinned snapshot from ${slam_upstream})" >&2; return 1; }
    local sum
    sum=$(sha256sum "$tarball" | cut -d' ' -f1)
    if [[ "$sum" != "$slam_sha256" ]]; then
      echo "install-slam: $slam_name: $tarball has SHA-256 $sum, expected $slam_sha256 (the pinned snapshot of $slam_upstream at $slam_commit)" >&2
      return 1
    fi
    tar -xzf "$tarball" -C "$dest" --strip-components=1
    echo "$sum"
  else
    echo "install-slam: $slam_name: no tarball folder; cloning $slam_upstream at $slam_commit" >&2
    git clone --quiet "$slam_upstream" "$dest/.clone" >&2
    git -C "$dest/.clone" -c advice.detachedHead=false checkout --quiet "$slam_commit" >&2
    git -C "$dest/.clone" archive --format=tar "$slam_commit" | tar -xf - -C "$dest"
    rm -rf "$dest/.clone"
    echo "git-$slam_commit"
  fi
}

# The first 8 hex digits of the recipe's SHA-256; with a recipe folder, of the recipe's and each file's digest
# (sorted by path), so that an edit of a stand-in header is a new build.
recipe_checksum() {
  local recipe=$1 folder=$2
  if [[ ! -d "$folder" ]]; then
    sha256sum "$recipe" | cut -c1-8
    return
  fi
  { sha256sum "$recipe" | cut -d' ' -f1
    (cd "$folder" && find . -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum)
  } | sha256sum | cut -c1-8
}

install_one() {
  local name=$1 recipe="$root/scripts/slam/$1.sh"
  [[ -f "$recipe" ]] || { echo "install-slam: unknown algorithm '$name' (expected one of: ${all_names[*]})" >&2; return 2; }
  # shellcheck source=/dev/null
  source "$recipe"
  local recipe_sum manifest key
  slam_files="$root/scripts/slam/$name"
  if ((packages_only)); then
    ((${#slam_packages[@]} == 0)) || "$root/scripts/install-deps.sh" "${slam_packages[@]}"
    return 0
  fi
  recipe_sum=$(recipe_checksum "$recipe" "$slam_files")
  key="$name-${slam_sha256:0:16}-$recipe_sum"
  manifest="$prefix/share/slamsweep/slam/$name.json"
  if [[ -f "$manifest" ]] && grep -q "\"key\": \"$key\"" "$manifest" && [[ -d "$prefix/$name" ]]; then
    echo "install-slam: $name up to date ($key)"
    return 0
  fi
  ((${#slam_packages[@]} == 0)) || "$root/scripts/install-deps.sh" "${slam_packages[@]}"
  local built="$cache/$key" seconds=0
  if [[ ! -f "$built/.complete" ]]; then
    local work
    work=$(mktemp -d "$cache/.build-$name-XXXXXX")
    mkdir -p "$work/src" "$work/out"
    local sum start
    sum=$(fetch_sources "$work/src")
    if [[ "$sum" != "$slam_sha256" && "$sum" != "git-$slam_commit" ]]; then
      echo "install-slam: $name: unexpected source checksum $sum" >&2
      return 1
    fi
    start=$(date +%s)
    echo "install-slam: building $name from ${slam_tarball} (cache $built)"
    (cd "$work/src" && slam_build "$work/src" "$work/out")
    seconds=$(($(date +%s) - start))
    echo "$seconds" > "$work/out/.build-seconds"
    touch "$work/out/.complete"
    rm -rf "$built"
    mv "$work/out" "$built"
    rm -rf "$work"
    echo "install-slam: built $name in ${seconds} s"
  else
    echo "install-slam: $name from cache ($built)"
  fi
  seconds=$(cat "$built/.build-seconds")
  rm -rf "${prefix:?}/${name:?}"
  cp -a "$built" "$prefix/$name"
  cat > "$manifest" <<JSON
{
  "name": "$name",
  "key": "$key",
  "upstream": "$slam_upstream",
  "commit": "$slam_commit",
  "license": "$slam_license",
  "tarball": "$slam_tarball",
  "tarball_sha256": "$slam_sha256",
  "recipe_sha256_8": "$recipe_sum",
  "build_seconds": $seconds,
  "root": "$prefix/$name"
}
JSON
  echo "install-slam: installed $name into $prefix/$name"
}

for name in "${names[@]}"; do
  # A subshell per recipe keeps one recipe's variables and functions out of the next.
  (install_one "$name")
done
