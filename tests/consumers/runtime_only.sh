#!/usr/bin/env bash
# The runtime alone (CI: .ci/run), on a machine where only its own dependencies can be seen:
# in a private mount namespace the headers and CMake packages of everything else asperity can
# use (nlohmann-json, pugixml, libzip, NLopt, CLI11, pybind11, Python's headers, GoogleTest,
# Google Benchmark, Highway, pocketfft) are hidden under empty folders, then the runtime alone is
# configured, built and installed (HDF5 and libcrypto; Boost.Math and toml11, header-only, to
# build it), and a C++ program is built against the installed tree with
# find_package(asperity COMPONENTS runtime) and run.
#   usage: tests/consumers/runtime_only.sh TABLE     TABLE: a default table to install (as root, or
#   through sudo)
set -euo pipefail
source_tree="$(cd "$(dirname "$0")/../.." && pwd)"
table="$(readlink -f "$1")"
if [ "${ASPERITY_RUNTIME_ONLY_HIDDEN:-}" != 1 ]; then
  # a private mount namespace needs root: sudo when not root, as scripts/install-packages.sh does
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  exec $sudo unshare --mount --propagation private env ASPERITY_RUNTIME_ONLY_HIDDEN=1 bash "$0" "$table"
fi
hide() {  # an empty folder over a folder, /dev/null over a file
  for path in "$@"; do
    if [ -d "$path" ]; then mount -t tmpfs -o ro,size=4k none "$path"
    elif [ -e "$path" ]; then mount --bind /dev/null "$path"
    fi
  done
}
shopt -s nullglob
hide /usr/include/nlohmann /usr/share/cmake/nlohmann_json \
     /usr/include/pugixml.hpp /usr/include/pugiconfig.hpp /usr/lib/x86_64-linux-gnu/cmake/pugixml \
     /usr/include/zip.h /usr/include/zipconf.h /usr/lib/x86_64-linux-gnu/cmake/libzip \
     /usr/lib/x86_64-linux-gnu/pkgconfig/libzip.pc \
     /usr/include/nlopt.h /usr/include/nlopt.hpp /usr/lib/x86_64-linux-gnu/cmake/nlopt* \
     /usr/include/CLI /usr/share/cmake/CLI11 /usr/include/pybind11 /usr/lib/cmake/pybind11 /usr/include/python3* \
     /usr/include/gtest /usr/include/gmock /usr/lib/x86_64-linux-gnu/cmake/GTest \
     /usr/include/benchmark /usr/lib/x86_64-linux-gnu/cmake/benchmark /usr/include/hwy \
     /usr/lib/x86_64-linux-gnu/cmake/hwy /usr/lib/python3/dist-packages/pythran
for header in /usr/include/nlohmann/json.hpp /usr/include/CLI/CLI.hpp /usr/include/pybind11/pybind11.h \
              /usr/include/gtest/gtest.h /usr/include/benchmark/benchmark.h; do
  if [ -s "$header" ]; then echo "runtime_only: $header is still visible"; exit 1; fi
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
start=$SECONDS
cmake -S "$source_tree" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DASPERITY_BUILD_GENERATOR=OFF \
  -DASPERITY_BUILD_TOPOGRAPHY=OFF -DASPERITY_BUILD_COMMANDS=OFF -DASPERITY_BUILD_PYTHON=OFF \
  -DASPERITY_BUILD_FORTRAN=OFF -DASPERITY_BUILD_BENCHMARKS=OFF -DASPERITY_BUILD_TESTS=OFF \
  -DASPERITY_DEFAULT_TABLE_SOURCE="$table" >"$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j"$(nproc)" >"$work/build.log" || { tail -50 "$work/build.log"; exit 1; }
cmake --install "$work/build" --prefix "$work/prefix" >/dev/null
echo "-- the runtime alone: configured, built and installed in $((SECONDS - start)) s"
find "$work/prefix/lib/cmake/asperity" -type f -printf '   %f\n' | sort
cmake -S "$source_tree/tests/consumers/runtime" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/runtime_consumer" | tee "$work/consumer.out"
grep -q "^table $work/prefix/" "$work/consumer.out" || { echo "not the installed table"; exit 1; }
echo "-- runtime only: passed"
