"""The keyword defaults of wearscale.dem are the case's: every binding that runs a DEM study defaults
each argument named as a key of that study (or of its [dem] table) to the key's default as the
study's key tables declare it (read from the compiled module, so that every key and every binding is
checked whenever one of them changes)."""
import inspect
import math

import pytest

import wearscale as ws
from wearscale import _wearscale

# Each binding and the study whose case it runs.
STUDY_OF = {
    "patch_test": "dem/patch_test",
    "sheared_junction": "dem/junction",
    "rough_shear": "dem/rough_shear",
    "trapped_particles": "dem/trapped_particles",
}
# The bindings that run no study: the material targets (6.35), (6.62), (6.65).
NO_STUDY = {"material"}
# Where a call's default differs from the case's on purpose, and why.
DIFFERS = {
    ("sheared_junction", "material"): "SiO2: the case's default is Table 6.4's unitless material, "
                                      "and the call's lengths are in metres",
    ("rough_shear", "material"): "as sheared_junction",
    ("trapped_particles", "material"): "as sheared_junction",
}


def schema(study):
    """{key: (type, default text)} of a study's case, from its key tables."""
    return {row["key"]: (row["type"], row["default"]) for row in _wearscale._study_keys(study)}


def derived(text, defaults):
    """A default written in terms of other arguments ("1.25 d0", "L", "1.5 D", "3 n D"): its value
    from the call's own defaults of those arguments; None when one of them has none, or the text
    names a quantity no argument gives ("0.6 d_c")."""
    symbols = {"d0": defaults.get("d0"), "D": defaults.get("diameter"), "n": defaults.get("count"),
               "L": (defaults.get("box") or [None])[0]}
    value = 1.0
    for token in text.split():
        try:
            value *= float(token)
        except ValueError:
            if symbols.get(token) is None:
                return None
            value *= symbols[token]
    return value


def expected(kind, text, defaults):
    """The value a call's default must have for a key of type `kind` defaulting to `text`."""
    if kind == "boolean":
        return {"true": True, "false": False}[text]
    if kind in ("string", "choice"):
        return text
    if kind == "list":
        return [float(x) for x in text.strip("[]").split(",")]
    try:
        return float(text)
    except ValueError:
        return derived(text, defaults)


def cases():
    for function, study in STUDY_OF.items():
        for name, parameter in inspect.signature(getattr(ws.dem, function)).parameters.items():
            if parameter.default is not inspect.Parameter.empty:
                yield function, study, name


def test_every_dem_binding_that_runs_a_study_is_checked():
    assert set(ws.dem.__all__) - NO_STUDY == set(STUDY_OF)


@pytest.mark.parametrize("function,study,argument", list(cases()), ids=[f"{f}.{a}" for f, _, a in cases()])
def test_a_dem_keyword_defaults_to_its_case_key(function, study, argument):
    keys = schema(study)
    table = study.replace("/", ".")
    key = next((k for k in (f"{table}.{argument}", f"dem.{argument}") if k in keys), None)
    if key is None:
        pytest.skip(f"{function}({argument}) is no key of {study}")
    kind, text = keys[key]
    call = getattr(ws.dem, function)
    default = inspect.signature(call).parameters[argument].default
    if text == "":
        pytest.skip(f"{key} has no default: a case gives it")
    if (function, argument) in DIFFERS:
        assert default != text, f"{function}({argument}) now defaults as {key}: drop it from DIFFERS"
        return
    if default is None and text == "the material's":
        return  # None: the material's own value, as the case takes it
    defaults = {n: p.default for n, p in inspect.signature(call).parameters.items()}
    value = expected(kind, text, defaults)
    if default is None or (default == 0 and value != 0):
        # the call derives the value itself, as the case does, and says so
        assert text in call.__doc__, f"{function}({argument}={default!r}): its docstring does not say '{text}'"
        return
    assert value is not None, f"{function}({argument}={default!r}) but {key} defaults to '{text}'"
    if isinstance(value, list):
        assert list(default) == pytest.approx(value, rel=1e-12), f"{function}({argument}) vs {key} = {text}"
    elif isinstance(value, float):
        assert math.isclose(default, value, rel_tol=1e-12), f"{function}({argument}={default!r}) but {key} = {text}"
    else:
        assert default == value, f"{function}({argument}={default!r}) but {key} = {text}"
