// A result record defined once: an X-macro list of its fields, from which its struct's members,
// its field table (names, CSV columns, meanings: what the Python records, docstrings and the test
// against the C header, the Fortran module and the Python stubs read) and its writers are made.
//
// A record's list, FIELDS(X), calls X(type, name, column, meaning) per field, in member order:
// type the member's C++ type (a number, bool, std::string, an enum, std::optional of an enum, a
// fixed array such as double[2]), name the member (the same in every language), column its CSV
// column and JSON key (the unit in its name; nullptr: kept in memory, never written), meaning what
// it is and its unit. A field may give its default after the meaning, X(type, name, column,
// meaning, default) (with ASPERITY_RECORD_MEMBER_INIT; value-initialised without one). Then
//   struct Record { FIELDS(ASPERITY_RECORD_MEMBER) };   (or ASPERITY_RECORD_MEMBER_ZERO: = 0,
//                                                         ASPERITY_RECORD_MEMBER_INIT: {default})
//   ASPERITY_DEFINE_RECORD(Record, FIELDS)              (in namespace asperity)
// and RecordFields<Record>::fields, ::count, ::for_each(record, visit) and
// ::for_each_member(visit) (visit(field, &Record::member): the Python bindings') serve every
// writer: csv_header<Record>() and csv_row(record) here (numbers only), the topography's JSON
// (record_json.hpp: every kind above; an enum by its name, to_string's).
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

// Specialised per record by ASPERITY_DEFINE_RECORD: fields[], count, for_each(record, visit),
// which calls visit(field, member) per field in order, the member with its own type, and
// for_each_member(visit), which calls visit(field, &Record::member).
template <class Record>
struct RecordFields;

// Whether a record's list is defined (ASPERITY_DEFINE_RECORD) for a type: a nested record
template <class T, class = void>
struct is_record : std::false_type {};
template <class T>
struct is_record<T, std::void_t<decltype(RecordFields<T>::count)>> : std::true_type {};

// A member's type as the list spells it (an array type included: record_member_t<double[2]> name)
template <class T>
using record_member_t = T;

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

// X's arguments after the column: the meaning, then optionally the default (both picked without
// leaving "..." empty, which ISO C++17 does not allow)
#define ASPERITY_RECORD_MEANING(...) ASPERITY_RECORD_MEANING_(__VA_ARGS__, unused)
#define ASPERITY_RECORD_MEANING_(meaning, ...) meaning
#define ASPERITY_RECORD_DEFAULT(...) ASPERITY_RECORD_DEFAULT_(__VA_ARGS__, , unused)
#define ASPERITY_RECORD_DEFAULT_(meaning, value, ...) value

#define ASPERITY_RECORD_MEMBER(type, name, column, ...) ::asperity::record_member_t<type> name;
#define ASPERITY_RECORD_MEMBER_ZERO(type, name, column, ...) ::asperity::record_member_t<type> name = 0;
#define ASPERITY_RECORD_MEMBER_INIT(type, name, column, ...) \
  ::asperity::record_member_t<type> name{ASPERITY_RECORD_DEFAULT(__VA_ARGS__)};
#define ASPERITY_RECORD_FIELD_ENTRY(type, name, column, ...) \
  ::asperity::RecordField{#name, column, ASPERITY_RECORD_MEANING(__VA_ARGS__)},
#define ASPERITY_RECORD_VISIT_MEMBER(type, name, column, ...) visit(fields[k++], record.name);
#define ASPERITY_RECORD_VISIT_POINTER(type, name, column, ...) visit(fields[k++], &Type::name);
#define ASPERITY_DEFINE_RECORD(Record, FIELDS)                                  \
  template <>                                                                   \
  struct RecordFields<Record> {                                                 \
    using Type = Record;                                                        \
    static constexpr RecordField fields[] = {FIELDS(ASPERITY_RECORD_FIELD_ENTRY)}; \
    static constexpr std::size_t count = sizeof fields / sizeof fields[0];      \
    template <class Visited, class Visit>                                       \
    static void for_each(Visited& record, Visit&& visit) {                      \
      std::size_t k = 0;                                                        \
      FIELDS(ASPERITY_RECORD_VISIT_MEMBER)                                      \
      (void)k;                                                                  \
    }                                                                           \
    template <class Visit>                                                      \
    static void for_each_member(Visit&& visit) {                                \
      std::size_t k = 0;                                                        \
      FIELDS(ASPERITY_RECORD_VISIT_POINTER)                                     \
      (void)k;                                                                  \
    }                                                                           \
  };
