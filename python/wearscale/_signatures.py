"""``inspect.signature`` for the compiled half of the package.

pybind11 writes each function's signature (its ``py::arg`` names and defaults) as the first line of
the docstring only, which ``inspect`` does not read from a builtin. Each compiled function and
method is given a thin Python wrapper whose ``__signature__`` is that line, parsed; the docstring
keeps the rest. The C++ side stays the one place a name or a default is written.
"""
import ast
import functools
import inspect
import math
import re

_LINE = re.compile(r"^(?P<name>\w+)\((?P<params>.*)\)(?:\s*->\s*(?P<ret>.+))?$")


def _split(text):
    """The top-level comma-separated parts of a parameter list (brackets and quotes kept whole)."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote and text[i - 1] != "\\":
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _value(text):
    """A default as pybind11 printed it (its repr)."""
    special = {"inf": math.inf, "-inf": -math.inf, "nan": math.nan}
    if text in special:
        return special[text]
    return ast.literal_eval(text)


def _top_level(text, sep):
    """Where `sep` first occurs outside brackets and quotes in `text` (-1: nowhere)."""
    depth, quote = 0, None
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        elif depth == 0 and text.startswith(sep, i):
            return i
    return -1


def defaults_of(f):
    """{argument: default} of a pybind11 function, as its signature line gives them (also for an argument
    order Python's signatures do not allow: a required argument after one with a default)."""
    return {p.name: p.default for p in _parameters(f) if p.default is not inspect.Parameter.empty}


def signature_of(f):
    """The inspect.Signature of a pybind11 function, from the first line of its docstring.
    ValueError when it has none (an overloaded function), a default is not a literal, or a required
    argument follows one with a default (no Python signature says that)."""
    params, ret = _parameters(f, with_return=True)
    return inspect.Signature(params, return_annotation=ret.strip() if ret else inspect.Signature.empty)


def _parameters(f, with_return=False):
    """The inspect.Parameter list of a pybind11 signature line (and its return annotation)."""
    doc = (getattr(f, "__doc__", None) or "").strip()
    first = doc.splitlines()[0] if doc else ""
    m = _LINE.match(first)
    if not m:
        raise ValueError(f"{getattr(f, '__qualname__', f)}: no pybind11 signature line in its docstring: {first!r}")
    params, kind = [], inspect.Parameter.POSITIONAL_OR_KEYWORD
    for part in _split(m.group("params")):
        if part == "*":
            kind = inspect.Parameter.KEYWORD_ONLY
            continue
        if part == "/":
            params = [p.replace(kind=inspect.Parameter.POSITIONAL_ONLY) for p in params]
            continue
        stars = len(part) - len(part.lstrip("*"))
        part = part.lstrip("*")
        eq = _top_level(part, "=")
        default = inspect.Parameter.empty
        if eq >= 0:
            default = _value(part[eq + 1:].strip())
            part = part[:eq].strip()
        colon = part.find(":")
        name, annotation = (part[:colon].strip(), part[colon + 1:].strip()) if colon >= 0 else (part, inspect.Parameter.empty)
        this_kind = {1: inspect.Parameter.VAR_POSITIONAL, 2: inspect.Parameter.VAR_KEYWORD}.get(stars, kind)
        if stars == 1:
            kind = inspect.Parameter.KEYWORD_ONLY
        params.append(inspect.Parameter(name, this_kind, default=default, annotation=annotation))
    return (params, m.group("ret")) if with_return else params


def own_doc(f):
    """The docstring without pybind11's signature line."""
    doc = getattr(f, "__doc__", None) or ""
    lines = doc.strip().splitlines()
    if lines and _LINE.match(lines[0].strip()):
        lines = lines[1:]
    return "\n".join(lines).strip() or None


def signed(f, module=None):
    """`f` (a pybind11 function or method) behind a Python function with its signature."""
    if getattr(f, "__signature__", None) is not None:
        return f
    try:
        sig = signature_of(f)
    except ValueError:
        return f  # no Python signature says it (tests/test_signatures.py finds such a function)

    @functools.wraps(f)
    def call(*args, **kwargs):
        return f(*args, **kwargs)

    call.__signature__ = sig
    call.__doc__ = own_doc(f)
    if module:
        call.__module__ = module
    return call


def _is_compiled(obj):
    return type(obj).__name__ in ("builtin_function_or_method", "instancemethod")


def sign_class(cls):
    """Gives each compiled method of a pybind11 class (and its constructor) its signature, in place."""
    for name, attr in list(vars(cls).items()):
        if isinstance(attr, staticmethod) and _is_compiled(attr.__func__) and not name.startswith("_"):
            wrapped = signed(attr.__func__, cls.__module__)
            if wrapped is not attr.__func__:
                setattr(cls, name, staticmethod(wrapped))
            continue
        if (name.startswith("_") and name != "__init__") or not _is_compiled(attr):
            continue
        function = attr.__func__ if hasattr(attr, "__func__") else attr
        wrapped = signed(function, cls.__module__)
        if wrapped is not function:
            setattr(cls, name, wrapped)
    return cls


def sign_module(module, into):
    """Every public function and class of the compiled `module` into the dict `into` (a Python
    module's globals()), each function behind a wrapper with its signature; returns their names."""
    names = []
    for name in dir(module):
        if name.startswith("_"):
            continue
        obj = getattr(module, name)
        if inspect.isclass(obj):
            into[name] = sign_class(obj)
        elif _is_compiled(obj):
            into[name] = signed(obj, into.get("__name__"))
        else:
            into[name] = obj
        names.append(name)
    return sorted(names)
