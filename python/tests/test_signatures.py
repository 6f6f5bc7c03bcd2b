"""inspect.signature works on every public callable of wearscale, compiled ones included (their
argument names and defaults are the C++ bindings' py::arg), and the Python defaults are the C++
ones: a default written in the bindings from a spec struct is that struct's, and the case's."""
import inspect
import math
import re

import pytest

import wearscale as ws

MODULES = [ws.surface, ws.contact, ws.wear, ws.dem, ws.materials, ws.io, ws.runner]


def callables():
    seen = []
    for module in MODULES:
        for name in module.__all__:
            obj = getattr(module, name)
            if not callable(obj):
                continue
            seen.append((f"{module.__name__}.{name}", obj))
            if inspect.isclass(obj):
                for attr in dir(obj):
                    if attr.startswith("_") or hasattr(object, attr) or hasattr(dict, attr):
                        continue
                    member = inspect.getattr_static(obj, attr)
                    if callable(member):
                        seen.append((f"{module.__name__}.{name}.{attr}", getattr(obj, attr)))
    for name in ("run", "check", "merge"):
        seen.append((f"wearscale.{name}", getattr(ws, name)))
    return seen


@pytest.mark.parametrize("name,call", callables(), ids=[n for n, _ in callables()])
def test_every_public_callable_has_a_signature_with_named_arguments(name, call):
    sig = inspect.signature(call)
    kinds = [p.kind for p in sig.parameters.values()]
    # a compiled call shows its own arguments, not a catch-all (*args, **kwargs)
    assert kinds != [inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD], f"{name}{sig}"


def test_the_signatures_are_the_bindings_arguments_and_defaults():
    solve = inspect.signature(ws.contact.NormalContact.solve).parameters
    assert list(solve)[:3] == ["self", "mean_pressure", "interference"] and "load" in solve
    assert solve["tolerance"].default == 1e-12 and solve["method"].default == "two-level"  # ContactOptions{}
    assert inspect.signature(ws.contact.FrictionalContact.solve).parameters["tolerance"].default == 1e-10
    assert inspect.signature(ws.surface.generate).parameters["hurst"].default == 0.8
    assert inspect.signature(ws.surface.analyze).parameters["q_max"].default == math.inf
    init = inspect.signature(ws.contact.NormalContact).parameters
    assert list(init) == ["heights", "lx", "ly", "e_star", "boundary"] and init["boundary"].default == "periodic"
    # binding, then call by keyword as the signature says
    assert inspect.signature(ws.contact.hertz).bind(radius=1e-3, load=1.0, e_star=1e11)


def case_default(source_dir, key):
    """The default of a study key as docs/keys.md (generated from the studies' schemas) lists it."""
    for line in (source_dir / "docs" / "keys.md").read_text().splitlines():
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)]  # a `|` escaped as `\|` is inside a cell
        if len(cells) > 6 and cells[1] == f"`{key}`":
            return cells[5].strip("`")
    raise AssertionError(f"{key} is not in docs/keys.md")


@pytest.mark.parametrize("function,argument,key", [
    (ws.dem.rough_shear, "velocity", "dem.rough_shear.velocity"),
    (ws.dem.rough_shear, "roughness", "dem.rough_shear.roughness"),
    (ws.dem.rough_shear, "hurst", "dem.rough_shear.hurst"),
    (ws.dem.rough_shear, "time_step", "dem.rough_shear.time_step"),
    (ws.dem.rough_shear, "record_every", "dem.rough_shear.record_every"),
    (ws.dem.trapped_particles, "velocity", "dem.trapped_particles.velocity"),
    (ws.dem.trapped_particles, "count", "dem.trapped_particles.count"),
    (ws.dem.trapped_particles, "clearance", "dem.trapped_particles.clearance"),
    (ws.dem.trapped_particles, "fit_from", "dem.trapped_particles.fit_from"),
    (ws.dem.patch_test, "length", "dem.patch_test.length"),
    (ws.dem.patch_test, "width", "dem.patch_test.width"),
    (ws.dem.patch_test, "load", "dem.patch_test.load"),
    (ws.dem.patch_test, "strengths", "dem.patch_test.strengths"),
    (ws.dem.patch_test, "max_elastic_steps", "dem.patch_test.max_elastic_steps"),
])
def test_a_python_default_is_the_cases(source_dir, function, argument, key):
    default = inspect.signature(function).parameters[argument].default
    text = case_default(source_dir, key)
    expected = {"true": True, "false": False}.get(text, None)
    if expected is None:
        expected = float(re.sub(r"\s.*", "", text))
    assert default == expected, f"{function.__name__}({argument}={default!r}) but the case's {key} defaults to {text}"
