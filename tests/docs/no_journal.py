#!/usr/bin/env python3
"""The manual is not a lab notebook: no page listed below may hold a dated
entry ("6 Dec", "Dec 6", "2026-12-06"), an issue number ("#NN") or the words
session, agent, helper, lane (dated measurement records belong in the results
log, bench/results/). Fenced code blocks are checked too.

Usage: no_journal.py REPO_ROOT [PAGE ...]   (pages relative to REPO_ROOT;
default: PAGES below). Prints every offending line as path:line: text and
exits 1 if there is one, 0 otherwise."""
import re
import sys
from pathlib import Path

# The pages checked: the README and every page of the manual (docs/**/*.md).
def all_pages(root):
    return ["README.md"] + sorted(str(p.relative_to(root)) for p in (root / "docs").rglob("*.md"))

MONTHS = r"(?:Jan|Feb|Mar|Apr|May|Jun|Jul|Aug|Sep|Sept|Oct|Nov|Dec)[a-z]*\.?"
RULES = [
    ("a date", re.compile(r"\b\d{1,2}(?:st|nd|rd|th)?[ \u00a0]" + MONTHS + r"(?![a-z])"
                          r"|\b" + MONTHS + r"[ \u00a0]\d{1,2}\b")),
    ("a date", re.compile(r"\b(?:19|20)\d\d-[01]\d-[0-3]?\d?")),
    ("an issue number", re.compile(r"(?<![\w&/#])#\d+\b")),
    ("a word about who worked when",
     re.compile(r"\b(?:sessions?|agents?|helpers?|lanes?)\b", re.IGNORECASE)),
]


CODE_SPAN = re.compile(r"`[^`]*`")


def offences(path: Path):
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        for what, rule in RULES:
            # A name in code (`mpi::Session`) is not a word about who worked.
            text = CODE_SPAN.sub("", line) if what.startswith("a word") else line
            match = rule.search(text)
            if match:
                yield number, what, match.group(0), line.strip()
                break


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = Path(argv[1])
    pages = argv[2:] or all_pages(root)
    found = 0
    for page in pages:
        path = root / page
        if not path.is_file():
            print(f"{page}: listed but not found")
            found += 1
            continue
        for number, what, text, line in offences(path):
            print(f"{page}:{number}: {what} ({text!r}): {line}")
            found += 1
    if found:
        print(f"{found} line(s) read as a lab notebook; dated records go to bench/results/")
        return 1
    print(f"{len(pages)} pages checked, no dated entry, issue number or who-did-what")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
