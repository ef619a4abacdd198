// Length units as instruments and file formats write them, to metres.
#pragma once
#include <string_view>

namespace asperity::topography {

// The metres in one unit: "m", "dm", "cm", "mm", "um" / "µm" (U+00B5 or U+03BC), "nm", "pm",
// "A" / "Å" (angstrom), "km"; surrounding blanks ignored. Throws asperity::Error for anything
// else (never guesses: a wrong unit is a silently wrong answer by a power of ten).
double length_unit_in_metres(std::string_view unit);

// Parses a length given with its unit, "1.5um", "1.5 um", "2e-7 m"; a bare number needs
// default_unit (empty: an error). Throws asperity::Error for a bad number or unit.
double parse_length(std::string_view text, std::string_view default_unit = {});

}  // namespace asperity::topography
