#!/usr/bin/env bash
# The verdict's size on self-affine Gaussian maps without roll-off (issue 40, item 1; the table of
# docs/surfaces.md, "Steep spectra"): bench/surface_ensembles --family self-affine on 128^2, 256^2
# and 512 x 64 maps, then per family and size the verdict's rejections with their 95% Wilson
# interval and how many maps each test rejected at the verdict's 2.5% (h: heights, s: summit heights).
#   bash scripts/surface-self-affine.sh [SEED_OFFSET] [SURROGATES]     (after building: cmake --build build)
# 60, 30 and 40 maps a family: about half an hour on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
offset="${1:-0}"
surrogates="${2:-99}"
out="$(mktemp -d)"
cmake --build build --target surface_ensembles >/dev/null
for cell in "128 128 60" "256 256 30" "512 64 40"; do
  set -- $cell
  build/bench/surface_ensembles --family self-affine --size "$1" --ny "$2" --maps "$3" --surrogates "$surrogates" \
    --seed-offset "$offset" --csv "$out/self-affine-$1x$2.csv" >/dev/null
done
python3 - "$out"/self-affine-*.csv <<'PY'
import csv, math, sys
from collections import defaultdict

def wilson(k, n, z=1.96):
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return f"{p:.3f} [{max(0, centre - half):.3f}, {min(1, centre + half):.3f}]"

cells = defaultdict(list)
sizes = []
for path in sys.argv[1:]:
    for row in csv.DictReader(open(path)):
        size = f"{row['nx']} x {row['ny']}"
        if size not in sizes:
            sizes.append(size)
        cells[(row["family"], size)].append(row)
families = sorted({family for family, _ in cells})
print("| family | " + " | ".join(sizes) + " |")
print("|---|" + "---|" * len(sizes))
for family in families:
    line = []
    for size in sizes:
        rows = cells[(family, size)]
        n = len(rows)
        rejected = sum(r["gaussian_rejected"] == "1" for r in rows)
        h = sum(float(r["p_heights"]) <= 0.025 for r in rows)
        s = sum(float(r["p_summits"]) <= 0.025 for r in rows)
        line.append(f"{wilson(rejected, n)} (h {h}, s {s}; {n} maps)")
    print(f"| {family} | " + " | ".join(line) + " |")
PY
