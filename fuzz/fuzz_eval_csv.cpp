// libFuzzer target: `asperity eval`'s CSV reader (apps/asperity/eval_csv.hpp) over a tiny table
// in memory. Whatever the bytes: rows out, bad rows named; no crash, no sanitizer report.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "asperity/error.hpp"
#include "eval_csv.hpp"
#include "tiny_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const asperity::Table table(asperity::fuzz::tiny_table());
  std::istringstream input(std::string(reinterpret_cast<const char*>(data), size));
  std::ostringstream output, errors;
  try {
    asperity::cli::eval_csv(table, input, output, errors);
  } catch (const asperity::Error&) {
  }
  return 0;
}
