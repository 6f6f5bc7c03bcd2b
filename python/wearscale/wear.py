"""Adhesive wear maps: one micro-contact (Fig. 3.7), two interacting micro-contacts
(Fig. 4.6, (4.48)-(4.49)) and the numerical map of rough surfaces (§5.3)."""
from . import _wearscale
from ._signatures import sign_module

__all__ = sign_module(_wearscale.wear, globals())
