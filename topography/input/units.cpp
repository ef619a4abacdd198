#include "asperity/topography/units.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
std::string_view trimmed(std::string_view text) {
  const char* blanks = " \t\r\n";
  const std::size_t first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}
}  // namespace

double length_unit_in_metres(std::string_view unit) {
  const std::string_view u = trimmed(unit);
  if (u == "m") return 1;
  if (u == "km") return 1e3;
  if (u == "dm") return 1e-1;
  if (u == "cm") return 1e-2;
  if (u == "mm") return 1e-3;
  // micro: ASCII u, MICRO SIGN U+00B5 (C2 B5), GREEK SMALL LETTER MU U+03BC (CE BC)
  if (u == "um" || u == "\xC2\xB5m" || u == "\xCE\xBCm" || u == "micron" || u == "microns") return 1e-6;
  if (u == "nm") return 1e-9;
  if (u == "pm") return 1e-12;
  // angstrom: A, Å (U+00C5, C3 85) or ANGSTROM SIGN U+212B (E2 84 AB)
  if (u == "A" || u == "\xC3\x85" || u == "\xE2\x84\xAB" || u == "angstrom") return 1e-10;
  throw Error("unknown length unit '" + detail::printable(u) + "' (m, mm, um, nm, pm, A, ...)");
}

double parse_length(std::string_view text, std::string_view default_unit) {
  const std::string_view t = trimmed(text);
  double value = 0;
  const std::size_t used = read_double_prefix(t, value);
  if (used == 0 || !std::isfinite(value)) throw Error("not a length: '" + detail::printable(text) + "'");
  const std::string_view unit = trimmed(t.substr(used));
  if (unit.empty()) {
    if (default_unit.empty()) throw Error("a length needs its unit: '" + detail::printable(text) + "' (e.g. 1.5um)");
    return value * length_unit_in_metres(default_unit);
  }
  return value * length_unit_in_metres(unit);
}

}  // namespace asperity::topography
