"""wearscale's HDF5 outputs (run.h5, contact.h5, surfaces) as NumPy arrays, without h5py."""
from . import _wearscale
from ._signatures import sign_module

__all__ = sign_module(_wearscale.io, globals())
