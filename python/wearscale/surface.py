"""Rough surfaces (thesis §1.1.2): generation with the PSD of Fig. 1.3, roughness
measures (1.4)-(1.6), the PSD (1.9) and Hurst exponent, and topography files.

A :class:`Surface` is an (nx, ny) float64 height array [m] (y fastest, as wearscale
and h5py store it) with its size lx x ly [m] and metadata; NumPy functions accept it
directly (``np.asarray(s)`` is the heights, no copy).
"""
from dataclasses import dataclass, field

import numpy as np

from ._wearscale import surface as _s

supported_formats = _s.supported_formats
sa = _s.sa
h_rms = _s.h_rms
h_prime_rms = _s.h_prime_rms


@dataclass
class Surface:
    """Heights [m] on lx x ly metres, with what produced them in ``meta``."""

    heights: np.ndarray
    lx: float
    ly: float
    meta: dict = field(default_factory=dict)

    def __array__(self, dtype=None, copy=None):
        return self.heights if dtype is None else self.heights.astype(dtype)

    @property
    def shape(self):
        """(nx, ny) of the heights."""
        return self.heights.shape

    def analyze(self, **kwargs):
        """:func:`analyze` of this surface."""
        return analyze(self, **kwargs)


def _heights_and_size(heights, lx, ly):
    if isinstance(heights, Surface):
        return heights.heights, heights.lx if lx is None else lx, heights.ly if ly is None else ly
    if lx is None:
        raise _s_input_error("a size lx [m] is needed for a plain array of heights")
    return heights, lx, -1.0 if ly is None else ly


def _s_input_error(message):
    from ._wearscale import InputError
    return InputError(message)


def generate(n, size, hurst=0.8, k_l=1.0, k_r=None, k_s=16.0, seed=0, ny=None, ly=None, sa=None, rms=None,
             slope_rms=None):
    h, meta = _s.generate(n, size, hurst, k_l, k_r, k_s, seed, ny, ly, sa, rms, slope_rms)
    return Surface(h, meta["lx_m"], meta["ly_m"], meta)


generate.__doc__ = _s.generate.__doc__.split("\n", 2)[-1] if _s.generate.__doc__ else None


def analyze(heights, lx=None, ly=None, q_min=0.0, q_max=float("inf"), detrend=False, window=False):
    h, lx, ly = _heights_and_size(heights, lx, ly)
    return _s.analyze(h, lx, ly, q_min, q_max, detrend, window)


def read(file, dataset="/surface/height", lx=None, ly=None, missing="refuse"):
    h, meta = _s.read(file, dataset, lx, ly, missing)  # a str, bytes or os.PathLike
    return Surface(h, meta["lx_m"], meta["ly_m"], meta)


def write(file, heights, lx=None, ly=None):
    """Writes heights [m] as wearscale's HDF5 surface with an XDMF sidecar (returned)."""
    h, lx, ly = _heights_and_size(heights, lx, ly)
    return _s.write(file, h, lx, ly)


def sphere(n, size, radius, cx=None, cy=None):
    """Spherical cap of radius [m] on an n x n grid of ``size`` [m], summit 0 at (cx, cy) (default: the centre)."""
    return Surface(_s.sphere(n, size, radius, cx, cy), size, size, {"radius_m": radius})


for _f, _c in ((analyze, _s.analyze), (read, _s.read)):
    _f.__doc__ = _c.__doc__.split("\n", 2)[-1] if _c.__doc__ else None

__all__ = ["Surface", "analyze", "generate", "h_prime_rms", "h_rms", "read", "sa", "sphere", "supported_formats", "write"]
