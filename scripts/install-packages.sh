#!/usr/bin/env bash
# Installs the Debian packages named on the command line that are not installed yet (apt-get,
# with sudo when not root); does nothing when all are there. Used by setup.sh and fuzz/run.sh.
#   bash scripts/install-packages.sh PACKAGE...
set -euo pipefail
missing=""
for package in "$@"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing="$missing $package"
done
[ -z "$missing" ] && exit 0
echo "installing:$missing" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
$sudo apt-get update -qq
# shellcheck disable=SC2086
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >/dev/null
