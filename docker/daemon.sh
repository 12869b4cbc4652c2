#!/usr/bin/env bash
# Starts or stops a private Docker daemon for scripts that build and run slamsweep's image on a
# machine whose own daemon is not running (a CI agent, a developer's container).
#
# usage: eval "$(docker/daemon.sh start [SCRATCH])"    sets DOCKER_HOST, and SLAMSWEEP_DOCKER_STARTED=1
#                                                     when it started the daemon (else 0: reused)
#        docker/daemon.sh stop [SCRATCH]               stops it, unmounts what it left in SCRATCH
#        docker/daemon.sh status [SCRATCH]
#   SCRATCH  default: $SLAMSWEEP_DOCKER_SCRATCH, else ${XDG_CACHE_HOME:-$HOME/.cache}/slamsweep/docker.
#            data/ (images, layers: kept between runs, the layer cache) and exec/ (sockets, mounts).
#
# `start` reuses a daemon that already answers (DOCKER_HOST, else /var/run/docker.sock) and prints
# the variables to reach it; only when none answers does it start dockerd with its data and exec roots
# in SCRATCH, the vfs storage driver (works on any file system, in a container too), no bridge and no
# iptables rules (nothing of the host's network is changed: containers and builds use --network host).
# `stop` stops only a daemon this script started (its pid file is in SCRATCH).
# Debian's client (/usr/bin/docker) is used: another one earlier on PATH may not match the daemon.
set -euo pipefail
docker_client=/usr/bin/docker

action=${1:-}
scratch=${2:-${SLAMSWEEP_DOCKER_SCRATCH:-${XDG_CACHE_HOME:-$HOME/.cache}/slamsweep/docker}}
[[ -x "$docker_client" ]] || { echo "daemon.sh: $docker_client missing (apt-get install docker.io)" >&2; exit 1; }
# exec/ holds containerd's sockets, whose paths must stay under the 108 bytes of a socket address.
socket="$scratch/exec/docker.sock"
pid_file="$scratch/exec/dockerd.pid"
log_file="$scratch/dockerd.log"

answers() { "$docker_client" ${1:+-H "$1"} version --format '{{.Server.Version}}' >/dev/null 2>&1; }

# Mount points under SCRATCH, deepest first (containers' roots, netns files, shm).
mounts_under() {
  awk -v prefix="$1/" '{ gsub(/\\040/, " ", $5); if (index($5, prefix) == 1) print $5 }' /proc/self/mountinfo |
    awk '{ print length($0) " " $0 }' | sort -rn | cut -d' ' -f2-
}

start() {
  if [[ -n "${DOCKER_HOST:-}" ]] && answers "$DOCKER_HOST"; then
    echo "daemon.sh: reusing the daemon at $DOCKER_HOST" >&2
    echo "export DOCKER_HOST=$DOCKER_HOST SLAMSWEEP_DOCKER_STARTED=0"
    return
  fi
  if answers "unix:///var/run/docker.sock"; then
    echo "daemon.sh: reusing the daemon at /var/run/docker.sock" >&2
    echo "export DOCKER_HOST=unix:///var/run/docker.sock SLAMSWEEP_DOCKER_STARTED=0"
    return
  fi
  if [[ -f "$pid_file" ]] && kill -0 "$(cat "$pid_file")" 2>/dev/null && answers "unix://$socket"; then
    echo "daemon.sh: reusing the private daemon at $socket" >&2
    echo "export DOCKER_HOST=unix://$socket SLAMSWEEP_DOCKER_STARTED=0"
    return
  fi
  command -v dockerd >/dev/null || { echo "daemon.sh: dockerd missing (apt-get install docker.io)" >&2; exit 1; }
  [[ $(id -u) -eq 0 ]] || { echo "daemon.sh: starting a daemon needs root; none answers at /var/run/docker.sock" >&2; exit 1; }
  mkdir -p "$scratch/data" "$scratch/exec"
  echo "daemon.sh: starting a private daemon (data $scratch/data, log $log_file)" >&2
  # setsid: the daemon outlives this script (stop ends it), in its own session so a caller's Ctrl-C
  # reaches the build, not the daemon.
  setsid dockerd --data-root "$scratch/data" --exec-root "$scratch/exec" --pidfile "$pid_file" \
    --host "unix://$socket" --storage-driver vfs --iptables=false --ip-masq=false --bridge=none \
    </dev/null >"$log_file" 2>&1 &
  local waited=0
  until answers "unix://$socket"; do
    if ! kill -0 $! 2>/dev/null; then
      echo "daemon.sh: dockerd exited at start; the end of $log_file:" >&2
      tail -n 20 "$log_file" >&2
      exit 1
    fi
    ((waited++ < 60)) || { echo "daemon.sh: dockerd did not answer within 60 s (see $log_file)" >&2; exit 1; }
    sleep 1
  done
  echo "export DOCKER_HOST=unix://$socket SLAMSWEEP_DOCKER_STARTED=1"
}

stop() {
  if [[ ! -f "$pid_file" ]]; then
    echo "daemon.sh: no private daemon in $scratch (nothing to stop)" >&2
  else
    local pid
    pid=$(cat "$pid_file")
    if kill -0 "$pid" 2>/dev/null; then
      kill -TERM "$pid"
      # dockerd stops its containers (10 s each at most) and its containerd before it exits.
      local waited=0
      while kill -0 "$pid" 2>/dev/null && ((waited++ < 60)); do sleep 1; done
      if kill -0 "$pid" 2>/dev/null; then
        echo "daemon.sh: dockerd $pid still running after 60 s; killing it" >&2
        kill -KILL "$pid"
      fi
    fi
    rm -f "$pid_file"
    echo "daemon.sh: stopped the private daemon" >&2
  fi
  local mount_point
  while IFS= read -r mount_point; do
    [[ -n "$mount_point" ]] || continue
    umount "$mount_point" 2>/dev/null || umount -l "$mount_point"
  done < <(mounts_under "$scratch")
}

status() {
  if [[ -f "$pid_file" ]] && kill -0 "$(cat "$pid_file")" 2>/dev/null; then
    echo "private daemon $(cat "$pid_file") at unix://$socket"
  else
    echo "no private daemon in $scratch"
  fi
  local left
  left=$(mounts_under "$scratch" | wc -l)
  echo "$left mounts under $scratch"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  status) status ;;
  *) echo "usage: docker/daemon.sh start|stop|status [SCRATCH]" >&2; exit 2 ;;
esac
