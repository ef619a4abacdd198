// Numbers as text: the project's one strict number reader and one writer (the commands' options
// and CSV, the surface files' numbers and lengths with units, the scene checks). A double is read
// from all of its text and rounded once (std::from_chars), and written in the shortest form that
// reads back to the same double (std::to_chars), so that what a command echoes is what it read.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace asperity {

// True if `text` is one decimal number and nothing else (an optional leading '+', digits, a
// point, an exponent; also "nan", "inf"). A value beyond the doubles rounds as IEEE does: to
// +-inf above DBL_MAX, to +-0 below the smallest subnormal. False (value untouched) for
// anything else: empty text, spaces, trailing bytes (an embedded NUL too), hexadecimal.
bool read_double(std::string_view text, double& value);

// The same number at the start of `text` (a length before its unit: "1.5um"): how many bytes
// it took, 0 (value untouched) where `text` does not start with one.
std::size_t read_double_prefix(std::string_view text, double& value);

// True if `text` is a whole number in decimal digits (optional sign) within [lo, hi].
bool read_whole_number(std::string_view text, long long lo, long long hi, long long& value);

// The shortest text that reads back to exactly `value` ("1.6", "1e-300", "-inf", "nan").
std::string format_double(double value);

// Three significant digits ("%.3g": "0.0244", "5.54", "1.1e-24"): a figure in a sentence, where
// format_double would give the full 17.
std::string three_digits(double value);

// `text` made safe to quote in a message: control bytes shown as \xNN, cut after `limit` bytes.
std::string quote_text(std::string_view text, std::size_t limit = 60);

// A message made safe for a terminal: newlines and tabs kept, valid UTF-8 kept (µm), every other
// control byte (an escape sequence from a file's bytes), DEL, C1 controls and bytes that are not
// UTF-8 shown as \xNN.
std::string terminal_text(std::string_view text);

}  // namespace asperity
