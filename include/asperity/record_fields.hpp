// A result record defined once: an X-macro list of its fields, from which its struct's members,
// its field table (names, CSV columns, meanings: what the Python records, docstrings and the test
// against the C header, the Fortran module and the Python stubs read) and its writers are made.
//
// A record's list, FIELDS(X), calls X(type, name, column, meaning) per field, in member order:
// type the member's C++ type (double, std::size_t, int), name the member (the same in every
// language), column its CSV column and JSON key (the unit in its name; nullptr: kept in memory,
// never written), meaning what it is and its unit. Then
//   struct Record { FIELDS(ASPERITY_RECORD_MEMBER) };   (or ASPERITY_RECORD_MEMBER_ZERO: = 0)
//   ASPERITY_DEFINE_RECORD(Record, FIELDS)              (in namespace asperity)
// and RecordFields<Record>::fields, ::count and ::for_each(record, visit) serve every writer:
// csv_header<Record>() and csv_row(record) here, the topography's JSON (record_json.hpp).
#pragma once
#include <cstddef>
#include <string>
#include <type_traits>

#include "asperity/number_text.hpp"

namespace asperity {

struct RecordField {
  const char* name;     // the member's name, in every language
  const char* column;   // the CSV column and JSON key (nullptr: not written)
  const char* meaning;  // what it is, its unit
};

// Specialised per record by ASPERITY_DEFINE_RECORD: fields[], count, and for_each(record, visit),
// which calls visit(field, member) per field in order, the member with its own type.
template <class Record>
struct RecordFields;

// The CSV columns of a record's written fields (those with a column), comma-separated, no newline;
// the first `fields` written ones only where a writer leaves out trailing ones (a column a table may
// not have)
template <class Record>
std::string csv_header(std::size_t fields = RecordFields<Record>::count) {
  std::string header;
  std::size_t k = 0;
  for (const RecordField& field : RecordFields<Record>::fields)
    if (field.column && k++ < fields) header += (header.empty() ? "" : ",") + std::string(field.column);
  return header;
}

// One CSV row (no newline) of the same columns: reals through format_real (default: the shortest
// text that reads back, format_double), integers in decimal
template <class Record, class FormatReal>
std::string csv_row(const Record& record, FormatReal format_real, std::size_t fields = RecordFields<Record>::count) {
  std::string row;
  std::size_t k = 0;
  bool first = true;
  RecordFields<Record>::for_each(record, [&](const RecordField& field, const auto& value) {
    if (!field.column || k++ >= fields) return;
    if (!first) row += ",";
    first = false;
    if constexpr (std::is_floating_point_v<std::decay_t<decltype(value)>>) row += format_real(value);
    else row += std::to_string(value);
  });
  return row;
}
template <class Record>
std::string csv_row(const Record& record) {
  return csv_row(record, [](double value) { return format_double(value); });
}

}  // namespace asperity

#define ASPERITY_RECORD_MEMBER(type, name, column, meaning) type name;
#define ASPERITY_RECORD_MEMBER_ZERO(type, name, column, meaning) type name = 0;
#define ASPERITY_RECORD_FIELD_ENTRY(type, name, column, meaning) ::asperity::RecordField{#name, column, meaning},
#define ASPERITY_RECORD_VISIT_MEMBER(type, name, column, meaning) visit(fields[k++], record.name);
#define ASPERITY_DEFINE_RECORD(Record, FIELDS)                                  \
  template <>                                                                   \
  struct RecordFields<Record> {                                                 \
    static constexpr RecordField fields[] = {FIELDS(ASPERITY_RECORD_FIELD_ENTRY)}; \
    static constexpr std::size_t count = sizeof fields / sizeof fields[0];      \
    template <class Visited, class Visit>                                       \
    static void for_each(Visited& record, Visit&& visit) {                      \
      std::size_t k = 0;                                                        \
      FIELDS(ASPERITY_RECORD_VISIT_MEMBER)                                      \
      (void)k;                                                                  \
    }                                                                           \
  };
