#!/usr/bin/env bash
# The Docker image built and run for real, as a lab administrator would deploy it: installs Debian's
# docker.io, debootstrap and docker-compose when missing, starts a private daemon when none runs
# (docker/daemon.sh), builds the image (docker/build-image.sh) and checks in containers:
#   - `slamsweep --version`, `slamsweep algorithms` (all eight roster algorithms installed, Cartographer's
#     options readable), every installed program's libraries present, no compiler in the image;
#   - the quick-start sweep with the shared data read-only and a results volume: every run ok, its report
#     and junit.xml copied to the host;
#   - docker-compose up of `slamsweep serve` on the host's loopback, `slamsweep submit --wait` from the
#     host running every roster driver, `down` leaving the results volume and its results intact;
#   - where the checkout has the sandbox, its hostile program run by a sweep in each service's container
#     (compose.yaml's seccomp profile and options, no privileges, Docker's masked /proc: the sandbox has
#     none of its own there): nothing escapes.
# Then it removes the containers, volumes and images it made and stops the daemon it started.
#
# usage: scripts/docker-check.sh [SLAMSWEEP_BIN] [OUT_DIR]
#   SLAMSWEEP_BIN  the host's slamsweep, for `submit` (default build/slamsweep)
#   OUT_DIR        what the check copies out of the containers, its logs and times.txt (default out/docker-check)
# Environment: SLAMSWEEP_SHARED (the data folder, default ../shared), SLAMSWEEP_PEERS (tarballs, default
# $SLAMSWEEP_SHARED/peers), SLAMSWEEP_DOCKER_SCRATCH (the private daemon's folder, docker/daemon.sh),
# SLAMSWEEP_DOCKER_KEEP=1 keeps the image and its build cache (a second run reuses the layers);
# SLAMSWEEP_HOSTILE the sandbox's hostile program (default beside SLAMSWEEP_BIN's build, tests/...);
# SLAMSWEEP_DOCKER_IMAGE=TAG checks that image (built before, kept) instead of building one, and keeps it.
# Exit code: 0 every check passed, 1 some failed; needs root (or a running daemon) and about 45 minutes
# on 2 cores when nothing is cached. The ctest `docker_check` (label docker) runs it; the nightly job runs that.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
docker_client=/usr/bin/docker
slamsweep=${1:-${SLAMSWEEP_BUILD_DIR:-$root/build}/slamsweep}
out=${2:-$root/out/docker-check}
shared=${SLAMSWEEP_SHARED:-$root/../shared}
export SLAMSWEEP_PEERS=${SLAMSWEEP_PEERS:-$shared/peers}
run_id="check-$$"
tag=${SLAMSWEEP_DOCKER_IMAGE:-slamsweep-$run_id:latest}
volume="slamsweep-$run_id-results"
project="slamsweep-$run_id"
compose_file=$root/docker/compose.yaml

passed=0
failed=0
pass() { passed=$((passed + 1)); echo "PASS $*"; }
fail() { failed=$((failed + 1)); echo "FAIL $*"; }
step() { echo "== $*"; }

[[ -x "$slamsweep" ]] || { echo "docker-check: $slamsweep is not built (scripts/build.sh)" >&2; exit 1; }
# Absolute: the hostile program beside it is bind-mounted, and docker-compose takes a relative source for a volume name.
slamsweep=$(cd "$(dirname "$slamsweep")" && pwd)/$(basename "$slamsweep")
[[ -d "$shared/datasets" ]] || { echo "docker-check: $shared/datasets missing (set SLAMSWEEP_SHARED to the shared data folder)" >&2; exit 1; }
shared=$(cd "$shared" && pwd)
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)

step "packages: docker.io, debootstrap, docker-compose"
"$root/scripts/install-deps.sh" docker.io debootstrap docker-compose

step "daemon"
eval "$("$root/docker/daemon.sh" start)"
images_before=$("$docker_client" images -aq --no-trunc | sort -u)
# From docker/: docker-compose 1.29 reads security_opt's seccomp profile relative to the working folder
# (not the compose file's): from docker/, compose.yaml's ./seccomp-sandbox.json is found whichever reads it.
# COMPOSE_HTTP_TIMEOUT: with vfs, creating a container copies the whole image (a minute or more on a loaded
# machine), longer than docker-compose 1.29's default 60 s wait for the daemon's answer.
compose() {
  (cd "$(dirname "$compose_file")" &&
    COMPOSE_HTTP_TIMEOUT=${COMPOSE_HTTP_TIMEOUT:-600} SLAMSWEEP_IMAGE=${compose_image:-$tag} SLAMSWEEP_DATASETS=$shared/datasets SLAMSWEEP_LISTEN=127.0.0.1:$port \
      docker-compose --project-name "$project" --file "$compose_file" "$@")
}
port=0
compose_image=""
hostile_tag="slamsweep-$run_id-hostile:latest"

# Containers, volumes and images this run made; the daemon when it started it. Runs on any exit.
cleanup() {
  local status=$?
  set +e
  step "cleanup"
  compose down --volumes --timeout 30 >/dev/null 2>&1
  "$docker_client" ps -aq --filter "label=slamsweep.check=$run_id" | xargs -r "$docker_client" rm -f >/dev/null
  "$docker_client" volume rm -f "$volume" >/dev/null 2>&1
  "$docker_client" rmi "$hostile_tag" >/dev/null 2>&1
  if [[ -n "${SLAMSWEEP_DOCKER_IMAGE:-}" ]]; then
    echo "docker-check: keeping $tag (SLAMSWEEP_DOCKER_IMAGE: not built by this run)"
  elif [[ "${SLAMSWEEP_DOCKER_KEEP:-0}" != 1 ]]; then
    "$docker_client" rmi "$tag" >/dev/null 2>&1
    # The build stage's layers and anything else this run built (newest first, until none goes).
    local leftover removed=1
    while ((removed > 0)); do
      removed=0
      for leftover in $(comm -13 <(echo "$images_before") <("$docker_client" images -aq --no-trunc | sort -u)); do
        "$docker_client" rmi "$leftover" >/dev/null 2>&1 && removed=$((removed + 1))
      done
    done
  else
    echo "docker-check: SLAMSWEEP_DOCKER_KEEP=1: keeping $tag and its build layers"
  fi
  if [[ "$SLAMSWEEP_DOCKER_STARTED" == 1 ]]; then
    "$root/docker/daemon.sh" stop
  fi
  exit "$status"
}
trap cleanup EXIT

# in_image ARGS...: a throw-away container of the image, marked for cleanup, without network, with the
# options compose.yaml gives it so that each SLAM program's sandbox can be made (docker/README.md).
in_image() {
  "$docker_client" run --rm --label "slamsweep.check=$run_id" --network none \
    --security-opt "seccomp=$root/docker/seccomp-sandbox.json" --security-opt apparmor=unconfined "$@"
}
# timed NAME COMMAND...: runs it and appends "NAME_s SECONDS" to times.txt; its exit status.
timed() {
  local name=$1 began status=0
  shift
  began=$(date +%s)
  "$@" || status=$?
  echo "${name}_s $(($(date +%s) - began))" >>"$out/times.txt"
  return "$status"
}
# no_proc_runs FOLDER: how many result.json under it say the program's sandbox had no /proc of its own.
no_proc_runs() { grep -rl --include=result.json '"proc":"none"' "$1" 2>/dev/null | wc -l; }

step "build"
start=$(date +%s)
if [[ -n "${SLAMSWEEP_DOCKER_IMAGE:-}" ]]; then
  "$docker_client" image inspect "$tag" >/dev/null 2>&1 && pass "the image $tag is there (not built: SLAMSWEEP_DOCKER_IMAGE)" ||
    { fail "no image $tag (SLAMSWEEP_DOCKER_IMAGE)"; echo "$passed passed, $failed failed"; exit 1; }
elif "$root/docker/build-image.sh" "$tag" >"$out/build.log" 2>&1; then
  pass "the image builds ($(($(date +%s) - start)) s)"
  echo "build_s $(($(date +%s) - start))" >>"$out/times.txt"
else
  fail "the image does not build; the end of $out/build.log:"
  tail -n 30 "$out/build.log"
  echo "$passed passed, $failed failed"
  exit 1
fi
size=$("$docker_client" image inspect --format '{{.Size}}' "$tag")
echo "image_mb $((size / 1000000))" >>"$out/times.txt"
echo "docker-check: image $tag is $((size / 1000000)) MB"

step "the program in the image"
if version=$(in_image "$tag" --version 2>&1); then
  pass "slamsweep --version: $version"
else
  fail "slamsweep --version failed: $version"
fi
in_image "$tag" algorithms >"$out/algorithms.txt" 2>&1 || true
for algorithm in gmapping tinyslam vinyslam hector cartographer slam-toolbox lama lama-pf; do
  if grep -qE "^$algorithm +\[installed\]" "$out/algorithms.txt"; then
    pass "slamsweep algorithms: $algorithm installed"
  else
    fail "slamsweep algorithms: $algorithm not installed ($out/algorithms.txt)"
  fi
done
# Cartographer's parameters come from its Lua options: listed only when the installed driver reads them.
if grep -q "trajectory_builder" "$out/algorithms.txt"; then
  pass "Cartographer's options read from the installed Lua files"
else
  fail "Cartographer lists no trajectory_builder parameters ($out/algorithms.txt)"
fi
missing=$(in_image --entrypoint /bin/sh "$tag" -c \
  'for f in /opt/slamsweep/bin/* /opt/slamsweep/lib/slamsweep/*; do ldd "$f" | sed "s|^|$f: |"; done' |
  grep 'not found' || true)
[[ -z "$missing" ]] && pass "every installed program finds its libraries" || fail "missing libraries: $missing"
compilers=$(in_image --entrypoint /bin/sh "$tag" -c 'for c in cc c++ gcc g++ clang cmake; do command -v $c; done' || true)
[[ -z "$compilers" ]] && pass "no compiler in the runtime image" || fail "compilers in the runtime image: $compilers"
user=$(in_image --entrypoint /usr/bin/id "$tag" -un 2>&1 || true)
[[ "$user" == slamsweep ]] && pass "sweeps run as the unprivileged user slamsweep" || fail "the image runs as '$user'"

step "the quick start in a container"
"$docker_client" volume create --label "slamsweep.check=$run_id" "$volume" >/dev/null
start=$(date +%s)
status=0
in_image -v "$shared:/data:ro" -v "$volume:/results" "$tag" \
  run configs/quickstart.yaml --output /results/quickstart >"$out/quickstart.log" 2>&1 || status=$?
quickstart_s=$(($(date +%s) - start))
echo "quickstart_s $quickstart_s" >>"$out/times.txt"
tail -n 3 "$out/quickstart.log"
((status == 0)) && pass "the quick start exits 0 in the container ($quickstart_s s)" ||
  fail "the quick start exited $status (see $out/quickstart.log)"
# The results, from the volume onto the host.
copier=$("$docker_client" create --label "slamsweep.check=$run_id" -v "$volume:/results" "$tag")
"$docker_client" cp "$copier:/results/quickstart" "$out/quickstart" || true
"$docker_client" rm -f "$copier" >/dev/null
count() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["counts"][sys.argv[2]])' "$@" 2>/dev/null || echo "?"; }
total=$(count "$out/quickstart/summary.json" total)
failed_runs=$(count "$out/quickstart/summary.json" failed)
[[ "$total" == 18 && "$failed_runs" == 0 ]] && pass "18 quick-start runs, every one ok" ||
  fail "quick start: $total runs, $failed_runs failed (expected 18, 0)"
[[ -s "$out/quickstart/report/index.html" ]] && grep -qi '<html' "$out/quickstart/report/index.html" &&
  pass "the report is on the host" || fail "no report/index.html on the host"
[[ $(grep -c '<testcase ' "$out/quickstart/junit.xml" 2>/dev/null) == 18 ]] &&
  pass "junit.xml with 18 testcases is on the host" || fail "junit.xml missing or without 18 testcases"
# Docker's masked /proc: the probe gives each sandbox none, and every program's result.json says so.
programs=$(grep -rl --include=result.json '"sandbox":{' "$out/quickstart/runs" 2>/dev/null | wc -l)
no_proc=$(no_proc_runs "$out/quickstart/runs")
((programs > 0 && no_proc == programs)) && pass "each of the $programs sandboxed quick-start runs says it had no /proc" ||
  fail "of $programs sandboxed quick-start runs, $no_proc say they had no /proc"

step "the service with docker-compose"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
compose config --quiet && pass "compose.yaml is valid for $(docker-compose version --short)" ||
  fail "docker-compose rejects compose.yaml"
if timed compose_up compose up --detach --no-build serve >"$out/compose-up.log" 2>&1; then
  pass "docker-compose up serve"
else
  fail "docker-compose up serve failed: $(tail -n 5 "$out/compose-up.log")"
fi
# vfs copies the image into the container's root before it starts: a minute or more.
waited=0
until (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || ((waited++ >= 300)); do sleep 1; done
echo "serve_listening_s $waited" >>"$out/times.txt"
mkdir -p "$out/service"
status=0
timed submit "$slamsweep" submit "$root/tests/docker/service_sweep.yaml" --server "http://127.0.0.1:$port" --wait \
  --junit "$out/service/junit.xml" --report "$out/service/report" >"$out/service/submit.log" 2>&1 || status=$?
tail -n 3 "$out/service/submit.log"
((status == 0)) && pass "slamsweep submit --wait from the host: every roster driver ran ok in the container" ||
  fail "submit --wait exited $status (see $out/service/submit.log; service log: compose logs serve)"
[[ $(grep -c '<testcase ' "$out/service/junit.xml" 2>/dev/null) == 9 ]] &&
  pass "the service's junit.xml has the 9 runs" || fail "the service's junit.xml is missing or lacks runs"
compose logs --no-color serve >"$out/service/serve.log" 2>&1 || true
grep -q "sandboxes have no /proc here" "$out/service/serve.log" &&
  pass "serve probed once: its programs' sandboxes have no /proc in this container" ||
  fail "serve's log does not say how its sandboxes get their /proc ($out/service/serve.log)"
if timed compose_down compose down --timeout 60 >"$out/compose-down.log" 2>&1; then
  pass "docker-compose down"
else
  fail "docker-compose down failed: $(tail -n 5 "$out/compose-down.log")"
fi
kept=$(in_image -v "${project}_results:/results" --entrypoint /bin/sh "$tag" -c \
  'ls /results/service/queue.sqlite && find /results/service -name summary.json | head -n 1 &&
   echo "sandboxed $(grep -rl --include=result.json "\"sandbox\":{" /results/service | wc -l) no_proc $(grep -rl --include=result.json "\"proc\":\"none\"" /results/service | wc -l)"' 2>&1 || true)
echo "$kept" >"$out/service/volume.txt"
[[ "$kept" == *queue.sqlite*summary.json* ]] && pass "the results volume outlives down (queue and results kept)" ||
  fail "the results volume lost the service's data: $kept"
# The eight roster drivers ran sandboxed without /proc (the odometry baseline runs no program): every
# result.json in the volume that has a sandbox says so (the data folder holds 18 for the 9 runs here).
counts=$(tail -n 1 <<<"$kept")
sandboxed=$(awk '{ print $2 }' <<<"$counts")
no_proc=$(awk '{ print $4 }' <<<"$counts")
[[ "$sandboxed" =~ ^[0-9]+$ ]] && ((sandboxed >= 8 && no_proc == sandboxed)) &&
  pass "the programs' results in the volume ($sandboxed result.json) all say their sandbox had no /proc" ||
  fail "the service's results in the volume: $counts (expected every sandboxed run without /proc, at least 8)"

step "the sandbox's hostile program as a SLAM program in a container"
# The sandbox's own test (a real sweep whose command-adapter program tries to escape), run inside the
# container of the `slamsweep` service with compose.yaml's security options, never --privileged.
hostile_script=$root/tests/orchestrator/sandbox/hostile_sweep_test.py
hostile=${SLAMSWEEP_HOSTILE:-$(dirname "$slamsweep")/tests/orchestrator/sandbox/slamsweep-hostile}
if [[ ! -f "$hostile_script" ]]; then
  echo "docker-check: this checkout has no sandbox (no $hostile_script): nothing to run"
elif [[ ! -x "$hostile" ]]; then
  fail "the hostile program $hostile is not built (cmake --build build --target slamsweep-hostile)"
else
  # Its settings, not its comments (which say "without --privileged").
  grep -v '^[[:space:]]*#' "$compose_file" | grep -qE 'privileged|cap_add' && fail "compose.yaml asks for privileges" ||
    pass "compose.yaml asks for no privileges or capabilities"
  grep -q 'seccomp=' "$compose_file" && pass "compose.yaml names a seccomp profile" ||
    fail "compose.yaml names no seccomp profile"
  # The test is Python; the image has none: an image of its own adds it, removed at cleanup.
  compose_image=$tag
  if ! in_image --entrypoint /bin/sh "$tag" -c 'command -v python3' >/dev/null 2>&1; then
    printf 'FROM %s\nUSER root\nRUN apt-get update && apt-get install -y --no-install-recommends python3 && rm -rf /var/lib/apt/lists/*\nUSER slamsweep\n' "$tag" |
      "$docker_client" build --network host -t "$hostile_tag" - >"$out/hostile-image.log" 2>&1 &&
      compose_image=$hostile_tag || fail "no image with python3 for the hostile test (see $out/hostile-image.log)"
  fi
  # In each service's container: `serve` shares the host's network (its sandboxes must not), `slamsweep` has
  # none. The probe must choose the sandbox without /proc there (--expect-proc none): Docker masks /proc.
  for service in serve slamsweep; do
    status=0
    timed "hostile_$service" compose run --rm --no-deps -T \
      -v "$shared/reference:/data/reference:ro" \
      -v "$hostile:/opt/hostile/slamsweep-hostile:ro" -v "$hostile_script:/opt/hostile/hostile_sweep_test.py:ro" \
      --entrypoint python3 "$service" /opt/hostile/hostile_sweep_test.py --slamsweep /opt/slamsweep/bin/slamsweep \
      --hostile /opt/hostile/slamsweep-hostile --shared /data --workdir /home/slamsweep --expect-proc none \
      >"$out/hostile-$service.log" 2>&1 || status=$?
    tail -n 3 "$out/hostile-$service.log"
    ((status == 0)) && pass "the hostile program, run by a sweep in the $service service's container, escaped nowhere" ||
      fail "the hostile program's test exited $status in the $service service's container (see $out/hostile-$service.log)"
  done
  compose_image=""
fi

echo "docker-check: times and size in $out/times.txt"
echo "$passed passed, $failed failed"
((failed == 0))
