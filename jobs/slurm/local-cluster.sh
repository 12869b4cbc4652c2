#!/usr/bin/env bash
# A one-node Slurm cluster on localhost, for the Slurm executor's test and for trying
# `slamsweep run CONFIG --executor slurm` on one machine.
#
#   jobs/slurm/local-cluster.sh start|stop|status STATE_DIR
#
# Everything (slurm.conf, munge key and socket, spool dirs, pid files, logs) lives in STATE_DIR,
# so the cluster never touches /etc/slurm or a system munged. Needs root (slurmd runs jobs as
# their submitter) and the Debian packages slurm-wlm and munge. Afterwards point the clients at
# it with:  export SLURM_CONF=STATE_DIR/slurm.conf
#
# The node is this machine with its real CPUs and memory (`slurmd -C`). ProctrackType linuxproc
# and TaskPlugin none need no cgroups, so it works in containers and CI virtual machines.
# Ports: SLURM_LOCAL_PORT (slurmctld, default 6817) and that + 1 (slurmd).
set -euo pipefail

usage() { echo "usage: $0 start|stop|status STATE_DIR" >&2; exit 2; }
(($# == 2)) || usage
action=$1
[[ $action == start || $action == stop || $action == status ]] || usage
state=$2
mkdir -p "$state"
state=$(cd "$state" && pwd)
conf=$state/slurm.conf
ctld_port=${SLURM_LOCAL_PORT:-6817}
export SLURM_CONF=$conf

need() {
  local missing=()
  for program in "$@"; do command -v "$program" >/dev/null 2>&1 || missing+=("$program"); done
  if ((${#missing[@]} > 0)); then
    echo "local-cluster: missing ${missing[*]} (install the Debian packages slurm-wlm and munge)" >&2
    exit 3
  fi
}

pid_alive() { [[ -f $1 ]] && kill -0 "$(cat "$1")" 2>/dev/null; }

write_conf() {
  local host node_line cpus memory
  host=$(hostname -s)
  node_line=$(slurmd -C | head -n 1)
  cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$node_line")
  memory=$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$node_line")
  [[ -n $cpus && -n $memory ]] || { echo "local-cluster: cannot read CPUs/RealMemory from 'slurmd -C': $node_line" >&2; exit 1; }
  mkdir -p "$state/ctld" "$state/spool" "$state/log"
  cat >"$conf" <<EOF
# Written by jobs/slurm/local-cluster.sh: one node, no accounting database, no cgroups.
ClusterName=slamsweep-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$((ctld_port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$state/munge/munge.socket
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool/%n
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
# Cores only: without cgroups Slurm cannot enforce memory anyway (the worker enforces
# memory_limit_mb on its program); --mem is still checked against RealMemory.
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
ReturnToService=2
# Finished jobs stay visible to scontrol (the executor's source of states without accounting).
MinJobAge=600
KillWait=10
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
}

start() {
  need munged slurmctld slurmd sinfo
  if pid_alive "$state/slurmctld.pid"; then echo "local-cluster: already running in $state"; return 0; fi
  write_conf
  mkdir -p "$state/munge"
  chmod 0700 "$state/munge"
  if [[ ! -f $state/munge/munge.key ]]; then
    head -c 1024 /dev/urandom >"$state/munge/munge.key"
    chmod 0400 "$state/munge/munge.key"
  fi
  # --force: root-owned state outside /etc/munge is fine for a throw-away test cluster.
  munged --force --socket="$state/munge/munge.socket" --key-file="$state/munge/munge.key" \
    --pid-file="$state/munge/munged.pid" --log-file="$state/log/munged.log" \
    --seed-file="$state/munge/munged.seed"
  slurmctld -f "$conf" -i
  slurmd -f "$conf"
  # Ready = the node is idle (it registered and the controller accepts jobs).
  for _ in $(seq 1 60); do
    if sinfo -h -o '%t' 2>/dev/null | grep -qx 'idle'; then
      echo "local-cluster: up ($(sinfo -h -o '%N %c CPUs %m MB')); export SLURM_CONF=$conf"
      return 0
    fi
    sleep 0.5
  done
  echo "local-cluster: the node did not become idle within 30 s; logs in $state/log" >&2
  tail -n 20 "$state/log/slurmctld.log" "$state/log/slurmd.log" >&2 || true
  stop
  exit 1
}

stop_daemon() {
  local pid_file=$1
  pid_alive "$pid_file" || { rm -f "$pid_file"; return 0; }
  local pid
  pid=$(cat "$pid_file")
  kill -TERM "$pid" 2>/dev/null || true
  for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || { rm -f "$pid_file"; return 0; }; sleep 0.2; done
  kill -KILL "$pid" 2>/dev/null || true
  rm -f "$pid_file"
}

stop() {
  # Jobs first: slurmd stopping does not end the tasks it started.
  if pid_alive "$state/slurmctld.pid" && command -v scancel >/dev/null; then
    scancel --full --quiet --partition=local 2>/dev/null || true
  fi
  stop_daemon "$state/slurmd.pid"
  stop_daemon "$state/slurmctld.pid"
  stop_daemon "$state/munge/munged.pid"
  echo "local-cluster: stopped ($state)"
}

status() {
  local all_up=0
  for daemon in munge/munged slurmctld slurmd; do
    if pid_alive "$state/$daemon.pid"; then echo "${daemon##*/}: running"; else echo "${daemon##*/}: stopped"; all_up=1; fi
  done
  ((all_up == 0)) && sinfo
  return $all_up
}

case $action in
  start) start ;;
  stop) stop ;;
  status) status ;;
  *) usage ;;
esac
