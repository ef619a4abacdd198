#!/usr/bin/env bash
# Measure scene tables against tolerance and refresh the measured section of docs/scenes.md
# and docs/scenes.svg/.png (after scripts/setup.sh; BUILD_DIR=build by default).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
source scripts/require-matplotlib.sh
cmake --build "$BUILD_DIR" --target scene_bench -j2
"$BUILD_DIR/bench/scene_bench" --benchmark_out="$BUILD_DIR/scene_bench.json" --benchmark_out_format=json
/usr/bin/python3 scripts/scenes_report.py "$BUILD_DIR/scene_bench.json" docs
echo "refreshed docs/scenes.md, docs/scenes.svg, docs/scenes.png"
