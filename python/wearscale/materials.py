"""Materials (Table 2.1), shipped strength tables (Fig. 9.18) and the junction model (§7.1.2, §9.3.2).

Shipped data are found in $WEARSCALE_DATA, else share/wearscale/data of the installation,
else the source tree (see :func:`data_directory`).
"""
from . import _wearscale
from ._signatures import sign_module

__all__ = sign_module(_wearscale.materials, globals())
