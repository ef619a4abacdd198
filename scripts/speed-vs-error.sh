#!/usr/bin/env bash
# Measure speed against error and write docs/speed-vs-error.md, .svg and .png.
#   scripts/speed-vs-error.sh            (after scripts/setup.sh; BUILD_DIR=build by default)
# Needs Debian's python3-matplotlib (scripts/require-matplotlib.sh says so if it is missing).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
source scripts/require-matplotlib.sh
cmake --build "$BUILD_DIR" --target speed_vs_error -j2
"$BUILD_DIR/bench/speed_vs_error" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.2 --benchmark_out="$BUILD_DIR/speed_vs_error.json" --benchmark_out_format=json
/usr/bin/python3 scripts/speed_vs_error_report.py "$BUILD_DIR/speed_vs_error.json" docs
echo "wrote docs/speed-vs-error.md, docs/speed-vs-error.svg, docs/speed-vs-error.png"
