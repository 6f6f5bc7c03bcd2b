"""wearscale.run: a case through the same runner as the CLI (``wearscale run``; a [contact]
case as ``wearscale contact``), returning what ``--json`` prints as a dict.

The one adapter to the C++ runner is python/src/bind_run.cpp.
"""
import json
import math
import os
from pathlib import Path


from . import _wearscale
from . import io as _io


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        if math.isnan(v):
            return "nan"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x)}" for k, x in v.items()) + " }"
    raise _wearscale.InputError(f"run: a case value must be a number, string, bool, list or dict, got {type(v).__name__}")


def _toml_key(k):
    k = str(k)
    return k if k.replace("_", "").replace("-", "").isalnum() else json.dumps(k)


def to_toml(case, prefix=""):
    """The TOML text of a case given as a (nested) dict."""
    lines, tables = [], []
    for k, v in case.items():
        if isinstance(v, dict):
            tables.append((k, v))
        else:
            lines.append(f"{_toml_key(k)} = {_toml_value(v)}")
    out = []
    if lines:
        if prefix:
            out.append(f"[{prefix}]")
        out += lines
    for k, v in tables:
        name = f"{prefix}.{_toml_key(k)}" if prefix else _toml_key(k)
        out.append(to_toml(v, name))
    return "\n".join(out) + "\n"


def _override(key, value):
    if isinstance(value, str):
        text = value
    elif isinstance(value, bool):
        text = "true" if value else "false"
    else:
        text = _toml_value(value)
    return f"{key}={text}"


def _path(value, what):
    """A file or folder name as text: a str, bytes (decoded as the file system names it) or os.PathLike;
    InputError for anything else."""
    try:
        return os.fsdecode(os.fspath(value))
    except TypeError:
        raise _wearscale.InputError(f"run: {what} = {value!r} is not a file name; allowed: a str, bytes or "
                                    "os.PathLike") from None


class RunResult(dict):
    """The run's ``--json`` summary (a dict: results, parameters, files, output_dir, ...), plus accessors."""

    @property
    def output_dir(self):
        """The run's output folder (summary.json, run.h5, ...) as a Path."""
        return Path(self["output_dir"])

    @property
    def results(self):
        """{name: value} of the headline results (units in ``self['results'][name]['unit']``)."""
        return {k: v["value"] if isinstance(v, dict) and "value" in v else v for k, v in self.get("results", {}).items()}

    def h5_files(self):
        """Every HDF5 file the run wrote (run.h5, contact.h5, those of a sweep's runs), sorted."""
        return sorted(self.output_dir.rglob("*.h5"))

    def load(self, dataset, file=None):
        """A dataset of the run's HDF5 output (``file``: a name in the output folder; default: the only
        .h5 file holding ``dataset``) as a NumPy array."""
        candidates = [self.output_dir / file] if file else self.h5_files()
        for f in candidates:
            if _io.exists(str(f), dataset):
                return _io.read(str(f), dataset)
        raise _wearscale.InputError(f"run: no HDF5 output of {self.output_dir} holds dataset '{dataset}'; "
                                    f"files: {', '.join(p.name for p in candidates) or 'none'}")


def run(case, out=None, resume=None, quiet=True, set=None, task=None, **overrides):
    """Runs a case as ``wearscale run CASE --set KEY=VALUE... --json`` does and returns a :class:`RunResult`.

    case: a TOML file path, a TOML string or a dict (relative file names in a dict or string are
    relative to the working directory, in a file to the file's folder). Overrides as keywords with ``__`` for the dots
    (``contact__grid=64`` is ``--set contact.grid=64``) or as ``set={"contact.grid": 64}``; strings
    keep their units ("1 um"). out: the output folder (--out), else the case's [output].dir;
    resume: the folder of a run to continue (--resume); task: "K/N", the K-th of N shards of the case's
    ensemble (--task: a job array's share of a sweep's runs or of a run's ensembles, written into ``out``
    beside the other shards'; :func:`merge` writes the outputs once all are done). Releases the GIL while it runs.
    ValueError (InputError) for a bad case, with the key and allowed range, before anything is written.
    """
    sets = [_override(k.replace("__", "."), v) for k, v in overrides.items()]
    sets += [_override(k, v) for k, v in (set or {}).items()]
    # A dict or TOML text goes to the runner as text, not through a temporary file: its relative
    # file names are relative to the working directory, and messages name "<case dict>:LINE".
    if isinstance(case, dict):
        path, text = "<case dict>", to_toml(case)
    elif isinstance(case, str) and ("\n" in case or "=" in case) and not os.path.exists(case):
        path, text = "<case string>", case
    else:
        path, text = _path(case, "case"), None
    # Folders go to the runner as paths (str, bytes or os.PathLike, as the file system names them), never
    # through str(): str(b"/tmp/x") is "b'/tmp/x'".
    summary = _wearscale.runner.run_case(path, sets, None if out is None else _path(out, "out"),
                                         None if resume is None else _path(resume, "resume"), quiet, text,
                                         None if task is None else str(task))
    return RunResult(json.loads(summary))


def merge(folder, quiet=True):
    """Writes the outputs of an ensemble whose shards (``run(..., task="K/N", out=folder)``) all ran into
    ``folder``, as ``wearscale merge DIR`` does, and returns its :class:`RunResult`. ValueError (InputError),
    naming each missing task and the shard that owes it, while some are not done; nothing is written then."""
    return RunResult(json.loads(_wearscale.runner.merge_shards(_path(folder, "folder"), quiet)))


def check(case_file, **overrides):
    """Every check :func:`run` makes before it writes anything; returns the output folders."""
    return _wearscale.runner.check_case(_path(case_file, "case_file"), [_override(k.replace("__", "."), v) for k, v in overrides.items()])


__all__ = ["RunResult", "check", "merge", "run", "to_toml"]
