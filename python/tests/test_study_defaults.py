"""The keyword defaults of the bindings that compute what a study computes (wearscale.wear's maps,
wearscale.surface's generator and reader, wearscale.contact's normal contact) are the study's: each
argument that stands for a key of the study defaults to that key's default in the study's schema,
or is listed in DIFFERS with why. The schemas are read from the compiled module
(wearscale._study_keys, the studies' key tables); the arguments' keys are listed in KEY_OF, one row
per argument."""
import functools
import inspect
import math
import re

import pytest

import wearscale as ws
from wearscale import _wearscale

# (module, function) -> {argument: (key, what of the key's default)}: "value" the default itself,
# "max" the upper end of a [MIN, MAX] range.
KEY_OF = {
    ("wear", "analytic_map_2d"): {
        "x_max": ("wearmap.analytic2d.dr_over_dstar", "max"),
        "y_max": ("wearmap.analytic2d.da_over_dstar", "max"),
        "nx": ("wearmap.analytic2d.n", "value"),
        "ny": ("wearmap.analytic2d.n", "value"),
    },
    ("wear", "analytic_map_3d"): {
        "x_max": ("wearmap.analytic3d.d_over_l", "max"),
        "y_max": ("wearmap.analytic3d.dstar_over_l", "max"),
        "nx": ("wearmap.analytic3d.n", "value"),
        "ny": ("wearmap.analytic3d.n", "value"),
    },
    ("wear", "rough_wear_map"): {
        "n": ("wearmap.rough.n", "value"),
        "hurst": ("wearmap.rough.hurst", "value"),
        "k_l": ("wearmap.rough.q_l", "value"),
        "k_s": ("wearmap.rough.q_s", "value"),
        "poisson": ("wearmap.rough.nu", "value"),
        "seeds": ("wearmap.rough.seeds", "value"),
        "tensile_strength": ("wearmap.rough.tensile_strength", "value"),
    },
    ("surface", "generate"): {
        "hurst": ("surface.generate.hurst", "value"),
        "k_l": ("surface.generate.k_l", "value"),
        "k_r": ("surface.generate.k_r", "value"),
        "k_s": ("surface.generate.k_s", "value"),
        "seed": ("surface.generate.seed", "value"),
    },
    ("surface", "read"): {
        "dataset": ("surface.analyze.dataset", "value"),
        "missing": ("surface.analyze.missing", "value"),
    },
    ("contact", "NormalContact"): {
        "boundary": ("contact.boundary", "value"),
    },
}
# Where a call's default differs from the case's on purpose, and why.
DIFFERS = {
    ("rough_wear_map", "n"): "128: a map in seconds from Python; the case's 512 is §5.3's",
    ("rough_wear_map", "seeds"): "[1], one surface; the case's count 5 is seeds 1…5",
}


def study_of(key):
    """The registered study whose case holds `key`: "wearmap.rough.n" -> "wearmap/rough", "contact.grid" -> "contact"."""
    parts = key.split(".")
    return "/".join(parts[:2]) if parts[0] in ("wearmap", "surface", "dem") else parts[0]


@functools.cache
def schemas():
    """{key: (type, default text)} of every study a KEY_OF row names, from its key tables."""
    found = {}
    for study in sorted({study_of(key) for arguments in KEY_OF.values() for key, _ in arguments.values()}):
        for row in _wearscale._study_keys(study):
            found.setdefault(row["key"], (row["type"], row["default"]))
    return found


def cases():
    for (module, function), arguments in KEY_OF.items():
        for argument in arguments:
            yield module, function, argument


def test_every_argument_named_is_a_keyword_with_a_default():
    for (module, function), arguments in KEY_OF.items():
        parameters = inspect.signature(getattr(getattr(ws, module), function)).parameters
        for argument in arguments:
            assert argument in parameters, f"{module}.{function} has no argument {argument}"
            assert parameters[argument].default is not inspect.Parameter.empty, f"{module}.{function}({argument})"


@pytest.mark.parametrize("module,function,argument", list(cases()), ids=[f"{m}.{f}.{a}" for m, f, a in cases()])
def test_a_keyword_defaults_to_its_case_key(module, function, argument):
    keys = schemas()
    key, part = KEY_OF[(module, function)][argument]
    assert key in keys, f"{key} is not declared by {study_of(key)}"
    kind, text = keys[key]
    call = getattr(getattr(ws, module), function)
    parameters = inspect.signature(call).parameters
    default = parameters[argument].default
    if (function, argument) in DIFFERS:
        assert str(default) != text, f"{function}({argument}) now defaults as {key}: drop it from DIFFERS"
        return
    if text == "":
        # the case must give it; the call's default is the spec's, and is said in its docstring
        assert default is not None
        return
    if part == "max":
        low, high = (float(x) for x in text.strip("[]").split(","))
        assert math.isclose(default, high, rel_tol=1e-12), f"{function}({argument}={default!r}) but {key} = {text}"
        return
    if kind in ("string", "choice"):
        assert default == text, f"{function}({argument}={default!r}) but {key} = {text}"
        return
    try:
        value = float(text)
    except ValueError:
        value = derived(text, parameters)
    if default is None:
        # the call derives it as the case does ("k_l": no plateau), and its docstring says so
        assert re.search(r"default " + re.escape(text), call.__doc__), f"{function}({argument}=None) vs {key} = {text}"
        return
    assert value is not None, f"{function}({argument}={default!r}) but {key} defaults to '{text}'"
    assert math.isclose(default, value, rel_tol=1e-12), f"{function}({argument}={default!r}) but {key} = {text}"


def derived(text, parameters):
    """A default written in terms of another key ("n/8"): its value from the call's defaults."""
    m = re.fullmatch(r"(\w+)/(\d+)", text)
    if not m or m.group(1) not in parameters:
        return None
    return parameters[m.group(1)].default / float(m.group(2))


def test_the_analytic_3d_map_defaults_to_the_case_interaction_constant():
    # C_inter (4.49) of the case's default nu and theta.
    keys = schemas()
    nu, theta = float(keys["wearmap.analytic3d.nu"][1]), float(keys["wearmap.analytic3d.theta"][1])
    default = inspect.signature(ws.wear.analytic_map_3d).parameters["c_inter"].default
    assert math.isclose(default, (1 - nu * math.sin(theta) ** 2) / (2 - nu), rel_tol=1e-15)
