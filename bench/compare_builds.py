#!/usr/bin/env python3
"""Two builds' bench_lookup against each other (docs/architecture.md, "Nothing slower").

Runs BEFORE and AFTER alternately, ROUNDS times each, every run with Google Benchmark's
repetitions and its median per row; then, for each row, its median time over the rounds in each
build and its ratio to the baselines in the same binary (the geometric mean of BASELINES: code
that is not asperity's and did not change, so a machine that is busier during one build's run
moves both), and the ratio of those ratios (after / before: above 1 is slower).

  python3 bench/compare_builds.py BEFORE/bench_lookup AFTER/bench_lookup [--rounds 4]
      [--filter REGEX] [--baselines BM_StdExp,BM_StdLog,BM_BoostCardinalQuinticHermite]
"""
import argparse
import json
import math
import statistics
import subprocess

KEY_ROWS = ("BM_ScalarKind/(weibull_tail_a2|weibull_bounded_a2|gaussian)|BM_ContactAllFour|"
            "BM_ContactAllFourScales|BM_PhysicalInverseLoad|BM_Batch/(avx2|avx512)|BM_BatchKind/gaussian|"
            "BM_BatchCApi")
BASELINES = "BM_StdExp,BM_StdLog,BM_BoostCardinalQuinticHermite"


def run(binary, pattern, repetitions):
    out = subprocess.run([binary, f"--benchmark_filter={pattern}", f"--benchmark_repetitions={repetitions}",
                          "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                         check=True, capture_output=True, text=True).stdout
    return {b["run_name"]: b["cpu_time"] for b in json.loads(out)["benchmarks"] if b.get("aggregate_name") == "median"}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--filter", default=KEY_ROWS)
    parser.add_argument("--baselines", default=BASELINES)
    args = parser.parse_args()
    baselines = args.baselines.split(",")
    pattern = f"^({args.filter}|{'|'.join(baselines)})$"
    runs = {"before": [], "after": []}
    for _ in range(args.rounds):
        for side, binary in (("before", args.before), ("after", args.after)):
            runs[side].append(run(binary, pattern, args.repetitions))

    def reference(times):
        return math.exp(statistics.fmean(math.log(times[b]) for b in baselines))

    rows = [name for name in runs["before"][0] if name not in baselines]
    print(f"{'row':34s} {'before ns':>10s} {'after ns':>10s} {'before/base':>11s} {'after/base':>10s} "
          f"{'after/before':>12s}")
    for name in rows + baselines:
        before = statistics.median(r[name] for r in runs["before"])
        after = statistics.median(r[name] for r in runs["after"])
        ratio_before = statistics.median(r[name] / reference(r) for r in runs["before"])
        ratio_after = statistics.median(r[name] / reference(r) for r in runs["after"])
        print(f"{name:34s} {before:10.2f} {after:10.2f} {ratio_before:11.4f} {ratio_after:10.4f} "
              f"{ratio_after / ratio_before:12.3f}")
    print(f"(cpu_time per iteration; base: the geometric mean of {', '.join(baselines)} in the same run; "
          f"{args.rounds} rounds of {args.repetitions} repetitions, medians)")


if __name__ == "__main__":
    main()
