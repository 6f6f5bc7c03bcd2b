"""help() is readable: every public function, class, method and property of wearscale has a
docstring of its own beyond the signature pybind11 writes, and the solver calls name their units.
(About 0.1 s: it only imports the module.)"""
import inspect
import re

import pytest

import wearscale as ws

MODULES = [ws.surface, ws.contact, ws.wear, ws.dem, ws.materials, ws.io]
# pybind11 starts a docstring with "name(arg: type, ...) -> type" (and "Overloaded function." ...).
SIGNATURE = re.compile(r"^(\d+\. )?[A-Za-z_]\w*\(.*\)( -> .*)?$|^Overloaded function\.$")


def own_text(obj):
    doc = inspect.getdoc(obj) or ""
    return "\n".join(l for l in doc.splitlines() if not SIGNATURE.match(l.strip())).strip()


def members():
    """(qualified name, object) of every public callable and property."""
    seen = []
    for module in MODULES:
        for name in module.__all__:
            obj = getattr(module, name)
            seen.append((f"{module.__name__}.{name}", obj))
            if inspect.isclass(obj):
                for attr in dir(obj):
                    if attr.startswith("_") or hasattr(object, attr):
                        continue
                    seen.append((f"{module.__name__}.{name}.{attr}", inspect.getattr_static(obj, attr)))
    for name in ("run", "check", "merge", "RunResult", "CaseCheck", "to_toml"):
        obj = getattr(ws, name)
        seen.append((f"wearscale.{name}", obj))
    for attr in ("output_dir", "is_sweep", "units", "results", "runs", "table", "h5_files", "load"):
        seen.append((f"wearscale.RunResult.{attr}", inspect.getattr_static(ws.RunResult, attr)))
    return seen


def test_every_public_function_class_method_and_property_has_a_docstring():
    missing = [name for name, obj in members() if not own_text(obj)]
    assert not missing, "no docstring: " + ", ".join(missing)


@pytest.mark.parametrize("call", [ws.contact.NormalContact.solve, ws.contact.FrictionalContact.solve,
                                  ws.contact.stresses, ws.contact.hertz_check, ws.surface.generate,
                                  ws.surface.analyze, ws.wear.energy_release, ws.dem.sheared_junction,
                                  ws.dem.rough_shear, ws.dem.trapped_particles, ws.materials.critical_pressure])
def test_the_solver_calls_name_their_units(call):
    assert re.search(r"\[(Pa|m|N|J|m/s|rad)\]|_Pa\b|_m\b|\bPa\b", own_text(call)), own_text(call)
