// Scene files: TOML read with toml11 (Debian's libtoml11-dev), which keeps every value's
// line, so each message can point at the key it is about. toml11 3.7 reads out of bounds on
// invalid UTF-8, recurses without bound into nested arrays and is quadratic in long lists:
// check_scene_text bounds all three before toml11 sees the text (fuzz/fuzz_scene.cpp).
#include "asperity/scene.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <toml.hpp>

#include "asperity/detail/regular_file.hpp"
#include "asperity/error.hpp"

namespace asperity {
namespace {

[[noreturn]] void fail_at(const toml::value& value, const std::string& message, const std::string& hint) {
  throw Error(toml::format_error("scene: " + message, value, hint));
}

double number(const toml::value& value, const std::string& key) {
  if (value.is_floating()) return value.as_floating();
  if (value.is_integer()) return static_cast<double>(value.as_integer());
  fail_at(value, "'" + key + "' must be a number", "here");
}

std::string text(const toml::value& value, const std::string& key) {
  if (!value.is_string()) fail_at(value, "'" + key + "' must be a string", "here");
  return value.as_string().str;
}

std::string name_text(const toml::value& value) {
  std::string name = text(value, "name");
  if (name.size() > scene_max_name_bytes)
    fail_at(value, "a name has at most " + std::to_string(scene_max_name_bytes) + " bytes", "too long");
  return name;
}

// The checks toml11 needs before it parses (see the top of this file).
void check_scene_text(const std::string& content, const std::string& source) {
  auto fail = [&](std::size_t at, const std::string& what) {
    const long line = 1 + std::count(content.begin(), content.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    throw Error("scene " + source + ": line " + std::to_string(line) + ": " + what);
  };
  if (content.size() > scene_max_bytes)
    throw Error("scene " + source + ": " + std::to_string(content.size()) + " bytes; a scene file has at most " +
                std::to_string(scene_max_bytes));
  const auto* bytes = reinterpret_cast<const unsigned char*>(content.data());
  const std::size_t size = content.size();
  for (std::size_t i = 0; i < size;) {
    const unsigned lead = bytes[i];
    if (lead < 0x80) {
      if ((lead < 0x20 && lead != '\t' && lead != '\n' && lead != '\r') || lead == 0x7F)
        fail(i, "a control character (byte " + std::to_string(lead) + "); scene files are text");
      ++i;
      continue;
    }
    // UTF-8: the length from the lead byte, continuation bytes, no overlong form, no surrogate.
    const int length = lead >= 0xC2 && lead <= 0xDF   ? 2
                       : lead >= 0xE0 && lead <= 0xEF ? 3
                       : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                      : 0;
    bool valid = length > 0 && i + static_cast<std::size_t>(length) <= size;
    unsigned code = length == 2 ? lead & 0x1F : length == 3 ? lead & 0x0F : lead & 0x07;
    for (int k = 1; valid && k < length; ++k) {
      valid = (bytes[i + k] & 0xC0) == 0x80;
      code = code << 6 | (bytes[i + k] & 0x3F);
    }
    valid = valid && !(length == 3 && code < 0x800) && !(length == 4 && (code < 0x10000 || code > 0x10FFFF)) &&
            !(code >= 0xD800 && code <= 0xDFFF);
    if (!valid) fail(i, "not valid UTF-8 (byte " + std::to_string(lead) + ")");
    i += static_cast<std::size_t>(length);
  }
  // Nesting and list length, outside comments and strings.
  enum { plain, comment, basic, literal, multiline_basic, multiline_literal } state = plain;
  int depth = 0, commas = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const char c = content[i];
    const bool triple_quote = content.compare(i, 3, "\"\"\"") == 0, triple_apostrophe = content.compare(i, 3, "'''") == 0;
    switch (state) {
      case plain:
        if (c == '#') {
          state = comment;
        } else if (triple_quote || triple_apostrophe) {
          state = triple_quote ? multiline_basic : multiline_literal;
          i += 2;
        } else if (c == '"' || c == '\'') {
          state = c == '"' ? basic : literal;
        } else if (c == '[' || c == '{') {
          if (++depth > scene_max_nesting)
            fail(i, "lists or tables nested deeper than " + std::to_string(scene_max_nesting));
        } else if (c == ']' || c == '}') {
          depth = depth > 0 ? depth - 1 : 0;
        } else if (c == ',' && ++commas > scene_max_list_entries) {
          fail(i, "more than " + std::to_string(scene_max_list_entries) + " list entries in a scene file");
        }
        break;
      case comment:
        if (c == '\n') state = plain;
        break;
      case basic:
        if (c == '\\') ++i;
        else if (c == '"' || c == '\n') state = plain;
        break;
      case literal:
        if (c == '\'' || c == '\n') state = plain;
        break;
      case multiline_basic:
        if (c == '\\') {
          ++i;
        } else if (triple_quote) {
          state = plain;
          i += 2;
        }
        break;
      case multiline_literal:
        if (triple_apostrophe) {
          state = plain;
          i += 2;
        }
        break;
    }
  }
}

void check_keys(const toml::value& table, const std::set<std::string>& allowed, const std::string& where) {
  for (const auto& [key, value] : table.as_table())
    if (!allowed.count(key)) {
      std::string list;
      for (const std::string& name : allowed) list += (list.empty() ? "" : ", ") + name;
      fail_at(value, "unknown key '" + key + "' in " + where + " (known: " + list + ")", "not a scene key");
    }
}

const toml::value* entry_of(const toml::value& table, const std::string& key) {
  const auto& entries = table.as_table();
  const auto found = entries.find(key);
  return found == entries.end() ? nullptr : &found->second;
}

double tolerance(const toml::value& value) {
  const double tolerance = number(value, "max_rel_error");
  if (!(tolerance >= scene_error_min && tolerance <= scene_error_max)) {
    std::ostringstream message;
    message << "max_rel_error must be between " << scene_error_min << " and " << scene_error_max;
    fail_at(value, message.str(), "out of range");
  }
  return tolerance;
}

// [lo, hi] of finite numbers with lo < hi.
void range(const toml::value& value, const std::string& key, double& lo, double& hi) {
  if (!value.is_array() || value.as_array().size() != 2)
    fail_at(value, "'" + key + "' must be a pair [min, max]", "here");
  lo = number(value.as_array()[0], key);
  hi = number(value.as_array()[1], key);
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    fail_at(value, "'" + key + "' must be two finite numbers, min < max", "impossible range");
}

SceneCurve read_curve(const toml::value& table, double default_tolerance, std::size_t index) {
  const std::string where = "curve " + std::to_string(index + 1);
  if (!table.is_table()) fail_at(table, where + " is not a table", "here");
  check_keys(table,
             {"name", "distribution", "shape", "side", "quantities", "orders", "separation", "load", "max_rel_error"},
             where);
  SceneCurve curve;
  curve.line = static_cast<int>(table.location().line());
  curve.max_rel_error = default_tolerance;
  auto required = [&](const std::string& key) -> const toml::value& {
    const toml::value* value = entry_of(table, key);
    if (!value) fail_at(table, where + " has no '" + key + "'", "this curve");
    return *value;
  };
  if (const toml::value* name = entry_of(table, "name")) curve.name = name_text(*name);

  const toml::value& distribution = required("distribution");
  if (!parse_distribution(text(distribution, "distribution"), curve.distribution))
    fail_at(distribution, "distribution must be \"weibull\" or \"gaussian\"", "unknown distribution");
  if (const toml::value* side = entry_of(table, "side"))
    if (!parse_side(text(*side, "side"), curve.side)) fail_at(*side, "side must be \"tail\" or \"bounded\"", "here");
  if (curve.distribution == Distribution::gaussian) {
    if (const toml::value* shape = entry_of(table, "shape"))
      fail_at(*shape, "the Gaussian has no shape", "remove this key");
    if (curve.side == Side::bounded) fail_at(*entry_of(table, "side"), "the Gaussian has a tail side only", "here");
    curve.shape = 2.0;
  } else {
    const toml::value& shape = required("shape");
    curve.shape = number(shape, "shape");
    if (!(curve.shape >= weibull_shape_min && curve.shape <= weibull_shape_max)) {
      std::ostringstream message;
      message << "shape must be between " << weibull_shape_min << " and " << weibull_shape_max;
      fail_at(shape, message.str(), "out of range");
    }
  }

  const toml::value* quantities = entry_of(table, "quantities");
  const toml::value* orders = entry_of(table, "orders");
  if (quantities && orders) fail_at(*orders, where + " has both 'quantities' and 'orders': give one", "here");
  if (!quantities && !orders) fail_at(table, where + " needs 'quantities' or 'orders'", "this curve");
  const toml::value& list = quantities ? *quantities : *orders;
  const std::string list_key = quantities ? "quantities" : "orders";
  if (!list.is_array() || list.as_array().empty())
    fail_at(list, "'" + list_key + "' must be a non-empty list", "here");
  for (const toml::value& entry : list.as_array()) {
    int twice_order;
    if (quantities) {
      twice_order = quantity_twice_order(text(entry, "quantities"));
      if (twice_order < 0)
        fail_at(entry, "unknown quantity (count, stiffness, area, load, F0, F1/2, F1, F3/2, F2, F5/2)", "here");
    } else {
      const double order = number(entry, "orders");
      twice_order = static_cast<int>(std::lround(2 * order));
      if (!(std::fabs(2 * order - twice_order) < 1e-12 && twice_order >= 0 && twice_order < order_count))
        fail_at(entry, "orders are 0, 0.5, 1, 1.5, 2 or 2.5", "here");
    }
    curve.twice_orders.push_back(twice_order);
  }
  std::sort(curve.twice_orders.begin(), curve.twice_orders.end());
  curve.twice_orders.erase(std::unique(curve.twice_orders.begin(), curve.twice_orders.end()), curve.twice_orders.end());

  const toml::value* separation = entry_of(table, "separation");
  const toml::value* load = entry_of(table, "load");
  if (separation && load) fail_at(*load, where + " has both 'separation' and 'load': give one", "here");
  if (!separation && !load) fail_at(table, where + " needs 'separation' or 'load'", "this curve");
  range(separation ? *separation : *load, separation ? "separation" : "load", curve.range_min, curve.range_max);
  curve.by_load = load != nullptr;
  if (curve.by_load && !(curve.range_min > 0))
    fail_at(*load, "'load' is a range of X_3/2 > 0", "impossible range");
  if (curve.by_load && curve.side == Side::tail && curve.range_max > 1e300)
    fail_at(*load, "'load' is beyond what the tail side reaches", "impossible range");
  if (!curve.by_load && curve.side == Side::bounded && !(curve.range_min < 0))
    fail_at(*separation, "on the bounded side every X is 0 for separation >= 0: the range must reach below 0",
            "impossible range");
  if (!curve.by_load && (std::fabs(curve.range_min) > 1e6 || std::fabs(curve.range_max) > 1e6))
    fail_at(*separation, "separations beyond 1e6 are not tabulated (use the series of asymptotic.hpp)", "too far");
  if (const toml::value* own = entry_of(table, "max_rel_error")) curve.max_rel_error = tolerance(*own);
  return curve;
}

// A [[law]]: its values read as TOML (types checked here, where they are), then every check of a
// law scene by make_scene_law, its message pointed at the key it names.
SceneLaw read_law(const toml::value& table, double default_tolerance) {
  const std::string where = "the law";
  if (!table.is_table()) fail_at(table, where + " is not a table", "here");
  std::set<std::string> keys;
  for (const SceneLawKey& k : scene_law_keys) keys.insert(k.key);
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p) keys.insert(p->key);
  check_keys(table, keys, where);
  SceneLawInputs in;
  const auto optional_number = [&](const char* key) {
    const toml::value* value = entry_of(table, key);
    return value ? number(*value, key) : 0.0 / 0.0;
  };
  if (const toml::value* name = entry_of(table, "name")) in.name = name_text(*name);
  const toml::value* law_name = entry_of(table, "law");
  if (!law_name) fail_at(table, where + " has no 'law'", "this law");
  if (!contact_law_kind_of(text(*law_name, "law").c_str(), in.law))
    fail_at(*law_name, "law must be one of " + contact_law_names(", ", true), "unknown law");
  if (const toml::value* given = entry_of(table, "distribution")) {
    if (!parse_distribution(text(*given, "distribution"), in.distribution))
      fail_at(*given, "distribution must be \"weibull\" or \"gaussian\"", "unknown distribution");
  } else {
    fail_at(table, where + " has no 'distribution'", "here");
  }
  if (const toml::value* side = entry_of(table, "side")) {
    if (!parse_side(text(*side, "side"), in.side)) fail_at(*side, "side must be \"tail\" or \"bounded\"", "here");
    in.side_given = true;
  }
  in.shape = optional_number("shape");
  const std::pair<const char*, double*> surface_numbers[] = {
      {"height_scale", &in.height_scale},     {"summit_radius", &in.summit_radius}, {"summit_density", &in.summit_density},
      {"nominal_area", &in.nominal_area},     {"contact_modulus", &in.contact_modulus}};
  for (const auto& [key, value] : surface_numbers) *value = optional_number(key);
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p) {
    const toml::value* value = entry_of(table, p->key);
    if (!value || !p->choices[0]) {
      in.material.set(p->id, optional_number(p->key));
      continue;
    }
    double index;
    if (!law_choice_index(p->id, text(*value, p->key), index))
      fail_at(*value, std::string("'") + p->key + "' is " + p->range_text, "here");
    in.material.set(p->id, index);
  }
  if (const toml::value* separation = entry_of(table, "separation")) range(*separation, "separation", in.range_min, in.range_max);
  if (const toml::value* own = entry_of(table, "max_rel_error")) in.max_rel_error = number(*own, "max_rel_error");
  in.approach_separation = optional_number("approach_separation");
  try {
    SceneLaw out = make_scene_law(in, LawNaming::scene_key, default_tolerance);
    out.line = static_cast<int>(table.location().line());
    return out;
  } catch (const SceneLawError& error) {
    const toml::value* at = error.key.empty() ? nullptr : entry_of(table, error.key);
    if (error.key == "law") at = law_name;
    fail_at(at ? *at : table, error.what(), error.label);
  }
}

}  // namespace

int quantity_twice_order(const std::string& quantity) {
  static const std::pair<const char*, int> names[] = {
      {"count", 0}, {"stiffness", 1}, {"area", 2}, {"load", 3}, {"F0", 0}, {"F1/2", 1},
      {"F1", 2},    {"F3/2", 3},      {"F2", 4},   {"F5/2", 5}, {"I0", 0}, {"I1/2", 1},
      {"I1", 2},    {"I3/2", 3},      {"I2", 4},   {"I5/2", 5}};
  for (const auto& [name, twice_order] : names)
    if (quantity == name) return twice_order;
  return -1;
}

Scene parse_scene(const std::string& content, const std::string& source) {
  check_scene_text(content, source);
  toml::value root;
  try {
    std::istringstream stream(content);
    root = toml::parse(stream, source);
  } catch (const std::exception& error) {
    throw Error(std::string("scene: not valid TOML: ") + error.what());
  }
  Scene scene;
  scene.source = source;
  check_keys(root, {"name", "max_rel_error", "memory_budget_kib", "curve", "law"}, "the scene");
  if (const toml::value* name = entry_of(root, "name")) scene.name = name_text(*name);
  double default_tolerance = 1e-8;
  if (const toml::value* value = entry_of(root, "max_rel_error")) default_tolerance = tolerance(*value);
  if (const toml::value* budget = entry_of(root, "memory_budget_kib")) {
    const double kib = number(*budget, "memory_budget_kib");
    if (!(kib > 0 && std::isfinite(kib))) fail_at(*budget, "memory_budget_kib must be positive", "here");
    scene.memory_budget_bytes = kib * 1024;
  }
  const toml::value* curves = entry_of(root, "curve");
  if (const toml::value* laws = entry_of(root, "law")) {
    if (curves) fail_at(*laws, "a scene names a law or curves, not both (a law scene makes a contact-curves table)", "here");
    if (!laws->is_array() || laws->as_array().size() != 1)
      fail_at(*laws, "'law' must be one table ([[law]]): a law scene tabulates one law", "here");
    scene.laws.push_back(read_law(laws->as_array()[0], default_tolerance));
    return scene;
  }
  if (!curves) throw Error("scene " + source + ": no [[curve]] entries");
  if (!curves->is_array() || curves->as_array().empty())
    fail_at(*curves, "'curve' must be a list of tables ([[curve]])", "here");
  if (curves->as_array().size() > scene_max_curves)
    fail_at(*curves,
            "a scene has at most " + std::to_string(scene_max_curves) + " curves; this one has " +
                std::to_string(curves->as_array().size()),
            "too many");
  for (std::size_t i = 0; i < curves->as_array().size(); ++i)
    scene.curves.push_back(read_curve(curves->as_array()[i], default_tolerance, i));
  return scene;
}

Scene read_scene_file(const std::string& path) {
  std::string content;
  try {
    content = detail::read_regular_file(path, scene_max_bytes);
  } catch (const detail::RegularFileError& error) {
    throw Error("scene " + path + ": " + error.what() +
                (error.failure() == detail::FileFailure::too_large ? " (a scene file has at most 64 KiB)" : ""));
  }
  return parse_scene(content, path);
}

}  // namespace asperity
