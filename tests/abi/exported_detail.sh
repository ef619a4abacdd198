#!/bin/sh
# The runtime exports nothing of asperity::detail but the named set of cmake/asperity.map (each
# there with the caller that needs it): no type information or virtual table of detail, and of
# detail's functions exactly the names below. Usage: exported_detail.sh LIBRARY [NM] [CXXFILT]
set -eu
library=$1
nm=${2:-nm}
cxxfilt=${3:-c++filt}
expected='asperity::detail::InheritInterrupt::InheritInterrupt
asperity::detail::InheritInterrupt::~InheritInterrupt
asperity::detail::SegmentMap::resolve
asperity::detail::contact_at_checked
asperity::detail::current_interrupt_state
asperity::detail::no_contact_products
asperity::detail::no_curve_value'
# each defined dynamic symbol's demangled name, without its address, type and version
symbols=$("$nm" -D --defined-only "$library" | "$cxxfilt" | sed -e 's/^[0-9a-fA-F]* [A-Za-z] //' -e 's/@.*//')
found=$(printf '%s\n' "$symbols" | grep '^asperity::detail::' | sed -e 's/[[(].*//' | sort -u || true)
tables=$(printf '%s\n' "$symbols" | grep -E '^(typeinfo|typeinfo name|vtable|VTT|construction vtable) for asperity::detail::' || true)
status=0
if [ "$found" != "$expected" ]; then
  echo "exported from asperity::detail (cmake/asperity.map names the allowed set):" >&2
  printf '%s\n' "$found" | diff -u /dev/fd/3 - 3<<EXPECTED >&2 || true
$expected
EXPECTED
  status=1
fi
if [ -n "$tables" ]; then
  echo "type information or virtual tables of asperity::detail exported:" >&2
  printf '%s\n' "$tables" >&2
  status=1
fi
[ "$status" -eq 0 ] && echo "asperity::detail: only the named set exported ($(printf '%s\n' "$found" | wc -l) names)"
exit "$status"
