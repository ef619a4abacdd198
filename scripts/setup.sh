#!/usr/bin/env bash
# Set-up on a fresh Debian machine: installs what is missing with apt-get, configures and
# builds. Safe to run again (it only does what is not done yet).
#   BUILD_DIR (default build), BUILD_TYPE (default Release), CMAKE_ARGS: passed to CMake.
set -euo pipefail
cd "$(dirname "$0")/.."

# python3-pythran: the FFT of the surface analysis (pocketfft, header-only; topography/statistics/fft.hpp);
# librsvg2-bin and imagemagick: the tests render the report's SVG plots with both
# abigail-tools: abidiff, the ABI check between two builds of the runtime (tests/abi/abi_check.sh)
packages="g++ gfortran cmake make libboost-dev libhdf5-dev pkg-config libgtest-dev libbenchmark-dev libtoml11-dev libssl-dev libcli11-dev libzip-dev libpugixml-dev libnlopt-dev libnlopt-cxx-dev nlohmann-json3-dev python3-pythran librsvg2-bin imagemagick libhwy-dev abigail-tools"
# the Python module (pybind11 from Debian, no PyPI), its tests, its example and its benchmark;
# python3-dask and python3-distributed: asperity.batch, many surfaces on a Dask cluster
packages="$packages python3 python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib python3-scipy"
packages="$packages python3-dask python3-distributed"
# `pip install .` without network or build isolation (setup.py, pyproject.toml): pip, venv and the
# build backend setuptools with wheel, all Debian's
packages="$packages python3-pip python3-venv python3-setuptools python3-wheel"
# CalculiX (ccx), which the FE export test (tests/fe_export_calculix.py) runs the exported card in
packages="$packages calculix-ccx"
# shellcheck disable=SC2086
bash scripts/install-packages.sh $packages

build_dir="${BUILD_DIR:-build}"
# shellcheck disable=SC2086
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
