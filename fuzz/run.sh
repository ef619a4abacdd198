#!/usr/bin/env bash
# Builds the libFuzzer targets with Clang under AddressSanitizer + UndefinedBehaviorSanitizer and
# runs each for SECONDS (default 60) from its seed corpus (fuzz/corpus/<target>, copied: the
# repository's corpus is not changed). Fails on any crash, sanitizer report, leak, timeout (a
# single input over 10 s) or memory over 2 GiB. Prints each target's executions at the end.
#   bash fuzz/run.sh [SECONDS]     (BUILD_DIR: default build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build_dir="${BUILD_DIR:-build-fuzz}"

# Clang 14 and its libFuzzer runtime (Debian), installed if missing.
packages="clang-14 libclang-rt-14-dev"
# shellcheck disable=SC2086
bash scripts/install-packages.sh $packages

CC=clang-14 CXX=clang++-14 cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DASPERITY_BUILD_FUZZERS=ON -DASPERITY_SANITIZE=ON -DASPERITY_BUILD_TESTS=OFF \
  -DASPERITY_BUILD_BENCHMARKS=OFF >/dev/null
# the targets fuzz/CMakeLists.txt made (a surface format's from the formats' list)
targets="$(cat "$build_dir/fuzz/targets.txt")"
# shellcheck disable=SC2086
cmake --build "$build_dir" -j"$(nproc)" --target $targets

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# One target's run: its seed corpus copied, libFuzzer for $seconds; 0 when it ran clean.
fuzz_target() {
  local target="$1" corpus="$work/$1"
  mkdir -p "$corpus" "$work/artifacts-$target"
  if ! compgen -G "fuzz/corpus/${target#fuzz_}/*" >/dev/null; then
    echo "$target: no seed files in fuzz/corpus/${target#fuzz_}/ (a new format needs a few small files there)" >"$work/$target.log"
    return 1
  fi
  cp fuzz/corpus/"${target#fuzz_}"/* "$corpus"/
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build_dir/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$work/artifacts-$target/" -print_final_stats=1 "$corpus" >"$work/$target.log" 2>&1
}
# The targets run side by side, one a core (each is one process for a fixed time: nproc of them at
# once take the wall time of one, CI's time, docs/architecture.md); a failure is reported when
# its batch ends.
jobs_at_once="$(nproc)"
summary=""
# shellcheck disable=SC2086
set -- $targets
while [ "$#" -gt 0 ]; do
  batch=()
  for _ in $(seq 1 "$jobs_at_once"); do
    [ "$#" -gt 0 ] || break
    batch+=("$1")
    shift
  done
  pids=()
  for target in "${batch[@]}"; do
    echo "== $target: ${seconds} s"
    fuzz_target "$target" &
    pids+=("$!")
  done
  for k in "${!batch[@]}"; do
    target="${batch[$k]}"
    if ! wait "${pids[$k]}"; then
      kill "${pids[@]}" 2>/dev/null || true
      tail -n 60 "$work/$target.log"
      echo "$target FAILED: the input is in the log above" >&2
      exit 1
    fi
    runs="$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 runs in \2 s/p' "$work/$target.log")"
    summary="$summary$target: $runs, 0 crashes\n"
  done
done
echo "== fuzzing: every target ran clean"
printf "%b" "$summary"
