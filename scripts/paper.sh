#!/usr/bin/env bash
# Reproduce the paper: docs/paper_fig{1,2,3}.svg/.png and the claims table of docs/paper.md
# (after scripts/setup.sh; BUILD_DIR=build by default).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-matplotlib >/dev/null
  else
    echo "paper: needs python3-matplotlib (apt-get install python3-matplotlib)" >&2
    exit 1
  fi
fi
cmake --build "$BUILD_DIR" --target paper_data -j2
mkdir -p "$BUILD_DIR/paper"
"$BUILD_DIR/examples/paper_data" "$BUILD_DIR/paper"
/usr/bin/python3 scripts/paper_report.py "$BUILD_DIR/paper" docs
echo "refreshed docs/paper.md and docs/paper_fig{1,2,3}.svg/.png"
