// Scene files: TOML read with toml11 (Debian's libtoml11-dev), which keeps every value's
// line, so each message can point at the key it is about.
#include "asperity/scene.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <toml.hpp>

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
  if (const toml::value* name = entry_of(table, "name")) curve.name = text(*name, "name");

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
    if (!(curve.shape >= scene_shape_min && curve.shape <= scene_shape_max)) {
      std::ostringstream message;
      message << "shape must be between " << scene_shape_min << " and " << scene_shape_max;
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
  toml::value root;
  try {
    std::istringstream stream(content);
    root = toml::parse(stream, source);
  } catch (const std::exception& error) {
    throw Error(std::string("scene: not valid TOML: ") + error.what());
  }
  Scene scene;
  scene.source = source;
  check_keys(root, {"name", "max_rel_error", "memory_budget_kib", "curve"}, "the scene");
  if (const toml::value* name = entry_of(root, "name")) scene.name = text(*name, "name");
  double default_tolerance = 1e-8;
  if (const toml::value* value = entry_of(root, "max_rel_error")) default_tolerance = tolerance(*value);
  if (const toml::value* budget = entry_of(root, "memory_budget_kib")) {
    const double kib = number(*budget, "memory_budget_kib");
    if (!(kib > 0 && std::isfinite(kib))) fail_at(*budget, "memory_budget_kib must be positive", "here");
    scene.memory_budget_bytes = kib * 1024;
  }
  const toml::value* curves = entry_of(root, "curve");
  if (!curves) throw Error("scene " + source + ": no [[curve]] entries");
  if (!curves->is_array() || curves->as_array().empty())
    fail_at(*curves, "'curve' must be a list of tables ([[curve]])", "here");
  for (std::size_t i = 0; i < curves->as_array().size(); ++i)
    scene.curves.push_back(read_curve(curves->as_array()[i], default_tolerance, i));
  return scene;
}

Scene read_scene_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error("scene " + path + ": cannot open the file");
  std::ostringstream content;
  content << file.rdbuf();
  return parse_scene(content.str(), path);
}

}  // namespace asperity
