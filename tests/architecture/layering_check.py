#!/usr/bin/python3
"""Checks the layering of the code from its #include lines: the top folders depend downwards only
(cli -> report -> orchestrator -> evaluator; the slam/ drivers use the evaluator's formats only) and no two folders
include each other, directly or through others. Prints each offending include and exits 1."""
import collections
import os
import re
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
LAYERS = {"evaluator": 0, "orchestrator": 1, "report": 2, "cli": 3}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')

def sources():
    for top in list(LAYERS) + ["slam"]:
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in sorted(names):
                if name.endswith((".h", ".cc")):
                    yield os.path.relpath(os.path.join(folder, name), ROOT)

problems = []
edges = collections.defaultdict(dict)  # folder -> included folder -> one example "file:line"
for path in sources():
    top = path.split(os.sep)[0]
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as source:
        for number, line in enumerate(source, 1):
            match = INCLUDE.match(line)
            if not match or not os.path.exists(os.path.join(ROOT, match.group(1))):
                continue
            target = match.group(1)
            target_top = target.split("/")[0]
            where = f"{path}:{number}: includes {target}"
            if top == "slam" and target_top not in ("slam", "evaluator"):
                problems.append(f"{where} (slam/ drivers use the evaluator only)")
            elif top in LAYERS and target_top in LAYERS and LAYERS[target_top] > LAYERS[top]:
                problems.append(f"{where} ({top} is below {target_top})")
            here, there = os.path.dirname(path), os.path.dirname(target)
            if here != there:
                edges[here].setdefault(there, where)

# Folder cycles: strongly connected components of more than one folder.
index, low, stack, on_stack, cycles = {}, {}, [], set(), []
sys.setrecursionlimit(100000)
def visit(node):
    index[node] = low[node] = len(index)
    stack.append(node)
    on_stack.add(node)
    for other in edges.get(node, {}):
        if other not in index:
            visit(other)
            low[node] = min(low[node], low[other])
        elif other in on_stack:
            low[node] = min(low[node], index[other])
    if low[node] == index[node]:
        component = []
        while True:
            member = stack.pop()
            on_stack.discard(member)
            component.append(member)
            if member == node:
                break
        if len(component) > 1:
            cycles.append(sorted(component))
for node in sorted(set(edges) | {t for e in edges.values() for t in e}):
    if node not in index:
        visit(node)
for cycle in cycles:
    members = set(cycle)
    arrows = [edges[a][b] for a in cycle for b in edges.get(a, {}) if b in members]
    problems.append("folders include each other: " + ", ".join(cycle) + "\n    " + "\n    ".join(arrows))

for problem in problems:
    print(problem)
print(f"{len(problems)} layering problem(s) in {len(edges)} folders")
sys.exit(1 if problems else 0)
