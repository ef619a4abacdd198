// A result record's Python attributes made from its list (asperity/record_fields.hpp): every field
// an attribute of its name with its meaning as the docstring, and the list itself as the class's
// _record_fields (name, JSON key or None, meaning), which asperity.topography.record_fields(cls)
// returns. A number, bool, string or nested record is read as itself, an enum bound in Python as
// its member (else by its name), an optional enum by its name or "" (none), a fixed array as a tuple,
// a vector of numbers as a new 1-d array (NumPy), another vector as a list. A field the class binds
// itself before (a conversion of its own: a vector of states as one record of arrays, a text that
// may not be UTF-8) is left as bound, its doc the list's meaning (record_meaning), and is listed.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "asperity/record_fields.hpp"

namespace asperity::python {

namespace record_detail {
template <class T>
struct optional_of {
  using type = void;
};
template <class T>
struct optional_of<std::optional<T>> {
  using type = T;
};
template <class T>
struct number_vector : std::false_type {};
template <class T, class Allocator>
struct number_vector<std::vector<T, Allocator>> : std::is_arithmetic<T> {};
}  // namespace record_detail

// A field's meaning from its record's list (the docstring of a field a binding converts itself)
template <class Record>
const char* record_meaning(const char* name) {
  for (const RecordField& field : RecordFields<Record>::fields)
    if (std::strcmp(field.name, name) == 0) return field.meaning;
  throw std::logic_error(std::string("record_meaning: no field ") + name);
}

// Every field of Record's list on cls: read-only, or read-write (writable: an input record's)
template <class Record, class... Options>
pybind11::class_<Record, Options...>& def_record_fields(pybind11::class_<Record, Options...>& cls,
                                                       bool writable = false) {
  namespace py = pybind11;
  py::list fields;
  RecordFields<Record>::for_each_member([&](const RecordField& field, auto member) {
    using T = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<const Record&>().*member)>>;
    using Optional = typename record_detail::optional_of<T>::type;
    fields.append(py::make_tuple(field.name, field.column ? py::object(py::str(field.column)) : py::object(py::none()),
                                 field.meaning));
    if (py::hasattr(cls, field.name)) return;  // bound by the caller, its own conversion
    if constexpr (record_detail::number_vector<T>::value) {
      cls.def_property_readonly(
          field.name,
          [member](const Record& record) {
            const T& values = record.*member;
            py::array_t<typename T::value_type> out(static_cast<py::ssize_t>(values.size()));
            std::copy(values.begin(), values.end(), out.mutable_data());
            return out;
          },
          field.meaning);
    } else if constexpr (std::is_array_v<T>) {
      cls.def_property_readonly(
          field.name,
          [member](const Record& record) {
            py::tuple values(std::extent_v<T>);
            for (std::size_t k = 0; k < std::extent_v<T>; ++k) values[k] = py::cast((record.*member)[k]);
            return values;
          },
          field.meaning);
    } else if constexpr (std::is_enum_v<Optional>) {
      cls.def_property_readonly(
          field.name,
          [member](const Record& record) {
            const T& value = record.*member;
            return value ? std::string(to_string(*value)) : std::string();
          },
          field.meaning);
    } else if constexpr (std::is_enum_v<T>) {
      if (py::detail::get_type_info(typeid(T))) {
        cls.def_readonly(field.name, member, field.meaning);
      } else {  // an enum Python has no type of: its name
        cls.def_property_readonly(
            field.name, [member](const Record& record) { return std::string(to_string(record.*member)); },
            field.meaning);
      }
    } else if (writable) {
      cls.def_readwrite(field.name, member, field.meaning);
    } else {
      cls.def_readonly(field.name, member, field.meaning);
    }
  });
  cls.attr("_record_fields") = py::tuple(fields);
  return cls;
}

}  // namespace asperity::python
