"""Shared by the examples: the output folder, Agg plotting and a check that prints and counts."""
import argparse
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SOURCE = Path(__file__).resolve().parents[2]


def arguments(description, **extra):
    """--out DIR (default out/examples) and the example's own options."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--out", default=os.environ.get("WEARSCALE_EXAMPLES_OUT", "out/examples"), help="output folder")
    for name, (default, help_) in extra.items():
        p.add_argument("--" + name.replace("_", "-"), type=type(default), default=default, help=help_)
    args = p.parse_args()
    Path(args.out).mkdir(parents=True, exist_ok=True)
    return args


failures = []
figures = []


def check(what, value, expected, tol):
    """Prints `what` and records a failure unless |value − expected| ≤ tol."""
    ok = abs(value - expected) <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {what}: {value:.6g} (expected {expected:.6g} ± {tol:.3g})")
    if not ok:
        failures.append(what)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    figures.append(Path(path))
    print(f"wrote {path}")


def finish():
    """Exits 1 if a check failed or a figure is missing or not a PNG (so ctest sees both)."""
    for f in figures:
        if not f.is_file() or f.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
            failures.append(f"figure {f}")
    if not figures:
        failures.append("no figure written")
    if failures:
        print(f"{len(failures)} check(s) failed: {', '.join(failures)}")
        sys.exit(1)
