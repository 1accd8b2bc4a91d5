"""Builds the extension module catplan._catplan with CMake (pyproject.toml has the metadata).

The library and the module are compiled in Release mode into build/python (ccache is used when
it is installed). Environment:
  CATPLAN_JOBS        parallel compile jobs (default 2)
  CATPLAN_CMAKE_ARGS  extra CMake arguments, split on spaces
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        out = Path(self.get_ext_fullpath(ext.name)).resolve().parent
        build = ROOT / "build" / "python"
        args = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_FLAGS_RELEASE=-O2",
            "-DCATPLAN_BUILD_TESTS=OFF", "-DCATPLAN_BUILD_BENCH=OFF",
            "-DCATPLAN_BUILD_PYTHON=ON",
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DCATPLAN_PYTHON_OUTPUT_DIR={out}",
        ]
        if shutil.which("ninja"):
            args += ["-G", "Ninja"]
        if shutil.which("ccache"):
            args += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
        args += os.environ.get("CATPLAN_CMAKE_ARGS", "").split()
        subprocess.run(args, check=True)
        jobs = os.environ.get("CATPLAN_JOBS", "2")
        subprocess.run(["cmake", "--build", str(build), "--target", "catplan_python", "-j", jobs],
                       check=True)


setup(ext_modules=[CMakeExtension("catplan._catplan")], cmdclass={"build_ext": CMakeBuild})
