#!/usr/bin/env bash
# Bounded load test of `slamsweep serve` on 127.0.0.1 (target: 20 sweeps submitted at once, 200 status
# reads per second for 20 s): nothing may be lost, and it reports the read latency (p50/p99) and the
# scheduler's overhead per run.
#
# Usage: bench/service/load_test.sh [SLAMSWEEP_BINARY]   (default: build/slamsweep)
# Environment: SWEEPS (20), ITERATIONS per sweep (3), RATE (200 reads/s), SECONDS_READ (20), JOBS (2).
#
# Each sweep runs the odometry baseline on a short simulated floor with its own seed, so every run is
# real work (none is reused). The reads cycle over the sweep list, each sweep, its runs and the page,
# at a fixed rate (bench/service/status_load.py, open loop: latency counts from each request's planned
# time). Afterwards every sweep must be ok with all its runs in its summary.json, and every read must
# have been answered 200. The scheduling overhead is the server's own measure (/metrics,
# slamsweep_scheduling_seconds: from a slot freeing to the next worker's start, recording the ended run
# included); for scale, the same runs through one `slamsweep run` are timed too. wrk (Debian) adds the
# status endpoint's throughput at full speed.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=${1:-$root/build/slamsweep}
sweeps=${SWEEPS:-20}
iterations=${ITERATIONS:-3}
rate=${RATE:-200}
seconds_read=${SECONDS_READ:-20}
jobs=${JOBS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/slamsweep-load.XXXXXX")
server_pid=
cleanup() {
  [[ -n "$server_pid" ]] && kill -TERM "$server_pid" 2>/dev/null && wait "$server_pid" 2>/dev/null
  rm -rf -- "$work"
}
trap cleanup EXIT

sweep_yaml() {
  cat <<YAML
name: load-$1
iterations: $iterations
seed: $((1000 + $1))
evaluation: {stages: 4}
algorithms:
  - {name: odometry, adapter: odometry, timeout_s: 120}
sequences:
  - {catalog: simulated-floor, name: floor, max_scans: 60}
noise:
  - name: noisy
    odometry: {alpha1: 0.01, alpha3: 0.01}
YAML
}

for ((i = 1; i <= sweeps; i++)); do sweep_yaml "$i" >"$work/sweep-$i.yaml"; done

"$bin" serve --data "$work/data" --listen 127.0.0.1:0 --port-file "$work/port" --jobs "$jobs" \
  --max-queued "$((sweeps + 5))" >"$work/serve.log" 2>&1 &
server_pid=$!
for _ in $(seq 1 300); do [[ -s "$work/port" ]] && break; sleep 0.1; done
url=http://127.0.0.1:$(cat "$work/port")
echo "server: $url, $jobs worker slots; $sweeps sweeps x $iterations runs"

# 20 submissions at once.
start_ns=$(date +%s%N)
for ((i = 1; i <= sweeps; i++)); do
  "$bin" submit "$work/sweep-$i.yaml" --server "$url" >"$work/submit-$i.log" 2>&1 &
done
wait_failed=0
for job in $(jobs -p); do
  [[ "$job" == "$server_pid" ]] && continue
  wait "$job" || wait_failed=$((wait_failed + 1))
done
submitted_ms=$((($(date +%s%N) - start_ns) / 1000000))
grep -ho "^sweep [0-9]*" "$work"/submit-*.log | awk '{print $2}' | sort -n >"$work/ids"
echo "submitted $(wc -l <"$work/ids") of $sweeps sweeps in ${submitted_ms} ms ($wait_failed submissions failed)"

/usr/bin/python3 "$here/status_load.py" "$url" "$rate" "$seconds_read" "$work/ids" "$work/reads.json" >/dev/null

# Until every sweep has ended (and its report is written).
deadline=$((SECONDS + 1800))
while ((SECONDS < deadline)); do
  pending=$(curl -s "$url/api/sweeps" | /usr/bin/python3 -c '
import json, sys
sweeps = json.load(sys.stdin)["sweeps"]
print(sum(1 for s in sweeps if s["state"] in ("queued", "running") or s["report"] == "writing"))')
  ((pending == 0)) && break
  sleep 1
done
makespan_ms=$((($(date +%s%N) - start_ns) / 1000000))
curl -s "$url/metrics" >"$work/metrics.txt"
curl -s "$url/api/sweeps" >"$work/sweeps.json"
throughput=$(command -v wrk >/dev/null && wrk -t 2 -c 8 -d 5s "$url/api/sweeps/1" 2>/dev/null | awk '/Requests\/sec/ {print $2}' || echo "n/a")

# The same runs through one `slamsweep run` (one sweep of sweeps x iterations iterations), for scale.
{ sweep_yaml 0 | sed "s/^iterations: .*/iterations: $((sweeps * iterations))/; s/^name: .*/name: load-plain/"; } \
  >"$work/plain.yaml"
plain_start=$(date +%s%N)
"$bin" run "$work/plain.yaml" --output "$work/plain" --jobs "$jobs" --no-report >"$work/plain.log" 2>&1 || true
plain_ms=$((($(date +%s%N) - plain_start) / 1000000))

/usr/bin/python3 - "$work" "$sweeps" "$iterations" "$submitted_ms" "$makespan_ms" "$plain_ms" "$throughput" <<'PY'
import json, os, re, sys
work, sweeps, iterations = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
submitted_ms, makespan_ms, plain_ms, throughput = int(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6]), sys.argv[7]
reads = json.load(open(f"{work}/reads.json"))
listed = json.load(open(f"{work}/sweeps.json"))["sweeps"]
problems = []
if len(listed) != sweeps:
    problems.append(f"{len(listed)} sweeps listed, {sweeps} submitted")
runs_total = 0
for sweep in listed:
    summary_file = os.path.join(sweep["result_dir"], "summary.json")
    summary = json.load(open(summary_file)) if os.path.exists(summary_file) else {"runs": []}
    ok = [r for r in summary["runs"] if r["status"] == "ok"]
    runs_total += len(summary["runs"])
    if sweep["state"] != "ok" or len(ok) != iterations or sweep["counts"]["ok"] != iterations:
        problems.append(f"sweep {sweep['id']}: {sweep['state']}, {len(ok)} ok runs in summary.json")
if set(reads["status_codes"]) != {"200"}:
    problems.append(f"status reads answered {reads['status_codes']}")
metrics = open(f"{work}/metrics.txt").read()
value = lambda name: float(re.search(rf"^{name} (\S+)$", metrics, re.M).group(1))
overhead_sum, overhead_count = value("slamsweep_scheduling_seconds_sum"), value("slamsweep_scheduling_seconds_count")
runs = sweeps * iterations
print(f"runs: {runs_total} of {runs} recorded, every sweep ok: {'yes' if not problems else 'NO'}")
print(f"status reads: {reads['requests']} in {reads['requests'] / reads['achieved_rate_per_s']:.1f} s "
      f"({reads['achieved_rate_per_s']:.0f}/s), codes {reads['status_codes']}")
print(f"read latency: p50 {reads['p50_ms']:.2f} ms, p90 {reads['p90_ms']:.2f} ms, p99 {reads['p99_ms']:.2f} ms, "
      f"max {reads['max_ms']:.1f} ms")
print(f"scheduling overhead per run (server, /metrics): {1000 * overhead_sum / max(overhead_count, 1):.2f} ms mean "
      f"over {overhead_count:.0f} starts")
print(f"submissions: {sweeps} in {submitted_ms} ms; all sweeps ended (reports written) after {makespan_ms / 1000:.1f} s; "
      f"the same {runs} runs by one `slamsweep run`: {plain_ms / 1000:.1f} s "
      f"(service minus run: {(makespan_ms - plain_ms) / runs:+.0f} ms per run, with the reports and the read load)")
print(f"wrk, GET /api/sweeps/1 at full speed (2 threads, 8 connections, 5 s): {throughput} requests/s")
for problem in problems:
    print("LOST:", problem)
sys.exit(1 if problems else 0)
PY
