"""ctest install.pip: the README's `pip install` of the Python module, offline, into a fresh venv.

    python3 -m venv --system-site-packages V && V/bin/pip install --no-build-isolation SOURCE

with WEARSCALE_BUILD_DIR pointing setup.py at this build tree (only the module's target is
brought up to date there: the test reuses the compiled objects) and PIP_NO_INDEX=1 (no network:
numpy comes from the system's site-packages). Then, from outside the source and build trees and
with -I (no PYTHONPATH, no user site): the package imports from the venv, its metadata version is
CMakeLists.txt's project version and the module's own, it finds the shipped data the wheel
installed into the venv, and it runs a case (the Hertz contact of the unworn pin, §8.1) and a
BEM solve.
    python3 tests/install/pip_install.py SOURCE BUILD SCRATCH VERSION
"""
import os
import shutil
import subprocess
import sys
import time

source, build, scratch, version = sys.argv[1:5]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
venv = os.path.join(scratch, "v")
env = dict(os.environ, WEARSCALE_BUILD_DIR=build, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
for name in ("PYTHONPATH", "WEARSCALE_DATA", "WEARSCALE_DATA_DIR", "PYTHONHOME"):
    env.pop(name, None)


def step(what, command, **kw):
    t0 = time.monotonic()
    done = subprocess.run(command, env=env, capture_output=True, text=True, **kw)
    print(f"{what}: {time.monotonic() - t0:.1f} s", flush=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return done.stdout


start = time.monotonic()
step("python3 -m venv --system-site-packages", [sys.executable, "-m", "venv", "--system-site-packages", venv])
step("pip install --no-build-isolation .", [os.path.join(venv, "bin", "pip"), "install", "--no-build-isolation", source],
     cwd=scratch)
check = f"""
import importlib.metadata, os, sys
import wearscale as ws
venv = {venv!r}
assert ws.__file__.startswith(venv), ws.__file__
assert importlib.metadata.version("wearscale") == ws.__version__ == {version!r}, (importlib.metadata.version("wearscale"), ws.__version__)
data = ws.materials.data_directory()
assert os.path.realpath(data) == os.path.realpath(os.path.join(venv, "share", "wearscale", "data")), data
case = {{"case": {{"name": "hertz"}}, "scale": {{"macro": {{"backend": "hertz", "pin_radius": "3 mm", "normal_load": "1 N",
        "elastic_modulus": "73 GPa", "poisson_ratio": 0.17}}}}}}
assert ws.check(case)["study"] == "pipeline"
r = ws.run(case, out="hertz")
d = 2 * r.results["contact_radius_m"]
assert abs(d / 78.2e-6 - 1) < 2e-3, d  # §8.1: 78.2 um
h = ws.contact.hertz_check(32)
assert h["approach_relative_error"] < 1e-3, h
print("wearscale", ws.__version__, "from", ws.__file__, "contact diameter", d)
"""
print(step("the installed package runs", [os.path.join(venv, "bin", "python"), "-I", "-c", check], cwd=scratch).strip())
print(f"install.pip: {time.monotonic() - start:.1f} s in all")
