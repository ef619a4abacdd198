#!/usr/bin/env bash
# The surface analysis's benchmark (bench_surface: the real 650 x 650 X3P map and a 512^2
# synthetic one, 99 surrogates on every core) of two or more builds alternately, ROUNDS rounds:
# each run's process CPU time and wall time per analysis.
#   scripts/bench-surface-ab.sh ROUNDS BUILD_DIR...
# Each build runs its own bench/bench_surface against its own libraries (RUNPATH). On a shared
# machine compare CPU times, and the spread of one build's runs before any difference.
set -euo pipefail
rounds=$1
shift
for round in $(seq "$rounds"); do
  for build in "$@"; do
    "$build/bench/bench_surface" --benchmark_filter='BM_RealX3P|BM_Synthetic/512/' --benchmark_format=json 2>/dev/null |
      /usr/bin/python3 -c "
import json, sys
for row in json.load(sys.stdin)['benchmarks']:
    print(sys.argv[1], row['run_name'].split('/iterations')[0], 'cpu %.3f s' % row['cpu_time'], 'wall %.3f s' % row['real_time'])" "$build"
  done
done
