#!/usr/bin/env bash
# The size, power and coverage of `asperity surface`'s verdict on synthetic ensembles (the table of
# docs/surfaces.md, section 4): bench/surface_ensembles over every family, written to
# docs/surfaces/ensembles.md.
#   bash scripts/surface-ensembles.sh [MAPS] [SURROGATES]     (after building: cmake --build build)
# 100 maps a family and 99 surrogates take about half an hour on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
maps="${1:-100}"
surrogates="${2:-99}"
cmake --build build --target surface_ensembles >/dev/null
build/bench/surface_ensembles --maps "$maps" --surrogates "$surrogates" | tee docs/surfaces/ensembles.md
