// Small helpers the commands' option readers share (defined in command_line.cpp): one usage
// error, "not given" for numbers, comma lists, numbers in messages. A header of its own so that
// a file with an older private copy still builds beside it.
#pragma once
#include <string>
#include <vector>

namespace asperity::cli {

// A usage error (the command's --help is pointed at): CLI::ValidationError.
[[noreturn]] void usage(const std::string& message);

// A number option left at NaN was not given.
bool given(double value);

// `text` split at `separator`, empty parts kept ("a,,b," has four).
std::vector<std::string> split(const std::string& text, char separator);

// A comma-separated list of positive numbers, each read by the one reader; `name` (the
// option) names a refused part.
std::vector<double> positive_numbers(const std::string& text, const std::string& name);

// A derived number in a message: four significant digits are enough to act on.
std::string approximately(double value);

}  // namespace asperity::cli
