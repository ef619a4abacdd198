// libFuzzer target: a table file's raw bytes (read_table_bytes). Whatever the bytes: a
// TableFileError with a message, or a table whose lookups hold; no crash, no sanitizer report.
// Mutated bytes fail the integrity check (a SHA-256), so this target covers what runs before
// HDF5: the header and the way out; fuzz_table_contents covers what comes after.
#include <cstddef>
#include <cstdint>

#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "tiny_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const asperity::Table table(asperity::read_table_bytes(data, size, "fuzz"));
    asperity::fuzz::exercise(table);
  } catch (const asperity::Error&) {
  }
  return 0;
}
