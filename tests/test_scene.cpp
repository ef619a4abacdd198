// Scenes: the file format and its errors, scene tables generated at tolerances from 1e-4 to
// 1e-12 and checked against 50-digit references computed here (never the generator's own
// numbers), exact shapes, memory budgets, and serving a scene from the default table.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <limits>
#include <thread>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "asperity/asperity.h"
#include "asperity/contact.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/inverse.hpp"
#include "asperity/error.hpp"
#include "asperity/scene.hpp"
#include "asperity/scene_curves.hpp"
#include "asperity/table.hpp"
#include "accuracy_harness.hpp"
#include "reference.hpp"
#include "asperity/generator/scene_table.hpp"
#include "asperity/table_writer.hpp"

namespace {
using namespace asperity;

std::string parse_error(const std::string& text) {
  try {
    parse_scene(text, "test.toml");
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(SceneFile, ReadsEveryField) {
  const Scene scene = parse_scene(R"(
name = "bearing"
max_rel_error = 1e-9
memory_budget_kib = 32
[[curve]]
name = "pad"
distribution = "weibull"
shape = 1.73
side = "bounded"
quantities = ["load", "stiffness", "load"]
separation = [-2, -0.01]
[[curve]]
distribution = "gaussian"
orders = [2.5, 2]
load = [1e-6, 1e-2]
max_rel_error = 1e-6
)",
                                  "test.toml");
  EXPECT_EQ(scene.name, "bearing");
  EXPECT_DOUBLE_EQ(scene.memory_budget_bytes, 32 * 1024);
  ASSERT_EQ(scene.curves.size(), 2u);
  const SceneCurve& pad = scene.curves[0];
  EXPECT_EQ(pad.name, "pad");
  EXPECT_EQ(pad.distribution, Distribution::weibull);
  EXPECT_EQ(pad.side, Side::bounded);
  EXPECT_DOUBLE_EQ(pad.shape, 1.73);
  EXPECT_EQ(pad.twice_orders, (std::vector<int>{1, 3}));
  EXPECT_FALSE(pad.by_load);
  EXPECT_DOUBLE_EQ(pad.range_min, -2);
  EXPECT_DOUBLE_EQ(pad.max_rel_error, 1e-9);
  EXPECT_EQ(pad.line, 5);  // its [[curve]] header
  const SceneCurve& film = scene.curves[1];
  EXPECT_EQ(film.distribution, Distribution::gaussian);
  EXPECT_EQ(film.side, Side::tail);
  EXPECT_EQ(film.twice_orders, (std::vector<int>{4, 5}));
  EXPECT_TRUE(film.by_load);
  EXPECT_DOUBLE_EQ(film.max_rel_error, 1e-6);
}

TEST(SceneFile, ErrorsNameTheKeyAndTheLine) {
  const std::string base = "[[curve]]\ndistribution = \"weibull\"\nshape = 2\norders = [1.5]\nseparation = [0, 1]\n";
  std::string message = parse_error(base + "shap = 3\n");
  EXPECT_NE(message.find("unknown key 'shap'"), std::string::npos) << message;
  EXPECT_NE(message.find(" 6 | shap = 3"), std::string::npos) << message;
  message = parse_error("[[curve]]\nshape = 2\norders = [1]\nseparation = [0, 1]\n");
  EXPECT_NE(message.find("no 'distribution'"), std::string::npos) << message;
  message = parse_error("[[curve]]\ndistribution = \"weibull\"\nshape = 0.2\norders = [1]\nseparation = [0, 1]\n");
  EXPECT_NE(message.find("shape must be between 0.3 and 50"), std::string::npos) << message;
  EXPECT_NE(message.find(" 3 | shape = 0.2"), std::string::npos) << message;
  message = parse_error(base + "max_rel_error = 1e-20\n");
  EXPECT_NE(message.find("max_rel_error must be between"), std::string::npos) << message;
  message = parse_error("[[curve]]\ndistribution = \"weibull\"\nshape = 2\norders = [1]\nseparation = [1, 0]\n");
  EXPECT_NE(message.find("impossible range"), std::string::npos) << message;
  message = parse_error(
      "[[curve]]\ndistribution = \"weibull\"\nshape = 2\nside = \"bounded\"\norders = [1]\nseparation = [0, 1]\n");
  EXPECT_NE(message.find("bounded side every X is 0"), std::string::npos) << message;
  message = parse_error("[[curve]]\ndistribution = \"gaussian\"\nshape = 2\norders = [1]\nseparation = [0, 1]\n");
  EXPECT_NE(message.find("the Gaussian has no shape"), std::string::npos) << message;
  message = parse_error(base + "quantities = [\"load\"]\n");
  EXPECT_NE(message.find("both 'quantities' and 'orders'"), std::string::npos) << message;
  message = parse_error("[[curve]]\ndistribution = \"weibull\"\nshape = 2\norders = [0.75]\nseparation = [0, 1]\n");
  EXPECT_NE(message.find("orders are 0, 0.5"), std::string::npos) << message;
  message = parse_error("[[curve]]\ndistribution = \"weibull\"\nshape = 2\norders = [1]\nload = [0, 1]\n");
  EXPECT_NE(message.find("X_3/2 > 0"), std::string::npos) << message;
  message = parse_error("name = \"x\"\n");
  EXPECT_NE(message.find("no [[curve]]"), std::string::npos) << message;
  message = parse_error("x = [1,\n");
  EXPECT_NE(message.find("not valid TOML"), std::string::npos) << message;
  message = parse_error("colour = 1\n[[curve]]\n");
  EXPECT_NE(message.find("unknown key 'colour'"), std::string::npos) << message;
  EXPECT_THROW(read_scene_file("/nonexistent/scene.toml"), Error);
}

// tables/scenes/tolerance-sweep.toml at a given tolerance for every curve.
Scene sweep_scene(double tolerance) {
  Scene scene = read_scene_file(std::string(ASPERITY_TEST_SCENES) + "/tolerance-sweep.toml");
  for (SceneCurve& curve : scene.curves) curve.max_rel_error = tolerance;
  return scene;
}

TEST(SceneTable, MeetsItsToleranceAgainstIndependentReferencesFrom1e4To1e12) {
  std::map<std::tuple<int, int, double>, double> references;
  for (double tolerance : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    const Scene scene = sweep_scene(tolerance);
    const generator::SceneResult result = generator::generate_scene_table(scene, 2);
    const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/scene.h5";
    write_table_file(result.table, path);
    const Table table = Table::open(path);
    EXPECT_TRUE(table.data().exact_shapes);
    const std::vector<SceneCurveView> views = serve_scene(table, scene);
    ASSERT_EQ(views.size(), 3u);
    for (std::size_t c = 0; c < views.size(); ++c) {
      const SceneCurveView& view = views[c];
      // loads resolved on the table's own curve: as close as the table is to the integral
      EXPECT_NEAR(view.separation_min, result.curves[c].separation_min, 10 * tolerance * (1 + std::fabs(view.separation_min)));
      EXPECT_LE(result.curves[c].achieved_error, tolerance);
      EXPECT_LE(view.error_bound, tolerance);
      double worst = 0;
      const double lo = result.curves[c].separation_min, hi = result.curves[c].separation_max;
      for (int i = 0; i <= 16; ++i) {
        const double separation = lo + (hi - lo) * i / 16.0;
        for (int twice_order : view.spec.twice_orders) {
          const auto key = std::make_tuple(static_cast<int>(c), twice_order, separation);
          if (!references.count(key))
            references[key] = static_cast<double>(test::reference_log(
                view.spec.distribution, view.spec.side, view.spec.shape, order_of(twice_order), separation));
          const double error = std::fabs(std::expm1(view.curve.log_value(twice_order, separation) - references[key]));
          worst = std::max(worst, error);
        }
      }
      RecordProperty("curve" + std::to_string(c) + "_tolerance" + std::to_string(tolerance), std::to_string(worst));
      EXPECT_LE(worst, tolerance) << view.spec.name << " at tolerance " << tolerance;
      // only the asked orders are held
      for (int twice_order = 0; twice_order < order_count; ++twice_order) {
        const bool asked = std::find(view.spec.twice_orders.begin(), view.spec.twice_orders.end(), twice_order) !=
                           view.spec.twice_orders.end();
        EXPECT_EQ(std::isnan(view.curve.log_value(twice_order, lo)), !asked);
      }
    }
    std::printf("tolerance %.0e: knots %d / %d / %d, memory %.1f / %.1f / %.1f KiB\n", tolerance,
                result.curves[0].knots, result.curves[1].knots, result.curves[2].knots,
                views[0].curve.memory_bytes() / 1024.0, views[1].curve.memory_bytes() / 1024.0,
                views[2].curve.memory_bytes() / 1024.0);
  }
}

// Issue #10: exact-shape scene tables at small shapes (the tail's power terms s^(n + a), the
// bounded side's d^(n + a)) and at a large one (steep near s = 1), checked next to s = 0 and
// near s = 1 against references computed here, within the tolerance asked. A scene per tolerance;
// ranges that keep X >= 1e-100.
std::string first_contact_scene(double tolerance, const std::vector<double>& shapes) {
  std::ostringstream text;
  text.precision(17);
  text << "name = \"first contact\"\nmax_rel_error = " << tolerance << "\n";
  for (const char* side : {"tail", "bounded"})
    for (double shape : shapes) {
      const bool tail = std::string(side) == "tail";
      text << "[[curve]]\ndistribution = \"weibull\"\nshape = " << shape << "\nside = \"" << side
           << "\"\norders = [0, 0.5, 1, 1.5, 2, 2.5]\nseparation = "
           << (tail ? (shape > 10 ? "[-1, 1.3]" : "[-1, 3]") : "[-2, -1e-15]") << "\n";
    }
  return text.str();
}

// The points of issue #10 inside a curve's range: +-1e-15 ... +-1e-3 (and s = 0), and near
// s = 1 at large shapes.
std::vector<double> first_contact_points(const SceneCurveView& view) {
  std::vector<double> points = {0.0};
  for (double magnitude : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3}) points.insert(points.end(), {-magnitude, magnitude});
  if (view.spec.shape > 10) points.insert(points.end(), {0.98, 1.0, 1.035, 1.07, 1.12, 1.2, 1.3});
  std::vector<double> inside;
  for (double point : points)
    if (point >= view.separation_min && point <= view.separation_max) inside.push_back(point);
  return inside;
}

// Generates the scenes at each tolerance and checks them; prints knots, memory, time.
void check_first_contact_scenes(const std::vector<double>& tolerances, const std::vector<double>& shapes) {
  std::map<std::tuple<int, double, int, double>, double> references;  // (side, shape, order, s)
  auto reference = [&](const SceneCurveView& view, int twice_order, double separation) {
    const auto key = std::make_tuple(static_cast<int>(view.spec.side), view.spec.shape, twice_order, separation);
    auto found = references.find(key);
    if (found != references.end()) return found->second;
    const auto exact = test::closed_form_log(view.spec.distribution, view.spec.side, view.spec.shape, twice_order,
                                             separation);
    const double value = static_cast<double>(
        exact ? *exact
              : test::reference_log(view.spec.distribution, view.spec.side, view.spec.shape, order_of(twice_order),
                                    separation));
    references.emplace(key, value);
    return value;
  };
  for (double tolerance : tolerances) {
    const Scene scene = parse_scene(first_contact_scene(tolerance, shapes), "first-contact.toml");
    const auto start = std::chrono::steady_clock::now();
    const generator::SceneResult result = generator::generate_scene_table(scene, 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/first-contact-scene.h5";
    write_table_file(result.table, path);
    const Table table = Table::open(path);
    const std::vector<SceneCurveView> views = serve_scene(table, scene);
    ASSERT_EQ(views.size(), result.curves.size());
    std::printf("first-contact scene at %.0e: generated in %.1f s\n", tolerance, seconds);
    for (std::size_t c = 0; c < views.size(); ++c) {
      const SceneCurveView& view = views[c];
      EXPECT_LE(view.error_bound, tolerance);
      double worst = 0;
      std::string where;
      for (double separation : first_contact_points(view))
        for (int twice_order : view.spec.twice_orders) {
          const double expected = reference(view, twice_order, separation);
          const double got = view.curve.log_value(twice_order, separation);
          const double error = std::fabs(std::expm1(got - expected));
          char point[160];
          std::snprintf(point, sizeof point, "%s shape %g order %g s %g", to_string(view.spec.side), view.spec.shape,
                        order_of(twice_order), separation);
          EXPECT_LE(error, tolerance) << point << " asked " << tolerance << ": value " << got << " reference "
                                      << expected;
          if (error > worst || where.empty()) worst = error, where = point;
        }
      std::printf("  %-8s a = %-5g asked %.0e: measured %.1e (%s), stored %.1e, %d knots, %.1f KiB\n",
                  to_string(view.spec.side), view.spec.shape, tolerance, worst, where.c_str(),
                  result.curves[c].achieved_error, result.curves[c].knots, result.curves[c].memory_bytes / 1024.0);
    }
  }
}

// The default run: every shape, at the middle tolerance. The full matrix is labelled slow.
TEST(SceneTable, ExactShapesMeetTheirToleranceNextToFirstContact) {
  check_first_contact_scenes({1e-8}, {0.3, 0.41, 0.77, 19.3});
}

TEST(SceneTableSlow, ExactShapesMeetTheirToleranceNextToFirstContactFrom1e6To1e10) {
  check_first_contact_scenes({1e-6, 1e-8, 1e-10}, {0.3, 0.41, 0.77, 19.3});
}

TEST(SceneTable, ServesOnlyItsOwnShapesAndOpensFromC) {
  const Scene scene = sweep_scene(1e-8);
  const generator::SceneResult result = generator::generate_scene_table(scene, 2);
  const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/scene-exact.h5";
  write_table_file(result.table, path);
  const Table table = Table::open(path);
  EXPECT_NO_THROW(table.curve(Distribution::weibull, Side::bounded, 1.73));
  // a shape a hair off its own (issue #28: 1e-12 off was served as the node) is not its own
  for (double other : {1.74, std::nextafter(1.73, 2.0), std::nextafter(1.73, 1.0), 1.73 * (1 + 1e-13)})
    try {
      table.curve(Distribution::weibull, Side::bounded, other);
      ADD_FAILURE() << "a scene table served shape " << other << " as 1.73";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("only its own"), std::string::npos) << error.what();
    }
  char message[256] = "";
  asperity_table* handle = asperity_table_open(path.c_str(), message, sizeof message);
  ASSERT_NE(handle, nullptr) << message;
  asperity_curve* curve = asperity_curve_open(handle, "gaussian", "tail", 0, message, sizeof message);
  ASSERT_NE(curve, nullptr) << message;
  EXPECT_NEAR(asperity_eval_log(curve, 5, 1.0),
              static_cast<double>(test::reference_log(Distribution::gaussian, Side::tail, 2, 2.5, 1.0)), 1e-8);
  asperity_curve_close(curve);
  EXPECT_EQ(asperity_curve_open(handle, "weibull", "tail", 2.0, message, sizeof message), nullptr);
  asperity_table_close(handle);
}

TEST(SceneTable, MemoryBudgetIsEnforcedAndShapesAtTheLimitsWork) {
  Scene scene = parse_scene(R"(
memory_budget_kib = 1
[[curve]]
distribution = "weibull"
shape = 0.3
orders = [1.5]
separation = [0, 10]
[[curve]]
distribution = "weibull"
shape = 50
orders = [1.5]
separation = [0.5, 1.1]
)",
                            "limits");
  try {
    generator::generate_scene_table(scene, 2);
    ADD_FAILURE() << "a 1 KiB budget was not enforced";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("over the budget"), std::string::npos) << error.what();
  }
  scene.memory_budget_bytes = 0;
  const generator::SceneResult result = generator::generate_scene_table(scene, 2);
  for (const generator::SceneCurveReport& report : result.curves) EXPECT_LE(report.achieved_error, 1e-8);
  const Curve curve(Distribution::weibull, Side::tail, 50, result.table.sets[0].layout,
                    &result.table.sets[0].knots[result.table.sets[0].curve_stride()], 1u << 3);
  const double reference = static_cast<double>(test::reference_log(Distribution::weibull, Side::tail, 50, 1.5, 1.0));
  EXPECT_NEAR(curve.log_value(3, 1.0), reference, 1e-8);
}

// Issue #28: the audit's scenes (a = 0.37 tail over [-1, 1e6], a = 17.3 tail over [-1, 1.46], a
// = 0.37 bounded over [-3, -1e-15]), at the tolerance asked.
Scene audit_scene(double tolerance) {
  std::ostringstream text;
  text << "name = \"audit\"\nmax_rel_error = " << tolerance << "\n";
  for (const char* curve : {"shape = 0.37\nside = \"tail\"\nseparation = [-1, 1e6]",
                            "shape = 17.3\nside = \"tail\"\nseparation = [-1, 1.46]",
                            "shape = 0.37\nside = \"bounded\"\nseparation = [-3, -1e-15]"})
    text << "[[curve]]\ndistribution = \"weibull\"\norders = [0, 0.5, 1, 1.5, 2, 2.5]\n" << curve << "\n";
  return parse_scene(text.str(), "audit.toml");
}

// The curve of a scene table at one of its shapes, as Table::curve gives it (all six orders).
Curve scene_curve(const Table& table, const CurveSet& set, std::size_t shape_index) {
  return table.curve(set.distribution, set.side, set.shapes[shape_index]);
}

// A scene table serves only what its scene modelled: outside the range every lookup answers
// NaN (the bounded side at s >= 0: exactly 0), through every path; the range asked is the
// range served (the bounded side up to -1e-15, not cut to -1e-12); inside, every order.
// The inverse of a scene curve whose knot at the deep end of the served range is polished by a
// Newton step an ulp past it: found by the surface analysis (a bounded Weibull of a synthetic
// map served NaN at every load). The inverse must answer across the whole range.
TEST(SceneTable, InverseAnswersAcrossTheServedRange) {
  Scene scene;
  scene.name = scene.source = "inverse at the range's end";
  SceneCurve spec;
  spec.name = "bounded";
  spec.distribution = Distribution::weibull;
  spec.side = Side::bounded;
  spec.shape = 2.4705558989027585;
  spec.twice_orders = {0, 1, 2, 3};
  spec.by_load = true;
  const double load_unit = (4.0 / 3.0) * 2939646201873.0493 * 1e11 * std::sqrt(3.9194154126039503e-06) *
                           std::pow(2.5870282486185612e-08, 1.5);
  spec.range_min = 1e5 / load_unit / 2;
  spec.range_max = 3e7 / load_unit * 2;
  spec.max_rel_error = 1e-8;
  scene.curves.push_back(spec);
  const Table table(generator::generate_scene_table(scene, 2).table);
  const Curve curve = table.curve(Distribution::weibull, Side::bounded, spec.shape);
  const InverseCurve inverse(curve, orders::load);
  const double lo = std::log(curve.value(orders::load, curve.served_max_separation()));
  const double hi = std::log(curve.value(orders::load, curve.served_min_separation()));
  for (int k = 0; k <= 200; ++k) {
    const double y = lo + (hi - lo) * k / 200;
    const double s = inverse.separation_at_log(y);
    ASSERT_TRUE(curve.serves(s)) << "ln X " << y << " gave " << s;
    EXPECT_NEAR(curve.log_value(orders::load, s), y, 1e-12 * std::fabs(y)) << k;
  }
}

TEST(SceneTable, ServesOnlyWhatItsSceneModelled) {
  const Scene scene = audit_scene(1e-6);
  const generator::SceneResult result = generator::generate_scene_table(scene, 2);
  const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/audit-scene.h5";
  write_table_file(result.table, path);
  const Table table = Table::open(path);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  struct Expected { Side side; double shape, lo, hi; std::vector<double> outside; };
  const std::vector<Expected> expected = {
      {Side::tail, 0.37, -1, 1e6, {-100, -1.0000000000000002, 1.0000000000000002e6, 2e6, -inf, inf, nan}},
      {Side::tail, 17.3, -1, 1.46, {-100, -1.0000000000000002, 1.4600000000000002, 3, 1e300}},
      {Side::bounded, 0.37, -3, -1e-15, {-30, -3.0000000000000004, -9.9999999999999990e-16, -1e-300, -4.9e-324}}};
  for (const Expected& e : expected) {
    const Curve curve = table.curve(Distribution::weibull, e.side, e.shape);
    EXPECT_EQ(curve.served_min_separation(), e.lo);
    EXPECT_EQ(curve.served_max_separation(), e.hi);
    const std::string name = std::string(to_string(e.side)) + " " + std::to_string(e.shape);
    for (double s : e.outside) {
      EXPECT_FALSE(curve.serves(s)) << name << " s " << s;
      double logs[order_count], values[4];
      curve.log_values(s, logs);
      double batch[3];
      const double in[3] = {s, s, s};
      for (int k = 0; k < order_count; ++k) {
        EXPECT_TRUE(std::isnan(curve.log_value(k, s))) << name << " s " << s << " order " << k;
        EXPECT_TRUE(std::isnan(curve.value(k, s))) << name << " s " << s << " order " << k;
        EXPECT_TRUE(std::isnan(logs[k])) << name << " s " << s << " order " << k;
        curve.value_batch(k, in, batch, 3);
        EXPECT_TRUE(std::isnan(batch[0]) && std::isnan(batch[2])) << name << " s " << s << " order " << k;
        curve.log_value_batch(k, in, batch, 3);
        EXPECT_TRUE(std::isnan(batch[1])) << name << " s " << s << " order " << k;
      }
      curve.contact_orders(s, logs, values);
      for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isnan(values[k])) << name << " s " << s;
      ContactState state;
      EXPECT_FALSE(contact_at(curve, SurfaceScales{}, s, state)) << name << " s " << s;
      EXPECT_TRUE(std::isnan(state.load));
      EXPECT_FALSE(contact_at_scales(curve, contact_scales(SurfaceScales{}), s, state)) << name << " s " << s;
    }
    // inside, to the ends themselves: finite everywhere
    for (double s : {e.lo, e.hi, 0.5 * (e.lo + e.hi), std::nextafter(e.lo, 0.0), std::nextafter(e.hi, e.lo)})
      for (int k = 0; k < order_count; ++k) {
        EXPECT_TRUE(curve.serves(s)) << name << " s " << s;
        EXPECT_TRUE(std::isfinite(curve.log_value(k, s))) << name << " s " << s << " order " << k;
      }
    if (e.side == Side::bounded)  // out of contact: exactly 0, wherever the range ends
      for (double s : {0.0, 4.9e-324, 2.0, 1e300}) {
        EXPECT_TRUE(curve.serves(s));
        EXPECT_EQ(curve.value(5, s), 0.0);
        EXPECT_EQ(curve.log_value(0, s), -inf);
      }
  }
  // the report says the range as asked (not cut to -1e-12)
  EXPECT_EQ(result.curves[2].separation_max, -1e-15);
  // Table::curve with options narrows what it serves, never widens it
  CurveOptions wider;
  wider.served_min_separation = -1e9;
  const Curve narrowed = table.curve(Distribution::weibull, Side::tail, 17.3, Curve::all_orders, wider);
  EXPECT_EQ(narrowed.served_min_separation(), -1.0);
  CurveOptions inside;
  inside.served_min_separation = 0.5;
  inside.served_max_separation = 1.0;
  const Curve part = table.curve(Distribution::weibull, Side::tail, 17.3, Curve::all_orders, inside);
  EXPECT_TRUE(std::isnan(part.log_value(3, 0.25)));
  EXPECT_NEAR(part.log_value(3, 0.75), narrowed.log_value(3, 0.75), 1e-9);
  CurveOptions beside;
  beside.served_min_separation = 2;
  EXPECT_THROW(table.curve(Distribution::weibull, Side::tail, 17.3, Curve::all_orders, beside), Error);
  // the inverse and the physical model: NaN where the separation would fall outside
  const InverseCurve load_inverse(table.curve(Distribution::weibull, Side::tail, 17.3), orders::load);
  const Curve tail = table.curve(Distribution::weibull, Side::tail, 17.3);
  for (double s : {-0.9, 0.3, 1.2, 1.45}) {
    const double back = load_inverse.separation_at_log(tail.log_value(orders::load, s));
    EXPECT_NEAR(back, s, 1e-9 * (1 + std::fabs(s))) << s;
  }
  EXPECT_TRUE(std::isnan(load_inverse.separation_at_log(tail.log_value(orders::load, -1) + 0.1)));
  EXPECT_TRUE(std::isnan(load_inverse.separation_at_log(tail.log_value(orders::load, 1.46) - 0.1)));
  RoughSurface surface;
  surface.shape = 17.3;
  surface.height_scale = 1e-6;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = 1e11;
  const ContactModel model(table, surface);
  EXPECT_TRUE(std::isfinite(model.at_separation(0.5e-6).load));
  EXPECT_TRUE(std::isnan(model.at_separation(-2e-6).load));
  const double load_at_end = model.at_separation(-1e-6).load;
  EXPECT_NEAR(model.at_load(0.5 * load_at_end).separation, model.at_separation(0).separation +
              (model.at_load(0.5 * load_at_end).separation - model.at_separation(0).separation), 1e-18);
  EXPECT_TRUE(std::isnan(model.at_load(2 * load_at_end).separation));
  EXPECT_TRUE(std::isnan(model.at_load(2 * load_at_end).load));
  // from C: the range, NaN and a status outside it
  char message[256] = "";
  asperity_table* handle = asperity_table_open(path.c_str(), message, sizeof message);
  ASSERT_NE(handle, nullptr) << message;
  asperity_curve* c_curve = asperity_curve_open(handle, "weibull", "bounded", 0.37, message, sizeof message);
  ASSERT_NE(c_curve, nullptr) << message;
  double lo = 0, hi = 0;
  EXPECT_EQ(asperity_curve_range(c_curve, &lo, &hi), ASPERITY_OK);
  EXPECT_EQ(lo, -3.0);
  EXPECT_EQ(hi, -1e-15);
  EXPECT_TRUE(std::isnan(asperity_eval(c_curve, 3, -30)));
  const double in[3] = {-1, -30, 0.5};
  double out[3];
  EXPECT_EQ(asperity_eval_batch(c_curve, 3, in, out, 3), ASPERITY_OUTSIDE_RANGE);
  EXPECT_TRUE(std::isfinite(out[0]) && std::isnan(out[1]) && out[2] == 0);
  asperity_contact_state contact;
  EXPECT_EQ(asperity_contact(c_curve, 1, 1, 1, 1, -30, &contact), ASPERITY_OUTSIDE_RANGE);
  EXPECT_TRUE(std::isnan(contact.load));
  EXPECT_EQ(asperity_contact(c_curve, 1, 1, 1, 1, -1, &contact), ASPERITY_OK);
  asperity_curve_close(c_curve);
  asperity_model* c_model = asperity_model_open(handle, "weibull", "tail", 17.3, 1e-6, 1e-4, 1e10, 1e-4, 1e11,
                                                message, sizeof message);
  ASSERT_NE(c_model, nullptr) << message;
  asperity_physical_state physical;
  EXPECT_EQ(asperity_model_at_separation(c_model, -2e-6, &physical), ASPERITY_OUTSIDE_RANGE);
  EXPECT_EQ(asperity_model_at_separation(c_model, 0.5e-6, &physical), ASPERITY_OK);
  EXPECT_EQ(asperity_model_at_load(c_model, 2 * load_at_end, &physical), ASPERITY_OUTSIDE_RANGE);
  asperity_model_close(c_model);
  asperity_table_close(handle);
}

// Where the error of a scene curve peaks: the middle and quarters of every interval of its layout
// (eighths in the two at each end of a segment), approaching every segment end and both ends of
// the range, the lookup grid's binade ends (just below each power of two: where its first-contact
// zone ends), toward s = 0 and past the table's end.
std::vector<double> dense_points(const CurveSet& set, std::size_t shape_index, double lo, double hi) {
  const double shape = set.shapes[shape_index];
  const auto maps = detail::SegmentMap::resolve(set.layout, set.distribution, set.side, shape);
  std::vector<double> points;
  for (std::size_t g = 0; g < maps.size(); ++g) {
    const int intervals = set.layout[g].knots - 1;
    const double step = (maps[g].u_hi - maps[g].u_lo) / intervals;
    for (int j = 0; j < intervals; ++j) {
      const int parts = j < 2 || j >= intervals - 2 ? 8 : 4;
      for (int k = 1; k < parts; ++k) points.push_back(maps[g].separation_of_u(maps[g].u_lo + step * (j + double(k) / parts)));
    }
    for (double end : {maps[g].s_lo, maps[g].s_hi})
      if (std::isfinite(end))
        for (int k = 2; k <= 14; k += 2)
          points.insert(points.end(), {end * (1 - std::pow(10.0, -k)), end * (1 + std::pow(10.0, -k))});
  }
  for (double end : {lo, hi})
    for (int k = 1; k <= 15; ++k) {
      const double offset = std::max(std::fabs(end), 1e-3) * std::pow(10.0, -k);
      points.insert(points.end(), {end + offset, end - offset});
    }
  for (int k = -10; k <= 72; ++k) {
    const double binade = std::ldexp(1.0, -k);
    points.insert(points.end(), {std::nextafter(binade, 0.0), -std::nextafter(binade, 0.0), binade, -binade});
  }
  for (int k = 1; k <= 300; k += (k < 30 ? 1 : 10)) points.insert(points.end(), {std::pow(10.0, -k), -std::pow(10.0, -k)});
  const double table_max = maps.back().s_hi;
  if (table_max > 0 && hi > table_max)
    for (int k = 1; k <= 64; ++k) points.push_back(table_max * std::pow(hi / table_max, k / 64.0));
  std::vector<double> inside;
  for (double point : points)
    if (point >= lo && point <= hi) inside.push_back(point);
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

// Issue #28: the stored max_rel_error is a bound. Every curve of the audit's scenes at 1e-6 and
// 1e-10, at every point of dense_points, against the 50-digit closed forms (the orders that have
// them there: J_0 and J_1 everywhere, J_2 for s <= 1, K_0 and K_1 everywhere, every order of the
// bounded side where d^a <= 1), and at the audit's own points against the quadrature too: never
// above the stored bound, which is within the tolerance asked.
void check_stored_bounds(double tolerance) {
  const Scene scene = audit_scene(tolerance);
  const generator::SceneResult result = generator::generate_scene_table(scene, 2);
  const Table table(result.table);
  struct Point { std::size_t set, shape; int twice_order; double separation, reference; bool known; };
  std::vector<Point> points;
  for (std::size_t s = 0; s < result.table.sets.size(); ++s) {
    const CurveSet& set = result.table.sets[s];
    for (std::size_t i = 0; i < set.shapes.size(); ++i) {
      const Curve curve = scene_curve(table, set, i);
      const std::vector<double> dense = dense_points(set, i, curve.served_min_separation(), curve.served_max_separation());
      for (std::size_t d = 0; d < dense.size(); d += test::subsample_stride())
        for (int k = 0; k < order_count; ++k) points.push_back({s, i, k, dense[d], 0, false});
    }
  }
  std::vector<std::thread> pool;
  for (unsigned worker = 0; worker < 2; ++worker)
    pool.emplace_back([&, worker] {
      for (std::size_t p = worker; p < points.size(); p += 2) {
        Point& point = points[p];
        const CurveSet& set = result.table.sets[point.set];
        const auto exact = test::closed_form_log(set.distribution, set.side, set.shapes[point.shape], point.twice_order,
                                                 point.separation);
        if (!exact) continue;
        point.reference = static_cast<double>(*exact);
        point.known = true;
      }
    });
  for (std::thread& thread : pool) thread.join();
  // the audit's points (and the quadrature there, for the orders without a closed form)
  struct Audit { std::size_t set; double shape, separation; };
  for (const Audit& audit : {Audit{0, 0.37, 8548.5}, Audit{1, 0.37, -3.3e-4}, Audit{1, 0.37, -3.13885761e-4},
                             Audit{0, 17.3, 2.95501469e-07}, Audit{0, 0.37, -7.73348438e-07}})
    for (int k = 0; k < order_count; ++k) {
      const CurveSet& set = result.table.sets[audit.set];
      const std::size_t shape = static_cast<std::size_t>(std::find(set.shapes.begin(), set.shapes.end(), audit.shape) -
                                                          set.shapes.begin());
      points.push_back({audit.set, shape, k, audit.separation,
                        static_cast<double>(test::reference_log(set.distribution, set.side, audit.shape, order_of(k),
                                                                audit.separation)),
                        true});
    }
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> worst;
  std::map<std::pair<std::size_t, std::size_t>, Curve> curves;
  std::size_t checked = 0;
  for (const Point& point : points) {
    if (!point.known) continue;
    const CurveSet& set = result.table.sets[point.set];
    auto found = curves.find({point.set, point.shape});
    if (found == curves.end()) found = curves.emplace(std::make_pair(point.set, point.shape), scene_curve(table, set, point.shape)).first;
    const Curve& curve = found->second;
    const double stored = set.max_rel_error[point.shape * order_count + point.twice_order];
    EXPECT_LE(stored, tolerance);
    const double value = curve.log_value(point.twice_order, point.separation);
    const double error = std::isinf(point.reference) ? (value == point.reference ? 0.0 : 1.0)
                                                     : std::fabs(std::expm1(value - point.reference));
    auto& row = worst[{point.set, point.shape}];
    row.resize(order_count, 0.0);
    row[point.twice_order] = std::max(row[point.twice_order], error);
    ++checked;
    EXPECT_LE(error, stored) << to_string(set.side) << " a = " << set.shapes[point.shape] << " order "
                             << order_of(point.twice_order) << " s = " << std::setprecision(17) << point.separation
                             << ": measured above the stored bound";
  }
  std::printf("asked %.0e: %zu values checked\n", tolerance, checked);
  for (const auto& [key, row] : worst) {
    const CurveSet& set = result.table.sets[key.first];
    std::printf("  %-8s a = %-5g measured / stored:", to_string(set.side), set.shapes[key.second]);
    for (int k = 0; k < order_count; ++k)
      std::printf(" %.1e/%.1e", row[k], set.max_rel_error[key.second * order_count + k]);
    std::printf("\n");
  }
}

TEST(SceneTableSlow, StoredBoundsHoldOnDenseChecksAt1e6And1e10) {
  check_stored_bounds(1e-6);
  check_stored_bounds(1e-10);
}

// A scene's tolerance holds where X < 1e-100 too (its grid does not take the default table's 100
// times more there): a Weibull tail over t = 125 to 729 and the Gaussian over [20, 38] at 1e-11,
// which could not be made before issue #28, within the stored bound at J_0 and J_1 (closed forms).
TEST(SceneTable, KeepsItsToleranceWhereXIsBelow1e100) {
  const Scene scene = parse_scene(R"(
max_rel_error = 1e-11
[[curve]]
distribution = "weibull"
shape = 3
orders = [0, 1, 1.5]
separation = [5, 9]
[[curve]]
distribution = "gaussian"
orders = [2.5]
separation = [20, 38]
)",
                                  "deep.toml");
  const generator::SceneResult result = generator::generate_scene_table(scene, 2);
  const Table table(result.table);
  const CurveSet& set = *table.find(Distribution::weibull, Side::tail);
  const Curve curve = table.curve(Distribution::weibull, Side::tail, 3.0);
  for (int k = 0; k < order_count; ++k) EXPECT_LE(set.max_rel_error[k], 1e-11) << k;
  for (int i = 0; i <= 32; ++i) {
    const double s = 5 + 4.0 * i / 32;
    for (int k : {0, 2}) {
      const double exact = static_cast<double>(*test::closed_form_log(Distribution::weibull, Side::tail, 3.0, k, s));
      EXPECT_LE(std::fabs(std::expm1(curve.log_value(k, s) - exact)), set.max_rel_error[k]) << "s " << s << " order " << k;
    }
  }
  const Curve gaussian = table.curve(Distribution::gaussian, Side::tail, 0);
  const double reference = static_cast<double>(test::reference_log(Distribution::gaussian, Side::tail, 2, 2.5, 33.0));
  EXPECT_LE(std::fabs(std::expm1(gaussian.log_value(5, 33.0) - reference)), 1e-11);
}

TEST(SceneFromDefaultTable, ServedWithTheTestedBoundOrRefused) {
  const Table table = Table::open(ASPERITY_TEST_TABLE);
  const Scene scene = sweep_scene(1e-8);
  const std::vector<SceneCurveView> views = serve_scene(table, scene);
  for (const SceneCurveView& view : views) {
    EXPECT_LE(view.error_bound, 1e-10);
    for (int twice_order : view.spec.twice_orders) {
      const double separation = 0.5 * (view.separation_min + view.separation_max);
      const double reference = static_cast<double>(test::reference_log(view.spec.distribution, view.spec.side,
                                                                       view.spec.shape, order_of(twice_order), separation));
      EXPECT_LE(std::fabs(std::expm1(view.curve.log_value(twice_order, separation) - reference)), view.error_bound);
    }
    // a scene curve holds only its orders: a third of the memory or less
    EXPECT_LE(view.curve.memory_bytes(), table.curve(view.spec.distribution, view.spec.side, view.spec.shape)
                                                 .memory_bytes() * view.spec.twice_orders.size() / 6 + 4096);
  }
  // 1e-12 between grid shapes is more than the default table guarantees
  EXPECT_THROW(serve_scene(table, sweep_scene(1e-12)), Error);
}

}  // namespace
