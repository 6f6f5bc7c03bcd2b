"""BEM contact of a rigid surface on an elastic half-space (thesis §2.3.2, Appendix A).

- :class:`NormalContact`: frictionless, periodic or free window, imposed mean pressure or
  interference; warm-started from the last solve (load ramps in a Python loop).
- :class:`FrictionalContact`: Coulomb (A.2) or Tresca (A.3) friction, imposed mean normal and
  tangential tractions; stick/slip map, slip, tractions and displacements.
- :func:`stresses`: the stress tensor and principal stresses below surface tractions.
- :func:`hertz`, :func:`hertz_check`: Hertz's solution, and a BEM solve checked against it.

Heights may be a :class:`wearscale.surface.Surface` (its size is used) or an (nx, ny) array
with ``lx`` (and ``ly``) in metres. Result arrays are read-only views on the solver's storage,
overwritten by its next solve: ``.copy()`` one to keep it.
"""
from ._signatures import defaults_of, sign_class, signed
from ._wearscale import contact as _c
from .surface import Surface, _heights_and_size

effective_modulus = signed(_c.effective_modulus, __name__)
hertz = signed(_c.hertz, __name__)
hertz_check = signed(_c.hertz_check, __name__)
sign_class(_c.NormalContact)
sign_class(_c.FrictionalContact)
# The defaults of the constructors are the compiled ones (one place: python/src/bind_contact.cpp).
_normal = defaults_of(_c.NormalContact.__init__)
_frictional = defaults_of(_c.FrictionalContact.__init__)


class NormalContact(_c.NormalContact):
    __doc__ = _c.NormalContact.__doc__

    def __init__(self, heights, lx=None, ly=None, e_star=None, boundary=_normal["boundary"]):
        if e_star is None:
            raise TypeError("NormalContact: e_star [Pa] is required")
        h, lx, ly = _heights_and_size(heights, lx, ly)
        super().__init__(h, lx, ly, e_star, boundary)

    def ramp(self, mean_pressures, **options):
        """Solves at each mean pressure [Pa] in turn, each warm-started from the last two (the load
        predictor, ``predict_load=True`` unless given); returns the result dicts."""
        options.setdefault("predict_load", True)
        return [self.solve(mean_pressure=p, **options) for p in mean_pressures]


class FrictionalContact(_c.FrictionalContact):
    __doc__ = _c.FrictionalContact.__doc__

    def __init__(self, heights, lx=None, ly=None, young=None, poisson=None, law=_frictional["law"], mu=None,
                 shear_strength=None):
        if young is None or poisson is None:
            raise TypeError("FrictionalContact: young [Pa] and poisson are required")
        h, lx, ly = _heights_and_size(heights, lx, ly)
        super().__init__(h, lx, ly, young, poisson, law, mu, shear_strength)


_stresses = defaults_of(_c.stresses)


def stresses(pressure, lx, ly=_stresses["ly"], poisson=None, depths=(0.0,), traction_x=None, traction_y=None,
             tensor=_stresses["tensor"]):
    if poisson is None:
        raise TypeError("stresses: poisson is required")
    return _c.stresses(pressure, lx, ly, poisson, list(depths), traction_x, traction_y, tensor)


stresses.__doc__ = _c.stresses.__doc__.split("\n", 2)[-1]


def stresses_of(contact, depths, tensor=False):
    """:func:`stresses` below the tractions of a solved contact (normal: ν must be given as ``contact.poisson``
    for a FrictionalContact; a NormalContact has no ν, use :func:`stresses`)."""
    lx, ly = contact.size
    tx = getattr(contact, "traction_x", None)
    ty = getattr(contact, "traction_y", None)
    return stresses(contact.pressure, lx, ly, contact.poisson, depths, tx, ty, tensor)


__all__ = ["FrictionalContact", "NormalContact", "Surface", "effective_modulus", "hertz", "hertz_check",
           "stresses", "stresses_of"]
