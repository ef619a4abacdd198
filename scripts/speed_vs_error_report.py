#!/usr/bin/python3
"""Turn bench/speed_vs_error's Google Benchmark JSON into docs/speed-vs-error.md and a plot.

usage: speed_vs_error_report.py RESULTS.json OUT_DIR

Each benchmark carries its method in the label ("study|method|family") and its measured
maximum relative error, knot density and table size as counters. Time per query is the
median over the repetitions (items/s counts queries, so batch runs are per query too).
"""
import json
import platform
import subprocess
import sys
from pathlib import Path

from matplotlib.lines import Line2D

from report_style import plt, save

# Our two paths are lines through their knot densities (labelled once, at the batch end of each
# density's pair); every other method is a marker of its own, named in the legend, not on the plot.
OURS = {"asperity scalar": ("o", "tab:blue"), "asperity batch": ("s", "tab:green")}
OTHERS = {
    "Boost cardinal_quintic_hermite": ("^", "tab:orange"),
    "Boost quintic_hermite": ("v", "tab:brown"),
    "Boost cubic_hermite": ("<", "tab:olive"),
    "Boost makima": (">", "tab:pink"),
    "quadrature": ("D", "tab:red"),
    "curve fit": ("X", "tab:purple"),
}
FLOOR = 1e-17  # an error of exactly 0 still gets a place on the log axis


def other_style(row):
    if row["family"] in ("quadrature", "curve fit"):
        return OTHERS[row["family"]]
    return OTHERS.get(row["method"], ("*", "tab:gray"))


def spread_labels(figure, labels, gap_points=9.0):
    """Moves density labels apart vertically (in each panel) so that no two overlap."""
    figure.canvas.draw()
    to_points = 72.0 / figure.dpi
    by_axis = {}
    for annotation in labels:
        by_axis.setdefault(id(annotation.axes), []).append(annotation)
    for group in by_axis.values():
        anchored = sorted(group, key=lambda a: a.axes.transData.transform(a.xy)[1])
        previous = None
        for annotation in anchored:
            y = annotation.axes.transData.transform(annotation.xy)[1] * to_points
            wanted = y if previous is None else max(y, previous + gap_points)
            annotation.set_position((annotation.xyann[0], wanted - y - 3))
            previous = wanted


def load(path):
    data = json.loads(Path(path).read_text())
    rows = []
    aggregated = any(b.get("run_type") == "aggregate" for b in data["benchmarks"])
    for bench in data["benchmarks"]:
        if aggregated and bench.get("aggregate_name") != "median":
            continue
        study, method, family = bench["label"].split("|")
        rows.append(
            {
                "study": study,
                "method": method,
                "family": family,
                "density": bench["density"],
                "bytes": bench["table_bytes"],
                "ns": 1e9 / bench["items_per_second"],
                "error": bench["max_rel_error"],
            }
        )
    return data["context"], rows


def pareto(rows):
    """Indices of the rows no other row beats on both time and error."""
    front = set()
    for i, a in enumerate(rows):
        dominated = any(
            (b["ns"] <= a["ns"] and b["error"] <= a["error"]) and (b["ns"] < a["ns"] or b["error"] < a["error"])
            for j, b in enumerate(rows)
            if j != i
        )
        if not dominated:
            front.add(i)
    return front


def machine_description(context):
    cpu = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        compiler = subprocess.run(["c++", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        compiler = "unknown compiler"
    caches = ", ".join(f"L{c['level']} {c['type']} {c['size'] // 1024} KiB" for c in context.get("caches", []))
    return [
        f"- CPU: {cpu}, {context.get('num_cpus')} logical CPUs at {context.get('mhz_per_cpu')} MHz ({caches})",
        f"- OS: {platform.system()} {platform.release()}; compiler: {compiler}; build: Release (-O3)",
        f"- batch path instruction set: {context.get('instruction_set', 'unknown')}",
        f"- measured: {context.get('date')}; load average {context.get('load_avg')}",
    ]


def main():
    results, out_dir = sys.argv[1], Path(sys.argv[2])
    context, rows = load(results)
    studies = list(dict.fromkeys(row["study"] for row in rows))

    figure, axes = plt.subplots(1, len(studies), figsize=(6.5 * len(studies), 6.4))
    if len(studies) == 1:
        axes = [axes]
    lines = [
        "# Speed against error",
        "",
        "Every way a user has to get X_n(s), on the same random separations: time per query (median of",
        "5 Google Benchmark repetitions, one binary, one run) against the maximum relative error over 400",
        "points of the range, measured against 50-digit references (Boost.Multiprecision double-exponential",
        "quadrature of the defining integrals, `tests/reference.hpp`). The Pareto front (no other method both",
        "faster and more accurate) is marked. Regenerate with `scripts/speed-vs-error.sh`.",
        "",
        "![speed against error](speed-vs-error.svg)",
        "",
        "Measured on:",
        "",
        *machine_description(context),
        "",
        "Methods: *asperity scalar* is `Curve::value` / `asperity_eval`; *asperity batch* is",
        "`Curve::value_batch` / `asperity_eval_batch` on 4096 queries; `xD` is the knot density relative to",
        "the default layout (`tablegen --density D`; x1 is the shipped table). The Boost.Math interpolators",
        "(`cardinal_quintic_hermite`, `quintic_hermite`, `cubic_hermite`, `makima`) get the default knots and",
        "our map from separation to each segment's variable and offset, so only the interpolation differs.",
        "Quadrature is Boost exp_sinh/tanh_sinh in double at tolerance 1e-14. The curve fit is the",
        "lubrication codes' F_5/2(h) = 4.4086e-5 (4 - h)^6.804. Table size is one curve, all six orders",
        "(ours) or the one order interpolated (Boost).",
        "",
    ]
    density_labels = []
    for axis, study in zip(axes, studies):
        study_rows = [row for row in rows if row["study"] == study]
        front = pareto(study_rows)
        for family, (marker, colour) in OURS.items():
            members = sorted((r for r in study_rows if r["family"] == family), key=lambda r: r["error"])
            axis.plot([r["ns"] for r in members], [max(r["error"], FLOOR) for r in members], marker=marker,
                      color=colour, markersize=6, linewidth=1, zorder=3)
        # each density's scalar and batch points share one error: join them, name the density once
        for row in study_rows:
            if row["family"] != "asperity batch":
                continue
            scalar = next((r for r in study_rows if r["family"] == "asperity scalar" and r["density"] == row["density"]),
                          None)
            if scalar:
                axis.plot([row["ns"], scalar["ns"]], [max(row["error"], FLOOR)] * 2, color="0.75", linewidth=0.8,
                          zorder=1)
            density_labels.append(axis.annotate(
                f"x{row['density']:g}", (row["ns"], max(row["error"], FLOOR)), xytext=(-6, -3),
                textcoords="offset points", ha="right", fontsize=8, color="tab:green"))
        for row in study_rows:
            if row["family"].startswith("asperity"):
                continue
            marker, colour = other_style(row)
            axis.scatter([row["ns"]], [max(row["error"], FLOOR)], marker=marker, color=colour, s=60, zorder=4,
                         edgecolors="black", linewidths=0.4)
        front_rows = sorted((study_rows[i] for i in front), key=lambda r: r["ns"])
        axis.step([r["ns"] for r in front_rows], [max(r["error"], FLOOR) for r in front_rows], where="post",
                  color="black", linewidth=1, linestyle="--", zorder=2)
        axis.set_xscale("log")
        axis.set_yscale("log")
        low, high = axis.get_xlim()
        axis.set_xlim(low / 2.5, high)  # room for the density labels left of the batch points
        axis.set_xlabel("median time per query (ns)")
        axis.set_ylabel("maximum relative error over the range")
        axis.set_title(study)

        default = next(r for r in study_rows if r["method"] == "asperity scalar" and r["density"] == 1)
        lines += [f"## {study}", "", "| method | density | table | ns/query | vs our scalar | max rel error | Pareto |",
                  "|---|---:|---:|---:|---:|---:|:---:|"]
        for index, row in sorted(enumerate(study_rows), key=lambda item: item[1]["ns"]):
            table = f"{row['bytes'] / 1024:.0f} KiB" if row["bytes"] else "-"
            density = f"{row['density']:g}" if row["density"] else "-"
            ratio = row["ns"] / default["ns"]
            lines.append(
                f"| {row['method']} | {density} | {table} | {row['ns']:.1f} | {ratio:.2f}x | {row['error']:.2g} |"
                f" {'yes' if index in front else ''} |"
            )
        lines.append("")
    present = {other_style(r)[0] for r in rows if not r["family"].startswith("asperity")}
    handles = [Line2D([], [], marker=m, color=c, label=f"ours, {f.split()[1]} (xD: knot density D)")
               for f, (m, c) in OURS.items()]
    handles += [Line2D([], [], marker=m, color=c, linestyle="none", markeredgecolor="black", markeredgewidth=0.4,
                       label=name) for name, (m, c) in OTHERS.items() if m in present]
    handles.append(Line2D([], [], color="black", linestyle="--", label="Pareto front (nothing both faster and more accurate)"))
    figure.legend(handles=handles, loc="lower center", ncol=3, frameon=False)
    figure.tight_layout(rect=(0, 0.13, 1, 1))
    spread_labels(figure, density_labels)
    save(figure, out_dir, "speed-vs-error", dpi=130)
    (out_dir / "speed-vs-error.md").write_text("\n".join(lines) + "\n" + READING)


READING = """## Reading it

- **Density buys accuracy and memory, not latency.** A lookup is O(1) whatever the knot count: its
  cost is the map from separation to the segment variable (a log, and an exp in the far tail), one
  Horner step and the final exp. Fewer knots make the table smaller (and more of it cache-resident)
  and the error larger; the time per query moves only with cache effects. To trade error for memory:
  `tablegen --density 0.25` (a quarter of the knots) for ~1e-10 worst case, `--density 0.125` for ~1e-8
  (figures above). There is no setting that halves the latency for 1e-6: the elementary functions
  dominate, and they are the same at any density.
- **The batch path** is where the speed is: the same arithmetic, vectorized (exp and log included),
  on machines with AVX-512 or AVX2; see `bench/bench_lookup.cpp` for the per-instruction-set figures.
- **Boost's interpolators** on the same knots and the same map: `cardinal_quintic_hermite` matches our
  accuracy (the same interpolant) at a higher cost; `cubic_hermite` and `makima` use less of the
  knot data (no second derivative, or no derivatives) and lose 3 to 6 digits.
- **Quadrature** is as accurate as the table and thousands of times slower.
- **The curve fit** is fast and wrong: up to 100% at the end of its range (it is 0 from h = 4, where
  F_5/2 is not), which no speed repays.
"""

if __name__ == "__main__":
    main()
