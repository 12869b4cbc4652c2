#!/usr/bin/env bash
# Whole-process cost of rejecting the five mutated MRPT rawlogs of ../shared/fuzz/rawlog-mutants (which once
# took 2.3-2.5 GB and 12-16 s each): `slamsweep data info MUTANT --json`, wall time and peak RSS by GNU time
# (/usr/bin/time -v; the peak RSS counts the reading child, which the program waits for), the median of --runs
# runs. Targets: each under 1 s and 100 MB, and rejected (exit 2). CPU seconds (user + system, the child's
# included) are shown beside the wall time: on a loaded machine the wall time is mostly waiting for a core.
#
# usage: bench/hostile/rawlog_mutants.sh [--runs N] [--check] [SLAMSWEEP_BINARY]
#   --check  exit 3 when a mutant misses a target (a nightly job fails on it); else the exit status is 0
# Needs ../shared (or $SLAMSWEEP_SHARED) with fuzz/rawlog-mutants/; exit 2 without it.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=5
check=0
binary="${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --check) check=1; shift ;;
    -*) echo "rawlog_mutants.sh: unexpected option '$1'" >&2; exit 2 ;;
    *) binary=$1; shift ;;
  esac
done
[[ -x "$binary" ]] || { echo "rawlog_mutants.sh: $binary: not an executable" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "rawlog_mutants.sh: /usr/bin/time (GNU time) is missing" >&2; exit 2; }
mutants="${SLAMSWEEP_SHARED:-$root/../shared}/fuzz/rawlog-mutants"
[[ -d "$mutants" ]] || { echo "rawlog_mutants.sh: $mutants is missing (set SLAMSWEEP_SHARED)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf -- "$work"' EXIT
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }
missed=0
echo "| mutant | wall s (median of $runs) | CPU s (median) | peak RSS MB (median) | exit | met (< 1 s, < 100 MB, exit 2) |"
echo "|---|---|---|---|---|---|"
for mutant in "$mutants"/*.rawlog; do
  : >"$work/wall" && : >"$work/cpu" && : >"$work/rss"
  status=0
  for ((i = 0; i < runs; ++i)); do
    status=0
    /usr/bin/time -v -o "$work/time" "$binary" data info "$mutant" --json >/dev/null 2>"$work/stderr" || status=$?
    # GNU time exits with the program's status; its report says how long and how much.
    awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' \
      "$work/time" >>"$work/wall"
    awk -F': ' '/User time|System time/ {s += $2} END {print s}' "$work/time" >>"$work/cpu"
    awk -F': ' '/Maximum resident set size/ {print $2 / 1024}' "$work/time" >>"$work/rss"
  done
  wall=$(median <"$work/wall")
  cpu=$(median <"$work/cpu")
  rss=$(median <"$work/rss")
  met=yes
  if ! awk -v w="$wall" -v r="$rss" 'BEGIN {exit !(w < 1 && r < 100)}' || [[ "$status" != 2 ]]; then
    met=NO
    missed=1
  fi
  printf '| %s | %.3f | %.3f | %.1f | %s | %s |\n' "$(basename "$mutant")" "$wall" "$cpu" "$rss" "$status" "$met"
  [[ "$status" == 2 ]] || sed 's/^/    /' "$work/stderr" >&2
done
echo "binary: $binary; $(nproc) cores; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
if ((check && missed)); then exit 3; fi
exit 0
