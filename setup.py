# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds meshbridge._core with the project's CMake (MESHBRIDGE_BUILD_PYTHON), for
`pip install --no-build-isolation .`. Metadata is in pyproject.toml.

Needs cmake, a C++17 compiler, libopenmesh-dev, pybind11-dev, python3-dev (Debian packages;
scripts/install_deps.sh installs them). ccache is used when it is installed.
MESHBRIDGE_CMAKE_ARGS adds arguments to the CMake configure step; MESHBRIDGE_BUILD_TEMP moves
the CMake build folder (default: setuptools' build_temp, below ./build).
"""

import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(os.environ.get("MESHBRIDGE_BUILD_TEMP") or self.build_temp).resolve() / "cmake"
        args = [
            "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DMESHBRIDGE_BUILD_PYTHON=ON",
            "-DMESHBRIDGE_BUILD_CLI=OFF",
            "-DMESHBRIDGE_BUILD_TESTS=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
        ]
        if shutil.which("ccache"):
            args += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        args += shlex.split(os.environ.get("MESHBRIDGE_CMAKE_ARGS", ""))
        subprocess.run(["cmake", *args], check=True)
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "meshbridge_python",
                        "--parallel", jobs], check=True)
        built = build_dir / "python" / "meshbridge" / Path(self.get_ext_filename(ext.name)).name
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(ext_modules=[CMakeExtension("meshbridge._core")], cmdclass={"build_ext": CMakeBuild})
