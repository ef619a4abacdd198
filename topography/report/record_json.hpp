// A result record's JSON object, made from its list (asperity/record_fields.hpp): one key a
// written field (its column), the member's own type (integers stay integers, bools bools); JSON has
// no NaN or infinity: null for those; an enum by its name (to_string's, found beside the enum), an
// optional enum by its name or "" (none), a fixed array or a vector as an array (a vector of records:
// an array of their objects), a nested record as its object, a model's surface (asperity::
// RoughSurface) as rough_surface_json writes it.
// The topography's JSON writers use it (nlohmann::json stays here: the runtime, where the lists
// are, does not depend on it).
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <type_traits>
#include <vector>

#include "asperity/record_fields.hpp"
#include "asperity/surface.hpp"

namespace asperity::topography {

template <class T>
struct is_optional_value : std::false_type {};
template <class T>
struct is_optional_value<std::optional<T>> : std::true_type {};

template <class T>
struct is_vector_value : std::false_type {};
template <class T, class Allocator>
struct is_vector_value<std::vector<T, Allocator>> : std::true_type {};

template <class Json, class Record>
void add_record_json(Json& object, const Record& record);

// A model's rough surface: its distribution and side by name, its Weibull shape (null for a
// Gaussian, which has none), its height scale, summit radius and density
template <class Json>
Json rough_surface_json(const RoughSurface& surface) {
  const auto number = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json object = Json::object();
  object["distribution"] = to_string(surface.distribution);
  object["side"] = to_string(surface.side);
  object["shape"] = number(surface.distribution == Distribution::weibull ? surface.shape : NAN);
  object["height_scale_m"] = number(surface.height_scale);
  object["summit_radius_m"] = number(surface.summit_radius);
  object["summit_density_per_m2"] = number(surface.summit_density);
  return object;
}

// A member of a kind that has a JSON form (a field kept in memory only may have none; a vector
// has one where its elements have)
template <class Json, class T>
struct json_writable_type
    : std::bool_constant<std::is_arithmetic_v<T> || std::is_enum_v<T> || is_optional_value<T>::value ||
                         std::is_array_v<T> || is_record<T>::value || std::is_same_v<T, RoughSurface> ||
                         std::is_constructible_v<Json, const T&>> {};
template <class Json, class T, class Allocator>
struct json_writable_type<Json, std::vector<T, Allocator>> : json_writable_type<Json, T> {};
template <class Json, class T>
constexpr bool json_writable = json_writable_type<Json, T>::value;

// One field's value as JSON
template <class Json, class T>
Json record_value_json(const T& value) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isfinite(value) ? Json(value) : Json(nullptr);
  } else if constexpr (std::is_enum_v<T>) {
    return Json(to_string(value));
  } else if constexpr (is_optional_value<T>::value) {
    return value ? record_value_json<Json>(*value) : Json("");
  } else if constexpr (std::is_array_v<T>) {
    Json array = Json::array();
    for (const auto& element : value) array.push_back(record_value_json<Json>(element));
    return array;
  } else if constexpr (is_vector_value<T>::value) {
    Json array = Json::array();
    for (const auto& element : value) array.push_back(record_value_json<Json, typename T::value_type>(element));
    return array;
  } else if constexpr (std::is_same_v<T, RoughSurface>) {
    return rough_surface_json<Json>(value);
  } else if constexpr (is_record<T>::value) {
    Json object = Json::object();
    add_record_json(object, value);
    return object;
  } else {
    return Json(value);
  }
}

// The record's written fields appended to a JSON object, in the list's order: where a writer
// composes an object of a record and keys of its own
template <class Json, class Record>
void add_record_json(Json& object, const Record& record) {
  RecordFields<Record>::for_each(record, [&](const RecordField& field, const auto& value) {
    using T = std::remove_cv_t<std::remove_reference_t<decltype(value)>>;
    if constexpr (json_writable<Json, T>)
      if (field.column) object[field.column] = record_value_json<Json, T>(value);
  });
}

template <class Json = nlohmann::json, class Record>
Json record_json(const Record& record) {
  Json object = Json::object();
  add_record_json(object, record);
  return object;
}

}  // namespace asperity::topography
