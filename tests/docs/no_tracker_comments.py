#!/usr/bin/env python3
"""Comments say what a thing is, not which ticket or work period brought it:
no comment in the sources (C and C++ `//` and `/* */` lines, `#` lines of
CMake, TOML and shell, every line of Python: its docstrings too) may hold an issue number ("#NN", "issue NN")
or a numbered stop ("stop NN"). Dated records belong in the results log
(bench/results/, docs/results/), which is not checked.

Usage: no_tracker_comments.py REPO_ROOT. Prints every offending line as
path:line: text and exits 1 if there is one, 0 otherwise."""
import re
import sys
from pathlib import Path

# The folders holding sources, and the suffixes read in them.
FOLDERS = ["apps", "bench", "cases", "cmake", "core", "coupling", "examples", "io", "materials",
           "python", "solvers", "studies", "tests", ".ci"]
C_LIKE = {".c", ".cc", ".cpp", ".h", ".hpp"}
HASH_COMMENTED = {".py", ".cmake", ".toml", ".sh", ".txt"}
SKIP = {"results"}  # dated records are the results log's business

ISSUE = re.compile(r"(?<![\w&/#])#\d+\b|\b[Ii]ssue\s+#?\d+\b|\bstop\s+\d+\b")
C_COMMENT = re.compile(r"//(.*)$|/\*(.*?)(?:\*/|$)|^\s*\*(.*)$")
HASH_COMMENT = re.compile(r"(?:^|\s)#(?!include|pragma|define|if|endif|else|elif|undef|error|!)(.*)$")


def comment_of(line: str, suffix: str) -> str:
    if suffix == ".py":
        return line
    if suffix in C_LIKE:
        match = C_COMMENT.search(line)
        return "" if match is None else next(g for g in match.groups() if g is not None)
    match = HASH_COMMENT.search(line)
    return "" if match is None else match.group(1)


def sources(root: Path):
    for folder in FOLDERS:
        base = root / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            if any(part in SKIP for part in path.relative_to(root).parts):
                continue
            if path.is_file() and (path.suffix in C_LIKE | HASH_COMMENTED or
                                   (folder == ".ci" and path.suffix == "")):
                yield path


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = Path(argv[1])
    found = checked = 0
    for path in sources(root):
        checked += 1
        suffix = ".sh" if path.suffix == "" else path.suffix
        try:
            lines = path.read_text(encoding="utf-8").splitlines()
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(lines, 1):
            match = ISSUE.search(comment_of(line, suffix))
            if match:
                print(f"{path.relative_to(root)}:{number}: {match.group(0)!r}: {line.strip()}")
                found += 1
    if found:
        print(f"{found} comment(s) name an issue or a stop: say what the code is instead")
        return 1
    print(f"{checked} source files checked, no comment names an issue or a stop")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
