#!/usr/bin/env bash
# The batch path against its floor (issue 41, item 7; docs/benchmarks.md, "The batch at its
# floor"): bench_lookup's batch rows, the scalar lookup and the floor's parts (BM_BatchFloor:
# the vector exp, the quintic, both in one pass, a memcpy of the same doubles), medians of
# REPETITIONS (default 9) randomly interleaved, CPU time per query, and the ratios within the run.
#   scripts/batch-floor.sh [BUILD_DIR] [REPETITIONS]
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
repetitions=${2:-9}
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$build/bench/bench_lookup" \
  --benchmark_filter='^BM_Batch/|^BM_BatchGaussian/|^BM_BatchCApi|^BM_ScalarCApi|^BM_ScalarKind/weibull_tail_a2$|^BM_BatchFloor/' \
  --benchmark_repetitions="$repetitions" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true --benchmark_format=json > "$json" 2>/dev/null
/usr/bin/python3 - "$json" <<'PY'
import json, sys
run = json.load(open(sys.argv[1]))
ns = {}  # median CPU ns a query (items_per_second counts queries)
for row in run["benchmarks"]:
    if row.get("aggregate_name") == "median" and row.get("items_per_second"):
        ns[row["run_name"]] = 1e9 / row["items_per_second"]
context = run["context"]
print("CPU: %s, %d cores at %d MHz; load average %s" % (
    open("/proc/cpuinfo").read().split("model name")[1].split(":")[1].split("\n")[0].strip(),
    context["num_cpus"], context["mhz_per_cpu"], " ".join("%.2f" % x for x in context.get("load_avg", []))))
print("\n| row | ns a query (median CPU) |\n|---|---:|")
for name in sorted(ns):
    print("| `%s` | %.3f |" % (name, ns[name]))
def ratio(a, b):
    return "%.2fx" % (ns[a] / ns[b]) if a in ns and b in ns else "-"
best = None  # the C API's batch runs the widest set this CPU has
for isa in ("avx512", "avx2"):
    compute, memory = "BM_BatchFloor/quintic_exp/" + isa, "BM_BatchFloor/stream"
    if compute not in ns:
        continue
    floor = max(ns[compute], ns[memory])
    batch = "BM_BatchCApi" if best is None else "BM_Batch/" + isa
    best = best or isa
    print("\n%s: floor %.3f ns = max(compute %.3f [exp %.3f + quintic %.3f apart], memory %.3f); "
          "batch %.3f ns = %.2fx the floor" % (
              isa, floor, ns[compute], ns["BM_BatchFloor/exp/" + isa], ns["BM_BatchFloor/quintic/" + isa],
              ns[memory], ns[batch], ns[batch] / floor))
print("\nBM_BatchCApi / BM_ScalarCApi: %s; BM_Batch/avx512 / BM_ScalarKind/weibull_tail_a2: %s; "
      "BM_Batch/avx2 / the same: %s" % (ratio("BM_BatchCApi", "BM_ScalarCApi"),
                                        ratio("BM_Batch/avx512", "BM_ScalarKind/weibull_tail_a2"),
                                        ratio("BM_Batch/avx2", "BM_ScalarKind/weibull_tail_a2")))
PY
