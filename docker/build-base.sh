#!/usr/bin/env bash
# Makes the base image docker/Dockerfile starts from (debian:12) available to the daemon: nothing to
# do when it is there or can be pulled; otherwise (no registry reachable) it is built with debootstrap
# (minbase variant of bookworm) from the Debian mirror this machine's apt uses and imported under
# that tag, so the Dockerfile is the same on every machine.
#
# usage: docker/build-base.sh [TAG]      (default debian:12; DOCKER_HOST says which daemon)
#   SLAMSWEEP_DEBIAN_MIRROR    the mirror for debootstrap and the image's apt (default: this machine's)
#   SLAMSWEEP_DEBIAN_SECURITY  its security mirror (default: this machine's, else deb.debian.org's)
# Needs root and debootstrap (apt-get install debootstrap); about 1.5 minutes.
set -euo pipefail
docker_client=/usr/bin/docker
tag=${1:-debian:12}

if "$docker_client" image inspect "$tag" >/dev/null 2>&1; then
  echo "build-base: $tag is there"
  exit 0
fi
if "$docker_client" pull "$tag" >/dev/null 2>&1; then
  echo "build-base: pulled $tag"
  exit 0
fi
echo "build-base: $tag cannot be pulled; building it with debootstrap"
command -v debootstrap >/dev/null || { echo "build-base: debootstrap missing (apt-get install debootstrap)" >&2; exit 1; }
[[ $(id -u) -eq 0 ]] || { echo "build-base: debootstrap needs root" >&2; exit 1; }

# The first URI of this machine's apt sources that serves Debian (not its security archive).
configured_mirror() {
  local kind=$1
  {
    grep -hE '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{ for (i = 2; i <= NF; ++i) print $i }'
    grep -hE '^deb ' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
      sed -E 's/^deb (\[[^]]*\] )?//' | awk '{ print $1 }'
  } | if [[ "$kind" == security ]]; then grep -E '/debian-security/?$'; else grep -E '/debian/?$'; fi | head -n 1 || true
}
mirror=${SLAMSWEEP_DEBIAN_MIRROR:-$(configured_mirror main)}
mirror=${mirror:-http://deb.debian.org/debian}
security=${SLAMSWEEP_DEBIAN_SECURITY:-$(configured_mirror security)}
security=${security:-http://deb.debian.org/debian-security}

root=$(mktemp -d "${TMPDIR:-/tmp}/slamsweep-base-XXXXXX")
chmod 755 "$root"  # the image's / (mktemp made it 700: apt's _apt user could not enter it)
trap 'rm -rf "$root"' EXIT
start=$(date +%s)
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.log" 2>&1 ||
  { echo "build-base: debootstrap failed; the end of its log:" >&2; tail -n 20 "$root.log" >&2; rm -f "$root.log"; exit 1; }
rm -f "$root.log"

# apt inside the image: the main archive with its updates and the security archive, as Debian's image.
rm -f "$root/etc/apt/sources.list"
cat > "$root/etc/apt/sources.list.d/debian.sources" <<SOURCES
Types: deb
URIs: $mirror
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb
URIs: $security
Suites: bookworm-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
# No downloaded packages or package lists in the image: every Dockerfile step runs apt-get update.
rm -rf "$root"/var/cache/apt/archives/*.deb "$root"/var/cache/apt/*.bin "$root"/var/lib/apt/lists/*
tar --numeric-owner -C "$root" -c . | "$docker_client" import --change 'CMD ["bash"]' - "$tag" >/dev/null
echo "build-base: built $tag from $mirror in $(($(date +%s) - start)) s"
