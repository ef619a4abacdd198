"""The installed Python module, imported from the installed tree only: the package and the
default table both come from PREFIX, and a value matches the closed form J_0 = exp(-s^a).
usage: check_installed.py PREFIX SURFACE.x3p"""
import math
import os
import sys

import numpy as np

import asperity

prefix = os.path.realpath(sys.argv[1])
package = os.path.realpath(asperity.__file__)
table_path = os.path.realpath(asperity.Table.default_path())
print(f"asperity {asperity.__version__} from {package}\ntable {table_path}")
assert package.startswith(prefix + os.sep), "the package is not the installed one"
from asperity import batch  # noqa: E402 (pure Python, installed beside the extension)
assert os.path.realpath(batch.__file__).startswith(prefix + os.sep), "asperity.batch is not the installed one"
assert table_path.startswith(prefix + os.sep), "the default table is not the installed one"
curve = asperity.Table.open_default().curve("weibull", "tail", 2.5)
s = np.linspace(0.0, 3.0, 7)
values = curve.value(0, s)
expected = np.exp(-s ** 2.5)
print("J_0:", values)
assert np.all(np.abs(values - expected) <= 1e-12 * expected)
try:
    curve.value(7, 1.0)
    sys.exit("a bad order was accepted")
except ValueError as error:
    print("expected error:", error)

# asperity.topography from the installed tree: a measured surface (argv[2]), and a report with its
# plots (drawn by the library)
import tempfile  # noqa: E402

from asperity import topography  # noqa: E402

surface = topography.read_height_map(sys.argv[2])
print(f"{sys.argv[2]}: heights {surface.heights.shape}, dx {surface.dx:.4g} m")
assert surface.heights.shape == (650, 650)
field = topography.gaussian_random_field(64, 64, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e-16)], seed=1)
analysis = topography.analyse_height_map(field, assessment=topography.AssessmentOptions(bootstrap=0), fit_heights=False)
with tempfile.TemporaryDirectory() as directory:
    outcome = analysis.write_report(directory)
print("report plots:", outcome.plots, outcome.plot_note)
assert outcome.plots, outcome.plot_note
