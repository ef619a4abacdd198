#!/usr/bin/env bash
# Measure the exact contact and refresh the measured sections of docs/exact-contact.md and its
# figures docs/exact-contact-*.svg/.png (after scripts/setup.sh; BUILD_DIR=build by default).
# The speed table needs exact_contact_bench's JSON: the benchmark runs first (2048^2 takes minutes;
# SKIP_BENCH=1 keeps the JSON of an earlier run).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
source scripts/require-matplotlib.sh
cmake --build "$BUILD_DIR" --target asperity asperity_python exact_contact_bench -j2
if [ "${SKIP_BENCH:-0}" != 1 ]; then
  "$BUILD_DIR/bench/exact_contact_bench" --benchmark_out="$BUILD_DIR/exact_contact_bench.json" \
    --benchmark_out_format=json
fi
/usr/bin/python3 scripts/exact_contact_report.py "$BUILD_DIR" "$BUILD_DIR/exact_contact_bench.json"
echo "refreshed docs/exact-contact.md and docs/exact-contact-*.svg/.png"
