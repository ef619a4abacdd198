#!/usr/bin/env bash
# Reproduce the paper: docs/paper_fig{1,2,3}.svg/.png and the claims table of docs/paper.md
# (after scripts/setup.sh; BUILD_DIR=build by default).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
source scripts/require-matplotlib.sh
cmake --build "$BUILD_DIR" --target paper_data -j2
mkdir -p "$BUILD_DIR/paper"
"$BUILD_DIR/examples/paper_data" "$BUILD_DIR/paper"
/usr/bin/python3 scripts/paper_report.py "$BUILD_DIR/paper" docs
echo "refreshed docs/paper.md and docs/paper_fig{1,2,3}.svg/.png"
