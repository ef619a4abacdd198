#!/usr/bin/python3
"""Plots of an `asperity surface --report DIR` report: DIR/fits.svg|png and DIR/contact.svg|png.

usage: surface_plots.py DIR      (reads DIR/report.json and DIR/summits.csv; installs nothing)
Exit status 3 when matplotlib is missing (the report says so), 2 on bad input.
SVGs are byte-reproducible (fixed hash salt, no date).
"""
import csv
import json
import math
import sys
from pathlib import Path
from statistics import NormalDist

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("surface_plots.py: matplotlib is missing (Debian: apt-get install python3-matplotlib)", file=sys.stderr)
    sys.exit(3)

matplotlib.rcParams["svg.hashsalt"] = "asperity-surface"
COLOURS = {"gaussian-moments": "0.55", "gaussian": "black", "weibull-tail": "tab:blue", "weibull-bounded": "tab:red"}
LABELS = {"gaussian-moments": "Gaussian from m0, m2, m4 (Nayak-McCool)", "gaussian": "Gaussian fit",
          "weibull-tail": "Weibull, tail up", "weibull-bounded": "Weibull mirrored (bounded)"}


def pdf(model, x):
    loc, scale, shape = model["location_m"], model["scale_m"], model["shape"]
    if model["model"] == "gaussian":
        z = (x - loc) / scale
        return math.exp(-0.5 * z * z) / (scale * math.sqrt(2 * math.pi))
    w = (x - loc if model["model"] == "weibull-tail" else loc - x) / scale
    if w <= 0:
        return 0.0
    return shape / scale * w ** (shape - 1) * math.exp(-(w ** shape))


def quantile(model, p):
    loc, scale, shape = model["location_m"], model["scale_m"], model["shape"]
    if model["model"] == "gaussian":
        return loc + scale * NormalDist().inv_cdf(p)
    if model["model"] == "weibull-tail":
        return loc + scale * (-math.log1p(-p)) ** (1 / shape)
    return loc - scale * (-math.log(p)) ** (1 / shape)


def save(figure, directory, name):
    figure.tight_layout()
    figure.savefig(directory / f"{name}.svg", metadata={"Date": None})
    figure.savefig(directory / f"{name}.png", dpi=110, metadata={"Software": None})
    plt.close(figure)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    directory = Path(sys.argv[1])
    report = json.loads((directory / "report.json").read_text())
    with open(directory / "summits.csv", newline="") as stream:
        heights = sorted(float(row["height_m"]) for row in csv.DictReader(stream))
    sq = report["statistics"]["Sq_m"]
    unit, factor = ("nm", 1e9) if sq < 1e-6 else ("µm", 1e6)

    fits = report["fits"]
    panels = 3 if "heights" in fits else 2
    figure, axes = plt.subplots(1, panels, figsize=(5 * panels, 4.2))
    lo, hi = heights[0], heights[-1]
    pad = 0.15 * (hi - lo)
    grid = [lo - pad + (hi - lo + 2 * pad) * k / 400 for k in range(401)]
    axes[0].hist([h * factor for h in heights], bins=min(60, max(10, len(heights) // 25)), density=True, color="0.85",
                 edgecolor="0.6", label=f"summit heights (n = {len(heights)})")
    for model in fits["summit_heights"]["models"]:
        name = model["model"]
        p = model["anderson_darling_p"]
        axes[0].plot([x * factor for x in grid], [pdf(model, x) / factor for x in grid], color=COLOURS[name],
                     label=f"{LABELS[name]} (AD p = {p:.3g})" if p is not None else LABELS[name])
    axes[0].set_xlabel(f"summit height [{unit}]")
    axes[0].set_ylabel(f"density [1/{unit}]")
    axes[0].set_title("summit heights and the three fits", fontsize=10)
    axes[0].legend(fontsize=7)
    n = len(heights)
    probabilities = [(k + 0.5) / n for k in range(n)]
    for model in fits["summit_heights"]["models"]:
        name = model["model"]
        axes[1].plot([quantile(model, p) * factor for p in probabilities], [h * factor for h in heights], ".",
                     markersize=2.5, color=COLOURS[name], label=LABELS[name])
    axes[1].plot([lo * factor, hi * factor], [lo * factor, hi * factor], color="0.5", linewidth=0.8, linestyle="--")
    axes[1].set_xlabel(f"model quantile [{unit}]")
    axes[1].set_ylabel(f"observed summit height [{unit}]")
    axes[1].set_title("quantile-quantile: on the line = fits", fontsize=10)
    axes[1].legend(fontsize=7, markerscale=3)
    if panels == 3:
        histogram = report["height_histogram"]
        bins = histogram["density_per_m"]
        width = (histogram["hi_m"] - histogram["lo_m"]) / len(bins)
        centres = [histogram["lo_m"] + width * (k + 0.5) for k in range(len(bins))]
        axes[2].bar([c * factor for c in centres], [d / factor for d in bins], width=width * factor, color="0.85",
                    edgecolor="0.6", label="all heights")
        grid = [histogram["lo_m"] + (histogram["hi_m"] - histogram["lo_m"]) * k / 400 for k in range(401)]
        for model in fits["heights"]["models"]:
            name = model["model"]
            p = model["anderson_darling_p"]
            axes[2].plot([x * factor for x in grid], [pdf(model, x) / factor for x in grid], color=COLOURS[name],
                         label=f"{LABELS[name]} (AD p = {p:.3g})" if p is not None else LABELS[name])
        axes[2].set_xlabel(f"height [{unit}]")
        axes[2].set_ylabel(f"density [1/{unit}]")
        axes[2].set_title(f"heights (fits on n = {fits['heights']['n']}, thinned)", fontsize=10)
        axes[2].legend(fontsize=7)
    for axis in axes:
        axis.grid(True, alpha=0.3)
    save(figure, directory, "fits")

    contact = report.get("contact")
    if contact:
        figure, axes = plt.subplots(1, 3, figsize=(15, 4.2))
        for model in contact["models"]:
            if not model["served"]:
                continue
            name = model["model"]
            curve = model["curve"]
            pressure = [s["pressure_Pa"] for s in curve]
            axes[0].plot([s["mean_separation_m"] * factor for s in curve], pressure, color=COLOURS[name], label=LABELS[name])
            axes[1].plot(pressure, [s["area_fraction"] for s in curve], color=COLOURS[name], label=LABELS[name])
            axes[2].plot(pressure, [s["stiffness_N_per_m"] / contact["nominal_area_m2"] for s in curve],
                         color=COLOURS[name], label=LABELS[name])
        for p in contact["pressures_Pa"]:
            axes[1].axvline(p, color="0.7", linewidth=0.8, linestyle=":")
            axes[2].axvline(p, color="0.7", linewidth=0.8, linestyle=":")
            axes[0].axhline(p, color="0.7", linewidth=0.8, linestyle=":")
        axes[0].set_yscale("log")
        axes[0].set_xlabel(f"separation from the mean summit height [{unit}]")
        axes[0].set_ylabel("nominal pressure [Pa]")
        axes[0].set_title("load-separation", fontsize=10)
        for axis in axes[1:]:
            axis.set_xscale("log")
            axis.set_yscale("log")
            axis.set_xlabel("nominal pressure [Pa]")
        axes[1].set_ylabel("real area / nominal area")
        axes[1].set_title("area-load", fontsize=10)
        axes[2].set_ylabel("normal stiffness per nominal area [N/m³]")
        axes[2].set_title(f"stiffness-load (E* = {contact['contact_modulus_Pa']:.3g} Pa)", fontsize=10)
        for axis in axes:
            axis.grid(True, alpha=0.3, which="both")
            axis.legend(fontsize=7)
        save(figure, directory, "contact")
    return 0


if __name__ == "__main__":
    sys.exit(main())
