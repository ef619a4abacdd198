#!/usr/bin/env bash
# The runtime's ABI does not depend on its kernels (docs/architecture.md, "The public face and the
# ABI"): the runtime is built three times from copies of this tree, as it is, with a kernel change
# (another field in the lookup a Curve stores, another entry in the kernel table), and with a
# change of the public Curve's storage, and Debian's abidiff (abigail-tools) compares their
# libasperity.so against the public headers:
#   the kernel change:       no ABI change (abidiff's exit status 0)
#   the public change:       reported (the check's own check: abidiff sees what it should)
#   usage: tests/abi/abi_check.sh [WORK_DIR]     (CI: .ci/run)
set -euo pipefail
source_tree="$(cd "$(dirname "$0")/../.." && pwd)"
command -v abidiff >/dev/null || { echo "abi_check: abidiff not found (Debian: abigail-tools)"; exit 1; }
work="${1:-$(mktemp -d)}"
mkdir -p "$work"

copy_tree() {  # the files a runtime-only configure reads
  rm -rf "$1" && mkdir -p "$1/docs"
  cp -r "$source_tree"/{CMakeLists.txt,cmake,runtime,include,LICENSE,CHANGELOG.md,README.md} "$1"/
  cp "$source_tree/docs/model.md" "$1/docs/"
}
build_runtime() {  # SOURCE BUILD: the runtime alone, with debug information for abidiff
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="-Og" -DASPERITY_BUILD_GENERATOR=OFF \
    -DASPERITY_BUILD_TOPOGRAPHY=OFF -DASPERITY_BUILD_COMMANDS=OFF -DASPERITY_BUILD_PYTHON=OFF \
    -DASPERITY_BUILD_FORTRAN=OFF -DASPERITY_BUILD_BENCHMARKS=OFF -DASPERITY_BUILD_TESTS=OFF >/dev/null
  cmake --build "$2" -j"$(nproc)" --target asperity_runtime >/dev/null
}
library() { readlink -f "$1/runtime/libasperity.so"; }
compare() {  # BUILD1 BUILD2: abidiff's status, its report on stdout
  local status=0
  abidiff --headers-dir1 "$source_tree/include" --headers-dir2 "$source_tree/include" \
    --suppressions "$source_tree/tests/abi/internal.suppr" "$(library "$1")" "$(library "$2")" || status=$?
  return $status
}

copy_tree "$work/base"
copy_tree "$work/kernel"
copy_tree "$work/public"
# a kernel change: the lookup a Curve stores grows, the kernel table gets an entry
sed -i 's|^  const double\* contact_records = nullptr;$|&\n  double abi_probe[4] = {};|' \
  "$work/kernel/runtime/include/asperity/detail/curve_data.hpp"
sed -i 's|^  void (\*exps)(const double\* logs, double\* out, int count) noexcept;$|&\n  void (*abi_probe)() noexcept = nullptr;|' \
  "$work/kernel/runtime/core/kernel/kernels.hpp"
grep -q abi_probe "$work/kernel/runtime/include/asperity/detail/curve_data.hpp"
grep -q abi_probe "$work/kernel/runtime/core/kernel/kernels.hpp"
# a change of the public face: the Curve's storage grows
sed -i 's|curve_lookup_bytes = 256;|curve_lookup_bytes = 264;|' "$work/public/include/asperity/curve.hpp"
grep -q "curve_lookup_bytes = 264" "$work/public/include/asperity/curve.hpp"

for variant in base kernel public; do
  build_runtime "$work/$variant" "$work/$variant-build"
done

echo "-- a kernel change against the base: no ABI change expected"
compare "$work/base-build" "$work/kernel-build"
echo "   none (abidiff: 0)"
echo "-- a change of the public Curve against the base: abidiff must report it"
status=0
compare "$work/base-build" "$work/public-build" >"$work/public.txt" || status=$?
if [ $((status & 4)) -eq 0 ]; then
  echo "abidiff did not report the public change (status $status):"; cat "$work/public.txt"; exit 1
fi
grep -m3 -E "Curve|size" "$work/public.txt" | sed 's/^/   /'
echo "-- abi: the kernels change without changing the ABI; a public change is seen"
