#!/usr/bin/env bash
# The steps of docker/Dockerfile, one per RUN, kept here so that the Dockerfile stays a list of stages.
#
# usage: docker/image-steps.sh roster|slamsweep|runtime
#   roster     build stage: the packages slamsweep compiles against and the roster ($SLAMSWEEP_ROSTER)
#              from the tarballs staged in docker/peers (else cloned at the pinned commits)
#   slamsweep  build stage: builds slamsweep (with its tests when RUN_TESTS=1, running them) and
#              installs it with the roster's drivers into /stage/opt/slamsweep
#   runtime    runtime stage: the runtime packages (scripts/install-deps.sh --runtime) and the user
#              `slamsweep` that owns /results
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prefix=/opt/slamsweep

# Package lists and downloaded packages never stay in a layer.
clean_apt() { rm -rf /var/lib/apt/lists/* /var/cache/apt/*.bin /var/cache/apt/archives/*.deb; }

roster() {
  "$root/scripts/install-deps.sh" --build
  local from=()
  if compgen -G "$root/docker/peers/*.tar.gz" >/dev/null; then
    from=(--from "$root/docker/peers")
  else
    echo "image-steps: no tarballs in docker/peers (docker/build-image.sh stages them); cloning the upstreams"
    "$root/scripts/install-deps.sh" git ca-certificates
  fi
  # The build cache of install-slam.sh is this layer's scratch: only the installed prefix stays.
  local cache
  cache=$(mktemp -d)
  read -r -a names <<<"${SLAMSWEEP_ROSTER:-gmapping slam-constructor hector cartographer slam-toolbox lama}"
  SLAMSWEEP_PEERS_CACHE=$cache "$root/scripts/install-slam.sh" "${from[@]}" "${names[@]}"
  rm -rf "$cache"
  clean_apt
}

slamsweep() {
  local build_dir=${SLAMSWEEP_BUILD_DIR:-$root/build}
  if [[ "${RUN_TESTS:-0}" == 1 ]]; then
    "$root/scripts/test.sh"
  else
    "$root/scripts/build.sh" -DSLAMSWEEP_BUILD_TESTS=OFF -DSLAMSWEEP_BUILD_BENCHMARKS=OFF
  fi
  DESTDIR=/stage cmake --install "$build_dir" --prefix "$prefix" --strip >/dev/null
  # The objects are not needed once installed; without them the layer is smaller.
  rm -rf "$build_dir"
  clean_apt
  echo "image-steps: installed slamsweep $("/stage$prefix/bin/slamsweep" --version) into $prefix"
}

runtime() {
  "$root/scripts/install-deps.sh" --runtime
  # Sweeps run as an unprivileged user; the results volume is theirs.
  useradd --system --uid 10001 --user-group --create-home --home-dir /home/slamsweep --shell /usr/sbin/nologin slamsweep
  mkdir -p /results /data
  chown slamsweep:slamsweep /results
  clean_apt
  rm -rf "$root"
}

case "${1:-}" in
  roster) roster ;;
  slamsweep) slamsweep ;;
  runtime) runtime ;;
  *) echo "usage: docker/image-steps.sh roster|slamsweep|runtime" >&2; exit 2 ;;
esac
