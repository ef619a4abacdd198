#!/usr/bin/python3
"""bench/scene_bench's JSON -> the measured section of docs/scenes.md and docs/scenes.svg/.png.

usage: scenes_report.py RESULTS.json DOCS_DIR
"""
import json
import re
import sys
from pathlib import Path

from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from report_style import plt, save


def main():
    data = json.loads(Path(sys.argv[1]).read_text())
    docs = Path(sys.argv[2])
    generate, lookup = {}, {}
    for bench in data["benchmarks"]:
        if bench.get("run_type") == "aggregate" and bench.get("aggregate_name") != "median":
            continue
        tolerance = bench["tolerance"]
        if bench["name"].startswith("BM_SceneGenerate"):
            generate[tolerance] = bench
        else:
            lookup[(tolerance, int(bench["curve"]))] = bench
    tolerances = sorted(generate, reverse=True)
    names = {curve: lookup[(tolerances[0], curve)]["label"] for (_, curve) in lookup}
    curves = sorted(names)

    lines = ["| max_rel_error | generation (3 curves, 2 threads) | knots (all curves) | worst achieved / asked |"
             + "".join(f" {names[c]}: KiB, ns |" for c in curves),
             "|---:|---:|---:|---:|" + "---:|" * len(curves)]
    for tolerance in tolerances:
        row = generate[tolerance]
        cells = "".join(
            f" {lookup[(tolerance, c)]['memory_kib']:.1f}, {lookup[(tolerance, c)]['real_time']:.1f} |" for c in curves)
        lines.append(f"| {tolerance:.0e} | {row['real_time']:.0f} ms | {row['knots']:.0f} | "
                     f"{row['achieved_over_asked']:.2f} |{cells}")
    table = "\n".join(lines)

    figure, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for c in curves:
        axes[0].plot(tolerances, [lookup[(t, c)]["memory_kib"] for t in tolerances], "o-", label=names[c])
        axes[2].plot(tolerances, [lookup[(t, c)]["real_time"] for t in tolerances], "o-", label=names[c])
    axes[1].plot(tolerances, [generate[t]["real_time"] for t in tolerances], "s-", color="black")
    axes[1].axhline(1000, color="red", linestyle="--", linewidth=1, label="1 s")
    for axis, title, unit in zip(axes, ["one curve in memory (its asked orders)", "generating the scene table (3 curves)",
                                        "lookup, one order (scalar)"],
                                 ["memory per curve (KiB)", "generation time (ms)", "time per lookup (ns)"]):
        axis.set_xscale("log")
        axis.invert_xaxis()  # stricter to the right
        axis.set_xlabel("max_rel_error asked (stricter to the right)")
        axis.set_ylabel(unit)
        axis.set_title(title)
        axis.legend()
    # Memory spans one decade or so: label 1, 2, 5 of each decade, not just the powers of ten.
    axes[0].set_yscale("log")
    axes[0].yaxis.set_major_locator(LogLocator(base=10, subs=(1, 2, 5)))
    axes[0].yaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axes[0].yaxis.set_minor_formatter(NullFormatter())
    axes[1].set_ylim(bottom=0)
    axes[2].set_ylim(bottom=0)
    figure.tight_layout()
    save(figure, docs, "scenes", dpi=120)

    context = data["context"]
    measured = (f"Measured {context.get('date')} on {context.get('num_cpus')} CPUs at "
                f"{context.get('mhz_per_cpu')} MHz (`scripts/scenes-report.sh`):\n\n{table}\n\n"
                "![size, generation time and latency against tolerance](scenes.svg)")
    page = docs / "scenes.md"
    text = page.read_text()
    text = re.sub(r"<!-- measured:begin -->.*<!-- measured:end -->",
                  "<!-- measured:begin -->\n" + measured.replace("\\", "\\\\") + "\n<!-- measured:end -->",
                  text, flags=re.S)
    page.write_text(text)


if __name__ == "__main__":
    main()
