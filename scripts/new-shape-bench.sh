#!/usr/bin/env bash
# A new shape (issue 41, item 6; docs/benchmarks.md, "A new shape"): what a curve at a shape
# between the table's nodes costs against one already made (build/bench/new_shape_bench), and
# `asperity eval` on 2,000 and 200,000 rows whose every row has its own shape against as many
# rows of one shape (farm-bench: the whole process, pairs alternated).
#   scripts/new-shape-bench.sh [BUILD_DIR]
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$work" <<'PY'
import random, sys
work = sys.argv[1]
random.seed(1)
for rows in (2000, 200000):
    with open(f"{work}/distinct{rows}.csv", "w") as distinct, open(f"{work}/repeated{rows}.csv", "w") as repeated:
        distinct.write("dist,side,shape,sep\n")
        repeated.write("dist,side,shape,sep\n")
        for _ in range(rows):
            distinct.write("weibull,tail,%r,%r\n" % (random.uniform(0.5, 20), random.uniform(-2, 3)))
            repeated.write("weibull,tail,1.73,%r\n" % random.uniform(-2, 3))
PY
"$build/bench/new_shape_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.3 | grep -E 'median|Benchmark'
for rows in 2000 200000; do
  echo "-- eval, $rows rows: every row its own shape (A) against one shape (B)"
  farm-bench -n 5 --timeout 600 --vs "$build/asperity eval $work/repeated$rows.csv" -- \
    "$build/asperity" eval "$work/distinct$rows.csv" | grep -E 'cpu s|A/B cpu'
  echo "-- the same against one shape with --grid (B)"
  farm-bench -n 5 --timeout 600 --vs "$build/asperity eval --grid $work/repeated$rows.csv" -- \
    "$build/asperity" eval "$work/distinct$rows.csv" | grep -E 'cpu s|A/B cpu'
done
