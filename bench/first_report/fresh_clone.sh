#!/usr/bin/env bash
# The first hour of a new user, timed: a fresh debian:12 container (no package, no cache, 2 cores of
# this machine) clones the repository and runs the README's main command (scripts/quickstart.sh:
# packages, build, quick-start sweep) to the report. Prints each step's time and the total.
#
# usage: bench/first_report/fresh_clone.sh [OUT_DIR]      (default out/first-report)
#   The checkout's committed HEAD is what is cloned (uncommitted edits are not). The shared data folder
#   (../shared or SLAMSWEEP_SHARED) is mounted read-only beside the clone, as on a user's machine.
#   Needs a Docker daemon (docker/daemon.sh starts a private one) and the base image (docker/build-base.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mkdir -p "${1:-$root/out/first-report}" && cd "${1:-$root/out/first-report}" && pwd)
shared=$(cd "${SLAMSWEEP_SHARED:-$root/../shared}" && pwd)
docker_client=/usr/bin/docker
eval "$("$root/docker/daemon.sh" start)"
"$root/docker/build-base.sh" debian:12 >/dev/null

# Inside: git (a user has it; timed anyway), the clone, the main command; each line stamped with the
# seconds since the container started.
cat >"$out/inside.sh" <<'INSIDE'
#!/bin/bash
set -euo pipefail
start=$(date +%s)
stamp() { while IFS= read -r line; do echo "[$(( $(date +%s) - start )) s] $line"; done; }
echo "step: git" | stamp
export DEBIAN_FRONTEND=noninteractive
{ apt-get update -q && apt-get install -y -q --no-install-recommends git ca-certificates; } >/dev/null 2>&1
echo "step: clone" | stamp
git clone -q /src /w/slamsweep
cd /w/slamsweep
echo "step: scripts/quickstart.sh" | stamp
scripts/quickstart.sh 2>&1 | stamp
echo "step: done" | stamp
INSIDE
chmod +x "$out/inside.sh"

# The sandbox's options of docker/compose.yaml, and systempaths=unconfined so that SLAM programs get a
# fresh /proc as on a machine of one's own.
start=$(date +%s)
"$docker_client" run --rm --network host \
  --security-opt "seccomp=$root/docker/seccomp-sandbox.json" --security-opt apparmor=unconfined \
  --security-opt systempaths=unconfined \
  -v "$root:/src:ro" -v "$shared:/w/shared:ro" -v "$out/inside.sh:/inside.sh:ro" debian:12 /inside.sh \
  >"$out/log.txt" 2>&1
total=$(($(date +%s) - start))
grep -E '^\[[0-9]+ s\] (step: |install-deps: |\[1/|sweep quickstart|report: |quickstart: )' "$out/log.txt" | cut -c1-160
echo "first_report: ${total} s from docker run to the report (log: $out/log.txt)"
