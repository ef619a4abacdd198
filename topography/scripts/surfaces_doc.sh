#!/usr/bin/env bash
# Regenerates the measured figures of docs/surfaces.md: the two real surfaces of
# tests/data/surfaces through `asperity surface`, one report directory each under
# docs/surfaces/ (report.md, report.json, curves.csv, summits.csv, fits.svg, contact.svg),
# and the terminal summaries (the size, power and coverage table: scripts/surface-ensembles.sh).
#   bash topography/scripts/surfaces_doc.sh        (after building: cmake --build build)
set -euo pipefail
cd "$(dirname "$0")/../.."

run() {  # name file extra-options...
  local name=$1 file=$2
  shift 2
  mkdir -p "docs/surfaces/$name"
  build/asperity surface "tests/data/surfaces/$file" --modulus 1e11 --pressure 1e6,1e7 --ensemble 99 --seed 1 \
    --report "docs/surfaces/$name" "$@" | sed "s|$PWD/||" > "docs/surfaces/$name/summary.txt"
  # the report names files relative to the repository
  sed -i "s|$PWD/||g" "docs/surfaces/$name/report.md" "docs/surfaces/$name/report.json"
  cat "docs/surfaces/$name/summary.txt"
}

run digitalsurf-x3p digitalsurf-650x650.x3p
run afm-zsensor afm-zsensor-10um.txt
run afm-zsensor-window3 afm-zsensor-10um.txt --summit-window 3
