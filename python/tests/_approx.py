"""pytest.approx with no absolute floor: the quantities here are SI (a 1e-17 J energy, a 1e-7 m
roughness), for which approx's default abs = 1e-12 would accept anything."""
import pytest


def approx(expected, rel=None, abs=0.0):  # noqa: A002 (pytest's own keyword)
    return pytest.approx(expected, rel=rel, abs=abs)
