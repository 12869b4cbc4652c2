#!/usr/bin/env bash
# Whole-process speed and memory of the slamsweep program (its targets are in the table below): start to exit,
# measured by hyperfine (median of --runs runs after 3 warm-up runs) and peak RSS by GNU time
# (median of --runs runs). Inputs are synthetic (bench/cli/make_inputs.py, no ../shared); the
# worker case needs ../shared/datasets/intel and is skipped without it.
#
# usage: bench/cli/cli_bench.sh [--runs N] [--out DIR] [--only REGEX] [--check] [LABEL=BINARY ...]
#   LABEL=BINARY  programs to compare, one column each (default: after=build/slamsweep), e.g.
#                 before=/tmp/before-slamsweep after=build/slamsweep
#   --out DIR     where inputs, hyperfine JSON, table.md and summary.json go (default build/bench-cli)
#   --only REGEX  only the cases whose name matches
#   --check       exit 3 when the last program misses a target (a nightly performance job fails on a
#                 regression); without it the table is written and the exit status is 0
# The `eval map` cases run on one core (taskset -c 0), as their target says.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=10
out="${SLAMSWEEP_BUILD_DIR:-$root/build}/bench-cli"
only=""
check=()
programs=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --check) check=(--check); shift ;;
    *=*) programs+=("$1"); shift ;;
    *) echo "cli_bench.sh: unexpected argument '$1' (see the usage at the top of the script)" >&2; exit 2 ;;
  esac
done
[[ ${#programs[@]} -gt 0 ]] || programs=("after=${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep")
for i in "${!programs[@]}"; do
  binary=${programs[$i]#*=}
  [[ -x "$binary" ]] || { echo "cli_bench.sh: $binary: not an executable" >&2; exit 2; }
  programs[i]="${programs[i]%%=*}=$(realpath "$binary")"  # the cases run in the inputs folder
done
command -v hyperfine >/dev/null || { echo "cli_bench.sh: hyperfine missing (apt install hyperfine)" >&2; exit 2; }

out=$(realpath -m -- "$out")  # the cases run inside the inputs folder
inputs="$out/inputs"
mkdir -p "$out"
shared=${SLAMSWEEP_SHARED:-$root/../shared}

# name | target ms ("half:B": at most half the first program's with two programs, else half of B, the
# median of the build of 3f81ea1, measured with this script) | target MB | arguments (run in $inputs;
# {root} is the repository)
cases=(
  "version|10|15|--version"
  "plan|10|15|plan {root}/configs/quickstart.yaml"
  "eval-ape-1k|10|15|eval ape tum-1000-ref.tum tum-1000-est.tum --align se3"
  "eval-rpe-1k|10|15|eval rpe tum-1000-ref.tum tum-1000-est.tum --delta 1 --delta-unit m"
  "eval-map-200|10|15|eval map map-200.yaml"
  "eval-ape-se3-100k|50|-|eval ape tum-100000-ref.tum tum-100000-est.tum --align se3"
  "eval-ape-se3-1M|500|-|eval ape tum-1000000-ref.tum tum-1000000-est.tum --align se3"
  "eval-rpe-1m-100k|80|-|eval rpe tum-100000-ref.tum tum-100000-est.tum --delta 1 --delta-unit m"
  "eval-map-2000|60|-|eval map map-2000.yaml"
  "eval-map-2000-png|-|-|eval map map-2000.png --unknown-value 205"
  "worker-odometry-intel-300|half:255.8|-|worker {rundir}"
)

# One prepared run folder per program for the worker case (the worker rewrites everything but run.json).
prepare_worker_run() {
  local label=$1 binary=$2 sweep_out="$out/worker-$1"
  if [[ ! -f "$sweep_out/runs.csv" ]]; then
    rm -rf "$sweep_out"
    "$binary" run "$root/bench/cli/worker_odometry_intel.yaml" --output "$sweep_out" --no-report >/dev/null
  fi
  find "$sweep_out/runs" -mindepth 1 -maxdepth 1 -type d | head -n 1
}

# Only the inputs the selected cases read (the generator's 1,000,000-pose pair takes minutes).
input_files=()
for entry in "${cases[@]}"; do
  IFS='|' read -r name _ _ arguments <<<"$entry"
  [[ -z "$only" || "$name" =~ $only ]] || continue
  for word in $arguments; do
    [[ "$word" =~ ^(tum|map|relations)-.*[.](tum|yaml|pgm|png|txt)$ ]] && input_files+=("$word")
  done
done
/usr/bin/python3 "$root/bench/cli/make_inputs.py" "$inputs" --files "${input_files[@]}"

median() { sort -n | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

rm -f "$out/cases.tmp"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for entry in "${cases[@]}"; do
  IFS='|' read -r name target_ms target_mb arguments <<<"$entry"
  [[ -z "$only" || "$name" =~ $only ]] || continue
  if [[ "$name" == worker-* && ! -f "$shared/datasets/intel/intel-corrected.log.gz" ]]; then
    echo "cli_bench.sh: skipping $name: $shared/datasets/intel/intel-corrected.log.gz missing" >&2
    continue
  fi
  pin=()
  [[ "$name" == eval-map-* ]] && pin=(taskset -c 0)
  hyperfine_commands=()
  for program in "${programs[@]}"; do
    label=${program%%=*}
    binary=${program#*=}
    args=${arguments//\{root\}/$root}
    if [[ "$args" == *"{rundir}"* ]]; then args=${args//\{rundir\}/$(prepare_worker_run "$label" "$binary")}; fi
    read -r -a words <<<"$args"
    argv=("${pin[@]}" "$binary" "${words[@]}")
    # The exit status and the peak RSS (median over the runs) of each program.
    status=0
    (cd "$inputs" && "${argv[@]}" >/dev/null 2>"$out/$name.$label.stderr") || status=$?
    echo "$status" >"$out/$name.$label.status"
    for ((i = 0; i < runs; ++i)); do
      (cd "$inputs" && /usr/bin/time -f %M -o "$out/time.tmp" "${argv[@]}" >/dev/null 2>&1) || true
      cat "$out/time.tmp"
    done | median >"$out/$name.$label.rss_kb"
    command_line="${argv[*]}"
    hyperfine_commands+=(--command-name "$label" "$command_line")
  done
  (cd "$inputs" && hyperfine -N -i --warmup 3 --runs "$runs" --style none \
    --export-json "$out/$name.json" "${hyperfine_commands[@]}" >/dev/null)
  echo "$name|$target_ms|$target_mb|$arguments" >>"$out/cases.tmp"
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
mv "$out/cases.tmp" "$out/cases.txt"
labels=()
for program in "${programs[@]}"; do labels+=("${program%%=*}"); done
table_status=0
/usr/bin/python3 "$root/bench/cli/cli_table.py" "${check[@]}" "$out" "$runs" "load average before: $load_before, after: $load_after; $(nproc) cores" "${labels[@]}" \
  >"$out/table.md" || table_status=$?
cat "$out/table.md"
echo "results: $out (table.md, summary.json, hyperfine JSON per case)"
exit "$table_status"
