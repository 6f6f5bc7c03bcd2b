"""The coarse-grained cohesive DEM (thesis ch. 6-7): material targets (§6.1), the patch test
(§6.2.1), the sheared junction (§6.3), sheared rough surfaces (§7.2) and trapped particles (§7.3),
each with its results, history arrays (time series) and final particles where the study has them.
The same studies run as cases through :func:`wearscale.run` (``[dem.*]``)."""
from . import _wearscale
from ._signatures import sign_module

__all__ = sign_module(_wearscale.dem, globals())
