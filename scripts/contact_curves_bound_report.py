#!/usr/bin/env python3
"""Whether a measured surface's contact-curves table bounds its own error (issue 42, item 4):
the AFM map of tests/data/surfaces (256 x 256, leveled, E* = 1e11 Pa, defaults: periodic,
Fourier, tolerance 1e-8) tabulated from 1e6 to 1e8 Pa, its served pressure, stiffness and area
fraction compared with direct solves (a fresh solver) at PER points an interval in ln p,
(j + 0.382)/PER (none at a node or check), against the bound each way of measuring it stores
(the nodes, and so the curves served, are the same each way):

  one check     the former method, emulated here: one solve an interval at its geometric-mean
                pressure, the largest error times 2
  5 checks      write_table(..., max_checks=5): the two estimates only (2, then 5 an interval)
  settled       write_table(...) as the command writes it: finer where the estimates differ by
                more than 1.25x, at most 47 checks an interval

Writes docs/exact-contact-table-bound.svg/.png and prints the table of docs/exact-contact.md
("The stored bound, measured"). Usage: contact_curves_bound_report.py BUILD_DIR [PER] (PER
default 16; the docs' figures: 16)
"""
import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from report_style import plt, save  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
BUILD = Path(sys.argv[1]).resolve()
PER = int(sys.argv[2]) if len(sys.argv) > 2 else 16
sys.path.insert(0, str(BUILD / "python"))
import asperity  # noqa: E402
from asperity import topography as topo  # noqa: E402

MAP = REPO / "tests/data/surfaces/afm-zsensor-10um.txt"
MODULUS = 1e11
QUANTITIES = ("pressure", "stiffness", "area fraction")


def afm_map():
    height_map = topo.read_height_map(str(MAP))
    topo.subtract_plane(height_map, topo.fit_plane(height_map))  # as asperity exact-contact does
    return height_map


def solver():
    return topo.ExactContact(afm_map(), contact_modulus=MODULUS, threads=1)


def errors_at(curves, step):
    u = step.mean_gap
    return (abs(float(curves.pressure(u)) / step.pressure - 1),
            abs(float(curves.stiffness(u)) / step.stiffness_per_area - 1),
            abs(float(curves.area_fraction(u)) / step.area_fraction - 1))


def table(path, pressures, **options):
    started = time.process_time()
    solver().write_table(str(path), pressures, overwrite=True, **options)
    return asperity.ContactCurves(str(path)), time.process_time() - started


def direct(curves, fresh):
    """Errors at PER points an interval, (j + 0.382)/PER in ln p (never a multiple of 1/(3 2^L): a check)."""
    nodes = np.sort(np.asarray(curves.nodes["pressure"]))
    rows = []
    for low, high in zip(nodes[:-1], nodes[1:]):
        for j in range(PER):
            t = (j + 0.382) / PER
            step = fresh.at_pressure(math.exp((1 - t) * math.log(low) + t * math.log(high)))
            rows.append((step.pressure,) + errors_at(curves, step))
    return np.array(rows)


def one_check_bound(curves, fresh):
    """The former method: one solve at each interval's geometric-mean pressure, times 2."""
    nodes = np.sort(np.asarray(curves.nodes["pressure"]))
    worst = np.zeros(3)
    for low, high in zip(nodes[:-1], nodes[1:]):
        worst = np.maximum(worst, errors_at(curves, fresh.at_pressure(math.sqrt(low * high))))
    return 2 * worst, len(nodes) - 1


def main():
    fresh = solver()
    rows, series = [], {}
    with tempfile.TemporaryDirectory() as folder:
        for count in (9, 17):
            pressures = list(1e6 * 10 ** (2 * np.arange(count) / (count - 1)))
            five, cpu_five = table(Path(folder) / f"five-{count}.h5", pressures, max_checks=5)
            settled, cpu_settled = table(Path(folder) / f"settled-{count}.h5", pressures)
            old_bound, old_checks = one_check_bound(settled, fresh)
            at = direct(settled, fresh)  # the same curves each way: the same nodes
            worst = at[:, 1:].max(axis=0)
            for name, bound, checks, cpu in (("one check (former)", old_bound, old_checks, None),
                                             ("5 checks", np.array(five.max_rel_error), five.check_points, cpu_five),
                                             ("settled (default)", np.array(settled.max_rel_error),
                                              settled.check_points, cpu_settled)):
                rows.append((count, name, checks, bound, worst, cpu))
            series[count] = (at, old_bound, np.array(five.max_rel_error), np.array(settled.max_rel_error),
                             np.sort(np.asarray(settled.nodes["pressure"])), settled.check_points)
    print(f"direct solves: {PER} an interval, at (j + 0.382)/{PER} in ln p\n")
    print("| nodes | bound measured by | checks | stored bound p / k / a | largest error at the direct solves "
          "p / k / a | within? | CPU to write |")
    print("|---|---|---|---|---|---|---|")
    for count, name, checks, bound, worst, cpu in rows:
        within = "yes" if np.all(worst <= bound) else "**no**: " + ", ".join(
            f"{q} {w / b:.2f}x" for q, w, b in zip(("p", "k", "a"), worst, bound) if w > b)
        print(f"| {count} | {name} | {checks} | " + " / ".join(f"{b:.3g}" for b in bound) + " | " +
              " / ".join(f"{w:.3g}" for w in worst) + f" | {within} | " + ("" if cpu is None else f"{cpu:.1f} s") +
              " |")
    figure(series[9])


def figure(data):
    at, old_bound, five_bound, settled_bound, nodes, checks = data
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharex=True)
    for k, ax in enumerate(axes):
        ax.loglog(at[:, 0], at[:, k + 1], ".", ms=3, color="C0", label="served vs direct solve")
        ax.axhline(old_bound[k], color="C3", ls="--", lw=1, label="stored: one check an interval (former)")
        ax.axhline(five_bound[k], color="0.4", ls=":", lw=1, label="stored: 2 then 5 checks")
        ax.axhline(settled_bound[k], color="C0", ls="-", lw=1, label=f"stored: until settled ({checks} checks)")
        for p in nodes:
            ax.axvline(p, color="0.85", lw=0.6, zorder=0)
        ax.set_title(QUANTITIES[k])
        ax.set_xlabel("nominal pressure [Pa]")
        ax.set_ylim(1e-5, 1)
    axes[0].set_ylabel("relative error of the served curve")
    axes[0].legend(loc="lower left")
    fig.suptitle("AFM map 256 x 256, E* = 1e11 Pa, 9 nodes from 1e6 to 1e8 Pa (grey lines)")
    fig.tight_layout()
    save(fig, REPO / "docs", "exact-contact-table-bound")


if __name__ == "__main__":
    main()
