#!/usr/bin/env bash
# `pip install .` as users run it, offline (ctest: python_pip_install), with the build backend
# python/packaging/asperity_build.py:
#  1. what is missing is named in one line before building: numpy hidden by a shadow module that
#     raises ImportError makes pip stop with "asperity needs numpy for PYTHON", no traceback; the
#     lines for pybind11, Python.h, CMake and an old Python checked on the backend's function;
#  2. a venv made with --system-site-packages, plain `pip install .` (build isolation, numpy from
#     the system's packages as pip's dependency);
#  3. the system's interpreter with setuptools and wheel hidden (they are not needed) into a system
#     layout (pip --root: /usr/local/lib/python3.X/dist-packages under a temporary folder, the real
#     system untouched) and into a --target folder;
# each installed package checked from a folder outside the source and build trees by
# check_pip_install.py with that interpreter.
#   usage: pip_install.sh PYTHON SOURCE_TREE BUILD_DIR [TABLE]
# BUILD_DIR keeps the build (ASPERITY_PIP_BUILD_DIR): later installs rebuild nothing. TABLE, when
# given, is the default table to copy (else the backend's own default: build/tables/ in the source
# tree, or tablegen). The source tree must be left as it was (the backend builds in BUILD_DIR).
set -euo pipefail
python="$1" source_tree="$2" build_dir="$3" table="${4-}"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH ASPERITY_TABLE
export ASPERITY_PIP_BUILD_DIR="$build_dir"
[ -n "$table" ] && export ASPERITY_DEFAULT_TABLE_SOURCE="$table"
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 PIP_ROOT_USER_ACTION=ignore
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
# The install is tested, not the module's speed: built without optimization (-O0 compiles the module
# and its libraries in about half the time of the backend's Release -O3; the flags after the
# backend's own, so they win).
export ASPERITY_CMAKE_ARGS="${ASPERITY_CMAKE_ARGS-} -DCMAKE_CXX_FLAGS_RELEASE=-O0 -DCMAKE_C_FLAGS_RELEASE=-O0"
# what a build would leave in the source tree if it built there
in_tree=(build-pip python/asperity.egg-info asperity.egg-info build/lib build/bdist.linux-x86_64
         python/packaging/__pycache__)
existing=()
for path in "${in_tree[@]}"; do [ -e "$source_tree/$path" ] && existing+=("$path"); done
mkdir "$work/elsewhere" "$work/shadow"
cp "$here/check_pip_install.py" "$work/elsewhere/"

echo "-- 1. a missing module named in one line before building"
for module in numpy setuptools wheel; do
  echo "raise ImportError('$module hidden by pip_install.sh')" > "$work/shadow/$module.py"
done
if PYTHONPATH="$work/shadow" "$python" -m pip install --no-build-isolation --no-deps --target "$work/none" \
     "$source_tree" > "$work/missing.log" 2>&1; then
  echo "pip install succeeded with numpy hidden"; cat "$work/missing.log"; exit 1
fi
grep -q "^ *asperity needs numpy for .*: install python3-numpy (Debian) or \`.* -m pip install numpy\`$" "$work/missing.log" \
  || { echo "no line naming numpy:"; cat "$work/missing.log"; exit 1; }
! grep -q "Traceback\|Building wheel\|Configuring" "$work/missing.log" \
  || { echo "a traceback, or a build started:"; cat "$work/missing.log"; exit 1; }
grep "asperity needs" "$work/missing.log"
"$python" "$work/elsewhere/check_pip_install.py" --prerequisites "$source_tree/python/packaging"
rm "$work/shadow/numpy.py"

echo "-- 2. a venv (--system-site-packages), its own interpreter, plain pip install (build isolation)"
"$python" -m venv --system-site-packages "$work/venv"
SECONDS=0
"$work/venv/bin/python" -m pip install "$source_tree"
echo "-- pip install into the venv: $SECONDS s"
(cd "$work/elsewhere" && "$work/venv/bin/python" check_pip_install.py "$work/venv")

echo "-- 3. the system's interpreter, setuptools and wheel hidden: the system's layout (pip --root)"
SECONDS=0
PYTHONPATH="$work/shadow" "$python" -m pip install --no-build-isolation --no-deps --root "$work/root" "$source_tree"
echo "-- pip install --root: $SECONDS s"
site="$(find "$work/root" -type d \( -name dist-packages -o -name site-packages \) | head -1)"
[ -d "$site/asperity" ] || { echo "no asperity under $work/root"; find "$work/root" | head -20; exit 1; }
(cd "$work/elsewhere" && PYTHONPATH="$site" "$python" check_pip_install.py "$work/root")
echo "-- and into a --target folder"
SECONDS=0
PYTHONPATH="$work/shadow" "$python" -m pip install --no-build-isolation --no-deps --target "$work/target" "$source_tree"
echo "-- pip install --target: $SECONDS s"
(cd "$work/elsewhere" && PYTHONPATH="$work/target" "$python" check_pip_install.py "$work/target")

for path in "${in_tree[@]}"; do
  if [ -e "$source_tree/$path" ] && [[ " ${existing[*]-} " != *" $path "* ]]; then
    echo "pip install left $source_tree/$path in the source tree"
    exit 1
  fi
done
echo "-- every install imports and answers from outside the source tree"
