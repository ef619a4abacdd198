#!/usr/bin/env python3
"""The rules of issue 40, items 2 and 3, measured: reads the per-map lines of
bench/surface_ensembles --csv and prints docs/surfaces.md's tables with Clopper-Pearson 95% intervals.

    python3 scripts/surface_rules_report.py summits FILE...   the summit test's power against the count
    python3 scripts/surface_rules_report.py sides FILE...     the side rule's size and power by map size

(scripts/surface-rules.sh runs the maps and this.)"""
import csv
import sys
from collections import defaultdict

from scipy.stats import beta


def clopper_pearson(k, n, level=0.95):
    a = 1 - level
    lo = 0.0 if k == 0 else beta.ppf(a / 2, k, n - k + 1)
    hi = 1.0 if k == n else beta.ppf(1 - a / 2, k + 1, n - k)
    return lo, hi


def rate(k, n):
    if n == 0:
        return "–"
    lo, hi = clopper_pearson(k, n)
    return f"{k}/{n} ({100 * k / n:.0f}% [{100 * lo:.1f}, {100 * hi:.1f}])"


def read(paths):
    out = []
    for path in paths:
        with open(path) as f:
            for row in csv.DictReader(f):
                out.append(row)
    return out


def truth(row):
    if float(row["truth_shape"]) == 0:
        return "gaussian"
    return "weibull-bounded" if row["truth_bounded"] == "1" else "weibull-tail"


BINS = (0, 20, 35, 50, 80, 100, 130, 200, 400, 10**9)


def summits(rows):
    """the summit heights' test at 2.5% (half the significance) against the summit count"""
    table = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    null_p = defaultdict(list)  # the p-values on the Gaussian maps: near 1 where the test cannot speak
    for r in rows:
        n = int(r["summits"])
        b = next(lo for lo, hi in zip(BINS, BINS[1:]) if lo <= n < hi)
        shape = float(r["truth_shape"])
        kind = "Gaussian" if shape == 0 else f"Weibull a = {shape:g}, both sides"
        cell = table[kind][b]
        cell[0] += float(r["p_summits"]) < 0.025
        cell[1] += 1
        if shape == 0:
            null_p[b].append(float(r["p_summits"]))
    kinds = sorted(table)
    bins = sorted({b for k in kinds for b in table[k]})
    print("| summits | " + " | ".join(kinds) + " | mean p, Gaussian maps |")
    print("|---|" + "---|" * len(kinds) + "---:|")
    for b in bins:
        hi = BINS[BINS.index(b) + 1]
        label = f"{b}–{hi - 1}" if hi < 10**9 else f"{b}+"
        mean_p = f"{sum(null_p[b]) / len(null_p[b]):.2f}" if null_p[b] else "–"
        print(f"| {label} | " + " | ".join(rate(*table[k][b]) if table[k][b][1] else "–" for k in kinds) + f" | {mean_p} |")


def sides(rows):
    """the side rule's rates by map size and family: a side told on a Gaussian map, the right and the
    wrong side on a Weibull map, a Weibull of the wrong side named for the contact"""
    groups = defaultdict(list)
    for r in rows:
        groups[(f"{r['nx']}x{r['ny']}", r["family"])].append(r)
    print("| map | family | summits | summit test applicable | side told right | side told wrong | contact Weibull of the wrong side |")
    print("|---|---|---:|---:|---|---|---|")
    pooled = defaultdict(lambda: [0, 0, 0, 0])
    for (size, family), g in sorted(groups.items(), key=lambda kv: (int(kv[0][0].split("x")[0]) * int(kv[0][0].split("x")[1]), kv[0][1])):
        t = truth(g[0])
        told = [r for r in g if r["side_told"] == "1"]
        right = sum(1 for r in told if r["orientation"] == t)
        wrong = len(told) - right
        contact_wrong = sum(1 for r in g if r["model_for_contact"] not in ("none", "gaussian", t))
        applicable = sum(1 for r in g if r["summit_test_applicable"] == "1")
        mean_summits = sum(int(r["summits"]) for r in g) / len(g)
        print(f"| {size} | {family} | {mean_summits:.0f} | {applicable}/{len(g)} | "
              f"{'–' if t == 'gaussian' else rate(right, len(g))} | {rate(wrong, len(g))} | {rate(contact_wrong, len(g))} |")
        p = pooled["Gaussian" if t == "gaussian" else "Weibull"]
        p[0] += right
        p[1] += wrong
        p[2] += contact_wrong
        p[3] += len(g)
    for kind, (right, wrong, contact_wrong, n) in sorted(pooled.items()):
        print(f"| all | {kind} maps | | | {'–' if kind == 'Gaussian' else rate(right, n)} | {rate(wrong, n)} | {rate(contact_wrong, n)} |")


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("summits", "sides"):
        sys.exit(__doc__)
    {"summits": summits, "sides": sides}[sys.argv[1]](read(sys.argv[2:]))
