"""Run by pip_install.sh with the interpreter a `pip install .` put asperity under, from a folder
outside the source and build trees: the package imports from PLACE, carries its own default
table and compiled module, and answers against a closed form. usage: check_pip_install.py PLACE

`check_pip_install.py --prerequisites BACKEND_DIR`: the build backend's lines for what is missing
(python/packaging/asperity_build.py's missing()), one plain line each, naming the interpreter."""
import math
import sys
import warnings
from pathlib import Path

if sys.argv[1] == "--prerequisites":
    sys.path.insert(0, sys.argv[2])
    sys.dont_write_bytecode = True   # nothing left in the source tree
    import asperity_build  # noqa: E402

    python = "/opt/python/bin/python3"
    everything = asperity_build.missing({}, python, (3, 8), None, False, pybind11_dirs=())
    expected = [f"asperity needs Python 3.9 or later, not 3.8 ({python})",
                f"asperity needs numpy for {python}: install python3-numpy (Debian) or `{python} -m pip install numpy`",
                f"asperity needs pybind11 to build for {python}: install pybind11-dev (Debian) "
                f"or `{python} -m pip install pybind11`",
                f"asperity needs Python's headers (Python.h) to build for {python}: install python3-dev (Debian)",
                "asperity needs CMake to build: install cmake (Debian; scripts/setup.sh installs every C++ dependency)"]
    assert everything == expected, everything
    found = {"numpy": "1.24", "pybind11": "/x/share/cmake/pybind11"}
    assert asperity_build.missing(found, python, (3, 9), "/usr/bin/cmake", True, pybind11_dirs=()) == []
    # pybind11's CMake package without the Python package (Debian's pybind11-dev), or named to CMake
    assert asperity_build.missing({"numpy": "1.24"}, python, (3, 13), "cmake", True,
                                  pybind11_dirs=(sys.argv[2],), cmake_args="") != []
    assert asperity_build.missing({"numpy": "1.24"}, python, (3, 13), "cmake", True,
                                  pybind11_dirs=(), cmake_args="-Dpybind11_DIR=/x") == []
    print("the backend names what is missing:", *everything, sep="\n  ")
    sys.exit(0)

place = Path(sys.argv[1]).resolve()
import asperity  # noqa: E402

package = Path(asperity.__file__).resolve().parent
assert place in package.parents, f"asperity imported from {package}, not under {place}"
assert Path(asperity._asperity.__file__).resolve().parent == package, asperity._asperity.__file__
table_path = Path(asperity.Table.default_path()).resolve()
assert table_path == package / "asperity-default.h5", f"the default table is {table_path}, not the package's"
for stub in ("__init__.pyi", "plot.pyi", "topography.pyi", "py.typed"):
    assert (package / stub).is_file(), stub

table = asperity.Table.open_default()
curve = table.curve("weibull", "tail", 2.0)
# Weibull a = 2, tail side: X_0(s) = exp(-s^2) for s >= 0 (docs/model.md section 5)
for s in (0.25, 0.5, 1.0, 2.0):
    value = curve.value("count", s)
    assert abs(value - math.exp(-s * s)) <= 1e-12 * math.exp(-s * s), (s, value)
model = asperity.ContactModel(table, asperity.RoughSurface(
    "gaussian", shape=None, rms=5e-7, summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4,
    contact_modulus=1.15e11))
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    model.at_real_area(0.5 * model.surface.nominal_area)
assert any(issubclass(w.category, asperity.AreaFractionWarning) for w in caught)
import asperity.plot  # noqa: E402,F401 (matplotlib only when it draws)
import asperity.topography  # noqa: E402,F401
print(f"asperity {asperity.__version__} from {package} ({sys.executable}), table {table_path}: X_0 = exp(-s^2) to 1e-12")
