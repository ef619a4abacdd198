// A result record's JSON object, made from its list (asperity/record_fields.hpp): one key a
// written field (its column), the member's own type (integers stay integers); JSON has no NaN or
// infinity: null for those. The topography's JSON writers use it (nlohmann::json stays here: the
// runtime, where the lists are, does not depend on it).
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "asperity/record_fields.hpp"

namespace asperity::topography {

template <class Json = nlohmann::json, class Record>
Json record_json(const Record& record) {
  Json object = Json::object();
  RecordFields<Record>::for_each(record, [&](const RecordField& field, const auto& value) {
    if (!field.column) return;
    if constexpr (std::is_floating_point_v<std::decay_t<decltype(value)>>)
      object[field.column] = std::isfinite(value) ? Json(value) : Json(nullptr);
    else
      object[field.column] = value;
  });
  return object;
}

}  // namespace asperity::topography
