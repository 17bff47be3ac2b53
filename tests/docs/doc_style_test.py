#!/usr/bin/env python3
"""Checks that the docs stay pages a user reads, not a lab notebook.

    doc_style_test.py SOURCE_DIR

Over README.md and every docs/**/*.md:
- docs/performance.md has at most MAX_PERFORMANCE_LINES lines;
- no document cites an issue or pull request by number ("issue 9",
  "issues #12", "PR 3"): a page must stand alone. A bare "#N" is not
  checked, since names such as glTF's "Wood #1" look the same;
- no document points at run logs or the old benchmark folder
  (docs/benchmarks/, runN.sh, runN.log): raw measurements live in git history,
  and docs/design/README.md, the one page that says where, is exempt;
- every relative link to a file ("[text](path)", "[text](path#anchor)")
  names a file or folder that exists, and its anchor, and that of a link
  within the page ("[text](#anchor)"), names a heading of that Markdown
  file (spelt as GitHub spells a heading's anchor).
Each problem is printed as FILE:LINE: what; the test fails if there is any.
"""
import os
import re
import sys

MAX_PERFORMANCE_LINES = 300

ISSUE_NUMBER = re.compile(r"\b(?:issues?|PRs?|pull requests?)\s*#?\s*\d+", re.IGNORECASE)
RUN_LOGS = re.compile(r"docs/benchmarks|\bbenchmarks/20\d\d-|\brun\d+\.(?:sh|log)\b|\brun\d+\.\{")
HISTORY_PAGE = os.path.join("docs", "design", "README.md")
LINK = re.compile(r"\]\(([^)\s]+)\)")


def documents(root):
    yield os.path.join(root, "README.md")
    for folder, _, files in os.walk(os.path.join(root, "docs")):
        for name in sorted(files):
            if name.endswith(".md"):
                yield os.path.join(folder, name)


def heading_anchors(path, cache={}):
    """The anchors GitHub gives the headings of a Markdown file: lowercase,
    punctuation other than '-' and '_' dropped, spaces turned into '-', and
    "-1", "-2", ... after a repeated one."""
    if path not in cache:
        anchors, fenced = set(), False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.startswith("```"):
                    fenced = not fenced
                heading = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line) if not fenced else None
                if not heading:
                    continue
                anchor = re.sub(r"[^\w\- ]", "", heading.group(1).lower()).replace(" ", "-")
                unique, repeat = anchor, 1
                while unique in anchors:
                    unique, repeat = f"{anchor}-{repeat}", repeat + 1
                anchors.add(unique)
        cache[path] = anchors
    return cache[path]


def problems_in(path, root):
    rel = os.path.relpath(path, root)
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    if rel == os.path.join("docs", "performance.md"):
        count = len(lines) - (1 if lines and lines[-1] == "" else 0)
        if count > MAX_PERFORMANCE_LINES:
            yield f"{rel}: {count} lines, more than {MAX_PERFORMANCE_LINES}: keep figures for users, decisions in docs/design/"
    for number, line in enumerate(lines, 1):
        for match in ISSUE_NUMBER.finditer(line):
            yield f"{rel}:{number}: cites an issue by number ({match.group(0)!r}): say what it means instead"
        for match in RUN_LOGS.finditer(line) if rel != HISTORY_PAGE else ():
            yield f"{rel}:{number}: points at a run log or the old benchmark folder ({match.group(0)!r})"
        for match in LINK.finditer(line):
            target = match.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue  # a URL
            file_part, _, anchor = target.partition("#")
            linked = os.path.join(os.path.dirname(path), file_part) if file_part else path
            if not os.path.exists(linked):
                yield f"{rel}:{number}: links to {target!r}, which does not exist"
            elif anchor and linked.endswith(".md") and anchor not in heading_anchors(linked):
                yield f"{rel}:{number}: links to {target!r}, which has no heading of that anchor"


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    if not os.path.isfile(os.path.join(root, "docs", "performance.md")):
        print(f"doc_style_test: {root}/docs/performance.md does not exist", file=sys.stderr)
        return 1
    found = [problem for path in documents(root) for problem in problems_in(path, root)]
    for problem in found:
        print(problem)
    checked = sum(1 for _ in documents(root))
    print(f"doc_style_test: {checked} documents checked, {len(found)} problems")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
