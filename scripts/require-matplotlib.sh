# Sourced by the report scripts: Debian's python3-matplotlib for /usr/bin/python3, installed
# here when missing and run as root.
if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-matplotlib >/dev/null
  else
    echo "$(basename "$0"): needs python3-matplotlib (apt-get install python3-matplotlib)" >&2
    exit 1
  fi
fi
