#!/usr/bin/env bash
# `pip install .` as a user runs it, without network or build isolation, with Debian's packages
# (ctest: python_pip_install): into a venv made with --system-site-packages, and into a system
# layout (pip --root: /usr/local/lib/python3.X/dist-packages under a temporary folder, the real
# system untouched); each checked from a folder outside the source and build trees by
# check_pip_install.py with that interpreter (the venv's own, the system's with PYTHONPATH).
#   usage: pip_install.sh PYTHON SOURCE_TREE BUILD_DIR TABLE
# BUILD_DIR keeps the build (ASPERITY_PIP_BUILD_DIR): the second install and later runs relink
# nothing. The source tree must be left as it was (setup.py builds elsewhere).
set -euo pipefail
python="$1" source_tree="$2" build_dir="$3" table="$4"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH ASPERITY_TABLE
export ASPERITY_PIP_BUILD_DIR="$build_dir" ASPERITY_DEFAULT_TABLE_SOURCE="$table"
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 PIP_ROOT_USER_ACTION=ignore
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
# what setuptools would leave in the source tree if setup.py let it build there
in_tree=(build-pip python/asperity.egg-info asperity.egg-info build/lib build/bdist.linux-x86_64)
existing=()
for path in "${in_tree[@]}"; do [ -e "$source_tree/$path" ] && existing+=("$path"); done
mkdir "$work/elsewhere"
cp "$here/check_pip_install.py" "$work/elsewhere/"

echo "-- a venv (--system-site-packages), its own interpreter"
"$python" -m venv --system-site-packages "$work/venv"
SECONDS=0
"$work/venv/bin/python" -m pip install --no-build-isolation --no-deps "$source_tree"
echo "-- pip install into the venv: $SECONDS s"
(cd "$work/elsewhere" && "$work/venv/bin/python" check_pip_install.py "$work/venv")

echo "-- the system's layout (pip --root), the system's interpreter"
SECONDS=0
"$python" -m pip install --no-build-isolation --no-deps --root "$work/root" "$source_tree"
echo "-- pip install --root: $SECONDS s"
site="$(find "$work/root" -type d \( -name dist-packages -o -name site-packages \) | head -1)"
[ -d "$site/asperity" ] || { echo "no asperity under $work/root"; find "$work/root" | head -20; exit 1; }
(cd "$work/elsewhere" && PYTHONPATH="$site" "$python" check_pip_install.py "$work/root")

for path in "${in_tree[@]}"; do
  if [ -e "$source_tree/$path" ] && [[ " ${existing[*]-} " != *" $path "* ]]; then
    echo "pip install left $source_tree/$path in the source tree"
    exit 1
  fi
done
echo "-- both installs import and answer from outside the source tree"
