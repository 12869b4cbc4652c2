#!/usr/bin/python3
"""Checks three shapes of the code that reviews otherwise lose track of:
- a run's, a sweep's or a queued run's state is spelled as a string only where its enum is turned into text and
  back (orchestrator/run/run_status.cc); everywhere else uses the enums;
- no class is longer than 400 lines, its header and source (x.h and x.cc) counted together;
- every folder of evaluator/, orchestrator/ and report/ declares its code in a namespace of its own, named by
  its path (evaluator/formats/map: slamsweep::evaluator::formats::map), and in no other.
Prints each offence and exits 1."""
import os
import re
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
TOPS = ["evaluator", "orchestrator", "report", "cli", "slam"]
STATE_WORDS = re.compile(r'"(ok|failed|running|queued|cancelled|cancelling|unfinished)"')
STATE_PLACES = {"orchestrator/run/run_status.cc"}
CLASS = re.compile(r"^class (\w+)\b[^;]*$")
MAX_CLASS_LINES = 400

def sources():
    for top in TOPS:
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in sorted(names):
                if name.endswith((".h", ".cc")):
                    yield os.path.relpath(os.path.join(folder, name), ROOT)

def lines_of(path):
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as source:
        return source.read().split("\n")

NAMESPACE_OPEN = re.compile(r"^(?:inline )?namespace ((?:inline )?[A-Za-z_]\w*(?:::(?:inline )?[A-Za-z_]\w*)*) \{")
ANONYMOUS_OPEN = re.compile(r"^namespace \{")
NAMESPACE_CLOSE = re.compile(r"^\}  // namespace")


def declared_namespaces(text):
    """The full names of the namespaces `text` opens (enclosing ones included), as nesting gives them."""
    stack, names = [], set()
    for line in text:
        match = NAMESPACE_OPEN.match(line)
        if match:
            stack.append(match.group(1).replace("inline ", ""))
            names.add("::".join(part for part in stack if part))
        elif ANONYMOUS_OPEN.match(line):
            stack.append("")
        elif NAMESPACE_CLOSE.match(line) and stack:
            stack.pop()
    return names


problems = []
for path in sources():
    text = lines_of(path)
    if path not in STATE_PLACES:
        for number, line in enumerate(text, 1):
            code = line.split("//")[0]
            for match in STATE_WORDS.finditer(code):
                problems.append(f"{path}:{number}: the state {match.group(0)} spelled outside {' and '.join(sorted(STATE_PLACES))}")
    folder = os.path.dirname(path)
    if folder.split(os.sep)[0] in ("evaluator", "orchestrator", "report") and os.sep in folder:
        own = "slamsweep::" + folder.replace(os.sep, "::")
        names = {name for name in declared_namespaces(text) if name.startswith("slamsweep")}
        inside = {name for name in names if name == own or name.startswith(own + "::")}
        enclosing = {name for name in names if own.startswith(name + "::")}
        if names and not inside:
            problems.append(f"{path}: declares {', '.join(sorted(names))}, not its folder's namespace {own}")
        for name in sorted(names - inside - enclosing):
            problems.append(f"{path}: declares {name}, outside its folder's namespace {own}")
    if path.endswith(".h"):
        for line in text:
            match = CLASS.match(line)
            if not match:
                continue
            source = path[:-2] + ".cc"
            count = len(text) - 1 + (len(lines_of(source)) - 1 if os.path.exists(os.path.join(ROOT, source)) else 0)
            if count > MAX_CLASS_LINES:
                problems.append(f"{path}: class {match.group(1)} has {count} lines with its source (at most {MAX_CLASS_LINES})")

for problem in problems:
    print(problem)
print(f"{len(problems)} problem(s)")
sys.exit(1 if problems else 0)
