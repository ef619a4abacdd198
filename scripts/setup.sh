#!/usr/bin/env bash
# Set-up on a fresh Debian machine: installs what is missing with apt-get, configures and
# builds. Safe to run again (it only does what is not done yet).
#   BUILD_DIR (default build), BUILD_TYPE (default Release), CMAKE_ARGS: passed to CMake.
set -euo pipefail
cd "$(dirname "$0")/.."

packages="g++ gfortran cmake make libboost-dev libhdf5-dev pkg-config libgtest-dev libbenchmark-dev libtoml11-dev libssl-dev libcli11-dev libzip-dev libpugixml-dev libnlopt-dev nlohmann-json3-dev libhwy-dev"
# the Python module (pybind11 from Debian, no PyPI), its tests, its example and its benchmark
packages="$packages python3 python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib python3-scipy"
missing=""
for package in $packages; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing="$missing $package"
done
if [ -n "$missing" ]; then
  echo "installing:$missing" >&2
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >/dev/null
fi

build_dir="${BUILD_DIR:-build}"
# shellcheck disable=SC2086
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
