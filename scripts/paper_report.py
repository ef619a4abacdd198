#!/usr/bin/python3
"""examples/paper_data's CSV -> docs/paper_fig{1,2,3}.svg/.png and the claims table of docs/paper.md.

usage: paper_report.py DATA_DIR DOCS_DIR
"""
import csv
import math
import re
import sys
from collections import defaultdict
from pathlib import Path

from report_style import plt, save

# The normalization, said once under the figures that use it.
SCALES = (r"$A_0^g = \sqrt{\pi/2}\,N R \sigma$ and $P_0^g = \frac{4}{3\sqrt{2\pi}}\,N E^* R^{1/2} \sigma^{3/2}$:"
          r" the Gaussian model's area and load scales ($\sigma$ the rms summit height, $N$ summits of radius $R$,"
          r" $E^*$ the contact modulus).")
SEPARATION = (r"$t = (s - \mu_a)/c_a$: the separation from the mean summit height in rms units"
              r" ($\mu_a$, $c_a$: mean and rms of the Weibull heights of unit scale; the Gaussian: $t = s$).")

STYLE = {"Weibull a = 1": ("tab:blue", "-"), "Weibull a = 2": ("tab:orange", "-"),
         "Weibull a = 3": ("tab:green", "-"), "Weibull a = 5": ("tab:red", "-"),
         "Gaussian (McCool)": ("black", "--")}


def curves(path):
    families = defaultdict(lambda: defaultdict(list))
    with open(path) as handle:
        for row in csv.DictReader(handle):
            family = families[row["family"]]
            for key in ("t", "s", "area", "load", "stiffness_over_load"):
                family[key].append(float(row[key]))
    return families


def finish(figure, docs, name, notes):
    """Notes under the panels (what the axes' symbols mean), then the files."""
    figure.text(0.01, 0.01, "\n".join(notes), fontsize=8.5, va="bottom", ha="left")
    figure.tight_layout(rect=(0, 0.04 + 0.035 * len(notes), 1, 1))
    save(figure, docs, name, dpi=110)


def main():
    data, docs = Path(sys.argv[1]), Path(sys.argv[2])
    tail, bounded = curves(data / "paper_tail.csv"), curves(data / "paper_bounded.csv")
    gaussian = tail["Gaussian (McCool)"]
    p_at_zero = gaussian["load"][min(range(len(gaussian["t"])), key=lambda i: abs(gaussian["t"][i]))]

    # Fig. 1: tail side
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    for name, family in tail.items():
        colour, dash = STYLE[name]
        keep = [i for i, p in enumerate(family["load"]) if 1e-8 < p < 10]
        left.loglog([family["load"][i] for i in keep], [family["area"][i] for i in keep], dash, color=colour, label=name)
        right.semilogy(family["t"], family["load"], dash, color=colour, label=name)
    ts = [i * 0.05 for i in range(0, 91)]
    for beta, dash in ((0.5, ":"), (1.0, "-.")):
        right.semilogy(ts, [p_at_zero * math.exp(-t / beta) for t in ts], dash, color="gray",
                       label=rf"Persson, $\beta$ = {beta} (through the Gaussian at $t$ = 0)")
    left.set_xlabel(r"load  $P/P_0^g$")
    left.set_ylabel(r"real area  $A/A_0^g$")
    left.set_title("Fig. 1a  area-load, tail side")
    right.set_xlabel(r"separation from the mean summit height  $t$   [rms units]")
    right.set_ylabel(r"load  $P/P_0^g$")
    right.set_ylim(1e-8, 10)
    right.set_xlim(-1, 4.5)
    right.set_title("Fig. 1b  load-separation, tail side")
    for axis in (left, right):
        axis.legend()
    finish(figure, docs, "paper_fig1", [SCALES, SEPARATION])

    # Fig. 2: bounded side
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    for name, family in bounded.items():
        colour, dash = STYLE[name]
        keep = [i for i, p in enumerate(family["load"]) if 1e-10 < p]
        left.loglog([family["load"][i] for i in keep], [family["area"][i] for i in keep], dash, color=colour, label=name)
        right.semilogy(family["t"], family["load"], dash, color=colour, label=name)
    left.set_xlabel(r"load  $P/P_0^g$")
    left.set_ylabel(r"real area  $A/A_0^g$")
    left.set_title("Fig. 2a  area-load, bounded side")
    right.set_xlabel(r"separation from first contact  $s/c_a$   [rms units; $< 0$ in contact]")
    right.set_ylabel(r"load  $P/P_0^g$")
    right.set_xlim(-3, 0)
    right.set_ylim(1e-10, 100)
    right.set_title("Fig. 2b  load-separation, bounded side")
    for axis in (left, right):
        axis.legend()
    finish(figure, docs, "paper_fig2",
           [SCALES, r"$s$: the separation from the highest summit (first contact) in units of the Weibull scale;"
                    r" $c_a$: the rms of the Weibull heights of unit scale."])

    # Fig. 3: stiffness / load
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    for name, family in tail.items():
        colour, dash = STYLE[name]
        left.plot(family["t"], family["stiffness_over_load"], dash, color=colour, label=name,
                  linewidth=2.5 if name == "Weibull a = 1" else 1.5)
    left.plot(ts, [0.92 * (1 + t) for t in ts], ":", color="black", label=r"paper: $0.92\,(1 + t)$")
    for beta in (0.5, 1.0):
        left.axhline(1 / beta, color="gray", linestyle="-." if beta == 1 else ":", label=rf"Persson $1/\beta$, $\beta$ = {beta}")
    left.set_xlabel(r"separation from the mean summit height  $t$   [rms units]")
    left.set_ylabel(r"stiffness / load  $-(dP/dt)\,/\,P$")
    left.set_xlim(-1, 4.5)
    left.set_ylim(0, 6)
    left.set_title("Fig. 3a  stiffness/load, tail side")
    for name, family in bounded.items():
        colour, dash = STYLE[name]
        right.loglog([-t for t in family["t"]], family["stiffness_over_load"], dash, color=colour, label=name)
    right.axhline(1, color="gray", linestyle=":", label="1")
    right.set_xlabel(r"distance from first contact  $-s/c_a$   [rms units]")
    right.set_ylabel(r"stiffness / load  $-(dP/dt)\,/\,P$")
    right.set_title("Fig. 3b  stiffness/load, bounded side (infinite at first contact)")
    for axis in (left, right):
        axis.legend()
    finish(figure, docs, "paper_fig3",
           [SEPARATION, r"The stiffness/load ratio is in the same rms units: $-(dP/dt)/P = (3/2)\,c_a X_{1/2}/X_{3/2}$;"
                        r" on the bounded side $t$ is $s/c_a$ (zero at first contact)."])

    # the claims
    claims = defaultdict(list)
    with open(data / "paper_claims.csv") as handle:
        for row in csv.DictReader(handle):
            claims[row["claim"]].append((float(row["at"]), float(row["engine"]), float(row["paper"]) if row["paper"] else None))
    lines = []
    def table(title, key, paper_label):
        lines.append(f"**{title}**\n")
        lines.append(f"| t | engine | {paper_label} | paper's error |")
        lines.append("|---:|---:|---:|---:|")
        for at, engine, paper in claims[key]:
            lines.append(f"| {at:g} | {engine:.4f} | {paper:.4f} | {100 * (paper - engine) / engine:+.1f}% |")
        lines.append("")
    table("Gaussian stiffness/load, -F'_3/2 / F_3/2 = (3/2) F_1/2 / F_3/2, against the paper's 0.92 (1 + t)",
          "stiffness_load_gaussian", "0.92 (1 + t)")
    table("Its large-t asymptote t (the paper's 'between 1 and 3' for t = 1..3)", "asymptotic_t", "t")
    table("Gaussian area/load ratio F_1 / F_3/2 against the paper's 1 + 0.148 t", "area_load_gaussian", "1 + 0.148 t")
    lines.append("**Weibull tail side: stiffness/load in rms units, against Persson's 1/beta (1 to 2)**\n")
    lines.append("| t | a = 1 | a = 2 | a = 3 | a = 5 | Gaussian |")
    lines.append("|---:|---:|---:|---:|---:|---:|")
    gauss = {at: engine for at, engine, _ in claims["stiffness_load_gaussian"]}
    for index, t in enumerate((0.0, 1.0, 2.0, 3.0)):
        cells = [f"{claims[f'stiffness_load_weibull_a{a}'][index][1]:.3f}" for a in ("1", "2", "3", "5")]
        gaussian_cell = f"{gauss[t]:.3f}" if t in gauss else "-"
        lines.append(f"| {t:g} | " + " | ".join(cells) + f" | {gaussian_cell} |")
    lines.append("")
    for side in ("tail", "bounded"):
        lines.append(f"**Area at a given load, {side} side: A/A0^g at P/P0^g**\n")
        shapes = ["1", "2", "3", "5"] + (["0"] if side == "tail" else [])
        header = " | ".join("Gaussian" if a == "0" else f"a = {a}" for a in shapes)
        lines.append(f"| P/P0^g | {header} | spread (max/min) |")
        lines.append("|---:|" + "---:|" * (len(shapes) + 1))
        for index, target in enumerate((1e-4, 1e-3, 1e-2, 1e-1)):
            values = [claims[f"area_at_load_{side}_a{a}"][index][1] for a in shapes]
            lines.append(f"| {target:g} | " + " | ".join(f"{v:.3g}" for v in values) + f" | {max(values) / min(values):.2f} |")
        lines.append("")
    lines.append("**Bounded side near first contact: stiffness/load against its limit (3/2 + a)/|t|**\n")
    lines.append("| a | t | engine | (3/2 + a)/abs(t) |")
    lines.append("|---:|---:|---:|---:|")
    for a in ("1", "2", "5"):
        for at, engine, limit in claims[f"bounded_stiffness_load_a{a}"]:
            lines.append(f"| {a} | {at:g} | {engine:.4g} | {limit:.4g} |")
    lines.append("")
    page = docs / "paper.md"
    text = page.read_text()
    text = re.sub(r"<!-- claims:begin -->.*<!-- claims:end -->",
                  "<!-- claims:begin -->\n" + "\n".join(lines) + "\n<!-- claims:end -->", text, flags=re.S)
    page.write_text(text)


if __name__ == "__main__":
    main()
