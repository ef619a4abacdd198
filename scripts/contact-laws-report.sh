#!/usr/bin/env bash
# Refresh the figures (docs/contact-laws-*.svg) and the measured tables of docs/contact-laws.md
# (after scripts/setup.sh; BUILD_DIR=build by default). Python's standard library only.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
cmake --build "$BUILD_DIR" --target contact_law_curves -j2
mkdir -p "$BUILD_DIR/contact-laws"
"$BUILD_DIR/tests/contact_law_curves" "$BUILD_DIR/contact-laws"
/usr/bin/python3 scripts/contact_laws_report.py "$BUILD_DIR/contact-laws" docs
echo "refreshed docs/contact-laws.md and docs/contact-laws-*.svg"
