"""Materials (Table 2.1), shipped strength tables (Fig. 9.18) and the junction model (§7.1.2, §9.3.2).

Shipped data are found in $WEARSCALE_DATA, else share/wearscale/data of the installation,
else the source tree (see :func:`data_directory`).
"""
from . import _wearscale

_compiled = _wearscale.materials
globals().update({k: getattr(_compiled, k) for k in dir(_compiled) if not k.startswith("_")})
__all__ = sorted(k for k in dir(_compiled) if not k.startswith("_"))
