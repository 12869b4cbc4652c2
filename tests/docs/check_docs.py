#!/usr/bin/python3
"""Checks the front page and the manual: README.md holds at most 250 lines, no table longer than 15 rows and no
dated measurement (studies live in docs/), and every relative link of README.md and docs/**/*.md resolves: to a
file or folder of the repository and, for a link into a Markdown file with #anchor, to one of its headings.

Usage: check_docs.py REPOSITORY          exit 0 when everything holds, 1 with one line per problem otherwise
       check_docs.py --self-test         plants each kind of problem in a scratch tree and checks it is found
"""
import os
import re
import sys
import tempfile

README_MAX_LINES = 250
README_MAX_TABLE_ROWS = 15
LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
DATE = re.compile(r"\b20\d\d-\d\d-\d\d\b")


def strip_code(text):
    """The text with fenced code blocks and inline code blanked (links in code are not links)."""
    out, fenced = [], False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else re.sub(r"`[^`]*`", "", line))
    return out


def anchors(path):
    """GitHub's heading anchors of a Markdown file: lower case, punctuation dropped, spaces to dashes."""
    found = set()
    counts = {}
    for line in strip_code(open(path, encoding="utf-8").read()):
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        n = counts.get(slug, 0)
        counts[slug] = n + 1
        found.add(slug if n == 0 else f"{slug}-{n}")
    return found


def markdown_files(root):
    files = [os.path.join(root, "README.md")]
    for folder, _, names in os.walk(os.path.join(root, "docs")):
        files += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    return [f for f in files if os.path.exists(f)]


def check(root):
    problems = []
    readme = os.path.join(root, "README.md")
    if not os.path.exists(readme):
        return [f"{readme}: missing"]
    lines = open(readme, encoding="utf-8").read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) > README_MAX_LINES:
        problems.append(f"README.md: {len(lines)} lines, the front page's budget is {README_MAX_LINES} (move the rest to docs/)")
    rows, start = 0, 0
    for number, line in enumerate(strip_code("\n".join(lines) + "\n"), 1):
        if line.startswith("|"):
            if rows == 0:
                start = number
            rows += 1
        else:
            if rows - 2 > README_MAX_TABLE_ROWS:
                problems.append(f"README.md:{start}: a table of {rows - 2} rows, at most {README_MAX_TABLE_ROWS} on the front page")
            rows = 0
        if DATE.search(line):
            problems.append(f"README.md:{number}: a dated measurement ({DATE.search(line).group(0)}): studies go to docs/")
    for path in markdown_files(root):
        relative = os.path.relpath(path, root)
        for number, line in enumerate(strip_code(open(path, encoding="utf-8").read()), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                file_part, _, anchor = target.partition("#")
                resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
                if not os.path.exists(resolved):
                    problems.append(f"{relative}:{number}: link to {target}: {os.path.relpath(resolved, root)} does not exist")
                elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                    problems.append(f"{relative}:{number}: link to {target}: no heading #{anchor} in {os.path.relpath(resolved, root)}")
    return problems


def self_test():
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        with open(os.path.join(root, "docs", "page.md"), "w") as f:
            f.write("# A page\n\n## Which is better? One verdict\n\n[back](../README.md) [gone](missing.md)\n"
                    "`[in code](nowhere.md)`\n")
        table = "| a |\n|---|\n" + "| x |\n" * 16
        body = ("[ok](docs/page.md#which-is-better-one-verdict) [bad anchor](docs/page.md#nope) "
                "[web](https://example.org/x) Measured on 2026-11-28.\n" + table + "\n" + "line\n" * 240)
        with open(os.path.join(root, "README.md"), "w") as f:
            f.write(body)
        found = check(root)
        expected = ["lines, the front page's budget", "a table of 16 rows", "a dated measurement (2026-11-28)",
                    "docs/page.md#nope: no heading", "link to missing.md"]
        missing = [e for e in expected if not any(e in p for p in found)]
        extra = [p for p in found if not any(e in p for e in expected)]
        if missing or extra:
            print("self-test failed: not found", missing, "found but not planted", extra)
            return 1
    print("self-test: every planted problem was found, nothing else")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    problems = check(sys.argv[1])
    for p in problems:
        print(p)
    if not problems:
        print(f"README.md and docs/: every relative link resolves; the front page keeps its budget")
    sys.exit(1 if problems else 0)
