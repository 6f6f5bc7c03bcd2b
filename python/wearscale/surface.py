"""Rough surfaces (thesis §1.1.2): generation with the PSD of Fig. 1.3, roughness
measures (1.4)-(1.6), the PSD (1.9) and Hurst exponent, and topography files.

A :class:`Surface` is an (nx, ny) float64 height array [m] (y fastest, as wearscale
and h5py store it) with its size lx x ly [m] and metadata; NumPy functions accept it
directly (``np.asarray(s)`` is the heights, no copy).
"""
from dataclasses import dataclass, field

import numpy as np

from ._signatures import defaults_of, own_doc, signed
from ._wearscale import surface as _s

supported_formats = signed(_s.supported_formats, __name__)
# The defaults of the wrappers below are the compiled functions' (one place: python/src/bind_surface.cpp).
_generate = defaults_of(_s.generate)
_analyze = defaults_of(_s.analyze)
_read = defaults_of(_s.read)
_sa = defaults_of(_s.sa)


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
    return heights, lx, _analyze["ly"] if ly is None else ly


def _s_input_error(message):
    from ._wearscale import InputError
    return InputError(message)


def generate(n, size, hurst=_generate["hurst"], k_l=_generate["k_l"], k_r=_generate["k_r"],
             k_s=_generate["k_s"], seed=_generate["seed"], ny=None, ly=None, sa=None, rms=None,
             slope_rms=None):
    h, meta = _s.generate(n, size, hurst, k_l, k_r, k_s, seed, ny, ly, sa, rms, slope_rms)
    return Surface(h, meta["lx_m"], meta["ly_m"], meta)


def analyze(heights, lx=None, ly=None, q_min=_analyze["q_min"], q_max=_analyze["q_max"],
            detrend=_analyze["detrend"], window=_analyze["window"]):
    h, lx, ly = _heights_and_size(heights, lx, ly)
    return _s.analyze(h, lx, ly, q_min, q_max, detrend, window)


def read(file, dataset=_read["dataset"], lx=None, ly=None, missing=_read["missing"]):
    h, meta = _s.read(file, dataset, lx, ly, missing)  # a str, bytes or os.PathLike
    return Surface(h, meta["lx_m"], meta["ly_m"], meta)


def _size_free(heights, lx):
    """Heights and an lx for Sa and h_rms, which do not depend on the size."""
    if lx is None and not isinstance(heights, Surface):
        lx = _sa["lx"]
    h, lx, _ = _heights_and_size(heights, lx, None)
    return h, lx


def sa(heights, lx=None):
    return _s.sa(*_size_free(heights, lx))


def h_rms(heights, lx=None):
    return _s.h_rms(*_size_free(heights, lx))


def h_prime_rms(heights, lx=None, ly=None):
    h, lx, ly = _heights_and_size(heights, lx, ly)
    return _s.h_prime_rms(h, lx, ly)


# generate and read return a Surface where the compiled calls return (heights, metadata).
generate.__doc__ = own_doc(_s.generate).replace(
    "Returns (heights [m], an (n, ny) float64 array with y fastest, metadata dict).",
    "Returns a Surface: heights [m] (an (n, ny) float64 array, y fastest), lx, ly [m] and meta (the\n"
    "generation parameters: lx_m, ly_m, hurst, k_l, k_r, k_s, seed).")
read.__doc__ = own_doc(_s.read).replace(
    "Returns (heights [m], metadata dict with lx_m, ly_m, format).",
    "Returns a Surface: heights [m], lx, ly [m] and meta (lx_m, ly_m, format, missing_points, file).")
sa.__doc__ = own_doc(_s.sa) + "\nheights: a Surface or an array of heights [m]."
h_rms.__doc__ = own_doc(_s.h_rms) + "\nheights: a Surface or an array of heights [m]."
h_prime_rms.__doc__ = own_doc(_s.h_prime_rms) + "\nheights: a Surface (its lx, ly) or an array of heights [m] with lx (and ly)."


def write(file, heights, lx=None, ly=None):
    """Writes heights [m] as wearscale's HDF5 surface with an XDMF sidecar (returned)."""
    h, lx, ly = _heights_and_size(heights, lx, ly)
    return _s.write(file, h, lx, ly)


def sphere(n, size, radius, cx=None, cy=None):
    """Spherical cap of radius [m] on an n x n grid of ``size`` [m], summit 0 at (cx, cy) (default: the centre)."""
    return Surface(_s.sphere(n, size, radius, cx, cy), size, size, {"radius_m": radius})


analyze.__doc__ = own_doc(_s.analyze) + "\nheights: a Surface (its lx, ly) or an array of heights [m] with lx (and ly)."

__all__ = ["Surface", "analyze", "generate", "h_prime_rms", "h_rms", "read", "sa", "sphere", "supported_formats", "write"]
