// Writing a table file (schema in asperity/table_schema.hpp): deterministic bytes for the
// same data (no timestamps), written to a temporary file and renamed into place, so a crash
// never leaves a half-written table at the target.
#pragma once
#include <string>

#include "asperity/table.hpp"

namespace asperity::tablegen {

void write_table_file(const TableData& table, const std::string& path);

}  // namespace asperity::tablegen
