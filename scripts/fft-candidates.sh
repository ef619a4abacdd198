#!/usr/bin/env bash
# Measures the FFT candidates of docs/surfaces.md ("The FFT") on this machine: a 2-d
# real-to-complex transform of an n x n map in double precision, n = 256 ... 2048.
# Needs libkissfft-dev, libeigen3-dev, libfftw3-dev and libbenchmark-dev (installed here if
# missing); FFTW is measured, never linked into asperity (GPL).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-packages.sh g++ libkissfft-dev libeigen3-dev python3-pythran libfftw3-dev libbenchmark-dev
out="$(mktemp -d)"
g++ -O3 -march=native -std=c++17 -DNDEBUG -I/usr/include/eigen3 -I/usr/lib/python3/dist-packages bench/fft_candidates.cpp -o "$out/fft_candidates" \
  -lfftw3 -lbenchmark -lpthread
"$out/fft_candidates" --benchmark_repetitions="${REPETITIONS:-3}" --benchmark_report_aggregates_only=true "$@"
rm -rf "$out"
