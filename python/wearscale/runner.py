"""wearscale.runner: cases through the same runner as the CLI (``wearscale run``; a [contact]
case as ``wearscale contact``): :func:`run` returns what ``--json`` prints, :func:`check` what
``wearscale check --json`` prints, :func:`merge` what ``wearscale merge --json`` prints.

The package exposes them as ``wearscale.run``, ``wearscale.check`` and ``wearscale.merge``.
The one adapter to the C++ runner is python/src/bind_run.cpp.

Results are keyed as every CSV table of wearscale names its columns: ``<name>_<SI unit>``
(``contact_radius_m``, ``disc_wear_m3``, ``mean_pressure_Pa``), a dimensionless figure by its
name alone (``mu_final``), the scheme of the contact solves' results (``mean_pressure_Pa``).
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


def _overrides(set_, overrides):
    sets = [_override(k.replace("__", "."), v) for k, v in overrides.items()]
    return sets + [_override(k, v) for k, v in (set_ or {}).items()]


def _case_source(case):
    """(path for messages, TOML text or None): a dict or TOML text goes to the runner as text, not
    through a temporary file, so that its relative file names are relative to the working
    directory and messages name "<case dict>:LINE"."""
    if isinstance(case, dict):
        return "<case dict>", to_toml(case)
    if isinstance(case, str) and ("\n" in case or "=" in case) and not os.path.exists(case):
        return "<case string>", case
    return _path(case, "case"), None


def _path(value, what):
    """A file or folder name as text: a str, bytes (decoded as the file system names it) or os.PathLike;
    InputError for anything else."""
    try:
        return os.fsdecode(os.fspath(value))
    except TypeError:
        raise _wearscale.InputError(f"run: {what} = {value!r} is not a file name; allowed: a str, bytes or "
                                    "os.PathLike") from None


def _swept_name(key):
    """A swept key's column in a sweep table, as the runner names it: its last two components joined,
    "materials.layer.thickness" -> "layer_thickness" (the table adds the unit)."""
    parts = key.split(".")
    return "_".join(parts[-2:]) if len(parts) > 1 and parts[0] else key


def _column(name, unit):
    """The key of a figure: its name with its SI unit, as the CSV tables' columns."""
    return _io.column_name(name, unit or "1")


def _flat(results):
    """{<name>_<unit>: value} of a summary's {name: {value, unit, description}}."""
    return {_column(k, v.get("unit", "1")): v["value"] for k, v in results.items()}


class RunResult(dict):
    """The run's ``--json`` summary (a dict: results, parameters, files, output_dir, ...), plus accessors.

    ``.results``: the headline figures {<name>_<SI unit>: value} (a sweep: one list per column, as
    ``.table()``); ``.runs``: a sweep's runs, each a RunResult; ``.table()``: the figures as a table
    (a pandas DataFrame when pandas is importable)."""

    def __init__(self, summary=None):
        super().__init__(summary or {})

    @property
    def output_dir(self):
        """The run's output folder (summary.json, run.h5, ...) as a Path."""
        return Path(self["output_dir"])

    @property
    def is_sweep(self):
        """Whether the case was a [sweep] (then ``.runs`` holds its runs)."""
        return "sweep" in self

    @property
    def units(self):
        """{key of .results: SI unit} ('1' for a dimensionless figure)."""
        if not self.is_sweep:
            return {_column(k, v.get("unit", "1")): v.get("unit", "1") for k, v in self.get("results", {}).items()}
        return dict(self._columns()[1])

    @property
    def results(self):
        """The headline figures, keyed ``<name>_<SI unit>`` as the CSV tables' columns (``disc_wear_m3``,
        ``mu_final``; the unit of each is ``.units``, its description ``self['results'][name]``).
        A sweep: {column: list of values, one per run}, the swept key's column first, as ``.table()``."""
        if not self.is_sweep:
            return _flat(self.get("results", {}))
        return {k: list(v) for k, v in self._columns()[0].items()}

    @property
    def runs(self):
        """The runs of a sweep, in order, each a :class:`RunResult` (results, output_dir, load()); []
        for a single run."""
        if not self.is_sweep:
            return []
        out = []
        for r in self["sweep"]["runs"]:
            one = RunResult({"output_dir": r["output_dir"], "results": r.get("results", {}), "study": self.get("study"),
                             "value": r["value"]})
            if "series" in r:
                one["series"] = r["series"]
            out.append(one)
        return out

    def _table_sidecar(self, key):
        """The JSON sidecar of the sweep's CSV table (its column names and units), if it is there."""
        for f in self.get("files", []):
            sidecar = self.output_dir / (Path(f).name + ".json")
            if f.endswith(".csv") and sidecar.exists():
                try:
                    j = json.loads(sidecar.read_text())
                except (OSError, ValueError):
                    continue
                if j.get("columns") and j["columns"][0].startswith(_swept_name(key)):
                    return j
        return None

    def _swept_column(self, key, values, sidecar=None):
        """The swept values in SI under the name the sweep's CSV table gives them ('<key>_<unit>' when
        they are all quantities of one dimension), else the text under the key."""
        try:
            parsed = [_io.quantity(str(v)) for v in values]
        except ValueError:
            return _swept_name(key), list(values), ""
        if len({u for _, u in parsed}) != 1:
            return _swept_name(key), list(values), ""
        unit = parsed[0][1]
        if sidecar:  # the table's own name and unit of the column (a key whose values are plain numbers in SI)
            name = sidecar["columns"][0]
            return name, [v for v, _ in parsed], sidecar.get("units", {}).get(name, unit)
        return _column(_swept_name(key), unit), [v for v, _ in parsed], unit

    def _columns(self):
        """({column: values}, [(column, unit)]) of the table."""
        columns, units = {}, []
        if not self.is_sweep:
            for k, v in self.get("results", {}).items():
                name = _column(k, v.get("unit", "1"))
                columns[name] = [v["value"]]
                units.append((name, v.get("unit", "1")))
            return columns, units
        sweep = self["sweep"]
        runs = sweep["runs"]
        name, values, unit = self._swept_column(sweep["key"], [r["value"] for r in runs],
                                                self._table_sidecar(sweep["key"]))
        columns[name] = values
        units.append((name, unit))
        if "series" in sweep:
            name, values, unit = self._swept_column(sweep["series"]["key"], [r["series"] for r in runs])
            columns[name] = values
            units.append((name, unit))
        figures = []
        for r in runs:
            for k, v in r.get("results", {}).items():
                if k not in [f for f, _ in figures]:
                    figures.append((k, v.get("unit", "1")))
        for k, u in figures:
            name = _column(k, u)
            columns[name] = [r.get("results", {}).get(k, {}).get("value", math.nan) for r in runs]
            units.append((name, u))
        if "failed" in self:
            failed = {f["run"] for f in self["failed"]}
            columns["failed"] = [1.0 if k + 1 in failed else 0.0 for k in range(len(runs))]
            units.append(("failed", "1"))
        return columns, units

    def table(self):
        """The headline figures as a table, one row per run (a single run: one row): a pandas
        DataFrame when pandas is importable (the columns of the sweep's CSV table, in SI; their
        units in ``df.attrs['units']``), else {column: NumPy array}."""
        columns, units = self._columns()
        try:
            import pandas
        except ImportError:
            import numpy as np
            return {k: np.asarray(v) for k, v in columns.items()}
        df = pandas.DataFrame(columns)
        df.attrs["units"] = dict(units)
        return df

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
    ValueError (InputError) for a bad case, naming every key in error with its allowed range, before anything
    is written. The results: ``.results`` {<name>_<SI unit>: value}, ``.table()``, ``.runs`` (a sweep).
    """
    path, text = _case_source(case)
    # Folders go to the runner as paths (str, bytes or os.PathLike, as the file system names them), never
    # through str(): str(b"/tmp/x") is "b'/tmp/x'".
    summary = _wearscale.runner.run_case(path, _overrides(set, overrides), None if out is None else _path(out, "out"),
                                         None if resume is None else _path(resume, "resume"), quiet, text,
                                         None if task is None else str(task))
    return RunResult(json.loads(summary))


class CaseCheck(dict):
    """What ``wearscale check --json`` prints (a dict: study, output_dirs, parameters (the resolved case
    with every default), defaults, described_defaults, memory); ``.text`` is what ``wearscale check``
    prints."""

    def __init__(self, report=None, text=""):
        super().__init__(report or {})
        self.text = text  # the report as `wearscale check` prints it: the resolved case as TOML, defaults marked

    def __str__(self):
        return self.text


def check(case, out=None, set=None, **overrides):
    """Checks a case as :func:`run` (and ``wearscale check``) reads it, without running or writing anything:
    every key, every independent error at once. Takes what :func:`run` takes. Returns a :class:`CaseCheck`
    (the resolved case with every default the run applies, the output folders, the memory the runs need);
    ValueError (InputError) listing every error of an invalid case."""
    path, text = _case_source(case)
    report, printed = _wearscale.runner.inspect_case(path, _overrides(set, overrides),
                                                     None if out is None else _path(out, "out"), text)
    return CaseCheck(json.loads(report), printed)


def merge(folder, quiet=True):
    """Writes the outputs of an ensemble whose shards (``run(..., task="K/N", out=folder)``) all ran into
    ``folder``, as ``wearscale merge DIR`` does, and returns its :class:`RunResult`. ValueError (InputError),
    naming each missing task and the shard that owes it, while some are not done; nothing is written then."""
    return RunResult(json.loads(_wearscale.runner.merge_shards(_path(folder, "folder"), quiet)))


__all__ = ["CaseCheck", "RunResult", "check", "merge", "run", "to_toml"]
