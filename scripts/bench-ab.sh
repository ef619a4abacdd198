#!/usr/bin/env bash
# Time two or more builds of bench_lookup against each other on a shared machine: the builds'
# runs alternate (ROUNDS times each, 3 repetitions a run, randomly interleaved rows, pinned to
# one core), and each row's minimum and median over all repetitions are printed per build.
#   scripts/bench-ab.sh --copy BUILD_DIR DIR      copy BUILD_DIR's bench_lookup and its library to DIR
#   scripts/bench-ab.sh FILTER ROUNDS DIR...      time the copies (FILTER: --benchmark_filter's regex)
# Each build runs with its own libasperity (LD_LIBRARY_PATH before the binary's RUNPATH): a
# bench_lookup built before a change of Curve's layout crashes against a newer library.
# BENCH_AB_TIME=cpu_time reports CPU time (default real_time): on a loaded machine the wall
# time counts the other tenants' turns too.
set -euo pipefail
if [ "${1:-}" = "--copy" ]; then
  mkdir -p "$3"
  cp "$2/bench/bench_lookup" "$3/"
  cp "$(readlink -f "$2/runtime/libasperity.so.0")" "$3/libasperity.so.0"
  exit 0
fi
filter=$1 rounds=$2
shift 2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for dir in "$@"; do
    LD_LIBRARY_PATH="$dir" taskset -c 1 "$dir/bench_lookup" --benchmark_filter="$filter" --benchmark_repetitions=3 \
      --benchmark_min_time=0.05 --benchmark_enable_random_interleaving=true --benchmark_format=json \
      > "$out/$(basename "$dir").$round.json" 2>/dev/null
  done
done
/usr/bin/python3 - "$out" "${BENCH_AB_TIME:-real_time}" "$@" <<'PY'
import collections, glob, json, os, statistics, sys
out, field = sys.argv[1], sys.argv[2]
for directory in sys.argv[3:]:
    name = os.path.basename(directory)
    times = collections.defaultdict(list)
    for path in glob.glob(os.path.join(out, name + ".*.json")):
        for row in json.load(open(path))["benchmarks"]:
            if row.get("run_type") == "iteration":
                times[row["run_name"]].append(row[field])
    for row in sorted(times):
        print("%-12s %-44s min %10.2f  median %10.2f  (%d)" % (name, row, min(times[row]), statistics.median(times[row]), len(times[row])))
PY
