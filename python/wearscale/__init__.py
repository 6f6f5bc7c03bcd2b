"""wearscale: friction and adhesive wear across scales, from Python.

Submodules (each function's docstring gives units, ranges and the thesis' equation numbers):

- :mod:`wearscale.surface`   rough surfaces: generate, analyze (PSD, Hurst, Sa, h_rms, h'_rms), read/write files
- :mod:`wearscale.contact`   BEM normal and frictional contact, stresses at depth, Hertz
- :mod:`wearscale.materials` material records, strength tables, the junction model (§7.1.2, §9.3.2)
- :mod:`wearscale.wear`      analytic 2D/3D wear maps, the rough-surface wear map
- :mod:`wearscale.dem`       the cohesive DEM: targets, patch test, sheared junction, rough shear, trapped particles
- :mod:`wearscale.io`        HDF5 datasets of wearscale's outputs as NumPy arrays
- :func:`wearscale.run`      any case through the CLI's runner, ``--set`` overrides as keywords;
  results keyed ``<name>_<SI unit>``, ``.table()`` (a pandas DataFrame when pandas is importable)
- :func:`wearscale.check`    a case checked as ``run`` reads it (every error at once), nothing written
- :mod:`wearscale.runner`    the module of run, check, merge, RunResult, to_toml

All quantities are SI (m, Pa, N, J). Bad input raises :class:`InputError` (a ValueError)
naming the key, value and allowed range; a numerical failure raises :class:`NumericalError`
(an ArithmeticError). Solves release the GIL, so threads run them in parallel.
"""
import os as _os

# How idle OpenMP threads wait: spin briefly, then sleep, as the CLI's do (docs/dem.md, "Waiting
# threads"). libgomp reads this once, when the compiled module below loads it; a user's
# OMP_WAIT_POLICY or GOMP_SPINCOUNT wins, and a libgomp already loaded by another module keeps its own.
_WAITING_SPIN_COUNT = "3000"  # wearscale::waiting_spin_count
if "OMP_WAIT_POLICY" not in _os.environ and "GOMP_SPINCOUNT" not in _os.environ:
    _os.environ["GOMP_SPINCOUNT"] = _WAITING_SPIN_COUNT

from ._wearscale import InputError, NumericalError, OutputError, __version__
from . import contact, dem, io, materials, runner, surface, wear
from .runner import CaseCheck, RunResult, check, merge, run, to_toml

__all__ = ["CaseCheck", "InputError", "NumericalError", "OutputError", "RunResult", "__version__", "check",
           "contact", "dem", "io", "materials", "merge", "run", "runner", "surface", "to_toml", "wear"]
