#include "asperity/number_text.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <system_error>

namespace asperity {

std::size_t read_double_prefix(std::string_view text, double& value) {
  // from_chars takes no '+' (strtod does): allow one in front of a number.
  std::size_t sign = 0;
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    sign = 1;
    if (text.empty() || text.front() == '+' || text.front() == '-') return 0;
  }
  if (text.empty()) return 0;
  double parsed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (end == text.data()) return 0;
  if (error == std::errc::result_out_of_range) {
    // Syntax is valid and the magnitude is beyond the doubles: round as IEEE does. strtod on
    // a terminated copy tells overflow (HUGE_VAL) from underflow (0 or a subnormal).
    const std::string copy(text.data(), end);
    parsed = std::strtod(copy.c_str(), nullptr);
  } else if (error != std::errc()) {
    return 0;
  }
  value = parsed;
  return sign + static_cast<std::size_t>(end - text.data());
}

bool read_double(std::string_view text, double& value) {
  double parsed = 0;
  const std::size_t used = read_double_prefix(text, parsed);
  if (used == 0 || used != text.size()) return false;
  value = parsed;
  return true;
}

bool read_whole_number(std::string_view text, long long lo, long long hi, long long& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return false;
  long long parsed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (error != std::errc() || end != text.data() + text.size() || parsed < lo || parsed > hi) return false;
  value = parsed;
  return true;
}

std::string format_double(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string three_digits(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

std::string quote_text(std::string_view text, std::size_t limit) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (text.size() > limit) out += "...";
  return out;
}

std::string terminal_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t k = 0;
  const auto escape = [&](unsigned char c) {
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
    out += escaped;
  };
  while (k < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[k]);
    if (c < 0x80) {
      if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) escape(c);
      else out += static_cast<char>(c);
      ++k;
      continue;
    }
    // whole UTF-8 sequences only (no C1 controls, overlong forms, surrogates, beyond U+10FFFF)
    std::size_t length = 0;
    unsigned lo = 0x80, hi = 0xbf;
    if (c >= 0xc2 && c <= 0xdf) length = 2, lo = c == 0xc2 ? 0xa0 : 0x80;
    else if (c >= 0xe0 && c <= 0xef) length = 3, lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
    else if (c >= 0xf0 && c <= 0xf4) length = 4, lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
    bool valid = length > 0 && k + length <= text.size();
    for (std::size_t m = 1; valid && m < length; ++m) {
      const unsigned char d = static_cast<unsigned char>(text[k + m]);
      valid = m == 1 ? (d >= lo && d <= hi) : (d >= 0x80 && d <= 0xbf);
    }
    if (!valid) {
      escape(c);
      ++k;
      continue;
    }
    out.append(text.substr(k, length));
    k += length;
  }
  return out;
}

}  // namespace asperity
