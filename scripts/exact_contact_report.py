#!/usr/bin/env python3
"""Measures the exact contact (topography/exact_contact.hpp) and refreshes the measured sections of
docs/exact-contact.md and its figures docs/exact-contact-*.svg/.png: the validations against
closed forms (Hertz, Westergaard, the self-affine area-load slope), the kernel's and the
boundary's effects, the two real maps of tests/data/surfaces solved beside the GW models of
`asperity surface`, every curve of `asperity surface --exact` against the exact one, Persson's
theory against the exact solution of self-affine surfaces, and the speed table from
exact_contact_bench's JSON.

Run by scripts/exact-contact-report.sh: exact_contact_report.py BUILD_DIR BENCH_JSON
"""
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from report_style import plt, save  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
BUILD = Path(sys.argv[1]).resolve()
BENCH = Path(sys.argv[2]) if len(sys.argv) > 2 else None
sys.path.insert(0, str(BUILD / "python"))
from asperity import topography as topo  # noqa: E402

DOCS = REPO / "docs"
ASPERITY = BUILD / "asperity"
MODULUS = 1e11
SURFACES = [("afm-zsensor-10um.txt", "AFM, 256 x 256, 10 um"), ("digitalsurf-650x650.x3p", "X3P, 650 x 650")]
CONFIGS = [("periodic", "fourier"), ("periodic", "love"), ("padded", "fourier"), ("padded", "love")]
MAP_PRESSURES = [1e5, 1e6, 1e7, 1e8]
sections = {}


def g(x, digits=3):
    return f"{x:.{digits}g}"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# ---- Hertz ----
def sphere(n, side, radius):
    c = (np.arange(n) + 0.5 - n / 2) * side / n
    return topo.HeightMap(-(c[None, :] ** 2 + c[:, None] ** 2) / (2 * radius), side / n, side / n)


def hertz():
    radius, side = 1e-2, 1e-3
    a = side / 5
    load = 4 * MODULUS * a ** 3 / (3 * radius)
    peak = 2 * MODULUS * a / (math.pi * radius)
    rows, errors = [], {}
    for kernel in ("love", "fourier"):
        for n in (32, 64, 128, 256, 512):
            solver = topo.ExactContact(sphere(n, side, radius), contact_modulus=MODULUS, boundary="padded", kernel=kernel)
            s = solver.at_pressure(load / side ** 2)
            e = (math.sqrt(s.real_area / math.pi) / a - 1, s.max_pressure / peak - 1,
                 s.approach_stiffness / (2 * MODULUS * a) - 1)
            errors.setdefault(kernel, []).append((a / (side / n), e))
            rows.append([kernel, n, g(a / (side / n)), f"{100 * e[0]:+.3f}", f"{100 * e[1]:+.4f}",
                         f"{100 * e[2]:+.3f}" if kernel == "love" else "(not free space)", s.iterations])
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for kernel, style in (("love", "-o"), ("fourier", "--s")):
        px = [p for p, _ in errors[kernel]]
        ax.loglog(px, [abs(e[0]) for _, e in errors[kernel]], style, label=f"contact radius ({kernel})")
        ax.loglog(px, [abs(e[1]) for _, e in errors[kernel]], style, label=f"peak pressure ({kernel})")
    ax.set_xlabel("pixels per contact radius")
    ax.set_ylabel("|relative error|")
    ax.set_title("Hertz, padded (non-periodic)")
    ax.legend()
    save(fig, DOCS, "exact-contact-hertz")
    sections["hertz"] = table(["kernel", "map", "pixels per radius", "radius error %", "peak pressure error %",
                               "stiffness 2E*a error %", "iterations"], rows)


# ---- Westergaard ----
def westergaard():
    nx, wavelength, amplitude = 512, 1e-3, 1e-6
    full = math.pi * MODULUS * amplitude / wavelength
    ratios = [0.003, 0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99]
    x = np.arange(nx) / nx
    surface = topo.HeightMap(np.tile(amplitude * np.cos(2 * math.pi * x), (4, 1)), wavelength / nx, wavelength / nx)
    rows, curves = [], {}
    for kernel in ("fourier", "love"):
        solver = topo.ExactContact(surface, contact_modulus=MODULUS, kernel=kernel, tolerance=1e-10)
        worst, ends = [0, 0, 0, 0], []
        for r in ratios:
            s = solver.at_pressure(r * full)
            area = 2 / math.pi * math.asin(math.sqrt(r))
            gap = 1 - r * (1 - math.log(r))
            stiffness = -full / (amplitude * math.log(r))
            curves.setdefault(kernel, []).append((r, s.area_fraction, s.mean_gap / amplitude))
            worst = [max(worst[0], abs(s.area_fraction - area) * nx), max(worst[1], abs(s.max_pressure / full - 2 * math.sqrt(r))),
                     max(worst[2], abs(s.mean_gap / amplitude - gap)),
                     max(worst[3], abs(s.stiffness_per_area / stiffness - 1)) if 0.01 <= r <= 0.95 else worst[3]]
            if r in (ratios[0], ratios[-1]):
                ends.append(f"{100 * (s.stiffness_per_area / stiffness - 1):+.1f}")
        s = solver.at_pressure(1.05 * full)
        rows.append([kernel, f"{worst[0]:.2f}", g(worst[1], 2), g(worst[2], 2), f"{100 * worst[3]:.2f}", " / ".join(ends),
                     f"{s.area_fraction:g}, {s.max_pressure / full:.7f}"])
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.6))
    fine = np.linspace(1e-4, 1, 400)
    left.plot(fine, 2 / np.pi * np.arcsin(np.sqrt(fine)), "k-", label="Westergaard")
    right.plot(fine, 1 - fine * (1 - np.log(fine)), "k-", label="Westergaard")
    for kernel, marker in (("fourier", "o"), ("love", "x")):
        c = np.array(curves[kernel])
        left.plot(c[:, 0], c[:, 1], marker, label=f"BEM {kernel}")
        right.plot(c[:, 0], c[:, 2], marker, label=f"BEM {kernel}")
    left.set_xlabel("p / p*")
    left.set_ylabel("contact area fraction")
    right.set_xlabel("p / p*")
    right.set_ylabel("mean gap / amplitude")
    left.legend()
    right.legend()
    fig.suptitle("Wavy surface, 512 points per wavelength, periodic")
    fig.tight_layout()
    save(fig, DOCS, "exact-contact-wavy")
    sections["wavy"] = table(["kernel", "area: largest error [pixels of width]", "peak pressure / p*: largest error",
                              "mean gap / g: largest error", "stiffness: largest error % (0.01 to 0.95)",
                              f"stiffness error % at {ratios[0]} / {ratios[-1]}",
                              "at 1.05 p*: area, peak / p* (exact 2.05)"], rows)


# ---- self-affine ----
def rough(n, rolloff, seed=1):
    return topo.self_affine_surface(n, n, 1e-3 / n, 1e-3 / n, hurst=0.8, rolloff_wavelength=1e-3 * rolloff,
                                    cutoff_wavelength=4e-3 / n, rms_height=1e-6, seed=seed)


def self_affine():
    loads = [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2]
    rows, curves, effects = [], {}, []
    for rolloff in (1 / 4, 1 / 8, 1 / 16):
        surface = rough(512, rolloff)
        gradient = topo.spectral_rms_gradient(surface)
        results = {}
        for boundary, kernel in (("periodic", "fourier"), ("periodic", "love")):
            solver = topo.ExactContact(surface, contact_modulus=MODULUS, kernel=kernel, stiffness=False)
            results[kernel] = [solver.at_pressure(p * MODULUS * gradient) for p in loads]
        fourier = results["fourier"]
        curves[rolloff] = [(p, s.area_fraction) for p, s in zip(loads, fourier)]
        i2, i5 = loads.index(0.02), loads.index(0.05)
        slope = (fourier[i5].area_fraction - fourier[i2].area_fraction) / (0.05 - 0.02)
        rows.append([f"L/{round(1 / rolloff)}", f"{512 * rolloff / 4:g}", g(gradient),
                     " / ".join(f"{s.area_fraction / p:.2f}" for p, s in zip(loads, fourier)), f"{slope:.3f}"])
        for p, f, lv in zip(loads, fourier, results["love"]):
            if p in (0.01, 0.05, 0.2):
                effects.append([f"L/{round(1 / rolloff)}", p, f"{f.area_fraction:.4f}", f"{lv.area_fraction:.4f}",
                                f"{100 * (lv.area_fraction / f.area_fraction - 1):+.2f}",
                                f"{100 * (lv.mean_gap / f.mean_gap - 1):+.2f}"])
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for rolloff, c in curves.items():
        c = np.array(c)
        ax.plot(c[:, 0], c[:, 1], "o-", label=f"roll-off L/{round(1 / rolloff)}")
    line = np.array([0, 0.2])
    ax.plot(line, 1.9 * line, "k:", label="kappa 1.9, 2.2")
    ax.plot(line, 2.2 * line, "k:")
    ax.set_xlabel("p / (E* h'_rms)")
    ax.set_ylabel("contact area fraction")
    ax.set_title("Self-affine H 0.8, 512^2, periodic, Fourier kernel")
    ax.legend()
    save(fig, DOCS, "exact-contact-self-affine")
    sections["kappa"] = table(["roll-off", "q_s / q_r", "h'_rms",
                               "A/A0 / (p/E*h') at p/(E*h') = " + ", ".join(str(p) for p in loads),
                               "slope 0.02 to 0.05"], rows)
    sections["kernel"] = table(["roll-off", "p/(E*h')", "area (fourier)", "area (love)", "love/fourier - 1: area %",
                                "mean gap %"], effects)


# ---- the real maps ----
def run(args):
    return subprocess.run([str(ASPERITY)] + args, check=True, capture_output=True, text=True).stdout


def real_maps():
    data = REPO / "tests" / "data" / "surfaces"
    effects, ratios, notes = [], [], []
    for name, label in SURFACES:
        path = str(data / name)
        exact = {}
        for boundary, kernel in CONFIGS:
            out = run(["exact-contact", path, "--modulus", str(MODULUS), "--sweep", "pressure:1e5:1e8:13", "--json",
                       "--boundary", boundary, "--kernel", kernel, "--quiet"])
            exact[(boundary, kernel)] = json.loads(out)
        gw = json.loads(run(["surface", path, "--modulus", str(MODULUS), "--pressure",
                             ",".join(f"{p:g}" for p in MAP_PRESSURES), "--bootstrap", "0", "--json"]))
        reference = exact[("periodic", "fourier")]
        summit = reference["map"]["mean_summit_height_m"]
        notes.append(f"{label}: rms height {g(reference['map']['rms_height_m'])} m, mean summit height "
                     f"{g(summit)} m above the mean plane ({reference['map']['summits']} summits), highest point "
                     f"{g(reference['map']['max_height_m'])} m")

        def at(config, pressure):
            steps = exact[config]["steps"]
            return min(steps, key=lambda s: abs(math.log(s["pressure_Pa"] / pressure)))

        for pressure in (1e6, 1e7, 1e8):
            base = at(("periodic", "fourier"), pressure)
            for config in CONFIGS[1:]:
                s = at(config, pressure)
                effects.append([label, g(pressure), f"{config[0]} {config[1]}",
                                f"{100 * (s['area_fraction'] / base['area_fraction'] - 1):+.1f}",
                                f"{100 * (s['mean_gap_m'] / base['mean_gap_m'] - 1):+.1f}",
                                f"{100 * (s['stiffness_per_area_N_per_m3'] / base['stiffness_per_area_N_per_m3'] - 1):+.1f}",
                                s["clusters"]])
        for k, pressure in enumerate(gw["contact"]["pressures_Pa"]):
            p_ref, f_ref = at(("periodic", "fourier"), pressure), at(("padded", "love"), pressure)
            ratios.append([label, g(pressure), "exact periodic / padded",
                           f"{1e9 * p_ref['separation_from_mean_summit_m']:.1f} / {1e9 * f_ref['separation_from_mean_summit_m']:.1f}",
                           f"{p_ref['area_fraction']:.3g} / {f_ref['area_fraction']:.3g}",
                           f"{p_ref['stiffness_per_area_N_per_m3']:.3g} / {f_ref['stiffness_per_area_N_per_m3']:.3g}"])
            for model in gw["contact"]["models"]:
                if not model["served"]:
                    continue
                m = model["at_pressures"][k]
                ratios.append([label, g(pressure), model["model"],
                               f"{1e9 * m['mean_separation_m']:.1f} ({1e9 * (m['mean_separation_m'] - p_ref['separation_from_mean_summit_m']):+.1f} / "
                               f"{1e9 * (m['mean_separation_m'] - f_ref['separation_from_mean_summit_m']):+.1f})",
                               f"{m['area_fraction']:.3g} ({m['area_fraction'] / p_ref['area_fraction']:.2f} / "
                               f"{m['area_fraction'] / f_ref['area_fraction']:.2f})",
                               f"{m['stiffness_per_area_N_per_m3']:.3g} ({m['stiffness_per_area_N_per_m3'] / p_ref['stiffness_per_area_N_per_m3']:.2f} / "
                               f"{m['stiffness_per_area_N_per_m3'] / f_ref['stiffness_per_area_N_per_m3']:.2f})"])
        # figure: load-separation, area-load, stiffness-load
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        for (boundary, kernel), style in zip(CONFIGS, ("k-", "k--", "b-.", "b-")):
            steps = exact[(boundary, kernel)]["steps"]
            p = [s["pressure_Pa"] for s in steps]
            lab = f"exact, {boundary} {kernel}"
            axes[0].semilogy([1e9 * s["separation_from_mean_summit_m"] for s in steps], p, style, label=lab)
            axes[1].loglog(p, [s["area_fraction"] for s in steps], style, label=lab)
            axes[2].loglog(p, [s["stiffness_per_area_N_per_m3"] for s in steps], style, label=lab)
        for model, colour in zip(gw["contact"]["models"], ("tab:orange", "tab:green", "tab:red", "tab:purple")):
            if not model["served"]:
                continue
            c = model["curve"]
            p = [s["pressure_Pa"] for s in c]
            axes[0].semilogy([1e9 * s["mean_separation_m"] for s in c], p, color=colour, label=f"GW {model['model']}")
            axes[1].loglog(p, [s["area_fraction"] for s in c], color=colour, label=f"GW {model['model']}")
            area = gw["contact"]["nominal_area_m2"]
            axes[2].loglog(p, [s["stiffness_N_per_m"] / area for s in c], color=colour, label=f"GW {model['model']}")
        axes[0].set_xlabel("separation from the mean summit height [nm]")
        axes[0].set_ylabel("nominal pressure [Pa]")
        axes[1].set_xlabel("nominal pressure [Pa]")
        axes[1].set_ylabel("real area fraction")
        axes[2].set_xlabel("nominal pressure [Pa]")
        axes[2].set_ylabel("stiffness per area [N/m^3]")
        for ax in axes:
            ax.set_xlim(*((None, None) if ax is axes[0] else (1e5, 1e8)))
        axes[0].set_ylim(1e5, 1e8)
        axes[2].legend(fontsize=7)
        fig.suptitle(f"{label}: exact contact (E* 1e11 Pa) and the GW models of asperity surface")
        fig.tight_layout()
        save(fig, DOCS, "exact-contact-" + name.split("-")[0])
    sections["maps-effects"] = table(["map", "pressure [Pa]", "solve", "area vs periodic fourier %",
                                      "mean gap %", "stiffness %", "clusters"], effects)
    sections["maps-ratios"] = "\n".join("- " + n for n in notes) + "\n\n" + table(
        ["map", "pressure [Pa]", "model", "separation from mean summit [nm] (model - exact periodic / padded)",
         "area fraction (model / exact periodic / padded)", "stiffness per area [N/m^3] (model / exact periodic / padded)"],
        ratios)


# ---- the surface report: every curve against the exact one; Persson against it ----
def surface_report():
    data = REPO / "tests" / "data" / "surfaces"
    rows = []
    for name, label in SURFACES:
        out = json.loads(run(["surface", str(data / name), "--modulus", str(MODULUS), "--pressure",
                              ",".join(f"{p:g}" for p in MAP_PRESSURES), "--ensemble", "0", "--no-height-fit",
                              "--exact", "--json"]))
        contact = out["contact"]
        for model in contact["models"]:
            if not model["served"] or model["model"] == "exact":
                continue
            at = model["at_pressures"]
            rows.append([label, model["model"],
                         " / ".join(f"{s['stiffness_over_exact']:.2f}" for s in at),
                         " / ".join(f"{s['area_over_exact']:.2f}" for s in at),
                         " / ".join(f"{1e9 * s['mean_separation_minus_exact_m']:+.0f}" for s in at)])
        rows.append([label, "closest: " + contact["references"]["closest_to_exact"], "", "", ""])
    # Persson against the exact solution of periodic self-affine surfaces (Fourier kernel: the
    # spectrum's own model)
    persson_rows = []
    for rolloff in (4, 16):
        surface = rough(512, 1 / rolloff)
        gradient = topo.spectral_rms_gradient(surface)
        theory = topo.PerssonContact(topo.radial_power_spectrum(surface, edges="none"), contact_modulus=MODULUS)
        solver = topo.ExactContact(surface, contact_modulus=MODULUS)
        for reduced in (0.005, 0.02, 0.05, 0.1):
            p = reduced * MODULUS * gradient
            e, t = solver.at_pressure(p), theory.at_pressure(p)
            persson_rows.append([f"L/{rolloff}", f"{reduced:g}", f"{e.area_fraction:.4f}",
                                 f"{t.area_fraction / e.area_fraction:.3f}", f"{t.mean_gap / e.mean_gap:.3f}",
                                 f"{t.stiffness_per_area / e.stiffness_per_area:.3f}"])
    sections["surface-report"] = table(
        ["map", "curve", "stiffness / exact at 1e5 / 1e6 / 1e7 / 1e8 Pa", "real area / exact",
         "mean separation - exact [nm]"], rows)
    sections["persson"] = table(["roll-off", "p/(E* h')", "exact area fraction", "Persson / exact: area",
                                 "mean gap", "stiffness"], persson_rows)


# ---- speed ----
def speed():
    if not BENCH or not BENCH.exists():
        return
    runs = json.loads(BENCH.read_text())
    rows, base = [], None
    for b in runs["benchmarks"]:
        name = b["name"].split("/iterations")[0]
        kind, n = name.split("/")
        n = int(n)
        grid = 2 * n if kind.startswith("padded") else n
        per = b["s_per_convolution"] / (grid * grid * math.log2(grid * grid))
        if kind == "periodic_fourier" and base is None:
            base = per
        rows.append([kind, f"{n}^2", f"{b['s_per_step']:.3f}", f"{b['cpu_s_per_step']:.3f}", f"{b['iterations_per_step']:.0f} + "
                     f"{b['stiffness_iterations_per_step']:.0f}", f"{b.get('coarse_iterations_per_step', 0):.0f}",
                     f"{1e3 * b['s_per_convolution']:.2f}",
                     f"{b['convolution_over_fft_pair']:.2f}", f"{per / base:.2f}", f"{b['s_setup']:.3f}"])
    sections["speed"] = (f"Machine: {runs['context'].get('num_cpus')} CPUs at {runs['context'].get('mhz_per_cpu')} MHz, "
                         f"load average {runs['context'].get('load_avg')} when it ran.\n\n") + table(
        ["solve", "map", "s per load step", "CPU s per step (all threads)", "iterations per step (constrained + stiffness)",
         "coarse start's iterations per step (all levels)", "ms per convolution", "convolution / FFT pair", "per convolution / (N log N), relative", "setup [s]"], rows)


def main():
    # PARTS=maps,speed (say) measures those parts only; the other sections keep their text
    parts = os.environ.get("PARTS", "hertz,wavy,self_affine,maps,report,speed").split(",")
    for name, part in (("hertz", hertz), ("wavy", westergaard), ("self_affine", self_affine), ("maps", real_maps),
                       ("report", surface_report), ("speed", speed)):
        if name in parts:
            part()
    page = DOCS / "exact-contact.md"
    text = page.read_text()
    for key, body in sections.items():
        text = re.sub(rf"<!-- {key}:begin -->.*?<!-- {key}:end -->",
                      lambda _: f"<!-- {key}:begin -->\n{body}\n<!-- {key}:end -->", text, flags=re.S)
    page.write_text(text)


if __name__ == "__main__":
    main()
