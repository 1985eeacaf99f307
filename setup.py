"""Builds the brdftab Python package: the pure-Python layer (python/brdftab), the pybind11
extension brdftab._core built by CMake for the interpreter running this script
(-DPython_EXECUTABLE=sys.executable), and the default tables (tables/*.h5) as package data.

Environment:
  BRDFTAB_CMAKE_BUILD_DIR   CMake build folder to (re)use (default: inside setuptools' build_temp)
  CMAKE_BUILD_PARALLEL_LEVEL  parallel compile jobs (default: the CPU count)
  CMAKE_CXX_COMPILER_LAUNCHER e.g. ccache (read by CMake itself)
  BRDFTAB_SETUPTOOLS_BUILD  setuptools' build folder (default: build/setuptools)
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent


def version() -> str:
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"project\(\s*brdftab\s+VERSION\s+([0-9.]+)", text)
    return m.group(1) if m else "0"


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = Path(os.environ.get("BRDFTAB_CMAKE_BUILD_DIR") or Path(self.build_temp).resolve() / "cmake")
        build_dir.mkdir(parents=True, exist_ok=True)
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        f"-DPython_EXECUTABLE={sys.executable}",
                        # the lookup library linked in statically: the installed module needs no other .so
                        "-DBRDFTAB_LOOKUP_SHARED=OFF"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "brdftab_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "brdftab" / ("_core" + suffix)
        if not built.exists():
            raise RuntimeError(f"CMake did not produce {built} (is the interpreter's Python.h installed?)")
        dest = Path(self.get_ext_fullpath(ext.name))
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, dest)


class BuildPyWithTables(build_py):
    """The default tables go into the package (brdftab/tables), the fallback table folder."""

    def run(self):
        super().run()
        dest = Path(self.build_lib) / "brdftab" / "tables"
        dest.mkdir(parents=True, exist_ok=True)
        for f in sorted((ROOT / "tables").glob("*.h5")) + [ROOT / "tables" / "default.json"]:
            shutil.copy2(f, dest / f.name)


# setuptools' own build files (build_lib, build_temp, egg-info) away from the sources and from
# a CMake build folder named build/.
BUILD_BASE = Path(os.environ.get("BRDFTAB_SETUPTOOLS_BUILD") or ROOT / "build" / "setuptools")
BUILD_BASE.mkdir(parents=True, exist_ok=True)

setup(
    version=version(),
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    packages=["brdftab"],
    package_dir={"": "python"},
    package_data={"brdftab": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("brdftab._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPyWithTables},
    zip_safe=False,
)
