"""The build backend of `pip install .` (PEP 517; pyproject.toml names it): the Python package
asperity with its compiled module and the default table, built by CMake from this source tree.

It needs nothing from an index, nor setuptools or wheel: only the standard library of the
interpreter pip runs, and to build, CMake, a C++ compiler, the C++ dependencies (scripts/setup.sh),
Python's headers and pybind11 (Debian's pybind11-dev, or the pybind11 Python package); numpy for
the package to work. What is missing is named, one line each, before anything is built. So
`python3 -m pip install .` works offline with or without build isolation, in a venv or not.

    python3 -m pip install .                          # a venv (numpy in it, or --system-site-packages)
    python3 -m pip install --break-system-packages .  # Debian's /usr/bin/python3, the system

The wheel holds python/asperity's files as CMake assembles them (python/CMakeLists.txt), the module
(the libraries linked statically into it) and asperity-default.h5 beside it, where the library
looks first (ASPERITY_PYTHON_PACKAGE_TABLE, cmake/install_layout.cmake).

Environment:
  ASPERITY_DEFAULT_TABLE_SOURCE  the default table to copy; default: build/tables/asperity-default.h5
                                 in this tree when it exists, else tablegen generates it (about
                                 100 s on 2 cores, once per build folder); `generate` to generate
  ASPERITY_PIP_BUILD_DIR         where CMake builds (default: build-pip/ in this tree), one folder
                                 per Python ABI; kept, so that installing again rebuilds only what changed
  ASPERITY_CMAKE_ARGS            more arguments for CMake (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CMAKE_BUILD_PARALLEL_LEVEL     parallel build jobs (default: every processor)
Progress: CMake's output with `pip -v`; without it, a line per tenth of the build on the terminal
(/dev/tty) when there is one; the whole output in <build folder>/build.log.
"""
import base64
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
TABLE_NAME = "asperity-default.h5"
NAME = "asperity"
SUMMARY = "Greenwood-Williamson asperity integrals from precomputed tables: rough-surface contact in nanoseconds"
REQUIRES_PYTHON = ">=3.9"
REQUIRES = ["numpy"]
EXTRAS = {"plot": ["matplotlib"],             # asperity.plot
          "batch": ["dask", "distributed"]}   # asperity.batch
# where CMake finds pybind11's package when the pybind11 Python package is not installed
PYBIND11_CMAKE_DIRS = ("/usr/lib/cmake/pybind11", "/usr/share/cmake/pybind11", "/usr/local/lib/cmake/pybind11",
                       "/usr/local/share/cmake/pybind11", "/usr/lib64/cmake/pybind11")


def version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(asperity VERSION ([0-9.]+)", text).group(1)


# ---- what the interpreter has ----

def interpreter_environment():
    """The environment without pip's build isolation: the interpreter's own site-packages (its
    numpy, its pybind11), which an isolated build hides."""
    environment = dict(os.environ)
    path = environment.get("PYTHONPATH", "")
    kept = [entry for entry in path.split(os.pathsep) if entry and "pip-build-env-" not in entry]
    if len(kept) != len([entry for entry in path.split(os.pathsep) if entry]):
        environment.pop("PYTHONNOUSERSITE", None)
    if kept:
        environment["PYTHONPATH"] = os.pathsep.join(kept)
    else:
        environment.pop("PYTHONPATH", None)
    return environment


PROBE = r"""
import json, sys
found = {}
try:
    import numpy
    found["numpy"] = numpy.__version__
except ImportError:
    pass
try:
    import pybind11
    found["pybind11"] = pybind11.get_cmake_dir()
except ImportError:
    pass
print(json.dumps(found))
"""


def probe():
    """numpy's version and pybind11's CMake folder, as the interpreter itself sees them."""
    done = subprocess.run([sys.executable, "-c", PROBE], env=interpreter_environment(),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        return {}
    return json.loads(done.stdout.strip().splitlines()[-1])


def missing(found, executable, version_info, cmake, python_header, pybind11_dirs=PYBIND11_CMAKE_DIRS,
            cmake_args=""):
    """One line for each thing the build or the package lacks (found: probe()'s answer)."""
    lines = []
    if tuple(version_info[:2]) < (3, 9):
        lines.append(f"asperity needs Python 3.9 or later, not {version_info[0]}.{version_info[1]} ({executable})")
    if "numpy" not in found:
        lines.append(f"asperity needs numpy for {executable}: install python3-numpy (Debian) "
                     f"or `{executable} -m pip install numpy`")
    if ("pybind11" not in found and "pybind11_DIR" not in cmake_args
            and not any(Path(folder, "pybind11Config.cmake").is_file() for folder in pybind11_dirs)):
        lines.append(f"asperity needs pybind11 to build for {executable}: install pybind11-dev (Debian) "
                     f"or `{executable} -m pip install pybind11`")
    if not python_header:
        lines.append(f"asperity needs Python's headers (Python.h) to build for {executable}: "
                     f"install python3-dev (Debian)")
    if not cmake:
        lines.append("asperity needs CMake to build: install cmake (Debian; scripts/setup.sh installs "
                     "every C++ dependency)")
    return lines


_checked = None


def check():
    """Stops (one line per missing thing, no traceback) before building; the probe's answer."""
    global _checked
    if _checked is None:
        found = probe()
        header = Path(sysconfig.get_paths()["include"], "Python.h").is_file()
        lines = missing(found, sys.executable, sys.version_info, shutil.which("cmake"), header,
                        cmake_args=os.environ.get("ASPERITY_CMAKE_ARGS", ""))
        if lines:
            raise SystemExit("\n".join(lines))
        _checked = found
    return _checked


# ---- the build ----

class Progress:
    """CMake's output line by line to stdout (pip -v shows it) and the log; a short line per
    tenth of the build to the terminal, when there is one (pip without -v hides stdout)."""

    def __init__(self, log):
        self.log = open(log, "w", encoding="utf-8", errors="replace")
        try:
            self.tty = open("/dev/tty", "w")
        except OSError:
            self.tty = None
        self.shown = -10
        self.lines = 0

    def terminal(self, line):
        # below pip's spinner line ("Building wheel ... |"), then each over the spinner's character
        self.tty.write(("\r" if self.lines else "\n") + line + "\n")
        self.tty.flush()
        self.lines += 1

    def say(self, line, terminal=True):
        print(line, flush=True)
        self.log.write(line + "\n")
        self.log.flush()
        if terminal and self.tty:
            self.terminal(line)

    def run(self, command, **keywords):
        self.log.write("$ " + shlex.join(command) + "\n")
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   errors="replace", bufsize=1, **keywords)
        for line in process.stdout:
            line = line.rstrip("\n")
            self.say(line, terminal=False)
            step = re.match(r"\[\s*(\d+)%\]", line) or re.match(r"\[(\d+)/(\d+)\]", line)
            if step and self.tty:
                percent = int(step.group(1)) if step.lastindex == 1 else 100 * int(step.group(1)) // int(step.group(2))
                if percent >= self.shown + 10:
                    self.shown = percent
                    self.terminal(f"asperity: building, {percent}%: {line[step.end():].strip()[:100]}")
        return process.wait()


def table_source():
    given = os.environ.get("ASPERITY_DEFAULT_TABLE_SOURCE", "")
    if given == "generate":
        return None
    if given:
        if not Path(given).is_file():
            raise SystemExit(f"asperity: ASPERITY_DEFAULT_TABLE_SOURCE={given} is not a file "
                             f"(name a default table, or `generate`)")
        return Path(given).resolve()
    candidate = SOURCE / "build" / "tables" / TABLE_NAME
    return candidate if candidate.is_file() else None


def build_folder():
    return Path(os.environ.get("ASPERITY_PIP_BUILD_DIR") or SOURCE / "build-pip").resolve()


def build(found):
    """The module and the table, built by CMake in the kept build folder: its package folder."""
    folder = build_folder()
    cmake_dir = folder / f"cmake-{sys.implementation.cache_tag}"
    cmake_dir.mkdir(parents=True, exist_ok=True)
    progress = Progress(folder / "build.log")
    table = table_source()
    # the venv's base interpreter: the same build for the venv and the system (the same headers)
    executable = getattr(sys, "_base_executable", "") or sys.executable
    arguments = [
        "-S", str(SOURCE), "-B", str(cmake_dir),
        "-DCMAKE_BUILD_TYPE=Release",
        f"-DPython_EXECUTABLE={executable}",
        "-DASPERITY_SHARED=OFF",                   # the libraries inside the module: nothing else to install
        "-DASPERITY_PYTHON_PACKAGE_TABLE=ON",      # the table beside the module
        "-DASPERITY_BUILD_PYTHON=ON", "-DASPERITY_BUILD_TESTS=OFF", "-DASPERITY_BUILD_BENCHMARKS=OFF",
        "-DASPERITY_BUILD_FORTRAN=OFF", "-DASPERITY_INSTALL=OFF",
        # tablegen only to generate the table when none is given
        f"-DASPERITY_BUILD_COMMANDS={'OFF' if table else 'ON'}",
        f"-DASPERITY_DEFAULT_TABLE_SOURCE={table or ''}",
    ]
    if "pybind11" in found:
        arguments.append(f"-Dpybind11_DIR={found['pybind11']}")
    arguments += shlex.split(os.environ.get("ASPERITY_CMAKE_ARGS", ""))
    progress.say(f"asperity: building with CMake in {cmake_dir} (log: {folder / 'build.log'}); the default table "
                 + (f"copied from {table}" if table else "generated by tablegen (about 100 s on 2 cores, once)"))
    # configured again only when the arguments change (the build reconfigures itself when CMake's files do)
    stamp = cmake_dir / "asperity-pip-arguments.txt"
    if not (cmake_dir / "CMakeCache.txt").is_file() or not stamp.is_file() or stamp.read_text() != shlex.join(arguments):
        stamp.unlink(missing_ok=True)
        if progress.run(["cmake", *arguments]) != 0:
            raise SystemExit(f"asperity: configuring with CMake failed (its output is above and in {folder / 'build.log'})")
        stamp.write_text(shlex.join(arguments))
    environment = dict(os.environ)
    environment.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
    # only the module and the table (and what they need), not the tests or the commands
    if progress.run(["cmake", "--build", str(cmake_dir), "--target", "asperity_python", "default_table"],
                    env=environment) != 0:
        raise SystemExit(f"asperity: the build failed (its output is above and in {folder / 'build.log'})")
    progress.say("asperity: built; packing the wheel")
    return cmake_dir


# ---- the wheel (PEP 427) ----

def wheel_tag():
    implementation = sys.implementation.name
    interpreter = {"cpython": "cp", "pypy": "pp"}.get(implementation, implementation) + "%d%d" % sys.version_info[:2]
    soabi = sysconfig.get_config_var("SOABI") or ""
    if implementation == "cpython" and soabi.startswith("cpython-"):
        abi = "cp" + soabi.split("-")[1]
    else:
        abi = re.sub(r"[^\w]", "_", soabi) or "none"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{interpreter}-{abi}-{platform}"


def dist_info_name():
    return f"{NAME}-{version()}.dist-info"


def metadata_files():
    lines = ["Metadata-Version: 2.1", f"Name: {NAME}", f"Version: {version()}", f"Summary: {SUMMARY}",
             "License: MIT", f"Requires-Python: {REQUIRES_PYTHON}"]
    lines += [f"Requires-Dist: {requirement}" for requirement in REQUIRES]
    for extra, requirements in EXTRAS.items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {requirement}; extra == "{extra}"' for requirement in requirements]
    lines.append("Description-Content-Type: text/markdown")
    metadata = "\n".join(lines) + "\n\n" + (SOURCE / "README.md").read_text(encoding="utf-8")
    wheel = f"Wheel-Version: 1.0\nGenerator: asperity_build\nRoot-Is-Purelib: false\nTag: {wheel_tag()}\n"
    return {"METADATA": metadata.encode(), "WHEEL": wheel.encode()}


def _record_hash(data):
    return "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()


# ---- PEP 517 hooks ----

def get_requires_for_build_wheel(config_settings=None):
    check()
    return []   # nothing from an index


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    check()
    folder = Path(metadata_directory, dist_info_name())
    folder.mkdir(parents=True, exist_ok=True)
    for name, data in metadata_files().items():
        (folder / name).write_bytes(data)
    return folder.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    found = check()
    cmake_dir = build(found)
    package = cmake_dir / "python" / "asperity"
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    modules = sorted(package.glob("_asperity*"))
    if [module.name for module in modules] != ["_asperity" + suffix]:
        raise SystemExit(f"asperity: expected the module _asperity{suffix} in {package}, found {modules}")
    files = {f"asperity/{path.name}": path for path in sorted(package.iterdir()) if path.is_file()}
    files[f"asperity/{TABLE_NAME}"] = cmake_dir / "tables" / TABLE_NAME
    info = dist_info_name()
    name = f"{NAME}-{version()}-{wheel_tag()}.whl"
    Path(wheel_directory).mkdir(parents=True, exist_ok=True)
    record = []
    with zipfile.ZipFile(Path(wheel_directory, name), "w") as wheel:
        entries = [(path, source.read_bytes()) for path, source in files.items()]
        entries += [(f"{info}/{meta}", data) for meta, data in metadata_files().items()]
        for path, data in entries:
            entry = zipfile.ZipInfo(path, date_time=(1980, 1, 1, 0, 0, 0))
            entry.external_attr = (0o755 if path.endswith(suffix) else 0o644) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data, compresslevel=1)
            record.append(f"{path},{_record_hash(data)},{len(data)}")
        record.append(f"{info}/RECORD,,")
        entry = zipfile.ZipInfo(f"{info}/RECORD", date_time=(1980, 1, 1, 0, 0, 0))
        entry.external_attr = 0o644 << 16
        wheel.writestr(entry, "\n".join(record) + "\n", compress_type=zipfile.ZIP_DEFLATED)
    return name


def build_sdist(sdist_directory, config_settings=None):
    """The source tree as git tracks it (git archive), for `python -m build` or `pip download`."""
    base = f"{NAME}-{version()}"
    Path(sdist_directory).mkdir(parents=True, exist_ok=True)
    subprocess.run(["git", "-C", str(SOURCE), "archive", "--format=tar.gz", f"--prefix={base}/",
                    "-o", str(Path(sdist_directory, base + ".tar.gz").resolve()), "HEAD"], check=True)
    return base + ".tar.gz"


if __name__ == "__main__":
    # `python python/packaging/asperity_build.py`: what this interpreter lacks, or "ready"
    check()
    print(f"asperity: {sys.executable} has what `pip install .` needs")
