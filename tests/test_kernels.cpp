// The per-instruction-set kernels (runtime/core/kernel/) on their own, for every set this CPU
// runs: contact4 (and contact_products, on a grid made here) on synthetic contact records whose
// log2 X sweep the whole range of exp2 (normal, both edges of its fast path, subnormal,
// underflow, overflow, -inf), against the scalar quintic and a long double exp2 of the kernel's
// own log2 X (the contact records' units, kernels.hpp); the AVX2 and AVX-512 builds of the
// same code give the same bits. The batch path's exp pass (Kernels::exps: exp_x86.hpp's exp4
// for AVX2, exp8 for AVX-512) over the same range, lanes of every regime mixed in one vector,
// and partial vectors. (Curve-level checks are test_curve's and test_batch's; those only
// reach the kernels the CPU's best instruction set selects.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "kernels.hpp"

namespace {
using namespace asperity;
using detail::contact_record_size;

constexpr double inf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

// the quintic of one order (lane k) at y, as fast_quintic writes it
double quintic(const double* record, int k, double y) {
  const double c[6] = {record[k], record[4 + k], record[8 + k], record[12 + k], record[16 + k], record[20 + k]};
  const double y2 = y * y;
  return (c[0] + y * c[1]) + y2 * ((c[2] + y * c[3]) + y2 * (c[4] + y * c[5]));
}

// the record's lane of each order (kernels.hpp: the lanes hold orders 0, 1, 3/2, 1/2)
constexpr int lane_of_order[4] = {0, 3, 1, 2};

struct alignas(64) Record {
  double coefficients[contact_record_size];
};

TEST(Kernels, Contact4IsTheQuinticAndItsExp2OnEverySet) {
  std::uniform_real_distribution<double> unit(-1, 1), y_of(-0.5, 0.5);
  // constant terms (log2 X): where exp2's fast path ends (-1021, 1023), DBL_MIN (-1022), the
  // smallest subnormal (-1074) and half of it (-1075), DBL_MAX (1024), and every other regime
  std::vector<double> levels;
  for (double level = -1100; level <= 1040; level += 0.53) levels.push_back(level);
  for (double edge : {detail::BinaryExp::surely_normal_min, detail::BinaryExp::surely_normal_max, -1022.0, -1074.0,
                      -1075.0, 1024.0}) {
    double below = edge, above = edge;
    for (int k = 0; k < 200; ++k) {
      levels.push_back(below = std::nextafter(below, -inf));
      levels.push_back(above = std::nextafter(above, inf));
    }
  }
  // beyond every range, where the AVX-512 build leaves vscalefpd for the masks (|t| > 2^50),
  // and the special values: the same bits on both x86 sets
  for (double special : {0x1p+50, -0x1p+50, std::nextafter(0x1p+50, inf), -std::nextafter(0x1p+50, inf), 1e300,
                         -1e300, inf, -inf, std::numeric_limits<double>::quiet_NaN()})
    levels.push_back(special);
  int sets = 0;
  std::vector<double> first_x86;  // the AVX2 build's values, to compare the AVX-512 build's with
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512}) {
    if (!instruction_set_available(isa)) continue;
    ++sets;
    const detail::Kernels& kernels = detail::kernels_for(isa);
    std::mt19937_64 random(14);  // the same records for every set
    double worst_log = 0, worst_exp = 0;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      Record record;
      for (int k = 0; k < 4; ++k) {
        // lanes near each other (one interval of a curve) or far apart (one lane alone in the
        // slow regime), slopes and curvature of a real interval's size
        record.coefficients[k] = (i % 3 == 0) ? levels[(i + 97 * k) % levels.size()] : levels[i] + unit(random);
        for (int c = 1; c < 6; ++c) record.coefficients[4 * c + k] = unit(random) * 4.0 / (1 << c);
      }
      if (i % 101 == 0) record.coefficients[2] = -inf;  // X_3/2 exactly 0 (no contact)
      // y = 0 makes the log the constant term exactly: the levels' edges land on the fast path's
      const double y = (i % 2) ? 0.0 : y_of(random);
      double log2s[4], values[4];  // orders 0, 1/2, 1, 3/2
      kernels.contact4(record.coefficients, y, log2s, values);
      if (isa == InstructionSet::avx2) first_x86.insert(first_x86.end(), values, values + 4);
      if (isa == InstructionSet::avx512 && !first_x86.empty()) {
        for (int k = 0; k < 4; ++k) EXPECT_TRUE(same_bits(values[k], first_x86[4 * i + k])) << "lane " << k;
      }
      for (int k = 0; k < 4; ++k) {
        const double expected = quintic(record.coefficients, lane_of_order[k], y);
        if (std::isnan(expected) || std::isnan(log2s[k])) {
          // a NaN constant term, or infinite ones: NaN in, NaN out (log2 X and X)
          EXPECT_TRUE(std::isnan(log2s[k]) && std::isnan(values[k])) << to_string(isa) << " lane " << k;
          ++checked;
          continue;
        }
        if (std::isinf(expected)) {
          EXPECT_EQ(log2s[k], expected);
        } else {
          // fused multiply-adds where the set has them: the rounding of the quintic's terms
          const double error = std::fabs(log2s[k] - expected) / (1 + std::fabs(expected));
          worst_log = std::max(worst_log, error);
          EXPECT_LE(error, 2e-15) << to_string(isa) << " lane " << k << " at " << expected;
        }
        // 2 to the kernel's own log2 X, within 2.3e-16 on the normal range (fast_exp2: 1.1e-16,
        // test_fast_math; the x86 sets' exp4 in base 2, exp_x86.hpp), 0.75 of the spacing below;
        // the generic set is fast_exp2 itself (this file is built like it), the others round
        // with fused multiply-adds
        if (isa == InstructionSet::generic) {
          EXPECT_TRUE(same_bits(values[k], detail::fast_exp2(log2s[k]))) << "lane " << k << " at " << log2s[k];
        }
        const long double exact = std::exp2(static_cast<long double>(log2s[k]));
        const double smallest_normal = std::numeric_limits<double>::min();
        if (exact >= smallest_normal && exact <= std::numeric_limits<double>::max()) {
          const double error = static_cast<double>(std::fabs((values[k] - exact) / exact));
          worst_exp = std::max(worst_exp, error);
          EXPECT_LE(error, 2.3e-16) << to_string(isa) << " lane " << k << ": exp2(" << log2s[k] << ") = " << values[k];
        } else if (exact < smallest_normal) {
          EXPECT_LE(static_cast<double>(std::fabs(values[k] - exact)), 0.75 * std::numeric_limits<double>::denorm_min())
              << to_string(isa) << " lane " << k << ": exp2(" << log2s[k] << ") = " << values[k];
        } else {
          EXPECT_EQ(values[k], inf) << to_string(isa) << " lane " << k << ": exp2(" << log2s[k] << ")";
        }
        ++checked;
      }
    }
    char figures[64];
    std::snprintf(figures, sizeof figures, "%.3g / %.3g", worst_log, worst_exp);
    RecordProperty(std::string("worst_log_and_exp_error_") + to_string(isa), figures);
    EXPECT_GT(checked, 10000u);
  }
  EXPECT_GE(sets, 1);
}

// Curve::contact_products' kernels (fast_grid.hpp's ContactProducts) on a grid made here: one
// binade, s in [1, 2), 64 intervals whose records sweep the same regimes as above (lanes:
// log2 X of orders 0, 1, 3/2, 1/2; one lane alone in a slow regime; X_3/2 exactly 0). Against a
// long double exp2 of contact4's log2 X: the products within 4.5e-16 (the exp's 2.3e-16 and the
// product's rounding) or the subnormal spacing times the factor; the ratio within 8e-16 of
// 1.5 2^(log2 X_1/2 - log2 X_3/2) or the subnormal spacing (contact_ratio_of_parts, every
// regime), NaN where X_3/2 = 0; the AVX2 and AVX-512 builds the same bits (the vector form of
// one is the lane-by-lane form of the other in the deep tails); false for a bad factor or off
// the grid. The surface form (ContactInputs::surface) gives the same bits as the factors
// contact_scales_of makes.
TEST(Kernels, ContactProductsOnEverySet) {
  constexpr int log2_intervals = 6, intervals = 1 << log2_intervals;
  detail::FastGrid grid;
  grid.sides[0].lower = 1.0;
  grid.sides[0].upper = std::nextafter(2.0, 0.0);
  std::vector<detail::FastBinade> directory(2048);
  directory[1023] = detail::FastBinade::make(0, log2_intervals);  // the binade of [1, 2)
  grid.directory = directory.data();
  grid.intervals = intervals;
  std::vector<Record> records(intervals);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::mt19937_64 random(15);
  // log2 X: below half the smallest subnormal, around it, subnormal, around the fast path's
  // lower end (-1021) and DBL_MIN (-1022), normal, around the upper end (1023)
  const double levels[] = {-1096, -1076, -1075, -1040, -1022.5, -1021, -1020.5, -1010, -433, -1.4, 0, 4.3,
                           721, 1023, 1023.5};
  for (int i = 0; i < intervals; ++i)
    for (int k = 0; k < 4; ++k) {
      const int n = static_cast<int>(sizeof levels / sizeof levels[0]);
      records[i].coefficients[k] = (i % 4 == 0) ? levels[(i + 5 * k) % n] : levels[i % n] + unit(random);
      for (int c = 1; c < 6; ++c) records[i].coefficients[4 * c + k] = unit(random) * 2.0 / (1 << c);
      if (i % 9 == 4) records[i].coefficients[2] = -inf;  // X_3/2 = 0 (lane 2)
    }
  const double denorm = std::numeric_limits<double>::denorm_min(), largest = std::numeric_limits<double>::max();
  const double factor_sets[][4] = {{1, 1, 1, 1}, {1e4, 3.1e-6, 1.3e4, 2e10}, {1e-300, 1e300, 5e-324, 1.7e308}};
  int sets = 0;
  std::vector<double> first_x86;
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512}) {
    if (!instruction_set_available(isa)) continue;
    ++sets;
    const detail::Kernels& kernels = detail::kernels_for(isa);
    std::size_t checked = 0, at = 0;
    for (const auto& factors : factor_sets)
      for (int step = 0; step < 20000; ++step) {
        const double s = 1.0 + step / 20000.0;
        double state[5];
        ASSERT_TRUE(kernels.contact_products(grid, records[0].coefficients, s, factors[0], factors[1], factors[2],
                                             factors[3], state))
            << to_string(isa) << " s = " << s;
        if (isa == InstructionSet::avx2) first_x86.insert(first_x86.end(), state, state + 5);
        if (isa == InstructionSet::avx512 && !first_x86.empty()) {
          for (int k = 0; k < 5; ++k) ASSERT_TRUE(same_bits(state[k], first_x86[at + k])) << "s = " << s << " " << k;
        }
        at += 5;
        // log2 X as contact4 gives them at the same position (orders 0, 1/2, 1, 3/2)
        const int interval = static_cast<int>((s - 1.0) * intervals);
        const double y = (s - 1.0) * intervals - interval - 0.5;
        double log2s[4], values[4];
        kernels.contact4(records[interval].coefficients, y, log2s, values);
        const int order_of[4] = {0, 2, 3, 1};  // the state's count, area, load, stiffness
        for (int j = 0; j < 4; ++j) {
          const long double x = std::exp2(static_cast<long double>(log2s[order_of[j]]));
          const long double expected = factors[j] * x;
          const long double bound = 4.5e-16L * std::fabs(expected) + (factors[j] + 1.0L) * denorm;
          if (expected > largest)  // the product overflows (X itself may not be a double)
            EXPECT_TRUE(std::isinf(state[j])) << to_string(isa) << " s = " << s << " quantity " << j;
          else
            ASSERT_LE(std::fabs(state[j] - expected), bound)
                << to_string(isa) << " s = " << s << " quantity " << j << " log2 X = " << log2s[order_of[j]];
        }
        // the surface form: N = count, R = area / (pi N sigma), ... are not exact, so the test
        // gives it a surface and compares with the factors contact_scales_of makes of it
        {
          const double surface[4] = {factors[0], 1e-4 * (1 + step % 7), 1e-6 * (1 + step % 5), 1e11 * (1 + step % 3)};
          const ContactScales scales = detail::contact_scales_of(surface[0], surface[1], surface[2], surface[3]);
          double from_surface[5], from_scales[5];
          const bool a = kernels.contact_products_of_surface(grid, records[0].coefficients, s, surface[0], surface[1],
                                                             surface[2], surface[3], from_surface);
          const bool b = kernels.contact_products(grid, records[0].coefficients, s, scales.count, scales.area,
                                                  scales.load, scales.stiffness, from_scales);
          ASSERT_EQ(a, b) << to_string(isa) << " s = " << s;
          for (int k = 0; a && k < 5; ++k)
            ASSERT_TRUE(same_bits(from_surface[k], from_scales[k])) << to_string(isa) << " s = " << s << " " << k;
        }
        if (log2s[3] == -inf) {
          EXPECT_TRUE(std::isnan(state[4])) << to_string(isa) << " s = " << s;
        } else {
          const long double expected = 1.5L * std::exp2(static_cast<long double>(log2s[1]) - log2s[3]);
          if (expected > largest) {
            EXPECT_TRUE(std::isinf(state[4]) || state[4] >= largest / 2) << to_string(isa) << " s = " << s;
          } else {
            // two exps' mantissas (2.3e-16 each), the division and the product by 1.5, then
            // exact scaling (one rounding to the subnormal spacing below DBL_MIN)
            const long double bound = 8e-16L * expected + denorm;
            ASSERT_LE(std::fabs(state[4] - expected), bound)
                << to_string(isa) << " s = " << s << " log2s " << log2s[1] << " " << log2s[3];
          }
        }
        ++checked;
      }
    // off the grid, and factors outside (0, DBL_MAX]: false
    double state[5];
    for (double s : {0.999, 2.0, -1.5, 0.0, inf, -inf, std::numeric_limits<double>::quiet_NaN()})
      EXPECT_FALSE(kernels.contact_products(grid, records[0].coefficients, s, 1, 1, 1, 1, state)) << s;
    for (int k = 0; k < 4; ++k)
      for (double bad : {0.0, -0.0, -denorm, -1.0, inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
        double factors[4] = {1, 1, 1, 1};
        factors[k] = bad;
        EXPECT_FALSE(kernels.contact_products(grid, records[0].coefficients, 1.25, factors[0], factors[1], factors[2],
                                              factors[3], state))
            << to_string(isa) << " factor " << k << " = " << bad;
      }
    EXPECT_EQ(checked, 60000u);
  }
  EXPECT_GE(sets, 1);
}

// The contact records' log2 X (write_contact_record: the grid's ln X coefficients times log2 e,
// each rounded once) against the exact value of the ln X quintic they come from (long double),
// beside the scalar path's own ln X quintic in double: what base 2 costs in rounding. Quintics
// like a grid's (constant terms over the whole range of ln X, slopes and curvature of an
// interval's size), every instruction set; within test_curve's bound 1e-15 (1 + |ln X|).
TEST(Kernels, ContactRecordsAgainstTheExactQuintic) {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<double> level(-745, 5), unit(-1, 1), y_of(-0.5, 0.5);
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512}) {
    if (!instruction_set_available(isa)) continue;
    const detail::Kernels& kernels = detail::kernels_for(isa);
    double worst_ln = 0, worst_log2 = 0;
    for (int i = 0; i < 20000; ++i) {
      double orders[4][detail::fast_stride];
      for (auto& order : orders) {
        order[0] = level(random);
        for (int j = 1; j < detail::fast_stride; ++j) order[j] = unit(random) * (1 + std::fabs(order[0])) / (8 << j);
      }
      const double* const ln_orders[4] = {orders[0], orders[1], orders[2], orders[3]};
      Record record;
      detail::write_contact_record(ln_orders, record.coefficients);
      const double y = y_of(random);
      double log2s[4], values[4];  // orders 0, 1/2, 1, 3/2
      kernels.contact4(record.coefficients, y, log2s, values);
      for (int k = 0; k < 4; ++k) {
        long double exact = 0, power = 1;
        for (int j = 0; j < detail::fast_stride; ++j, power *= y) exact += orders[k][j] * power;
        const long double scale = 1 + std::fabs(exact);
        const double ln_error = static_cast<double>(std::fabs(detail::fast_quintic(orders[k], 0, y) - exact) / scale);
        const double log2_error =
            static_cast<double>(std::fabs(0.693147180559945309417232121458176568L * log2s[k] - exact) / scale);
        worst_ln = std::max(worst_ln, ln_error);
        worst_log2 = std::max(worst_log2, log2_error);
        ASSERT_LE(log2_error, 1e-15) << to_string(isa) << " ln X = " << static_cast<double>(exact);
      }
    }
    char figures[64];
    std::snprintf(figures, sizeof figures, "%.2g / %.2g", worst_ln, worst_log2);
    RecordProperty(std::string("ln_quintic_and_contact_record_error_") + to_string(isa), figures);
    std::printf("%s: |error| / (1 + |ln X|) against the exact quintic: ln X quintic %.2g, contact records %.2g\n",
                to_string(isa), worst_ln, worst_log2);
  }
}

// exp's accuracy as the kernels' tests state it: 2.3e-16 relative where e^x is a normal
// double, 0.75 of the subnormal spacing below, inf above, NaN for NaN
// (returns the relative error where it is normal, else 0)
double expect_exp(double x, double value, const char* what) {
  const long double exact = std::exp(static_cast<long double>(x));
  const double smallest_normal = std::numeric_limits<double>::min();
  if (std::isnan(x)) {
    EXPECT_TRUE(std::isnan(value)) << what << ": exp(NaN) = " << value;
  } else if (exact >= smallest_normal && exact <= std::numeric_limits<double>::max()) {
    const double error = static_cast<double>(std::fabs((value - exact) / exact));
    EXPECT_LE(error, 2.3e-16) << what << ": exp(" << x << ") = " << value;
    return error;
  } else if (exact < smallest_normal) {
    EXPECT_LE(static_cast<double>(std::fabs(value - exact)), 0.75 * std::numeric_limits<double>::denorm_min())
        << what << ": exp(" << x << ") = " << value;
  } else {
    EXPECT_EQ(value, inf) << what << ": exp(" << x << ")";
  }
  return 0;
}

TEST(Kernels, BatchExpOnEverySetOverTheWholeRange) {
  std::vector<double> inputs;
  for (double x = -760; x <= 720; x += 0.0373) inputs.push_back(x);
  for (double edge : {-708.0, 709.0, -745.13, -708.3964, 709.7827, -746.0, 710.0, 0.0}) {
    double below = edge, above = edge;
    for (int k = 0; k < 200; ++k) {
      inputs.push_back(below = std::nextafter(below, -inf));
      inputs.push_back(above = std::nextafter(above, inf));
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double special : {-inf, inf, nan, -nan, -0.0, 1e300, -1e300, std::numeric_limits<double>::denorm_min(),
                         -std::numeric_limits<double>::max()})
    inputs.push_back(special);
  // lanes of every regime side by side: a random order puts the slow ones in fast vectors
  std::mt19937_64 random(17);
  std::shuffle(inputs.begin(), inputs.end(), random);
  const std::size_t sorted_part = inputs.size();
  for (std::size_t i = 0; i < sorted_part; i += 7) inputs.push_back(-700 + 1e-3 * static_cast<double>(i % 1400));
  int sets = 0;
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512}) {
    if (!instruction_set_available(isa)) continue;
    ++sets;
    const detail::Kernels& kernels = detail::kernels_for(isa);
    std::size_t checked = 0;
    double worst = 0;
    // blocks of every length up to a few vectors (partial vectors at the end), then whole ones
    for (std::size_t start = 0; start < inputs.size();) {
      const int count = start < 4000 ? static_cast<int>(1 + start % 19) : detail::batch_block;
      const int used = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(count), inputs.size() - start));
      std::vector<double> logs(static_cast<std::size_t>(used + detail::batch_pad), 0.0);
      std::copy(inputs.begin() + static_cast<long>(start), inputs.begin() + static_cast<long>(start) + used, logs.begin());
      std::vector<double> out(static_cast<std::size_t>(used + detail::batch_pad), -1.0);
      kernels.exps(logs.data(), out.data(), used);
      for (int j = 0; j < used; ++j) {
        const double x = logs[static_cast<std::size_t>(j)], value = out[static_cast<std::size_t>(j)];
        worst = std::max(worst, expect_exp(x, value, to_string(isa)));
        if (isa == InstructionSet::generic) {  // the baseline's pass is fast_exp itself
          EXPECT_TRUE(same_bits(value, detail::fast_exp(x))) << x;
        }
        ++checked;
      }
      for (std::size_t j = static_cast<std::size_t>(used); j < out.size(); ++j)
        EXPECT_EQ(out[j], -1.0) << to_string(isa) << ": wrote past " << used;
      start += static_cast<std::size_t>(used);
    }
    EXPECT_EQ(checked, inputs.size());
    char figure[32];
    std::snprintf(figure, sizeof figure, "%.3g", worst);
    RecordProperty(std::string("worst_batch_exp_error_") + to_string(isa), figure);
  }
  EXPECT_GE(sets, 1);
}

}  // namespace
