#!/bin/sh
# A shared library exports nothing of its internals but a named set, each there with the caller
# that needs it: no type information or virtual table of them, and of their functions exactly the
# names below. Usage: exported_detail.sh LIBRARY [NM] [CXXFILT] [runtime|topography]
#   runtime     libasperity: asperity::detail, cmake/asperity.map's named set (the default)
#   topography  libasperity_topography: asperity::topography::detail and ::verdict, none
#               (topography/topography.map)
set -eu
library=$1
nm=${2:-nm}
cxxfilt=${3:-c++filt}
which=${4:-runtime}
case $which in
  runtime)
    internal='asperity::detail::' label='asperity::detail'
    map=cmake/asperity.map
    expected='asperity::detail::InheritInterrupt::InheritInterrupt
asperity::detail::InheritInterrupt::~InheritInterrupt
asperity::detail::SegmentMap::resolve
asperity::detail::contact_at_checked
asperity::detail::current_interrupt_state
asperity::detail::no_contact_products
asperity::detail::no_curve_value' ;;
  topography)
    internal='asperity::topography::(detail|verdict)::' label='asperity::topography::detail and ::verdict'
    map=topography/topography.map
    expected='' ;;
  *) echo "exported_detail.sh: runtime or topography, not '$which'" >&2; exit 2 ;;
esac
# each defined dynamic symbol's demangled name, without its address, type and version
symbols=$("$nm" -D --defined-only "$library" | "$cxxfilt" | sed -e 's/^[0-9a-fA-F]* [A-Za-z] //' -e 's/@.*//')
found=$(printf '%s\n' "$symbols" | grep -E "^($internal)" | sed -e 's/[[(].*//' | sort -u || true)
tables=$(printf '%s\n' "$symbols" | grep -E "^(typeinfo|typeinfo name|vtable|VTT|construction vtable) for ($internal)" || true)
status=0
if [ "$found" != "$expected" ]; then
  echo "exported from $label ($map names the allowed set):" >&2
  printf '%s\n' "$found" | diff -u /dev/fd/3 - 3<<EXPECTED >&2 || true
$expected
EXPECTED
  status=1
fi
if [ -n "$tables" ]; then
  echo "type information or virtual tables of $label exported:" >&2
  printf '%s\n' "$tables" >&2
  status=1
fi
count=$(printf '%s' "$found" | grep -c . || true)
[ "$status" -eq 0 ] && echo "$label: only the named set exported ($count names)"
exit "$status"
