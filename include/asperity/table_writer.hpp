// Writing a table file (format in docs/reliability.md): the HDF5 file is built in memory
// with a 512-byte user block, the integrity header (SHA-256 of the rest) put in that block, and
// the bytes written under the output policy (asperity/output.hpp): a crash never leaves a
// half-written table at the target, and a file that is not such a table is replaced only with
// `overwrite`. Deterministic: the same data give the same bytes (no timestamps).
#pragma once
#include <string>
#include <vector>

#include "asperity/table.hpp"

namespace asperity {

// The whole table file's bytes. Throws asperity::Error for data that CurveSet::validate refuses
// or text too long for an attribute.
std::vector<unsigned char> table_file_bytes(const TableData& table);

void write_table_file(const TableData& table, const std::string& path, bool overwrite = false);

}  // namespace asperity
