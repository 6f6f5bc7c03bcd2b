#!/usr/bin/env python3
"""Every wearscale command of the manual still works as written.

Reads the shell blocks (```sh, ```bash) of README.md and docs/**/*.md, takes
each line that runs `wearscale` (or `build/apps/wearscale`), and runs it with
the built program from a scratch folder that sees the repository's cases/:

- a command that runs a study (run, contact, dem, wearmap, surface, strength-table)
  runs with --dry-run: the case and every option are checked as the run reads
  them, nothing is computed or written (--resume DIR and --task K/N, which a
  check refuses, are left out of the check; the rest of the line is kept);
- `surface generate` runs for real (a second), so that a later line may read
  what it writes;
- check, version, backends, --help-all run as written;
- a line is left out only for a stated reason (SKIPPED below).

Usage: commands.py REPO_ROOT WEARSCALE. Prints each command and its status;
exits 1 if a command fails, naming the page and the line."""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

STUDIES = {"run", "contact", "dem", "wearmap", "surface", "strength-table"}
AS_WRITTEN = {"check", "version", "backends", "--help-all"}
# Lines that cannot run here, each with why.
SKIPPED = {
    "<command>": "a placeholder for any command",
    "scan.x3p": "a user's measurement, not in the repository",
    "merge ": "needs the shards of a job array first",
}
# Variables of a Slurm job, as a job array's first task of two sees them.
SLURM = {"SLURM_CPUS_PER_TASK": "1", "SLURM_ARRAY_TASK_ID": "1", "SLURM_ARRAY_TASK_COUNT": "2"}


def pages(root):
    return [root / "README.md"] + sorted((root / "docs").rglob("*.md"))


def commands(page):
    """(line number, command) of every wearscale line in the page's shell blocks."""
    text = page.read_text(encoding="utf-8")
    for block in re.finditer(r"^```(?:sh|bash)\n(.*?)^```", text, re.S | re.M):
        first = text.count("\n", 0, block.start(1)) + 1
        lines = block.group(1).split("\n")
        k = 0
        while k < len(lines):
            start, line = k, lines[k]
            while line.rstrip().endswith("\\") and k + 1 < len(lines):
                k += 1
                line = line.rstrip()[:-1] + " " + lines[k].strip()
            k += 1
            line = line.strip()
            if re.match(r"(build/apps/)?wearscale(\s|$)", line):
                yield first + start, line


def words(line):
    """The command's words, without its comment and output redirection."""
    lexer = shlex.shlex(line, posix=True, punctuation_chars="><|")
    lexer.whitespace_split = True
    lexer.commenters = "#"
    out = []
    for w in lexer:
        if w in (">", ">>", "|"):
            break
        out.append(w)
    return out


def checked(argv):
    """The words to run: a study under --dry-run, without --resume/--task."""
    i = 1
    while i < len(argv) and argv[i].startswith("-") and argv[i] not in AS_WRITTEN:
        i += 2 if argv[i] in ("-j", "--threads") else 1  # global options
    sub = argv[i] if i < len(argv) else ""
    if sub in AS_WRITTEN or sub not in STUDIES:
        return argv
    if sub == "surface" and i + 1 < len(argv) and argv[i + 1] == "generate":
        return argv
    out, k = [], 0
    while k < len(argv):
        if argv[k] in ("--resume", "--task"):
            k += 2
            continue
        out.append(argv[k])
        k += 1
    if "--dry-run" not in out:
        out.append("--dry-run")
    return out


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    root, program = Path(argv[1]).resolve(), str(Path(argv[2]).resolve())
    failures, ran = [], 0
    work = Path(tempfile.mkdtemp(prefix="wearscale_docs_commands_"))
    try:
        for name in ("cases", "examples", "materials"):
            if (root / name).exists():
                os.symlink(root / name, work / name)
        env = dict(os.environ, **SLURM, CI="true")
        for page in pages(root):
            for number, line in commands(page):
                where = f"{page.relative_to(root)}:{number}"
                reason = next((why for key, why in SKIPPED.items() if key in line), None)
                if reason:
                    print(f"skipped {where}: {line}  ({reason})")
                    continue
                expanded = re.sub(r"\$\{?(\w+)\}?", lambda m: SLURM.get(m.group(1), m.group(0)), line)
                argv_ = words(expanded)
                argv_ = [program] + checked(argv_)[1:]
                ran += 1
                try:
                    r = subprocess.run(argv_, cwd=work, env=env, capture_output=True, text=True, timeout=300)
                    status, err = r.returncode, r.stderr
                except subprocess.TimeoutExpired:
                    status, err = "timeout", ""
                print(f"{'ok' if status == 0 else 'FAILED'} {where}: {shlex.join(argv_[1:])}")
                if status != 0:
                    failures.append(f"{where}: `{line}` exits {status}: {err.strip()[-600:]}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print(f, file=sys.stderr)
    print(f"{ran} documented commands run, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
