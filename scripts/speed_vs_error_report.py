#!/usr/bin/python3
"""Turn bench/speed_vs_error's and bench/bench_lookup's Google Benchmark JSON into
docs/speed-vs-error.md and its figure (SVG and PNG).

usage: speed_vs_error_report.py SPEED_VS_ERROR.json BENCH_LOOKUP.json OUT_DIR

speed_vs_error: each benchmark carries its method in the label ("study|method|family") and its
measured maximum relative error, knot density, grid tolerance and bytes as counters.
bench_lookup: the rows bench/bench_lookup.cpp documents; the targets of the lookup (issue 14)
are ratios of its medians. Time per query is the median over the repetitions (items/s counts
queries, so batch runs are per query too; CPU time, except the thread rows, which are wall time).
"""
import json
import platform
import subprocess
import sys
from pathlib import Path

from matplotlib.lines import Line2D

from report_style import plt, save

# Our two paths, coloured by grid tolerance; every other method is a marker of its own, named in
# the legend, not on the plot.
OURS = {"asperity scalar": "o", "asperity batch": "s"}
TOLERANCE_COLOURS = {1e-13: "#08306b", 1e-11: "#2171b5", 1e-9: "#6baed6", 1e-7: "#bdd7e7"}
OTHERS = {
    "Boost cardinal_quintic_hermite": ("^", "tab:orange"),
    "Boost quintic_hermite": ("v", "tab:brown"),
    "Boost cubic_hermite": ("<", "tab:olive"),
    "Boost makima": (">", "tab:pink"),
    "quadrature": ("D", "tab:red"),
    "curve fit": ("X", "tab:purple"),
}
FLOOR = 1e-17  # an error of exactly 0 still gets a place on the log axis
DEFAULT_TOLERANCE = 1e-13  # CurveOptions::grid_tolerance's default


def other_style(row):
    if row["family"] in ("quadrature", "curve fit"):
        return OTHERS[row["family"]]
    return OTHERS.get(row["method"], ("*", "tab:gray"))


def tolerance_colour(tolerance):
    return min(TOLERANCE_COLOURS.items(), key=lambda item: abs(item[0] - tolerance) / item[0])[1]


def spread_labels(figure, labels, gap_points=9.0):
    """Moves labels apart vertically (in each panel) so that no two overlap."""
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


def medians(path):
    """The benchmarks of a Google Benchmark JSON file (medians where there are aggregates)."""
    data = json.loads(Path(path).read_text())
    aggregated = any(b.get("run_type") == "aggregate" for b in data["benchmarks"])
    rows = []
    for bench in data["benchmarks"]:
        if aggregated and bench.get("aggregate_name") != "median":
            continue
        rows.append(bench)
    return data["context"], rows


def load(path):
    context, benches = medians(path)
    rows = []
    for bench in benches:
        study, method, family = bench["label"].split("|")
        rows.append(
            {
                "study": study,
                "method": method,
                "family": family,
                "density": bench["density"],
                "tolerance": bench.get("grid_tolerance", 0.0),
                "table_bytes": bench["table_bytes"],
                "bytes": bench.get("memory_bytes", bench["table_bytes"]),
                "bytes_all": bench.get("memory_all_orders", 0.0),
                "ns": 1e9 / bench["items_per_second"],
                "error": bench["max_rel_error"],
            }
        )
    return context, rows


def pareto(rows, key):
    """Indices of the rows no other row beats on both `key` and error (rows without `key` left out)."""
    front = set()
    candidates = [(i, r) for i, r in enumerate(rows) if r[key] > 0]
    for i, a in candidates:
        dominated = any(
            (b[key] <= a[key] and b["error"] <= a["error"]) and (b[key] < a[key] or b["error"] < a["error"])
            for j, b in candidates
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


def kib(value):
    return f"{value / 1024:.0f}" if value >= 10 * 1024 else f"{value / 1024:.1f}"


# ---- the figure: time against error (top), memory against error (bottom), one column per study ----


def plot(rows, studies):
    figure, axes = plt.subplots(2, len(studies), figsize=(6.6 * len(studies), 11.5), squeeze=False)
    labels = []
    for column, study in enumerate(studies):
        study_rows = [row for row in rows if row["study"] == study]
        time_axis, memory_axis = axes[0][column], axes[1][column]

        # time against error: every (density, tolerance) of ours, scalar and batch
        for row in study_rows:
            if row["family"] in OURS:
                time_axis.scatter([row["ns"]], [max(row["error"], FLOOR)], marker=OURS[row["family"]], s=30,
                                  color=tolerance_colour(row["tolerance"]), edgecolors="black", linewidths=0.3,
                                  zorder=3)
            else:
                marker, colour = other_style(row)
                time_axis.scatter([row["ns"]], [max(row["error"], FLOOR)], marker=marker, color=colour, s=60,
                                  zorder=4, edgecolors="black", linewidths=0.4)
        front = sorted((study_rows[i] for i in pareto(study_rows, "ns")), key=lambda r: r["ns"])
        time_axis.step([r["ns"] for r in front], [max(r["error"], FLOOR) for r in front], where="post",
                       color="black", linewidth=1, linestyle="--", zorder=2)
        time_axis.set_xscale("log")
        time_axis.set_yscale("log")
        time_axis.set_xlabel("median time per query (ns)")
        time_axis.set_ylabel("maximum relative error over the range")
        time_axis.set_title(f"{study}\ntime against error")

        # memory against error: ours (one point per density and tolerance; scalar and batch hold
        # the same curve) joined along each density, and the interpolators on the default knots
        ours = [r for r in study_rows if r["family"] == "asperity scalar"]
        label_column = 1.06 * max(r["bytes"] for r in study_rows) / 1024  # density labels in a column, right
        for density in sorted({r["density"] for r in ours}):
            line = sorted((r for r in ours if r["density"] == density), key=lambda r: r["tolerance"])
            memory_axis.plot([r["bytes"] / 1024 for r in line], [max(r["error"], FLOOR) for r in line], color="0.6",
                             linewidth=0.8, zorder=1)
            for r in line:
                memory_axis.scatter([r["bytes"] / 1024], [max(r["error"], FLOOR)], marker="o", s=34,
                                    color=tolerance_colour(r["tolerance"]), edgecolors="black", linewidths=0.3,
                                    zorder=3)
            tightest = line[0]
            labels.append(memory_axis.annotate(
                f"x{density:g}", (tightest["bytes"] / 1024, max(tightest["error"], FLOOR)),
                xytext=(label_column, -3), textcoords=("data", "offset points"), ha="left", fontsize=8,
                color="0.2", arrowprops=dict(arrowstyle="-", color="0.75", linewidth=0.6, shrinkA=1, shrinkB=3)))
        for row in study_rows:
            if row["family"] in OURS or row["bytes"] <= 0:
                continue
            marker, colour = other_style(row)
            memory_axis.scatter([row["bytes"] / 1024], [max(row["error"], FLOOR)], marker=marker, color=colour, s=60,
                                zorder=4, edgecolors="black", linewidths=0.4)
        memory_rows = [r for r in study_rows if r["family"] != "asperity batch"]
        front = sorted((memory_rows[i] for i in pareto(memory_rows, "bytes")), key=lambda r: r["bytes"])
        memory_axis.step([r["bytes"] / 1024 for r in front], [max(r["error"], FLOOR) for r in front], where="post",
                         color="black", linewidth=1, linestyle="--", zorder=2)
        memory_axis.set_yscale("log")
        memory_axis.set_xlim(0, label_column * 1.1)  # from 0; room for the density labels
        memory_axis.set_xlabel("KiB held for the curve, one order (Curve::memory_bytes)")
        memory_axis.set_ylabel("maximum relative error over the range")
        memory_axis.set_title("memory against error (quadrature and the fit hold no table)")

    handles = [Line2D([], [], marker=m, color="0.5", markeredgecolor="black", markeredgewidth=0.3, linestyle="none",
                      label=f"ours, {family.split()[1]}") for family, m in OURS.items()]
    handles += [Line2D([], [], marker="o", color=c, markeredgecolor="black", markeredgewidth=0.3, linestyle="none",
                       label=f"ours, grid tolerance {t:g}") for t, c in TOLERANCE_COLOURS.items()]
    handles.append(Line2D([], [], color="0.6", linewidth=0.8,
                          label="ours, one knot density xD (tablegen --density D), grid tolerances joined"))
    present = {other_style(r)[0] for r in rows if r["family"] not in OURS}
    handles += [Line2D([], [], marker=m, color=c, linestyle="none", markeredgecolor="black", markeredgewidth=0.4,
                       label=name) for name, (m, c) in OTHERS.items() if m in present]
    handles.append(Line2D([], [], color="black", linestyle="--", label="Pareto front (nothing both better on the axis and more accurate)"))
    figure.legend(handles=handles, loc="lower center", ncol=3, frameon=False)
    figure.tight_layout(rect=(0, 0.09, 1, 1), h_pad=2.5)
    spread_labels(figure, labels)
    return figure


# ---- the tables ----


def study_tables(rows, study):
    study_rows = [row for row in rows if row["study"] == study]
    default = next(r for r in study_rows if r["family"] == "asperity scalar" and r["density"] == 1
                   and r["tolerance"] == DEFAULT_TOLERANCE)
    ours = [r for r in study_rows if r["family"] == "asperity scalar"]
    densities = sorted({r["density"] for r in ours})
    tolerances = sorted({r["tolerance"] for r in ours})
    lines = [f"## {study}", "",
             "Ours, by knot density (rows) and grid tolerance (columns): maximum relative error, and KiB the",
             "curve holds for this one order (for all six orders in brackets).", "",
             "| density | " + " | ".join(f"grid tolerance {t:g}" for t in tolerances) + " |",
             "|---:|" + "---:|" * len(tolerances)]
    for density in densities:
        cells = []
        for tolerance in tolerances:
            r = next(r for r in ours if r["density"] == density and r["tolerance"] == tolerance)
            cells.append(f"{r['error']:.2g}, {kib(r['bytes'])} ({kib(r['bytes_all'])})")
        lines.append(f"| x{density:g} | " + " | ".join(cells) + " |")
    lines.append("")
    time_front = pareto(study_rows, "ns")
    memory_front = pareto([r if r["family"] != "asperity batch" else dict(r, bytes=0) for r in study_rows], "bytes")
    lines += ["Every method, fastest first (*front*: on the Pareto front of time and error, or of memory and error):",
              "", "| method | density | grid tolerance | KiB held | ns/query | vs our default scalar | max rel error | front |",
              "|---|---:|---:|---:|---:|---:|---:|:---:|"]
    for index, row in sorted(enumerate(study_rows), key=lambda item: item[1]["ns"]):
        fronts = [name for name, members in (("time", time_front), ("memory", memory_front)) if index in members]
        density = f"{row['density']:g}" if row["density"] else "-"
        tolerance = f"{row['tolerance']:g}" if row["tolerance"] else "-"
        held = kib(row["bytes"]) if row["bytes"] else "-"
        lines.append(f"| {row['method']} | {density} | {tolerance} | {held} | {row['ns']:.1f} | "
                     f"{row['ns'] / default['ns']:.2f}x | {row['error']:.2g} | {', '.join(fronts)} |")
    lines.append("")
    return lines


class Lookup:
    """bench_lookup's medians by name: ns per query (CPU time; wall time for the thread rows)."""

    def __init__(self, path):
        self.context, benches = medians(path)
        self.rows = {}
        for bench in benches:
            name = bench.get("run_name", bench["name"])
            if bench.get("error_occurred"):
                continue
            self.rows[name] = bench

    def has(self, name):
        return name in self.rows

    def ns(self, name):
        return 1e9 / self.rows[name]["items_per_second"]

    def rate(self, name):
        return self.rows[name]["items_per_second"]


WEIBULL_KINDS = ["weibull_tail_a0.5", "weibull_tail_a2", "weibull_tail_a20", "weibull_bounded_a0.5",
                 "weibull_bounded_a2", "weibull_bounded_a20"]
ALL_KINDS = WEIBULL_KINDS + ["gaussian", "gaussian_fit_domain"]
ISA_TO_HIGHWAY = {"generic": "sse4", "avx2": "avx2", "avx512": "avx3"}


def lookup_section(lookup):
    ns, has = lookup.ns, lookup.has
    fit = ns("BM_GaussianF52CurveFit")
    lines = ["## Lookup speed against its targets (bench_lookup)", "",
             "From the same command, `build/bench/bench_lookup` (rows described at the top of",
             "`bench/bench_lookup.cpp`): medians of 5 repetitions, randomly interleaved, CPU time per query",
             "(wall time for the thread rows), 4096 random separations over each curve's whole table range.",
             f"Load average during the run: {lookup.context.get('load_avg')}.", "",
             "| target | measured | ratio | met |", "|---|---|---:|:---:|"]

    def row(target, measured, ratio, met):
        lines.append(f"| {target} | {measured} | {ratio} | {'yes' if met else '**no**'} |")

    gaussian = ns("BM_ScalarKind/gaussian_fit_domain")
    row("Gaussian F_5/2 scalar <= 0.8x the fit 4.4086e-5 (4 - h)^6.804 on h in [0, 4)",
        f"{gaussian:.1f} ns vs fit {fit:.1f} ns", f"{gaussian / fit:.2f}x", gaussian / fit <= 0.8)
    for kind in WEIBULL_KINDS + ["gaussian"]:
        value = ns(f"BM_ScalarKind/{kind}")
        target = "<= 1.0x the fit" if kind.startswith("weibull") else "(the Gaussian over its whole range)"
        row(f"scalar `{kind}`, X_3/2 {target}" if kind.startswith("weibull") else f"scalar `{kind}` F_5/2 {target}",
            f"{value:.1f} ns", f"{value / fit:.2f}x", value / fit <= 1.0 if kind.startswith("weibull") else True)
    one = ns("BM_ScalarKind/weibull_tail_a2")
    four = ns("BM_ContactAllFour")
    row("four quantities (`contact_at`, a `SurfaceScales`: its factors on every query) <= 1.5x one order (Weibull a = 2 tail)",
        f"{four:.1f} ns vs {one:.1f} ns", f"{four / one:.2f}x", four / one <= 1.5)
    if has("BM_ContactAllFourScales"):
        scaled = ns("BM_ContactAllFourScales")
        row("four quantities (`contact_at_scales`, the factors computed once) <= 1.5x one order",
            f"{scaled:.1f} ns vs {one:.1f} ns", f"{scaled / one:.2f}x", scaled / one <= 1.5)
    if has("BM_ContactOrders"):
        orders = ns("BM_ContactOrders")
        row("`Curve::contact_orders` (the four integrals X_0, X_1/2, X_1, X_3/2, logs and values) <= 1.5x one order",
            f"{orders:.1f} ns", f"{orders / one:.2f}x", orders / one <= 1.5)
    for name, limit, label in (("BM_Batch/avx512", 3.0, "Weibull a = 2"), ("BM_BatchGaussian/avx512", 2.0, "Gaussian F_5/2")):
        if has(name):
            value = ns(name)
            row(f"batch {label} on AVX-512 <= {limit:g} ns a query", f"{value:.2f} ns", "", value <= limit)
    for name, limit, label in (("BM_Batch/avx512", 3.0, "Weibull a = 2"), ("BM_BatchGaussian/avx512", 2.0, "Gaussian F_5/2")):
        if has(name):  # the ns were measured beside a fit of 10.1 ns: the same targets as fractions of the fit
            value = ns(name)
            row(f"(batch {label} on AVX-512 against the fit in this run; the issue's {limit:g} ns was "
                f"{limit / 10.1:.2f}x its fit)", f"{value:.2f} ns vs fit {fit:.1f} ns", f"{value / fit:.2f}x",
                value / fit <= limit / 10.1)
    for name, scalar, label in (("BM_Batch/avx2", "BM_ScalarKind/weibull_tail_a2", "Weibull a = 2"),
                                ("BM_BatchGaussian/avx2", "BM_ScalarKind/gaussian", "Gaussian F_5/2")):
        if has(name):
            value, reference = ns(name), ns(scalar)
            row(f"batch {label} on AVX2 >= 3x scalar", f"{value:.2f} ns vs {reference:.1f} ns",
                f"{reference / value:.2f}x", reference / value >= 3)
    for name, scalar, label in (("BM_Batch/avx512", "BM_ScalarKind/weibull_tail_a2", "Weibull a = 2"),
                                ("BM_BatchGaussian/avx512", "BM_ScalarKind/gaussian", "Gaussian F_5/2")):
        if has(name):
            value, reference = ns(name), ns(scalar)
            row(f"(batch {label} on AVX-512 against scalar)", f"{value:.2f} ns vs {reference:.1f} ns",
                f"{reference / value:.2f}x", True)
    for kind in ALL_KINDS:
        quadrature, scalar = ns(f"BM_DirectQuadrature/{kind}"), ns(f"BM_ScalarKind/{kind}")
        row(f"scalar >= 1000x direct quadrature, `{kind}`", f"{quadrature / 1000:.1f} us vs {scalar:.1f} ns",
            f"{quadrature / scalar:.0f}x", quadrature / scalar >= 1000)
    threads = "BM_BatchThreads/min_time:1.000/real_time/threads:"
    if has(threads + "1") and has(threads + "2"):
        ratio = lookup.rate(threads + "2") / lookup.rate(threads + "1")
        row("two threads on one curve's batch path >= 1.8x one thread (throughput)",
            f"{lookup.rate(threads + '2') / 1e6:.0f} vs {lookup.rate(threads + '1') / 1e6:.0f} M queries/s",
            f"{ratio:.2f}x", ratio >= 1.8)
    probe = "BM_CoreProbe/min_time:1.000/real_time/threads:"
    if has(probe + "1") and has(probe + "2"):
        ratio = lookup.rate(probe + "2") / lookup.rate(probe + "1")
        row("(the machine: two threads of register-only arithmetic against one)", "", f"{ratio:.2f}x", True)
    lines.append("")

    # Highway and hand-written intrinsics against the runtime's own code, per instruction set
    lines += ["Highway (`bench/highway_kernel.cpp`: the same loop with Highway 1.0.3's gathers and Exp) and the",
              "loop written by hand in AVX-512 intrinsics (`bench/intrinsics_kernel_avx512.cpp`: all six",
              "coefficients by masked gathers), both one fused loop, against `Curve::value_batch` (the runtime's",
              "three passes, `runtime/core/kernel/`),",
              "ns a query (ratio < 1: the other code faster):", "",
              "| kind | instruction set | ours | Highway (target) | Highway / ours | intrinsics | intrinsics / ours |",
              "|---|---|---:|---:|---:|---:|---:|"]
    for kind, ours_row in (("weibull_tail_a2", "BM_Batch/"), ("gaussian", "BM_BatchGaussian/")):
        for isa, target in ISA_TO_HIGHWAY.items():
            name = f"BM_HighwayBatch/{target}/{kind}"
            hand = f"BM_IntrinsicsBatch/{isa}/{kind}"
            if has(ours_row + isa) and has(name):
                ours = ns(ours_row + isa)
                intrinsics = f"{ns(hand):.2f} | {ns(hand) / ours:.2f}x" if has(hand) else "- | -"
                lines.append(f"| {kind} | {isa} | {ours:.2f} | {ns(name):.2f} ({target}) | "
                             f"{ns(name) / ours:.2f}x | {intrinsics} |")
    lines.append("")

    # the runtime's three passes against its former fused loop
    lines += ["The runtime's batch path (three passes: positions, quintics by 128-bit row loads paired in registers, a",
              "vector `exp` without a table in memory) against its former single loop that the compiler",
              "vectorized (gathers for the coefficients and the `exp` table; kept in `bench/record_kernels.hpp`,",
              "`BM_Record/batch_ISA/48B`), ns a query:", "",
              "| kind | instruction set | three passes | fused loop | fused / three passes |", "|---|---|---:|---:|---:|"]
    for kind, ours_row in (("weibull_tail_a2", "BM_Batch/"), ("gaussian", "BM_BatchGaussian/")):
        for isa in ("generic", "avx2", "avx512"):
            fused = f"BM_Record/batch_{isa}/48B/{kind}"
            if has(ours_row + isa) and has(fused):
                ours = ns(ours_row + isa)
                lines.append(f"| {kind} | {isa} | {ours:.2f} | {ns(fused):.2f} | {ns(fused) / ours:.2f}x |")
    lines.append("")

    # issue 13: 48-byte against 64-byte records
    lines += ["Interval records (issue 13): bench-local copies of the lookup (`bench/record_kernels.hpp`) with",
              "48-byte records where the runtime's allocation puts them, from a 64-byte aligned base, and padded",
              "to 64 bytes (one cache line each), ns a query:", "",
              "| kind | path | 48 B | 48 B, aligned base | 64 B, aligned | 64 B / 48 B |", "|---|---|---:|---:|---:|---:|"]
    for kind in ("weibull_tail_a0.5", "weibull_tail_a2", "gaussian"):
        for path in ("scalar", "batch_generic", "batch_avx2", "batch_avx512"):
            names = [f"BM_Record/{path}/{r}/{kind}" for r in ("48B", "48B_aligned64", "64B_aligned64")]
            if all(has(n) for n in names):
                values = [ns(n) for n in names]
                lines.append(f"| {kind} | {path.replace('_', ' ')} | {values[0]:.2f} | {values[1]:.2f} | {values[2]:.2f} | "
                             f"{values[2] / values[0]:.2f}x |")
    lines.append("")
    return lines


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: speed_vs_error_report.py SPEED_VS_ERROR.json BENCH_LOOKUP.json OUT_DIR")
    results, lookup_results, out_dir = sys.argv[1], sys.argv[2], Path(sys.argv[3])
    context, rows = load(results)
    lookup = Lookup(lookup_results)
    studies = list(dict.fromkeys(row["study"] for row in rows))

    figure = plot(rows, studies)
    save(figure, out_dir, "speed-vs-error", dpi=110)

    lines = [
        "# Speed, error and memory",
        "",
        "Every way a user has to get X_n(s), on the same random separations: time per query (median of",
        "5 Google Benchmark repetitions, randomly interleaved, one binary, one run), the maximum relative",
        "error over 400 points of the range, measured against 50-digit references (Boost.Multiprecision",
        "double-exponential quadrature of the defining integrals, `tests/reference.hpp`), and the bytes",
        "the method holds for the curve. The figure shows the three axes as two panels per study: time",
        "against error (top) and memory against error (bottom), with the Pareto front of each (no other",
        "method both better on that axis and more accurate) dashed. Regenerate everything here, figures",
        "and the lookup targets below included, with one command: `scripts/speed-vs-error.sh`.",
        "",
        "![speed, error and memory](speed-vs-error.svg)",
        "",
        "Measured on:",
        "",
        *machine_description(context),
        "",
        "Methods: *asperity scalar* is `Curve::value` / `asperity_eval`; *asperity batch* is",
        "`Curve::value_batch` / `asperity_eval_batch` on 4096 queries. Ours is measured at each knot",
        "density `xD` of the table (knots relative to the default layout: `tablegen --density D`; x1 is",
        "the default table) and each grid tolerance (`CurveOptions::grid_tolerance`: how closely the",
        "lookup grid built at load time follows the table, in ln X, where X >= 1e-100, and 100 times",
        "looser below; the default is 1e-13), each curve holding the one order studied (`order_mask`),",
        "as the interpolators do; *KiB held* is `Curve::memory_bytes()`. The Boost.Math interpolators",
        "(`cardinal_quintic_hermite`, `quintic_hermite`, `cubic_hermite`, `makima`) get the default knots",
        "and our map from separation to each segment's variable and offset, so only the interpolation",
        "differs; they hold their knot vectors. Quadrature is Boost exp_sinh/tanh_sinh in double at",
        "tolerance 1e-14 on the generator's scaled integrands (which never underflow). The curve fit is",
        "the lubrication codes' F_5/2(h) = 4.4086e-5 (4 - h)^6.804.",
        "",
    ]
    for study in studies:
        lines += study_tables(rows, study)
    lines += lookup_section(lookup)
    (out_dir / "speed-vs-error.md").write_text("\n".join(lines) + "\n" + READING)


READING = """## Reading it

- **Time does not depend on the table.** A lookup is the bits of s picking a binade and an interval
  of the grid, one quintic and one exp, at any knot density and grid tolerance; what moves the time
  is the machine (cache, other programs), not the point chosen.
- **Memory is set by the grid tolerance, and error by the tolerance and the density together.** The
  error of a curve is that of its table (set by `tablegen --density`) plus what the grid adds (set by
  `CurveOptions::grid_tolerance`); the grid's size follows the tolerance, and a coarse table needs a
  larger grid at a tight tolerance (its interpolant has more structure to follow). A curve never
  needs the table's knots after it is built: the table can be closed.
- **To pick a point**: find the error you need on the vertical axis of the lower panel and take the
  leftmost point below it. The default (x1, 1e-13) is at the table's own accuracy.
- **The batch path** is where the speed is: the same arithmetic, vectorized (exp included), on
  machines with AVX-512 or AVX2; per instruction set in the lookup section above.
- **Boost's interpolators** on the same knots and the same map: `cardinal_quintic_hermite` matches our
  accuracy (the same interpolant) at a higher cost; `cubic_hermite` and `makima` use less of the
  knot data (no second derivative, or no derivatives) and lose 3 to 6 digits.
- **Quadrature** is as accurate as the table and thousands of times slower.
- **The curve fit** is fast and wrong: up to 100% at the end of its range (it is 0 from h = 4, where
  F_5/2 is not), which no speed repays.
"""

if __name__ == "__main__":
    main()
