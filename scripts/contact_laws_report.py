"""The figures and tables of docs/contact-laws.md from the CSV files of contact_law_curves
(scripts/contact-laws-report.sh). Python's standard library only: the figures are written as SVG
by hand (no matplotlib), the same bytes for the same data.

    contact_laws_report.py DATA_DIR DOCS_DIR
"""
import csv
import math
import pathlib
import re
import sys

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"]
DASHES = ["", "6,3", "2,2", "8,3,2,3"]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def nice_ticks(low, high, count=6):
    span = high - low
    step = 10 ** math.floor(math.log10(span / count))
    for m in (1, 2, 2.5, 5, 10):
        if span / (m * step) <= count:
            step *= m
            break
    first = math.ceil(low / step) * step
    ticks, t = [], first
    while t <= high + 1e-9 * step:
        ticks.append(round(t, 12))
        t += step
    return ticks


def label(value):
    if value == 0:
        return "0"
    if abs(value) >= 1e4 or abs(value) < 1e-3:
        exponent = math.floor(math.log10(abs(value)))
        mantissa = value / 10 ** exponent
        return f"1e{exponent}" if abs(mantissa - 1) < 1e-9 else f"{mantissa:g}e{exponent}"
    return f"{value:g}"


def plot(path, series, xlabel, ylabel, title, xlog=False, ylog=False, xrange=None, yrange=None):
    """series: list of (label, xs, ys, color index, dash index). Writes an SVG line plot."""
    width, height, left, right, top, bottom = 640, 420, 70, 190, 34, 50
    pw, ph = width - left - right, height - top - bottom
    points = [(x, y) for _, xs, ys, _, _ in series for x, y in zip(xs, ys)
              if math.isfinite(x) and math.isfinite(y) and (not xlog or x > 0) and (not ylog or y > 0)]
    fx = (lambda v: math.log10(v)) if xlog else (lambda v: v)
    fy = (lambda v: math.log10(v)) if ylog else (lambda v: v)
    x0, x1 = xrange or (min(fx(p[0]) for p in points), max(fx(p[0]) for p in points))
    y0, y1 = yrange or (min(fy(p[1]) for p in points), max(fy(p[1]) for p in points))
    if xrange and xlog:
        x0, x1 = math.log10(xrange[0]), math.log10(xrange[1])
    if yrange and ylog:
        y0, y1 = math.log10(yrange[0]), math.log10(yrange[1])
    if y1 == y0:
        y1 = y0 + 1

    def px(v):
        return left + (fx(v) - x0) / (x1 - x0) * pw

    def py(v):
        return top + ph - (fy(v) - y0) / (y1 - y0) * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{left + pw / 2}" y="20" text-anchor="middle" font-size="13">{title}</text>']
    # grid and ticks
    xt = [10 ** e for e in range(math.ceil(x0), math.floor(x1) + 1)] if xlog else nice_ticks(x0, x1)
    yt = [10 ** e for e in range(math.ceil(y0), math.floor(y1) + 1)] if ylog else nice_ticks(y0, y1)
    for t in xt:
        X = px(t)
        out.append(f'<line x1="{X:.2f}" y1="{top}" x2="{X:.2f}" y2="{top + ph}" stroke="#ddd"/>')
        out.append(f'<text x="{X:.2f}" y="{top + ph + 15}" text-anchor="middle">{label(t)}</text>')
    for t in yt:
        Y = py(t)
        out.append(f'<line x1="{left}" y1="{Y:.2f}" x2="{left + pw}" y2="{Y:.2f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 5}" y="{Y + 4:.2f}" text-anchor="end">{label(t)}</text>')
    out.append(f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    out.append(f'<text x="{left + pw / 2}" y="{height - 12}" text-anchor="middle">{xlabel}</text>')
    out.append(f'<text x="16" y="{top + ph / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {top + ph / 2})">{ylabel}</text>')
    out.append(f'<clipPath id="plot"><rect x="{left}" y="{top}" width="{pw}" height="{ph}"/></clipPath>')
    for i, (name, xs, ys, color, dash) in enumerate(series):
        segments, pen = [], "M"
        for x, y in zip(xs, ys):
            if not (math.isfinite(x) and math.isfinite(y)) or (xlog and x <= 0) or (ylog and y <= 0):
                pen = "M"
                continue
            segments.append(f"{pen}{px(x):.2f},{py(y):.2f}")
            pen = "L"
        stroke = COLORS[color % len(COLORS)]
        dasharray = f' stroke-dasharray="{DASHES[dash % len(DASHES)]}"' if DASHES[dash % len(DASHES)] else ""
        out.append(f'<path d="{" ".join(segments)}" fill="none" stroke="{stroke}" stroke-width="1.6"{dasharray} '
                   f'clip-path="url(#plot)"/>')
        ly = top + 12 + 16 * i
        out.append(f'<line x1="{left + pw + 10}" y1="{ly}" x2="{left + pw + 36}" y2="{ly}" stroke="{stroke}" '
                   f'stroke-width="1.6"{dasharray}/>')
        out.append(f'<text x="{left + pw + 40}" y="{ly + 4}">{name}</text>')
    out.append("</svg>\n")
    pathlib.Path(path).write_text("\n".join(out))


def column(rows, key):
    return [float(r[key]) for r in rows]


def replace_section(text, name, body):
    pattern = re.compile(rf"(<!-- BEGIN {name} -->\n).*?(<!-- END {name} -->)", re.S)
    if not pattern.search(text):
        sys.exit(f"contact_laws_report.py: docs/contact-laws.md has no section {name}")
    return pattern.sub(lambda m: m.group(1) + body + m.group(2), text)


def main(data, docs):
    data, docs = pathlib.Path(data), pathlib.Path(docs)
    names = ["hertz", "chang-etsion-bogy", "zhao-maietta-chang", "kogut-etsion", "jackson-green-cosine",
             "jackson-green-exponential"]
    single = read(data / "single_laws.csv")
    for quantity, ylabel, name in (("load", "P / P_c (Kogut-Etsion's)", "load"),
                                   ("area", "A / A_c", "area"),
                                   ("stiffness", "(dP/dω) / (P_c/ω_c)", "stiffness")):
        series = []
        for i, law in enumerate(names):
            rows = [r for r in single if r["law"] == law]
            series.append((law, column(rows, "x"), column(rows, quantity), i, 0 if i < 4 else 1))
        plot(docs / f"contact-laws-single-{name}.svg", series, "ω / ω_c (Kogut-Etsion's)", ylabel,
             f"One asperity: {name} (steel, R = 100 µm, Y = 1 GPa, ν = 0.3)", xlog=True, ylog=True)

    md = read(data / "maugis_dugdale.csv")
    series = []
    for i, key in enumerate(["dmt", "0.1", "0.5", "1", "2", "5", "jkr"]):
        rows = [r for r in md if (r["law"] == key) or (r["law"] == "maugis-dugdale" and r["lambda"] == key)]
        name = key.upper() if key in ("dmt", "jkr") else f"MD λ = {key}"
        series.append((name, column(rows, "interference"), column(rows, "load"), i, 0 if key != "jkr" else 1))
    plot(docs / "contact-laws-maugis-dugdale.svg", series, "ω / (π²Δγ²R/K²)^(1/3)", "P / (π Δγ R)",
         "Maugis-Dugdale between DMT and JKR (stable branch, fixed grips)", yrange=(-2.2, 3.0), xrange=(-1.0, 2.0))

    ke = read(data / "kogut_etsion_2003.csv")
    series = []
    for i, psi in enumerate(["0.5", "1", "2", "4", "8"]):
        rows = [r for r in ke if r["psi"] == psi]
        series.append((f"KE ψ = {psi}", column(rows, "h"), column(rows, "load"), i, 0))
        if psi in ("0.5", "8"):
            series.append((f"Hertz, ψ = {psi}", column(rows, "h"), column(rows, "elastic_load"), i, 1))
    plot(docs / "contact-laws-kogut-etsion-2003.svg", series, "h / σ (from the mean of the surface heights)",
         "P / (A_n H)", "Kogut-Etsion 2003's surface (β = 0.04): load against separation", ylog=True,
         yrange=(1e-8, 1))

    al = read(data / "area_load.csv")
    series = []
    for i, law in enumerate(names):
        for j, psi in enumerate(["1", "4"]):
            rows = [r for r in al if r["law"] == law and r["psi"] == psi]
            series.append((f"{law} ψ={psi}", column(rows, "load"), column(rows, "area"), i, j))
    plot(docs / "contact-laws-area-load.svg", series, "P / (A_n S_y)", "A / A_n",
         "Area against load, β = 0.04 (Jackson-Green 2006's comparison)", xlog=True, ylog=True,
         xrange=(1e-5, 10), yrange=(1e-5, 1))

    ft = read(data / "fuller_tabor.csv")
    series = []
    for i, (law, lam, s0) in enumerate([("jkr", "inf", "0"), ("jkr", "inf", "-2"), ("maugis-dugdale", "1", "0"),
                                        ("maugis-dugdale", "3", "0")]):
        rows = [r for r in ft if r["law"] == law and r["lambda"] == lam and r["s0"] == s0]
        name = f"JKR, s0 = {s0}" if law == "jkr" else f"MD λ = {lam}, s0 = {s0}"
        series.append((name, column(rows, "delta_c"), column(rows, "fraction"), i, 0 if law == "jkr" else 1))
    plot(docs / "contact-laws-fuller-tabor.svg", series, "Δc = σ / δc", "pull-off / smooth surface's",
         "Fuller-Tabor: pull-off against the adhesion parameter", yrange=(0, 1.05))

    # tables
    jumps = read(data / "switch_jumps.csv")
    table = ["| law | switch ω/ω_c | P right/left | A right/left | dP/dω right/left |", "|---|---|---|---|---|"]
    for r in jumps:
        table.append(f"| {r['law']} | {float(r['x']):.4g} | {float(r['load_ratio']):.6f} | "
                     f"{float(r['area_ratio']):.6f} | {float(r['stiffness_ratio']):.6f} |")
    text = (docs / "contact-laws.md").read_text()
    text = replace_section(text, "jumps", "\n".join(table) + "\n")
    table = ["| Δc | JKR, s0 = 0 | JKR, s0 = -2 | MD λ = 1 | MD λ = 3 |", "|---|---|---|---|---|"]
    for dc in sorted({float(r["delta_c"]) for r in ft}):
        cells = []
        for law, lam, s0 in [("jkr", "inf", "0"), ("jkr", "inf", "-2"), ("maugis-dugdale", "1", "0"),
                             ("maugis-dugdale", "3", "0")]:
            match = [r for r in ft if r["law"] == law and r["lambda"] == lam and r["s0"] == s0
                     and float(r["delta_c"]) == dc]
            cells.append(f"{float(match[0]['fraction']):.4f}" if match else "")
        table.append(f"| {dc:g} | " + " | ".join(cells) + " |")
    text = replace_section(text, "fuller-tabor", "\n".join(table) + "\n")
    table = ["| h/σ | " + " | ".join(f"ψ = {p}" for p in ["0.5", "1", "2", "4", "8"]) + " |", "|---" * 6 + "|"]
    for h in ["0", "1", "2", "3", "4"]:
        cells = []
        for psi in ["0.5", "1", "2", "4", "8"]:
            match = [r for r in ke if r["psi"] == psi and abs(float(r["h"]) - float(h)) < 1e-9]
            cells.append(f"{float(match[0]['load']):.4e}")
        table.append(f"| {h} | " + " | ".join(cells) + " |")
    text = replace_section(text, "kogut-etsion-2003", "\n".join(table) + "\n")
    (docs / "contact-laws.md").write_text(text)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: contact_laws_report.py DATA_DIR DOCS_DIR")
    main(sys.argv[1], sys.argv[2])
