#include "replace_file.hpp"

#include "asperity/output.hpp"

namespace asperity {

// The output policy's one-file write, for any regular file the caller names.
void replace_file(const std::string& path, const void* data, std::size_t size) {
  try {
    write_output_file(path, {static_cast<const char*>(data), size}, output_kinds::any_file, false, "writing the table");
  } catch (const Interrupted&) {
    throw;
  } catch (const Error& error) {
    throw Error(std::string("writing the table failed: ") + error.what());
  }
}

}  // namespace asperity
