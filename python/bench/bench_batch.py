#!/usr/bin/python3
"""asperity.batch against a plain loop, in one run (docs/surfaces.md: "Many surfaces (Dask)").

  FILES synthetic Gaussian maps of SIZE x SIZE points (correlation 2 points, seeds 1..FILES) written
  as GSF files, each analysed with the default ensemble (AssessmentOptions().bootstrap surrogates)
  and the contact curves (E* = 1.1e11 Pa):
  - loop: analyse_surface_file(path).json() written per file, one file after the other in this
    process, each analysis on every core (the library's own threads): the way without the batch;
  - batch: analyse_files on a LocalCluster of a worker process per core, one thread each and each
    analysis on one thread (the files are the parallelism), the cluster's start included;
  - resumed: analyse_files again on the same folder: every surface finished, nothing analysed.
Rounds alternate between the loop and the batch; wall-clock medians over the rounds, and ratios
within the run. The JSON documents of the loop and the batch are compared byte for byte.

usage: PYTHONPATH=build/python python3 python/bench/bench_batch.py [--files 16] [--size 192] [--rounds 3]
"""
import argparse
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

import asperity
from asperity import batch, topography


def cpu_name():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--files", type=int, default=16)
    parser.add_argument("--size", type=int, default=192)
    parser.add_argument("--bootstrap", type=int, default=topography.AssessmentOptions().bootstrap)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    cores = os.cpu_count() or 1
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        paths = []
        for k in range(args.files):
            field = topography.gaussian_random_field(args.size, args.size, 1e-6, 1e-6,
                                                     [topography.SpectrumComponent(2.0, 1e-14)], seed=k + 1)
            path = work / f"part-{k:03d}.gsf"
            topography.write_gsf(field, path)
            paths.append(str(path))
        options = topography.AnalysisOptions(assessment=topography.AssessmentOptions(bootstrap=args.bootstrap),
                                             contact=topography.ContactOptions(1.1e11))

        loops, batches, resumes, shares, same = [], [], [], [], True
        for r in range(args.rounds):
            loop_dir = work / f"loop-{r}"
            loop_dir.mkdir()
            started = time.perf_counter()
            for path in paths:
                text = topography.analyse_surface_file(path, options).json()
                (loop_dir / (batch.output_name(path) + ".json")).write_text(text)
            loops.append(time.perf_counter() - started)

            out = work / f"batch-{r}"
            started = time.perf_counter()
            rows = batch.analyse_files(paths, out, options, progress=False)
            batches.append(time.perf_counter() - started)
            assert all(row["status"] == "analysed" for row in rows), [row["error"] for row in rows if row["error"]]
            same = same and all((out / (row["name"] + ".json")).read_bytes() ==
                                (loop_dir / (row["name"] + ".json")).read_bytes() for row in rows)
            shares.append(sum(row["seconds"] for row in rows) / (batches[-1] * cores))

            started = time.perf_counter()
            rows = batch.analyse_files(paths, out, options, progress=False)
            resumes.append(time.perf_counter() - started)
            assert all(row["status"] == "resumed" for row in rows)
        loop, batched, resumed = (statistics.median(v) for v in (loops, batches, resumes))

    print(f"asperity {asperity.__version__}, {cpu_name()}, {cores} cores; {args.files} maps of "
          f"{args.size} x {args.size} points, {args.bootstrap} surrogates, contact curves; medians of "
          f"{args.rounds} rounds")
    print("| run | wall time | per surface | x loop |\n|---|---:|---:|---:|")
    print(f"| loop, each analysis on {cores} threads | {loop:.1f} s | {loop / args.files:.2f} s | 1 |")
    print(f"| analyse_files, LocalCluster {cores} processes x 1 thread (start included) | {batched:.1f} s | "
          f"{batched / args.files:.2f} s | {batched / loop:.2f} |")
    print(f"| analyse_files again, all finished (resumed) | {resumed:.2f} s | {resumed / args.files * 1e3:.1f} ms | "
          f"{resumed / loop:.3f} |")
    print(f"batch: the workers' analyses filled {statistics.median(shares):.0%} of {cores} cores over the run; "
          f"JSON documents identical to the loop's: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
