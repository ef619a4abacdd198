#!/usr/bin/env bash
# Measure speed, error and memory, and the lookup against its speed targets, and write
# docs/speed-vs-error.md, .svg and .png: one command, from configuring to the report.
#   scripts/speed-vs-error.sh            (BUILD_DIR=build by default; configured here if it is not)
# Takes ~10 minutes on 2 cores. Run it on a quiet machine: the figures are medians of 5
# repetitions, interleaved, but other programs on the same cores still move them.
# Needs Debian's python3-matplotlib (scripts/require-matplotlib.sh says so if it is missing).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
source scripts/require-matplotlib.sh
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" --target default_table speed_vs_error bench_lookup -j2
runs=(--benchmark_repetitions=5 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
      --benchmark_out_format=json)
echo "== uptime before: $(uptime)"
# the copies and baselines bench_lookup times answer like Curve (fails the script otherwise)
"$BUILD_DIR/bench/bench_lookup" --check >/dev/null
"$BUILD_DIR/bench/bench_lookup" "${runs[@]}" --benchmark_min_time=0.2 --benchmark_out="$BUILD_DIR/bench_lookup.json"
"$BUILD_DIR/bench/speed_vs_error" "${runs[@]}" --benchmark_min_time=0.2 --benchmark_out="$BUILD_DIR/speed_vs_error.json"
echo "== uptime after: $(uptime)"
/usr/bin/python3 scripts/speed_vs_error_report.py "$BUILD_DIR/speed_vs_error.json" "$BUILD_DIR/bench_lookup.json" docs
echo "wrote docs/speed-vs-error.md, docs/speed-vs-error.svg, docs/speed-vs-error.png"
