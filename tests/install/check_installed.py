"""Run by install_test.cmake with the installed package first on sys.path, from the
prefix (outside the source and build trees): the package imports from the prefix, finds the
shipped data of that prefix and solves a Hertz contact."""
import os
import sys

prefix, site = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(prefix, site))
import wearscale  # noqa: E402

assert wearscale.__file__.startswith(prefix), wearscale.__file__
data = wearscale.materials.data_directory()
print("wearscale", wearscale.__version__, "from", wearscale.__file__, "data:", data)
assert os.path.realpath(data) == os.path.realpath(os.path.join(prefix, "share", "wearscale", "data")), data
print(wearscale.materials.interface_law("SiO2", "Si"))
r = wearscale.contact.hertz_check(32)
print(r)
assert r["approach_relative_error"] < 1e-3
