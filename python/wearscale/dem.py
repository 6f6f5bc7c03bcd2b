"""The coarse-grained cohesive DEM (thesis ch. 6-7): material targets and the patch test (§6.2.1).
The other DEM studies (sheared junction, rough shear, trapped particles) run as cases
through :func:`wearscale.run`."""
from . import _wearscale

_compiled = _wearscale.dem
globals().update({k: getattr(_compiled, k) for k in dir(_compiled) if not k.startswith("_")})
__all__ = sorted(k for k in dir(_compiled) if not k.startswith("_"))
