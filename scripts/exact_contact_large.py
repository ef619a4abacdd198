#!/usr/bin/python3
"""The exact contact on large maps (docs/exact-contact.md, "Large maps"; issue 42, item 3).

For each size N (default 512 1024 2048 4096 8192) a periodic self-affine map of N x N points
(H 0.8, roll-off at a quarter of the map, cutoff at 4 pixels, rms height 1 um on 1 mm: the
surface of build/bench/exact_contact_bench) is written once as a .gsf file under CACHE, then
`build/asperity exact-contact MAP --modulus 1e11 --pressure P` runs under /usr/bin/time -v at
P = 0.02 E* h'_rms (about 5% of the map in contact), one step from no contact (the cold start a
single command makes), the default solver or another given by --solver. Printed per run, as a
Markdown row: the wall and CPU time of the whole command (reading the map, setting up, the step
and its stiffness), the peak resident memory, the solver's estimate (from its refusal under
--max-memory 1, before allocating), the area fraction, the iterations (constrained + stiffness)
and the load average before it ran.

  /usr/bin/python3 scripts/exact_contact_large.py build [--sizes 512 1024] [--solver polonsky-keer]
      [--cache /tmp/asperity-large-maps] [--extra=--no-coarse-start]

Needs the Python module (PYTHONPATH=build/python) to write the maps.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time


def make_map(cache, n):
    path = os.path.join(cache, f"self-affine-{n}.gsf")
    if not os.path.exists(path):
        from asperity import topography

        side = 1e-3
        surface = topography.self_affine_surface(n, n, side / n, side / n, hurst=0.8, rolloff_wavelength=side / 4,
                                                 cutoff_wavelength=4 * side / n, rms_height=1e-6, seed=1)
        topography.write_gsf(surface, path)
    return path


def rms_gradient(path):
    from asperity import topography

    return topography.spectral_rms_gradient(topography.read_height_map(path))


def time_v(text, key):
    match = re.search(re.escape(key) + r":\s*(.+)", text)
    return match.group(1).strip() if match else ""


def wall_seconds(text):
    value = time_v(text, "Elapsed (wall clock) time (h:mm:ss or m:ss)")
    parts = [float(p) for p in value.split(":")]
    seconds = 0.0
    for p in parts:
        seconds = seconds * 60 + p
    return seconds


def estimate(build, path, extra):
    """The solver's memory estimate [GB], from its refusal under --max-memory 1 (before allocating)."""
    done = subprocess.run([os.path.join(build, "asperity"), "exact-contact", path, "--modulus", "1e11", "--pressure", "1",
                           "--max-memory", "1"] + extra, capture_output=True, text=True)
    match = re.search(r"needs about ([0-9.]+) (kB|MB|GB|TB)", done.stderr)
    if not match:
        return None
    return float(match.group(1)) * {"kB": 1e-6, "MB": 1e-3, "GB": 1.0, "TB": 1e3}[match.group(2)]


def run(build, path, pressure, solver, extra):
    command = ["/usr/bin/time", "-v", os.path.join(build, "asperity"), "exact-contact", path, "--modulus", "1e11",
               "--pressure", repr(pressure), "--solver", solver, "--json"] + extra
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        return {"error": done.stderr.strip().splitlines()[-3:], "load": load}
    document = json.loads(done.stdout)
    step = document["steps"][0]
    return {
        "load": load,
        "wall": wall_seconds(done.stderr),
        "cpu": float(time_v(done.stderr, "User time (seconds)")) + float(time_v(done.stderr, "System time (seconds)")),
        "rss_gb": float(time_v(done.stderr, "Maximum resident set size (kbytes)")) * 1024 / 1e9,
        "estimate": estimate(build, path, extra),
        "iterations": step["iterations"],
        "stiffness_iterations": step["stiffness_iterations"],
        "area_fraction": step["area_fraction"],
        "command": " ".join(["asperity exact-contact", os.path.basename(path), "--modulus 1e11", f"--pressure {pressure:.4g}",
                             "--solver", solver] + extra),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--sizes", type=int, nargs="+", default=[512, 1024, 2048, 4096, 8192])
    parser.add_argument("--solver", default="preconditioned")
    parser.add_argument("--cache", default="/tmp/asperity-large-maps")
    parser.add_argument("--extra", default="", help="more options for asperity exact-contact, one string")
    args = parser.parse_args()
    os.makedirs(args.cache, exist_ok=True)
    extra = args.extra.split()
    print("| map | solver | load average before | wall s | CPU s | peak RSS GB | estimate GB | area fraction | "
          "iterations (constrained + stiffness) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in args.sizes:
        path = make_map(args.cache, n)
        pressure = 0.02 * 1e11 * rms_gradient(path)
        started = time.time()
        r = run(args.build, path, pressure, args.solver, extra)
        label = args.solver + (" " + args.extra if args.extra else "")
        if "error" in r:
            print(f"| {n}^2 | {label} | {r['load']} | failed after {time.time() - started:.0f} s: {' '.join(r['error'])} |")
        else:
            estimate = f"{r['estimate']:.3g}" if r["estimate"] else ""
            print(f"| {n}^2 | {label} | {r['load']} | {r['wall']:.1f} | {r['cpu']:.1f} | {r['rss_gb']:.2f} | {estimate} | "
                  f"{r['area_fraction']:.4f} | {r['iterations']} + {r['stiffness_iterations']} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
