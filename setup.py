"""The build of `pip install .` (pyproject.toml): setuptools around the project's CMake.

build_py copies the pure-Python files of python/wearscale/, then builds the CMake target
`wearscale_python` (the compiled module _wearscale*.so) and copies it beside them; the shipped
data go to <prefix>/share/wearscale/data, where the module finds them (docs/install.md).

The CMake build tree: WEARSCALE_BUILD_DIR if set (an existing, configured build tree of this
source, e.g. `build`: only the module's target is brought up to date there), else a tree of its
own under setuptools' build folder, configured Release with the tests and benchmarks off.
CMAKE_ARGS adds configure options (e.g. "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache");
CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: the cores).
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

SOURCE = Path(__file__).resolve().parent


def cmake_version():
    """The one version: project(wearscale VERSION x.y.z) of CMakeLists.txt."""
    text = (SOURCE / "CMakeLists.txt").read_text()
    m = re.search(r"project\(\s*wearscale\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        sys.exit("setup.py: no project(wearscale VERSION ...) in CMakeLists.txt")
    return m.group(1)


def run(command, cwd=None):
    print("+", " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], cwd=cwd, check=True)


class BuildWithCMake(build_py):
    """The pure-Python files, then the compiled module from the CMake build."""

    def run(self):
        super().run()
        build_dir = self.cmake_tree()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        run(["cmake", "--build", build_dir, "--target", "wearscale_python", "-j", jobs])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        module = build_dir / "python" / "wearscale" / f"_wearscale{suffix}"
        if not module.exists():
            found = sorted(p.name for p in (build_dir / "python" / "wearscale").glob("_wearscale*"))
            sys.exit(f"setup.py: {module} was not built; the build tree {build_dir} holds {found or 'no module'}: "
                     f"it was configured for another Python than {sys.executable} ({suffix})")
        target = Path(self.build_lib) / "wearscale"
        target.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, target / module.name)

    def cmake_tree(self):
        given = os.environ.get("WEARSCALE_BUILD_DIR")
        if given:
            build_dir = Path(given).resolve()
            if not (build_dir / "CMakeCache.txt").exists():
                sys.exit(f"setup.py: WEARSCALE_BUILD_DIR={given} is not a configured CMake build tree "
                         f"(cmake -S {SOURCE} -B {given} first)")
            return build_dir
        build_dir = Path(self.get_finalized_command("build").build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     "-DWEARSCALE_BUILD_TESTS=OFF", "-DWEARSCALE_BUILD_BENCH=OFF", "-DWEARSCALE_PYTHON=ON",
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        configure += os.environ.get("CMAKE_ARGS", "").split()
        run(configure)
        return build_dir


class BinaryDistribution(Distribution):
    """A wheel for this interpreter and platform: it holds a compiled module."""

    def has_ext_modules(self):
        return True


def scratch_options():
    """With WEARSCALE_BUILD_DIR, setuptools' own files (build/, *.egg-info) go into that tree, not the source tree."""
    given = os.environ.get("WEARSCALE_BUILD_DIR")
    if not given:
        return {}
    base = Path(given).resolve() / "python-package"
    (base / "egg-info").mkdir(parents=True, exist_ok=True)
    return {"build": {"build_base": str(base / "build")}, "egg_info": {"egg_base": str(base / "egg-info")}}


setup(
    version=cmake_version(),
    options=scratch_options(),
    packages=["wearscale"],
    package_dir={"": "python"},
    data_files=[("share/wearscale/data", sorted(str(p.relative_to(SOURCE)) for p in (SOURCE / "materials" / "data").iterdir()
                                                if p.is_file()))],
    cmdclass={"build_py": BuildWithCMake},
    distclass=BinaryDistribution,
)
