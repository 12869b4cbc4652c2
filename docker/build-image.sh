#!/usr/bin/env bash
# Builds slamsweep's image from this checkout without reaching a registry or the upstream repositories:
# stages the roster's pinned tarballs into docker/peers, makes the base image (docker/build-base.sh)
# and runs `docker build` on docker/Dockerfile with host networking (the Debian mirror is reached
# from the build steps; a daemon without a bridge has no other network).
#
# usage: docker/build-image.sh [TAG] [docker build options...]     (default TAG slamsweep:latest)
#   SLAMSWEEP_PEERS  the folder of pinned tarballs (default ../shared/peers beside the repository)
#   DOCKER_HOST      the daemon (docker/daemon.sh start prints it)
#   SLAMSWEEP_DOCKER_INSTALLED=PREFIX  a developer's shortcut: the Dockerfile's runtime stage alone, with
#                    PREFIX (a `cmake --install` of this checkout on a Debian 12 host) in place of the build
#                    stage's /opt/slamsweep. Its instructions are the runtime stage's, so they share its layers.
# Prints the build's duration; docker build's own output goes to stdout, each line with its time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
docker_client=/usr/bin/docker
tag=${1:-slamsweep:latest}
shift || true

installed=${SLAMSWEEP_DOCKER_INSTALLED:-}
if [[ -n "$installed" ]]; then
  [[ -x "$installed/bin/slamsweep" ]] || { echo "build-image: $installed/bin/slamsweep missing (cmake --install)" >&2; exit 1; }
  "$root/docker/build-base.sh" "$(sed -n 's/^ARG BASE=//p' "$root/docker/Dockerfile")"
  context=$(mktemp -d)
  trap 'rm -rf "$context"' EXIT
  mkdir -p "$context/scripts" "$context/docker"
  cp "$root/scripts/install-deps.sh" "$context/scripts/"
  cp "$root/docker/image-steps.sh" "$context/docker/"
  cp -a "$installed" "$context/installed"
  # The base argument, then the runtime stage with the installed tree copied from the context.
  { grep '^ARG BASE=' "$root/docker/Dockerfile"
    sed -n '/^FROM .* AS runtime$/,$p' "$root/docker/Dockerfile" |
      sed 's|^COPY --from=build /stage/opt/slamsweep/ /opt/slamsweep/$|COPY installed/ /opt/slamsweep/|'
  } >"$context/Dockerfile"
  grep -q '^COPY installed/' "$context/Dockerfile" || { echo "build-image: no COPY --from=build line in the runtime stage" >&2; exit 1; }
  start=$(date +%s)
  "$docker_client" build --network host -t "$tag" "$@" "$context" 2>&1 |
    while IFS= read -r line; do printf '%(%H:%M:%S)T %s\n' -1 "$line"; done
  echo "build-image: built $tag (runtime stage with $installed) in $(($(date +%s) - start)) s"
  exit 0
fi

# The tarball each recipe pins, copied into the build context (install-slam.sh checks its SHA-256).
peers=${SLAMSWEEP_PEERS:-$root/../shared/peers}
staged=0
for recipe in "$root"/scripts/slam/*.sh; do
  tarball=$(sed -n 's/^slam_tarball=//p' "$recipe")
  if [[ -f "$peers/$tarball" ]]; then
    cmp -s "$peers/$tarball" "$root/docker/peers/$tarball" || cp "$peers/$tarball" "$root/docker/peers/$tarball"
    chmod 644 "$root/docker/peers/$tarball"
    staged=$((staged + 1))
  fi
done
if ((staged == 0)); then
  echo "build-image: no pinned tarballs in $peers; the build clones the upstreams at the pinned commits"
fi

"$root/docker/build-base.sh" "$(sed -n 's/^ARG BASE=//p' "$root/docker/Dockerfile")"

# The checkout's revision, recorded by every run (the build context has no .git). A file rather than a
# build argument: an argument would be one more instruction, a full layer copy with vfs.
revision=$(git -C "$root" describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
echo "$revision" >"$root/docker/revision"
start=$(date +%s)
# Each line of docker build's output with the time it came: how long each step took, in the log.
"$docker_client" build --network host -f "$root/docker/Dockerfile" -t "$tag" "$@" "$root" 2>&1 |
  while IFS= read -r line; do printf '%(%H:%M:%S)T %s\n' -1 "$line"; done
echo "build-image: built $tag ($revision) in $(($(date +%s) - start)) s"
