# Sourced by the report scripts: they need Debian's python3-matplotlib for /usr/bin/python3.
# Nothing is installed here: the script says what is missing and stops.
if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  echo "$(basename "$0"): needs matplotlib for /usr/bin/python3; install it with" >&2
  echo "  sudo apt-get install python3-matplotlib" >&2
  exit 1
fi
