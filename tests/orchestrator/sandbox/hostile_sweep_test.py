#!/usr/bin/python3
"""A hostile SLAM program run by a real sweep, as the worker runs any program (adapter: command).

It tries to read the shared reference (by absolute path and by ../), a decoy output folder's
reference.tum and its own run.json; to unmount or mount anything; to read the worker's
/proc/PID/{environ,cmdline,root,mem} and /proc/1/environ; to ptrace its parent and signal the
worker's group; to connect to a listener on 127.0.0.1; to write outside raw/ and into the host's
/tmp; to hold capabilities or gain them through a setuid program; to leave a setsid daemon behind and a symbolic link in raw/ pointing at
the reference; then a bounded fork storm and a file larger than the run's disk limit.

A write attempt is judged twice: by what the program saw and by what the host has afterwards. "refused"
when both say no; "SUCCEEDED" (an escape) when the host has the file; "PHANTOM" when the program wrote a
file the host never got (a writable copy of a folder made inside the sandbox: still a fault, since the
program must see its run folder read-only); "private" for write_tmp alone, whose private /tmp must take it.

--run-folder tmp makes the sweep's folder (its output, hence every run folder) under /tmp, where the
sandbox's private /tmp is; outside (the default) makes it in --workdir, or in /var/tmp when that is
under /tmp too.

Passes when every attempt fails, the attempts run is scored ok, the fork storm and the big file end
as failed runs naming their limits, and the sweep finishes with every run recorded. Prints one line
per attempt with its outcome. --user nobody runs the whole sweep as that unprivileged user.
--legacy leaves out the keys an older slamsweep does not know (to measure it), and only reports.
--proc none makes every sandbox go without /proc (SLAMSWEEP_SANDBOX_PROC, as where the kernel refuses a fresh
one: a container); --expect-proc checks which kind the attempts run's result.json says it had.
"""
import argparse
import json
import os
import pwd
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

REFERENCE = "reference/trajectories/intel_corrected.tum"
PROCESS_LIMIT = 64
DISK_LIMIT_MB = 8
STORM = 400


def listener():
    """A TCP listener on 127.0.0.1 that counts the connections it accepts."""
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.bind(("127.0.0.1", 0))
    server.listen(16)
    server.settimeout(0.2)
    accepted = []
    stop = threading.Event()

    def serve():
        while not stop.is_set():
            try:
                connection, _ = server.accept()
                accepted.append(1)
                connection.close()
            except socket.timeout:
                pass

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    return server.getsockname()[1], accepted, stop


def sweep_yaml(args, folder, port, marker, host_tmp, decoy):
    reference = os.path.join(args.shared, REFERENCE)
    dotdot = "../" * 40 + reference.lstrip("/")
    limits = "" if args.legacy else f"""
    process_limit: {PROCESS_LIMIT}
    disk_limit_mb: {DISK_LIMIT_MB}"""
    argv = [args.hostile, "--mode", "{param:mode}", "--input", "{input}", "--output-dir", "{output_dir}",
            "--reference", reference, "--reference-dotdot", dotdot, "--decoy", decoy, "--host-tmp", host_tmp,
            "--port", str(port), "--shared", args.shared, "--marker", marker, "--storm", str(STORM), "--disk-mb", str(DISK_LIMIT_MB)]
    return f"""name: hostile
output: {folder}/out
iterations: 1
seed: 1
evaluation: {{align: se2, stages: 0}}
algorithms:
  - name: hostile
    adapter: command
    timeout_s: 120{limits}
    command:
      argv: {json.dumps(argv)}
      input_format: tum
      trajectory: {{path: trajectory.tum, format: tum}}
    parameters: {{mode: [attempts, fork, disk]}}
  - name: odometry
    adapter: odometry
sequences:
  - {{catalog: intel, name: intel-100, max_scans: 100}}
"""


def hostile_processes(hostile):
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/cmdline", "rb") as cmdline:
                if cmdline.read().split(b"\0")[0].decode(errors="replace") == hostile:
                    found.append(int(entry))
        except OSError:
            pass
    return found


def under_tmp(path):
    """Whether `path` is under /tmp as given (what the sandbox binds) or once its links are resolved."""
    return any(p == "/tmp" or p.startswith("/tmp/") for p in (os.path.normpath(path), os.path.realpath(path)))


def judge_write(name, in_sandbox, host_path, private=False):
    """One write attempt's verdict from the program's own report and the host's file: see the module's doc."""
    on_host = os.path.lexists(host_path)
    if in_sandbox is None:
        outcome = "SUCCEEDED" if on_host else "missing"
    elif on_host:
        outcome = "SUCCEEDED"
    elif in_sandbox[0] == "SUCCEEDED":
        outcome = "private" if private else "PHANTOM"
    else:
        outcome = "refused"
    seen = f"{in_sandbox[0]} ({in_sandbox[1]})" if in_sandbox else "no ATTEMPT line"
    return name, outcome, f"in the sandbox: {seen}; on the host: {host_path} {'exists' if on_host else 'does not exist'}"


def read_runs(out):
    runs = {}
    for run_id in sorted(os.listdir(os.path.join(out, "runs"))):
        folder = os.path.join(out, "runs", run_id)
        with open(os.path.join(folder, "run.json")) as handle:
            spec = json.load(handle)
        result = None
        if os.path.exists(os.path.join(folder, "result.json")):
            with open(os.path.join(folder, "result.json")) as handle:
                result = json.load(handle)
        log = ""
        if os.path.exists(os.path.join(folder, "log.txt")):
            with open(os.path.join(folder, "log.txt"), errors="replace") as handle:
                log = handle.read()
        name = spec["algorithm"]["parameters"].get("mode", spec["algorithm"]["name"])
        runs[name] = {"folder": folder, "result": result, "log": log}
    return runs


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--slamsweep", required=True)
    parser.add_argument("--hostile", required=True)
    parser.add_argument("--shared", required=True)
    parser.add_argument("--user", choices=["self", "nobody"], default="self")
    parser.add_argument("--legacy", action="store_true")
    parser.add_argument("--proc", choices=["auto", "own", "none"], default="auto",
                        help="how sandboxes get their /proc (auto: slamsweep probes)")
    parser.add_argument("--expect-proc", choices=["own", "none"], default=None)
    parser.add_argument("--workdir", default=None,
                        help="folder for the sweep with --run-folder outside (default: the current folder)")
    parser.add_argument("--run-folder", choices=["outside", "tmp"], default="outside",
                        help="make the sweep's folder under /tmp (the sandbox's private /tmp is there) or outside it")
    args = parser.parse_args()
    args.slamsweep, args.hostile = os.path.abspath(args.slamsweep), os.path.abspath(args.hostile)

    if not os.path.exists(os.path.join(args.shared, REFERENCE)) or \
            not os.path.exists(os.path.join(args.shared, "datasets/intel/intel-corrected.log.gz")):
        print(f"missing shared data: {args.shared}/{REFERENCE} and datasets/intel are needed")
        return 1 if os.environ.get("CI") == "true" else 77
    if args.user == "nobody" and os.geteuid() != 0:
        print("--user nobody needs root to switch to that user")
        return 1 if os.environ.get("CI") == "true" else 77

    if args.run_folder == "tmp":
        base = "/tmp"
    else:
        base = os.path.abspath(args.workdir or os.getcwd())
        base = "/var/tmp" if under_tmp(base) else base
    folder = tempfile.mkdtemp(prefix="slamsweep-hostile-", dir=base)
    os.chmod(folder, 0o755)
    if under_tmp(folder) != (args.run_folder == "tmp"):
        print(f"the sweep's folder {folder} is not {'under' if args.run_folder == 'tmp' else 'outside'} /tmp")
        return 1
    print(f"the sweep's folder: {folder} ({'under' if args.run_folder == 'tmp' else 'outside'} /tmp)")
    decoy_dir = os.path.join(folder, "decoy", "runs", "r0")
    os.makedirs(decoy_dir)
    decoy = os.path.join(decoy_dir, "reference.tum")
    with open(decoy, "w") as handle:
        handle.write("0 1 2 0 0 0 0 1\n")
    host_tmp = tempfile.NamedTemporaryFile("w", prefix="slamsweep-hostile-host-", dir="/tmp", delete=False)
    host_tmp.write("the host's /tmp\n")
    host_tmp.close()
    os.chmod(host_tmp.name, 0o644)
    marker = "hostile-secret-" + secrets.token_hex(8)
    port, accepted, stop = listener()
    config = os.path.join(folder, "sweep.yaml")
    with open(config, "w") as handle:
        handle.write(sweep_yaml(args, folder, port, marker, host_tmp.name, decoy))

    env = dict(os.environ)
    env["SLAMSWEEP_SHARED"] = args.shared
    # The worker holds this; a program that reads it got into the worker's environment.
    env["SLAMSWEEP_HOSTILE_SECRET"] = marker
    if args.proc != "auto":
        env["SLAMSWEEP_SANDBOX_PROC"] = args.proc
    else:
        env.pop("SLAMSWEEP_SANDBOX_PROC", None)
    command = [args.slamsweep, "run", config, "--jobs", "1", "--no-report"]
    if args.user == "nobody":
        nobody = pwd.getpwnam("nobody")
        for root, dirs, files in os.walk(folder):
            for name in [root] + [os.path.join(root, item) for item in dirs + files]:
                os.chown(name, nobody.pw_uid, nobody.pw_gid)
        env["HOME"] = folder
        command = ["setpriv", f"--reuid={nobody.pw_uid}", f"--regid={nobody.pw_gid}", "--clear-groups",
                   "--inh-caps=-all", "--"] + command
    print("running:", " ".join(command), flush=True)
    started = time.monotonic()
    sweep = subprocess.run(command, env=env, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(sweep.stdout)
    print(f"sweep exit code {sweep.returncode} after {time.monotonic() - started:.1f} s")
    time.sleep(0.5)
    stop.set()

    problems = []
    outcomes = []  # (attempt, outcome, detail)
    out = os.path.join(folder, "out")
    runs = read_runs(out) if os.path.isdir(os.path.join(out, "runs")) else {}
    attempts = runs.get("attempts", {"log": "", "result": None, "folder": ""})
    run_folder = attempts["folder"] or os.path.join(out, "runs", "(none)")
    # Each write attempt and the file the host would have if it got through.
    writes = {"write_run_folder": os.path.join(run_folder, "hostile-was-here"),
              "mkdir_run_folder": os.path.join(run_folder, "hostile-folder"),
              "write_output_folder": os.path.join(out, "hostile-was-here"),
              "write_input_folder": os.path.join(run_folder, "input", "hostile-was-here"),
              "write_decoy_output": decoy + ".hostile",
              "write_root": "/hostile-was-here",
              "write_tmp": host_tmp.name + ".hostile"}
    written = {}
    for line in attempts["log"].splitlines():
        if line.startswith("ATTEMPT "):
            name, _, rest = line[len("ATTEMPT "):].partition(": ")
            outcome, _, detail = rest.partition(" (")
            if name in writes:
                written[name] = (outcome, detail.rstrip(")"))
                continue
            outcomes.append((name, outcome, detail.rstrip(")")))
    seen = {name for name, _, _ in outcomes} | set(written)
    # The private /tmp is the program's scratch: write_tmp must get through there and only there.
    outcomes += [judge_write(name, written.get(name), path, private=name == "write_tmp")
                 for name, path in writes.items()]
    if not seen:
        problems.append("the attempts run printed no ATTEMPT line (log.txt):\n" + attempts["log"][-2000:])

    # What is judged from outside the sandbox.
    link = os.path.join(attempts["folder"], "raw", "stolen-reference.tum")
    outcomes.append(("symlink_out_of_raw", "SUCCEEDED" if os.path.lexists(link) else "refused",
                     "raw/stolen-reference.tum is still there for the worker to follow" if os.path.lexists(link)
                     else "the worker removed the link before reading raw/"))
    daemons = hostile_processes(args.hostile)
    for pid in daemons:
        os.kill(pid, signal.SIGKILL)
    outcomes.append(("setsid_daemon", "SUCCEEDED" if daemons else "refused",
                     f"{len(daemons)} hostile process(es) outlived the run" if daemons else "nothing outlived the run"))
    outcomes.append(("tcp_listener_side", "SUCCEEDED" if accepted else "refused",
                     f"the listener accepted {len(accepted)} connection(s)"))
    for name in ["fork", "disk"]:
        for line in runs.get(name, {"log": ""})["log"].splitlines():
            if line.startswith("ATTEMPT "):
                attempt, _, rest = line[len("ATTEMPT "):].partition(": ")
                outcome, _, detail = rest.partition(" (")
                outcomes.append((attempt, outcome, detail.rstrip(")")))

    def expected(name):
        return "private" if name == "write_tmp" else "refused"

    print(f"\n{'attempt':28} outcome     detail")
    for name, outcome, detail in outcomes:
        print(f"{name:28} {outcome:11} {detail[:250]}")
        if outcome != expected(name):
            problems.append(f"attempt {name} {outcome}: {detail}")

    def result_of(name):
        return (runs.get(name) or {}).get("result") or {}

    print()
    for name in ["attempts", "fork", "disk", "odometry"]:
        result = result_of(name)
        print(f"run {name:9} status={result.get('status')} failure_kind={result.get('failure_kind')} "
              f"reason={result.get('reason')} flags={result.get('flags')}")
    if result_of("attempts").get("status") != "ok":
        problems.append(f"the attempts run was not scored ok: {result_of('attempts')}")
    if result_of("odometry").get("status") != "ok":
        problems.append("the odometry baseline beside it did not finish ok: the sweep was affected")
    fork, disk = result_of("fork"), result_of("disk")
    if fork.get("failure_kind") != "process_limit" or "process_limit" not in (fork.get("reason") or ""):
        problems.append(f"the fork storm did not end as a failed run naming process_limit: {fork}")
    if disk.get("failure_kind") != "disk_limit" or "disk_limit_mb" not in (disk.get("reason") or ""):
        problems.append(f"the big file did not end as a failed run naming disk_limit_mb: {disk}")
    if not os.path.exists(os.path.join(out, "summary.json")):
        problems.append("the sweep wrote no summary.json")
    elif len(json.load(open(os.path.join(out, "summary.json")))["runs"]) != 4:
        problems.append("summary.json does not hold the 4 runs")
    if sweep.returncode != 1:
        problems.append(f"the sweep exited with {sweep.returncode}, expected 1 (two runs failed on their limits)")
    for check in ["attempts"] + [name for name in ["attempts", "fork", "disk"] if name not in runs]:
        if check not in runs:
            problems.append(f"no run folder for mode {check}")
    if ("umount" not in seen or "nested_user_namespace" not in seen) and seen:
        problems.append("the attempts run stopped before trying everything")
    sandbox = result_of("attempts").get("sandbox") or {}
    print(f"sandbox of the attempts run: {json.dumps(sandbox)}")
    if not args.legacy and sandbox.get("isolated") is not True:
        problems.append(f"result.json does not say the attempts run was isolated: {sandbox}")
    expected_proc = args.expect_proc or (args.proc if args.proc != "auto" else None)
    if expected_proc and sandbox.get("proc") != expected_proc:
        problems.append(f"the sandbox's /proc was {sandbox.get('proc')!r}, expected {expected_proc!r}")

    os.unlink(host_tmp.name)
    for leftover in [host_tmp.name + ".hostile"]:
        if os.path.exists(leftover):
            os.unlink(leftover)
    if args.legacy:
        print(f"\n(legacy: {sum(1 for o in outcomes if o[1] != expected(o[0]))} of {len(outcomes)} attempts succeeded; "
              f"results in {folder})")
        return 0
    if problems:
        print("\nFAILED:\n- " + "\n- ".join(problems))
        print(f"(results kept in {folder})")
        return 1
    shutil.rmtree(folder, ignore_errors=True)
    print(f"\nevery attempt was refused ({len(outcomes)} attempts, as {args.user}, /proc: {sandbox.get('proc')}, "
          f"run folder {'under' if args.run_folder == 'tmp' else 'outside'} /tmp)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
