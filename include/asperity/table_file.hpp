// Table files on disk: why one could not be opened, and the integrity header that every table
// file carries (layout in table_schema.hpp, trust model in docs/reliability.md).
//
// A table is read whole with plain file reads, its SHA-256 checked against the header, and only
// then handed to HDF5 (from memory, so the bytes checked are the bytes parsed).
#pragma once
#include <cstddef>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

// Why a table file was refused; each has its own message too.
enum class TableFileStatus {
  missing,        // no such file
  unreadable,     // not a regular file (a directory, FIFO, device), no permission, a read error
  not_hdf5,       // neither an asperity table nor any HDF5 file
  other_schema,   // an HDF5 file, but not an asperity table
  other_version,  // an asperity table of another format version (regenerate it)
  damaged,        // the integrity header does not match the bytes: truncated, extended or changed
  invalid,        // intact, but its contents break the schema (types, sizes, limits, values)
};
const char* to_string(TableFileStatus status) noexcept;

// The asperity::Error of a refused table file, with the reason as a value.
class TableFileError : public Error {
 public:
  TableFileError(TableFileStatus status, const std::string& message) : Error(message), status_(status) {}
  TableFileStatus status() const noexcept { return status_; }

 private:
  TableFileStatus status_;
};

// The table format this library reads and writes: its schema name ("asperity-table") and
// version (table_schema.hpp, the format's internals, defines them), for --version texts.
const char* table_schema_name() noexcept;
int table_schema_version() noexcept;

// What a table file holds (table_schema.hpp): Greenwood-Williamson integrals (Table, table.hpp)
// or contact curves against separation (ContactCurves, contact_curves.hpp).
enum class TableKind { integrals, contact_curves };
const char* to_string(TableKind kind) noexcept;
// The kind of a table file, after its integrity header is checked. Throws TableFileError as
// reading it would for a file that is no table (missing, damaged, another schema or version,
// an unknown kind: invalid).
TableKind read_table_kind(const std::string& path);

// Fills the first schema::header_bytes of a table file's bytes (an HDF5 file made with a user
// block of that size) with the integrity header of the rest. Throws Error if size is too small.
void seal_table_bytes(unsigned char* bytes, std::size_t size);

// Checks the integrity header of a whole file's bytes; throws TableFileError (naming `name`)
// unless the header is present, of this format version, and matches the bytes after it.
void verify_table_bytes(const unsigned char* bytes, std::size_t size, const std::string& name);

}  // namespace asperity
