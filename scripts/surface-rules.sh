#!/usr/bin/env bash
# The rules of issue 40, items 2 and 3, measured on small synthetic maps (docs/surfaces.md, "When a
# test cannot speak, and when the side can be told"): bench/surface_ensembles --csv over
#   the summit count: smooth fields (Gaussian correlation 3 points) of 48^2 to 96^2, and 64^2 at
#                     correlations 5 and 8 (about 10 to 170 summits; at 12 a 64^2 map has under 5
#                     summits, which the analysis refuses);
#   the side:         the nine families of the table on 48^2, 64^2 and 128^2 maps and 256 x 32 strips,
# then scripts/surface_rules_report.py's tables (Clopper-Pearson intervals).
#   bash scripts/surface-rules.sh [MAPS] [SEED_OFFSET]     (after building: cmake --build build)
# 20 maps a cell take about an hour on 2 cores; the thresholds were chosen on SEED_OFFSET 0, and
# docs/surfaces.md's tables are of SEED_OFFSET 5000.
set -euo pipefail
cd "$(dirname "$0")/.."
maps="${1:-20}"
offset="${2:-5000}"
out="$(mktemp -d)"
cmake --build build --target surface_ensembles >/dev/null
smooth=smooth-gaussian,smooth-weibull-tail-1.5,smooth-weibull-bounded-1.5,smooth-weibull-tail-2,smooth-weibull-bounded-2
for n in 48 64 80 96; do
  build/bench/surface_ensembles --maps "$maps" --size "$n" --correlation 3 --family "$smooth" --seed-offset "$offset" \
    --csv "$out/summits-$n.csv" >/dev/null
done
for xi in 5 8; do
  build/bench/surface_ensembles --maps "$maps" --size 64 --correlation "$xi" --family "$smooth" --seed-offset "$offset" \
    --csv "$out/summits-64-$xi.csv" >/dev/null
done
for size in "48 48" "64 64" "128 128" "256 32"; do
  set -- $size
  build/bench/surface_ensembles --maps "$maps" --size "$1" --ny "$2" --seed-offset "$offset" --csv "$out/sides-$1x$2.csv" >/dev/null
done
python3 scripts/surface_rules_report.py summits "$out"/summits-*.csv
echo
python3 scripts/surface_rules_report.py sides "$out"/sides-*.csv
