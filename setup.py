# SPDX-License-Identifier: GPL-3.0-or-later
"""pip's build of the Python package roughroll (pyproject.toml): the extension roughroll._roughroll
is built by the project's own CMakeLists.txt (the target roughroll_python, with roughroll_core),
not by setuptools, and copied into the wheel beside python/roughroll/*.py.

Environment:
  ROUGHROLL_CMAKE_BUILD_DIR  a CMake build folder to configure and build in (kept, so a second
                             install rebuilds only what changed); default: one under build-pip/.
  ROUGHROLL_CMAKE_ARGS       more arguments for the configure step (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache).
  CMAKE_BUILD_PARALLEL_LEVEL the build's jobs (default: every core).
"""

import glob
import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
# Not build/: that folder name is the CMake build tree of the README (.gitignore: /build*/).
BUILD_BASE = os.path.join(ROOT, "build-pip")


def configured_elsewhere(build):
    """Whether the CMake cache in build belongs to another source folder."""
    try:
        with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("CMAKE_HOME_DIRECTORY:"):
                    return os.path.realpath(line.split("=", 1)[1].strip()) != os.path.realpath(ROOT)
    except FileNotFoundError:
        pass
    return False


class CMakeBuild(build_ext):
    """Configures and builds roughroll_python with CMake, then copies the module it made."""

    def build_extension(self, ext):
        build = os.path.abspath(os.environ.get("ROUGHROLL_CMAKE_BUILD_DIR") or os.path.join(BUILD_BASE, "cmake"))
        if not os.environ.get("ROUGHROLL_CMAKE_BUILD_DIR") and configured_elsewhere(build):
            shutil.rmtree(build)  # a moved or copied source tree: CMake refuses a cache of another source
        configure = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                     # Only the module: no tests, benchmarks or their libraries needed.
                     "-DBUILD_TESTING=OFF", "-DROUGHROLL_BENCHMARKS=OFF", "-DROUGHROLL_PYTHON=ON",
                     # The interpreter pip runs (a venv's python3): its headers and module suffix.
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        configure += shlex.split(os.environ.get("ROUGHROLL_CMAKE_ARGS", ""))
        compile_ = ["cmake", "--build", build, "--target", "roughroll_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            compile_ += ["-j", str(self.parallel or os.cpu_count() or 1)]
        for command in (configure, compile_):
            print(" ".join(shlex.quote(c) for c in command), flush=True)
            subprocess.run(command, check=True)
        built = glob.glob(os.path.join(build, "python", "roughroll", "_roughroll*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one extension in {build}/python/roughroll, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


os.makedirs(BUILD_BASE, exist_ok=True)
setup(
    ext_modules=[Extension("roughroll._roughroll", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Every setuptools folder under build-pip/, none in the source tree (python/*.egg-info).
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
    zip_safe=False,
)
