#!/usr/bin/python3
"""Plants known defects (mutants.json) one at a time and shows that the tests meant to catch them fail.

Nothing in the source tree is changed. For each mutant the one source file is copied into a scratch
folder with the defect planted, compiled with the build's own compile command, and linked into a copy
of the test program with the build's own link command, the mutant object placed before the libraries
so that it replaces the library's member. Then the named tests run, first in the unmutated test
program (they must pass) and then in the mutant (they must fail: the mutant is "killed").

Usage: bench/mutation/mutation_check.py BUILD_DIR [--only NAME[,NAME...]] [--keep DIR]
BUILD_DIR is a configured Ninja build (scripts/build.sh) whose test programs are built.
Prints a table; exit code 0 when every mutant is killed, 1 when one survives, 2 on a usage or
build error (a mutant whose text no longer occurs is an error: the list must follow the code).
"""
import argparse
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_ROOT = os.path.dirname(os.path.dirname(HERE))


def fail(message):
    print(f"mutation_check: error: {message}", file=sys.stderr)
    sys.exit(2)


def ninja_commands(build_dir, target):
    """The commands Ninja would run to build `target` from scratch, one per line, in order."""
    result = subprocess.run(["ninja", "-C", build_dir, "-t", "commands", target], capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"ninja -t commands {target}: {result.stderr.strip()}")
    return result.stdout.splitlines()


def test_program_path(build_dir, target):
    for line in reversed(ninja_commands(build_dir, target)):
        words = shlex.split(line)
        if "-o" in words and os.path.basename(words[words.index("-o") + 1]) == target:
            return words[words.index("-o") + 1], line
    fail(f"no link command for {target} in {build_dir}")


def compile_command(build_dir, source):
    with open(os.path.join(build_dir, "compile_commands.json")) as f:
        entries = json.load(f)
    wanted = os.path.join(SOURCE_ROOT, source)
    for entry in entries:
        if os.path.realpath(entry["file"]) == os.path.realpath(wanted):
            return entry["command"]
    fail(f"{source}: not in {build_dir}/compile_commands.json")


def run(words, cwd, log):
    with open(log, "a") as out:
        out.write("$ " + " ".join(shlex.quote(w) for w in words) + "\n")
        out.flush()
        return subprocess.run(words, cwd=cwd, stdout=out, stderr=subprocess.STDOUT).returncode


def gtest(program, gtest_filter, log):
    """(exit status, number of failed tests) of the filtered tests."""
    status = run([program, f"--gtest_filter={gtest_filter}", "--gtest_brief=1"], os.path.dirname(program), log)
    return status


def check_mutant(build_dir, mutant, scratch, log):
    source = os.path.join(SOURCE_ROOT, mutant["source"])
    with open(source) as f:
        text = f.read()
    if text.count(mutant["find"]) != 1:
        fail(f"mutant {mutant['name']}: its text occurs {text.count(mutant['find'])} times in {mutant['source']} "
             "(expected once): update bench/mutation/mutants.json")
    folder = os.path.join(scratch, mutant["name"])
    os.makedirs(folder, exist_ok=True)
    mutant_source = os.path.join(folder, os.path.basename(source))
    with open(mutant_source, "w") as f:
        f.write(text.replace(mutant["find"], mutant["replace"]))

    # Compile the planted copy with the build's command for the original (same flags, includes, cwd).
    words = shlex.split(compile_command(build_dir, mutant["source"]))
    mutant_object = os.path.join(folder, "mutant.o")
    out = []
    skip = 0
    for i, word in enumerate(words):
        if skip:
            skip -= 1
            continue
        if word in ("-MD",):
            continue
        if word in ("-MT", "-MF"):
            skip = 1
            continue
        if word == "-o":
            out += ["-o", mutant_object]
            skip = 1
            continue
        if word == "-c":
            out += ["-c", mutant_source]
            skip = 1
            continue
        out.append(word)
    if run(out, build_dir, log) != 0:
        fail(f"mutant {mutant['name']} does not compile (see {log})")

    # Link a copy of the test program with the mutant object ahead of the libraries.
    program, link_line = test_program_path(build_dir, mutant["test_target"])
    link = shlex.split(link_line)
    # Ninja wraps link commands as ": && c++ ... && :"; keep the command between the no-ops.
    while link and link[0] in (":", "&&"):
        link.pop(0)
    # ... and may chain post-build steps (gtest test discovery) after "&&": only the link itself runs.
    if "&&" in link:
        link = link[:link.index("&&")]
    output_index = link.index("-o")
    mutant_program = os.path.join(folder, mutant["test_target"])
    link = link[:output_index] + [mutant_object, "-o", mutant_program] + link[output_index + 2:]
    if run(link, build_dir, log) != 0:
        fail(f"mutant {mutant['name']} does not link (see {log})")

    original = os.path.join(build_dir, program)
    if not os.access(original, os.X_OK):
        fail(f"{original} is not built: cmake --build {build_dir} --target {mutant['test_target']}")
    clean_status = gtest(original, mutant["gtest_filter"], log)
    mutant_status = gtest(mutant_program, mutant["gtest_filter"], log)
    return clean_status, mutant_status


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("--only", default="", help="comma-separated mutant names")
    parser.add_argument("--keep", default="", help="keep the scratch folder (and its log) here")
    args = parser.parse_args()
    build_dir = os.path.abspath(args.build_dir)
    if not os.path.isfile(os.path.join(build_dir, "build.ninja")):
        fail(f"{build_dir}: not a Ninja build folder (scripts/build.sh makes one)")
    with open(os.path.join(HERE, "mutants.json")) as f:
        mutants = json.load(f)["mutants"]
    if args.only:
        wanted = args.only.split(",")
        unknown = [name for name in wanted if name not in {m["name"] for m in mutants}]
        if unknown:
            fail(f"--only: no mutant {', '.join(unknown)} (known: {', '.join(m['name'] for m in mutants)})")
        mutants = [m for m in mutants if m["name"] in wanted]
    scratch = args.keep or tempfile.mkdtemp(prefix="slamsweep-mutants-")
    os.makedirs(scratch, exist_ok=True)
    log = os.path.join(scratch, "mutation.log")
    rows, survivors = [], 0
    try:
        for mutant in mutants:
            start = time.monotonic()
            clean, mutated = check_mutant(build_dir, mutant, scratch, log)
            if clean != 0:
                fail(f"{mutant['test_target']} --gtest_filter={mutant['gtest_filter']} fails without any mutant "
                     f"(see {log}): fix the test first")
            killed = mutated != 0
            survivors += 0 if killed else 1
            rows.append((mutant["name"], mutant["what"], f"{mutant['source']}", f"{mutant['test_target']} {mutant['gtest_filter']}",
                         "pass", "FAIL (killed)" if killed else "pass (SURVIVED)", f"{time.monotonic() - start:.0f} s"))
            print(f"mutation_check: {mutant['name']}: {'killed' if killed else 'SURVIVED'}", flush=True)
    finally:
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
    print("| mutant | defect | planted in | tests | unmutated | mutant | time |")
    print("|---|---|---|---|---|---|---|")
    for row in rows:
        print("| " + " | ".join(row) + " |")
    print(f"{len(rows) - survivors} of {len(rows)} mutants killed")
    return 1 if survivors else 0


if __name__ == "__main__":
    sys.exit(main())
