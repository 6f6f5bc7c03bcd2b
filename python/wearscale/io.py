"""wearscale's HDF5 outputs (run.h5, contact.h5, surfaces) as NumPy arrays, without h5py."""
from . import _wearscale

_compiled = _wearscale.io
globals().update({k: getattr(_compiled, k) for k in dir(_compiled) if not k.startswith("_")})
__all__ = sorted(k for k in dir(_compiled) if not k.startswith("_"))
