"""The installed Python module, imported from the installed tree only: the package and the
default table both come from PREFIX, and a value matches the closed form J_0 = exp(-s^a).
usage: check_installed.py PREFIX"""
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
