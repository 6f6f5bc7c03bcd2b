"""Adhesive wear maps: one micro-contact (Fig. 3.7), two interacting micro-contacts
(Fig. 4.6, (4.48)-(4.49)) and the numerical map of rough surfaces (§5.3)."""
from . import _wearscale

_compiled = _wearscale.wear
globals().update({k: getattr(_compiled, k) for k in dir(_compiled) if not k.startswith("_")})
__all__ = sorted(k for k in dir(_compiled) if not k.startswith("_"))
