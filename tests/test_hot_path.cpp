// The query path allocates nothing and can be hammered from several threads at once on one
// curve, giving the same answers as a single thread.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <thread>
#include <vector>

#include "asperity/asperity.h"
#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/table.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// Count every allocation of the process (the test reads the counter around query loops only).
void* operator new(std::size_t size) {
  ++allocations;
  if (void* memory = std::malloc(size ? size : 1)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

std::vector<double> separations() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<double> values(4096);
  for (double& value : values) value = std::sinh(8 * unit(rng));
  values[0] = NAN;
  values[1] = INFINITY;
  return values;
}

TEST(HotPath, QueriesDoNotAllocate) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.7);
  const Curve gaussian = table().curve(Distribution::gaussian, Side::tail, 0);
  asperity_table* c_table = asperity_table_open(ASPERITY_TEST_TABLE, nullptr, 0);
  asperity_curve* c_curve = asperity_curve_open(c_table, "weibull", "bounded", 1.3, nullptr, 0);
  ASSERT_NE(c_curve, nullptr);
  const std::vector<double> inputs = separations();
  std::vector<double> out(inputs.size());
  double sum = 0, logs[order_count];
  ContactState state;
  const long before = allocations.load();
  for (double s : inputs) {
    for (int k = -1; k <= order_count; ++k) sum += curve.log_value(k, s) + gaussian.value(k, s);
    curve.log_values(s, logs);
    contact_at(curve, SurfaceScales{10, 1e-4, 1e-6, 1e9}, s, state);
    sum += logs[3] + state.load + asperity_eval(c_curve, 3, s) + asperity_eval_log(c_curve, 1, s);
  }
  asperity_eval_batch(c_curve, 2, inputs.data(), out.data(), inputs.size());
  asperity_eval_log_batch(c_curve, 5, inputs.data(), out.data(), inputs.size());
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512}) {
    curve.value_batch(1, inputs.data(), out.data(), inputs.size(), isa);
    gaussian.log_value_batch(4, inputs.data(), out.data(), inputs.size(), isa);
  }
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(std::isnan(sum));  // the NaN input went through, by value
  asperity_curve_close(c_curve);
  asperity_table_close(c_table);
}

TEST(HotPath, ContactCurvesQueriesDoNotAllocate) {
  // a measured surface's table (contact_curves.hpp), of a smooth law's shape
  ContactCurvesData data;
  data.source = "test";
  for (int i = 0; i < 40; ++i) {
    const double u = 1e-7 * (1 + i), p = 1e8 * std::exp(-u / 2e-7);
    data.separation.push_back(u);
    data.pressure.push_back(p);
    data.stiffness.push_back(p / 2e-7);
    data.area_fraction.push_back(0.1 * std::exp(-u / 4e-7));
  }
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-6;
  const ContactCurves curves(data);
  const ContactCurves copy = curves;
  std::vector<double> inputs = separations();
  for (double& s : inputs) s = 2e-6 + 2e-6 * std::tanh(s);  // in the range and out of it, NaN, +-inf
  double sum = 0;
  const long before = allocations.load();
  for (double s : inputs) {
    const ContactCurvesState state = copy.at_separation(s);
    sum += curves.pressure(s) + curves.stiffness(s) + curves.area_fraction(s) + state.stiffness +
           curves.separation_at_pressure(s * 1e14) + copy.at_pressure(s * 1e14).separation + curves.summit_count(s);
  }
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(std::isnan(sum));
}

TEST(HotPath, AdhesiveContactCurvesQueriesDoNotAllocate) {
  // an adhesive law's table's shape: compressive p_c = 1e8 exp(-u/2e-7), tensile p_t = 3e7
  // exp(-u/4e-7) (net tension beyond u ~ 2.4e-7, the pull-off inside), a summit count
  ContactCurvesData data;
  data.source = "test";
  for (int i = 0; i < 40; ++i) {
    const double u = 1e-7 * (1 + i), p = 1e8 * std::exp(-u / 2e-7), q = 3e7 * std::exp(-u / 4e-7);
    data.separation.push_back(u);
    data.pressure.push_back(p);
    data.stiffness.push_back(p / 2e-7);
    data.tensile_pressure.push_back(q);
    data.tensile_stiffness.push_back(q / 4e-7);
    data.area_fraction.push_back(0.1 * std::exp(-u / 4e-7));
    data.summit_count.push_back(1e9 * std::exp(-u / 3e-7));
  }
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-6;
  const ContactCurves curves(data);
  ASSERT_TRUE(curves.has_tension());
  ASSERT_TRUE(curves.pull_off_pressure() < 0);
  const ContactCurves copy = curves;
  std::vector<double> inputs = separations();
  for (double& s : inputs) s = 2e-6 + 2e-6 * std::tanh(s);  // in the range and out of it, NaN, +-inf
  double sum = 0;
  const long before = allocations.load();
  for (double s : inputs) {
    const ContactCurvesState state = copy.at_separation(s);
    sum += curves.pressure(s) + curves.stiffness(s) + curves.area_fraction(s) + state.stiffness +
           curves.summit_count(s) + curves.tensile_part(s).pressure + curves.separation_at_pressure(s * 1e13 - 1e7) +
           copy.at_pressure(s * 1e13 - 1e7).separation + curves.pull_off_pressure() + curves.pull_off_separation();
  }
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(std::isnan(sum));
}

TEST(HotPath, ManyThreadsOnOneCurve) {
  const Curve curve = table().curve(Distribution::weibull, Side::bounded, 4.2);
  const std::vector<double> inputs = separations();
  std::vector<double> expected(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) expected[i] = curve.log_value(3, inputs[i]);
  std::atomic<long> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 50; ++round)
        for (std::size_t i = t; i < inputs.size(); i += 3) {
          const double value = curve.log_value(3, inputs[i]);
          if (!(value == expected[i] || (std::isnan(value) && std::isnan(expected[i])))) ++mismatches;
        }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(HotPath, ManyThreadsBatchOnOneCurve) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 0.8);
  const std::vector<double> inputs = separations();
  std::vector<double> expected(inputs.size());
  curve.log_value_batch(2, inputs.data(), expected.data(), inputs.size());
  std::atomic<long> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      std::vector<double> out(inputs.size());
      for (int round = 0; round < 20; ++round) {
        curve.log_value_batch(2, inputs.data(), out.data(), inputs.size());
        for (std::size_t i = 0; i < inputs.size(); ++i)
          if (!(out[i] == expected[i] || (std::isnan(out[i]) && std::isnan(expected[i])))) ++mismatches;
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(mismatches.load(), 0);
}

}  // namespace
