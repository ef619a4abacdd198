"""`pip install .`: the Python package asperity (python/asperity) with its compiled module and the
default table, built by CMake from this source tree with Debian's packages and no network:

    python3 -m pip install --no-build-isolation --no-deps .            # a venv, or --user
    python3 -m pip install --no-build-isolation --no-deps --break-system-packages .   # the system

(a venv made with `python3 -m venv --system-site-packages` sees Debian's numpy, pybind11, setuptools;
scripts/setup.sh installs them). The module links the asperity libraries statically, so the package
needs nothing from this tree once installed; the default table sits beside the module, where the
library looks first (ASPERITY_PYTHON_PACKAGE_TABLE, cmake/install_layout.cmake).

Environment:
  ASPERITY_DEFAULT_TABLE_SOURCE  a default table to copy (e.g. build/tables/asperity-default.h5) instead
                                 of generating one with tablegen (a minute or two on 2 cores)
  ASPERITY_PIP_BUILD_DIR         where CMake and setuptools build (default: build-pip/ in this tree);
                                 kept, so that installing again only relinks what changed
  ASPERITY_CMAKE_ARGS            more arguments for CMake (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CMAKE_BUILD_PARALLEL_LEVEL     parallel build jobs (default: every processor)
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("ASPERITY_PIP_BUILD_DIR") or SOURCE / "build-pip").resolve()
TABLE_NAME = "asperity-default.h5"


def project_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(asperity VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    """asperity._asperity, built by CMake's target asperity_python (python/CMakeLists.txt)."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            raise RuntimeError("asperity: building the module needs CMake (Debian: cmake; scripts/setup.sh)")
        cmake_dir = BUILD / "cmake"
        table_source = os.environ.get("ASPERITY_DEFAULT_TABLE_SOURCE", "")
        arguments = [
            "-S", str(SOURCE), "-B", str(cmake_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}",   # the interpreter pip runs: the venv's, or the system's
            "-DASPERITY_SHARED=OFF",                   # the libraries inside the module: nothing else to install
            "-DASPERITY_PYTHON_PACKAGE_TABLE=ON",      # the table beside the module
            "-DASPERITY_BUILD_PYTHON=ON", "-DASPERITY_BUILD_TESTS=OFF", "-DASPERITY_BUILD_BENCHMARKS=OFF",
            "-DASPERITY_BUILD_FORTRAN=OFF", "-DASPERITY_INSTALL=OFF",
            # tablegen only to generate the table when none is given
            f"-DASPERITY_BUILD_COMMANDS={'OFF' if table_source else 'ON'}",
            f"-DASPERITY_DEFAULT_TABLE_SOURCE={os.path.abspath(table_source) if table_source else ''}",
        ]
        arguments += shlex.split(os.environ.get("ASPERITY_CMAKE_ARGS", ""))
        subprocess.run(["cmake", *arguments], check=True)
        environment = dict(os.environ)
        environment.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        # only the module and the table (and what they need), not the tests or the commands
        subprocess.run(["cmake", "--build", str(cmake_dir), "--target", "asperity_python", "default_table"],
                       check=True, env=environment)

        built = sorted((cmake_dir / "python" / "asperity").glob("_asperity*.so"))
        if len(built) != 1:
            raise RuntimeError(f"asperity: expected one built module in {cmake_dir / 'python' / 'asperity'}, found {built}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)
        shutil.copy2(cmake_dir / "tables" / TABLE_NAME, target.parent / TABLE_NAME)


setup(
    version=project_version(),
    packages=["asperity"],
    package_dir={"": "python"},
    package_data={"asperity": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("asperity._asperity")],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own files (build/, egg-info) under the build folder, not in the source tree
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD)}},
    zip_safe=False,
)
