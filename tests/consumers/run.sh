#!/usr/bin/env bash
# Programs using an installed asperity from outside, against PREFIX only (CI: .ci/run):
#   a C++ project through find_package (asperity::runtime, and asperity::topography reading a
#   measured surface), a C program through pkg-config with cc, a Fortran
#   program through pkg-config with gfortran, and the Python module from its installed place.
# Each checks a value against a closed form and that the default table it found is PREFIX's.
#   usage: tests/consumers/run.sh PREFIX [SOURCE_TREE]
# With SOURCE_TREE the source (and the build tree inside it) is renamed away while they run,
# so that nothing can come from there; it is renamed back on exit.
set -euo pipefail
prefix="$(cd "$1" && pwd -P)"
source_tree="${2:-}"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
cp -r "$here"/cxx "$here"/c "$here"/fortran "$here"/python "$work"/
cp "$here"/../data/surfaces/digitalsurf-650x650.x3p "$work"/surface.x3p  # the source tree goes away

restore() {
  if [ -n "$source_tree" ] && [ -d "$source_tree.away" ]; then mv "$source_tree.away" "$source_tree"; fi
  rm -rf "$work"
}
trap restore EXIT
if [ -n "$source_tree" ]; then
  source_tree="$(cd "$source_tree" && pwd -P)"
  mv "$source_tree" "$source_tree.away"
fi
cd "$work"
unset ASPERITY_TABLE
export PKG_CONFIG_PATH="$(dirname "$(find "$prefix" -name asperity.pc | head -1)")"
libdir="$(pkg-config --variable=libdir asperity)"
static=""   # a static libasperity: its users link HDF5 and the C++ runtime too
compgen -G "$libdir/libasperity.so*" >/dev/null || static="--static"

check_table() {  # the program's output names the table it used: it must be the installed one
  grep -q "^table $prefix/" "$1" || { echo "not the installed table:"; cat "$1"; exit 1; }
}

echo "-- C++ (find_package(asperity 0.2), asperity::runtime, asperity::topography)"
cmake -S cxx -B cxx/build -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build cxx/build >/dev/null
cxx/build/cxx_consumer surface.x3p | tee cxx.out
check_table cxx.out

echo "-- C (cc \$(pkg-config --cflags --libs asperity))"
# shellcheck disable=SC2046
cc -std=c99 -Wall -Wextra -o c_consumer c/main.c $(pkg-config $static --cflags --libs asperity) -lm -Wl,-rpath,"$libdir"
./c_consumer

if command -v gfortran >/dev/null && [ -f "$(pkg-config --variable=includedir asperity)/asperity.mod" ]; then
  echo "-- Fortran (gfortran \$(pkg-config --cflags --libs asperity), use asperity)"
  # shellcheck disable=SC2046
  gfortran -o fortran_consumer fortran/main.f90 $(pkg-config $static --cflags --libs asperity) -Wl,-rpath,"$libdir"
  ./fortran_consumer
fi

pythondir="$(pkg-config --variable=pythondir asperity || true)"
if [ -n "$pythondir" ]; then
  echo "-- Python (import asperity from $pythondir)"
  PYTHONPATH="$pythondir" "$(pkg-config --variable=python asperity)" python/check_installed.py "$prefix" surface.x3p | tee python.out
  check_table python.out
fi
echo "-- all consumers passed"
