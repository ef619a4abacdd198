#!/usr/bin/python3
"""Python against C++ and against scipy.integrate.quad, in one run (README: "Python").

  numpy arrays through the module (curve.value(k, array)) on 1e6 random separations, against
  Curve::value_batch in C++ on the very same separations (python/bench/batch_reference, Google
  Benchmark), per element; a Python loop of scalar calls; and scipy.integrate.quad per point
  the way ContactMechanics computes these integrals (quad(lambda z: (z - h)**n * phi(z), h, inf)).
Rounds alternate between C++ and Python; the figures are medians over all of them, in CPU time
on both sides.

usage: PYTHONPATH=build/python python3 python/bench/bench_python.py [--build build] [--rounds 3]
"""
import argparse
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy.integrate import quad

import asperity

COUNT = 1_000_000


def cpu_name():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def per_call(function, number, repeat):
    """CPU seconds per call of function(), each sample the mean over `number` calls. CPU time, as
    Google Benchmark's items_per_second on the C++ side: on a shared, busy machine wall time
    counts the other processes' share too."""
    samples = []
    for _ in range(repeat):
        start = time.process_time()
        for _ in range(number):
            function()
        samples.append((time.process_time() - start) / number)
    return samples


def cxx_ns_per_element(binary, files, repetitions):
    """ns per element (CPU time) of Curve::value_batch, per benchmark, every repetition."""
    result = subprocess.run([str(binary), *map(str, files), f"--benchmark_repetitions={repetitions}",
                             "--benchmark_format=json", "--benchmark_min_time=0.5"],
                            check=True, capture_output=True, text=True)
    samples = {}
    for row in json.loads(result.stdout)["benchmarks"]:
        if row.get("run_type") == "iteration":
            samples.setdefault(row["run_name"], []).append(1e9 / row["items_per_second"])
    return samples


def quad_weibull(h, a, n):
    phi = lambda z: a * z ** (a - 1) * np.exp(-z ** a)  # noqa: E731
    value, _ = quad(lambda z: (z - h) ** n * phi(z), max(h, 0.0), np.inf)
    return value


def quad_gaussian(h, n):
    phi = lambda z: np.exp(-z ** 2 / 2) / (2 * np.pi) ** 0.5  # noqa: E731  (ContactMechanics' Fn)
    value, _ = quad(lambda z: (z - h) ** n * phi(z), h, np.inf)
    return value


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build", help="the build directory (default: build)")
    parser.add_argument("--rounds", type=int, default=3)
    options = parser.parse_args()
    binary = Path(options.build) / "python" / "bench" / "batch_reference"
    if not binary.exists():
        sys.exit(f"{binary} is missing: cmake --build {options.build} --target python_batch_reference")

    table = asperity.Table.open_default()
    weibull = table.curve("weibull", "tail", 2.0)
    gaussian = table.curve("gaussian", "tail")
    rng = np.random.default_rng(12345)
    cases = {   # name: (curve, twice_order, separations, quad per point)
        "weibull_a2_X3_2": (weibull, 3, rng.uniform(weibull.table_min_separation, weibull.table_max_separation, COUNT),
                            lambda h: quad_weibull(h, 2.0, 1.5)),
        "gaussian_F5_2": (gaussian, 5, rng.uniform(0.0, 4.0, COUNT), lambda h: quad_gaussian(h, 2.5)),
    }
    with tempfile.TemporaryDirectory() as folder:
        files = []
        for name, (_, _, separations, _) in cases.items():
            files.append(Path(folder) / f"{name}.f64")
            separations.astype(np.float64).tofile(files[-1])
        cxx = {name: [] for name in cases}
        numpy_path = {name: [] for name in cases}
        numpy_out = {name: [] for name in cases}
        for _ in range(options.rounds):
            for run_name, samples in cxx_ns_per_element(binary, files, 3).items():
                cxx[run_name.split("/", 1)[1]] += samples
            for name, (curve, order, separations, _) in cases.items():
                numpy_path[name] += [t / COUNT * 1e9 for t in per_call(lambda: curve.value(order, separations), 10, 3)]
                buffer = np.empty_like(separations)
                numpy_out[name] += [t / COUNT * 1e9
                                    for t in per_call(lambda: curve.value(order, separations, out=buffer), 10, 3)]

    scalar_loop, quad_point, quad_error = {}, {}, {}
    for name, (curve, order, separations, by_quad) in cases.items():
        points = [float(x) for x in separations[:100_000]]
        scalar_loop[name] = statistics.median(
            t / len(points) * 1e9 for t in per_call(lambda: [curve.value(order, x) for x in points], 1, 3))
        few = [float(x) for x in separations[:300]]
        quad_point[name] = statistics.median(
            t / len(few) * 1e9 for t in per_call(lambda: [by_quad(h) for h in few], 1, 3))
        ours = curve.value(order, np.array(few))
        theirs = np.array([by_quad(h) for h in few])
        keep = ours > 1e-300
        quad_error[name] = float(np.max(np.abs(theirs[keep] - ours[keep]) / ours[keep]))

    print(f"asperity {asperity.__version__}, Python {platform.python_version()}, numpy {np.__version__}; "
          f"{cpu_name()}, {os.cpu_count()} cores, batch kernel {asperity.best_instruction_set().name}; "
          f"{options.rounds} rounds, medians, CPU time\n")
    print("| per element, 1e6 random separations | Weibull a = 2, X_3/2 | Gaussian F_5/2, h in [0, 4) |")
    print("|---|---:|---:|")

    def row(label, values, reference=None, unit="ns"):
        cells = []
        for name in cases:
            value = values[name]
            text = f"{value / 1000:.1f} µs" if unit == "us" else f"{value:.1f} ns"
            if reference is not None:
                text += f" ({value / reference[name]:.2f}x)" if value / reference[name] < 100 else \
                        f" ({value / reference[name]:,.0f}x)"
            cells.append(text)
        print(f"| {label} | " + " | ".join(cells) + " |")

    cxx_median = {name: statistics.median(cxx[name]) for name in cases}
    numpy_median = {name: statistics.median(numpy_path[name]) for name in cases}
    row("C++ `Curve::value_batch`", cxx_median)
    row("Python `curve.value(k, array)` (x C++)", numpy_median, cxx_median)
    row("Python `curve.value(k, array, out=buffer)` (x C++)",
        {name: statistics.median(numpy_out[name]) for name in cases}, cxx_median)
    row("Python loop of `curve.value(k, x)` (x numpy path)", scalar_loop, numpy_median)
    row("`scipy.integrate.quad` per point, ContactMechanics' way (x numpy path)", quad_point, numpy_median, unit="us")
    print("\nquad against the table on 300 of the points (max relative difference): " +
          ", ".join(f"{name} {quad_error[name]:.1e}" for name in cases))


if __name__ == "__main__":
    main()
