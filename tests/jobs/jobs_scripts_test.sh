#!/usr/bin/env bash
# End-to-end tests of the Jenkins job scripts (jobs/*.sh) and of what the pipelines and the Docker image
# call, run by ctest (tests/jobs/CMakeLists.txt). Jenkins and Docker do not run here, so these check that
# every step they would run exists and works when CI runs it the same way.
# Usage: tests/jobs/jobs_scripts_test.sh CASE SLAMSWEEP_BINARY
#   CASE: static (Jenkinsfiles, Dockerfile, bad arguments), shard_merge (shards 1/2 + 2/2 merged equal a
#   single sweep; nightly-compare), nightly (three nights of shards + merge + history: a re-run is no
#   regression, noisier odometry is one; exit 77 = skipped while slamsweep has no `history` command),
#   quickstart (jobs/run-sweep.sh on configs/quickstart.yaml), service (jobs/submit-sweep.sh against a real
#   `slamsweep serve`), groovy_lint (npm-groovy-lint on every Jenkinsfile; exit 77 = skipped when the linter
#   is not installed, a failure under CI=true), speed (jobs/speed-check.sh on two cases, one run each: its
#   outputs and exit status, never the timings), paired_speed (jobs/paired-speed-check.sh: the same program on
#   both sides is run and tabled; a program planted with a busy loop before it starts is found slower, exit 3).
set -euo pipefail

case_name=${1:?usage: jobs_scripts_test.sh CASE SLAMSWEEP_BINARY}
SLAMSWEEP_BIN=${2:?usage: jobs_scripts_test.sh CASE SLAMSWEEP_BINARY}
# Absolute: the cases run from a temporary folder.
SLAMSWEEP_BIN=$(cd "$(dirname "$SLAMSWEEP_BIN")" && pwd)/$(basename "$SLAMSWEEP_BIN")
export SLAMSWEEP_BIN
root=$(cd "$(dirname "$0")/../.." && pwd)
jobs_dir=$root/jobs
work=$(mktemp -d "${TMPDIR:-/tmp}/slamsweep-jobs-test.XXXXXX")
trap 'rm -rf -- "$work"' EXIT

failures=0
checks=0
pass() {
  checks=$((checks + 1))
  echo "ok: $*"
}
fail() {
  checks=$((checks + 1))
  failures=$((failures + 1))
  echo "FAILED: $*" >&2
}
# expect_status EXPECTED DESCRIPTION COMMAND...: runs the command (output to $work/last.log) and checks its code.
expect_status() {
  local expected=$1 description=$2
  shift 2
  local status=0
  "$@" >"$work/last.log" 2>&1 || status=$?
  if [[ "$status" == "$expected" ]]; then
    pass "$description (exit $status)"
  else
    fail "$description: expected exit $expected, got $status; output:"
    sed 's/^/    /' "$work/last.log" >&2
  fi
}
# expect_log PATTERN DESCRIPTION: the last expect_status command's output matches the extended regex.
expect_log() {
  if grep -Eq -- "$1" "$work/last.log"; then pass "$2"; else fail "$2: output lacks /$1/"; fi
}

# --- static: what Jenkins and Docker would run ------------------------------------------------------------

# Prints the command of every `sh` step of a Jenkinsfile, one a line: sh 'x', sh "x", sh(script: 'x', ...).
jenkinsfile_sh_steps() {
  local opening="\bsh[[:space:]]*(\([[:space:]]*(script:[[:space:]]*)?)?"
  grep -oE "$opening'[^']*'|$opening\"[^\"]*\"" "$1" | sed -E "s/^${opening#\\b}['\"]//; s/['\"]$//"
}

check_jenkinsfile() {
  local file=$1 minimum_steps=$2 steps=0 command script
  [[ -f "$file" ]] || { fail "$file is missing"; return; }
  while IFS= read -r command; do
    steps=$((steps + 1))
    script=${command%% *}
    if [[ "$script" != jobs/* ]]; then
      fail "$(basename "$file"): sh step '$command' does not call a script in jobs/"
    elif [[ ! -f "$root/$script" || ! -x "$root/$script" ]]; then
      fail "$(basename "$file"): sh step '$command' calls $script, which is missing or not executable"
    else
      pass "$(basename "$file"): sh step calls executable $script"
    fi
  done < <(jenkinsfile_sh_steps "$file")
  # A parser that found nothing would make the checks above vacuous.
  if ((steps >= minimum_steps)); then
    pass "$(basename "$file"): $steps sh steps found"
  else
    fail "$(basename "$file"): found $steps sh steps, expected at least $minimum_steps"
  fi
  # Every stage the task requires, and the publishing steps.
  local needed
  for needed in "${@:3}"; do
    if grep -qF -- "$needed" "$file"; then
      pass "$(basename "$file") has $needed"
    else
      fail "$(basename "$file") lacks $needed"
    fi
  done
}

check_dockerfile() {
  local file=$root/docker/Dockerfile
  [[ -f "$file" ]] || { fail "docker/Dockerfile is missing"; return; }
  # The base is an argument (debian:12 by default) that every stage starts from.
  grep -qE '^ARG BASE=debian:12$' "$file" && [[ $(grep -cE '^FROM ' "$file") == $(grep -cE '^FROM \$\{BASE\}( AS [a-z]+)?$' "$file") ]] &&
    pass "Dockerfile: every stage FROM \${BASE}, debian:12 by default" || fail "Dockerfile: stages not FROM \${BASE} (ARG BASE=debian:12)"
  # RUN instructions with their continuation lines joined.
  local runs
  runs=$(sed -e ':a' -e '/\\$/N; s/\\\n//; ta' "$file" | grep -E '^RUN ' || true)
  [[ -n "$runs" ]] || { fail "Dockerfile: no RUN instruction"; return; }
  local line script
  while IFS= read -r line; do
    local scripts
    scripts=$(grep -oE '(scripts|jobs|docker)/[A-Za-z0-9_.-]+\.sh' <<<"$line" || true)
    if [[ -z "$scripts" ]]; then
      fail "Dockerfile: '$line' calls no shared script (keep every step in scripts/ so that CI runs it)"
      continue
    fi
    for script in $scripts; do
      if [[ -x "$root/$script" ]]; then
        pass "Dockerfile: $script exists and is executable"
      else
        fail "Dockerfile: $script missing or not executable"
      fi
    done
  done <<<"$runs"
  # The runtime stage: the last one, with the installed tree of the build stage and no build step of its own.
  local runtime
  runtime=$(awk '/^FROM /{stage = ""} {stage = stage $0 "\n"} END {printf "%s", stage}' "$file")
  grep -qF 'COPY --from=build /stage/opt/slamsweep/ /opt/slamsweep/' <<<"$runtime" &&
    pass "Dockerfile: the runtime stage copies the installed tree of the build stage" ||
    fail "Dockerfile: the runtime stage lacks COPY --from=build /stage/opt/slamsweep/ /opt/slamsweep/"
  grep -qE 'image-steps\.sh (roster|slamsweep)|build\.sh|test\.sh' <<<"$runtime" &&
    fail "Dockerfile: the runtime stage builds (compilers would stay in the image)" ||
    pass "Dockerfile: the runtime stage builds nothing"
  grep -qE '^ENTRYPOINT \["/opt/slamsweep/bin/slamsweep"\]' "$file" &&
    pass "Dockerfile: the installed slamsweep is the entry point" ||
    fail "Dockerfile: ENTRYPOINT is not [\"/opt/slamsweep/bin/slamsweep\"]"
  local compose=$root/docker/compose.yaml
  if [[ -f "$compose" ]] && grep -q 'dockerfile: docker/Dockerfile' "$compose" &&
    grep -q ':/data/datasets:ro' "$compose" && grep -q 'configs/radish.yaml' "$compose" &&
    grep -qE 'command: \["serve"' "$compose"; then
    pass "compose.yaml builds docker/Dockerfile, mounts the datasets read-only, runs configs/radish.yaml and serves"
  else
    fail "docker/compose.yaml missing or lacks the Dockerfile, the read-only datasets mount, the radish command or serve"
  fi
  # Both services run SLAM programs in bubblewrap sandboxes: each needs the seccomp profile that allows
  # user namespaces, mount and pivot_root, and no AppArmor profile refusing mount; nothing docker-compose
  # 1.29 cannot pass (systempaths=unconfined: the daemon refuses it from Compose), no privilege, no capability.
  if python3 - "$compose" "$root/docker/seccomp-sandbox.json" <<'PY'
import json, sys, yaml
services = yaml.safe_load(open(sys.argv[1]))["services"]
wanted = {"seccomp=./seccomp-sandbox.json", "apparmor=unconfined"}
assert all(wanted <= set(service.get("security_opt", [])) for service in services.values()), services
assert not any("systempaths=unconfined" in service.get("security_opt", []) for service in services.values()), services
assert not any(service.get("privileged") or service.get("cap_add") for service in services.values()), services
profile = json.load(open(sys.argv[2]))
assert profile["defaultAction"] != "SCMP_ACT_ALLOW"
allowed = {name for rule in profile["syscalls"] if rule["action"] == "SCMP_ACT_ALLOW" for name in rule["names"]}
assert {"unshare", "clone", "mount", "pivot_root", "umount2"} <= allowed, allowed
assert not {"open_by_handle_at", "kexec_load", "init_module"} & allowed
PY
  then
    pass "compose.yaml: both services use docker/seccomp-sandbox.json (namespaces allowed, escapes refused) and apparmor=unconfined, nothing Compose 1.29 cannot pass, no privilege"
  else
    fail "compose.yaml or docker/seccomp-sandbox.json does not let the SLAM programs' sandbox be made"
  fi
}

# The Docker check needs root or a daemon and most of an hour: CI leaves its ctest out by label (never by
# skipping it), the nightly job runs exactly that label.
check_docker_label() {
  grep -qE '^ctest .*--label-exclude docker' "$root/scripts/test.sh" &&
    pass "scripts/test.sh leaves out the label docker" || fail "scripts/test.sh runs ctest without --label-exclude docker"
  grep -qE 'docker_check PROPERTIES LABELS docker\b' "$root/tests/docker/CMakeLists.txt" &&
    pass "docker_check has the label docker" || fail "tests/docker/CMakeLists.txt: docker_check lacks the label docker"
  grep -qF "'jobs/docker-check.sh out/docker'" "$jobs_dir/Jenkinsfile.nightly" && grep -qF -- "--label-regex '^docker\$'" "$jobs_dir/docker-check.sh" &&
    pass "the nightly job runs the label docker (jobs/docker-check.sh)" || fail "the nightly job does not run ctest -L docker"
}

check_bad_arguments() {
  expect_status 2 "run-shard.sh without arguments" "$jobs_dir/run-shard.sh"
  expect_log 'usage: jobs/run-shard.sh' "run-shard.sh prints its usage"
  expect_status 2 "run-shard.sh 3 2 (I > N)" "$jobs_dir/run-shard.sh" 3 2
  expect_log "got '3/2'" "run-shard.sh names the bad shard"
  expect_status 2 "run-shard.sh 0 2" "$jobs_dir/run-shard.sh" 0 2
  expect_status 2 "run-shard.sh x 2" "$jobs_dir/run-shard.sh" x 2
  expect_status 2 "merge-shards.sh with one argument" "$jobs_dir/merge-shards.sh" "$work/merged"
  expect_status 2 "merge-shards.sh with a folder that is no result directory" "$jobs_dir/merge-shards.sh" \
    "$work/merged" "$work/no-such-shard"
  expect_log 'no-such-shard: not a result directory' "merge-shards.sh names the bad shard"
  expect_status 2 "nightly-compare.sh without arguments" "$jobs_dir/nightly-compare.sh"
  expect_status 2 "run-sweep.sh with a missing config" "$jobs_dir/run-sweep.sh" "$work/missing.yaml" "$work/out-missing"
  mkdir -p "$work/precious" && echo keep >"$work/precious/notes.txt"
  expect_status 2 "run-sweep.sh into a non-empty folder that is no result directory" \
    "$jobs_dir/run-sweep.sh" "$root/tests/jobs/shard_sweep.yaml" "$work/precious"
  [[ -f "$work/precious/notes.txt" ]] && pass "run-sweep.sh left the foreign folder alone" ||
    fail "run-sweep.sh deleted a foreign folder"
  expect_status 2 "run-sweep.sh with an unknown algorithm filter" env ALGORITHMS=no-such-algorithm \
    "$jobs_dir/run-sweep.sh" "$root/tests/jobs/shard_sweep.yaml" "$work/out-filter"
  expect_status 2 "run-sweep.sh without a slamsweep program" env SLAMSWEEP_BIN="$work/no-slamsweep" \
    "$jobs_dir/run-sweep.sh" "$root/tests/jobs/shard_sweep.yaml" "$work/out-nobin"
  expect_log 'run jobs/setup.sh first' "run-sweep.sh says how to get the program"
  expect_status 2 "speed-check.sh with two output folders" "$jobs_dir/speed-check.sh" "$work/a" "$work/b"
  expect_log 'usage: jobs/speed-check.sh' "speed-check.sh prints its usage"
  expect_status 2 "speed-check.sh with BENCH_RUNS=0" env BENCH_RUNS=0 "$jobs_dir/speed-check.sh" "$work/speed-bad"
  expect_log "BENCH_RUNS must be a positive integer, got '0'" "speed-check.sh names the bad BENCH_RUNS"
  expect_status 2 "speed-check.sh without a slamsweep program" env SLAMSWEEP_BIN="$work/no-slamsweep" \
    "$jobs_dir/speed-check.sh" "$work/speed-nobin"
  expect_status 2 "paired-speed-check.sh with two output folders" "$jobs_dir/paired-speed-check.sh" "$work/a" "$work/b"
  expect_log 'usage: jobs/paired-speed-check.sh' "paired-speed-check.sh prints its usage"
  expect_status 2 "paired-speed-check.sh with BENCH_RUNS=2" env BENCH_RUNS=2 "$jobs_dir/paired-speed-check.sh" \
    "$work/paired-bad"
  expect_log "BENCH_RUNS must be an integer of at least 3, got '2'" "paired-speed-check.sh names the bad BENCH_RUNS"
  expect_status 2 "paired-speed-check.sh with a baseline that is no commit" env SPEED_BASELINE=no-such-commit \
    "$jobs_dir/paired-speed-check.sh" "$work/paired-nocommit"
  expect_log "SPEED_BASELINE 'no-such-commit' names no commit" "paired-speed-check.sh names the bad SPEED_BASELINE"
  expect_status 2 "scale-check.sh with two output folders" "$jobs_dir/scale-check.sh" "$work/a" "$work/b"
  expect_log 'usage: jobs/scale-check.sh' "scale-check.sh prints its usage"
  expect_status 2 "scale-check.sh with SCALE_SIZES=1k" env SCALE_SIZES=1k "$jobs_dir/scale-check.sh" "$work/scale-bad"
  expect_log "SCALE_SIZES must be a comma-separated list of run counts, got '1k'" "scale-check.sh names the bad SCALE_SIZES"
  expect_status 2 "scale-check.sh without a slamsweep program" env SLAMSWEEP_BIN="$work/no-slamsweep" \
    "$jobs_dir/scale-check.sh" "$work/scale-nobin"
}

# nightly-compare.sh's handling of `slamsweep history` with a stand-in program (the real one is exercised in
# shard_merge): which commands it runs, and how their exit codes map onto its own.
check_nightly_compare_mapping() {
  local fake=$work/fake-slamsweep night=$work/night
  mkdir -p "$night"
  echo '{"counts": {"total": 0, "ok": 0, "failed": 0}, "runs": []}' >"$night/summary.json"
  cat >"$fake" <<'EOF'
#!/usr/bin/env bash
# Stand-in for slamsweep: logs its arguments; `history record` creates the database; `history compare`
# exits with $FAKE_COMPARE_STATUS.
echo "$*" >>"$FAKE_LOG"
if [[ "$1 $2" == "history record" ]]; then echo db >"$5"; exit 0; fi
exit "${FAKE_COMPARE_STATUS:-0}"
EOF
  chmod +x "$fake"
  export FAKE_LOG=$work/fake.log
  : >"$FAKE_LOG"
  expect_status 0 "nightly-compare.sh, first night (stand-in)" env SLAMSWEEP_BIN="$fake" \
    "$jobs_dir/nightly-compare.sh" "$night" "$work/fake-history.sqlite"
  if [[ $(cat "$FAKE_LOG") == "history record $night --history $work/fake-history.sqlite" ]]; then
    pass "the first night is only recorded"
  else
    fail "first night: expected only 'history record', the stand-in saw: $(cat "$FAKE_LOG")"
  fi
  : >"$FAKE_LOG"
  expect_status 3 "nightly-compare.sh passes a regression (3) on" env SLAMSWEEP_BIN="$fake" FAKE_COMPARE_STATUS=3 \
    NIGHT_LABEL=n2 REGRESSION_ALPHA=0.01 REGRESSION_MIN_EFFECT=0.5 \
    "$jobs_dir/nightly-compare.sh" "$night" "$work/fake-history.sqlite"
  if grep -qx -- "history record $night --history $work/fake-history.sqlite --label n2" "$FAKE_LOG" &&
    grep -qx -- "history compare $night --history $work/fake-history.sqlite --junit $night/regressions.xml \
--previous --alpha 0.01 --min-effect 0.5" "$FAKE_LOG"; then
    pass "record with the label, then compare with the previous night and the options"
  else
    fail "unexpected slamsweep commands: $(cat "$FAKE_LOG")"
  fi
  : >"$FAKE_LOG"
  expect_status 0 "nightly-compare.sh with BASELINE_LABEL, no regression" \
    env SLAMSWEEP_BIN="$fake" BASELINE_LABEL=base \
    "$jobs_dir/nightly-compare.sh" "$night" "$work/fake-history.sqlite"
  if grep -q -- "--baseline-label base" "$FAKE_LOG" && ! grep -q -- "--previous" "$FAKE_LOG"; then
    pass "BASELINE_LABEL replaces --previous"
  else
    fail "BASELINE_LABEL not passed: $(cat "$FAKE_LOG")"
  fi
  expect_status 2 "nightly-compare.sh passes a compare error (2) on" env SLAMSWEEP_BIN="$fake" FAKE_COMPARE_STATUS=2 \
    "$jobs_dir/nightly-compare.sh" "$night" "$work/fake-history.sqlite"
  expect_status 4 "nightly-compare.sh on a folder without summary.json" env SLAMSWEEP_BIN="$fake" \
    "$jobs_dir/nightly-compare.sh" "$work/precious" "$work/fake-history.sqlite"
}

# --- shard_merge: shards 1/2 + 2/2 merged equal one sweep ---------------------------------------------------

# Compares two summary.json files: the same run ids with the same statuses, identical metrics for the
# odometry runs (deterministic given the seed), the same metric names for the others.
compare_summaries() {
  python3 - "$1" "$2" <<'EOF'
import json, sys
single, merged = (json.load(open(path)) for path in sys.argv[1:3])
problems = []
runs_single = {run["run_id"]: run for run in single["runs"]}
runs_merged = {run["run_id"]: run for run in merged["runs"]}
if sorted(runs_single) != sorted(runs_merged):
    problems.append(f"run ids differ: {sorted(runs_single)} vs {sorted(runs_merged)}")
for run_id in sorted(set(runs_single) & set(runs_merged)):
    a, b = runs_single[run_id], runs_merged[run_id]
    if a["status"] != b["status"]:
        problems.append(f"{run_id}: status {a['status']} vs {b['status']}")
    if a["status"] != "ok":
        problems.append(f"{run_id}: not ok ({a.get('reason')})")
    if a["algorithm"] == "odometry" and a["metrics"] != b["metrics"]:
        problems.append(f"{run_id}: odometry metrics differ")
    if sorted(a["metrics"]) != sorted(b["metrics"]):
        problems.append(f"{run_id}: metric names differ")
if single["counts"] != merged["counts"]:
    problems.append(f"counts {single['counts']} vs {merged['counts']}")
odometry = [r for r in runs_single.values() if r["algorithm"] == "odometry" and "ape_trans" in r["metrics"]]
if not odometry:
    problems.append("no odometry run with ape_trans: the metric comparison would be vacuous")
print("\n".join(problems) if problems else f"{len(runs_single)} runs equal")
sys.exit(1 if problems else 0)
EOF
}

check_shard_merge() {
  local config=$root/tests/jobs/shard_sweep.yaml
  cd "$work"
  expect_status 0 "run-sweep.sh on the shard test config" "$jobs_dir/run-sweep.sh" "$config" single
  expect_status 0 "run-shard.sh 1 2" "$jobs_dir/run-shard.sh" 1 2 "$config" shard-1
  [[ ! -e shard-1/report ]] && pass "a shard writes no report" || fail "shard-1 has a report"
  expect_status 0 "run-shard.sh 2 2" "$jobs_dir/run-shard.sh" 2 2 "$config" shard-2
  expect_status 0 "merge-shards.sh" "$jobs_dir/merge-shards.sh" merged shard-1 shard-2
  expect_log 'merged 2 shards: 4 runs, 0 failed' "merge-shards.sh reports 4 runs, 0 failed"
  local file
  for file in merged/junit.xml merged/report/index.html merged/results.sqlite; do
    [[ -s "$file" ]] && pass "merge wrote $file" || fail "merge did not write $file"
  done
  expect_status 0 "merged summary.json equals the single sweep's" \
    compare_summaries single/summary.json merged/summary.json
  [[ $(grep -c '<testcase ' merged/junit.xml) == 4 ]] && pass "merged junit.xml has 4 testcases" ||
    fail "merged junit.xml has $(grep -c '<testcase ' merged/junit.xml) testcases, expected 4"

  # The job's parameters reach `slamsweep run`: one algorithm, one iteration = that cell's first run, same id.
  expect_status 0 "run-sweep.sh with ALGORITHMS=odometry SEQUENCES=floor ITERATIONS=1" \
    env ALGORITHMS=odometry SEQUENCES=floor ITERATIONS=1 "$jobs_dir/run-sweep.sh" "$config" filtered
  local filtered_ids expected_ids
  local list_ids='import json, sys
print(" ".join(r["run_id"] for r in json.load(open(sys.argv[1]))["runs"]
               if len(sys.argv) < 3 or (r["algorithm"] == sys.argv[2] and r["iteration"] == 0)))'
  filtered_ids=$(python3 -c "$list_ids" filtered/summary.json)
  expected_ids=$(python3 -c "$list_ids" single/summary.json odometry)
  if [[ -n "$filtered_ids" && "$filtered_ids" == "$expected_ids" ]]; then
    pass "the filtered sweep is the single sweep's odometry iteration 0 ($filtered_ids)"
  else
    fail "filtered sweep ran '$filtered_ids', expected '$expected_ids'"
  fi

  # Running a shard again into its old folder starts afresh (the nightly workspace is reused).
  expect_status 0 "run-shard.sh 1 2 again into the same folder" "$jobs_dir/run-shard.sh" 1 2 "$config" shard-1
  expect_log 'removing the earlier results in shard-1' "the earlier shard results are removed"
  # Which runs a shard holds follows from the run ids' hashes: ask the planner how many.
  local shard_runs
  shard_runs=$("$SLAMSWEEP_BIN" plan "$config" --shard 1/2 | tail -n 1 | awk '{print $1}')
  expect_log "^.*\b$shard_runs runs to do, 0 already done" "no run of the shard's $shard_runs is skipped as done"

  # A failed run makes merge-shards.sh exit 1 (the nightly maps it to FAILURE): a shard whose icp-slam
  # runs time out at once.
  sed -e 's/timeout_s: 120/timeout_s: 0.001/; s/timeout_s: 60/timeout_s: 0.001/' "$config" >broken.yaml
  expect_status 1 "run-shard.sh with runs that fail" "$jobs_dir/run-shard.sh" 1 1 broken.yaml broken-shard
  expect_status 1 "merge-shards.sh of a shard with failed runs" "$jobs_dir/merge-shards.sh" broken-merged broken-shard
  expect_log '[1-9][0-9]* runs failed' "merge-shards.sh counts the failed runs"

  # nightly-compare.sh: the first night has nothing to compare with; an identical second night is no regression.
  local help
  help=$("$SLAMSWEEP_BIN" --help 2>&1 || true)
  if grep -qE '^[[:space:]]+history[[:space:]]' <<<"$help"; then
    expect_status 0 "nightly-compare.sh, first night" "$jobs_dir/nightly-compare.sh" merged history.sqlite
    expect_log 'first, nothing to compare with' "the first night is recorded without a comparison"
    expect_status 0 "nightly-compare.sh, second identical night" "$jobs_dir/nightly-compare.sh" single history.sqlite
    [[ -s single/regressions.xml ]] && pass "nightly-compare.sh wrote regressions.xml" ||
      fail "no single/regressions.xml"
    if [[ -s single/regressions.xml ]] && ! grep -q '<failure' single/regressions.xml; then
      pass "regressions.xml lists no regression"
    else
      fail "regressions.xml is missing or lists a regression between identical nights"
    fi
    expect_status 2 "nightly-compare.sh with an unknown baseline" env BASELINE_LABEL=no-such-night \
      "$jobs_dir/nightly-compare.sh" single history.sqlite
  else
    echo "note: this slamsweep has no 'history' command yet: nightly-compare.sh not tested"
  fi
}

# --- nightly: the nightly job's chain (shards, merge, history) three nights running -----------------------

# run_night DIR CONFIG: the nightly job's steps for one night, results merged into DIR.
run_night() {
  local night=$1 config=$2
  expect_status 0 "$night: run-shard.sh 1 2" "$jobs_dir/run-shard.sh" 1 2 "$config" "$night-shard-1"
  expect_status 0 "$night: run-shard.sh 2 2" "$jobs_dir/run-shard.sh" 2 2 "$config" "$night-shard-2"
  expect_status 0 "$night: merge-shards.sh" "$jobs_dir/merge-shards.sh" "$night" "$night-shard-1" "$night-shard-2"
}

check_nightly() {
  local help
  help=$("$SLAMSWEEP_BIN" --help 2>&1 || true)
  if ! grep -qE '^[[:space:]]+history[[:space:]]' <<<"$help"; then
    if [[ "${CI:-}" == true ]]; then
      fail "this slamsweep has no 'history' command: the nightly cannot be checked"
      return
    fi
    echo "skipped: this slamsweep has no 'history' command"
    exit 77
  fi
  local config=$root/tests/jobs/nightly_sweep.yaml
  cd "$work"
  export SLAMSWEEP_HISTORY=$work/history.sqlite
  run_night night-1 "$config"
  expect_status 0 "night 1: nightly-compare.sh records the first night" env NIGHT_LABEL=night-1 \
    "$jobs_dir/nightly-compare.sh" night-1
  expect_log 'nothing to compare with' "night 1 is not compared"
  [[ -s "$SLAMSWEEP_HISTORY" ]] && pass "the history database is at \$SLAMSWEEP_HISTORY" ||
    fail "no history database at $SLAMSWEEP_HISTORY"

  # The same setting again: no regression (exit 0, which the nightly job leaves SUCCESS).
  run_night night-2 "$config"
  expect_status 0 "night 2 (same setting): no regression" env NIGHT_LABEL=night-2 "$jobs_dir/nightly-compare.sh" night-2
  if [[ -s night-2/regressions.xml ]] && ! grep -q '<failure' night-2/regressions.xml; then
    pass "night 2: regressions.xml without failures"
  else
    fail "night 2: regressions.xml missing or with a failure"
  fi

  # Twenty times noisier odometry under the same noise name: a regression (exit 3, UNSTABLE in Jenkins).
  sed -e 's/alpha1: 0.002, alpha2: 0.0001, alpha3: 0.002, alpha4: 0.0001/alpha1: 0.04, alpha2: 0.002, alpha3: 0.04,/' \
    -e 's/alpha3: 0.04,}/alpha3: 0.04, alpha4: 0.002}/' "$config" >noisier.yaml
  grep -q 'alpha1: 0.04' noisier.yaml && pass "noisier.yaml injects the noise" || fail "could not inject the noise"
  run_night night-3 noisier.yaml
  expect_status 3 "night 3 (noisier odometry): regression" env NIGHT_LABEL=night-3 \
    "$jobs_dir/nightly-compare.sh" night-3
  expect_log 'regression found' "nightly-compare.sh says so"
  if grep -q '<failure' night-3/regressions.xml && grep -q 'odometry' night-3/regressions.xml; then
    pass "night 3: regressions.xml has a failing testcase for odometry"
  else
    fail "night 3: regressions.xml lacks the odometry regression"
  fi
  # Against night 2 named as the baseline, the same verdict.
  expect_status 3 "night 3 against BASELINE_LABEL=night-2" env BASELINE_LABEL=night-2 NIGHT_LABEL=night-3 \
    "$jobs_dir/nightly-compare.sh" night-3
}

# --- service: the service job's script against a real `slamsweep serve` ------------------------------------

check_service() {
  cd "$work"
  local server_pid port
  "$SLAMSWEEP_BIN" serve --data service-data --listen 127.0.0.1:0 --port-file service.port --jobs 2 \
    >service.log 2>&1 &
  server_pid=$!
  for _ in $(seq 1 200); do [[ -s service.port ]] && break; sleep 0.1; done
  [[ -s service.port ]] || { fail "slamsweep serve did not start:"; cat service.log >&2; kill "$server_pid"; return; }
  port=$(cat service.port)
  export SLAMSWEEP_SERVER=http://127.0.0.1:$port
  expect_status 0 "submit-sweep.sh through the service" "$jobs_dir/submit-sweep.sh" \
    "$root/tests/jobs/service_sweep.yaml" service-out
  expect_log '\[4/4\] ok' "submit-sweep.sh streams a line per finished run"
  [[ $(grep -c '<testcase ' service-out/junit.xml) == 4 ]] && pass "the downloaded junit.xml has 4 testcases" ||
    fail "service-out/junit.xml lacks the 4 testcases"
  [[ -s service-out/report/index.html ]] && pass "the report was downloaded" || fail "no service-out/report/index.html"
  # The same sweep again: every run is reused from the first, and the job is green.
  expect_status 0 "the same sweep a second time" "$jobs_dir/submit-sweep.sh" \
    "$root/tests/jobs/service_sweep.yaml" service-out
  expect_log 'reused' "the second sweep reuses the first one's runs"
  printf 'name: broken\nalgorithms: 3\n' >broken-service.yaml
  expect_status 2 "a refused sweep exits 2" "$jobs_dir/submit-sweep.sh" broken-service.yaml service-out
  expect_log 'broken-service.yaml:2' "the refusal names the file and line"
  expect_status 2 "an unreachable service exits 2" env SLAMSWEEP_SERVER=http://127.0.0.1:1 \
    "$jobs_dir/submit-sweep.sh" "$root/tests/jobs/service_sweep.yaml" service-out
  kill -TERM "$server_pid"
  local server_status=0
  wait "$server_pid" || server_status=$?
  ((server_status == 0)) && pass "the server drains and exits 0 on SIGTERM" ||
    { fail "the server exited $server_status on SIGTERM"; cat service.log >&2; }
}

# --- groovy_lint: npm-groovy-lint on the Jenkinsfiles ------------------------------------------------------

check_groovy_lint() {
  local linter
  if ! linter=$("$root/scripts/install-groovy-lint.sh" --check); then
    if [[ "${CI:-}" == true ]]; then
      fail "npm-groovy-lint is not installed (scripts/install-groovy-lint.sh; scripts/test.sh runs it)"
      return
    fi
    echo "skipped: npm-groovy-lint is not installed (scripts/install-groovy-lint.sh)"
    exit 77
  fi
  # JSON, because the linter exits 0 when CodeNarc fails: count what it linted and found. --noserver: no
  # CodeNarc daemon (a 2 GB-heap JVM) is left running after the suite.
  (cd "$jobs_dir" && "$linter" --noserver --failon warning --output json Jenkinsfile Jenkinsfile.nightly Jenkinsfile.service) \
    >"$work/lint.json" 2>"$work/lint.err" || true
  if python3 - "$work/lint.json" <<'EOF'
import json, sys
try:
    result = json.load(open(sys.argv[1]))
except ValueError as error:
    sys.exit(f"no JSON from npm-groovy-lint: {error}")
summary = result["summary"]
for path, found in result["files"].items():
    for error in found.get("errors", []):
        if error["severity"] in ("error", "warning"):
            print(f"{path}:{error['line']}: {error['rule']}: {error['msg']}")
if summary["totalFilesLinted"] != 3:
    sys.exit(f"linted {summary['totalFilesLinted']} files, expected the 3 Jenkinsfiles")
sys.exit(1 if summary["totalFoundErrorNumber"] + summary["totalFoundWarningNumber"] > 0 else 0)
EOF
  then
    pass "npm-groovy-lint: no error or warning in the 3 Jenkinsfiles (jobs/.groovylintrc.json)"
  else
    fail "npm-groovy-lint found problems:"
    head -c 3000 "$work/lint.err" >&2
  fi
}

# --- quickstart: the parameterised job's sweep on the real quick-start config --------------------------------

check_quickstart() {
  cd "$work"
  local status=0
  "$jobs_dir/run-sweep.sh" "$root/configs/quickstart.yaml" quickstart >"$work/last.log" 2>&1 || status=$?
  tail -5 "$work/last.log"
  if [[ ! -s quickstart/summary.json ]]; then
    fail "run-sweep.sh (exit $status) wrote no summary.json"
    return
  fi
  local total failed
  local count='import json, sys; print(json.load(open(sys.argv[1]))["counts"][sys.argv[2]])'
  total=$(python3 -c "$count" quickstart/summary.json total)
  failed=$(python3 -c "$count" quickstart/summary.json failed)
  # The exit code says whether runs failed, as the Jenkinsfile reads it.
  if { ((failed == 0)) && ((status == 0)); } || { ((failed > 0)) && ((status == 1)); }; then
    pass "run-sweep.sh exit $status matches $failed failed runs"
  else
    fail "run-sweep.sh exited $status with $failed failed runs"
  fi
  ((failed == 0)) && pass "every quick-start run ok" || fail "$failed quick-start runs failed"
  # 3 algorithms x 2 sequences x 1 noise x 3 iterations.
  ((total == 18)) && pass "18 runs" || fail "$total runs, expected 18"
  [[ $(grep -c '<testcase ' quickstart/junit.xml) == 18 ]] && pass "junit.xml has 18 testcases" ||
    fail "junit.xml has $(grep -c '<testcase ' quickstart/junit.xml) testcases, expected 18"
  python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' quickstart/junit.xml &&
    pass "junit.xml is well-formed XML" || fail "junit.xml is not well-formed XML"
  [[ -s quickstart/report/index.html ]] && grep -qi '<html' quickstart/report/index.html &&
    pass "report/index.html written" || fail "report/index.html missing or not HTML"
}

# --- speed: the nightly's speed stage, end to end on two cases ---------------------------------------------

# run_speed_stage NAME COMMAND...: runs a speed stage's script (output to $work/last.log) and leaves its exit
# status in $status. 3 is a slow verdict, which a loaded CI machine may give: the wiring is what is checked, not
# the speed, so 0 and 3 pass and anything else fails (return 1).
run_speed_stage() {
  local name=$1
  shift
  status=0
  "$@" >"$work/last.log" 2>&1 || status=$?
  tail -8 "$work/last.log"
  if ((status == 0 || status == 3)); then
    pass "$name exit $status (0 no verdict against it, 3 slow)"
  else
    fail "$name exited $status"
    return 1
  fi
}

check_speed() {
  cd "$work"
  local status=0
  run_speed_stage speed-check.sh env BENCH_RUNS=1 BENCH_ONLY='^(version|eval-ape-1k)$' \
    "$jobs_dir/speed-check.sh" speed || return
  [[ -s speed/table.md ]] && pass "speed/table.md written" || fail "speed/table.md missing"
  if python3 - speed/summary.json <<'EOF'
import json, sys
cases = {case["case"]: case for case in json.load(open(sys.argv[1]))["cases"]}
assert set(cases) == {"version", "eval-ape-1k"}, sorted(cases)
assert all(case["programs"]["after"]["exit_status"] == 0 for case in cases.values()), cases
assert all(case["met"] in (True, False) for case in cases.values()), cases
EOF
  then
    pass "summary.json has the two cases, each program exited 0 and each has a verdict"
  else
    fail "speed/summary.json lacks a case, a verdict or a clean exit"
  fi
  local missed
  missed=$(grep -c '| NO |' speed/table.md || true)
  if { ((status == 0)) && ((missed == 0)); } || { ((status == 3)) && ((missed > 0)); }; then
    pass "the exit status agrees with the table ($missed targets missed)"
  else
    fail "speed-check.sh exited $status but the table has $missed NO rows"
  fi
  # The check must be able to fail: a program that spends 200 ms before it starts misses the 10 ms
  # start-up target on any machine, and the stage must say so (exit 3, a NO row).
  local slow=$work/slow-slamsweep
  printf '#!/bin/sh\nsleep 0.2\nexec "%s" "$@"\n' "$SLAMSWEEP_BIN" >"$slow"
  chmod +x "$slow"
  expect_status 3 "speed-check.sh on a program 200 ms slow to start" env BENCH_RUNS=1 BENCH_ONLY='^version$' \
    SLAMSWEEP_BIN="$slow" "$jobs_dir/speed-check.sh" slow
  if grep -q '| NO |' slow/table.md 2>/dev/null; then
    pass "the slow program's table has a NO row"
  else
    fail "the slow program's table has no NO row: $(cat slow/table.md 2>/dev/null)"
  fi
}

# --- paired_speed: the nightly's paired stage, the same program against itself and against a planted slowdown ---

check_paired_speed() {
  cd "$work"
  local status=0
  # The same program twice: 3 would be a false alarm of the rank test (alpha 0.01) on a noisy machine.
  run_speed_stage "paired-speed-check.sh on the same program twice" env SPEED_BASELINE_BIN="$SLAMSWEEP_BIN" \
    BENCH_RUNS=6 BENCH_ONLY='^eval-ape-se3-100k$' "$jobs_dir/paired-speed-check.sh" same || return
  if python3 - same/verdict.json same/samples.json <<'EOF'
import json, sys
verdict = json.load(open(sys.argv[1]))
samples = json.load(open(sys.argv[2]))
assert [case["case"] for case in verdict["cases"]] == ["eval-ape-se3-100k"], verdict
case = samples["cases"][0]
assert case["same_output"] and len(case["before"]["cpu_s"]) == 6 and len(case["after"]["cpu_s"]) == 6, case
EOF
  then
    pass "verdict.json and samples.json hold the case, six pairs and equal outputs"
  else
    fail "same/verdict.json or same/samples.json is wrong"
  fi
  # The guard must be able to fail: a program that burns CPU in a loop before it starts is slower on any machine.
  local slow=$work/busy-slamsweep
  printf '#!/bin/sh\ni=0\nwhile [ $i -lt 300000 ]; do i=$((i + 1)); done\nexec "%s" "$@"\n' "$SLAMSWEEP_BIN" >"$slow"
  chmod +x "$slow"
  expect_status 3 "paired-speed-check.sh on a program planted with a busy loop" env SPEED_BASELINE_BIN="$SLAMSWEEP_BIN" \
    SLAMSWEEP_BIN="$slow" BENCH_RUNS=6 BENCH_ONLY='^eval-ape-se3-100k$' "$jobs_dir/paired-speed-check.sh" slow
  if grep -q '| SLOWER |' slow/table.md 2>/dev/null; then
    pass "the planted slowdown's table has a SLOWER row"
  else
    fail "the planted slowdown's table has no SLOWER row: $(cat slow/table.md 2>/dev/null)"
  fi
}

# --- programs: one build handed to every shard (jobs/pack-programs.sh, jobs/unpack-programs.sh) ----------

check_programs() {
  local root=$work/programs-root archive=$work/stash/programs.tar.gz digest_before digest_after
  mkdir -p "$root/src/configs" "$root/src/.git" "$root/build/slam/bin" "$root/build/CMakeFiles"
  printf 'binary one\n' >"$root/build/slamsweep"
  printf 'helper\n' >"$root/build/slamsweep-sweep"
  printf 'module\n' >"$root/build/slamsweep-rawlog.so"
  printf 'driver\n' >"$root/build/slam/bin/slamsweep-slam-cartographer"
  printf 'options = {}\n' >"$root/build/slam/bin/slamsweep-slam-cartographer.lua"
  printf 'object\n' >"$root/build/CMakeFiles/left-out.o"
  printf 'name: x\n' >"$root/src/configs/x.yaml"
  printf 'history\n' >"$root/src/.git/HEAD"
  digest_before=$(cd "$root" && sha256sum build/slamsweep build/slam/bin/slamsweep-slam-cartographer.lua)
  expect_status 0 "pack-programs.sh packs the programs of ROOT" "$jobs_dir/pack-programs.sh" "$root" "$archive"
  if tar -tzf "$archive" | grep -q '/\.git/\|CMakeFiles'; then
    fail "the archive holds .git or build intermediates"
  else
    pass "the archive leaves .git and build intermediates out"
  fi
  # Another agent: nothing at ROOT yet.
  rm -rf -- "$root"
  expect_status 0 "unpack-programs.sh on an agent without them" "$jobs_dir/unpack-programs.sh" "$archive"
  expect_log "^programs: $root/build/slamsweep\$" "it names the unpacked program"
  digest_after=$(cd "$root" && sha256sum build/slamsweep build/slam/bin/slamsweep-slam-cartographer.lua)
  if [[ "$digest_before" == "$digest_after" ]]; then
    pass "the unpacked programs are the very bytes that were built (same digests, same paths)"
  else
    fail "digests differ after unpacking: $digest_before / $digest_after"
  fi
  # A second shard on the same agent: already there, only checked.
  expect_status 0 "unpack-programs.sh again on the same agent" "$jobs_dir/unpack-programs.sh" "$archive"
  printf 'tampered\n' >"$root/build/slamsweep"
  expect_status 5 "unpack-programs.sh over a changed program" "$jobs_dir/unpack-programs.sh" "$archive"
  # Another night's build left at ROOT with a consistent manifest of its own.
  printf 'binary two\n' >"$root/build/slamsweep"
  (cd "$root" && sha256sum build/slamsweep >PROGRAMS.sha256)
  expect_status 5 "unpack-programs.sh over another build's programs" "$jobs_dir/unpack-programs.sh" "$archive"
  expect_status 2 "unpack-programs.sh without an archive" "$jobs_dir/unpack-programs.sh" "$work/none.tar.gz"
  expect_status 2 "pack-programs.sh with a relative ROOT" "$jobs_dir/pack-programs.sh" relative "$archive"
  # The nightly runs shards from the unpacked programs, not from a build of their own.
  if grep -q "jobs/unpack-programs.sh" "$jobs_dir/Jenkinsfile.nightly" && grep -q "jobs/build-programs.sh" "$jobs_dir/Jenkinsfile.nightly"; then
    pass "Jenkinsfile.nightly builds the programs once and unpacks them on every shard"
  else
    fail "Jenkinsfile.nightly does not build once and hand the programs to the shards"
  fi
}

case $case_name in
  programs) check_programs ;;
  static)
    check_jenkinsfile "$jobs_dir/Jenkinsfile" 2 "stage('Setup')" "stage('Sweep')" "stage('Publish')" \
      "junit testResults: 'out/junit.xml', allowEmptyResults: false" "archiveArtifacts" "publishHTML" \
      "reportDir: 'out/report'" "keepAll: true" "name: 'ALGORITHMS'" "name: 'SEQUENCES'" "name: 'ITERATIONS'"
    check_jenkinsfile "$jobs_dir/Jenkinsfile.nightly" 4 "cron(" "jobs/run-shard.sh" "jobs/merge-shards.sh" \
      "jobs/nightly-compare.sh" "unstable(" "error(" "publishHTML" "junit testResults" "stage('Speed')" \
      "jobs/speed-check.sh out/speed" "label 'slamsweep-bench'" "stage('Scale')" "jobs/scale-check.sh out/scale" \
      "stage('Report in a browser')" "jobs/browser-check.sh out/screenshots" "artifacts: 'out/screenshots/**'" \
      "stage('Speed against the previous build')" "jobs/paired-speed-check.sh out/paired" "name: 'SPEED_BASELINE'"
    check_jenkinsfile "$jobs_dir/Jenkinsfile.service" 2 "stage('Setup')" "stage('Sweep')" "stage('Publish')" \
      "jobs/submit-sweep.sh" "withCredentials" "junit testResults: 'out/junit.xml', allowEmptyResults: false" \
      "publishHTML" "name: 'SLAMSWEEP_SERVER'" "name: 'PRIORITY'"
    check_dockerfile
    check_docker_label
    check_bad_arguments
    check_nightly_compare_mapping
    if command -v shellcheck >/dev/null; then
      (cd "$root" && shellcheck -x -S warning jobs/*.sh tests/jobs/jobs_scripts_test.sh docker/*.sh scripts/docker-check.sh) \
        >"$work/last.log" 2>&1 && pass "shellcheck finds no warning in jobs/*.sh, docker/*.sh and scripts/docker-check.sh" ||
        { fail "shellcheck warnings:"; cat "$work/last.log" >&2; }
    elif [[ "${CI:-}" == true ]]; then
      fail "shellcheck is not installed (scripts/install-deps.sh): under CI the scripts must be linted"
    else
      echo "note: shellcheck is not installed: the scripts are not linted"
    fi
    ;;
  shard_merge) check_shard_merge ;;
  nightly) check_nightly ;;
  quickstart) check_quickstart ;;
  service) check_service ;;
  groovy_lint) check_groovy_lint ;;
  speed) check_speed ;;
  paired_speed) check_paired_speed ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac

echo "$case_name: $((checks - failures)) of $checks checks passed"
((failures == 0))
